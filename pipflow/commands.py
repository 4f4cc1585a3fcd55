"""Commands that the library adds to the ``pipflow`` command line: bench, report, view, compare.

Why here and not in ``engine/cli.py``: the engine knows no particular step and no part of the
library; these commands are registered through the ``pipflow.commands`` entry-point group (as
steps are through ``pipflow.steps``), so the CLI imports nothing above it. Each entry point is a
function ``register(subparsers, common)`` that adds its sub-commands.
"""
from __future__ import annotations

import argparse
import os
from pathlib import Path

from pipflow.engine.cliargs import port_number, positive_int
from pipflow.engine.recordref import BENCH_DIR, resolve_record
from pipflow.engine.writes import DiskError
from pipflow.errors import UserError


#: how every command names a record (:mod:`pipflow.engine.recordref`)
RECORD_HELP = ("a run or bench folder, latest, -N (the N-th newest run), a workflow's name (its newest run), "
               "a run's id (the end of its folder name), or a bench folder's name in bench-out/")


def _record(ref: str, args: argparse.Namespace) -> Path:
    return resolve_record(ref, getattr(args, "runs_dir", None) or "runs")


def register(sub: argparse._SubParsersAction, common: argparse.ArgumentParser) -> None:
    bench = sub.add_parser("bench", parents=[common], help="run a task file's tasks x seeds and score them")
    bench.add_argument("tasks", help="task file (benchmarks/README.md format)")
    bench.add_argument("--workflow", default=None, help="workflow to run per task (default: the task file's, else its task domain's built-in workflow)")
    bench.add_argument("--seeds", type=int, default=1, help="runs per task; seeds vary the robots' start positions")
    bench.add_argument("--jobs", type=positive_int, default=None,
                       help="parallel processes, or workers of a local dask cluster (default: CPU count)")
    bench.add_argument("--out", default=None, help="output directory: new, empty, or a bench's (default: bench-out/<UTC time>-<random>)")
    bench.add_argument("--matrix", action="append", metavar="KEY=V1,V2", help="run variants side by side")
    bench.add_argument("-i", "--input", action="append", metavar="KEY=VALUE", help="set a workflow input for every run")
    bench.add_argument("--faults", default=None, metavar="KIND=N,...",
                       help="inject faults into every run, drawn from each run's seed: robot-loss=1, slowdown=1, "
                            "passage-closed=1, and the domain's own surprise kind; --matrix faults=none,"
                            "robot-loss=1,... compares them side by side")
    bench.add_argument("--no-cache", action="store_true")
    bench.add_argument("--backend", default=None, metavar="local|dask[=ADDRESS]",
                       help="where the runs execute: local (default): a process pool of --jobs; dask: a "
                            "LocalCluster of --jobs workers; dask=tcp://host:8786: a running dask scheduler")
    # the name before the rename ("executor" now names only the engine's), kept so that scripts keep
    # working: hidden from --help; bench_main prints a one-line notice when it is used
    bench.add_argument("--executor", default=None, help=argparse.SUPPRESS)
    bench.add_argument("--resume", action="store_true",
                       help="complete the bench in --out: run only the runs without a row file")
    bench.add_argument("--llm-concurrency", default=None, metavar="N|PROVIDER=N,...",
                       help="most concurrent LLM calls per provider across a dask cluster "
                            "(default: $PIPFLOW_LLM_CONCURRENCY or 4)")
    bench.add_argument("--table", choices=["paper"], default=None,
                       help="also lay the results out as the paper's tables (I-III: text, CSV, LaTeX) in OUT/paper/")
    bench.add_argument("--min-runs", type=positive_int, default=None, metavar="N",
                       help="with --table: mark a cell over fewer than N runs (default: 3)")
    bench.set_defaults(func=cmd_bench)

    table = sub.add_parser("bench-table", parents=[common],
                           help="a bench's results as the paper's tables (I-III), as text, CSV or LaTeX")
    table.add_argument("dir", help="bench output directory (results.json, runs.json)")
    table.add_argument("--format", choices=["text", "csv", "latex"], default="text", help="what to print (default: text)")
    table.add_argument("--min-runs", type=positive_int, default=None, metavar="N",
                       help="mark a cell over fewer than N runs (default: 3)")
    table.add_argument("-o", "--out", default=None, metavar="DIR",
                       help="also write every table in every format into DIR (table1.md, table1.csv, table1.tex, ...)")
    table.set_defaults(func=cmd_bench_table)

    report = sub.add_parser("report", parents=[common], help="write a static HTML report of a run or a bench")
    report.add_argument("dir", metavar="RUN_OR_BENCH", help=RECORD_HELP)
    report.add_argument("-o", "--output", help="HTML file (default: DIR/report.html)")
    report.set_defaults(func=cmd_report)

    view = sub.add_parser("view", parents=[common],
                          help="browse runs and benches in a local read-only web page (loopback)")
    view.add_argument("dir", nargs="*", default=None, metavar="DIR_OR_RECORD",
                      help="folders of runs and benches (default: --runs-dir, ./runs, and ./bench-out); a record "
                           "(run or bench, as `pipflow show` names it) opens its report")
    view.add_argument("--port", type=port_number, default=0, help="port on 127.0.0.1 (default: any free port)")
    view.add_argument("--no-browser", action="store_true", help="print the address only")
    view.set_defaults(func=cmd_view)

    track = sub.add_parser("mlflow-log", parents=[common],
                           help="log runs or benches to MLflow (needs the mlflow extra); the records stay pipflow's")
    track.add_argument("records", nargs="+", metavar="RUN_OR_BENCH", help=RECORD_HELP)
    track.add_argument("--tracking-uri", default=None,
                       help="MLflow store (default: $MLFLOW_TRACKING_URI, else MLflow's own default, "
                            "sqlite:///mlflow.db here); e.g. sqlite:///mlflow.db, file:./mlruns, http://host:5000")
    track.add_argument("--experiment", default="pipflow", help="MLflow experiment name (default: pipflow)")
    track.add_argument("--again", action="store_true", help="log a record that is already in the store once more")
    track.set_defaults(func=cmd_mlflow_log)

    compare = sub.add_parser("compare", parents=[common],
                             help="runs, or benches (per variant), side by side with intervals over seeds")
    compare.add_argument("records", nargs="+", metavar="RUN_OR_BENCH", help=RECORD_HELP + " (two or more)")
    compare.set_defaults(func=cmd_compare)


def cmd_mlflow_log(args: argparse.Namespace) -> int:
    # deferred: the MLflow export (and mlflow itself, an optional extra) only for this command
    from pipflow.records.tracking import log_record

    for ref in args.records:
        folder = _record(ref, args)
        done = log_record(folder, tracking_uri=args.tracking_uri, experiment=args.experiment, again=args.again)
        what = "already logged as" if done.existing else "logged as"
        extra = f" with {done.children} variant run(s)" if done.children else ""
        print(f"{folder}: {what} MLflow run {done.run_id}{extra} (experiment {args.experiment!r}, "
              f"id {done.experiment_id}; store {done.tracking_uri}); see it with `mlflow ui --backend-store-uri "
              f"{done.tracking_uri}`")
    return 0


def cmd_bench(args: argparse.Namespace) -> int:
    # deferred: pulls networkx and jsonschema (the engine's runner; every CLI command loads this module)
    from pipflow.experiments.benchmarking import bench_main

    return bench_main(args)


def cmd_bench_table(args: argparse.Namespace) -> int:
    # deferred: the bench package pulls the engine's runner (networkx, jsonschema); every CLI command loads this module
    from pipflow.experiments.papertables import MIN_RUNS, bench_tables, render, write_tables

    tables = bench_tables(Path(args.dir), args.min_runs or MIN_RUNS)
    if args.out:
        for path in write_tables(tables, Path(args.out)):
            print(f"wrote {path}")
    print(render(tables, args.format))
    return 0


def cmd_report(args: argparse.Namespace) -> int:
    # deferred: ~30 ms of import (report, pictures); every CLI command loads this module
    from pipflow.records.report import write_report

    try:
        print(write_report(_record(args.dir, args), args.output or None))  # the text: a trailing / names a folder
    except DiskError as err:
        if args.output:
            raise
        raise DiskError(f"{err}; write the report elsewhere with -o FILE (nothing is then written into the record)",
                        err.path, err.errno) from None
    return 0


def cmd_view(args: argparse.Namespace) -> int:
    from pipflow.records.view import serve  # deferred: pulls http.server (~30 ms; every CLI command loads this module)

    runs_dir = getattr(args, "runs_dir", None) or "runs"
    folders, opened = [], None
    for ref in args.dir or []:
        p = Path(ref)
        if p.is_dir() and not (p / "run.json").is_file() and not (p / "results.json").is_file():
            folders.append(p)
        else:  # a record: its folder is served and its report opened
            opened = _record(ref, args)
            folders.append(opened.parent)
    if not args.dir:
        folders = [Path(runs_dir)]
    if any(Path(os.path.abspath(f)) == Path(os.path.abspath(runs_dir)) for f in folders) and BENCH_DIR.is_dir():
        folders.append(BENCH_DIR)  # the runs folder's benches: `pipflow bench` writes them to bench-out/
    serve(folders, port=args.port, open_browser=not args.no_browser, opened=opened)
    return 0


def cmd_compare(args: argparse.Namespace) -> int:
    if len(args.records) < 2:
        raise UserError("compare needs two or more records (runs, or benches): e.g. `pipflow compare latest -2`")
    # deferred: the comparison's statistics and bench readers (every CLI command loads this module)
    from pipflow.records.compare import compare_text
    print(compare_text(*[_record(ref, args) for ref in args.records]))
    return 0

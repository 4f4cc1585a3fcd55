"""Commands that the library adds to the ``pipflow`` command line: bench, report, view, compare.

Why here and not in ``engine/cli.py``: the engine knows no particular step and no part of the
library; these commands are registered through the ``pipflow.commands`` entry-point group (as
steps are through ``pipflow.steps``), so the CLI imports nothing above it. Each entry point is a
function ``register(subparsers, common)`` that adds its sub-commands.
"""
from __future__ import annotations

import argparse
from pathlib import Path

from pipflow.engine.cliargs import port_number, positive_int
from pipflow.engine.writes import DiskError
from pipflow.records.compare import compare_text


def register(sub: argparse._SubParsersAction, common: argparse.ArgumentParser) -> None:
    bench = sub.add_parser("bench", parents=[common], help="run a task file's tasks x seeds and score them")
    bench.add_argument("tasks", help="task file (benchmarks/README.md format)")
    bench.add_argument("--workflow", default=None, help="workflow to run per task (default: the task file's, else its task domain's built-in workflow)")
    bench.add_argument("--seeds", type=int, default=1, help="runs per task; seeds vary the robots' start positions")
    bench.add_argument("--jobs", type=positive_int, default=None,
                       help="parallel processes, or workers of a local dask cluster (default: CPU count)")
    bench.add_argument("--out", default=None, help="output directory (default: bench-out/<time>)")
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
    report.add_argument("dir", help="run directory or bench output directory")
    report.add_argument("-o", "--output", help="HTML file (default: DIR/report.html)")
    report.set_defaults(func=cmd_report)

    view = sub.add_parser("view", parents=[common],
                          help="browse runs and benches in a local read-only web page (loopback)")
    view.add_argument("dir", nargs="?", default=None, help="folder of runs/benches (default: --runs-dir, ./runs)")
    view.add_argument("--port", type=port_number, default=0, help="port on 127.0.0.1 (default: any free port)")
    view.add_argument("--no-browser", action="store_true", help="print the address only")
    view.set_defaults(func=cmd_view)

    compare = sub.add_parser("compare", parents=[common], help="two runs or two benches side by side")
    compare.add_argument("a", help="run or bench directory")
    compare.add_argument("b", help="run or bench directory")
    compare.set_defaults(func=cmd_compare)


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
        print(write_report(Path(args.dir), args.output or None))  # the text: a trailing / names a folder
    except DiskError as err:
        if args.output:
            raise
        raise DiskError(f"{err}; write the report elsewhere with -o FILE (nothing is then written into the record)",
                        err.path, err.errno) from None
    return 0


def cmd_view(args: argparse.Namespace) -> int:
    from pipflow.records.view import serve  # deferred: pulls http.server (~30 ms; every CLI command loads this module)

    serve(args.dir or getattr(args, "runs_dir", None) or "runs", port=args.port, open_browser=not args.no_browser)
    return 0


def cmd_compare(args: argparse.Namespace) -> int:
    print(compare_text(Path(args.a), Path(args.b)))
    return 0

"""``pipflow bench``: run every task of a task file (benchmarks/README.md format) with N seeds
and optional variants, in parallel processes, score each run against the task's ground truth,
and write results.json, runs.csv and a markdown table shaped like the paper's.

A run is one (variant, task, seed). It runs the workflow in a worker process with the inputs
``command``, ``world`` and ``seed`` (plus the variant's and ``-i`` inputs), then is scored from
what the run record holds: the workflow's outputs ``graph``, ``schedule`` and ``simulation``,
or the refusal or error that ended it. The seed varies the robots' start positions.
"""
from __future__ import annotations

import argparse
import csv
import datetime as _dt
import itertools
import json
import os
import sys
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from pipflow.errors import UserError

RESULT_FIELDS = ["variant", "task", "seed", "status", "success", "goal_met", "gcr", "exe", "ru", "tc_max",
                 "tc_avg", "tc_avg_moved", "makespan", "planned", "executed", "seconds", "error", "run_dir"]


@dataclass(frozen=True)
class RunSpec:
    variant: str
    task: dict
    seed: int
    workflow: str
    inputs: dict
    world_path: str
    runs_dir: str
    use_cache: bool = True


@dataclass
class BenchConfig:
    tasks_file: Path
    workflow: str | None = None  # None: the task file's, else its domain's built-in workflow
    seeds: int = 1
    jobs: int = 1
    out: Path = Path("bench-out")
    matrix: dict[str, list[str]] = field(default_factory=dict)
    inputs: dict[str, str] = field(default_factory=dict)
    use_cache: bool = True
    executor: str = "local"
    resume: bool = False
    llm_limits: dict[str, int] = field(default_factory=dict)


def parse_matrix(items: list[str] | None) -> dict[str, list[str]]:
    """``--matrix key=v1,v2`` (repeatable) -> {key: [v1, v2]}; ``workflow`` is a key too."""
    matrix: dict[str, list[str]] = {}
    for item in items or []:
        if "=" not in item:
            raise UserError(f"--matrix {item!r}: expected key=v1,v2")
        key, values = item.split("=", 1)
        matrix[key.strip()] = [v.strip() for v in values.split(",") if v.strip()]
        if not matrix[key.strip()]:
            raise UserError(f"--matrix {item!r}: no values")
    return matrix


def variants(matrix: dict[str, list[str]]) -> list[tuple[str, dict[str, str]]]:
    """Every combination of the matrix, named like ``allocator=greedy,graph_mode=paper``."""
    if not matrix:
        return [("default", {})]
    keys = list(matrix)
    out = []
    for combo in itertools.product(*(matrix[k] for k in keys)):
        values = dict(zip(keys, combo))
        out.append((",".join(f"{k}={Path(v).stem if k == 'workflow' else v}" for k, v in values.items()), values))
    return out


def run_one(spec: RunSpec) -> dict:
    """Run and score one (variant, task, seed) in this process; never raises."""
    from pipflow.engine.executor import RunOptions
    from pipflow.engine.runner import run_workflow
    from pipflow.benchdomains import domain_named
    from pipflow.engine.store import read_json

    task = spec.task
    row: dict[str, Any] = {"variant": spec.variant, "task": task["id"], "seed": spec.seed}
    started = time.perf_counter()
    inputs = {"command": task["command"], "world": spec.world_path, "seed": spec.seed,
              **(task.get("inputs") or {}), **spec.inputs}  # per-task inputs: a household task's team
    refusal = error = None
    outputs: dict = {}
    try:
        result = run_workflow(spec.workflow, inputs, runs_dir=spec.runs_dir, inputs_from_text=True,
                              options=RunOptions(use_cache=spec.use_cache))
        row["status"], row["run_dir"] = result.status, str(result.run_dir)
        outputs = result.outputs or {}
        if result.status == "refused":
            refusal = result.error
        elif result.status != "succeeded":
            error = result.error
        metrics = read_json(result.run_dir / "metrics.json", {})
        row["stage_seconds"] = metrics.get("step_seconds", {})
    except Exception as err:  # an invalid workflow or input: the run never started
        row["status"], error = "error", f"{type(err).__name__}: {err}"
    score = domain_named(task.get("domain")).score(spec.world_path, task, outputs, refusal, error)
    row.update(score)
    row["seconds"] = round(time.perf_counter() - started, 3)
    return row


def _workers(jobs: int | None) -> int:
    return max(1, jobs or os.cpu_count() or 1)


def _safe(name: str) -> str:
    """A variant or task name as one path component."""
    out = "".join(c if (c.isalnum() or c in "-_.,=+@") else "_" for c in str(name))
    return out if out not in ("", ".", "..") else "_"


def row_path(out: Path, key: tuple[str, str, int]) -> Path:
    """Where a finished run's row lives: ``OUT/runs/<variant>/<task>/<seed>.json``."""
    variant, task, seed = key
    return Path(out) / "runs" / _safe(variant) / _safe(task) / f"{int(seed)}.json"


def read_row(out: Path, key: tuple[str, str, int]) -> dict | None:
    """The stored row of a run, or None (missing, torn or of another run)."""
    from pipflow.engine.store import read_json
    from pipflow.executors import run_key

    try:
        row = read_json(row_path(out, key))
    except (OSError, ValueError):
        return None
    if not isinstance(row, dict):
        return None
    try:
        return row if run_key(row) == tuple(key) else None
    except (KeyError, TypeError, ValueError):
        return None


def build_specs(config: BenchConfig, tasks_doc: dict, world_path: str) -> list[RunSpec]:
    specs: list[RunSpec] = []
    records = str(Path(config.out) / "records")
    for name, values in variants(config.matrix):
        values = dict(values)
        workflow = values.pop("workflow", config.workflow)
        for task in tasks_doc["tasks"]:
            for seed in range(config.seeds):
                specs.append(RunSpec(name, task, seed, workflow, {**config.inputs, **values}, world_path,
                                     records, config.use_cache))
    return specs


def run_bench(config: BenchConfig, progress: bool = True, on_row=None) -> dict:
    """Run the whole bench; write results into ``config.out``; return results.json's content.

    Each finished run's row is written at once to ``OUT/runs/<variant>/<task>/<seed>.json``; with
    ``config.resume`` the runs whose row file exists are not run again. ``on_row(row)`` is called
    after each row is stored (tests use it to interrupt or to kill a worker)."""
    from pipflow.executors import make_executor, run_key
    from pipflow.benchdomains import domain_of

    domain = domain_of(config.tasks_file)
    tasks_doc = domain.load_tasks(Path(config.tasks_file))
    if config.workflow is None:
        config.workflow = tasks_doc.get("workflow") or domain.workflow
    world_path = str(tasks_doc["world_path"] if "world_path" in tasks_doc else
                     (Path(config.tasks_file).parent / tasks_doc["world"]).resolve())
    out = Path(config.out)
    out.mkdir(parents=True, exist_ok=True)
    specs = build_specs(config, tasks_doc, world_path)
    done: dict[tuple, dict] = {}
    if config.resume:
        for spec in specs:
            row = read_row(out, run_key(spec))
            if row is not None:
                done[run_key(spec)] = row
    todo = [s for s in specs if run_key(s) not in done]
    executor = make_executor(config.executor, config.jobs, llm_limits=config.llm_limits,
                             records_dir=out / "records")
    started = time.perf_counter()
    fresh = _execute(executor, todo, done, out, progress, total=len(specs), on_row=on_row)
    wall = time.perf_counter() - started
    rows = [done[run_key(s)] for s in specs if run_key(s) in done]
    results = _results(rows, tasks_doc["tasks"], config, wall, domain.name)
    results["executed_runs"], results["resumed_runs"] = fresh, len(specs) - len(todo)
    _write(out, rows, results)
    return results


def _execute(executor, todo: list[RunSpec], done: dict, out: Path, progress: bool, total: int,
             on_row=None) -> int:
    """Run ``todo`` on the executor; store each row as it arrives (first arrival wins: a run
    retried after a worker died counts once). Returns how many runs finished here."""
    from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeElapsedColumn

    from pipflow.engine.store import write_json
    from pipflow.executors import run_key

    fresh = 0
    columns = [TextColumn(f"bench ({executor.name})"), BarColumn(), MofNCompleteColumn(), TimeElapsedColumn()]
    with Progress(*columns, disable=not progress, transient=False) as bar:
        task_id = bar.add_task("runs", total=total, completed=total - len(todo))

        def receive(row: dict) -> None:
            nonlocal fresh
            key = run_key(row)
            if key in done and done[key].get("status") != "lost":
                return
            done[key] = row
            if row.get("status") != "lost":  # an executor failure is not stored: --resume reruns it
                write_json(row_path(out, key), row)
            fresh += 1
            bar.advance(task_id)
            if on_row is not None:
                on_row(row)

        if todo:
            executor.run(todo, receive)
    return fresh


def _results(rows: list[dict], tasks: list[dict], config: BenchConfig, wall: float, domain: str) -> dict:
    from pipflow.scoring import aggregate_task, summarize

    by_variant: dict[str, list[dict]] = {}
    for row in rows:
        by_variant.setdefault(row["variant"], []).append(row)
    variant_results = []
    for name, vrows in by_variant.items():
        task_rows = [aggregate_task(t["id"], [r for r in vrows if r["task"] == t["id"]]) for t in tasks]
        stage = {}
        for r in vrows:
            for k, v in (r.get("stage_seconds") or {}).items():
                stage.setdefault(k, []).append(v)
        variant_results.append({"name": name, "summary": summarize(task_rows), "tasks": task_rows,
                                "stage_seconds": {k: sum(v) / len(v) for k, v in stage.items()}})
    first = variant_results[0]
    return {"summary": first["summary"], "tasks": first["tasks"], "variants": variant_results,
            "config": {"tasks": str(config.tasks_file), "domain": domain, "workflow": config.workflow, "seeds": config.seeds,
                       "jobs": config.jobs, "executor": config.executor, "matrix": config.matrix, "inputs": config.inputs},
            "wall_seconds": round(wall, 3),
            "created": _dt.datetime.now(_dt.timezone.utc).isoformat(timespec="seconds")}


def _fmt(value: Any, digits: int = 1) -> str:
    if value is None:
        return "--"
    return f"{value:.{digits}f}"


def markdown_table(results: dict) -> str:
    """The paper's table for the task file's domain: for the warehouse, per task SR (%) and
    travel cost max/avg (m); a domain may group it otherwise (household: per category)."""
    from pipflow.benchdomains import domain_named

    config = results.get("config") or {}
    domain = domain_named(config.get("domain"))
    if domain.table is not None:
        return domain.table(results, Path(config["tasks"]))
    lines = []
    for variant in results["variants"]:
        if len(results["variants"]) > 1:
            lines.append(f"### {variant['name']}\n")
        lines += ["| Task | SR (%) | TC max/avg all robots/avg robots that moved (m) | GCR | Exe | RU | makespan (s) | error |",
                  "|---|---|---|---|---|---|---|---|"]
        for t in variant["tasks"]:
            err = (t.get("error") or "").replace("|", "/").replace("\n", " ")[:80]
            lines.append(f"| {t['id']} | {100 * t['sr']:.0f} | {_fmt(t['tc_max'])}/{_fmt(t['tc_avg'])}/{_fmt(t.get('tc_avg_moved'))} | "
                         f"{t['gcr']:.2f} | {t['exe']:.2f} | {t['ru']:.2f} | {_fmt(t.get('makespan'))} | {err} |")
        s = variant["summary"]
        lines.append(f"| **all** ({s['runs']} runs) | {100 * s['sr']:.0f} | {_fmt(s['tc_max'])}/{_fmt(s['tc_avg'])}/{_fmt(s.get('tc_avg_moved'))} | "
                     f"{s['gcr']:.2f} | {s['exe']:.2f} | {s['ru']:.2f} | | |")
        lines.append("")
    lines.append(f"wall time: {results['wall_seconds']:.1f} s")
    return "\n".join(lines)


def _write(out: Path, rows: list[dict], results: dict) -> None:
    from pipflow.engine.store import atomic_write, write_json

    write_json(out / "results.json", results)
    write_json(out / "runs.json", rows)
    with open(out / "runs.csv", "w", newline="", encoding="utf-8") as fh:
        writer = csv.DictWriter(fh, fieldnames=RESULT_FIELDS, extrasaction="ignore")
        writer.writeheader()
        for row in rows:
            writer.writerow({k: (json.dumps(v) if isinstance(v, (list, dict)) else v) for k, v in row.items()})
    atomic_write(out / "table.md", markdown_table(results) + "\n")


def bench_main(args: argparse.Namespace) -> int:
    """The CLI entry: build the config from arguments, run, print the table."""
    from pipflow.engine.cli import _key_values

    stamp = _dt.datetime.now(_dt.timezone.utc).strftime("%Y%m%dT%H%M%SZ")
    tasks_file = Path(args.tasks)
    if not tasks_file.exists():
        raise UserError(f"{tasks_file}: no such task file")
    from pipflow.executors import parse_executor, parse_limits

    executor = getattr(args, "executor", None) or "local"
    parse_executor(executor)  # a typo fails before anything runs
    resume = bool(getattr(args, "resume", False))
    if resume and not args.out:
        raise UserError("--resume needs --out DIR (the bench directory to complete)")
    limits = getattr(args, "llm_concurrency", None) or os.environ.get("PIPFLOW_LLM_CONCURRENCY") or "4"
    config = BenchConfig(
        tasks_file=tasks_file, workflow=args.workflow, seeds=max(1, args.seeds),
        jobs=_workers(args.jobs), out=Path(args.out or f"bench-out/{stamp}"),
        matrix=parse_matrix(args.matrix), inputs=_key_values(args.input or []), use_cache=not args.no_cache,
        executor=executor, resume=resume, llm_limits=parse_limits(limits))
    results = run_bench(config, progress=not args.quiet)
    print(markdown_table(results))
    print(f"results: {config.out / 'results.json'}")
    lost = [r for r in json.loads((config.out / "runs.json").read_text()) if r.get("status") == "lost"]
    if lost:  # the executor could not finish these runs: the table is incomplete
        print(f"{len(lost)} run(s) were lost by the executor (first: {lost[0].get('error')}); "
              f"`pipflow bench ... --out {config.out} --resume` runs them again", file=sys.stderr)
        return 1
    return 0

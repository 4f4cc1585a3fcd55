"""``pipflow bench``: run every task of a task file (benchmarks/README.md format) with N seeds
and optional variants, in parallel processes, score each run against the task's ground truth,
and write results.json, runs.csv and a markdown table shaped like the paper's.

A run is one (variant, task, seed). It runs the workflow in a worker process with the inputs
``command``, ``world`` and ``seed`` (plus the variant's and ``-i`` inputs), then is scored from
what the run record holds: the workflow's outputs ``graph``, ``schedule`` and ``simulation``,
or the refusal or error that ended it. The seed varies the robots' start positions.

Before the first run every variant is validated (its workflow, and the matrix and ``-i`` values
against the workflow's input types): a bench that cannot run is a user error (exit 2), never a
table of zero scores. A run that ends in a user error (an unknown planner, a missing provider key)
stops the bench the same way. Each row carries a fingerprint of everything that defines its run
(the content of the workflow and of every file it extends or names, the inputs, the task, the seed,
pipflow's version); ``--resume`` reuses a row only when its fingerprint is the run's, and refuses,
saying what differs, when the bench folder holds rows of another configuration.

Besides the outcome (SR, as in the paper), each run is scored on understanding
(:mod:`pipflow.meaning`): whether the goal and robot rules it resolved (outputs ``goal`` and
``constraints``) mean what the task's gold means (``understood``), whether they mean something
else (``misread``, whatever happened next: executed, failed later in planning, refused for
another reason), and whether robots executed that other meaning (``misread_executed``, the worst
failure: robots moved wrongly).
"""
from __future__ import annotations

import argparse
import contextlib
import csv
import datetime as _dt
import hashlib
import io
import itertools
import json
import os
import shutil
import sys
import time
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any

from pipflow.engine.cliargs import key_values
from pipflow.engine.interrupts import held, interrupt_signals
from pipflow.engine.locks import FolderLock, writer_alive
from pipflow.engine.progress import CountProgress
from pipflow.engine.registry import default_registry
from pipflow.engine.runner import find_workflow, resolve_inputs
from pipflow.engine.store import atomic_write, read_json, write_json
from pipflow.engine.writes import DiskError, disk_error, make_dirs, writing
from pipflow.engine.validate import check_given_values, load_workflow
from pipflow.errors import UserError
from pipflow.experiments.backends import build_bundle, make_backend, parse_backend, parse_limits, run_key
from pipflow.experiments.benchdomains import domain_named, domain_of
from pipflow.experiments.benchstats import aggregate_task, summarize
from pipflow.experiments.faultstats import FAULT_FIELDS, fault_summary, fault_table
from pipflow.experiments.papertables import MIN_RUNS, bench_tables, render, write_tables
from pipflow.experiments.runspec import RunSpec, recorded_outputs, run_one  # noqa: F401  (the bench's face: tests, scripts)
from pipflow.meaning import misread_cell
from pipflow.metrics import DEFINITIONS
from pipflow.records.compare import variants_side_by_side
from pipflow.taskdomain import Capability, TaskDomain
from pipflow.version import __version__

RESULT_FIELDS = ["variant", "task", "seed", "status", "loop", "reader", "model", "planner", "engine", "fallback",
                 "success", "understood", "misread", "misread_executed", "goal_met", "gcr", "exe", "ru", "tc_max", "tc_avg", "tc_avg_team", "makespan",
                 "planned", "executed", "seconds", "error", "run_dir", "config_hash"]


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
    backend: str = "local"  # where the runs execute: local | dask | dask=ADDRESS (experiments.backends)
    resume: bool = False
    llm_limits: dict[str, int] = field(default_factory=dict)


def parse_matrix(items: list[str] | None) -> dict[str, list[str]]:
    """``--matrix key=v1,v2`` (repeatable) -> {key: [v1, v2]}; ``workflow`` is a key too."""
    matrix: dict[str, list[str]] = {}
    for item in items or []:
        if "=" not in item:
            raise UserError(f"--matrix {item!r}: expected key=v1,v2")
        key, values = item.split("=", 1)
        if not key.strip():
            raise UserError(f"--matrix {item!r}: no input name before '='")
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
    names = [name for name, _ in out]
    clash = sorted({n for n in names if names.count(n) > 1})
    if clash:  # their rows would share one file and one column of the table
        raise UserError(f"--matrix: two variants would both be named {clash[0]!r} (workflow files with the "
                        "same name, or a value given twice); rename one file or drop the repeated value")
    return out


def _workers(jobs: int | None) -> int:
    return max(1, jobs or os.cpu_count() or 1)


def _safe(name: str) -> str:
    """A variant or task name as one path component, one-to-one: letters, digits and ``-_.,=+@``
    stay, every other character (``/``, ``%``, spaces) becomes its UTF-8 bytes as ``%XX``. Two
    names never share a row file (``a/b`` and ``a_b`` did, so one row was lost and every
    ``--resume`` ran a task again)."""
    out = "".join(c if (c.isalnum() or c in "-_.,=+@") else "".join(f"%{b:02X}" for b in c.encode("utf-8"))
                  for c in str(name))
    if out in (".", ".."):
        return out.replace(".", "%2E")
    return out or "%"


def row_path(out: Path, key: tuple[str, str, int]) -> Path:
    """Where a finished run's row lives: ``OUT/runs/<variant>/<task>/<seed>.json``."""
    variant, task, seed = key
    return Path(out) / "runs" / _safe(variant) / _safe(task) / f"{int(seed)}.json"


def read_row(out: Path, key: tuple[str, str, int]) -> dict | None:
    """The stored row of a run, or None (missing, torn or of another run)."""
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


#: where runs write their records while they run; a record moves to ``OUT/records/`` just after its
#: row (which names the record's place there) is stored, so a killed bench leaves no record that no
#: row refers to. When the next bench into the same folder starts, a record whose row is stored
#: finishes its move, and the records of unfinished runs are removed (those runs run again).
RUNNING = ".running"


def build_specs(config: BenchConfig, tasks_doc: dict, world_path: str,
                domain: TaskDomain | None = None) -> list[RunSpec]:
    """One spec per (variant, task, seed). A workflow named by a method (``pip-llm``,
    ``pip-llm-checked``) runs the task file's domain's workflow for it
    (:meth:`pipflow.taskdomain.TaskDomain.workflow_for`); the variant keeps the name given."""
    specs: list[RunSpec] = []
    records = str(Path(config.out) / RUNNING)
    for name, values in variants(config.matrix):
        values = dict(values)
        workflow = values.pop("workflow", config.workflow)
        workflow = domain.workflow_for(workflow) if domain is not None and workflow else workflow
        for task in tasks_doc["tasks"]:
            for seed in range(config.seeds):
                specs.append(RunSpec(name, task, seed, workflow, {**config.inputs, **values}, world_path,
                                     records, config.use_cache))
    return specs


def _sha(data: Any) -> str:
    text = data if isinstance(data, str) else json.dumps(data, sort_keys=True, default=str, ensure_ascii=False)
    return hashlib.sha256(text.encode("utf-8")).hexdigest()


def check_variants(specs: list[RunSpec]) -> dict[tuple, dict[str, str]]:
    """Validate every variant before the first run: its workflow file (and every file it extends),
    and its inputs (matrix, ``-i`` and per-task values) against the workflow's declared types, with
    each task's command and seed as a run will get them. Returns, per (workflow, inputs), the
    content hash of every file the run reads (see :func:`pipflow.experiments.backends.build_bundle`: the
    workflow and its extends, the files its path inputs name, its prompt templates).

    Raises :class:`UserError` naming the variant (and the task, when only one task's inputs are
    wrong): a bench that cannot run is an error of the bench, not a table of zero scores."""
    registry = default_registry()
    files: dict[tuple, dict[str, str]] = {}
    loaded: dict[str, Any] = {}
    checked: set[tuple] = set()
    for spec in specs:
        given = _given(spec)
        where = f"bench variant {spec.variant!r}, nothing was run"
        try:
            if spec.workflow not in loaded:
                loaded[spec.workflow] = load_workflow(find_workflow(spec.workflow), registry)
            wf = loaded[spec.workflow]
            key = (spec.workflow, tuple(sorted(given.items())))
            if key not in files:
                bundle = build_bundle(spec.workflow, {**given, "world": spec.world_path})
                files[key] = {rel: _sha(text) for rel, text in bundle.files.items()}
        except UserError as err:
            raise UserError(f"{where}: {err}") from None
        except (OSError, UnicodeDecodeError) as err:  # a file the workflow names cannot be read
            raise UserError(f"{where}: {err}") from None
        task_inputs = tuple(sorted((spec.task.get("inputs") or {}).items()))
        if (key, task_inputs) not in checked:
            checked.add((key, task_inputs))
            try:
                values = resolve_inputs(wf, _run_inputs(spec), from_text=True)
                # the steps' own checks of the values a variant sets (a misspelt fault kind, say)
                check_given_values(wf, registry, {k: values[k] for k in spec.inputs if k in values})
            except UserError as err:
                raise UserError(f"{where} (task {spec.task['id']!r}): {err}") from None
    return files


def _given(spec: RunSpec) -> dict[str, str]:
    """The inputs a variant sets (matrix and ``-i``), as text."""
    return {k: (str(v) if v is not None else "") for k, v in spec.inputs.items()}


def _run_inputs(spec: RunSpec) -> dict[str, Any]:
    """The inputs one run gets (as :func:`run_one` passes them)."""
    return {"command": spec.task["command"], "world": spec.world_path, "seed": spec.seed,
            **(spec.task.get("inputs") or {}), **spec.inputs}


def fingerprint(spec: RunSpec, files: dict[str, str]) -> dict:
    """What defines one run: the hashes of the files it reads, its inputs, its task, its seed and
    pipflow's version. Two runs with equal fingerprints are the same experiment."""
    return {"files": dict(sorted(files.items())), "inputs": {k: str(v) for k, v in sorted(_given(spec).items())},
            "task": spec.task, "seed": int(spec.seed), "pipflow": __version__, "metrics": DEFINITIONS}


def fingerprint_hash(fp: dict) -> str:
    return _sha(fp)


def differences(old: dict | None, new: dict) -> list[str]:
    """What differs between a stored row's fingerprint and this run's, in words."""
    if not isinstance(old, dict):
        return ["the stored row has no fingerprint (written by an older pipflow)"]
    out = []
    if old.get("pipflow") != new["pipflow"]:
        out.append(f"pipflow {old.get('pipflow')} -> {new['pipflow']}")
    if old.get("metrics") != new["metrics"]:
        out.append(f"the metrics' definitions {old.get('metrics') or 'before they were versioned'} -> "
                   f"{new['metrics']} (the row was scored by other definitions)")
    of, nf = old.get("files") or {}, new["files"]
    changed = sorted(k for k in set(of) & set(nf) if of[k] != nf[k])
    if changed:
        out.append(f"changed file(s): {', '.join(changed)}")
    if set(of) != set(nf):
        out.append(f"other files: {', '.join(sorted(set(of) ^ set(nf)))}")
    oi, ni = old.get("inputs") or {}, new["inputs"]
    for k in sorted(set(oi) | set(ni)):
        if oi.get(k) != ni.get(k):
            out.append(f"input {k}: {oi.get(k, '(unset)')!r} -> {ni.get(k, '(unset)')!r}")
    ot, nt = old.get("task") or {}, new["task"]
    keys = sorted(k for k in set(ot) | set(nt) if ot.get(k) != nt.get(k))
    if keys:
        out.append(f"task {nt.get('id')!r}: {', '.join(keys)} changed")
    if old.get("seed") != new["seed"]:
        out.append(f"seed {old.get('seed')} -> {new['seed']}")
    return out or ["the fingerprints differ"]


def run_bench(config: BenchConfig, progress: bool = True, on_row=None) -> dict:
    """Run the whole bench; write results into ``config.out``; return results.json's content.

    Every variant is validated first (:func:`check_variants`). Each finished run's row is written
    at once to ``OUT/runs/<variant>/<task>/<seed>.json`` with its fingerprint; with
    ``config.resume`` the runs whose row file exists with the same fingerprint are not run again,
    and a row with another fingerprint is refused (:class:`UserError` saying what differs).
    ``on_row(row)`` is called after each row is stored (tests use it to interrupt or to kill a
    worker)."""
    domain = domain_of(config.tasks_file)
    tasks_doc = domain.load_tasks(Path(config.tasks_file))
    if config.workflow is None:
        config.workflow = tasks_doc.get("workflow") or domain.workflow
    world_path = str(tasks_doc["world_path"] if "world_path" in tasks_doc else
                     (Path(config.tasks_file).parent / tasks_doc["world"]).resolve())
    specs = build_specs(config, tasks_doc, world_path, domain)
    files = check_variants(specs)
    specs = [replace(s, fingerprint=fingerprint(s, files[(s.workflow, tuple(sorted(_given(s).items())))]))
             for s in specs]
    out = Path(config.out)
    _prepare_out(out, specs)
    lock = FolderLock(out, "bench folder")  # one bench at a time writes a folder (a second is refused)
    lock.acquire()
    try:
        _clear_unfinished(out)
        done: dict[tuple, dict] = {}
        if config.resume:
            done = _resumable(out, specs)
        todo = [s for s in specs if run_key(s) not in done]
        backend = make_backend(config.backend, config.jobs, llm_limits=config.llm_limits,
                               records_dir=out / RUNNING)
        started = time.perf_counter()
        with interrupt_signals():  # SIGTERM and SIGHUP stop the bench as Ctrl-C does (rows kept)
            fresh = _execute(backend, todo, done, out, progress, total=len(specs), on_row=on_row)
        wall = time.perf_counter() - started
        rows = [done[run_key(s)] for s in specs if run_key(s) in done]
        results = _results(rows, tasks_doc["tasks"], config, wall, domain.name)
        results["config"]["workflows"] = {s.variant: s.workflow for s in specs}  # what each variant ran
        results["config"]["variant_values"] = dict(variants(config.matrix))  # each variant's matrix values
        results["config"]["groups"] = domain.table_groups(tasks_doc["tasks"])  # the paper's tables (papertables)
        results["executed_runs"], results["resumed_runs"] = fresh, len(specs) - len(todo)
        _write(out, rows, results)
        return results
    finally:
        with contextlib.suppress(OSError):
            (out / RUNNING).rmdir()  # only when empty: every run's record moved to records/
        lock.release()


def _prepare_out(out: Path, specs: list[RunSpec]) -> None:
    """Make the bench folder (a user error, naming it, when that cannot be done) and refuse a
    bench whose rows would share a file on this folder's file system (names that differ only in
    case, where the file system ignores case)."""
    refuse_foreign_folder(out)
    try:
        out.mkdir(parents=True, exist_ok=True)
        probe = out / f".pipflow-Write-Test-{os.getpid()}"
        probe.write_text("")
        blind = (out / probe.name.lower()).exists()
        probe.unlink()
    except OSError as err:
        full = disk_error(err, out)
        if full is not None and full.full:
            raise DiskError(f"{full}; nothing was run", full.path, full.errno) from None
        raise UserError(f"--out {out}: cannot write the bench folder there ({err.strerror or err}); "
                        "nothing was run") from None
    if blind:
        seen: dict[str, tuple] = {}
        for spec in specs:
            key = run_key(spec)
            name = str(row_path(out, key)).casefold()
            if seen.setdefault(name, key) != key:
                raise UserError(f"--out {out}: runs {seen[name]} and {key} would share one row file on this file "
                                "system, which ignores upper and lower case; rename one task or variant")


#: what a bench folder holds: a folder with none of these (and not empty) is someone else's
BENCH_MARKS = ("results.json", "runs", "records", RUNNING, "runs.json")


def refuse_foreign_folder(out: Path) -> None:
    """Refuse to write a bench into a folder that holds other things than a bench (a bench's
    rows, records and tables would be mixed with the user's files); an empty or missing folder,
    or one a bench wrote, is fine."""
    if out.is_symlink() or (out.exists() and not out.is_dir()):
        raise UserError(f"--out {out}: cannot write the bench folder there: it is not a folder (a bench writes a "
                        "folder of results); nothing was run")
    if not out.is_dir():
        return
    try:
        names = [p.name for p in out.iterdir()]
    except OSError as err:
        raise UserError(f"--out {out}: cannot read the folder ({err.strerror or err}); nothing was run") from None
    if names and not any(n in BENCH_MARKS for n in names):
        shown = ", ".join(sorted(names)[:3]) + (" ..." if len(names) > 3 else "")
        raise UserError(f"--out {out}: the folder holds files that are not a bench's ({shown}); a bench writes into "
                        "a new or empty folder, or one a bench wrote (to continue it: --resume); nothing was run")


def fresh_out(root: Path = Path("bench-out"), label: str = "") -> Path:
    """A new bench folder under ``root``: the UTC time to the second, plus a short random part so
    that two benches started in one second never share a folder."""
    stamp = _dt.datetime.now(_dt.timezone.utc).strftime("%Y%m%dT%H%M%SZ")
    return root / f"{stamp}{'-' + label if label else ''}-{os.urandom(3).hex()}"


def _clear_unfinished(out: Path) -> None:
    """Finish the moves a killed bench left undone, then remove the records of runs it left
    unfinished (they have no row; those runs run again). Only records no live process holds: this
    bench holds the folder's lock, so any other writer is a worker its killed bench left behind."""
    running = out / RUNNING
    if not running.is_dir() or running.is_symlink():
        return
    stored = _stored_record_names(out)
    for record in running.iterdir():
        if not record.is_dir() or record.is_symlink() or writer_alive(record) is True:
            continue
        if record.name in stored and not (out / "records" / record.name).exists():
            _move_record(out, record)  # its row is stored: a kill came between the row and the move
        else:
            shutil.rmtree(record, ignore_errors=True)


def _stored_record_names(out: Path) -> set[str]:
    """The names of the records that stored rows refer to in ``OUT/records``."""
    names: set[str] = set()
    for path in (out / "runs").glob("*/*/*.json"):
        try:
            run_dir = read_json(path).get("run_dir")
        except (OSError, ValueError, AttributeError):
            continue
        if run_dir and Path(str(run_dir)).parent == out / "records":
            names.add(Path(str(run_dir)).name)
    return names


def _running_record(out: Path, row: dict) -> Path | None:
    """A finished run's record in ``OUT/.running``, or None for a run without a record there."""
    run_dir = row.get("run_dir")
    source = Path(str(run_dir)) if run_dir else None
    return source if source is not None and source.parent == out / RUNNING and source.is_dir() else None


def _move_record(out: Path, source: Path) -> None:
    """Move a finished run's record from ``OUT/.running`` into ``OUT/records``."""
    target = out / "records" / source.name
    make_dirs(target.parent, root=out)
    with writing(target, "moving a run record to"):
        os.replace(source, target)


def _store_row(out: Path, key: tuple, row: dict) -> None:
    """Store a finished run's row, then move its record to where the row says it is. A kill
    between the two leaves a stored row whose record is still in ``OUT/.running``, which the next
    bench moves (:func:`_clear_unfinished`); the other order left a record no row referred to,
    which ``--resume`` could not tell from a killed run's and kept beside the rerun's."""
    source = _running_record(out, row)
    if source is not None:
        row["run_dir"] = str(out / "records" / source.name)
    write_json(row_path(out, key), row, root=out)
    if source is not None:
        _move_record(out, source)


def _resumable(out: Path, specs: list[RunSpec]) -> dict[tuple, dict]:
    """The stored rows of runs with this configuration; refuses rows of another one."""
    done: dict[tuple, dict] = {}
    clashes: list[str] = []
    for spec in specs:
        row = read_row(out, run_key(spec))
        if row is None:
            continue
        if row.get("config_hash") == fingerprint_hash(spec.fingerprint):
            done[run_key(spec)] = row
        else:
            v, t, s = run_key(spec)
            clashes.append(f"{v}/{t}/seed {s}: " + "; ".join(differences(row.get("fingerprint"), spec.fingerprint)))
    if clashes:
        more = f" (and {len(clashes) - 3} more)" if len(clashes) > 3 else ""
        raise UserError(f"{out}: --resume refused: {len(clashes)} stored row(s) were made with another "
                        f"configuration than this bench's: " + " | ".join(clashes[:3]) + more
                        + "; resume with the same configuration, or use another --out")
    return done


def _execute(backend, todo: list[RunSpec], done: dict, out: Path, progress: bool, total: int,
             on_row=None) -> int:
    """Run ``todo`` on the backend; store each row as it arrives (first arrival wins: a run
    retried after a worker died counts once), stamped with its run's fingerprint. A run that
    ended in a user error stops the bench (:class:`UserError`; its row is not stored, so a
    ``--resume`` after the fix runs it). Returns how many runs finished here."""
    from rich.progress import (BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeElapsedColumn,
                               TimeRemainingColumn)

    fresh = 0
    by_key = {run_key(s): s for s in todo}
    columns = [TextColumn(f"bench ({backend.name})"), BarColumn(), MofNCompleteColumn(), TimeElapsedColumn(),
               TextColumn("left"), TimeRemainingColumn()]
    # a live bar on a terminal; elsewhere (CI, nohup, a file) a line every few runs or 30 s
    live = progress and sys.stderr.isatty()
    lines = CountProgress(f"bench ({backend.name})", total, total - len(todo)) if progress and not live else None
    with Progress(*columns, disable=not live, transient=False) as bar, contextlib.ExitStack() as stack:
        if lines is not None:
            stack.callback(lines.close)
        task_id = bar.add_task("runs", total=total, completed=total - len(todo))

        def receive(row: dict) -> None:
            nonlocal fresh
            key = run_key(row)
            if key in done and done[key].get("status") != "lost":
                return
            if row.get("user_error"):
                v, t, s = key
                raise UserError(f"bench stopped: run {v}/{t}/seed {s} could not be done as configured: "
                                f"{row.get('error')} (the rows finished before are kept)")
            spec = by_key.get(key)
            if spec is not None and spec.fingerprint is not None:
                row["fingerprint"] = spec.fingerprint
                row["config_hash"] = fingerprint_hash(spec.fingerprint)
            done[key] = row
            if row.get("status") != "lost":  # a backend failure is not stored: --resume reruns it
                try:
                    with held():  # the row is written and its record moves, or neither (an interrupt waits)
                        _store_row(out, key, row)
                except DiskError as err:
                    raise DiskError(f"{err}; the bench stopped (the rows stored before are kept: `pipflow bench ... "
                                    f"--out {out} --resume` continues once there is space)", err.path, err.errno) from None
            fresh += 1
            bar.advance(task_id)
            if lines is not None:
                lines.advance()
            if on_row is not None:
                on_row(row)

        if todo:
            backend.run(todo, receive)
    return fresh


def _results(rows: list[dict], tasks: list[dict], config: BenchConfig, wall: float, domain: str) -> dict:
    groups = domain_named(domain).task_groups
    by_variant: dict[str, list[dict]] = {}
    for row in rows:
        by_variant.setdefault(row["variant"], []).append(row)
    variant_results = []
    for name, vrows in by_variant.items():
        task_rows = []
        for t in tasks:
            trows = [r for r in vrows if r["task"] == t["id"]]
            task_rows.append({**aggregate_task(t["id"], trows), **understanding(trows),
                              **({"construction": t["construction"]} if t.get("construction") else {}),
                              **{g: t[g] for g in groups if t.get(g) is not None}})  # the domain's task groups
        stage = {}
        for r in vrows:
            for k, v in (r.get("stage_seconds") or {}).items():
                stage.setdefault(k, []).append(v)
        variant_results.append({"name": name, "summary": {**summarize(task_rows), **understanding(vrows)},
                                "tasks": task_rows, "constructions": _by_construction(vrows, tasks),
                                "stage_seconds": {k: sum(v) / len(v) for k, v in stage.items()}})
        faults = fault_summary(vrows)  # runs under faults: SR where reachable, refusals, recovery times
        if faults is not None:
            variant_results[-1]["faults"] = faults
    first = variant_results[0]
    return {"summary": first["summary"], "tasks": first["tasks"], "constructions": first["constructions"],
            "variants": variant_results,
            "config": {"tasks": str(Path(config.tasks_file).resolve()), "domain": domain, "workflow": config.workflow, "seeds": config.seeds,
                       "jobs": config.jobs, "backend": config.backend, "matrix": config.matrix, "inputs": config.inputs},
            "wall_seconds": round(wall, 3),
            "created": _dt.datetime.now(_dt.timezone.utc).isoformat(timespec="seconds")}


def understanding(rows: list[dict]) -> dict:
    """``understood``: the share of runs whose resolved goal and rules mean what the gold means
    (None when no run of these was measured); ``misread``: how many runs resolved another meaning
    (whatever happened next); ``misread_executed``: how many of those robots executed."""
    measured = [r for r in rows if r.get("understood") is not None]
    asked = [r for r in rows if r.get("candidate_hit") is not None]
    out = {"understood": (sum(1 for r in measured if r["understood"]) / len(measured)) if measured else None,
           "misread": sum(1 for r in rows if r.get("misread")),
           "misread_executed": sum(1 for r in rows if r.get("misread_executed"))}
    if asked:  # of the clear, feasible commands refused as not understood: the share whose gold
        # reading was among the candidate readings the refusal offered (issue 23)
        out["candidate_recall"] = sum(1 for r in asked if r["candidate_hit"]) / len(asked)
    return out


def _by_construction(rows: list[dict], tasks: list[dict]) -> dict[str, dict]:
    """Understanding per ``construction`` label of the task file (tasks without one are left out)."""
    label = {t["id"]: t.get("construction") for t in tasks}
    groups: dict[str, list[dict]] = {}
    for r in rows:
        if label.get(r["task"]):
            groups.setdefault(label[r["task"]], []).append(r)
    return {k: {"runs": len(v), **understanding(v)} for k, v in sorted(groups.items())}


def _fmt(value: Any, digits: int = 1) -> str:
    if value is None:
        return "--"
    return f"{value:.{digits}f}"


def _pct(value: float | None) -> str:
    return "--" if value is None else f"{100 * value:.0f}"




def markdown_table(results: dict) -> str:
    """The paper's table for the task file's domain: by default per task SR (%), understood
    (%), misread runs (of them executed) and travel cost max/avg (m; TC-avg over the robots that
    moved) and the mean over the team; a domain may group it otherwise (its ``bench_table``, e.g.
    per category)."""
    config = results.get("config") or {}
    domain = domain_named(config.get("domain"))
    faults = fault_table(results)  # runs under faults (None without)
    if domain.supports(Capability.BENCH_TABLE):  # its layout is the domain's, understanding columns included
        table = domain.bench_table(results, Path(config["tasks"]))  # type: ignore[attr-defined]
        return table + (f"\n\n{faults}" if faults else "")
    lines = []
    for variant in results["variants"]:
        if len(results["variants"]) > 1:
            lines.append(f"### {variant['name']}\n")
        lines += ["| Task | SR (%) | understood (%) | misread (executed) | TC max/avg (m) | TC avg over the team (m) "
                  "| GCR | Exe | RU | makespan (s) | error |",
                  "|---|---|---|---|---|---|---|---|---|---|---|"]
        for t in variant["tasks"]:
            err = (t.get("error") or "").replace("|", "/").replace("\n", " ")[:80]
            lines.append(f"| {t['id']} | {100 * t['sr']:.0f} | {_pct(t.get('understood'))} | {misread_cell(t)} | "
                         f"{_fmt(t['tc_max'])}/{_fmt(t['tc_avg'])} | {_fmt(t.get('tc_avg_team'))} | "
                         f"{t['gcr']:.2f} | {t['exe']:.2f} | {t['ru']:.2f} | {_fmt(t.get('makespan'))} | {err} |")
        s = variant["summary"]
        lines.append(f"| **all** ({s['runs']} runs) | {100 * s['sr']:.0f} | {_pct(s.get('understood'))} | "
                     f"{misread_cell(s)} | {_fmt(s['tc_max'])}/{_fmt(s['tc_avg'])} | {_fmt(s.get('tc_avg_team'))} | "
                     f"{s['gcr']:.2f} | {s['exe']:.2f} | {s['ru']:.2f} | | |")
        lines.append("")
        if variant.get("constructions"):
            lines += ["| Construction | runs | understood (%) | misread (executed) |", "|---|---|---|---|"]
            for name, c in variant["constructions"].items():
                lines.append(f"| {name} | {c['runs']} | {_pct(c['understood'])} | {misread_cell(c)} |")
            lines.append("")
    if faults:
        lines.append(faults)
    for variant in results["variants"]:
        recall = (variant.get("summary") or {}).get("candidate_recall")
        if recall is not None:
            lines.append(f"candidate_recall{' (' + variant['name'] + ')' if len(results['variants']) > 1 else ''}: "
                         f"{recall:.2f} (of the clear, feasible commands refused as not understood, the share "
                         f"whose gold reading was among the readings offered)")
    lines.append(f"wall time: {results['wall_seconds']:.1f} s")
    return "\n".join(lines)


def planner_lines(rows: list[dict]) -> list[str]:
    """Which planner answered, per variant, and every fallback: a plan another planner made is
    never shown as the asked-for planner's (the run rows say ``planner``, ``engine``, ``fallback``)."""
    lines = []
    variants = list(dict.fromkeys(r.get("variant", "default") for r in rows))
    for v in variants:
        vrows = [r for r in rows if r.get("variant", "default") == v]
        engines: dict[str, int] = {}
        for r in vrows:
            if r.get("engine"):
                engines[str(r["engine"])] = engines.get(str(r["engine"]), 0) + 1
        fell = [r for r in vrows if r.get("fallback")]
        if not engines and not fell:
            continue
        name = f" ({v})" if len(variants) > 1 else ""
        line = f"planner{name}: " + ", ".join(f"{e} answered {n} run(s)" for e, n in engines.items())
        if fell:
            failed = sum(1 for r in fell if r.get("error_kind") == "PlannerFallback")
            line += (f"; FELL BACK in {len(fell)} run(s)" + (f" ({failed} counted as failed: the bench names the "
                                                              "planner)" if failed else "")
                     + f", e.g. {fell[0]['task']} seed {fell[0]['seed']}: {fell[0]['fallback']}")
        lines.append(line)
    return lines


def _write(out: Path, rows: list[dict], results: dict) -> None:
    write_json(out / "results.json", results, root=out)
    write_json(out / "runs.json", rows, root=out)
    text = io.StringIO(newline="")
    fields = RESULT_FIELDS + (FAULT_FIELDS if any(r.get("faults") for r in rows) else [])
    writer = csv.DictWriter(text, fieldnames=fields, extrasaction="ignore")
    writer.writeheader()
    for row in rows:
        writer.writerow({k: (json.dumps(v) if isinstance(v, (list, dict)) else v) for k, v in row.items()})
    atomic_write(out / "runs.csv", text.getvalue(), root=out)
    atomic_write(out / "table.md", "\n".join([markdown_table(results), *planner_lines(rows)]) + "\n", root=out)


def chosen_backend(args: argparse.Namespace) -> str:
    """The backend the command line names: ``--backend``, or its deprecated alias ``--executor``
    (kept so that scripts written before the rename keep working; it prints a one-line notice).

    Why the alias is read here and not by argparse into one destination: given both with different
    values, the bench would run on whichever came last; it refuses instead (exit 2)."""
    backend, old = getattr(args, "backend", None), getattr(args, "executor", None)
    if old is not None:
        print("pipflow bench: --executor is deprecated, use --backend (same values: local|dask[=ADDRESS])",
              file=sys.stderr)
        if backend is not None and parse_backend(backend) != parse_backend(old):
            raise UserError(f"--backend {backend!r} and --executor {old!r} (its deprecated alias) name two "
                            "backends; give --backend only")
        backend = backend if backend is not None else old
    backend = backend or "local"
    parse_backend(backend)
    return backend


def bench_main(args: argparse.Namespace) -> int:
    """The CLI entry: build the config from arguments, run, print the table."""
    tasks_file = Path(args.tasks)
    if not tasks_file.exists():
        raise UserError(f"{tasks_file}: no such task file")

    backend = chosen_backend(args)  # a typo fails before anything runs
    resume = bool(getattr(args, "resume", False))
    if resume and not args.out:
        raise UserError("--resume needs --out DIR (the bench directory to complete)")
    limits = getattr(args, "llm_concurrency", None) or os.environ.get("PIPFLOW_LLM_CONCURRENCY") or "4"
    if args.seeds < 1:
        raise UserError(f"--seeds {args.seeds}: a bench runs each task at least once (--seeds 1 or more)")
    if args.jobs is not None and args.jobs < 1:
        raise UserError(f"--jobs {args.jobs}: expected 1 or more parallel runs (unset: one per CPU)")
    if getattr(args, "min_runs", None) is not None and getattr(args, "table", None) is None:
        raise UserError("--min-runs marks the cells of the paper's tables: give it with --table paper")
    inputs = key_values(args.input or [])
    matrix = parse_matrix(args.matrix)
    faults = getattr(args, "faults", None)
    if faults is not None:  # --faults SPEC: the `faults` input of every run (README, "Faults, monitoring and recovery")
        if "faults" in inputs or "faults" in matrix:
            raise UserError("--faults and -i faults= / --matrix faults= both set the faults; give one of them")
        inputs["faults"] = faults
    config = BenchConfig(
        tasks_file=tasks_file, workflow=args.workflow, seeds=args.seeds,
        jobs=_workers(args.jobs), out=Path(args.out) if args.out else fresh_out(),
        matrix=matrix, inputs=inputs, use_cache=not args.no_cache,
        backend=backend, resume=resume, llm_limits=parse_limits(limits))
    results = run_bench(config, progress=not args.quiet)
    print(markdown_table(results))
    for line in planner_lines(json.loads((config.out / "runs.json").read_text())):
        print(line)
    if len(results.get("variants", [])) > 1:
        print(variants_side_by_side(results, json.loads((config.out / "runs.json").read_text())))
    if getattr(args, "table", None) == "paper":  # the paper's tables (I-III), also in OUT/paper/
        tables = bench_tables(config.out, getattr(args, "min_runs", None) or MIN_RUNS)
        write_tables(tables, config.out / "paper")
        print(render(tables, "text"))
        print(f"the paper's tables (text, CSV, LaTeX): {config.out / 'paper'}")
    print(f"results: {config.out / 'results.json'}")
    lost = [r for r in json.loads((config.out / "runs.json").read_text()) if r.get("status") == "lost"]
    if lost:  # the backend could not finish these runs: the table is incomplete
        print(f"{len(lost)} run(s) were lost by the backend (first: {lost[0].get('error')}); "
              f"`pipflow bench ... --out {config.out} --resume` runs them again", file=sys.stderr)
        return 1
    return 0

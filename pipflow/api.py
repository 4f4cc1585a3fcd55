"""The Python API for notebooks and scripts: ``pipflow.run`` and ``pipflow.bench``.

Why a separate face over the CLI's machinery: a notebook wants values back (status, outputs,
where the record is), not exit codes and printed tables. Both functions run exactly what
``pipflow run`` / ``pipflow bench`` run, with the same validation and the same run records, so a
result seen in a notebook can be reopened with ``pipflow show`` or ``pipflow report``.

Failures of the run itself (a step failed, the command was refused) come back as a :class:`Run`
(the engine's one run class) whose ``status`` (a :class:`~pipflow.engine.status.RunStatus`) says
so; problems found before a run exists (an invalid workflow, an unknown input) raise the usual
:class:`pipflow.errors.UserError`.
"""
from __future__ import annotations

from pathlib import Path
from typing import Any

from pipflow.engine.executor import RunOptions
from pipflow.engine.runner import Run, run_workflow
from pipflow.engine.status import RunStatus
from pipflow.experiments.benchmarking import BenchConfig, fresh_out, run_bench
from pipflow.records import report as _report  # noqa: F401  (installs the writer of Run.report())

__all__ = ["Run", "RunStatus", "run", "bench"]


def run(workflow: str | Path, *, runs_dir: str | Path | None = None, jobs: int = 1,
        cache: bool = True, **inputs: Any) -> Run:
    """Validate and run a workflow file (or a built-in workflow's name, e.g. ``"warehouse"``)
    with the given inputs as Python values; return the finished :class:`Run`.

    >>> r = pipflow.run("warehouse", command="shelf2 holds 3 product1")   # doctest: +SKIP
    >>> r.status, r.outputs["goal"]                                         # doctest: +SKIP
    ('succeeded', {'shelf2': {'product1': 3}})
    """
    return run_workflow(workflow, inputs, runs_dir=runs_dir or "runs", options=RunOptions(jobs=jobs, use_cache=cache))


def bench(tasks: str | Path, *, workflow: str | None = None, seeds: int = 1, jobs: int = 1,
          out: str | Path | None = None, matrix: dict[str, list[str]] | None = None,
          cache: bool = True, **inputs: Any) -> dict[str, Any]:
    """Run a task file's tasks x seeds (optionally x a matrix of input variants) and return the
    content of the bench's ``results.json`` (its ``summary`` and per-task rows; ``["out"]`` says
    where the bench folder is).

    Each call writes a fresh folder ``bench-out/<UTC time>-api-<random>`` unless ``out`` names
    one: a new or empty folder, or a bench's folder (its rows are replaced run by run); a folder
    holding anything else is refused (:class:`~pipflow.errors.UserError`), so two calls never mix
    their results."""
    folder = Path(out) if out is not None else fresh_out(label="api")
    config = BenchConfig(tasks_file=Path(tasks), workflow=workflow, seeds=max(1, seeds), jobs=max(1, jobs),
                         out=folder, matrix={k: [str(v) for v in vs] for k, vs in (matrix or {}).items()},
                         inputs={k: str(v) for k, v in inputs.items()}, use_cache=cache)
    results = run_bench(config, progress=False)
    return {**results, "out": str(folder)}

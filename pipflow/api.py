"""The Python API for notebooks and scripts: ``pipflow.run`` and ``pipflow.bench``.

Why a separate face over the CLI's machinery: a notebook wants values back (status, outputs,
where the record is), not exit codes and printed tables. Both functions run exactly what
``pipflow run`` / ``pipflow bench`` run, with the same validation and the same run records, so a
result seen in a notebook can be reopened with ``pipflow show`` or ``pipflow report``.

Failures of the run itself (a step failed, the command was refused) come back as a ``Run`` whose
``status`` says so; problems found before a run exists (an invalid workflow, an unknown input)
raise the usual :class:`pipflow.errors.UserError`.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from pipflow.engine.executor import RunOptions
from pipflow.engine.runner import run_workflow
from pipflow.experiments.benchmarking import BenchConfig, run_bench
from pipflow.records.report import write_report


@dataclass
class Run:
    """One finished run: ``status`` is succeeded, failed, refused or interrupted."""

    status: str
    outputs: dict[str, Any] = field(default_factory=dict)
    record: Path | None = None
    error: str | None = None
    error_step: str | None = None
    seconds: float = 0.0
    #: readings a refusal offered instead (each with ``reading``, ``words``, its goal); run one
    #: with the workflow's input ``reading`` (1-based)
    candidates: list = field(default_factory=list)

    @property
    def ok(self) -> bool:
        return self.status == "succeeded"

    def report(self) -> Path:
        """Write the run's static HTML report and return its path."""
        return write_report(self.record)


def run(workflow: str | Path, *, runs_dir: str | Path | None = None, jobs: int = 1,
        cache: bool = True, **inputs: Any) -> Run:
    """Validate and run a workflow file (or a built-in workflow's name, e.g. ``"warehouse"``)
    with the given inputs as Python values; return the finished :class:`Run`.

    >>> r = pipflow.run("warehouse", command="shelf2 holds 3 product1")   # doctest: +SKIP
    >>> r.status, r.outputs["goal"]                                         # doctest: +SKIP
    ('succeeded', {'shelf2': {'product1': 3}})
    """
    result = run_workflow(workflow, inputs, runs_dir=runs_dir or "runs",
                          options=RunOptions(jobs=jobs, use_cache=cache))
    return Run(status=result.status, outputs=result.outputs, record=Path(result.run_dir),
               error=result.error, error_step=result.error_step, seconds=result.seconds,
               candidates=result.candidates)


def bench(tasks: str | Path, *, workflow: str | None = None, seeds: int = 1, jobs: int = 1,
          out: str | Path = "bench-out/api", matrix: dict[str, list[str]] | None = None,
          cache: bool = True, **inputs: Any) -> dict[str, Any]:
    """Run a task file's tasks x seeds (optionally x a matrix of input variants) and return the
    content of the bench's ``results.json`` (its ``summary`` and per-task rows)."""
    config = BenchConfig(tasks_file=Path(tasks), workflow=workflow, seeds=max(1, seeds), jobs=max(1, jobs),
                         out=Path(out), matrix={k: [str(v) for v in vs] for k, vs in (matrix or {}).items()},
                         inputs={k: str(v) for k, v in inputs.items()}, use_cache=cache)
    return run_bench(config, progress=False)

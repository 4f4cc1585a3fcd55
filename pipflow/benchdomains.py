"""What ``pipflow bench`` needs to know about the domain of a task file.

A task file may name its domain (``domain: household``); without one it is a warehouse task file
(the format of benchmarks/README.md). A domain says how its task files load, which workflow runs
them by default, how one run is scored against its task, and, where the paper's table for it is
grouped differently, how the markdown table looks. The bench itself knows no domain.
"""
from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Callable

import yaml

from pipflow.errors import UserError


@dataclass(frozen=True)
class BenchDomain:
    name: str
    workflow: str                                    # built-in workflow run unless --workflow says otherwise
    load_tasks: Callable[[Path], dict]               # {"world_path", "tasks": [...], "workflow"?}
    score: Callable[[str, dict, dict, "str | None", "str | None"], dict]  # world_path, task, outputs, refusal, error
    table: Callable[[dict, Path], str] | None = None  # results, task file -> markdown; None: one row per task


def _warehouse_tasks(path: Path) -> dict:
    from pipflow.world import load_tasks

    return load_tasks(path)


def _warehouse_score(world_path: str, task: dict, outputs: dict, refusal: str | None, error: str | None) -> dict:
    from pipflow.scoring import score_run
    from pipflow.world import load_world

    return score_run(load_world(world_path), task.get("goal") or {}, constraints=task.get("constraints"),
                     feasible=task.get("feasible", True), graph=outputs.get("graph"),
                     schedule=outputs.get("schedule"), simulation=outputs.get("simulation"),
                     refusal=refusal, error=error)


def _household_tasks(path: Path) -> dict:
    from pipflow.household.scoring import load_tasks

    return load_tasks(path)


def _household_score(world_path: str, task: dict, outputs: dict, refusal: str | None, error: str | None) -> dict:
    from pipflow.household.scoring import score_bench_run

    return score_bench_run(world_path, task, outputs, refusal, error)


def _household_table(results: dict, tasks_file: Path) -> str:
    from pipflow.household.scoring import bench_table

    return bench_table(results, tasks_file)


DOMAINS = {
    "warehouse": BenchDomain("warehouse", "warehouse", _warehouse_tasks, _warehouse_score),
    "household": BenchDomain("household", "household", _household_tasks, _household_score, _household_table),
}


def domain_named(name: str | None) -> BenchDomain:
    try:
        return DOMAINS[name or "warehouse"]
    except KeyError:
        raise UserError(f"unknown task domain {name!r}; known: {', '.join(DOMAINS)}") from None


def domain_of(tasks_file: str | Path) -> BenchDomain:
    """The domain a task file declares (read cheaply; validation comes with loading)."""
    try:
        data = yaml.safe_load(Path(tasks_file).read_text(encoding="utf-8"))
    except (OSError, yaml.YAMLError):
        data = None  # the loader reports the problem with its location
    return domain_named(data.get("domain") if isinstance(data, dict) else None)

"""What ``pipflow bench`` needs to know about the domain of a task file.

A task file may name its domain (``domain: household``); without one it is a warehouse task file
(the format of benchmarks/README.md). A domain says how its task files load, which workflow runs
them by default, how one run is scored against its task, and, where the paper's table for it is
grouped differently, how the markdown table looks, and how the goal and rules a run resolved are
compared with the task's gold (understanding, issue 12). The bench itself knows no domain.
"""
from __future__ import annotations

import json
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Callable

import yaml

from pipflow.errors import UserError
from pipflow.yamlsource import read_source, safe_load


@dataclass(frozen=True)
class BenchDomain:
    name: str
    workflow: str                                    # built-in workflow run unless --workflow says otherwise
    load_tasks: Callable[[Path], dict]               # {"world_path", "tasks": [...], "workflow"?}
    score: Callable[[str, dict, dict, "str | None", "str | None"], dict]  # world_path, task, outputs, refusal, error
    table: Callable[[dict, Path], str] | None = None  # results, task file -> markdown; None: one row per task
    #: task, outputs, status, error kind -> {"understood", "misread", "understanding"}; None: not measured
    understand: Callable[[dict, dict, str, "str | None"], dict] | None = None


def _warehouse_tasks(path: Path) -> dict:
    from pipflow.warehouse.world import load_tasks

    return load_tasks(path)


def _warehouse_score(world_path: str, task: dict, outputs: dict, refusal: str | None, error: str | None) -> dict:
    from pipflow.warehouse.scoring import score_run
    from pipflow.warehouse.world import load_world

    return score_run(load_world(world_path), task.get("goal") or {}, constraints=task.get("constraints"),
                     feasible=task.get("feasible", True) and task.get("expect") != "refuse",
                     graph=outputs.get("graph"),
                     schedule=outputs.get("schedule"), simulation=outputs.get("simulation"),
                     refusal=refusal, error=error)


#: how a run ends when the command was refused: infeasible (Refusal), or not understood
#: (TranslationError: the translator refuses what it cannot place rather than guess)
REFUSED_KINDS = ("Refusal", "TranslationError")


def _goal_limits(goal: Any) -> dict | None:
    """A goal as {place: {item: (lowest, highest)}}: an exact count n is (n, n), so a bound
    {at_least: n, at_most: n} equals n; places with no item are left out. None if malformed."""
    from pipflow.goalcounts import limits

    if not isinstance(goal, dict):
        return None
    try:
        return {place: {item: limits(v) for item, v in items.items()}
                for place, items in goal.items() if isinstance(items, dict) and items}
    except (TypeError, ValueError, KeyError):
        return None


def _rule_key(rule: Any) -> str:
    """A robot rule as a comparable string: its ``words`` ignored, robot lists as sets."""
    if not isinstance(rule, dict):
        return json.dumps(rule, sort_keys=True, default=str)
    r = {k: (sorted(map(str, v)) if k in ("only", "never") and isinstance(v, list) else v)
         for k, v in rule.items() if k != "words" and v is not None}
    return json.dumps(r, sort_keys=True, default=str)


def _goal_difference(gold: dict, run: dict) -> str:
    def show(lim):
        lo, hi = lim
        return str(lo) if lo == hi else (f"at least {lo}" if hi is None else f"{lo}..{hi}")

    out = []
    for place in sorted(set(gold) | set(run)):
        g, r = gold.get(place, {}), run.get(place, {})
        for item in sorted(set(g) | set(r)):
            if g.get(item) != r.get(item):
                out.append(f"{place} {item}: gold {show(g[item]) if item in g else '(none)'}, "
                           f"run {show(r[item]) if item in r else '(none)'}")
    return "; ".join(out[:4]) + (" ..." if len(out) > 4 else "")


def warehouse_understanding(task: dict, outputs: dict, status: str, error_kind: str | None) -> dict:
    """Whether a run resolved the task's gold goal and rules. A task whose right answer is a
    refusal (``feasible: false``, ``expect: refuse``) is understood when the run was refused;
    any other task when the run's goal equals the gold (values compared as ranges: an exact count
    or a bound) and its rules equal the gold as a set (``words`` ignored). ``misread``: the run
    went on to the end (robots moved) with a goal or rules other than the gold."""
    refused = status == "refused" or error_kind in REFUSED_KINDS
    executed = status == "succeeded"
    if task.get("feasible") is False or task.get("expect") == "refuse":
        return {"understood": refused, "misread": executed,
                "understanding": "refused, as it should be" if refused else
                ("executed a command whose right answer is a refusal" if executed else "not refused")}
    if executed and "goal" not in outputs:
        return {"understood": None, "misread": None,
                "understanding": "not measured: the workflow has no output `goal`"}
    gold_goal, run_goal = _goal_limits(task.get("goal") or {}), _goal_limits(outputs.get("goal"))
    gold_rules = {_rule_key(r) for r in task.get("constraints") or []}
    run_rules = {_rule_key(r) for r in outputs.get("constraints") or []}
    if run_goal is None:
        return {"understood": False, "misread": False,
                "understanding": "refused" if refused else "no goal among the run's outputs (it did not finish)"}
    problems = []
    if run_goal != gold_goal:
        problems.append("goal: " + _goal_difference(gold_goal or {}, run_goal))
    if run_rules != gold_rules:
        missing, extra = sorted(gold_rules - run_rules), sorted(run_rules - gold_rules)
        problems.append("rules:" + (f" missing {', '.join(missing)}" if missing else "")
                        + (f" unexpected {', '.join(extra)}" if extra else ""))
    return {"understood": not problems, "misread": bool(problems) and executed,
            "understanding": "; ".join(problems) or "goal and rules as the gold"}


def _household_tasks(path: Path) -> dict:
    from pipflow.household.scoring import load_tasks

    return load_tasks(path)


def _household_score(world_path: str, task: dict, outputs: dict, refusal: str | None, error: str | None) -> dict:
    from pipflow.household.scoring import score_bench_run

    return score_bench_run(world_path, task, outputs, refusal, error)


def _household_understanding(task: dict, outputs: dict, status: str, error_kind: str | None) -> dict:
    from pipflow.household.scoring import understanding

    return understanding(task, outputs, status, error_kind)


def _household_table(results: dict, tasks_file: Path) -> str:
    from pipflow.household.scoring import bench_table

    return bench_table(results, tasks_file)


DOMAINS = {
    "warehouse": BenchDomain("warehouse", "warehouse", _warehouse_tasks, _warehouse_score,
                             understand=warehouse_understanding),
    "household": BenchDomain("household", "household", _household_tasks, _household_score, _household_table,
                             understand=_household_understanding),
}


def domain_named(name: str | None) -> BenchDomain:
    try:
        return DOMAINS[name or "warehouse"]
    except KeyError:
        raise UserError(f"unknown task domain {name!r}; known: {', '.join(DOMAINS)}") from None


def domain_of(tasks_file: str | Path) -> BenchDomain:
    """The domain a task file declares (read cheaply; validation comes with loading)."""
    try:  # the shared bounded reader: no /dev/zero, no alias bomb, no deep nesting
        data = safe_load(read_source(tasks_file, "task file"))
    except (UserError, yaml.YAMLError):
        data = None  # the loader reports the problem with its location
    return domain_named(data.get("domain") if isinstance(data, dict) else None)

"""Whether a warehouse bench run understood its command: the goal and robot rules it resolved,
compared with the task's gold (issue 12). A goal is compared as ranges per shelf and product (an
exact count n is the range n..n, so ``{at_least: n, at_most: n}`` equals n); rules as a set,
their source ``words`` ignored."""
from __future__ import annotations

import json
from typing import Any

from pipflow.taskdomain import REFUSED_KINDS
from pipflow.goalcounts import limits


def _goal_limits(goal: Any) -> dict | None:
    """A goal as {place: {item: (lowest, highest)}}: an exact count n is (n, n), so a bound
    {at_least: n, at_most: n} equals n; places with no item are left out. None if malformed."""
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


def understanding(task: dict, outputs: dict, status: str, error_kind: str | None) -> dict:
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

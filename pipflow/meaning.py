"""Whether a run read its command as the task's gold: meanings compared, never texts.

Why meanings: two goals or two rule sets written differently may ask for exactly the same thing
(a goal that lists 0 for the shelves a gathering empties, and one that leaves them to
conservation), and two written alike may not (``never: [all robots]`` against ``never: [the
tugs]``). The bench counts a *misreading* whenever the run's meaning differs from the gold's,
whether or not robots then moved (``misread``); :func:`misread_executed` says whether they did.

What is generic lives here: robot rules as meanings (which robot may take part in which move),
and the verdict of one run (:func:`judge`) from a domain's comparison of goals. Each domain says
when two of its goals mean the same (``goal_difference``): the warehouse by the final stocks they
accept (:mod:`pipflow.warehouse.feasibility`), the household by the final states they accept.

Rules: a rule ``{only|never: [robots], <field>: name, ...}`` governs the moves that agree with
every field it gives; ``never`` keeps its robots out of them, ``only`` keeps every other robot
out. A rule set means the set of (robot, move) pairs it forbids. Two rule sets are compared on
every robot of the world (and any a rule names) and every combination of the field values either
set mentions, plus one stand-in for the values neither mentions: values no rule names are
treated alike by every rule, so these are all the cases the rules can tell apart, and equal
verdicts there are equal meanings everywhere.
"""
from __future__ import annotations

import itertools
import json
from typing import Any, Callable, Iterable, Mapping

from pipflow.engine.status import RunStatus
from pipflow.values import NOT_UNDERSTOOD, REFUSED_AS_IMPOSSIBLE, ambiguous, impossible, states_goal

#: the stand-in for every value of a field that no rule names
OTHER = "(any other)"

GoalDifference = Callable[[Any, Any], "str | None"]


# ------------------------------------------------------------------------------------------
# robot rules
# ------------------------------------------------------------------------------------------
def _rule_shape_ok(rule: Any, fields: Iterable[str]) -> bool:
    if not isinstance(rule, dict) or not ({"only", "never"} & set(rule)):
        return False
    known = {"only", "never", "words", *fields}
    if set(rule) - known:
        return False
    if any(not isinstance(rule[k], list) or not all(isinstance(r, str) for r in rule[k])
           for k in ("only", "never") if k in rule):
        return False
    return all(isinstance(rule[k], str) for k in fields if k in rule)


def _rule_text(rule: Any) -> str:
    if not isinstance(rule, dict):
        return json.dumps(rule, sort_keys=True, default=str)
    r = {k: (sorted(map(str, v)) if k in ("only", "never") and isinstance(v, list) else v)
         for k, v in rule.items() if k != "words" and v is not None}
    return json.dumps(r, sort_keys=True, default=str)


def _forbids(rules: list[dict], robot: str, move: Mapping[str, str]) -> bool:
    for rule in rules:
        if any(move.get(k) != v for k, v in rule.items() if k not in ("only", "never", "words")):
            continue
        if robot in rule.get("never", ()) or ("only" in rule and robot not in rule["only"]):
            return True
    return False


def rules_difference(gold: list | None, run: list | None, robots: Iterable[str],
                     fields: Mapping[str, Iterable[str]]) -> str | None:
    """None when the two rule sets forbid exactly the same (robot, move) pairs in a world with
    ``robots`` whose moves take the values ``fields`` (``{field: names}``); otherwise the first
    cases where they disagree, in words. A rule of another shape (unknown keys, robots not a list)
    is compared as written, so it equals only an identical rule."""
    gold, run = list(gold or []), list(run or [])
    if not all(_rule_shape_ok(r, fields) for r in gold + run):
        return rules_as_written(gold, run)
    rules = gold + run
    named = {r for rule in rules for k in ("only", "never") for r in rule.get(k, ())}
    who = sorted(set(robots) | named)
    axes = []
    for field in sorted({k for rule in rules for k in rule if k in fields}):
        mentioned = {rule[field] for rule in rules if field in rule}
        values = sorted(mentioned) + ([OTHER] if set(fields[field]) - mentioned else [])
        axes.append([(field, v) for v in values])
    out = []
    for robot in who:
        for combo in itertools.product(*axes):
            move = dict(combo)
            g, r = _forbids(gold, robot, move), _forbids(run, robot, move)
            if g != r:
                scope = ", ".join(f"{k}={v}" for k, v in combo) or "every move"
                out.append(f"{robot} on {scope}: the gold {'forbids' if g else 'allows'} it, "
                           f"the run {'forbids' if r else 'allows'} it")
    if not out:
        return None
    return "rules: " + "; ".join(out[:3]) + (f" (and {len(out) - 3} more cases)" if len(out) > 3 else "")


def rules_as_written(gold: list | None, run: list | None) -> str | None:
    """None when the two rule sets are the same set of rules as written (``words`` left out,
    robot lists as sets); otherwise the rules one has and the other lacks."""
    a, b = {_rule_text(r) for r in gold or []}, {_rule_text(r) for r in run or []}
    if a == b:
        return None
    return "rules:" + (f" missing {', '.join(sorted(a - b))}" if a - b else "") \
        + (f" unexpected {', '.join(sorted(b - a))}" if b - a else "")


# ------------------------------------------------------------------------------------------
# one run's verdict
# ------------------------------------------------------------------------------------------
def judge(task: Mapping[str, Any], outputs: Mapping[str, Any], status: str, error_kind: str | None, *,
          goal_difference: GoalDifference, rule_difference: Callable[[list, list], str | None]) -> dict:
    """``{"understood", "misread", "understanding"}`` of one bench run.

    * A task marked ``feasible: false`` is understood when the run was refused as impossible (a
      ``Refusal``: the command was understood and found impossible in this world), never when the
      reader could not place its words (a ``TranslationError``: not understood, although nothing
      moves). Where the task states what the command asks (``goal``) and the run resolved a goal,
      the two must mean the same.
    * A task marked ``expect: refuse`` (ambiguous) is understood when the reader refused to guess
      (``TranslationError``, quoting the words); a run that resolved any goal read one meaning into
      it: a misreading.
    * Any other task is understood when the goal and the rules the run resolved mean what the
      gold means (``goal_difference``, ``rule_difference``: None for the same meaning).

    ``misread``: the run resolved a meaning other than the command's, whatever happened next
    (executed, failed later in planning, refused for another reason); a feasible command refused
    as impossible read an impossible meaning into it, so it is misread too. ``understood`` is None
    (not measured) only when a finished run has no ``goal`` output."""
    state = RunStatus.of(status)
    refused = state is RunStatus.REFUSED or error_kind == REFUSED_AS_IMPOSSIBLE
    unclear = error_kind == NOT_UNDERSTOOD
    has_goal = isinstance(outputs, Mapping) and outputs.get("goal") is not None
    executed = state is RunStatus.SUCCEEDED
    if executed and not has_goal:
        return {"understood": None, "misread": None,
                "understanding": "not measured: the workflow has no output `goal`"}
    gold_rules, run_rules = list(task.get("constraints") or []), list(outputs.get("constraints") or [])

    def reading() -> str | None:
        problems = [p for p in (goal_difference(task.get("goal"), outputs.get("goal")),
                                rule_difference(gold_rules, run_rules)) if p]
        return "; ".join(problems) or None

    if ambiguous(task) and impossible(task) and (unclear or refused):
        return {"understood": True, "misread": False,
                "understanding": "refused, as it should be (ambiguous, and impossible in every reading)"}
    if ambiguous(task):
        if unclear:
            return {"understood": True, "misread": False, "understanding": "refused to guess, as it should"}
        if has_goal or executed:
            return {"understood": False, "misread": True,
                    "understanding": "read one meaning into an ambiguous command"
                                     + (" and executed it" if executed else "")}
        return {"understood": False, "misread": False,
                "understanding": "refused as impossible instead of asking what was meant" if refused else "not refused"}
    if impossible(task):
        if unclear:
            return {"understood": False, "misread": False,
                    "understanding": "not understood (the reader could not place its words), so not refused as impossible"}
        wrong = reading() if has_goal and states_goal(task) else None
        if refused:
            return {"understood": wrong is None, "misread": wrong is not None,
                    "understanding": "refused as impossible, as it should be" if wrong is None
                    else f"refused, but read another impossible meaning: {wrong}"}
        if executed:
            return {"understood": False, "misread": True,
                    "understanding": "executed a command whose right answer is a refusal"}
        return {"understood": False, "misread": wrong is not None,
                "understanding": wrong or "not refused as impossible"}
    if not has_goal:
        if refused:
            return {"understood": False, "misread": True,
                    "understanding": "refused as impossible a command the world can do: read another meaning"}
        return {"understood": False, "misread": False,
                "understanding": "not understood (refused to guess)" if unclear
                else "no goal among the run's outputs (it did not finish)"}
    wrong = reading()
    return {"understood": wrong is None, "misread": wrong is not None,
            "understanding": wrong or "goal and rules mean what the gold means"}


def misread_executed(misread: bool | None, executed: int | None) -> bool | None:
    """A misreading that robots carried out: at least one action executed with it."""
    if misread is None:
        return None
    return bool(misread) and int(executed or 0) > 0


def misread_cell(counts: Mapping[str, Any]) -> str:
    """A table cell ``misread (executed)``: runs that read another meaning, and of them the runs
    robots executed, e.g. ``3 (1)``."""
    return f"{counts.get('misread', 0) or 0} ({counts.get('misread_executed', 0) or 0})"

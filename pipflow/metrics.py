"""The definitions of the run metrics every domain reports (paper, Sec. IV-B), written once.

Why one module: each domain measures travel and goal conditions its own way (metres on a shelf
floor, objects in a home), but what TC-avg or GCR *means* must be the same in every domain, every
table and every record. A domain computes the raw facts (each robot's travel; each goal condition,
true or not at the start and at the end) and asks this module for the figures.

* **TC-max**: the most metres one robot travels. **TC-avg**: the mean over the robots that
  moved (the paper's "average travel cost for robots to finish all the tasks"; an idle robot
  finishes no task, so adding idle robots to a team does not lower it). ``tc_avg_team`` is the
  other mean, over every robot of the team, idle ones included (it falls as idle robots are
  added); records written before this definition call TC-avg ``tc_avg_moved`` and the team mean
  ``tc_avg`` (:func:`upgrade_travel_keys` reads them in today's names).
* **GCR** (goal condition recall): the share of the goal's conditions that hold at the end.
  Conditions that already held at the start count only when the run achieved at least one
  condition it was asked to change: a run that changed nothing the goal asks for (refused,
  failed before executing, or busy elsewhere) recalls nothing, and gets 0, however many
  conditions were true all along. A goal with nothing to change (every condition holds at the
  start) is recalled by keeping it: the share that holds at the end.
* **Which runs the travel figures average over** (:func:`counts_for_travel`): the paper's
  "successful runs", read as the successful runs that executed their task; a right refusal
  moved nobody and is not a 0 m run.
"""
from __future__ import annotations

from typing import Any, Iterable, Mapping

#: the version of these definitions (and of the bench's understanding, :mod:`pipflow.meaning`): a
#: bench row records it in its fingerprint, so ``pipflow bench --resume`` never mixes rows scored
#: by other definitions into one table
DEFINITIONS = 2
#: a robot whose travel is at most this many metres did not move
MOVED = 1e-9


def travel_costs(travel: Mapping[str, float]) -> dict[str, float]:
    """``{tc_max, tc_avg, tc_avg_team}`` from each robot's metres (module docstring); 0.0 for a
    team that did not move."""
    metres = [float(v) for v in travel.values()]
    moved = [v for v in metres if v > MOVED]
    return {"tc_max": max(metres, default=0.0),
            "tc_avg": sum(moved) / len(moved) if moved else 0.0,
            "tc_avg_team": sum(metres) / len(metres) if metres else 0.0}


def goal_condition_recall(at_start: Iterable[bool], at_end: Iterable[bool]) -> float:
    """GCR of a goal whose conditions held (``at_start``) and hold (``at_end``), in the same
    order (module docstring). A goal with no condition is recalled: 1.0."""
    start, end = list(map(bool, at_start)), list(map(bool, at_end))
    if len(start) != len(end):
        raise ValueError(f"{len(start)} conditions at the start but {len(end)} at the end")
    if not end:
        return 1.0
    to_change = [e for s, e in zip(start, end) if not s]
    if to_change and not any(to_change):
        return 0.0
    return sum(end) / len(end)


def upgrade_travel_keys(record: Mapping[str, Any]) -> dict[str, Any]:
    """A result row, summary or outputs mapping in today's travel names: a record written before
    TC-avg had one definition carries ``tc_avg_moved`` (today's ``tc_avg``) and ``tc_avg`` (today's
    ``tc_avg_team``). Anything else comes back unchanged (a copy)."""
    out = dict(record)
    if "tc_avg_moved" in out:
        old_team = out.pop("tc_avg", None)
        out["tc_avg"] = out.pop("tc_avg_moved")
        out.setdefault("tc_avg_team", old_team)
    return out


def counts_for_travel(score: Mapping[str, Any]) -> bool:
    """Whether a scored run counts in the travel figures (TC-max, TC-avg, makespan), which are
    averaged "over successful runs": a run that succeeded by executing its task. A right refusal
    (an impossible command refused) succeeds without moving; counted as 0 m it would lower the
    travel of the tasks that were done."""
    return bool(score.get("success")) and not score.get("refused")


def upgrade_results(results: Mapping[str, Any]) -> dict[str, Any]:
    """A bench's ``results.json`` with every summary and task row in today's travel names
    (:func:`upgrade_travel_keys`)."""
    out = dict(results)
    for key in ("summary",):
        if isinstance(out.get(key), Mapping):
            out[key] = upgrade_travel_keys(out[key])
    if isinstance(out.get("tasks"), list):
        out["tasks"] = [upgrade_travel_keys(t) if isinstance(t, Mapping) else t for t in out["tasks"]]
    if isinstance(out.get("variants"), list):
        out["variants"] = [upgrade_results(v) if isinstance(v, Mapping) else v for v in out["variants"]]
    return out

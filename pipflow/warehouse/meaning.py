"""When two warehouse goals mean the same: the warehouse's half of whether a bench run understood
its command (the verdict, rules included, is the protocol's: :meth:`pipflow.taskdomain.TaskDomain.understand`).

Two goals mean the same when they accept exactly the same final stocks the world can reach
(every unit on some shelf, capacities kept): a goal that lists 0 for the shelves a gathering
empties equals one that leaves those zeros to conservation, while a count the run states that the
gold leaves open (0 of a product a shelf never had, when the product could end up there) is a
different meaning, since it turns away final stocks the gold accepts. The test is exact
(:func:`pipflow.warehouse.feasibility.final_ranges`): the two accept the same stocks exactly when, on
every cell either goal states, the fewest and the most units a cell can hold under the one equal
those under the other. Goals that no final stock meets (an infeasible task's gold and a reading
of it) are compared as written: every impossible goal accepts the same nothing, yet "50" read as
"500" is still a misreading. Rules are compared by what they forbid (:func:`pipflow.meaning.rules_difference`).
"""
from __future__ import annotations

from typing import Any

from pipflow.goalcounts import limits, value_problems
from pipflow.warehouse.feasibility import final_ranges


def _goal_limits(goal: Any) -> dict | None:
    """A goal as {place: {item: (lowest, highest)}}: an exact count n is (n, n), so a bound
    {at_least: n, at_most: n} equals n; places with no item are left out. None if malformed."""
    if not isinstance(goal, dict):
        return None
    try:
        out = {}
        for place, items in goal.items():
            if not isinstance(items, dict):
                return None
            if items:
                if any(value_problems(v) for v in items.values()):
                    return None
                out[place] = {item: limits(v) for item, v in items.items()}
        return out
    except (TypeError, ValueError, KeyError, AttributeError):
        return None


def _show(lim: tuple[int, int | None]) -> str:
    lo, hi = lim
    return str(lo) if lo == hi else (f"at least {lo}" if hi is None else f"{lo}..{hi}")


def _as_written(gold: dict, run: dict) -> str:
    out = []
    for place in sorted(set(gold) | set(run)):
        g, r = gold.get(place, {}), run.get(place, {})
        for item in sorted(set(g) | set(r)):
            if g.get(item) != r.get(item):
                out.append(f"{place} {item}: gold {_show(g[item]) if item in g else '(none)'}, "
                           f"run {_show(r[item]) if item in r else '(none)'}")
    return "; ".join(out[:4]) + (" ..." if len(out) > 4 else "")


def _in_world(world: dict, goal: dict) -> bool:
    return all(place in world["shelves"] and all(item in world["products"] for item in items)
               for place, items in goal.items())


def goal_difference(world: dict | None, gold: Any, run: Any) -> str | None:
    """None when ``gold`` and ``run`` accept the same final stocks of ``world`` (module
    docstring); otherwise what differs, in words. Without a world they are compared as written."""
    g, r = _goal_limits(gold or {}), _goal_limits(run)
    if g is None or r is None:
        return f"goal: the run's goal {run!r} is not a goal of counts" if r is None else "goal: the gold is malformed"
    if g == r:
        return None
    if world is None:
        return "goal: " + _as_written(g, r)
    if not (_in_world(world, g) and _in_world(world, r)):
        return "goal: " + _as_written(g, r) + " (a name that is not the world's)"
    cells = sorted({(s, p) for goal in (g, r) for s, items in goal.items() for p in items})
    in_gold, in_run = final_ranges(world, gold, cells), final_ranges(world, run, cells)
    if in_gold is None or in_run is None:
        if in_gold is None and in_run is None:
            return "goal: " + _as_written(g, r) + " (no final stock meets either)"
        return "goal: " + _as_written(g, r) + (" (no final stock meets the run's goal)" if in_run is None
                                               else " (no final stock meets the gold)")
    differ = [c for c in cells if in_gold[c] != in_run[c]]
    if not differ:
        return None
    text = [f"{s} {p}: the gold allows {_show(in_gold[s, p])}, the run's goal {_show(in_run[s, p])}"
            for s, p in differ]
    return "goal: " + "; ".join(text[:4]) + (" ..." if len(text) > 4 else "")

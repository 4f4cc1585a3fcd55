"""The household's RU reference: the length of an optimal team-level plan of a task's goal.

Why a planner: RU (paper, Sec. IV-B) compares a plan's actions with what the task needs. A count
of the conditions to change misses what a plan must do around them (open the fridge an egg is
taken from and close it again, carry a washed mug back to the table), so an optimal plan scored
below 1 (hc-12's five actions against a count of three). The reference is instead the length of
a plan that Fast Downward proves optimal (A* with the admissible LM-cut heuristic, unit costs, so
the fewest actions: :mod:`pipflow.pddl.optimal`) on the team-level problem of the goal. The team-level domain
names no robot, so the reference is the same for every team and every seed; it is computed once
per process and goal.

A count condition ("any 3 school supplies on the bed") has no PDDL form: the reference is the
shortest over the ways of meeting it, each written as placements of chosen members. Members that
already lie there and that no other condition names are kept there (a plan never needs to move
them: no action's precondition depends on where another object lies), and members that no other
condition names and that lie in one place are interchangeable, so only how many of each such
group are brought is enumerated.
"""
from __future__ import annotations

import hashlib
import itertools
from pipflow.household.problem import write_problem
from pipflow.pddl.common import parse
from pipflow.pddl.optimal import ALIAS, fewest_actions
from pipflow.resources import data_file

#: the planner whose plans are proved optimal (fewest actions)
PLANNER = f"Fast Downward, {ALIAS}"
#: the most ways of meeting a goal's counts that are planned for (more: no optimal reference)
MOST_CHOICES = 256
#: seconds the planner may take for one problem
TIMEOUT = 120.0

_LENGTHS: dict[str, tuple[int | None, str]] = {}


def _reach(world: dict, obj: str) -> set[str]:
    """Where an object can end: where it lies, or any receptacle or garbage can when it can be
    picked up (``store`` and ``trash`` are the only actions that move things)."""
    entity = world["objects"][obj]
    if "pickupable" not in entity["properties"]:
        return {entity["in"]}
    return {entity["in"]} | {p for p, e in world["places"].items() if {"receptacle", "garbage"} & set(e["properties"])}


def _count_options(world: dict, count: dict, pinned: dict[str, str], named: set[str]) -> list[dict[str, str]]:
    """The ways of meeting one count: each a mapping object -> the count's place (extra
    placements), up to interchangeable members."""
    place, need = count["in"], int(count["at_least"])
    members = [o for o, e in world["objects"].items() if count["category"] in e["categories"]]
    need -= sum(1 for o in members if pinned.get(o) == place)
    kept = [o for o in members if o not in pinned and o not in named and world["objects"][o]["in"] == place]
    keep = kept[:max(0, need)]
    need -= len(keep)
    base = {o: place for o in keep}
    if need <= 0:
        return [base]
    movable = [o for o in members if o not in pinned and o not in keep and place in _reach(world, o)]
    singles = [o for o in movable if o in named or world["objects"][o]["in"] == place]
    groups: dict[str, list[str]] = {}
    for o in movable:
        if o not in singles:
            groups.setdefault(world["objects"][o]["in"], []).append(o)
    units = [[o] for o in singles] + list(groups.values())
    out = []
    for takes in itertools.product(*[range(len(u) + 1) for u in units]):
        if sum(takes) == need:
            out.append({**base, **{o: place for u, k in zip(units, takes) for o in u[:k]}})
            if len(out) > MOST_CHOICES:
                break
    return out


def concrete_goals(world: dict, goal: dict) -> list[dict] | None:
    """The goal without counts, one per way of meeting them (:func:`_count_options`); None when
    there are more than :data:`MOST_CHOICES`; [] when the counts cannot be met."""
    placed = {place: list(items) for place, items in (goal.get("in") or {}).items()}
    state = {name: list(conds) for name, conds in (goal.get("state") or {}).items()}
    counts = list(goal.get("count") or [])
    pinned = {o: place for place, items in placed.items() for o in items}
    in_counts: dict[str, int] = {}
    for c in counts:
        for o, e in world["objects"].items():
            if c["category"] in e["categories"]:
                in_counts[o] = in_counts.get(o, 0) + 1
    named = set(state) | {o for o, n in in_counts.items() if n > 1}
    options = [_count_options(world, c, pinned, named) for c in counts]
    if any(len(o) > MOST_CHOICES for o in options):
        return None
    out: list[dict] = []
    for combo in itertools.product(*options):
        extra: dict[str, str] = {}
        if any(extra.setdefault(o, p) != p for choice in combo for o, p in choice.items()):
            continue  # one object in two places
        goal_in = {place: list(items) for place, items in placed.items()}
        for o, p in extra.items():
            if pinned.get(o) != p:
                goal_in.setdefault(p, []).append(o)
        out.append({"in": goal_in, "state": state})
        if len(out) > MOST_CHOICES:
            return None
    return out


def optimal_length(world: dict, goal: dict) -> tuple[int | None, str]:
    """``(actions, how)``: the fewest actions of a team-level plan reaching ``goal`` (counts
    met in the cheapest way), or ``(None, why not)`` when no plan was proved optimal (a
    time-out, a planner error, too many ways of meeting the counts, no way at all)."""
    goals = concrete_goals(world, goal)
    if goals is None:
        return None, f"more than {MOST_CHOICES} ways of meeting the goal's counts"
    if not goals:
        return None, "no way of meeting the goal's counts"
    best: int | None = None
    for concrete in goals:
        n, why = _plan_length(world, concrete)
        if n is None and why != "unsolvable":
            return None, why
        if n is not None and (best is None or n < best):
            best = n
    if best is None:
        return None, "no plan reaches the goal"
    return best, f"an optimal plan ({PLANNER})"


def _plan_length(world: dict, goal: dict) -> tuple[int | None, str]:
    text = write_problem(world, goal)
    key = hashlib.sha256(text.encode("utf-8")).hexdigest()
    if key not in _LENGTHS:
        _LENGTHS[key] = fewest_actions(parse(data_file("domains/household.pddl"), text), timeout=TIMEOUT)
    return _LENGTHS[key]


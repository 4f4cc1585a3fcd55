"""What the debugger and the verifier learn from a garden problem that parsed (a model wrote it,
or the offline writer did): its goal read back into the garden's goal form, every way its objects
and initial state differ from the world's, and why no plan could ever reach its goal here.

Why: a model's problem that invents a bed or starts with ten ripe pumpkins would be solved in a
garden that is not ours; a goal asking the shed for more pumpkins than grow is a refusal, not a
planning failure. The problem is read through unified-planning's objects (``parsed``), never as
text.
"""
from __future__ import annotations

from typing import Any

from pipflow.plugin import fluent_call, goal_atoms, number_value

from pipflow_garden.problem import initial_facts
from pipflow_garden.world import ripe_total


def goal_from_problem(parsed: Any) -> tuple[dict, list[str]]:
    """The problem's goal in the garden's form, and the conditions that form cannot hold (each a
    message for the model: a condition we cannot judge is never dropped silently)."""
    goal: dict[str, Any] = {}
    bounds: dict[tuple[str, str, str], dict[str, int]] = {}
    unread = []
    for g in goal_atoms(parsed):
        f = fluent_call(g)
        if f and f[0] in ("watered", "clear"):
            goal.setdefault(f[0], []).append(f[1][0])
            continue
        side = None
        if g.is_le() or g.is_lt() or g.is_equals():
            a, b = g.args
            fa, fb, na, nb = fluent_call(a), fluent_call(b), number_value(a), number_value(b)
            shift = 1 if g.is_lt() else 0
            if fa and fa[0] in ("stored", "ripe") and nb is not None:
                side = (fa, {"at_most": nb - shift} if not g.is_equals() else {"at_least": nb, "at_most": nb})
            elif fb and fb[0] in ("stored", "ripe") and na is not None:
                side = (fb, {"at_least": na + shift} if not g.is_equals() else {"at_least": na, "at_most": na})
        if side is None:
            unread.append(f"the goal condition {g} is not one a garden goal can state (watered, clear, "
                          f"or a count of stored or ripe units compared with a number)")
            continue
        (name, (place, crop)), bound = side
        have = bounds.setdefault((name, place, crop), {})
        if "at_least" in bound:
            have["at_least"] = max(have.get("at_least", bound["at_least"]), bound["at_least"])
        if "at_most" in bound:
            have["at_most"] = min(have.get("at_most", bound["at_most"]), bound["at_most"])
    for (name, place, crop), b in bounds.items():
        exact = "at_least" in b and b["at_least"] == b.get("at_most")
        goal.setdefault(name, {}).setdefault(place, {})[crop] = b["at_least"] if exact else b
    for key in ("watered", "clear"):
        if key in goal:
            goal[key] = sorted(set(goal[key]))
    return goal, unread


def world_mismatches(parsed: Any, world: dict) -> list[str]:
    """Objects and initial facts of the problem that are not the world's."""
    out = []
    kinds = {"bed": set(world["beds"]), "tap": set(world["taps"]), "store": set(world["stores"]),
             "crop": set(world["crops"])}
    seen: dict[str, set[str]] = {k: set() for k in kinds}
    for obj in parsed.all_objects:
        kind = obj.type.name
        if kind in kinds:
            seen[kind].add(obj.name)
            if obj.name not in kinds[kind]:
                out.append(f"object {obj.name} - {kind} is not a {kind} of this garden "
                           f"({', '.join(sorted(kinds[kind]))})")
    for kind, names in kinds.items():
        missing = sorted(names - seen[kind])
        if missing:
            out.append(f"the problem leaves out the garden's {kind} objects {', '.join(missing)}")
    expected = initial_facts(world)
    for fluent_exp, value in parsed.explicit_initial_values.items():
        f = fluent_call(fluent_exp)
        if f is None:
            continue
        v = value.bool_constant_value() if value.is_bool_constant() else number_value(value)
        want = expected.get(f, False if isinstance(v, bool) else 0)
        if v != want and all(a in set().union(*kinds.values()) for a in f[1]):
            out.append(f"initial state: ({f[0]} {' '.join(f[1])}) is {v} in the problem, {want} in the garden")
    return out


def goal_refusal(world: dict, goal: dict) -> str | None:
    """Why no plan can reach ``goal`` in this garden (more units than can be there), or None."""
    reasons = []
    for store, items in (goal.get("stored") or {}).items():
        free = world["stores"][store]["room"] if store in world["stores"] else 0
        need_total = 0
        for crop, value in items.items():
            least = value.get("at_least", 0) if isinstance(value, dict) else value
            most_there = world["stores"].get(store, {}).get("holds", {}).get(crop, 0) + ripe_total(world, crop)
            if least > most_there:
                reasons.append(f"{store} cannot hold {least} {crop}: at most {most_there} can be there")
            need_total += least
        if need_total > free:
            reasons.append(f"{store} has room for {free} units, the goal asks for {need_total}")
    for bed, items in (goal.get("ripe") or {}).items():
        for crop, value in items.items():
            least = value.get("at_least", 0) if isinstance(value, dict) else value
            have = world["beds"].get(bed, {}).get("ripe", {}).get(crop, 0)
            if least > have:
                reasons.append(f"{bed} has {have} ripe {crop}, and ripening is not an action")
    return "; ".join(reasons) or None

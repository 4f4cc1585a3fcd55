"""The garden's facts for pipflow's scoring and bench: RU's reference (the fewest actions a goal
needs), what is wrong with a task file's goal, and when two goals mean the same. The score, the
bench row, the task file's reading and the understanding verdict are pipflow's own, the same for
every domain (:class:`pipflow.plugin.TaskDomain`)."""
from __future__ import annotations

import json
from typing import Any

from pipflow.plugin import did_you_mean

GOAL_KEYS = ("watered", "clear", "stored", "ripe")


def _least(value: Any) -> int:
    return int(value.get("at_least") or 0) if isinstance(value, dict) else int(value)


def _most(value: Any) -> int | None:
    return value.get("at_most") if isinstance(value, dict) else int(value)


def reference_actions(world: dict, goal: dict) -> int:
    """A lower bound on the team actions any plan for ``goal`` needs (the RU reference): one water
    per bed to be watered, one prune per overgrown bed to be cleared or harvested from, one harvest
    per unit that must reach a store or leave a bed (per crop, the larger of the two)."""
    beds = world["beds"]
    water = sum(1 for b in set(goal.get("watered") or []) if b in beds and not beds[b]["watered"])
    into: dict[str, int] = {}
    for store, items in (goal.get("stored") or {}).items():
        for crop, value in items.items():
            held = world["stores"].get(store, {}).get("holds", {}).get(crop, 0)
            into[crop] = into.get(crop, 0) + max(0, _least(value) - held)
    out_of: dict[str, int] = {}
    picked = set()
    for bed, items in (goal.get("ripe") or {}).items():
        for crop, value in items.items():
            most, have = _most(value), beds.get(bed, {}).get("ripe", {}).get(crop, 0)
            if most is not None and have > most:
                out_of[crop] = out_of.get(crop, 0) + have - most
                picked.add(bed)
    prune = sum(1 for b in set(goal.get("clear") or []) | picked if b in beds and beds[b]["overgrown"])
    harvest = sum(max(into.get(c, 0), out_of.get(c, 0)) for c in set(into) | set(out_of))
    return water + prune + harvest


def goal_problems(goal: Any, world: dict) -> list[tuple[tuple, str, bool]]:
    """What is wrong with a task file's goal in ``world``: ``(path in the goal, message, about a key)``."""
    if not isinstance(goal, dict):
        return [((), f"goal must be a mapping of {', '.join(GOAL_KEYS)}", False)]
    out = []
    for key, value in goal.items():
        if key not in GOAL_KEYS:
            out.append(((key,), f"unknown goal key {key!r}{did_you_mean(key, GOAL_KEYS)}", True))
        elif key in ("watered", "clear"):
            out += [((key, k), f"unknown bed {b!r}{did_you_mean(b, world['beds'])}", False)
                    for k, b in enumerate(value if isinstance(value, list) else [value]) if b not in world["beds"]]
        else:
            places = world["stores"] if key == "stored" else world["beds"]
            for place, items in (value or {}).items():
                if place not in places:
                    out.append(((key, place), f"unknown {'store' if key == 'stored' else 'bed'} {place!r}"
                                              f"{did_you_mean(place, places)}", True))
                out += [((key, place, crop), f"unknown crop {crop!r}{did_you_mean(crop, world['crops'])}", True)
                        for crop in (items or {}) if crop not in world["crops"]]
    return out




def canonical_goal(goal: Any) -> str | None:
    """A garden goal as sorted JSON (bed lists as sets, empty entries dropped), None if malformed."""
    if not isinstance(goal, dict):
        return None
    out = {k: sorted(goal.get(k) or []) for k in ("watered", "clear")}
    for k in ("stored", "ripe"):
        out[k] = {p: v for p, v in (goal.get(k) or {}).items() if v}
    return json.dumps(out, sort_keys=True)

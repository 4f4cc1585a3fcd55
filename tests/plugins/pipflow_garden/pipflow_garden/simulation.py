"""A kinematic garden simulator: replays a schedule and checks it could really happen.

Why not trust the schedule: the schedule says which robots do what and where they drive; the
simulator re-checks each subtask in start order against the garden's own state (a bed must be
overgrown to be pruned, clear and ripe to be harvested, a store must have room), that the
coalition's skills cover the need, that each robot's legs join up (no jumps) and that no leg
drives through a bed, tap or store. Travel is measured from the legs' paths. The final state is
judged against the goal. No physics engine: the garden's actions have no dynamics worth it.
"""
from __future__ import annotations

import math
from typing import Any, Callable

from pipflow.plugin import goal_condition_recall, travel_costs

STEP = 0.05  # metres between the points of a path that are checked against footprints


def recall(world: dict, state: dict, goal: dict) -> float:
    """GCR in pipflow's one definition (:func:`pipflow.metrics.goal_condition_recall`)."""
    return goal_condition_recall([ok for _, ok in condition_values(initial_state(world), goal)],
                                 [ok for _, ok in condition_values(state, goal)])


def initial_state(world: dict) -> dict:
    """The garden's state as data (JSON-like), from the world file."""
    return {"watered": sorted(b for b, s in world["beds"].items() if s["watered"]),
            "overgrown": sorted(b for b, s in world["beds"].items() if s["overgrown"]),
            "ripe": {b: dict(s["ripe"]) for b, s in world["beds"].items()},
            "stored": {s: dict(spec["holds"]) for s, spec in world["stores"].items()},
            "room": {s: spec["room"] - sum(spec["holds"].values()) for s, spec in world["stores"].items()}}


def holds(value: Any, have: int) -> bool:
    """Whether count ``have`` meets a goal value: an exact count or ``{at_least, at_most}``."""
    if isinstance(value, dict):
        return (value.get("at_least") is None or have >= value["at_least"]) and \
               (value.get("at_most") is None or have <= value["at_most"])
    return have == value


def check_goal(state: dict, goal: dict) -> tuple[int, int, list[str]]:
    """(met, total, unmet descriptions) of the goal's conditions in ``state``."""
    conditions = condition_values(state, goal)
    return sum(ok for _, ok in conditions), len(conditions), [words for words, ok in conditions if not ok]


def condition_values(state: dict, goal: dict) -> list[tuple[str, bool]]:
    """Each condition of the goal in ``state``, in the goal's order: (description, holds)."""
    conditions = [(f"{b} watered", b in state["watered"]) for b in goal.get("watered", [])]
    conditions += [(f"{b} clear", b not in state["overgrown"]) for b in goal.get("clear", [])]
    for s, items in (goal.get("stored") or {}).items():
        for crop, value in items.items():
            have = state["stored"].get(s, {}).get(crop, 0)
            conditions.append((f"{s} holds {value} {crop} (has {have})", holds(value, have)))
    for b, items in (goal.get("ripe") or {}).items():
        for crop, value in items.items():
            have = state["ripe"].get(b, {}).get(crop, 0)
            conditions.append((f"{b} keeps {value} ripe {crop} (has {have})", holds(value, have)))
    return conditions


def _apply(state: dict, action: str, args: list[str]) -> list[str]:
    """Apply one team action; the reasons it cannot happen (then the state is unchanged)."""
    if action == "water":
        if args[0] not in state["watered"]:
            state["watered"] = sorted(state["watered"] + [args[0]])
        return []
    if action == "prune":
        bed = args[0]
        if bed not in state["overgrown"]:
            return [f"bed {bed} is not overgrown"]
        state["overgrown"] = [b for b in state["overgrown"] if b != bed]
        return []
    if action == "harvest":
        crop, bed, store = args
        why = [f"bed {bed} is overgrown"] if bed in state["overgrown"] else []
        if state["ripe"].get(bed, {}).get(crop, 0) < 1:
            why.append(f"no ripe {crop} left in bed {bed}")
        if state["room"].get(store, 0) < 1:
            why.append(f"store {store} is full")
        if not why:
            state["ripe"][bed][crop] -= 1
            state["stored"].setdefault(store, {})[crop] = state["stored"][store].get(crop, 0) + 1
            state["room"][store] -= 1
        return why
    return [f"the garden has no action {action!r}"]


def _through(world: dict, path: list) -> str | None:
    """The place whose footprint a path crosses (strictly inside), or None."""
    rects = [(n, p["x"], p["y"], p["x"] + p["width"], p["y"] + p["depth"]) for n, p in world["places"].items()]
    for (ax, ay), (bx, by) in zip(path, path[1:]):
        n = max(1, int(math.hypot(bx - ax, by - ay) / STEP))
        for k in range(n + 1):
            x, y = ax + (bx - ax) * k / n, ay + (by - ay) * k / n
            for name, x0, y0, x1, y1 in rects:
                if x0 + 1e-6 < x < x1 - 1e-6 and y0 + 1e-6 < y < y1 - 1e-6:
                    return name
    return None


def simulate(world: dict, schedule: dict, graph: dict | None, goal: dict | None,
             log: Callable[[str], None] = print) -> dict:
    """Replay ``schedule`` in ``world``; the outputs of step ``garden.simulate``."""
    state = initial_state(world)
    nodes = {n["id"]: n for n in (graph or {}).get("nodes", [])}
    legs_of: dict[str, dict[str, list[dict]]] = {}
    for robot, plan in (schedule.get("robots") or {}).items():
        for leg in plan.get("legs", []):
            legs_of.setdefault(leg["subtask"], {}).setdefault(robot, []).append(leg)
    pos = {r: list(spec["start"]) for r, spec in world["robots"].items()}
    travel = {r: 0.0 for r in world["robots"]}
    jumps: dict[str, list[dict]] = {}
    failures, executed = [], 0
    for sub in sorted(schedule.get("subtasks", []), key=lambda s: (s["start"], s["end"], s["id"])):
        why = []
        node = nodes.get(sub["id"], {})
        for skill, need in (node.get("skills") or {}).items():
            have = sum(world["robots"].get(r, {}).get("skills", {}).get(skill, 0) for r in sub["robots"])
            if have + 1e-9 < need:
                why.append(f"{skill} {have:g} < {need:g}")
        for robot in sub["robots"]:
            if robot not in world["robots"]:
                why.append(f"unknown robot {robot}")
                continue
            for leg in legs_of.get(sub["id"], {}).get(robot, []):
                if math.dist(pos[robot], leg["from"]) > 1e-6:
                    jumps.setdefault(robot, []).append({"subtask": sub["id"], "metres": round(math.dist(pos[robot], leg["from"]), 3)})
                path = [list(p) for p in (leg.get("path") or [leg["from"], leg["to"]])]
                crossed = _through(world, path)
                if crossed:
                    why.append(f"{robot} drives through {crossed}")
                travel[robot] += sum(math.dist(a, b) for a, b in zip(path, path[1:]))
                pos[robot] = list(leg["to"])
            route = node.get("route") or []
            if route and route[-1] in world["places"] and math.dist(pos[robot], world["places"][route[-1]]["access"]) > 1e-6:
                why.append(f"{robot} is not at {route[-1]}")
        if not why:
            why = _apply(state, sub["action"], list(sub["args"]))
        if why:
            failures.append({"subtask": sub["id"], "action": sub["action"], "reasons": why})
            log(f"{sub['id']} {sub['action']} {' '.join(sub['args'])}: refused ({'; '.join(why)})")
        else:
            executed += 1
    planned = len(schedule.get("subtasks", []))
    met, total, unmet = check_goal(state, goal or {})
    return {"final_state": state, "executed": executed, "failed": len(failures), "failures": failures,
            "exe": executed / planned if planned else 1.0, "travel": {r: round(d, 3) for r, d in travel.items()},
            **travel_costs(travel),  # pipflow's one definition of TC-max, TC-avg, the team's mean
            "goal_met": met == total and not failures, "gcr": recall(world, state, goal or {}),
            "conditions": {"met": met, "total": total, "unmet": unmet}, "jumps": jumps,
            "makespan": float(schedule.get("makespan", 0.0) or 0.0)}

"""Scoring garden runs and reading garden task files (the bench's side of the domain).

A run succeeds when every subtask executed in the simulator and the final state meets the task's
gold goal (not the run's own reading of the command: a misread command fails here), with every
robot rule of the task kept. A task whose right answer is a refusal (``feasible: false``)
succeeds exactly when the run was refused with a reason and nothing moved.
"""
from __future__ import annotations

import json
from pathlib import Path
from typing import Any

from pipflow.errors import Diagnostic, WorldError
from pipflow.meaning import judge, rules_difference
from pipflow.metrics import travel_costs
from pipflow.suggest import did_you_mean
from pipflow.worldfile import parse_mapping, read_world_file

from pipflow_garden.simulation import check_goal, initial_state, recall
from pipflow_garden.world import load_world

GOAL_KEYS = ("watered", "clear", "stored", "ripe")
TASK_KEYS = ("id", "command", "goal", "constraints", "feasible", "expect", "construction", "category", "inputs")


def broken_rules(constraints: list[dict] | None, graph: dict | None, schedule: dict | None) -> list[str]:
    """The task's only/never rules that the schedule breaks (fields matched on the graph's nodes)."""
    nodes = {n["id"]: n for n in (graph or {}).get("nodes", [])}
    out = []
    for sub in (schedule or {}).get("subtasks", []):
        node = nodes.get(sub["id"], {})
        have = {"action": sub["action"], **(node.get("fields") or {})}
        for rule in constraints or []:
            match = {k: v for k, v in rule.items() if k not in ("only", "never", "words")}
            if any(have.get(k) != v for k, v in match.items()):
                continue
            bad = [r for r in sub["robots"] if (r in rule["never"] if "never" in rule else r not in rule["only"])]
            if bad:
                out.append(f"{sub['id']} {sub['action']}: {', '.join(bad)} break rule {rule.get('words') or match}")
    return out


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


def score_run(world: dict, goal: dict, *, constraints: list[dict] | None = None, feasible: bool = True,
              graph: dict | None = None, schedule: dict | None = None, simulation: dict | None = None,
              refusal: str | None = None, error: str | None = None) -> dict:
    """The flat score of one run (the keys of pipflow's ``metrics.score``)."""
    sim = simulation or {}
    planned = len((schedule or {}).get("subtasks", []))
    executed = int(sim.get("executed", 0))
    base = {"planned": planned, "executed": executed, "refused": bool(refusal), "error": refusal or error or None,
            "makespan": float(sim.get("makespan", 0.0) or 0.0),
            "lower_bound": reference_actions(world, goal or {}) if feasible else None,
            **travel_costs(sim.get("travel") or {})}
    if not feasible:
        ok = bool(refusal and str(refusal).strip()) and planned == 0 and executed == 0
        why = [] if ok else ["infeasible command was not refused" if not refusal else "actions were planned"]
        return {**base, "success": ok, "goal_met": ok, "gcr": float(ok), "exe": 1.0 if ok else 0.0,
                "ru": 1.0 if ok else 0.0, "violations": why}
    state = sim.get("final_state") or initial_state(world)
    met, total, unmet = check_goal(state, goal or {})
    if simulation is None:
        why = "refused a feasible command" if refusal else f"run failed: {error}" if error else "no simulation"
        return {**base, "success": False, "goal_met": False, "gcr": recall(world, state, goal or {}), "exe": 0.0,
                "ru": 0.0, "violations": [why]}
    violations = [f"goal: {u}" for u in unmet]
    violations += [f"{f['subtask']} {f['action']} refused: {'; '.join(f['reasons'])}" for f in sim.get("failures") or []]
    violations += [f"{r} jumps {j['metres']:g} m" for r, js in (sim.get("jumps") or {}).items() for j in js]
    violations += broken_rules(constraints, graph, schedule)
    return {**base, "success": not violations, "goal_met": met == total, "gcr": recall(world, state, goal or {}),
            "exe": float(sim.get("exe", 0.0)), "violations": violations,
            "ru": min(1.0, base["lower_bound"] / planned) if planned else float(base["lower_bound"] == 0)}


def load_tasks(path: str | Path, default_workflow: str) -> dict:
    """A garden task file read and checked (every problem located): ``{"path", "world_path",
    "workflow", "domain", "tasks"}``. ``workflow:`` in the file is a path relative to it."""
    p, text = read_world_file(path)
    data, locate = parse_mapping(text, str(p), "garden task")
    diags: list[Diagnostic] = []
    world_path = (p.parent / str(data.get("world", ""))).resolve()
    if not data.get("world") or not world_path.is_file():
        raise WorldError([Diagnostic(locate(("world",)), f"world file {data.get('world')!r} not found "
                                                         f"(looked at {world_path})")], f"invalid task file {p}")
    world = load_world(world_path)
    workflow = str((p.parent / data["workflow"]).resolve()) if data.get("workflow") else default_workflow
    tasks, seen = [], set()
    for i, t in enumerate(data.get("tasks") or []):
        where = ("tasks", i)
        if not isinstance(t, dict):
            diags.append(Diagnostic(locate(where), "a task must be a mapping"))
            continue
        tid = str(t.get("id"))
        for k in t:
            if k not in TASK_KEYS:
                diags.append(Diagnostic(locate(where + (k,), key=True), f"task {tid}: unknown key {k!r}{did_you_mean(k, TASK_KEYS)}"))
        refuse = t.get("feasible", True) is False or t.get("expect") == "refuse"
        if t.get("expect") not in (None, "refuse"):
            diags.append(Diagnostic(locate(where + ("expect",)), f"task {tid}: expect must be 'refuse', got {t.get('expect')!r}"))
        for key in ("id", "command") + (() if refuse else ("goal",)):
            if key not in t:
                diags.append(Diagnostic(locate(where), f"task {tid}: missing {key!r}"))
        if tid in seen:
            diags.append(Diagnostic(locate(where + ("id",)), f"duplicate task id {tid!r}"))
        seen.add(tid)
        diags += _goal_problems(t.get("goal"), world, locate, where + ("goal",), tid)
        tasks.append({**t, "id": tid, "domain": "garden", "feasible": t.get("feasible", True) is not False})
    if diags:
        raise WorldError(diags, f"invalid garden task file {p}")
    return {"path": str(p), "world_path": str(world_path), "world": world, "domain": "garden",
            "workflow": workflow, "tasks": tasks}


def _goal_problems(goal: Any, world: dict, locate, where: tuple, tid: str) -> list[Diagnostic]:
    if goal is None:
        return []
    if not isinstance(goal, dict):
        return [Diagnostic(locate(where), f"task {tid}: goal must be a mapping of {', '.join(GOAL_KEYS)}")]
    out = []
    for key, value in goal.items():
        if key not in GOAL_KEYS:
            out.append(Diagnostic(locate(where + (key,), key=True),
                                  f"task {tid}: unknown goal key {key!r}{did_you_mean(key, GOAL_KEYS)}"))
        elif key in ("watered", "clear"):
            for k, b in enumerate(value if isinstance(value, list) else [value]):
                if b not in world["beds"]:
                    out.append(Diagnostic(locate(where + (key, k)), f"task {tid}: unknown bed {b!r}{did_you_mean(b, world['beds'])}"))
        else:
            places = world["stores"] if key == "stored" else world["beds"]
            for place, items in (value or {}).items():
                if place not in places:
                    out.append(Diagnostic(locate(where + (key, place), key=True),
                                          f"task {tid}: unknown {'store' if key == 'stored' else 'bed'} {place!r}"
                                          f"{did_you_mean(place, places)}"))
                for crop in (items or {}):
                    if crop not in world["crops"]:
                        out.append(Diagnostic(locate(where + (key, place, crop), key=True),
                                              f"task {tid}: unknown crop {crop!r}{did_you_mean(crop, world['crops'])}"))
    return out


def canonical_goal(goal: Any) -> str | None:
    """A garden goal as sorted JSON (bed lists as sets, empty entries dropped), None if malformed."""
    if not isinstance(goal, dict):
        return None
    out = {k: sorted(goal.get(k) or []) for k in ("watered", "clear")}
    for k in ("stored", "ripe"):
        out[k] = {p: v for p, v in (goal.get(k) or {}).items() if v}
    return json.dumps(out, sort_keys=True)


def understanding(task: dict, outputs: dict, status: str, error_kind: str | None, world: dict | None = None,
                  rule_fields: dict | None = None) -> dict:
    """Whether a run read the command as its gold (pipflow's verdict, :func:`pipflow.meaning.judge`):
    the goal compared as written (bed lists as sets), the rules by what they forbid in ``world``."""
    def goals(gold: Any, run: Any) -> str | None:
        a, b = canonical_goal(gold or {}), canonical_goal(run)
        return None if a == b else f"goal {b}; gold {a}"

    robots = list((world or {}).get("robots") or [])
    return judge(task, outputs, status, error_kind, goal_difference=goals,
                 rule_difference=lambda gold, run: rules_difference(gold, run, robots, rule_fields or {}))

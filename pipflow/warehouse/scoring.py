"""Scoring one run of a warehouse task (the aggregation into the bench table is :mod:`pipflow.experiments.benchstats`).

A run succeeds when, judged on what the *simulation* reports (never on what the plan claims):

* every goal value listed by the task holds in the final stock: an exact count exactly, a bound
  (``{at_least, at_most}``) when the final count lies within it;
* every move obeys the task's constraints (``only``/``never``, matched on the move's
  ``product``/``from``/``to`` fields, all given fields must agree);
* units are conserved (per product, the final shelves hold what the initial shelves held, and no
  unit lies off the shelves);
* no shelf ever held more than its capacity (the simulator's ``peak_load``);
* every move's coalition had the skill levels it needs (summed per skill);
* every robot's legs connect (the simulator reports ``jumps`` otherwise).

A task marked ``feasible: false`` succeeds only when it was refused with a reason and nothing was
executed.

Metrics (paper, Sec. IV-B; their definitions, shared by every domain, are :mod:`pipflow.metrics`):
GCR = fraction of goal counts met at the end, counts that already held at the start counting
only once the run achieved a count it had to change; Exe = executed / planned actions; TC-max,
TC-avg (over the robots that moved: the paper's meaning) and ``tc_avg_team`` (over every robot
of the world, which falls as idle robots are added) from the simulated travel; RU =
``lower_bound / plan_length`` (capped at 1).

RU's lower bound is :func:`pipflow.warehouse.bounds.fewest_moves`: the fewest moves of any plan once
the order of moves is dropped (an integer program, SCIP), so RU = 1 exactly when the plan has the
fewest moves possible, and below 1 by how many moves it wastes.
"""
from __future__ import annotations

from collections import Counter
from typing import Iterable

from pipflow.goalcounts import values_met
from pipflow.metrics import goal_condition_recall, travel_costs


# ------------------------------------------------------------------------------------------
# checks
# ------------------------------------------------------------------------------------------


def goal_counts(stock: dict, goal: dict) -> tuple[int, int]:
    """(met, listed) goal values: an exact count is met when the final count equals it, a bound
    ``{at_least, at_most}`` when the final count lies within it."""
    met = values_met(stock, goal)
    return sum(met), len(met)


def recall(world: dict, stock: dict, goal: dict) -> float:
    """GCR of the final ``stock`` (:func:`pipflow.metrics.goal_condition_recall`): the share of
    goal counts that hold, counts that held in the world's initial stock counting only once the
    run achieved a count it had to change."""
    return goal_condition_recall(values_met(world.get("stock", {}), goal), values_met(stock, goal))


def move_fields(graph: dict | None, schedule: dict | None) -> list[dict]:
    """Every scheduled move as ``{"id", "robots", "fields", "skills"}`` (fields and skills from
    the graph node; move-product's argument order when the graph lacks them)."""
    nodes = {n["id"]: n for n in (graph or {}).get("nodes", [])}
    moves = []
    for s in (schedule or {}).get("subtasks", []):
        node = nodes.get(s["id"], {})
        fields = dict(node.get("fields") or {})
        args = list(s.get("args") or node.get("args") or [])
        if not fields and s.get("action") == "move-product" and len(args) >= 3:
            fields = {"from": args[0], "to": args[1], "product": args[2]}
        moves.append({"id": s["id"], "robots": list(s.get("robots") or []), "fields": fields,
                      "skills": dict(node.get("skills") or {})})
    return moves


def constraint_violations(moves: Iterable[dict], constraints: list[dict] | None) -> list[str]:
    """``never``: no listed robot in a matching move; ``only``: every robot of a matching move is
    listed. A move matches when it agrees with every one of product/from/to the rule gives."""
    out = []
    for c in constraints or []:
        keys = [k for k in ("product", "from", "to") if k in c]
        for m in moves:
            if any(m["fields"].get(k) != c[k] for k in keys):
                continue
            robots = set(m["robots"])
            if "never" in c and robots & set(c["never"]):
                out.append(f"{m['id']}: {sorted(robots & set(c['never']))} used although `never` "
                           f"{_rule_text(c)}")
            if "only" in c and robots - set(c["only"]):
                out.append(f"{m['id']}: {sorted(robots - set(c['only']))} used although `only` "
                           f"{_rule_text(c)}")
    return out


def _rule_text(c: dict) -> str:
    who = c.get("only", c.get("never"))
    scope = ", ".join(f"{k}={c[k]}" for k in ("product", "from", "to") if k in c) or "every move"
    return f"{who} for {scope}"


def skill_violations(moves: Iterable[dict], world: dict) -> list[str]:
    robots = world.get("robots", {})
    out = []
    for m in moves:
        for skill, need in m["skills"].items():
            have = sum(float(robots.get(r, {}).get("skills", {}).get(skill, 0)) for r in m["robots"])
            if have + 1e-9 < float(need):
                out.append(f"{m['id']}: coalition {m['robots']} has {skill} {have:g} < {float(need):g}")
    return out


def conservation_violations(world: dict, final_stock: dict, stray_units: int = 0) -> list[str]:
    before, after = Counter(), Counter()
    for items in world.get("stock", {}).values():
        before.update({p: int(n) for p, n in items.items()})
    for items in (final_stock or {}).values():
        after.update({p: int(n) for p, n in items.items()})
    out = [f"{p}: {before[p]} units before, {after[p]} on the shelves after"
           for p in sorted(set(before) | set(after)) if before[p] != after[p]]
    if stray_units:
        out.append(f"{stray_units} units lie on no shelf at the end")
    return out


def capacity_violations(world: dict, peak_load: dict | None, final_stock: dict | None = None) -> list[str]:
    """Peak per shelf as the simulator measured it; the final stock as a fallback."""
    out = []
    peaks = dict(peak_load or {})
    for s, items in (final_stock or {}).items():
        peaks[s] = max(peaks.get(s, 0), sum(int(n) for n in items.values()))
    for s, peak in peaks.items():
        cap = world.get("shelves", {}).get(s, {}).get("capacity")
        if cap is not None and int(peak) > int(cap):
            out.append(f"{s} held {peak} units, capacity {cap}")
    return out


# ------------------------------------------------------------------------------------------
# RU lower bound
# ------------------------------------------------------------------------------------------


def plan_lower_bound(world: dict, goal: dict, time_limit: float = 10.0) -> int | None:
    """The fewest moves any plan needs (order-free IP; its proven bound if SCIP runs out of
    time); None when no final state meets the goal."""
    # deferred: pulls unified_planning and networkx (~500 ms; only the plan's lower bound needs them)
    from pipflow.warehouse.bounds import fewest_moves
    from pipflow.warehouse.planner import instance_from_world  # deferred: pulls unified_planning (as above)

    moves, _ = fewest_moves(instance_from_world(world, goal), time_limit=time_limit)
    return moves


# ------------------------------------------------------------------------------------------
# one run
# ------------------------------------------------------------------------------------------


def score_run(world: dict, goal: dict, *, constraints: list | None = None, feasible: bool = True,
              graph: dict | None = None, schedule: dict | None = None,
              simulation: dict | None = None, refusal: str | None = None, error: str | None = None,
              ) -> dict:
    """Score one run. ``refusal`` is the message of a :class:`pipflow.Refusal`, ``error`` that
    of any other failure; both mean the pipeline stopped before simulating (normally).

    Returns ``{success, goal_met, gcr, exe, ru, tc_max, tc_avg, tc_avg_team, makespan, planned, executed,
    lower_bound, violations, refused, error}``."""
    sim = simulation or {}
    travel = travel_costs(sim.get("travel") or {})
    planned = len((schedule or {}).get("subtasks", []))
    executed = int(sim.get("executed", 0))
    base = {"planned": planned, "executed": executed, "refused": bool(refusal),
            "error": refusal or error or None, "makespan": float(sim.get("makespan", (schedule or {}).get("makespan", 0.0)) or 0.0)}

    if not feasible:
        ok = bool(refusal and str(refusal).strip()) and executed == 0 and planned == 0
        violations = [] if ok else (
            ["infeasible command was not refused"] if not refusal else
            ["refusal has no reason"] if not str(refusal).strip() else ["actions were executed"])
        return {**base, "success": ok, "goal_met": ok, "gcr": 1.0 if ok else 0.0,
                "exe": 1.0 if ok else (sim.get("exe", 0.0) or 0.0), "ru": 1.0 if ok else 0.0,
                **travel, "lower_bound": None, "violations": violations}

    if simulation is None:  # refused or failed before execution: nothing changed, nothing recalled
        why = "refused a feasible command" if refusal else f"run failed: {error}" if error else "no simulation"
        return {**base, "success": False, "goal_met": False, "gcr": recall(world, world.get("stock", {}), goal),
                "exe": 0.0, "ru": 0.0, **travel_costs({}), "lower_bound": None, "violations": [why]}

    final = sim.get("final_stock", {})
    met, listed = goal_counts(final, goal)
    moves = move_fields(graph, schedule)
    violations = []
    if met != listed:
        violations.append(f"goal: {listed - met} of {listed} counts do not hold")
    violations += constraint_violations(moves, constraints)
    violations += conservation_violations(world, final, int(sim.get("stray_units", 0)))
    violations += capacity_violations(world, sim.get("peak_load"), final)
    violations += skill_violations(moves, world)
    for robot, jumps in (sim.get("jumps") or {}).items():
        violations += [f"{robot} jumps {j['metres']:g} m at t={j['time']:g} (legs do not connect)" for j in jumps]
    lb = plan_lower_bound(world, goal)
    if planned == 0:
        ru = 1.0 if lb == 0 else 0.0
    else:
        ru = min(1.0, (lb or 0) / planned)
    return {**base, "success": not violations, "goal_met": met == listed,
            "gcr": recall(world, final, goal),
            "exe": float(sim.get("exe", executed / planned if planned else 1.0)), "ru": ru,
            **travel, "lower_bound": lb, "violations": violations}

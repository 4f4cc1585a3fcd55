"""The warehouse's facts for scoring a run: the goal's counts in a stock, the checks only a
warehouse has, and RU's reference. The score itself is the protocol's, the same for every domain
(:func:`pipflow.scoring.score_run`; the bench's aggregation is :mod:`pipflow.experiments.benchstats`).

A warehouse run succeeds when, judged on what the *simulation* reports (never on what the plan
claims), besides what every domain asks (every goal condition holds, no subtask refused, no robot
jumps, the task's rules kept):

* every goal value listed by the task holds in the final stock: an exact count exactly, a bound
  (``{at_least, at_most}``) when the final count lies within it (:func:`goal_conditions`);
* every move obeys the task's constraints (``only``/``never``, matched on the move's
  ``product``/``from``/``to`` fields, all given fields must agree: :func:`constraint_violations`);
* units are conserved (per product, the final shelves hold what the initial shelves held, and no
  unit lies off the shelves);
* no shelf ever held more than its capacity (the simulator's ``peak_load``);
* every move's coalition had the skill levels it needs (summed per skill).

RU's lower bound is :func:`pipflow.warehouse.bounds.fewest_moves`: the fewest moves of any plan once
the order of moves is dropped (an integer program, SCIP), so RU = 1 exactly when the plan has the
fewest moves possible, and below 1 by how many moves it wastes.
"""
from __future__ import annotations

from collections import Counter
from typing import Iterable

from pipflow.goalcounts import describe, holds
from pipflow.taskdomain import Condition


# ------------------------------------------------------------------------------------------
# checks
# ------------------------------------------------------------------------------------------


def goal_conditions(stock: dict | None, goal: dict | None) -> list[Condition]:
    """Each value of ``goal`` in ``stock`` (``{shelf: {product: count}}``, a missing count is 0),
    in the goal's order: an exact count holds when the count equals it, a bound
    ``{at_least, at_most}`` when the count lies within it."""
    out = []
    for shelf, items in (goal or {}).items():
        for product, value in items.items():
            have = int((stock or {}).get(shelf, {}).get(product, 0))
            out.append(Condition(f"{shelf} holds {describe(value)} {product} (it holds {have})", holds(have, value)))
    return out


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

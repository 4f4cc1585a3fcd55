"""How few moves a transport problem can take: a cheap bound and an exact order-free count.

Used by ``benchmarks/team_plans.py`` and the tests to judge plan quality.

* :func:`ceil_bound`: per product, every cell below (above) its goal range needs at least
  ceil(units / largest magnitude) moves in (out); units that must come from (or go to) other
  cells need ceil(rest / largest) more (:func:`pipflow.pddl.transport.lower_bound`). Instant,
  but blind to capacity: a full shelf that must first send units away costs moves this bound
  does not see.
* :func:`fewest_moves`: an integer program (SCIP via pyscipopt) over moves per (from, to,
  product) with the final state free where the goal leaves it free and within capacity. It drops
  only the order of moves (intermediate capacity), so it is a lower bound on every plan and equal
  to the fewest moves whenever some plan reaches it; a plan of that length is proven optimal.
* :func:`exact_moves`: the fewest moves *with* capacity at every step: an A* over stock states
  with an admissible bound, run to the end (``budget`` and ``time_limit`` only guard against a
  runaway). For small instances only; it is the reference the capacity-tight benchmark suite
  measures plans against (and the tests check it against a plain breadth-first search).
"""
from __future__ import annotations

import time
from math import ceil

from pipflow.pddl.transport import Instance, MoveLimit, largest_move, lower_bound, search_moves


def ceil_bound(inst: Instance) -> int:
    """A cheap lower bound on the number of moves (see module docstring)."""
    return lower_bound(inst)


def fewest_moves(inst: Instance, time_limit: float = 60.0) -> tuple[int | None, bool]:
    """``(moves, proven)``: the order-free minimum number of moves from SCIP, and whether SCIP
    proved it optimal within ``time_limit`` (otherwise its best bound, rounded up, and False).
    ``(None, True)`` when no final state exists."""
    from pyscipopt import Model, quicksum

    big = largest_move(inst)  # no move carries more than the warehouse's free room
    small = min(inst.magnitudes.values())
    m = Model("fewest-moves")
    m.hideOutput()
    m.setParam("limits/time", time_limit)
    S, P = inst.shelves, inst.products
    y, n = {}, {}
    for s in S:
        for t in S:
            if s == t:
                continue
            for p in P:
                hi = inst.total(p)
                if hi == 0:
                    continue
                y[s, t, p] = m.addVar(vtype="I", lb=0, ub=hi)
                n[s, t, p] = m.addVar(vtype="I", lb=0, ub=hi)
                m.addCons(y[s, t, p] <= big * n[s, t, p])
                m.addCons(y[s, t, p] >= small * n[s, t, p])
    for s in S:
        final = {}
        for p in P:
            inflow = quicksum(y[t, s, p] for t in S if (t, s, p) in y)
            outflow = quicksum(y[s, t, p] for t in S if (s, t, p) in y)
            final[p] = inst.stock[s, p] + inflow - outflow
            m.addCons(final[p] >= 0)
            m.addCons(outflow <= inst.stock[s, p] + inflow)
            lo, hi = inst.goal.get((s, p), (0, None))
            if lo:
                m.addCons(final[p] >= lo)
            if hi is not None:
                m.addCons(final[p] <= hi)
        m.addCons(quicksum(final.values()) <= inst.capacity[s])
    m.setObjective(quicksum(n.values()), "minimize")
    m.optimize()
    status = m.getStatus()
    if status == "infeasible":
        return None, True
    if status == "optimal":
        return int(round(m.getObjVal())), True
    return int(ceil(m.getDualbound() - 1e-6)), False


def exact_moves(inst: Instance, limit: MoveLimit | None = None, budget: int = 10**9,
                time_limit: float = 120.0) -> tuple[int | None, bool]:
    """``(moves, proven)``: the fewest moves of any plan that respects capacity at every step.
    ``(None, True)``: no plan exists; ``proven`` False: the search ran out of ``budget`` or time
    (then ``moves`` is a lower bound)."""
    found = search_moves(inst, limit, None, budget, time.monotonic() + time_limit)
    if found.moves is not None:
        return len(found.moves), True
    return (None, True) if found.complete else (found.lower_bound, False)

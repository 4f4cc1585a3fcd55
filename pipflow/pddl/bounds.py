"""How few moves a transport problem can take: a cheap bound and an exact order-free count.

Used by ``benchmarks/team_plans.py`` and the tests to judge plan quality.

* :func:`ceil_bound`: per product, every cell the goal must fill (or empty) needs at least
  ceil(units / largest magnitude) moves of its own; units that must come from (or go to) free
  cells need ceil(rest / largest) more. Instant, but blind to capacity: a full shelf that must
  first send units away costs moves this bound does not see.
* :func:`fewest_moves`: an integer program (SCIP via pyscipopt) over moves per (from, to,
  product) with the final state free where the goal leaves it free and within capacity. It drops
  only the order of moves (intermediate capacity), so it is a lower bound on every plan and equal
  to the fewest moves whenever some plan reaches it; a plan of that length is proven optimal.
"""
from __future__ import annotations

from math import ceil

from pipflow.pddl.transport import Instance


def ceil_bound(inst: Instance) -> int:
    """A cheap lower bound on the number of moves (see module docstring)."""
    big = max(inst.magnitudes.values())
    total = 0
    for p in inst.products:
        fill = [inst.goal[s, p] - inst.stock[s, p] for s in inst.shelves
                if (s, p) in inst.goal and inst.goal[s, p] > inst.stock[s, p]]
        empty = [inst.stock[s, p] - inst.goal[s, p] for s in inst.shelves
                 if (s, p) in inst.goal and inst.goal[s, p] < inst.stock[s, p]]
        rest = sum(fill) - sum(empty)
        into = sum(ceil(d / big) for d in fill) + (ceil(-rest / big) if rest < 0 else 0)
        out = sum(ceil(d / big) for d in empty) + (ceil(rest / big) if rest > 0 else 0)
        total += max(into, out)
    return total


def fewest_moves(inst: Instance, time_limit: float = 60.0) -> tuple[int | None, bool]:
    """``(moves, proven)``: the order-free minimum number of moves from SCIP, and whether SCIP
    proved it optimal within ``time_limit`` (otherwise its best bound, rounded up, and False).
    ``(None, True)`` when no final state exists."""
    from pyscipopt import Model, quicksum

    big = max(inst.magnitudes.values())
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
            if (s, p) in inst.goal:
                m.addCons(final[p] == inst.goal[s, p])
        m.addCons(quicksum(final.values()) <= inst.capacity[s])
    m.setObjective(quicksum(n.values()), "minimize")
    m.optimize()
    status = m.getStatus()
    if status == "infeasible":
        return None, True
    if status == "optimal":
        return int(round(m.getObjVal())), True
    return int(ceil(m.getDualbound() - 1e-6)), False

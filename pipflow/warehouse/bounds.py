"""How few moves a transport problem can take: a cheap bound and an exact order-free count.

Used by ``benchmarks/team_plans.py`` and the tests to judge plan quality.

* :func:`ceil_bound`: per product, every cell below (above) its goal range needs at least
  ceil(units / largest magnitude) moves in (out); units that must come from (or go to) other
  cells need ceil(rest / largest) more (:func:`pipflow.warehouse.planner.lower_bound`). Instant,
  but blind to capacity: a full shelf that must first send units away costs moves this bound
  does not see.
* :func:`fewest_moves` (defined beside the planner, which uses it): an integer program (SCIP via pyscipopt) over moves per (from, to,
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

from pipflow.warehouse.planner import Instance, MoveLimit, fewest_moves, lower_bound, search_moves

__all__ = ["ceil_bound", "exact_moves", "fewest_moves"]


def ceil_bound(inst: Instance) -> int:
    """A cheap lower bound on the number of moves (see module docstring)."""
    return lower_bound(inst)


def exact_moves(inst: Instance, limit: MoveLimit | None = None, budget: int = 10**9,
                time_limit: float = 120.0) -> tuple[int | None, bool]:
    """``(moves, proven)``: the fewest moves of any plan that respects capacity at every step.
    ``(None, True)``: no plan exists; ``proven`` False: the search ran out of ``budget`` or time
    (then ``moves`` is a lower bound)."""
    found = search_moves(inst, limit, None, budget, time.monotonic() + time_limit)
    if found.moves is not None:
        return len(found.moves), True
    return (None, True) if found.complete else (found.lower_bound, False)

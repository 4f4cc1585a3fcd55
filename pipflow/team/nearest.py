"""Costs of only the robots that can matter: an exact prefilter for the per-subtask IP.

Why: the paper's IP (eq. 3) takes every robot's cost c_i, and c_i is an obstacle-free shortest
path (:mod:`pipflow.team.travel`). With 5,000 robots and 64 subtasks that is 320,000 path
queries, 40 s, for coalitions of two or three robots that stand near the subtask.

The argument (exact: the same optimum, the same coalition). Let ``lb_i <= c_i`` be a lower bound
of every robot's cost: the straight line is never longer than a path around obstacles, so
``lb_i = driven_i + |p_i - first place| + route`` (``total`` cost) or without ``driven_i``
(``subtask`` cost). Evaluate the exact c_i for the robots in increasing order of ``lb_i``; let E
be the evaluated ones and ``t_E`` the first stage's threshold computed on E alone (the smallest
t at which E's robots with c_i <= t admit a feasible coalition; feasibility only grows with t).
If every robot outside E has ``lb_i > t_E`` (with the IP's own tolerance as margin), then:

1. for every ``t <= t_E`` the robots with ``c_i <= t`` are the same in E as in all robots (a robot
   outside has ``c_i >= lb_i > t_E``), so the first stage over all robots, the smallest feasible
   t, is ``t_E`` as well;
2. the second stage's eligible set ``{i : c_i <= t*}`` is then the same set, so it solves the same
   IP over the same robots and returns the same coalition, ties included.

So a robot farther (in its lower bound) than the threshold of the nearest capable coalitions is
never in the optimal solution, and the IP never needs its exact cost. E grows by doubling
(4, 8, 16, ... robots), so a subtask evaluates at most about twice the robots it needs, and a
round costs a sort of the bounds (n log n) and one first stage. (Why 4: a coalition is a few
robots; at 10,000 robots a first round of 4 asks a quarter of the paths 16 does, and the
allocation's time halves.)

Robots outside E get the cost ``inf`` in the vector handed to the IP: they sort last and are
never eligible. ``method="naive"`` (the textbook model over every robot) never prefilters: it is
the reference the tests compare against.
"""
from __future__ import annotations

from typing import Callable

import numpy as np

#: robots whose exact cost the first round evaluates (then twice as many per round)
FIRST_ROUND = 4
#: a lower bound must exceed the threshold by this much before a robot is left out: the IP's
#: eligibility tolerance (1e-9) plus float rounding of path sums
MARGIN = 1e-6


def straight_bounds(xy: np.ndarray, target: tuple[float, float], base: np.ndarray) -> np.ndarray:
    """``base + |xy - target|`` per robot, shrunk by a relative 1e-9 so that rounding in a path's
    sum of segments can never put the exact cost below it."""
    d = np.hypot(xy[:, 0] - target[0], xy[:, 1] - target[1])
    return (base + d) * (1.0 - 1e-9)


def nearest_costs(bounds: np.ndarray, allowed: np.ndarray, exact: Callable[[int], float],
                  threshold: Callable[[np.ndarray], float | None]) -> np.ndarray:
    """The cost vector for the IP: exact where a robot may be in the optimum, ``inf`` elsewhere.

    ``bounds``: lower bounds of the costs; ``allowed``: robots the rules allow; ``exact(i)``:
    robot i's cost; ``threshold(c)``: the first stage's threshold for costs ``c`` (None: no
    feasible coalition). See the module docstring for why the result gives the same optimum."""
    n = len(bounds)
    c = np.full(n, np.inf)
    order = np.flatnonzero(allowed)
    order = order[np.argsort(bounds[order], kind="stable")]
    done = 0
    size = FIRST_ROUND
    while True:
        upto = min(len(order), size)
        for i in order[done:upto]:
            c[i] = exact(int(i))
        done = upto
        if done >= len(order):
            return c  # every allowed robot evaluated: nothing was left out
        t = threshold(c)
        if t is not None and np.isfinite(t) and bounds[order[done]] > t + MARGIN:
            return c
        size *= 2

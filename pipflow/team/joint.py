"""The joint allocation-and-sequencing problem of a dependency graph, as data, and what a schedule
of it scores.

Alg. 1 decides the robots of each subtask one at a time, in frontier order; the schedule then
follows from :class:`~pipflow.team.scheduling.Timeline`. The *joint* problem decides everything at
once: which coalition does each subtask and in which order the subtasks are committed (a robot
serves its subtasks in commit order), minimising (makespan, TC-max, TC-sum) lexicographically.
Two modules work on it: :mod:`pipflow.team.exact` (a MILP that SCIP solves to proven optimality
on small instances) and :mod:`pipflow.team.improve` (local search after the paper's walk). Both
read the instance from one :class:`JointProblem`, so both see the same skills, rules, travel
and timing as the allocator and the ``schedule`` step.

A solution is a *plan*: a commit order (a topological order of the graph) and a coalition per
subtask. :meth:`JointProblem.evaluate` times a plan with the Timeline's arithmetic but without
recording legs and paths (thousands of plans are evaluated in a search);
:func:`replay` times it with the Timeline itself, which is what ``schedule`` reports.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Sequence

import numpy as np

from pipflow.errors import InputError
from pipflow.team.allocation import Linear, Rules, covers, need_vector, skill_matrix
from pipflow.team.scheduling import Timeline, build_schedule, predecessors

#: the objective, in priority order: seconds, metres, metres
OBJECTIVE = ("makespan", "tc_max", "tc_sum")
#: relative tolerance of "equal" in the lexicographic comparison (floating sums in another order)
REL_TOL = 1e-9


def lex_less(a: Sequence[float], b: Sequence[float], rel: float = REL_TOL) -> bool:
    """Is objective ``a`` strictly better than ``b`` (lexicographically, within ``rel``)?"""
    for x, y in zip(a, b):
        tol = rel * max(1.0, abs(x), abs(y))
        if x < y - tol:
            return True
        if x > y + tol:
            return False
    return False


def schedule_key(schedule: dict) -> tuple[float, float, float]:
    """(makespan, TC-max, TC-sum) of a schedule (the ``schedule`` step's contract)."""
    dists = [r["distance"] for r in schedule["robots"].values()]
    return (float(schedule["makespan"]), float(max(dists, default=0.0)), float(sum(dists)))


@dataclass
class Plan:
    """A commit order and each subtask's coalition (robot indices, sorted)."""

    order: list[str]
    coalitions: dict[str, tuple[int, ...]]


@dataclass
class Outcome:
    """What :meth:`JointProblem.evaluate` finds for a plan."""

    key: tuple[float, float, float]
    start: dict[str, float]
    end: dict[str, float]
    #: why each subtask could not start earlier: None (its predecessors or time zero) or the index
    #: of the robot that arrived last
    late_robot: dict[str, int | None]
    distance: np.ndarray  # metres per robot


class JointProblem:
    """One instance: the graph's subtasks and order constraints, the team's skills, the user's
    robot rules, the travel map, speed and handling time."""

    def __init__(self, graph: dict, world: dict, constraints: list | None = None, linear: list | None = None,
                 *, travel: Any = None, speed: float = 1.0, handling: float = 2.0):
        self.graph = graph
        self.world = world
        self.timeline = Timeline(world, travel=travel, speed=speed, handling=handling)
        self.travel = self.timeline.travel
        self.speed, self.handling = self.timeline.speed, self.timeline.handling
        self.nodes = {n["id"]: n for n in graph["nodes"]}
        self.preds = predecessors(graph)
        self.succs: dict[str, list[str]] = {s: [] for s in self.nodes}
        for v, ps in self.preds.items():
            for p in ps:
                self.succs[p].append(v)
        self.ids = sorted(self.nodes, key=lambda s: self.nodes[s].get("index", 0))
        self.robots, self.skills, self.Q = skill_matrix(world, graph["nodes"])
        self.rules = Rules(self.robots, self.skills, self.Q, constraints, linear, graph["nodes"])
        self.need: dict[str, np.ndarray] = {}
        self.allowed: dict[str, np.ndarray] = {}
        self.lin: dict[str, list[Linear]] = {}
        self.first: dict[str, str] = {}
        self.last: dict[str, str] = {}
        self.route_len: dict[str, float] = {}
        self.duration: dict[str, float] = {}
        for sid, node in self.nodes.items():
            route = self.timeline.check_route(node)
            self.need[sid] = need_vector(node, self.skills)
            self.allowed[sid] = self.rules.mask(node)[0]
            self.lin[sid] = self.rules.lin(node)
            self.first[sid], self.last[sid] = route[0], route[-1]
            self.route_len[sid] = self.timeline.route_length(node)
            self.duration[sid] = self.timeline.duration(node)
        self._dist: dict[tuple[str, str], float] = {}
        self._feasible: dict[tuple[str, tuple[int, ...]], bool] = {}

    # ------------------------------------------------------------------ pieces
    def dist(self, a: str, b: str) -> float:
        """Metres from place (or robot start) ``a`` to place ``b`` (cached: the search asks often)."""
        d = self._dist.get((a, b))
        if d is None:
            d = self._dist[(a, b)] = self.travel.distance(a, b)
        return d

    def feasible(self, sid: str, coalition: Sequence[int]) -> bool:
        """Do these robots cover the subtask's skills, and do the user's rules allow them?
        (Remembered: a search asks about the same coalitions again and again.)"""
        key = (sid, tuple(sorted(coalition)))
        ok = self._feasible.get(key)
        if ok is None:
            ok = bool(coalition) and all(self.allowed[sid][i] for i in coalition)
            if ok:
                x = np.zeros(len(self.robots))
                x[list(coalition)] = 1.0
                ok = covers(self.Q, self.need[sid], x) and all(L.holds(x) for L in self.lin[sid])
            self._feasible[key] = ok
        return ok

    def topological(self, order: Sequence[str]) -> bool:
        """Is ``order`` every subtask once, each after its predecessors?"""
        if sorted(order) != sorted(self.nodes):
            return False
        pos = {s: k for k, s in enumerate(order)}
        return all(pos[p] < pos[s] for s in order for p in self.preds[s])

    def check(self, plan: Plan) -> None:
        """Raise InputError unless ``plan`` is a valid plan (order, skills, rules)."""
        if not self.topological(plan.order):
            raise InputError("plan order is not a topological order of every subtask")
        bad = [s for s in plan.order if not self.feasible(s, plan.coalitions[s])]
        if bad:
            raise InputError(f"plan coalitions of {bad} do not cover their skills or break a robot rule")

    # ------------------------------------------------------------------ timing
    def evaluate(self, plan: Plan) -> Outcome:
        """Time ``plan`` as :class:`Timeline` does (start = max(predecessors' ends, the coalition's
        arrivals); a robot drives approach and route and ends at the route's last place)."""
        n = len(self.robots)
        pos: list[str] = list(self.robots)
        free = [0.0] * n
        distance = np.zeros(n)
        start: dict[str, float] = {}
        end: dict[str, float] = {}
        late: dict[str, int | None] = {}
        speed = self.speed
        for sid in plan.order:
            t = max((end[p] for p in self.preds[sid]), default=0.0)
            who = None
            f = self.first[sid]
            for i in plan.coalitions[sid]:
                d = self.dist(pos[i], f)
                a = free[i] + d / speed
                if a > t:
                    t, who = a, i
                distance[i] += d
            start[sid], late[sid] = t, who
            e = t + self.duration[sid]
            end[sid] = e
            last, length = self.last[sid], self.route_len[sid]
            for i in plan.coalitions[sid]:
                pos[i], free[i] = last, e
                distance[i] += length
        key = (max(end.values(), default=0.0), float(distance.max(initial=0.0)), float(distance.sum()))
        return Outcome(key, start, end, late, distance)

    # ------------------------------------------------------------------ the allocation contract
    def plan_of(self, allocation: dict) -> Plan:
        """The plan an allocation (the ``allocate.*`` contract) stands for."""
        index = {r: i for i, r in enumerate(self.robots)}
        order, coalitions = [], {}
        for a in allocation.get("assignments", []):
            sid = a["subtask"]
            order.append(sid)
            coalitions[sid] = tuple(sorted(index[r] for r in a["robots"]))
        return Plan(order, coalitions)

    def assignments(self, plan: Plan, cost: str | None = None) -> list[dict]:
        """The plan as the contract's assignments, with each robot's cost c_i as a Timeline of the
        same cost definition prices it at commit time (``cost``: an allocation's ``cost`` entry,
        when it records one; None: the Timeline's default)."""
        kind = {"cost": cost} if cost is not None else {}
        tl = Timeline(self.world, travel=self.travel, speed=self.speed, handling=self.handling, **kind)
        out = []
        for sid in plan.order:
            node = self.nodes[sid]
            names = [self.robots[i] for i in plan.coalitions[sid]]
            out.append({"subtask": sid, "robots": names, "costs": {r: float(tl.cost(r, node)) for r in names}})
            tl.commit(node, names, self.preds[sid])
        return out


def replay(problem: JointProblem, plan: Plan) -> dict:
    """The schedule ``schedule`` makes of ``plan`` (the Timeline itself, legs and paths included)."""
    allocation = {"assignments": [{"subtask": s, "robots": [problem.robots[i] for i in plan.coalitions[s]]}
                                  for s in plan.order]}
    return build_schedule(problem.graph, allocation, problem.world, speed=problem.speed,
                          handling=problem.handling, travel=problem.travel)

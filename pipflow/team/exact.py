"""The joint allocation-and-sequencing problem solved to proven optimality with SCIP (small
instances: it measures how far Alg. 1 and the improvement phase are from the best schedule).

The MILP models exactly what :class:`~pipflow.team.scheduling.Timeline` does with a plan:

* ``y[i, a, b]`` = 1 when robot i goes from ``a`` (its start, or subtask a's last place) straight
  to subtask b's first place; ``x[i, b] = sum_a y[i, a, b]`` says robot i is in b's coalition.
  Each robot leaves its start at most once and leaves a subtask at most once, and only if it did
  it (a path per robot). Only robots the user's rules allow get variables, and a robot never goes
  from a subtask to one of its ancestors in the graph.
* skills: ``sum_i Q[i, u] x[i, b] >= Y[b, u]``; the user's linear rules on ``x[., b]``; at least
  one robot per subtask (a Timeline commits none without).
* time: ``S_b >= E_p`` for a predecessor p; ``S_b >= dist(start_i, first_b) / speed`` when robot
  i comes from its start; ``S_b >= E_a + dist(last_a, first_b) / speed`` when it comes from a
  (big-M off, one M per arc from the graph's bounds); ``E_b = S_b + duration_b`` (handling at
  every stop plus driving the route).
* with a zero-length subtask, ranks ``u`` (``u_b >= u_a + 1`` along edges and used arcs) forbid a
  cycle of arcs that would have no commit order; with positive lengths the times forbid it.
* a robot's metres: the sum over its arcs of ``dist(from, first_b) + route_b``.

Three solves, each fixing the optimum of the one before (lexicographic): makespan ``C``; TC-max
``W >= metres_i``; TC-sum. Each later stage is a fresh model built with the makespan bound just
proven, so its big-Ms are tight and arcs that cannot meet it are left out. A schedule with later
starts than the Timeline's cannot end sooner (each time is the latest of what it waits for), so
the optimal values are the Timeline's: the plan read back from ``y`` (commit order: a topological
order of the graph and the robots' sequences, by start time) is what the result holds, with its
objective as the Timeline computes it.

What makes 8 subtasks and 6 robots provable in seconds to minutes (:mod:`pipflow.team.bounds`):
``C >= E_b + tail_b`` (the longest chain of successors); per robot, ``C >=`` its driving and
handling (it does its subtasks one after another); per robot and subtask, ``S_b >=`` the earliest
its one arc into b allows (no big-M); for two subtasks no two disjoint coalitions can serve (some
robot does both), an order binary with the drive between them; and the makespan's lower bound
from the best order of each group of such subtasks. Without the last two, a 7-subtask instance
took 80 s to prove; with them, 2 s.
"""
from __future__ import annotations

import itertools
import math
import time
from dataclasses import dataclass, field

from pipflow.errors import InputError
from pipflow.team.allocation import IPStatus
from pipflow.team.bounds import ancestors, apart_pairs, chain_bound, heads_tails
from pipflow.team.joint import JointProblem, Plan, lex_less, replay, schedule_key

START = "@start"  # the arc tail that stands for a robot's start
#: a proven optimum is fixed this far above itself for the next stage (SCIP's tolerances)
SLACK_REL, SLACK_ABS = 1e-7, 1e-6


@dataclass
class ExactResult:
    """The proven optimum (``proven``) or the best plan SCIP found within its time limit."""

    plan: Plan
    key: tuple[float, float, float]  # (makespan, TC-max, TC-sum) of the plan, the Timeline's arithmetic
    proven: bool
    stages: list[dict] = field(default_factory=list)  # SCIP's outcome and time of each of the three solves
    time_s: float = 0.0


def solve_exact(p: JointProblem, hint: Plan | None = None, time_limit: float = 300.0) -> ExactResult:
    """Minimise (makespan, TC-max, TC-sum) over every plan. ``hint``: a known plan (e.g. Alg. 1's),
    given to SCIP as a first solution and used as the first makespan bound; ``time_limit``:
    seconds for the three solves together. ``proven``: SCIP proved every stage optimal."""
    t0 = time.perf_counter()
    if not p.nodes:
        return ExactResult(Plan([], {}), (0.0, 0.0, 0.0), True)
    deadline = t0 + time_limit
    best = hint
    if best is not None:
        p.check(best)
        ub = p.evaluate(best).key[0] * (1 + SLACK_REL) + SLACK_ABS
    else:
        ub = _upper_bound(p)
    stages: list[dict] = []
    w_ub = None
    for stage in ("makespan", "tc_max", "tc_sum"):
        model = _Model(p, ub, w_ub)
        if best is not None:
            model.hint(best)
        status, value, plan, took = model.solve(stage, max(0.5, deadline - time.perf_counter()))
        stages.append({"objective": stage, "status": str(status), "value": value, "time_s": took})
        if plan is None:
            if best is None:
                raise InputError(f"the joint problem has no solution ({stage}: SCIP says {status}): "
                                 "some subtask has no coalition the rules allow, or time ran out")
            plan = best  # a later stage found nothing in time: keep the previous stage's plan
        best = plan
        key = p.evaluate(best).key
        if stage == "makespan":
            ub = key[0] * (1 + SLACK_REL) + SLACK_ABS
        elif stage == "tc_max":
            w_ub = key[1] * (1 + SLACK_REL) + SLACK_ABS
    proven = all(s["status"] == str(IPStatus.OPTIMAL) for s in stages)
    return ExactResult(best, p.evaluate(best).key, proven, stages, time.perf_counter() - t0)


class _Model:
    """The MILP of the module docstring for one makespan bound ``ub`` (and TC-max bound ``w_ub``)."""

    def __init__(self, p: JointProblem, ub: float, w_ub: float | None):
        from pyscipopt import Model, quicksum  # deferred: SCIP loads only when a model is built

        self.p, self.ub, self.sum = p, ub, quicksum
        self.head, self.tail = heads_tails(p)
        self.anc = ancestors(p)
        self.latest = {b: ub - self.tail[b] - p.duration[b] for b in p.ids}  # latest start within the bound
        self.m = Model()
        self.m.hideOutput()
        self._arcs()
        self._coverage()
        apart = apart_pairs(p)
        self._times(apart)
        self._apart(apart)
        self._robots_busy()
        self._no_subtours()
        self._travel(w_ub)

    def _arcs(self) -> None:
        """y[i, a, b]: robot i serves b right after a (``START``: first); only arcs that can keep
        the makespan bound exist. ``drive``: metres from the arc's tail to b's first place."""
        p, head, latest = self.p, self.head, self.latest
        drive: dict[tuple[int, str, str], float] = {}
        for i in range(len(p.robots)):
            for b in p.ids:
                if not p.allowed[b][i]:
                    continue
                d = p.dist(p.robots[i], p.first[b])
                if d / p.speed <= latest[b] + SLACK_ABS:
                    drive[(i, START, b)] = d
                for a in p.ids:
                    if a == b or not p.allowed[a][i] or b in self.anc[a]:
                        continue  # robot i cannot serve a before b when b must end before a starts
                    d = p.dist(p.last[a], p.first[b])
                    if head[a] + p.duration[a] + d / p.speed <= latest[b] + SLACK_ABS:
                        drive[(i, a, b)] = d
        self.y = {k: self.m.addVar(vtype="B") for k in drive}
        self.drive = drive

    def _coverage(self) -> None:
        """Flows (a robot leaves a subtask at most as often as it enters it), every subtask served
        by a coalition that covers its skills and its linear rules."""
        p, m, quicksum = self.p, self.m, self.sum
        into: dict[tuple[int, str], list] = {}
        out_of: dict[tuple[int, str], list] = {}
        for (i, a, b), v in self.y.items():
            into.setdefault((i, b), []).append(v)
            out_of.setdefault((i, a), []).append(v)
        x = {k: quicksum(vs) for k, vs in into.items()}
        for (i, a), vs in out_of.items():
            m.addCons(quicksum(vs) <= (1 if a == START else x.get((i, a), 0)))
        for vs in into.values():
            m.addCons(quicksum(vs) <= 1)
        for b in p.ids:
            mine = {i: x[(i, b)] for i in range(len(p.robots)) if (i, b) in x}
            if not mine:
                raise InputError(f"subtask {b}: no robot the rules allow can reach it within {self.ub:g} s")
            m.addCons(quicksum(mine.values()) >= 1)
            need = p.need[b]
            for u in range(len(p.skills)):
                if need[u] > 0:
                    m.addCons(quicksum(float(p.Q[i, u]) * v for i, v in mine.items() if p.Q[i, u] > 0) >= float(need[u]))
            for L in p.lin[b]:
                expr = quicksum(float(L.coef[i]) * v for i, v in mine.items() if L.coef[i] != 0)
                m.addCons(expr <= L.rhs if L.sense == "<=" else expr >= L.rhs if L.sense == ">=" else expr == L.rhs)
        self.into = into

    def _times(self, apart: set) -> None:
        """Start times S, the makespan C; precedence, and an arc's drive before its subtask starts."""
        p, m, head, latest = self.p, self.m, self.head, self.latest
        S = {b: m.addVar(lb=head[b], ub=max(head[b], latest[b]), vtype="C") for b in p.ids}
        C = m.addVar(lb=min(self.ub, chain_bound(p, apart, head, self.tail, self.anc)), ub=self.ub, vtype="C")
        for b in p.ids:
            m.addCons(C >= S[b] + p.duration[b] + self.tail[b])
            for q in p.preds[b]:
                m.addCons(S[b] >= S[q] + p.duration[q])
        for (i, a, b), v in self.y.items():
            t = self.drive[(i, a, b)] / p.speed
            if a == START:
                if t > head[b]:
                    m.addCons(S[b] >= t * v)
            else:
                big = (latest[a] + p.duration[a]) + t - head[b]
                if big > 0:
                    m.addCons(S[b] >= S[a] + p.duration[a] + t - big * (1 - v))
        self.S, self.C = S, C

    def _apart(self, apart: set) -> None:
        """Subtasks no two disjoint coalitions can serve share a robot, so one ends (and that
        robot drives to the other) before the other starts: a disjunction SCIP can branch on."""
        p, m, S, latest, head = self.p, self.m, self.S, self.latest, self.head
        for b, c in sorted(apart):
            t_bc = p.dist(p.last[b], p.first[c]) / p.speed
            t_cb = p.dist(p.last[c], p.first[b]) / p.speed
            if b in self.anc[c]:
                m.addCons(S[c] >= S[b] + p.duration[b] + t_bc)
            elif c in self.anc[b]:
                m.addCons(S[b] >= S[c] + p.duration[c] + t_cb)
            else:
                o = m.addVar(vtype="B")  # 1: b first
                big_bc = latest[b] + p.duration[b] + t_bc - head[c]
                big_cb = latest[c] + p.duration[c] + t_cb - head[b]
                m.addCons(S[c] >= S[b] + p.duration[b] + t_bc - max(big_bc, 0.0) * (1 - o))
                m.addCons(S[b] >= S[c] + p.duration[c] + t_cb - max(big_cb, 0.0) * o)

    def _robots_busy(self) -> None:
        """A robot does its subtasks one after another (the makespan is at least its busy time),
        and b starts no sooner than the one arc into it that robot i uses allows at the earliest
        (no big-M, so the LP sees it)."""
        p, m, y, quicksum = self.p, self.m, self.y, self.sum
        for i in range(len(p.robots)):
            busy = [(v, self.drive[k] / p.speed + p.duration[k[2]]) for k, v in y.items() if k[0] == i]
            if busy:
                m.addCons(self.C >= quicksum(t * v for v, t in busy))
        for (i, b) in self.into:
            early = [(v, self.drive[(i, a, b)] / p.speed + (0.0 if a == START else self.head[a] + p.duration[a]))
                     for (j, a, bb), v in y.items() if j == i and bb == b]
            if any(t > self.head[b] for _, t in early):
                m.addCons(self.S[b] >= quicksum(t * v for v, t in early))

    def _no_subtours(self) -> None:
        """With subtasks of zero duration the times alone allow cycles of arcs: order variables U
        (Miller-Tucker-Zemlin) forbid them."""
        p, m = self.p, self.m
        self.U = {}
        if min(p.duration.values()) <= 0:
            U = self.U = {b: m.addVar(lb=0.0, ub=len(p.ids) - 1, vtype="C") for b in p.ids}
            for b in p.ids:
                for q in p.preds[b]:
                    m.addCons(U[b] >= U[q] + 1)
            for (i, a, b), v in self.y.items():
                if a != START:
                    m.addCons(U[b] >= U[a] + 1 - len(p.ids) * (1 - v))

    def _travel(self, w_ub: float | None) -> None:
        """Each robot's metres, TC-max W (bounded by ``w_ub``) and the three objectives."""
        p, m, quicksum = self.p, self.m, self.sum
        self.metres = {i: quicksum((self.drive[k] + p.route_len[k[2]]) * v for k, v in self.y.items() if k[0] == i)
                       for i in range(len(p.robots))}
        W = m.addVar(lb=0.0, ub=w_ub if w_ub is not None else m.infinity(), vtype="C")
        for i in range(len(p.robots)):
            m.addCons(W >= self.metres[i])
        self.W = W
        self.objectives = {"makespan": self.C, "tc_max": W, "tc_sum": quicksum(self.metres.values())}

    def hint(self, plan: Plan) -> None:
        """A known plan as SCIP's first solution (partial: SCIP completes and checks it; a plan that
        does not fit this model's bounds is simply not kept)."""
        m, out = self.m, self.p.evaluate(plan)
        used, at = set(), {}
        for sid in plan.order:
            for i in plan.coalitions[sid]:
                used.add((i, at.get(i, START), sid))
                at[i] = sid
        if not used <= set(self.y):
            return
        sol = m.createPartialSol()
        for k, v in self.y.items():
            m.setSolVal(sol, v, 1.0 if k in used else 0.0)
        for rank, sid in enumerate(plan.order):
            m.setSolVal(sol, self.S[sid], out.start[sid])
            if self.U:
                m.setSolVal(sol, self.U[sid], float(rank))
        m.addSol(sol)

    def solve(self, objective: str, time_limit: float) -> tuple[IPStatus, float | None, Plan | None, float]:
        t0 = time.perf_counter()
        m = self.m
        m.setParam("limits/time", time_limit)
        m.setObjective(self.objectives[objective], "minimize")
        m.optimize()
        status = IPStatus.of(m)
        if m.getNSols() == 0:
            return status, None, None, time.perf_counter() - t0
        sol = m.getBestSol()
        used = [k for k, v in self.y.items() if m.getSolVal(sol, v) > 0.5]
        starts = {b: m.getSolVal(sol, v) for b, v in self.S.items()}
        return status, float(m.getObjVal()), _read_plan(self.p, used, starts), time.perf_counter() - t0


def _read_plan(p: JointProblem, arcs: list[tuple[int, str, str]], starts: dict[str, float]) -> Plan:
    """Coalitions from the arcs, and a commit order that respects the graph and every robot's
    sequence (Kahn's algorithm on both, earliest start first)."""
    coalitions: dict[str, list[int]] = {b: [] for b in p.ids}
    after: dict[str, set[str]] = {b: set(p.preds[b]) for b in p.ids}
    for i, a, b in arcs:
        coalitions[b].append(i)
        if a != START:
            after[b].add(a)
    order: list[str] = []
    left = set(p.ids)
    while left:
        ready = [b for b in left if not (after[b] & left)]
        if not ready:
            raise InputError("the solution's robot sequences contradict the dependency graph (a cycle)")
        b = min(ready, key=lambda s: (starts[s], p.ids.index(s)))
        order.append(b)
        left.remove(b)
    plan = Plan(order, {b: tuple(sorted(c)) for b, c in coalitions.items()})
    p.check(plan)
    return plan


def _upper_bound(p: JointProblem) -> float:
    """A makespan every instance can meet: subtasks one after another, each reached from the
    farthest place any robot can be."""
    places = set(p.robots) | set(p.last.values())
    far = max((p.dist(a, b) for a in places for b in set(p.first.values())), default=0.0)
    return sum(far / p.speed + p.duration[s] for s in p.nodes) + 1.0


def brute_force(p: JointProblem) -> tuple[tuple[float, float, float], Plan]:
    """The optimum by enumerating every commit order and every allowed coalition of every subtask,
    each plan timed by the Timeline itself (tests: a handful of subtasks and robots only)."""
    options = {}
    for s in p.ids:
        idx = [i for i in range(len(p.robots)) if p.allowed[s][i]]
        options[s] = [c for k in range(1, len(idx) + 1) for c in itertools.combinations(idx, k) if p.feasible(s, c)]
        if not options[s]:
            raise InputError(f"subtask {s} has no feasible coalition")
    best_key: tuple[float, float, float] = (math.inf, math.inf, math.inf)
    best_plan: Plan | None = None
    for order in itertools.permutations(p.ids):
        if not p.topological(order):
            continue
        for combo in itertools.product(*(options[s] for s in order)):
            plan = Plan(list(order), dict(zip(order, combo)))
            key = schedule_key(replay(p, plan))
            if best_plan is None or lex_less(key, best_key):
                best_key, best_plan = key, plan
    return best_key, best_plan

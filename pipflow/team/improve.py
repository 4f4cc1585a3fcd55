"""The improvement phase after Alg. 1 (beyond the paper; off unless asked for): local search over
which robots do each subtask and in which order they are committed, accepting only plans whose
(makespan, TC-max, TC-sum) is lexicographically better.

Why it helps: Alg. 1 decides one subtask at a time by travel cost, blind to time. It may pick a
robot that is still busy far away (the subtask waits for it), or a coalition that leaves a later
subtask short of nearby robots; and a robot serves its subtasks in frontier order, whatever the
graph allows. On small instances that leaves schedules tens of percent slower than the proven
optimum (``benchmarks/optimality.py``).

How: a plan (commit order + coalitions, :class:`~pipflow.team.joint.Plan`) is timed by the
Timeline's arithmetic (:meth:`JointProblem.evaluate`). Starting points: Alg. 1's own plan, and
the same order with each coalition re-chosen for the earliest start (robots that arrive soonest,
the cheapest in metres among those), in the walk's order and in earliest-start-first order.
From the best of them, a descent over these moves, on the subtasks that hold up the makespan
first (the critical chain: who or what each one waited for) and then on all:

* ``retime``: re-choose a subtask's coalition for the earliest start;
* ``swap``: one robot of a coalition for another (the soonest to arrive and the nearest);
* ``add``: a robot joins, and members it makes redundant leave (latest arrival first);
* ``drop``: a member whose skills are not needed leaves;
* ``move``: a subtask to another place in the commit order, between its predecessors and its
  successors (a robot then serves it before or after its other subtasks).

Every move keeps the skills covered, the user's only/never and linear rules, and the graph's
order (a commit order is always topological). After a local optimum the search kicks the best
plan (a few random moves) and descends again, until a budget of evaluations is spent; the seed
makes it deterministic. The result never worsens the objective: :func:`improve_allocation`
replays both plans with the Timeline itself and keeps Alg. 1's unless the new one is better.
"""
from __future__ import annotations

import math
import random
import time
from typing import Iterator

import numpy as np

from pipflow.errors import InputError
from pipflow.team.allocation import greedy, solve_lexicographic
from pipflow.team.joint import JointProblem, Outcome, Plan, lex_less, replay, schedule_key
from pipflow.team.scheduling import build_schedule

#: plan evaluations (each times the whole plan) the search may spend by default
DEFAULT_BUDGET = 6000
#: robots considered to join a subtask: the soonest to arrive and the nearest, this many of each
CANDIDATES = 6
#: random moves of a kick
KICK = 3
#: kicks in a row that find nothing better before the search stops (small instances end early)
PATIENCE = 40


class _Spent(Exception):
    """The evaluation budget is used up."""


class Search:
    """One local search over the plans of a :class:`JointProblem`."""

    def __init__(self, p: JointProblem, budget: int = DEFAULT_BUDGET, seed: int = 0):
        if budget < 0:
            raise InputError(f"improvement budget must be >= 0 evaluations, got {budget}")
        self.p = p
        self.budget = budget
        self.rng = random.Random(seed)
        self.evaluations = 0
        self.accepted: dict[str, int] = {}
        self.xy = np.array([p.travel.point(r) for r in p.robots], dtype=float).reshape(-1, 2)
        self.small = len(p.robots) <= 2 * CANDIDATES

    # ------------------------------------------------------------------ evaluation
    def evaluate(self, plan: Plan) -> Outcome:
        if self.evaluations >= self.budget:
            raise _Spent
        self.evaluations += 1
        return self.p.evaluate(plan)

    # ------------------------------------------------------------------ the run
    def run(self, plan: Plan) -> tuple[Plan, Outcome]:
        """The best plan found from ``plan`` (``plan`` itself when nothing beats it)."""
        self.p.check(plan)
        best, best_out = plan, self.p.evaluate(plan)
        try:
            for name, start in (("retimed", lambda: self.retimed(plan.order)), ("earliest", self.earliest)):
                cand = start()
                out = self.evaluate(cand)
                if lex_less(out.key, best_out.key):
                    best, best_out = cand, out
                    self._count(name)
            moves: dict[str, int] = {}
            best, best_out = self.descend(best, best_out, moves)
            self._count(moves)
            idle = 0
            while idle < PATIENCE:
                moves = {"kick": 1}
                cand = self.kick(best, best_out)
                out = self.evaluate(cand)
                cand, out = self.descend(cand, out, moves)
                idle += 1
                if lex_less(out.key, best_out.key):
                    best, best_out, idle = cand, out, 0
                    self._count(moves)
        except _Spent:
            pass
        return best, best_out

    def descend(self, plan: Plan, out: Outcome, moves: dict[str, int]) -> tuple[Plan, Outcome]:
        """First-improvement descent to a local optimum, tallying the moves it takes in ``moves``
        (it raises _Spent when the budget ends: the caller keeps the best plan it holds)."""
        improved = True
        while improved:
            improved = False
            for name, cand in self.neighbours(plan, out):
                c_out = self.evaluate(cand)
                if lex_less(c_out.key, out.key):
                    plan, out = cand, c_out
                    moves[name] = moves.get(name, 0) + 1
                    improved = True
                    break
        return plan, out

    def _count(self, moves: dict[str, int] | str) -> None:
        """Moves on the way to a new best plan (``accepted`` in the stats)."""
        for name, k in ({moves: 1} if isinstance(moves, str) else moves).items():
            self.accepted[name] = self.accepted.get(name, 0) + k

    # ------------------------------------------------------------------ where robots are
    def state_before(self, plan: Plan, out: Outcome, sid: str) -> tuple[list, list[float]]:
        """Each robot's place and free time just before ``sid`` is committed."""
        pos: list = list(self.p.robots)
        free = [0.0] * len(self.p.robots)
        for s in plan.order:
            if s == sid:
                break
            for i in plan.coalitions[s]:
                pos[i], free[i] = self.p.last[s], out.end[s]
        return pos, free

    def arrivals(self, sid: str, pos: list, free: list[float], keep: int | None = None) -> dict[int, float]:
        """When each allowed robot can be at ``sid``'s first place; with ``keep``, only for about
        that many of the soonest (exact distances for the soonest by straight line, a lower bound)."""
        p = self.p
        allowed = np.flatnonzero(p.allowed[sid])
        if keep is not None and len(allowed) > 3 * keep:
            here = np.array(p.travel.point(p.first[sid]))
            pts = np.array([p.travel.point(pos[i]) for i in allowed])
            lower = np.array([free[i] for i in allowed]) + np.hypot(*(pts - here).T) / p.speed
            allowed = allowed[np.argsort(lower, kind="stable")[:3 * keep]]
        return {int(i): free[i] + p.dist(pos[i], p.first[sid]) / p.speed for i in allowed}

    def candidates(self, plan: Plan, out: Outcome, sid: str) -> list[int]:
        """Robots that might join ``sid``: every allowed one in a small team, otherwise the soonest
        to arrive and the nearest."""
        pos, free = self.state_before(plan, out, sid)
        if self.small:
            return [int(i) for i in np.flatnonzero(self.p.allowed[sid])]
        arr = self.arrivals(sid, pos, free, keep=CANDIDATES)
        soon = sorted(arr, key=lambda i: (arr[i], i))[:CANDIDATES]
        near = sorted(arr, key=lambda i: (self.p.dist(pos[i], self.p.first[sid]), i))[:CANDIDATES]
        return list(dict.fromkeys(soon + near))

    # ------------------------------------------------------------------ coalitions by time
    def soonest_coalition(self, sid: str, pos: list, free: list[float], ready: float) -> tuple[int, ...] | None:
        """The coalition that can start ``sid`` soonest; among the robots there by then, the one
        the paper's IP picks (least metres: the largest, then the sum)."""
        p = self.p
        arr = self.arrivals(sid, pos, free, keep=None if self.small else 4 * CANDIDATES)
        idx = sorted(arr, key=lambda i: (arr[i], i))
        need = p.need[sid]
        have = np.zeros(len(p.skills))
        t = None
        for i in idx:  # the earliest time by which the robots there cover the skills
            have = have + p.Q[i]
            if np.all(have >= need - 1e-9) and (not p.lin[sid] or self._lin_feasible(sid, idx[:idx.index(i) + 1])):
                t = arr[i]
                break
        if t is None:
            return None
        t = max(t, ready)
        eligible = np.zeros(len(p.robots), dtype=bool)
        eligible[[i for i in idx if arr[i] <= t + 1e-9]] = True
        metres = np.zeros(len(p.robots))
        for i in idx:
            metres[i] = p.dist(pos[i], p.first[sid]) + p.route_len[sid]
        if p.lin[sid]:
            chosen = solve_lexicographic(p.Q, need, metres, eligible, p.lin[sid]).robots
        else:
            chosen = greedy(p.Q, need, metres, eligible)
        chosen = tuple(sorted(int(i) for i in chosen))
        return chosen if chosen and p.feasible(sid, chosen) else None

    def _lin_feasible(self, sid: str, robots: list[int]) -> bool:
        p = self.p
        allowed = np.zeros(len(p.robots), dtype=bool)
        allowed[robots] = True
        return bool(solve_lexicographic(p.Q, p.need[sid], np.zeros(len(p.robots)), allowed, p.lin[sid]).robots)

    def retimed(self, order: list[str]) -> Plan:
        """``order`` with every coalition re-chosen, in turn, for the earliest start."""
        return self._build(list(order))

    def earliest(self) -> Plan:
        """A new commit order: always the ready subtask that can start soonest."""
        return self._build(None)

    def _build(self, order: list[str] | None) -> Plan:
        p = self.p
        pos: list = list(p.robots)
        free = [0.0] * len(p.robots)
        end: dict[str, float] = {}
        done: list[str] = []
        coalitions: dict[str, tuple[int, ...]] = {}
        left = list(p.ids)
        while left:
            ready = [s for s in left if all(q in end for q in p.preds[s])]
            if order is not None:
                ready = [order[len(done)]]
            best = None
            for s in ready:
                r = max((end[q] for q in p.preds[s]), default=0.0)
                c = self.soonest_coalition(s, pos, free, r)
                if c is None:
                    raise InputError(f"subtask {s} has no coalition the rules allow")
                start = max([r] + [free[i] + p.dist(pos[i], p.first[s]) / p.speed for i in c])
                if best is None or start < best[0] - 1e-9:
                    best = (start, s, c)
            start, s, c = best
            end[s] = start + p.duration[s]
            for i in c:
                pos[i], free[i] = p.last[s], end[s]
            coalitions[s] = c
            done.append(s)
            left.remove(s)
        return Plan(done, coalitions)

    # ------------------------------------------------------------------ moves
    def critical(self, plan: Plan, out: Outcome) -> list[str]:
        """The chain of subtasks the makespan waited on: from the last to end, back through the
        robot that arrived last (its previous subtask) or the predecessor that ended last."""
        p = self.p
        if not plan.order:
            return []
        pos = {s: k for k, s in enumerate(plan.order)}
        sid = max(plan.order, key=lambda s: (out.end[s], -pos[s]))
        chain = []
        while sid is not None and sid not in chain:
            chain.append(sid)
            i = out.late_robot[sid]
            if i is not None:
                before = [s for s in plan.order[:pos[sid]] if i in plan.coalitions[s]]
                sid = before[-1] if before else None
            else:
                preds = p.preds[sid]
                sid = max(preds, key=lambda q: out.end[q]) if preds and out.start[sid] > 0 else None
        return chain

    def neighbours(self, plan: Plan, out: Outcome) -> Iterator[tuple[str, Plan]]:
        """Moves, the critical chain's subtasks first, then every other subtask (in commit order)."""
        chain = self.critical(plan, out)
        rest = [s for s in plan.order if s not in chain]
        for sid in chain + rest:
            yield from self.moves_of(plan, out, sid)

    def moves_of(self, plan: Plan, out: Outcome, sid: str) -> Iterator[tuple[str, Plan]]:
        p = self.p
        coal = plan.coalitions[sid]
        pos, free = self.state_before(plan, out, sid)
        ready = max((out.end[q] for q in p.preds[sid]), default=0.0)
        c = self.soonest_coalition(sid, pos, free, ready)
        if c is not None and c != coal:
            yield "retime", self._with(plan, sid, c)
        cands = [i for i in self.candidates(plan, out, sid) if i not in coal]
        arrive = {i: free[i] + p.dist(pos[i], p.first[sid]) / p.speed for i in set(coal) | set(cands)}
        for i in coal:
            rest = tuple(j for j in coal if j != i)
            if rest and p.feasible(sid, rest):
                yield "drop", self._with(plan, sid, rest)
        for new in cands:
            for i in coal:
                c2 = tuple(sorted(j for j in coal if j != i) + [new])
                if p.feasible(sid, tuple(sorted(c2))):
                    yield "swap", self._with(plan, sid, tuple(sorted(c2)))
            c3 = self._pruned(sid, tuple(sorted(coal + (new,))), new, arrive)
            if c3 is not None and c3 != coal:
                yield "add", self._with(plan, sid, c3)
        k = plan.order.index(sid)
        lo = max((plan.order.index(q) for q in p.preds[sid]), default=-1) + 1
        hi = min((plan.order.index(s) for s in p.succs[sid]), default=len(plan.order)) - 1
        for j in range(lo, hi + 1):
            if j != k:
                order = list(plan.order)
                order.insert(j, order.pop(k))
                yield "move", Plan(order, plan.coalitions)

    def _pruned(self, sid: str, coal: tuple[int, ...], keep: int, arrive: dict[int, float]) -> tuple[int, ...] | None:
        """``coal`` less the members it can do without, the latest to arrive first (``keep`` stays)."""
        if not self.p.feasible(sid, coal):
            return None
        members = list(coal)
        for i in sorted(coal, key=lambda j: (-arrive.get(j, math.inf), j)):
            if i == keep:
                continue
            trial = tuple(j for j in members if j != i)
            if self.p.feasible(sid, trial):
                members = list(trial)
        return tuple(sorted(members))

    @staticmethod
    def _with(plan: Plan, sid: str, coalition: tuple[int, ...]) -> Plan:
        coalitions = dict(plan.coalitions)
        coalitions[sid] = coalition
        return Plan(plan.order, coalitions)

    def kick(self, plan: Plan, out: Outcome) -> Plan:
        """A few random moves of ``plan`` (the search's way out of a local optimum)."""
        for _ in range(KICK):
            sid = self.rng.choice(plan.order)
            moves = list(self.moves_of(plan, out, sid))
            if moves:
                plan = self.rng.choice(moves)[1]
                out = self.evaluate(plan)
        return plan


def improve_allocation(graph: dict, world: dict, allocation: dict, constraints: list | None = None,
                       linear: list | None = None, *, speed: float = 1.0, handling: float = 2.0,
                       budget: int = DEFAULT_BUDGET, seed: int = 0, travel=None) -> dict:
    """An allocation (the ``allocate.*`` contract) at least as good as ``allocation``, from the
    local search above. Both are replayed by the Timeline itself and the new one is kept only when
    its (makespan, TC-max, TC-sum) is lexicographically better; its assignments are in its commit
    order, with costs as the original allocation's cost definition prices them."""
    t0 = time.perf_counter()
    p = JointProblem(graph, world, constraints, linear, travel=travel, speed=speed, handling=handling)
    plan0 = p.plan_of(allocation)
    try:
        p.check(plan0)
    except InputError as exc:
        raise InputError(f"the allocation to improve is not a valid plan of this graph: {exc}") from None
    search = Search(p, budget=budget, seed=seed)
    plan, _ = search.run(plan0)
    before = schedule_key(build_schedule(graph, allocation, world, speed=speed, handling=handling, travel=p.travel))
    after_schedule = replay(p, plan)
    after = schedule_key(after_schedule)
    better = lex_less(after, before)
    stats = {
        "before": dict(zip(("makespan", "tc_max", "tc_sum"), before)),
        "after": dict(zip(("makespan", "tc_max", "tc_sum"), after if better else before)),
        "improved": better, "evaluations": search.evaluations, "budget": budget, "seed": seed,
        "accepted": search.accepted, "time_s": time.perf_counter() - t0,
    }
    result = dict(allocation)
    result["stats"] = {**allocation.get("stats", {}), "improve": stats}
    if better:
        result["method"] = f"{allocation.get('method', 'allocation')}+improve"
        result["assignments"] = p.assignments(plan, allocation.get("cost"))
        n = len(p.robots)
        result["stats"]["predicted"] = {"makespan": after[0], "tc_max": after[1], "tc_avg": after[2] / n if n else 0.0}
    return result

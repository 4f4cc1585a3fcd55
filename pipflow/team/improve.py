"""The improvement phase after Alg. 1 (beyond the paper; off unless asked for): a search over which
robots do each subtask and in which order the subtasks are committed, keeping only plans whose
(makespan, TC-max, TC-sum) is lexicographically better.

Why it helps: Alg. 1 decides one subtask at a time by travel cost, blind to time. It may pick a
robot that is still busy far away (the subtask waits for it), or a coalition that leaves a later
subtask short of robots; and a robot serves its subtasks in frontier order, whatever the graph
allows. On small instances that leaves schedules tens of percent slower than the proven optimum
(``benchmarks/optimality.py``).

How. A plan (commit order + coalitions, :class:`~pipflow.team.joint.Plan`) is timed by the
Timeline's arithmetic (:meth:`JointProblem.evaluate`). The search has two levels:

1. **Orders.** A commit order is turned into a plan by choosing each subtask's coalition in turn
   for the earliest start given the robots' places and free times so far (:meth:`Search.decode`),
   by one of two rules among the robots there by then: the paper's (least metres: the largest,
   then the sum) or the tightest fit (least skill beyond the need, then metres: it leaves the
   strong robots for later subtasks). From Alg. 1's order and an earliest-start-first order, a
   descent moves one subtask at a time to another place in the order (within the graph).
2. **Coalitions and places.** From the best plan so far, a descent over single changes, on the
   subtasks that hold up the makespan first (the critical chain: who or what each waited for):
   ``retime`` (re-choose the coalition for the earliest start), ``swap`` (one member for another
   robot: the soonest to arrive and the nearest), ``add`` (a robot joins; members it makes
   redundant leave, latest arrival first), ``drop`` (a member not needed leaves), ``move`` (the
   subtask to another place in the commit order, so a robot serves it earlier or later), ``shift``
   (a move, and the coalition re-chosen for the earliest start at the new place).

Every plan keeps the skills covered, the user's only/never and linear rules, and the graph's
order (a commit order is always topological). At a local optimum the search kicks the best plan
(a few random changes; a few subtasks moved in the order and the plan decoded again; or one
subtask given a random coalition and the rest decoded again) and descends again, until :data:`PATIENCE` kicks in a row find nothing better, the budget is spent,
or the makespan meets the lower bound of :func:`~pipflow.team.bounds.makespan_bound` (no plan
ends sooner; the descents still lower TC-max and TC-sum). A seed makes it deterministic. The
result never worsens the objective: :func:`improve_allocation` replays both plans with the
Timeline itself and keeps Alg. 1's unless the new one is better.
"""
from __future__ import annotations

import itertools
import math
import random
import time
from typing import Any, Iterator

import numpy as np

from pipflow.errors import InputError
from pipflow.team.allocation import solve_lexicographic
from pipflow.team.bounds import makespan_bound
from pipflow.team.joint import REL_TOL, JointProblem, Outcome, Plan, lex_less, replay, schedule_key
from pipflow.team.scheduling import build_schedule

#: the search's default budget, in subtask timings (timing a plan of n subtasks costs n; choosing a
#: coalition :data:`COALITION_COST` plus the robots it prices), so that its time follows the work
#: done and not the instance's size
DEFAULT_BUDGET = 150_000
#: robots considered to join a subtask: the soonest to arrive and the nearest, this many of each
CANDIDATES = 6
#: random changes of a kick, at most
KICK = 3
#: kicks in a row that find nothing better before the search stops (small instances end early)
PATIENCE = 60
#: coalition rules of :meth:`Search.decode`
RULES = ("metres", "fit")
#: the tightest-fit rule tries coalitions of at most this many of the robots there in time
FIT_SIZE = 3
#: ... among at most this many of them (the soonest)
FIT_POOL = 10
#: the order descent moves every subtask up to this many subtasks; beyond, only the critical chain
ORDER_ALL = 12
#: what choosing one coalition costs, in subtask timings, besides one per robot it prices
#: (measured: a 7-subtask plan decodes in about 10 timings of it)
COALITION_COST = 8


class _Spent(Exception):
    """The budget is used up."""


class Search:
    """One search over the plans of a :class:`JointProblem`. It keeps the best plan it has
    evaluated (``best``), whatever it was doing when the budget ran out."""

    def __init__(self, p: JointProblem, budget: int = DEFAULT_BUDGET, seed: int = 0):
        if budget < 0:
            raise InputError(f"improvement budget must be >= 0 subtask timings, got {budget}")
        self.p = p
        self.budget = budget
        self.spent = 0
        self.rng = random.Random(seed)
        self.evaluations = 0
        self.accepted: dict[str, int] = {}
        self.xy = np.array([p.travel.point(r) for r in p.robots], dtype=float).reshape(-1, 2)
        self.small = len(p.robots) <= 2 * CANDIDATES
        self.bound = makespan_bound(p)  # kicks stop once a plan's makespan meets it
        self.best: Plan | None = None
        self.best_out: Outcome | None = None
        self._seen: dict[tuple, Outcome] = {}
        self._decoded: dict[tuple, Plan] = {}
        self._skill = [tuple(float(q) for q in row) for row in p.Q]  # per robot, plain floats
        self._need = {sid: tuple(float(y) for y in need) for sid, need in p.need.items()}

    # ------------------------------------------------------------------ budget and the best plan
    def _charge(self, cost: int) -> None:
        if self.spent + cost > self.budget:
            raise _Spent
        self.spent += cost

    def evaluate(self, plan: Plan, move: str | None = None) -> Outcome:
        """Time ``plan`` (once: a plan met again is looked up), and keep it if it is the best yet;
        ``move`` names what made it, for the stats."""
        key = (tuple(plan.order), tuple(plan.coalitions[s] for s in plan.order))
        out = self._seen.get(key)
        if out is None:
            self._charge(max(1, len(plan.order)))
            self.evaluations += 1
            out = self._seen[key] = self.p.evaluate(plan)
        if self.best_out is None or lex_less(out.key, self.best_out.key):
            if self.best_out is not None and move:
                self.accepted[move] = self.accepted.get(move, 0) + 1
            self.best, self.best_out = plan, out
        return out

    def at_bound(self) -> bool:
        """Does the best plan's makespan meet the lower bound (no plan ends sooner)?"""
        return self.best_out.key[0] <= self.bound * (1 + REL_TOL) + REL_TOL

    # ------------------------------------------------------------------ the run
    def run(self, plan: Plan) -> tuple[Plan, Outcome]:
        """The best plan found from ``plan`` (``plan`` itself when nothing beats it)."""
        self.p.check(plan)
        self.best, self.best_out = plan, self.p.evaluate(plan)
        if not plan.order:
            return self.best, self.best_out
        try:
            starts = [list(plan.order), self.earliest_order()]
            for order, rule in itertools.product(starts, RULES):
                self.evaluate(self.decode(order, rule), f"decode-{rule}")
            self.descend(*self.order_descent(self.best, self.best_out))
            idle = 0
            while idle < PATIENCE and not self.at_bound():
                before = self.best_out
                cand = self.kick(self.best, self.best_out)
                self.descend(*self.order_descent(cand, self.evaluate(cand, "kick")))
                idle = 0 if self.best_out is not before else idle + 1
        except _Spent:
            pass
        return self.best, self.best_out

    def order_descent(self, plan: Plan, out: Outcome) -> tuple[Plan, Outcome]:
        """Level 1: move one subtask to another place in ``plan``'s order and decode the order by
        either rule, all of it or from the moved subtask on (the coalitions before it kept); take
        the first better plan; again, until no move helps."""
        improved = True
        while improved and not self.at_bound():
            improved = False
            order = list(plan.order)
            movers = order if len(order) <= ORDER_ALL else self.critical(plan, out)
            tries = ((sid, j, rule, part) for sid in movers for j in self._places(order, sid)
                     for part in (False, True) for rule in RULES)
            for sid, j, rule, part in tries:
                trial = list(order)
                k = trial.index(sid)
                trial.insert(j, trial.pop(k))
                cand = self.decode(trial, rule, plan, min(j, k) if part else 0)
                c_out = self.evaluate(cand, "order")
                if lex_less(c_out.key, out.key):
                    plan, out, improved = cand, c_out, True
                    break
        return plan, out

    def descend(self, plan: Plan, out: Outcome) -> tuple[Plan, Outcome]:
        """Level 2: first-improvement descent over single changes to a local optimum (it raises
        _Spent when the budget ends; :meth:`evaluate` keeps the best plan all along)."""
        improved = True
        while improved:
            improved = False
            for name, cand in self.neighbours(plan, out):
                c_out = self.evaluate(cand, name)
                if lex_less(c_out.key, out.key):
                    plan, out = cand, c_out
                    improved = True
                    break
        return plan, out

    def kick(self, plan: Plan, out: Outcome) -> Plan:
        """The way out of a local optimum, one of three at random: a few random changes of
        ``plan``; its order with a few subtasks moved at random, decoded again by a random rule
        (another order hands the nearest robots to other subtasks); or one subtask given a random
        coalition and the subtasks after it decoded again (a coalition that is worse for its own
        subtask but frees the robots a later one needs)."""
        kind = self.rng.randrange(3)
        if kind == 0:
            order = list(plan.order)
            for _ in range(self.rng.randint(1, KICK)):
                sid = self.rng.choice(order)
                order.insert(self.rng.choice(self._places(order, sid) or [order.index(sid)]),
                             order.pop(order.index(sid)))
            return self.decode(order, self.rng.choice(RULES))
        if kind == 1:
            k = self.rng.randrange(len(plan.order))
            sid = plan.order[k]
            coalition = self.random_coalition(sid, self.state_before(plan, out, sid))
            if coalition is not None:
                return self.decode(plan.order, self.rng.choice(RULES), self._with(plan, sid, coalition), k + 1)
        for _ in range(self.rng.randint(1, KICK)):
            sid = self.rng.choice(plan.order)
            moves = list(self.moves_of(plan, out, sid))
            if moves:
                plan = self.rng.choice(moves)[1]
                out = self.evaluate(plan, "kick")
        return plan

    def random_coalition(self, sid: str, state: tuple) -> tuple[int, ...] | None:
        """Candidates of ``sid`` in random order until they cover it, less the ones not needed."""
        cands = self.candidates(sid, state)
        self.rng.shuffle(cands)
        chosen: list[int] = []
        for i in cands:
            chosen.append(i)
            if self.p.feasible(sid, tuple(sorted(chosen))):
                return self._pruned(sid, tuple(sorted(chosen)), -1, {})
        return None

    def _places(self, order: list[str], sid: str) -> list[int]:
        """Where else ``sid`` may go in ``order``: after its predecessors, before its successors."""
        k = order.index(sid)
        pos = {s: i for i, s in enumerate(order)}
        lo = max((pos[q] for q in self.p.preds[sid]), default=-1) + 1
        hi = min((pos[s] for s in self.p.succs[sid]), default=len(order)) - 1
        return [j for j in range(lo, hi + 1) if j != k]

    # ------------------------------------------------------------------ where robots are
    def state_before(self, plan: Plan, out: Outcome, sid: str) -> tuple[list, np.ndarray, np.ndarray]:
        """Each robot's place, free time and floor point just before ``sid`` is committed."""
        p = self.p
        pos: list = list(p.robots)
        free = np.zeros(len(p.robots))
        xy = self.xy.copy()
        for s in plan.order:
            if s == sid:
                break
            here = p.travel.point(p.last[s])
            for i in plan.coalitions[s]:
                pos[i], free[i], xy[i] = p.last[s], out.end[s], here
        return pos, free, xy

    def arrivals(self, sid: str, state: tuple, keep: int | None = None) -> dict[int, float]:
        """When each allowed robot can be at ``sid``'s first place; with ``keep``, only for about
        that many of the soonest (exact distances for the soonest by straight line, a lower bound)."""
        p = self.p
        pos, free, xy = state
        allowed = np.flatnonzero(p.allowed[sid])
        if keep is not None and len(allowed) > 3 * keep:
            here = np.array(p.travel.point(p.first[sid]))
            lower = free[allowed] + np.hypot(*(xy[allowed] - here).T) / p.speed
            allowed = allowed[np.argsort(lower, kind="stable")[:3 * keep]]
        return {int(i): float(free[i]) + p.dist(pos[i], p.first[sid]) / p.speed for i in allowed}

    def candidates(self, sid: str, state: tuple) -> list[int]:
        """Robots that might join ``sid``: every allowed one in a small team, otherwise the soonest
        to arrive and the nearest."""
        if self.small:
            return [int(i) for i in np.flatnonzero(self.p.allowed[sid])]
        pos = state[0]
        arr = self.arrivals(sid, state, keep=CANDIDATES)
        soon = sorted(arr, key=lambda i: (arr[i], i))[:CANDIDATES]
        near = sorted(arr, key=lambda i: (self.p.dist(pos[i], self.p.first[sid]), i))[:CANDIDATES]
        return list(dict.fromkeys(soon + near))

    # ------------------------------------------------------------------ coalitions by time
    def soonest_coalition(self, sid: str, state: tuple, ready: float, rule: str = "metres") -> tuple[int, ...] | None:
        """A coalition that can start ``sid`` soonest. Among the robots there by then: ``metres``,
        the paper's choice (least metres: the cheapest robots that add a needed skill until the
        need is covered; with linear rules the paper's IP itself); ``fit``, the fewest skills
        beyond the need (then metres), among small coalitions of the soonest (else ``metres``).
        Plain Python over the few skills: this runs for every subtask of every decoded plan."""
        p = self.p
        pos = state[0]
        need, skill = self._need[sid], self._skill
        t = None
        for keep in ((None,) if self.small else (2 * CANDIDATES, None)):
            # the soonest few robots first; all of them when those few cannot cover the need
            arr = self.arrivals(sid, state, keep=keep)
            self._charge(COALITION_COST + len(arr))
            idx = sorted(arr, key=lambda i: (arr[i], i))
            have = [0.0] * len(need)
            for k, i in enumerate(idx):  # the earliest time by which the robots there cover the skills
                have = [h + q for h, q in zip(have, skill[i])]
                if all(h >= n - 1e-9 for h, n in zip(have, need)) and (
                        not p.lin[sid] or self._lin_feasible(sid, idx[:k + 1])):
                    t = arr[i]
                    break
            if t is not None:
                break
        if t is None:
            return None
        t = max(t, ready)
        there = [i for i in idx if arr[i] <= t + 1e-9]
        metres = {i: p.dist(pos[i], p.first[sid]) + p.route_len[sid] for i in there}
        if rule == "fit":
            best = None
            pool = sorted(there[:FIT_POOL])
            for size in range(1, min(FIT_SIZE, len(pool)) + 1):
                for combo in itertools.combinations(pool, size):
                    got = [sum(skill[i][u] for i in combo) for u in range(len(need))]
                    if any(g < n - 1e-9 for g, n in zip(got, need)) or not p.feasible(sid, combo):
                        continue
                    key = (sum(g - n for g, n in zip(got, need)), sum(metres[i] for i in combo))
                    if best is None or key < best[0]:
                        best = (key, combo)
            if best is not None:
                return best[1]
        if p.lin[sid]:
            eligible = np.zeros(len(p.robots), dtype=bool)
            eligible[there] = True
            c = np.zeros(len(p.robots))
            for i in there:
                c[i] = metres[i]
            chosen = tuple(sorted(int(i) for i in solve_lexicographic(p.Q, p.need[sid], c, eligible, p.lin[sid]).robots))
        else:
            have = [0.0] * len(need)
            picked = []
            for i in sorted(there, key=lambda j: (metres[j], j)):  # allocation.greedy, on the few robots there
                if all(h >= n - 1e-9 for h, n in zip(have, need)):
                    break
                if any(q > 0 and h < n - 1e-9 for q, h, n in zip(skill[i], have, need)):
                    picked.append(i)
                    have = [h + q for h, q in zip(have, skill[i])]
            chosen = tuple(sorted(picked))
        return chosen if chosen and p.feasible(sid, chosen) else None

    def _lin_feasible(self, sid: str, robots: list[int]) -> bool:
        p = self.p
        allowed = np.zeros(len(p.robots), dtype=bool)
        allowed[robots] = True
        return bool(solve_lexicographic(p.Q, p.need[sid], np.zeros(len(p.robots)), allowed, p.lin[sid]).robots)

    def decode(self, order: list[str], rule: str = "metres", keep: Plan | None = None, prefix: int = 0) -> Plan:
        """The plan of a commit order: each coalition chosen in turn for the earliest start, by
        ``rule`` (:meth:`soonest_coalition`); the first ``prefix`` subtasks keep their coalitions
        in ``keep``. (Remembered: kicks and descents decode the same orders again.)"""
        p = self.p
        memo = (tuple(order), rule, tuple(keep.coalitions[s] for s in order[:prefix]) if keep else ())
        if memo in self._decoded:
            return self._decoded[memo]
        state = (list(p.robots), np.zeros(len(p.robots)), self.xy.copy())
        pos, free, xy = state
        end: dict[str, float] = {}
        coalitions: dict[str, tuple[int, ...]] = {}
        for k, s in enumerate(order):
            r = max((end[q] for q in p.preds[s]), default=0.0)
            c = keep.coalitions[s] if k < prefix else self.soonest_coalition(s, state, r, rule)
            if c is None:
                raise InputError(f"subtask {s} has no coalition the rules allow")
            start = max([r] + [float(free[i]) + p.dist(pos[i], p.first[s]) / p.speed for i in c])
            end[s] = start + p.duration[s]
            here = p.travel.point(p.last[s])
            for i in c:
                pos[i], free[i], xy[i] = p.last[s], end[s], here
            coalitions[s] = c
        plan = self._decoded[memo] = Plan(list(order), coalitions)
        return plan

    def earliest_order(self) -> list[str]:
        """A commit order by list scheduling: always the ready subtask that can start soonest (of
        the :data:`CANDIDATES` ready the longest, so that a wide frontier costs no more than a few)."""
        p = self.p
        self._charge(max(1, len(p.ids)))
        state = (list(p.robots), np.zeros(len(p.robots)), self.xy.copy())
        pos, free, xy = state
        end: dict[str, float] = {}
        order: list[str] = []
        left = list(p.ids)
        while left:
            ready = [s for s in left if all(q in end for q in p.preds[s])]
            ready = sorted(ready, key=lambda s: (max((end[q] for q in p.preds[s]), default=0.0),
                                                 p.ids.index(s)))[:CANDIDATES]
            best = None
            for s in ready:
                r = max((end[q] for q in p.preds[s]), default=0.0)
                c = self.soonest_coalition(s, state, r)
                if c is None:
                    raise InputError(f"subtask {s} has no coalition the rules allow")
                start = max([r] + [float(free[i]) + p.dist(pos[i], p.first[s]) / p.speed for i in c])
                if best is None or start < best[0] - 1e-9:
                    best = (start, s, c)
            start, s, c = best
            end[s] = start + p.duration[s]
            here = p.travel.point(p.last[s])
            for i in c:
                pos[i], free[i], xy[i] = p.last[s], end[s], here
            order.append(s)
            left.remove(s)
        return order

    # ------------------------------------------------------------------ single changes
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
        """Changes, the critical chain's subtasks first, then every other subtask (in commit order)."""
        chain = self.critical(plan, out)
        rest = [s for s in plan.order if s not in chain]
        for sid in chain + rest:
            yield from self.moves_of(plan, out, sid)

    def moves_of(self, plan: Plan, out: Outcome, sid: str) -> Iterator[tuple[str, Plan]]:
        """Every single change of ``sid``'s coalition or place (module docstring), as plans."""
        p = self.p
        coal = plan.coalitions[sid]
        state = self.state_before(plan, out, sid)
        pos, free, _ = state
        ready = max((out.end[q] for q in p.preds[sid]), default=0.0)
        c = self.soonest_coalition(sid, state, ready)
        if c is not None and c != coal:
            yield "retime", self._with(plan, sid, c)
        cands = [i for i in self.candidates(sid, state) if i not in coal]
        arrive = {i: float(free[i]) + p.dist(pos[i], p.first[sid]) / p.speed for i in set(coal) | set(cands)}
        for i in coal:
            rest = tuple(j for j in coal if j != i)
            if rest and p.feasible(sid, rest):
                yield "drop", self._with(plan, sid, rest)
        for new in cands:
            for i in coal:
                c2 = tuple(sorted([j for j in coal if j != i] + [new]))
                if p.feasible(sid, c2):
                    yield "swap", self._with(plan, sid, c2)
            c3 = self._pruned(sid, tuple(sorted(coal + (new,))), new, arrive)
            if c3 is not None and c3 != coal:
                yield "add", self._with(plan, sid, c3)
        for j in self._places(plan.order, sid):
            order = list(plan.order)
            order.insert(j, order.pop(order.index(sid)))
            moved = Plan(order, plan.coalitions)
            yield "move", moved
            # and with a coalition chosen for the earliest start at the new place (the others'
            # times taken from before the move: a guess; the evaluation is exact)
            state = self.state_before(moved, out, sid)
            for rule in RULES:
                c = self.soonest_coalition(sid, state, ready, rule)
                if c is not None and c != coal:
                    yield "shift", self._with(moved, sid, c)

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


def improve_allocation(graph: dict, world: dict, allocation: dict, constraints: list | None = None,
                       linear: list | None = None, *, budget: int = DEFAULT_BUDGET, seed: int = 0,
                       **timing: Any) -> dict:
    """An allocation (the ``allocate.*`` contract) at least as good as ``allocation``, from the
    search above; ``timing``: the :class:`JointProblem`'s ``speed``, ``handling`` and ``travel``. Both are replayed by the Timeline itself and the new one is kept only when its
    (makespan, TC-max, TC-sum) is lexicographically better; its assignments are in its commit
    order, with costs as the original allocation's cost definition prices them."""
    t0 = time.perf_counter()
    p = JointProblem(graph, world, constraints, linear, **timing)
    plan0 = p.plan_of(allocation)
    try:
        p.check(plan0)
    except InputError as exc:
        raise InputError(f"the allocation to improve is not a valid plan of this graph: {exc}") from None
    search = Search(p, budget=budget, seed=seed)
    plan, _ = search.run(plan0)
    before = schedule_key(build_schedule(graph, allocation, world, speed=p.speed, handling=p.handling, travel=p.travel))
    after = schedule_key(replay(p, plan))
    better = lex_less(after, before)
    names = ("makespan", "tc_max", "tc_sum")
    stats = {
        "before": dict(zip(names, before)), "after": dict(zip(names, after if better else before)),
        "improved": better, "lower_bound": search.bound, "evaluations": search.evaluations,
        "budget": budget, "spent": search.spent, "seed": seed, "accepted": search.accepted,
        "time_s": time.perf_counter() - t0,
    }
    result = dict(allocation)
    result["stats"] = {**allocation.get("stats", {}), "improve": stats}
    if better:
        result["method"] = f"{allocation.get('method', 'allocation')}+improve"
        result["assignments"] = p.assignments(plan, allocation.get("cost"))
        n = len(p.robots)
        result["stats"]["predicted"] = {"makespan": after[0], "tc_max": after[1], "tc_avg": after[2] / n if n else 0.0}
    return result

"""Lower bounds of the joint allocation-and-sequencing problem (:mod:`pipflow.team.joint`): when
a subtask can start at the earliest, how long its successors take at least, which subtasks can
never run at the same time, and from these a makespan no plan can beat.

Two users: the exact model (:mod:`pipflow.team.exact`) takes them as variable bounds, big-Ms and
cuts, and the improvement phase (:mod:`pipflow.team.improve`) stops looking for a shorter
makespan once a plan meets :func:`makespan_bound`. Every bound assumes only what the Timeline
does: robots start at their starts at time zero and drive shortest paths at ``speed`` (so no
robot reaches a place sooner than the shortest path from its start allows), a subtask starts after
its predecessors end, and a robot does its subtasks one after another.
"""
from __future__ import annotations

import itertools
import math

import networkx as nx
import numpy as np

from pipflow.errors import InputError
from pipflow.team.joint import JointProblem


def ancestors(p: JointProblem) -> dict[str, set[str]]:
    """Every subtask's ancestors in the dependency graph."""
    out: dict[str, set[str]] = {}
    for b in topological_ids(p):
        out[b] = set().union(*({q} | out[q] for q in p.preds[b])) if p.preds[b] else set()
    return out


def topological_ids(p: JointProblem) -> list[str]:
    """The subtasks in a topological order (graph order among the ready ones)."""
    order: list[str] = []
    done: set[str] = set()
    while len(order) < len(p.ids):
        ready = [b for b in p.ids if b not in done and all(q in done for q in p.preds[b])]
        if not ready:
            raise InputError(f"the dependency graph has a cycle among {sorted(set(p.ids) - done)}")
        for b in ready:
            order.append(b)
            done.add(b)
    return order


#: the most robots for which :func:`apart_pairs` enumerates coalitions (2^n subsets per subtask)
APART_MAX_ROBOTS = 8


def apart_pairs(p: JointProblem) -> set[tuple[str, str]]:
    """Pairs of subtasks that cannot run at the same time: no coalition of one is disjoint from a
    coalition of the other (e.g. each needs more than half the team's carrying), so some robot
    does both. Found by enumerating coalitions; empty for teams above :data:`APART_MAX_ROBOTS`."""
    n = len(p.robots)
    if n > APART_MAX_ROBOTS:
        return set()
    masks: dict[str, list[int]] = {}
    for b in p.ids:
        allowed = [i for i in range(n) if p.allowed[b][i]]
        feas = []
        for k in range(1, len(allowed) + 1):
            for combo in itertools.combinations(allowed, k):
                if p.feasible(b, combo):
                    feas.append(sum(1 << i for i in combo))
        masks[b] = feas
    out = set()
    for b, c in itertools.combinations(p.ids, 2):
        if not any(mb & mc == 0 for mb in masks[b] for mc in masks[c]):
            out.add((b, c))
    return out


def chain_bound(p: JointProblem, apart: set[tuple[str, str]], head: dict[str, float], tail: dict[str, float],
                anc: dict[str, set[str]]) -> float:
    """A makespan lower bound from the largest groups of pairwise :func:`apart_pairs` subtasks: they run
    one after another, with a robot driving from each to the next; the best order (a dynamic
    program over subsets) still takes this long."""
    g = nx.Graph()
    g.add_nodes_from(p.ids)
    g.add_edges_from(apart)
    best = 0.0
    for clique in nx.find_cliques(g):
        if len(clique) < 2 or len(clique) > 12:
            continue
        k = len(clique)
        travel = [[p.dist(p.last[a], p.first[b]) / p.speed for b in clique] for a in clique]
        # end[(subset, last)]: the earliest end of the subset's subtasks in some order ending with last
        end: dict[tuple[int, int], float] = {}
        for j, b in enumerate(clique):
            end[(1 << j, j)] = head[b] + p.duration[b]
        for subset in range(1, 1 << k):
            for j in range(k):
                e = end.get((subset, j))
                if e is None:
                    continue
                for nxt in range(k):
                    if subset & (1 << nxt):
                        continue
                    if any(clique[q] in anc[clique[nxt]] and not subset & (1 << q) for q in range(k)):
                        continue  # a predecessor of nxt in the group has not run yet
                    b = clique[nxt]
                    e2 = max(head[b], e + travel[j][nxt]) + p.duration[b]
                    key = (subset | (1 << nxt), nxt)
                    if e2 < end.get(key, float("inf")):
                        end[key] = e2
        full = (1 << k) - 1
        best = max(best, min((end[(full, j)] + tail[clique[j]] for j in range(k) if (full, j) in end),
                             default=0.0))
    return best


def heads_tails(p: JointProblem) -> tuple[dict[str, float], dict[str, float]]:
    """Earliest start of each subtask (its predecessors' chain, or the nearest allowed robot's
    drive from its start: none gets there sooner, by the triangle inequality) and the longest
    chain of its successors' durations."""
    head: dict[str, float] = {}
    tail: dict[str, float] = {}
    order = topological_ids(p)
    starts = np.array([p.travel.point(r) for r in p.robots], dtype=float).reshape(-1, 2)
    for b in order:
        drive = nearest_start(p, b, starts) / p.speed
        head[b] = max([drive] + [head[q] + p.duration[q] for q in p.preds[b]])
    for b in reversed(order):
        tail[b] = max((p.duration[s] + tail[s] for s in p.succs[b]), default=0.0)
    return head, tail


def nearest_start(p: JointProblem, sid: str, starts: np.ndarray) -> float:
    """Metres from the nearest allowed robot's start to ``sid``'s first place. The straight line
    never exceeds the path, so the robots are tried nearest by straight line first and the search
    stops when the next one's straight line is already longer than the best path: a thousand
    robots cost a handful of path searches, and the result is exact."""
    allowed = np.flatnonzero(p.allowed[sid])
    if allowed.size == 0:
        return 0.0
    here = np.array(p.travel.point(p.first[sid]))
    line = np.hypot(*(starts[allowed] - here).T)
    best = math.inf
    for k in np.argsort(line, kind="stable"):
        if line[k] >= best:
            break
        best = min(best, p.dist(p.robots[int(allowed[k])], p.first[sid]))
    return best


def makespan_bound(p: JointProblem) -> float:
    """No plan ends sooner: the longest chain of earliest start, durations and successors, and
    the best order of each group of subtasks that cannot overlap."""
    if not p.ids:
        return 0.0
    head, tail = heads_tails(p)
    bound = max(head[b] + p.duration[b] + tail[b] for b in p.ids)
    return max(bound, chain_bound(p, apart_pairs(p), head, tail, ancestors(p)))

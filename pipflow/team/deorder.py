"""Minimal deordering of a totally ordered plan: keep an ordering only where a precondition needs it.

Why: in the read/write ("exact") graph every two moves through one shelf are ordered, because
both write the shelf's ``load``. But two increments of one fluent commute, so what must stay
ordered is only what some precondition needs: the move that brings units before the move that
takes them, the move that frees room before the move that fills it. This is plan deordering
(Backstrom 1998) with numeric resources; Muise, Beck and McIlraith (2016) compute the optimum
with MaxSAT, here a greedy pass in plan order that keeps every order the graph allows valid.

How every allowed order is kept valid (the envelope test): each ground precondition that is
linear in the fluents, ``sum(c_k * f_k) + c0  op  0``, is bounded over all orders at once. Actions
that are *ancestors* of the action always precede it (their whole effect counts); actions that
are *incomparable* may or may not (only their harmful effects count, each fluent separately, so
even a robot-level execution that lifts units at the start and sets them down at the end, with
several moves in flight, stays within the bound); *descendants* never precede it. Hence

    worst(a, c) = base + sum_{ancestors b} w_b(c) + sum_{incomparable b} neg_b(c)

where ``w_b(c)`` is b's change of the condition's value and ``neg_b(c)`` the sum of its negative
parts. ``worst >= 0`` (``> 0``; for ``==`` also the best case ``== 0``) for every precondition
means every linearization, and every interleaving of effects, meets it. Effects that are not
additive constants (assignments, increases by a changing fluent) and conditions that are not
linear are ordered as in the read/write graph.

The pass, for action j in plan order: (1) edges from earlier actions that conflict through
non-additive fluents; (2) while one of j's preconditions fails the envelope, an edge from the
earlier helper (an action that raises the condition) that finishes earliest in the graph so far,
then drop helpers that turned out redundant; if helpers cannot do it, edges from every earlier
action touching the condition (then the bound is the plan's own prefix, which holds); (3) for
every earlier, incomparable action whose precondition j could now break, an edge to j. Edges only
point forward, so the plan's own order stays allowed. Adding edges never lowers an envelope,
which is why one pass suffices. A relaxation pass then tries to drop each edge of the transitive
reduction (plans up to :data:`RELAX_ACTIONS` actions), so no single edge left can go: a local
minimum, not the global one that Muise et al.'s MaxSAT finds (on the benchmarks' plans the greedy
pass already leaves nothing to drop).
"""
from __future__ import annotations

from dataclasses import dataclass, field
from fractions import Fraction
from typing import Any, Iterable

from pipflow.pddl.convert import initial_numbers
from pipflow.pddl.linear import Comparison, Linear, NotLinear, comparison, conjuncts, key_of, linear

Key = tuple


@dataclass
class Numeric:
    """What one ground action reads and changes, split into the additive and the rest."""

    index: int
    conds: list[Comparison] = field(default_factory=list)  # linear preconditions over changing fluents
    deltas: dict[Key, Fraction] = field(default_factory=dict)  # additive constant effects
    opaque_reads: set = field(default_factory=set)  # fluents read any other way
    opaque_writes: set = field(default_factory=set)  # fluents written any other way


def _match(a: Key, b: Key) -> bool:
    return len(a) == len(b) and a[0] == b[0] and all(x == y or "*" in (x, y) for x, y in zip(a[1:], b[1:]))


def _meets(xs: Iterable[Key], ys: Iterable[Key]) -> bool:
    ys = list(ys)
    return any(_match(x, y) for x in xs for y in ys)


def _fluents(expr: Any) -> set:
    out, stack = set(), [expr]
    while stack:
        e = stack.pop()
        if e.is_fluent_exp():
            out.add(key_of(e))
        stack.extend(e.args)
    return out


@dataclass
class _Lifted:
    """One action's conditions and effects with parameters as ``?name``, read once per action."""

    conds: list  # Comparison (lifted keys) or a set of keys read non-linearly
    effects: list  # (key, Linear value or None, increase/decrease sign or 0, extra read keys)


def _lift(action: Any) -> _Lifted:
    conds: list = []
    for pre in getattr(action, "preconditions", []):
        for cond in conjuncts(pre):
            keys = _fluents(cond)
            if not keys:
                continue  # e.g. (not (= ?from ?to)): independent of the state
            try:
                conds.append(comparison(cond))
            except NotLinear:
                conds.append(keys)
    effects = []
    for eff in getattr(action, "effects", []):
        sign = (1 if eff.is_increase() else -1) if (eff.is_increase() or eff.is_decrease()) else 0
        if not eff.condition.is_true():
            sign = 0
        try:
            value = linear(eff.value) if sign else None
        except NotLinear:
            value = None
        effects.append((key_of(eff.fluent), value, sign, _fluents(eff.value) | _fluents(eff.condition)))
    return _Lifted(conds, effects)


def _bind(key: Key, objects: dict[str, str]) -> Key:
    return (key[0], *(objects.get(x, x) for x in key[1:]))


def numeric_view(problem: Any, grounded: list) -> list[Numeric]:
    """Split every ground action (``dependency.GroundAction``, with ``objects``: parameter ->
    object name) into linear conditions, additive deltas and opaque reads/writes. Fluents that no
    action of the domain writes are static: replaced by their initial values."""
    written = {eff.fluent.fluent().name for a in problem.actions for eff in getattr(a, "effects", [])}
    init = initial_numbers(problem)
    lifted: dict[str, _Lifted] = {}

    def ground(form: Linear, objects: dict[str, str]) -> Linear:
        coefs: dict[Key, Fraction] = {}
        const = form.const
        for k, c in form.coefs.items():
            gk = _bind(k, objects)
            if gk[0] not in written and gk in init:
                const += c * Fraction(init[gk])
            else:
                coefs[gk] = coefs.get(gk, Fraction(0)) + c
        return Linear({k: c for k, c in coefs.items() if c}, const)

    out = []
    for g in grounded:
        if g.action.name not in lifted:
            lifted[g.action.name] = _lift(g.action)
        spec, objects = lifted[g.action.name], g.objects
        view = Numeric(g.index)
        for cond in spec.conds:
            if isinstance(cond, Comparison):
                form = ground(cond.form, objects)
                if form.coefs:
                    view.conds.append(Comparison(form, cond.op))
            else:
                view.opaque_reads |= {_bind(k, objects) for k in cond}
        for key, value, sign, extra in spec.effects:
            gk = _bind(key, objects)
            amount = ground(value, objects) if value is not None else None
            if sign and amount is not None and not amount.coefs and "*" not in gk:
                view.deltas[gk] = view.deltas.get(gk, Fraction(0)) + sign * amount.const
                continue
            view.opaque_writes.add(gk)
            view.opaque_reads |= {_bind(k, objects) for k in extra}
        out.append(view)
    # a fluent that some action writes opaquely is opaque everywhere: its value is not a sum
    opaque = set().union(*(v.opaque_writes for v in out)) if out else set()
    for v in out:
        for cmp in list(v.conds):
            if any(_match(k, o) for k in cmp.form.coefs for o in opaque) or \
                    any(k not in init and k[0] in written for k in cmp.form.coefs) or \
                    any(k[0] not in written for k in cmp.form.coefs):
                v.conds.remove(cmp)  # also: a static fluent without a value (unknown, not zero)
                v.opaque_reads |= set(cmp.form.coefs)
        for k in [k for k in v.deltas if any(_match(k, o) for o in opaque)]:
            v.opaque_writes.add(k)
            del v.deltas[k]
        # whole numbers as ints: the envelope sums thousands of them, and Fraction is slow
        v.deltas = {k: _num(d) for k, d in v.deltas.items()}
        v.conds = [Comparison(Linear({k: _num(c) for k, c in cmp.form.coefs.items()}, _num(cmp.form.const)), cmp.op)
                   for cmp in v.conds]
    return out


def _num(x: Fraction) -> Any:
    return int(x) if x.denominator == 1 else x


def conflicts(a: Numeric, b: Numeric) -> bool:
    """Must stay in plan order regardless of numbers: one writes opaquely what the other touches,
    or one reads opaquely what the other changes."""
    touched_a = a.opaque_reads | set(a.deltas) | {k for c in a.conds for k in c.form.coefs}
    touched_b = b.opaque_reads | set(b.deltas) | {k for c in b.conds for k in c.form.coefs}
    return (_meets(a.opaque_writes, touched_b | b.opaque_writes) or _meets(b.opaque_writes, touched_a)
            or _meets(set(a.deltas), b.opaque_reads) or _meets(set(b.deltas), a.opaque_reads))


class _Envelope:
    """Per (action, condition): base value, and each other action's whole and harmful change."""

    def __init__(self, problem: Any, views: list[Numeric]):
        init = initial_numbers(problem)
        self.views = views
        by_key: dict[Key, list[int]] = {}
        for v in views:
            for k in v.deltas:
                by_key.setdefault(k, []).append(v.index)
        self.base: dict[tuple[int, int], Fraction] = {}
        self.touch: dict[tuple[int, int], dict[int, tuple[Fraction, Fraction, Fraction]]] = {}
        for v in views:
            for ci, cmp in enumerate(v.conds):
                base = cmp.form.const + sum(c * init.get(k, 0) for k, c in cmp.form.coefs.items())
                effects: dict[int, tuple[Fraction, Fraction, Fraction]] = {}
                for k, c in cmp.form.coefs.items():
                    for b in by_key.get(k, ()):
                        if b == v.index:
                            continue
                        d = c * views[b].deltas[k]
                        w, neg, pos = effects.get(b, (0, 0, 0))
                        effects[b] = (w + d, neg + min(d, 0), pos + max(d, 0))
                self.base[v.index, ci] = base
                self.touch[v.index, ci] = {b: e for b, e in effects.items() if e != (0, 0, 0)}

    def bounds(self, a: int, ci: int, upto: int, anc: list[int], j: int, j_mask: int) -> tuple[Fraction, Fraction]:
        """(worst, best) value of condition ci of action a over every order of the actions before
        ``upto`` that the graph allows; ``anc`` holds ancestor bitmasks, action j's is ``j_mask``."""
        mine = j_mask if a == j else anc[a]
        lo = hi = self.base[a, ci]
        for b, (w, neg, pos) in self.touch[a, ci].items():
            if b >= upto:
                continue
            if mine >> b & 1:
                lo += w
                hi += w
                continue
            if b > a and ((j_mask if b == j else anc[b]) >> a) & 1:
                continue  # a descendant of a: never before it
            lo += neg
            hi += pos
        return lo, hi

    def holds(self, a: int, ci: int, lo: Fraction, hi: Fraction) -> bool:
        cmp = self.views[a].conds[ci]
        if cmp.op == "==":
            return lo == 0 and hi == 0
        return cmp.holds(lo)


def deorder(problem: Any, grounded: list) -> list[tuple[int, int]]:
    """Edges ``(i, j)`` (plan indices, i < j) of a deordering of the plan in which every
    linearization, and every interleaving of effects, keeps every precondition (module docstring)."""
    views = numeric_view(problem, grounded)
    env = _Envelope(problem, views)
    n = len(views)
    anc = [0] * n  # bitmask of ancestors
    level = [0] * n  # longest chain of actions ending at each (unit durations)
    parents: list[set[int]] = [set() for _ in range(n)]
    # later actions' conditions that an action touches: (action, condition) pairs per action
    watched: dict[int, list[tuple[int, int]]] = {}
    for a in range(n):
        for ci in range(len(views[a].conds)):
            for b in env.touch[a, ci]:
                watched.setdefault(b, []).append((a, ci))

    def closure(ps: Iterable[int]) -> int:
        mask = 0
        for p in ps:
            mask |= anc[p] | (1 << p)
        return mask

    current: dict[tuple[int, int], tuple] = {}  # (action, condition) -> envelope over actions so far
    with_opaque: list[int] = []  # only pairs with a non-additive side can conflict
    for j in range(n):
        opaque_j = bool(views[j].opaque_reads or views[j].opaque_writes)
        ps = {i for i in (range(j) if opaque_j else with_opaque) if conflicts(views[i], views[j])}
        if opaque_j:
            with_opaque.append(j)
        # (2) j's own conditions
        for ci in range(len(views[j].conds)):
            mask = closure(ps)
            if env.holds(j, ci, *env.bounds(j, ci, j, anc, j, mask)):
                continue
            helpers = sorted((b for b, (w, _, _) in env.touch[j, ci].items() if b < j and w > 0 and not mask >> b & 1),
                             key=lambda b: (level[b], -env.touch[j, ci][b][0], -b))
            added = []
            for b in helpers:
                ps.add(b)
                added.append(b)
                mask = closure(ps)
                if env.holds(j, ci, *env.bounds(j, ci, j, anc, j, mask)):
                    break
            else:
                ps |= {b for b in env.touch[j, ci] if b < j}
                continue
            for b in reversed(added[:-1]):  # a later, larger helper may make an earlier one redundant
                trial = ps - {b}
                if env.holds(j, ci, *env.bounds(j, ci, j, anc, j, closure(trial))):
                    ps = trial
        # (3) earlier actions' conditions that j could break while incomparable
        mask = closure(ps)
        for a, ci in sorted(watched.get(j, ()), key=lambda x: -x[0]):
            if a >= j or mask >> a & 1:
                continue  # j already follows a
            _, neg, pos = env.touch[a, ci][j]
            lo, hi = current[a, ci]
            if not env.holds(a, ci, lo + neg, hi + pos):
                ps.add(a)
                mask |= anc[a] | (1 << a)
        parents[j] = ps
        anc[j] = mask
        level[j] = 1 + max((level[p] for p in ps), default=0)
        # envelopes so far: j joins those of the earlier actions it stays incomparable to
        for a, ci in watched.get(j, ()):
            if a < j and not mask >> a & 1:
                _, neg, pos = env.touch[a, ci][j]
                lo, hi = current[a, ci]
                current[a, ci] = (lo + neg, hi + pos)
        for ci in range(len(views[j].conds)):
            current[j, ci] = env.bounds(j, ci, j, anc, j, mask)
    edges = [(i, j) for j in range(n) for i in sorted(parents[j])]
    if n <= RELAX_ACTIONS:
        required = [(i, j) for j in range(n) for i in (range(j) if views[j].opaque_reads or views[j].opaque_writes
                                                         else with_opaque) if i < j and conflicts(views[i], views[j])]
        edges = relax(env, n, edges, required)
    return edges


RELAX_ACTIONS = 150
"""Plans up to this many actions get the relaxation pass (each trial re-checks every envelope)."""


def _ancestors(n: int, edges: Iterable[tuple[int, int]]) -> list[int]:
    parents: list[list[int]] = [[] for _ in range(n)]
    for i, j in edges:
        parents[j].append(i)
    anc = [0] * n
    for j in range(n):  # edges point forward, so plan order is a topological order
        for p in parents[j]:
            anc[j] |= anc[p] | (1 << p)
    return anc


def envelopes_hold(env: _Envelope, n: int, edges: Iterable[tuple[int, int]]) -> bool:
    """Whether every precondition holds over every order (and interleaving) the edges allow."""
    anc = _ancestors(n, edges)
    for a in range(n):
        for ci in range(len(env.views[a].conds)):
            if not env.holds(a, ci, *env.bounds(a, ci, n, anc, -1, 0)):
                return False
    return True


def relax(env: _Envelope, n: int, edges: list[tuple[int, int]], required: list[tuple[int, int]]) -> list[tuple[int, int]]:
    """Drop every edge of the transitive reduction whose removal keeps all envelopes and every
    ``required`` order (non-additive conflicts): no single remaining edge can go (a local
    minimum of the deordering; the greedy pass may add an edge that a later choice made unneeded)."""
    import networkx as nx

    g = nx.DiGraph()
    g.add_nodes_from(range(n))
    g.add_edges_from(edges)
    current = sorted(nx.transitive_reduction(g).edges(), key=lambda e: (-e[1], -e[0]))
    for e in list(current):
        trial = [x for x in current if x != e]
        anc = _ancestors(n, trial)
        if all(anc[j] >> i & 1 for i, j in required) and envelopes_hold(env, n, trial):
            current = trial
    return sorted(current, key=lambda e: (e[1], e[0]))

"""``pipflow-transport``: a planner of our own for transport-like numeric problems, as a UP engine.

Why: the warehouse domain is a transport problem (move k <= 6 units of one product between
shelves, never over a shelf's capacity). ENHSP's default search (gbfs + hadd) solves the paper's
small tasks in about a second with near-fewest moves, but it grows quickly and ``enhsp-opt``
times out even on some paper tasks. The structure is better served by network flow, then an
exact search where capacity makes the flow's answer too long:

1. **Final state.** Goal cells are ranges ``lo <= stock <= hi`` (``=`` is ``lo == hi``; bounds
   goals give one side). A final state exists iff a bipartite flow (free units of each product
   -> the room each shelf has left) carries every free unit; otherwise *proven unsolvable*.
2. **Flows.** Per product, the transfers from cells that must give to cells that must receive in
   the fewest moves (a small SCIP integer program; moves are ceil(units / 6) per route, so 6 + 6
   beats 7 + 5; on many routes, whole moves are paired off first and the program gets only the
   remainders), kept when it beats a networkx min-cost flow (SCIP may stop at its time limit); units that must come from (or go
   to) cells with slack come from those already giving, then the fullest.
3. **Moves.** Each arc's flow is cut into moves of at most the largest magnitude.
4. **Order.** Moves are sequenced so that stock never goes negative and no shelf ever exceeds its
   capacity; when every waiting move targets a full shelf (a swap or cycle of full shelves), a
   move is split to the room there is or parked on a shelf with room.
5. **Exact search.** When the plan is longer than an admissible lower bound (per product, the
   moves that the cells below and above their range need, :func:`lower_bound`, and the order-free
   IP of :mod:`pipflow.warehouse.bounds`), an A* search over stock states with that bound looks for a
   shorter plan, pruned at the flow plan's length and limited to ``search_budget`` (generated
   states times their size). If it ends within the budget, the plan is *proven*
   to have the fewest moves (UP status SOLVED_OPTIMALLY); otherwise the flow plan (or the best
   found) is returned with the gap in the engine's log. Capacity-tight instances (swaps through
   one free slot, cycles of full shelves) are where step 4 loses moves and step 5 wins them back.

A bound that makes both the search and the IP sharp: the warehouse's free room never changes
(units only change shelves) and a move needs that much room on its target, so no move carries
more than it (:func:`largest_move`); with one free slot every move carries one unit.

Measured by ``benchmarks/team_plans.py``: the fewest moves (proven) on the paper's ten tasks and
on all 36 instances of the generated capacity-tight suite, in well under a second each; on an
8 x 6 x 120 instance 20 moves, equal to the lower bound, in 0.9 s (ENHSP's gbfs: 21 moves in 43 s
in an earlier run; no plan within 120 s at load 9-11); at 50 x 10 x 2000 no search (the state
space is far too large): 327 moves against a cheap bound of 315 (the flow alone: 381), in
about 4-8 s at load 10.

Which problems: any domain whose single action has the *shape* of a transport move, whatever its
names: parameters (from, to: one type; item; magnitude), effects ``decrease S(from, item)``,
``increase S(to, item)`` by ``A(magnitude)`` (and optionally ``decrease L(from)``,
``increase L(to)`` by the same amount), preconditions ``S(from, item) >= A(magnitude)`` and
``L(to) + A(magnitude) <= C(to)`` (and optionally ``from != to``), with ``A`` and ``C`` static.
The goal is a conjunction of comparisons of single ``S`` cells with numbers. Anything else is
answered UNSUPPORTED_PROBLEM. Each plan is checked by UP's ``sequential_plan_validator`` before
it is returned (``validate=False`` skips that), so a bug here shows as an engine error, never
as a wrong plan.
"""
from __future__ import annotations

import functools
import heapq
import itertools
import math
from math import ceil
import threading
import time
from collections import OrderedDict
from dataclasses import dataclass, field
from fractions import Fraction
from typing import Any, Callable, Optional

from pipflow.pddl.convert import data_to_plan, initial_numbers
from pipflow.pddl.linear import NotLinear, comparison, conjuncts, key_of
from pipflow.warehouse.problem import magnitudes

ENGINE_NAME = "pipflow-transport"
ACTION = "move-product"
ROLES = ("from", "to", "product", "magnitude")
DEFAULT_BUDGET = 6_000_000
"""What the A* search may generate per solve, in cells (a state of S shelves x P products costs
S * P): 400,000 states of 15 cells, about 3 s of CPU and 0.3 GB at most, spent only when the
flow plan is longer than the order-free IP bound; large instances get proportionally fewer states."""
SEARCH_CELLS = 200
"""Above this many (shelf, product) cells the exact search is not tried: its first expansion alone
would use most of the budget, and plans there are too long for it to reach the goal."""
IP_SECONDS = 8.0
"""At most this much SCIP time for the per-product fewest-moves IPs of one plan (and 2 s per
product): a safety net, not the expected cost. The paper's tasks and the tight suite need
milliseconds and are solved to optimality; on many routes the remainder programs stop at their
root (:func:`_chunked_fewest_moves`): about 0.4 s per product at 50 shelves x 10 products, 381
-> 327 moves. Plans are the same on every machine unless a time limit is reached."""
IP_ARCS = 600
IP_DIRECT_ARCS = 120
"""Per product, the fewest-moves flow (:func:`_fewest_moves_flow`) is solved as an integer program
up to this many (source, sink) arcs; above it, networkx's min-cost flow (fewest units)."""
IP_CELLS = 4000
"""The order-free IP has two variables per (from, to, product): above this many it is skipped
(building it would cost more than it saves)."""


class NotTransport(Exception):
    """The problem does not follow the transport schema (reason in the message)."""


class Unsolvable(Exception):
    """No final state satisfies the goal (proven); the message says why."""


class Stuck(Exception):
    """The heuristic found no move order (every shelf full); the problem may still be solvable."""


Range = tuple  # (lo, hi); hi None = no upper bound


@dataclass
class Instance:
    """A transport problem in plain numbers, read from a UP problem (or built directly).

    ``goal`` maps a cell ``(shelf, product)`` to a range ``(lo, hi)`` (``hi`` None: unbounded);
    a bare int ``n`` is accepted and means ``(n, n)``."""

    shelves: list[str]
    products: list[str]
    stock: dict[tuple[str, str], int]
    capacity: dict[str, int]
    load: dict[str, int]
    magnitudes: dict[str, int]
    goal: dict[tuple[str, str], Any]
    action: str = ACTION
    arg_roles: tuple = ROLES

    def __post_init__(self) -> None:
        self.goal = {c: (r, r) if isinstance(r, int) else (int(r[0]), None if r[1] is None else int(r[1]))
                     for c, r in self.goal.items()}

    def total(self, product: str) -> int:
        return sum(self.stock.get((s, product), 0) for s in self.shelves)

    def lo(self, s: str, p: str) -> int:
        return self.goal.get((s, p), (0, None))[0]

    def hi(self, s: str, p: str) -> Optional[int]:
        return self.goal.get((s, p), (0, None))[1]

    def satisfied(self, stock: dict[tuple[str, str], int]) -> bool:
        """Whether ``stock`` meets every goal range."""
        return all(lo <= stock.get(c, 0) and (hi is None or stock.get(c, 0) <= hi)
                   for c, (lo, hi) in self.goal.items())


# ---------------------------------------------------------------------------------------------
# reading a UP problem: the schema by shape, not by name
# ---------------------------------------------------------------------------------------------
@dataclass
class Schema:
    """Which of the domain's fluents and parameters play which transport role."""

    action: str
    params: dict = field(default_factory=dict)  # role -> parameter name ("?from")
    stock: str = ""
    load: Optional[str] = None
    capacity: str = ""
    amount: str = ""
    arg_roles: tuple = ROLES


def _int(value: Any, what: str) -> int:
    v = float(value)
    if not v.is_integer():
        raise NotTransport(f"{what} = {value} is not a whole number")
    return int(v)


def read_schema(problem: Any) -> Schema:
    """The transport roles of ``problem``'s single action; :class:`NotTransport` if it has another shape."""
    if len(problem.actions) != 1:
        raise NotTransport("the domain must have a single action (a transport move)")
    action = problem.actions[0]
    if len(action.parameters) != 4:
        raise NotTransport(f"{action.name} must take four parameters (from, to, item, magnitude)")
    dec: dict[int, tuple] = {}
    inc: dict[int, tuple] = {}
    amounts = set()
    for eff in action.effects:
        if not (eff.is_increase() or eff.is_decrease()) or not eff.condition.is_true():
            raise NotTransport(f"effect {eff} is not an unconditional increase or decrease")
        if not eff.value.is_fluent_exp() or len(eff.value.args) != 1 or not eff.value.args[0].is_parameter_exp():
            raise NotTransport(f"effect {eff} does not change by an amount of a parameter")
        amounts.add(key_of(eff.value))
        k = key_of(eff.fluent)
        (dec if eff.is_decrease() else inc).setdefault(len(k) - 1, k)
        if sum(1 for e in action.effects if key_of(e.fluent)[0] == k[0]) != 2:
            raise NotTransport(f"fluent {k[0]} must be decreased at the source and increased at the target")
    if len(amounts) != 1 or 2 not in dec or 2 not in inc or len(action.effects) not in (2, 4):
        raise NotTransport("effects must move an amount of one item between two places")
    amount_key = next(iter(amounts))
    s_dec, s_inc = dec[2], inc[2]
    if s_dec[0] != s_inc[0] or s_dec[2] != s_inc[2] or s_dec[1] == s_inc[1]:
        raise NotTransport("the two-argument fluent must move one item from one place to another")
    params = {"from": s_dec[1], "to": s_inc[1], "product": s_dec[2], "magnitude": amount_key[1]}
    if len(set(params.values())) != 4:
        raise NotTransport("from, to, item and magnitude must be four different parameters")
    load = None
    if 1 in dec or 1 in inc:
        if dec.get(1, ("",))[1:] != (params["from"],) or inc.get(1, ("",))[1:] != (params["to"],) \
                or dec[1][0] != inc[1][0]:
            raise NotTransport("the one-argument fluent must be decreased at the source and increased at the target")
        load = dec[1][0]
    # preconditions: stock at the source covers the amount; the target has room; from != to
    capacity = None
    has_stock_pre = False
    for pre in conjuncts(action.preconditions[0]) if len(action.preconditions) == 1 else \
            [c for p in action.preconditions for c in conjuncts(p)]:
        if pre.is_not() and pre.args[0].is_equals() and {str(a) for a in pre.args[0].args} == \
                {params["from"][1:], params["to"][1:]}:
            continue
        try:
            cmp = comparison(pre)
        except NotLinear as exc:
            raise NotTransport(f"precondition {pre} is not understood: {exc}") from None
        one = Fraction(1)
        if cmp.op == ">=" and cmp.form.const == 0 and cmp.form.coefs == {s_dec: one, amount_key: -one}:
            has_stock_pre = True
            continue
        if cmp.op == ">=" and cmp.form.const == 0 and load and len(cmp.form.coefs) == 3 \
                and cmp.form.coefs.get((load, params["to"])) == -one and cmp.form.coefs.get(amount_key) == -one:
            (cap_key, c), = [(k, v) for k, v in cmp.form.coefs.items() if k not in ((load, params["to"]), amount_key)]
            if c == one and cap_key[1:] == (params["to"],):
                capacity = cap_key[0]
                continue
        raise NotTransport(f"precondition {pre} is not a transport precondition")
    if not has_stock_pre:
        raise NotTransport("no precondition that the source holds the amount moved")
    if load and capacity is None:
        raise NotTransport("no capacity precondition on the target")
    names = ["?" + p.name for p in action.parameters]
    by_param = {v: k for k, v in params.items()}
    return Schema(action.name, params, s_dec[0], load, capacity or "", amount_key[0],
                  tuple(by_param[n] for n in names))


def read_goal(problem: Any, stock: str) -> dict[tuple[str, str], Range]:
    """Goal ranges per stock cell from ``=``, ``<=``, ``>=``, ``<``, ``>`` conditions."""
    goal: dict[tuple[str, str], list] = {}
    for g in [c for top in problem.goals for c in conjuncts(top)]:
        try:
            cmp = comparison(g)
        except NotLinear:
            raise NotTransport(f"goal condition {g} is not a comparison of a count with a number") from None
        if len(cmp.form.coefs) != 1:
            raise NotTransport(f"goal condition {g} compares more than one count")
        (key, coef), = cmp.form.coefs.items()
        if key[0] != stock or len(key) != 3 or "*" in key:
            raise NotTransport(f"goal condition {g} is not about one {stock} cell")
        bound = -cmp.form.const / coef  # coef * x + const op 0
        lo, hi = goal.setdefault((key[1], key[2]), [0, None])
        if cmp.op == "==":
            if bound.denominator != 1:
                raise Unsolvable(f"goal {g} asks for a fraction of a unit")
            lo, hi = max(lo, int(bound)), int(bound) if hi is None else min(hi, int(bound))
        elif coef > 0:  # x >= bound (or x > bound when strict)
            b = math.floor(bound) + 1 if cmp.op == ">" else math.ceil(bound)
            lo = max(lo, b)
        else:  # coef < 0: x <= bound (or x < bound when strict)
            b = math.ceil(bound) - 1 if cmp.op == ">" else math.floor(bound)
            hi = b if hi is None else min(hi, b)
        goal[key[1], key[2]] = [lo, hi]
    for (s, p), (lo, hi) in goal.items():
        if hi is not None and hi < max(lo, 0):
            raise Unsolvable(f"the goal asks {s} to hold at least {lo} and at most {hi} units of {p}")
    return {c: (lo, hi) for c, (lo, hi) in goal.items()}


def instance_from_problem(problem: Any) -> Instance:
    """Read a transport problem out of a UP problem; :class:`NotTransport` if it does not fit."""
    schema = read_schema(problem)
    action = problem.action(schema.action)
    ptype = {"?" + p.name: p.type for p in action.parameters}
    shelves = [o.name for o in problem.objects(ptype[schema.params["from"]])]
    products = [o.name for o in problem.objects(ptype[schema.params["product"]])]
    mags = [o.name for o in problem.objects(ptype[schema.params["magnitude"]])]
    init = initial_numbers(problem)
    stock = {(s, p): _int(init.get((schema.stock, s, p), 0), f"({schema.stock} {s} {p})")
             for s in shelves for p in products}
    capacity, load = {}, {}
    for s in shelves:
        total = sum(stock[s, p] for p in products)
        if schema.load:
            if (schema.capacity, s) not in init:
                raise NotTransport(f"({schema.capacity} {s}) has no initial value")
            capacity[s] = _int(init[(schema.capacity, s)], f"({schema.capacity} {s})")
            load[s] = _int(init.get((schema.load, s), total), f"({schema.load} {s})")
        else:  # no capacity in the domain: room for everything
            capacity[s] = sum(sum(stock[x, p] for x in shelves) for p in products)
            load[s] = total
    magnitudes = {m: _int(init[(schema.amount, m)], f"({schema.amount} {m})")
                  for m in mags if (schema.amount, m) in init and init[(schema.amount, m)] > 0}
    if not magnitudes:
        raise NotTransport("no magnitude has a positive amount")
    goal = read_goal(problem, schema.stock)
    return Instance(shelves, products, stock, capacity, load, magnitudes, goal, schema.action, schema.arg_roles)


def goal_range(value: Any) -> Range:
    """A world-level goal value (int, or ``{at_least, at_most}``) as a range."""
    if isinstance(value, dict):
        return (int(value.get("at_least", 0)), None if value.get("at_most") is None else int(value["at_most"]))
    return (int(value), int(value))


def instance_from_world(world: dict, goal: dict[str, dict[str, Any]]) -> Instance:
    """The instance a world dict and a goal describe (with the magnitudes the writer writes)."""
    shelves, products = list(world["shelves"]), list(world["products"])
    stock = {(s, p): world["stock"].get(s, {}).get(p, 0) for s in shelves for p in products}
    return Instance(shelves, products, stock,
                    {s: world["shelves"][s]["capacity"] for s in shelves},
                    {s: sum(world["stock"].get(s, {}).values()) for s in shelves},
                    magnitudes(world),
                    {(s, p): goal_range(n) for s, items in goal.items() for p, n in items.items()})


# ---------------------------------------------------------------------------------------------
# step 1: the final state
# ---------------------------------------------------------------------------------------------
def check_final_state(inst: Instance) -> None:
    """Raise :class:`Unsolvable` with the reason when no final state meets the goal."""
    import networkx as nx

    for p in inst.products:
        have = inst.total(p)
        want = sum(inst.lo(s, p) for s in inst.shelves)
        if want > have:
            raise Unsolvable(f"the goal needs at least {want} units of {p} but only {have} exist")
        his = [inst.hi(s, p) for s in inst.shelves]
        if all(h is not None for h in his) and sum(his) < have:
            raise Unsolvable(f"the goal leaves room for at most {sum(his)} units of {p} on the shelves but "
                             f"{have} exist; units cannot disappear")
    for s in inst.shelves:
        fixed = sum(inst.lo(s, p) for p in inst.products)
        if fixed > inst.capacity[s]:
            raise Unsolvable(f"the goal puts at least {fixed} units on {s} but its capacity is {inst.capacity[s]}")
    g = nx.DiGraph()
    free_total = 0
    for p in inst.products:
        free = inst.total(p) - sum(inst.lo(s, p) for s in inst.shelves)
        if free <= 0:
            continue
        free_total += free
        g.add_edge("src", ("p", p), capacity=free)
        for s in inst.shelves:
            hi = inst.hi(s, p)
            if hi is None:
                g.add_edge(("p", p), ("s", s))
            elif hi > inst.lo(s, p):
                g.add_edge(("p", p), ("s", s), capacity=hi - inst.lo(s, p))
    for s in inst.shelves:
        g.add_edge(("s", s), "dst", capacity=inst.capacity[s] - sum(inst.lo(s, p) for p in inst.products))
    if free_total:
        flow = nx.maximum_flow_value(g, "src", "dst")
        if flow < free_total:
            raise Unsolvable(f"{free_total} units beyond what the goal places must stay on some shelf, "
                             f"but only {flow} fit in the room the goal leaves")


def plan_targets(inst: Instance) -> tuple[dict[tuple[str, str], int], dict[tuple[str, str], int]]:
    """``(final, slack)``: a first final count per cell (its stock clamped into its range, then
    shelves over capacity evacuated, largest free cell first), and how many units each cell
    could still give without leaving its range."""
    final = {}
    for s in inst.shelves:
        for p in inst.products:
            x, lo, hi = inst.stock[s, p], inst.lo(s, p), inst.hi(s, p)
            final[s, p] = max(lo, x if hi is None else min(x, hi))
        over = sum(final[s, p] for p in inst.products) - inst.capacity[s]
        for p in sorted(inst.products, key=lambda p: -(final[s, p] - inst.lo(s, p))):
            if over <= 0:
                break
            take = min(over, final[s, p] - inst.lo(s, p))
            final[s, p] -= take
            over -= take
    slack = {c: final[c] - inst.lo(*c) for c in final}
    return final, slack


# ---------------------------------------------------------------------------------------------
# step 2: flows per product
# ---------------------------------------------------------------------------------------------
def product_flows(inst: Instance, p: str, final: dict, slack: dict, room: dict[str, int],
                  limit: "MoveLimit | None" = None, ip_time: float = 2.0) -> dict[tuple[str, str], int]:
    """Units of ``p`` to move ``{(from, to): units}``; updates ``room`` (final free room). Routes
    on which no move fits within ``limit`` are left out. The fewest-moves IP gets ``ip_time``
    seconds (0: the min-cost flow only)."""
    import networkx as nx

    smallest = min(inst.magnitudes.values())
    supply = {s: inst.stock[s, p] - final[s, p] for s in inst.shelves if inst.stock[s, p] > final[s, p]}
    demand = {s: final[s, p] - inst.stock[s, p] for s in inst.shelves if inst.stock[s, p] < final[s, p]}
    need = sum(demand.values()) - sum(supply.values())
    if not supply and not demand:
        return {}
    g = nx.DiGraph()
    for s, m in supply.items():
        g.add_node(("out", s), demand=-m)
    for t, d in demand.items():
        g.add_node(("in", t), demand=d)
    free_src: list[str] = []
    free_dst: list[str] = []
    if need > 0:  # units must come from cells with slack: those already giving, then the fullest
        free_src = sorted((s for s in inst.shelves if slack[s, p] > 0 and s not in demand),
                          key=lambda s: (s not in supply, -final[s, p]))
        g.add_node("X", demand=-need)
        for rank, s in enumerate(free_src):
            g.add_edge("X", ("out", s), capacity=slack[s, p], weight=rank)
    elif need < 0:  # surplus goes where the range and the shelf have room: receivers first, most room first
        def take(s: str) -> int:
            hi = inst.hi(s, p)
            return min(room[s], hi - final[s, p] if hi is not None else room[s])
        free_dst = sorted((s for s in inst.shelves if s not in supply and take(s) > 0),
                          key=lambda s: (s not in demand, -room[s]))
        g.add_node("Y", demand=-need)
        for rank, s in enumerate(free_dst):
            g.add_edge(("in", s), "Y", capacity=take(s), weight=rank)
    sources = list(dict.fromkeys(list(supply) + free_src))
    sinks = list(dict.fromkeys(list(demand) + free_dst))
    arcs = {}
    sizes = sorted(set(inst.magnitudes.values()))
    big = largest_move(inst)  # a sum over every shelf: once, not per arc
    for s in sources:
        for t in sinks:
            if s != t and (limit is None or limit(s, t, p) >= smallest):
                g.add_edge(("out", s), ("in", t), weight=0)
                cap = limit(s, t, p) if limit is not None else float("inf")
                arcs[s, t] = min(big, max(z for z in sizes if z <= cap))
    extra_src = {s: slack[s, p] for s in free_src}
    extra_dst = {t: g[("in", t)]["Y"]["capacity"] for t in free_dst}
    try:
        flow = nx.min_cost_flow(g)
    except nx.NetworkXUnfeasible:
        raise Stuck(f"no flow of {p} meets the goal within the room left") from None
    out: dict[tuple[str, str], int] = {}
    for u, targets in flow.items():
        if not (isinstance(u, tuple) and u[0] == "out"):
            continue
        for v, x in targets.items():
            if x > 0 and isinstance(v, tuple) and v[0] == "in":
                out[u[1], v[1]] = x
    if ip_time > 0 and arcs:
        if len(arcs) <= IP_DIRECT_ARCS:  # small: the whole program, usually solved to optimality
            fewer = _fewest_moves_flow(supply, demand, extra_src, extra_dst, need, arcs, ip_time)
        else:
            fewer = _chunked_fewest_moves(supply, demand, extra_src, extra_dst, need, arcs, ip_time)

        def moves(f: dict) -> int:
            return sum(-(-x // arcs[a]) for a, x in f.items())
        if fewer is not None and moves(fewer) < moves(out):  # SCIP stopped early may do worse
            out = fewer
    for (s, t), x in out.items():  # the final state moves with the flow
        room[t] -= x - min(x, demand.get(t, 0))
        demand[t] = max(0, demand.get(t, 0) - x)
        room[s] += max(0, x - supply.get(s, 0))
        supply[s] = max(0, supply.get(s, 0) - x)
    return out


def _chunked_fewest_moves(supply: dict, demand: dict, extra_src: dict, extra_dst: dict, need: int,
                          arcs: dict[tuple[str, str], int], time_limit: float) -> Optional[dict]:
    """Full moves first, then the fewest moves for the rest: when every route carries the same
    most per move (no rule narrows one), each cell's whole multiples of it are paired off as full
    moves, and only the remainders (under one move per cell) and the cells with slack go to
    :func:`_fewest_moves_flow`, a far smaller program, solved at its root only (SCIP's
    heuristics; the same answer on every machine while within the time limit). At 50 shelves x 10
    products this reaches 327 moves against a per-cell bound of 315, where the whole program,
    stopped at its time limit, stays about 15% above it. None when the remainder program finds
    nothing."""
    sizes = set(arcs.values())
    flows: dict[tuple[str, str], int] = {}
    supply, demand = dict(supply), dict(demand)
    if len(sizes) == 1 and all((s, t) in arcs for s in supply for t in demand if s != t):
        big = sizes.pop()
        src = [s for s in supply for _ in range(supply[s] // big)]
        dst = [t for t in demand for _ in range(demand[t] // big)]
        for s, t in zip(src, dst):  # supply and demand cells differ, so s != t
            flows[s, t] = flows.get((s, t), 0) + big
            supply[s] -= big
            demand[t] -= big
    supply = {s: v for s, v in supply.items() if v}
    demand = {t: v for t, v in demand.items() if v}
    if not supply and not demand and not need:
        return flows
    rest = {(s, t): b for (s, t), b in arcs.items()
            if (s in supply or s in extra_src) and (t in demand or t in extra_dst)}
    if len(rest) > IP_ARCS:
        return None
    more = _fewest_moves_flow(supply, demand, extra_src, extra_dst, need, rest, time_limit, nodes=1)
    if more is None:
        return None
    for a, x in more.items():
        flows[a] = flows.get(a, 0) + x
    return flows


#: the last per-product programs and their answers (:func:`_fewest_moves_flow`)
_SOLVED_FLOWS: "OrderedDict[tuple, Optional[dict]]" = OrderedDict()
_SOLVED_FLOWS_MAX = 512
_SOLVED_FLOWS_LOCK = threading.Lock()


def _fewest_moves_flow(supply: dict, demand: dict, extra_src: dict, extra_dst: dict, need: int,
                       arcs: dict[tuple[str, str], int], time_limit: float = 2.0,
                       nodes: int = 0) -> Optional[dict]:
    """:func:`_solve_fewest_moves_flow`, remembered: the same program (the same cells, amounts,
    preferences and arcs, in the same order) is answered as before. Why: a re-plan after a
    fault (:mod:`pipflow.execution`) solves the whole goal again from the observed state, and
    every product the fault and the moves made since did not touch poses exactly the program it
    posed the first time; at 100 shelves x 20 products these programs are most of a re-plan's
    time. The answer is a copy (callers may not share it)."""
    key = (tuple(supply.items()), tuple(demand.items()), tuple(extra_src.items()), tuple(extra_dst.items()),
           need, tuple(arcs.items()), time_limit, nodes)
    with _SOLVED_FLOWS_LOCK:
        if key in _SOLVED_FLOWS:
            _SOLVED_FLOWS.move_to_end(key)
            hit = _SOLVED_FLOWS[key]
            return dict(hit) if hit is not None else None
    found = _solve_fewest_moves_flow(supply, demand, extra_src, extra_dst, need, arcs, time_limit, nodes)
    with _SOLVED_FLOWS_LOCK:
        _SOLVED_FLOWS[key] = dict(found) if found is not None else None
        while len(_SOLVED_FLOWS) > _SOLVED_FLOWS_MAX:
            _SOLVED_FLOWS.popitem(last=False)
    return found


def _solve_fewest_moves_flow(supply: dict, demand: dict, extra_src: dict, extra_dst: dict, need: int,
                             arcs: dict[tuple[str, str], int], time_limit: float = 2.0,
                             nodes: int = 0) -> Optional[dict]:
    """One product's transfers ``{(from, to): units}`` in the fewest moves (each arc carries at
    most ``arcs[from, to]`` units per move), by a small SCIP integer program; then the fewest
    units, then cells earlier in ``extra_src``/``extra_dst`` (the preferred ones). ``nodes``: stop
    after that many branch-and-bound nodes (1: the root and SCIP's heuristics; a limit on work,
    unlike time, gives the same answer on every machine). None when SCIP finds no solution (the
    caller falls back to the min-cost flow).

    Why not the flow alone: it minimises units, and moves are ceil(units / 6) per arc, so a flow
    that splits 12 units as 7 + 5 costs 4 moves where 6 + 6 costs 2."""
    # deferred import: pyscipopt costs 0.3 s to load, and the allocation loads it anyway
    from pyscipopt import Model, quicksum

    if not arcs:
        return None
    m = Model("product-moves")
    m.hideOutput()
    m.setParam("limits/time", time_limit)
    if nodes:
        m.setParam("limits/totalnodes", nodes)
    total = sum(supply.values()) + sum(extra_src.values()) + 1
    y = {a: m.addVar(vtype="I", lb=0, ub=total) for a in arcs}
    n = {a: m.addVar(vtype="I", lb=0, ub=total) for a in arcs}
    for a, big in arcs.items():
        m.addCons(y[a] <= big * n[a])
        m.addCons(y[a] >= n[a])
    e_src = {s: m.addVar(vtype="I", lb=0, ub=c) for s, c in extra_src.items()}
    e_dst = {t: m.addVar(vtype="I", lb=0, ub=c) for t, c in extra_dst.items()}
    out_of: dict[str, list] = {}  # each cell's arcs in the order of ``arcs``: one pass, not one per cell
    into: dict[str, list] = {}
    for a in arcs:
        out_of.setdefault(a[0], []).append(y[a])
        into.setdefault(a[1], []).append(y[a])
    for s in dict.fromkeys([*supply, *extra_src]):  # a fixed order: SCIP's answer depends on it
        m.addCons(quicksum(out_of.get(s, [])) == supply.get(s, 0) + (e_src[s] if s in e_src else 0))
    for t in dict.fromkeys([*demand, *extra_dst]):
        m.addCons(quicksum(into.get(t, [])) == demand.get(t, 0) + (e_dst[t] if t in e_dst else 0))
    if e_src:
        m.addCons(quicksum(e_src.values()) == max(need, 0))
    if e_dst:
        m.addCons(quicksum(e_dst.values()) == max(-need, 0))
    rank = {**{s: i for i, s in enumerate(extra_src)}, **{t: i for i, t in enumerate(extra_dst)}}
    units = quicksum(y.values())
    prefer = quicksum(rank[s] * v for s, v in e_src.items()) + quicksum(rank[t] * v for t, v in e_dst.items())
    m.setObjective(total * len(rank) * quicksum(n.values()) + len(rank) * units + prefer
                   if rank else total * quicksum(n.values()) + units, "minimize")
    m.optimize()
    if m.getNSols() == 0:
        return None
    sol = m.getBestSol()
    return {a: int(round(sol[y[a]])) for a in arcs if round(sol[y[a]]) > 0}


# ---------------------------------------------------------------------------------------------
# how much one move may carry
# ---------------------------------------------------------------------------------------------
MoveLimit = Callable[[str, str, str], float]


def no_limit(src: str, dst: str, product: str) -> float:
    return float("inf")


def coalition_limit(robots: dict[str, float], rules: list[dict] | None) -> MoveLimit:
    """The most units one move (src, dst, product) can carry: the total ``carry`` of the robots
    that the ``only``/``never`` rules allow on it. Planning within it means the robot level always
    finds a coalition (e.g. "only robot1 may move to shelf1", robot1 carrying one unit, gets
    one-unit moves to shelf1 and full-size moves elsewhere). Names compare as PDDL does, ignoring case."""
    team = {str(r).lower(): float(c) for r, c in robots.items()}
    rules = [{k: ([str(x).lower() for x in v] if k in ("only", "never") else str(v).lower()) for k, v in r.items()}
             for r in rules or []]

    everyone = set(team)
    whole_team = sum(team[r] for r in everyone)  # a move no rule names: the whole team, summed once

    @functools.lru_cache(maxsize=None)
    def limit(src: str, dst: str, product: str) -> float:
        move = {"from": src.lower(), "to": dst.lower(), "product": product.lower()}
        matching = [rule for rule in rules if all(rule[k] == move[k] for k in move if k in rule)]
        if not matching:
            return whole_team
        allowed = set(everyone)
        for rule in matching:
            allowed -= set(rule.get("never", ()))
            if "only" in rule:
                allowed &= set(rule["only"])
        return sum(team[r] for r in allowed)

    return limit


def sizes_within(sizes: list[int], cap: float) -> list[int]:
    return [z for z in sizes if z <= cap]


# ---------------------------------------------------------------------------------------------
# step 3: moves
# ---------------------------------------------------------------------------------------------
def split_amount(x: int, sizes: list[int]) -> list[int]:
    """``x`` as the fewest parts from ``sizes`` (coin change; sizes sorted, largest used greedily
    for the bulk, exact DP for the remainder)."""
    big = max(sizes)
    q, r = divmod(x, big)
    if r and q:  # let the DP use one big part too: with sizes {3, 4, 6}, 7 = 4 + 3, not 6 + 1
        q, r = q - 1, r + big
    best: list[Optional[list[int]]] = [[]] + [None] * r
    for v in range(1, r + 1):
        for c in sizes:
            if c <= v and best[v - c] is not None and (best[v] is None or len(best[v - c]) + 1 < len(best[v])):
                best[v] = best[v - c] + [c]
    if best[r] is None:
        raise Stuck(f"{x} units cannot be made from magnitudes {sorted(set(sizes))}")
    return [big] * q + sorted(best[r], reverse=True)


@dataclass
class Move:
    src: str
    dst: str
    product: str
    units: int


def flows_to_moves(flows: dict[tuple[str, str, str], int], sizes: list[int], limit: MoveLimit = no_limit) -> list[Move]:
    moves = []
    for (s, t, p), x in flows.items():
        for u in split_amount(x, sizes_within(sizes, limit(s, t, p))):
            moves.append(Move(s, t, p, u))
    return moves


# ---------------------------------------------------------------------------------------------
# step 4: order under capacity
# ---------------------------------------------------------------------------------------------
def order_moves(inst: Instance, moves: list[Move], sizes: list[int], limit: MoveLimit = no_limit) -> list[Move]:
    """A sequence of the moves (split or parked where capacity forces it) that keeps every shelf
    within capacity and every count non-negative."""
    stock = dict(inst.stock)
    load = dict(inst.load)
    pending = list(moves)
    done: list[Move] = []
    budget = 4 * len(moves) + 100

    def room(s: str) -> int:
        return inst.capacity[s] - load[s]

    def run(m: Move) -> None:
        stock[m.src, m.product] -= m.units
        stock[m.dst, m.product] = stock.get((m.dst, m.product), 0) + m.units
        load[m.src] -= m.units
        load[m.dst] += m.units
        done.append(m)

    while pending:
        budget -= 1
        if budget < 0:
            raise Stuck("no order of the moves keeps every shelf within capacity")
        ready = [m for m in pending if stock.get((m.src, m.product), 0) >= m.units and room(m.dst) >= m.units]
        if ready:
            waited_on = {m.dst for m in pending if room(m.dst) < m.units}
            pick = next((m for m in ready if m.src in waited_on), ready[0])
            pending.remove(pick)
            run(pick)
            continue
        # every pending move waits for room: split one to the room there is, or park units
        blocked = [m for m in pending if stock.get((m.src, m.product), 0) >= m.units]
        if not blocked:
            raise Stuck("moves wait for units that never arrive")
        fit = [m for m in blocked if 0 < room(m.dst) and any(z <= room(m.dst) for z in sizes)]
        if fit:
            m = fit[0]
            part = max(z for z in sizes_within(sizes, limit(m.src, m.dst, m.product)) if z <= min(room(m.dst), m.units))
            pending.remove(m)
            run(Move(m.src, m.dst, m.product, part))
            if m.units - part:
                pending.append(Move(m.src, m.dst, m.product, m.units - part))
            continue
        m = blocked[0]
        parks = sorted((s for s in inst.shelves if s not in (m.src, m.dst) and room(s) > 0
                        and min(limit(m.src, s, m.product), limit(s, m.dst, m.product)) >= min(sizes)),
                       key=room, reverse=True)
        if not parks:
            raise Stuck("every shelf is full: no room to park units while full shelves swap")
        park = parks[0]
        cap = min(limit(m.src, park, m.product), limit(park, m.dst, m.product))
        part = max(z for z in sizes_within(sizes, cap) if z <= min(room(park), m.units))
        pending.remove(m)
        run(Move(m.src, park, m.product, part))
        pending.append(Move(park, m.dst, m.product, part))
        if m.units - part:
            pending.append(Move(m.src, m.dst, m.product, m.units - part))
    return done


# ---------------------------------------------------------------------------------------------
# step 5: exact search where capacity costs moves
# ---------------------------------------------------------------------------------------------
def largest_move(inst: Instance) -> int:
    """The most units any move can ever carry: the largest magnitude, but never more than the
    free room of the whole warehouse, which no move changes (units only change shelves), and a
    move needs that much room on its target. With one free slot every move carries one unit.
    (A shelf that starts over capacity only sheds units, so its excess is the most room it adds.)"""
    room = sum(inst.capacity[s] - inst.load[s] + max(0, inst.load[s] - inst.capacity[s]) for s in inst.shelves)
    return max(1, min(max(inst.magnitudes.values()), room))


class _Cells:
    """The instance as flat arrays for the search: cell index ``i * P + j`` for shelf i, product j."""

    def __init__(self, inst: Instance, limit: "MoveLimit"):
        self.S, self.P = len(inst.shelves), len(inst.products)
        self.inst = inst
        self._move_limit = limit
        self.lo = [inst.lo(s, p) for s in inst.shelves for p in inst.products]
        self.hi = [inst.hi(s, p) for s in inst.shelves for p in inst.products]
        self.cap = [inst.capacity[s] for s in inst.shelves]
        self.big = largest_move(inst)
        self.sizes = sorted(set(inst.magnitudes.values()))

    @functools.cached_property
    def limit(self) -> list[list[list[float]]]:
        """Most units per move, ``[i][k][j]`` for shelf i -> shelf k, product j: S x S x P
        entries, built only when a search asks (the lower bound never does; 400 shelves x 40
        products are 6.4 million)."""
        inst, limit = self.inst, self._move_limit
        return [[[limit(a, b, p) for p in inst.products] for b in inst.shelves] for a in inst.shelves]

    def start(self) -> tuple[tuple, tuple]:
        inst = self.inst
        return (tuple(inst.stock[s, p] for s in inst.shelves for p in inst.products),
                tuple(inst.load[s] for s in inst.shelves))

    def h_product(self, stock: tuple, j: int) -> int:
        """Admissible moves still needed for product ``j`` (see :func:`lower_bound`)."""
        big, P = self.big, self.P
        need_in = need_out = deficit = surplus = spare_in = spare_out = 0
        for c in range(j, self.S * P, P):
            x, lo, hi = stock[c], self.lo[c], self.hi[c]
            if x < lo:
                d = lo - x
                k = -(-d // big)
                need_in += k
                deficit += d
                spare_in += min(k * big - d, big if hi is None else hi - lo)
            elif hi is not None and x > hi:
                e = x - hi
                k = -(-e // big)
                need_out += k
                surplus += e
                spare_out += min(k * big - e, hi - lo)
        if deficit > surplus + spare_out:
            need_out += -(-(deficit - surplus - spare_out) // big)
        if surplus > deficit + spare_in:
            need_in += -(-(surplus - deficit - spare_in) // big)
        return max(need_in, need_out)

    def successors(self, stock: tuple, load: tuple):
        """``(i, k, j, units)`` for every applicable move: shelf i -> shelf k, product j."""
        S, P, sizes, limits = self.S, self.P, self.sizes, self.limit
        targets = [(k, self.cap[k] - load[k]) for k in range(S) if self.cap[k] > load[k]]
        if not targets:
            return
        for i in range(S):
            base = i * P
            for j in range(P):
                x = stock[base + j]
                if x <= 0:
                    continue
                for k, room in targets:
                    if k == i:
                        continue
                    most = x if x < room else room
                    cap = limits[i][k][j]
                    if cap < most:
                        most = cap
                    for u in sizes:
                        if u > most:
                            break
                        yield i, k, j, u


@dataclass
class SearchResult:
    moves: Optional[list]  # None: nothing shorter than the bound given was found
    complete: bool  # the search space (below the bound) was exhausted: the answer is proven
    lower_bound: int  # no plan has fewer moves
    expanded: int


def search_moves(inst: Instance, limit: "MoveLimit" = None, shorter_than: Optional[int] = None,
                 budget: int = DEFAULT_BUDGET, deadline: Optional[float] = None) -> SearchResult:
    """A* over stock states with the admissible :func:`lower_bound`, for a plan of fewer than
    ``shorter_than`` moves. ``complete`` says the search ended within ``budget`` (generated states times cells per state; and
    before ``deadline``, a ``time.monotonic()`` value): then ``moves`` is a plan with the fewest
    moves, or None if none is shorter than ``shorter_than``."""
    cells = _Cells(inst, limit or no_limit)
    P = cells.P
    stock0, load0 = cells.start()
    hs0 = [cells.h_product(stock0, j) for j in range(P)]
    h0 = sum(hs0)
    cap = shorter_than if shorter_than is not None else math.inf
    if h0 >= cap:
        return SearchResult(None, True, h0, 0)
    tie = itertools.count()
    best_g = {stock0: 0}
    parent: dict[tuple, tuple] = {stock0: None}
    frontier = [(h0, 0, next(tie), stock0, load0, tuple(hs0))]
    expanded = generated = 0
    size = len(stock0)
    floor = h0
    while frontier:
        f, neg_g, _, stock, load, hs = heapq.heappop(frontier)
        g = -neg_g
        if g > best_g.get(stock, math.inf):
            continue
        floor = max(floor, f)
        if f >= cap:
            break
        if sum(hs) == 0:
            path = []
            node = stock
            while parent[node] is not None:
                prev, move = parent[node]
                path.append(move)
                node = prev
            path.reverse()
            s, p = inst.shelves, inst.products
            return SearchResult([Move(s[i], s[k], p[j], u) for i, k, j, u in path], True, g, expanded)
        expanded += 1
        if deadline is not None and expanded % 64 == 0 and time.monotonic() > deadline:
            return SearchResult(None, False, floor, expanded)
        for i, k, j, u in cells.successors(stock, load):
            generated += size
            if generated > budget:
                return SearchResult(None, False, floor, expanded)
            nxt = list(stock)
            nxt[i * P + j] -= u
            nxt[k * P + j] += u
            nxt = tuple(nxt)
            ng = g + 1
            if ng >= best_g.get(nxt, math.inf):
                continue
            hj = cells.h_product(nxt, j)
            nf = ng + sum(hs) - hs[j] + hj
            if nf >= cap:
                continue
            best_g[nxt] = ng
            parent[nxt] = (stock, (i, k, j, u))
            nl = list(load)
            nl[i] -= u
            nl[k] += u
            nhs = hs[:j] + (hj,) + hs[j + 1:]
            heapq.heappush(frontier, (nf, -ng, next(tie), nxt, tuple(nl), nhs))
    return SearchResult(None, True, cap if cap != math.inf else floor, expanded)


def lower_bound(inst: Instance) -> int:
    """An admissible lower bound on the number of moves: per product, every cell below its range
    needs ceil(deficit / largest move) moves in and every cell above it as many out; units the
    deficits need beyond what the surpluses (and their moves' spare room) give need further moves
    out of other cells, and symmetrically. Blind to capacity."""
    cells = _Cells(inst, no_limit)
    stock, _ = cells.start()
    return sum(cells.h_product(stock, j) for j in range(cells.P))


# ---------------------------------------------------------------------------------------------
# the whole planner
# ---------------------------------------------------------------------------------------------
@dataclass
class Outcome:
    moves: list
    optimal: bool  # proven to have the fewest moves
    lower_bound: int
    note: str = ""


def flow_plan(inst: Instance, limit: "MoveLimit" = None, checked: bool = False) -> list["Move"]:
    """Steps 1-4: the flow plan (no search). Raises :class:`Unsolvable` or :class:`Stuck`.
    ``checked``: the caller already ran :func:`check_final_state` (a max-flow over products and
    shelves: not twice per solve)."""
    limit = limit or no_limit
    if not checked:
        check_final_state(inst)
    final, slack = plan_targets(inst)
    room = {s: inst.capacity[s] - sum(final[s, p] for p in inst.products) for s in inst.shelves}
    flows: dict[tuple[str, str, str], int] = {}
    deadline = time.monotonic() + IP_SECONDS
    for p in inst.products:
        share = min(2.0, deadline - time.monotonic())
        for (s, t), x in product_flows(inst, p, final, slack, room, limit, max(share, 0.0)).items():
            flows[s, t, p] = x
    sizes = sorted(set(inst.magnitudes.values()))
    return order_moves(inst, flows_to_moves(flows, sizes, limit), sizes, limit)


def solve_instance(inst: Instance, limit: "MoveLimit" = None, budget: int = DEFAULT_BUDGET,
                   deadline: Optional[float] = None) -> Outcome:
    """The flow plan, improved by the bounded exact search when it may not be the shortest."""
    limit = limit or no_limit
    check_final_state(inst)
    try:
        moves: Optional[list] = flow_plan(inst, limit, checked=True)
    except Stuck as exc:
        moves, stuck = None, exc
    bound = lower_bound(inst)
    if moves is not None and len(moves) > bound and len(inst.shelves) ** 2 * len(inst.products) <= IP_CELLS:
        # the order-free IP (SCIP) is a tighter bound and proves most flow plans optimal at once
        ip, _ = fewest_moves(inst, time_limit=2.0)
        bound = max(bound, ip or 0)
    if moves is not None and len(moves) <= bound:
        return Outcome(moves, True, bound)
    if budget <= 0 or len(inst.shelves) * len(inst.products) > SEARCH_CELLS:
        if moves is None:
            raise stuck
        return Outcome(moves, False, bound, f"{len(moves)} moves; at least {bound} are needed")
    found = search_moves(inst, limit, len(moves) if moves is not None else None, budget, deadline)
    if found.moves is not None:
        return Outcome(found.moves, True, len(found.moves))
    if moves is None:
        if found.complete:
            raise Unsolvable("no sequence of moves reaches the goal within every shelf's capacity")
        raise stuck
    if found.complete:
        return Outcome(moves, True, len(moves))
    lb = max(bound, found.lower_bound)
    return Outcome(moves, False, lb, f"{len(moves)} moves; at least {lb} are needed "
                   f"(search stopped after {found.expanded} states)")


def plan_instance(inst: Instance, limit: "MoveLimit" = None, budget: int = DEFAULT_BUDGET) -> list["Move"]:
    """Moves (in executable order) that take ``inst`` to its goal, none larger than ``limit``.

    Raises :class:`Unsolvable` (proven) or :class:`Stuck` (heuristic gave up)."""
    return solve_instance(inst, limit, budget).moves


def moves_to_plan(inst: Instance, moves: list["Move"]) -> list[dict]:
    """pipflow plan list; each move names the magnitude object of its amount, arguments in the
    order the action declares them."""
    by_amount = {}
    for name, k in sorted(inst.magnitudes.items()):
        by_amount.setdefault(k, name)
    out = []
    for m in moves:
        role = {"from": m.src, "to": m.dst, "product": m.product, "magnitude": by_amount[m.units]}
        out.append({"action": inst.action, "args": [role[r] for r in inst.arg_roles]})
    return out


# ---------------------------------------------------------------------------------------------
# UP engine
# ---------------------------------------------------------------------------------------------
try:
    import unified_planning as up
    from unified_planning.engines import Engine, PlanGenerationResult, PlanGenerationResultStatus
    from unified_planning.engines.mixins import OneshotPlannerMixin
    from unified_planning.model import ProblemKind
except ImportError:  # pragma: no cover - UP is a hard dependency
    raise


class TransportPlanner(Engine, OneshotPlannerMixin):
    """UP OneshotPlanner ``pipflow-transport`` (see the module docstring). Parameters:
    ``validate`` (default True): check each plan with UP's sequential plan validator;
    ``robots`` ({name: carry}) and ``rules`` (only/never rules): keep every move within what the
    robots allowed on it can carry (:func:`coalition_limit`); ``search_budget``: what the A* search
    may generate, in cells (:data:`DEFAULT_BUDGET`; 0: the flow plan only)."""

    def __init__(self, validate: bool = True, robots: dict | None = None, rules: list | None = None,
                 search_budget: int = DEFAULT_BUDGET, **kwargs: Any):
        Engine.__init__(self)
        OneshotPlannerMixin.__init__(self)
        self.validate = validate
        self.budget = int(search_budget)
        self.limit = coalition_limit(robots, rules) if robots else no_limit

    @property
    def name(self) -> str:
        return ENGINE_NAME

    @staticmethod
    def supported_kind() -> ProblemKind:
        kind = ProblemKind(version=2)
        kind.set_problem_class("ACTION_BASED")
        kind.set_typing("FLAT_TYPING")
        kind.set_fluents_type("INT_FLUENTS")
        kind.set_fluents_type("REAL_FLUENTS")
        kind.set_conditions_kind("NEGATIVE_CONDITIONS")
        kind.set_conditions_kind("EQUALITIES")
        kind.set_problem_type("SIMPLE_NUMERIC_PLANNING")
        kind.set_problem_type("GENERAL_NUMERIC_PLANNING")
        kind.set_effects_kind("INCREASE_EFFECTS")
        kind.set_effects_kind("DECREASE_EFFECTS")
        kind.set_effects_kind("FLUENTS_IN_NUMERIC_ASSIGNMENTS")
        kind.set_effects_kind("STATIC_FLUENTS_IN_NUMERIC_ASSIGNMENTS")
        kind.set_initial_state("UNDEFINED_INITIAL_NUMERIC")
        return kind

    @staticmethod
    def supports(problem_kind: ProblemKind) -> bool:
        return problem_kind <= TransportPlanner.supported_kind()

    @staticmethod
    def supports_plan_generation_result_status(status: Any) -> bool:
        return True

    def _result(self, status: Any, plan: Any = None, message: str = "") -> PlanGenerationResult:
        from unified_planning.engines import LogLevel, LogMessage

        logs = [LogMessage(LogLevel.INFO, message)] if message else []
        return PlanGenerationResult(status, plan, self.name, log_messages=logs)

    def _solve(self, problem: Any, heuristic: Optional[Callable] = None, timeout: Optional[float] = None,
               output_stream: Any = None) -> PlanGenerationResult:
        S = PlanGenerationResultStatus
        started = time.monotonic()
        try:
            inst = instance_from_problem(problem)
        except NotTransport as exc:
            return self._result(S.UNSUPPORTED_PROBLEM, message=f"not a transport problem: {exc}")
        except Unsolvable as exc:  # the goal itself is contradictory (e.g. at least 5 and at most 3)
            return self._result(S.UNSOLVABLE_PROVEN, message=str(exc))
        deadline = started + 0.5 * timeout if timeout is not None else None  # the rest: validation
        try:
            outcome = solve_instance(inst, self.limit, self.budget, deadline)
        except Unsolvable as exc:
            return self._result(S.UNSOLVABLE_PROVEN, message=str(exc))
        except Stuck as exc:
            return self._result(S.UNSOLVABLE_INCOMPLETELY, message=str(exc))
        plan = data_to_plan(problem, moves_to_plan(inst, outcome.moves))
        if self.validate:
            from unified_planning.shortcuts import PlanValidator

            with PlanValidator(name="sequential_plan_validator") as validator:
                check = validator.validate(problem, plan)
            if not check.status == up.engines.ValidationResultStatus.VALID:
                reason = "; ".join(m.message for m in check.log_messages or []) or str(check.reason)
                return self._result(S.INTERNAL_ERROR, message=f"{ENGINE_NAME} produced an invalid plan: {reason}")
        if outcome.optimal:
            return self._result(S.SOLVED_OPTIMALLY, plan, f"{len(outcome.moves)} moves, proven fewest")
        return self._result(S.SOLVED_SATISFICING, plan, outcome.note)


def fewest_moves(inst: Instance, time_limit: float = 60.0) -> tuple[int | None, bool]:
    """``(moves, proven)``: the order-free minimum number of moves from SCIP, and whether SCIP
    proved it optimal within ``time_limit`` (otherwise its best bound, rounded up, and False).
    ``(None, True)`` when no final state exists."""
    from pyscipopt import Model, quicksum  # deferred: pyscipopt costs 0.3 s to load

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

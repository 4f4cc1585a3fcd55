"""``pipflow-transport``: a planner of our own for transport-like numeric problems, as a UP engine.

Why: the warehouse domain is a transport problem (move k <= 6 units of one product between
shelves, never over a shelf's capacity). ENHSP's default search (gbfs + hadd) solves the paper's
small tasks in about a second with near-fewest moves, but it grows quickly (about 30 s already at
8 shelves x 6 products x 120 units) and ``enhsp-opt`` times out even on some paper tasks. The
structure is better served by network flow:

1. **Final state.** Listed goal counts are fixed. Units a goal does not place must end somewhere:
   existence of such a final state is a bipartite flow (free units of each product -> free room
   of the shelves where that product is not listed); no final state means *proven unsolvable*.
   Shelves that would end over capacity evacuate products the goal leaves free (largest first).
2. **Flows.** Per product, a networkx min-cost flow from surplus to deficit cells; when units
   must come from (or go to) cells that the goal leaves free, the fullest such cells are
   preferred, which keeps the number of distinct (from, to) pairs, hence moves, low.
3. **Moves.** Each arc's flow is cut into moves of at most the largest magnitude (6), the rest
   as few magnitudes as sum to it.
4. **Order.** Moves are sequenced so that stock never goes negative and no shelf ever exceeds its
   capacity. Moves out of a shelf that others wait on go first; when every waiting move targets a
   full shelf (a swap between full shelves), a move is split to fit the room there is or parked
   on a shelf with room (one extra move each): that is where capacity forces extra moves, which
   the flow lower bound cannot see.

Trade-off (measured by ``benchmarks/team_plans.py``): the flow step minimises units moved, not
moves. On the ten paper tasks every plan equals the fewest moves proven by an integer program
(ENHSP's default search also finds them, in 1-4 s instead of ~0.03 s); on a random 8 shelves x
6 products x 120 units instance it makes 24 moves where ENHSP makes 21 (in 43 s), and on
50 x 10 x 2000 it makes 381 moves against a cheap bound of 315 in about 1.5 s (validation
included) where ENHSP does not finish. So: optimal where the paper measures, fast everywhere,
not proven optimal in general, and the planner is incomplete when every shelf is full (no room to park):
it then answers UNSOLVABLE_INCOMPLETELY and the caller may fall back to ENHSP. In exchange it
plans 50 shelves x 10 products x 2000 units in well under a second. Each plan is checked by UP's
``sequential_plan_validator`` before it is returned (``validate=False`` skips that), so a bug
here shows as an engine error, never as a wrong plan.

Which problems: those written against the transport schema of ``domains/warehouse.pddl``:
fluents ``stock(shelf, product)``, ``load(shelf)``, ``capacity(shelf)``, ``amount(magnitude)``,
one action ``move-product(?from ?to ?product ?magnitude)``, and a goal that is a conjunction of
``(= (stock s p) n)``. Anything else is answered UNSUPPORTED_PROBLEM.
"""
from __future__ import annotations

import functools
import time
from dataclasses import dataclass
from typing import Any, Callable, Optional

ENGINE_NAME = "pipflow-transport"
ACTION = "move-product"
FLUENTS = {"stock": 2, "load": 1, "capacity": 1, "amount": 1}


class NotTransport(Exception):
    """The problem does not follow the transport schema (reason in the message)."""


class Unsolvable(Exception):
    """No final state satisfies the goal (proven); the message says why."""


class Stuck(Exception):
    """The heuristic found no move order (every shelf full); the problem may still be solvable."""


@dataclass
class Instance:
    """A transport problem in plain numbers, read from a UP problem (or built directly)."""

    shelves: list[str]
    products: list[str]
    stock: dict[tuple[str, str], int]
    capacity: dict[str, int]
    load: dict[str, int]
    magnitudes: dict[str, int]
    goal: dict[tuple[str, str], int]
    action: str = ACTION

    def total(self, product: str) -> int:
        return sum(self.stock.get((s, product), 0) for s in self.shelves)


# ---------------------------------------------------------------------------------------------
# reading a UP problem
# ---------------------------------------------------------------------------------------------
def _int(value: Any, what: str) -> int:
    v = float(value)
    if not v.is_integer():
        raise NotTransport(f"{what} = {value} is not a whole number")
    return int(v)


def instance_from_problem(problem: Any) -> Instance:
    """Read the transport schema out of a UP problem; :class:`NotTransport` if it does not fit."""
    from pipflow.pddl.common import initial_numbers, stock_goals

    fluents = {f.name: f for f in problem.fluents}
    for name, arity in FLUENTS.items():
        if name not in fluents or len(fluents[name].signature) != arity:
            raise NotTransport(f"no numeric fluent {name} with {arity} argument(s)")
    if not problem.has_action(ACTION) or len(problem.actions) != 1:
        raise NotTransport(f"the domain must have the single action {ACTION}")
    params = problem.action(ACTION).parameters
    if len(params) != 4:
        raise NotTransport(f"{ACTION} must take (?from ?to ?product ?magnitude)")
    shelf_t = fluents["stock"].signature[0].type
    product_t = fluents["stock"].signature[1].type
    mag_t = fluents["amount"].signature[0].type
    shelves = [o.name for o in problem.objects(shelf_t)]
    products = [o.name for o in problem.objects(product_t)]
    mags = [o.name for o in problem.objects(mag_t)]
    init = initial_numbers(problem)
    stock = {(s, p): _int(init.get(("stock", s, p), 0), f"(stock {s} {p})") for s in shelves for p in products}
    capacity = {}
    load = {}
    for s in shelves:
        if ("capacity", s) not in init:
            raise NotTransport(f"(capacity {s}) has no initial value")
        capacity[s] = _int(init[("capacity", s)], f"(capacity {s})")
        load[s] = _int(init.get(("load", s), sum(stock[s, p] for p in products)), f"(load {s})")
    magnitudes = {}
    for m in mags:
        if ("amount", m) in init and init[("amount", m)] > 0:
            magnitudes[m] = _int(init[("amount", m)], f"(amount {m})")
    if not magnitudes:
        raise NotTransport("no magnitude has a positive amount")
    goal_map, other = stock_goals(problem)
    if other:
        raise NotTransport(f"goal conditions other than (= (stock s p) n): {', '.join(other[:3])}")
    goal = {(s, p): n for s, items in goal_map.items() for p, n in items.items()}
    return Instance(shelves, products, stock, capacity, load, magnitudes, goal)


def instance_from_world(world: dict, goal: dict[str, dict[str, int]]) -> Instance:
    """The instance a world dict and a goal describe (with the magnitudes the writer writes)."""
    from pipflow.pddl.writer import magnitudes

    shelves, products = list(world["shelves"]), list(world["products"])
    stock = {(s, p): world["stock"].get(s, {}).get(p, 0) for s in shelves for p in products}
    return Instance(shelves, products, stock,
                    {s: world["shelves"][s]["capacity"] for s in shelves},
                    {s: sum(world["stock"].get(s, {}).values()) for s in shelves},
                    magnitudes(world),
                    {(s, p): n for s, items in goal.items() for p, n in items.items()})


# ---------------------------------------------------------------------------------------------
# step 1: the final state
# ---------------------------------------------------------------------------------------------
def check_final_state(inst: Instance) -> None:
    """Raise :class:`Unsolvable` with the reason when no final state meets the goal."""
    import networkx as nx

    for p in inst.products:
        listed = [s for s in inst.shelves if (s, p) in inst.goal]
        want = sum(inst.goal[s, p] for s in listed)
        have = inst.total(p)
        if want > have:
            raise Unsolvable(f"the goal needs {want} units of {p} but only {have} exist")
        if len(listed) == len(inst.shelves) and want != have:
            raise Unsolvable(f"the goal places {want} units of {p} on every shelf but {have} exist; "
                             "units cannot disappear")
    for s in inst.shelves:
        fixed = sum(n for (gs, _), n in inst.goal.items() if gs == s)
        if fixed > inst.capacity[s]:
            raise Unsolvable(f"the goal puts {fixed} units on {s} but its capacity is {inst.capacity[s]}")
    g = nx.DiGraph()
    free_total = 0
    for p in inst.products:
        free = inst.total(p) - sum(inst.goal.get((s, p), 0) for s in inst.shelves)
        if free <= 0:
            continue
        free_total += free
        g.add_edge("src", ("p", p), capacity=free)
        for s in inst.shelves:
            if (s, p) not in inst.goal:
                g.add_edge(("p", p), ("s", s))
    for s in inst.shelves:
        room = inst.capacity[s] - sum(n for (gs, _), n in inst.goal.items() if gs == s)
        g.add_edge(("s", s), "dst", capacity=room)
    if free_total:
        flow = nx.maximum_flow_value(g, "src", "dst") if "dst" in g and "src" in g else 0
        if flow < free_total:
            raise Unsolvable(f"{free_total} units that the goal leaves free must stay on some shelf, "
                             f"but only {flow} fit in the room the goal leaves")


def plan_targets(inst: Instance) -> tuple[dict[tuple[str, str], int], dict[tuple[str, str], int]]:
    """Mandatory changes: ``(target, evacuate)``: target final counts of listed cells, and units
    of free cells that must leave their shelf so that it ends within capacity."""
    target = dict(inst.goal)
    evacuate: dict[tuple[str, str], int] = {}
    for s in inst.shelves:
        final = sum(target.get((s, p), inst.stock[s, p]) for p in inst.products)
        over = final - inst.capacity[s]
        # free products on s, largest first: the fewest moves carry the overflow away
        free = sorted((p for p in inst.products if (s, p) not in inst.goal and inst.stock[s, p] > 0),
                      key=lambda p: -inst.stock[s, p])
        for p in free:
            if over <= 0:
                break
            take = min(over, inst.stock[s, p])
            evacuate[s, p] = take
            over -= take
    return target, evacuate


# ---------------------------------------------------------------------------------------------
# step 2: flows per product
# ---------------------------------------------------------------------------------------------
def product_flows(inst: Instance, p: str, target: dict, evacuate: dict, room: dict[str, int],
                  limit: "MoveLimit | None" = None) -> dict[tuple[str, str], int]:
    """Units of ``p`` to move ``{(from, to): units}``; updates ``room`` (final free room). Routes
    on which no move fits within ``limit`` are left out."""
    smallest = min(inst.magnitudes.values())
    import networkx as nx

    supply: dict[str, int] = {}
    demand: dict[str, int] = {}
    for s in inst.shelves:
        if (s, p) in target:
            d = target[s, p] - inst.stock[s, p]
            if d > 0:
                demand[s] = d
            elif d < 0:
                supply[s] = -d
        elif evacuate.get((s, p)):
            supply[s] = evacuate[s, p]
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
    if need > 0:  # units must come from cells the goal leaves free: fullest first
        free_src = sorted((s for s in inst.shelves if (s, p) not in target and s not in supply
                           and inst.stock[s, p] > 0), key=lambda s: -inst.stock[s, p])
        g.add_node("X", demand=-need)
        for rank, s in enumerate(free_src):
            g.add_edge("X", ("out", s), capacity=inst.stock[s, p], weight=rank)
    elif need < 0:  # surplus must go to shelves where p is free: most room first
        free_dst = sorted((s for s in inst.shelves if (s, p) not in target and room[s] > 0
                           and s not in supply), key=lambda s: -room[s])
        g.add_node("Y", demand=-need)
        for rank, s in enumerate(free_dst):
            g.add_edge(("in", s), "Y", capacity=room[s], weight=rank)
    sources = list(supply) + free_src
    sinks = list(demand) + free_dst
    for s in sources:
        for t in sinks:
            if s != t and (limit is None or limit(s, t, p) >= smallest):
                g.add_edge(("out", s), ("in", t), weight=0)
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
                if v[1] in free_dst:
                    room[v[1]] -= x
    return out


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

    @functools.lru_cache(maxsize=None)
    def limit(src: str, dst: str, product: str) -> float:
        move = {"from": src.lower(), "to": dst.lower(), "product": product.lower()}
        allowed = set(team)
        for rule in rules:
            if all(rule[k] == move[k] for k in move if k in rule):
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
# the whole planner
# ---------------------------------------------------------------------------------------------
def plan_instance(inst: Instance, limit: MoveLimit = no_limit) -> list[Move]:
    """Moves (in executable order) that take ``inst`` to its goal, none larger than ``limit``.

    Raises :class:`Unsolvable` (proven) or :class:`Stuck` (heuristic gave up)."""
    check_final_state(inst)
    target, evacuate = plan_targets(inst)
    final_load = {s: sum(target.get((s, p), inst.stock[s, p] - evacuate.get((s, p), 0)) for p in inst.products)
                  for s in inst.shelves}
    room = {s: inst.capacity[s] - final_load[s] for s in inst.shelves}
    flows: dict[tuple[str, str, str], int] = {}
    # products whose surplus must find room go first while room is plentiful; others after
    for p in inst.products:
        for (s, t), x in product_flows(inst, p, target, evacuate, room, limit).items():
            flows[s, t, p] = x
    sizes = sorted(set(inst.magnitudes.values()))
    return order_moves(inst, flows_to_moves(flows, sizes, limit), sizes, limit)


def moves_to_plan(inst: Instance, moves: list[Move]) -> list[dict]:
    """pipflow plan list; each move names the magnitude object of its amount."""
    by_amount = {}
    for name, k in sorted(inst.magnitudes.items()):
        by_amount.setdefault(k, name)
    return [{"action": inst.action, "args": [m.src, m.dst, m.product, by_amount[m.units]]} for m in moves]


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
    robots allowed on it can carry (:func:`coalition_limit`)."""

    def __init__(self, validate: bool = True, robots: dict | None = None, rules: list | None = None, **kwargs: Any):
        Engine.__init__(self)
        OneshotPlannerMixin.__init__(self)
        self.validate = validate
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
        from pipflow.pddl.common import data_to_plan

        S = PlanGenerationResultStatus
        started = time.monotonic()
        try:
            inst = instance_from_problem(problem)
        except NotTransport as exc:
            return self._result(S.UNSUPPORTED_PROBLEM, message=f"not a transport problem: {exc}")
        try:
            moves = plan_instance(inst, self.limit)
        except Unsolvable as exc:
            return self._result(S.UNSOLVABLE_PROVEN, message=str(exc))
        except Stuck as exc:
            return self._result(S.UNSOLVABLE_INCOMPLETELY, message=str(exc))
        if timeout is not None and time.monotonic() - started > timeout:
            return self._result(S.TIMEOUT, message=f"no plan within {timeout} s")
        plan = data_to_plan(problem, moves_to_plan(inst, moves))
        if self.validate:
            from unified_planning.shortcuts import PlanValidator

            with PlanValidator(name="sequential_plan_validator") as validator:
                check = validator.validate(problem, plan)
            if not check.status == up.engines.ValidationResultStatus.VALID:
                reason = "; ".join(m.message for m in check.log_messages or []) or str(check.reason)
                return self._result(S.INTERNAL_ERROR, message=f"{ENGINE_NAME} produced an invalid plan: {reason}")
        return self._result(S.SOLVED_SATISFICING, plan)


def register(env: Any) -> None:
    """Add ``pipflow-transport`` to a UP environment's engine factory (idempotent)."""
    if ENGINE_NAME not in env.factory.engines:
        env.factory.add_engine(ENGINE_NAME, __name__, "TransportPlanner")

"""The warehouse's side of execution under faults (:mod:`pipflow.execution`): what only the
warehouse knows about its world changing.

* **stock surprise**: a shelf holds another count of a product than the world file says (fewer
  units, or more); a robot that arrives at the shelf sees it. Drawn at a shelf the schedule first
  visits to take that product from, so it always matters.
* **play**: the pybullet simulation, its loads as the moment a move's work begins and its
  unloads as the moment it ends.
* **with_state**: the world with a stock the simulation reached, so that the warehouse's own
  problem writer writes the observed stock as a new problem.
* **drop place**: a robot that stops while carrying keeps its units; they lie on a small "shelf"
  where it stands, holding exactly what it carried (so a new plan may fetch them, and never
  parks anything else there).
* **feasibility**: whether the robots still working can reach the goal from a stock, checked
  without the planner: the verifier's count and room check, then an order-free integer program
  (SCIP) over the moves the robot rules leave to robots that still work (a unit moves from one
  shelf to another only where some coalition of allowed working robots carries at least one).
"""
from __future__ import annotations

import math
import random
from typing import Any

from pipflow.errors import FaultNotApplicable, InputError
from pipflow.execution.capability import Played
from pipflow.goalcounts import limits
from pipflow.pddl.names import pddl_name
from pipflow.suggest import did_you_mean
from pipflow.warehouse.problem import goal_in_world_names, goal_problems, magnitudes, stock_goals

#: the warehouse's name for a state surprise
SURPRISE_NAMES = ("stock-surprise",)


# ------------------------------------------------------------------------------------------
# surprises
# ------------------------------------------------------------------------------------------
def _words(shelf: str, product: str, count: int, records: int) -> str:
    return f"{shelf} holds {count} {product}, not {records} as the records say"


#: how a drawn stock surprise came about: units gone (stolen, damaged, never delivered), or units
#: put on another shelf than the records say (the same units, in the wrong place)
MISSING, MISPLACED = "missing", "misplaced"


def draw_surprise(world: dict, schedule: dict, graph: dict | None, rng: random.Random) -> dict | None:
    """A shelf the schedule first visits to take a product from holds fewer of it than the
    records say, drawn the way stock goes wrong in a warehouse (each half the time):

    * **missing**: 1 to 3 units (at most what is recorded there) are gone for good;
    * **misplaced**: they lie on another shelf with room for them (drawn among all shelves but
      the first), a shelf that then holds more than recorded. The two shelves are two parts of
      the surprise, each found when a robot first arrives there (``parts``): a robot that finds
      units missing does not know where they went.

    Drawn where the plan takes from, so that it always matters; never chosen so that the goal
    stays reachable: when the goal needed the units that are gone (or the room that misplaced
    ones take), the run's right answer is a refusal, and the bench counts it as such.
    :class:`FaultNotApplicable` when the plan takes from no shelf that holds units."""
    nodes = {n["id"]: n for n in (graph or {}).get("nodes", [])}
    first: dict[str, tuple[str, str]] = {}  # shelf -> (role of its first visit, product)
    for rec in sorted(schedule.get("subtasks", []), key=lambda r: (float(r["start"]), r["id"])):
        fields = (nodes.get(rec["id"]) or {}).get("fields") or {}
        for role in ("from", "to"):
            shelf = fields.get(role)
            if shelf in world["shelves"] and shelf not in first:
                first[shelf] = (role, fields.get("product"))
    candidates = sorted((s, p) for s, (role, p) in first.items()
                        if role == "from" and p in world["products"] and int(world["stock"].get(s, {}).get(p, 0)) > 0)
    if not candidates:
        raise FaultNotApplicable("the plan takes no product from a shelf that holds it (a first visit that loads), "
                                 "so no shelf's count can matter to it")
    shelf, product = rng.choice(candidates)
    records = int(world["stock"].get(shelf, {}).get(product, 0))
    k = rng.randint(1, min(3, records))
    short = {"place": shelf, "product": product, "count": records - k, "records": records, "places": [shelf],
             "words": _words(shelf, product, records - k, records)}
    how = MISSING if rng.random() < 0.5 else MISPLACED
    if how == MISPLACED:
        room = {t: int(info["capacity"]) - sum(int(n) for n in (world["stock"].get(t) or {}).values())
                for t, info in world["shelves"].items() if t != shelf and not info.get("drop")}
        hosts = sorted(t for t, free in room.items() if free >= k)
        if hosts:
            host = rng.choice(hosts)
            had = int(world["stock"].get(host, {}).get(product, 0))
            extra = {"place": host, "product": product, "count": had + k, "records": had, "places": [host],
                     "words": f"{_words(host, product, had + k, had)} ({k} misplaced from {shelf})"}
            short["words"] += f" ({k} misplaced, lying elsewhere)"
            return {"how": MISPLACED, "parts": [short, extra],
                    "words": f"{k} {product} recorded on {shelf} lie on {host}"}
        how = MISSING  # no shelf has room for them: they are gone
    short["words"] += f" ({k} missing)"
    return {**short, "how": how}


def check_surprise(world: dict, given: dict, where: str) -> dict:
    """``{place: SHELF, product: PRODUCT, count: N}`` (the true count) or ``delta: +-N``."""
    allowed = ("place", "product", "count", "delta")
    unknown = sorted(k for k in given if k not in allowed)
    if unknown:
        raise InputError(f"{where}: a stock-surprise has no field {', '.join(map(repr, unknown))}; its fields: "
                         f"place, product, and count (the true count) or delta (the difference from the records)")
    shelf, product = given.get("place"), given.get("product")
    if shelf not in world["shelves"]:
        raise InputError(f"{where}: unknown shelf {shelf!r}{did_you_mean(str(shelf), world['shelves'])}; "
                         f"shelves: {', '.join(world['shelves'])}")
    if product not in world["products"]:
        raise InputError(f"{where}: unknown product {product!r}{did_you_mean(str(product), world['products'])}")
    if ("count" in given) == ("delta" in given):
        raise InputError(f"{where}: give the true `count` or the `delta` from the records, one of them")
    value = given.get("count", given.get("delta"))
    if not isinstance(value, int) or isinstance(value, bool):
        raise InputError(f"{where}: count and delta are whole numbers of units, got {value!r}")
    records = int(world["stock"].get(shelf, {}).get(product, 0))
    count = value if "count" in given else records + value
    load = sum(world["stock"].get(shelf, {}).values()) - records + count
    if count < 0:
        raise InputError(f"{where}: {shelf} cannot hold {count} {product} (the records say {records})")
    if count == records:
        raise InputError(f"{where}: {count} {product} on {shelf} is what the records say: no surprise")
    if load > int(world["shelves"][shelf]["capacity"]):
        raise InputError(f"{where}: {count} {product} would put {load} units on {shelf}, over its capacity "
                         f"{world['shelves'][shelf]['capacity']}")
    return {"place": shelf, "product": product, "count": count, "records": records, "places": [shelf],
            "words": _words(shelf, product, count, records)}


def apply_surprise(world: dict, surprise: dict) -> dict:
    """The world whose shelf holds the surprise's true count (the difference from the records is
    added, so a world already changed elsewhere keeps its changes)."""
    shelf, product = surprise["place"], surprise["product"]
    items = dict(world["stock"].get(shelf) or {})
    out = {**world, "stock": {**world["stock"], shelf: items}}  # copied where it changes
    count = int(items.get(product, 0)) + int(surprise["count"]) - int(surprise["records"])
    if count:
        items[product] = count
    else:
        items.pop(product, None)
    return out


# ------------------------------------------------------------------------------------------
# the world's state, drop places
# ------------------------------------------------------------------------------------------
def with_state(world: dict, stock: dict) -> dict:
    """The world whose stock is ``stock`` (a simulation's final stock); a drop place holds room
    for exactly what it holds (nothing is parked on a stopped robot)."""
    out = {**world, "shelves": dict(world["shelves"])}  # copied where it changes
    out["stock"] = {s: {p: int(n) for p, n in (stock.get(s) or {}).items() if n} for s in out["shelves"]}
    for name, shelf in world["shelves"].items():
        if shelf.get("drop"):
            out["shelves"][name] = {**shelf, "capacity": sum(out["stock"][name].values())}
    return out


def drop_place(world: dict, robot: str, site: dict) -> tuple[dict, str]:
    """The world with a small shelf ``<robot>-cargo`` where the stopped robot stands, room for
    what it can carry (the simulation puts its units there; :func:`with_state` then fits the room
    to them)."""
    out = {**world, "shelves": dict(world["shelves"]), "stock": dict(world["stock"])}  # copied where it changes
    name, k = f"{robot}-cargo", 1
    while name in out["shelves"] or name in out["robots"] or name in out["products"]:
        k += 1
        name = f"{robot}-cargo{k}"
    carry = float(out["robots"][robot].get("skills", {}).get("carry", 0))
    out["shelves"][name] = {**{k2: site[k2] for k2 in ("x", "y", "width", "depth")}, "access": list(site["access"]),
                            "capacity": max(1, int(math.ceil(carry))), "drop": robot}
    out["stock"][name] = {}
    return out, name


# ------------------------------------------------------------------------------------------
# playing and planning
# ------------------------------------------------------------------------------------------
def play(world: dict, schedule: dict, graph: dict | None) -> Played:
    """The pybullet simulation of ``schedule``: a move's load is when its work began, its unload
    when it ended."""
    # deferred: pulls pybullet (only runs with faults play schedules here)
    from pipflow.warehouse.simulation import simulate

    result = simulate(world, schedule, graph, None, trace=True)
    began = {e["subtask"]: float(e["time"]) for e in result["events"] if e["event"] == "load"}
    ended = {e["subtask"]: float(e["time"]) for e in result["events"] if e["event"] == "unload"}
    return Played(result["final_stock"], began, ended, list(result["failures"]), dict(result["interrupted"]), result)


def updated_problem(parsed: Any, world: dict) -> Any | None:
    """The accepted problem with the world's stock as its initial state: a clone of ``parsed`` whose
    ``stock``, ``load`` and ``capacity`` are the world's, drop places added as shelves. Why not the
    writer's text: UP's reader takes seconds on a large warehouse (200 x 20 cells: 15 s), and a
    recovery must not. None when the problem's other objects differ from the world's (a lost
    robot changed which move sizes the team can carry): then the text is parsed."""
    from unified_planning.model import Object  # deferred: pulls unified_planning (a recovery's re-plan only)

    problem = parsed.clone()
    kinds = {t.name: t for t in problem.user_types}
    if set(kinds) != {"shelf", "product", "magnitude"}:
        return None
    have = {o.name for o in problem.objects(kinds["magnitude"])}
    if have != {pddl_name(m) for m in magnitudes(world)} or \
            {o.name for o in problem.objects(kinds["product"])} != {pddl_name(p) for p in world["products"]}:
        return None
    for shelf in world["shelves"]:
        if not problem.has_object(pddl_name(shelf)):
            problem.add_object(Object(pddl_name(shelf), kinds["shelf"]))
    stock, load, capacity = problem.fluent("stock"), problem.fluent("load"), problem.fluent("capacity")
    products = [problem.object(pddl_name(p)) for p in world["products"]]
    for shelf, info in world["shelves"].items():
        s = problem.object(pddl_name(shelf))
        items = world["stock"].get(shelf) or {}
        for name, obj in zip(world["products"], products):
            problem.set_initial_value(stock(s, obj), int(items.get(name, 0)))
        problem.set_initial_value(load(s), sum(int(n) for n in items.values()))
        problem.set_initial_value(capacity(s), int(info["capacity"]))
    return problem


def plan_goal(parsed: Any, world: dict) -> dict:
    """The accepted problem's stock goal, spelled as the world spells its names."""
    return goal_in_world_names(stock_goals(parsed)[0], world)


def feasibility(world: dict, goal: dict, constraints: list[dict]) -> tuple[bool | None, str]:
    """Module docstring: counts and room (the verifier's check), robots that can still carry, and
    an order-free flow over the moves the rules leave to them (SCIP)."""
    messages, refusal = goal_problems(world, goal)
    if refusal or messages:
        return False, refusal or "; ".join(messages)
    robots = {r: float(info.get("skills", {}).get("carry", 0)) for r, info in world.get("robots", {}).items()}
    if not any(c > 0 for c in robots.values()):
        return False, "no robot that still works can carry anything"
    if not any(_carry_allowed(robots, [], "", "", "") >= 1.0 for _ in (0,)):
        return False, "the robots still working cannot carry one unit even together"
    if not constraints:  # every move is open to every robot: the verifier's check is the answer
        return True, "the units exist, the shelves have room, and the robots still working may make every move"
    shelves, products = list(world["shelves"]), list(world["products"])
    if len(shelves) * (len(shelves) - 1) * len(products) > MOST_ARCS:
        return None, f"too many moves for the order-free check ({len(shelves)} shelves x {len(products)} products)"
    arcs = [(s, t, p) for s in shelves for t in shelves if s != t for p in products]
    allowed = [a for a in arcs if _carry_allowed(robots, constraints, *a) >= 1.0]
    return _flow(world, goal, allowed)


#: the most (from, to, product) moves the order-free check takes on (beyond: unknown)
MOST_ARCS = 20_000


def _carry_allowed(robots: dict[str, float], rules: list[dict], src: str, dst: str, product: str) -> float:
    """What the working robots the rules allow on a move can carry together."""
    move = {"from": src, "to": dst, "product": product}
    allowed = set(robots)
    for rule in rules or []:
        if all(rule[k] == move[k] for k in move if k in rule):
            allowed -= set(rule.get("never") or ())
            if "only" in rule:
                allowed &= set(rule["only"])
    return sum(robots[r] for r in allowed)


def _flow(world: dict, goal: dict, arcs: list[tuple[str, str, str]]) -> tuple[bool, str]:
    """Is there a final stock, within every goal range and every capacity, that units can reach
    along ``arcs`` (in any order; multi-hop allowed)? SCIP, as a feasibility problem."""
    from pyscipopt import Model, quicksum  # deferred: pyscipopt costs 0.3 s to load

    m = Model("recovery-feasibility")
    m.hideOutput()
    x = {a: m.addVar(vtype="I", lb=0) for a in arcs}
    final = {}
    for s in world["shelves"]:
        for p in world["products"]:
            have = int(world["stock"].get(s, {}).get(p, 0))
            flow = quicksum(x[a] for a in arcs if a[1] == s and a[2] == p) - quicksum(x[a] for a in arcs if a[0] == s and a[2] == p)
            f = m.addVar(vtype="I", lb=0)
            m.addCons(f == have + flow)
            final[(s, p)] = f
            if p in (goal.get(s) or {}):
                lo, hi = limits(goal[s][p])
                m.addCons(f >= lo)
                if hi is not None:
                    m.addCons(f <= hi)
        m.addCons(quicksum(final[(s, p)] for p in world["products"]) <= int(world["shelves"][s]["capacity"]))
    m.setParam("limits/solutions", 1)
    m.optimize()
    if m.getNSols() > 0:
        return True, ("the units exist, the shelves have room, and the robots still working may make the moves "
                      "(order-free check)")
    return False, ("no final stock meets the goal with the moves the robots still working may make "
                   "(the rules leave some units to robots that stopped)")

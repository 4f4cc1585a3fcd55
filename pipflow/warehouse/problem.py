"""World + goal -> PDDL problem text for stock problems (shelves, products, magnitudes), the
default task domain's (``domains/warehouse.pddl``).

The back half of the offline problem generator: its objects and initial state are exactly the
world's (every stock count written, zeros included, because ENHSP treats an unset fluent as
undefined rather than 0), and the goal is one ``(= (stock s p) n)`` per exact count and, for a
bound (``{at_least: n, at_most: m}``, see :mod:`pipflow.goalcounts`), ``(>= (stock s p) n)`` and/or
``(<= (stock s p) m)``: numeric goals that ENHSP, UP's validator and the goal reader
(:func:`stock_goals`) all understand.

The rest is the stock problem's other half in the loop: its goal read back from a problem
(:func:`stock_goals`, names in the world's spelling), the debugger's check of a problem's objects
and initial state against the world (:func:`world_mismatches`) and the verifier's check of its
goal (:func:`goal_problems`); :class:`pipflow.warehouse.domain.WarehouseDomain` points the
generic steps at them.
"""
from __future__ import annotations

import math
from fractions import Fraction
from typing import Any

from pipflow.errors import InputError
from pipflow.goalcounts import from_limits, is_bound, value_problems
from pipflow.pddl.common import goal_conditions, parse
from pipflow.pddl.convert import initial_numbers
from pipflow.pddl.debugger import find_form
from pipflow.pddl.names import pddl_name, world_spelling
from pipflow.pddl.textpos import find_word
from pipflow.suggest import closest, did_you_mean_clause
from pipflow.taskdomain import DEFAULT_DOMAIN

LARGEST_MOVE = 6
"""The paper's domain moves 1..6 units at a time (objects magnitude1..magnitude6)."""


def magnitudes(world: dict) -> dict[str, int]:
    """The magnitude objects of a world's problems and the units each stands for (``amount``):
    1..6 as in the paper, but never more than the whole team can carry at once, so that the
    team-level planner cannot plan a move no coalition of robots could make."""
    team = sum(float(r.get("skills", {}).get("carry", 0)) for r in world.get("robots", {}).values())
    largest = max(1, min(LARGEST_MOVE, int(team)))
    return {f"magnitude{k}": k for k in range(1, largest + 1)}


def cell_conditions(shelf: str, product: str, value: Any) -> list[str]:
    """The PDDL goal conditions of one goal value: an exact count or a bound.

    Raises :class:`InputError` for a value that is neither (a negative count, ``at_least`` above
    ``at_most``...): a problem must never say something other than the goal it was given."""
    problems = value_problems(value)
    if problems:
        raise InputError(f"goal value of {product} on {shelf}: {'; '.join(problems)}")
    fluent = f"(stock {shelf} {product})"
    if not is_bound(value):
        return [f"(= {fluent} {value})"]
    out = []
    if "at_least" in value:
        out.append(f"(>= {fluent} {value['at_least']})")
    if "at_most" in value:
        out.append(f"(<= {fluent} {value['at_most']})")
    return out


def write_problem(world: dict, goal: dict[str, dict[str, Any]], name: str = "task",
                  domain: str = DEFAULT_DOMAIN) -> str:
    """PDDL problem text for moving the world's stock to ``goal`` (``{shelf: {product: value}}``,
    a value being an exact count or a bound mapping)."""
    shelves, products = list(world["shelves"]), list(world["products"])
    amounts = magnitudes(world)
    lines = [f"(define (problem {name})", f"  (:domain {domain})", "  (:objects"]
    lines.append(f"    {' '.join(shelves)} - shelf")
    lines.append(f"    {' '.join(products)} - product")
    lines.append(f"    {' '.join(amounts)} - magnitude)")
    lines.append("  (:init")
    for s in shelves:
        stock = world["stock"].get(s, {})
        counts = " ".join(f"(= (stock {s} {p}) {stock.get(p, 0)})" for p in products)
        lines.append(f"    {counts}")
        lines.append(f"    (= (load {s}) {sum(stock.values())}) (= (capacity {s}) {world['shelves'][s]['capacity']})")
    lines.append("    " + " ".join(f"(= (amount {m}) {k})" for m, k in amounts.items()) + ")")
    conds = [c for s, items in goal.items() for p, v in items.items() for c in cell_conditions(s, p, v)]
    lines.append("  (:goal (and")
    lines += [f"    {c}" for c in conds]
    lines.append("  )))")
    return "\n".join(lines) + "\n"


def problem_object(world: dict, goal: dict[str, dict[str, Any]], domain_text: str, name: str = "task") -> Any:
    """The problem :func:`write_problem` writes, built with unified-planning's API instead of
    parsed from the text: equal (``==``) to what UP's PDDL reader makes of that text against
    ``domain_text`` (tests/test_scale_parse.py checks it on random worlds and goals).

    Why: UP's reader (pyparsing) takes 16 s for a 400-shelf x 40-product problem (17,000 facts),
    the API 0.4 s. The offline reader hands the object to :func:`pipflow.pddl.common.share` keyed
    by the text it wrote, so the debugger, planner and verifier use it without parsing: the text
    is our writer's, so its parse is known. Names are spelled as UP's reader spells them (lower
    case), numbers read as it reads them (a whole number an Int, else a Real). Raises whatever
    UP raises when ``domain_text`` is not a domain these names and fluents fit (the caller then
    shares nothing and the text is parsed as any other)."""
    from unified_planning.model import Object  # deferred: unified_planning (only the offline reader builds)

    problem = parse(domain_text, None).clone()
    problem.name = pddl_name(name)
    em = problem.environment.expression_manager
    kinds = {t: problem.user_type(t) for t in ("shelf", "product", "magnitude")}
    stock, load, capacity, amount = (problem.fluent(f) for f in ("stock", "load", "capacity", "amount"))
    amounts = magnitudes(world)
    objects: dict[str, Any] = {}
    for kind, names in (("shelf", world["shelves"]), ("product", world["products"]), ("magnitude", amounts)):
        for n in names:
            objects[n] = Object(pddl_name(n), kinds[kind], problem.environment)
    problem.add_objects(list(objects.values()))

    def number(value: Any) -> Any:  # as the reader reads the number the writer wrote
        n = Fraction(str(value))
        return em.Int(n.numerator) if n.denominator == 1 else em.Real(n)

    for s in world["shelves"]:
        held = world["stock"].get(s, {})
        for p in world["products"]:
            problem.set_initial_value(stock(objects[s], objects[p]), number(held.get(p, 0)))
        problem.set_initial_value(load(objects[s]), number(sum(held.values())))
        problem.set_initial_value(capacity(objects[s]), number(world["shelves"][s]["capacity"]))
    for m, k in amounts.items():
        problem.set_initial_value(amount(objects[m]), number(k))
    conditions = []
    for s, items in goal.items():
        for p, value in items.items():
            cell_conditions(s, p, value)  # the writer's refusals, the same
            fluent = stock(objects[s], objects[p])
            if not is_bound(value):
                conditions.append(em.Equals(fluent, number(value)))
                continue
            if "at_least" in value:
                conditions.append(em.GE(fluent, number(value["at_least"])))
            if "at_most" in value:
                conditions.append(em.LE(fluent, number(value["at_most"])))
    problem.add_goal(em.And(conditions))
    return problem


# ---------------------------------------------------------------------------------------------
# reading a problem's goal back
# ---------------------------------------------------------------------------------------------
def stock_goals(problem: Any) -> tuple[dict[str, dict[str, Any]], list[str]]:
    """The goal's stock conditions as ``{shelf: {product: value}}``, plus a list of goal
    conditions of any other form (as text) that pipflow's goal checks do not understand.

    ``=``, ``>=``, ``<=``, ``>``, ``<`` of ``(stock s p)`` with a number are read, and each
    cell's conditions merged into one goal value of :mod:`pipflow.goalcounts`: an int when an
    exact count is stated and agrees with the bounds, else ``{at_least, at_most}`` (a
    contradiction is kept so that the verifier names it)."""
    cells: dict[tuple[str, str], list] = {}  # (shelf, product) -> [lo, hi, exact stated]
    other: list[str] = []
    for g in goal_conditions(problem):
        cell = _stock_comparison(g)
        if cell is None:
            other.append(str(g))
            continue
        (s, p), lo, hi = cell
        c = cells.setdefault((s, p), [None, None, False])
        if lo is not None:
            c[0] = lo if c[0] is None else max(c[0], lo)
        if hi is not None:
            c[1] = hi if c[1] is None else min(c[1], hi)
        c[2] = c[2] or g.is_equals()
    goal: dict[str, dict[str, Any]] = {}
    for (s, p), (lo, hi, exact) in cells.items():
        goal.setdefault(s, {})[p] = from_limits(lo, hi, exact)
    return goal, other


def _stock_comparison(g: Any) -> tuple[tuple[str, str], int | None, int | None] | None:
    """``((shelf, product), lowest, highest)`` for a comparison of ``(stock s p)`` with a number
    (whole limits: strict comparisons and fractions rounded inward, counts being whole), or None
    for any other condition (an exact count that is a fraction included)."""
    if not (g.is_equals() or g.is_le() or g.is_lt()) or len(g.args) != 2:
        return None
    a, b = g.args
    stock_left = a.is_fluent_exp()
    fexp, num = (a, b) if stock_left else (b, a)
    if not (fexp.is_fluent_exp() and fexp.fluent().name == "stock" and len(fexp.args) == 2
            and (num.is_int_constant() or num.is_real_constant())):
        return None
    v = float(num.constant_value())
    cell = (str(fexp.args[0]), str(fexp.args[1]))
    if g.is_equals():
        return (cell, int(v), int(v)) if v.is_integer() else None
    strict = g.is_lt()
    if stock_left:  # stock <= v  /  stock < v
        hi = int(v) - 1 if strict and v.is_integer() else math.floor(v)
        return cell, None, hi
    lo = int(v) + 1 if strict and v.is_integer() else math.ceil(v)  # v <= stock  /  v < stock
    return cell, lo, None


def goal_in_world_names(goal: dict[str, dict[str, int]], world: dict | None) -> dict[str, dict[str, int]]:
    """A goal ``{shelf: {product: n}}`` spelled as the world spells its names."""
    names = world_spelling(world)
    return {names.get(s, s): {names.get(p, p): n for p, n in items.items()} for s, items in goal.items()}


# ---------------------------------------------------------------------------------------------
# the checks of pddl.debug and pddl.verify against the world
# ---------------------------------------------------------------------------------------------
def world_mismatches(problem: Any, text: str, world: dict) -> list[str]:
    """Every way the parsed stock problem's objects and initial state differ from the world's
    (shelves, products, stock, loads, capacities, magnitudes)."""
    out: list[str] = []
    shelves, products = world["shelves"], world["products"]
    by_type: dict[str, list[str]] = {}
    for o in problem.all_objects:
        by_type.setdefault(str(o.type), []).append(o.name)
    amounts = magnitudes(world)
    # UP reads names in lower case: compare the world's names as UP spells them
    expect = {"shelf": [pddl_name(s) for s in shelves], "product": [pddl_name(p) for p in products],
              "magnitude": list(amounts)}
    for typ, names in expect.items():
        have = by_type.get(typ, [])
        for n in have:
            if n not in names:
                out.append(f"{find_word(text, n)}object {n!r} ({typ}) is not in the world{did_you_mean_clause(n, names)}; "
                           f"the world's {typ} objects are {', '.join(names)}")
        for n in names:
            if n not in have:
                out.append(f"the problem lacks {typ} {n!r} of the world; declare it in :objects as '{n} - {typ}'")
    for typ in by_type:
        if typ not in expect:
            out.append(f"objects of type {typ!r} are not part of this domain's worlds")
    init = initial_numbers(problem)
    want: dict[tuple, int] = {}
    for s in shelves:
        for p in products:
            want[("stock", pddl_name(s), pddl_name(p))] = world["stock"].get(s, {}).get(p, 0)
        want[("load", pddl_name(s))] = sum(world["stock"].get(s, {}).values())
        want[("capacity", pddl_name(s))] = world["shelves"][s]["capacity"]
    for m, k in amounts.items():
        want[("amount", m)] = k
    declared = {o.name for o in problem.all_objects}
    for key, value in want.items():
        if not all(a in declared for a in key[1:]):
            continue  # already reported as a missing object
        form = f"({' '.join(key)})"
        if key not in init:
            out.append(f"{form} has no initial value; the world's is {value}: add (= {form} {value}) to :init")
        elif init[key] != value:
            what = {"stock": "units of {2} on {1}", "load": "units in all on {1}", "capacity": "the capacity of {1}",
                    "amount": "the units of {1}"}[key[0]].format(*key)
            out.append(f"{find_form(text, *key)}(= {form} {init[key]}) but the world has {value} "
                       f"({what} is {value}); the initial state must be the world's: write (= {form} {value})")
    for key, value in init.items():
        if key not in want and all(a in declared for a in key[1:]):
            out.append(f"{find_form(text, *key)}unexpected initial value (= ({' '.join(key)}) {value})")
    return out


def goal_problems(world: dict, goal: dict[str, dict[str, Any]]) -> tuple[list[str], str | None]:
    """``(messages, refusal)`` for a goal ``{shelf: {product: value}}`` in ``world``, a value
    being an exact count or a bound ``{at_least, at_most}`` (:mod:`pipflow.goalcounts`).

    Unknown names and malformed values are messages (the problem is wrong, a better problem may
    fix it); goals no final state of the world meets are a refusal (no problem can fix the
    command): :func:`pipflow.warehouse.feasibility.infeasibility_reasons` says why."""
    # deferred: pulls networkx (~200 ms; paid when a goal is checked, not by importers of the verifier)
    from pipflow.warehouse.feasibility import infeasibility_reasons

    messages = []
    for s, items in goal.items():
        if s not in world["shelves"]:
            near = closest(s, world["shelves"])
            messages.append(f"the goal names shelf {s!r}, which is not in the world"
                            + (f" (did you mean {near[0]!r}?)" if near else ""))
        for p, n in items.items():
            if p not in world["products"]:
                near = closest(p, world["products"])
                messages.append(f"the goal names product {p!r}, which is not in the world"
                                + (f" (did you mean {near[0]!r}?)" if near else ""))
            messages += [f"the goal for {p} on {s}: {why}" for why in value_problems(n)]
    if messages:
        return messages, None
    reasons = infeasibility_reasons(world, goal)
    if reasons:
        return reasons, "the command cannot be done in this world: " + "; ".join(reasons)
    return [], None

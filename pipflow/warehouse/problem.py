"""World + goal -> PDDL problem text for stock problems (shelves, products, magnitudes), the
default task domain's (``domains/warehouse.pddl``).

The back half of the offline problem generator: its objects and initial state are exactly the
world's (every stock count written, zeros included, because ENHSP treats an unset fluent as
undefined rather than 0), and the goal is one ``(= (stock s p) n)`` per exact count and, for a
bound (``{at_least: n, at_most: m}``, see :mod:`pipflow.goalcounts`), ``(>= (stock s p) n)`` and/or
``(<= (stock s p) m)``: numeric goals that ENHSP, UP's validator and the goal reader
(:func:`pipflow.pddl.common.stock_goals`) all understand.
"""
from __future__ import annotations

from typing import Any

from pipflow.errors import InputError
from pipflow.goalcounts import is_bound, value_problems
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


def goal_conditions(shelf: str, product: str, value: Any) -> list[str]:
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
    conds = [c for s, items in goal.items() for p, v in items.items() for c in goal_conditions(s, p, v)]
    lines.append("  (:goal (and")
    lines += [f"    {c}" for c in conds]
    lines.append("  )))")
    return "\n".join(lines) + "\n"

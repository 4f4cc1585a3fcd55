"""Does any final state meet a goal in a world? The verifier's refusal reasons, in words.

A final state puts every unit that exists on some shelf (units neither appear nor disappear),
never more than a shelf's capacity, and each goal cell within its value (an exact count or a bound
``{at_least, at_most}``, :mod:`pipflow.goalcounts`). Whether one exists is a flow problem: place
each cell's lowest allowed count first; the units left over of each product must then fit in the
cells that may take more (up to ``at_most``, or without limit where the goal is silent) and in the
room the shelves have left. A maximum flow (networkx) answers that exactly and in whole units.

The simple reasons (a count over a shelf's capacity, more units than exist, too few places for the
units that exist) are checked first so that the refusal names the cause a user can act on; the
flow catches every remaining case. The order of moves is not considered here: whether the planner
finds a route through full shelves is the planner's question.
"""
from __future__ import annotations

from typing import Any

import networkx as nx

from pipflow.goalcounts import is_bound, limits


def _cells(world: dict, goal: dict) -> dict[tuple[str, str], tuple[int, int | None]]:
    """(shelf, product) -> (lowest, highest) final count; unlisted cells are (0, None)."""
    out = {(s, p): (0, None) for s in world["shelves"] for p in world["products"]}
    for s, items in goal.items():
        for p, value in items.items():
            out[s, p] = limits(value)
    return out


def _units(value: Any, lo: int) -> str:
    return f"at least {lo}" if is_bound(value) else str(lo)


def infeasibility_reasons(world: dict, goal: dict[str, dict[str, Any]]) -> list[str]:
    """Why no final state meets ``goal`` (empty when one exists). ``goal`` must name only shelves
    and products of ``world`` and hold valid values (the verifier checks that first)."""
    shelves, products = list(world["shelves"]), list(world["products"])
    cap = {s: int(world["shelves"][s]["capacity"]) for s in shelves}
    total = {p: sum(int(world["stock"].get(s, {}).get(p, 0)) for s in shelves) for p in products}
    cells = _cells(world, goal)
    value_of = {(s, p): v for s, items in goal.items() for p, v in items.items()}

    reasons = []
    for (s, p), v in value_of.items():
        lo = cells[s, p][0]
        if lo > cap[s]:
            reasons.append(f"{s} cannot hold {_units(v, lo)} units of {p}: its capacity is {cap[s]}")
    for p in products:
        listed = [(s, p) for s in shelves if (s, p) in value_of]
        want = sum(cells[c][0] for c in listed)
        bounded = any(is_bound(value_of[c]) for c in listed)
        if want > total[p]:
            reasons.append(f"the goal needs {'at least ' if bounded else ''}{want} units of {p} "
                           f"but only {total[p]} exist")
        highs = [cells[s, p][1] for s in shelves]
        if all(h is not None for h in highs) and sum(highs) < total[p]:
            if bounded:
                reasons.append(f"the goal allows at most {sum(highs)} units of {p} on the shelves but "
                               f"{total[p]} exist; units cannot disappear")
            else:
                reasons.append(f"the goal places {sum(highs)} units of {p} on every shelf but "
                               f"{total[p]} exist; units cannot disappear")
    for s in shelves:
        listed = [(s, p) for p in products if (s, p) in value_of]
        fixed = sum(cells[c][0] for c in listed)
        if fixed > cap[s] and len(listed) > 1:
            bounded = any(is_bound(value_of[c]) for c in listed)
            reasons.append(f"the goal puts {'at least ' if bounded else ''}{fixed} units on {s} "
                           f"but its capacity is {cap[s]}")
    if reasons:
        return reasons
    room = {s: cap[s] - sum(cells[s, p][0] for p in products) for s in shelves}
    free_total, flow = _leftover_flow(shelves, products, room, total, cells)
    if flow >= free_total:
        return []
    for p in products:  # one product alone without room names the product to blame
        free, alone = _leftover_flow(shelves, [p], room, total, cells)
        if alone < free:
            reasons.append(f"{free} units of {p} must stay on some shelf, but the goal leaves room "
                           f"for only {alone} of them")
    return reasons or [f"{free_total} units that the goal leaves free must stay on some shelf, "
                       f"but only {flow} fit in the room the goal leaves"]


def _leftover_flow(shelves: list[str], products: list[str], room: dict[str, int], total: dict[str, int],
                   cells: dict[tuple[str, str], tuple[int, int | None]]) -> tuple[int, int]:
    """``(units of ``products`` left over once every cell holds its lowest count, units of those
    that fit)``; ``room``: what each shelf has left once every cell holds its lowest count."""
    g = nx.DiGraph()
    g.add_node("src")
    g.add_node("dst")
    free_total = 0
    for p in products:
        free = total[p] - sum(cells[s, p][0] for s in shelves)
        if free <= 0:
            continue
        free_total += free
        g.add_edge("src", ("p", p), capacity=free)
        for s in shelves:
            lo, hi = cells[s, p]
            if hi is None:
                g.add_edge(("p", p), ("s", s))  # no capacity attribute: unlimited
            elif hi > lo:
                g.add_edge(("p", p), ("s", s), capacity=hi - lo)
    for s in shelves:
        g.add_edge(("s", s), "dst", capacity=max(0, room[s]))
    if not free_total:
        return 0, 0
    return free_total, int(nx.maximum_flow_value(g, "src", "dst"))



def final_ranges(world: dict, goal: dict[str, dict[str, Any]],
                 cells: list[tuple[str, str]]) -> dict[tuple[str, str], tuple[int, int]] | None:
    """For each (shelf, product) cell of ``cells``: the fewest and the most units it holds in the
    final states that meet ``goal`` (every unit on some shelf, capacities kept, each goal cell
    within its value); None when no final state meets the goal. Why: two goals accept the same
    final states exactly when these ranges agree on every cell either goal states (the states a
    goal accepts are those of a box cut by conservation and capacity, and such a set is contained
    in a box exactly when its range on each of the box's cells is), which is how the bench tells a
    goal that lists 0 for the shelves a gathering empties from one that leaves them to
    conservation (:mod:`pipflow.warehouse.meaning`).

    Each end is a minimum-cost flow (networkx's network simplex: exact, whole units): the units
    left once every cell holds its lowest count flow to the cells that may take more, costed
    only on the cell asked about. ``goal`` and ``cells`` must name shelves and products of the
    world."""
    if infeasibility_reasons(world, goal):
        return None
    shelves, products = list(world["shelves"]), list(world["products"])
    cap = {s: int(world["shelves"][s]["capacity"]) for s in shelves}
    total = {p: sum(int(world["stock"].get(s, {}).get(p, 0)) for s in shelves) for p in products}
    limits_of = _cells(world, goal)
    room = {s: cap[s] - sum(limits_of[s, p][0] for p in products) for s in shelves}
    free = {p: total[p] - sum(limits_of[s, p][0] for s in shelves) for p in products}
    out = {}
    for cell in cells:
        lo, hi = limits_of[cell]
        if free[cell[1]] <= 0 or hi == lo or room[cell[0]] <= 0:
            out[cell] = (lo, lo)
            continue
        out[cell] = (lo + _extra_units(cell, +1, shelves, products, room, free, limits_of),
                     lo + _extra_units(cell, -1, shelves, products, room, free, limits_of))
    return out


def _extra_units(cell: tuple[str, str], sign: int, shelves: list[str], products: list[str], room: dict[str, int],
                 free: dict[str, int], limits_of: dict[tuple[str, str], tuple[int, int | None]]) -> int:
    """Units above its lowest count that ``cell`` holds when every left-over unit is placed and
    the cell's share is as small (``sign`` +1) or as large (-1) as it can be."""
    g = nx.DiGraph()
    g.add_node("dst", demand=sum(max(0, free[p]) for p in products))
    for p in products:
        if free[p] <= 0:
            continue
        g.add_node(("p", p), demand=-free[p])
        for s in shelves:
            lo, hi = limits_of[s, p]
            width = free[p] if hi is None else min(free[p], hi - lo)
            if width > 0:
                g.add_edge(("p", p), ("s", s), capacity=width, weight=sign if (s, p) == cell else 0)
    for s in shelves:
        if room[s] > 0:
            g.add_edge(("s", s), "dst", capacity=room[s], weight=0)
    flow = nx.min_cost_flow(g)
    return int(flow[("p", cell[1])].get(("s", cell[0]), 0)) if ("p", cell[1]) in flow else 0

"""The team-level PDDL problem of a garden goal: the world's facts as the initial state, the goal
as conditions on the domain's predicates and fluents (garden.pddl). It names no robot: robots
enter at allocation, from the action metadata."""
from __future__ import annotations

from typing import Any


def write_problem(world: dict, goal: dict, domain_name: str = "garden", name: str = "task") -> str:
    """PDDL problem text for ``goal`` (the reader's goal form) in ``world``."""
    beds, taps, stores, crops = list(world["beds"]), list(world["taps"]), list(world["stores"]), list(world["crops"])
    init = [f"({fluent} {' '.join(args)})" if value is True else f"(= ({fluent} {' '.join(args)}) {value})"
            for (fluent, args), value in initial_facts(world).items()]
    conds = [f"(watered {b})" for b in goal.get("watered", [])]
    conds += [f"(clear {b})" for b in goal.get("clear", [])]
    for s, items in (goal.get("stored") or {}).items():
        conds += [c for crop, value in items.items() for c in _compare(f"(stored {s} {crop})", value)]
    for b, items in (goal.get("ripe") or {}).items():
        conds += [c for crop, value in items.items() for c in _compare(f"(ripe {b} {crop})", value)]
    objects = [f"{' '.join(names)} - {kind}" for names, kind in
               ((beds, "bed"), (taps, "tap"), (stores, "store"), (crops, "crop")) if names]
    lines = [f"(define (problem {name})", f"  (:domain {domain_name})",
             "  (:objects " + "\n             ".join(objects) + ")",
             "  (:init", *(f"    {f}" for f in init), "  )",
             "  (:goal (and", *(f"    {c}" for c in conds), "  ))", ")"]
    return "\n".join(lines) + "\n"


def initial_facts(world: dict) -> dict[tuple[str, tuple[str, ...]], bool | int]:
    """The initial state of ``world``: true predicates and every fluent's value (zeros included)."""
    crops = list(world["crops"])
    facts: dict[tuple[str, tuple[str, ...]], bool | int] = {}
    for b, spec in world["beds"].items():
        facts[("overgrown" if spec["overgrown"] else "clear", (b,))] = True
        if spec["watered"]:
            facts[("watered", (b,))] = True
        facts.update({("ripe", (b, c)): spec["ripe"].get(c, 0) for c in crops})
    for s, spec in world["stores"].items():
        facts.update({("stored", (s, c)): spec["holds"].get(c, 0) for c in crops})
        facts[("room", (s,))] = spec["room"] - sum(spec["holds"].values())
    facts.update({("weight", (c,)): spec["weight"] for c, spec in world["crops"].items()})
    return facts


def _compare(fluent: str, value: Any) -> list[str]:
    """An exact count n as n <= x <= n (two bounds: every numeric planner reads them); a bound
    mapping as its one or two sides."""
    if isinstance(value, dict):
        out = []
        if value.get("at_least") is not None:
            out.append(f"(>= {fluent} {int(value['at_least'])})")
        if value.get("at_most") is not None:
            out.append(f"(<= {fluent} {int(value['at_most'])})")
        return out
    return [f"(>= {fluent} {int(value)})", f"(<= {fluent} {int(value)})"]

"""World names and PDDL names.

PDDL is case-insensitive and UP reads every name in lower case, while a world may spell its
things and robots in any case (``A1``, ``SKU-7781``). Problems are checked in lower
case, and what comes back out of UP (plans, goals) is mapped back to the world's spelling here,
so every later step (allocation rules, travel, simulation, scoring) sees the world's own names.
A world whose names differ only in case is rejected when it is loaded.
"""
from __future__ import annotations

from pipflow.taskdomains import task_domain


def pddl_name(name: str) -> str:
    """How UP spells a world name."""
    return name.lower()


def world_spelling(world: dict | None) -> dict[str, str]:
    """Lower-case name -> the world's spelling, for every named thing of the world."""
    if not world:
        return {}
    sections = task_domain(world).name_sections  # where the world keeps the names of its things
    return {pddl_name(n): n for section in sections for n in (world.get(section) or {})}


def plan_in_world_names(plan: list[dict] | None, world: dict | None) -> list[dict] | None:
    """A plan whose object arguments are spelled as the world spells them."""
    if plan is None or not world:
        return plan
    names = world_spelling(world)
    return [{**step, "args": [names.get(a, a) for a in step["args"]]} for step in plan]

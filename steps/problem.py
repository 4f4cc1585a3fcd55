"""Problem generation from a structured goal: the offline generator's back half.

Until (and besides) the language step, a workflow can write the team-level problem straight from a
goal ``{shelf: {product: n}}``. The language step fills the same interface: world + goal (or a
command) in, PDDL problem text out.
"""
from __future__ import annotations

import re
from typing import Annotated

from pipflow import Doc, PathStr, StepContext, step
from pipflow.taskdomain import pddl_domain_name
from pipflow.taskdomains import task_domain


@step("problem.write",
      doc="Write the team-level PDDL problem for a goal with the world's task domain's writer: the world's objects and initial state, and the goal in the domain's form (counts: one (= ...) per count, (>= ...)/(<= ...) per bound).",
      outputs={"problem": "string"},
      cacheable=True)
def write(
    ctx: StepContext,
    world: Annotated[dict | None, Doc("world dict from world.load")],
    goal: Annotated[dict | None, Doc("goal in the world's task domain's form (the default domain's: {place: {item: units or {at_least, at_most}}})")],
    domain: Annotated[PathStr, Doc("team-level PDDL domain (its name goes into the problem)")],
    name: Annotated[str, Doc("problem name")] = "task",
) -> dict:
    """Returns ``problem=None`` (and logs why) when the world or goal is missing, so a skipped
    upstream step does not crash the run."""
    if world is None or goal is None:
        ctx.log("problem.write: no " + ("world" if world is None else "goal") + "; no problem written")
        return {"problem": None}
    task = task_domain(world)
    text = ctx.resolve_path(domain).read_text()
    problem = task.write_problem(world, goal, pddl_domain_name(text, task.name),
                                 name=re.sub(r"[^\w-]", "-", name) or "task")
    ctx.write_artifact("problem.pddl", problem)
    return {"problem": problem}

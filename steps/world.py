"""World step: load and validate a world file with its task domain's loader (the file's top-level
``domain:`` key; none: the default domain), see :meth:`pipflow.taskdomain.TaskDomain.load_world`."""
from __future__ import annotations

from typing import Annotated

from pipflow import Doc, PathStr, StepContext, step


@step("world.load",
      doc="Load a world file (its task domain's format: floor, shelves, products, stock, robots by default), "
          "validated with every problem located.",
      outputs={"world": "object"},
      cacheable=True)
def load(
    ctx: StepContext,
    path: Annotated[PathStr, Doc("world YAML file, relative to the workflow file; its `domain:` key names "
                                 "its task domain")],
    seed: Annotated[int | None, Doc("vary the robots' start positions reproducibly (none: as in the file)")] = None,
) -> dict:
    """Raises WorldError (exit 2) listing each problem with file:line:col, InputError for an
    unknown ``domain:``; returns the normalized world dict of docs/architecture.md."""
    from pipflow.taskdomains import declared_domain

    file = ctx.resolve_path(path)
    domain = declared_domain(file)
    world = domain.load_world(file, seed=seed)
    ctx.log(f"world {world['name']}: {domain.describe(world)}")
    return {"world": world}

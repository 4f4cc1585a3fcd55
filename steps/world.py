"""World step: load and validate a world file (heavy work in :mod:`pipflow.warehouse.world`)."""
from __future__ import annotations

from typing import Annotated

from pipflow import Doc, PathStr, StepContext, step


@step("world.load",
      doc="Load a world file (floor, shelves, products, stock, robots), validated with every problem located.",
      outputs={"world": "object"},
      cacheable=True)
def load(
    ctx: StepContext,
    path: Annotated[PathStr, Doc("world YAML file, relative to the workflow file")],
    seed: Annotated[int | None, Doc("vary the robots' start positions reproducibly (none: as in the file)")] = None,
) -> dict:
    """Raises WorldError (exit 2) listing each problem with file:line:col; returns the normalized
    world dict of docs/architecture.md."""
    from pipflow.starts import vary_starts
    from pipflow.warehouse.world import load_world

    world = vary_starts(load_world(ctx.resolve_path(path)), seed)
    ctx.log(f"world {world['name']}: {len(world['shelves'])} shelves, {len(world['products'])} products, "
            f"{len(world['robots'])} robots")
    return {"world": world}

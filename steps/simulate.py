"""Step ``simulate.pybullet``: execute a schedule in headless pybullet (see
:mod:`pipflow.warehouse.simulation`). Thin on purpose: the library does the work, this declares the face."""
from __future__ import annotations

from typing import Annotated

from pipflow import Doc, StepContext, step


@step(
    "simulate.pybullet",
    doc="Execute the schedule in a headless pybullet warehouse; read stock and travel back from the bodies.",
    outputs={
        "final_stock": "object", "executed": "integer", "failed": "integer", "failures": "array",
        "exe": "number", "travel": "object", "tc_max": "number", "tc_avg": "number", "tc_avg_moved": "number",
        "goal_met": "boolean", "gcr": "number", "peak_load": "object", "stray_units": "integer",
        "jumps": "object",
        "makespan": "number", "pictures": "array",
    },
    version="1",
)
def simulate_pybullet(
    ctx: StepContext,
    world: Annotated[dict, Doc("the world (output of world.load)")],
    schedule: Annotated[dict, Doc("the schedule (output of schedule)")],
    graph: Annotated[dict | None, Doc("the dependency graph: units, fields and route per subtask")] = None,
    goal: Annotated[dict | None, Doc("{SHELF: {PRODUCT: units}} to judge the final stock against")] = None,
    snapshots: Annotated[bool, Doc("save key-moment snapshots and the path map (PNG)")] = False,
    animation: Annotated[bool, Doc("save a top-down animation GIF (needs Pillow)")] = False,
    picture: Annotated[bool, Doc("save the path map (PNG) without snapshots (workflows pass pictures == "
                                 "'always')")] = False,
) -> dict:
    from pipflow.warehouse.simulation import simulate

    want_files = bool(snapshots or animation or picture)
    out_dir = ctx.artifact_path("paths.png").parent if want_files else None
    result = simulate(world, schedule, graph, goal, snapshots=snapshots, animation=animation,
                      out_dir=out_dir, log=ctx.log)
    # the trajectories and event log are bulky: keep them as an artifact, not as outputs
    ctx.write_artifact("trajectories.json", {"trajectories": result.pop("trajectories"),
                                             "events": result.pop("events")})
    result.pop("animation_skipped", None)
    ctx.metrics.update({k: result[k] for k in ("exe", "tc_max", "tc_avg", "tc_avg_moved", "gcr")})
    return result

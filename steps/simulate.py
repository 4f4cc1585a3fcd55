"""Step ``simulate.pybullet``: execute a schedule in headless pybullet (see
:mod:`pipflow.simulation`). Thin on purpose: the library does the work, this declares the face."""
from __future__ import annotations

from pipflow import Input, StepContext, step


@step(
    "simulate.pybullet",
    doc="Execute the schedule in a headless pybullet warehouse; read stock and travel back from the bodies.",
    inputs={
        "world": Input("object", doc="the world (output of world.load)"),
        "schedule": Input("object", doc="the schedule (output of schedule)"),
        "graph": Input("object", default=None, doc="the dependency graph: units, fields and route per subtask"),
        "goal": Input("object", default=None, doc="{SHELF: {PRODUCT: units}} to judge the final stock against"),
        "snapshots": Input("boolean", default=False, doc="save key-moment snapshots and the path map (PNG)"),
        "animation": Input("boolean", default=False, doc="save a top-down animation GIF (needs Pillow)"),
        "picture": Input("boolean", default=False,
                         doc="save the path map (PNG) without snapshots (workflows pass pictures == 'always')"),
    },
    outputs={
        "final_stock": "object", "executed": "integer", "failed": "integer", "failures": "array",
        "exe": "number", "travel": "object", "tc_max": "number", "tc_avg": "number", "tc_avg_moved": "number",
        "goal_met": "boolean", "gcr": "number", "peak_load": "object", "stray_units": "integer",
        "jumps": "object",
        "makespan": "number", "pictures": "array",
    },
    version="1",
)
def simulate_pybullet(ctx: StepContext, world: dict, schedule: dict, graph: dict | None = None,
                      goal: dict | None = None, snapshots: bool = False, animation: bool = False,
                      picture: bool = False) -> dict:
    from pipflow.simulation import simulate

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

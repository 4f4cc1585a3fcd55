"""The ``schedule`` step: Alg. 1 timing of an allocation (thin face of :mod:`pipflow.team.scheduling`)."""
from __future__ import annotations

from typing import Annotated

from pipflow import Doc, StepContext, step
from pipflow.pictures import gantt
from pipflow.team.scheduling import build_schedule
from pipflow.values import ScheduleOutputs


@step("schedule",
      doc="Time an allocation: start when predecessors are done and the coalition has gathered.",
      version="2",  # 2: tc_avg is the mean over the robots that moved, tc_avg_team over every robot
      cacheable=True)
def schedule(
    ctx: StepContext,
    graph: Annotated[dict, Doc("output of graph.dependencies")],
    allocation: Annotated[dict, Doc("output of an allocate.* step")],
    world: Annotated[dict, Doc("output of world.load")],
    speed: Annotated[float, Doc("robot speed, m/s")] = 1.0,
    handling: Annotated[float, Doc("seconds of loading/unloading per route stop")] = 2.0,
    picture: Annotated[bool, Doc("also draw a Gantt chart (workflows pass pictures == 'always'; see "
                                 "pipflow.pictures)")] = True,
) -> ScheduleOutputs:
    """Replay the allocation in its order; legs follow obstacle-free paths."""


    result = build_schedule(graph, allocation, world, speed=speed, handling=handling)
    ctx.write_artifact("schedule.json", result)
    if picture:
        gantt(result, ctx.artifact_path("gantt.png"))
    ctx.metrics.update({k: result[k] for k in ("makespan", "tc_max", "tc_avg", "tc_avg_team")})
    ctx.log(f"makespan {result['makespan']:.1f} s, TC-max {result['tc_max']:.1f} m, TC-avg {result['tc_avg']:.1f} m "
            f"over the robots that moved, {result['tc_avg_team']:.1f} m over every robot")
    return {"schedule": result, "makespan": result["makespan"], "tc_max": result["tc_max"], "tc_avg": result["tc_avg"],
            "tc_avg_team": result["tc_avg_team"]}

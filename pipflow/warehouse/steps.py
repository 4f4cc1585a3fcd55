"""The warehouse's own steps, ``simulate.pybullet`` and ``metrics.score``: the names workflows
written before the generic steps ``simulate`` and ``score`` use, kept working unchanged. Each is a
thin face of :class:`pipflow.warehouse.domain.WarehouseDomain` in the flat shape those workflows
read (``final_stock``, ``peak_load``, ``stray_units`` beside the simulation core). Registered by
pipflow's own entry point (``STEP_MODULES`` of :mod:`pipflow.steps`).

The domain (the order language, UP, pybullet) is imported inside the step functions on purpose:
listing steps or running a workflow that does not use them stays fast."""
from __future__ import annotations

from typing import Annotated

from pipflow import Doc, StepContext, step
from pipflow.taskdomain import SCORE_CORE, report_score


def _domain():
    from pipflow.warehouse.domain import WarehouseDomain  # deferred: see the module docstring

    return WarehouseDomain()


@step(
    "simulate.pybullet",
    doc="Execute the schedule in a headless pybullet warehouse; read stock and travel back from the bodies.",
    outputs={
        "final_stock": "object", "executed": "integer", "failed": "integer", "failures": "array",
        "exe": "number", "travel": "object", "tc_max": "number", "tc_avg": "number", "tc_avg_team": "number",
        "goal_met": "boolean", "gcr": "number", "peak_load": "object", "stray_units": "integer",
        "jumps": "object",
        "makespan": "number", "pictures": "array",
    },
    version="2",  # 2: tc_avg over the robots that moved, tc_avg_team; GCR of pipflow.metrics
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
    """The trajectories and event log are bulky: an artifact (trajectories.json), not outputs."""
    result = _domain().simulate(world, schedule, graph, goal, snapshots=snapshots,
                                out_dir=ctx.artifact_path("paths.png").parent, log=ctx.log,
                                save=ctx.write_artifact, animation=animation, picture=picture)
    result = {"final_stock": result.pop("final_state"), **result}
    ctx.metrics.update({k: result[k] for k in ("exe", "tc_max", "tc_avg", "tc_avg_team", "gcr")})
    return result


@step(
    "metrics.score",
    doc="Score a run: success (goal, constraints, conservation, capacity, skills), GCR, Exe, RU, TC-max, "
        "TC-avg over the robots that moved (tc_avg) and over every robot (tc_avg_team).",
    outputs=dict(SCORE_CORE),
)
def score(
    ctx: StepContext,
    world: Annotated[dict, Doc("the world (output of world.load)")],
    goal: Annotated[dict, Doc("ground-truth goal {SHELF: {PRODUCT: units}}")],
    constraints: Annotated[list | None, Doc("ground-truth only/never rules")] = None,
    graph: Annotated[dict | None, Doc("dependency graph (fields and skills per subtask)")] = None,
    schedule: Annotated[dict | None, Doc("the schedule that was simulated")] = None,
    simulation: Annotated[dict | None, Doc("outputs of simulate.pybullet (or of simulate)")] = None,
    feasible: Annotated[bool, Doc("false: only a refusal with nothing executed succeeds")] = True,
    refusal: Annotated[str | None, Doc("refusal message, when the pipeline refused")] = None,
) -> dict:
    result = _domain().score(world, goal, constraints=constraints or [], feasible=feasible, graph=graph,
                             schedule=schedule, simulation=simulation, refusal=refusal)
    return report_score(ctx, result)

"""Step ``metrics.score``: judge one run against its task (see :mod:`pipflow.warehouse.scoring`)."""
from __future__ import annotations

from typing import Annotated

from pipflow import Doc, StepContext, step


@step(
    "metrics.score",
    doc="Score a run: success (goal, constraints, conservation, capacity, skills), GCR, Exe, RU, TC-max, "
        "TC-avg over all robots (tc_avg) and over the robots that moved (tc_avg_moved).",
    outputs={
        "success": "boolean", "goal_met": "boolean", "gcr": "number", "exe": "number", "ru": "number",
        "tc_max": "number", "tc_avg": "number", "tc_avg_moved": "number", "makespan": "number", "planned": "integer",
        "executed": "integer", "lower_bound": "any", "violations": "array", "refused": "boolean",
        "error": "any",
    },
)
def score(
    ctx: StepContext,
    world: Annotated[dict, Doc("the world (output of world.load)")],
    goal: Annotated[dict, Doc("ground-truth goal {SHELF: {PRODUCT: units}}")],
    constraints: Annotated[list | None, Doc("ground-truth only/never rules")] = None,
    graph: Annotated[dict | None, Doc("dependency graph (fields and skills per subtask)")] = None,
    schedule: Annotated[dict | None, Doc("the schedule that was simulated")] = None,
    simulation: Annotated[dict | None, Doc("outputs of simulate.pybullet")] = None,
    feasible: Annotated[bool, Doc("false: only a refusal with nothing executed succeeds")] = True,
    refusal: Annotated[str | None, Doc("refusal message, when the pipeline refused")] = None,
) -> dict:
    from pipflow.warehouse.scoring import score_run

    result = score_run(world, goal, constraints=constraints or [], feasible=feasible, graph=graph,
                       schedule=schedule, simulation=simulation, refusal=refusal)
    for v in result["violations"]:
        ctx.log(f"violation: {v}")
    ctx.metrics.update({k: result[k] for k in ("success", "gcr", "exe", "ru", "tc_max", "tc_avg", "tc_avg_moved")})
    return result

"""Step ``metrics.score``: judge one run against its task (see :mod:`pipflow.scoring`)."""
from __future__ import annotations

from pipflow import Input, StepContext, step


@step(
    "metrics.score",
    doc="Score a run: success (goal, constraints, conservation, capacity, skills), GCR, Exe, RU, TC-max, "
        "TC-avg over all robots (tc_avg) and over the robots that moved (tc_avg_moved).",
    inputs={
        "world": Input("object", doc="the world (output of world.load)"),
        "goal": Input("object", doc="ground-truth goal {SHELF: {PRODUCT: units}}"),
        "constraints": Input("array", default=[], doc="ground-truth only/never rules"),
        "graph": Input("object", default=None, doc="dependency graph (fields and skills per subtask)"),
        "schedule": Input("object", default=None, doc="the schedule that was simulated"),
        "simulation": Input("object", default=None, doc="outputs of simulate.pybullet"),
        "feasible": Input("boolean", default=True, doc="false: only a refusal with nothing executed succeeds"),
        "refusal": Input("string", default=None, doc="refusal message, when the pipeline refused"),
    },
    outputs={
        "success": "boolean", "goal_met": "boolean", "gcr": "number", "exe": "number", "ru": "number",
        "tc_max": "number", "tc_avg": "number", "tc_avg_moved": "number", "makespan": "number", "planned": "integer",
        "executed": "integer", "lower_bound": "any", "violations": "array", "refused": "boolean",
        "error": "any",
    },
)
def score(ctx: StepContext, world: dict, goal: dict, constraints: list | None = None,
          graph: dict | None = None, schedule: dict | None = None, simulation: dict | None = None,
          feasible: bool = True, refusal: str | None = None) -> dict:
    from pipflow.scoring import score_run

    result = score_run(world, goal, constraints=constraints or [], feasible=feasible, graph=graph,
                       schedule=schedule, simulation=simulation, refusal=refusal)
    for v in result["violations"]:
        ctx.log(f"violation: {v}")
    ctx.metrics.update({k: result[k] for k in ("success", "gcr", "exe", "ru", "tc_max", "tc_avg", "tc_avg_moved")})
    return result

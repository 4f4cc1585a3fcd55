"""The garden's one step of its own, registered through ``pipflow.steps`` (this package's
pyproject.toml): execute a schedule in the garden's simulator. Everything else a garden run needs
is a generic pipflow step that reaches the garden through the task-domain protocol (world.load,
llm.problem offline or with a model, pddl.*, graph.dependencies, allocate.*, schedule)."""
from __future__ import annotations

from typing import Annotated

from pipflow import Doc, StepContext, step

from pipflow_garden.domain import GardenDomain

DOMAIN = GardenDomain()


@step("garden.simulate",
      doc="Replay a schedule in the garden: preconditions, coalition skills, joined legs, no driving through beds; travel measured.",
      outputs={"final_state": "object", "executed": "integer", "failed": "integer", "failures": "array",
               "exe": "number", "travel": "object", "tc_max": "number", "tc_avg": "number",
               "tc_avg_moved": "number", "goal_met": "boolean", "gcr": "number", "conditions": "object",
               "jumps": "object", "makespan": "number"})
def simulate(ctx: StepContext,
             world: Annotated[dict, Doc("output of world.load (a garden world)")],
             schedule: Annotated[dict, Doc("output of schedule")],
             graph: Annotated[dict | None, Doc("output of graph.dependencies (skills and route per subtask)")] = None,
             goal: Annotated[dict | None, Doc("the goal to judge the final state against")] = None,
             ) -> dict:
    result = DOMAIN.simulate(world, schedule, graph, goal, log=ctx.log)
    ctx.metrics.update({k: result[k] for k in ("exe", "tc_max", "tc_avg", "gcr")})
    ctx.log(f"executed {result['executed']}/{len(schedule.get('subtasks', []))}, goal conditions "
            f"{result['conditions']['met']}/{result['conditions']['total']}")
    return result

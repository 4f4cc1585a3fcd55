"""The garden's steps, registered through ``pipflow.steps`` (this package's pyproject.toml): load
a garden world, read a command into a team-level problem, execute a schedule, score a run. Thin
faces of :class:`pipflow_garden.domain.GardenDomain`; pipflow's generic steps (pddl.*,
graph.dependencies, allocate.*, schedule) do the rest unchanged."""
from __future__ import annotations

from typing import Annotated

from pipflow import Doc, PathStr, StepContext, step

from pipflow_garden.domain import GardenDomain

DOMAIN = GardenDomain()


@step("garden.load", doc="Load a garden world (beds, taps, stores, crops, robots), every problem located.",
      outputs={"world": "object"}, cacheable=True)
def load(ctx: StepContext,
         path: Annotated[PathStr, Doc("garden world YAML file, relative to the workflow file")],
         seed: Annotated[int | None, Doc("vary the robots' start positions reproducibly (none: as in the file)")] = None,
         ) -> dict:
    """Raises WorldError (exit 2) listing each problem with file:line:col."""
    world = DOMAIN.load_world(ctx.resolve_path(path), seed=seed)
    ctx.log(DOMAIN.describe(world))
    return {"world": world}


@step("garden.problem",
      doc="Read a garden command offline (it refuses what it cannot place) into its goal, rules and team-level PDDL problem.",
      outputs={"problem": "string", "goal": "object", "concrete": "object", "constraints": "array", "errors": "array"},
      cacheable=True)
def problem(ctx: StepContext,
            command: Annotated[str, Doc("the command, in the garden language (pipflow_garden.language)")],
            world: Annotated[dict, Doc("output of garden.load")],
            domain: Annotated[PathStr, Doc("team-level PDDL domain (its name goes into the problem)")],
            ) -> dict:
    """TranslationError quotes the words it cannot place; Refusal says why the garden cannot."""
    read = DOMAIN.read_offline(command, world, ctx.resolve_path(domain).read_text(), save=ctx.write_artifact)
    ctx.log("understood:\n" + read["explanation"])
    return {"problem": read["problem"], "goal": read["goal"], "concrete": read["goal"],
            "constraints": read["constraints"], "errors": []}


@step("garden.simulate",
      doc="Replay a schedule in the garden: preconditions, coalition skills, joined legs, no driving through beds; travel measured.",
      outputs={"final_state": "object", "executed": "integer", "failed": "integer", "failures": "array",
               "exe": "number", "travel": "object", "tc_max": "number", "tc_avg": "number",
               "tc_avg_moved": "number", "goal_met": "boolean", "gcr": "number", "conditions": "object",
               "jumps": "object", "makespan": "number"})
def simulate(ctx: StepContext,
             world: Annotated[dict, Doc("output of garden.load")],
             schedule: Annotated[dict, Doc("output of schedule")],
             graph: Annotated[dict | None, Doc("output of graph.dependencies (skills and route per subtask)")] = None,
             goal: Annotated[dict | None, Doc("the goal to judge the final state against")] = None,
             ) -> dict:
    result = DOMAIN.simulate(world, schedule, graph, goal, log=ctx.log)
    ctx.metrics.update({k: result[k] for k in ("exe", "tc_max", "tc_avg", "gcr")})
    ctx.log(f"executed {result['executed']}/{len(schedule.get('subtasks', []))}, goal conditions "
            f"{result['conditions']['met']}/{result['conditions']['total']}")
    return result


@step("garden.score",
      doc="Score a garden run against a gold goal and rules (SR, GCR, Exe, TC); the flat outputs of metrics.score.",
      outputs={"success": "boolean", "goal_met": "boolean", "gcr": "number", "exe": "number", "ru": "number",
               "tc_max": "number", "tc_avg": "number", "tc_avg_moved": "number", "makespan": "number",
               "planned": "integer", "executed": "integer", "lower_bound": "any", "violations": "array",
               "refused": "boolean", "error": "any"})
def score(ctx: StepContext,
          world: Annotated[dict, Doc("output of garden.load")],
          goal: Annotated[dict, Doc("gold goal")],
          constraints: Annotated[list | None, Doc("gold robot rules")] = None,
          schedule: Annotated[dict | None, Doc("output of schedule")] = None,
          graph: Annotated[dict | None, Doc("output of graph.dependencies")] = None,
          simulation: Annotated[dict | None, Doc("output of garden.simulate")] = None,
          ) -> dict:
    return DOMAIN.score(world, goal, constraints=constraints, graph=graph, schedule=schedule, simulation=simulation)

"""The household's own steps (the paper's AI2-THOR experiment on pipflow's own home simulator):
load a household world with its robot team, write the team-level problem for a command, execute
the schedule, score the final state. Thin faces of
:class:`pipflow.household.domain.HouseholdDomain`, kept for the workflows that name them (the
generic steps world.load, llm.problem, simulate and score reach the same methods); the
domain-general steps (pddl.*, graph.dependencies, allocate.*, schedule) do the rest unchanged.
Registered by pipflow's own entry point (``STEP_MODULES`` of :mod:`pipflow.steps`).

The domain (its parser, UP, pybullet) is imported inside the step functions on purpose: listing
steps or running a workflow that does not use them stays fast."""
from __future__ import annotations

from typing import Annotated

from pipflow import Doc, PathStr, StepContext, step
from pipflow.taskdomain import SCORE_CORE, report_score


def _domain():
    from pipflow.household.domain import HouseholdDomain  # deferred: see the module docstring

    return HouseholdDomain()


@step("household.load",
      doc="Load a household world (places, objects, categories, robots), validated with every problem located; keep the task's team.",
      outputs={"world": "object"}, cacheable=True)
def load(
    ctx: StepContext,
    path: Annotated[PathStr, Doc("household world YAML file, relative to the workflow file")],
    team: Annotated[str | None, Doc("a team of the world, or robot names 'a,b,c' (none: every robot)")] = None,
    seed: Annotated[int | None, Doc("vary the robots' start positions reproducibly (none: as in the file)")] = None,
) -> dict:
    """Raises WorldError (exit 2) listing each problem with file:line:col."""
    world = _domain().load_world(ctx.resolve_path(path), seed=seed, team=team)
    ctx.log(f"household world {world['name']}: {len(world['places'])} places, {len(world['objects'])} objects, "
            f"team {', '.join(world['robots'])}")
    return {"world": world}


@step("household.problem",
      doc="Translate a household command (offline, deterministic) into goal conditions and the team-level PDDL problem.",
      outputs={"problem": "string", "goal": "object", "concrete": "object", "constraints": "array", "errors": "array"},
      cacheable=True)
def problem(
    ctx: StepContext,
    command: Annotated[str, Doc("the natural-language command")],
    world: Annotated[dict, Doc("output of household.load")],
    domain: Annotated[PathStr, Doc("team-level PDDL domain (its name goes into the problem)")],
    feedback: Annotated[list | None, Doc("previous round's messages (the offline translator is deterministic "
                                         "and ignores them)")] = None,
) -> dict:
    """``goal`` keeps the command's conditions (counts included) for judging; ``concrete`` has the
    counts resolved to objects, which is what the problem asks for. Untranslatable commands raise
    TranslationError; impossible ones (slice a mug) raise Refusal with the reason."""
    result = _domain().read_offline(command, world, ctx.resolve_path(domain).read_text(), save=ctx.write_artifact)
    ctx.log(f"goal: {result['goal']}")
    return {key: result[key] for key in ("problem", "goal", "concrete", "constraints", "errors")}


@step("household.simulate",
      doc="Execute a schedule in the home: preconditions and coalition skills checked, state updated, travel measured, pybullet pictures.",
      outputs={"final_state": "object", "executed": "integer", "failed": "integer", "failures": "array",
               "exe": "number", "travel": "object", "tc_max": "number", "tc_avg": "number", "tc_avg_team": "number",
               "goal_met": "boolean",
               "gcr": "number", "conditions": "object", "jumps": "object", "makespan": "number", "pictures": "array"},
      version="2")  # 2: tc_avg over the robots that moved, tc_avg_team; GCR of pipflow.metrics
def simulate(
    ctx: StepContext,
    world: Annotated[dict, Doc("output of household.load")],
    schedule: Annotated[dict, Doc("output of schedule")],
    graph: Annotated[dict | None, Doc("output of graph.dependencies (skills and route per subtask)")] = None,
    goal: Annotated[dict | None, Doc("goal conditions to judge the final state against")] = None,
    snapshots: Annotated[bool, Doc("save pybullet pictures of the start and the end")] = False,
) -> dict:
    out_dir = ctx.artifact_path("snapshot_1_start.png").parent if snapshots else None
    result = _domain().simulate(world, schedule, graph, goal, snapshots=snapshots, out_dir=out_dir, log=ctx.log)
    ctx.metrics.update({k: result[k] for k in ("exe", "tc_max", "tc_avg", "tc_avg_team", "gcr")})
    ctx.log(f"executed {result['executed']}/{len(schedule.get('subtasks', []))}, goal conditions "
            f"{result['conditions']['met']}/{result['conditions']['total']}")
    return result


@step("household.score",
      doc="Score a household run's final state against ground-truth conditions (SR, GCR, Exe, RU, TC); "
          "the outputs of metrics.score, flat.",
      outputs=dict(SCORE_CORE))
def score(
    ctx: StepContext,
    world: Annotated[dict, Doc("output of household.load")],
    goal: Annotated[dict, Doc("ground-truth goal conditions")],
    schedule: Annotated[dict | None, Doc("output of schedule")] = None,
    graph: Annotated[dict | None, Doc("output of graph.dependencies")] = None,
    simulation: Annotated[dict | None, Doc("output of household.simulate")] = None,
) -> dict:
    """The same flat outputs as ``metrics.score`` (one shape per family), so a workflow or the
    bench reads ``success``/``gcr`` the same way in either domain."""
    return report_score(ctx, _domain().score(world, goal, graph=graph, schedule=schedule, simulation=simulation))

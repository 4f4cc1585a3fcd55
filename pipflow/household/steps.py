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

from typing import Annotated, Any, TypedDict

from pipflow import Doc, PathStr, StepContext, step
from pipflow.engine.step import shape
from pipflow.taskdomain import report_score, report_simulation
from pipflow.values import READING, SIMULATION, Score, SimulationCore, WorldOutputs


@shape(SIMULATION)
class HouseholdSimulation(SimulationCore):
    """The outputs of ``household.simulate``: the simulation core (``final_state``: where each
    object is and its states), the goal's conditions met / total / unmet, the pictures drawn."""

    conditions: dict[str, Any]
    pictures: list[str]


@shape(READING)
class HouseholdReading(TypedDict):
    """The outputs of ``household.problem``: the problem, the goal as the command says it, the
    goal with counts resolved to objects (what the problem asks), rules, errors."""

    problem: str
    goal: dict
    concrete: dict
    constraints: list
    errors: list


def _domain():
    from pipflow.household.domain import HouseholdDomain  # deferred: see the module docstring

    return HouseholdDomain()


@step("household.load",
      doc="Load a household world (places, objects, categories, robots), validated with every problem located; keep the task's team.",
      cacheable=True)
def load(
    ctx: StepContext,
    path: Annotated[PathStr, Doc("household world YAML file, relative to the workflow file")],
    team: Annotated[str | None, Doc("a team of the world, or robot names 'a,b,c' (none: every robot)")] = None,
    seed: Annotated[int | None, Doc("vary the robots' start positions reproducibly (none: as in the file)")] = None,
) -> WorldOutputs:
    """Raises WorldError (exit 2) listing each problem with file:line:col."""
    world = _domain().load_world(ctx.resolve_path(path), seed=seed, team=team)
    ctx.log(f"household world {world['name']}: {len(world['places'])} places, {len(world['objects'])} objects, "
            f"team {', '.join(world['robots'])}")
    return {"world": world}


@step("household.problem",
      doc="Translate a household command (offline, deterministic) into goal conditions and the team-level PDDL problem.",
      cacheable=True)
def problem(
    ctx: StepContext,
    command: Annotated[str, Doc("the natural-language command")],
    world: Annotated[dict, Doc("output of household.load")],
    domain: Annotated[PathStr, Doc("team-level PDDL domain (its name goes into the problem)")],
    feedback: Annotated[list | None, Doc("previous round's messages (the offline translator is deterministic "
                                         "and ignores them)")] = None,
) -> HouseholdReading:
    """``goal`` keeps the command's conditions (counts included) for judging; ``concrete`` has the
    counts resolved to objects, which is what the problem asks for. Untranslatable commands raise
    TranslationError; impossible ones (slice a mug) raise Refusal with the reason."""
    result = _domain().read_offline(command, world, ctx.resolve_path(domain).read_text(), save=ctx.write_artifact)
    ctx.log(f"goal: {result['goal']}")
    return {key: result[key] for key in ("problem", "goal", "concrete", "constraints", "errors")}


@step("household.simulate",
      doc="Execute a schedule in the home: preconditions and coalition skills checked, state updated, travel measured, pybullet pictures.",
      version="2")  # 2: tc_avg over the robots that moved, tc_avg_team; GCR of pipflow.metrics
def simulate(
    ctx: StepContext,
    world: Annotated[dict, Doc("output of household.load")],
    schedule: Annotated[dict, Doc("output of schedule")],
    graph: Annotated[dict | None, Doc("output of graph.dependencies (skills and route per subtask)")] = None,
    goal: Annotated[dict | None, Doc("goal conditions to judge the final state against")] = None,
    snapshots: Annotated[bool, Doc("save pybullet pictures of the start and the end")] = False,
) -> HouseholdSimulation:
    out_dir = ctx.artifact_path("snapshot_1_start.png").parent if snapshots else None
    result = _domain().simulate(world, schedule, graph, goal, snapshots=snapshots, out_dir=out_dir, log=ctx.log)
    ctx.log(f"goal conditions {result['conditions']['met']}/{result['conditions']['total']}")
    return report_simulation(ctx, result, schedule)


@step("household.score",
      doc="Score a household run's final state against ground-truth conditions (SR, GCR, Exe, RU, TC); "
          "the outputs of metrics.score, flat.")
def score(
    ctx: StepContext,
    world: Annotated[dict, Doc("output of household.load")],
    goal: Annotated[dict, Doc("ground-truth goal conditions")],
    schedule: Annotated[dict | None, Doc("output of schedule")] = None,
    graph: Annotated[dict | None, Doc("output of graph.dependencies")] = None,
    simulation: Annotated[dict | None, Doc("output of household.simulate")] = None,
) -> Score:
    """The same flat outputs as ``metrics.score`` (one shape per family), so a workflow or the
    bench reads ``success``/``gcr`` the same way in either domain."""
    return report_score(ctx, _domain().score(world, goal, graph=graph, schedule=schedule, simulation=simulation))

"""Steps that reach a world's task domain through the protocol (:mod:`pipflow.taskdomain`):
load a world file, simulate a schedule in it, score a run against its task. One step each for
every domain, so a domain plugin needs no step of its own; the domain is the world's
(``domain:`` in the file, ``world["domain"]`` in the dict; none: the default domain)."""
from __future__ import annotations

from typing import Annotated

from pipflow import Doc, PathStr, StepContext, step
from pipflow.errors import InputError
from pipflow.taskdomain import report_score, report_simulation
from pipflow.taskdomains import declared_domain, task_domain
from pipflow.values import Score, Simulation, WorldOutputs, count_refused, simulation_outputs, split_refused


@step("world.load",
      doc="Load a world file in its task domain's format (the file's domain: key; the default domain's without one), "
          "validated with every problem located.",
      cacheable=True)
def load(
    ctx: StepContext,
    path: Annotated[PathStr, Doc("world YAML file, relative to the workflow file; its `domain:` key names "
                                 "its task domain")],
    seed: Annotated[int | None, Doc("vary the robots' start positions reproducibly (none: as in the file)")] = None,
    task_domain: Annotated[str | None, Doc("the task domain the workflow is written for: a world of another "
                                           "is refused, naming that domain's workflows (none: any)")] = None,
) -> WorldOutputs:
    """Raises WorldError (exit 2) listing each problem with file:line:col, InputError for an
    unknown ``domain:`` or a world of another domain than ``task_domain``; returns the
    normalized world dict of docs/architecture.md."""
    file = ctx.resolve_path(path)
    domain = declared_domain(file)
    if task_domain is not None and domain.name != task_domain:
        own = sorted({domain.workflow, *domain.workflows.values()})
        raise InputError(f"{file} is a {domain.name} world, but this workflow is written for {task_domain} "
                         f"worlds; run one of the {domain.name} domain's workflows ({', '.join(own)})")
    world = domain.load_world(file, seed=seed)
    ctx.log(f"world {world['name']}: {domain.describe(world)}")
    return {"world": world}


@step("simulate",
      doc="Execute a schedule in the world's task domain's simulator; the same core outputs in every domain "
          "(final state, executed, failures, travel, TC, goal met, GCR), the domain's own under `details`.",
      version="2")  # 2: tc_avg over the robots that moved, tc_avg_team; GCR of pipflow.metrics
def simulate(
    ctx: StepContext,
    world: Annotated[dict, Doc("the world (output of world.load)")],
    schedule: Annotated[dict, Doc("the schedule (output of schedule)")],
    graph: Annotated[dict | None, Doc("the dependency graph: skills, fields and route per subtask")] = None,
    goal: Annotated[dict | None, Doc("the goal to judge the final state against")] = None,
    snapshots: Annotated[bool, Doc("save pictures of key moments (PNG), where the domain draws them")] = False,
    options: Annotated[dict | None, Doc("the domain's own switches (its simulate's options), e.g. "
                                        "{picture: true, animation: true}: a path map, a GIF")] = None,
) -> Simulation:
    """The step's artifact folder is where a domain draws, when ``snapshots`` or its own options
    ask; the trajectories and event logs it keeps are artifacts too, not outputs. Subtasks the
    schedule holds as ``refused`` (a plan's actions this world cannot place) are not handed to the
    domain: they count as planned and failed (:func:`pipflow.values.count_refused`)."""
    domain = task_domain(world)
    unknown = sorted(set(options or {}) - set(domain.simulate_options))
    if unknown:
        raise InputError(f"simulate: options {', '.join(map(repr, unknown))} are not switches of the "
                         f"{domain.name!r} simulation (known: {', '.join(domain.simulate_options) or 'none'})")
    out_dir = ctx.artifact_path("pictures").parent
    runnable, refused = split_refused(schedule)  # a plan's actions the world cannot place: failed, counted here
    for s in refused:
        ctx.log(f"execute: {s['id']} {s.get('action')} {' '.join(map(str, s.get('args') or []))} refused: "
                f"{'; '.join(s['refused'])}")
    result = domain.simulate(world, runnable, graph, goal, snapshots=snapshots, out_dir=out_dir,
                             log=ctx.log, save=ctx.write_artifact, **(options or {}))
    outputs = simulation_outputs(count_refused(result, refused, len(schedule.get("subtasks") or [])))
    return report_simulation(ctx, outputs, schedule)


@step("score",
      doc="Score a run against its task in the world's task domain: success, GCR, Exe, RU, TC-max, TC-avg "
          "(over the robots that moved; tc_avg_team over every robot), violations; flat, the same keys in every domain.")
def score(
    ctx: StepContext,
    world: Annotated[dict, Doc("the world (output of world.load)")],
    goal: Annotated[dict, Doc("the task's ground-truth goal")],
    constraints: Annotated[list | None, Doc("the task's ground-truth robot rules")] = None,
    graph: Annotated[dict | None, Doc("dependency graph (fields and skills per subtask)")] = None,
    schedule: Annotated[dict | None, Doc("the schedule that was simulated")] = None,
    simulation: Annotated[dict | None, Doc("outputs of simulate")] = None,
    feasible: Annotated[bool, Doc("false: only a refusal with nothing executed succeeds")] = True,
    refusal: Annotated[str | None, Doc("refusal message, when the pipeline refused")] = None,
) -> Score:
    result = task_domain(world).score(world, goal, constraints=constraints or [], feasible=feasible, graph=graph,
                                      schedule=schedule, simulation=simulation, refusal=refusal)
    return report_score(ctx, result)

"""The ``execute`` step: a schedule carried out under faults, watched and recovered (thin face of
:mod:`pipflow.execution`). Its outputs are what the simulation step then plays: the world as it
really was, the schedule the robots really carried out, its graph; and what happened: the faults,
the recovery rounds, the refusal when the goal went out of reach (a later ``core.refuse`` ends the
run with it, after the simulation has recorded what was done), and the faults asked for that did
not apply to this run (a drawn target the run does not offer: carried out without them).

Without faults the step hands its inputs on unchanged (the built-in workflows skip it then)."""
from __future__ import annotations

from typing import Annotated, Any

from pipflow import Check, Choices, Doc, PathStr, StepContext, step
from pipflow.errors import AllocationError
from pipflow.execution import faults as fault_specs
from pipflow.execution.capability import capable
from pipflow.liberrors import SCIP, library_errors
from pipflow.taskdomains import task_domain
from pipflow.values import ExecutionOutputs


@step("execute",
      doc="Carry out a schedule under faults (declared, or drawn from the seed): watch it against the schedule and "
          "recover, cheapest first (re-allocate, re-plan, refuse); outputs the world, schedule and graph to simulate.")
def execute(
    ctx: StepContext,
    world: Annotated[dict, Doc("the world (output of world.load)")],
    schedule: Annotated[dict, Doc("the schedule (output of schedule)")],
    graph: Annotated[dict, Doc("the dependency graph (output of graph.dependencies)")],
    problem: Annotated[str, Doc("the accepted team-level problem: its goal is what a re-plan reaches")],
    domain: Annotated[PathStr, Doc("the team-level PDDL domain")],
    actions: Annotated[Any, Doc("the domain's action metadata: a path or its content")],
    faults: Annotated[Any, Check(fault_specs.check_input),
                      Doc("none; counts drawn from the seed (robot-loss=1,slowdown=1,passage-closed=1, the domain's "
                          "own surprise kind ...); or a list of fault specs (pipflow.execution.faults)")] = None,
    seed: Annotated[int | None, Doc("the run's seed: drawn faults are drawn from it")] = None,
    planner: Annotated[str, Doc("the planner a re-plan uses (the run's)")] = "pipflow-transport",
    planner_params: Annotated[dict | None, Doc("its parameters")] = None,
    fallback: Annotated[str | None, Doc("the planner to fall back on")] = None,
    planner_timeout: Annotated[float, Doc("seconds per re-plan")] = 60.0,
    graph_mode: Annotated[str, Choices("deorder", "exact", "paper"), Doc("the dependency graph's mode")] = "deorder",
    allocation: Annotated[dict | None, Doc("the run's allocation (output of an allocate.* step): a recovery "
                                           "allocates with the same method, mode and cost")] = None,
    constraints: Annotated[list | None, Doc("the run's robot rules")] = None,
    speed: Annotated[float, Doc("robot speed, m/s")] = 1.0,
    handling: Annotated[float, Doc("seconds of loading/unloading per route stop")] = 2.0,
    repair: Annotated[bool, Doc("a re-plan first repairs the old plan (keeps its steps that still apply, plans what "
                                "they leave undone); false: every re-plan is a plan from scratch")] = True,
) -> ExecutionOutputs:
    """Faults are checked against the world before anything is played (an unknown robot or shelf
    is exit 2, naming the fault)."""
    identity = {"world": world, "schedule": schedule, "graph": graph, "faults": [], "recoveries": [],
                "refusal": None, "feasible": None, "feasibility": "", "not_applicable": []}
    owner = task_domain(world)
    specs = fault_specs.parse(faults, tuple(getattr(owner, "surprise_names", ()) or ()))
    if not specs:
        return identity
    # deferred: pulls numpy, unified_planning, pyscipopt (the executor; only runs with faults get here)
    from pipflow.execution.executor import Executor
    # deferred: pulls the same (the recovery's planning settings)
    from pipflow.execution.recovery import Planning

    domain_obj = capable(owner)
    method = str((allocation or {}).get("method") or "scip")
    mode = "frontier" if method.endswith("-frontier") else "subtask"
    method = method.removesuffix("-frontier")
    cost = str((allocation or {}).get("cost") or "total")
    placement = fault_specs.resolve(specs, world, schedule, graph, seed, domain_obj)
    placed, skipped = placement.faults, [f.to_json() for f in placement.not_applicable]
    for na in placement.not_applicable:
        ctx.log(f"fault {na.id}: {na.describe()}; the run goes on without it")
    for f in placed:
        ctx.log(f"fault {f.id}: {f.describe()}")
    if not placed:  # nothing applies: the schedule is carried out as planned
        ctx.write_artifact("execution.json", {"faults": [], "not_applicable": skipped, "recoveries": []})
        ctx.metrics.update({"faults": 0, "faults_not_applicable": len(skipped)})
        return {**identity, "not_applicable": skipped}
    planning = Planning(domain_text=ctx.resolve_path(domain).read_text(encoding="utf-8"),
                        metadata=ctx.read_yaml(actions, "action metadata file"), problem=problem, planner=planner,
                        planner_params=planner_params, fallback=fallback,
                        planner_timeout=planner_timeout, graph_mode=graph_mode, method=method, mode=mode, cost=cost,
                        constraints=list(constraints or []), speed=speed, handling=handling, repair=repair)
    with library_errors(SCIP, AllocationError, "re-allocating after a fault"):
        outcome = Executor(domain_obj, world, schedule, graph, placed, planning, log=ctx.log,
                           save=ctx.write_artifact).run()
    ctx.write_artifact("execution.json", {"faults": outcome.faults, "not_applicable": skipped,
                                          "recoveries": outcome.rounds,
                                          "refusal": outcome.refusal, "feasible": outcome.feasible,
                                          "feasibility": outcome.feasibility, "notes": outcome.notes})
    ctx.write_artifact("schedule.json", outcome.schedule)
    ctx.metrics.update({"faults": len(outcome.faults), "faults_not_applicable": len(skipped),
                        "recoveries": len(outcome.rounds),
                        "recovery_seconds": sum(r.get("seconds", 0.0) for r in outcome.rounds)})
    if outcome.refusal:
        ctx.log(f"refusing: {outcome.refusal}")
    return {"world": outcome.world, "schedule": outcome.schedule, "graph": outcome.graph, "faults": outcome.faults,
            "recoveries": outcome.rounds, "refusal": outcome.refusal, "feasible": outcome.feasible,
            "feasibility": outcome.feasibility, "not_applicable": skipped}

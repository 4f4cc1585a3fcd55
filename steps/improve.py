"""Steps of the ``improve`` family: improvement phases after an allocator (beyond the paper), thin
faces of :mod:`pipflow.team.improve`. They take an allocation (the ``allocate.*`` contract) and
return one in the same contract, never worse in (makespan, TC-max, TC-sum), so ``schedule`` and
the simulation replay it as they replay any allocation. Workflows run them only when asked (the
warehouse workflow's input ``improve``), so that the paper's Alg. 1 stays the default."""
from __future__ import annotations

from typing import Annotated

from pipflow import Doc, StepContext, step
from pipflow.errors import AllocationError
from pipflow.liberrors import SCIP, library_errors


@step("improve.local",
      doc="Local search after the allocation: reassign and reorder subtasks under the graph, the robot rules "
          "and the skills; keeps a plan only if (makespan, TC-max, TC-sum) is lexicographically better.",
      outputs={"allocation": "object", "improved": "boolean", "before": "object", "after": "object"},
      cacheable=True)
def local(
    ctx: StepContext,
    graph: Annotated[dict, Doc("output of graph.dependencies")],
    world: Annotated[dict, Doc("output of world.load")],
    allocation: Annotated[dict, Doc("output of an allocate.* step: the plan to start from")],
    constraints: Annotated[list | None, Doc("the allocation's only/never rules (the same list)")] = None,
    linear: Annotated[list | None, Doc("the allocation's extra linear constraints (the same list)")] = None,
    speed: Annotated[float, Doc("robot speed, m/s (as the schedule uses it)")] = 1.0,
    handling: Annotated[float, Doc("seconds of loading/unloading per route stop")] = 2.0,
    budget: Annotated[int, Doc("the search's budget in subtask timings (timing a plan of n subtasks costs n; "
                               "pipflow.team.improve.DEFAULT_BUDGET)")] = 150_000,
    seed: Annotated[int, Doc("the search's random kicks (the same seed, the same result)")] = 0,
) -> dict:
    """Start from the allocator's plan; the result is replayed by the Timeline and kept only when better."""
    # deferred: pulls numpy and the travel map (the registry loads every step module)
    from pipflow.team.improve import improve_allocation

    with library_errors(SCIP, AllocationError, "improving the allocation"):
        result = improve_allocation(graph, world, allocation, constraints or [], linear or [], speed=speed,
                                    handling=handling, budget=budget, seed=seed)
    st = result["stats"]["improve"]
    ctx.write_artifact("allocation.json", result)
    ctx.metrics.update({f"improve_{k}": v for k, v in st["after"].items()})
    b, a = st["before"], st["after"]
    ctx.log(f"makespan {b['makespan']:.1f} -> {a['makespan']:.1f} s, TC-max {b['tc_max']:.1f} -> {a['tc_max']:.1f} m, "
            f"TC-sum {b['tc_sum']:.1f} -> {a['tc_sum']:.1f} m ({st['evaluations']} plans in {st['time_s']:.2f} s"
            f"{'' if st['improved'] else '; kept the allocation: nothing better found'})")
    return {"allocation": result, "improved": st["improved"], "before": b, "after": a}

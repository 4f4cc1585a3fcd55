"""Steps of the ``allocate`` family: skill-based MRTA over the dependency graph (paper Alg. 1 and
eq. 3), thin faces of :mod:`pipflow.team.allocation`. All of them output the allocation contract of
docs/architecture.md, so `schedule` and the metrics do not care which one ran, and `cost`: which
allocation cost c_i they used (``total``, the paper's, or ``subtask``; docs/paper.md)."""
from __future__ import annotations

from typing import Annotated

from pipflow import Choices, Doc, StepContext, step
from pipflow.errors import AllocationError
from pipflow.liberrors import SCIP, library_errors
from pipflow.team.scheduling import COSTS, DEFAULT_COST
from pipflow.values import AllocationOutputs

# the inputs every allocator takes, named once (each step's signature is its contract)
Graph = Annotated[dict, Doc("output of graph.dependencies")]
World = Annotated[dict, Doc("output of world.load")]
RobotRules = Annotated[list | None, Doc("only/never rules: [{only|never: [robots], product?, from?, to?}]")]
LinearRules = Annotated[list | None, Doc("extra linear constraints: [{robots: [..]|all, coef: n|{robot: n}, "
                                         "skill?, sense, rhs, <field>?}]")]
Speed = Annotated[float, Doc("robot speed, m/s (times in stats and frontier mode)")]
Handling = Annotated[float, Doc("seconds of loading/unloading per route stop")]
Cost = Annotated[str, Choices(*COSTS),
                 Doc("c_i of the IP: total = the robot's travel so far plus this subtask (the paper's, balances "
                     "work: lower TC-max and makespan); subtask = this subtask's approach and route only "
                     "(nearest robots: less travel in sum, one robot may do most subtasks)")]


def _run(ctx: StepContext, method: str, graph: dict, world: dict, constraints: list | None,
         linear: list | None, speed: float, handling: float, cost: str, mode: str = "subtask",
         time_limit: float = 10.0) -> dict:
    # deferred: pulls numpy (~150 ms; the registry loads every step module, e.g. for `pipflow validate`)
    from pipflow.team.allocation import allocate

    with library_errors(SCIP, AllocationError, f"allocating with {method}"):
        result = allocate(graph, world, method=method, constraints=constraints or [], linear=linear or [],
                          mode=mode, speed=speed, handling=handling, time_limit=time_limit, cost=cost)
    ctx.write_artifact("allocation.json", result)
    st = result["stats"]
    ctx.metrics.update({"alloc_median_ms": st["solve_median_ms"], **{f"predicted_{k}": v for k, v in st["predicted"].items()}})
    ctx.log(f"allocated {st['subtasks']} subtasks ({result['method']}, cost {result['cost']}), "
            f"median solve {st['solve_median_ms']:.1f} ms")
    return {"allocation": result, "cost": result["cost"]}  # which c_i ran, for the run's outputs


@step("allocate.scip",
      doc="Lexicographic IP per subtask (min max cost, then min sum of costs) with SCIP; or frontier mode.", cacheable=True)
def scip(
    ctx: StepContext,
    graph: Graph,
    world: World,
    constraints: RobotRules = None,
    linear: LinearRules = None,
    speed: Speed = 1.0,
    handling: Handling = 2.0,
    mode: Annotated[str, Choices("subtask", "frontier"),
                    Doc("subtask: the paper's one IP per subtask; frontier: all ready subtasks in one IP")] = "subtask",
    time_limit: Annotated[float, Doc("seconds per frontier wave (frontier mode)")] = 10.0,
    naive: Annotated[bool, Doc("solve the first stage as a full SCIP model (slow; for comparison)")] = False,
    cost: Cost = DEFAULT_COST,
) -> AllocationOutputs:
    """The paper's allocator; the fast first stage gives the same optimum as the naive model."""
    return _run(ctx, "naive" if naive else "scip", graph, world, constraints, linear, speed, handling,
                cost, mode, time_limit)


@step("allocate.greedy", doc="Baseline: cheapest capable robots first until the skills are covered.", cacheable=True)
def greedy(ctx: StepContext, graph: Graph, world: World, constraints: RobotRules = None, linear: LinearRules = None,
           speed: Speed = 1.0, handling: Handling = 2.0, cost: Cost = DEFAULT_COST) -> AllocationOutputs:
    """Greedy baseline for comparison with the IP; "cheapest" by ``cost`` (subtask: the nearest)."""
    return _run(ctx, "greedy", graph, world, constraints, linear, speed, handling, cost)


@step("allocate.blind", doc="Ablation (paper's w/o AS): fewest robots by robot order, ignoring travel cost.", cacheable=True)
def blind(ctx: StepContext, graph: Graph, world: World, constraints: RobotRules = None, linear: LinearRules = None,
          speed: Speed = 1.0, handling: Handling = 2.0, cost: Cost = DEFAULT_COST) -> AllocationOutputs:
    """Cost-blind allocation: shows what the allocation strategy buys. It never looks at costs;
    ``cost`` only says what the recorded ``costs`` of each assignment mean."""
    return _run(ctx, "blind", graph, world, constraints, linear, speed, handling, cost)

"""The warehouse's own steps, ``simulate.pybullet`` and ``metrics.score``: the names workflows
written before the generic steps ``simulate`` and ``score`` use, kept working. Each is a thin face
of :class:`pipflow.warehouse.domain.WarehouseDomain`; ``simulate.pybullet`` keeps the flat shape
those workflows read (``final_stock``, ``peak_load``, ``stray_units`` beside the simulation core,
:class:`PybulletSimulation`: a member of the simulation family). Registered by pipflow's own
entry point (``STEP_MODULES`` of :mod:`pipflow.steps`).

The domain (the order language, UP, pybullet) is imported inside the step functions on purpose:
listing steps or running a workflow that does not use them stays fast."""
from __future__ import annotations

from typing import Annotated

from pipflow import Doc, StepContext, step
from pipflow.engine.step import shape
from pipflow.taskdomain import report_score, report_simulation
from pipflow.values import SIMULATION, Score, SimulationCore


@shape(SIMULATION)
class PybulletSimulation(SimulationCore):
    """The outputs of ``simulate.pybullet``: the simulation core, the final stock again under the
    name older workflows read, the most units each shelf held, units left off the shelves, and
    the file names of the pictures drawn."""

    final_stock: dict[str, dict[str, int]]
    peak_load: dict[str, int]
    stray_units: int
    pictures: list[str]


def _domain():
    from pipflow.warehouse.domain import WarehouseDomain  # deferred: see the module docstring

    return WarehouseDomain()


@step(
    "simulate.pybullet",
    doc="Execute the schedule in a headless pybullet warehouse; read stock and travel back from the bodies.",
    version="3",  # 3: final_state beside final_stock (the simulation core); 2: tc_avg over the robots that moved
)
def simulate_pybullet(
    ctx: StepContext,
    world: Annotated[dict, Doc("the world (output of world.load)")],
    schedule: Annotated[dict, Doc("the schedule (output of schedule)")],
    graph: Annotated[dict | None, Doc("the dependency graph: units, fields and route per subtask")] = None,
    goal: Annotated[dict | None, Doc("{SHELF: {PRODUCT: units}} to judge the final stock against")] = None,
    snapshots: Annotated[bool, Doc("save key-moment snapshots and the path map (PNG)")] = False,
    animation: Annotated[bool, Doc("save a top-down animation GIF (needs Pillow)")] = False,
    picture: Annotated[bool, Doc("save the path map (PNG) without snapshots (workflows pass pictures == "
                                 "'always')")] = False,
) -> PybulletSimulation:
    """The trajectories and event log are bulky: an artifact (trajectories.json), not outputs."""
    result = _domain().simulate(world, schedule, graph, goal, snapshots=snapshots,
                                out_dir=ctx.artifact_path("paths.png").parent, log=ctx.log,
                                save=ctx.write_artifact, animation=animation, picture=picture)
    return report_simulation(ctx, {"final_stock": result["final_state"], "pictures": [], **result}, schedule)


@step(
    "metrics.score",
    doc="Score a run: success (goal, constraints, conservation, capacity, skills), GCR, Exe, RU, TC-max, "
        "TC-avg over the robots that moved (tc_avg) and over every robot (tc_avg_team).",
)
def score(
    ctx: StepContext,
    world: Annotated[dict, Doc("the world (output of world.load)")],
    goal: Annotated[dict, Doc("ground-truth goal {SHELF: {PRODUCT: units}}")],
    constraints: Annotated[list | None, Doc("ground-truth only/never rules")] = None,
    graph: Annotated[dict | None, Doc("dependency graph (fields and skills per subtask)")] = None,
    schedule: Annotated[dict | None, Doc("the schedule that was simulated")] = None,
    simulation: Annotated[dict | None, Doc("outputs of simulate.pybullet (or of simulate)")] = None,
    feasible: Annotated[bool, Doc("false: only a refusal with nothing executed succeeds")] = True,
    refusal: Annotated[str | None, Doc("refusal message, when the pipeline refused")] = None,
) -> Score:
    result = _domain().score(world, goal, constraints=constraints or [], feasible=feasible, graph=graph,
                             schedule=schedule, simulation=simulation, refusal=refusal)
    return report_score(ctx, result)

"""The values that cross pipflow's steps, typed, each with its one JSON form.

Why one module: the world, the goal, the schedule, a simulation's result and a score travel from
step to step, into run records, bench rows, the report and the view. As plain dicts described in
prose each reader guessed their shape from their keys (the report found "the simulation" by the
warehouse's key ``final_stock``, and missed every other domain's). Here each is a ``TypedDict``
(its JSON form is itself: records stay plain JSON) and each step declares what it returns by its
return annotation (:mod:`pipflow.engine.step`); the families a reader looks for carry a
:func:`~pipflow.engine.step.shape`, which the run record keeps beside each step.

What a domain fills in its own way (the world's places, a goal, a final state) is typed here by
what every domain shares, and is otherwise the domain's (docs/architecture.md, "Data between
steps"). Also here: what a bench task says about its right answer (:func:`refusal_expected`) and
how a run that was refused ends (:data:`REFUSED_AS_IMPOSSIBLE`, :data:`NOT_UNDERSTOOD`), each once.
"""
from __future__ import annotations

from typing import Any, Mapping, TypedDict

from pipflow.engine.step import shape

# ------------------------------------------------------------------------------------------
# the families a reader of run records looks for (the names the record keeps)
# ------------------------------------------------------------------------------------------
WORLD = "world"
READING = "reading"
DEBUG = "debug"
PLAN = "plan"
VERIFY = "verify"
CHECK = "check"
GRAPH = "graph"
ALLOCATION = "allocation"
SCHEDULE = "schedule"
EXECUTION = "execution"
SIMULATION = "simulation"
SCORE = "score"

# ------------------------------------------------------------------------------------------
# bench tasks: when a refusal is the right answer, and how a refused run ends
# ------------------------------------------------------------------------------------------
#: how a run ends when its command was refused as impossible in its world (understood, then refused)
REFUSED_AS_IMPOSSIBLE = "Refusal"
#: how a run ends when its reader refused to guess (a word it could not place, an ambiguity)
NOT_UNDERSTOOD = "TranslationError"


def impossible(task: Mapping[str, Any]) -> bool:
    """The task says its command cannot be done in its world (``feasible: false``): the right
    answer is a refusal as impossible."""
    return task.get("feasible", True) is False


def states_goal(task: Mapping[str, Any]) -> bool:
    """Whether the task writes down what its command asks: a goal with something in it. An impossible
    command's goal may be left out or empty ("no goal needed"; ``{}`` when the literal goal cannot
    be written): then there is nothing to compare a reading with, and an empty goal is never what
    a command asks (it would hold already)."""
    goal = task.get("goal")
    return isinstance(goal, Mapping) and any(bool(v) for v in goal.values())


def ambiguous(task: Mapping[str, Any]) -> bool:
    """The task says its command can be read more than one way (``expect: refuse``): the right
    answer is a refusal to guess, quoting the words."""
    return task.get("expect") == "refuse"


def refusal_expected(task: Mapping[str, Any]) -> bool:
    """A refusal is the right answer to the task (impossible or ambiguous): it succeeds exactly
    when the run was refused with a reason and nothing moved."""
    return impossible(task) or ambiguous(task)


#: the usage record of a reading that called no model (the offline reader)
NO_USAGE: dict[str, Any] = {"calls": 0, "cached": False, "prompt_tokens": 0, "completion_tokens": 0,
                            "total_tokens": 0, "latency_s": 0.0, "cost_usd": 0.0}


# ------------------------------------------------------------------------------------------
# the world
# ------------------------------------------------------------------------------------------
class Robot(TypedDict):
    """A robot of the team, in every domain."""

    start: list[float]                 # [x, y] in metres
    skills: dict[str, float]           # skill -> level (the allocation's Q)
    kind: str | None                   # commands select robots by it ("the tugs")
    tags: list[str]


class Place(TypedDict):
    """A fixture of the floor plan (a shelf, a counter, a bed): its footprint, where a robot
    stands to use it; a domain adds what it holds. Travel and pictures read only these."""

    x: float
    y: float
    width: float
    depth: float
    access: list[float]                # [x, y]


class World(TypedDict, total=False):
    """A world file's content, normalized by its task domain (the output ``world`` of
    ``world.load``): what every domain's world has; the domain's own facts sit beside them
    (stock on shelves, objects in places, crops in beds)."""

    domain: str                        # absent: the default domain
    name: str
    path: str
    floor: dict[str, float]            # {width, height}
    robots: dict[str, Robot]


# ------------------------------------------------------------------------------------------
# the schedule (Alg. 1)
# ------------------------------------------------------------------------------------------
Leg = TypedDict("Leg", {"subtask": str, "from": list, "to": list, "path": list, "start": float, "end": float,
                        "distance": float})


class RobotPlan(TypedDict):
    legs: list[Leg]
    distance: float


class ScheduledSubtask(TypedDict):
    id: str
    action: str
    args: list[str]
    robots: list[str]
    ready: float
    start: float
    end: float


class Schedule(TypedDict):
    """Output ``schedule`` of the step of that name: when each subtask runs, who drives where."""

    subtasks: list[ScheduledSubtask]
    robots: dict[str, RobotPlan]
    makespan: float
    tc_max: float
    tc_avg: float
    tc_avg_team: float


# ------------------------------------------------------------------------------------------
# simulation and score: one shape per family, every domain
# ------------------------------------------------------------------------------------------
class SimulationCore(TypedDict):
    """What every domain's simulation returns (:meth:`pipflow.taskdomain.TaskDomain.simulate`),
    plus keys of its own. ``final_state`` is the domain's own picture of the world afterwards
    (stock per shelf, where each object is); travel is metres per robot, and ``tc_max``,
    ``tc_avg`` (over the robots that moved: the paper's TC-avg) and ``tc_avg_team`` (over every
    robot) come from it through :func:`pipflow.metrics.travel_costs`; ``gcr`` is
    :func:`pipflow.metrics.goal_condition_recall`; ``jumps`` the legs that start away from where
    a robot stood (a broken schedule); ``failures`` the subtasks the simulation refused, each
    ``{subtask, action, reasons, ...}``."""

    final_state: dict[str, Any]
    executed: int
    failed: int
    failures: list[dict]
    exe: float
    travel: dict[str, float]
    tc_max: float
    tc_avg: float
    tc_avg_team: float
    goal_met: bool
    gcr: float
    jumps: dict[str, list]
    makespan: float


@shape(SIMULATION)
class Simulation(SimulationCore):
    """The outputs of the generic step ``simulate``: the core, the file names of the pictures it
    drew (``pictures``, artifacts of the step) and the domain's own keys under ``details``."""

    pictures: list[str]
    details: dict[str, Any]


@shape(SCORE)
class Score(TypedDict):
    """One run judged against its task, flat: the outputs of every score step and the scoring
    columns of a bench row; the metrics mean what :mod:`pipflow.metrics` says."""

    success: bool
    goal_met: bool
    gcr: float
    exe: float
    ru: float
    tc_max: float
    tc_avg: float
    tc_avg_team: float
    makespan: float
    planned: int
    executed: int
    lower_bound: Any                   # RU's reference (int), None when there is none
    violations: list[str]
    refused: bool
    error: Any                         # the refusal's or the failure's message, else None


#: the figures every simulation step records as the step's metrics
SIMULATION_METRICS = ("exe", "tc_max", "tc_avg", "tc_avg_team", "gcr")
#: the headline figures every score step records as the step's metrics
SCORE_METRICS = ("success", "gcr", "exe", "ru", "tc_max", "tc_avg", "tc_avg_team")


def simulation_outputs(result: Mapping[str, Any]) -> Simulation:
    """A domain's simulation result in the generic step's shape: the core keys, ``pictures``
    (none: ``[]``) and every other key under ``details``. A result that lacks a core key is the
    domain's bug, said with the keys it lacks."""
    core = SimulationCore.__annotations__
    missing = [key for key in core if key not in result]
    if missing:
        raise TypeError(f"a simulation result lacks {', '.join(missing)} (every domain returns the SimulationCore)")
    outputs: dict[str, Any] = {key: result[key] for key in core}
    outputs["pictures"] = list(result.get("pictures") or [])
    outputs["details"] = {k: v for k, v in result.items() if k not in outputs}
    return outputs  # type: ignore[return-value]


def split_refused(schedule: Mapping[str, Any]) -> tuple[dict, list[dict]]:
    """The schedule a domain's simulation runs (without its refused subtasks) and the refused
    ones: actions of a plan that cannot be placed in the world (a place or object the world
    lacks, a robot that does not exist; :meth:`pipflow.team.scheduling.Timeline.refuse`). No
    domain's simulation has to know them: :func:`count_refused` adds them to its result."""
    subtasks = list(schedule.get("subtasks") or [])
    refused = [s for s in subtasks if s.get("refused")]
    if not refused:
        return dict(schedule), []
    return {**schedule, "subtasks": [s for s in subtasks if not s.get("refused")]}, refused


def count_refused(result: dict, refused: list[dict], planned: int) -> dict:
    """A simulation's result with the refused subtasks (:func:`split_refused`) counted: each is
    planned and failed, with its reasons among ``failures``, and Exe is executed over every
    planned action (``planned``, the whole schedule's subtasks)."""
    if not refused:
        return result
    failures = list(result.get("failures") or []) + [
        {"subtask": s["id"], "action": s.get("action"), "args": list(s.get("args") or []),
         "time": round(float(s.get("start", 0.0)), 3), "reasons": list(s["refused"])} for s in refused]
    executed = int(result.get("executed", 0))
    return {**result, "failed": int(result.get("failed", 0)) + len(refused), "failures": failures,
            "exe": executed / planned if planned else 1.0}


def flat_simulation(simulation: Mapping[str, Any] | None) -> dict | None:
    """A simulation as one flat mapping, from the generic step's shape (``details`` nested) or a
    domain step's (flat): what scoring reads. None stays None (no simulation ran)."""
    if simulation is None:
        return None
    details = simulation.get("details")
    rest = {k: v for k, v in simulation.items() if k != "details"}
    return {**details, **rest} if isinstance(details, Mapping) else rest


# ------------------------------------------------------------------------------------------
# the outputs of the built-in steps (their families)
# ------------------------------------------------------------------------------------------
@shape(WORLD)
class WorldOutputs(TypedDict):
    world: World


@shape(READING)
class ProblemReading(TypedDict):
    """``llm.problem``: one generator round (offline: the domain's reading of the command)."""

    problem: str
    goal: Any
    constraints: list
    messages: list
    response: str
    usage: dict
    errors: list
    order: Any                         # offline: the order, where the domain has one
    explanation: Any                   # offline: the reading's arithmetic in words
    varied: str                        # what changed in a prompt that would repeat
    round: dict                        # this round, for the next one
    concrete: dict                     # offline, where the domain has it: the goal with counts resolved
    reader: str                        # who wrote this round's goal: offline or model


@shape(DEBUG)
class DebugOutputs(TypedDict):
    ok: bool
    messages: list
    problem: str


@shape(PLAN)
class SolveOutputs(TypedDict):
    """``engine``: the engine that answered; ``requested``: the one asked for; ``fallback``: when
    they differ, why the first could not answer (None otherwise)."""

    status: str
    plan: list
    message: str
    messages: list
    time: float
    engine: str
    requested: str
    fallback: str


@shape(VERIFY)
class VerifyOutputs(TypedDict):
    ok: bool
    messages: list
    refusal: str
    goal: dict


@shape(CHECK)
class CheckOutputs(TypedDict):
    ok: bool
    messages: list
    refusal: str
    disagreement: list
    basis: str


@shape(GRAPH)
class GraphOutputs(TypedDict):
    graph: dict


@shape(ALLOCATION)
class AllocationOutputs(TypedDict):
    allocation: dict
    cost: str


@shape(SCHEDULE)
class ScheduleOutputs(TypedDict):
    schedule: Schedule
    makespan: float
    tc_max: float
    tc_avg: float
    tc_avg_team: float


@shape(EXECUTION)
class ExecutionOutputs(TypedDict):
    """``execute`` (:mod:`pipflow.execution`): the world as it really was, the schedule the robots
    really carried out and its graph (what the simulation then plays), the faults, the recovery
    rounds, the refusal when the goal went out of reach, whether it was still reachable
    (``feasible``: None when unknown) and why, and the faults asked for that did not apply to the
    run (``not_applicable``: id, kind, name, why; :class:`pipflow.execution.faults.NotApplicable`)."""

    world: dict
    schedule: dict
    graph: dict
    faults: list
    recoveries: list
    refusal: Any
    feasible: Any
    feasibility: str
    not_applicable: list

"""What a task domain provides so that faults can be injected into its runs and its runs
recovered: an optional capability, a mixin of a few methods, kept apart from the required core
of :class:`pipflow.taskdomain.TaskDomain` (a domain without it runs exactly as before; a run that
asks it for faults is refused, naming what is missing).

Why these methods and no others: everything about robots, time, paths, allocation and planning
is generic (:mod:`pipflow.execution`); what only the domain knows is how its world changes and
how it is written down:

* :meth:`play`: its simulation, played on demand, reporting when each subtask's work began and
  ended (the monitor compares that with the schedule);
* the state **surprise**: how one is drawn for a schedule, checked when written by hand, and put
  into a world (the world file was wrong there);
* :meth:`with_state`: a world whose initial state is a state the simulation reached (so the
  domain's own problem writer writes the observed state as a new PDDL problem), and
  :meth:`drop_place`: a place where a robot that stopped keeps what it was carrying;
* :meth:`plan_goal`: the goal of an accepted problem, as the writer takes it, and
  :meth:`observed_problem`: that goal from an observed state as a parsed problem (by default
  written and parsed; a domain may build it faster);
* :meth:`feasibility`: whether the remaining robots can still reach the goal from a state,
  checked independently of the planner (the bench's denominator for runs after a fault).
"""
from __future__ import annotations

import random
from dataclasses import dataclass, field
from typing import Any, ClassVar

from pipflow.errors import InputError, PlanningError
from pipflow.liberrors import UNIFIED_PLANNING, library_errors
from pipflow.pddl.common import parse
from pipflow.taskdomain import Capability, pddl_domain_name, register_capability


@dataclass
class Played:
    """A schedule played in a domain's simulation, as the executor reads it.

    ``began``/``ended``: when each subtask's work began (its first effect: a load, a pick-up) and
    ended (its effects landed); ``failures``: subtasks refused when they were due ``{"subtask",
    "time", "reasons"}``; ``interrupted``: subtasks whose coalition lost a member while they ran
    (their effects did not land as planned); ``result``: the simulation's own result."""

    final_state: Any
    began: dict[str, float] = field(default_factory=dict)
    ended: dict[str, float] = field(default_factory=dict)
    failures: list[dict] = field(default_factory=list)
    interrupted: dict[str, float] = field(default_factory=dict)
    result: dict = field(default_factory=dict)


@register_capability
class ExecutionCapability:
    """Mixin for a :class:`~pipflow.taskdomain.TaskDomain` whose runs can take faults (module doc).

    A robot that stops is described in a world as ``world["robots"][name]["stopped"] = {"time":
    t, "drop": place or None}``: the simulation then refuses its work from ``t`` on and, when it
    carried something, puts that on the ``drop`` place at ``t``."""

    capability: ClassVar[Capability] = Capability.EXECUTION
    #: the domain's own names for a state surprise (``--faults stock-surprise=1``); ``surprise``
    #: always works
    surprise_names: ClassVar[tuple[str, ...]] = ()

    def play(self, world: dict, schedule: dict, graph: dict | None) -> Played:
        """Play ``schedule`` in the domain's simulation of ``world`` (no pictures)."""
        raise NotImplementedError

    def draw_surprise(self, world: dict, schedule: dict, graph: dict | None,
                      rng: random.Random) -> dict | None:
        """A surprise that matters to this schedule (at a place it takes something from), drawn
        with ``rng``; when the schedule offers none, None or :class:`pipflow.errors.FaultNotApplicable`
        saying why in the domain's words (the run goes on without it). The dict has ``places`` (where a robot
        that arrives notices it), ``words`` (what it is) and the domain's own fields; or ``parts``,
        a list of such dicts found each on its own (units missing at one place lie at another),
        and ``how`` it came about (the domain's word, kept in the record)."""
        return None

    def check_surprise(self, world: dict, given: dict, where: str) -> dict:
        """A surprise written by hand, checked (InputError naming ``where`` and the cause) and
        completed into the form :meth:`draw_surprise` returns."""
        raise InputError(f"{where}: this task domain does not describe state surprises")

    def apply_surprise(self, world: dict, surprise: dict) -> dict:
        """A copy of ``world`` whose state is what it really is under ``surprise``."""
        raise NotImplementedError

    def as_it_was(self, world: dict, faults: list[dict] | None) -> dict:
        """The world as a run under ``faults`` (an ``execute`` step's output) really found it:
        every surprise in it put in (:meth:`apply_surprise`). What a bench scores such a run
        against (the units or objects the records got wrong were never the run's to conserve)."""
        for fault in faults or []:
            if isinstance(fault, dict) and fault.get("kind") == "surprise" and fault.get("surprise"):
                world = self.apply_surprise(world, fault["surprise"])
        return world

    def with_state(self, world: dict, state: Any) -> dict:
        """A copy of ``world`` whose initial state is ``state`` (a :class:`Played` final state)."""
        raise NotImplementedError

    def drop_place(self, world: dict, robot: str, site: dict) -> tuple[dict, str]:
        """A copy of ``world`` with a place (footprint and access point ``site``) where robot
        ``robot``, stopped, keeps what it carries; and the place's name."""
        raise NotImplementedError

    def observed_problem(self, parsed_problem: Any, world: dict, goal: Any, domain_text: str,
                         name: str) -> tuple[Any, str]:
        """The problem of ``goal`` from ``world``'s state (its robots: those still working): the
        parsed UP problem and its text. By default the domain's writer writes it and UP parses
        it; a domain may build it faster from ``parsed_problem`` (the accepted problem, parsed),
        which is read-only (clone it)."""
        text = self.write_problem(world, goal, pddl_domain_name(domain_text, getattr(self, "name", "")), name=name)
        with library_errors(UNIFIED_PLANNING, PlanningError, "reading the recovery problem"):
            return parse(domain_text, text), text

    def plan_goal(self, parsed_problem: Any, world: dict) -> Any:
        """The goal of an accepted (parsed) problem, in the form :meth:`write_problem` takes."""
        raise NotImplementedError

    def feasibility(self, world: dict, goal: Any, constraints: list[dict]) -> tuple[bool | None, str]:
        """Whether the robots of ``world`` (the ones still working) can still reach ``goal`` from
        its state under the robot rules, and why: checked without the planner. None: unknown."""
        return None, "this task domain does not check feasibility"


class ModuleExecution(ExecutionCapability):
    """The capability for a domain that keeps its side of it in a module of plain functions
    (``fault_model``: ``play``, ``draw_surprise``, ``check_surprise``, ``apply_surprise``,
    ``with_state``, ``drop_place``, ``plan_goal``, ``feasibility``, taking the same arguments as
    these methods, and ``SURPRISE_NAMES``): the delegation written once, not per domain."""

    fault_model: ClassVar[Any]

    def __init_subclass__(cls, **kwargs: Any) -> None:
        super().__init_subclass__(**kwargs)
        if "fault_model" in cls.__dict__:
            cls.surprise_names = tuple(cls.fault_model.SURPRISE_NAMES)

    def play(self, world: dict, schedule: dict, graph: dict | None) -> Played:
        return self.fault_model.play(world, schedule, graph)

    def draw_surprise(self, world: dict, schedule: dict, graph: dict | None, rng: random.Random) -> dict | None:
        return self.fault_model.draw_surprise(world, schedule, graph, rng)

    def check_surprise(self, world: dict, given: dict, where: str) -> dict:
        return self.fault_model.check_surprise(world, given, where)

    def apply_surprise(self, world: dict, surprise: dict) -> dict:
        return self.fault_model.apply_surprise(world, surprise)

    def with_state(self, world: dict, state: Any) -> dict:
        return self.fault_model.with_state(world, state)

    def drop_place(self, world: dict, robot: str, site: dict) -> tuple[dict, str]:
        return self.fault_model.drop_place(world, robot, site)

    def plan_goal(self, parsed_problem: Any, world: dict) -> Any:
        return self.fault_model.plan_goal(parsed_problem, world)

    def feasibility(self, world: dict, goal: Any, constraints: list[dict]) -> tuple[bool | None, str]:
        return self.fault_model.feasibility(world, goal, constraints)


def capable(domain: Any) -> ExecutionCapability:
    """``domain`` if it has the execution capability, else an InputError saying so."""
    if not isinstance(domain, ExecutionCapability):
        name = getattr(domain, "name", type(domain).__name__)
        raise InputError(f"the {name!r} task domain does not support faults: its domain class does not provide "
                         f"pipflow.execution.capability.ExecutionCapability (play, surprises, state)")
    return domain

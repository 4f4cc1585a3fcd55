"""The one public face for authors of a task-domain plugin: everything a domain package needs of
pipflow, re-exported here, so it imports ``pipflow.plugin`` and nothing else of pipflow.

Why one face: a plugin that reached into pipflow's modules (``pipflow.language.offline``'s usage
record, ``pipflow.pddl.common``) broke whenever those rooms were rearranged, and its author could
not tell a stable name from an internal one. What is here is the supported surface (it changes
only with a note in the README); what is not is pipflow's own business.

The surface, by what a domain does (README, "Writing a domain plugin"):

* **the protocol** -- :class:`TaskDomain` (the required core and the template methods), the
  capability mixins :class:`ComparesGoals`, :class:`SecondOpinion`, :class:`TransportPlanning`,
  :class:`GroundedDecoding`, :class:`OwnBenchTable`, :class:`ExecutionCapability` (execution under
  faults: what :meth:`ExecutionCapability.play` returns is a :class:`Played`; :class:`ModuleExecution`
  when a module of functions holds the domain's side of it) and
  :class:`Capability`; the small values its methods return: :class:`Reading`, :class:`Condition`,
  :class:`Reference`, :class:`GoalCheck`, :class:`Facts`;
  ``Save`` (the artifact hook a simulation gets) and :func:`pddl_domain_name`;
* **typed values** -- :class:`World`, :class:`Robot`, :class:`Place`, :class:`Schedule`,
  :class:`SimulationCore`, :class:`Score` (:mod:`pipflow.values`), and
  :func:`refusal_expected` (when a refusal is a task's right answer);
* **world and task files** -- :func:`read_world_file`, :func:`parse_mapping`, :func:`is_point`
  (located YAML), :class:`WorldChecker` (sections, names, numbers, footprints and the robot team,
  every problem located at once), :func:`load_task_file` (a task file and its world, checked);
* **the floor plan** -- :func:`footprint`, :func:`inside_footprint`, :func:`seeded_starts`;
* **metrics** -- :func:`travel_costs`, :func:`goal_condition_recall` (pipflow's one definition
  of TC and GCR);
* **problems** -- :func:`goal_atoms`, :func:`number_value`, :func:`fluent_call` (what a parsed
  UP problem's goal and initial state say);
* **words for users** -- :func:`did_you_mean`, :func:`closest`;
* **errors** -- :class:`Diagnostic`, :class:`WorldError`, :class:`TaskFileError`,
  :class:`TranslationError` (refuse, never guess: the words that could not be placed),
  :class:`Refusal` (impossible in this world), :class:`InputError`;
* **steps** -- :func:`step`, :class:`StepContext`, :class:`Doc`, :data:`PathStr`, :func:`shape`,
  for a domain that also ships steps of its own.
"""
from __future__ import annotations

from pipflow.engine.step import Doc, PathStr, StepContext, shape, step
from pipflow.errors import Diagnostic, InputError, Refusal, TaskFileError, TranslationError, WorldError
from pipflow.execution.capability import ExecutionCapability, ModuleExecution, Played
from pipflow.floorplan import footprint, inside_footprint, seeded_starts
from pipflow.metrics import goal_condition_recall, travel_costs
from pipflow.pddl.common import fluent_call, goal_atoms, number_value
from pipflow.suggest import closest, did_you_mean
from pipflow.taskdomain import (Capability, ComparesGoals, Condition, Facts, GoalCheck, GroundedDecoding,
                                OwnBenchTable, Reading, Reference, Save, SecondOpinion, TaskDomain, TransportPlanning,
                                pddl_domain_name)
from pipflow.taskfile import load_task_file
from pipflow.values import Place, Robot, Schedule, Score, SimulationCore, World, refusal_expected
from pipflow.worldcheck import WorldChecker
from pipflow.worldfile import is_point, parse_mapping, read_world_file

__all__ = [
    # the protocol
    "TaskDomain", "Capability", "ComparesGoals", "SecondOpinion", "TransportPlanning", "GroundedDecoding",
    "OwnBenchTable", "ExecutionCapability", "ModuleExecution", "Played", "Reading", "Condition", "Reference", "GoalCheck", "Facts",
    "Save", "pddl_domain_name",
    # typed values
    "World", "Robot", "Place", "Schedule", "SimulationCore", "Score", "refusal_expected",
    # files
    "read_world_file", "parse_mapping", "is_point", "WorldChecker", "load_task_file",
    # floor plan, metrics, problems, words
    "footprint", "inside_footprint", "seeded_starts", "travel_costs", "goal_condition_recall",
    "goal_atoms", "number_value", "fluent_call", "did_you_mean", "closest",
    # errors
    "Diagnostic", "WorldError", "TaskFileError", "TranslationError", "Refusal", "InputError",
    # steps
    "step", "StepContext", "Doc", "PathStr", "shape",
]

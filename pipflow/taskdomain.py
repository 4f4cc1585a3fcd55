"""The task-domain protocol: a small required core, optional capabilities, and the logic every
domain shares written once.

Why this shape: the generator, the debugger, the verifier, the planner step, the LLM check, the
simulation and score steps and the bench are the same for every kind of task (pallets in a
warehouse, a tidy home, a garden); what differs is how a world file is read, how a command is
read and a goal written as PDDL, how a schedule is simulated and what a final state means. The
generic modules ask :func:`pipflow.taskdomains.task_domain` for the world's domain and call it;
they never name a domain.

* **The required core** (abstract methods: a domain that leaves one out cannot be instantiated,
  and says which): the files it ships (:meth:`~TaskDomain.pddl_domain`,
  :meth:`~TaskDomain.action_metadata`); load a world and describe it; read a command
  (:meth:`~TaskDomain.read_command`); write a problem and read one back
  (:meth:`~TaskDomain.write_problem`, :meth:`~TaskDomain.read_goal`); check a goal
  (:meth:`~TaskDomain.goal_problems`); simulate; the facts scoring needs (the initial state, the
  goal's conditions in a state, RU's reference).
* **Template methods**, written here once and the same for every domain (kedro's runner: the
  base does the work, the domain supplies small hooks): the offline reading
  (:meth:`~TaskDomain.read_offline`), the verifier's goal check (:meth:`~TaskDomain.check_goal`),
  a model's problem read back (:meth:`~TaskDomain.read_problem`), the score of a run
  (:meth:`~TaskDomain.score`: one definition of success, GCR, Exe, RU and TC in every domain),
  a bench run's row (:meth:`~TaskDomain.score_bench_run`) and whether it understood its command
  (:meth:`~TaskDomain.understand`). Hooks with defaults a domain may override:
  :meth:`~TaskDomain.describe`, :meth:`~TaskDomain.places`, :meth:`~TaskDomain.rule_names`,
  :meth:`~TaskDomain.example_problem`, :meth:`~TaskDomain.feedback_facts`,
  :meth:`~TaskDomain.world_mismatches`, :meth:`~TaskDomain.final_state`,
  :meth:`~TaskDomain.rule_violations`, :meth:`~TaskDomain.extra_violations`,
  :meth:`~TaskDomain.load_tasks` (a plain task file, :mod:`pipflow.taskfile`) with
  :meth:`~TaskDomain.task_goal_problems`, :meth:`~TaskDomain.task_world`, and the report's
  :meth:`~TaskDomain.goal_words`, :meth:`~TaskDomain.floor_plan` (from :meth:`~TaskDomain.places`),
  :meth:`~TaskDomain.table_groups`.
* **Capabilities** (mixins, the way unified-planning's engines declare their operation modes):
  a domain that offers grounded decoding, a second opinion in the checked loop, pipflow's
  transport planner, a comparison of goals by meaning, a bench table of its own or execution
  under faults (:class:`pipflow.execution.capability.ExecutionCapability`, which registers itself
  with :func:`register_capability` from the layer above) inherits the mixin and writes its
  methods; callers ask :meth:`TaskDomain.supports` (never a method that answers "not supported"
  with None).

A third-party package adds a domain by subclassing :class:`TaskDomain` (imported from the one
public face, :mod:`pipflow.plugin`) and registering it in the entry-point group
``pipflow.task_domains`` (README, "Writing a domain plugin"). Methods never raise for a world
they cannot judge; user errors are :class:`pipflow.errors.InputError` subclasses with the file,
line and cause (WorldError, TranslationError, Refusal).

A world dict names its domain with ``world["domain"]``; a world without one is of the default
domain (:data:`DEFAULT_DOMAIN`), as every world file was before domains were named. The values
that cross the interface are typed in :mod:`pipflow.values`.
"""
from __future__ import annotations

import re
from abc import ABC, abstractmethod
from dataclasses import dataclass, field
from enum import Enum
from pathlib import Path
from typing import Any, Callable, ClassVar, Iterable, Mapping, NamedTuple

from pipflow.meaning import judge, rules_as_written, rules_difference
from pipflow.scoring import score_run
from pipflow.taskfile import GoalProblem, load_task_file
from pipflow.values import NO_USAGE, SCORE_METRICS, SIMULATION_METRICS, Score, refusal_expected

#: the domain of a world (or task file) that does not name one
DEFAULT_DOMAIN = "warehouse"

#: the line the default example problem leaves in its goal: where the command's conditions go
GOAL_PLACEHOLDER = "; the goal conditions of the command go here"

#: ``save(name, data)``: keep an artifact of the step (the engine's ``ctx.write_artifact``)
Save = Callable[[str, Any], Any]


def plain_words(value: Any, prefix: str = "") -> list[str]:
    """``{"a": {"b": [1, 2]}}`` -> ``["a b: 1, 2"]``: any JSON value as lines of words."""
    if isinstance(value, Mapping):
        lines: list[str] = []
        for key, inner in value.items():
            lines += plain_words(inner, f"{prefix} {key}".strip())
        return lines
    if isinstance(value, (list, tuple)):
        if all(not isinstance(x, (Mapping, list, tuple)) for x in value):
            return [f"{prefix}: {', '.join(map(str, value))}" if prefix else ", ".join(map(str, value))]
        return [line for x in value for line in plain_words(x, prefix)]
    return [f"{prefix}: {value}" if prefix else str(value)]


def pddl_domain_name(domain_text: str, default: str) -> str:
    """The name in ``(define (domain NAME)`` of a PDDL domain text, or ``default``: a problem must
    name the domain it is read with."""
    m = re.search(r"\(\s*domain\s+([^\s()]+)", domain_text or "", flags=re.IGNORECASE)
    return m.group(1) if m else default


# ------------------------------------------------------------------------------------------
# small values of the protocol
# ------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class Reading:
    """A command read offline (:meth:`TaskDomain.read_command`): the goal it asks for (the
    domain's goal form, compared with a task's gold), the robot rules it states, and what
    explains it: ``order`` (the typed meaning, where the domain has one), ``explanation`` (the
    arithmetic in words). ``concrete``: the goal the problem asks for when it is not ``goal``
    itself (counts resolved to objects); None: ``goal``."""

    goal: Any
    constraints: list[dict] = field(default_factory=list)
    order: Any = None
    explanation: Any = None
    concrete: Any = None

    @property
    def problem_goal(self) -> Any:
        """What the written problem asks for."""
        return self.goal if self.concrete is None else self.concrete


@dataclass(frozen=True)
class GoalCheck:
    """What the verifier learns from a problem's goal in a world: the goal as data (shown in the
    step's ``goal`` output), problems with it worth feeding back, and a refusal reason when no
    plan can ever reach it in this world (more units than exist, slicing a mug)."""

    goal: Any = field(default_factory=dict)
    messages: list[str] = field(default_factory=list)
    refusal: str | None = None


@dataclass(frozen=True)
class Facts:
    """What a domain tells a model about the names that feedback messages mention, for a prompt
    that would otherwise repeat (:mod:`pipflow.language.feedback`): ``together``: groups of names
    that one message names together (a line of the quoted previous answer that names every name
    of a group is marked); ``lines``: the world's facts about those names, one line each."""

    together: list[tuple[str, ...]] = field(default_factory=list)
    lines: list[str] = field(default_factory=list)


class Condition(NamedTuple):
    """One condition of a goal in a state: what it asks, in words, and whether it holds."""

    words: str
    holds: bool


class Reference(NamedTuple):
    """RU's reference for a goal: the fewest team actions a plan needs (None: no plan can meet
    the goal, or no reference) and, where worth saying, how it was found."""

    actions: int | None
    how: str = ""


# ------------------------------------------------------------------------------------------
# capabilities
# ------------------------------------------------------------------------------------------
class Capability(str, Enum):
    """What a domain may offer beyond the core (:meth:`TaskDomain.supports`)."""

    GROUNDED_DECODING = "grounded decoding"      # GroundedDecoding
    SECOND_OPINION = "second opinion"            # SecondOpinion
    TRANSPORT_PLANNER = "transport planner"      # TransportPlanning
    UNDERSTANDING = "understanding"              # ComparesGoals
    BENCH_TABLE = "bench table"                  # OwnBenchTable
    EXECUTION = "execution"                      # pipflow.execution.capability.ExecutionCapability

    def __str__(self) -> str:
        return self.value


class GroundedDecoding:
    """Capability: the model answers in a constrained form (an order in JSON) instead of PDDL."""

    capability: ClassVar[Capability] = Capability.GROUNDED_DECODING

    @abstractmethod
    def grounding_gbnf(self, world: dict) -> str:
        """A llama.cpp grammar of the answers allowed in ``world``."""

    @abstractmethod
    def grounding_schema(self, world: dict) -> dict:
        """An OpenAI ``response_format`` (JSON schema) of the answers allowed in ``world``."""

    @abstractmethod
    def read_grounded(self, text: str, world: dict) -> dict:
        """An answer checked, resolved and its problem written: ``{"problem", "goal",
        "constraints", "order", "explanation", "errors"}`` (raises
        :class:`pipflow.language.parsing.ParseIssue` with words for the model)."""

    @abstractmethod
    def answer_size(self, world: dict, reading: Any) -> tuple[int, int]:
        """``(goal items, rules)`` a grounded answer is expected to hold, from the offline
        reading's outputs when the parser read the command (``reading``, else None: from the
        world's size): the call's token budget (:mod:`pipflow.language.budget`)."""


class SecondOpinion:
    """Capability: the checked loop compares a model's goal and rules with the offline reading."""

    capability: ClassVar[Capability] = Capability.SECOND_OPINION

    @abstractmethod
    def second_opinion(self, command: str, world: dict, goal: Any, constraints: list[dict],
                       refusal: str | None, last: bool = False) -> Any:
        """The test of a model's goal and rules against the offline reading of the command, or the
        doubts the command's words raise when the parser does not read it (a
        :class:`pipflow.language.agreement.Opinion`, usually from
        :func:`pipflow.language.agreement.judge`); feedback names what disagrees and the command's
        words, never the reading's value. ``last``: the loop's last round. A domain without it:
        only whether the verifier's refusal is final is decided."""


class TransportPlanning:
    """Capability: the domain's problems are transport problems pipflow's own planner solves."""

    capability: ClassVar[Capability] = Capability.TRANSPORT_PLANNER

    @abstractmethod
    def planner_params(self, world: dict, constraints: list[dict]) -> dict:
        """Parameters for the transport planner: robots' capacities, the only/never rules."""


class ComparesGoals:
    """Capability: the bench measures whether a run understood its command, comparing the goal
    it resolved with the task's gold by meaning (:meth:`TaskDomain.understand`)."""

    capability: ClassVar[Capability] = Capability.UNDERSTANDING

    @abstractmethod
    def goal_difference(self, world: dict | None, gold: Any, run: Any) -> str | None:
        """None when the two goals mean the same in ``world`` (None: compare them as written);
        otherwise what differs, in words."""


class OwnBenchTable:
    """Capability: the bench's markdown table grouped the domain's way (else one row per task)."""

    capability: ClassVar[Capability] = Capability.BENCH_TABLE

    @abstractmethod
    def bench_table(self, results: dict, tasks_file: Path) -> str:
        """The markdown table of a bench's ``results``."""


_MIXINS: dict[Capability, type] = {m.capability: m for m in
                                   (GroundedDecoding, SecondOpinion, TransportPlanning, ComparesGoals, OwnBenchTable)}


def register_capability(mixin: type) -> type:
    """Make ``mixin`` (with a ``capability`` class attribute) the one :meth:`TaskDomain.supports`
    asks about for its capability: for a mixin defined in a layer above this module (execution
    under faults, :mod:`pipflow.execution.capability`). A capability whose mixin was never
    imported is offered by no domain (a domain inheriting it imports it). Returns ``mixin``."""
    _MIXINS[Capability(mixin.capability)] = mixin
    return mixin


# ------------------------------------------------------------------------------------------
# the protocol
# ------------------------------------------------------------------------------------------
class TaskDomain(ABC):
    """One kind of task. Subclass it, set the class attributes, write the abstract methods; add a
    capability by inheriting its mixin too (``class Garden(TaskDomain, ComparesGoals)``)."""

    #: the name worlds and task files use in ``domain:`` (and the entry point's name)
    name: ClassVar[str]
    #: the workflow ``pipflow bench`` runs for this domain's task files (unless the task file or
    #: ``--workflow`` names another): a built-in workflow's name, or the path of a workflow file
    #: (a plugin gives the absolute path of the one its package ships)
    workflow: ClassVar[str]
    #: the workflows that carry out a method by its name on this domain's worlds (what a bench
    #: runs for ``--workflow NAME`` or ``--matrix workflow=NAME,...``), e.g. ``{"pip-llm":
    #: "household", "pip-llm-checked": "household-checked"}``: see :meth:`workflow_for`
    workflows: ClassVar[Mapping[str, str]] = {}
    #: the prompt template the generator renders when the workflow names none
    default_prompt: ClassVar[str]
    #: the fields a robot rule may narrow by, besides ``only``/``never``
    rule_fields: ClassVar[tuple[str, ...]] = ()
    #: the switches its ``simulate`` reads from ``options`` (the generic step refuses others)
    simulate_options: ClassVar[tuple[str, ...]] = ()
    #: goal conditions in the PDDL of its problems, for a model whose goal states nothing
    goal_example: ClassVar[str] = ""
    #: the world's sections whose keys name things (PDDL objects, robots): the spellings a plan
    #: that comes back from UP in lower case is mapped back to (:mod:`pipflow.pddl.names`)
    name_sections: ClassVar[tuple[str, ...]] = ("robots", "places", "objects")
    #: task-file fields the bench groups its tasks by, in its tables and report (household:
    #: ``("category",)``: compound, complex, vague); each task row of results.json carries them
    task_groups: ClassVar[tuple[str, ...]] = ()

    def supports(self, capability: Capability) -> bool:
        """Whether this domain offers ``capability`` (inherits its mixin)."""
        mixin = _MIXINS.get(Capability(capability))
        return mixin is not None and isinstance(self, mixin)

    def capabilities(self) -> list[Capability]:
        """Every capability this domain offers."""
        return [c for c in Capability if self.supports(c)]

    def workflow_for(self, name: str) -> str:
        """The workflow that carries out method ``name`` on this domain's worlds
        (:attr:`workflows`), or ``name`` itself (a built-in workflow's name or a path)."""
        return self.workflows.get(name) or (self.workflow if name == "pip-llm" else name)

    # == the required core =====================================================================
    # -- files it ships ------------------------------------------------------------------------
    @abstractmethod
    def pddl_domain(self) -> Path:
        """The team-level PDDL domain file."""

    @abstractmethod
    def action_metadata(self) -> Path:
        """The action metadata file (which action argument is the item, the source, ... and the
        skills each action needs), read by the dependency graph and the allocation."""

    # -- worlds --------------------------------------------------------------------------------
    @abstractmethod
    def load_world(self, path: str | Path, *, seed: int | None = None, **options: Any) -> dict:
        """The world file read and checked (WorldError listing every problem with file:line:col),
        its robots' starts varied reproducibly by ``seed`` (None: as in the file). ``options``:
        domain-specific load options (household: ``team``). The dict carries ``domain`` (the
        default domain's worlds may leave it out) and :class:`pipflow.values.World`'s keys."""

    @abstractmethod
    def describe(self, world: dict) -> str:
        """One line for the run log: what the world holds."""

    # -- language: a command, a problem ----------------------------------------------------------
    @abstractmethod
    def read_command(self, command: str, world: dict) -> Reading:
        """The command read deterministically, with no model. Raises TranslationError (quoting
        the words it could not place: refuse, never guess) or Refusal (impossible in this
        world, with the reason)."""

    def candidate_reading(self, candidate: dict, world: dict) -> Reading:
        """The :class:`Reading` of a reading the user chose among those a refusal offered
        (``TranslationError.candidates``: ``goal``, ``constraints``, ``order``, ``reading``). A
        domain whose goal needs resolving in the world (counts to objects) overrides this."""
        return Reading(candidate.get("goal") or {}, list(candidate.get("constraints") or []),
                       order=candidate.get("order"),
                       explanation=list(candidate.get("explanation") or [str(candidate.get("reading") or "")]))

    @abstractmethod
    def write_problem(self, world: dict, goal: Any, domain_name: str, name: str = "task") -> str:
        """The PDDL problem ``name`` for ``goal`` in ``world``, naming PDDL domain ``domain_name``."""

    @abstractmethod
    def read_goal(self, parsed: Any, world: dict | None) -> tuple[Any, list[str]]:
        """A problem's goal read back (UP problem ``parsed``) into the domain's goal form, and the
        conditions that form cannot hold, each a message for the model (never dropped)."""

    @abstractmethod
    def goal_problems(self, world: dict, goal: Any) -> tuple[list[str], str | None]:
        """A goal checked against ``world``: messages worth feeding back (a name that is not the
        world's, a malformed count: a better problem may fix them), and why no plan can ever
        reach it here (more units than exist, slicing a mug: no problem can fix the command), in
        words; ``([], None)`` when it may be reachable."""

    # -- simulation and what scoring needs -----------------------------------------------------
    @abstractmethod
    def simulate(self, world: dict, schedule: dict, graph: dict | None, goal: Any, *,
                 snapshots: bool = False, out_dir: Path | None = None,
                 log: Callable[[str], None] = print, save: Save | None = None, **options: Any) -> dict:
        """Execute a schedule: :class:`pipflow.values.SimulationCore` plus keys of the domain's own
        (small: the step's outputs). ``snapshots``: pictures into ``out_dir`` (their names under
        ``pictures``); ``save``: where to keep bulky records (trajectories, event logs) as the
        step's artifacts; ``options``: the domain's own switches (:attr:`simulate_options`)."""

    @abstractmethod
    def initial_state(self, world: dict) -> Any:
        """The world's state before anything moved, in the form of a simulation's ``final_state``."""

    @abstractmethod
    def goal_conditions(self, world: dict, state: Any, goal: Any) -> list[Condition]:
        """Each condition of ``goal`` in ``state``, in the goal's order (GCR, goal met and the
        unmet conditions come from these, for every domain alike)."""

    @abstractmethod
    def reference(self, world: dict, goal: Any) -> Reference:
        """RU's reference: the fewest team actions any plan for ``goal`` needs (or a bound no plan
        beats), and how it was found."""

    # == hooks with defaults ===================================================================
    def rule_names(self, world: dict) -> Mapping[str, tuple[Any, str]]:
        """For each rule field: the names it may take in this world and what they are called
        (``{"bed": (world["beds"], "bed")}``); the robot lists are checked by the caller."""
        return {}

    def places(self, world: dict) -> Mapping[str, Mapping[str, Any]]:
        """The fixtures of the world's floor plan by name, each a :class:`pipflow.values.Place`
        (footprint ``x``, ``y``, ``width``, ``depth`` and the ``access`` point robots stand at):
        what travel (:class:`pipflow.team.travel.TravelMap`) avoids, the execution monitor and
        the pictures read. Default: ``world["places"]``."""
        return world.get("places") or {}

    def feedback_facts(self, messages: list[str], world: dict) -> Facts:
        """What to tell a model about the names the round's ``messages`` mention when its next
        prompt would repeat the last one (:class:`Facts`). Default: none."""
        return Facts()

    def example_problem(self, world: dict, domain_text: str = "") -> str | None:
        """A problem for this world that shows a model the expected form. Default: the world's
        objects and initial state with an empty goal, and a line in it saying where the goal's
        conditions go."""
        text = self.write_problem(world, {}, pddl_domain_name(domain_text, self.name))
        return text.replace("(:goal (and\n", f"(:goal (and\n    {GOAL_PLACEHOLDER}\n", 1)

    def world_mismatches(self, parsed: Any, problem_text: str, world: dict) -> list[str]:
        """The debugger's check of a parsed problem against the world: objects and initial state
        that are not the world's, each message located in ``problem_text``. Default: none."""
        return []

    def final_state(self, simulation: Mapping[str, Any]) -> Any:
        """The final state in a simulation's outputs (flat). Default: ``final_state``."""
        return simulation.get("final_state")

    def rule_violations(self, constraints: list[dict] | None, graph: dict | None,
                        schedule: dict | None, world: dict) -> list[str]:
        """The task's only/never rules that the schedule breaks. Default: a rule governs the
        subtasks whose action and graph-node fields agree with every field it gives."""
        nodes = {n["id"]: n for n in (graph or {}).get("nodes", [])}
        out = []
        for sub in (schedule or {}).get("subtasks", []):
            have = {"action": sub.get("action"), **(nodes.get(sub["id"], {}).get("fields") or {})}
            for rule in constraints or []:
                match = {k: v for k, v in rule.items() if k not in ("only", "never", "words")}
                if any(have.get(k) != v for k, v in match.items()):
                    continue
                bad = [r for r in sub.get("robots", []) if
                       (r in rule["never"] if "never" in rule else r not in rule.get("only", []))]
                if bad:
                    out.append(f"{sub['id']} {sub.get('action')}: {', '.join(bad)} break rule "
                               f"{rule.get('words') or match}")
        return out

    def extra_violations(self, world: dict, simulation: Mapping[str, Any], graph: dict | None,
                         schedule: dict | None) -> list[str]:
        """What else fails a run in this domain (units lost, a capacity exceeded). Default: none."""
        return []

    def load_tasks(self, path: Path) -> dict:
        """A task file read and checked (every problem located): ``{"path", "world_path",
        "world", "domain", "workflow", "tasks": [...]}``. Default: the plain task file of
        :mod:`pipflow.taskfile`, each task's goal checked by :meth:`task_goal_problems`."""
        return load_task_file(path, domain=self.name, load_world=self.load_world, default_workflow=self.workflow,
                              goal_problems=self.task_goal_problems)

    def task_goal_problems(self, goal: Any, world: dict) -> Iterable[GoalProblem]:
        """What is wrong with a task file's goal in its world: ``(path inside the goal, message,
        about a key?)`` each, e.g. ``(("stored", "shedd"), "unknown store 'shedd'", True)``.
        Default: nothing is checked."""
        return []

    def task_world(self, world_path: str | Path, task: Mapping[str, Any]) -> dict:
        """The world a bench task is judged in. Default: the task file's world as in the file."""
        return self.load_world(world_path)

    # -- the report (hooks with defaults) ------------------------------------------------------
    def goal_words(self, goal: Any) -> list[str]:
        """A goal in plain words, a line per condition, for the report's "Understood" (never a
        Python list). Default: a mapping spelled out key by key, lists joined by commas."""
        return plain_words(goal)

    def floor_plan(self, world: dict) -> list[dict]:
        """The footprints the replay draws under the robots: ``[{"name", "x", "y", "width",
        "depth", "access"}]`` in metres, from :meth:`places` (empty: the floor alone)."""
        return [{"name": name, "x": float(p["x"]), "y": float(p["y"]), "width": float(p["width"]),
                 "depth": float(p["depth"]), "access": list(p.get("access") or [])}
                for name, p in self.places(world).items()]

    def table_groups(self, tasks: list[dict]) -> list[tuple[str, list[str]]] | None:
        """The groups of tasks the paper's tables report (its table of the household experiment
        has one column group per task category), as ``(name, [task ids])`` in the paper's order;
        None: the paper reports this domain per task (its warehouse table). ``tasks``: the task
        file's tasks as :meth:`load_tasks` returns them."""
        return None

    # == template methods: the same for every domain ============================================
    def read_offline(self, command: str, world: dict, domain_text: str = "",
                     save: Save | None = None) -> dict:
        """Model ``offline``: :meth:`read_command`, its problem written; the outputs of one
        generator round (``problem``, ``goal``, ``constraints``, ``messages``, ``response``,
        ``usage``, ``errors``, and ``order``, ``explanation``, ``concrete`` where the reading has
        them). ``save`` keeps the reading (``goal.json``, ``order.json``) and the problem."""
        return self.offline_round(self.read_command(command, world), world, domain_text, save)

    def read_candidate(self, candidate: dict, world: dict, domain_text: str = "",
                       save: Save | None = None) -> dict:
        """Model ``offline`` with a reading the user chose after a refusal
        (:meth:`candidate_reading`): the outputs of :meth:`read_offline`."""
        return self.offline_round(self.candidate_reading(candidate, world), world, domain_text, save)

    def offline_round(self, reading: Reading, world: dict, domain_text: str = "",
                      save: Save | None = None) -> dict:
        """The outputs of one offline generator round for ``reading``: its problem written, the
        reading kept (:meth:`read_offline`)."""
        problem = self.write_problem(world, reading.problem_goal, pddl_domain_name(domain_text, self.name))
        out: dict[str, Any] = {"problem": problem, "goal": reading.goal, "constraints": list(reading.constraints),
                               "messages": [], "response": "", "usage": dict(NO_USAGE), "errors": []}
        out.update({k: v for k, v in (("order", reading.order), ("explanation", reading.explanation),
                                      ("concrete", reading.concrete)) if v is not None})
        if save is not None:
            save("goal.json", reading.goal)
            if reading.order is not None:
                save("order.json", {"order": reading.order, "explanation": reading.explanation})
            save("problem.pddl", problem)
        return out

    def read_problem(self, parsed: Any, world: dict, constraints: list[dict]) -> dict:
        """What the generator learns from a model's problem that parsed: ``goal`` (and other keys
        a domain adds), and ``errors``, feedback lines (the problem is then not used): conditions
        the goal form cannot hold, or a goal that states nothing (copying the example unchanged
        would otherwise "succeed" doing nothing)."""
        goal, unread = self.read_goal(parsed, world)
        if unread:
            return {"goal": goal, "errors": list(unread)}
        if states_nothing(goal):
            example = f", e.g. {self.goal_example}" if self.goal_example else ""
            return {"errors": [f"the problem's (:goal ...) states no condition: write the conditions the command "
                               f"asks for{example}"]}
        return {"goal": goal}

    def check_goal(self, parsed: Any, world: dict | None) -> GoalCheck:
        """The verifier's reading of a problem's goal (``world`` None: no world checks): the goal,
        what cannot be read of it, and the refusal when no plan can reach it here (the reason is
        a message too: the paper's loop feeds back all the verifier finds)."""
        goal, unread = self.read_goal(parsed, world)
        if world is None:
            return GoalCheck(goal, list(unread))
        messages, why = self.goal_problems(world, goal)
        if not why:
            return GoalCheck(goal, [*unread, *messages])
        return GoalCheck(goal, [*unread, *(messages or [f"the goal cannot be reached in this world: {why}"])],
                         f"the command cannot be done in this world: {why}")

    def score(self, world: dict, goal: Any, *, constraints: list[dict] | None = None,
              feasible: bool = True, graph: dict | None = None, schedule: dict | None = None,
              simulation: Mapping[str, Any] | None = None, refusal: str | None = None,
              error: str | None = None) -> Score:
        """Judge one run against its task, on what the simulation reports (never on what the plan
        claims): :class:`pipflow.values.Score`. ``simulation``: either shape of a simulation
        (the generic step's, ``details`` nested, or a domain step's, flat). See
        :func:`pipflow.scoring.score_run` for the definitions."""
        return score_run(self, world, goal, constraints=constraints, feasible=feasible, graph=graph,
                         schedule=schedule, simulation=simulation, refusal=refusal, error=error)[0]

    def score_bench_run(self, world_path: str, task: Mapping[str, Any], outputs: Mapping[str, Any],
                        refusal: str | None, error: str | None) -> dict:
        """One bench run of ``task`` scored from the workflow's outputs against the task's gold
        (its goal, rules, and whether a refusal is the right answer), in :meth:`task_world` as
        the run really found it (a run under faults: its surprises put in, by the execution
        capability's ``as_it_was``); the row also says how RU's reference was found
        (``reference``), where the domain says."""
        world = self.task_world(world_path, task)
        if self.supports(Capability.EXECUTION) and outputs.get("faults"):
            world = self.as_it_was(world, outputs.get("faults"))  # type: ignore[attr-defined]
        row, ref = score_run(self, world, task.get("goal") or {}, constraints=task.get("constraints"),
                             feasible=not refusal_expected(task), graph=outputs.get("graph"),
                             schedule=outputs.get("schedule"), simulation=outputs.get("simulation"),
                             refusal=refusal, error=error)
        if ref is not None and ref.how and row.get("lower_bound") is not None:
            row = {**row, "reference": ref.how}
        return row

    def understand(self, task: Mapping[str, Any], outputs: Mapping[str, Any], status: str,
                   error_kind: str | None, world_path: str | None = None) -> dict | None:
        """``{"understood", "misread", "understanding"}``: whether the run resolved a meaning equal
        to the task's gold goal and rules (:func:`pipflow.meaning.judge`), the goals compared by
        the domain's :meth:`ComparesGoals.goal_difference` in the task's world, the rules by what
        they forbid; None when the domain does not compare goals."""
        if not self.supports(Capability.UNDERSTANDING):
            return None
        world = self.task_world(world_path, task) if world_path else None

        def goals(gold: Any, run: Any) -> str | None:
            return self.goal_difference(world, gold or {}, run)  # type: ignore[attr-defined]

        if world is None:
            return judge(task, outputs, status, error_kind, goal_difference=goals, rule_difference=rules_as_written)
        fields = {f: list(names) for f, (names, _) in self.rule_names(world).items()}
        robots = list(world.get("robots") or {})
        return judge(task, outputs, status, error_kind, goal_difference=goals,
                     rule_difference=lambda gold, run: rules_difference(gold, run, robots, fields))


def states_nothing(goal: Any) -> bool:
    """Whether a goal asks for nothing: no value in it but empty mappings and lists (``{}``,
    ``{"in": {}, "state": {}}``). A count of 0 or a name is something."""
    if isinstance(goal, Mapping):
        return all(states_nothing(v) for v in goal.values())
    if isinstance(goal, (list, tuple)):
        return all(states_nothing(v) for v in goal)
    return goal is None


# ------------------------------------------------------------------------------------------
# what every simulation and score step records (the generic steps and a domain's own)
# ------------------------------------------------------------------------------------------
def report_simulation(ctx: Any, result: Mapping[str, Any], schedule: Mapping[str, Any] | None) -> Any:
    """Record a simulation's headline figures as the step's metrics and say in the log how it
    went; returns ``result``."""
    ctx.metrics.update({k: result[k] for k in SIMULATION_METRICS})
    ctx.log(f"executed {result['executed']}/{len((schedule or {}).get('subtasks', []))}, goal met: "
            f"{result['goal_met']} (GCR {result['gcr']:.2f})")
    return result


def report_score(ctx: Any, result: Score) -> Score:
    """Log each violation and record a score's headline figures as the step's metrics; returns
    ``result``."""
    for violation in result["violations"]:
        ctx.log(f"violation: {violation}")
    ctx.metrics.update({k: result[k] for k in SCORE_METRICS})
    return result

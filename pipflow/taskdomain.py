"""The task-domain protocol: everything pipflow's generic code needs to know about a domain.

Why one interface: the generator, the debugger, the verifier, the planner step, the LLM check and
the bench are the same for every kind of task (moving pallets in a warehouse, tidying a home,
...); what differs is how a world file is read, how a goal is written as PDDL, how a command is
read offline, how a run is simulated and scored. The generic modules ask
:func:`pipflow.taskdomains.task_domain` for the world's domain and call the methods below; they
never name a domain. A third-party package adds a domain by subclassing :class:`TaskDomain` and
registering it in the entry-point group ``pipflow.task_domains`` (see the README, "Writing a
domain plugin"), exactly as steps are registered in ``pipflow.steps``.

Style: a base class with the few methods a domain must write (``abstractmethod``) and defaults for
what a domain may leave out (no grounded decoding, goals not compared, no world checks beyond the
PDDL parse). Methods never raise for a world they cannot judge; user errors are
:class:`pipflow.errors.InputError` subclasses with the file, line and cause (WorldError,
TranslationError, Refusal).

A world dict says its domain with ``world["domain"]``; a world without one is of the default
domain (:data:`DEFAULT_DOMAIN`), as every world file was before domains were named.

Contract of the dicts that cross the interface (unchanged from the steps' outputs):

* offline reading: ``{"problem", "goal", "constraints", "messages", "response", "usage",
  "errors"}`` plus optional ``"order"``, ``"explanation"``, ``"concrete"``;
* robot rules: ``{"only"|"never": [robot names], <rule field>: name, "words"?: ...}``;
* simulations: :data:`SIMULATION_CORE` (every domain's ``simulate`` returns these keys, its
  final state under ``final_state``) plus keys of the domain's own; the generic step
  ``simulate`` passes the core and ``pictures`` through and keeps the rest under ``details``
  (:func:`simulation_outputs`), and a domain's ``score`` reads either form
  (:func:`flat_simulation`);
* scores: :data:`SCORE_CORE`, flat (``success``, ``gcr``, ``exe``, ``ru``, ``tc_max``, ``tc_avg``,
  ``makespan``, ``violations``, ...): the outputs of the generic step ``score``.
"""
from __future__ import annotations

import re
from abc import ABC, abstractmethod
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Callable, ClassVar, Mapping

#: the domain of a world (or task file) that does not name one
DEFAULT_DOMAIN = "warehouse"

#: how a run ends when the command was refused: infeasible (Refusal), or not understood
#: (TranslationError: a reader refuses what it cannot place rather than guess)
REFUSED_KINDS = ("Refusal", "TranslationError")

#: ``save(name, data)``: keep an artifact of the step (the engine's ``ctx.write_artifact``)
Save = Callable[[str, Any], Any]

#: What every domain's ``simulate`` returns, with the output types the generic step ``simulate``
#: declares: one shape, so a workflow, the bench and the report read a run the same way in any
#: domain. ``final_state`` is the domain's own picture of the world afterwards (stock per shelf,
#: where each object is, ...); travel is metres per robot, and ``tc_max``, ``tc_avg`` (the mean
#: over the robots that moved: the paper's TC-avg) and ``tc_avg_team`` (the mean over every robot
#: of the team) come from it through :func:`pipflow.metrics.travel_costs`; ``gcr`` is
#: :func:`pipflow.metrics.goal_condition_recall`; ``jumps`` the legs that start away from where a
#: robot stood (a broken schedule).
SIMULATION_CORE: dict[str, str] = {
    "final_state": "object", "executed": "integer", "failed": "integer", "failures": "array",
    "exe": "number", "travel": "object", "tc_max": "number", "tc_avg": "number", "tc_avg_team": "number",
    "goal_met": "boolean", "gcr": "number", "jumps": "object", "makespan": "number",
}
#: what every domain's ``score`` returns (the generic step ``score`` declares these, flat); the
#: metrics mean what :mod:`pipflow.metrics` says, in every domain
SCORE_CORE: dict[str, str] = {
    "success": "boolean", "goal_met": "boolean", "gcr": "number", "exe": "number", "ru": "number",
    "tc_max": "number", "tc_avg": "number", "tc_avg_team": "number", "makespan": "number",
    "planned": "integer", "executed": "integer", "lower_bound": "any", "violations": "array",
    "refused": "boolean", "error": "any",
}


#: the headline figures every score step records as the step's metrics
SCORE_METRICS = ("success", "gcr", "exe", "ru", "tc_max", "tc_avg", "tc_avg_team")


def report_score(ctx: Any, result: dict) -> dict:
    """Log each violation and record the headline metrics of a score: the generic ``score`` step
    and the domains' own score steps do this alike. Returns ``result``."""
    for violation in result["violations"]:
        ctx.log(f"violation: {violation}")
    ctx.metrics.update({k: result[k] for k in SCORE_METRICS})
    return result


def simulation_outputs(result: Mapping[str, Any]) -> dict:
    """A domain's simulation result in the generic step's shape: the core keys, ``pictures``
    (file names of the step's artifacts; none: ``[]``) and every other key under ``details``.
    A result that lacks a core key is the domain's bug, said with the keys it lacks."""
    missing = [key for key in SIMULATION_CORE if key not in result]
    if missing:
        raise TypeError(f"a simulation result lacks {', '.join(missing)} (every domain returns SIMULATION_CORE)")
    outputs = {key: result[key] for key in SIMULATION_CORE}
    outputs["pictures"] = list(result.get("pictures") or [])
    outputs["details"] = {k: v for k, v in result.items() if k not in outputs}
    return outputs


def flat_simulation(simulation: Mapping[str, Any] | None) -> dict | None:
    """A simulation as one flat mapping, from the generic step's shape (``details`` nested) or a
    domain step's (flat): what a domain's scoring reads. None stays None (no simulation ran)."""
    if simulation is None:
        return None
    details = simulation.get("details")
    rest = {k: v for k, v in simulation.items() if k != "details"}
    return {**details, **rest} if isinstance(details, Mapping) else rest


def pddl_domain_name(domain_text: str, default: str) -> str:
    """The name in ``(define (domain NAME)`` of a PDDL domain text, or ``default``: a problem must
    name the domain it is read with."""
    m = re.search(r"\(\s*domain\s+([^\s()]+)", domain_text or "", flags=re.IGNORECASE)
    return m.group(1) if m else default


@dataclass(frozen=True)
class GoalCheck:
    """What the verifier learns from a problem's goal in a world: the goal as data (shown in the
    step's ``goal`` output), problems with it worth feeding back, and a refusal reason when no
    plan can ever reach it in this world (more units than exist, slicing a mug)."""

    goal: Any = field(default_factory=dict)
    messages: list[str] = field(default_factory=list)
    refusal: str | None = None


@dataclass(frozen=True)
class Grounding:
    """Grounded decoding for a domain: the model answers in a constrained form instead of PDDL.
    ``gbnf(world)``: a llama.cpp grammar; ``response_format(world)``: an OpenAI JSON schema;
    ``read(text, world)``: the answer checked, resolved and its problem written: ``{"problem",
    "goal", "constraints", "order", "explanation", "errors"}`` (raises
    :class:`pipflow.language.parsing.ParseIssue` with words for the model)."""

    gbnf: Callable[[dict], str]
    response_format: Callable[[dict], dict]
    read: Callable[[str, dict], dict]
    #: ``answer_size(world, reading)``: ``(goal items, rules)`` a grounded answer is expected to
    #: hold, from the offline reading's outputs when the parser read the command (``reading``,
    #: else None: from the world's size); the call's token budget (:mod:`pipflow.language.budget`)
    answer_size: Callable[[dict, Any], tuple[int, int]]


@dataclass(frozen=True)
class Facts:
    """What a domain tells a model about the names that feedback messages mention, for a prompt
    that would otherwise repeat (:mod:`pipflow.language.feedback`): ``together``: groups of names
    that one message names together (a line of the quoted previous answer that names every name
    of a group is marked); ``lines``: the world's facts about those names, one line each."""

    together: list[tuple[str, ...]] = field(default_factory=list)
    lines: list[str] = field(default_factory=list)


class TaskDomain(ABC):
    """One kind of task. Subclass it, set the class attributes, write the abstract methods."""

    #: the name worlds and task files use in ``domain:`` (and the entry point's name)
    name: ClassVar[str]
    #: the workflow ``pipflow bench`` runs for this domain's task files (unless the task file or
    #: ``--workflow`` names another): a built-in workflow's name, or the path of a workflow file
    #: (a plugin gives the absolute path of the one its package ships)
    workflow: ClassVar[str]
    #: the workflows that carry out a method by its name on this domain's worlds: what a bench
    #: of its task files runs for ``--workflow NAME`` or ``--matrix workflow=NAME,...`` (e.g.
    #: ``{"pip-llm": "household", "pip-llm-checked": "household-checked"}``); each a built-in
    #: workflow's name or a workflow file's path. ``pip-llm`` (the paper's pipeline) is
    #: :attr:`workflow` unless mapped; names not mapped are left as they are (a built-in name or a
    #: path): see :meth:`workflow_for`
    workflows: ClassVar[Mapping[str, str]] = {}
    #: the prompt template the generator renders when the workflow names none
    default_prompt: ClassVar[str]
    #: the fields a robot rule may narrow by, besides ``only``/``never``
    rule_fields: ClassVar[tuple[str, ...]] = ()
    #: grounded decoding, when the domain offers it (None: the generator refuses ``grounded``)
    grounding: ClassVar[Grounding | None] = None
    #: the switches its ``simulate`` reads from ``options`` (the generic step refuses others)
    simulate_options: ClassVar[tuple[str, ...]] = ()
    #: the world's sections whose keys name things (PDDL objects, robots): the spellings a plan
    #: that comes back from UP in lower case is mapped back to (:mod:`pipflow.pddl.names`)
    name_sections: ClassVar[tuple[str, ...]] = ("robots", "places", "objects")

    def workflow_for(self, name: str) -> str:
        """The workflow that carries out method ``name`` on this domain's worlds
        (:attr:`workflows`), or ``name`` itself (a built-in workflow's name or a path)."""
        return self.workflows.get(name) or (self.workflow if name == "pip-llm" else name)

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
        default domain's worlds may leave it out)."""

    def describe(self, world: dict) -> str:
        """One line for the run log: what the world holds."""
        return f"{len(world.get('robots', {}))} robots"

    def places(self, world: dict) -> Mapping[str, Mapping[str, Any]]:
        """The fixtures of the world's floor plan by name, each a footprint (``x``, ``y``,
        ``width``, ``depth``) with the ``access`` point robots stand at: what travel
        (:class:`pipflow.team.travel.TravelMap`) and the path pictures read."""
        return world.get("places") or {}

    def rule_names(self, world: dict) -> Mapping[str, tuple[Any, str]]:
        """For each rule field: the names it may take in this world and what they are called
        (``{"from": (world["shelves"], "shelf")}``); the robot lists are checked by the caller."""
        return {}

    # -- language: reading a command, writing a problem ----------------------------------------

    @abstractmethod
    def read_offline(self, command: str, world: dict, domain_text: str = "",
                     save: Save | None = None) -> dict:
        """Model ``offline``: the command read deterministically and its problem written. Raises
        TranslationError (quoting the words it could not place) or Refusal (impossible in this
        world)."""

    def read_candidate(self, candidate: dict, world: dict, domain_text: str = "",
                       save: Save | None = None) -> dict:
        """Model ``offline`` with a reading the user chose among those a refusal offered
        (``TranslationError.candidates``: ``goal``, ``constraints``, ``order``, ``reading``): its
        problem written, the outputs of :meth:`read_offline`. A domain whose goal needs more than
        :meth:`write_problem` of the candidate's goal overrides this."""
        goal = candidate.get("goal") or {}
        if save is not None and candidate.get("order") is not None:
            save("order.json", candidate["order"])
        return {"problem": self.write_problem(world, goal, pddl_domain_name(domain_text, self.name)),
                "goal": goal, "constraints": list(candidate.get("constraints") or []),
                "order": candidate.get("order"),
                "explanation": list(candidate.get("explanation") or [str(candidate.get("reading") or "")]),
                "messages": [], "response": "", "usage": {"calls": 0, "cached": False, "prompt_tokens": 0,
                                                          "completion_tokens": 0, "total_tokens": 0,
                                                          "latency_s": 0.0, "cost_usd": 0.0}, "errors": []}

    @abstractmethod
    def write_problem(self, world: dict, goal: Any, domain_name: str, name: str = "task") -> str:
        """The PDDL problem ``name`` for ``goal`` in ``world``, naming PDDL domain ``domain_name``
        (take it from the domain file with :func:`pddl_domain_name`)."""

    def example_problem(self, world: dict, domain_text: str = "") -> str | None:
        """A problem for this world that shows a model the expected form (None: no example)."""
        return None

    def read_problem(self, parsed: Any, world: dict, constraints: list[dict]) -> dict:
        """What the generator learns from a model's problem that parsed (UP problem ``parsed``):
        keys to add to the round's outputs (``goal``, ``order``, ``explanation``), and
        ``errors``: a list of feedback lines (the problem is then not used)."""
        return {}

    # -- the debugger, the verifier and the planner --------------------------------------------

    def world_mismatches(self, parsed: Any, problem_text: str, world: dict) -> list[str]:
        """The debugger's check of a parsed problem against the world: objects and initial state
        that are not the world's, each message located in ``problem_text``."""
        return []

    def check_goal(self, parsed: Any, world: dict | None) -> GoalCheck:
        """The verifier's reading of a problem's goal (``world`` None: no world checks)."""
        return GoalCheck()

    def planner_params(self, world: dict, constraints: list[dict]) -> dict | None:
        """Parameters for pipflow's own transport planner (robots' capacities, rules), or None
        when the domain's problems are not transport problems."""
        return None

    # -- the LLM loop --------------------------------------------------------------------------

    def feedback_facts(self, messages: list[str], world: dict) -> Facts:
        """What to tell a model about the names the round's ``messages`` mention when its next
        prompt would repeat the last one (:class:`Facts`; none by default)."""
        return Facts()

    def second_opinion(self, command: str, world: dict, goal: Any, constraints: list[dict],
                       refusal: str | None, last: bool = False) -> Any | None:
        """The checked loop's test of a model's goal and rules against the offline reading of the
        command, or the doubts the command's words raise when the parser does not read it (a
        :class:`pipflow.language.agreement.Opinion`, usually from
        :func:`pipflow.language.agreement.judge`); feedback names what disagrees and the
        command's words, never the reading's value. ``last``: the loop's last round (an
        unconfirmed refusal is then final). None when this domain's goals are not compared: then
        only whether the verifier's refusal is final is decided."""
        return None

    # -- simulation and scoring ----------------------------------------------------------------

    @abstractmethod
    def simulate(self, world: dict, schedule: dict, graph: dict | None, goal: Any, *,
                 snapshots: bool = False, out_dir: Path | None = None,
                 log: Callable[[str], None] = print, save: Save | None = None, **options: Any) -> dict:
        """Execute a schedule: :data:`SIMULATION_CORE` plus keys of the domain's own (small: the
        step's outputs). ``snapshots``: pictures into ``out_dir`` (their names under
        ``pictures``); ``save``: where to keep bulky records (trajectories, event logs) as the
        step's artifacts; ``options``: the domain's own switches (the workflow's ``options:``)."""

    @abstractmethod
    def score(self, world: dict, goal: Any, *, constraints: list[dict] | None = None,
              feasible: bool = True, graph: dict | None = None, schedule: dict | None = None,
              simulation: dict | None = None, refusal: str | None = None,
              error: str | None = None) -> dict:
        """Judge one run against its task: :data:`SCORE_CORE`, flat. ``simulation`` is either shape
        of a simulation (read it through :func:`flat_simulation`)."""

    # -- the bench -----------------------------------------------------------------------------

    @abstractmethod
    def load_tasks(self, path: Path) -> dict:
        """A task file read and checked: ``{"world_path", "tasks": [...], "workflow"?}``."""

    @abstractmethod
    def score_bench_run(self, world_path: str, task: dict, outputs: dict, refusal: str | None,
                        error: str | None) -> dict:
        """Score one bench run of ``task`` from the workflow's outputs."""

    def understand(self, task: dict, outputs: dict, status: str, error_kind: str | None,
                   world_path: str | None = None) -> dict | None:
        """``{"understood", "misread", "understanding"}``: whether the run resolved a meaning
        equal to the task's gold goal and rules (``misread``: another meaning, whatever happened
        next); None when understanding is not measured for this domain. ``world_path``: the task
        file's world, in which meanings are compared. :func:`pipflow.meaning.judge` gives the
        verdict from a comparison of the domain's goals."""
        return None

    def bench_table(self, results: dict, tasks_file: Path) -> str | None:
        """The markdown table of a bench, when the domain groups it its own way (None: the
        generic table, one row per task)."""
        return None

    def table_groups(self, tasks: list[dict]) -> list[tuple[str, list[str]]] | None:
        """The groups of tasks the paper's tables report (its table of the household experiment
        has one column group per task category), as ``(name, [task ids])`` in the paper's order;
        None: the paper reports this domain per task (its warehouse table). ``tasks``: the task
        file's tasks as :meth:`load_tasks` returns them."""
        return None

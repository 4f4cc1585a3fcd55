"""The household as a pipflow task domain (the paper's AI2-THOR experiment on pipflow's own home
simulator): the one object the generic code talks to, registered as ``household`` in the
entry-point group ``pipflow.task_domains``.

The core of :class:`pipflow.taskdomain.TaskDomain` and four capabilities (the checked loop's
second opinion, goals compared by meaning, a bench table by category, execution under faults),
each a thin face of a module of this package: the world loader (:mod:`.world`), the translator
(:mod:`.language.translator`) and problem writer and checks (:mod:`.problem`), the simulation
(:mod:`.simulation`), the facts of scoring and the task files (:mod:`.scoring`) and the side of
faults (:mod:`.faults`). Household goals are conditions (``{"in": {place:
[objects]}, "state": {thing: [conditions]}}``), read back from a model's problem; the checked
loop compares them with the translator's reading (:mod:`.agreement`).

The translator's parser (lark), UP and pybullet are imported inside the methods on purpose: the
registry imports this module for every household run, and a run pays only for what it uses.
"""
from __future__ import annotations

from pathlib import Path
from typing import Any, Callable, Mapping

from pipflow.execution.capability import ModuleExecution
from pipflow.household import agreement, meaning, scoring
from pipflow.household import faults as fault_model
from pipflow.household import world as worlds
from pipflow.household.problem import goal_from_problem, goal_refusal, world_mismatches, write_problem
from pipflow.household.simulation import simulate
from pipflow.resources import data_file
from pipflow.taskdomain import (ComparesGoals, Condition, OwnBenchTable, Reading, Reference, Save, SecondOpinion,
                                TaskDomain)

#: the fields a household rule may narrow by (domains/household.actions.yaml ``fields``)
RULE_FIELDS = ("object", "from", "to", "at")


class HouseholdDomain(TaskDomain, SecondOpinion, ComparesGoals, OwnBenchTable, ModuleExecution):
    """A home: objects in places, states to change (open, on, dirty, sliced), a robot team."""

    name = "household"
    workflow = "household"
    workflows = {"pip-llm": "household", "pip-llm-checked": "household-checked",
                 # the paper's ablations (Table III) and the w/o B (docs/paper.md, "Ablations")
                 **{f"pip-llm-{name}": f"household-{name}" for name in ("no-domain", "no-debugger", "no-bv", "no-as",
                                                                        "n1", "n2", "n3", "n4")},
                 # the paper's baselines (Sec. V): pipflow/baselines/, docs/paper.md "Baselines"
                 "cot": "household-cot", "smart-llm": "household-smart-llm", "lamma-p": "household-lamma-p"}
    default_prompt = "household_problem"
    rule_fields = RULE_FIELDS
    goal_example = "(at apple fridge) or (not (is-on floorlamp))"
    fault_model = fault_model  # its side of execution under faults (ModuleExecution)
    task_groups = ("category",)  # the paper's three: compound, complex, vague

    # -- files ---------------------------------------------------------------------------------
    def pddl_domain(self) -> Path:
        return data_file("domains/household.pddl")

    def action_metadata(self) -> Path:
        return data_file("domains/household.actions.yaml")

    # -- worlds --------------------------------------------------------------------------------
    def load_world(self, path: str | Path, *, seed: int | None = None, **options: Any) -> dict:
        """``team``: a team of the world, or robot names ``"a,b,c"`` (None: every robot)."""
        return worlds.vary_starts(worlds.select_team(worlds.load_world(path), options.get("team")), seed)

    def describe(self, world: dict) -> str:
        return (f"{len(world['places'])} places, {len(world['objects'])} objects, "
                f"team {', '.join(world['robots'])}")

    def rule_names(self, world: dict) -> Mapping[str, tuple[Any, str]]:
        places, objects = world.get("places", {}), world.get("objects", {})
        return {"object": ({**places, **objects}, "place or object"), "from": (places, "place"),
                "to": (places, "place"), "at": (places, "place")}

    def task_world(self, world_path: str | Path, task: Mapping[str, Any]) -> dict:
        """The task's team's world (where objects can end, which flags can change; the team's
        robots for the rules)."""
        return worlds.select_team(worlds.load_world(world_path), task.get("team"))

    # -- language ------------------------------------------------------------------------------
    def read_command(self, command: str, world: dict) -> Reading:
        """The translator: ``goal`` keeps the command's conditions (counts included) for
        judging, ``concrete`` resolves counts to objects, which is what the problem asks for.
        Untranslatable commands raise TranslationError, impossible ones Refusal."""
        # deferred: builds the lark parser (~150 ms; only offline reading needs it)
        from pipflow.household.language.translator import translate

        result = translate(command, world)
        return Reading(result["goal"], [], concrete=result["concrete"])

    def candidate_reading(self, candidate: dict, world: dict) -> Reading:
        """A reading the user chose among those a refusal offered: its goal (containers closed
        again) with counts resolved to objects, as :meth:`read_command` resolves them."""
        # deferred: the translator builds the lark parser (only offline reading needs it)
        from pipflow.household.language.translator import resolve_counts

        goal = candidate.get("goal") or {}
        return Reading(goal, [], order=candidate.get("order"), explanation=[str(candidate.get("reading") or "")],
                       concrete=resolve_counts(world, goal))

    def write_problem(self, world: dict, goal: Any, domain_name: str, name: str = "task") -> str:
        return write_problem(world, goal, name=name, domain=domain_name)

    def read_goal(self, parsed: Any, world: dict | None) -> tuple[Any, list[str]]:
        """The goal conditions read back from the problem."""
        return goal_from_problem(parsed), []

    def world_mismatches(self, parsed: Any, problem_text: str, world: dict) -> list[str]:
        return world_mismatches(parsed, problem_text, world)

    def goal_problems(self, world: dict, goal: Any) -> tuple[list[str], str | None]:
        """A state the thing cannot take (slicing a mug) is refused."""
        return [], goal_refusal(world, goal)

    # -- capabilities --------------------------------------------------------------------------
    def second_opinion(self, command: str, world: dict, goal: Any, constraints: list[dict],
                       refusal: str | None, last: bool = False) -> Any:
        """The goal conditions and robot rules against the translator's reading."""
        return agreement.second_opinion(command, world, goal, constraints, refusal, last)

    def goal_difference(self, world: dict | None, gold: Any, run: Any) -> str | None:
        """Goals compared by the final states of ``world`` they accept (:mod:`.meaning`);
        without a world, as written."""
        if world is None:
            a, b = meaning.canonical(gold or {}), meaning.canonical(run)
            return None if a == b else f"goal {b}, gold {a}"
        return meaning.goal_difference(world, gold or {}, run)

    def bench_table(self, results: dict, tasks_file: Path) -> str:
        return scoring.bench_table(results, tasks_file)

    # -- simulation and scoring ----------------------------------------------------------------
    def simulate(self, world: dict, schedule: dict, graph: dict | None, goal: Any, *,
                 snapshots: bool = False, out_dir: Path | None = None,
                 log: Callable[[str], None] = print, save: Save | None = None, **options: Any) -> dict:
        """The home simulator's result (``final_state``: where each object is and its states),
        plus ``conditions`` (goal conditions met / total / unmet)."""
        return simulate(world, schedule, graph, goal, snapshots=snapshots, out_dir=out_dir, log=log)

    def initial_state(self, world: dict) -> Any:
        return scoring.initial(world)

    def goal_conditions(self, world: dict, state: Any, goal: Any) -> list[Condition]:
        return [Condition(words, ok) for ok, words in scoring.condition_values(world, state or {}, goal or {})]

    def reference(self, world: dict, goal: Any) -> Reference:
        """An optimal plan's length (Fast Downward), or a relaxed count no plan beats."""
        return Reference(*scoring.reference_actions(world, goal or {}))

    # -- the bench -----------------------------------------------------------------------------
    def load_tasks(self, path: Path) -> dict:
        return scoring.load_tasks(path)

    def table_groups(self, tasks: list[dict]) -> list[tuple[str, list[str]]] | None:
        """The paper's categories, in its order (compound, complex, vague)."""
        return [(c, [t["id"] for t in tasks if t.get("category") == c]) for c in scoring.CATEGORIES]

    # -- the report ----------------------------------------------------------------------------
    def goal_words(self, goal: Any) -> list[str]:
        """``fridge holds pumpkin``, ``lettuce: sliced``, ``at least 2 of fruit in fridge``."""
        if not isinstance(goal, Mapping):
            return super().goal_words(goal)
        lines = [f"{place} holds {', '.join(map(str, objs))}" for place, objs in (goal.get("in") or {}).items()]
        lines += [f"{thing}: {', '.join(map(str, states))}" for thing, states in (goal.get("state") or {}).items()]
        for c in goal.get("count") or []:
            if isinstance(c, Mapping):
                lines.append(f"at least {c.get('at_least')} of {c.get('category')} in {c.get('in')}")
        rest = {k: v for k, v in goal.items() if k not in ("in", "state", "count")}
        return lines + (super().goal_words(rest) if rest else [])

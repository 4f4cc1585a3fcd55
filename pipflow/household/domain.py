"""The household as a pipflow task domain (the paper's AI2-THOR experiment on pipflow's own home
simulator): the one object the generic code talks to, registered as ``household`` in the
entry-point group ``pipflow.task_domains``.

Each method is a thin face of a module of this package: the world loader (:mod:`.world`), the
translator (:mod:`.translator`) and problem writer and checks (:mod:`.problem`), the simulation
(:mod:`.simulation`) and the scoring (:mod:`.scoring`). Household goals are conditions
(``{"in": {place: [objects]}, "state": {thing: [conditions]}}``), read back from a model's
problem; the checked loop compares them with the translator's reading (:mod:`.agreement`).

The translator's parser (lark), UP and pybullet are imported inside the methods on purpose: the
registry imports this module for every household run, and a run pays only for what it uses.
"""
from __future__ import annotations

from pathlib import Path
from typing import Any, Callable, Mapping

from pipflow.household import agreement
from pipflow.household import world as worlds
from pipflow.household.problem import goal_from_problem, goal_refusal, world_mismatches, write_problem
from pipflow.household.scoring import CATEGORIES, bench_table, load_tasks, score_bench_run, score_run, understanding
from pipflow.household.simulation import simulate
from pipflow.language.offline import NO_USAGE
from pipflow.pddl.common import goal_atoms
from pipflow.resources import data_file
from pipflow.taskdomain import GoalCheck, Save, TaskDomain, flat_simulation, pddl_domain_name

#: the fields a household rule may narrow by (domains/household.actions.yaml ``fields``)
RULE_FIELDS = ("object", "from", "to", "at")
#: where the example problem of a household prompt leaves room for the goal
GOAL_PLACEHOLDER = "; the goal conditions of the command go here"


class HouseholdDomain(TaskDomain):
    """A home: objects in places, states to change (open, on, dirty, sliced), a robot team."""

    name = "household"
    workflow = "household"
    workflows = {"pip-llm": "household", "pip-llm-checked": "household-checked",
                 # the paper's ablations (Table III) and the w/o B (docs/paper.md, "Ablations")
                 **{f"pip-llm-{name}": f"household-{name}" for name in ("no-domain", "no-debugger", "no-bv", "no-as",
                                                                        "n1", "n2", "n3", "n4")}}
    default_prompt = "household_problem"
    rule_fields = RULE_FIELDS

    def pddl_domain(self) -> Path:
        return data_file("domains/household.pddl")

    def action_metadata(self) -> Path:
        return data_file("domains/household.actions.yaml")

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

    def read_offline(self, command: str, world: dict, domain_text: str = "",
                     save: Save | None = None) -> dict:
        """The translator and writer: ``goal`` keeps the command's conditions (counts included)
        for judging, ``concrete`` resolves counts to objects, which is what the problem asks for.
        Untranslatable commands raise TranslationError, impossible ones Refusal (the same as step
        ``household.problem``)."""
        # deferred: builds the lark parser (~150 ms; only offline reading needs it)
        from pipflow.household.language.translator import translate

        result = translate(command, world)
        problem = self.write_problem(world, result["concrete"], pddl_domain_name(domain_text, self.name))
        if save is not None:
            save("goal.json", result)
            save("problem.pddl", problem)
        return {"problem": problem, "goal": result["goal"], "concrete": result["concrete"], "constraints": [],
                "messages": [], "response": "", "usage": dict(NO_USAGE), "errors": []}

    def read_candidate(self, candidate: dict, world: dict, domain_text: str = "",
                       save: Save | None = None) -> dict:
        """A reading the user chose among those a refusal offered: its goal (containers closed
        again) with counts resolved to objects, as :meth:`read_offline` writes it."""
        # deferred: the translator builds the lark parser (only offline reading needs it)
        from pipflow.household.language.translator import resolve_counts

        goal = candidate.get("goal") or {}
        concrete = resolve_counts(world, goal)
        problem = self.write_problem(world, concrete, pddl_domain_name(domain_text, self.name))
        if save is not None:
            save("goal.json", {"goal": goal, "concrete": concrete, "order": candidate.get("order"),
                               "explain": [candidate.get("reading")]})
            save("problem.pddl", problem)
        return {"problem": problem, "goal": goal, "concrete": concrete, "constraints": [],
                "explanation": [str(candidate.get("reading") or "")],
                "messages": [], "response": "", "usage": dict(NO_USAGE), "errors": []}

    def write_problem(self, world: dict, goal: Any, domain_name: str, name: str = "task") -> str:
        return write_problem(world, goal, name=name, domain=domain_name)

    def example_problem(self, world: dict, domain_text: str = "") -> str | None:
        """The world's objects and initial state, with room left for the goal."""
        text = self.write_problem(world, {}, pddl_domain_name(domain_text, self.name))
        return text.replace("  (:goal (and\n", f"  (:goal (and\n    {GOAL_PLACEHOLDER}\n", 1)

    def read_problem(self, parsed: Any, world: dict, constraints: list[dict]) -> dict:
        """The goal conditions read back from the problem. A problem whose goal states nothing
        is no answer: copying the example unchanged would otherwise "succeed" doing nothing."""
        if not goal_atoms(parsed):
            return {"errors": ["the problem's (:goal ...) states no condition: write in it the conditions "
                               "the command asks for, e.g. (at apple fridge) or (not (is-on floorlamp))"]}
        return {"goal": goal_from_problem(parsed)}

    def world_mismatches(self, parsed: Any, problem_text: str, world: dict) -> list[str]:
        return world_mismatches(parsed, problem_text, world)

    def check_goal(self, parsed: Any, world: dict | None) -> GoalCheck:
        """A goal no plan can reach (slicing a mug) is refused, the reason also a message (the
        paper's loop feeds it back); the step's ``goal`` output is empty for household problems
        (the goal conditions are the problem step's ``goal``)."""
        goal: dict = {}
        if world is None:
            return GoalCheck(goal)
        refusal = goal_refusal(world, goal_from_problem(parsed))
        if not refusal:
            return GoalCheck(goal)
        # the reason is a message too: the paper's loop feeds back all the verifier finds
        return GoalCheck(goal, [f"the goal cannot be reached in this world: {refusal}"],
                         f"the command cannot be done in this world: {refusal}")

    def second_opinion(self, command: str, world: dict, goal: Any, constraints: list[dict],
                       refusal: str | None, last: bool = False) -> Any | None:
        """The goal conditions and robot rules against the translator's reading."""
        return agreement.second_opinion(command, world, goal, constraints, refusal, last)

    def simulate(self, world: dict, schedule: dict, graph: dict | None, goal: Any, *,
                 snapshots: bool = False, out_dir: Path | None = None,
                 log: Callable[[str], None] = print, save: Save | None = None, **options: Any) -> dict:
        """The home simulator's result (``final_state``: where each object is and its states),
        plus ``conditions`` (goal conditions met / total / unmet)."""
        return simulate(world, schedule, graph, goal, snapshots=snapshots, out_dir=out_dir, log=log)

    def score(self, world: dict, goal: Any, *, constraints: list[dict] | None = None,
              feasible: bool = True, graph: dict | None = None, schedule: dict | None = None,
              simulation: dict | None = None, refusal: str | None = None,
              error: str | None = None) -> dict:
        return score_run(world, goal, feasible=feasible, graph=graph, schedule=schedule,
                         simulation=flat_simulation(simulation), refusal=refusal, error=error)

    def load_tasks(self, path: Path) -> dict:
        return load_tasks(path)

    def score_bench_run(self, world_path: str, task: dict, outputs: dict, refusal: str | None,
                        error: str | None) -> dict:
        return score_bench_run(world_path, task, {**outputs, "simulation": flat_simulation(outputs.get("simulation"))},
                               refusal, error)

    def understand(self, task: dict, outputs: dict, status: str, error_kind: str | None,
                   world_path: str | None = None) -> dict | None:
        """Meanings compared in the task's team's world (where objects can end, which flags can
        change; the team's robots for the rules)."""
        world = worlds.select_team(worlds.load_world(world_path), task.get("team")) if world_path else None
        fields = {f: list(names) for f, (names, _) in self.rule_names(world).items()} if world else None
        return understanding(task, outputs, status, error_kind, world, fields)

    def bench_table(self, results: dict, tasks_file: Path) -> str | None:
        return bench_table(results, tasks_file)

    def table_groups(self, tasks: list[dict]) -> list[tuple[str, list[str]]] | None:
        """The paper's categories, in its order (compound, complex, vague)."""
        return [(c, [t["id"] for t in tasks if t.get("category") == c]) for c in CATEGORIES]

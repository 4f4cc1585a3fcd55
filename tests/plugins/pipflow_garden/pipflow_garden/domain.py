"""The garden as a pipflow task domain: the one object pipflow's generic code (and the bench)
talks to, registered in ``pipflow.task_domains`` by this package's pyproject.toml.

Each method is a thin face of a module of this package (world, language, problem, simulation,
scoring); nothing here is garden knowledge pipflow has to have.
"""
from __future__ import annotations

from pathlib import Path
from typing import Any, Callable, Mapping

from pipflow.language.offline import NO_USAGE  # the usage record of a reading that called no model
from pipflow.pddl.common import goal_atoms
from pipflow.taskdomain import GoalCheck, Save, TaskDomain, flat_simulation, pddl_domain_name

from pipflow_garden import checks, language, problem, scoring, simulation, world as worlds

HERE = Path(__file__).resolve().parent
DATA = HERE / "data"
#: where the example problem of the prompt leaves room for the goal
GOAL_PLACEHOLDER = "; the goal conditions of the command go here"


class GardenDomain(TaskDomain):
    """Robots water beds, prune overgrown ones and harvest ripe crops into stores."""

    name = "garden"
    workflow = str(HERE / "workflows" / "garden.yaml")
    default_prompt = str(HERE / "prompts" / "garden_problem.j2")
    rule_fields = ("bed", "crop", "to")

    def pddl_domain(self) -> Path:
        return DATA / "garden.pddl"

    def action_metadata(self) -> Path:
        return DATA / "garden.actions.yaml"

    def load_world(self, path: str | Path, *, seed: int | None = None, **options: Any) -> dict:
        return worlds.vary_starts(worlds.load_world(path), seed)

    def describe(self, world: dict) -> str:
        return (f"{len(world['beds'])} beds, {len(world['taps'])} taps, "
                f"{len(world['stores'])} stores, {len(world['robots'])} robots")

    def rule_names(self, world: dict) -> Mapping[str, tuple[Any, str]]:
        return {"bed": (world["beds"], "bed"), "crop": (world["crops"], "crop"), "to": (world["stores"], "store")}

    def read_offline(self, command: str, world: dict, domain_text: str = "",
                     save: Callable[[str, Any], Any] | None = None) -> dict:
        read = language.read_command(command, world)
        text = problem.write_problem(world, read["goal"], pddl_domain_name(domain_text, self.name))
        if save is not None:
            save("order.json", {"order": read["order"], "explanation": read["explanation"]})
            save("problem.pddl", text)
        return {"problem": text, "goal": read["goal"], "constraints": read["constraints"], "messages": [],
                "response": "", "usage": dict(NO_USAGE), "errors": [], "order": read["order"],
                "explanation": read["explanation"]}

    def write_problem(self, world: dict, goal: Any, domain_name: str, name: str = "task") -> str:
        return problem.write_problem(world, goal, domain_name, name=name)

    def example_problem(self, world: dict, domain_text: str = "") -> str | None:
        """The garden's objects and initial state, with room left for the goal."""
        text = problem.write_problem(world, {}, pddl_domain_name(domain_text, self.name))
        return text.replace("  (:goal (and\n", f"  (:goal (and\n    {GOAL_PLACEHOLDER}\n", 1)

    def read_problem(self, parsed: Any, world: dict, constraints: list[dict]) -> dict:
        """A model's goal read back; a goal that states nothing, or a condition the garden's goal
        form cannot hold, is feedback (never dropped)."""
        if not goal_atoms(parsed):
            return {"errors": ["the problem's (:goal ...) states no condition: write the conditions the command "
                               "asks for, e.g. (watered north) or (>= (stored shed tomato) 3)"]}
        goal, unread = checks.goal_from_problem(parsed)
        return {"goal": goal, "errors": unread} if unread else {"goal": goal}

    def world_mismatches(self, parsed: Any, problem_text: str, world: dict) -> list[str]:
        return checks.world_mismatches(parsed, world)

    def check_goal(self, parsed: Any, world: dict | None) -> GoalCheck:
        goal, unread = checks.goal_from_problem(parsed)
        if world is None:
            return GoalCheck(goal, unread)
        refusal = checks.goal_refusal(world, goal)
        return GoalCheck(goal, unread, f"the command cannot be done in this garden: {refusal}" if refusal else None)

    def simulate(self, world: dict, schedule: dict, graph: dict | None, goal: Any, *,
                 snapshots: bool = False, out_dir: Path | None = None,
                 log: Callable[[str], None] = print, save: Save | None = None, **options: Any) -> dict:
        """The kinematic replay (it draws no pictures and keeps no records): pipflow's generic
        step ``simulate`` runs it, so the garden needs no step of its own."""
        return simulation.simulate(world, schedule, graph, goal, log=log)

    def score(self, world: dict, goal: Any, *, constraints: list[dict] | None = None,
              feasible: bool = True, graph: dict | None = None, schedule: dict | None = None,
              simulation: dict | None = None, refusal: str | None = None,
              error: str | None = None) -> dict:
        return scoring.score_run(world, goal, constraints=constraints, feasible=feasible, graph=graph,
                                 schedule=schedule, simulation=flat_simulation(simulation), refusal=refusal,
                                 error=error)

    def load_tasks(self, path: Path) -> dict:
        return scoring.load_tasks(path, self.workflow)

    def score_bench_run(self, world_path: str, task: dict, outputs: dict, refusal: str | None,
                        error: str | None) -> dict:
        return self.score(worlds.load_world(world_path), task.get("goal") or {},
                          constraints=task.get("constraints"),
                          feasible=task.get("feasible", True) is not False and task.get("expect") != "refuse",
                          graph=outputs.get("graph"), schedule=outputs.get("schedule"),
                          simulation=outputs.get("simulation"), refusal=refusal, error=error)

    def understand(self, task: dict, outputs: dict, status: str, error_kind: str | None,
                   world_path: str | None = None) -> dict | None:
        world = worlds.load_world(world_path) if world_path else None
        fields = {f: list(names) for f, (names, _) in self.rule_names(world).items()} if world else None
        return scoring.understanding(task, outputs, status, error_kind, world, fields)

"""The garden as a pipflow task domain: the one object pipflow's generic code (and the bench)
talks to, registered in ``pipflow.task_domains`` by this package's pyproject.toml.

The protocol's required core, each method a thin face of a module of this package (world,
language, problem, checks, simulation, scoring), and one capability: goals compared by meaning
(the bench's understanding). Scoring, the bench row, task files and the understanding verdict are
pipflow's template methods; nothing here is garden knowledge pipflow has to have, and nothing of
pipflow is imported but its public face, :mod:`pipflow.plugin`.
"""
from __future__ import annotations

from pathlib import Path
from typing import Any, Callable, Mapping

from pipflow.plugin import ComparesGoals, Condition, Reading, Reference, Save, TaskDomain

from pipflow_garden import checks, language, problem, scoring, simulation, world as worlds

HERE = Path(__file__).resolve().parent
DATA = HERE / "data"


class GardenDomain(TaskDomain, ComparesGoals):
    """Robots water beds, prune overgrown ones and harvest ripe crops into stores."""

    name = "garden"
    workflow = str(HERE / "workflows" / "garden.yaml")
    default_prompt = str(HERE / "prompts" / "garden_problem.j2")
    rule_fields = ("bed", "crop", "to")
    goal_example = "(watered north) or (>= (stored shed tomato) 3)"

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

    def read_command(self, command: str, world: dict) -> Reading:
        read = language.read_command(command, world)
        return Reading(read["goal"], read["constraints"], order=read["order"], explanation=read["explanation"])

    def write_problem(self, world: dict, goal: Any, domain_name: str, name: str = "task") -> str:
        return problem.write_problem(world, goal, domain_name, name=name)

    def read_goal(self, parsed: Any, world: dict | None) -> tuple[Any, list[str]]:
        return checks.goal_from_problem(parsed)

    def world_mismatches(self, parsed: Any, problem_text: str, world: dict) -> list[str]:
        return checks.world_mismatches(parsed, world)

    def goal_problems(self, world: dict, goal: Any) -> tuple[list[str], str | None]:
        return [], checks.goal_refusal(world, goal)

    def simulate(self, world: dict, schedule: dict, graph: dict | None, goal: Any, *,
                 snapshots: bool = False, out_dir: Path | None = None,
                 log: Callable[[str], None] = print, save: Save | None = None, **options: Any) -> dict:
        """The kinematic replay (it draws no pictures and keeps no records)."""
        return simulation.simulate(world, schedule, graph, goal, log=log)

    def initial_state(self, world: dict) -> Any:
        return simulation.initial_state(world)

    def goal_conditions(self, world: dict, state: Any, goal: Any) -> list[Condition]:
        return [Condition(*c) for c in simulation.condition_values(state, goal or {})]

    def reference(self, world: dict, goal: Any) -> Reference:
        return Reference(scoring.reference_actions(world, goal or {}))

    def task_goal_problems(self, goal: Any, world: dict) -> list[tuple[tuple, str, bool]]:
        return scoring.goal_problems(goal, world)

    def goal_difference(self, world: dict | None, gold: Any, run: Any) -> str | None:
        """Goals compared as written (bed lists as sets)."""
        a, b = scoring.canonical_goal(gold), scoring.canonical_goal(run)
        return None if a == b else f"goal {b}; gold {a}"

"""The pipeline on a world and commands that the paper never saw (other names, six racks, robots
of four sizes): nothing in pipflow may depend on the benchmark's shelves, products or robots."""
from __future__ import annotations

import json
from pathlib import Path

import pytest

from pipflow.engine.cli import main

TASKS = Path(__file__).resolve().parent / "fixtures" / "generalization" / "tasks.yaml"


def test_bench_on_an_unseen_world_succeeds_on_every_task(tmp_path, capsys):
    out = tmp_path / "bench"
    assert main(["bench", str(TASKS), "--seeds", "2", "--jobs", "2", "--out", str(out), "-q",
                 "--runs-dir", str(tmp_path / "runs")]) == 0
    results = json.loads((out / "results.json").read_text())
    by_id = {t["id"]: t for t in results["tasks"]}
    assert set(by_id) == {"g-01", "g-02", "g-03", "g-04", "g-05"}
    for task in results["tasks"]:
        assert task["sr"] == 1.0, task
        assert task["runs"] == 2
    # the infeasible task is refused with its reason; the others move robots
    assert "rack_e" in by_id["g-05"]["error"] and "30" in by_id["g-05"]["error"]
    assert all(by_id[t]["tc_max"] > 0 for t in ("g-01", "g-02", "g-03", "g-04"))


def test_translator_reads_every_name_from_the_unseen_world():
    import yaml

    from pipflow.errors import Refusal
    from pipflow.warehouse.language.translator import translate
    from pipflow.warehouse.world import load_world

    tasks = yaml.safe_load(TASKS.read_text())["tasks"]
    world = load_world(TASKS.parent / "world.yaml")
    for task in tasks:
        if task.get("feasible", True) is False:  # refused with its reason, before any robot moves
            with pytest.raises(Refusal):
                translate(task["command"], world)
            continue
        got = translate(task["command"], world)
        assert got["goal"] == task["goal"], task["id"]
        assert got["constraints"] == task.get("constraints", []), task["id"]


def test_a_small_team_gets_moves_it_can_carry(tmp_path):
    """Two robots that carry one unit each: the team-level problem offers moves of at most two
    units (the paper's 1..6 would plan moves no coalition can make), and the command succeeds."""
    import yaml

    from pipflow.engine import run_workflow

    world = yaml.safe_load((TASKS.parent / "world.yaml").read_text())
    world["robots"] = {"r1": {"start": [1, 1], "skills": {"carry": 1}},
                       "r2": {"start": [39, 1], "skills": {"carry": 1}}}
    path = tmp_path / "small-team.yaml"
    path.write_text(yaml.safe_dump(world))
    result = run_workflow("warehouse", {"world": str(path), "command": "rack e should hold 5 pear"},
                          runs_dir=tmp_path / "runs")
    assert result.ok, result.error
    sizes = [int(step["args"][3].removeprefix("magnitude")) for step in result.outputs["plan"]]
    assert max(sizes) <= 2 and sum(sizes) == 5
    assert result.outputs["goal_met"] is True


MIXED_CASE_WORLD = """\
floor: {width: 40, height: 30}
shelves:
  A1: {x: 2, y: 2, width: 4, depth: 2, capacity: 20, access: [4, 1]}
  Bay-12: {x: 10, y: 2, width: 4, depth: 2, capacity: 20, access: [12, 1]}
products:
  Apple: {color: red}
  SKU-7781: {color: blue}
stock:
  A1: {Apple: 5, SKU-7781: 3}
robots:
  Forklift-2: {start: [1, 10], skills: {carry: 3}}
  alpha: {start: [5, 10], skills: {carry: 2}}
"""


def test_names_in_any_case_reach_the_robots_spelled_as_the_world_spells_them(tmp_path):
    """PDDL reads names in lower case; plans, goals and rules still use the world's spelling, and
    a rule that leaves only a weak robot makes the planner keep moves within its carry."""
    from pipflow.engine import run_workflow

    path = tmp_path / "mixed.yaml"
    path.write_text(MIXED_CASE_WORLD)
    command = "Bay-12 should hold 2 SKU-7781 and 3 apple. Do not use Forklift-2."
    result = run_workflow("warehouse", {"world": str(path), "command": command}, runs_dir=tmp_path / "runs")
    assert result.ok, result.error
    assert result.outputs["goal"] == {"Bay-12": {"SKU-7781": 2, "Apple": 3}}
    assert {a for step in result.outputs["plan"] for a in step["args"][:3]} <= {"A1", "Bay-12", "Apple", "SKU-7781"}
    robots = {r for s in result.outputs["schedule"]["subtasks"] for r in s["robots"]}
    assert robots == {"alpha"} and result.outputs["goal_met"] is True


def test_a_rule_that_leaves_one_weak_robot_gets_moves_it_can_carry(tmp_path):
    """Only robot1 (carries one unit) may move to shelf1: every move to shelf1 carries one unit,
    so allocation never meets a move no allowed coalition can make."""
    from pipflow.engine import run_workflow

    command = "There should be 16 product1 in shelf1. We can only use robot1 to move product to shelf1."
    result = run_workflow("warehouse", {"command": command}, runs_dir=tmp_path / "runs")
    assert result.ok, result.error
    into_shelf1 = [s for s in result.outputs["plan"] if s["args"][1] == "shelf1"]
    assert len(into_shelf1) == 6 and all(s["args"][3] == "magnitude1" for s in into_shelf1)
    assert result.outputs["goal_met"] is True


def test_names_that_differ_only_in_case_are_rejected_with_their_location(tmp_path):
    from pipflow.errors import WorldError
    from pipflow.warehouse.world import load_world

    path = tmp_path / "clash.yaml"
    path.write_text(MIXED_CASE_WORLD.replace("  alpha:", "  ALPHA: {start: [7, 10], skills: {carry: 1}}\n  alpha:"))
    with pytest.raises(WorldError) as err:
        load_world(path)
    assert any("only in case" in d.message and d.location.line == 13 for d in err.value.diagnostics), err.value

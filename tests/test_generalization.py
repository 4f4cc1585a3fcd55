"""The pipeline on a world and commands that the paper never saw (other names, six racks, robots
of four sizes): nothing in pipflow may depend on the benchmark's shelves, products or robots."""
from __future__ import annotations

import json
from pathlib import Path

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

    from pipflow.language.translator import translate
    from pipflow.world import load_world

    tasks = yaml.safe_load(TASKS.read_text())["tasks"]
    world = load_world(TASKS.parent / "world.yaml")
    for task in tasks:
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

"""Bad planner choices and planner time-outs (issue 13, defects 5 and 11), with the real engines.

An unknown planner is a user error (exit 2) that names the installed planners, never a silent
run of another one; a fallback happens only where the workflow names one, and the step's outputs
say which engine answered. A problem that found no plan is not solved again when it comes back
unchanged, and a time-out ends the run with "the planner ... timed out after N s" instead of
spending the time limit in every round of the refinement loop.
"""
from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

from pipflow import StepContext
from pipflow.errors import InputError, PlanningError

REPO = Path(__file__).resolve().parents[1]
DOMAIN = str(REPO / "domains/warehouse.pddl")

pytestmark = pytest.mark.usefixtures("no_hang")


@pytest.fixture(scope="module")
def problem():
    from pipflow.warehouse.problem import write_problem
    from pipflow.warehouse.world import load_world

    world = load_world(REPO / "benchmarks/warehouse/world.yaml")
    return world, write_problem(world, {"shelf4": {"product3": 12, "product1": 5}})


def solve(tmp_path: Path, problem: str, world: dict, logs: list | None = None, **args):
    from pipflow.steps.pddl import solve as step

    ctx = StepContext("solve", tmp_path / "art", base_dir=REPO / "workflows",
                      log=(logs.append if logs is not None else None))
    return step.func(ctx, problem=problem, domain=DOMAIN, world=world, **args)


def pipflow(tmp_path: Path, *args: str) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "pipflow.engine.cli", "run", "warehouse", "--runs-dir",
                           str(tmp_path / "runs"), "--no-cache", *args], capture_output=True, text=True,
                          timeout=240, cwd=tmp_path, env={**os.environ, "PIPFLOW_MODEL": "offline"})


def test_an_unknown_planner_is_a_user_error_naming_the_installed_ones(tmp_path, problem):
    proc = pipflow(tmp_path, "-i", "planner=enshp")
    assert proc.returncode == 2, proc.stderr
    assert "unknown planner 'enshp' (did you mean 'enhsp'?)" in proc.stderr
    assert "installed planners:" in proc.stderr and "pipflow-transport" in proc.stderr
    assert "Traceback" not in proc.stderr
    world, text = problem
    with pytest.raises(InputError, match="unknown planner 'nosuch'"):
        solve(tmp_path, text, world, engine="nosuch")
    with pytest.raises(InputError, match="unknown planner 'nosuch'"):  # a misspelt fallback as well
        solve(tmp_path, text, world, engine="enhsp", fallback="nosuch")


def test_a_fallback_only_where_named_and_recorded(tmp_path, problem):
    world, text = problem
    alone = solve(tmp_path, text, world, engine="fast-downward", timeout=60)  # classical: no numeric fluents
    assert alone["status"] == "error" and alone["engine"] == "fast-downward" and alone["plan"] is None
    assert len(alone["message"]) < 1200  # the engine's log is cut to a readable length
    helped = solve(tmp_path, text, world, engine="fast-downward", fallback="enhsp", timeout=60)
    assert helped["status"] == "solved" and helped["engine"] == "enhsp"
    assert "fell back to enhsp" in helped["message"]


def test_a_time_out_ends_the_step_and_an_unchanged_problem_is_not_solved_again(tmp_path, problem):
    world, text = problem
    logs: list[str] = []
    with pytest.raises(PlanningError, match=r"the planner enhsp timed out after 0\.3 s"):
        solve(tmp_path, text, world, logs, engine="enhsp", timeout=0.3)
    with pytest.raises(PlanningError, match="not solved again"):
        solve(tmp_path, text, world, logs, engine="enhsp", timeout=0.3)
    assert any("already answered this exact problem" in line for line in logs)
    other = text.replace("(= (stock shelf4 product3) 12)", "(= (stock shelf4 product3) 11)")
    assert other != text
    with pytest.raises(PlanningError) as info:  # a changed problem is solved anew
        solve(tmp_path, other, world, engine="enhsp", timeout=0.3)
    assert "not solved again" not in str(info.value)


def test_a_planner_time_out_ends_the_refinement_loop_at_once(tmp_path):
    proc = pipflow(tmp_path, "-i", "planner=enhsp", "-i", "planner_timeout=0.3", "-i", "rounds=4")
    assert proc.returncode == 1, proc.stderr
    assert "the planner enhsp timed out after 0.3 s" in proc.stderr and "Traceback" not in proc.stderr
    (run,) = list((tmp_path / "runs").iterdir())
    events = [json.loads(line) for line in (run / "events.jsonl").read_text().splitlines() if line.strip()]
    starts = [e for e in events if e.get("step") == "solve" and e.get("event") == "start"]
    assert len(starts) == 1, "one solve, not one per round of the loop"

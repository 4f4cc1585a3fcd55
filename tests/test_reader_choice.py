"""Issue 23, point 4: ask rather than refuse. A command refused with candidate readings keeps them
in its record and in the API's answer; the workflow input ``reading`` runs one; ``pipflow run`` on a
terminal asks which (or none), and with ``--no-input`` asks nothing. Through the real workflow
(parser, ENHSP, SCIP, simulation) and the real CLI on a pseudo-terminal."""
from __future__ import annotations

import json
import os
import pty
import subprocess
from pathlib import Path

import pipflow
from cli_entry import PIPFLOW

REPO = Path(__file__).resolve().parent.parent

COMMAND = "Send 2 product1 from shelf1 to shelf2 yonder"   # 'yonder' is placed by no rule
GOAL = {"shelf1": {"product1": 8}, "shelf2": {"product1": 10}}


def test_the_api_and_the_record_keep_the_candidates_and_reading_runs_one(tmp_path: Path) -> None:
    refused = pipflow.run("warehouse", command=COMMAND, runs_dir=tmp_path)
    assert refused.status == "failed" and "yonder" in (refused.error or "")
    assert [c["goal"] for c in refused.candidates] == [GOAL]
    record = json.loads((refused.record / "run.json").read_text())
    assert [c["goal"] for c in record["candidates"]] == [GOAL]
    chosen = pipflow.run("warehouse", command=COMMAND, reading=1, runs_dir=tmp_path)
    assert chosen.ok and chosen.outputs["goal"] == GOAL
    assert any("chosen by the user" in line for line in chosen.outputs["understood"])


def test_a_reading_that_was_not_offered_is_a_user_error(tmp_path: Path) -> None:
    run = pipflow.run("warehouse", command=COMMAND, reading=2, runs_dir=tmp_path)
    assert run.status == "failed" and "offers 1 candidate reading" in (run.error or "")


def _pipflow_on_terminal(args: list[str], answer: bytes, cwd: Path) -> tuple[int, str]:
    """``pipflow ARGS`` with stdin on a pseudo-terminal that types ``answer``."""
    main, child = pty.openpty()
    proc = subprocess.Popen([PIPFLOW, *args], stdin=child, stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, cwd=cwd, env={**os.environ, "PYTHONUNBUFFERED": "1"})
    os.close(child)
    os.write(main, answer)
    out, _ = proc.communicate(timeout=600)
    os.close(main)
    return proc.returncode, out.decode()


def test_pipflow_run_on_a_terminal_asks_which_reading(tmp_path: Path) -> None:
    root = Path(__file__).resolve().parent.parent
    code, out = _pipflow_on_terminal(["run", "warehouse", "-i", f"command={COMMAND}", "--runs-dir", str(tmp_path)],
                                     b"1\n", root)
    assert "run which reading? [1-1" in out and "running reading 1" in out
    assert code == 0, out
    code, out = _pipflow_on_terminal(["run", "warehouse", "-i", f"command={COMMAND}", "--runs-dir", str(tmp_path)],
                                     b"\n", root)
    assert "run which reading?" in out and code == 1, out
    code, out = _pipflow_on_terminal(["run", "warehouse", "-i", f"command={COMMAND}", "--runs-dir", str(tmp_path),
                                      "--no-input"], b"1\n", root)
    assert "run which reading?" not in out and code == 1, out
    assert "Did you mean: (1)" in out   # the candidates are said in the refusal all the same


def test_the_bench_reports_candidate_recall(tmp_path: Path) -> None:
    """Of the clear, feasible commands refused as not understood, the share whose gold reading
    was among the candidates: here one of two (the first offers it; the second offers only the
    reading without "Blorp", a bound of at most 4, which is not the gold)."""
    from pipflow.experiments.benchmarking import BenchConfig, run_bench

    fixture = Path(__file__).resolve().parent / "fixtures" / "bench"
    tasks = tmp_path / "tasks.yaml"
    tasks.write_text(f"""world: {fixture / 'world.yaml'}
tasks:
  - id: offered
    command: "There should be 4 product1 in shelf2 yonder."
    goal: {{shelf2: {{product1: 4}}}}
  - id: not-offered
    command: "Blorp shelf2 up to 4 product1."
    goal: {{shelf2: {{product1: 4}}}}
  - id: read
    command: "There should be 4 product1 in shelf2."
    goal: {{shelf2: {{product1: 4}}}}
""")
    results = run_bench(BenchConfig(tasks_file=tasks, seeds=1, jobs=1, out=tmp_path / "out", use_cache=False),
                        progress=False)
    assert results["summary"]["candidate_recall"] == 0.5
    assert "candidate_recall: 0.50" in (tmp_path / "out" / "table.md").read_text()


def test_a_household_reading_chosen_after_a_refusal_is_written_with_its_counts_resolved():
    """`-i reading=K` on a home: the chosen reading's count ("two fruits in the fridge") becomes
    the objects the problem moves, and the round keeps the reading (it raised NameError before:
    the household's own copy of the offline round had lost its imports)."""
    from pipflow.household import world as household_world
    from pipflow.household.domain import HouseholdDomain

    world = household_world.load_world(REPO / "benchmarks/household/world.yaml")
    saved: dict = {}
    out = HouseholdDomain().read_candidate(
        {"goal": {"count": [{"category": "fruit", "in": "fridge", "at_least": 2}]}, "reading": "two fruits in the fridge"},
        world, (REPO / "domains/household.pddl").read_text(), saved.__setitem__)
    goal_part = out["problem"].split("(:goal", 1)[1]
    assert "(at apple fridge)" in goal_part and "(at watermelon fridge)" in goal_part
    assert out["goal"] == {"count": [{"category": "fruit", "in": "fridge", "at_least": 2}]}
    assert out["explanation"] == ["two fruits in the fridge"] and out["errors"] == []
    assert {"goal.json", "problem.pddl"} <= set(saved)

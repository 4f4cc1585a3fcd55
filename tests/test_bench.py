"""`pipflow bench` with the local executor: results.json schema, a `feasible: false` task,
`--matrix` variants side by side, runs.csv / table.md, one row file per run, `--resume`.

The fixture (tests/fixtures/bench/) is a tiny world with three tasks, one infeasible; a run takes
about half a second. The step cache is off so that the results never come from another test.
"""
from __future__ import annotations

import csv
import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

from conftest import interrupt_after
from pipflow.bench import BenchConfig, read_row, row_path, run_bench
from pipflow.executors import parse_executor, parse_limits, run_key
from pipflow.errors import UserError
from pipflow.scoring import score_run

FIXTURE = Path(__file__).resolve().parent / "fixtures" / "bench"
TASKS = FIXTURE / "tasks.yaml"
TASK_IDS = ["t-move", "t-two", "t-too-many"]
SUMMARY_KEYS = {"runs", "sr", "gcr", "exe", "ru", "tc_max", "tc_avg"}
TASK_KEYS = {"id", "runs", "sr", "gcr", "exe", "ru", "tc_max", "tc_avg", "error"}


pytestmark = pytest.mark.usefixtures("no_hang")


def config(out: Path, **kw) -> BenchConfig:
    return BenchConfig(tasks_file=TASKS, seeds=kw.pop("seeds", 2), jobs=kw.pop("jobs", 2), out=out,
                       use_cache=False, **kw)


@pytest.fixture(scope="module")
def local_bench(tmp_path_factory):
    out = tmp_path_factory.mktemp("bench_local")
    return out, run_bench(config(out), progress=False)


def test_results_schema(local_bench):
    out, results = local_bench
    on_disk = json.loads((out / "results.json").read_text())
    assert on_disk["summary"] == pytest.approx(results["summary"])
    assert SUMMARY_KEYS <= set(on_disk["summary"])
    assert on_disk["summary"]["runs"] == 6
    assert [t["id"] for t in on_disk["tasks"]] == TASK_IDS
    for t in on_disk["tasks"]:
        assert TASK_KEYS <= set(t)
        assert t["runs"] == 2
        for k in ("sr", "gcr", "exe", "ru"):
            assert 0.0 <= t[k] <= 1.0
    assert on_disk["config"]["executor"] == "local"
    assert on_disk["executed_runs"] == 6 and on_disk["resumed_runs"] == 0


def test_feasible_tasks_succeed_and_the_infeasible_one_is_refused_with_a_reason(local_bench):
    _, results = local_bench
    tasks = {t["id"]: t for t in results["tasks"]}
    assert tasks["t-move"]["sr"] == 1.0 and tasks["t-move"]["tc_max"] > 0
    assert tasks["t-two"]["sr"] == 1.0 and tasks["t-two"]["error"] is None
    refused = tasks["t-too-many"]
    assert refused["sr"] == 1.0, "an infeasible command refused with a reason counts as a success"
    assert refused["error"] and "50" in refused["error"]  # the reason names the impossible count
    rows = json.loads((Path(local_bench[0]) / "runs.json").read_text())
    for row in rows:
        if row["task"] == "t-too-many":
            assert row["status"] == "refused" and row["executed"] == 0


def test_infeasible_task_is_a_failure_unless_refused_with_a_reason():
    world = {"shelves": {"shelf1": {"capacity": 5}}, "stock": {"shelf1": {"product1": 1}}}
    goal = {"shelf1": {"product1": 50}}
    assert score_run(world, goal, feasible=False, refusal="shelf1 cannot hold 50 units")["success"]
    assert not score_run(world, goal, feasible=False, refusal="   ")["success"]
    assert not score_run(world, goal, feasible=False)["success"]
    executed = score_run(world, goal, feasible=False, refusal="no", schedule={"subtasks": [{"id": "s1"}]},
                         simulation={"executed": 1})
    assert not executed["success"]


def test_row_file_per_run_runs_csv_and_table(local_bench):
    out, _ = local_bench
    files = sorted((out / "runs").rglob("*.json"))
    assert len(files) == 6
    for task in TASK_IDS:
        for seed in (0, 1):
            row = read_row(out, ("default", task, seed))
            assert row is not None and row["seed"] == seed
            assert Path(row["run_dir"]).is_dir() and (Path(row["run_dir"]) / "run.json").exists()
    with open(out / "runs.csv", newline="") as fh:
        rows = list(csv.DictReader(fh))
    assert len(rows) == 6 and {"variant", "task", "seed", "success", "tc_max", "run_dir"} <= set(rows[0])
    table = (out / "table.md").read_text()
    assert "| Task | SR (%)" in table
    for task in TASK_IDS:
        assert f"| {task} |" in table
    assert "**all** (6 runs)" in table


def test_resume_runs_only_missing_rows(local_bench, tmp_path):
    src, _ = local_bench
    out = tmp_path / "b"
    import shutil
    shutil.copytree(src, out)
    gone = [("default", "t-two", 1), ("default", "t-move", 0)]
    for key in gone:
        row_path(out, key).unlink()
    kept = {p: p.stat().st_mtime_ns for p in (out / "runs").rglob("*.json")}
    results = run_bench(config(out, resume=True), progress=False)
    assert results["executed_runs"] == 2 and results["resumed_runs"] == 4
    assert results["summary"]["runs"] == 6
    for p, mtime in kept.items():
        assert p.stat().st_mtime_ns == mtime, f"{p} was rewritten although its run was done"
    for key in gone:
        assert read_row(out, key) is not None


def test_interrupted_bench_resumes_with_every_run_once(tmp_path):
    out = tmp_path / "b"
    stop_after_two = interrupt_after(2)
    seen = stop_after_two.seen

    with pytest.raises(KeyboardInterrupt):
        run_bench(config(out, seeds=2, jobs=1), progress=False, on_row=stop_after_two)
    assert len(list((out / "runs").rglob("*.json"))) == 2
    assert not (out / "results.json").exists()
    again = []
    results = run_bench(config(out, seeds=2, jobs=1, resume=True), progress=False,
                        on_row=lambda r: again.append(run_key(r)))
    assert results["resumed_runs"] == 2 and results["executed_runs"] == 4
    assert not set(again) & set(seen)
    assert results["summary"]["runs"] == 6
    rows = json.loads((out / "runs.json").read_text())
    assert len({run_key(r) for r in rows}) == len(rows) == 6


def test_matrix_runs_variants_side_by_side(tmp_path):
    out = tmp_path / "m"
    results = run_bench(config(out, seeds=1, matrix={"graph_mode": ["exact", "paper"]}), progress=False)
    names = [v["name"] for v in results["variants"]]
    assert names == ["graph_mode=exact", "graph_mode=paper"]
    for v in results["variants"]:
        assert v["summary"]["runs"] == 3 and [t["id"] for t in v["tasks"]] == TASK_IDS
    assert results["summary"] == results["variants"][0]["summary"]
    table = (out / "table.md").read_text()
    assert "### graph_mode=exact" in table and "### graph_mode=paper" in table
    assert len(list((out / "runs" / "graph_mode=paper").rglob("*.json"))) == 3
    rows = list(csv.DictReader(open(out / "runs.csv", newline="")))
    assert {r["variant"] for r in rows} == {"graph_mode=exact", "graph_mode=paper"}


def test_cli_bench_prints_the_table(tmp_path):
    out = tmp_path / "cli"
    proc = subprocess.run([sys.executable, "-m", "pipflow.engine.cli", "bench", str(TASKS), "--seeds", "1",
                           "--jobs", "2", "--out", str(out), "--no-cache", "-q"],
                          capture_output=True, text=True, timeout=180, env={**os.environ, "PIPFLOW_MODEL": "offline"})
    assert proc.returncode == 0, proc.stderr
    assert "| t-move | 100 |" in proc.stdout
    assert json.loads((out / "results.json").read_text())["summary"]["runs"] == 3


def test_cli_rejects_bad_executor_and_resume_without_out(tmp_path):
    with pytest.raises(UserError):
        parse_executor("spark")
    with pytest.raises(UserError):
        parse_executor("local=tcp://x:1")
    assert parse_executor("dask=tcp://10.0.0.1:8786") == ("dask", "tcp://10.0.0.1:8786")
    assert parse_executor("dask") == ("dask", None)
    assert parse_limits("openai=4,2") == {"openai": 4, "default": 2}
    with pytest.raises(UserError):
        parse_limits("openai=0")
    proc = subprocess.run([sys.executable, "-m", "pipflow.engine.cli", "bench", str(TASKS), "--resume"],
                          capture_output=True, text=True, timeout=120, cwd=tmp_path)
    assert proc.returncode == 2 and "--resume needs --out" in proc.stderr

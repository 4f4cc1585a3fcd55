"""`pipflow bench` with the local backend: results.json schema, a `feasible: false` task,
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
from pipflow.experiments.benchmarking import BenchConfig, read_row, row_path, run_bench
from pipflow.experiments.backends import parse_backend, parse_limits, run_key
from pipflow.errors import UserError
from pipflow.warehouse.domain import WarehouseDomain

score_run = WarehouseDomain().score  # the protocol's score of a warehouse run

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
    assert on_disk["config"]["backend"] == "local" and "executor" not in on_disk["config"]
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


def test_a_method_name_runs_the_task_files_domains_workflow_and_rows_say_which_loop_ran(tmp_path):
    """``--matrix workflow=pip-llm,pip-llm-checked`` runs, for a warehouse task file, the paper's
    loop and the checked one; for a household task file the household's files of those names.
    Each row (runs.json, runs.csv) says which loop ran and whose reading the goal was; with the
    offline parser the two loops give the same results task by task."""
    out = tmp_path / "loops"
    results = run_bench(config(out, seeds=1, matrix={"workflow": ["pip-llm", "pip-llm-checked"]}), progress=False)
    assert [v["name"] for v in results["variants"]] == ["workflow=pip-llm", "workflow=pip-llm-checked"]
    assert results["config"]["workflows"] == {"workflow=pip-llm": "pip-llm",
                                              "workflow=pip-llm-checked": "pip-llm-checked"}
    rows = json.loads((out / "runs.json").read_text())
    # the infeasible task is refused by the parser before any goal is written: no reader
    assert {(r["variant"], r["loop"], r["reader"]) for r in rows} == {
        (v, loop, reader) for v, loop in (("workflow=pip-llm", "pip-llm"), ("workflow=pip-llm-checked", "checked"))
        for reader in ("offline", None)}
    assert all((r["reader"] is None) == (r["task"] == "t-too-many") for r in rows)
    csv_rows = list(csv.DictReader(open(out / "runs.csv", newline="")))
    assert {r["loop"] for r in csv_rows} == {"pip-llm", "checked"}
    paper, checked = ([(t["id"], t["sr"], t["tc_max"]) for t in v["tasks"]] for v in results["variants"])
    assert paper == checked

    home = Path(__file__).resolve().parents[1] / "benchmarks" / "household" / "world.yaml"
    tasks = tmp_path / "home" / "tasks.yaml"
    tasks.parent.mkdir()
    tasks.write_text(f"domain: household\nworld: {home}\ntasks:\n  - id: h-1\n    category: compound\n"
                     "    team: homogeneous\n    command: \"Put the apple and the tomato in the fridge.\"\n"
                     "    goal: {in: {fridge: [apple, tomato]}, state: {fridge: [closed]}}\n")
    results = run_bench(BenchConfig(tasks_file=tasks, seeds=1, jobs=1, out=tmp_path / "h", use_cache=False,
                                    matrix={"workflow": ["pip-llm", "pip-llm-checked"]}), progress=False)
    assert results["config"]["workflows"] == {"workflow=pip-llm": "household",
                                              "workflow=pip-llm-checked": "household-checked"}
    rows = json.loads((tmp_path / "h" / "runs.json").read_text())
    assert sorted((r["loop"], r["success"]) for r in rows) == [("checked", True), ("pip-llm", True)]


def test_cli_bench_prints_the_table(tmp_path):
    out = tmp_path / "cli"
    proc = subprocess.run([sys.executable, "-m", "pipflow.engine.cli", "bench", str(TASKS), "--seeds", "1",
                           "--jobs", "2", "--out", str(out), "--no-cache", "-q"],
                          capture_output=True, text=True, timeout=180, env={**os.environ, "PIPFLOW_MODEL": "offline"})
    assert proc.returncode == 0, proc.stderr
    assert "| t-move | 100 |" in proc.stdout
    assert json.loads((out / "results.json").read_text())["summary"]["runs"] == 3


def test_cli_rejects_bad_backend_and_resume_without_out(tmp_path):
    with pytest.raises(UserError):
        parse_backend("spark")
    with pytest.raises(UserError):
        parse_backend("local=tcp://x:1")
    assert parse_backend("dask=tcp://10.0.0.1:8786") == ("dask", "tcp://10.0.0.1:8786")
    assert parse_backend("dask") == ("dask", None)
    assert parse_limits("openai=4,2") == {"openai": 4, "default": 2}
    with pytest.raises(UserError):
        parse_limits("openai=0")
    proc = subprocess.run([sys.executable, "-m", "pipflow.engine.cli", "bench", str(TASKS), "--resume"],
                          capture_output=True, text=True, timeout=120, cwd=tmp_path)
    assert proc.returncode == 2 and "--resume needs --out" in proc.stderr


# --- `--backend` (issue 14: "executor" names only the engine's), `--executor` its deprecated alias ----

DEPRECATED = "--executor is deprecated, use --backend"


def test_backend_flag_and_its_deprecated_executor_alias(tmp_path):
    import argparse

    from pipflow.experiments.benchmarking import chosen_backend

    proc = subprocess.run([sys.executable, "-m", "pipflow.engine.cli", "bench", "--help"],
                          capture_output=True, text=True, timeout=120)
    assert proc.returncode == 0 and "--backend local|dask[=ADDRESS]" in proc.stdout
    assert "--executor" not in proc.stdout  # the alias is hidden from help
    proc = cli_bench(tmp_path, "--out", str(tmp_path / "new"), "--backend", "local")
    assert proc.returncode == 0, proc.stderr
    assert DEPRECATED not in proc.stderr
    assert json.loads((tmp_path / "new" / "results.json").read_text())["config"]["backend"] == "local"
    proc = cli_bench(tmp_path, "--out", str(tmp_path / "old"), "--executor", "local")  # a script of before
    assert proc.returncode == 0, proc.stderr
    assert [line for line in proc.stderr.splitlines() if DEPRECATED in line] == [
        "pipflow bench: --executor is deprecated, use --backend (same values: local|dask[=ADDRESS])"]
    config = json.loads((tmp_path / "old" / "results.json").read_text())["config"]
    assert config["backend"] == "local" and "executor" not in config
    # a typo names the flag; the alias and the flag naming two backends is refused, not last-wins
    for args, said in ((["--backend", "spark"], "--backend 'spark': expected local, dask or dask=ADDRESS"),
                       (["--executor", "spark"], "--backend 'spark'"),
                       (["--backend", "local", "--executor", "dask"], "name two backends; give --backend only")):
        proc = cli_bench(tmp_path, "--out", str(tmp_path / "bad"), *args)
        assert proc.returncode == 2 and said in proc.stderr and "Traceback" not in proc.stderr, (args, proc.stderr)
    assert not (tmp_path / "bad").exists()
    ns = argparse.Namespace
    assert chosen_backend(ns(backend=None, executor=None)) == "local"
    assert chosen_backend(ns(backend="dask=tcp://h:1", executor=None)) == "dask=tcp://h:1"
    assert chosen_backend(ns(backend=None, executor="dask")) == "dask"
    assert chosen_backend(ns(backend="DASK", executor="dask")) == "DASK"  # the same backend twice


def test_resume_of_a_bench_made_before_the_rename(local_bench, tmp_path):
    """A bench folder written when the flag was ``--executor``: results.json says
    ``config.executor``. Its rows are resumed (they are keyed and fingerprinted by what defines a
    run, never by the backend), by a script that still says ``--executor`` as by one that says
    ``--backend``, and the rewritten results.json says ``backend``."""
    import shutil

    src, _ = local_bench
    out = tmp_path / "before"
    shutil.copytree(src, out)
    results = json.loads((out / "results.json").read_text())
    results["config"] = {("executor" if k == "backend" else k): v for k, v in results["config"].items()}
    (out / "results.json").write_text(json.dumps(results))
    for flag in ("--executor", "--backend"):
        proc = subprocess.run([sys.executable, "-m", "pipflow.engine.cli", "bench", str(TASKS), "--seeds", "2",
                               "--jobs", "1", "--no-cache", "-q", "--out", str(out), "--resume", flag, "local"],
                              capture_output=True, text=True, timeout=240, cwd=tmp_path,
                              env={**os.environ, "PIPFLOW_MODEL": "offline"})
        assert proc.returncode == 0, proc.stderr
        again = json.loads((out / "results.json").read_text())
        assert again["resumed_runs"] == 6 and again["executed_runs"] == 0, flag
        assert again["config"]["backend"] == "local" and "executor" not in again["config"]
        assert again["summary"] == pytest.approx(results["summary"])


# --- a bench that cannot run is an error of the bench (issue 13, defects 2, 3, 5) ------------

def cli_bench(tmp_path: Path, *args: str) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "pipflow.engine.cli", "bench", str(TASKS), "--seeds", "1",
                           "--jobs", "1", "--no-cache", "-q", *args], capture_output=True, text=True,
                          timeout=240, cwd=tmp_path, env={**os.environ, "PIPFLOW_MODEL": "offline"})


def test_a_matrix_value_of_the_wrong_type_stops_the_bench_before_any_run(tmp_path):
    out = tmp_path / "abc"
    proc = cli_bench(tmp_path, "--out", str(out), "--matrix", "rounds=2,abc")
    assert proc.returncode == 2, proc.stderr
    assert "rounds=abc" in proc.stderr and "'rounds'" in proc.stderr and "nothing was run" in proc.stderr
    assert "Traceback" not in proc.stderr
    assert not (out / "runs").exists() and not (out / "results.json").exists()


def test_an_invalid_workflow_variant_stops_the_bench_before_any_run(tmp_path):
    bad = tmp_path / "broken.yaml"
    bad.write_text("pipflow: 1\nname: broken\nsteps:\n  - id: a\n    uses: no.such.step\n")
    out = tmp_path / "wf"
    with pytest.raises(UserError, match=r"(?s)variant 'workflow=broken', nothing was run: .*no\.such\.step"):
        run_bench(config(out, seeds=1, matrix={"workflow": ["warehouse", str(bad)]}), progress=False)
    assert not (out / "runs").exists()
    proc = cli_bench(tmp_path, "--out", str(out), "--workflow", str(bad))
    assert proc.returncode == 2 and "no.such.step" in proc.stderr and "Traceback" not in proc.stderr


def test_an_unknown_planner_is_a_user_error_naming_the_planners_never_a_substitute(tmp_path):
    out = tmp_path / "planner"
    proc = cli_bench(tmp_path, "--out", str(out), "-i", "planner=nosuch")
    assert proc.returncode == 2, proc.stderr
    assert "unknown planner 'nosuch'" in proc.stderr and "enhsp" in proc.stderr and "pipflow-transport" in proc.stderr
    assert "Traceback" not in proc.stderr
    assert not list((out / "runs").rglob("*.json")) if (out / "runs").exists() else True
    assert not (out / "results.json").exists()


def test_resume_with_another_configuration_is_refused_saying_what_differs(local_bench, tmp_path):
    import shutil

    src, _ = local_bench
    out = tmp_path / "b"
    shutil.copytree(src, out)
    with pytest.raises(UserError, match=r"input planner: '\(unset\)' -> 'enhsp'"):
        run_bench(config(out, resume=True, inputs={"planner": "enhsp"}), progress=False)
    # another world file under the same task file: the file's content differs
    tasks = tmp_path / "tasks" / "tasks.yaml"
    shutil.copytree(FIXTURE, tasks.parent)
    moved = tmp_path / "m"
    run_bench(BenchConfig(tasks_file=tasks, seeds=1, jobs=1, out=moved, use_cache=False), progress=False)
    world = tasks.parent / "world.yaml"
    world.write_text(world.read_text() + "\n# edited\n")
    with pytest.raises(UserError, match=r"changed file\(s\): .*world\.yaml"):
        run_bench(BenchConfig(tasks_file=tasks, seeds=1, jobs=1, out=moved, use_cache=False, resume=True),
                  progress=False)
    # a row of an older pipflow (no fingerprint) is not silently reused either
    row = json.loads(row_path(out, ("default", "t-move", 0)).read_text())
    row.pop("fingerprint"), row.pop("config_hash")
    row_path(out, ("default", "t-move", 0)).write_text(json.dumps(row))
    with pytest.raises(UserError, match="no fingerprint"):
        run_bench(config(out, resume=True), progress=False)


def test_bench_refuses_zero_seeds_and_jobs(tmp_path):
    for args in (["--seeds", "0"], ["--jobs", "0"], ["--jobs", "-5"]):
        proc = cli_bench(tmp_path, "--out", str(tmp_path / "z"), *args)
        assert proc.returncode == 2 and args[0] in proc.stderr and "Traceback" not in proc.stderr


# --- understanding (issue 12, item 9) ---------------------------------------------------------

def test_results_report_understanding_per_task_and_in_the_summary(local_bench):
    out, results = local_bench
    assert results["summary"]["understood"] == 1.0 and results["summary"]["misread"] == 0
    for t in results["tasks"]:
        assert t["understood"] == 1.0 and t["misread"] == 0
    table = (out / "table.md").read_text()
    assert "| Task | SR (%) | understood (%) | misread (executed) |" in table and "| t-too-many | 100 | 100 | 0 (0) |" in table


def test_a_run_that_executes_another_goal_than_the_gold_is_misread(tmp_path):
    import shutil

    folder = tmp_path / "gold"
    shutil.copytree(FIXTURE, folder)
    (folder / "tasks.yaml").write_text(
        "world: world.yaml\ntasks:\n"
        "  - {id: right, construction: set, command: 'There should be 4 product1 in shelf2.', goal: {shelf2: {product1: 4}}}\n"
        "  - {id: wrong-gold, construction: set, command: 'There should be 4 product1 in shelf2.', goal: {shelf2: {product1: 3}}}\n")
    results = run_bench(BenchConfig(tasks_file=folder / "tasks.yaml", seeds=1, jobs=1, out=tmp_path / "o",
                                    use_cache=False), progress=False)
    tasks = {t["id"]: t for t in results["tasks"]}
    assert tasks["right"]["understood"] == 1.0 and tasks["right"]["misread"] == 0
    assert tasks["wrong-gold"]["understood"] == 0.0 and tasks["wrong-gold"]["misread"] == 1
    assert tasks["wrong-gold"]["misread_executed"] == 1  # robots moved with the other meaning
    assert results["summary"]["understood"] == 0.5 and results["summary"]["misread"] == 1
    assert results["constructions"] == {"set": {"runs": 2, "understood": 0.5, "misread": 1, "misread_executed": 1}}
    row = read_row(tmp_path / "o", ("default", "wrong-gold", 0))
    assert "shelf2 product1: the gold allows 3, the run's goal 4" in row["understanding"]


def test_understanding_compares_bounds_as_ranges_and_rules_as_sets():
    understand = WarehouseDomain().understand  # meanings compared as written: no world

    task = {"goal": {"s1": {"p1": 3, "p2": {"at_least": 2}}},
            "constraints": [{"never": ["r1", "r0"], "product": "p1"}, {"only": ["r2"]}]}
    outputs = {"goal": {"s1": {"p1": {"at_least": 3, "at_most": 3}, "p2": {"at_least": 2}}, "s9": {}},
               "constraints": [{"only": ["r2"], "words": "only r2"}, {"never": ["r0", "r1"], "product": "p1"}]}
    assert understand(task, outputs, "succeeded", None) == {
        "understood": True, "misread": False, "understanding": "goal and rules mean what the gold means"}
    looser = {**outputs, "goal": {"s1": {"p1": 3, "p2": {"at_least": 1}}}}
    verdict = understand(task, looser, "succeeded", None)
    assert verdict["understood"] is False and verdict["misread"] is True
    assert "s1 p2: gold at least 2, run at least 1" in verdict["understanding"]
    dropped = {**outputs, "constraints": [{"only": ["r2"]}]}
    verdict = understand(task, dropped, "failed", "AllocationError")  # another meaning, failed later: misread
    assert verdict["understood"] is False and verdict["misread"] is True and "missing" in verdict["understanding"]
    assert understand(task, {}, "refused", "Refusal", None)["understood"] is False  # a feasible task refused
    assert understand(task, {"plan": []}, "succeeded", None)["understood"] is None  # a workflow without `goal`
    infeasible, ambiguous = {"feasible": False, "goal": {"s1": {"p1": 99}}}, {"expect": "refuse", "goal": {}}
    assert understand(infeasible, {}, "refused", "Refusal", None)["understood"] is True
    assert understand(ambiguous, {}, "failed", "TranslationError", None)["understood"] is True
    for spec in (infeasible, ambiguous):
        executed = understand(spec, {"goal": {"s1": {"p1": 1}}}, "succeeded", None)
        assert executed["understood"] is False and executed["misread"] is True


def test_matrix_variants_with_one_name_are_refused():
    from pipflow.experiments.benchmarking import variants

    with pytest.raises(UserError, match="both be named 'workflow=warehouse'"):
        variants({"workflow": ["a/warehouse.yaml", "b/warehouse.yaml"]})
    with pytest.raises(UserError, match="both be named 'rounds=2'"):
        variants({"rounds": ["2", "2"]})
    assert [n for n, _ in variants({"rounds": ["1", "2"]})] == ["rounds=1", "rounds=2"]


def test_an_out_folder_that_cannot_be_written_is_exit_2(tmp_path):
    blocker = tmp_path / "a-file"
    blocker.write_text("mine")
    for out in (blocker, blocker / "sub"):
        proc = cli_bench(tmp_path, "--out", str(out))
        assert proc.returncode == 2 and "cannot write the bench folder" in proc.stderr, proc.stderr
        assert "Traceback" not in proc.stderr
    assert blocker.read_text() == "mine"
    proc = cli_bench(tmp_path, "--out", str(tmp_path / "x"), "--matrix", "=1,2")
    assert proc.returncode == 2 and "no input name" in proc.stderr


def test_the_goal_of_a_run_that_did_not_finish_is_read_from_its_record(local_bench, tmp_path):
    import shutil

    from pipflow.experiments.benchmarking import recorded_outputs

    out, _ = local_bench
    row = read_row(out, ("default", "t-two", 0))
    record = tmp_path / "record"
    shutil.copytree(row["run_dir"], record)
    finished = json.loads((record / "outputs.json").read_text())
    assert recorded_outputs(record, ("goal", "constraints")) == {"goal": finished["goal"],
                                                                 "constraints": finished["constraints"]}
    for later in ("graph", "allocate", "schedule", "simulate"):  # as if it failed after the loop
        shutil.rmtree(record / "steps" / later, ignore_errors=True)
    (record / "outputs.json").unlink()
    assert recorded_outputs(record, ("goal",)) == {"goal": {"shelf1": {"product2": 5}, "shelf2": {"product2": 0}}}
    shutil.rmtree(record / "steps" / "verify")
    assert recorded_outputs(record, ("goal",)) == {}
    assert recorded_outputs(tmp_path / "nowhere", ("goal",)) == {}


def _paper_bench(tmp_path: Path, *tasks: str) -> tuple[dict, dict]:
    """A one-seed bench of tasks (YAML flow mappings) in the paper's world: the results and the
    task rows by id."""
    world = Path(__file__).resolve().parents[1] / "benchmarks" / "warehouse" / "world.yaml"
    path = tmp_path / "tasks.yaml"
    path.write_text(f"world: {world}\ntasks:\n" + "".join(f"  - {t}\n" for t in tasks))
    results = run_bench(BenchConfig(tasks_file=path, seeds=1, jobs=1, out=tmp_path / "out", use_cache=False),
                        progress=False)
    return results, {t["id"]: t for t in results["tasks"]}


def test_a_refusal_to_guess_is_a_success_where_the_task_expects_one(tmp_path):
    """``expect: refuse`` marks a command a correct system refuses to guess at: its refusal
    (a TranslationError quoting the words) scores SR 1 and understood 1; executing a guess
    would score 0."""
    results, by_id = _paper_bench(tmp_path,
                                  "{id: vague, command: 'put some product1 on shelf2', goal: {}, expect: refuse}",
                                  "{id: clear, command: 'put 3 product4 on shelf1', goal: {shelf1: {product4: 3}},"
                                  " expect: refuse}")
    assert by_id["vague"]["sr"] == 1.0 and by_id["vague"]["understood"] == 1.0
    assert by_id["clear"]["sr"] == 0.0  # it ran: not the refusal the task asks for


def test_a_reading_asked_as_a_choice_is_a_refusal_to_guess_and_its_offers_count(tmp_path):
    """A refusal that asks which reading is meant (a ``Choice``, a subclass of
    TranslationError) is the reader refusing to guess: where the task expects a refusal it is
    understood and a success (it had been scored "not refused"), and where the command is clear
    its offered readings count in ``candidate_recall`` (they had been left out)."""
    results, by_id = _paper_bench(tmp_path,
                                  "{id: shared, command: 'shelf1 and shelf2 should have 6 product4 in total',"
                                  " goal: {}, expect: refuse}",
                                  "{id: each, command: 'Move 2 product1 from shelf1 and shelf2 to shelf3',"
                                  " goal: {shelf1: {product1: 8}, shelf2: {product1: 6}, shelf3: {product1: 9}}}")
    assert by_id["shared"]["understood"] == 1.0 and by_id["shared"]["sr"] == 1.0
    assert by_id["each"]["understood"] == 0.0 and by_id["each"]["misread"] == 0
    assert results["summary"]["candidate_recall"] == 1.0

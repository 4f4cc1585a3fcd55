"""Defects a new researcher met (issue 25), each through the CLI or the API: a planner fallback
that is visible (and an error where a bench names the planner), ``validate`` checking step
arguments against ``Choices`` (built-in and plugin steps), ``pipflow.bench`` writing a fresh
folder per call, ``extends:`` a built-in workflow's name, a copied built-in workflow's defaults
saying what to do, and bench progress when the output is not a terminal."""
from __future__ import annotations

import json
import os
import re
import shutil
import subprocess
from pathlib import Path

import pytest
import yaml

import pipflow
from pipflow.errors import UserError
from test_engine_plugin import pipflow as pipflow_with_plugin
from cli_entry import PIPFLOW

REPO = Path(__file__).resolve().parents[1]


def cli(*args: str, cwd: Path, check: bool = True) -> subprocess.CompletedProcess:
    env = {**os.environ, "PIPFLOW_CACHE_DIR": str(cwd / "cache")}
    out = subprocess.run([PIPFLOW, *args], cwd=cwd, capture_output=True, text=True, timeout=1800, env=env)
    if check:
        assert out.returncode == 0, out.stderr[-3000:]
    return out


def one_task(folder: Path, ids: tuple[str, ...] = ("wh-01",)) -> Path:
    doc = yaml.safe_load((REPO / "benchmarks/warehouse/tasks.yaml").read_text())
    doc["tasks"] = [t for t in doc["tasks"] if t["id"] in ids]
    doc["world"] = str(REPO / "benchmarks/warehouse/world.yaml")
    path = folder / "tasks.yaml"
    path.write_text(yaml.safe_dump(doc))
    return path


# ------------------------------------------------------------------ planner fallback

def test_a_planner_fallback_is_said_in_the_run_summary(tmp_path):
    out = cli("run", "warehouse", "-i", "planner=fast-downward", cwd=tmp_path)
    assert "planner: \"fast-downward\"" in out.stdout and "engine: \"enhsp\"" in out.stdout
    assert "planner_fallback: \"the planner fast-downward could not answer" in out.stdout
    warning = [line for line in out.stderr.splitlines() if line.startswith("warning: step solve")]
    assert warning and "fast-downward could not answer" in warning[-1] and "enhsp answered instead" in warning[-1]
    quiet = cli("run", "warehouse", "-q", "-i", "planner=fast-downward", cwd=tmp_path)
    assert "fast-downward could not answer" in quiet.stderr  # -q still says it


def test_a_bench_that_names_a_planner_does_not_count_another_planners_plan(tmp_path):
    tasks = one_task(tmp_path)
    out = cli("bench", str(tasks), "--out", "b", "--jobs", "1", "--matrix", "planner=enhsp,fast-downward", cwd=tmp_path)
    rows = {r["variant"]: r for r in json.loads((tmp_path / "b" / "runs.json").read_text())}
    ok, asked = rows["planner=enhsp"], rows["planner=fast-downward"]
    assert ok["engine"] == "enhsp" and ok["fallback"] is None and ok["success"] is True
    assert asked["planner"] == "fast-downward" and asked["engine"] == "enhsp" and asked["fallback"]
    assert asked["success"] is False and asked["error_kind"] == "PlannerFallback"
    assert "the planner fast-downward that this bench asks for could not run the problem" in asked["error"]
    assert "FELL BACK in 1 run(s) (1 counted as failed" in out.stdout
    assert "planner (planner=enhsp): enhsp answered 1 run(s)" in (tmp_path / "b" / "table.md").read_text()
    csv_head = (tmp_path / "b" / "runs.csv").read_text().splitlines()[0].split(",")
    assert {"planner", "engine", "fallback"} <= set(csv_head)
    html = Path(cli("report", "b", cwd=tmp_path).stdout.strip()).read_text()
    assert ">planner fell back</th>" in html and "<span class='bad'>1</span>" in html


# ------------------------------------------------------------------ validate: Choices

def test_validate_checks_arguments_against_their_choices(tmp_path):
    wf = tmp_path / "wide.yaml"
    wf.write_text("pipflow: 1\nname: wide\nextends: warehouse\ninputs:\n"
                  "  spread: {type: string, default: everything}\n"
                  "steps:\n  - id: allocate\n    with: {mode: everything}\n"
                  "  - id: graph\n    with: {mode: \"${inputs.spread}\"}\n")
    out = cli("validate", str(wf), cwd=tmp_path, check=False)
    assert out.returncode == 2, out.stdout
    assert re.search(r"wide\.yaml:8:\d+: step 'allocate': argument 'mode': 'everything' is not one of "
                     r"'subtask', 'frontier'", out.stderr), out.stderr
    assert "step 'graph': argument 'mode': 'everything' (the default of input 'spread') is not one of" in out.stderr
    ran = cli("run", str(wf), cwd=tmp_path, check=False)
    assert ran.returncode == 2 and not (tmp_path / "runs").exists()  # nothing ran, not a failure after the loop
    # a value given for a run is checked the same way before anything runs
    ok = tmp_path / "ok.yaml"
    ok.write_text("pipflow: 1\nname: ok\nextends: warehouse\ninputs:\n  spread: {type: string, default: exact}\n"
                  "steps:\n  - id: graph\n    with: {mode: \"${inputs.spread}\"}\n")
    assert cli("validate", str(ok), cwd=tmp_path).returncode == 0
    given = cli("run", str(ok), "-i", "spread=everything", cwd=tmp_path, check=False)
    assert given.returncode == 2 and "input 'spread' (used by step 'graph')" in given.stderr
    assert "'everything' (the given value of input 'spread') is not one of 'deorder', 'exact', 'paper'" in given.stderr


def test_validate_checks_a_plugins_choices(demo_plugin_site, tmp_path):
    wf = tmp_path / "pick.yaml"
    wf.write_text("pipflow: 1\nname: pick\nsteps:\n  - id: say\n    uses: demo.pick\n"
                  "    with: {text: hi, style: shouty}\n")
    out = pipflow_with_plugin(demo_plugin_site, tmp_path, "validate", str(wf))
    assert out.returncode == 2
    assert "pick.yaml:6:29: step 'say': argument 'style': 'shouty' is not one of 'plain', 'spaced'" in out.stderr
    wf.write_text(wf.read_text().replace("shouty", "spaced"))
    assert pipflow_with_plugin(demo_plugin_site, tmp_path, "validate", str(wf)).returncode == 0


# ------------------------------------------------------------------ pipflow.bench's folder

def test_each_api_bench_writes_a_folder_of_its_own(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("PIPFLOW_CACHE_DIR", str(tmp_path / "cache"))
    tasks = one_task(tmp_path)
    first = pipflow.bench(tasks)
    second = pipflow.bench(tasks, graph_mode="paper")
    assert first["out"] != second["out"]
    for results in (first, second):
        stored = json.loads((Path(results["out"]) / "results.json").read_text())
        assert stored["config"]["inputs"] == results["config"]["inputs"]
        assert len(list((Path(results["out"]) / "records").iterdir())) == 1  # its own run only
    assert json.loads((Path(second["out"]) / "results.json").read_text())["config"]["inputs"] == {"graph_mode": "paper"}
    mine = tmp_path / "notes"
    mine.mkdir()
    (mine / "thesis.tex").write_text("mine")
    with pytest.raises(UserError, match="holds files that are not a bench's"):
        pipflow.bench(tasks, out=mine)
    assert sorted(p.name for p in mine.iterdir()) == ["thesis.tex"]
    again = pipflow.bench(tasks, out=first["out"])  # a bench's own folder: its rows are replaced
    assert again["out"] == first["out"]


# ------------------------------------------------------------------ built-in names and copies

def test_extends_names_a_built_in_workflow(tmp_path):
    wf = tmp_path / "mine.yaml"
    wf.write_text("pipflow: 1\nname: mine\nextends: warehouse\ninputs:\n  graph_mode: {type: string, default: paper}\n")
    assert cli("validate", str(wf), cwd=tmp_path).stdout.strip().endswith(": ok")
    out = cli("run", str(wf), "-i", "command=shelf2 holds 9 product1", cwd=tmp_path)
    assert "goal_met: true" in out.stdout
    run = next((tmp_path / "runs").iterdir())
    assert json.loads((run / "run.json").read_text())["inputs"]["graph_mode"] == "paper"
    bad = tmp_path / "typo.yaml"
    bad.write_text("pipflow: 1\nname: typo\nextends: warehous\n")
    out = cli("validate", str(bad), cwd=tmp_path, check=False)
    assert out.returncode == 2 and "no built-in workflow of that name (built-in: " in out.stderr
    assert " warehouse," in out.stderr.split("(built-in: ")[1]


def test_a_copied_built_in_workflow_says_what_to_do(tmp_path):
    (tmp_path / "flows").mkdir()
    copy = tmp_path / "flows" / "warehouse.yaml"
    shutil.copy(REPO / "workflows" / "warehouse.yaml", copy)
    world = (REPO / "benchmarks" / "warehouse" / "world.yaml").resolve()
    for command in (["validate", str(copy)], ["run", str(copy)]):
        out = cli(*command, cwd=tmp_path, check=False)
        assert out.returncode == 2 and "Traceback" not in out.stderr
        assert "default of input 'world': '../benchmarks/warehouse/world.yaml' names" in out.stderr
        assert f"-i world={world}" in out.stderr and "write `extends: warehouse` instead of a copy" in out.stderr
    named = cli("run", str(copy), "-q", "-i", f"world={world}", "-i", f"domain={REPO / 'domains/warehouse.pddl'}",
                "-i", f"actions={REPO / 'domains/warehouse.actions.yaml'}", cwd=tmp_path)
    assert "run succeeded" in named.stderr


# ------------------------------------------------------------------ bench progress

def test_bench_progress_when_the_output_is_not_a_terminal(tmp_path):
    tasks = one_task(tmp_path, ("wh-01", "wh-02"))
    out = cli("bench", str(tasks), "--out", "p", "--jobs", "1", cwd=tmp_path)  # stderr is a pipe
    lines = [line for line in out.stderr.splitlines() if line.startswith("bench (local): ")]
    assert lines[0].startswith("bench (local): 0/2 runs (0%)")
    assert re.match(r"bench \(local\): 1/2 runs \(50%\), \S+ elapsed, [\d.]+ runs/(min|s), about \S+ left$", lines[1])
    assert lines[-1].startswith("bench (local): 2/2 runs (100%)")


@pytest.mark.skipif(shutil.which("script") is None, reason="needs util-linux `script` for a terminal")
def test_bench_bar_on_a_terminal_shows_the_time_left(tmp_path):
    tasks = one_task(tmp_path, ("wh-01", "wh-02"))
    env = {**os.environ, "PIPFLOW_CACHE_DIR": str(tmp_path / "cache")}
    out = subprocess.run(["script", "-qec", f"{PIPFLOW} bench {tasks} --out t --jobs 1", "/dev/null"], cwd=tmp_path,
                         capture_output=True, text=True, timeout=1800, env=env)
    assert out.returncode == 0, out.stdout[-2000:]
    screen = re.sub(r"\x1b\[[0-9;]*[A-Za-z]", "", out.stdout).replace("\r", "\n")
    assert re.search(r"2/2 \S+ left \d+:\d\d:\d\d", screen), screen[-1500:]
    assert "runs (50%)" not in screen  # on a terminal the bar, not the lines

"""An external step plugin, installed from its own pyproject.toml into a private folder, is
found through the `pipflow.steps` entry point by the `pipflow` command in a fresh process; a
demo workflow with a loop, a condition and the plugin's step runs and leaves a complete record."""
from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

WORKFLOWS = Path(__file__).resolve().parent / "fixtures" / "workflows"
DEMO = WORKFLOWS / "demo_plugin.yaml"


def pipflow(site: Path, cwd: Path, *args: str) -> subprocess.CompletedProcess:
    exe = shutil.which("pipflow")
    cmd = [exe] if exe else [sys.executable, "-m", "pipflow.engine.cli"]
    env = {**os.environ, "PYTHONPATH": os.pathsep.join([str(site), os.environ.get("PYTHONPATH", "")]).rstrip(os.pathsep),
           "PIPFLOW_CACHE_DIR": str(cwd / "cache")}
    return subprocess.run([*cmd, *args], cwd=cwd, env=env, capture_output=True, text=True, timeout=120)


def test_plugin_package_declares_no_pipflow_dependency():
    text = (Path(__file__).resolve().parent / "fixtures" / "plugin_pkg" / "pyproject.toml").read_text()
    deps = text.split("dependencies =", 1)[1].split("]", 1)[0]
    assert "pipflow" not in deps, "pip must never fetch the unrelated `pipflow` from PyPI"


def test_demo_workflow_with_plugin_step_in_a_fresh_process(demo_plugin_site, tmp_path):
    proc = pipflow(demo_plugin_site, tmp_path, "run", str(DEMO), "--runs-dir", "runs")
    assert proc.returncode == 0, proc.stderr
    assert "HELLO!!!! after 3 rounds" in proc.stdout  # the outputs are printed
    outputs = {"text": "HELLO!!!!", "rounds": 3, "quiet": None, "announced": "HELLO!!!! after 3 rounds"}

    (run,) = (tmp_path / "runs").iterdir()
    info = json.loads((run / "run.json").read_text())
    assert info["status"] == "succeeded" and info["error"] is None and info["finished"]
    assert info["inputs"] == {"text": "hello", "rounds": 3, "loud": True}
    for name in ("workflow.yaml", "inputs.json", "events.jsonl", "outputs.json", "metrics.json"):
        assert (run / name).is_file(), name
    assert json.loads((run / "outputs.json").read_text()) == outputs
    # per-step outputs and the plugin step's artifacts, per loop iteration too
    assert json.loads((run / "steps" / "first" / "outputs.json").read_text()) == {"text": "HELLO!"}
    assert (run / "steps" / "first" / "artifacts" / "shout.txt").read_text() == "HELLO"
    for n, text in ((1, "HELLO!!"), (2, "HELLO!!!"), (3, "HELLO!!!!")):
        step_dir = run / "steps" / "refine" / "iterations" / str(n) / "louder"
        assert json.loads((step_dir / "outputs.json").read_text()) == {"text": text}
        assert (step_dir / "artifacts" / "shout.txt").is_file()
    events = [json.loads(line) for line in (run / "events.jsonl").read_text().splitlines()]
    kinds = {(e["event"], e.get("step")) for e in events}
    assert ("skip", "quiet") in kinds and ("end", "announce") in kinds
    assert sum(1 for e in events if e["event"] == "end" and e.get("step") == "louder") == 3
    assert all("duration" in e and e["status"] for e in events if e["event"] == "end")
    metrics = json.loads((run / "metrics.json").read_text())
    assert set(metrics["step_seconds"]) >= {"first", "refine", "louder", "announce"}


def test_plugin_steps_are_listed_and_validated(demo_plugin_site, tmp_path):
    proc = pipflow(demo_plugin_site, tmp_path, "steps", "demo.shout")
    assert proc.returncode == 0, proc.stderr
    assert "pipflow-demo-plugin:demo" in proc.stdout and "text" in proc.stdout
    proc = pipflow(demo_plugin_site, tmp_path, "validate", str(DEMO))
    assert proc.returncode == 0, proc.stderr


def test_without_the_plugin_its_steps_are_unknown(tmp_path):
    proc = pipflow(Path(tmp_path / "empty"), tmp_path, "run", str(DEMO), "--runs-dir", "runs")
    assert proc.returncode == 2
    assert "demo_plugin.yaml:10:11: step 'first': unknown step 'demo.shout'" in proc.stderr
    assert not (tmp_path / "runs").exists()


def test_condition_flips_with_an_input(demo_plugin_site, tmp_path):
    proc = pipflow(demo_plugin_site, tmp_path, "run", "-q", str(DEMO), "-i", "loud=false", "-i", "rounds=1",
                   "--runs-dir", "runs")
    assert proc.returncode == 0, proc.stderr
    (run,) = (tmp_path / "runs").iterdir()
    outputs = json.loads((run / "outputs.json").read_text())
    assert outputs == {"text": "HELLO!!", "rounds": 1, "quiet": "HELLO!!", "announced": None}

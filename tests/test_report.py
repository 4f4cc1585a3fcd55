"""The HTML report, rendered by a real headless Chromium (Debian package ``chromium``).

These tests fail, never skip, when Chromium is missing: the issue asks for a rendered page."""
from __future__ import annotations

import json
import os
import re
import shutil
import subprocess
import tempfile
from pathlib import Path

import numpy as np
import pytest

from pipflow.records.report import write_report
from sim_fixtures import chain, load_world, wh01

CHROMIUM_FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
                  "--disable-component-update", "--disable-sync", "--no-first-run",
                  "--allow-file-access-from-files", "--virtual-time-budget=5000"]


def chromium() -> str:
    for name in ("chromium", "chromium-browser", "google-chrome"):
        path = shutil.which(name)
        if path:
            return path
    pytest.fail("Chromium is not installed: apt-get install -y chromium (see .ci/apt-packages.txt)")


def render(page: Path, out_png: Path) -> str:
    """Screenshot the page and return its DOM after scripts ran."""
    exe = chromium()
    with tempfile.TemporaryDirectory() as profile:
        common = [exe, *CHROMIUM_FLAGS, f"--user-data-dir={profile}"]
        subprocess.run(common + [f"--screenshot={out_png}", "--window-size=1200,4000", page.resolve().as_uri()],
                       check=True, capture_output=True, timeout=120)
    with tempfile.TemporaryDirectory() as profile:
        common = [exe, *CHROMIUM_FLAGS, f"--user-data-dir={profile}"]
        dom = subprocess.run(common + ["--dump-dom", page.resolve().as_uri()], check=True,
                             capture_output=True, text=True, timeout=120).stdout
    return dom


def assert_rendered(page: Path, tmp: Path, min_images: int) -> None:
    from PIL import Image

    shot = tmp / "screenshot.png"
    dom = render(page, shot)
    body = re.search(r"<body[^>]*>", dom).group(0)
    assert 'data-images-ok="true"' in body, body
    assert int(re.search(r'data-images="(\d+)"', body).group(1)) >= min_images
    img = np.asarray(Image.open(shot).convert("RGB"), dtype=float)
    assert img.shape[1] == 1200
    assert img.std() > 10  # not blank
    assert (img.reshape(-1, 3).std(axis=1) > 30).mean() > 0.01  # some colour: the pictures drew


def write_json(path: Path, value) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(json.dumps(value))


def start_events(run: Path, uses: dict[str, str]) -> None:
    """The start event of each step as the engine writes it: the step it used and the family of
    outputs it declares (what the report finds steps by)."""
    from pipflow.engine.registry import default_registry

    registry = default_registry()
    lines = [json.dumps({"event": "start", "step": sid, "uses": name,
                         **({"shape": registry.get(name).shape} if registry.get(name).shape else {})})
             for sid, name in uses.items()]
    (run / "events.jsonl").write_text("\n".join(lines) + "\n")


def make_run_dir(root: Path) -> Path:
    """A run record as the engine writes it, with real simulate/metrics step outputs."""
    from pipflow.engine.step import StepContext
    from pipflow.warehouse.steps import score
    from pipflow.warehouse.steps import simulate_pybullet

    world = load_world()
    spec = [("s1", "shelf4", "shelf1", "product4", 6, ["robot9", "robot10"], []),
            ("s2", "shelf1", "shelf3", "product4", 6, ["robot9", "robot10"], ["s1"]),
            ("s3", "shelf1", "shelf3", "product1", 2, ["robot5"], [])]
    graph, schedule = chain(world, spec)
    goal = {"shelf3": {"product4": 10, "product1": 7}}
    run = root / "run1"
    write_json(run / "run.json", {"status": "succeeded", "workflow": "warehouse.yaml"})
    write_json(run / "inputs.json", {"command": "There should be 10 product4 and 7 product1 in shelf3.", "goal": goal})
    write_json(run / "steps" / "world" / "outputs.json", {"world": world})
    write_json(run / "steps" / "plan" / "outputs.json",
               {"plan": [{"action": n["action"], "args": n["args"]} for n in graph["nodes"]]})
    write_json(run / "steps" / "graph" / "outputs.json", {"graph": graph})
    write_json(run / "steps" / "schedule" / "outputs.json", {"schedule": schedule})
    ctx = StepContext("simulate", run / "steps" / "simulate" / "artifacts", run)
    sim = simulate_pybullet.func(ctx, world=world, schedule=schedule, graph=graph, goal=goal,
                                 snapshots=True, animation=False)
    write_json(run / "steps" / "simulate" / "outputs.json", sim)
    m = score.func(StepContext("metrics", run / "steps" / "metrics" / "artifacts", run), world=world, goal=goal,
                   graph=graph, schedule=schedule, simulation=sim)
    write_json(run / "steps" / "metrics" / "outputs.json", m)
    start_events(run, {"world": "world.load", "plan": "pddl.solve", "graph": "graph.dependencies",
                       "schedule": "schedule", "simulate": "simulate.pybullet", "metrics": "metrics.score"})
    return run


def test_run_report_renders_in_chromium(tmp_path):
    run = make_run_dir(tmp_path)
    page = write_report(run)
    html = page.read_text()
    for needle in ("There should be 10 product4", "(move-product shelf4 shelf1 product4 magnitude6)",
                   "report/graph.png", "report/gantt.png", "steps/simulate/artifacts/paths.png",
                   "snapshot_1_start.png", "Metrics", "TC-max"):
        assert needle in html, needle
    assert not re.search(r"<tr>(<th></th>)+</tr>", html), "a key-value table drew an empty header row"
    assert_rendered(page, tmp_path, min_images=7)


def test_bench_report_renders_in_chromium(tmp_path):
    """results.json and runs.json as `pipflow bench` writes them (with two variants)."""
    bench = tmp_path / "bench"
    run = make_run_dir(bench / "runs")
    write_report(run)
    tasks = [{"id": f"wh-{i:02d}", "runs": 3, "sr": 1.0 if i % 3 else 2 / 3, "gcr": 1.0, "exe": 1.0, "ru": 0.8,
              "tc_max": 31.0 + i, "tc_avg": 8.0 + i / 2, "makespan": 50.0,
              "error": None if i % 3 else "refused: over capacity"} for i in range(1, 4)]
    summary = {"runs": 9, "sr": 8 / 9, "gcr": 1.0, "exe": 1.0, "ru": 0.8, "tc_max": 32.0, "tc_avg": 9.0}
    runs = [{"variant": v, "task": t["id"], "seed": s, "success": bool(i % 3 or s), "tc_max": 30.0 + i + s,
             "tc_avg": 8.0 + s, "run_dir": str(run)} for v in ("default", "graph_mode=paper")
            for i, t in enumerate(tasks, 1) for s in range(3)]
    task_file = tmp_path / "tasks.yaml"
    task_file.write_text("world: w.yaml\ntasks:\n" + "".join(
        f"  - {{id: {t['id']}, command: 'put {i} product1 on shelf2', goal: {{shelf2: {{product1: {i}}}}}}}\n"
        for i, t in enumerate(tasks, 1)))
    write_json(bench / "results.json", {"summary": summary, "tasks": tasks, "wall_seconds": 12.5,
                                        "config": {"seeds": 3, "workflow": "warehouse", "tasks": str(task_file),
                                                   "matrix": {"graph_mode": ["exact", "paper"]}},
                                        "variants": [{"name": "default", "summary": summary, "tasks": tasks},
                                                     {"name": "graph_mode=paper", "summary": summary, "tasks": tasks}]})
    write_json(bench / "runs.json", runs)
    page = write_report(bench)
    html = page.read_text()
    assert "wh-03" in html and "refused: over capacity" in html and "href='runs/run1/report.html'" in html
    # variants side by side in one table, each task with its command, seeds labelled, SR as a percentage
    assert html.count("<h2 id='tasks'>Tasks</h2>") == 1
    assert "<th colspan='5'>default</th><th colspan='5'>graph_mode=paper</th>" in html
    assert "\u0394 TC-max (m) vs default" in html
    assert "put 3 product1 on shelf2" in html and ">seed 2</a>" in html and "67%" in html and "0.67" not in html
    assert "matrix: graph_mode" in html and "exact, paper" in html
    # wh-01's TC-max over its three seeds (31, 32, 33 m): mean 32, Student t 95% interval 32 -+ 4.303 * 1 / sqrt(3)
    assert "32.00 <span class='small'>[29.52, 34.48]</span>" in html
    assert_rendered(page, tmp_path, min_images=1)


def test_broken_image_is_detected(tmp_path):
    """The check itself must be able to fail: a page with a missing picture is not ok."""
    page = tmp_path / "p.html"
    from pipflow.records import htmlparts

    page.write_text(f"<html><body><img src='missing.png'>{htmlparts.CHECK_SCRIPT}</body></html>")
    dom = render(page, tmp_path / "s.png")
    assert 'data-images-ok="false"' in dom


def test_output_elsewhere_rebases_links(tmp_path):
    """Links into the record are rebased; the pictures the report draws go beside the page, and
    nothing is written into the record (it may be read-only: issue 21)."""
    run = make_run_dir(tmp_path)
    before = sorted(p.relative_to(run) for p in run.rglob("*"))
    page = write_report(run, tmp_path / "elsewhere" / "r.html")
    text = page.read_text()
    assert "src='r_files/gantt.png'" in text and "src='../run1/steps/" in text
    assert sorted(p.relative_to(run) for p in run.rglob("*")) == before
    assert_rendered(page, tmp_path, min_images=7)


def test_not_a_report_dir(tmp_path):
    from pipflow.errors import InputError

    with pytest.raises(InputError):
        write_report(tmp_path)


# ------------------------------------------------------------- every domain: the same sections
SECTIONS = ("<h2 id='plan'>Team plan</h2>", "<h2>Dependency graph</h2>", "<h2>Schedule</h2>", "<h2>Robot paths</h2>",
            "<h2>Simulation</h2>", "<h3>Goal</h3>")


def _report_of_only_run(runs: Path) -> tuple[Path, str]:
    (run,) = runs.iterdir()
    page = write_report(run)
    return page, page.read_text()


def test_household_run_report_shows_the_simulation_and_the_robot_paths(tmp_path, monkeypatch):
    """The report finds a run's steps by the families their outputs declare, in any domain: a
    household run (its own step household.simulate, final_state, no trajectories kept) shows the
    same sections as a warehouse run, the path map drawn from the schedule's legs on the home's
    floor plan, the goal's conditions as the household reads them."""
    from pipflow.api import run as run_workflow

    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("PIPFLOW_CACHE_DIR", str(tmp_path / "cache"))
    done = run_workflow("household", runs_dir=tmp_path / "runs",
                        command="Put the apple in the fridge and switch off the floor lamp.")
    assert done.ok, done.error
    page, html = _report_of_only_run(tmp_path / "runs")
    for section in SECTIONS:
        assert section in html, section
    assert "report/paths.png" in html and "apple in fridge" in html
    assert "<td>floorlamp off</td><td class='num'><span class='ok'>yes</span>" in html
    shot = tmp_path / "household.png"
    dom = render(page, shot)
    assert 'data-images-ok="true"' in re.search(r"<body[^>]*>", dom).group(0)
    shutil.copy(shot, Path(os.environ.get("PIPFLOW_REPORT_SHOTS", tmp_path)) / "household-report.png")


def test_garden_run_report_shows_the_simulation_and_the_robot_paths(garden_plugin_site, tmp_path):
    """The same sections for a domain pipflow knows only through its plugin (the generic step
    simulate, the garden's floor plan and goal conditions asked of the domain)."""
    import sys

    workflow = garden_plugin_site / "pipflow_garden" / "workflows" / "garden.yaml"
    env = {**os.environ, "PYTHONPATH": str(garden_plugin_site), "PIPFLOW_CACHE_DIR": str(tmp_path / "cache")}
    env.pop("PIPFLOW_MODEL", None)
    cli = [sys.executable, "-m", "pipflow.engine.cli"]
    proc = subprocess.run(cli + ["run", str(workflow), "-i", "command=Prune south, then bring two pumpkins from south "
                                 "into the shed.", "--runs-dir", "runs"], cwd=tmp_path, env=env, capture_output=True,
                          text=True, timeout=600)
    assert proc.returncode == 0, proc.stderr
    (run,) = (tmp_path / "runs").iterdir()
    proc = subprocess.run(cli + ["report", str(run)], cwd=tmp_path, env=env, capture_output=True, text=True, timeout=300)
    assert proc.returncode == 0, proc.stderr
    html = (run / "report.html").read_text()
    for section in SECTIONS:
        assert section in html, section
    assert "report/paths.png" in html and "shed holds 2 pumpkin" in html
    shot = tmp_path / "garden.png"
    dom = render(run / "report.html", shot)
    assert 'data-images-ok="true"' in re.search(r"<body[^>]*>", dom).group(0)
    shutil.copy(shot, Path(os.environ.get("PIPFLOW_REPORT_SHOTS", tmp_path)) / "garden-report.png")

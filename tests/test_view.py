"""`pipflow view` and `pipflow compare`: the browsable history, served on loopback and rendered by
real headless Chromium (screenshots kept with PIPFLOW_SCREENSHOTS=DIR), plus the CLI faces."""
from __future__ import annotations

import os
import shutil
import subprocess
import tempfile
import urllib.error
import urllib.request
from pathlib import Path

import numpy as np
import pytest
import yaml

import pipflow
from pipflow.records.compare import compare_text
from pipflow.records.view import ViewServer
from test_report import CHROMIUM_FLAGS, chromium
from cli_entry import PIPFLOW

REPO = Path(__file__).resolve().parents[1]


@pytest.fixture(scope="module")
def records(tmp_path_factory) -> Path:
    """A folder with three runs (two succeeded, one refused) and a two-task bench."""
    root = tmp_path_factory.mktemp("records")
    runs = root / "runs"
    pipflow.run("warehouse", runs_dir=runs, command="There should be 7 product1 in shelf3.")
    pipflow.run("warehouse", runs_dir=runs, command="shelf2 has 9 product1")
    pipflow.run("warehouse", runs_dir=runs, command="shelf1 holds 500 product1")
    doc = yaml.safe_load((REPO / "benchmarks/warehouse/tasks.yaml").read_text())
    doc["tasks"] = doc["tasks"][:2]
    doc["world"] = str(REPO / "benchmarks/warehouse/world.yaml")
    tasks = root / "tasks.yaml"
    tasks.write_text(yaml.safe_dump(doc))
    pipflow.bench(tasks, out=root / "benches" / "b1", matrix={"graph_mode": ["exact", "paper"]})
    return root


def _chromium(url: str, shot: Path) -> tuple[str, str]:
    """Screenshot a page at 1400 px wide; return (DOM after scripts, console log)."""
    with tempfile.TemporaryDirectory() as profile:
        base = [chromium(), *CHROMIUM_FLAGS, f"--user-data-dir={profile}", "--enable-logging=stderr", "--v=0"]
        shot_run = subprocess.run(base + [f"--screenshot={shot}", "--window-size=1400,1000", url],
                                  capture_output=True, text=True, timeout=120)
    with tempfile.TemporaryDirectory() as profile:
        base = [chromium(), *CHROMIUM_FLAGS, f"--user-data-dir={profile}"]
        dom = subprocess.run(base + ["--dump-dom", url], capture_output=True, text=True, timeout=120, check=True).stdout
    return dom, shot_run.stderr


def _keep(shot: Path, name: str) -> None:
    keep = os.environ.get("PIPFLOW_SCREENSHOTS")
    if keep:
        Path(keep).mkdir(parents=True, exist_ok=True)
        shutil.copy(shot, Path(keep) / name)


def _looks_rendered(shot: Path) -> None:
    from PIL import Image

    img = np.asarray(Image.open(shot).convert("RGB"), dtype=float)
    assert img.shape[1] == 1400 and img.std() > 10


def test_index_lists_every_record_and_filters(records, tmp_path):
    server = ViewServer(records).start()
    try:
        dom, console = _chromium(server.url, tmp_path / "index.png")
        _looks_rendered(tmp_path / "index.png")
        _keep(tmp_path / "index.png", "view_index.png")
        assert "Uncaught" not in console
        # the three runs and the bench; the bench's own four run records (2 tasks x 2 variants) are
        # reached through the bench's report, not listed one by one
        assert dom.count("href=\"/report/runs/") == 3 and dom.count("<td>bench</td>") == 1
        assert dom.count("<td>run</td>") == 3
        assert "refused" in dom and "succeeded" in dom
        refused, _ = _chromium(server.url + "?status=refused", tmp_path / "refused.png")
        assert refused.count("<td>run</td>") == 1 and "succeeded</td>" not in refused
        assert "1 of 4 shown" in refused
    finally:
        server.stop()


def test_report_is_one_click_away_and_written_on_demand(records, tmp_path):
    run = sorted((records / "runs").iterdir())[0]
    assert not (run / "report.html").exists()
    server = ViewServer(records).start()
    try:
        rel = run.relative_to(records).as_posix()
        with urllib.request.urlopen(server.url + "report/" + rel) as answer:  # follows the redirect
            page = answer.read().decode()
        assert "pipflow run:" in page and (run / "report.html").is_file()
        with pytest.raises(urllib.error.HTTPError) as err:  # nothing outside the viewed folder
            urllib.request.urlopen(server.url + "..%2f..%2fetc%2fpasswd")
        assert err.value.code == 404
    finally:
        server.stop()


def test_compare_two_runs_in_the_page_and_on_the_command_line(records, tmp_path):
    import json

    a, b = [p for p in sorted((records / "runs").iterdir())
            if json.loads((p / "run.json").read_text())["status"] == "succeeded"]
    text = compare_text(a, b)
    assert "goal" in text and "makespan (s)" in text and "(B - A)" in text
    server = ViewServer(records).start()
    try:
        url = f"{server.url}compare?a=runs/{a.name}&b=runs/{b.name}"
        dom, console = _chromium(url, tmp_path / "compare.png")
        _looks_rendered(tmp_path / "compare.png")
        _keep(tmp_path / "compare.png", "view_compare.png")
        assert "Compare 2 runs" in dom and "shelf3" in dom and "shelf2" in dom
        assert "Uncaught" not in console
    finally:
        server.stop()
    out = subprocess.run([PIPFLOW, "compare", str(a), str(b)], capture_output=True, text=True)
    assert out.returncode == 0 and "tc_max (m)" in out.stdout
    bad = subprocess.run([PIPFLOW, "compare", str(a), str(records / "benches" / "b1")], capture_output=True, text=True)
    assert bad.returncode == 2 and "cannot compare a run" in bad.stderr and "Traceback" not in bad.stderr


def test_show_latest_and_runs_filters(records):
    runs = str(records / "runs")
    latest = subprocess.run([PIPFLOW, "show", "latest", "--runs-dir", runs], capture_output=True, text=True)
    assert latest.returncode == 0 and "refused" in latest.stdout
    second = subprocess.run([PIPFLOW, "show", "-2", "--runs-dir", runs], capture_output=True, text=True)
    assert second.returncode == 0 and "status    succeeded" in second.stdout
    full = subprocess.run([PIPFLOW, "show", "-2", "--full", "--runs-dir", runs], capture_output=True, text=True)
    assert '"tc_avg"' in full.stdout and '"simulation"' in full.stdout  # --full: whole outputs, not cut
    listed = subprocess.run([PIPFLOW, "runs", "--status", "refused", "--runs-dir", runs], capture_output=True, text=True)
    assert listed.stdout.count("\n") == 1 and "refused" in listed.stdout


def test_bench_matrix_report_shows_variants_side_by_side(records, tmp_path):
    server = ViewServer(records).start()
    try:
        dom, console = _chromium(server.url + "report/benches/b1", tmp_path / "bench.png")
        _looks_rendered(tmp_path / "bench.png")
        _keep(tmp_path / "bench.png", "bench_matrix_report.png")
    finally:
        server.stop()
    assert "Uncaught" not in console
    assert ">graph_mode=exact</th>" in dom and ">graph_mode=paper</th>" in dom
    assert "There should be 7 product 1 in shelf 3." in dom  # each task's command
    assert "matrix: graph_mode" in dom and dom.count("seed 0</a>") == 4


def test_matrix_side_by_side_table_in_the_terminal(records):
    import json

    from pipflow.records.compare import variants_side_by_side

    bench = records / "benches" / "b1"
    text = variants_side_by_side(json.loads((bench / "results.json").read_text()),
                                 json.loads((bench / "runs.json").read_text()))
    lines = text.splitlines()
    assert "graph_mode=exact" in lines[1] and "graph_mode=paper" in lines[1]
    assert [ln.split()[0] for ln in lines[2:]] == ["wh-01", "wh-02", "all"]
    assert all("100%" in ln for ln in lines[2:])  # both tasks succeed under both variants


def test_the_api_names_stay_functions_after_the_bench_module_is_imported():
    """`pipflow.bench` is the API function even once the bench runner module is loaded (a
    submodule of the same name would replace it on the package)."""
    import importlib

    importlib.import_module("pipflow.experiments.benchmarking")
    importlib.import_module("pipflow.experiments.runspec")
    assert callable(pipflow.bench) and callable(pipflow.run)
    assert pipflow.bench.__module__ == "pipflow.api"

"""`pipflow mlflow-log`: runs and benches in a real local MLflow store (sqlite), read back with
MLflow's own client, and `mlflow ui` (started here on loopback) listing the bench in a real
headless Chromium. MLflow comes with the `test` extra; the records stay pipflow's own."""
from __future__ import annotations

import json
import os
import socket
import subprocess
import sys
import time
import urllib.request
from pathlib import Path

import pytest
import yaml

from cdp import Browser, looks_drawn
from cli_entry import PIPFLOW

mlflow = pytest.importorskip("mlflow", reason="the `mlflow` extra (in the `test` extra): pip install -e '.[test]'")

REPO = Path(__file__).resolve().parents[1]


def cli(*args: str, cwd: Path) -> subprocess.CompletedProcess:
    env = {**os.environ, "PIPFLOW_CACHE_DIR": str(cwd / "cache")}
    out = subprocess.run([PIPFLOW, *args], cwd=cwd, capture_output=True, text=True, timeout=1800, env=env)
    assert out.returncode == 0, out.stderr[-3000:]
    return out


@pytest.fixture(scope="module")
def logged(tmp_path_factory):
    root = tmp_path_factory.mktemp("mlflow")
    doc = yaml.safe_load((REPO / "benchmarks/warehouse/tasks.yaml").read_text())
    doc["tasks"] = [t for t in doc["tasks"] if t["id"] in ("wh-01", "wh-10")]
    doc["world"] = str(REPO / "benchmarks/warehouse/world.yaml")
    (root / "tasks.yaml").write_text(yaml.safe_dump(doc))
    cli("bench", "tasks.yaml", "--out", "matrix-bench", "--jobs", "2", "--matrix", "graph_mode=deorder,paper",
        "--matrix", "allocation_cost=total,subtask", cwd=root)
    cli("run", "warehouse", "-q", "-i", "command=shelf2 holds 9 product1", cwd=root)
    uri = f"sqlite:///{root / 'mlflow.db'}"
    out = cli("mlflow-log", "matrix-bench", "latest", "--tracking-uri", uri, "--experiment", "pipflow-test", cwd=root)
    return root, uri, out.stdout


def test_a_bench_and_a_run_are_logged_with_params_metrics_tags_and_artifacts(logged):
    root, uri, printed = logged
    assert "matrix-bench: logged as MLflow run" in printed and "with 4 variant run(s)" in printed
    client = mlflow.tracking.MlflowClient(tracking_uri=uri)
    exp = client.get_experiment_by_name("pipflow-test")
    runs = client.search_runs([exp.experiment_id], max_results=100)
    bench = [r for r in runs if r.data.tags.get("pipflow.kind") == "bench"]
    variants = [r for r in runs if r.data.tags.get("pipflow.kind") == "bench variant"]
    single = [r for r in runs if r.data.tags.get("pipflow.kind") == "run"]
    assert len(bench) == 1 and len(variants) == 4 and len(single) == 1
    parent = bench[0]
    assert parent.info.run_name == "matrix-bench"
    assert parent.data.params["matrix.graph_mode"] == '["deorder", "paper"]' and parent.data.params["seeds"] == "1"
    results = json.loads((root / "matrix-bench" / "results.json").read_text())
    for v in variants:
        assert v.data.tags["mlflow.parentRunId"] == parent.info.run_id
        name = v.data.tags["pipflow.variant"]
        assert v.data.params["graph_mode"] in ("deorder", "paper") and v.data.params["variant"] == name
        assert name == f"graph_mode={v.data.params['graph_mode']},allocation_cost={v.data.params['allocation_cost']}"
        assert v.data.tags["pipflow.workflow"] == "warehouse" and v.data.tags["pipflow.model"] == "(workflow default)"
        summary = next(x["summary"] for x in results["variants"] if x["name"] == name)
        assert v.data.metrics["sr"] == pytest.approx(summary["sr"])
        assert v.data.metrics["tc_max"] == pytest.approx(summary["tc_max"])
        assert "tc_max.wh-10" in v.data.metrics
    arts = {a.path for a in client.list_artifacts(parent.info.run_id)}
    assert {"report.html", "results.json", "runs.json", "runs.csv", "table.md", "records"} <= arts
    records = client.list_artifacts(parent.info.run_id, "records")
    assert len(records) == 4 * 2  # every run record of the bench
    run = single[0]
    assert run.data.params["command"] == "shelf2 holds 9 product1" and run.data.tags["pipflow.model"] == "offline"
    assert run.data.metrics["goal_met"] == 1.0 and run.data.metrics["makespan"] > 0
    assert "report.html" in {a.path for a in client.list_artifacts(run.info.run_id)}
    # logged once: a second export finds it
    again = cli("mlflow-log", "matrix-bench", "--tracking-uri", uri, "--experiment", "pipflow-test", cwd=root)
    assert f"already logged as MLflow run {parent.info.run_id}" in again.stdout
    assert len(client.search_runs([exp.experiment_id], max_results=100)) == 6


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def test_mlflow_ui_lists_the_bench(logged, tmp_path):
    root, uri, _ = logged
    port = _free_port()
    exe = Path(sys.executable).with_name("mlflow")
    server = subprocess.Popen([str(exe) if exe.exists() else "mlflow", "ui", "--backend-store-uri", uri,
                               "--host", "127.0.0.1", "--port", str(port), "--workers", "1"],
                              cwd=root, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, start_new_session=True)
    try:
        base = f"http://127.0.0.1:{port}"
        deadline = time.monotonic() + 240
        while True:
            try:
                urllib.request.urlopen(base + "/health", timeout=5)
                break
            except OSError:
                assert server.poll() is None, "mlflow ui ended"
                assert time.monotonic() < deadline, "mlflow ui did not answer"
                time.sleep(1)
        exp = mlflow.tracking.MlflowClient(tracking_uri=uri).get_experiment_by_name("pipflow-test")
        with Browser(1500, 1000) as b:
            b.goto(f"{base}/#/experiments/{exp.experiment_id}/runs")
            text = ""
            for _ in range(120):  # the page is a React app: it fills in after loading
                text = b.eval("document.body ? document.body.innerText : ''")
                if "matrix-bench" in text:
                    break
                b.eval("new Promise(done => setTimeout(done, 1000))")
            assert "matrix-bench" in text, text[:2000]
            looks_drawn(b.screenshot(tmp_path / "mlflow_ui_bench.png"), min_colour=0.0005)
    finally:
        for signal_number in (15, 9):  # the server and its uvicorn worker: the group this test started
            try:
                os.killpg(server.pid, signal_number)
            except ProcessLookupError:
                break
            try:
                server.wait(timeout=20)
                break
            except subprocess.TimeoutExpired:
                continue

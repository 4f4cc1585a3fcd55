"""`pipflow bench --backend dask` against a real LocalCluster of two single-threaded worker
processes: the same table as the local backend, a worker killed mid-bench, `--resume` after an
interrupted bench, runs shipped by content, and the cluster-wide LLM slots per provider.

Every cluster operation has a timeout and SIGALRM fails a test after 240 s, so nothing hangs.
"""
from __future__ import annotations

import json
import os
import shutil
import time
from pathlib import Path

import pytest

distributed = pytest.importorskip("distributed")

from conftest import interrupt_after
from pipflow.experiments.benchmarking import BenchConfig, read_row, run_bench  # noqa: E402
from pipflow.experiments.backends import build_bundle, materialize, run_key  # noqa: E402

FIXTURE = Path(__file__).resolve().parent / "fixtures" / "bench"
TASKS = FIXTURE / "tasks.yaml"
METRICS = ("sr", "gcr", "exe", "ru", "tc_max", "tc_avg")
TIMEOUT = 60


pytestmark = pytest.mark.usefixtures("no_hang")


@pytest.fixture(scope="module")
def cluster():
    from distributed import Client, LocalCluster

    lc = LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=":0",
                      silence_logs=50)
    client = Client(lc, timeout=TIMEOUT)
    client.wait_for_workers(2, timeout=TIMEOUT)
    yield lc, client
    client.close(timeout=10)
    lc.close(timeout=30)


def config(out: Path, backend: str, **kw) -> BenchConfig:
    return BenchConfig(tasks_file=TASKS, seeds=kw.pop("seeds", 2), jobs=2, out=out, use_cache=False,
                       backend=backend, **kw)


def table(results: dict) -> dict:
    return {t["id"]: tuple(None if t[k] is None else round(t[k], 6) for k in METRICS) + (t["runs"],)
            for t in results["tasks"]}


def rows_once(out: Path, n: int) -> list[dict]:
    rows = json.loads((out / "runs.json").read_text())
    assert len(rows) == n and len({run_key(r) for r in rows}) == n
    assert all(r["status"] != "lost" for r in rows)
    assert len(list((out / "runs").rglob("*.json"))) == n
    return rows


def test_bundle_holds_everything_a_run_reads(tmp_path):
    bundle = build_bundle("warehouse", {"world": str(FIXTURE / "world.yaml")})
    names = set(bundle.files)
    assert bundle.workflow in names
    for key in ("world", "domain", "actions", "prompt"):
        assert bundle.path_inputs[key] in names, key
    assert any(n.endswith("_warehouse_common.j2") for n in names), "partials of the prompt's folder"
    assert all(not n.startswith("/") and ".." not in n for n in names)
    root = materialize(bundle.files, bundle.digest)
    assert root == materialize(bundle.files, bundle.digest)  # written once per machine
    for rel, text in bundle.files.items():
        assert (root / rel).read_text() == text


def test_dask_gives_the_local_table(cluster, tmp_path):
    lc, _ = cluster
    local = run_bench(config(tmp_path / "local", "local"), progress=False)
    dask = run_bench(config(tmp_path / "dask", f"dask={lc.scheduler_address}"), progress=False)
    assert table(dask) == table(local)
    assert dask["summary"] == pytest.approx(local["summary"])
    assert dask["config"]["backend"].startswith("dask=")
    rows = rows_once(tmp_path / "dask", 6)
    workers = {r.get("worker") for r in rows}
    assert workers <= set(lc.scheduler_info["workers"]) | {None}
    # run records came back by content into OUT/records, not as paths on a worker
    for r in rows:
        assert Path(r["run_dir"]).parent == tmp_path / "dask" / "records"
        assert (Path(r["run_dir"]) / "run.json").exists()
        assert "pipflow-bundles" in json.loads((Path(r["run_dir"]) / "inputs.json").read_text())["world"]


def test_resume_after_an_interrupted_dask_bench(cluster, tmp_path):
    lc, _ = cluster
    out = tmp_path / "r"
    stop_after_two = interrupt_after(2)
    seen = stop_after_two.seen

    with pytest.raises(KeyboardInterrupt):
        run_bench(config(out, f"dask={lc.scheduler_address}"), progress=False, on_row=stop_after_two)
    stored = sorted(p.relative_to(out) for p in (out / "runs").rglob("*.json"))
    assert len(stored) >= 2
    again = []
    results = run_bench(config(out, f"dask={lc.scheduler_address}", resume=True), progress=False,
                        on_row=lambda r: again.append(run_key(r)))
    assert results["resumed_runs"] == len(stored)
    assert results["executed_runs"] == 6 - len(stored) == len(again)
    assert not set(again) & set(seen)
    assert results["summary"]["runs"] == 6 and results["summary"]["sr"] == 1.0
    rows_once(out, 6)
    # deleting row files (a lost client) reruns exactly those runs
    for key in [("default", "t-two", 0), ("default", "t-too-many", 1)]:
        (out / "runs" / key[0] / key[1] / f"{key[2]}.json").unlink()
    third = []
    results = run_bench(config(out, f"dask={lc.scheduler_address}", resume=True), progress=False,
                        on_row=lambda r: third.append(run_key(r)))
    assert sorted(third) == [("default", "t-too-many", 1), ("default", "t-two", 0)]
    assert results["executed_runs"] == 2 and results["summary"]["runs"] == 6


def test_llm_slots_are_bounded_per_provider_across_the_cluster(cluster):
    _, client = cluster

    def hold(limit: int, model: str):
        import time as _t

        from pipflow.experiments.backends import configure_llm_limits, llm_slot

        configure_llm_limits({"mockprov": limit, "default": 8}, "dask")
        with llm_slot(model, timeout=30):
            start = _t.time()
            _t.sleep(0.4)
            return start, _t.time()

    def overlaps(spans):
        spans = sorted(spans)
        return any(b[0] < a[1] - 1e-3 for a, b in zip(spans, spans[1:]))

    spans = [f.result(timeout=TIMEOUT) for f in client.map(hold, [1] * 4, ["mockprov/m"] * 4, pure=False)]
    assert not overlaps(spans), "one slot for mockprov: calls must not overlap across workers"
    spans = [f.result(timeout=TIMEOUT) for f in client.map(hold, [1] * 4, ["otherprov/m"] * 4, pure=False)]
    assert overlaps(spans), "another provider has its own (default) limit"


def test_llm_complete_holds_a_slot(monkeypatch):
    import contextlib

    import pipflow.experiments.backends as ex
    from pipflow import llmslot
    from pipflow.language.llm import complete

    entered = []

    @contextlib.contextmanager
    def slot(model, timeout=None):
        entered.append(model)
        yield

    monkeypatch.setattr(llmslot, "_hook", slot)  # the hook a bench backend installs
    out = complete([{"role": "user", "content": "hi"}], model="openai/gpt-4o",
                   extra={"mock_response": "hello"})
    assert out.text == "hello" and entered == ["openai/gpt-4o"]
    # the dask backend installs its limiter as that hook; any other backend removes it
    ex.configure_llm_limits({"default": 2}, "dask")
    assert llmslot._hook is ex.llm_slot
    ex.configure_llm_limits(None, None)
    assert llmslot._hook is None


def test_a_worker_killed_mid_bench_still_counts_every_run_once(cluster, tmp_path):
    lc, client = cluster
    out = tmp_path / "k"
    killed = []

    def kill_a_busy_worker(row):
        if killed:
            return
        deadline = time.time() + 10
        while time.time() < deadline:
            busy = [w for w, keys in client.processing().items() if keys]
            if busy:
                break
            time.sleep(0.05)
        else:
            return
        killed.append(busy[0])
        try:
            client.run(os._exit, 1, workers=[busy[0]], wait=False)
        except Exception:
            pass

    results = run_bench(config(out, f"dask={lc.scheduler_address}", seeds=4), progress=False,
                        on_row=kill_a_busy_worker)
    assert killed, "no worker was busy to kill"
    assert results["summary"]["runs"] == 12 and results["summary"]["sr"] == 1.0
    rows = rows_once(out, 12)
    assert {run_key(r) for r in rows} == {("default", t, s) for t in ("t-move", "t-two", "t-too-many")
                                          for s in range(4)}
    for r in rows:
        assert read_row(out, run_key(r)) is not None
    client.wait_for_workers(2, timeout=TIMEOUT)  # the nanny restarted it


def test_dask_backend_starts_its_own_local_cluster(tmp_path):
    results = run_bench(config(tmp_path / "own", "dask", seeds=1), progress=False)
    assert results["summary"]["runs"] == 3 and results["summary"]["sr"] == 1.0
    rows_once(tmp_path / "own", 3)
    shutil.rmtree(tmp_path / "own")

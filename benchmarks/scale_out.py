"""Scale-out of `pipflow bench --backend dask`: the speedup of 2 workers over 1 on the paper's
ten warehouse tasks x 4 seeds, and the scheduler's overhead per run.

    python benchmarks/scale_out.py [--seeds 4] [--trivial 400]

Each measurement starts a LocalCluster of N single-threaded worker processes, warms every worker
(imports pipflow and runs one bench run, outside the timing), then times the whole bench through
the same code path as `pipflow bench --backend dask=ADDRESS` (bundles by content, streamed row
files, zipped run records). The step cache is off, so neither measurement reuses the other's
results. The overhead is measured with trivial tasks: ``--trivial`` no-op runs submitted and
collected with as_completed on a 1-worker cluster, against the same number of direct calls, and
per real run as the share of the 1-worker bench not spent inside ``run_one``.
"""
from __future__ import annotations

import argparse
import json
import os
import sys
import tempfile
import time
from pathlib import Path

REPO = Path(__file__).resolve().parent.parent
TASKS = REPO / "benchmarks" / "warehouse" / "tasks.yaml"


def _noop(x):
    return x


def _warm(_=None):
    import pipflow.experiments.benchmarking  # noqa: F401
    import pipflow.warehouse.simulation  # noqa: F401
    return os.getpid()


def cluster(n: int):
    from distributed import Client, LocalCluster

    lc = LocalCluster(n_workers=n, threads_per_worker=1, processes=True, dashboard_address=":0", silence_logs=50)
    client = Client(lc, timeout=60)
    client.wait_for_workers(n, timeout=60)
    client.run(_warm)
    return lc, client


def bench_on(n: int, seeds: int) -> tuple[float, dict, list[dict]]:
    from pipflow.experiments.benchmarking import BenchConfig, run_bench

    lc, client = cluster(n)
    try:
        with tempfile.TemporaryDirectory() as tmp:
            # warm every worker with one real run each (first pybullet / SCIP use), not timed
            tasks_one = Path(tmp) / "one.yaml"
            tasks_one.write_text(f"world: {REPO / 'benchmarks' / 'warehouse' / 'world.yaml'}\n"
                                 "tasks:\n  - id: warm\n    command: \"There should be 7 product 1 in shelf 3.\"\n"
                                 "    goal: {shelf3: {product1: 7}}\n")
            run_bench(BenchConfig(tasks_file=tasks_one, seeds=2 * n, jobs=n, out=Path(tmp) / "warm", use_cache=False,
                                  backend=f"dask={lc.scheduler_address}"), progress=False)
            config = BenchConfig(tasks_file=TASKS, seeds=seeds, jobs=n, out=Path(tmp) / "b", use_cache=False,
                                 backend=f"dask={lc.scheduler_address}")
            started = time.perf_counter()
            results = run_bench(config, progress=False)
            wall = time.perf_counter() - started
            return wall, results, json.loads((Path(tmp) / "b" / "runs.json").read_text())
    finally:
        client.close(timeout=10)
        lc.close(timeout=30)


def overhead(trivial: int) -> tuple[float, float]:
    from distributed import as_completed

    started = time.perf_counter()
    for i in range(trivial):
        _noop(i)
    direct = (time.perf_counter() - started) / trivial
    lc, client = cluster(1)
    try:
        started = time.perf_counter()
        futures = [client.submit(_noop, i, pure=False, retries=2) for i in range(trivial)]
        for fut in as_completed(futures):
            fut.result(timeout=60)
        per_task = (time.perf_counter() - started) / trivial
    finally:
        client.close(timeout=10)
        lc.close(timeout=30)
    return per_task, direct


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seeds", type=int, default=4)
    parser.add_argument("--trivial", type=int, default=400)
    args = parser.parse_args()
    n_runs = 10 * args.seeds
    print(f"machine: {os.cpu_count()} CPUs; {n_runs} runs (10 tasks x {args.seeds} seeds), dask LocalCluster, "
          "1 thread per worker, step cache off")
    t1, r1, rows1 = bench_on(1, args.seeds)
    t2, r2, _ = bench_on(2, args.seeds)
    same = [(t["id"], t["sr"], t["tc_max"]) for t in r1["tasks"]] == [(t["id"], t["sr"], t["tc_max"]) for t in r2["tasks"]]
    print(f"1 worker : {t1:6.1f} s  ({t1 / n_runs:.2f} s/run)  SR {100 * r1['summary']['sr']:.0f}%")
    print(f"2 workers: {t2:6.1f} s  ({t2 / n_runs:.2f} s/run)  SR {100 * r2['summary']['sr']:.0f}%")
    print(f"speedup 2 over 1: {t1 / t2:.2f}x (target >= 1.7x); same table: {same}")
    inside = sum(float(r.get("seconds") or 0) for r in rows1)
    if inside:
        print(f"per real run: {t1 / n_runs:.3f} s wall on 1 worker, {inside / n_runs:.3f} s inside run_one -> "
              f"{(t1 - inside) / n_runs * 1000:.0f} ms per run for scheduling, bundles, record zip/unzip, row files")
    per_task, direct = overhead(args.trivial)
    print(f"scheduler overhead: {per_task * 1000:.2f} ms per trivial task ({args.trivial} submitted, as_completed) "
          f"vs {direct * 1e6:.2f} us per direct call")
    return 0 if t1 / t2 >= 1.7 else 1


if __name__ == "__main__":
    sys.exit(main())

"""Engine overhead per step: a workflow of 1000 trivial `core.value` steps, run in-process.

Two shapes: a chain (each step reads the previous one: the worst case for references) and a
wide fan (1000 independent steps, then one step reading them all). The baseline is the same
1000 step functions called directly in the same process; the engine's overhead is the run's
wall time minus that baseline. Target: under 1 ms per step.

    python benchmarks/engine_overhead.py [--steps 1000] [--repeat 3] [--profile]
"""
from __future__ import annotations

import argparse
import cProfile
import pstats
import sys
import tempfile
import time
from pathlib import Path

import yaml

from pipflow.engine import RunOptions, run_workflow
from pipflow.engine.registry import default_registry
from pipflow.engine.step import StepContext


def chain(n: int) -> dict:
    steps = [{"id": "s0", "uses": "core.value", "with": {"value": 0}}]
    steps += [{"id": f"s{i}", "uses": "core.value", "with": {"value": f"${{s{i - 1}.value + 1}}"}} for i in range(1, n)]
    return {"pipflow": 1, "name": "chain", "steps": steps, "outputs": {"last": f"${{s{n - 1}.value}}"}}


def fan(n: int) -> dict:
    steps = [{"id": f"s{i}", "uses": "core.value", "with": {"value": i}} for i in range(n - 1)]
    steps.append({"id": "total", "uses": "core.value",
                  "with": {"value": [f"${{s{i}.value}}" for i in range(n - 1)]}})
    return {"pipflow": 1, "name": "fan", "steps": steps, "outputs": {"total": "${total.value}"}}


def baseline(n: int, tmp: Path) -> float:
    """The same n step functions called directly (with a context each, as the engine does)."""
    func = default_registry().get("core.value").func
    started = time.perf_counter()
    value = 0
    for i in range(n):
        ctx = StepContext(f"s{i}", tmp / "a", tmp)
        value = func(ctx, value=value + 1)["value"]
    return time.perf_counter() - started


def measure(shape: str, n: int, repeat: int, tmp: Path, jobs: int = 1) -> dict:
    wf_file = tmp / f"{shape}.yaml"
    wf_file.write_text(yaml.safe_dump((chain if shape == "chain" else fan)(n), sort_keys=False))
    best = None
    for r in range(repeat):
        runs = tmp / f"runs-{shape}-{jobs}-{r}"
        started = time.perf_counter()
        result = run_workflow(wf_file, runs_dir=runs, options=RunOptions(jobs=jobs, use_cache=False))
        total = time.perf_counter() - started
        assert result.ok, result.error
        base = baseline(n, tmp)
        row = {"shape": shape, "jobs": jobs, "total": total, "base": base, "overhead": total - base}
        if best is None or row["total"] < best["total"]:
            best = row
    return best


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--steps", type=int, default=1000)
    parser.add_argument("--repeat", type=int, default=3, help="runs per shape; the fastest is reported")
    parser.add_argument("--profile", action="store_true", help="cProfile the chain run, print the hot spots")
    args = parser.parse_args(argv)
    n = args.steps
    default_registry()  # load steps once, outside the timings
    with tempfile.TemporaryDirectory(prefix="pipflow-bench-") as d:
        tmp = Path(d)
        if args.profile:
            wf_file = tmp / "p.yaml"
            wf_file.write_text(yaml.safe_dump(chain(n), sort_keys=False))
            prof = cProfile.Profile()
            prof.enable()
            run_workflow(wf_file, runs_dir=tmp / "runs-prof", options=RunOptions(use_cache=False))
            prof.disable()
            pstats.Stats(prof).sort_stats("tottime").print_stats(15)
        rows = [measure("chain", n, args.repeat, tmp), measure("fan", n, args.repeat, tmp),
                measure("fan", n, args.repeat, tmp, jobs=4)]
    print(f"engine overhead, {n} trivial core.value steps (validate + run + run record; best of {args.repeat})")
    print(f"{'shape':<6} {'jobs':>4} {'total s':>8} {'steps s':>8} {'overhead ms/step':>17} {'overhead share':>15}")
    worst = 0.0
    for row in rows:
        per_step = row["overhead"] / n * 1000
        worst = max(worst, per_step)
        print(f"{row['shape']:<6} {row['jobs']:>4} {row['total']:>8.3f} {row['base']:>8.4f} "
              f"{per_step:>17.3f} {row['overhead'] / row['total']:>14.1%}")
    verdict = "OK" if worst < 1.0 else "OVER TARGET"
    print(f"worst overhead per step: {worst:.3f} ms (target < 1 ms): {verdict}")
    return 0 if worst < 1.0 else 1


if __name__ == "__main__":
    sys.exit(main())

"""Engine overhead per step: a workflow of 1000 trivial `core.value` steps, run in-process.

Two shapes, each with 1 and 4 jobs: a chain (each step reads the previous one: the worst case for references) and a
wide fan (1000 independent steps, then one step reading them all). The baseline is the same
1000 step functions called directly in the same process; the engine's overhead is the run's
wall time minus that baseline. Target: under 1 ms per step.

    python benchmarks/engine_overhead.py [--steps 1000] [--repeat 3] [--profile] [--baseline REV]

``--baseline REV`` runs the same measurement with the code of git revision REV (exported with
``git archive``, put first on PYTHONPATH; see benchmarks/baseline_code.py) in the same invocation,
and prints the current / baseline ratio of the overhead per step beside the load average: on a
shared machine an absolute figure moves with the load, a ratio measured under the same load does
not (much). With a baseline, both codes are measured in child processes, alternating, ``--rounds``
times each, and the fastest of each is kept. Run records go to the temporary folder: with
``TMPDIR=/dev/shm`` the figures are the engine's own cost, without the disk's (on a busy disk
each file a step's record creates costs 0.3-1 ms, whatever the engine does).

It also measures the engine's fixed cost per run, which the per-step figure leaves out: one
``pipflow run`` of a one-step workflow in a fresh process (interpreter start, the engine's and the
steps' imports, validation, the run record), best of ``--rounds`` x ``--repeat`` runs, for each
code in turn. No step parses a command, so neither code touches the command parser or its cache
(benchmarks/pipeline.py measures that warm and cold); the step cache is off in every run.
"""
from __future__ import annotations

import argparse
import cProfile
import json
import os
import pstats
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import yaml

from pipflow.engine import RunOptions, run_workflow
from pipflow.engine.registry import default_registry
from pipflow.engine.step import StepContext

sys.path.insert(0, str(Path(__file__).resolve().parent))
from baseline_code import baseline_env, baseline_site, load_text  # noqa: E402  (a sibling script module)


def chain(n: int) -> dict:
    steps = [{"id": "s0", "uses": "core.value", "with": {"value": 0}}]
    steps += [{"id": f"s{i}", "uses": "core.value", "with": {"value": f"${{s{i - 1}.value + 1}}"}} for i in range(1, n)]
    return {"pipflow": 1, "name": "chain", "steps": steps, "outputs": {"last": f"${{s{n - 1}.value}}"}}


def fan(n: int) -> dict:
    steps = [{"id": f"s{i}", "uses": "core.value", "with": {"value": i}} for i in range(n - 1)]
    steps.append({"id": "total", "uses": "core.value",
                  "with": {"value": [f"${{s{i}.value}}" for i in range(n - 1)]}})
    return {"pipflow": 1, "name": "fan", "steps": steps, "outputs": {"total": "${total.value}"}}


def baseline(n: int, tmp: Path) -> tuple[float, float]:
    """The same n step functions called directly (with a context each, as the engine does): wall
    and CPU seconds."""
    func = default_registry().get("core.value").func
    started, cpu = time.perf_counter(), time.process_time()
    value = 0
    for i in range(n):
        ctx = StepContext(f"s{i}", tmp / "a", tmp)
        value = func(ctx, value=value + 1)["value"]
    return time.perf_counter() - started, time.process_time() - cpu


def measure(shape: str, n: int, repeat: int, tmp: Path, jobs: int = 1) -> dict:
    wf_file = tmp / f"{shape}.yaml"
    wf_file.write_text(yaml.safe_dump((chain if shape == "chain" else fan)(n), sort_keys=False))
    best = None
    for r in range(repeat):
        runs = tmp / f"runs-{shape}-{jobs}-{r}"
        started, cpu = time.perf_counter(), time.process_time()
        result = run_workflow(wf_file, runs_dir=runs, options=RunOptions(jobs=jobs, use_cache=False))
        total, total_cpu = time.perf_counter() - started, time.process_time() - cpu
        assert result.ok, result.error
        base, base_cpu = baseline(n, tmp)
        row = {"shape": shape, "jobs": jobs, "total": total, "base": base, "overhead": total - base,
               "cpu_overhead": total_cpu - base_cpu}
        if best is None:
            best = row
        else:  # the fastest wall time, and (separately) the least CPU time
            cpu_best = min(best["cpu_overhead"], row["cpu_overhead"])
            best = dict(row if row["total"] < best["total"] else best, cpu_overhead=cpu_best)
    return best


def measure_all(n: int, repeat: int, profile: bool = False) -> list[dict]:
    """The three shapes, in this process, with the code ``pipflow`` imports here."""
    default_registry()  # load steps once, outside the timings
    with tempfile.TemporaryDirectory(prefix="pipflow-bench-") as d:
        tmp = Path(d)
        if profile:
            wf_file = tmp / "p.yaml"
            wf_file.write_text(yaml.safe_dump(chain(n), sort_keys=False))
            prof = cProfile.Profile()
            prof.enable()
            run_workflow(wf_file, runs_dir=tmp / "runs-prof", options=RunOptions(use_cache=False))
            prof.disable()
            pstats.Stats(prof).sort_stats("tottime").print_stats(15)
        return [measure("chain", n, repeat, tmp), measure("fan", n, repeat, tmp),
                measure("chain", n, repeat, tmp, jobs=4), measure("fan", n, repeat, tmp, jobs=4)]


def measure_child(n: int, repeat: int, site: Path | None) -> list[dict]:
    """:func:`measure_all` in a child process, with the current code or the copy at ``site``."""
    env = baseline_env(site) if site else None
    proc = subprocess.run([sys.executable, __file__, "--child", "--steps", str(n), "--repeat", str(repeat)],
                          capture_output=True, text=True, env=env, cwd=tempfile.gettempdir())
    if proc.returncode != 0:
        raise SystemExit(f"{'baseline' if site else 'current'} run failed:\n{proc.stderr[-2000:]}")
    return json.loads(proc.stdout.strip().splitlines()[-1])


def startup(tmp: Path, site: Path | None) -> dict:
    """One `pipflow run` of a one-step workflow in a fresh process: wall and CPU seconds (the
    child's own, from ``os.wait4``)."""
    wf_file = tmp / "one.yaml"
    if not wf_file.exists():
        wf_file.write_text(yaml.safe_dump(chain(1), sort_keys=False))
    args = [sys.executable, "-m", "pipflow.engine.cli", "run", str(wf_file), "--no-cache", "-q",
            "--runs-dir", str(tmp / "runs-startup")]
    env = baseline_env(site) if site else None
    started = time.perf_counter()
    proc = subprocess.Popen(args, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, cwd=tmp, env=env)
    _, status, usage = os.wait4(proc.pid, 0)
    wall = time.perf_counter() - started
    if os.waitstatus_to_exitcode(status) != 0:
        raise SystemExit(f"{'baseline' if site else 'current'} one-step run failed (exit {status})")
    return {"wall": wall, "cpu": usage.ru_utime + usage.ru_stime}


def _best(runs: list[list[dict]]) -> list[dict]:
    return [dict(min(rows, key=lambda r: r["overhead"]), cpu_overhead=min(r["cpu_overhead"] for r in rows))
            for rows in zip(*runs)]


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--steps", type=int, default=1000)
    parser.add_argument("--repeat", type=int, default=3, help="runs per shape; the fastest is reported")
    parser.add_argument("--profile", action="store_true", help="cProfile the chain run, print the hot spots")
    parser.add_argument("--baseline", metavar="REV", help="also measure the code of git revision REV")
    parser.add_argument("--rounds", type=int, default=2, help="with --baseline: child runs of each code")
    parser.add_argument("--work", type=Path, help="with --baseline: where to export REV (default: a temp folder)")
    parser.add_argument("--child", action="store_true", help=argparse.SUPPRESS)  # print rows as JSON
    args = parser.parse_args(argv)
    n = args.steps
    if args.child:
        print(json.dumps(measure_all(n, args.repeat)))
        return 0
    load_before = load_text()
    base_rows: list[dict] = []
    starts: dict[str, list[dict]] = {"current": [], "baseline": []}
    with tempfile.TemporaryDirectory(prefix="pipflow-bench-start-") as d:
        site = baseline_site(args.baseline, args.work or Path(d)) if args.baseline else None
        codes = [("current", None)] + ([("baseline", site)] if site else [])
        for name, where in codes:  # unmeasured: bytecode compiled for each code
            startup(Path(d), where)
        for _ in range(max(1, args.rounds) * max(1, args.repeat)):
            for name, where in codes:  # the codes take turns, so they share the load
                starts[name].append(startup(Path(d), where))
        if site:
            current_runs, base_runs = [], []
            for _ in range(max(1, args.rounds)):
                current_runs.append(measure_child(n, args.repeat, None))
                base_runs.append(measure_child(n, args.repeat, site))
            rows, base_rows = _best(current_runs), _best(base_runs)
        else:
            rows = measure_all(n, args.repeat, args.profile)
    print(f"engine overhead, {n} trivial core.value steps (validate + run + run record; best of {args.repeat}"
          + (f" x {args.rounds} child runs per code" if args.baseline else "") + ")")
    print(f"load average before: {load_before}; after: {load_text()} ({os.cpu_count()} CPUs)")
    print(f"{'shape':<6} {'jobs':>4} {'total s':>8} {'steps s':>8} {'overhead ms/step':>17} {'cpu ms/step':>12}"
          + (f" {'base ms/step':>13} {'base cpu':>9} {'ratio wall':>11} {'ratio cpu':>10}" if base_rows else ""))
    worst = 0.0
    for i, row in enumerate(rows):
        per_step = row["overhead"] / n * 1000
        cpu_step = row["cpu_overhead"] / n * 1000
        worst = max(worst, per_step)
        line = (f"{row['shape']:<6} {row['jobs']:>4} {row['total']:>8.3f} {row['base']:>8.4f} "
                f"{per_step:>17.3f} {cpu_step:>12.3f}")
        if base_rows:
            base_step = base_rows[i]["overhead"] / n * 1000
            base_cpu = base_rows[i]["cpu_overhead"] / n * 1000
            line += f" {base_step:>13.3f} {base_cpu:>9.3f} {per_step / base_step:>11.2f} {cpu_step / base_cpu:>10.2f}"
        print(line)
    print("overhead = the run's time minus the same step functions called directly; cpu = process CPU time "
          "(less moved by other processes than wall time; the disk's waits are not in it)")
    if base_rows:
        print(f"baseline: git revision {args.baseline}, measured in the same invocation; ratio = current / baseline")
    best = {name: (min(r["wall"] for r in rows_), min(r["cpu"] for r in rows_)) for name, rows_ in starts.items() if rows_}
    line = (f"fixed cost per run (a one-step workflow in a fresh process, best of {len(starts['current'])}): "
            f"current {best['current'][0]:.3f} s wall, {best['current'][1]:.3f} s cpu")
    if "baseline" in best:
        line += (f"; baseline {best['baseline'][0]:.3f} s wall, {best['baseline'][1]:.3f} s cpu; ratio "
                 f"{best['current'][0] / best['baseline'][0]:.2f} wall, {best['current'][1] / best['baseline'][1]:.2f} cpu")
    print(line)
    verdict = "OK" if worst < 1.0 else "OVER TARGET"
    print(f"worst overhead per step: {worst:.3f} ms (target < 1 ms): {verdict}")
    return 0 if worst < 1.0 else 1


if __name__ == "__main__":
    sys.exit(main())

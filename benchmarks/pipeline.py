"""Per-stage times of the whole `pipflow run` at the paper's size and at generated scales.

    python benchmarks/pipeline.py [--sizes paper,1000x100x20,1000x400x40:24,5000x400x40:24,10000x400x40:24]
                                  [--baseline REV] [--baseline-sizes ...] [--repeat N]
                                  [--timeout 900] [--keep DIR]

Each size is one `pipflow run workflows/warehouse.yaml` in a fresh child process (the way a user
runs it: imports included), with the step cache off. The per-stage times are read back from the
run record's ``events.jsonl`` (``end`` events of top-level steps and of the refinement loop's inner
steps); the wall time is the child's, measured here. Every size's wall time is printed as a ratio
to the paper-sized run *of the same invocation*, so a ratio is comparable across machines and loads
while an absolute figure is not. The load average (``os.getloadavg``) is printed before and after
each run, and the peak memory and CPU seconds are the child's own (``os.wait4``).

Sizes are ``ROBOTSxSHELVESxPRODUCTS``; ``paper`` is the main job (benchmarks/warehouse/world.yaml and
the workflow's default command). Generated worlds put 8 x 2 m shelves on a grid with 6 m aisles,
an access point 1 m in front of each shelf, robots on free aisle cells (carry 1-3), and stock at
about half of each shelf's capacity. Small worlds get the paper's default command form (a dozen and
a quintet of two products on the last shelf); worlds with more than six shelves get "empty" six of
them, so the planner, the graph and the allocation have real work.

``--current REV`` measures a commit instead of the working tree (which, in a shared checkout, holds
other people's unfinished edits). ``--repeat N`` runs every size N times and keeps the fastest run (on a shared machine the
fastest is the one least slowed by others). ``--baseline REV`` (repeatable) also runs every size
with the code of git revision REV (exported with ``git archive`` into the work folder, compiled to
bytecode, and put first on ``PYTHONPATH``); the codes take turns within each repetition, so they
share the load, and the current / baseline ratio is printed per size: a before/after comparison
measured in one invocation.

The command parser's grammar cache (:mod:`pipflow.language.earley`) is measured honestly in three
variants of the current code at the paper's size: ``warm`` (the cache holds the parser: every run
after the first), ``cold`` (an empty cache folder for each run: the first run after installing
or changing the grammar, which builds the parser and stores it) and ``off`` (no disk cache: built
in memory only, as before the cache existed). Other sizes run warm. Before any measurement, each
code makes one unmeasured run of the paper's size, so that every code has its bytecode compiled
and the warm cache is filled; the cold variant still pays the parser build in every run.

Sizes may end in ``:N``, the number of shelves the command empties (``5000x400x40:24``: issue
26's row, "Empty shelf1, ..., shelf23 and shelf24."). The sizes that differ only in robots (the
default ``1000x400x40:24``, ``5000x400x40:24`` and ``10000x400x40:24``) give the growth of each
stage with the fleet, printed as a ratio and the exponent k of robots^k it means.

Targets (issue 15): the main job at most 1.5 s wall on an idle 2-core machine; 1000 x 100 x 20
within 8x the main job. Issue 26: 5000 x 400 x 40 (24 shelves emptied) within 15x the main job;
peak memory under 2 GB at 10,000 robots; nothing worse than n log n in robots where the work
allows it.
"""
from __future__ import annotations

import argparse
import compileall
import json
import math
import os
import random
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path

import numpy as np
import yaml

sys.path.insert(0, str(Path(__file__).resolve().parent))
from baseline_code import REPO, baseline_site  # noqa: E402,F401  (a sibling script module; shared with engine_overhead.py)
WORKFLOW = REPO / "workflows" / "warehouse.yaml"
DEFAULT_SIZES = "paper,1000x100x20,1000x400x40:24,5000x400x40:24,10000x400x40:24"

SHELF_W, SHELF_D, AISLE_X, AISLE_Y = 8.0, 2.0, 6.0, 6.0
CAPACITY = 30
GRAMMAR_ENV = "PIPFLOW_GRAMMAR_CACHE_DIR"  # pipflow.language.earley.ENV_DIR (not imported: baselines lack it)


def generate_world(robots: int, shelves: int, products: int, seed: int = 0) -> dict:
    """A warehouse world of the given size (deterministic for a seed)."""
    rng = random.Random(seed)
    cols = max(1, math.ceil(math.sqrt(shelves * (SHELF_D + AISLE_Y) / (SHELF_W + AISLE_X))))
    rows = math.ceil(shelves / cols)
    pitch_x, pitch_y = SHELF_W + AISLE_X, SHELF_D + AISLE_Y
    width, height = cols * pitch_x + AISLE_X, rows * pitch_y + AISLE_Y
    shelf_names = [f"shelf{i + 1}" for i in range(shelves)]
    product_names = [f"product{i + 1}" for i in range(products)]
    out_shelves = {}
    for i, name in enumerate(shelf_names):
        r, c = divmod(i, cols)
        x, y = AISLE_X + c * pitch_x, AISLE_Y + r * pitch_y
        out_shelves[name] = {"x": x, "y": y, "width": SHELF_W, "depth": SHELF_D, "capacity": CAPACITY,
                             "access": [x + SHELF_W / 2, y - 1.0]}
    # free cells: 1 m lattice, off every shelf inflated by 1 m (which covers its access point),
    # in lattice order; marked per shelf on a grid (a test of every cell against every shelf took
    # minutes at 400 shelves)
    taken = np.zeros((int(width) + 1, int(height) + 1), dtype=bool)
    for sh in out_shelves.values():
        x0, y0 = max(1, math.ceil(sh["x"] - 1)), max(1, math.ceil(sh["y"] - 1))
        x1, y1 = math.floor(sh["x"] + SHELF_W + 1), math.floor(sh["y"] + SHELF_D + 1)
        taken[x0:x1 + 1, y0:y1 + 1] = True
    cells = [[float(gx), float(gy)] for gx in range(1, int(width)) for gy in range(1, int(height))
             if not taken[gx, gy]]
    if len(cells) < robots:
        raise SystemExit(f"{robots} robots do not fit on {len(cells)} free cells")
    starts = rng.sample(cells, robots)
    out_robots = {f"robot{i}": {"start": starts[i], "skills": {"carry": 1 + i % 3}} for i in range(robots)}
    stock: dict[str, dict[str, int]] = {}
    for name in shelf_names:
        held = rng.sample(product_names, min(products, rng.randint(1, 4)))
        left = CAPACITY // 2
        stock[name] = {}
        for p in held:
            n = rng.randint(1, max(1, left // len(held)))
            stock[name][p] = n
            left -= n
    return {"name": f"generated-{robots}x{shelves}x{products}", "floor": {"width": width, "height": height},
            "shelves": out_shelves, "products": {p: {"color": "grey"} for p in product_names},
            "stock": stock, "robots": out_robots}


def parse_size(label: str) -> tuple[int, int, int, int | None]:
    """``ROBOTSxSHELVESxPRODUCTS[:EMPTIED]`` -> the numbers (EMPTIED None: the default command)."""
    dims, _, emptied = label.partition(":")
    r, s, p = (int(x) for x in dims.split("x"))
    return r, s, p, int(emptied) if emptied else None


def command_for(world: dict, emptied: int | None = None) -> str:
    """Small worlds: the paper's default form on the last shelf, with counts that fit what exists;
    larger worlds: empty six shelves (every unit they hold moves elsewhere), or ``emptied``
    shelves where the size says so (issue 26's rows empty 24)."""
    shelves = list(world["shelves"])
    if emptied or len(shelves) > 6:
        some = shelves[:emptied or 6]
        return "Empty " + ", ".join(some[:-1]) + f" and {some[-1]}."
    totals: dict[str, int] = {}
    for items in world["stock"].values():
        for p, n in items.items():
            totals[p] = totals.get(p, 0) + n
    top = sorted(totals, key=lambda p: -totals[p])[:2]
    a, b = min(12, totals[top[0]]), min(5, totals[top[-1]])
    return f"{shelves[-1]} stores {a} {top[0]} and {b} {top[-1]}."


def stage_times(run_dir: Path) -> dict[str, float]:
    """Seconds per step, summed over loop iterations, from the run record's event log."""
    out: dict[str, float] = {}
    for line in (run_dir / "events.jsonl").read_text().splitlines():
        ev = json.loads(line)
        if ev.get("event") == "end" and ev.get("duration") is not None and ev.get("step") != "refine":
            out[ev["step"]] = out.get(ev["step"], 0.0) + float(ev["duration"])
    return out


def run_size(label: str, work: Path, timeout: float, site: Path | None = None, grammar: Path | str | None = None,
             name: str = "now") -> dict:
    """One `pipflow run` in a child process; wall time, stages, status and peak memory so far.
    ``site``: run that copy of the code (see :func:`baseline_site`) instead of the current one.
    ``grammar``: the parser cache folder the child uses (``""``: none); ``name``: the code's
    label, for the record folder."""
    workflow = site / "pipflow" / "workflows" / WORKFLOW.name if site else WORKFLOW
    record = work / "runs" / f"{label.replace(':', '-')}-{name}"
    args = [sys.executable, "-m", "pipflow.engine.cli", "run", str(workflow), "--no-cache", "-q",
            "--runs-dir", str(record)]
    if label != "paper":
        r, s, p, emptied = parse_size(label)
        world = generate_world(r, s, p)
        path = work / f"world-{label.replace(':', '-')}.yaml"
        if not path.exists():  # one world per size, whichever code runs it
            path.write_text(yaml.safe_dump(world, sort_keys=False))
        args += ["-i", f"world={path}", "-i", f"command={command_for(world, emptied)}"]
    env = dict(os.environ, PYTHONPATH=str(site)) if site else dict(os.environ)
    if grammar is not None:
        env[GRAMMAR_ENV] = str(grammar)
    load_before = os.getloadavg()[0]
    with tempfile.TemporaryFile() as out, tempfile.TemporaryFile() as errors:
        started = time.perf_counter()
        proc = subprocess.Popen(args, stdout=out, stderr=errors, cwd=work, env=env)
        timer = threading.Timer(timeout, proc.kill)
        timer.start()
        _, status, usage = os.wait4(proc.pid, 0)  # this child's own resource use, peak memory included
        wall = time.perf_counter() - started
        timer.cancel()
        proc.returncode = os.waitstatus_to_exitcode(status)
        errors.seek(0)
        err = errors.read().decode("utf-8", "replace").strip().splitlines()[-1:] or [""]
    code = proc.returncode
    if code == -9 and wall >= timeout:
        code, err = None, [f"timed out after {timeout:.0f} s"]
    cpu = usage.ru_utime + usage.ru_stime
    peak_mb = usage.ru_maxrss / 1024
    runs = sorted(record.glob("*/events.jsonl"))
    stages = stage_times(runs[-1].parent) if runs else {}
    return {"label": label, "code_name": name, "wall": wall, "cpu": cpu, "code": code, "error": err[0] if code else "", "stages": stages,
            "peak_mb": peak_mb, "load": (load_before, os.getloadavg()[0])}


def _row(r: dict, base: float, stages: list[str]) -> str:
    status = "ok" if r["code"] == 0 else f"exit {r['code']}"
    return (f"{r['label']:>12} {r['wall']:7.2f} {r['wall'] / base:7.2f} {r['cpu']:6.2f} {r['peak_mb']:8.0f} "
            f"{r['load'][0]:5.2f}>{r['load'][1]:<5.2f}  {status:7}  "
            + " ".join(f"{r['stages'][s]:9.2f}" if s in r["stages"] else f"{'-':>9}" for s in stages))


class Code:
    """One code variant to measure: the current tree (``site`` None) or a baseline revision, with
    the parser cache folder its runs use (``None``: the default; ``""``: none; ``"cold"``: a new
    empty folder per run)."""

    def __init__(self, name: str, site: Path | None, grammar: Path | str | None):
        self.name, self.site, self.grammar = name, site, grammar

    def run(self, label: str, work: Path, timeout: float, serial: int) -> dict:
        grammar = self.grammar
        if grammar == "cold":
            grammar = work / "grammar-cold" / f"{label}-{serial}"
            grammar.mkdir(parents=True)
        return run_size(label, work, timeout, self.site, grammar, self.name)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sizes", default=DEFAULT_SIZES, help=f"comma-separated (default {DEFAULT_SIZES})")
    parser.add_argument("--current", default=None, metavar="REV",
                        help="measure git revision REV as the current code (default: the working tree, "
                             "with whatever uncommitted edits it holds)")
    parser.add_argument("--baseline", action="append", default=[], metavar="REV",
                        help="also run the code of git revision REV (repeatable)")
    parser.add_argument("--baseline-sizes", default=None,
                        help="run the baselines only at these sizes (the old code may take minutes at the big ones)")
    parser.add_argument("--repeat", type=int, default=1, help="runs per size and code; the fastest is kept")
    parser.add_argument("--timeout", type=float, default=900.0, help="seconds per run")
    parser.add_argument("--keep", type=Path, default=None, help="keep worlds and run records here")
    args = parser.parse_args()
    sizes = [s.strip() for s in args.sizes.split(",") if s.strip()]
    if "paper" not in sizes:
        sizes.insert(0, "paper")
    work = (args.keep or Path(tempfile.mkdtemp(prefix="pipflow-pipeline-"))).resolve()
    work.mkdir(parents=True, exist_ok=True)
    warm = work / "grammar-warm"

    def commit(rev: str) -> str:  # HEAD today is not HEAD tomorrow: folders and labels by commit
        return subprocess.run(["git", "-C", str(REPO), "rev-parse", "--short", rev], check=True, capture_output=True,
                              text=True).stdout.strip()

    def exported(rev: str) -> Path:
        site = baseline_site(commit(rev), work)
        compileall.compile_dir(str(site.parent / "src"), quiet=1)  # bytecode, as the working tree has it
        return site

    here = exported(args.current) if args.current else None
    now = [Code("now warm", here, warm), Code("now cold", here, "cold"), Code("now off", here, "")]
    bases = [Code(commit(rev), exported(rev), None) for rev in args.baseline]
    print(f"machine: {os.cpu_count()} CPUs; load average {' '.join(f'{x:.2f}' for x in os.getloadavg())}; "
          f"one `pipflow run` per size, step cache off; current code: "
          f"{'revision ' + commit(args.current) if args.current else 'the working tree'}; records in {work}")
    for code in [now[0], *bases]:  # unmeasured: bytecode for every code, the parser in the warm cache
        r = code.run("paper", work, args.timeout, 0)
        print(f"warm-up run of {code.name} (not measured): {r['wall']:.2f} s, exit {r['code']}")
    base_sizes = set(sizes if args.baseline_sizes is None else ["paper"] + args.baseline_sizes.split(","))
    best: dict[tuple[str, str], dict] = {}
    for rep in range(1, max(1, args.repeat) + 1):
        for label in sizes:
            codes = now if label == "paper" else now[:1]
            codes = codes + (bases if label in base_sizes else [])
            for code in codes:  # the codes take turns, so they see the same load
                r = code.run(label, work, args.timeout, rep)
                old = best.get((code.name, label))
                if old is None or (r["code"] != 0, r["wall"]) < (old["code"] != 0, old["wall"]):
                    best[(code.name, label)] = r
    rows = list(best.values())
    stages = list(dict.fromkeys(k for r in rows for k in r["stages"]))
    header = (f"{'size':>12} {'wall s':>7} {'x paper':>7} {'cpu s':>6} {'peak MB':>8} {'load':>11}  status   "
              + " ".join(f"{s[:9]:>9}" for s in stages))
    ok = True
    for code in now + bases:
        mine = [best[(code.name, label)] for label in sizes if (code.name, label) in best]
        if not mine:
            continue
        base = next(r for r in mine if r["label"] == "paper")["wall"]
        what = {"now warm": "current code, parser cache warm", "now cold": "current code, parser cache cold "
                "(empty folder each run: builds and stores the parser)", "now off": "current code, no parser "
                "disk cache (builds it in memory, as before the cache)"}.get(code.name, f"baseline {code.name}")
        print(f"-- {what} (best of {args.repeat}; x paper: wall / this code's paper-sized run; cpu: the child's "
              "user+system seconds, less sensitive to other load; stages in seconds)")
        print(header)
        for r in mine:
            print(_row(r, base, stages))
            if r["code"] != 0:
                print(f"{'':>12} {r['error']}")
                ok = ok and code in bases
    warm_paper = best[("now warm", "paper")]
    print("-- ratios measured in this invocation (wall; cpu in brackets):")
    for code in now[1:] + bases:
        pairs = [(label, best[("now warm", label)], best[(code.name, label)]) for label in sizes
                 if (code.name, label) in best and ("now warm", label) in best]
        print(f"   now warm / {code.name}: " + ", ".join(
            f"{label} {a['wall'] / b['wall']:.2f} ({a['cpu'] / b['cpu']:.2f})" for label, a, b in pairs))
    cold, off = best[("now cold", "paper")], best[("now off", "paper")]
    print(f"   parser cache: a cold run costs {cold['wall'] - warm_paper['wall']:+.2f} s wall over a warm one "
          f"(cpu {cold['cpu'] - warm_paper['cpu']:+.2f} s); storing the parser costs {cold['wall'] - off['wall']:+.2f} s "
          f"over building it without a disk cache")
    base = warm_paper["wall"]
    print_growth([best[("now warm", label)] for label in sizes if ("now warm", label) in best], stages)
    big = best.get(("now warm", "1000x100x20"))
    scaled = best.get(("now warm", "5000x400x40:24"))
    fleet = [r for r in rows if r["code_name"] == "now warm" and label_robots(r["label"]) >= 10_000]
    print(f"targets: paper <= 1.5 s wall on an idle machine: warm {base:.2f} s, cold {cold['wall']:.2f} s "
          f"(load {warm_paper['load'][0]:.2f}); "
          + (f"1000x100x20 <= 8x paper: {big['wall'] / base:.1f}x; " if big else "")
          + (f"5000x400x40:24 <= 15x paper (issue 26): {scaled['wall'] / base:.1f}x; " if scaled else "")
          + (f"peak memory at 10,000 robots < 2048 MB: {max(r['peak_mb'] for r in fleet):.0f} MB; " if fleet else "")
          + f"largest child's peak memory: {max(r['peak_mb'] for r in rows):.0f} MB")
    return 0 if ok else 1


def label_robots(label: str) -> int:
    return 0 if label == "paper" else parse_size(label)[0]


def print_growth(rows: list[dict], stages: list[str]) -> None:
    """How each stage grows with the fleet: for sizes that differ only in robots (same shelves,
    products and command), the time at the most robots over the time at the fewest, and the
    exponent k of robots^k that ratio means (1: linear; n log n from 1,000 to 10,000 robots is
    about 1.3; 2: quadratic). Stages under 0.05 s at the fewest robots are too short to say."""
    groups: dict[str, list[dict]] = {}
    for r in rows:
        if r["label"] != "paper" and r["code"] == 0:
            groups.setdefault(r["label"].split("x", 1)[1], []).append(r)
    for rest, members in groups.items():
        if len(members) < 2:
            continue
        members.sort(key=lambda r: label_robots(r["label"]))
        lo, hi = members[0], members[-1]
        n = label_robots(hi["label"]) / label_robots(lo["label"])
        print(f"-- growth from {lo['label']} to {hi['label']} ({n:g}x the robots): time ratio (exponent k of robots^k)")
        parts = []
        for s in ["wall", *stages]:
            a = lo["wall"] if s == "wall" else lo["stages"].get(s)
            b = hi["wall"] if s == "wall" else hi["stages"].get(s)
            if a is None or b is None:
                continue
            parts.append(f"{s} {b / a:.2f} (k={math.log(b / a) / math.log(n):.2f})" if a >= 0.05
                         else f"{s} {a:.2f}->{b:.2f} s")
        parts.append(f"peak memory {hi['peak_mb'] / lo['peak_mb']:.2f}")
        print("   " + "; ".join(parts))


if __name__ == "__main__":
    sys.exit(main())

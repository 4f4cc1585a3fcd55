#!/usr/bin/env python3
"""Reading time per command: this checkout's offline reader against a base commit's, in one run.

Issue 23 asks that reading a command does not grow by more than 1.5x while the reader learns to
offer candidate readings for what it refuses. This script measures that on this machine, now:

1. it extracts the base commit (default ``a344570``, the issue's baseline) into a throwaway
   directory with ``git archive`` (nothing of this checkout is touched; the copy is deleted at the
   end);
2. it reads the commands of the task files (default: every warehouse and household task file of
   ``benchmarks/language/``, from this checkout, so both trees read the same commands) with each
   tree's offline reader (``pipflow.language.generator.offline``, what ``pipflow run`` does with
   model ``offline``), each tree in a subprocess of its own (its own imports, its own grammar
   cache folder), in rounds that alternate which tree goes first (A/B, B/A, ...), so that load
   from other work on the machine falls on both alike;
3. it prints, per task file and overall, the CPU time per command of each tree (process time:
   what the reading costs, not what waiting for a core costs), the ratio this/base, how many
   commands each tree refused, and the load average.

In each subprocess the first command of every file is read once untimed (it builds that world's
grammar, cached on disk once per tree); the other commands are timed, each read once. A command
refused costs its whole refusal, candidate readings included. A file the base tree cannot load
(a field it did not know yet) is left out for both trees and said so.

    python benchmarks/parse_speed.py [--base REV] [--rounds N] [TASKS.yaml ...]
"""
from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
from collections import defaultdict
from pathlib import Path

import yaml

ROOT = Path(__file__).resolve().parent.parent
LANGUAGE = ROOT / "benchmarks" / "language"

#: what each subprocess runs (with its tree first on sys.path): load every file with the tree's
#: own loader, read each file's first command untimed, then time every other command once
_CHILD = r"""
import json, sys, time
tree = sys.argv[1]
sys.path.insert(0, tree)
import pipflow
assert pipflow.__file__.startswith(tree), f"imported {pipflow.__file__}, not the tree {tree}"
from pipflow.errors import PipflowError
from pipflow.language.generator import offline
files = json.loads(sys.stdin.read())
out = {}
for path, domain in files:
    try:
        if domain == "household":
            from pipflow.household.scoring import load_tasks
        else:
            from pipflow.warehouse.world import load_tasks
        loaded = load_tasks(path)
    except Exception as exc:
        out[path] = {"error": f"{type(exc).__name__}: {exc}"}
        continue
    world, commands = loaded["world"], [str(t["command"]) for t in loaded["tasks"]]
    def read(command):
        try:
            offline(command, world)
            return 0
        except PipflowError:
            return 1
    read(commands[0])
    refused = 0
    start = time.process_time()
    for command in commands[1:]:
        refused += read(command)
    out[path] = {"seconds": time.process_time() - start, "n": len(commands) - 1, "refused": refused}
print(json.dumps(out))
"""


def default_files() -> list[Path]:
    """Every task file (a YAML mapping with ``tasks``) of ``benchmarks/language/``."""
    return [p for p in sorted(LANGUAGE.glob("*.yaml"))
            if "tasks" in (yaml.safe_load(p.read_text(encoding="utf-8")) or {})]


def domain_of(path: Path) -> str:
    return (yaml.safe_load(path.read_text(encoding="utf-8")) or {}).get("domain") or "warehouse"


def extract(rev: str, into: Path) -> str:
    """The base commit's tree under ``into`` (``git archive``); returns the commit's short hash."""
    sha = subprocess.run(["git", "-C", str(ROOT), "rev-parse", "--short", rev], check=True,
                         capture_output=True, text=True).stdout.strip()
    archive = subprocess.Popen(["git", "-C", str(ROOT), "archive", sha], stdout=subprocess.PIPE)
    subprocess.run(["tar", "-x", "-C", str(into)], stdin=archive.stdout, check=True)
    if archive.wait() != 0:
        raise SystemExit(f"error: git archive {rev} failed")
    return sha


def run_tree(tree: Path, cache: Path, files: list[tuple[str, str]]) -> dict:
    """One subprocess reading every file with ``tree``'s reader: ``{file: {seconds, n, refused}}``."""
    env = {**os.environ, "PYTHONPATH": str(tree), "PIPFLOW_GRAMMAR_CACHE_DIR": str(cache / "grammar"),
           "PIPFLOW_CACHE_DIR": str(cache / "steps")}
    done = subprocess.run([sys.executable, "-c", _CHILD, str(tree)], input=json.dumps(files), text=True,
                          capture_output=True, env=env, cwd=str(tree))
    if done.returncode != 0:
        raise SystemExit(f"error: the reader of {tree} failed:\n{done.stderr[-3000:]}")
    return json.loads(done.stdout.strip().splitlines()[-1])


def load() -> str:
    return " / ".join(f"{x:.2f}" for x in os.getloadavg())


def main(argv: list[str]) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("files", nargs="*", type=Path, help="task files (default: every benchmarks/language one)")
    ap.add_argument("--base", default="a344570", help="the base commit (default a344570, issue 23's baseline)")
    ap.add_argument("--rounds", type=int, default=3, help="rounds of base/this, alternating which goes first")
    args = ap.parse_args(argv)
    paths = [p.resolve() for p in args.files] or default_files()
    files = [(str(p), domain_of(p)) for p in paths]
    with tempfile.TemporaryDirectory(prefix="parse-speed-") as tmp:
        base_tree = Path(tmp) / "base"
        base_tree.mkdir()
        sha = extract(args.base, base_tree)
        trees = {"base": (base_tree, Path(tmp) / "base-cache"), "this": (ROOT, Path(tmp) / "this-cache")}
        print(f"{len(files)} task files; base {sha} (extracted to {base_tree}); this tree {ROOT}; "
              f"load average {load()}")
        got: dict[str, list[dict]] = defaultdict(list)
        for r in range(args.rounds):
            order = ["base", "this"] if r % 2 == 0 else ["this", "base"]
            for name in order:
                result = run_tree(*trees[name], files)
                got[name].append(result)
                ok = [v for v in result.values() if "seconds" in v]
                ms = 1000 * sum(v["seconds"] for v in ok) / max(1, sum(v["n"] for v in ok))
                print(f"round {r + 1}: {name:4} {ms:6.1f} ms/command (load average {load()})")
    skipped = {f for res in got["base"] + got["this"] for f, v in res.items() if "error" in v}
    for f in sorted(skipped):
        why = next(res[f]["error"] for res in got["base"] + got["this"] if "error" in res[f])
        print(f"left out {Path(f).name}: {why.splitlines()[0][:160]}")
    print()
    head = f"{'task file':<40} {'n':>4} {'base ms':>8} {'this ms':>8} {'ratio':>6} {'refused base/this':>18}"
    print(head)
    print("-" * len(head))
    totals = {"base": [0.0, 0], "this": [0.0, 0]}
    by_domain: dict[str, dict[str, list]] = defaultdict(lambda: {"base": [0.0, 0], "this": [0.0, 0]})
    for path, domain in files:
        if path in skipped:
            continue
        row = {}
        for name in ("base", "this"):
            secs = [res[path]["seconds"] for res in got[name]]
            n = got[name][0][path]["n"]
            row[name] = (1000 * sum(secs) / len(secs) / max(1, n), got[name][0][path]["refused"])
            for into in (totals, by_domain[domain]):
                into[name][0] += sum(secs) / len(secs)
                into[name][1] += n
        ratio = row["this"][0] / row["base"][0] if row["base"][0] else float("nan")
        print(f"{Path(path).name:<40} {n:>4} {row['base'][0]:>8.1f} {row['this'][0]:>8.1f} {ratio:>5.2f}x "
              f"{row['base'][1]:>8}/{row['this'][1]}")
    print("-" * len(head))
    for label, sums in [*((f"all {d}", by_domain[d]) for d in sorted(by_domain)), ("overall", totals)]:
        b = 1000 * sums["base"][0] / max(1, sums["base"][1])
        t = 1000 * sums["this"][0] / max(1, sums["this"][1])
        print(f"{label:<40} {sums['this'][1]:>4} {b:>8.1f} {t:>8.1f} {t / b:>5.2f}x")
    print(f"\nCPU ms per command (mean of {args.rounds} rounds); ratio this/base; load average {load()}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))

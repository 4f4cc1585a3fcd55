"""Household reading time per command: this checkout against another source tree, interleaved.

Issue 23 asks that reading a command does not grow by more than 1.5x. This script reads every
command of the household sets (``benchmarks/language/household*.yaml`` and
``benchmarks/household/tasks.yaml``, all from this checkout) with the household translator of two
source trees: this checkout and a baseline (a tree of an older commit, e.g. made with
``git archive a344570 | tar -x -C /tmp/base``). Each tree runs in a subprocess of its own (its
own imports), in rounds that alternate which goes first, so that load from other work on the
machine falls on both alike. It prints CPU time per command (process time: what the reading
costs, not what waiting costs) for each round and in total, the ratio, and the load average.
A command refused costs its refusal, candidate readings included.

    python benchmarks/language/household_reader_speed.py /tmp/base [--rounds 3]
"""
from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import yaml

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent.parent

#: what each subprocess runs: read every command once to warm the grammars, then time a second pass
_CHILD = r"""
import json, sys, time
sys.path.insert(0, sys.argv[1])
from pipflow.errors import PipflowError
from pipflow.household.world import load_world
from pipflow.household.language.translator import translate
sets = json.loads(sys.stdin.read())
items = [(load_world(world), command) for world, commands in sets for command in commands]
def once():
    for w, c in items:
        try:
            translate(c, w)
        except PipflowError:
            pass
once()
start = time.process_time()
once()
print(json.dumps({"seconds": time.process_time() - start, "n": len(items)}))
"""


def household_sets() -> list[tuple[str, list[str]]]:
    """(world file, commands) of every household task file of this checkout."""
    files = sorted(HERE.glob("household*.yaml")) + [ROOT / "benchmarks" / "household" / "tasks.yaml"]
    out = []
    for path in files:
        data = yaml.safe_load(path.read_text(encoding="utf-8")) or {}
        if "tasks" not in data:
            continue
        out.append((str((path.parent / data["world"]).resolve()), [str(t["command"]) for t in data["tasks"]]))
    return out


def per_command(tree: Path, sets: list[tuple[str, list[str]]]) -> float:
    """Milliseconds of CPU per command reading every command with ``tree``'s translator."""
    env = {**os.environ, "PYTHONPATH": str(tree)}
    done = subprocess.run([sys.executable, "-c", _CHILD, str(tree)], input=json.dumps(sets), text=True,
                          capture_output=True, env=env, cwd=str(tree), check=True)
    got = json.loads(done.stdout.strip().splitlines()[-1])
    return 1000.0 * got["seconds"] / got["n"]


def main(argv: list[str]) -> int:
    if not argv or argv[0].startswith("-"):
        print(__doc__)
        return 2
    base = Path(argv[0]).resolve()
    rounds = int(argv[argv.index("--rounds") + 1]) if "--rounds" in argv else 3
    sets = household_sets()
    n = sum(len(c) for _, c in sets)
    print(f"{n} household commands in {len(sets)} files; baseline tree {base}; this tree {ROOT}")
    ours, theirs = [], []
    for r in range(rounds):
        order = [("base", base), ("this", ROOT)] if r % 2 == 0 else [("this", ROOT), ("base", base)]
        for name, tree in order:
            ms = per_command(tree, sets)
            (theirs if name == "base" else ours).append(ms)
            print(f"round {r + 1}: {name:4} {ms:7.1f} ms/command (load {os.getloadavg()[0]:.2f})")
    b, t = sum(theirs) / len(theirs), sum(ours) / len(ours)
    print(f"mean: base {b:.1f} ms/command, this {t:.1f} ms/command, ratio {t / b:.2f}x "
          f"(load average {' / '.join(f'{x:.2f}' for x in os.getloadavg())})")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))

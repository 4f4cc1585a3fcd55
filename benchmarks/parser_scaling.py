#!/usr/bin/env python3
"""How the offline parser's time grows with the command's length (it should grow linearly).

Usage: ``python benchmarks/parser_scaling.py``. Commands of 1, 2, 4, ... 32 sentences of the
same kind, up to the 4000-character cap, are parsed in one run on this machine; the script prints
the time per command and the ratio to the 1-sentence baseline, next to the ratio of lengths, with
the load average (the machine is shared, so compare ratios, not seconds). Exit status 0 always:
this measures, it does not judge.
"""
from __future__ import annotations

import os
import sys
import time
from pathlib import Path

import yaml

ROOT = Path(__file__).resolve().parent.parent
if str(ROOT) not in sys.path:
    sys.path.insert(0, str(ROOT))

from pipflow.warehouse.language.parser import parse  # noqa: E402
from pipflow.warehouse.language.lexicon import MAX_COMMAND_CHARS  # noqa: E402

SENTENCE = "Move 2 product1 from shelf4 to shelf1 and 1 more to shelf2, but robot 3 must not carry product1."
REPEATS = 3


def _best(command: str, world: dict) -> float:
    best = float("inf")
    for _ in range(REPEATS):
        t = time.perf_counter()
        parse(command, world)
        best = min(best, time.perf_counter() - t)
    return best


def main() -> int:
    world = yaml.safe_load((ROOT / "benchmarks" / "warehouse" / "world.yaml").read_text())
    parse(SENTENCE, world)  # builds the parser once, outside the measurement
    base = _best(SENTENCE, world)
    print(f"load average {os.getloadavg()[0]:.2f}; baseline: 1 sentence, {len(SENTENCE)} chars, {base * 1000:.1f} ms")
    print(f"{'sentences':>9} {'chars':>6} {'ms':>9} {'time ratio':>10} {'length ratio':>12}")
    n = 1
    while len(" ".join([SENTENCE] * n)) <= MAX_COMMAND_CHARS:
        command = " ".join([SENTENCE] * n)
        t = _best(command, world)
        print(f"{n:>9} {len(command):>6} {t * 1000:>9.1f} {t / base:>10.2f} {n:>12}")
        n *= 2
    print(f"load average {os.getloadavg()[0]:.2f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())

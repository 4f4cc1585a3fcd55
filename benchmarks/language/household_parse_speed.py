"""Household parse speed: the grammar with only the world's noun twins against the grammar with a
twin for every lexicon class (what the parser built before), in one run on this machine.

A lexicon word that is also a name of the world ("trash", "microwave") is a token with a
``__NOUN`` twin, and every twin is one more alternative wherever a noun may stand; the parser now
builds its grammar with the twins of the world at hand only. This script parses the household
sets' commands with both grammars, interleaved, and prints CPU time per command, the ratio, and
the load average (other work on the machine slows both alike).

    python benchmarks/language/household_parse_speed.py
"""
from __future__ import annotations

import os
import sys
import time
from pathlib import Path

import yaml

from pipflow.household.language.grammar import classes
from pipflow.household.language.parser import _dual_classes, _lark, tag
from pipflow.household.world import load_world

HERE = Path(__file__).resolve().parent
SETS = ["household.yaml", "household-studio.yaml", "household-fresh.yaml", "household-fresh2.yaml",
        "household-fresh3.yaml"]


def commands() -> list[tuple[dict, list]]:
    """(world, tags) of every command the tagger accepts (tagging is the same for both grammars)."""
    out = []
    for name in SETS:
        data = yaml.safe_load((HERE / name).read_text(encoding="utf-8"))
        world = load_world((HERE / data["world"]).resolve())
        for task in data["tasks"]:
            try:
                out.append((world, tag(task["command"], world)))
            except Exception:  # refused by the tagger: no parse to time
                continue
    return out


def cpu_per_parse(items: list[tuple[dict, list]], every_twin: bool) -> float:
    start = time.process_time()
    for world, tags in items:
        parser = _lark(frozenset(classes()) if every_twin else _dual_classes(world))
        try:
            parser.parse(tags)
        except Exception:  # a command the grammar rejects costs its failed parse all the same
            pass
    return (time.process_time() - start) / len(items)


def main() -> int:
    items = commands()
    for world, _ in items:   # build both grammars before timing
        _lark(_dual_classes(world))
    _lark(frozenset(classes()))
    every, own = [], []
    for _ in range(2):
        every.append(cpu_per_parse(items, True))
        own.append(cpu_per_parse(items, False))
    a, b = min(every), min(own)
    print(f"{len(items)} commands; CPU per parse: every twin {a * 1000:.1f} ms, the world's twins {b * 1000:.1f} ms; "
          f"ratio {a / b:.2f}x; load average {os.getloadavg()[0]:.2f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())

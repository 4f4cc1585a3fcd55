#!/usr/bin/env python3
"""Share of a task file's commands that the offline translator turns into the exact gold.

Usage: ``python benchmarks/translator.py [TASKS.yaml]`` (default: the paper's warehouse tasks).
The world path in the task file is relative to it. A task counts as exact when the goal equals
the gold goal and the constraints equal the gold constraints (missing means none); commands
marked ``feasible: false`` count when the translator refuses them or yields the gold.
Exits 0 when every command is exact, 1 otherwise, so CI can use it as a check.
"""
from __future__ import annotations

import sys
import time
from pathlib import Path

import yaml

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from pipflow.errors import PipflowError, Refusal  # noqa: E402
from pipflow.language.translator import translate  # noqa: E402


def _norm(constraints: list[dict] | None) -> list[dict]:
    """Constraints compared as data: robots as sorted lists, item order kept."""
    return [{k: (sorted(v) if isinstance(v, list) else v) for k, v in c.items()}
            for c in constraints or []]


def main(argv: list[str]) -> int:
    tasks_path = Path(argv[0]) if argv else ROOT / "benchmarks" / "warehouse" / "tasks.yaml"
    spec = yaml.safe_load(tasks_path.read_text())
    world = yaml.safe_load((tasks_path.parent / spec["world"]).read_text())
    exact = 0
    started = time.perf_counter()
    for task in spec["tasks"]:
        try:
            got = translate(task["command"], world)
        except Refusal as exc:
            ok = task.get("feasible", True) is False
            print(f"{'ok  ' if ok else 'FAIL'} {task['id']}: refused: {exc}")
            exact += ok
            continue
        except PipflowError as exc:
            print(f"FAIL {task['id']}: {type(exc).__name__}: {exc}")
            continue
        ok = got["goal"] == task["goal"] and _norm(got["constraints"]) == _norm(task.get("constraints"))
        exact += ok
        if ok:
            print(f"ok   {task['id']}")
        else:
            print(f"FAIL {task['id']}: got {got}, gold goal {task['goal']}, "
                  f"gold constraints {task.get('constraints', [])}")
    n = len(spec["tasks"])
    if n:
        print(f"mean time per command: {(time.perf_counter() - started) / n * 1000:.2f} ms")
    print(f"exact goal and constraints: {exact}/{n} = {exact / n:.0%}" if n else "no tasks")
    return 0 if exact == n else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))

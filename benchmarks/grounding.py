"""Measure grounded decoding: free PDDL answers vs grammar-constrained answers, same model.

    python benchmarks/grounding.py [--model local/smollm2] [--api-base URL] [--no-cache]
                                   [--modes free,grounded] [--limit N]

For each paper task it asks the model twice (free text, then grounded: an order, see
pipflow/warehouse/language/grounding.py) and reports per mode the share of answers that yield a problem,
that name only the world's objects (the paper's failure: ``prodcut3`` invented as a new
product), whose counts fit the shelves, and whose goal is exactly the gold one; for grounded
answers also the share that are complete JSON of the order schema; plus tokens and latency. Default model ``local/smollm2`` starts a llama.cpp server
on loopback (extra ``pipflow[local]``). Responses are cached (``--cache-dir``), so a second run
replays without the model.
"""
from __future__ import annotations

import argparse
import json
import os
import re
import sys
from pathlib import Path

import yaml

HERE = Path(__file__).resolve().parent
_GOAL = re.compile(r"\(\s*=\s*\(\s*stock\s+([^\s()]+)\s+([^\s()]+)\s*\)\s*(-?\d+)\s*\)", re.I)


def goal_of(problem: str) -> dict[str, dict[str, int]]:
    """The ``(= (stock s p) n)`` facts of a problem's :goal section, read leniently."""
    i = problem.lower().find("(:goal")
    goal: dict[str, dict[str, int]] = {}
    for s, p, n in _GOAL.findall(problem[i:] if i >= 0 else ""):
        goal.setdefault(s, {})[p] = int(n)
    return goal


def score(out: dict, gold: dict, world: dict) -> dict[str, bool]:
    goal = out["goal"] if out.get("goal") is not None else goal_of(out["problem"])
    names = {s for s in goal} | {p for items in goal.values() for p in items}
    known = set(world["shelves"]) | set(world["products"])
    fits = all(s in world["shelves"] and all(0 <= v <= world["shelves"][s]["capacity"] for v in
                                             ([n] if isinstance(n, int) else n.values()))
               for s, items in goal.items() for n in items.values())
    return {"problem": bool(out["problem"]) and bool(goal), "invented": bool(names - known),
            "bad_counts": bool(goal) and not fits, "exact_goal": goal == gold,
            "order": is_order(out["response"]) if out.get("order") is not None or out.get("goal") is not None
            or out["response"].lstrip().startswith("{") else False}


def is_order(text: str) -> bool:
    """Whether an answer is complete JSON of the order schema (rule scopes "any" dropped)."""
    from pipflow.errors import TranslationError
    from pipflow.warehouse.language.order import validate_order

    try:
        data = json.loads(text)
        data["rules"] = [{k: v for k, v in r.items() if v != "any"} for r in data.get("rules") or []]
        validate_order(data)
    except (ValueError, TypeError, AttributeError, TranslationError):
        return False
    return True


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--tasks", default=str(HERE / "warehouse/tasks.yaml"))
    ap.add_argument("--model", default="local/smollm2")
    ap.add_argument("--api-base", default=None)
    ap.add_argument("--max-tokens", type=int, default=384)
    ap.add_argument("--cache-dir", default=None)
    ap.add_argument("--no-cache", action="store_true")
    ap.add_argument("--prompt", default="warehouse_problem")
    ap.add_argument("--modes", default="free,grounded", help="comma-separated: free, grounded")
    ap.add_argument("--limit", type=int, default=None, help="only the first N tasks")
    args = ap.parse_args(argv)

    from pipflow.language.cache import ResponseCache
    from pipflow.language.asking import ModelCall, RoundRecord
    from pipflow.language.generator import generate
    from pipflow.language.llm import Retry
    from pipflow.language.llm import sum_usage

    tasks_file = Path(args.tasks)
    spec = yaml.safe_load(tasks_file.read_text())
    world_path = tasks_file.parent / spec["world"]
    world = yaml.safe_load(world_path.read_text())
    world["stock"] = {s: dict(world.get("stock", {}).get(s) or {}) for s in world["shelves"]}
    domain = (HERE.parent / "domains/warehouse.pddl").read_text()

    modes = [m for m in args.modes.split(",") if m]
    rows: dict[str, list[dict]] = {m: [] for m in modes}
    usages: dict[str, list[dict]] = {m: [] for m in modes}
    tasks = [t for t in spec["tasks"] if t.get("feasible", True)][:args.limit]
    for task in tasks:
        for mode in rows:
            out = generate(task["command"], world, domain, prompt=args.prompt,
                           call=ModelCall(model=args.model, api_base=args.api_base, max_tokens=args.max_tokens,
                                          grounded=mode == "grounded", retry=Retry(timeout=300)),
                           record=RoundRecord(cache=None if args.no_cache else ResponseCache(args.cache_dir)))
            rows[mode].append(score(out, task["goal"], world))
            usages[mode].append(out["usage"])
            print(f"{task['id']} {mode:8s} {rows[mode][-1]}", file=sys.stderr)

    n = len(tasks)
    print(f"model {args.model}, prompt {args.prompt}, {n} tasks ({tasks_file}), "
          f"load average {os.getloadavg()[0]:.2f}")
    print("problem: answers that yield a goal; invented: answers naming a shelf or product the world "
          "lacks; bad counts: a count outside 0..capacity; exact: the gold goal; order: complete JSON "
          "of the order schema")
    print(f"{'mode':9s} {'problem':>8s} {'invented':>9s} {'bad counts':>11s} {'exact':>6s} {'order':>6s} "
          f"{'tokens':>7s} {'latency s':>10s} {'cached':>7s}")
    for mode, r in rows.items():
        u = sum_usage(usages[mode])
        count = {k: sum(x[k] for x in r) for k in r[0]}
        print(f"{mode:9s} {count['problem']:5d}/{n} {count['invented']:6d}/{n} {count['bad_counts']:8d}/{n} "
              f"{count['exact_goal']:3d}/{n} {count['order']:3d}/{n} {u['total_tokens']:7d} {u['latency_s']:10.1f} "
              f"{u['cached']:4d}/{n}")
    return 0


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/env python3
"""The refinement loop with a real local model (issue 17): how many rounds, how many wasted.

Usage::

    python benchmarks/llm_loop.py [--model local/smollm2] [--modes free,grounded]
                                  [--workflow pip-llm-checked] [--tasks wh-01,wh-05] [--rounds 4]
                                  [--out DIR] [--json FILE]

Each task of ``benchmarks/warehouse/tasks.yaml`` (the paper's ten) runs through a real warehouse
workflow (``pipflow.run``, no cache, so every round calls the model): the checked loop
(``pip-llm-checked``, the default here) or the paper's (``--workflow pip-llm``), once per mode,
free (the model writes PDDL) and grounded (the model answers JSON under a grammar). From each
run's record it reads, per round, the prompt as sent (``messages.json``), the request's
temperature and what the generator varied, and prints per mode:

* ``rounds``: rounds used, in all and per run;
* ``repeats``: rounds whose prompt (and temperature) is byte-identical to an earlier round's of
  the same run: a wasted round at temperature 0 (target 0);
* ``refused feasible``: runs refused although the task is feasible (target 0);
* ``accepted disagreeing``: runs that succeeded with a goal or rules different from the offline
  reading of the command (or from the task's gold where the parser does not read it) (target 0);
* ``succeeded``, ``failed``, the calls that ran to their token budget (``finish_reason`` length),
  and the mean latency and completion tokens per call.

The machine's load average (``os.getloadavg()``) is printed with the table: the latencies mean
little without it. Nothing here is asserted by a test; the model is far too small to be right
often: the loop's behaviour, not the model's accuracy, is what this measures.
"""
from __future__ import annotations

import argparse
import hashlib
import json
import os
import sys
import tempfile
import time
from pathlib import Path
from typing import Any

import yaml

ROOT = Path(__file__).resolve().parent.parent
if str(ROOT) not in sys.path:
    sys.path.insert(0, str(ROOT))

import pipflow  # noqa: E402
from pipflow.language.agreement import offline_reading  # noqa: E402
from pipflow.warehouse.agreement import compare_with_reading  # noqa: E402
from pipflow.warehouse.world import load_world  # noqa: E402

TASKS = ROOT / "benchmarks" / "warehouse" / "tasks.yaml"


def _read(path: Path, default: Any = None) -> Any:
    try:
        return json.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return default


def rounds_of(record: Path) -> list[dict]:
    """Per round of loop ``refine``: the sent prompt's digest (with the temperature), what was
    varied, the call's usage, and whether the checks passed."""
    out = []
    folder = record / "steps" / "refine" / "iterations"
    for it in sorted(folder.glob("*"), key=lambda p: int(p.name) if p.name.isdigit() else 0):
        gen = _read(it / "generate" / "outputs.json", {}) or {}
        messages = gen.get("messages") or _read(it / "generate" / "artifacts" / "messages.json", [])
        usage = gen.get("usage") or {}
        round_ = gen.get("round") or {}
        digest = round_.get("sent") or hashlib.sha256(json.dumps(messages).encode()).hexdigest()[:16]
        out.append({"n": int(it.name), "sent": digest, "varied": gen.get("varied") or "",
                    "latency_s": usage.get("latency_s"), "completion_tokens": usage.get("completion_tokens"),
                    "finish_reason": usage.get("finish_reason"), "max_tokens": round_.get("max_tokens"),
                    "errors": gen.get("errors") or []})
    return out


def judge(task: dict, world: dict, result: Any) -> dict:
    """One run's row: status, rounds, repeats, and whether an accepted goal disagrees."""
    rounds = rounds_of(Path(result.record))
    seen, repeats = set(), 0
    for r in rounds:
        repeats += r["sent"] in seen
        seen.add(r["sent"])
    feasible = task.get("feasible", True) is not False
    disagree: list[str] = []
    if result.status == "succeeded":
        goal, rules = result.outputs.get("goal") or {}, result.outputs.get("constraints") or []
        state, reading = offline_reading(task["command"], world)
        if state != "read":  # the parser does not read it: the task's gold is the reference
            reading = {"goal": task.get("goal") or {}, "constraints": task.get("constraints") or []}
        disagree = [f.said for f in compare_with_reading(task["command"], goal, rules, reading, world)]
    return {"task": task["id"], "status": result.status, "rounds": len(rounds), "repeats": repeats,
            "refused_feasible": result.status == "refused" and feasible,
            "accepted_disagreeing": bool(disagree), "disagreement": disagree,
            "warned": bool(result.outputs.get("disagreement")) if result.status == "succeeded" else False,
            "varied": [r["varied"] for r in rounds if r["varied"]],
            "calls": [{k: r[k] for k in ("latency_s", "completion_tokens", "finish_reason", "max_tokens")}
                      for r in rounds],
            "error": (result.error or "")[:300]}


def summary(rows: list[dict]) -> dict:
    calls = [c for r in rows for c in r["calls"] if c.get("latency_s") is not None]
    rounds = sum(r["rounds"] for r in rows)
    return {
        "runs": len(rows), "rounds": rounds, "rounds_per_run": round(rounds / max(1, len(rows)), 2),
        "repeats": sum(r["repeats"] for r in rows),
        "repeat_share": round(sum(r["repeats"] for r in rows) / max(1, rounds), 3),
        "refused_feasible": sum(r["refused_feasible"] for r in rows),
        "accepted_disagreeing": sum(r["accepted_disagreeing"] for r in rows),
        "succeeded": sum(r["status"] == "succeeded" for r in rows),
        "refused": sum(r["status"] == "refused" for r in rows),
        "failed": sum(r["status"] == "failed" for r in rows),
        "varied_rounds": sum(len(r["varied"]) for r in rows),
        "calls_at_budget": sum(c.get("finish_reason") == "length" for c in calls),
        "mean_latency_s": round(sum(c["latency_s"] for c in calls) / max(1, len(calls)), 2),
        "mean_completion_tokens": round(sum(c.get("completion_tokens") or 0 for c in calls) / max(1, len(calls)), 1),
    }


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--model", default="local/smollm2")
    ap.add_argument("--modes", default="free,grounded")
    ap.add_argument("--workflow", default="pip-llm-checked", help="pip-llm (the paper's loop) or pip-llm-checked")
    ap.add_argument("--tasks", default="", help="comma-separated task ids (default: all ten)")
    ap.add_argument("--rounds", type=int, default=4)
    ap.add_argument("--out", default="", help="runs folder (default: a temporary one)")
    ap.add_argument("--json", default="", help="write the rows and summaries here")
    ap.add_argument("--llm-timeout", type=float, default=600, help="seconds per request (a CPU model under load is slow)")
    ap.add_argument("--llm-deadline", type=float, default=900, help="seconds per call, retries included")
    args = ap.parse_args(argv)
    os.environ.setdefault("OPENAI_API_KEY", "no-key")  # a loopback server needs none
    spec = yaml.safe_load(TASKS.read_text(encoding="utf-8"))
    world = load_world(TASKS.parent / spec["world"])
    wanted = [t for t in args.tasks.split(",") if t]
    tasks = [t for t in spec["tasks"] if not wanted or t["id"] in wanted]
    runs_dir = Path(args.out or tempfile.mkdtemp(prefix="llm-loop-"))
    load_before = os.getloadavg()
    report: dict[str, Any] = {"model": args.model, "workflow": args.workflow, "rounds": args.rounds, "load_before": load_before, "modes": {}}
    started = time.perf_counter()
    for mode in [m for m in args.modes.split(",") if m]:
        rows = []
        for task in tasks:
            t0 = time.perf_counter()
            result = pipflow.run(args.workflow, command=task["command"], model=args.model, grounded=(mode == "grounded"),
                                 rounds=args.rounds, cache=False, runs_dir=runs_dir / mode,
                                 llm_timeout=args.llm_timeout, llm_deadline=args.llm_deadline)
            row = judge(task, world, result)
            row["seconds"] = round(time.perf_counter() - t0, 1)
            rows.append(row)
            print(f"{mode:8s} {task['id']}: {row['status']:9s} rounds {row['rounds']} repeats {row['repeats']} "
                  f"varied {row['varied'] or '-'} {row['seconds']} s"
                  + (f" DISAGREES: {row['disagreement'][:2]}" if row["accepted_disagreeing"] else "")
                  + (f" | {row['error'][:160]}" if row["status"] != "succeeded" else ""), flush=True)
        report["modes"][mode] = {"summary": summary(rows), "rows": rows}
    report["load_after"] = os.getloadavg()
    report["seconds"] = round(time.perf_counter() - started, 1)
    print(f"\nmodel {args.model}, workflow {args.workflow}, {len(tasks)} task(s), at most {args.rounds} rounds; load average "
          f"{load_before[0]:.1f} before, {report['load_after'][0]:.1f} after; {report['seconds']} s in all")
    keys = ["runs", "rounds", "rounds_per_run", "repeats", "repeat_share", "refused_feasible",
            "accepted_disagreeing", "succeeded", "refused", "failed", "varied_rounds", "calls_at_budget",
            "mean_latency_s", "mean_completion_tokens"]
    print(f"{'':24s}" + "".join(f"{m:>12s}" for m in report["modes"]))
    for k in keys:
        print(f"{k:24s}" + "".join(f"{report['modes'][m]['summary'][k]!s:>12s}" for m in report["modes"]))
    print(f"runs: {runs_dir}")
    if args.json:
        Path(args.json).write_text(json.dumps(report, indent=2, default=str), encoding="utf-8")
    return 0


if __name__ == "__main__":
    sys.exit(main())

"""Team-level plan quality and planning time on the paper's warehouse tasks, and at scale.

For each paper task: the default planner's plan length, the fewest moves (an order-free integer
program, SCIP; a lower bound on every plan, so a plan that reaches it is proven optimal), a cheap
lower bound (per-cell ceil(units / 6), blind to capacity), the ratio plan / fewest, the solve
time, and ENHSP's default search (gbfs + hadd) for comparison. Then a generated instance of
50 shelves x 10 products with 2000 units moved (target: under 30 s).

    python benchmarks/team_plans.py [--no-enhsp] [--enhsp-scale]
"""
from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
if str(ROOT) not in sys.path:
    sys.path.insert(0, str(ROOT))

from pipflow.pddl.bounds import ceil_bound, fewest_moves  # noqa: E402
from pipflow.pddl.common import parse  # noqa: E402
from pipflow.pddl.generate import scale_instance  # noqa: E402
from pipflow.pddl.solver import DEFAULT_ENGINE, solve_problem  # noqa: E402
from pipflow.pddl.transport import instance_from_problem  # noqa: E402
from pipflow.pddl.verifier import verify_plan  # noqa: E402
from pipflow.pddl.writer import write_problem  # noqa: E402
from pipflow.world import load_tasks  # noqa: E402

DOMAIN = str(ROOT / "domains/warehouse.pddl")


def run_task(world: dict, goal: dict, enhsp: bool) -> dict:
    problem = parse(DOMAIN, write_problem(world, goal))
    inst = instance_from_problem(problem)
    res = solve_problem(problem, DEFAULT_ENGINE)
    valid = res.plan is not None and verify_plan(problem, res.plan, world).ok
    best, proven = fewest_moves(inst, time_limit=60)
    row = {"plan": len(res.plan) if res.plan else None, "valid": valid, "fewest": best, "proven": proven,
           "bound": ceil_bound(inst), "time": res.time}
    row["ratio"] = row["plan"] / best if row["plan"] and best else None
    if enhsp:
        e = solve_problem(problem, "enhsp", timeout=120)
        row["enhsp"] = len(e.plan) if e.plan else e.status
        row["enhsp_time"] = e.time
    return row


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--no-enhsp", action="store_true", help="skip the ENHSP comparison column")
    ap.add_argument("--enhsp-scale", action="store_true", help="also run ENHSP on an 8 x 6 x 120 instance")
    args = ap.parse_args(argv)
    tasks = load_tasks(ROOT / "benchmarks/warehouse/tasks.yaml")
    enhsp = not args.no_enhsp
    print(f"default planner: {DEFAULT_ENGINE}; fewest = order-free IP optimum (* = proven); "
          f"bound = ceil(units/6) per cell")
    head = f"{'task':8}{'plan':>6}{'fewest':>8}{'bound':>7}{'ratio':>7}{'time s':>9}"
    head += f"{'enhsp':>7}{'enhsp s':>9}" if enhsp else ""
    print(head)
    print("-" * len(head))
    worst = 0.0
    for task in tasks["tasks"]:
        r = run_task(tasks["world"], task["goal"], enhsp)
        worst = max(worst, r["ratio"] or 0)
        ratio = f"{r['ratio']:.2f}" if r["ratio"] else "-"
        line = (f"{task['id']:8}{r['plan']!s:>6}{(str(r['fewest']) + ('*' if r['proven'] else '')):>8}"
                f"{r['bound']:>7}{ratio:>7}"
                f"{r['time']:>9.3f}")
        if enhsp:
            line += f"{r['enhsp']!s:>7}{r['enhsp_time']:>9.2f}"
        print(line + ("" if r["valid"] else "  INVALID"))
    print(f"worst ratio plan/fewest: {worst:.3f} (target <= 1.05)")

    world, goal = scale_instance(50, 10, 2000)
    t0 = time.monotonic()
    problem = parse(DOMAIN, write_problem(world, goal))
    t_parse = time.monotonic() - t0
    res = solve_problem(problem, DEFAULT_ENGINE, timeout=30)
    t1 = time.monotonic()
    ok = res.plan is not None and verify_plan(problem, res.plan, world).ok
    t_verify = time.monotonic() - t1
    bound = ceil_bound(instance_from_problem(problem))
    units = sum(int(s["args"][3][len("magnitude"):]) for s in res.plan or [])
    print(f"\nscale 50 shelves x 10 products, 2000 units transferred to make the goal: "
          f"{res.status}, {len(res.plan or [])} moves carrying {units} units (bound {bound}, "
          f"ratio {len(res.plan or []) / bound:.3f}); parse {t_parse:.2f} s, solve {res.time:.2f} s "
          f"(incl. UP validation), verify {t_verify:.2f} s, valid={ok}; "
          f"total {t_parse + res.time + t_verify:.2f} s (target < 30 s)")
    if args.enhsp_scale:
        world, goal = scale_instance(8, 6, 120, capacity=60, seed=1)
        problem = parse(DOMAIN, write_problem(world, goal))
        for engine in (DEFAULT_ENGINE, "enhsp"):
            r = solve_problem(problem, engine, timeout=120)
            print(f"8 x 6 x 120 with {engine}: {r.status}, {len(r.plan or [])} moves, {r.time:.2f} s")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())

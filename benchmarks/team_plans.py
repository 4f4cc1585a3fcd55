"""Team-level plan quality and planning time: the paper's tasks, a capacity-tight suite, scale.

For each paper task: the default planner's plan length, the fewest moves (an order-free integer
program, SCIP; a lower bound on every plan, so a plan that reaches it is proven optimal), a cheap
lower bound (per-cell ceil(units / 6), blind to capacity), the ratio plan / fewest, the solve
time, and ENHSP's default search (gbfs + hadd) for comparison.

Then the **capacity-tight suite**: 36 generated instances in six families (swaps of two full
shelves, cycles of 3-4 full shelves, full shelves whose contents were exchanged unit by unit,
the same with a single free unit in the whole warehouse, bounds goals on full shelves, and a
weak team whose moves carry at most 3 units). Each row: the planner's plan (through the real
UP engine, validated), the flow plan alone (search budget 0), the order-free IP bound, the
fewest moves under capacity from an exact method (an A* over stock states with an admissible
bound, run to the end: a proven optimum; tests/test_transport.py checks it against a plain
breadth-first search), plan / optimum (target <= 1.05 on every one), and ENHSP's plan
length and its ratio to ours (``enhsp`` = gbfs + hadd, ``enhsp-opt`` = A* with an admissible
heuristic where it finishes within the timeout).

Last, a generated instance of 50 shelves x 10 products with 2000 units moved (target: under 30 s).
The load average is printed at the start and the end (2 shared cores: timings are indicative,
ratios are measured in the same run).

    python benchmarks/team_plans.py [--no-enhsp] [--enhsp-timeout S] [--only-tight] [--enhsp-scale]
"""
from __future__ import annotations

import argparse
import os
import random
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
if str(ROOT) not in sys.path:
    sys.path.insert(0, str(ROOT))

from pipflow.warehouse.bounds import ceil_bound, fewest_moves  # noqa: E402
from pipflow.pddl.common import parse  # noqa: E402
from pipflow.warehouse.generate import scale_instance  # noqa: E402
from pipflow.pddl.solver import DEFAULT_ENGINE, solve_problem  # noqa: E402
from pipflow.warehouse.bounds import exact_moves  # noqa: E402
from pipflow.warehouse.planner import flow_plan, instance_from_problem  # noqa: E402
from pipflow.pddl.verifier import verify_plan  # noqa: E402
from pipflow.warehouse.problem import write_problem  # noqa: E402
from pipflow.warehouse.world import load_tasks  # noqa: E402

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


# ------------------------------------------------------------------------------ capacity-tight suite
def _world(caps: dict[str, int], stock: dict[str, dict[str, int]], products: list[str], carry: int = 6) -> dict:
    shelves = {s: {"x": 10 * i + 1, "y": 4, "width": 8, "depth": 2, "capacity": c, "access": [10 * i + 5, 3]}
               for i, (s, c) in enumerate(caps.items())}
    return {"name": "tight", "path": "<generated>", "floor": {"width": 10 * len(caps) + 2, "height": 10},
            "shelves": shelves, "products": {p: {"color": "grey"} for p in products},
            "stock": {s: {p: n for p, n in stock.get(s, {}).items() if n} for s in caps},
            "robots": {"robot0": {"start": [0, 0], "skills": {"carry": carry}}}}


def _swap(rng: random.Random) -> tuple[dict, dict]:
    n, free = rng.randint(3, 8), rng.randint(1, 3)
    caps = {"s1": n, "s2": n, "s3": free} if rng.random() < 0.5 else {"s1": n + free, "s2": n}
    world = _world(caps, {"s1": {"a": n}, "s2": {"b": n}}, ["a", "b"])
    return world, {"s1": {"b": n}, "s2": {"a": n}}


def _cycle(rng: random.Random) -> tuple[dict, dict]:
    k, n, free = rng.choice([3, 4]), rng.randint(2, 6), rng.randint(1, 2)
    shelves = [f"s{i + 1}" for i in range(k)]
    products = [f"p{i + 1}" for i in range(k)]
    caps = dict.fromkeys(shelves, n) | {"buffer": free}
    world = _world(caps, {s: {products[i]: n} for i, s in enumerate(shelves)}, products)
    return world, {s: {products[(i + 1) % k]: n} for i, s in enumerate(shelves)}


def _shuffled(rng: random.Random, free: int, shelves: int, products: int, carry: int = 6,
              bounds: bool = False) -> tuple[dict, dict]:
    """Full shelves (``free`` units of room in all) whose contents rotate by one shelf (half the
    time), then are exchanged by random unit swaps."""
    cap = rng.randint(5, 8)
    S = [f"s{i + 1}" for i in range(shelves)]
    P = [f"p{j + 1}" for j in range(products)]
    stock = {s: dict.fromkeys(P, 0) for s in S}
    load = dict.fromkeys(S, 0)
    for _ in range(cap * shelves - free):
        s = rng.choice([x for x in S if load[x] < cap])
        stock[s][rng.choice(P)] += 1
        load[s] += 1
    order = S[1:] + S[:1] if rng.random() < 0.5 else S[:]  # half the time the shelves' contents rotate
    final = {t: dict(stock[s]) for s, t in zip(S, order)}
    while sum(abs(final[s][p] - stock[s][p]) for s in S for p in P) < 2 * shelves:  # a real rearrangement
        s, t = rng.sample(S, 2)
        ps, qs = [p for p in P if final[s][p]], [q for q in P if final[t][q]]
        p, q = rng.choice(ps), rng.choice(qs)
        if p != q:
            final[s][p] -= 1
            final[t][p] += 1
            final[t][q] -= 1
            final[s][q] += 1
    goal: dict = {}
    for s in S:
        for p in P:
            if final[s][p] == stock[s][p] and rng.random() < 0.5:
                continue  # unchanged cells are listed only sometimes
            n = final[s][p]
            if bounds and n != stock[s][p]:
                goal.setdefault(s, {})[p] = {"at_least": n} if n > stock[s][p] else {"at_most": n}
            else:
                goal.setdefault(s, {})[p] = n
    return _world(dict.fromkeys(S, cap), stock, P, carry), goal


FAMILIES = {
    "swap": _swap,
    "cycle": _cycle,
    "full": lambda rng: _shuffled(rng, rng.randint(2, 4), rng.randint(4, 5), rng.randint(2, 3)),
    "one-free": lambda rng: _shuffled(rng, 1, rng.randint(3, 4), rng.randint(2, 3)),
    "bounds": lambda rng: _shuffled(rng, rng.randint(1, 2), rng.randint(3, 4), 2, bounds=True),
    "weak-team": lambda rng: _shuffled(rng, rng.randint(1, 2), 3, 2, carry=3),
}


def tight_suite(per_family: int = 6, seed: int = 15) -> list[tuple[str, dict, dict]]:
    """``[(label, world, goal)]``: the capacity-tight instances, deterministic for a seed."""
    rng = random.Random(seed)
    return [(f"{name}-{i + 1}", *make(rng)) for name, make in FAMILIES.items() for i in range(per_family)]


def run_tight(enhsp: bool, enhsp_timeout: float) -> bool:
    print("\ncapacity-tight suite: plan = pipflow-transport (UP engine, validated); flow = its flow plan "
          "without search; ip = order-free bound; opt = fewest moves under capacity (exact A*, proven)")
    head = f"{'instance':13}{'plan':>5}{'flow':>5}{'ip':>4}{'opt':>5}{'plan/opt':>9}{'time s':>8}"
    if enhsp:
        head += f"{'enhsp':>7}{'enhsp/plan':>11}{'opt-pl':>7}{'opt/plan':>9}"
    print(head)
    print("-" * len(head))
    ratios, vs_enhsp, vs_opt, ok = [], [], [], True
    for label, world, goal in tight_suite():
        problem = parse(DOMAIN, write_problem(world, goal))
        inst = instance_from_problem(problem)
        res = solve_problem(problem, DEFAULT_ENGINE, timeout=60)
        valid = res.plan is not None and verify_plan(problem, res.plan, world).ok
        flow = len(flow_plan(inst))
        ip, _ = fewest_moves(inst, time_limit=30)
        opt, proven = exact_moves(inst, time_limit=120)
        plan = len(res.plan) if res.plan is not None else None
        ratio = plan / opt if plan is not None and opt else (1.0 if plan == opt == 0 else None)
        ratios.append(ratio)
        ok &= bool(valid and proven and ratio is not None and ratio <= 1.05)
        line = (f"{label:13}{plan!s:>5}{flow:>5}{ip!s:>4}{(str(opt) + ('' if proven else '?')):>5}"
                f"{(f'{ratio:.3f}' if ratio else '-'):>9}{res.time:>8.2f}")
        if enhsp:
            for engine in ("enhsp", "enhsp-opt"):
                e = solve_problem(problem, engine, timeout=enhsp_timeout)
                n = len(e.plan) if e.plan is not None else None
                if n is not None and plan:
                    (vs_enhsp if engine == "enhsp" else vs_opt).append(n / plan)
                line += f" {(n if n is not None else e.status[:7])!s:>6}" + \
                        f"{(f'{n / plan:.3f}' if n is not None and plan else '-'):>{11 if engine == 'enhsp' else 9}}"
        print(line + ("" if valid else "  INVALID"), flush=True)
    good = [r for r in ratios if r is not None]
    print(f"plan/opt: worst {max(good):.3f}, mean {sum(good) / len(good):.3f} over {len(good)}/{len(ratios)} "
          f"instances (target <= 1.05 on every one): {'met' if ok else 'NOT met'}")
    if enhsp:
        for name, xs in (("enhsp", vs_enhsp), ("enhsp-opt", vs_opt)):
            if xs:
                print(f"{name} plan length / ours: mean {sum(xs) / len(xs):.3f}, min {min(xs):.3f}, "
                      f"max {max(xs):.3f} over the {len(xs)} instances it solved within {enhsp_timeout:g} s")
            else:
                print(f"{name}: no plan within {enhsp_timeout:g} s on any instance")
    return ok


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--no-enhsp", action="store_true", help="skip the ENHSP comparison column")
    ap.add_argument("--enhsp-scale", action="store_true", help="also run ENHSP on an 8 x 6 x 120 instance")
    ap.add_argument("--enhsp-timeout", type=float, default=20.0, help="seconds per ENHSP run on the tight suite")
    ap.add_argument("--only-tight", action="store_true", help="only the capacity-tight suite")
    args = ap.parse_args(argv)
    print(f"load average at start: {os.getloadavg()[0]:.2f} (2 shared cores)")
    if args.only_tight:
        ok = run_tight(not args.no_enhsp, args.enhsp_timeout)
        print(f"load average at end: {os.getloadavg()[0]:.2f}")
        return 0 if ok else 1
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
    ok = run_tight(enhsp, args.enhsp_timeout)

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
    print(f"load average at end: {os.getloadavg()[0]:.2f}")
    return 0 if ok else 1


if __name__ == "__main__":
    raise SystemExit(main())

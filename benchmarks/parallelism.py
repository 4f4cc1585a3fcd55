"""Parallelism won by the dependency graph: makespan of the minimal deordering vs the exact
read/write graph vs the paper's Alg. 2, on the paper's ten tasks and on a scaled suite.

For every task: the team plan (pipflow-transport), one graph per mode, the paper's per-subtask
SCIP allocation and the Alg. 1 schedule (the same code a `pipflow run` uses), and the makespan.
Every graph is validated the way a robot team would feel it: each allowed order of the subtasks
is replayed with unified-planning's sequential simulator against the team-level problem (stock
never below what a move takes, no shelf over capacity). All orders when a graph allows at most
``--all-orders`` of them, otherwise ``--samples`` random ones (a random ready subtask at each
step). A graph that allows an invalid order is marked INVALID (the paper's Alg. 2 can: it keeps
only one parent).

Scaled suite: generated warehouses (8-16 shelves, 4-6 products, 12-24 robots carrying 1-3 units,
60-200 units moved), where many moves share shelves: the case the read/write graph chains.
Target: mean makespan ratio deorder / exact <= 0.80 (at least 20% lower).

    python benchmarks/parallelism.py [--samples 60] [--all-orders 2000] [--only paper|scaled]

Prints the load average at the start and the end; ratios are measured in the same run.
"""
from __future__ import annotations

import argparse
import itertools
import os
import random
import statistics
import sys
import time
from pathlib import Path

import networkx as nx
import yaml

ROOT = Path(__file__).resolve().parents[1]
if str(ROOT) not in sys.path:
    sys.path.insert(0, str(ROOT))

from pipflow.team.allocation import allocate  # noqa: E402
from pipflow.team.dependency import build_graph, to_networkx  # noqa: E402
from pipflow.pddl.common import parse  # noqa: E402
from pipflow.warehouse.generate import scale_instance  # noqa: E402
from pipflow.pddl.solver import solve_problem  # noqa: E402
from pipflow.warehouse.problem import write_problem  # noqa: E402
from pipflow.team.scheduling import build_schedule  # noqa: E402
from pipflow.warehouse.world import load_tasks  # noqa: E402

DOMAIN_PATH = ROOT / "domains" / "warehouse.pddl"
META = yaml.safe_load((ROOT / "domains" / "warehouse.actions.yaml").read_text())
MODES = ("exact", "deorder", "paper")


def orders(graph: dict, all_limit: int, samples: int, rng: random.Random) -> tuple[list[list[str]], bool]:
    """``(orders, exhaustive)``: every linearization if there are at most ``all_limit``, else
    ``samples`` random ones."""
    g = to_networkx(graph)
    first = list(itertools.islice(nx.all_topological_sorts(g), all_limit + 1))
    if len(first) <= all_limit:
        return first, True
    out = []
    for _ in range(samples):
        indeg = {n: g.in_degree(n) for n in g}
        ready = [n for n, d in indeg.items() if d == 0]
        order = []
        while ready:
            n = ready.pop(rng.randrange(len(ready)))
            order.append(n)
            for m in g.successors(n):
                indeg[m] -= 1
                if indeg[m] == 0:
                    ready.append(m)
        out.append(order)
    return out, False


def invalid_orders(problem, plan: list[dict], graph: dict, order_list: list[list[str]]) -> int:
    """How many of the orders fail a precondition in UP's sequential simulator."""
    from unified_planning.engines import UPSequentialSimulator

    sim = UPSequentialSimulator(problem, error_on_failed_checks=False)
    index = {n["id"]: n["index"] for n in graph["nodes"]}
    ground = [(problem.action(a["action"]), [problem.object(x.lower()) for x in a["args"]]) for a in plan]
    bad = 0
    for order in order_list:
        state = sim.get_initial_state()
        for node in order:
            act, objs = ground[index[node]]
            if not sim.is_applicable(state, act, objs):
                bad += 1
                break
            state = sim.apply(state, act, objs)
    return bad


def measure(world: dict, goal: dict, args, rng: random.Random) -> dict | None:
    text = write_problem(world, goal)
    problem = parse(str(DOMAIN_PATH), text)
    res = solve_problem(problem, "pipflow-transport", timeout=120)
    if res.plan is None:
        return None
    domain_text = DOMAIN_PATH.read_text()
    row = {"moves": len(res.plan)}
    for mode in MODES:
        graph = build_graph(domain_text, text, res.plan, META, mode)
        alloc = allocate(graph, world)
        sched = build_schedule(graph, alloc, world)
        order_list, exhaustive = orders(graph, args.all_orders, args.samples, rng)
        bad = invalid_orders(problem, res.plan, graph, order_list)
        levels = len(list(nx.topological_generations(to_networkx(graph)))) if graph["nodes"] else 0
        row[mode] = {"makespan": sched["makespan"], "edges": len(graph["edges"]), "levels": levels,
                     "orders": len(order_list), "exhaustive": exhaustive, "invalid": bad}
    return row


def scaled_world(shelves: int, products: int, moved: int, robots: int, seed: int) -> tuple[dict, dict]:
    """A generated warehouse (pipflow.warehouse.generate) with a team of ``robots`` along both aisles."""
    world, goal = scale_instance(shelves, products, moved, capacity=40, fill=0.7, seed=seed)
    rng = random.Random(seed)
    width = world["floor"]["width"]
    world["robots"] = {f"robot{i}": {"start": [round(1 + (width - 2) * i / max(1, robots - 1), 1),
                                               1 if i % 2 else 8],
                                     "skills": {"carry": rng.choice([1, 2, 3])}}
                       for i in range(robots)}
    # list only the cells the transfers changed: the goal a command would state
    changed = {s: {p: n for p, n in items.items() if n != world["stock"].get(s, {}).get(p, 0)}
               for s, items in goal.items()}
    return world, {s: items for s, items in changed.items() if items}


SCALED = [(8, 4, 60, 12), (10, 4, 80, 12), (10, 5, 100, 16), (12, 5, 120, 16), (14, 6, 160, 20),
          (16, 6, 200, 24)]


def report(title: str, rows: list[tuple[str, dict]]) -> dict:
    print(f"\n{title}")
    head = (f"{'task':10}{'moves':>6}" + "".join(f"{m + ' mk':>12}{'edges':>6}{'lvls':>5}" for m in MODES)
            + f"{'deo/exact':>10}{'paper/exact':>12}  orders checked (invalid)")
    print(head)
    print("-" * len(head))
    r_deo, r_paper, invalid = [], [], {m: 0 for m in MODES}
    for label, row in rows:
        ex = row["exact"]["makespan"]
        rd = row["deorder"]["makespan"] / ex if ex else 1.0
        rp = row["paper"]["makespan"] / ex if ex else 1.0
        r_deo.append(rd)
        r_paper.append(rp)
        checked = []
        for m in MODES:
            invalid[m] += row[m]["invalid"]
            checked.append(f"{m[:3]} {row[m]['orders']}{'' if row[m]['exhaustive'] else '~'}"
                           f"({row[m]['invalid']})")
        print(f"{label:10}{row['moves']:>6}"
              + "".join(f"{row[m]['makespan']:>12.1f}{row[m]['edges']:>6}{row[m]['levels']:>5}" for m in MODES)
              + f"{rd:>10.3f}{rp:>12.3f}  " + ", ".join(checked))
    if r_deo:
        print(f"mean makespan ratio deorder/exact {statistics.mean(r_deo):.3f} (min {min(r_deo):.3f}, "
              f"max {max(r_deo):.3f}); paper/exact {statistics.mean(r_paper):.3f}; invalid orders: "
              + ", ".join(f"{m} {invalid[m]}" for m in MODES) + "  (~ = random sample)")
    return {"deorder": statistics.mean(r_deo) if r_deo else None, "invalid": invalid}


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--samples", type=int, default=60, help="random orders per graph when there are too many")
    ap.add_argument("--all-orders", type=int, default=2000, help="check every order when there are at most this many")
    ap.add_argument("--only", choices=("paper", "scaled"))
    ap.add_argument("--seed", type=int, default=0)
    args = ap.parse_args(argv)
    rng = random.Random(args.seed)
    print(f"load average at start: {os.getloadavg()[0]:.2f} (2 shared cores)")
    started = time.monotonic()
    ok = True
    if args.only != "scaled":
        tasks = load_tasks(ROOT / "benchmarks" / "warehouse" / "tasks.yaml")
        rows = []
        for task in tasks["tasks"]:
            if task.get("feasible", True) is False:
                continue
            row = measure(tasks["world"], task["goal"], args, rng)
            if row:
                rows.append((task["id"], row))
        res = report("paper tasks (makespan in s; lvls = topological levels)", rows)
        ok &= res["invalid"]["deorder"] == 0 and res["invalid"]["exact"] == 0
    if args.only != "paper":
        rows = []
        for i, (s, p, moved, robots) in enumerate(SCALED):
            world, goal = scaled_world(s, p, moved, robots, seed=i)
            row = measure(world, goal, args, rng)
            if row:
                rows.append((f"{s}x{p}x{moved}", row))
        res = report("scaled suite (shelves x products x units moved; makespan in s)", rows)
        target = res["deorder"] is not None and res["deorder"] <= 0.80
        print(f"target mean deorder/exact <= 0.80: {'met' if target else 'NOT met'}")
        ok &= target and res["invalid"]["deorder"] == 0 and res["invalid"]["exact"] == 0
    print(f"total {time.monotonic() - started:.0f} s; load average at end: {os.getloadavg()[0]:.2f}")
    return 0 if ok else 1


if __name__ == "__main__":
    raise SystemExit(main())

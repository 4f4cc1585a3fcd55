"""Robot-level planning benchmark: allocation quality on the paper's ten warehouse tasks and the
speed of the fast first stage.

    python benchmarks/allocation.py [--tasks benchmarks/warehouse/tasks.yaml] [--runs 10]

Part 1 (needs the team planner ``pipflow.warehouse.planner``; skipped with a message otherwise):
for each task, plan the gold goal, build the exact dependency graph, allocate with the paper's
per-subtask IP, frontier mode and greedy, each with both allocation costs side by side (``total``,
the paper's c_i: each robot's travel so far plus the subtask; ``subtask``: the subtask's approach
and route only), and cost-blind (which looks at no cost), and schedule. Prints TC-max, TC-avg
(over every robot: TC-sum / N) and makespan, and each as a ratio to a lower bound:

* total distance >= sum over subtasks of route length x the LP relaxation of "fewest robots that
  cover Y" (solved with clarabel), since every robot of a coalition drives the whole route;
* TC-max >= max over subtasks of min over allowed robots of (start -> first stop + route), since
  whoever does a subtask drives at least that far (triangle inequality), and >= total / N;
* makespan >= the critical path of subtask durations (handling + route) plus the quickest
  approach to a first subtask.

Part 2: random instances (costs uniform, carry 1-3, need 1-6), median solve time of the first
stage, fast (sort + cumsum) vs naive (SCIP min-max model), at 12, 100 and 1000 robots, and of the
whole lexicographic solve; every instance checks that both reach the same optimum.
"""
from __future__ import annotations

import argparse
import statistics
import sys
import time
from pathlib import Path

import numpy as np
import yaml

ROOT = Path(__file__).resolve().parents[1]


# ------------------------------------------------------------------------------- lower bounds
def lp_fewest_robots(Q: np.ndarray, Y: np.ndarray, allowed: np.ndarray) -> float:
    """min 1'x s.t. Q'x >= Y, 0 <= x <= 1 (x = 0 off ``allowed``), with clarabel."""
    import clarabel
    from scipy import sparse  # clarabel's Python API takes scipy CSC matrices

    idx = np.flatnonzero(allowed)
    if not np.any(Y > 0):
        return 0.0
    n = len(idx)
    Qa = Q[idx]
    rows = [-Qa.T, np.eye(n), -np.eye(n)]
    A = sparse.csc_matrix(np.vstack(rows))
    b = np.concatenate([-Y, np.ones(n), np.zeros(n)])
    P = sparse.csc_matrix((n, n))
    settings = clarabel.DefaultSettings()
    settings.verbose = False
    sol = clarabel.DefaultSolver(P, np.ones(n), A, b, [clarabel.NonnegativeConeT(len(b))], settings).solve()
    if str(sol.status) not in ("Solved", "AlmostSolved", "SolverStatus.Solved"):
        raise RuntimeError(f"LP bound failed: {sol.status}")
    return float(sol.obj_val)


def bounds(graph: dict, world: dict, constraints: list, speed: float, handling: float) -> dict:
    from pipflow.team.allocation import Rules, need_vector, skill_matrix
    from pipflow.team.dependency import critical_path
    from pipflow.team.scheduling import Timeline

    robots, skills, Q = skill_matrix(world, graph["nodes"])
    rules = Rules(robots, skills, Q, constraints, [], graph["nodes"])
    tl = Timeline(world, speed=speed, handling=handling)
    total, tc_max, durations, first_approach = 0.0, 0.0, {}, []
    has_pred = {v for _, v in graph["edges"]}
    for node in graph["nodes"]:
        allowed, _ = rules.mask(node)
        route = tl.route_length(node)
        total += route * lp_fewest_robots(Q, need_vector(node, skills), allowed)
        approach = min(tl.approach(robots[i], node) for i in np.flatnonzero(allowed))
        tc_max = max(tc_max, approach + route)
        durations[node["id"]] = tl.duration(node)
        if node["id"] not in has_pred:
            first_approach.append(approach / speed)
    n = len(robots)
    return {"tc_max": max(tc_max, total / n), "tc_avg": total / n,
            "makespan": critical_path(graph, durations) + min(first_approach, default=0.0)}


# ------------------------------------------------------------------------------- part 1
def plan_task(world: dict, goal: dict, domain_text: str) -> tuple[str, list[dict]]:
    from pipflow.pddl.common import parse
    from pipflow.warehouse.planner import instance_from_problem, moves_to_plan, plan_instance
    from pipflow.warehouse.problem import write_problem

    problem_text = write_problem(world, goal)
    inst = instance_from_problem(parse(domain_text, problem_text))
    return problem_text, moves_to_plan(inst, plan_instance(inst))


def tasks_part(tasks_file: Path, speed: float, handling: float, time_limit: float) -> None:
    from pipflow.team.allocation import allocate
    from pipflow.team.dependency import build_graph
    from pipflow.errors import PipflowError
    from pipflow.team.scheduling import COSTS, build_schedule

    try:
        import pipflow.warehouse.planner  # noqa: F401  (the team planner)
        import pipflow.warehouse.problem  # noqa: F401
    except ImportError as exc:
        print(f"[part 1 skipped] team-level planner not available ({exc}); "
              "plans come from pipflow.pddl once it lands.\n")
        return
    spec = yaml.safe_load(tasks_file.read_text())
    world = yaml.safe_load((tasks_file.parent / spec["world"]).read_text())
    domain_text = (ROOT / "domains" / "warehouse.pddl").read_text()
    meta = yaml.safe_load((ROOT / "domains" / "warehouse.actions.yaml").read_text())
    methods = [(f"{label}/{cost}", dict(kw, cost=cost)) for label, kw in
               (("per-subtask", dict(method="scip")), ("frontier", dict(method="scip", mode="frontier")),
                ("greedy", dict(method="greedy"))) for cost in COSTS]
    methods.append(("cost-blind", dict(method="blind")))
    ratios = {m: {"tc_max": [], "tc_avg": [], "makespan": []} for m, _ in methods}
    means = {m: {"tc_max": [], "tc_avg": [], "makespan": []} for m, _ in methods}
    print(f"Part 1: paper tasks ({tasks_file}), speed {speed} m/s, handling {handling} s/stop")
    print(f"{'task':6} {'moves':>5} {'edges':>5} {'method/cost':20} {'TC-max':>8} {'TC-avg':>8} {'makespan':>9}"
          f"  {'ratio to lower bound (max/avg/makespan)':>40}")
    for task in spec["tasks"]:
        if task.get("feasible", True) is False:
            print(f"{task['id']:6} infeasible by design: skipped")
            continue
        constraints = task.get("constraints", [])
        try:
            problem_text, plan = plan_task(world, task["goal"], domain_text)
            graph = build_graph(domain_text, problem_text, plan, meta, "exact")
            lb = bounds(graph, world, constraints, speed, handling)
        except PipflowError as exc:
            print(f"{task['id']:6} failed before allocation: {exc}")
            continue
        except Exception as exc:  # the planner's own exceptions (Unsolvable, Stuck)
            print(f"{task['id']:6} planning failed: {type(exc).__name__}: {exc}")
            continue
        for label, kw in methods:
            try:
                alloc = allocate(graph, world, constraints=constraints, speed=speed, handling=handling,
                                 time_limit=time_limit, **kw)
                s = build_schedule(graph, alloc, world, speed=speed, handling=handling)
            except PipflowError as exc:
                print(f"{task['id']:6} {len(plan):5} {len(graph['edges']):5} {label:20} failed: {exc}")
                continue
            r = {k: s[k] / lb[k] if lb[k] > 0 else float("nan") for k in ("tc_max", "tc_avg", "makespan")}
            for k in r:
                ratios[label][k].append(r[k])
                means[label][k].append(s[k])
            gap = ""
            if "waves" in alloc["stats"]:
                gaps = [w.get("gap", float("nan")) for w in alloc["stats"]["waves"]]
                gap = f"  waves {len(gaps)}, max gap {max(gaps):.1%}"
            print(f"{task['id']:6} {len(plan):5} {len(graph['edges']):5} {label:20} {s['tc_max']:8.1f} "
                  f"{s['tc_avg']:8.1f} {s['makespan']:9.1f}  {r['tc_max']:12.2f} {r['tc_avg']:8.2f} "
                  f"{r['makespan']:8.2f}{gap}")
    print("\nMean over tasks            TC-max   TC-avg  makespan   ratio TC-max  TC-avg  makespan")
    print("(method/cost: the allocation cost c_i, total = the paper's, subtask = this subtask only)")
    for label, _ in methods:
        if not means[label]["tc_max"]:
            continue
        m = {k: statistics.mean(v) for k, v in means[label].items()}
        q = {k: statistics.mean(v) for k, v in ratios[label].items()}
        print(f"  {label:22} {m['tc_max']:8.1f} {m['tc_avg']:8.1f} {m['makespan']:9.1f}   "
              f"{q['tc_max']:12.2f} {q['tc_avg']:7.2f} {q['makespan']:9.2f}")
    print("\nTotal-travel cost / subtask cost, means over tasks (the trade-off: TC-max and makespan fall,")
    print("the sum of travel, TC-avg x robots, may rise)")
    print(f"  {'method':12} {'TC-max':>8} {'TC-avg':>8} {'makespan':>9}")
    for label in ("per-subtask", "frontier", "greedy"):
        a, b = means[f"{label}/total"], means[f"{label}/subtask"]
        if a["tc_max"] and len(a["tc_max"]) == len(b["tc_max"]):
            ratio = {k: statistics.mean(a[k]) / statistics.mean(b[k]) for k in ("tc_max", "tc_avg", "makespan")}
            print(f"  {label:12} {ratio['tc_max']:8.2f} {ratio['tc_avg']:8.2f} {ratio['makespan']:9.2f}")
    print()


# ------------------------------------------------------------------------------- part 2
def speed_part(runs: int, seed: int) -> None:
    from pipflow.team.allocation import first_stage_fast, solve_lexicographic, solve_naive

    print(f"Part 2: first-stage solve time, fast (threshold) vs naive (SCIP min-max), {runs} random instances each")
    print(f"{'robots':>6} {'fast stage1 ms':>15} {'naive stage1 ms':>16} {'ratio':>8} "
          f"{'fast total ms':>14} {'naive total ms':>15} {'same optimum':>13}")
    rng = np.random.default_rng(seed)
    for n in (12, 100, 1000):
        f1, n1, ft, nt, same = [], [], [], [], 0
        for _ in range(runs):
            Q = rng.integers(1, 4, size=(n, 1)).astype(float)
            Y = np.array([float(rng.integers(1, 7))])
            c = rng.uniform(0.0, 60.0, size=n)
            allowed = rng.random(n) > 0.1
            t0 = time.perf_counter()
            first_stage_fast(Q, Y, c, allowed)
            f1.append(time.perf_counter() - t0)
            t0 = time.perf_counter()
            fast = solve_lexicographic(Q, Y, c, allowed)
            ft.append(time.perf_counter() - t0)
            t0 = time.perf_counter()
            naive = solve_naive(Q, Y, c, allowed)
            nt.append(time.perf_counter() - t0)
            n1.append(naive.stats.get("stage1_s", nt[-1]))
            same += abs(fast.max_cost - naive.max_cost) < 1e-6 and abs(fast.sum_cost - naive.sum_cost) < 1e-6
        mf, mn = statistics.median(f1) * 1e3, statistics.median(n1) * 1e3
        print(f"{n:6} {mf:15.3f} {mn:16.1f} {mn / mf:7.0f}x {statistics.median(ft) * 1e3:14.2f} "
              f"{statistics.median(nt) * 1e3:15.1f} {same:>6}/{runs}")


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--tasks", type=Path, default=ROOT / "benchmarks" / "warehouse" / "tasks.yaml")
    ap.add_argument("--runs", type=int, default=10, help="random instances per team size (part 2)")
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--speed", type=float, default=1.0)
    ap.add_argument("--handling", type=float, default=2.0)
    ap.add_argument("--time-limit", type=float, default=10.0, help="seconds per frontier wave")
    ap.add_argument("--skip-tasks", action="store_true")
    args = ap.parse_args(argv)
    if not args.skip_tasks:
        tasks_part(args.tasks, args.speed, args.handling, args.time_limit)
    speed_part(args.runs, args.seed)
    return 0


if __name__ == "__main__":
    sys.exit(main())

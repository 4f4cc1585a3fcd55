"""Schedules against the proven optimum (issue 26, part 3), and what the improvement phase buys at scale.

    python benchmarks/optimality.py [--instances 36] [--seed 0] [--time-limit 900]
                                    [--sizes 12x4x4,200x20x10,1000x100x20,12x40x10,30x100x20] [--repeat 1]
                                    [--skip-small] [--skip-scaled]

Part 1, small instances (up to 8 subtasks and 6 robots; half from the paper's world, half from
generated worlds; seeded): each is a real plan (pipflow's team planner) of a seeded goal, its
dependency graph, and sometimes a robot rule. For each:

Half of the graphs are ``deorder`` graphs (the workflow's default), half ``exact`` ones (every
read/write order kept: more edges, the option ``graph_mode=exact``).

* Alg. 1 (``allocate``: the paper's per-subtask IP in frontier order, with this checkout's
  default allocation cost, or each of ``--cost total,subtask`` where ``allocate`` takes one),
* Alg. 1 followed by the improvement phase (``pipflow.team.improve``, the step ``improve.local``),
* the proven optimum of the joint problem (``pipflow.team.exact``: SCIP, allocation and order
  together, minimising makespan, then TC-max, then TC-sum), given the better of the two plans as
  a first solution.

It prints each instance's makespan and its gap to the optimum, ``(ours - optimum) / optimum``, and
the mean and worst gap with and without the improvement (only instances SCIP proved optimal
count; the others are listed). Targets: with the improvement, mean <= 3 %, worst <= 10 %.

Part 2, the scaled suite (the generated worlds of benchmarks/pipeline.py and its commands, at its
sizes and at two where robots are scarce): one whole ``pipflow run workflows/warehouse.yaml`` per
size and setting in a child process (step cache off), ``-i improve=false`` and ``-i improve=true``
taking turns so that both see the same load. Prints the makespan change (target: -10 % or
better), the makespan lower bound of the run's graph (where Alg. 1 meets it, no plan is
shorter), the TC changes, and the wall-time ratio of the whole run with and without the
improvement (target: <= 1.2x), with the load average before and after each run.
"""
from __future__ import annotations

import argparse
import copy
import inspect
import json
import os
import random
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import yaml

sys.path.insert(0, str(Path(__file__).resolve().parent))
from pipeline import command_for, generate_world  # noqa: E402  (a sibling script: the scaled suite's worlds)

ROOT = Path(__file__).resolve().parents[1]
WORLD = ROOT / "benchmarks" / "warehouse" / "world.yaml"
TASKS = ROOT / "benchmarks" / "warehouse" / "tasks.yaml"
MAX_SUBTASKS, MAX_ROBOTS = 8, 6
#: the scaled suite: benchmarks/pipeline.py's generated sizes (robots x shelves x products; with
#: hundreds of robots for a few dozen moves), and two where robots are scarce (a dozen and thirty
#: robots for the same kind of command)
SIZES = "12x4x4,200x20x10,1000x100x20,12x40x10,30x100x20"


# ------------------------------------------------------------------------------- instances
def plan_graph(world: dict, goal: dict, mode: str) -> dict:
    """The dependency graph of pipflow's plan for ``goal`` (``mode``: deorder, the workflow's
    default, keeps only the orders a precondition needs; exact keeps every read/write order)."""
    from pipflow.pddl.common import parse
    from pipflow.warehouse.planner import instance_from_problem, moves_to_plan, plan_instance
    from pipflow.warehouse.problem import write_problem
    from pipflow.team.dependency import build_graph

    domain = (ROOT / "domains" / "warehouse.pddl").read_text()
    meta = yaml.safe_load((ROOT / "domains" / "warehouse.actions.yaml").read_text())
    problem = write_problem(world, goal)
    inst = instance_from_problem(parse(domain, problem))
    return build_graph(domain, problem, moves_to_plan(inst, plan_instance(inst)), meta, mode)


def random_goal(rng: random.Random, world: dict, pairs: int, most: int = 9) -> dict:
    """Up to ``pairs`` (shelf, product) targets, each a shelf holding 2 to ``most`` more units of a
    product than it has (counts that the other shelves' stock and the shelf's room allow); or,
    sometimes, a shelf emptied (its units go wherever the planner finds room)."""
    if rng.random() < 0.2:
        full = [s for s, items in world["stock"].items() if sum(items.values()) > 0]
        if full:
            shelf = rng.choice(full)
            return {shelf: {prod: 0 for prod in world["stock"][shelf]}}
    totals: dict[str, int] = {}
    for items in world["stock"].values():
        for prod, k in items.items():
            totals[prod] = totals.get(prod, 0) + k
    goal: dict[str, dict[str, int]] = {}
    room = {s: v["capacity"] - sum(world["stock"].get(s, {}).values()) for s, v in world["shelves"].items()}
    for _ in range(4 * pairs):
        if sum(len(v) for v in goal.values()) >= pairs:
            break
        shelf = rng.choice(list(world["shelves"]))
        have = world["stock"].get(shelf, {})
        more = [q for q in totals if totals[q] > have.get(q, 0) and q not in goal.get(shelf, {})]
        if not more or room[shelf] <= 0:
            continue
        prod = rng.choice(more)
        extra = min(totals[prod] - have.get(prod, 0), room[shelf], rng.randint(2, most))
        goal.setdefault(shelf, {})[prod] = have.get(prod, 0) + extra
        room[shelf] -= extra
        totals[prod] -= extra
    return goal


def random_rule(rng: random.Random, world: dict, goal: dict) -> list[dict]:
    """Sometimes a robot rule of the paper's kinds: a robot never moves a product, or only some
    robots may take products to a shelf."""
    robots = list(world["robots"])
    roll = rng.random()
    if roll < 0.25:
        prod = rng.choice(sorted({p for items in goal.values() for p in items}))
        return [{"never": [rng.choice(robots)], "product": prod}]
    if roll < 0.35 and len(robots) > 3:
        return [{"only": rng.sample(robots, len(robots) - 1), "to": rng.choice(sorted(goal))}]
    return []


def small_instances(count: int, seed: int) -> list[dict]:
    """``count`` instances, alternately from the paper's world (a random team of 3-6 of its
    robots at seeded starts; a paper task's goal or a random one) and from generated worlds, with
    2 to 8 subtasks in turn (so that the large ones are as many as the small ones)."""
    from pipflow.errors import PipflowError
    from pipflow.team.allocation import allocate
    from pipflow.warehouse.starts import vary_starts

    paper = yaml.safe_load(WORLD.read_text())
    tasks = [t for t in yaml.safe_load(TASKS.read_text())["tasks"] if t.get("feasible", True)]
    rng = random.Random(f"optimality-{seed}")
    out: list[dict] = []
    tries = 0
    while len(out) < count and tries < 60 * count:
        tries += 1
        source = "paper" if len(out) % 2 == 0 else "generated"
        size = 2 + (len(out) // 2) % (MAX_SUBTASKS - 1)  # 2, 2, 3, 3, ... 8, 8, 2, 2, ...
        k = rng.randint(3, MAX_ROBOTS)
        if source == "paper":
            world = copy.deepcopy(paper)
            keep = rng.sample(list(world["robots"]), k)
            world["robots"] = {r: world["robots"][r] for r in sorted(keep, key=list(paper["robots"]).index)}
            world = vary_starts(world, rng.randint(0, 10_000))
            task = tasks[tries % len(tasks)]
            goal = task["goal"] if rng.random() < 0.3 else random_goal(rng, world, max(1, size // 2), 12)
        else:
            world = generate_world(k, rng.randint(4, 6), rng.randint(2, 4), seed=rng.randint(0, 10_000))
            goal = random_goal(rng, world, max(1, size // 2), 12)
        if not goal:
            continue
        rules = random_rule(rng, world, goal)
        try:
            graph = plan_graph(world, goal, "deorder" if len(out) % 4 < 2 else "exact")
            if len(graph["nodes"]) != size and not (tries % 40 == 0 and 2 <= len(graph["nodes"]) <= MAX_SUBTASKS):
                continue  # another size than this turn's (every 40th try takes any size that fits)
            allocate(graph, world, constraints=rules)  # the rules leave every subtask a coalition
        except PipflowError:
            continue
        except Exception:  # the planner's own exceptions (no plan): another goal
            continue
        out.append({"id": f"{source[0]}{len(out) + 1:02d}", "source": source, "world": world, "goal": goal,
                    "rules": rules, "graph": graph, "mode": graph["mode"]})
    return out


# ------------------------------------------------------------------------------- part 1
def small_part(count: int, seed: int, time_limit: float, costs: list[str | None], budget: int) -> bool:
    """Alg. 1 and Alg. 1 + improvement for each cost, and one exact solve per instance (given the
    best plan of them all as a first solution); a table per cost."""
    from pipflow.team.allocation import allocate
    from pipflow.team.exact import solve_exact
    from pipflow.team.improve import improve_allocation
    from pipflow.team.joint import JointProblem, lex_less

    t0 = time.perf_counter()
    instances = small_instances(count, seed)
    print(f"Part 1: {len(instances)} small instances (<= {MAX_SUBTASKS} subtasks, <= {MAX_ROBOTS} robots; "
          f"seed {seed}; made in {time.perf_counter() - t0:.1f} s); load average "
          f"{' '.join(f'{x:.2f}' for x in os.getloadavg())}")
    ok = True
    rows: dict[str | None, list[dict]] = {cost: [] for cost in costs}
    for inst in instances:
        g, w, rules = inst["graph"], inst["world"], inst["rules"]
        p = JointProblem(g, w, rules)
        found = []
        for cost in costs:
            a = allocate(g, w, constraints=rules, **({"cost": cost} if cost else {}))
            t1 = time.perf_counter()
            b = improve_allocation(g, w, a, rules, budget=budget)
            imp_s = time.perf_counter() - t1
            plans = (p.plan_of(a), p.plan_of(b))
            keys = tuple(p.evaluate(plan).key for plan in plans)
            found += list(zip(keys, plans))
            rows[cost].append({"inst": inst, "paper": keys[0], "improved": keys[1], "imp_s": imp_s})
        hint = min(found, key=lambda kp: kp[0])[1]
        ex = solve_exact(p, hint=hint, time_limit=time_limit)
        if ex.proven and any(lex_less(k, ex.key) for k, _ in found):
            print(f"   !! {inst['id']}: a plan beats the proven optimum (a model error)")
            ok = False
        for cost in costs:
            rows[cost][-1]["exact"] = ex
    for cost in costs:
        print(f"\n-- allocation cost: {cost or 'this checkout default'}")
        print(f"{'inst':5} {'src':4} {'graph':7} {'sub':>3} {'edg':>3} {'rob':>3} {'rule':4} {'Alg.1':>8} {'+improve':>8} "
              f"{'optimum':>8} {'gap':>7} {'gap+imp':>7} {'lex=':>4} {'imp s':>6} {'exact s':>7} proven")
        gaps, gaps_imp, lex_same, unproven, imp_times = [], [], 0, [], []
        for row in rows[cost]:
            inst, ex, k_paper, k_imp = row["inst"], row["exact"], row["paper"], row["improved"]
            g, w = inst["graph"], inst["world"]
            gap, gap_imp = k_paper[0] / ex.key[0] - 1, k_imp[0] / ex.key[0] - 1
            same = not lex_less(ex.key, k_imp)
            imp_times.append(row["imp_s"])
            if ex.proven:
                gaps.append(gap)
                gaps_imp.append(gap_imp)
                lex_same += same
            else:
                unproven.append(inst["id"])
            print(f"{inst['id']:5} {inst['source'][:4]:4} {inst['mode']:7} {len(g['nodes']):3} {len(g['edges']):3} "
                  f"{len(w['robots']):3} {'yes' if inst['rules'] else '':4} {k_paper[0]:8.2f} {k_imp[0]:8.2f} "
                  f"{ex.key[0]:8.2f} {gap:7.1%} {gap_imp:7.1%} {'yes' if same else 'no':>4} {row['imp_s']:6.2f} "
                  f"{ex.time_s:7.1f} {'yes' if ex.proven else 'NO (' + ', '.join(s['status'] for s in ex.stages) + ')'}")
        n = len(gaps)
        if n:
            print(f"   makespan gap to the proven optimum over {n} instances: Alg. 1 mean {statistics.mean(gaps):.1%}, "
                  f"worst {max(gaps):.1%}; with the improvement mean {statistics.mean(gaps_imp):.1%}, worst "
                  f"{max(gaps_imp):.1%} (targets: mean <= 3%, worst <= 10%); the improved plan equals the "
                  f"optimum in all three objectives on {lex_same}/{n}; improvement time median "
                  f"{statistics.median(imp_times):.2f} s, max {max(imp_times):.2f} s")
        if unproven:
            print(f"   not proven optimal within {time_limit:.0f} s (left out of the means): {', '.join(unproven)}")
    print(f"load average after part 1: {' '.join(f'{x:.2f}' for x in os.getloadavg())}")
    return ok


# ------------------------------------------------------------------------------- part 2
def run_once(label: str, work: Path, improve: bool, timeout: float, cost: str | None = None) -> dict:
    """One whole `pipflow run` of the warehouse workflow in a child process (``cost``: its input
    ``allocation_cost``, where the workflow has one)."""
    record = work / "runs" / f"{label}-{cost or 'default'}-{'on' if improve else 'off'}"
    args = [sys.executable, "-m", "pipflow.engine.cli", "run", str(ROOT / "workflows" / "warehouse.yaml"),
            "--no-cache", "-q", "--runs-dir", str(record), "-i", f"improve={'true' if improve else 'false'}"]
    if cost:
        args += ["-i", f"allocation_cost={cost}"]
    if label != "paper":
        r, s, p = (int(x) for x in label.split("x"))
        world = generate_world(r, s, p)
        path = work / f"world-{label}.yaml"
        if not path.exists():
            path.write_text(yaml.safe_dump(world, sort_keys=False))
        args += ["-i", f"world={path}", "-i", f"command={command_for(world)}"]
    load = os.getloadavg()[0]
    started = time.perf_counter()
    proc = subprocess.run(args, cwd=work, capture_output=True, text=True, timeout=timeout)
    wall = time.perf_counter() - started
    runs = sorted(record.glob("*/outputs.json"))
    outputs = json.loads(runs[-1].read_text()) if runs else {}
    steps = {}
    if runs:
        for line in (runs[-1].parent / "events.jsonl").read_text().splitlines():
            ev = json.loads(line)
            if ev.get("event") == "end" and ev.get("duration") is not None:
                steps[ev["step"]] = steps.get(ev["step"], 0.0) + float(ev["duration"])
    tc_sum = None
    if outputs.get("schedule"):
        tc_sum = sum(r["distance"] for r in outputs["schedule"]["robots"].values())
    return {"wall": wall, "code": proc.returncode, "err": proc.stderr.strip().splitlines()[-1:] if proc.returncode else [],
            "makespan": outputs.get("makespan"), "tc_max": outputs.get("tc_max"), "tc_sum": tc_sum,
            "goal_met": outputs.get("goal_met"), "steps": steps, "load": (load, os.getloadavg()[0]),
            "record": runs[-1].parent if runs else None, "subtasks": len((outputs.get("graph") or {}).get("nodes", []))}


def lower_bound(record: Path) -> float:
    """The makespan no plan of that run's graph can beat (pipflow.team.bounds)."""
    from pipflow.team.bounds import makespan_bound
    from pipflow.team.joint import JointProblem

    outputs = json.loads((record / "outputs.json").read_text())
    world = json.loads((record / "steps" / "world" / "outputs.json").read_text())["world"]
    return makespan_bound(JointProblem(outputs["graph"], world, outputs.get("constraints") or []))


def scaled_part(sizes: list[str], repeat: int, timeout: float, costs: list[str | None]) -> None:
    work = Path(tempfile.mkdtemp(prefix="pipflow-optimality-"))
    print(f"\nPart 2: the scaled suite, one whole `pipflow run` per size and setting (step cache off), improve=false "
          f"and improve=true taking turns, best of {repeat}; load average {' '.join(f'{x:.2f}' for x in os.getloadavg())}; "
          f"records in {work}")
    run_once("paper", work, False, timeout)  # unmeasured: bytecode and the parser cache
    for cost in costs:
        scaled_table(sizes, repeat, timeout, work, cost)


def scaled_table(sizes: list[str], repeat: int, timeout: float, work: Path, cost: str | None) -> None:
    print(f"-- allocation cost: {cost or 'the workflow default'}")
    print(f"{'size':>12} {'sub':>4} {'wall off':>8} {'wall on':>8} {'ratio':>6} {'improve s':>9} "
          f"{'makespan off':>12} {'on':>8} {'change':>7} {'bound':>8} {'TC-max':>7} {'TC-sum':>7} {'goal':>5}  load (off; on)")
    changes, ratios = [], []
    for label in sizes:
        best: dict[bool, dict] = {}
        for _ in range(max(1, repeat)):
            for improve in (False, True):
                r = run_once(label, work, improve, timeout, cost)
                if improve not in best or (r["code"] != 0, r["wall"]) < (best[improve]["code"] != 0, best[improve]["wall"]):
                    best[improve] = r
        off, on = best[False], best[True]
        if off["code"] or on["code"]:
            print(f"{label:>12} failed: off exit {off['code']} {off['err']}; on exit {on['code']} {on['err']}")
            continue
        change = on["makespan"] / off["makespan"] - 1
        bound = lower_bound(off["record"])
        changes.append(change)
        ratios.append(on["wall"] / off["wall"])
        print(f"{label:>12} {off['subtasks']:4} {off['wall']:8.2f} {on['wall']:8.2f} {on['wall'] / off['wall']:6.2f} "
              f"{on['steps'].get('improve', 0.0):9.2f} {off['makespan']:12.1f} {on['makespan']:8.1f} {change:7.1%} "
              f"{bound:8.1f} {on['tc_max'] / off['tc_max'] - 1:7.1%} {on['tc_sum'] / off['tc_sum'] - 1:7.1%} "
              f"{str(on['goal_met']):>5}  {off['load'][0]:.2f}>{off['load'][1]:.2f}; {on['load'][0]:.2f}>{on['load'][1]:.2f}")
    if changes:
        print(f"mean makespan change {statistics.mean(changes):.1%}, mean wall ratio {statistics.mean(ratios):.2f}x, "
              f"worst {max(ratios):.2f}x (targets: makespan -10% or better, wall <= 1.2x). 'bound': no plan of that "
              "run's graph ends sooner (pipflow.team.bounds); where Alg. 1 already meets it, no plan is shorter")


def main(argv: list[str] | None = None) -> int:
    from pipflow.team.allocation import allocate
    from pipflow.team.improve import DEFAULT_BUDGET

    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--instances", type=int, default=36, help="small instances (part 1)")
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--time-limit", type=float, default=900.0, help="seconds SCIP may spend on one instance")
    ap.add_argument("--budget", type=int, default=DEFAULT_BUDGET, help="the improvement's plan evaluations")
    ap.add_argument("--cost", default=None,
                    help="allocation costs to compare, comma-separated (when this checkout's allocate takes `cost`)")
    ap.add_argument("--sizes", default=SIZES, help="scaled suite (part 2)")
    ap.add_argument("--repeat", type=int, default=1, help="runs per size and setting in part 2; the fastest is kept")
    ap.add_argument("--timeout", type=float, default=900.0, help="seconds per run in part 2")
    ap.add_argument("--skip-small", action="store_true")
    ap.add_argument("--skip-scaled", action="store_true")
    args = ap.parse_args(argv)
    costs: list[str | None] = [None]
    if args.cost:
        if "cost" not in inspect.signature(allocate).parameters:
            ap.error("this checkout's allocate() has no `cost` parameter")
        costs = [c.strip() for c in args.cost.split(",") if c.strip()]
    print(f"machine: {os.cpu_count()} CPUs; load average {' '.join(f'{x:.2f}' for x in os.getloadavg())}")
    ok = True
    if not args.skip_small:
        ok = small_part(args.instances, args.seed, args.time_limit, costs, args.budget)
    if not args.skip_scaled:
        scaled_part([s.strip() for s in args.sizes.split(",") if s.strip()], args.repeat, args.timeout, costs)
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())

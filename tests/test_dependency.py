"""Dependency graph: read/write interaction from UP grounding; exact vs the paper's Alg. 2 vs the
minimal deordering (every order it allows checked with UP's own simulator)."""
import itertools
import json
import random
from pathlib import Path

import networkx as nx
import pytest
import yaml

from pipflow import StepContext
from pipflow.team.dependency import build_graph, to_networkx
from pipflow.errors import InputError, PlanningError

FIX = Path(__file__).parent / "fixtures" / "robot"
DOMAIN = (FIX / "warehouse_mini.pddl").read_text()
PROBLEM = (FIX / "problem.pddl").read_text()
META = yaml.safe_load((FIX / "warehouse_mini.actions.yaml").read_text())


def mv(a, b, p, m):
    return {"action": "move-product", "args": [a, b, p, m]}


# s3 needs the red units s1 brings to shelfC, and shares shelfD's load with s2
DIAMOND = [mv("shelfA", "shelfC", "red", "m2"), mv("shelfB", "shelfD", "blue", "m1"),
           mv("shelfC", "shelfD", "red", "m2")]


def _applicable_in_order(order: list[dict], domain: str = DOMAIN, problem_text: str = PROBLEM) -> bool:
    """Execute actions with UP's sequential simulator; False if any precondition fails."""
    from unified_planning.engines import UPSequentialSimulator
    from unified_planning.io import PDDLReader

    problem = PDDLReader().parse_problem_string(domain, problem_text)
    sim = UPSequentialSimulator(problem, error_on_failed_checks=False)
    state = sim.get_initial_state()
    for a in order:
        act = problem.action(a["action"])
        objs = [problem.object(x.lower()) for x in a["args"]]
        if not sim.is_applicable(state, act, objs):
            return False
        state = sim.apply(state, act, objs)
    return True


def _every_order_safe(graph: dict, plan: list[dict]) -> bool:
    g = to_networkx(graph)
    return all(_applicable_in_order([plan[g.nodes[n]["index"]] for n in order])
               for order in nx.all_topological_sorts(g))


def test_exact_keeps_both_parents_and_paper_loses_one():
    exact = build_graph(DOMAIN, PROBLEM, DIAMOND, META, "exact")
    paper = build_graph(DOMAIN, PROBLEM, DIAMOND, META, "paper")
    assert sorted(map(tuple, exact["edges"])) == [("s1", "s3"), ("s2", "s3")]
    assert paper["edges"] == [["s2", "s3"]]  # Alg. 2: nearest interacting parent only
    assert _applicable_in_order(DIAMOND)
    assert _every_order_safe(exact, DIAMOND)
    # paper mode allows s3 before s1: shelfC has no red yet, so the move is not applicable
    assert not _every_order_safe(paper, DIAMOND)


def test_independent_moves_run_in_parallel_and_shared_shelf_load_links_moves():
    plan = [mv("shelfA", "shelfC", "red", "m1"), mv("shelfB", "shelfD", "blue", "m1"),
            mv("shelfA", "shelfD", "blue", "m1")]
    g = build_graph(DOMAIN, PROBLEM, plan, META)
    # s1 and s2 touch disjoint shelves; s3 shares shelfA's load with s1 and shelfD's with s2
    assert sorted(map(tuple, g["edges"])) == [("s1", "s3"), ("s2", "s3")]
    assert _every_order_safe(g, plan)


def test_transitive_edges_are_reduced():
    plan = [mv("shelfA", "shelfC", "red", "m1"), mv("shelfC", "shelfA", "red", "m1"),
            mv("shelfA", "shelfC", "red", "m1")]
    g = build_graph(DOMAIN, PROBLEM, plan, META)
    assert g["edges"] == [["s1", "s2"], ["s2", "s3"]]


def test_nodes_carry_skills_route_fields():
    g = build_graph(DOMAIN, PROBLEM, DIAMOND, META)
    n = g["nodes"][0]
    assert n["id"] == "s1" and n["index"] == 0
    assert n["skills"] == {"carry": 2.0}  # (amount m2) in the problem
    assert n["route"] == ["shelfA", "shelfC"]
    assert n["fields"] == {"product": "red", "from": "shelfA", "to": "shelfC"}
    const = {"actions": {"move-product": dict(META["actions"]["move-product"], skills={"carry": 4, "lift": 1})}}
    assert build_graph(DOMAIN, PROBLEM, DIAMOND, const)["nodes"][2]["skills"] == {"carry": 4.0, "lift": 1.0}


def test_bad_plans_fail_clearly():
    with pytest.raises(PlanningError, match="unknown object 'shelfZ'"):
        build_graph(DOMAIN, PROBLEM, [mv("shelfZ", "shelfA", "red", "m1")], META)
    with pytest.raises(PlanningError, match="unknown action"):
        build_graph(DOMAIN, PROBLEM, [{"action": "fly", "args": []}], META)
    with pytest.raises(InputError, match="no action metadata"):
        build_graph(DOMAIN, PROBLEM, DIAMOND, {"actions": {}})
    with pytest.raises(InputError, match="mode"):
        build_graph(DOMAIN, PROBLEM, DIAMOND, META, "magic")


def test_step_writes_json_dot_png(tmp_path):
    from pipflow.steps.graph import dependencies

    ctx = StepContext("graph", tmp_path / "art", FIX)
    out = dependencies.func(ctx, domain="warehouse_mini.pddl", problem=PROBLEM, plan=DIAMOND,
                            actions="warehouse_mini.actions.yaml", mode="exact")
    assert out["graph"]["mode"] == "exact"
    assert json.loads((tmp_path / "art" / "graph.json").read_text()) == out["graph"]
    assert '"s1" -> "s3"' in (tmp_path / "art" / "graph.dot").read_text()
    assert (tmp_path / "art" / "graph.png").read_bytes()[:4] == b"\x89PNG"


# ---------------------------------------------------------------- minimal deordering
def _orders(graph: dict, limit: int = 1500):
    """Every linearization the graph allows (at most ``limit`` of them)."""
    return list(itertools.islice(nx.all_topological_sorts(to_networkx(graph)), limit))


def _all_orders_valid(graph: dict, plan: list[dict]) -> bool:
    """Replay every allowed order with UP's simulator (one parse, many runs)."""
    from unified_planning.engines import UPSequentialSimulator
    from unified_planning.io import PDDLReader

    problem = PDDLReader().parse_problem_string(DOMAIN, PROBLEM)
    sim = UPSequentialSimulator(problem, error_on_failed_checks=False)
    index = {n["id"]: n["index"] for n in graph["nodes"]}
    for order in _orders(graph):
        state = sim.get_initial_state()
        for node in order:
            a = plan[index[node]]
            act, objs = problem.action(a["action"]), [problem.object(x.lower()) for x in a["args"]]
            if not sim.is_applicable(state, act, objs):
                return False
            state = sim.apply(state, act, objs)
    return True


def _closure(graph: dict) -> set:
    return set(nx.transitive_closure_dag(to_networkx(graph)).edges())


def test_deorder_lets_commuting_fills_of_one_shelf_run_in_parallel():
    # three moves into shelfD (room 6): increments of its load commute, and 2 + 2 + 2 fit in any order
    plan = [mv("shelfA", "shelfD", "red", "m2"), mv("shelfB", "shelfD", "blue", "m2"),
            mv("shelfA", "shelfD", "red", "m2")]
    exact = build_graph(DOMAIN, PROBLEM, plan, META, "exact")
    deo = build_graph(DOMAIN, PROBLEM, plan, META, "deorder")
    assert exact["edges"] == [["s1", "s2"], ["s2", "s3"]]  # every move writes load(shelfD)
    assert deo["edges"] == [] and deo["mode"] == "deorder"
    assert len(_orders(deo)) == 6 and _all_orders_valid(deo, plan)


def test_deorder_keeps_exactly_what_stock_and_room_need():
    plan = [mv("shelfA", "shelfC", "red", "m5"),   # s1: fills shelfC (1 + 5 = 6, its capacity)
            mv("shelfC", "shelfB", "red", "m3"),   # s2: needs the red s1 brought
            mv("shelfB", "shelfC", "blue", "m3"),  # s3: needs the room s2 made in shelfC
            mv("shelfA", "shelfD", "blue", "m1")]  # s4: touches nothing the others need
    assert _applicable_in_order(plan)
    exact = build_graph(DOMAIN, PROBLEM, plan, META, "exact")
    deo = build_graph(DOMAIN, PROBLEM, plan, META, "deorder")
    assert sorted(map(tuple, deo["edges"])) == [("s1", "s2"), ("s2", "s3")]
    assert ("s1", "s4") in _closure(exact)  # exact orders s4 after s1: both write load(shelfA)
    assert _all_orders_valid(deo, plan)


def test_deorder_needs_both_suppliers_when_one_is_not_enough():
    plan = [mv("shelfA", "shelfC", "red", "m2"), mv("shelfB", "shelfC", "red", "m1"),
            mv("shelfA", "shelfC", "red", "m1"), mv("shelfC", "shelfD", "red", "m4")]
    deo = build_graph(DOMAIN, PROBLEM, plan, META, "deorder")
    assert sorted(map(tuple, deo["edges"])) == [("s1", "s4"), ("s2", "s4"), ("s3", "s4")]
    assert _all_orders_valid(deo, plan)


def _random_plan(rng: random.Random, length: int) -> list[dict]:
    """A valid plan by a random walk over the fixture problem's states (capacity kept)."""
    stock = {("shelfA", "red"): 6, ("shelfA", "blue"): 2, ("shelfB", "red"): 1, ("shelfB", "blue"): 3,
             ("shelfC", "red"): 0, ("shelfC", "blue"): 1, ("shelfD", "red"): 0, ("shelfD", "blue"): 0}
    cap = {"shelfA": 10, "shelfB": 10, "shelfC": 6, "shelfD": 6}
    shelves = list(cap)
    plan = []
    while len(plan) < length:
        s, t = rng.sample(shelves, 2)
        p = rng.choice(["red", "blue"])
        room = cap[t] - sum(n for (x, _), n in stock.items() if x == t)
        most = min(stock[s, p], room, 6)
        if most <= 0:
            continue
        k = rng.randint(1, most)
        stock[s, p] -= k
        stock[t, p] += k
        plan.append(mv(s, t, p, f"m{k}"))
    return plan


@pytest.mark.parametrize("seed", range(6))
def test_deorder_every_allowed_order_of_random_plans_is_valid(seed):
    plan = _random_plan(random.Random(seed), 6)
    exact = build_graph(DOMAIN, PROBLEM, plan, META, "exact")
    deo = build_graph(DOMAIN, PROBLEM, plan, META, "deorder")
    assert _all_orders_valid(deo, plan)
    assert _closure(deo) <= _closure(exact)  # never orders more than read/write interaction does


BOOL_DOMAIN = """(define (domain doors) (:requirements :strips :typing)
  (:types door)
  (:predicates (open ?d - door) (passed ?d - door))
  (:action open-door :parameters (?d - door) :precondition (not (open ?d)) :effect (open ?d))
  (:action pass :parameters (?d - door) :precondition (open ?d) :effect (passed ?d))
  (:action close-door :parameters (?d - door) :precondition (open ?d) :effect (not (open ?d))))"""
BOOL_PROBLEM = """(define (problem p) (:domain doors) (:objects d1 d2 - door) (:init)
  (:goal (and (passed d1) (passed d2) (not (open d1)))))"""
BOOL_META = {"actions": {name: {"skills": {"hands": 1}, "route": [], "fields": {}}
                         for name in ("open-door", "pass", "close-door")}}


def test_deorder_orders_non_numeric_effects_like_the_read_write_graph():
    plan = [{"action": "open-door", "args": ["d1"]}, {"action": "open-door", "args": ["d2"]},
            {"action": "pass", "args": ["d1"]}, {"action": "pass", "args": ["d2"]},
            {"action": "close-door", "args": ["d1"]}]
    exact = build_graph(BOOL_DOMAIN, BOOL_PROBLEM, plan, BOOL_META, "exact")
    deo = build_graph(BOOL_DOMAIN, BOOL_PROBLEM, plan, BOOL_META, "deorder")
    assert deo["edges"] == exact["edges"]
    assert sorted(map(tuple, deo["edges"])) == [("s1", "s3"), ("s2", "s4"), ("s3", "s5")]


def test_step_default_mode_is_deorder(tmp_path):
    from pipflow.steps.graph import dependencies

    ctx = StepContext("graph", tmp_path / "art", FIX)
    out = dependencies.func(ctx, domain="warehouse_mini.pddl", problem=PROBLEM, plan=DIAMOND,
                            actions="warehouse_mini.actions.yaml", picture=False)
    assert out["graph"]["mode"] == "deorder" and out["graph"]["edges"] == [["s1", "s3"]]


@pytest.mark.parametrize("task_id", ["wh-04", "wh-06"])
def test_deordered_schedule_runs_in_pybullet_and_is_shorter(task_id):
    """The whole robot level on a paper task: transport plan, deordered graph, SCIP allocation,
    schedule, pybullet execution (preconditions checked at every load, several moves in flight)."""
    from pipflow.team.allocation import allocate
    from pipflow.pddl.common import parse
    from pipflow.pddl.solver import solve_problem
    from pipflow.warehouse.problem import write_problem
    from pipflow.team.scheduling import build_schedule
    from pipflow.warehouse.simulation import simulate
    from pipflow.warehouse.world import load_tasks

    root = Path(__file__).resolve().parents[1]
    tasks = load_tasks(root / "benchmarks/warehouse/tasks.yaml")
    world, goal = tasks["world"], next(t["goal"] for t in tasks["tasks"] if t["id"] == task_id)
    domain = (root / "domains/warehouse.pddl").read_text()
    meta = yaml.safe_load((root / "domains/warehouse.actions.yaml").read_text())
    text = write_problem(world, goal)
    plan = solve_problem(parse(domain, text)).plan
    makespan = {}
    for mode in ("exact", "deorder"):
        graph = build_graph(domain, text, plan, meta, mode)
        schedule = build_schedule(graph, allocate(graph, world), world)
        sim = simulate(world, schedule, graph, goal)
        assert sim["goal_met"] and sim["exe"] == 1.0 and not sim["failures"], sim["failures"]
        makespan[mode] = schedule["makespan"]
    assert makespan["deorder"] < 0.8 * makespan["exact"]


@pytest.mark.parametrize("seed", range(4))
def test_deorder_is_locally_minimal(seed):
    """No single edge of the deordered graph can go: without it, the stock/room envelope of some
    precondition fails (the greedy pass plus the relaxation pass leave no removable edge)."""
    from pipflow.team.deorder import _Envelope, envelopes_hold, numeric_view
    from pipflow.team.dependency import _parse, ground_plan

    plan = _random_plan(random.Random(100 + seed), 8)
    graph = build_graph(DOMAIN, PROBLEM, plan, META, "deorder")
    problem = _parse(DOMAIN, PROBLEM)
    views = numeric_view(problem, ground_plan(problem, plan))
    env = _Envelope(problem, views)
    index = {n["id"]: n["index"] for n in graph["nodes"]}
    edges = [(index[u], index[v]) for u, v in graph["edges"]]
    assert envelopes_hold(env, len(plan), edges)
    for e in edges:
        assert not envelopes_hold(env, len(plan), [x for x in edges if x != e]), f"edge {e} is not needed"

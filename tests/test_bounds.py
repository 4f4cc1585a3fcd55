"""Bounds in goals end to end: ``{at_least: n}``, ``{at_most: m}`` or both as a goal value.

The writer's numeric goals are parsed by unified-planning and read back, ENHSP solves them, the
verifier accepts what some final state meets and refuses (with the cause) what none does, the
simulation and the scoring count a bound as held when the final count lies within it, and task
files report bad bounds at their line."""
from __future__ import annotations

from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from pipflow.errors import InputError, WorldError
from pipflow.goalcounts import describe, holds, limits, value_problems
from pipflow.pddl.common import parse
from pipflow.warehouse.feasibility import infeasibility_reasons
from pipflow.pddl.verifier import verify_plan
from pipflow.warehouse.problem import goal_problems, stock_goals, write_problem
from pipflow.warehouse.world import load_tasks, load_world

ROOT = Path(__file__).resolve().parents[1]
DOMAIN = ROOT / "domains" / "warehouse.pddl"
WORLD = load_world(ROOT / "benchmarks" / "warehouse" / "world.yaml")
# the paper's world: product1 10/8/5/15 on shelf1..4 (38 units), capacities 30; product4 0/2/4/6


# ---------------------------------------------------------------- goal values
@pytest.mark.parametrize("value, count, ok", [
    (7, 7, True), (7, 6, False),
    ({"at_least": 3}, 3, True), ({"at_least": 3}, 2, False), ({"at_least": 3}, 30, True),
    ({"at_most": 4}, 0, True), ({"at_most": 4}, 4, True), ({"at_most": 4}, 5, False),
    ({"at_least": 2, "at_most": 4}, 1, False), ({"at_least": 2, "at_most": 4}, 3, True),
    ({"at_least": 2, "at_most": 4}, 5, False),
])
def test_a_bound_holds_within_its_ends(value, count, ok):
    assert holds(count, value) is ok


def test_bad_values_are_named():
    assert value_problems({"at_least": 5, "at_most": 3}) == ["at_least 5 is more than at_most 3: no count lies between them"]
    assert "negative" in value_problems({"at_most": -1})[0]
    assert "negative" in value_problems(-2)[0]
    assert "unknown bound key(s) 'at_leest'" in value_problems({"at_leest": 2})[0]
    assert value_problems({}) == ["a bound needs at_least, at_most or both"]
    assert "not a whole number" in value_problems({"at_least": 1.5})[0]
    assert "neither a whole number" in value_problems(True)[0]
    assert [describe(v) for v in (4, {"at_least": 1}, {"at_most": 2}, {"at_least": 1, "at_most": 2})] == \
        ["4", "at least 1", "at most 2", "between 1 and 2"]


# ---------------------------------------------------------------- writer and reader
def test_writer_goals_parse_and_read_back():
    goal = {"shelf3": {"product1": 7, "product2": {"at_least": 2}},
            "shelf4": {"product1": {"at_least": 1, "at_most": 3}, "product3": {"at_most": 0}},
            "shelf2": {"product4": {"at_least": 2, "at_most": 2}}}
    text = write_problem(WORLD, goal)
    assert "(>= (stock shelf3 product2) 2)" in text and "(<= (stock shelf4 product3) 0)" in text
    assert "(= (stock shelf3 product1) 7)" in text
    problem = parse(DOMAIN, text)
    assert stock_goals(problem) == (goal, [])


def test_reader_makes_strict_and_fractional_comparisons_whole():
    text = write_problem(WORLD, {"shelf3": {"product1": 7}}).replace(
        "(= (stock shelf3 product1) 7)",
        "(> (stock shelf1 product1) 2) (< (stock shelf2 product1) 5) (<= (stock shelf3 product1) 7.5)"
        " (>= (stock shelf3 product1) 6.2) (< 1 (stock shelf4 product1))")
    goal, other = stock_goals(parse(DOMAIN, text))
    assert other == []
    assert goal == {"shelf1": {"product1": {"at_least": 3}}, "shelf2": {"product1": {"at_most": 4}},
                    "shelf3": {"product1": {"at_least": 7, "at_most": 7}}, "shelf4": {"product1": {"at_least": 2}}}


def test_reader_merges_an_exact_count_with_bounds_and_keeps_contradictions():
    base = write_problem(WORLD, {"shelf3": {"product1": 7}})
    agree = base.replace("(= (stock shelf3 product1) 7)", "(= (stock shelf3 product1) 7) (>= (stock shelf3 product1) 2)")
    assert stock_goals(parse(DOMAIN, agree))[0] == {"shelf3": {"product1": 7}}
    clash = base.replace("(= (stock shelf3 product1) 7)", "(>= (stock shelf3 product1) 5) (<= (stock shelf3 product1) 3)")
    problem = parse(DOMAIN, clash)
    goal = stock_goals(problem)[0]
    assert goal == {"shelf3": {"product1": {"at_least": 5, "at_most": 3}}}
    report = verify_plan(problem, [], WORLD)
    assert not report.ok and report.refusal is None  # a malformed problem: a message, the loop may fix it
    assert any("at_least 5 is more than at_most 3" in m for m in report.messages)


@pytest.mark.parametrize("value, words", [
    (-1, "negative"), ({"at_least": 4, "at_most": 2}, "more than at_most"), ({"at_leest": 2}, "unknown bound key"),
    ({}, "needs at_least"),
])
def test_writer_refuses_values_that_are_neither_count_nor_bound(value, words):
    with pytest.raises(InputError, match=words):
        write_problem(WORLD, {"shelf3": {"product1": value}})


# ---------------------------------------------------------------- planner and verifier
def _final_stock(world: dict, plan: list[dict]) -> dict:
    stock = {s: dict(items) for s, items in world["stock"].items()}
    for step in plan:
        src, dst, product, magnitude = step["args"]
        units = int(magnitude.removeprefix("magnitude"))
        stock[src][product] = stock[src].get(product, 0) - units
        stock[dst][product] = stock[dst].get(product, 0) + units
        assert stock[src][product] >= 0
    return stock


def test_enhsp_solves_a_bound_goal_and_the_plan_is_verified():
    from pipflow.pddl.solver import solve_problem

    goal = {"shelf4": {"product1": {"at_most": 3}}, "shelf3": {"product1": {"at_least": 6, "at_most": 9}}}
    problem = parse(DOMAIN, write_problem(WORLD, goal))
    result = solve_problem(problem, engine="enhsp", timeout=120)
    assert result.status == "solved", result.message
    report = verify_plan(problem, result.plan, WORLD)
    assert report.ok, report.messages
    assert report.goal == goal
    final = _final_stock(WORLD, result.plan)
    assert final["shelf4"]["product1"] <= 3 and 6 <= final["shelf3"]["product1"] <= 9
    # a plan that stops short of a bound is caught by UP's validator
    short = verify_plan(problem, result.plan[:-1] if len(result.plan) > 1 else [], WORLD)
    assert not short.ok and any("not satisfied" in m or "not valid" in m for m in short.messages)


@pytest.mark.parametrize("goal, reason", [
    ({"shelf3": {"product1": {"at_least": 31}}}, "shelf3 cannot hold at least 31 units of product1: its capacity is 30"),
    ({"shelf3": {"product4": {"at_least": 13}}}, "the goal needs at least 13 units of product4 but only 12 exist"),
    ({"shelf1": {"product4": {"at_least": 5}}, "shelf2": {"product4": {"at_least": 8}}},
     "the goal needs at least 13 units of product4 but only 12 exist"),
    ({s: {"product4": {"at_most": 2}} for s in ("shelf1", "shelf2", "shelf3", "shelf4")},
     "the goal allows at most 8 units of product4 on the shelves but 12 exist; units cannot disappear"),
    ({"shelf3": {"product1": {"at_least": 20}, "product2": {"at_least": 11}}},
     "the goal puts at least 31 units on shelf3 but its capacity is 30"),
])
def test_bounds_no_final_state_meets_are_refused_with_the_cause(goal, reason):
    messages, refusal = goal_problems(WORLD, goal)
    assert refusal and reason in refusal, refusal
    assert refusal.startswith("the command cannot be done in this world: ")


def test_units_pushed_off_shelves_by_upper_bounds_must_fit_elsewhere():
    """Each bound alone is possible; together they leave the units too little room: only the
    flow over every shelf sees it."""
    goal = {"shelf1": {"product1": {"at_most": 0}}, "shelf2": {"product1": {"at_most": 0}},
            "shelf3": {"product2": {"at_least": 3}, "product3": {"at_least": 4}, "product4": {"at_least": 4}},
            "shelf4": {"product4": {"at_least": 6}, "product3": {"at_least": 2}}}
    # shelf3 keeps 11 units (room 19), shelf4 keeps 8 (room 22): 38 units of product1 need 41 of room
    assert goal_problems(WORLD, goal)[1] is None
    tight = {**goal, "shelf4": {"product4": {"at_least": 6}, "product3": {"at_least": 2}, "product2": {"at_least": 2},
                                "product1": {"at_most": 18}}}
    (reason,) = infeasibility_reasons(WORLD, tight)
    assert reason == "38 units of product1 must stay on some shelf, but the goal leaves room for only 37 of them"
    # room that each product alone would find, but not all of them together
    shared = {"shelf1": {"product1": {"at_most": 0}, "product2": {"at_most": 0}},
              "shelf2": {"product1": {"at_most": 0}, "product2": {"at_most": 0}},
              "shelf3": {"product3": {"at_least": 4}, "product4": {"at_least": 4}},
              "shelf4": {"product3": {"at_least": 2}, "product4": {"at_least": 6}}}
    # product1 (38) and product2 (10) may only go to shelf3 and shelf4 (room 22 each): each alone
    # fits, together 48 units find 44 of room; of 59 free units (+9 product3, +2 product4) 55 fit
    (reason,) = infeasibility_reasons(WORLD, shared)
    assert reason == "59 units that the goal leaves free must stay on some shelf, but only 55 fit in the room the goal leaves"


def test_bounds_that_an_exact_count_would_break_are_feasible():
    # every shelf at most 10 product1: 38 units fit (10+10+10+8); at least 0 is no constraint at all
    goal = {s: {"product1": {"at_most": 10}} for s in WORLD["shelves"]}
    goal["shelf3"]["product2"] = {"at_least": 0}
    assert goal_problems(WORLD, goal) == ([], None)


def test_a_malformed_value_from_a_problem_is_a_message_not_a_refusal():
    messages, refusal = goal_problems(WORLD, {"shelf3": {"product1": {"at_least": -2}}})
    assert refusal is None and messages == ["the goal for product1 on shelf3: at_least -2 is negative; "
                                            "counts are whole numbers >= 0"]


# ---------------------------------------------------------------- simulation and scoring
def test_simulation_and_scoring_count_bounds():
    from sim_fixtures import wh01

    from pipflow.warehouse.domain import WarehouseDomain
    from pipflow.warehouse.scoring import goal_conditions
    from pipflow.warehouse.simulation import goal_check, simulate

    def holding(stock: dict, goal: dict) -> list[bool]:
        return [c.holds for c in goal_conditions(stock, goal)]

    score_run = WarehouseDomain().score
    final = {"shelf3": {"product1": 7}, "shelf4": {"product1": 15}}
    goal = {"shelf3": {"product1": {"at_least": 6}}, "shelf4": {"product1": {"at_most": 10}}}
    assert holding(final, goal) == [True, False] and goal_check(final, goal, WORLD["stock"]) == (False, 0.5)
    assert holding(final, {"shelf3": {"product1": {"at_least": 7, "at_most": 7}}}) == [True]
    assert holding(final, {"shelf1": {"product4": {"at_most": 0}}}) == [True]  # an absent product counts 0

    graph, schedule = wh01()  # two units of product1 from shelf1 to shelf3: shelf3 ends with 7
    within = {"shelf3": {"product1": {"at_least": 6, "at_most": 8}}}
    sim = simulate(WORLD, schedule, graph, within)
    assert sim["goal_met"] and sim["gcr"] == 1.0
    assert score_run(WORLD, within, graph=graph, schedule=schedule, simulation=sim)["success"]
    above = {"shelf3": {"product1": {"at_most": 6}}}
    sim = simulate(WORLD, schedule, graph, above)
    assert not sim["goal_met"] and sim["gcr"] == 0.0
    s = score_run(WORLD, above, graph=graph, schedule=schedule, simulation=sim)
    assert not s["success"] and "goal: shelf3 holds at most 6 product1 (it holds 7)" in s["violations"]


# ---------------------------------------------------------------- task files
def _tasks(tmp_path: Path, body: str) -> Path:
    path = tmp_path / "tasks.yaml"
    path.write_text(f"world: {ROOT / 'benchmarks/warehouse/world.yaml'}\ntasks:\n{body}")
    return path


def test_task_bounds_load_as_given(tmp_path):
    t = load_tasks(_tasks(tmp_path,
                          "  - id: b1\n    command: take shelf3 up to ten product1\n"
                          "    construction: bound-at-most\n"
                          "    goal: {shelf3: {product1: {at_most: 10}, product2: 3}}\n"
                          "    constraints: [{never: [robot0], words: not robot 0}]\n"
                          "  - id: b2\n    command: shelf3 needs at least 40 product1\n"
                          "    goal: {shelf3: {product1: {at_least: 40}}}\n    feasible: false\n"
                          "  - id: b3\n    command: put some product1 on shelf3\n"
                          "    goal: {shelf3: {product1: 99}}\n    expect: refuse\n"))
    b1, b2, b3 = t["tasks"]
    assert b1["goal"] == {"shelf3": {"product1": {"at_most": 10}, "product2": 3}}
    assert b1["construction"] == "bound-at-most" and b2["construction"] is None
    assert b1["constraints"] == [{"never": ["robot0"], "words": "not robot 0"}]
    assert b2["feasible"] is False and b3["expect"] == "refuse" and b1["expect"] is None


@pytest.mark.parametrize("goal, line, words", [
    ("{shelf3: {product1: {at_least: 5, at_most: 3}}}", 5, "task b1: goal for 'product1' on 'shelf3': at_least 5 is more than at_most 3"),
    ("{shelf3: {product1: {at_least: -1}}}", 5, "tasks/0/goal/shelf3/product1/at_least: -1 is less than the minimum of 0"),
    ("{shelf3: {product1: {at_leest: 2}}}", 5, "unknown key 'at_leest' in tasks/0/goal/shelf3/product1 (did you mean 'at_least'"),
    ("{shelf3: {product1: -4}}", 5, "tasks/0/goal/shelf3/product1: -4 is less than the minimum of 0"),
    ("{shelf3: {product1: lots}}", 5, "'lots' is not valid: the final count of a product on a shelf"),
    ("{shelf3: {product1: {at_least: 31}}}", 5, "task b1: no final state of the world meets the gold goal "
     "(shelf3 cannot hold at least 31 units of product1: its capacity is 30); fix the goal or mark the task `feasible: false`"),
    ("{shelf3: {product1: 31}}", 5, "shelf3 cannot hold 31 units of product1"),
])
def test_bad_bounds_in_task_files_are_located(tmp_path, goal, line, words):
    path = _tasks(tmp_path, f"  - id: b1\n    command: some command\n    goal: {goal}\n")
    with pytest.raises(WorldError) as info:
        load_tasks(path)
    (d,) = info.value.diagnostics
    assert words in d.message, d.message
    assert d.location.file == str(path) and d.location.line == line


def test_an_infeasible_task_may_ask_over_capacity(tmp_path):
    t = load_tasks(_tasks(tmp_path, "  - id: b1\n    command: c\n    goal: {shelf3: {product1: {at_least: 31}}}\n"
                                    "    feasible: false\n"))
    assert t["tasks"][0]["goal"] == {"shelf3": {"product1": {"at_least": 31}}}


# ---------------------------------------------------------------- the whole pipeline
def test_a_bound_goal_runs_end_to_end_with_enhsp(tmp_path):
    """problem.write -> debug -> ENHSP -> verify -> graph -> SCIP -> schedule -> pybullet."""
    from pipflow.engine import run_workflow

    goal = {"shelf4": {"product1": {"at_most": 9}}, "shelf2": {"product3": {"at_least": 8}}}
    result = run_workflow(ROOT / "tests/fixtures/workflows/warehouse_goal.yaml", {"goal": goal},
                          runs_dir=tmp_path / "runs")
    assert result.ok, result.error
    out = result.outputs
    assert out["engine"] == "enhsp" and out["verified"] and out["goal"] == goal
    assert out["goal_met"] is True and out["gcr"] == 1.0
    assert out["final_stock"]["shelf4"]["product1"] <= 9 and out["final_stock"]["shelf2"]["product3"] >= 8
    # the report's goal table states each bound in the domain's words and that it holds
    from pipflow.records.report import write_report

    page = write_report(result.run_dir).read_text()
    table = page[page.index("<h3>Goal</h3>"):page.index("</table>", page.index("<h3>Goal</h3>"))]
    rows = table.split("<tr>")[2:]
    assert len(rows) == 2 and all("<span class='ok'>yes</span>" in row for row in rows), table
    assert "shelf4 holds at most 9 product1" in table and "shelf2 holds at least 8 product3" in table
    assert table.count("<span class='ok'>yes</span>") == 2


def test_a_bound_goal_no_final_state_meets_is_refused_before_robots_move(tmp_path):
    from pipflow.engine import run_workflow

    goal = {"shelf3": {"product1": {"at_least": 12}, "product2": {"at_least": 20}}}
    result = run_workflow(ROOT / "tests/fixtures/workflows/warehouse_goal.yaml",
                          {"goal": goal, "planner": "pipflow-transport"}, runs_dir=tmp_path / "runs")
    assert result.status == "refused" and result.error_step == "refuse"
    assert "the goal needs at least 20 units of product2 but only 10 exist" in result.error
    assert "the goal puts at least 32 units on shelf3 but its capacity is 30" in result.error
    ran = {d.name for d in (result.run_dir / "steps").iterdir()}
    assert {"verify", "refuse"} <= ran and not ran & {"graph", "allocate", "schedule", "simulate"}


# ---------------------------------------------------------------- properties
@st.composite
def small_world_and_goal(draw):
    """2-3 shelves x 1-3 products with random stock within capacity, and a goal of random counts
    and bounds (often impossible ones)."""
    shelves = [f"s{i}" for i in range(draw(st.integers(2, 3)))]
    products = [f"p{j}" for j in range(draw(st.integers(1, 3)))]
    cap = {s: draw(st.integers(0, 8)) for s in shelves}
    stock = {}
    for s in shelves:
        left, stock[s] = cap[s], {}
        for p in products:
            n = draw(st.integers(0, left))
            left -= n
            if n:
                stock[s][p] = n
    world = {"shelves": {s: {"capacity": cap[s]} for s in shelves}, "products": {p: {} for p in products},
             "stock": stock}
    goal: dict = {}
    for s in shelves:
        for p in products:
            kind = draw(st.sampled_from(["none", "none", "exact", "least", "most", "both"]))
            a, b = sorted(draw(st.lists(st.integers(0, 9), min_size=2, max_size=2)))
            value = {"exact": a, "least": {"at_least": a}, "most": {"at_most": b},
                     "both": {"at_least": a, "at_most": b}}.get(kind)
            if value is not None:
                goal.setdefault(s, {})[p] = value
    return world, goal


def _exists_final_state(world: dict, goal: dict) -> bool:
    """Ground truth by an integer program (scipy's HiGHS MILP): final counts x[s, p] >= 0 within
    each goal value, every unit of each product on some shelf, each shelf within capacity."""
    import numpy as np
    from scipy.optimize import Bounds, LinearConstraint, milp

    shelves, products = list(world["shelves"]), list(world["products"])
    cells = [(s, p) for s in shelves for p in products]
    lo, hi = [], []
    for s, p in cells:
        low, high = limits(goal[s][p]) if p in goal.get(s, {}) else (0, None)
        lo.append(low)
        hi.append(np.inf if high is None else high)
    rows, lb, ub = [], [], []
    for p in products:  # conservation
        rows.append([1.0 if c[1] == p else 0.0 for c in cells])
        units = sum(world["stock"].get(s, {}).get(p, 0) for s in shelves)
        lb.append(units)
        ub.append(units)
    for s in shelves:  # capacity
        rows.append([1.0 if c[0] == s else 0.0 for c in cells])
        lb.append(0)
        ub.append(world["shelves"][s]["capacity"])
    res = milp(np.zeros(len(cells)), constraints=LinearConstraint(np.array(rows), lb, ub),
               integrality=np.ones(len(cells)), bounds=Bounds(lo, hi))
    return res.status == 0


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(small_world_and_goal())
def test_refusal_exactly_when_no_final_state_exists(case):
    world, goal = case
    reasons = infeasibility_reasons(world, goal)
    assert (not reasons) == _exists_final_state(world, goal), reasons


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(small_world_and_goal())
def test_written_goals_read_back_unchanged(case):
    _, goal = case
    goal = {f"shelf{int(s[1:]) + 1}": {f"product{int(p[1:]) + 1}": v for p, v in items.items()}
            for s, items in goal.items()}
    assert stock_goals(parse(DOMAIN, write_problem(WORLD, goal))) == (goal, [])


def test_a_bench_of_bound_tasks_scores_them_by_their_bounds(tmp_path):
    """A task file with bounds, through `pipflow bench`: the command is read, planned, executed and
    scored against the bound gold; an infeasible bound is a correct refusal."""
    import json

    from pipflow.engine.cli import main

    (tmp_path / "tasks.yaml").write_text(
        f"world: {ROOT / 'benchmarks/warehouse/world.yaml'}\n"
        "tasks:\n"
        "  - id: b1\n    command: Shelf 3 should hold at least 8 product1 and at most 2 product2.\n"
        "    goal: {shelf3: {product1: {at_least: 8}, product2: {at_most: 2}}}\n"
        "  - id: b2\n    command: Shelf 3 should hold at least 31 product1.\n"
        "    goal: {shelf3: {product1: {at_least: 31}}}\n    feasible: false\n")
    out = tmp_path / "bench"
    assert main(["bench", str(tmp_path / "tasks.yaml"), "--seeds", "1", "--out", str(out), "-q",
                 "--runs-dir", str(tmp_path / "runs")]) == 0
    rows = {t["id"]: t for t in json.loads((out / "results.json").read_text())["tasks"]}
    assert rows["b1"]["sr"] == 1.0 and rows["b1"]["gcr"] == 1.0 and rows["b1"]["tc_max"] > 0
    assert rows["b2"]["sr"] == 1.0 and "capacity" in rows["b2"]["error"]

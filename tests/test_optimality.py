"""Schedules against the optimum (issue 26, part 3): the exact model of the joint allocation-and-
sequencing problem equals brute-force enumeration replayed by the Timeline; the improvement phase
never worsens (makespan, TC-max, TC-sum), keeps skills, robot rules and the graph; the workflow
input turns it off and then the schedule replays the paper's allocation exactly."""
from __future__ import annotations

import itertools
import json
import random
from pathlib import Path

import numpy as np
import pytest
import yaml
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import pipflow
from pipflow.errors import InputError
from pipflow.team.allocation import Rules, allocate, covers, need_vector, skill_matrix
from pipflow.team.exact import brute_force, solve_exact
from pipflow.team.improve import Search, improve_allocation
from pipflow.team.joint import JointProblem, Plan, lex_less, replay, schedule_key
from pipflow.team.scheduling import build_schedule, predecessors

ROOT = Path(__file__).resolve().parents[1]
FIX = Path(__file__).parent / "fixtures" / "robot"
MINI = yaml.safe_load((FIX / "world.yaml").read_text())  # four shelves, five robots
SHELVES = list(MINI["shelves"])
FREE = [[1, 1], [1, 5], [10, 6], [19, 1], [19, 11], [7, 10], [12, 11], [3, 3], [16, 1], [11, 4]]


def tiny(rng: random.Random, n_sub: int, n_rob: int, *, edges: float = 0.3, rules: bool = True,
         one_place: bool = False) -> tuple[dict, dict, list, list]:
    """A random instance on the mini world: ``n_rob`` robots (carry 1-3) at random free points,
    ``n_sub`` moves between random shelves with random carry needs, random order edges, and
    sometimes an only/never rule and a linear rule. ``one_place``: routes of one shelf."""
    world = dict(MINI)
    starts = rng.sample(FREE, n_rob)
    world["robots"] = {f"r{i}": {"start": starts[i], "skills": {"carry": rng.randint(1, 3)}} for i in range(n_rob)}
    team = sum(r["skills"]["carry"] for r in world["robots"].values())
    nodes = []
    for k in range(n_sub):
        a, b = rng.sample(SHELVES, 2)
        route = [a] if one_place else [a, b]
        nodes.append({"id": f"s{k + 1}", "index": k, "action": "move-product", "args": [a, b, "red"],
                      "skills": {"carry": float(rng.randint(1, min(team, 4)))}, "route": route,
                      "fields": {"product": rng.choice(["red", "blue"]), "from": a, "to": b}})
    graph = {"mode": "exact", "nodes": nodes,
             "edges": [[f"s{i + 1}", f"s{j + 1}"] for i, j in itertools.combinations(range(n_sub), 2)
                       if rng.random() < edges]}
    constraints, linear = [], []
    if rules and rng.random() < 0.4:
        r = rng.choice(list(world["robots"]))
        constraints.append({"never": [r], "product": rng.choice(["red", "blue"])})
    if rules and rng.random() < 0.25:
        linear.append({"robots": "all", "coef": 1, "sense": "<=", "rhs": 2, "name": "at most two robots"})
    return graph, world, constraints, linear


def feasible_or_skip(graph, world, constraints, linear):
    """The instance has a coalition for every subtask (else it is not one to test)."""
    robots, skills, Q = skill_matrix(world, graph["nodes"])
    rules = Rules(robots, skills, Q, constraints, linear, graph["nodes"])
    for node in graph["nodes"]:
        allowed, _ = rules.mask(node)
        idx = np.flatnonzero(allowed)
        ok = False
        for k in range(1, len(idx) + 1):
            for combo in itertools.combinations(idx, k):
                x = np.zeros(len(robots))
                x[list(combo)] = 1
                if covers(Q, need_vector(node, skills), x) and all(L.holds(x) for L in rules.lin(node)):
                    ok = True
                    break
            if ok:
                break
        if not ok:
            return False
    return True


# ------------------------------------------------------------------------------- the exact model
@pytest.mark.parametrize("k", range(14))
def test_exact_model_equals_brute_force_on_tiny_instances(k):
    rng = random.Random(f"exact-{k}")
    while True:
        # mostly 3 subtasks and 2-3 robots; some with 4 subtasks (edges keep the orders few)
        n_sub = 4 if k % 4 == 3 else rng.randint(2, 3)
        inst = tiny(rng, n_sub, rng.randint(2, 3), edges=0.5 if n_sub == 4 else 0.3)
        if feasible_or_skip(*inst):
            break
    graph, world, constraints, linear = inst
    p = JointProblem(graph, world, constraints, linear)
    best_key, best_plan = brute_force(p)
    ex = solve_exact(p, time_limit=120)
    assert ex.proven
    assert ex.key == pytest.approx(best_key, rel=1e-6, abs=1e-6)
    # the model's plan is a real plan: the Timeline replays it to the same objective
    assert schedule_key(replay(p, ex.plan)) == pytest.approx(best_key, rel=1e-6, abs=1e-6)
    p.check(ex.plan)


@pytest.mark.parametrize("k", range(4))
def test_exact_model_equals_brute_force_with_zero_length_subtasks(k):
    """No handling time and one-place routes: subtasks take no time, so only the ranks keep the
    robots' sequences free of cycles (a cycle has no commit order)."""
    rng = random.Random(f"zero-{k}")
    while True:
        inst = tiny(rng, 3, rng.randint(2, 3), one_place=True, rules=False)
        if feasible_or_skip(*inst):
            break
    graph, world, constraints, linear = inst
    p = JointProblem(graph, world, constraints, linear, handling=0.0)
    assert min(p.duration.values()) == 0.0
    best_key, _ = brute_force(p)
    ex = solve_exact(p, time_limit=120)
    assert ex.proven and ex.key == pytest.approx(best_key, rel=1e-6, abs=1e-6)
    assert schedule_key(replay(p, ex.plan)) == pytest.approx(best_key, rel=1e-6, abs=1e-6)


def test_a_subtask_no_allowed_coalition_can_do_is_an_error():
    rng = random.Random(3)
    graph, world, _, _ = tiny(rng, 2, 2, rules=False)
    never_all = [{"never": list(world["robots"]), "product": graph["nodes"][0]["fields"]["product"]}]
    p = JointProblem(graph, world, never_all)
    with pytest.raises(InputError, match="s1"):
        solve_exact(p, time_limit=30)


@pytest.mark.parametrize("k", range(20))
def test_evaluate_times_a_plan_as_the_timeline_does(k):
    """The search's fast timing and the Timeline agree on random plans (any topological order,
    any allowed covering coalitions)."""
    rng = random.Random(f"eval-{k}")
    while True:
        inst = tiny(rng, rng.randint(2, 6), rng.randint(2, 5))
        if feasible_or_skip(*inst):
            break
    graph, world, constraints, linear = inst
    p = JointProblem(graph, world, constraints, linear, speed=rng.choice([0.5, 1.0, 2.0]))
    order, left = [], list(p.ids)
    while left:
        ready = [s for s in left if all(q in order for q in p.preds[s])]
        s = rng.choice(ready)
        order.append(s)
        left.remove(s)
    coalitions = {}
    for s in order:
        idx = [i for i in range(len(p.robots)) if p.allowed[s][i]]
        options = [c for n in range(1, len(idx) + 1) for c in itertools.combinations(idx, n) if p.feasible(s, c)]
        coalitions[s] = rng.choice(options)
    plan = Plan(order, coalitions)
    sched = replay(p, plan)
    out = p.evaluate(plan)
    assert out.key == pytest.approx(schedule_key(sched), rel=1e-9, abs=1e-9)
    for rec in sched["subtasks"]:
        assert out.start[rec["id"]] == pytest.approx(rec["start"]) and out.end[rec["id"]] == pytest.approx(rec["end"])


# ------------------------------------------------------------------------------- the improvement
def _check_plan(graph, world, constraints, linear, allocation):
    """Every subtask once, after its predecessors, by robots the rules allow that cover its skills."""
    robots, skills, Q = skill_matrix(world, graph["nodes"])
    rules = Rules(robots, skills, Q, constraints, linear, graph["nodes"])
    nodes = {n["id"]: n for n in graph["nodes"]}
    preds = predecessors(graph)
    seen = []
    for a in allocation["assignments"]:
        node = nodes[a["subtask"]]
        assert all(q in seen for q in preds[a["subtask"]]), "committed before a predecessor"
        seen.append(a["subtask"])
        allowed, _ = rules.mask(node)
        x = np.zeros(len(robots))
        for r in a["robots"]:
            assert allowed[robots.index(r)], f"{r} is not allowed on {a['subtask']}"
            x[robots.index(r)] = 1
        assert covers(Q, need_vector(node, skills), x)
        assert all(L.holds(x) for L in rules.lin(node))
        assert set(a["costs"]) == set(a["robots"])
    assert sorted(seen) == sorted(nodes)


@settings(max_examples=30, deadline=None, derandomize=True, suppress_health_check=[HealthCheck.too_slow])
@given(seed=st.integers(0, 10_000), n_sub=st.integers(1, 6), n_rob=st.integers(2, 5),
       speed=st.sampled_from([0.5, 1.0, 1.5]), handling=st.sampled_from([0.0, 2.0]))
def test_improvement_never_worsens_and_keeps_skills_rules_and_graph(seed, n_sub, n_rob, speed, handling):
    rng = random.Random(seed)
    graph, world, constraints, linear = tiny(rng, n_sub, n_rob)
    if not feasible_or_skip(graph, world, constraints, linear):
        return
    paper = allocate(graph, world, constraints=constraints, linear=linear, speed=speed, handling=handling)  # real SCIP
    better = improve_allocation(graph, world, paper, constraints, linear, speed=speed, handling=handling, budget=5000)
    before = schedule_key(build_schedule(graph, paper, world, speed=speed, handling=handling))
    after = schedule_key(build_schedule(graph, better, world, speed=speed, handling=handling))
    assert not lex_less(before, after), f"worse: {before} -> {after}"
    _check_plan(graph, world, constraints, linear, better)
    st_ = better["stats"]["improve"]
    assert st_["improved"] == lex_less(after, before)
    assert [st_["after"][k] for k in ("makespan", "tc_max", "tc_sum")] == pytest.approx(list(after))
    if not st_["improved"]:
        assert better["assignments"] == paper["assignments"]


def test_improvement_keeps_the_users_rules_when_breaking_them_would_be_faster():
    """Two far-apart jobs; the robot next to the second may not take it (a never rule) and the
    team may send at most one robot per subtask (a linear rule): the improvement finds a better
    plan, and it still honours both."""
    world = dict(MINI)
    world["robots"] = {"r0": {"start": [1, 1], "skills": {"carry": 2}},
                       "r1": {"start": [19, 11], "skills": {"carry": 2}},
                       "r2": {"start": [3, 3], "skills": {"carry": 2}},
                       "r3": {"start": [16, 1], "skills": {"carry": 2}}}
    def mv(k, a, b, product):
        return {"id": f"s{k}", "index": k - 1, "action": "move-product", "args": [a, b, product],
                "skills": {"carry": 2.0}, "route": [a, b], "fields": {"product": product, "from": a, "to": b}}
    graph = {"mode": "exact", "nodes": [mv(1, "shelfA", "shelfC", "red"), mv(2, "shelfA", "shelfB", "red"),
                                        mv(3, "shelfB", "shelfD", "blue"), mv(4, "shelfC", "shelfA", "blue")],
             "edges": [["s1", "s4"]]}
    constraints = [{"never": ["r1"], "product": "blue"}]
    linear = [{"robots": "all", "coef": 1, "sense": "<=", "rhs": 1, "name": "one robot per subtask"}]
    paper = allocate(graph, world, constraints=constraints, linear=linear)
    better = improve_allocation(graph, world, paper, constraints, linear)
    _check_plan(graph, world, constraints, linear, better)
    before = schedule_key(build_schedule(graph, paper, world))
    after = schedule_key(build_schedule(graph, better, world))
    assert not lex_less(before, after)
    # the brute-force optimum bounds it from below, and the improvement reaches it here
    p = JointProblem(graph, world, constraints, linear)
    best, _ = brute_force(p)
    assert not lex_less(after, best)
    assert after[0] == pytest.approx(best[0])


def test_search_is_deterministic_for_a_seed():
    rng = random.Random(11)
    while True:
        inst = tiny(rng, 5, 4, rules=False)
        if feasible_or_skip(*inst):
            break
    graph, world, constraints, linear = inst
    paper = allocate(graph, world)
    runs = [improve_allocation(graph, world, paper, budget=500, seed=7)["assignments"] for _ in range(2)]
    assert runs[0] == runs[1]


def test_an_allocation_that_breaks_the_rules_is_refused_not_repaired():
    rng = random.Random(5)
    graph, world, _, _ = tiny(rng, 2, 3, rules=False)
    paper = allocate(graph, world)
    first = paper["assignments"][0]
    product = next(n for n in graph["nodes"] if n["id"] == first["subtask"])["fields"]["product"]
    rule = [{"never": [first["robots"][0]], "product": product}]  # a rule the allocation did not have
    with pytest.raises(InputError, match="not a valid plan"):
        improve_allocation(graph, world, paper, rule)


# ------------------------------------------------------------------------------- the workflow input
COMMAND = "Empty shelf4."


def _small_team_world(tmp_path: Path) -> Path:
    """The paper's world with six of its robots, most of them far from shelf4: emptying it takes
    five moves, and Alg. 1 (with either allocation cost) leaves the makespan 10-50% above what
    the improvement finds."""
    world = yaml.safe_load((ROOT / "benchmarks" / "warehouse" / "world.yaml").read_text())
    starts = {"robot3": [9.0, 9.5], "robot5": [9.0, 17.5], "robot7": [8.0, 9.0], "robot8": [11.0, 2.0],
              "robot10": [1.0, 8.0], "robot11": [9.5, 3.0]}
    world["robots"] = {r: {**world["robots"][r], "start": xy} for r, xy in starts.items()}
    path = tmp_path / "world.yaml"
    path.write_text(yaml.safe_dump(world, sort_keys=False))
    return path


def _step(run, sid: str) -> dict:
    return json.loads((Path(run.record) / "steps" / sid / "outputs.json").read_text())


def test_workflow_input_off_replays_the_papers_allocation_exactly(tmp_path):
    world = _small_team_world(tmp_path)
    run = pipflow.run("warehouse", command=COMMAND, world=str(world),
                      runs_dir=str(tmp_path / "runs"), cache=False)
    assert run.status == "succeeded", run.error
    events = [json.loads(line) for line in (Path(run.record) / "events.jsonl").read_text().splitlines()]
    assert any(e.get("event") == "skip" and e.get("step") == "improve" for e in events)
    alloc = _step(run, "allocate")["allocation"]
    expected = build_schedule(run.outputs["graph"], alloc, yaml.safe_load(world.read_text()))
    assert run.outputs["schedule"]["subtasks"] == expected["subtasks"]
    assert run.outputs["makespan"] == pytest.approx(expected["makespan"])


def test_workflow_input_on_improves_and_the_simulation_replays_it(tmp_path):
    world = _small_team_world(tmp_path)
    off = pipflow.run("warehouse", command=COMMAND, world=str(world),
                      runs_dir=str(tmp_path / "runs"), cache=False)
    on = pipflow.run("warehouse-improve", command=COMMAND, world=str(world),
                     runs_dir=str(tmp_path / "runs"), cache=False)
    assert off.status == on.status == "succeeded", (off.error, on.error)
    assert on.outputs["makespan"] < 0.95 * off.outputs["makespan"]
    improved = _step(on, "improve")
    assert improved["improved"] is True
    assert improved["after"]["makespan"] == pytest.approx(on.outputs["makespan"])
    # the simulation executes the improved schedule: every move done, goal met, same timing
    assert on.outputs["goal_met"] is True and on.outputs["exe"] == 1.0
    assert on.outputs["simulation"]["makespan"] == pytest.approx(on.outputs["makespan"])
    assert on.outputs["goal"] == off.outputs["goal"]


def test_the_step_searches_with_the_libraries_default_budget():
    from pipflow.steps.improve import local
    from pipflow.team.improve import DEFAULT_BUDGET

    assert local.inputs["budget"].default == DEFAULT_BUDGET


def test_a_skill_only_far_robots_have_is_found_in_a_big_team():
    """In a team larger than the candidate lists, a subtask whose skill only two far robots have
    still gets them: the search widens its look when the soonest robots cannot cover a need."""
    world = dict(MINI)
    points = [[x, y] for y in (1, 5, 6, 11) for x in range(1, 20, 2)]
    world["robots"] = {f"r{i}": {"start": points[i], "skills": {"carry": 1}} for i in range(40)}
    for far in ("r38", "r39"):  # the top right corner: farther from the shelves than all but a few
        world["robots"][far]["skills"] = {"carry": 1, "lift": 1}

    def mv(k, a, b, skills):
        return {"id": f"s{k}", "index": k - 1, "action": "move-product", "args": [a, b, "red"], "skills": skills,
                "route": [a, b], "fields": {"product": "red", "from": a, "to": b}}
    graph = {"mode": "exact", "nodes": [mv(1, "shelfC", "shelfA", {"carry": 2.0}), mv(2, "shelfC", "shelfD", {"carry": 1.0}),
                                        mv(3, "shelfC", "shelfA", {"carry": 1.0, "lift": 1.0}),
                                        mv(4, "shelfA", "shelfC", {"carry": 3.0})],
             "edges": [["s1", "s4"]]}
    paper = allocate(graph, world)
    better = improve_allocation(graph, world, paper)
    _check_plan(graph, world, [], [], better)
    lifted = next(a for a in better["assignments"] if a["subtask"] == "s3")
    assert set(lifted["robots"]) & {"r38", "r39"}
    assert not lex_less(schedule_key(build_schedule(graph, paper, world)), schedule_key(build_schedule(graph, better, world)))

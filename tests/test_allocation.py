"""Allocation: the fast lexicographic model gives the true optimum; rules hold; failures are clear."""
from pathlib import Path

import numpy as np
import pytest
import yaml

from pipflow import StepContext
from pipflow.team.allocation import (Linear, allocate, brute_force, first_stage_fast, solve_lexicographic,
                                solve_naive)
from pipflow.errors import AllocationError, InputError, Refusal, TeamLacksSkill

FIX = Path(__file__).parent / "fixtures" / "robot"
WORLD = yaml.safe_load((FIX / "world.yaml").read_text())


def node(sid, a, b, product, carry, index=0):
    return {"id": sid, "index": index, "action": "move-product", "args": [a, b, product, f"m{carry}"],
            "skills": {"carry": float(carry)}, "route": [a, b],
            "fields": {"product": product, "from": a, "to": b}}


def graph(*nodes, edges=()):
    return {"mode": "exact", "nodes": list(nodes), "edges": [list(e) for e in edges]}


def random_instance(rng, n, skills=1, with_lin=False):
    Q = rng.integers(0, 4, size=(n, skills)).astype(float)
    Q[rng.random((n, skills)) < 0.2] = 0
    Y = rng.integers(1, 3 * min(n, 4) + 1, size=skills).astype(float)
    c = np.round(rng.uniform(0, 50, size=n), 1)  # rounded: ties happen
    allowed = rng.random(n) > 0.15
    lin = []
    if with_lin:
        coef = (rng.random(n) < 0.5).astype(float)
        lin.append(Linear(coef, "<=", float(rng.integers(1, 3)), "random <="))
        if rng.random() < 0.5:
            lin.append(Linear(np.ones(n), ">=", 2.0, "at least two robots"))
    return Q, Y, c, allowed, lin


@pytest.mark.parametrize("seed", range(40))
def test_fast_matches_brute_force_on_tiny_instances(seed):
    rng = np.random.default_rng(seed)
    n = int(rng.integers(3, 9))
    Q, Y, c, allowed, lin = random_instance(rng, n, skills=int(rng.integers(1, 3)), with_lin=seed % 2 == 1)
    best = brute_force(Q, Y, c, allowed, lin)
    sol = solve_lexicographic(Q, Y, c, allowed, lin)
    if best is None:
        assert sol.robots == []
        return
    x = np.zeros(n)
    x[sol.robots] = 1
    assert np.all(Q.T @ x >= Y - 1e-9)
    assert all(L.holds(x) for L in lin)
    assert all(allowed[i] for i in sol.robots)
    assert (sol.max_cost, sol.sum_cost) == pytest.approx(best)


@pytest.mark.parametrize("seed", range(12))
def test_fast_matches_naive_scip_on_random_instances(seed):
    rng = np.random.default_rng(1000 + seed)
    n = [30, 120, 400][seed % 3]
    Q, Y, c, allowed, lin = random_instance(rng, n, skills=1 + seed % 2, with_lin=seed % 4 == 3)
    fast = solve_lexicographic(Q, Y, c, allowed, lin)
    naive = solve_naive(Q, Y, c, allowed, lin)
    assert bool(fast.robots) == bool(naive.robots)
    if fast.robots:
        assert fast.max_cost == pytest.approx(naive.max_cost, abs=1e-6)
        assert fast.sum_cost == pytest.approx(naive.sum_cost, abs=1e-6)


def test_threshold_is_the_smallest_covering_cost():
    Q = np.array([[1.0], [1.0], [3.0], [2.0]])
    c = np.array([1.0, 2.0, 9.0, 5.0])
    allowed = np.ones(4, dtype=bool)
    # carry 3: robots by cost 1,1,2(@5) cover at t=5; robot 2 alone would cost 9
    assert first_stage_fast(Q, np.array([3.0]), c, allowed) == 5.0
    sol = solve_lexicographic(Q, np.array([3.0]), c, allowed)
    assert sol.max_cost == 5.0 and sol.sum_cost == 6.0 and sorted(sol.robots) == [0, 3]
    assert first_stage_fast(Q, np.array([8.0]), c, allowed) is None


def test_world_allocation_obeys_only_and_never_rules():
    g = graph(node("s1", "shelfA", "shelfC", "red", 2), node("s2", "shelfB", "shelfA", "blue", 3, 1))
    free = allocate(g, WORLD)
    rules = [{"never": ["r2", "r4"], "product": "red"}, {"only": ["r0", "r1", "r3"], "to": "shelfA"}]
    ruled = allocate(g, WORLD, constraints=rules)
    by = {a["subtask"]: set(a["robots"]) for a in ruled["assignments"]}
    assert not by["s1"] & {"r2", "r4"}
    assert by["s2"] <= {"r0", "r1", "r3"}
    # the rules bind: without them the optimum uses an excluded robot
    free_by = {a["subtask"]: set(a["robots"]) for a in free["assignments"]}
    assert free_by["s1"] & {"r2", "r4"} or not free_by["s2"] <= {"r0", "r1", "r3"}


def test_rules_are_typed_and_match_on_their_fields_only():
    from pipflow.team.allocation import LinearRule, RobotRule, Rules, skill_matrix

    g = graph(node("s1", "shelfA", "shelfC", "red", 2), node("s2", "shelfB", "shelfA", "blue", 3, 1))
    robots, skills, Q = skill_matrix(WORLD, g["nodes"])
    rules = Rules(robots, skills, Q, [{"never": ["r2"], "product": "red", "words": "not r2 for red"}],
                  [{"robots": ["r1"], "sense": "<=", "rhs": 0, "to": "shelfA", "name": "r1 not to A"}], g["nodes"])
    (rule,) = rules.rules
    assert rule == RobotRule("never", frozenset({"r2"}), {"product": "red"}, rule.label)  # words: not a field
    assert rule.applies(g["nodes"][0]) and not rule.applies(g["nodes"][1])
    assert rule.excludes("r2") and not rule.excludes("r1")
    (lin,) = rules.linear
    assert isinstance(lin, LinearRule) and lin.match == {"to": "shelfA"} and lin.label == "r1 not to A"
    assert rules.lin(g["nodes"][0]) == [] and [L.label for L in rules.lin(g["nodes"][1])] == ["r1 not to A"]
    allowed, why = rules.mask(g["nodes"][0])
    assert not allowed[robots.index("r2")] and why == {"r2": rule.label}


def test_the_walk_holds_its_state():
    from pipflow.team.allocation import AllocationWalk

    g = graph(node("s1", "shelfA", "shelfC", "red", 2), node("s2", "shelfC", "shelfA", "red", 1, 1),
              edges=[("s1", "s2")])
    walk = AllocationWalk(g, WORLD, "scip", None, None)
    assert walk.ready() == ["s1"]
    walk.allocate_one("s1")
    assert walk.done == {"s1"} and walk.ready() == ["s2"] and len(walk.solve_s) == 1
    walk.run_per_subtask()  # s1 is done: only s2 is left
    assert [a["subtask"] for a in walk.assignments] == ["s1", "s2"]
    assert walk.result("subtask", 0.0)["assignments"] == allocate(g, WORLD)["assignments"]


def test_linear_constraints_from_yaml_data():
    g = graph(node("s1", "shelfB", "shelfD", "blue", 3))
    base = allocate(g, WORLD)["assignments"][0]["robots"]
    assert base == ["r4"]  # carry 3 alone, nearest
    # "at least two robots in every blue move" and "r3 takes part"
    lin = [{"robots": "all", "sense": ">=", "rhs": 2, "product": "blue"},
           {"coef": {"r3": 1}, "sense": "==", "rhs": 1}]
    got = allocate(g, WORLD, linear=lin)["assignments"][0]["robots"]
    assert len(got) >= 2 and "r3" in got
    # carry capacity cap via `skill`: total carry of the coalition at most 3
    capped = allocate(g, WORLD, linear=[{"robots": "all", "skill": "carry", "sense": "<=", "rhs": 3},
                                        {"robots": ["r4"], "sense": "<=", "rhs": 0}])
    robots = capped["assignments"][0]["robots"]
    assert "r4" not in robots and sum(WORLD["robots"][r]["skills"]["carry"] for r in robots) == 3


def test_infeasible_names_subtask_skill_and_rules():
    g = graph(node("s1", "shelfA", "shelfC", "red", 6))
    rules = [{"never": ["r4"], "product": "red"}, {"only": ["r0", "r1", "r2", "r4"], "from": "shelfA"}]
    with pytest.raises(AllocationError) as err:
        allocate(g, WORLD, constraints=rules)
    msg = str(err.value)
    assert "s1" in msg and "carry" in msg and "needs 6" in msg and "short by 2" in msg
    assert "r4 excluded by rule #1" in msg and "r3 excluded by rule #2" in msg
    with pytest.raises(AllocationError, match="linear constraints"):
        allocate(g, WORLD, linear=[{"robots": "all", "sense": "<=", "rhs": 1}])


def test_a_skill_no_allowed_robot_has_is_a_refusal_of_the_command():
    """Short of carry (some robots carry, too little): a failed allocation. No allowed robot has
    the skill at all: the command cannot be done by this team, a refusal (exit 3) that is still
    an AllocationError for a re-allocation after a fault."""
    g = graph(node("s1", "shelfA", "shelfC", "red", 6))
    with pytest.raises(AllocationError) as short:
        allocate(g, WORLD, constraints=[{"never": ["r4"], "product": "red"}, {"only": ["r0", "r1", "r2", "r4"],
                                                                                "from": "shelfA"}])
    assert not isinstance(short.value, Refusal)
    with pytest.raises(TeamLacksSkill) as none:
        allocate(g, WORLD, constraints=[{"only": ["r0"]}, {"never": ["r0"], "product": "red"}])
    assert isinstance(none.value, AllocationError) and isinstance(none.value, Refusal)
    assert none.value.exit_code == 3 and "the whole team has" in str(none.value)


def test_bad_rules_are_input_errors():
    g = graph(node("s1", "shelfA", "shelfC", "red", 1))
    with pytest.raises(InputError, match="unknown robots"):
        allocate(g, WORLD, constraints=[{"never": ["robot99"]}])
    with pytest.raises(InputError, match="no field"):
        allocate(g, WORLD, constraints=[{"never": ["r0"], "colour": "red"}])
    with pytest.raises(InputError, match="sense"):
        allocate(g, WORLD, linear=[{"robots": "all", "sense": "<", "rhs": 1}])
    with pytest.raises(InputError, match="exactly one"):
        allocate(g, WORLD, constraints=[{"only": ["r0"], "never": ["r1"]}])


def test_baselines_cover_skills_and_cost_at_least_the_optimum():
    nodes = [node("s1", "shelfA", "shelfC", "red", 4), node("s2", "shelfB", "shelfD", "blue", 3, 1),
             node("s3", "shelfA", "shelfB", "blue", 2, 2)]
    g = graph(*nodes, edges=[("s1", "s3"), ("s2", "s3")])
    results = {m: allocate(g, WORLD, method=m) for m in ("scip", "greedy", "blind")}
    for m, res in results.items():
        assert [a["subtask"] for a in res["assignments"]][-1] == "s3"  # after both parents
        for a in res["assignments"]:
            need = next(n for n in nodes if n["id"] == a["subtask"])["skills"]["carry"]
            assert sum(WORLD["robots"][r]["skills"]["carry"] for r in a["robots"]) >= need
    # the first subtask sees the same positions under every method: scip's max cost is minimal
    first = {m: max(r["assignments"][0]["costs"].values()) for m, r in results.items()}
    assert first["scip"] <= first["greedy"] + 1e-9 and first["scip"] <= first["blind"] + 1e-9


def test_frontier_mode_reports_gap_and_covers_everything():
    nodes = [node("s1", "shelfA", "shelfC", "red", 2), node("s2", "shelfB", "shelfD", "blue", 3, 1),
             node("s3", "shelfA", "shelfB", "red", 3, 2)]
    g = graph(*nodes)
    res = allocate(g, WORLD, mode="frontier", time_limit=5)
    assert res["method"] == "scip-frontier"
    assert sorted(a["subtask"] for a in res["assignments"]) == ["s1", "s2", "s3"]
    waves = res["stats"]["waves"]
    assert all("gap" in w or w.get("fallback") for w in waves)
    # within one wave no robot is in two coalitions
    for w in waves:
        robots = [r for a in res["assignments"] if a["subtask"] in w.get("allocated", []) for r in a["robots"]]
        assert len(robots) == len(set(robots))
    per = allocate(g, WORLD)
    assert res["stats"]["predicted"]["makespan"] <= per["stats"]["predicted"]["makespan"] + 1e-6


def test_frontier_mode_never_hangs_on_a_big_wave():
    import time

    rng = np.random.default_rng(7)
    world = dict(WORLD, robots={f"q{i}": {"start": [float(rng.uniform(0.5, 19.5)), 0.5 + 0.1 * (i % 5)],
                                          "skills": {"carry": int(rng.integers(1, 4))}} for i in range(60)})
    shelves = ["shelfA", "shelfB", "shelfC", "shelfD"]
    nodes = [node(f"s{k + 1}", shelves[k % 4], shelves[(k + 1) % 4], "red", int(rng.integers(1, 7)), k)
             for k in range(20)]
    t0 = time.perf_counter()
    res = allocate(graph(*nodes), world, mode="frontier", time_limit=2.0)
    assert time.perf_counter() - t0 < 15
    assert len(res["assignments"]) == 20


def test_steps_write_the_allocation_contract(tmp_path):
    from pipflow.steps.allocate import blind, greedy, scip

    g = graph(node("s1", "shelfA", "shelfC", "red", 2))
    for st, name in ((scip, "scip"), (greedy, "greedy"), (blind, "blind")):
        ctx = StepContext(name, tmp_path / name, FIX)
        out = st.func(ctx, graph=g, world=WORLD)["allocation"]
        assert out["method"] == name
        a = out["assignments"][0]
        assert a["subtask"] == "s1" and set(a["costs"]) == set(a["robots"])
        assert (tmp_path / name / "allocation.json").is_file()


def test_a_robot_that_adds_no_skill_is_not_taken_even_when_it_costs_nothing():
    """Two robots already stand at the place (cost 0): only the one with the needed skill goes.
    Equal totals must not drag an idle robot into the coalition (it would be blocked for the
    subtask's duration for nothing)."""
    Q = np.array([[1.0, 0.0],   # robot 0: lifts, cannot open
                  [0.0, 1.0],   # robot 1: opens
                  [0.0, 1.0]])  # robot 2: opens, but is far away
    Y = np.array([0.0, 1.0])   # the subtask needs `open` only
    c = np.array([0.0, 0.0, 9.0])
    allowed = np.ones(3, dtype=bool)
    for method in ("fast", "naive"):
        assert solve_lexicographic(Q, Y, c, allowed, method=method).robots == [1], method


def test_scip_outcomes_are_an_enum_that_reads_as_scips_word():
    import json

    from pipflow.team.allocation import USABLE_OUTCOMES, IPStatus

    assert IPStatus("timelimit") is IPStatus.TIME_LIMIT and f"{IPStatus.INFEASIBLE}" == "infeasible"
    assert IPStatus("a word of a newer SCIP") is IPStatus.UNKNOWN
    assert IPStatus.OPTIMAL in USABLE_OUTCOMES and IPStatus.INFEASIBLE not in USABLE_OUTCOMES
    # an infeasible model answers with the enum, and it is the word in JSON
    Q, Y, c = np.array([[1.0]]), np.array([2.0]), np.array([1.0])
    sol = solve_naive(Q, Y, c, np.array([True]))
    assert sol.robots == [] and sol.stats["status"] is IPStatus.INFEASIBLE
    assert json.loads(json.dumps(sol.stats)) == {"status": "infeasible"}


def test_frontier_waves_record_scips_outcome():
    from pipflow.team.allocation import IPStatus

    g = graph(node("s1", "shelfA", "shelfC", "red", 2), node("s2", "shelfB", "shelfD", "blue", 1, index=1))
    waves = allocate(g, WORLD, mode="frontier", time_limit=5.0)["stats"]["waves"]
    assert waves and all(isinstance(w["status"], IPStatus) for w in waves)
    assert waves[0]["status"] is IPStatus.OPTIMAL and waves[0]["allocated"] == ["s1", "s2"]


@pytest.mark.parametrize("level", [float("nan"), float("inf"), -1, "lots"])
def test_skill_levels_and_needs_must_be_finite_and_non_negative(level):
    """A NaN need compares false with every level and would silently drop its row; a negative
    level breaks the fast first stage (more robots must never cover less)."""
    bad_world = yaml.safe_load(yaml.safe_dump(WORLD))
    bad_world["robots"]["r1"]["skills"]["carry"] = level
    g = graph(node("s1", "shelfA", "shelfC", "red", 2))
    with pytest.raises(InputError, match="robot r1: skill 'carry'"):
        allocate(g, bad_world)
    bad_node = node("s1", "shelfA", "shelfC", "red", 2)
    bad_node["skills"]["carry"] = level
    with pytest.raises(InputError, match="subtask s1: needed skill 'carry'"):
        allocate(graph(bad_node), WORLD)

"""Dependency graph: read/write interaction from UP grounding; exact vs the paper's Alg. 2."""
import json
from pathlib import Path

import networkx as nx
import pytest
import yaml

from pipflow import StepContext
from pipflow.dependency import build_graph, to_networkx
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


def _applicable_in_order(order: list[dict]) -> bool:
    """Execute actions with UP's sequential simulator; False if any precondition fails."""
    from unified_planning.engines import UPSequentialSimulator
    from unified_planning.io import PDDLReader

    problem = PDDLReader().parse_problem_string(DOMAIN, PROBLEM)
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
                            actions="warehouse_mini.actions.yaml")
    assert out["graph"]["mode"] == "exact"
    assert json.loads((tmp_path / "art" / "graph.json").read_text()) == out["graph"]
    assert '"s1" -> "s3"' in (tmp_path / "art" / "graph.dot").read_text()
    assert (tmp_path / "art" / "graph.png").read_bytes()[:4] == b"\x89PNG"

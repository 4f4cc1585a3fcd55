"""The allocation cost c_i (paper, Sec. IV-C as typeset; issue 20 calls it III-C): by default each
robot's total travel (what it has driven so far plus this subtask), so the IP's max objective
balances the team's work; the per-subtask cost (approach and route of this subtask only) stays
available as ``cost: subtask``. Through SCIP, both walks, the steps and the built-in workflows, and the run record."""
from __future__ import annotations

import collections
import json
from pathlib import Path

import pytest
import yaml

from pipflow import StepContext
from pipflow.engine.runner import find_workflow
from pipflow.engine.validate import load_workflow
from pipflow.errors import InputError
from pipflow.team.allocation import allocate
from pipflow.team.dependency import build_graph
from pipflow.team.scheduling import COSTS, Timeline, build_schedule

FIX = Path(__file__).parent / "fixtures" / "robot"
ROBOT_WORLD = yaml.safe_load((FIX / "world.yaml").read_text())

# Two shelves 12 m apart on a straight aisle; r0 starts at shelfA's access point, r1 4 m from
# shelfB's. Each subtask needs one unit of carry, so one robot suffices for any of them.
AISLE = {
    "name": "aisle", "floor": {"width": 20, "height": 12},
    "shelves": {"shelfA": {"x": 2, "y": 8, "width": 4, "depth": 1, "capacity": 10, "access": [4, 7]},
                "shelfB": {"x": 14, "y": 8, "width": 4, "depth": 1, "capacity": 10, "access": [16, 7]}},
    "products": {"red": {"color": "red"}},
    "stock": {"shelfA": {"red": 3}, "shelfB": {}},
    "robots": {"r0": {"start": [4, 7], "skills": {"carry": 1}},
               "r1": {"start": [16, 3], "skills": {"carry": 1}}},
}


def move(sid: str, a: str, b: str, index: int) -> dict:
    return {"id": sid, "index": index, "action": "move-product", "args": [a, b, "red", "m1"],
            "skills": {"carry": 1.0}, "route": [a, b], "fields": {"product": "red", "from": a, "to": b}}


# a chain: red goes A -> B, back B -> A, and A -> B again
CHAIN = {"mode": "exact",
         "nodes": [move("s1", "shelfA", "shelfB", 0), move("s2", "shelfB", "shelfA", 1),
                   move("s3", "shelfA", "shelfB", 2)],
         "edges": [["s1", "s2"], ["s2", "s3"]]}


def who(alloc: dict) -> dict[str, list[str]]:
    return {a["subtask"]: a["robots"] for a in alloc["assignments"]}


@pytest.mark.parametrize("method,mode", [("scip", "subtask"), ("naive", "subtask"), ("scip", "frontier"),
                                         ("greedy", "subtask")])
def test_total_travel_shares_a_chain_the_subtask_cost_gives_to_one_robot(method, mode):
    """With the subtask cost the robot that stands at each next subtask's start always costs
    least (12 m against r1's 16 m), so r0 does all three moves and r1 idles. With the total
    travel r0 has already driven 12 m when s2 comes: r1 (16 m in all) is cheaper than r0 (24 m),
    and again for s3 (28 m against 36 m). The trade-off: TC-max falls, the sum of travel rises."""
    subtask = allocate(CHAIN, AISLE, method=method, mode=mode, cost="subtask")
    total = allocate(CHAIN, AISLE, method=method, mode=mode, cost="total")
    assert who(subtask) == {"s1": ["r0"], "s2": ["r0"], "s3": ["r0"]}
    assert who(total) == {"s1": ["r0"], "s2": ["r1"], "s3": ["r1"]}
    by_subtask, by_total = build_schedule(CHAIN, subtask, AISLE), build_schedule(CHAIN, total, AISLE)
    assert by_subtask["tc_max"] == pytest.approx(36.0) and by_total["tc_max"] == pytest.approx(28.0)
    travel = {name: sum(r["distance"] for r in s["robots"].values()) for name, s in
              (("subtask", by_subtask), ("total", by_total))}
    assert travel == pytest.approx({"subtask": 36.0, "total": 40.0})
    assert total["cost"] == total["stats"]["cost"] == "total"
    assert subtask["cost"] == subtask["stats"]["cost"] == "subtask"


def test_the_default_cost_is_the_papers_total_travel():
    assert COSTS[0] == "total"
    assert allocate(CHAIN, AISLE)["cost"] == "total"
    assert who(allocate(CHAIN, AISLE)) == who(allocate(CHAIN, AISLE, cost="total"))


def _mini_graph() -> dict:
    domain = (FIX / "warehouse_mini.pddl").read_text()
    problem = (FIX / "problem.pddl").read_text()
    meta = yaml.safe_load((FIX / "warehouse_mini.actions.yaml").read_text())

    def mv(a, b, p, m):
        return {"action": "move-product", "args": [a, b, p, m]}

    plan = [mv("shelfA", "shelfC", "red", "m3"), mv("shelfB", "shelfD", "blue", "m2"),
            mv("shelfC", "shelfD", "red", "m2"), mv("shelfA", "shelfB", "blue", "m1"),
            mv("shelfB", "shelfA", "red", "m1"), mv("shelfA", "shelfC", "red", "m2")]
    return build_graph(domain, problem, plan, meta)


@pytest.mark.parametrize("method,mode", [("scip", "subtask"), ("scip", "frontier"), ("greedy", "subtask"),
                                         ("blind", "subtask")])
@pytest.mark.parametrize("cost", COSTS)
def test_the_costs_the_allocator_optimised_are_the_distances_the_schedule_reports(method, mode, cost):
    """One source of truth: with the total cost a robot's cost in its last subtask is its whole
    distance in the schedule (so the largest cost is TC-max); with the subtask cost a robot's
    costs add up to its distance."""
    graph = _mini_graph()
    alloc = allocate(graph, ROBOT_WORLD, method=method, mode=mode, cost=cost)
    sched = build_schedule(graph, alloc, ROBOT_WORLD)
    seen: dict[str, list[float]] = collections.defaultdict(list)
    for a in alloc["assignments"]:
        assert set(a["costs"]) == set(a["robots"])
        for r, c in a["costs"].items():
            seen[r].append(c)
    assert seen, "nothing allocated"
    for robot, costs in seen.items():
        driven = sched["robots"][robot]["distance"]
        if cost == "total":
            assert costs == sorted(costs) and costs[-1] == pytest.approx(driven, abs=1e-9), robot
        else:
            assert sum(costs) == pytest.approx(driven, abs=1e-9), robot
    if cost == "total":
        assert max(max(c) for c in seen.values()) == pytest.approx(sched["tc_max"])
    assert alloc["stats"]["predicted"]["tc_max"] == pytest.approx(sched["tc_max"])


def test_an_unknown_cost_is_refused_naming_both():
    with pytest.raises(InputError, match="unknown allocation cost 'distance'.*total.*subtask"):
        allocate(CHAIN, AISLE, cost="distance")
    with pytest.raises(InputError, match="unknown allocation cost"):
        Timeline(AISLE, cost="")


def test_every_allocate_step_takes_the_cost_by_name_and_records_it(tmp_path):
    from pipflow.engine.registry import default_registry
    from pipflow.steps.allocate import blind, greedy, scip

    registry = default_registry()
    for name, st in (("scip", scip), ("greedy", greedy), ("blind", blind)):
        spec = registry.get(f"allocate.{name}")
        assert list(spec.inputs["cost"].choices) == list(COSTS) and spec.inputs["cost"].default == "total"
        for cost in COSTS:
            folder = tmp_path / name / cost
            out = st.func(StepContext(name, folder, FIX), graph=CHAIN, world=AISLE, cost=cost)
            assert out["cost"] == cost == out["allocation"]["cost"]
            written = json.loads((folder / "allocation.json").read_text())
            assert written["cost"] == written["stats"]["cost"] == cost


def _built_in_workflows() -> dict[str, bool]:
    """Every built-in workflow by name, and whether it has an allocate step."""
    out = {}
    for path in sorted(find_workflow("warehouse").parent.glob("*.yaml")):
        steps = load_workflow(path).all_steps()
        out[path.stem] = any(s.uses.startswith("allocate.") for s in steps)
    return out


BUILT_IN = _built_in_workflows()


@pytest.mark.parametrize("name", sorted(n for n, allocates in BUILT_IN.items() if allocates))
def test_every_built_in_workflow_passes_its_allocation_cost_input_to_the_allocator(name):
    """The built-in workflows and their variants (greedy and blind replace the allocate step)
    declare the input with the paper's default and hand it to the allocator, and output it."""
    workflow = load_workflow(find_workflow(name))
    allocators = [s for s in workflow.all_steps() if s.uses.startswith("allocate.")]
    spec = workflow.inputs["allocation_cost"]
    assert spec.default == "total" and list(spec.choices) == list(COSTS)
    for st in allocators:
        assert st.args.get("cost") == "${inputs.allocation_cost}", (name, st.id)
    assert workflow.outputs.get("allocation_cost") == f"${{{allocators[0].id}.cost}}"


def test_the_workflows_without_an_allocator_are_the_baselines_whose_model_names_the_robots():
    """Only the paper's baselines have no allocate step: their model's plan names its robots
    (steps baseline.*). Any other workflow without one would have escaped the cost check above."""
    for name in (n for n, allocates in BUILT_IN.items() if not allocates):
        uses = {s.uses for s in load_workflow(find_workflow(name)).all_steps()}
        assert any(u.startswith("baseline.") for u in uses), (name, sorted(uses))


WH05 = ("There should be 20 product1 in shelf2, 16 product1 in shelf4, 2 product1 in shelf3. "
        "But robot 0 should not be used to move product1 from one shelf to another.")


def test_the_warehouse_run_records_which_cost_ran_and_the_total_balances_wh05(tmp_path):
    """The paper's task 5 (seed 0): with the subtask cost one robot does 3 of the 5 moves; with
    the total travel the busiest robot does fewer and TC-max falls. Each run's outputs and
    allocation record say which cost ran."""
    from pipflow.engine import run_workflow

    runs = {}
    for cost in COSTS:
        result = run_workflow("warehouse", {"command": WH05, "seed": 0, "allocation_cost": cost},
                              runs_dir=tmp_path / cost)
        assert result.ok, result.error
        assert result.outputs["allocation_cost"] == cost
        record = json.loads((result.run_dir / "steps" / "allocate" / "artifacts" / "allocation.json").read_text())
        assert record["cost"] == record["stats"]["cost"] == cost
        runs[cost] = result.outputs
    busiest = {cost: max(collections.Counter(r for s in out["schedule"]["subtasks"] for r in s["robots"]).values())
               for cost, out in runs.items()}
    assert busiest["total"] < busiest["subtask"]
    assert runs["total"]["tc_max"] < runs["subtask"]["tc_max"]
    assert runs["total"]["goal_met"] and runs["subtask"]["goal_met"]


def test_an_unknown_cost_input_is_a_user_error_before_anything_runs(tmp_path, capsys):
    from pipflow.engine.cli import main

    code = main(["run", "warehouse", "-i", "allocation_cost=distance", "--runs-dir", str(tmp_path)])
    assert code == 2
    err = capsys.readouterr().err
    assert "allocation_cost" in err and "total" in err and "subtask" in err and "Traceback" not in err

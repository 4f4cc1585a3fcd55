"""Schedules: precedence, one subtask per robot at a time, coalitions gathered, shelf capacity."""
from pathlib import Path

import pytest
import yaml

from pipflow import StepContext
from pipflow.team.allocation import allocate
from pipflow.team.dependency import build_graph
from pipflow.errors import InputError
from pipflow.team.scheduling import build_schedule
from pipflow.team.travel import TravelMap

FIX = Path(__file__).parent / "fixtures" / "robot"
WORLD = yaml.safe_load((FIX / "world.yaml").read_text())
DOMAIN = (FIX / "warehouse_mini.pddl").read_text()
PROBLEM = (FIX / "problem.pddl").read_text()
META = yaml.safe_load((FIX / "warehouse_mini.actions.yaml").read_text())


def mv(a, b, p, m):
    return {"action": "move-product", "args": [a, b, p, m]}


PLAN = [mv("shelfA", "shelfC", "red", "m3"), mv("shelfB", "shelfD", "blue", "m2"),
        mv("shelfC", "shelfD", "red", "m2"), mv("shelfA", "shelfB", "blue", "m1"),
        mv("shelfB", "shelfA", "red", "m1"), mv("shelfA", "shelfC", "red", "m2")]
CAPACITY = {"shelfA": 10, "shelfB": 10, "shelfC": 6, "shelfD": 6}
LOAD = {"shelfA": 8, "shelfB": 4, "shelfC": 1, "shelfD": 0}
AMOUNT = {f"m{k}": k for k in range(1, 7)}


def check(graph, sched, speed=1.0, handling=2.0):
    subs = {s["id"]: s for s in sched["subtasks"]}
    assert set(subs) == {n["id"] for n in graph["nodes"]}
    for u, v in graph["edges"]:  # precedence
        assert subs[v]["start"] >= subs[u]["end"] - 1e-9
    for name, r in sched["robots"].items():  # one place at a time, legs chained in space and time
        legs = r["legs"]
        for a, b in zip(legs, legs[1:]):
            assert b["start"] >= a["end"] - 1e-9
            assert b["from"] == a["to"]
        assert r["distance"] == pytest.approx(sum(leg["distance"] for leg in legs))
        mine = sorted((s["start"], s["end"]) for s in sched["subtasks"] if name in s["robots"])
        for (s0, e0), (s1, _) in zip(mine, mine[1:]):
            assert s1 >= e0 - 1e-9
    tm = TravelMap(WORLD)
    nodes = {n["id"]: n for n in graph["nodes"]}
    for s in sched["subtasks"]:  # every member has arrived at the first stop before the start
        first = tm.point(nodes[s["id"]]["route"][0])
        for r in s["robots"]:
            arrive = [leg for leg in sched["robots"][r]["legs"] if leg["subtask"] == s["id"]]
            if arrive and arrive[0]["to"] == list(first) and arrive[0]["end"] <= s["start"] + 1e-9:
                continue
            # already standing there: its previous leg ended at the first stop
            before = [leg for leg in sched["robots"][r]["legs"] if leg["end"] <= s["start"] + 1e-9]
            pos = before[-1]["to"] if before else WORLD["robots"][r]["start"]
            assert list(map(float, pos)) == list(first), (s["id"], r)
        assert s["end"] - s["start"] >= handling * len(nodes[s["id"]]["route"]) - 1e-9
    # shelf capacity: applying moves at their end times never overfills a shelf; moves that
    # touch the same shelf never overlap in time
    load = dict(LOAD)
    for s in sorted(sched["subtasks"], key=lambda s: s["end"]):
        a, b, _, m = s["args"]
        load[a] -= AMOUNT[m]
        load[b] += AMOUNT[m]
        assert load[b] <= CAPACITY[b] and load[a] >= 0
    for s in sched["subtasks"]:
        for t in sched["subtasks"]:
            if s["id"] < t["id"] and set(s["args"][:2]) & set(t["args"][:2]):
                assert s["end"] <= t["start"] + 1e-9 or t["end"] <= s["start"] + 1e-9


@pytest.mark.parametrize("method,mode", [("scip", "subtask"), ("greedy", "subtask"), ("blind", "subtask"),
                                         ("scip", "frontier")])
def test_schedule_respects_precedence_capacity_and_gathering(method, mode):
    g = build_graph(DOMAIN, PROBLEM, PLAN, META)
    alloc = allocate(g, WORLD, method=method, mode=mode)
    sched = build_schedule(g, alloc, WORLD)
    check(g, sched)
    assert sched["makespan"] == pytest.approx(alloc["stats"]["predicted"]["makespan"])
    assert sched["tc_max"] == pytest.approx(max(r["distance"] for r in sched["robots"].values()))
    assert sched["tc_avg_team"] == pytest.approx(sum(r["distance"] for r in sched["robots"].values()) / len(WORLD["robots"]))
    moved = [r["distance"] for r in sched["robots"].values() if r["distance"] > 0]
    assert sched["tc_avg"] == pytest.approx(sum(moved) / len(moved))  # the paper's TC-avg
    if len(moved) < len(WORLD["robots"]):
        assert sched["tc_avg"] > sched["tc_avg_team"]


def test_parallel_subtasks_overlap_and_speed_scales_time():
    plan = [mv("shelfA", "shelfC", "red", "m1"), mv("shelfB", "shelfD", "blue", "m1")]
    g = build_graph(DOMAIN, PROBLEM, plan, META)
    assert g["edges"] == []
    alloc = allocate(g, WORLD)
    slow = build_schedule(g, alloc, WORLD, speed=0.5, handling=0)
    fast = build_schedule(g, alloc, WORLD, speed=1.0, handling=0)
    s1, s2 = slow["subtasks"]
    assert set(s1["robots"]).isdisjoint(s2["robots"])
    assert s2["start"] < s1["end"]  # independent moves run at the same time
    assert slow["makespan"] == pytest.approx(2 * fast["makespan"])
    assert slow["tc_max"] == pytest.approx(fast["tc_max"])


def test_handling_time_and_waiting_for_the_coalition():
    # s1 needs carry 5: a coalition gathers; start = the last member's arrival
    g = {"mode": "exact", "edges": [], "nodes": [
        {"id": "s1", "index": 0, "action": "move-product", "args": ["shelfA", "shelfB", "red", "m5"],
         "skills": {"carry": 5.0}, "route": ["shelfA", "shelfB"], "fields": {}}]}
    alloc = {"method": "manual", "assignments": [{"subtask": "s1", "robots": ["r0", "r4"], "costs": {}}], "stats": {}}
    tm = TravelMap(WORLD)
    sched = build_schedule(g, alloc, WORLD, speed=1.0, handling=3.0)
    s = sched["subtasks"][0]
    arrive = max(tm.distance("r0", "shelfA"), tm.distance("r4", "shelfA"))
    assert s["start"] == pytest.approx(arrive)
    assert s["end"] == pytest.approx(arrive + 3.0 * 2 + tm.distance("shelfA", "shelfB"))
    assert sched["robots"]["r1"] == {"legs": [], "distance": 0}


def test_bad_allocations_are_rejected():
    g = build_graph(DOMAIN, PROBLEM, PLAN[:3], META)
    alloc = allocate(g, WORLD)
    out_of_order = dict(alloc, assignments=list(reversed(alloc["assignments"])))
    with pytest.raises(InputError, match="before its predecessors"):
        build_schedule(g, out_of_order, WORLD)
    with pytest.raises(InputError, match="unallocated"):
        build_schedule(g, dict(alloc, assignments=alloc["assignments"][:1]), WORLD)
    with pytest.raises(InputError, match="unknown robots"):
        bad = [dict(a, robots=["robotX"]) for a in alloc["assignments"]]
        build_schedule(g, dict(alloc, assignments=bad), WORLD)


@pytest.mark.parametrize("speed, handling", [(float("nan"), 2.0), (float("inf"), 2.0), (0.0, 2.0), (-1.0, 2.0),
                                             (1.0, float("nan")), (1.0, float("inf")), (1.0, -0.5)])
def test_speed_and_handling_must_be_finite_and_in_range(speed, handling):
    """NaN compares false with everything: it must not slip past the range checks and make
    every time of the schedule (and the allocator's frontier costs) NaN."""
    g = build_graph(DOMAIN, PROBLEM, PLAN[:1], META)
    with pytest.raises(InputError, match="speed|handling"):
        allocate(g, WORLD, speed=speed, handling=handling)
    alloc = allocate(g, WORLD)
    with pytest.raises(InputError, match="speed|handling"):
        build_schedule(g, alloc, WORLD, speed=speed, handling=handling)


def test_schedule_step(tmp_path):
    from pipflow.steps.schedule import schedule

    g = build_graph(DOMAIN, PROBLEM, PLAN, META)
    alloc = allocate(g, WORLD)
    out = schedule.func(StepContext("schedule", tmp_path, FIX), graph=g, allocation=alloc, world=WORLD)
    assert out["makespan"] == out["schedule"]["makespan"] > 0
    assert (tmp_path / "schedule.json").is_file() and (tmp_path / "gantt.png").is_file()
    assert out["tc_avg"] == out["schedule"]["tc_avg"] >= out["tc_avg_team"]
    none = tmp_path / "none"
    schedule.func(StepContext("schedule", none, FIX), graph=g, allocation=alloc, world=WORLD, picture=False)
    assert (none / "schedule.json").is_file() and not (none / "gantt.png").exists()

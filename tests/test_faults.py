"""Execution under faults (issue 27): each fault kind, each recovery path (continue, re-allocate,
re-plan, refuse), a run that takes two faults, faults off meaning the paper's pipeline, the bench
and the report. Every run goes through the real pipeline: the offline reader, the planners
(pipflow-transport, ENHSP), SCIP's allocation, the pybullet warehouse and the home simulator.

The faults are placed from the run without faults (a robot on its way, a robot carrying, a shelf a
robot takes from), so a test says what it exercises rather than trusting a seed's draw."""
from __future__ import annotations

import csv
import json
import math
import subprocess
import sys
from pathlib import Path

import pytest

import pipflow
from pipflow.errors import InputError
from pipflow.execution import faults as fk
from pipflow.experiments.benchmarking import RESULT_FIELDS
from pipflow.team.scheduling import Standing, Timeline
from pipflow.team.trajectory import ARRIVAL_TOLERANCE

REPO = Path(__file__).resolve().parent.parent
WH01 = "There should be 7 product 1 in shelf 3."
WH10 = "shelf4 stores a dozen product3 and a quintet of product1."


def run(tmp_path: Path, command: str, workflow: str = "warehouse", **inputs):
    return pipflow.run(workflow, command=command, runs_dir=tmp_path / "runs", cache=False, **inputs)


def step_outputs(run_, step: str) -> dict:
    data = json.loads((run_.record / "steps" / step / "outputs.json").read_text())
    return data.get("outputs", data)


def legs_of(schedule: dict, robot: str) -> list[dict]:
    return ((schedule.get("robots") or {}).get(robot) or {}).get("legs") or []


def leg_where(schedule: dict, pick) -> tuple[str, dict, dict]:
    """The first (robot, leg, subtask record) of the schedule for which ``pick(leg, record)``."""
    records = {s["id"]: s for s in schedule["subtasks"]}
    for r in sorted(schedule["robots"]):
        for leg in legs_of(schedule, r):
            rec = records.get(leg.get("subtask"))
            if rec is not None and pick(leg, rec):
                return r, leg, rec
    raise AssertionError("no such leg in the schedule")


def approach(leg: dict, rec: dict) -> bool:
    """A leg on the way to a subtask, before its work begins (long enough to be stopped on)."""
    return float(leg["end"]) <= float(rec["start"]) + 1e-9 and float(leg["end"]) - float(leg["start"]) > 2.0


def carrying(leg: dict, rec: dict) -> bool:
    """A leg of a subtask's route, after the load (the robot carries units)."""
    return float(leg["start"]) > float(rec["start"]) and float(leg["end"]) - float(leg["start"]) > 2.0


def crosses(path: list, rect: tuple[float, float, float, float]) -> bool:
    """Does a polyline pass through the open rectangle? (sampled every 5 cm)"""
    for a, b in zip(path, path[1:]):
        n = max(2, int(math.dist(a, b) / 0.05))
        for k in range(n + 1):
            x, y = a[0] + (b[0] - a[0]) * k / n, a[1] + (b[1] - a[1]) * k / n
            if rect[0] < x < rect[2] and rect[1] < y < rect[3]:
                return True
    return False


@pytest.fixture(scope="module")
def base(tmp_path_factory):
    """WH10 and WH01 without faults, seed 3: the schedules the faults are placed in."""
    tmp = tmp_path_factory.mktemp("base")
    return {"wh10": run(tmp, WH10, seed=3), "wh01": run(tmp, WH01, seed=3)}


# ------------------------------------------------------------------------------------------
# faults off: the paper's pipeline, unchanged
# ------------------------------------------------------------------------------------------
def test_without_faults_nothing_changes(tmp_path, base):
    """`none` skips the executor; a fault list that asks for nothing passes everything through."""
    a = base["wh10"]
    b = run(tmp_path, WH10, seed=3, faults="none")
    c = run(tmp_path, WH10, seed=3, faults="off")
    assert a.ok and b.ok and c.ok
    assert a.outputs == b.outputs
    assert a.outputs["faults"] is None and a.outputs["recoveries"] is None
    events = [json.loads(line) for line in (b.record / "events.jsonl").read_text().splitlines()]
    assert any(e.get("event") == "skip" and e.get("step") == "execute" for e in events)
    for key in ("goal", "plan", "schedule", "graph", "makespan", "tc_max", "tc_avg", "goal_met", "exe"):
        assert c.outputs[key] == a.outputs[key], key
    assert c.outputs["faults"] == [] and c.outputs["recoveries"] == []


# ------------------------------------------------------------------------------------------
# robot loss: re-allocate, re-plan, and the monitor's timing
# ------------------------------------------------------------------------------------------
def test_robot_lost_on_its_way_is_replaced_by_reallocation(tmp_path, base):
    schedule = base["wh10"].outputs["schedule"]
    robot, leg, rec = leg_where(schedule, approach)
    t = round((float(leg["start"]) + float(leg["end"])) / 2, 3)
    r = run(tmp_path, WH10, seed=3, faults=[{"kind": "robot-loss", "robot": robot, "time": t}])
    assert r.ok, r.error
    (fault,), (first,) = r.outputs["faults"], r.outputs["recoveries"]
    assert fault["occurred"] and fault["detected"] == pytest.approx(t)  # the heartbeat stops: known at once
    assert first["cause"]["kind"] == "stopped" and first["action"] == "re-allocate"
    assert rec["id"] in first["reallocated"] and robot in first["lost"]
    done = r.outputs["schedule"]
    assert all(robot not in s["robots"] for s in done["subtasks"] if float(s["start"]) > t)
    assert max(float(l["end"]) for l in legs_of(done, robot)) <= t + 1e-6  # it moved no more
    sim = r.outputs["simulation"]
    assert sim["goal_met"] and not sim["failures"]
    assert {p: sim["final_stock"]["shelf4"][p] for p in ("product3", "product1")} == {"product3": 12, "product1": 5}
    # robots on their way to work not yet begun stopped where they were and were given new legs from there
    cut = [l for rr in done["robots"] for l in legs_of(done, rr) if l.get("cut") and l.get("done")]
    assert cut and all(float(l["end"]) == pytest.approx(t) for l in cut)


def test_robot_lost_while_carrying_leaves_its_load_and_the_run_replans(tmp_path, base):
    schedule = base["wh10"].outputs["schedule"]
    robot, leg, rec = leg_where(schedule, carrying)
    t = round((float(leg["start"]) + float(leg["end"])) / 2, 3)
    r = run(tmp_path, WH10, seed=3, faults=[{"kind": "robot-loss", "robot": robot, "time": t}])
    assert r.ok, r.error
    (first,) = r.outputs["recoveries"]
    assert first["action"] == "re-plan" and rec["id"] in first["broken"]
    assert first["replanned"] and all(s.startswith("r1-") for s in first["replanned"])
    assert first["feasible"] is True
    sim = r.outputs["simulation"]
    assert sim["goal_met"] and not sim["failures"]
    drop = f"{robot}-cargo"
    assert drop in sim["final_stock"]  # its units lay where it stopped: a place of the new plan
    before = {p: sum(items.get(p, 0) for items in base["wh10"].outputs["simulation"]["final_stock"].values())
              for p in ("product1", "product3")}
    after = {p: sum(items.get(p, 0) for items in sim["final_stock"].values()) for p in before}
    assert after == before  # every unit is accounted for, on a shelf or on the stopped robot
    assert r.outputs["faults"][0]["drop"] == drop


def test_goal_out_of_reach_after_a_loss_is_refused_saying_what_and_what_was_done(tmp_path):
    """The handler is the only robot that opens the fridge: lost before it does, the goal is out
    of reach; exit 3, the reason, what was carried out, and the record of it."""
    out = subprocess.run([sys.executable, "-m", "pipflow.engine.cli", "run", "household",
                          "-i", "command=Put the apple in the fridge.", "-i", "team=lifters-handler",
                          "-i", "faults=[{kind: robot-loss, robot: robot6, time: 0.5}]",
                          "--runs-dir", str(tmp_path / "runs")], capture_output=True, text=True, cwd=tmp_path)
    assert out.returncode == 3, out.stderr + out.stdout
    assert "Traceback" not in out.stderr
    text = out.stderr + out.stdout
    assert "robot6" in text and "open" in text and "cannot be reached" in text and "Carried out" in text
    record = next((tmp_path / "runs").iterdir())
    execute = json.loads((record / "steps" / "execute" / "outputs.json").read_text())
    execute = execute.get("outputs", execute)
    assert execute["feasible"] is False and "open" in execute["feasibility"]
    assert execute["recoveries"][-1]["action"] == "refuse"
    sim = json.loads((record / "steps" / "simulate" / "outputs.json").read_text())
    assert "executed" in sim.get("outputs", sim)  # the simulation of what was done is kept


def test_two_faults_in_one_run(tmp_path, base):
    """Two robots lost at two moments: two rounds, each from where the team then stands."""
    schedule = base["wh10"].outputs["schedule"]
    first, leg1, _ = leg_where(schedule, approach)
    t1 = round((float(leg1["start"]) + float(leg1["end"])) / 2, 3)
    second = next(r for r in sorted(schedule["robots"], key=lambda r: -len(legs_of(schedule, r)))
                  if r != first and legs_of(schedule, r))
    t2 = round(t1 + 3.0, 3)
    r = run(tmp_path, WH10, seed=3, faults=[{"kind": "robot-loss", "robot": first, "time": t1},
                                            {"kind": "robot-loss", "robot": second, "time": t2}])
    assert r.ok, r.error
    rounds = r.outputs["recoveries"]
    assert [x["cause"]["robot"] for x in rounds] == [first, second]
    assert rounds[1]["lost"] == sorted([first, second])
    done = r.outputs["schedule"]
    for robot, t in ((first, t1), (second, t2)):
        assert all(robot not in s["robots"] for s in done["subtasks"] if float(s["start"]) > t)
    assert r.outputs["simulation"]["goal_met"]


def test_robot_lost_after_its_first_subtask_does_no_other(tmp_path, base):
    """``after: 1``: the robot stops once its first subtask ends; the subtasks it still had go to
    others, and the goal is met."""
    wh06 = "On shelf4, there oughta be 14 prodcut3, 2 prodcut1, and 1 prduct2."  # seven moves for twelve robots
    schedule = run(tmp_path, wh06, seed=3).outputs["schedule"]
    counts = {r: sum(1 for s in schedule["subtasks"] if r in s["robots"]) for r in schedule["robots"]}
    robot = next(r for r, n in sorted(counts.items()) if n >= 2)
    first_end = min(float(s["end"]) for s in schedule["subtasks"] if robot in s["robots"])
    r = run(tmp_path, wh06, seed=3, faults=[{"kind": "robot-loss", "robot": robot, "after": 1}])
    assert r.ok, r.error
    fault = r.outputs["faults"][0]
    assert fault["occurred"] and fault["time"] == pytest.approx(first_end, abs=0.5)
    done = r.outputs["schedule"]["subtasks"]
    assert sum(1 for s in done if robot in s["robots"]) == 1
    assert r.outputs["recoveries"] and r.outputs["simulation"]["goal_met"]


def test_robot_loss_drawn_from_the_seed_is_reproducible(tmp_path):
    a = run(tmp_path, WH10, seed=5, faults="robot-loss=1")
    b = run(tmp_path, WH10, seed=5, faults="robot-loss=1")
    assert a.ok and b.ok
    assert a.outputs["faults"] == b.outputs["faults"] and a.outputs["faults"][0]["drawn"]
    assert a.outputs["simulation"]["final_stock"] == b.outputs["simulation"]["final_stock"]


# ------------------------------------------------------------------------------------------
# stock surprise, slowdown, closed passage
# ------------------------------------------------------------------------------------------
def _source(base_run) -> tuple[str, str, dict]:
    graph = base_run.outputs["graph"]
    node = graph["nodes"][0]
    rec = next(s for s in base_run.outputs["schedule"]["subtasks"] if s["id"] == node["id"])
    return node["fields"]["from"], node["fields"]["product"], rec


def test_stock_surprise_is_found_on_arrival_and_the_run_replans(tmp_path, base):
    shelf, product, rec = _source(base["wh01"])
    world = base["wh01"].outputs  # the records say what the world file says
    r = run(tmp_path, WH01, seed=3, faults=[{"kind": "stock-surprise", "place": shelf, "product": product, "count": 1}])
    assert r.ok, r.error
    (first,) = r.outputs["recoveries"]
    assert first["cause"]["kind"] == "surprise" and first["cause"]["place"] == shelf
    # known when the first robot arrives there, before it takes anything: the load's moment
    assert first["time"] <= float(rec["start"]) + 30 and first["action"] == "re-plan"
    assert rec["id"] in first["aborted"]
    sim = r.outputs["simulation"]
    assert sim["goal_met"] and sim["final_stock"]["shelf3"]["product1"] == 7 and not sim["failures"]
    assert world["goal"] == {"shelf3": {"product1": 7}}


def test_replan_repairs_the_plan_keeping_the_steps_that_still_apply(tmp_path, base):
    """WH10's first move takes from a shelf that holds one unit fewer than recorded: the re-plan
    keeps every step not begun that still applies from the observed state, drops the one that
    takes more than is there, and plans only what that leaves undone; with repair=false the
    same fault is re-planned from scratch. Both meet the goal; the repaired plan keeps the
    old plan's untouched steps (the same action and arguments) and adds only the patch."""
    shelf, product, rec = _source(base["wh10"])
    fault = [{"kind": "stock-surprise", "place": shelf, "product": product, "delta": -1}]
    repaired = run(tmp_path, WH10, seed=3, faults=fault)
    scratch = run(tmp_path, WH10, seed=3, faults=fault, repair=False)
    assert repaired.ok and scratch.ok, (repaired.error, scratch.error)
    (first,) = repaired.outputs["recoveries"]
    assert first["action"] == "re-plan" and first["repaired"]["kept"] >= 1
    nodes = {n["id"]: n for n in base["wh10"].outputs["graph"]["nodes"]}
    steps = [(nodes[s]["action"], nodes[s]["args"]) for s in first["aborted"]]
    dropped = [(nodes[s]["action"], nodes[s]["args"]) for s in first["repaired"]["dropped"]]
    kept = [x for x in steps if x not in dropped]
    assert len(kept) == first["repaired"]["kept"]
    new = [(p["action"], p["args"]) for p in first["plan"]]
    assert new[:len(kept)] == kept  # the old steps that still apply, in their order, then the patch
    assert "repaired the plan" in first["planner"]
    (other,) = scratch.outputs["recoveries"]
    assert other["action"] == "re-plan" and "repaired" not in other
    for r in (repaired, scratch):
        sim = r.outputs["simulation"]
        assert sim["goal_met"] and not sim["failures"]
        assert sim["final_stock"]["shelf4"] == {"product3": 12, "product1": 5} | {
            k: v for k, v in sim["final_stock"]["shelf4"].items() if k not in ("product3", "product1")}


def test_the_records_are_never_written_into(tmp_path, base):
    """The executor builds the worlds it plays from the records, copying only what it changes:
    after a run with a lost robot, a surprise and a closed passage, the world as loaded is as it
    was (nothing downstream wrote into a world it shares with the records)."""
    from pipflow.execution.executor import Executor

    seen = {}
    original = Executor.__init__

    def keep(self, domain, world, *args, **kwargs):
        seen["records"], seen["copy"] = world, json.loads(json.dumps(world))
        original(self, domain, world, *args, **kwargs)

    schedule = base["wh10"].outputs["schedule"]
    robot, leg, _ = leg_where(schedule, carrying)
    shelf, product, _ = _source(base["wh10"])
    Executor.__init__ = keep
    try:
        r = run(tmp_path, WH10, seed=3, faults=[
            {"kind": "robot-loss", "robot": robot, "time": round((float(leg["start"]) + float(leg["end"])) / 2, 3)},
            {"kind": "stock-surprise", "place": shelf, "product": product, "delta": -1}])
    finally:
        Executor.__init__ = original
    assert r.ok, r.error
    assert len(r.outputs["recoveries"]) >= 2
    assert json.loads(json.dumps(seen["records"])) == seen["copy"]


def test_misplaced_units_are_two_surprises_found_one_after_the_other(tmp_path, base):
    """One unit recorded on the first shelf WH10 takes from lies on the shelf that move brings
    its units to: the shortage is found on arrival at the first shelf, the extra unit when a
    robot first reaches the other; two rounds, each from what was known then, and the goal is
    met in the world as it really was (the same units, one elsewhere)."""
    shelf, product, _ = _source(base["wh10"])
    other = base["wh10"].outputs["graph"]["nodes"][0]["fields"]["to"]
    r = run(tmp_path, WH10, seed=3, faults=[
        {"kind": "stock-surprise", "place": shelf, "product": product, "delta": -1},
        {"kind": "stock-surprise", "place": other, "product": product, "delta": 1}])
    assert r.ok, r.error
    rounds = r.outputs["recoveries"]
    assert [x["cause"]["fault"] for x in rounds if x["cause"]["kind"] == "surprise"] == ["f1", "f2"]
    assert rounds[0]["time"] < rounds[1]["time"]
    assert [f["detected"] is not None for f in r.outputs["faults"]] == [True, True]
    sim = r.outputs["simulation"]
    assert sim["goal_met"] and sim["final_stock"]["shelf4"]["product3"] == 12 and sim["final_stock"]["shelf4"]["product1"] == 5
    before = sum(items.get(product, 0) for items in base["wh10"].outputs["simulation"]["final_stock"].values())
    assert sum(items.get(product, 0) for items in sim["final_stock"].values()) == before


def test_units_found_where_the_plan_brings_more_are_planned_away(tmp_path, base):
    """WH01 brings product1 to shelf3 until it holds 7; one of the units recorded on the shelf it
    takes from lies on shelf3 already. When the robots get to shelf3 nothing of the plan is left,
    but the goal does not hold in what they see: the run re-plans from there (never ends
    believing itself done), and shelf3 holds 7 at the end."""
    shelf, product, _ = _source(base["wh01"])
    assert product == "product1" and shelf != "shelf3"
    r = run(tmp_path, WH01, seed=3, faults=[
        {"kind": "stock-surprise", "place": shelf, "product": product, "delta": -1},
        {"kind": "stock-surprise", "place": "shelf3", "product": product, "delta": 1}])
    assert r.ok, r.error
    last = r.outputs["recoveries"][-1]
    assert last["cause"]["fault"] == "f2" and last["action"] == "re-plan" and not last["pending"]
    sim = r.outputs["simulation"]
    assert sim["goal_met"] and sim["final_stock"]["shelf3"]["product1"] == 7


def test_stock_surprise_the_plan_still_fits_continues(tmp_path, base):
    shelf, product, _ = _source(base["wh01"])
    r = run(tmp_path, WH01, seed=3, faults=[{"kind": "stock-surprise", "place": shelf, "product": product, "delta": 2}])
    assert r.ok, r.error
    (first,) = r.outputs["recoveries"]
    assert first["action"] == "continue" and "still reaches the goal" in first["why"]
    assert r.outputs["schedule"]["subtasks"] == base["wh01"].outputs["schedule"]["subtasks"]
    assert r.outputs["simulation"]["goal_met"]


def test_slow_robot_is_noticed_behind_plan_and_reallocated(tmp_path, base):
    schedule = base["wh10"].outputs["schedule"]
    robot, leg, _ = leg_where(schedule, approach)
    t = float(leg["start"])
    r = run(tmp_path, WH10, seed=3, faults=[{"kind": "slowdown", "robot": robot, "time": t, "factor": 0.4}])
    assert r.ok, r.error
    first = r.outputs["recoveries"][0]
    assert first["cause"]["kind"] == "behind" and first["cause"]["robot"] == robot
    # noticed once it is the arrival tolerance behind: 0.75 m at 60% of 1 m/s lost, about 1.25 s
    assert t < first["time"] <= t + ARRIVAL_TOLERANCE / 0.6 + 0.2
    assert first["action"] in ("re-allocate", "continue")
    later = [l for l in legs_of(r.outputs["schedule"], robot) if float(l["start"]) >= first["time"] and not l.get("done")]
    assert later and all(l.get("pace") == pytest.approx(0.4) for l in later)  # planned at its real speed
    sim = r.outputs["simulation"]
    assert sim["goal_met"] and not sim["failures"] and not sim["jumps"]


def test_closed_passage_is_found_and_driven_around(tmp_path, base):
    """The aisle between shelf2 and shelf4 closes from the start: the robot that takes product3
    from shelf2 meets the barrier, and every leg after that goes round it."""
    r = run(tmp_path, WH10, seed=3, faults=[{"kind": "passage-closed", "between": ["shelf2", "shelf4"], "time": 0}])
    assert r.ok, r.error
    (fault,) = r.outputs["faults"]
    b = fault["barrier"]
    rect = (b["x"], b["y"], b["x"] + b["width"], b["y"] + b["depth"])
    rounds = r.outputs["recoveries"]
    assert rounds and rounds[0]["cause"]["kind"] == "blocked"
    t = rounds[0]["time"]
    for robot, info in r.outputs["schedule"]["robots"].items():
        for leg in info["legs"]:
            if float(leg["start"]) >= t - 1e-6:
                assert not crosses(leg.get("path") or [leg["from"], leg["to"]], rect), (robot, leg)
    sim = r.outputs["simulation"]
    assert sim["goal_met"] and not sim["failures"] and not sim["jumps"]
    assert sim["tc_max"] > base["wh10"].outputs["tc_max"] - 1e-6  # the detour is driven, not skipped


# ------------------------------------------------------------------------------------------
# the household
# ------------------------------------------------------------------------------------------
def test_a_passage_that_cuts_the_floor_in_two_is_a_clear_refusal(tmp_path):
    """The only passage from shelf1 to shelf2 closes: the robot carrying the units finds it closed
    and no path leads on; the run stops with a refusal that says which passage and what was
    carried out (exit 3, no traceback), not a crash and not a silent partial result."""
    world = REPO / "tests" / "fixtures" / "faults" / "corridor.yaml"
    out = subprocess.run([sys.executable, "-m", "pipflow.engine.cli", "run", "warehouse",
                          "-i", "command=There should be 3 product1 in shelf2.", "-i", f"world={world}",
                          "-i", "faults=[{kind: passage-closed, between: [shelf1, shelf2], time: 0}]",
                          "--runs-dir", str(tmp_path / "runs")], capture_output=True, text=True, cwd=tmp_path)
    text = out.stderr + out.stdout
    assert out.returncode == 3, text
    assert "Traceback" not in text and "np.float64" not in text
    assert "found the passage closed" in text and "shelf1 and shelf2" in text and "Carried out" in text
    record = next((tmp_path / "runs").iterdir())
    execute = json.loads((record / "steps" / "execute" / "outputs.json").read_text())
    execute = execute.get("outputs", execute)
    assert execute["recoveries"][-1]["action"] == "refuse" and execute["refusal"]


def test_household_compound_task_survives_a_robot_loss(tmp_path):
    base_run = run(tmp_path, "Put the apple and the tomato in the fridge.", "household", team="homogeneous", seed=1)
    assert base_run.ok
    schedule = base_run.outputs["schedule"]
    robot = next(r for r in sorted(schedule["robots"]) if legs_of(schedule, r))
    t = round(float(legs_of(schedule, robot)[0]["end"]) / 2, 3)
    r = run(tmp_path, "Put the apple and the tomato in the fridge.", "household", team="homogeneous", seed=1,
            faults=[{"kind": "robot-loss", "robot": robot, "time": t}])
    assert r.ok, r.error
    assert r.outputs["recoveries"][0]["cause"]["robot"] == robot
    assert r.outputs["simulation"]["goal_met"] and r.outputs["feasible_after_faults"] is True


def test_household_object_surprise_is_fetched_where_it_really_is(tmp_path):
    r = run(tmp_path, "Put the apple in the fridge.", "household", team="homogeneous", seed=1,
            faults=[{"kind": "object-surprise", "object": "apple", "in": "sink"}])
    assert r.ok, r.error
    first = r.outputs["recoveries"][0]
    assert first["cause"]["kind"] == "surprise" and first["action"] == "re-plan"
    assert any(step["args"][:2] == ["apple", "sink"] for step in first["plan"])
    sim = r.outputs["simulation"]
    assert sim["goal_met"] and sim["final_state"]["at"]["apple"] == "fridge" and not sim["failures"]


# ------------------------------------------------------------------------------------------
# bad fault specs: clear messages, exit 2
# ------------------------------------------------------------------------------------------
@pytest.mark.parametrize("value, words", [
    ("robot-los=1", "did you mean 'robot-loss'"),
    ("robot-loss=0", "between 1 and"),
    ("[{kind: slowdown, factor: 1.5}]", "factor"),
    ("[{kind: robot-loss, time: 3, after: 1}]", "not both"),
    ("[{kind: passage-closed, between: [shelf1]}]", "two different places"),
])
def test_a_bad_fault_spec_is_refused_before_anything_runs(tmp_path, value, words):
    out = subprocess.run([sys.executable, "-m", "pipflow.engine.cli", "run", "warehouse", "-i", f"faults={value}",
                          "--runs-dir", str(tmp_path / "runs")], capture_output=True, text=True, cwd=tmp_path)
    assert out.returncode == 2 and words in out.stderr and "Traceback" not in out.stderr, out.stderr
    assert not (tmp_path / "runs").exists() or not any((tmp_path / "runs").iterdir())


@pytest.mark.parametrize("spec, words", [
    ({"kind": "robot-loss", "robot": "robot99"}, "unknown robot 'robot99'"),
    ({"kind": "object-surprise", "object": "apple", "in": "sink"}, "'object-surprise' is not a fault kind"),
    ({"kind": "stock-surprise", "place": "shelf9", "product": "product1", "count": 1}, "unknown shelf"),
])
def test_a_fault_the_world_has_no_place_for_is_a_user_error(tmp_path, spec, words):
    r = run(tmp_path, WH01, faults=[spec])
    assert r.status == "failed" and words in r.error, r.error
    assert r.error_step == "execute"


# ------------------------------------------------------------------------------------------
# the bench and the report
# ------------------------------------------------------------------------------------------
def test_a_fault_with_nothing_to_strike_is_run_without_and_recorded_not_applicable(tmp_path):
    """A goal the world already meets: the schedule gives no robot work, takes from no shelf and
    drives no leg, so no drawn fault of any kind has a target. The run is carried out (exit 0)
    without them, and its record names each fault, its kind and why it did not apply."""
    r = run(tmp_path, "There should be 5 product1 in shelf3.", seed=1,
            faults="stock-surprise=1,robot-loss=1,passage-closed=1,slowdown=1")
    assert r.ok, r.error
    assert r.outputs["faults"] == [] and r.outputs["simulation"]["goal_met"]
    skipped = {f["name"]: f for f in r.outputs["faults_not_applicable"]}
    assert set(skipped) == {"stock-surprise", "robot-loss", "passage-closed", "slowdown"}
    assert "takes no product from a shelf" in skipped["stock-surprise"]["why"]
    assert "no robot any work" in skipped["robot-loss"]["why"] and "no robot any work" in skipped["slowdown"]["why"]
    assert "no passage to close" in skipped["passage-closed"]["why"]
    execution = json.loads((r.record / "steps" / "execute" / "artifacts" / "execution.json").read_text())
    assert [f["id"] for f in execution["not_applicable"]] == ["f1", "f2", "f3", "f4"]
    html = r.report().read_text()  # the report says so too
    assert "Faults not applicable" in html and "no passage to close" in html


def test_a_fault_that_names_its_target_stays_a_user_error_on_the_command_line(tmp_path):
    """Only drawn targets can be not applicable: a household object surprise naming an object the
    home lacks is exit 2 naming the spec, with no traceback."""
    out = subprocess.run([sys.executable, "-m", "pipflow.engine.cli", "run", "household", "-i", "team=homogeneous",
                          "-i", "command=Slice the apple.", "-i", "faults=[{kind: object-surprise, object: melon, in: sink}]",
                          "--runs-dir", str(tmp_path / "runs"), "--no-cache"], capture_output=True, text=True, cwd=tmp_path)
    assert out.returncode == 2 and "faults[1]" in out.stderr and "unknown object 'melon'" in out.stderr, out.stderr
    assert "Traceback" not in out.stderr


def test_bench_runs_a_task_a_fault_does_not_apply_to_and_counts_it_apart(tmp_path):
    """Household, object-surprise=1: slicing carries no object anywhere, so no object lying
    elsewhere can matter (issue 27: hc-09 stopped the whole bench). The bench runs every task;
    the slicing run is carried out without the fault (and meets its goal), recorded as not
    applicable; the fault row's SR and recovery numbers are over the one run that had the fault,
    and the table counts the other apart, saying which kind and why."""
    home = REPO / "benchmarks" / "household" / "world.yaml"
    tasks = tmp_path / "tasks.yaml"
    tasks.write_text(f"domain: household\nworld: {home}\ntasks:\n"
                     "  - id: slice\n    category: compound\n    team: homogeneous\n"
                     "    command: \"Slice the apple and the tomato.\"\n    goal: {state: {apple: [sliced], tomato: [sliced]}}\n"
                     "  - id: store\n    category: compound\n    team: homogeneous\n"
                     "    command: \"Put the apple in the fridge.\"\n    goal: {in: {fridge: [apple]}, state: {fridge: [closed]}}\n")
    results = pipflow.bench(tasks, seeds=1, out=tmp_path / "b", faults="object-surprise=1")
    f = results["variants"][0]["faults"]
    assert (f["runs"], f["not_applicable"], f["applied"], f["with_faults"]) == (2, 1, 1, 1)
    assert f["kinds"] == ["object-surprise"]
    assert list(f["not_applicable_why"]) == ["object-surprise"]
    (why, which), = f["not_applicable_why"]["object-surprise"].items()
    assert which == ["slice seed 0"] and "carries no object" in why
    with (tmp_path / "b" / "runs.csv").open() as fh:
        rows = {r["task"]: r for r in csv.DictReader(fh)}
    assert rows["slice"]["status"] == "succeeded" and rows["slice"]["success"] == "True"
    assert rows["slice"]["fault_outcome"] == "fault not applicable" and "object-surprise" in rows["slice"]["faults_not_applicable"]
    assert rows["store"]["fault_outcome"] != "fault not applicable" and json.loads(rows["store"]["faults"]) == ["object-surprise"]
    store_ok = rows["store"]["success"] == "True"
    assert f["sr"] == (1.0 if store_ok else 0.0)  # over the run that had the fault, not both
    table = (tmp_path / "b" / "table.md").read_text()
    row = next(line for line in table.splitlines() if line.startswith("| default |"))
    assert [c.strip() for c in row.strip("|").split("|")][:5] == ["default", "object-surprise", "2", "1",
                                                                   "100" if store_ok else "0"]
    assert "object-surprise not applicable: 1 run(s) (slice seed 0)" in table


def test_bench_measures_with_and_without_faults_side_by_side(tmp_path):
    tasks = tmp_path / "tasks.yaml"
    tasks.write_text(f"world: {REPO / 'benchmarks/warehouse/world.yaml'}\ntasks:\n"
                     f"  - id: wh-01\n    command: \"{WH01}\"\n    goal: {{shelf3: {{product1: 7}}}}\n"
                     f"  - id: wh-10\n    command: \"{WH10}\"\n    goal: {{shelf4: {{product3: 12, product1: 5}}}}\n")
    results = pipflow.bench(tasks, seeds=1, out=tmp_path / "b", matrix={"faults": ["none", "robot-loss=1"]})
    by = {v["name"]: v for v in results["variants"]}
    assert "faults" not in by["faults=none"]
    f = by["faults=robot-loss=1"]["faults"]
    assert f["runs"] == 2 and f["with_faults"] == 2 and f["sr"] == 1.0 and f["sr_feasible"] == 1.0
    assert f["recovery_seconds_max"] is not None and sum(f["recoveries"].values()) >= 2
    table = (tmp_path / "b" / "table.md").read_text()
    assert "Faults and recovery" in table and "faults=robot-loss=1" in table
    with (tmp_path / "b" / "runs.csv").open() as fh:
        header = next(csv.reader(fh))
    assert "fault_outcome" in header and "recovery_seconds" in header
    plain = pipflow.bench(tasks, seeds=1, out=tmp_path / "p")
    with (tmp_path / "p" / "runs.csv").open() as fh:
        assert next(csv.reader(fh)) == RESULT_FIELDS  # a bench without faults reads as before
    assert "Faults" not in (tmp_path / "p" / "table.md").read_text() and "faults" not in plain["variants"][0]


def test_bench_table_says_sr_where_reachable_and_the_clear_refusals(tmp_path):
    """A shelf short of one unit of a product the goal needs every unit of: that run's goal is out
    of reach and its right answer is a refusal; the other task never visits the shelf and
    succeeds. The table's row names the fault kind, SR over all runs (50%), the runs whose goal
    stayed reachable (1) and SR among them (100%), and the clear refusal (1), apart from
    refusals of a goal still reachable (0); runs.csv says per run whether it stayed reachable."""
    tasks = tmp_path / "tasks.yaml"
    tasks.write_text(f"world: {REPO / 'benchmarks/warehouse/world.yaml'}\ntasks:\n"
                     f"  - id: wh-01\n    command: \"{WH01}\"\n    goal: {{shelf3: {{product1: 7}}}}\n"
                     "  - id: all-p3\n    command: \"shelf4 stores 15 product3.\"\n    goal: {shelf4: {product3: 15}}\n")
    surprise = [{"kind": "stock-surprise", "place": "shelf2", "product": "product3", "delta": -1}]
    results = pipflow.bench(tasks, seeds=1, out=tmp_path / "b", faults=surprise)
    f = results["variants"][0]["faults"]
    assert (f["runs"], f["sr"], f["reachable"], f["sr_feasible"], f["refused_right"], f["refused_wrong"]) == \
        (2, 0.5, 1, 1.0, 1, 0)
    assert f["kinds"] == ["stock-surprise"]
    row = next(line for line in (tmp_path / "b" / "table.md").read_text().splitlines() if line.startswith("| default |"))
    assert [c.strip() for c in row.strip("|").split("|")][:9] == ["default", "stock-surprise", "2", "0", "50", "1", "100",
                                                                   "1", "0"]
    with (tmp_path / "b" / "runs.csv").open() as fh:
        rows = {r["task"]: r for r in csv.DictReader(fh)}
    assert rows["all-p3"]["feasible_after_faults"] == "False" and rows["all-p3"]["fault_outcome"] == "refused: out of reach"
    assert rows["wh-01"]["fault_outcome"] == "succeeded"


def test_report_shows_where_and_when_faults_struck(tmp_path, base):
    schedule = base["wh10"].outputs["schedule"]
    robot, leg, _ = leg_where(schedule, carrying)
    t = round((float(leg["start"]) + float(leg["end"])) / 2, 3)
    r = run(tmp_path, WH10, seed=3, faults=[{"kind": "robot-loss", "robot": robot, "time": t}])
    page = r.report()
    html = page.read_text()
    assert "Faults and recovery" in html and "re-plan" in html and robot in html
    from PIL import Image

    for name in ("faults-map.png", "faults-gantt.png"):
        with Image.open(r.record / "report" / name) as img:
            assert img.size[0] > 300


# ------------------------------------------------------------------------------------------
# the pieces: a timeline that continues, fault specs
# ------------------------------------------------------------------------------------------
def test_timeline_continues_from_where_the_team_stands():
    world = {"floor": {"width": 20, "height": 10},
             "shelves": {"a": {"x": 2, "y": 6, "width": 4, "depth": 1, "capacity": 9, "access": [4, 5]},
                         "b": {"x": 12, "y": 6, "width": 4, "depth": 1, "capacity": 9, "access": [14, 5]}},
             "robots": {"r1": {"start": [1, 1], "skills": {"carry": 1}}, "r2": {"start": [19, 1], "skills": {"carry": 1}}}}
    standing = Standing(time=10.0, pos={"r1": [10.0, 2.0], "r2": "b"}, free={"r1": 10.0, "r2": 12.0},
                        driven={"r1": 9.0, "r2": 3.0}, ended={"s0": 11.0}, pace={"r1": 0.5})
    tl = Timeline(world, standing=standing)
    node = {"id": "s1", "route": ["a", "b"]}
    rec = tl.commit(node, ["r1"], ["s0"])
    first = tl.legs["r1"][0]
    assert first["from"] == [10.0, 2.0] and first["start"] == 10.0 and first["pace"] == 0.5
    assert first["end"] == pytest.approx(10.0 + first["distance"] / 0.5)  # at its real pace
    assert rec["start"] >= 11.0 and rec["start"] == pytest.approx(first["end"])  # after s0, once it arrived
    assert tl.driven["r1"] == pytest.approx(9.0 + sum(l["distance"] for l in tl.legs["r1"]))
    assert tl.cost("r2", node) == pytest.approx(3.0 + tl.subtask_cost("r2", node))  # total: travel so far counts


def test_fault_counts_and_specs_are_read():
    specs = fk.parse("robot-loss=2+slowdown, stock-surprise=1", ("stock-surprise",))
    assert [s.kind for s in specs] == ["robot-loss", "robot-loss", "slowdown", "surprise"]
    assert fk.parse("none") == [] and fk.parse(None) == [] and fk.parse([]) == []
    (one,) = fk.parse({"kind": "robot-loss", "robot": "robot2", "after": 2})
    assert one.given == {"robot": "robot2", "after": 2}


def test_only_a_drawn_target_can_be_not_applicable(base):
    """In the warehouse's real world and WH01's schedule: three robot losses drawn where the
    schedule gives fewer robots work set the extra ones apart, while a robot loss and a slowdown
    naming their robot always apply; a surprise a domain cannot place where the user named it is
    the user's error (a domain that says so with FaultNotApplicable), never set apart."""
    from pipflow.errors import FaultNotApplicable
    from pipflow.execution.capability import capable
    from pipflow.taskdomains import task_domain

    run_ = base["wh01"]
    world = step_outputs(run_, "world")["world"]
    schedule, graph = run_.outputs["schedule"], run_.outputs["graph"]
    domain = capable(task_domain(world))
    working = fk.working_windows(schedule)
    n = len(working)
    placed = fk.resolve(fk.parse(f"robot-loss={n + 2}"), world, schedule, graph, 1, domain)
    assert sorted(f.robot for f in placed.faults) == sorted(working)
    assert [na.id for na in placed.not_applicable] == [f"f{n + 1}", f"f{n + 2}"]
    assert all("already stopped" in na.why for na in placed.not_applicable)
    idle = next(r for r in world["robots"] if r not in working)
    named = fk.resolve(fk.parse([{"kind": "robot-loss", "robot": idle, "time": 1}, {"kind": "slowdown", "robot": idle}]),
                       world, schedule, graph, 1, domain)
    assert [f.robot for f in named.faults] == [idle, idle] and not named.not_applicable

    class Picky(type(domain)):
        def check_surprise(self, world, given, where):
            raise FaultNotApplicable("nothing here to be surprised about")

    with pytest.raises(InputError, match=r"faults\[1\]: nothing here"):
        fk.resolve(fk.parse([{"kind": "stock-surprise", "place": "shelf1", "product": "product1", "count": 1}],
                            domain.surprise_names), world, schedule, graph, 1, Picky())


def test_a_drawn_stock_surprise_is_units_missing_or_misplaced(base):
    """Over seeds, the warehouse's drawn surprise is either units gone from a shelf the plan takes
    from (fewer in the world than recorded), or the same units lying on another shelf with room
    for them (the total conserved); a misplaced draw is two faults, each found where a robot
    arrives. Never units from nowhere, never at a shelf recorded empty."""
    from pipflow.taskdomains import task_domain
    from pipflow.execution.capability import capable

    run_ = base["wh10"]
    world = json.loads((run_.record / "steps" / "world" / "outputs.json").read_text())
    world = world.get("outputs", world)["world"]
    domain = capable(task_domain(world))
    takes = {n["fields"]["from"] for n in run_.outputs["graph"]["nodes"]}
    seen = set()
    for seed in range(40):
        placed = fk.resolve(fk.parse("stock-surprise=1", domain.surprise_names), world, run_.outputs["schedule"],
                            run_.outputs["graph"], seed, domain).faults
        real = world
        for f in placed:
            real = domain.apply_surprise(real, f.surprise)
        total = {p: sum(items.get(p, 0) for items in world["stock"].values()) for p in world["products"]}
        after = {p: sum(items.get(p, 0) for items in real["stock"].values()) for p in world["products"]}
        first = placed[0].surprise
        assert first["place"] in takes and first["records"] > 0 and first["count"] < first["records"]
        k = first["records"] - first["count"]
        assert 1 <= k <= 3
        how = first["how"]
        seen.add(how)
        if how == "missing":
            assert len(placed) == 1 and after[first["product"]] == total[first["product"]] - k
        else:
            assert how == "misplaced" and [f.id for f in placed] == ["f1a", "f1b"]
            host = placed[1].surprise
            assert host["place"] != first["place"] and host["count"] == host["records"] + k
            assert after == total  # the same units, elsewhere
            assert sum(real["stock"][host["place"]].values()) <= world["shelves"][host["place"]]["capacity"]
            assert placed[0].surprise["places"] == [first["place"]] and placed[1].surprise["places"] == [host["place"]]
    assert seen == {"missing", "misplaced"}


def test_a_drop_place_never_walls_its_own_access_point_in():
    """A robot stops in a pocket between two pieces of furniture (the hv-12 home, seed 1): the
    square beside it on the side it came from, with the furniture's margins, would close the
    pocket, and no robot could fetch what it carried (the run was refused). The drop place goes
    on a side that keeps its access point reachable the way the robot came."""
    from pipflow.execution.motion import drop_site
    from pipflow.team.travel import TravelMap
    from pipflow.warehouse.faults import drop_place

    world = {"floor": {"width": 10, "height": 8}, "products": {"p": {}}, "stock": {"desk": {}, "bookshelf": {}},
             "shelves": {"desk": {"x": 8.6, "y": 2.5, "width": 1.2, "depth": 0.7, "capacity": 5, "access": [9.2, 3.9]},
                         "bookshelf": {"x": 9.4, "y": 0.2, "width": 0.5, "depth": 1.4, "capacity": 5,
                                       "access": [8.6, 0.5]}},
             "robots": {"r1": {"start": [1, 1], "skills": {"carry": 1}}}}
    point, came = (9.2, 1.9), (6.0, 1.7)

    def reaches(site: dict) -> bool:
        try:
            TravelMap(drop_place(world, "r1", site)[0]).distance(came, tuple(site["access"]))
        except InputError:
            return False
        return True

    blind = drop_site(world, point, came)
    assert not reaches(blind)  # the side it came from walls the pocket in
    site = drop_site(world, point, came, reaches)
    assert reaches(site) and site["access"] == [9.2, 1.9]

"""Metrics that mean what they say (issue 20, part 3), through the real bench, planner and
simulators: understood and misread compare meanings (and count misreadings that never moved a
robot), the household's RU reference is an optimal plan, a right refusal is no 0 m run in the
travel figures, GCR credits nothing to a run that changed nothing, and TC-avg has one meaning.

Each test fails on the code before this change (checked against its commit's parent)."""
from __future__ import annotations

import shutil
from pathlib import Path

import pytest
import yaml

from pipflow.experiments.benchmarking import BenchConfig, read_row, run_bench

ROOT = Path(__file__).resolve().parent.parent
TINY = Path(__file__).resolve().parent / "fixtures" / "bench"  # 2 shelves, 2 products, 3 robots
HOME = ROOT / "benchmarks" / "household" / "world.yaml"
DOMAIN = ROOT / "domains" / "household.pddl"
ACTIONS = ROOT / "domains" / "household.actions.yaml"

pytestmark = pytest.mark.usefixtures("no_hang")


def bench(tmp_path: Path, tasks: list[dict], world: Path = TINY / "world.yaml", **head) -> tuple[dict, Path]:
    """Run ``tasks`` (one seed, no cache) on a copy of ``world``; (results, bench folder)."""
    folder = tmp_path / "tasks"
    folder.mkdir()
    shutil.copy(world, folder / "world.yaml")
    (folder / "tasks.yaml").write_text(yaml.safe_dump({**head, "world": "world.yaml", "tasks": tasks},
                                                      sort_keys=False))
    out = tmp_path / "out"
    results = run_bench(BenchConfig(tasks_file=folder / "tasks.yaml", seeds=1, jobs=1, out=out, use_cache=False),
                        progress=False)
    return results, out


def by_id(results: dict) -> dict:
    return {t["id"]: t for t in results["tasks"]}


# --------------------------------------------------------------------------------- understood
def test_an_infeasible_command_that_was_not_understood_is_not_understood(tmp_path):
    """Refusing the impossible counts as understanding it only when the command was read and
    found impossible (a Refusal); a reader that could not place a word (a TranslationError)
    understood nothing, although nothing moved either."""
    results, out = bench(tmp_path, [
        {"id": "refused", "command": "There should be 50 product1 in shelf2.",
         "goal": {"shelf2": {"product1": 50}}, "feasible": False},
        {"id": "not-placed", "command": "There should be 50 product1 together in shelf2.",
         "goal": {"shelf2": {"product1": 50}}, "feasible": False},
    ])
    tasks = by_id(results)
    assert tasks["refused"]["understood"] == 1.0 and tasks["refused"]["sr"] == 1.0
    assert tasks["not-placed"]["understood"] == 0.0 and tasks["not-placed"]["misread"] == 0
    assert "not understood" in read_row(out, ("default", "not-placed", 0))["understanding"]
    assert results["summary"]["understood"] == 0.5


# ---------------------------------------------------------------------------------- misread
def test_goals_are_compared_by_the_final_stocks_they_accept(tmp_path):
    """The tiny world has 5 product2 in all: a gold listing the 0 that gathering them leaves on
    shelf2 means what a run that leaves it to conservation means, and the other way round. A
    count the run states that holds at the start but that the gold leaves open (shelf1 keeps its
    2 product2) turns away final stocks the gold accepts: another meaning, though robots moved
    and the gold holds at the end."""
    results, out = bench(tmp_path, [
        {"id": "gold-lists-zero", "command": "There should be 5 product2 in shelf1.",
         "goal": {"shelf1": {"product2": 5}, "shelf2": {"product2": 0}}},
        {"id": "run-lists-zero", "command": "There should be 5 product2 in shelf1, 0 product2 in shelf2.",
         "goal": {"shelf1": {"product2": 5}}},
        {"id": "run-keeps-a-count", "command": "There should be 4 product1 in shelf2, 2 product2 in shelf1.",
         "goal": {"shelf2": {"product1": 4}}},
    ])
    tasks = by_id(results)
    for tid in ("gold-lists-zero", "run-lists-zero"):
        assert tasks[tid]["understood"] == 1.0 and tasks[tid]["misread"] == 0, read_row(out, ("default", tid, 0))
    kept = tasks["run-keeps-a-count"]
    assert kept["understood"] == 0.0 and kept["misread"] == 1 and kept["misread_executed"] == 1
    assert "shelf1 product2: the gold allows 0..5, the run's goal 2" in \
        read_row(out, ("default", "run-keeps-a-count", 0))["understanding"]


@pytest.fixture(scope="module")
def rule_bench(tmp_path_factory):
    return bench(tmp_path_factory.mktemp("rules"), [
        {"id": "split-rule", "command": "There should be 4 product1 in shelf2. robot0 and robot1 must not move product1.",
         "goal": {"shelf2": {"product1": 4}},
         "constraints": [{"never": ["robot1"], "product": "product1"}, {"never": ["robot0"], "product": "product1"}]},
        {"id": "every-robot", "command": "There should be 4 product1 in shelf2. No robot may move product1.",
         "goal": {"shelf2": {"product1": 4}}, "constraints": [{"never": ["robot0"], "product": "product1"}]},
    ])


def test_rules_are_compared_by_what_they_forbid(rule_bench):
    """``never [robot0, robot1]`` forbids what ``never [robot0]`` and ``never [robot1]`` forbid."""
    results, _ = rule_bench
    split = by_id(results)["split-rule"]
    assert split["understood"] == 1.0 and split["misread"] == 0


def test_a_misreading_that_failed_before_moving_a_robot_is_counted(rule_bench):
    """A run that read "keep robot0 off product1" as "keep every robot off it" misread the
    command although it never got as far as moving a robot: counted in ``misread``, not in
    ``misread_executed``, in the task's row, the summary and the printed table."""
    results, out = rule_bench
    wrong = by_id(results)["every-robot"]
    assert wrong["sr"] == 0.0 and wrong["understood"] == 0.0
    assert wrong["misread"] == 1 and wrong["misread_executed"] == 0
    row = read_row(out, ("default", "every-robot", 0))
    assert row["status"] != "succeeded" and "robot1 on product=product1: the gold allows it" in row["understanding"]
    summary = results["summary"]
    assert summary["misread"] == 1 and summary["misread_executed"] == 0
    assert "| every-robot | 0 | 0 | 1 (0) |" in (out / "table.md").read_text()


@pytest.fixture(scope="module")
def household_bench(tmp_path_factory):
    """Five household tasks in one bench (the real translator, ENHSP, SCIP, the home simulator)."""
    team = {"category": "compound", "team": "homogeneous"}
    return bench(tmp_path_factory.mktemp("household"), [
        {"id": "lamp", **team, "command": "Switch off the floor lamp.", "goal": {"state": {"floorlamp": ["off"]}}},
        {"id": "mug", **team, "feasible": False, "command": "Heat the mug in the microwave."},
        {"id": "apple", **team, "command": "Put the apple in the fridge sideways.",   # not understood: refused
         "goal": {"in": {"fridge": ["apple"]}, "state": {"fridge": ["closed"], "microwave": ["closed"]}}},
        # the milk comes out of the closed fridge, which is closed again (the household sets' convention)
        {"id": "two-drinks", **team, "command": "Put two drinks on the desk.",
         "goal": {"in": {"desk": ["milk", "bottle"]}, "state": {"fridge": ["closed"]}}},
        {"id": "a-drink", **team, "command": "Put a drink on the desk.", "goal": {"in": {"desk": ["milk"]}}},
    ], world=HOME, domain="household")


def test_household_goals_are_compared_by_the_final_states_they_accept(household_bench):
    """The home has two drinks, so "two drinks on the desk" is "the milk and the bottle on the
    desk"; "a drink" is not "the milk" (the bottle would do)."""
    results, out = household_bench
    tasks = by_id(results)
    assert tasks["two-drinks"]["understood"] == 1.0 and tasks["two-drinks"]["misread"] == 0
    assert tasks["a-drink"]["understood"] == 0.0 and tasks["a-drink"]["misread_executed"] == 1
    assert "milk in desk: required by the gold, not by the run's goal" in \
        read_row(out, ("default", "a-drink", 0))["understanding"]


def test_household_conditions_no_final_state_can_break_change_no_meaning():
    """A mug that cannot be sliced stays whole: a goal stating it accepts the same final states
    (a model may well write it); the fridge closed is not such a condition."""
    from pipflow.household.meaning import goal_difference
    from pipflow.household.world import load_world

    home = load_world(HOME)
    assert goal_difference(home, {"state": {"mug": ["clean"]}}, {"state": {"mug": ["clean", "whole"]}}) is None
    closed = goal_difference(home, {"in": {"fridge": ["apple"]}, "state": {"fridge": ["closed"]}},
                             {"in": {"fridge": ["apple"]}})
    assert closed == "goal: fridge: the gold allows closed, the run's goal open or closed"


# ----------------------------------------------------------------------------- household RU
def _household_score(team_name: str, goal: dict, plan: list[dict]) -> dict:
    """``plan`` through the real graph, SCIP allocation, schedule and home simulator, scored."""
    from pipflow.household.domain import HouseholdDomain
    from pipflow.household.problem import write_problem
    from pipflow.household.simulation import simulate
    from pipflow.household.world import load_world, select_team
    from pipflow.team.allocation import allocate
    from pipflow.team.dependency import build_graph
    from pipflow.team.scheduling import build_schedule

    team = select_team(load_world(HOME), team_name)
    graph = build_graph(DOMAIN.read_text(), write_problem(team, goal), plan, yaml.safe_load(ACTIONS.read_text()))
    schedule = build_schedule(graph, allocate(graph, team), team)
    return HouseholdDomain().score(team, goal, graph=graph, schedule=schedule,
                                   simulation=simulate(team, schedule, graph, goal))


def step(action: str, *args: str) -> dict:
    return {"action": action, "args": list(args)}


def test_household_ru_is_1_for_an_optimal_plan_and_counts_what_a_plan_must_do_around_the_goal():
    """hc-12: the egg lies in the closed fridge, so an optimal plan opens and closes it (5
    actions); hc-36: a washed mug is carried back to the table (3 actions). Both score RU 1; a plan
    with a needless open and close of the microwave scores 5/7."""
    egg = {"in": {"bed": ["book"]}, "state": {"knife": ["clean"], "egg": ["hot"], "fridge": ["closed"]}}
    optimal = [step("store", "book", "bookshelf", "bed"), step("open", "fridge"), step("store", "egg", "fridge", "stove"),
               step("close", "fridge"), step("heat", "egg", "stove")]
    score = _household_score("homogeneous", egg, optimal)
    assert score["success"] and score["lower_bound"] == 5 and score["ru"] == 1.0
    detour = optimal[:4] + [step("open", "microwave"), step("close", "microwave"), optimal[4]]
    assert _household_score("homogeneous", egg, detour)["ru"] == pytest.approx(5 / 7)
    mug = {"in": {"diningtable": ["mug"]}, "state": {"mug": ["clean"]}}
    carry = [step("store", "mug", "diningtable", "sink"), step("wash", "mug", "sink"),
             step("store", "mug", "sink", "diningtable")]
    score = _household_score("homogeneous", mug, carry)
    assert score["success"] and score["ru"] == 1.0


def test_the_optimal_search_leaves_the_working_directory_alone(tmp_path, monkeypatch):
    """Fast Downward's driver keeps an intermediate ``output.sas`` in its working directory and
    deletes it: run where the user stands, it would delete theirs (and two runs at once would
    read each other's). The reference's search runs in a folder of its own."""
    from pipflow.household.problem import write_problem
    from pipflow.household.world import load_world
    from pipflow.pddl.common import parse
    from pipflow.pddl.optimal import fewest_actions

    monkeypatch.chdir(tmp_path)
    (tmp_path / "output.sas").write_text("the user's file")
    home = load_world(HOME)
    problem = parse(DOMAIN, write_problem(home, {"in": {"garbagecan": ["egg", "milk"]}, "state": {"fridge": ["closed"]}}))
    assert fewest_actions(problem) == (4, "")  # open the fridge, trash both, close it
    assert (tmp_path / "output.sas").read_text() == "the user's file"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["output.sas"]


# ------------------------------------------------------------------ household table, TC and GCR
def test_household_travel_leaves_right_refusals_out(household_bench):
    """A refused infeasible task succeeds without moving: the category's TC is that of the tasks
    that were done, not lowered by a 0 m run."""
    results, out = household_bench
    tasks = by_id(results)
    assert tasks["mug"]["sr"] == 1.0 and tasks["mug"]["tc_max"] is None
    done = [t for t in tasks.values() if t["tc_max"] is not None]
    assert "lamp" in {t["id"] for t in done} and all(t["sr"] > 0 for t in done)
    tc_max = sum(t["tc_max"] for t in done) / len(done)
    tc_avg = sum(t["tc_avg"] for t in done) / len(done)
    row = next(line for line in (out / "table.md").read_text().splitlines() if line.startswith("| compound |"))
    assert f"| {tc_max:.1f}/{tc_avg:.1f} |" in row
    assert results["summary"]["tc_max"] == pytest.approx(tc_max)


def test_gcr_credits_nothing_to_a_run_that_changed_nothing(household_bench):
    """A feasible task that was not understood executed nothing: the conditions that held from
    the start (fridge and microwave closed) recall nothing: GCR 0, not 2/3."""
    apple = by_id(household_bench[0])["apple"]
    assert apple["sr"] == 0.0 and apple["gcr"] == 0.0


# ------------------------------------------------------------------------------------ TC-avg
def test_tc_avg_is_the_mean_over_the_robots_that_moved_in_both_domains(tmp_path):
    """One definition: the warehouse bench and the household score both give TC-avg as the mean
    travel of the robots that moved, and the mean over the whole team as ``tc_avg_team``."""
    results, out = bench(tmp_path, [{"id": "move", "command": "There should be 4 product1 in shelf2.",
                                     "goal": {"shelf2": {"product1": 4}}}])
    row = read_row(out, ("default", "move", 0))
    sim = yaml.safe_load((Path(row["run_dir"]) / "steps" / "simulate" / "outputs.json").read_text())
    travel = (sim.get("outputs") or sim)["travel"]
    moved = [v for v in travel.values() if v > 0]
    assert len(moved) < len(travel)  # a robot stood idle
    assert row["tc_avg"] == pytest.approx(sum(moved) / len(moved))
    assert row["tc_avg_team"] == pytest.approx(sum(travel.values()) / len(travel))
    assert by_id(results)["move"]["tc_avg"] == pytest.approx(row["tc_avg"])
    lamp = _household_score("homogeneous", {"in": {}, "state": {"floorlamp": ["off"]}},
                            [step("switch-off", "floorlamp", "floorlamp")])
    assert lamp["success"] and lamp["tc_avg"] == pytest.approx(lamp["tc_max"])  # one robot moved
    assert lamp["tc_avg_team"] == pytest.approx(lamp["tc_max"] / 3)  # of the three of the team


# ----------------------------------------------------------------------------- older records
def test_older_records_are_read_in_todays_names_and_never_resumed_into_a_new_table(tmp_path):
    """A bench written before TC-avg had one definition kept the team's mean as ``tc_avg`` and
    today's TC-avg as ``tc_avg_moved``: ``pipflow compare`` shows them in today's names, so two
    benches are never compared on two meanings; ``--resume`` refuses a row scored by the old
    definitions rather than mixing it into a table of the new ones."""
    import json

    from pipflow.errors import UserError
    from pipflow.experiments.benchmarking import fingerprint_hash, row_path
    from pipflow.records.compare import comparison

    old, new = tmp_path / "old", tmp_path / "new"
    for folder, row in ((old, {"id": "t", "runs": 1, "sr": 1.0, "tc_max": 20.0, "tc_avg": 2.0, "tc_avg_moved": 19.0}),
                        (new, {"id": "t", "runs": 1, "sr": 1.0, "tc_max": 20.0, "tc_avg": 19.0, "tc_avg_team": 2.0})):
        folder.mkdir()
        (folder / "results.json").write_text(json.dumps({"summary": dict(row), "tasks": [row]}))
    rows = {r.label: r for r in comparison(old, new).rows}
    assert rows["t TC-avg (m)"].cells == ["19.00", "19.00"] and not rows["t TC-avg (m)"].differs

    (tmp_path / "b").mkdir()
    results, out = bench(tmp_path / "b", [{"id": "move", "command": "There should be 4 product1 in shelf2.",
                                          "goal": {"shelf2": {"product1": 4}}}])
    stored = row_path(out, ("default", "move", 0))
    row = json.loads(stored.read_text())
    del row["fingerprint"]["metrics"]  # as a row of before the definitions were versioned
    row["config_hash"] = fingerprint_hash(row["fingerprint"])
    stored.write_text(json.dumps(row))
    folder = tmp_path / "b" / "tasks"
    with pytest.raises(UserError, match="the metrics' definitions before they were versioned -> 2"):
        run_bench(BenchConfig(tasks_file=folder / "tasks.yaml", seeds=1, jobs=1, out=out, use_cache=False,
                              resume=True), progress=False)


@pytest.mark.parametrize("gold", [None, {}, {"in": {}, "state": {}}])
def test_an_impossible_command_whose_gold_writes_no_goal_is_understood_when_refused_as_impossible(gold):
    """ "no goal needed" for an impossible household task (benchmarks/README.md): the run that read
    "wash my crocs" and was refused as impossible (no robot of the team can wash) understood it.
    An empty goal was compared as if the command asked for nothing, and the run counted misread."""
    from pipflow.meaning import judge
    from pipflow.values import REFUSED_AS_IMPOSSIBLE

    task = {"id": "crocs", "command": "give my crocs a wash", "feasible": False}
    if gold is not None:
        task["goal"] = gold
    differs = lambda gold, run: "differs"   # noqa: E731 - any comparison made would find a difference
    verdict = judge(task, {"goal": {"state": {"crocs": ["clean"]}}}, "refused", REFUSED_AS_IMPOSSIBLE,
                    goal_difference=differs, rule_difference=lambda a, b: None)
    assert verdict["understood"] is True and verdict["misread"] is False
    # a goal that is written is still compared: another impossible meaning is a misreading
    task["goal"] = {"state": {"sofa": ["clean"]}}
    verdict = judge(task, {"goal": {"state": {"crocs": ["clean"]}}}, "refused", REFUSED_AS_IMPOSSIBLE,
                    goal_difference=differs, rule_difference=lambda a, b: None)
    assert verdict["misread"] is True

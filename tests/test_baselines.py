"""The paper's baselines (issue 24, parts 1 and 4): CoT, SMART-LLM and LaMMA-P as built-in
workflows, driven end to end through a scripted OpenAI-compatible server on loopback (litellm's
real HTTP path), the real readers, ENHSP for LaMMA-P's per-robot problems, the schedule, the
simulations (pybullet, the home) and the scoring PIP-LLM is judged by.

The server answers each question by the command and the stage it asks about
(tests/baseline_answers.py), with answers written from a known-good plan: for the warehouse the
offline PIP-LLM run's plan and robots, for the household plans written here. Broken answers are
scripted per test: text outside each format (located refusals, no second question where the
paper gives none), code that would do harm if it were run (it is not), actions the world cannot
place or the robots cannot do (failed actions, Exe < 1, never a crash), LaMMA-P's one validator
round."""
from __future__ import annotations

import json
from pathlib import Path

import pytest
import yaml

import pipflow
from baseline_answers import (Gold, cot_answer, gold_from_pip_llm, responder, smart_llm_answer, summary_answer,
                              warehouse_problems)
from fake_openai import FakeOpenAI
from pipflow.baselines.cot import read_cot
from pipflow.baselines.lammap import Subtask, merge_in_time, read_summary
from pipflow.baselines.located import Issue, Unreadable
from pipflow.baselines.robotplan import RobotStep
from pipflow.baselines.skills import domain_skills
from pipflow.baselines import robotplan, smartllm
from pipflow.baselines.smartllm import read_smart_llm
from pipflow.steps import baselines as baseline_steps
from pipflow.experiments.benchmarking import BenchConfig, run_bench
from pipflow.household.world import load_world as load_home, select_team
from pipflow.warehouse.problem import write_problem
from pipflow.warehouse.world import load_tasks, load_world

REPO = Path(__file__).resolve().parents[1]
WAREHOUSE_TASKS = REPO / "benchmarks" / "warehouse" / "tasks.yaml"
HOME = REPO / "benchmarks" / "household" / "world.yaml"
WORLD = load_world(REPO / "benchmarks" / "warehouse" / "world.yaml")
TEAM = list(WORLD["robots"])
WAREHOUSE_SKILLS = domain_skills((REPO / "domains" / "warehouse.pddl").read_text())
HOUSEHOLD_SKILLS = domain_skills((REPO / "domains" / "household.pddl").read_text())
METHODS = ["cot", "smart-llm", "lamma-p"]
WH01 = "There should be 7 product 1 in shelf 3."  # shelf3 holds 5 product1: move 2 from shelf1
WH01_GOLD = [Gold("a1", "move-product", ["shelf1", "shelf3", "product1", "magnitude2"], ["robot4"])]


@pytest.fixture(autouse=True)
def _env(engine_env, monkeypatch):
    monkeypatch.setenv("OPENAI_API_KEY", "sk-test-not-a-real-key-000")
    monkeypatch.delenv("PIPFLOW_MODEL", raising=False)


def answers_for(gold: list[Gold], world: dict, problems: dict[int, str] | None = None) -> dict:
    """Every baseline's answers to one command, written from one known-good plan."""
    team = list(world["robots"])
    return {"cot": {"plan": cot_answer(gold)},
            "smart-llm": {"decompose": "# GENERAL TASK DECOMPOSITION\n# (subtasks)", "allocate": "# SOLUTION (robots)",
                          "code": smart_llm_answer(gold, team)},
            "lamma-p": {"decompose": "SubTask 1: ...", "allocate": "Robots as follows.",
                        "summary": summary_answer(gold),
                        "problem": problems if problems is not None else warehouse_problems(gold, world)}}


def run(workflow: str, server: FakeOpenAI, command: str = WH01, **inputs):
    return pipflow.run(workflow, command=command, model="openai/fake", api_base=server.api_base, runs_dir="runs",
                       **inputs)


def score(world_path: Path, task: dict, outputs: dict) -> dict:
    from pipflow.taskdomains import declared_domain

    return declared_domain(world_path).score_bench_run(str(world_path), task, outputs, None, None)


# ---------------------------------------------------------------------------------------------
# end to end: the ten paper tasks and the household categories, through the bench by method name
# ---------------------------------------------------------------------------------------------
@pytest.fixture(scope="module")
def paper_answers(tmp_path_factory) -> dict:
    """For each of the ten paper tasks: the four methods' right answers (PIP-LLM's: the gold
    problem; the baselines': the offline PIP-LLM run's plan and robots in their formats)."""
    runs = tmp_path_factory.mktemp("gold")
    out = {}
    for task in load_tasks(WAREHOUSE_TASKS)["tasks"]:
        gold = gold_from_pip_llm("pip-llm", task["command"], runs_dir=runs)
        out[task["command"]] = {**answers_for(gold, WORLD), "pip-llm": {"pip-llm": (
            f"```pddl\n{write_problem(WORLD, task['goal'])}\n```\n"
            f"```json\n{json.dumps({'constraints': task.get('constraints') or []})}\n```\n")}}
    return out


def test_the_comparison_runs_by_method_name_and_every_baseline_succeeds_on_the_ten_paper_tasks(paper_answers, tmp_path):
    """``--matrix workflow=pip-llm,cot,smart-llm,lamma-p`` on the paper's warehouse task file:
    each method by its name (the warehouse's workflows of those names), each run through the
    same simulation and scoring; with right answers every method succeeds on every task, with
    every action executed, and the rows say which method ran (no refinement loop for a
    baseline, the model as reader; understanding not measured, since a baseline writes no goal)."""
    with FakeOpenAI(responder(paper_answers)) as server:
        results = run_bench(BenchConfig(tasks_file=WAREHOUSE_TASKS, seeds=1, jobs=2, out=tmp_path / "b", use_cache=False,
                                        matrix={"workflow": ["pip-llm", *METHODS]},
                                        inputs={"model": "openai/fake", "api_base": server.api_base}), progress=False)
    assert results["config"]["workflows"] == {f"workflow={m}": m for m in ["pip-llm", *METHODS]}
    for variant in results["variants"]:
        assert [(t["id"], t["sr"], t["exe"]) for t in variant["tasks"]] == \
            [(f"wh-{k:02d}", 1.0, 1.0) for k in range(1, 11)], variant["name"]
    rows = json.loads((tmp_path / "b" / "runs.json").read_text())
    assert {(r["variant"], r["loop"], r["reader"]) for r in rows if r["variant"] != "workflow=pip-llm"} == \
        {(f"workflow={m}", "none", "model") for m in METHODS}
    # a baseline writes no goal: whether it read the command right is not measured (PIP-LLM's goal is)
    assert {(r["variant"] == "workflow=pip-llm", r["understood"]) for r in rows} == {(True, True), (False, None)}


HOUSEHOLD = {  # one task of each category (benchmarks/household/tasks.yaml), a right plan for each
    "hc-01": [Gold("a1", "slice", ["lettuce", "countertop"], ["robot1"]),
              Gold("a2", "trash", ["mug", "diningtable", "garbagecan"], ["robot2"]),
              Gold("a3", "switch-off", ["floorlamp", "floorlamp"], ["robot3"])],
    "hx-01": [Gold("a1", "open", ["fridge"], ["robot6"]),
              Gold("a2", "store", ["watermelon", "diningtable", "fridge"], ["robot4", "robot5"], ["a1"]),
              Gold("a3", "close", ["fridge"], ["robot6"], ["a2"])],
    "hv-01": [Gold("a1", "switch-off", ["lightswitch", "lightswitch"], ["robot1"]),
              Gold("a2", "switch-off", ["floorlamp", "floorlamp"], ["robot2"]),
              Gold("a3", "switch-off", ["desklamp", "desk"], ["robot3"])],
}


def pddl(n: int, objects: str, init: str, goal: str) -> str:
    return (f"```pddl\n(define (problem subtask{n}) (:domain household-robots)\n  (:objects {objects})\n"
            f"  (:init {init})\n  (:goal {goal}))\n```\n")


HOUSEHOLD_PROBLEMS = {  # LaMMA-P's per-robot problems of those plans, as a model that got them right writes them
    "hc-01": {1: pddl(1, "robot1 - robot countertop - place lettuce - item",
                      "(at lettuce countertop) (sliceable lettuce) (accessible countertop) (can-slice robot1)",
                      "(sliced lettuce)"),
              2: pddl(2, "robot2 - robot diningtable garbagecan - place mug - item",
                      "(at mug diningtable) (pickupable mug) (= (mass mug) 1) (is-garbage garbagecan) "
                      "(accessible diningtable) (= (pickup robot2) 1)", "(at mug garbagecan)"),
              3: pddl(3, "robot3 - robot floorlamp - place",
                      "(at floorlamp floorlamp) (toggleable floorlamp) (is-on floorlamp) (can-toggle robot3)",
                      "(not (is-on floorlamp))")},
    "hx-01": {1: pddl(1, "robot6 - robot fridge - place", "(openable fridge) (can-open robot6)", "(is-open fridge)"),
              2: pddl(2, "robot4 robot5 - robot diningtable fridge - place watermelon - item",
                      "(at watermelon diningtable) (pickupable watermelon) (= (mass watermelon) 2) "
                      "(is-receptacle fridge) (openable fridge) (is-open fridge) (accessible diningtable) "
                      "(accessible fridge) (= (pickup robot4) 1) (= (pickup robot5) 1)", "(at watermelon fridge)"),
              3: pddl(3, "robot6 - robot fridge - place", "(openable fridge) (is-open fridge) (accessible fridge) "
                      "(can-open robot6)", "(not (is-open fridge))")},
    "hv-01": {1: pddl(1, "robot1 - robot lightswitch - place", "(at lightswitch lightswitch) (toggleable lightswitch) "
                      "(is-on lightswitch) (can-toggle robot1)", "(not (is-on lightswitch))"),
              2: pddl(2, "robot2 - robot floorlamp - place", "(at floorlamp floorlamp) (toggleable floorlamp) "
                      "(is-on floorlamp) (can-toggle robot2)", "(not (is-on floorlamp))"),
              3: pddl(3, "robot3 - robot desk - place desklamp - item", "(at desklamp desk) (toggleable desklamp) "
                      "(is-on desklamp) (can-toggle robot3)", "(not (is-on desklamp))")},
}


def test_every_baseline_succeeds_on_household_tasks_of_each_category(tmp_path):
    """A compound, a complex (two lifters carry the 2-unit watermelon; the handler opens the
    fridge) and a vague task, through the bench by method name: the household's own workflows
    run (household-cot, ...), with the task's team, and each method succeeds on each."""
    all_tasks = {t["id"]: t for t in yaml.safe_load((REPO / "benchmarks" / "household" / "tasks.yaml").read_text())["tasks"]}
    tasks_file = tmp_path / "tasks.yaml"
    tasks_file.write_text(yaml.safe_dump({"domain": "household", "world": str(HOME),
                                          "tasks": [all_tasks[i] for i in HOUSEHOLD]}, sort_keys=False))
    answers = {}
    for tid, gold in HOUSEHOLD.items():
        team = select_team(load_home(HOME), all_tasks[tid]["team"])
        answers[all_tasks[tid]["command"]] = answers_for(gold, team, HOUSEHOLD_PROBLEMS[tid])
    with FakeOpenAI(responder(answers)) as server:
        results = run_bench(BenchConfig(tasks_file=tasks_file, seeds=1, jobs=2, out=tmp_path / "b", use_cache=False,
                                        matrix={"workflow": METHODS},
                                        inputs={"model": "openai/fake", "api_base": server.api_base}), progress=False)
    assert results["config"]["workflows"] == {f"workflow={m}": f"household-{m}" for m in METHODS}
    rows = json.loads((tmp_path / "b" / "runs.json").read_text())
    assert sorted((r["variant"], r["task"], r["success"], r["exe"]) for r in rows) == sorted(
        (f"workflow={m}", tid, True, 1.0) for m in METHODS for tid in HOUSEHOLD), [r.get("violations") for r in rows]


# ---------------------------------------------------------------------------------------------
# answers outside the format: located, and no round the paper does not give
# ---------------------------------------------------------------------------------------------
def test_a_cot_answer_outside_its_format_ends_the_run_with_every_problem_located_and_no_second_question():
    answer = ("First the stock.\nPLAN:\n1. robot4: (move-product shelf1 shelf3 product1 magnitude2)\n"
              "2. robot5 (move-product shelf1 shelf3 product1 magnitude1)\n"
              "4. robot6: (move-product shelf1 shelf3 product1 magnitude1)\n"
              "5. robot7: (fly shelf1)\nEND\n")
    with FakeOpenAI([answer]) as server:
        result = run("cot", server)
        assert len(server.requests) == 1  # CoT has no feedback round
    assert result.status == "failed"
    assert "line 4, column 11: expected ',' between robots or ':' after the robots, found '('" in result.error
    assert "line 5, column 1: step 4 follows step 2: expected step 2 or 3" in result.error
    assert "line 6, column 13: 'fly' is not an action of the domain" in result.error
    assert (result.record / "steps" / "read" / "artifacts" / "issues.txt").is_file()
    assert not (result.record / "steps" / "schedule").exists()  # nothing planned, nothing executed


def test_a_smart_llm_answer_with_a_syntax_error_is_located_after_its_three_questions():
    code = "def f(robot_list):\n    MoveProduct(robot_list[0], 'shelf1', 'shelf3', 'product1', 'magnitude2'\nf([robots[4]])\n"
    with FakeOpenAI(["# decomposition", "# allocation", code]) as server:
        result = run("smart-llm", server)
        assert len(server.requests) == 3  # decompose, allocate, code: SMART-LLM's stages, no feedback
    assert result.status == "failed" and "line 2, column 16: Python syntax: '(' was never closed" in result.error


def test_a_lamma_p_summary_it_cannot_read_gets_one_round_with_the_located_problems_then_ends_the_run():
    """LaMMA-P re-asks once for a summary subtask it cannot read: the second question carries
    every problem located; still unreadable, the run ends there (no subtask to plan)."""
    summary = ("Problem content summary:\nSubTask 1: move two\nAssigned Robot: robot44\nAfter: none\n"
               "SubTask 1: again\nAssigned Robot: robot4\nAfter: 1, 7\n")
    with FakeOpenAI(["decomposition", "allocation", summary, summary, "never asked"]) as server:
        result = run("lamma-p", server)
        prompts = server.prompts()
    assert len(prompts) == 4
    assert result.status == "failed"
    for located in ("line 3, column 17: 'robot44' is not a robot of the team", "line 5, column 9: a second SubTask 1",
                    "line 5, column 1: the subtask of line 5 comes after 7, which is not a subtask of the summary"):
        assert located in prompts[3], prompts[3][-1500:]
        assert located in result.error, result.error


def test_a_lamma_p_subtask_still_unreadable_after_its_round_is_skipped_and_the_others_are_planned():
    """Two subtasks, the second naming a robot the team lacks, in the summary and in its fix:
    the second is skipped (as LaMMA-P skips a subtask it cannot read), the first planned and
    executed; the task is not done."""
    gold = WH01_GOLD + [Gold("a2", "move-product", ["shelf1", "shelf3", "product1", "magnitude1"], ["robot5"])]
    summary = summary_answer(gold).replace("Assigned Robot: robot5", "Assigned Robot: robot55")
    problems = warehouse_problems(gold, WORLD)
    with FakeOpenAI(["decomposition", "allocation", summary, summary, problems[1]]) as server:
        result = run("lamma-p", server)
        assert len(server.requests) == 5
    assert result.status == "succeeded", result.error
    assert [(s["subtask"], s["status"], s["actions"]) for s in result.outputs["subtasks"]] == [
        (1, "solved", 1), (2, "skipped", 0)]
    assert "'robot55' is not a robot of the team" in result.outputs["subtasks"][1]["message"]
    assert result.outputs["exe"] == 1.0


# ---------------------------------------------------------------------------------------------
# SMART-LLM's code is read, never run
# ---------------------------------------------------------------------------------------------
VALID = ("def move_two(robot_list):\n"
         "    MoveProduct(robot_list[0], 'shelf1', 'shelf3', 'product1', 'magnitude2')\n\n")
HARMFUL = {  # what a model could write (after VALID's 3 lines), where the refusal points, and what it says
    "import": ("import os\nos.system('touch {marker}')\n", "line 4, column 1", "import os: the plan may import only"),
    "__import__": ("__import__('os').system('touch {marker}')\n", "line 4, column 1", "'__import__' is not part"),
    "open": ("open('{marker}', 'w').write('x')\n", "line 4, column 1", "is not something the format calls"),
    "exec": ("exec(\"open('{marker}', 'w')\")\n", "line 4, column 1", "'exec' is not a skill"),
    "eval in a function": ("def g(robot_list):\n    eval(\"open('{marker}', 'w')\")\ng([robots[0]])\n",
                           "line 5, column 5", "'eval' is not a skill"),
    "dunder chain": ("().__class__.__base__.__subclasses__()\n", "line 4, column 1", "the attribute '__subclasses__'"),
    "lambda thread": ("t = threading.Thread(target=lambda: open('{marker}', 'w'))\nt.start()\n",
                      "line 4, column 29", "a lambda is not part of the SMART-LLM format"),
    "comprehension": ("[open('{marker}', 'w') for _ in range(1)]\n", "line 4, column 1", "a comprehension"),
    "loop": ("for r in [robots[0]]:\n    open('{marker}', 'w')\n", "line 4, column 1", "a `for` loop"),
    "skill argument": ("MoveProduct(robots[0], open('{marker}', 'w'), 'shelf3', 'product1', 'magnitude1')\n",
                       "line 4, column 24", "the arguments after the robots are names in quotes"),
    "thread args": ("t = threading.Thread(target=move_two, args=(open('{marker}', 'w'),))\nt.start()\n",
                    "line 4, column 45", "is not robots"),
}


@pytest.mark.parametrize("kind", sorted(HARMFUL))
def test_smart_llm_code_that_would_do_harm_is_refused_located_and_nothing_runs(kind, tmp_path, monkeypatch):
    """The answer's code would create a file if anything ran it. The run fails with the
    offending line and column, the file does not exist, and the modules that handle the answer
    never call exec, eval or compile (they raise here; ast.parse builds a tree and runs nothing)."""
    marker = tmp_path / "PWNED"
    snippet, where, words = HARMFUL[kind]
    code = VALID + snippet.format(marker=marker) + "move_two([robots[4]])\n"

    def never(*args, **kwargs):
        raise AssertionError("model text was executed")

    for module in (smartllm, robotplan, baseline_steps):  # the modules that handle the answer: their globals
        monkeypatch.setattr(module, "exec", never, raising=False)
        monkeypatch.setattr(module, "eval", never, raising=False)
        monkeypatch.setattr(module, "compile", never, raising=False)
    with FakeOpenAI(["# decomposition", "# allocation", code]) as server:
        result = run("smart-llm", server)
    assert result.status == "failed", result.error
    assert any(line.strip().startswith(where) and words in line for line in result.error.splitlines()), result.error
    assert "nothing is executed" in result.error
    assert not marker.exists()
    assert not (result.record / "steps" / "schedule").exists()


# ---------------------------------------------------------------------------------------------
# what the world cannot place or the robots cannot do: failed actions, Exe < 1, not a crash
# ---------------------------------------------------------------------------------------------
@pytest.mark.parametrize("method", METHODS)
def test_an_action_on_a_missing_shelf_or_beyond_the_robots_skill_is_a_failed_action_not_a_crash(method, tmp_path):
    """wh-01 planned with three mistakes a model makes: a robot that carries 1 moving 2 units,
    a shelf that does not exist, a robot outside the team (SMART-LLM: robots[17]). Each is a
    planned action that fails in the simulation; the run finishes and the task fails with Exe < 1."""
    gold = [Gold("a1", "move-product", ["shelf1", "shelf3", "product1", "magnitude2"], ["robot0"]),
            Gold("a2", "move-product", ["shelf9", "shelf3", "product1", "magnitude1"], ["robot4"]),
            Gold("a3", "move-product", ["shelf1", "shelf3", "product1", "magnitude1"], ["robot5"], ["a1"])]
    answers = answers_for(gold, WORLD)[method]
    if method == "smart-llm":
        answers["code"] = answers["code"].replace("robots[5]", "robots[17]")
    elif method == "cot":
        answers["plan"] = answers["plan"].replace("robot5:", "robot17:")
    else:  # LaMMA-P plans each subtask with a planner: the problem claims the robot carries 2
        answers["problem"][1] = answers["problem"][1].replace("(= (carry robot0) 1)", "(= (carry robot0) 2)")
        answers["problem"][2] = answers["problem"][2].replace("shelf9", "shelf9").replace("(= (stock shelf9 product1) 0)",
                                                                                        "(= (stock shelf9 product1) 4)")
    with FakeOpenAI(responder({WH01: {method: answers}})) as server:
        result = run(method, server)
    assert result.status == "succeeded", result.error
    sim = result.outputs["simulation"]
    reasons = [" ".join(f["reasons"]) for f in sim["failures"]]
    assert any("carry 1 < 2" in r for r in reasons), reasons
    assert any("'shelf9' is not in this world" in r for r in reasons), reasons
    if method != "lamma-p":
        assert any("robots[17]" in r or "'robot17' is not a robot of the team" in r for r in reasons), reasons
    assert sim["exe"] < 1.0
    judged = score(REPO / "benchmarks" / "warehouse" / "world.yaml", {"goal": {"shelf3": {"product1": 7}}}, result.outputs)
    assert not judged["success"] and judged["exe"] < 1.0


@pytest.mark.parametrize("method", ["cot", "smart-llm"])
def test_household_actions_beyond_the_robots_skills_or_on_a_missing_place_fail_in_the_home(method):
    """hx-01 with the lifters-handler team, planned wrongly: a lifter opens the fridge (it has
    no open skill), one lifter carries the 2-unit watermelon, the handler puts the mug on a
    balcony the home lacks. The home simulator refuses each; the run finishes, Exe < 1."""
    gold = [Gold("a1", "open", ["fridge"], ["robot4"]),
            Gold("a2", "store", ["watermelon", "diningtable", "fridge"], ["robot5"], ["a1"]),
            Gold("a3", "store", ["mug", "diningtable", "balcony"], ["robot6"])]
    team = select_team(load_home(HOME), "lifters-handler")
    command = "Put the watermelon in the fridge."
    with FakeOpenAI(responder({command: answers_for(gold, team, problems={})})) as server:
        result = run(f"household-{method}", server, command=command, team="lifters-handler")
    assert result.status == "succeeded", result.error
    reasons = {f["args"][0]: " ".join(f["reasons"]) for f in result.outputs["simulation"]["failures"]}
    assert "open: needs 1, the coalition has 0" in reasons["fridge"]
    assert "pickup: needs 2, the coalition has 1" in reasons["watermelon"]
    assert "'balcony' is not in this world" in reasons["mug"]
    assert result.outputs["exe"] == 0.0 and result.outputs["unexecutable"] == 1
    task = {"team": "lifters-handler", "goal": {"in": {"fridge": ["watermelon"]}, "state": {"fridge": ["closed"]}}}
    assert not score(HOME, task, result.outputs)["success"]


# ---------------------------------------------------------------------------------------------
# LaMMA-P: one validator round, with the debugger's located messages
# ---------------------------------------------------------------------------------------------
def lamma_p_script(*problems: str) -> list[str]:
    return ["decomposition", "allocation", summary_answer(WH01_GOLD), *problems]


@pytest.mark.parametrize("mistake", ["misspelt product", "a robot not assigned"])
def test_lamma_p_gets_one_validator_round_with_the_debuggers_located_message_and_then_succeeds(mistake):
    good = warehouse_problems(WH01_GOLD, WORLD)[1]
    if mistake == "misspelt product":
        broken, said = good.replace("(= (stock shelf3 product1) 5)", "(= (stock shelf3 prodcut1) 5)"), \
            ["prodcut1", "line 3", "did you mean 'product1'"]
    else:  # the problem adds robot9 (carry 3): LaMMA-P's per-robot domains hold no other robot
        broken = good.replace("robot4 - robot", "robot4 robot9 - robot").replace("(= (carry robot4) 2)",
                                                                               "(= (carry robot4) 2) (= (carry robot9) 3)")
        said = ["line 2, column", "declares the robot robot9, which the summary did not assign to SubTask 1"]
    with FakeOpenAI(lamma_p_script(broken, good)) as server:
        result = run("lamma-p", server)
        prompts = server.prompts()
    assert result.status == "succeeded", result.error
    assert len(prompts) == 5
    assert "The PDDL validator found these problems:" in prompts[4]
    assert all(words in prompts[4] for words in said), prompts[4][-1200:]
    sub = result.outputs["subtasks"][0]
    assert sub["status"] == "solved" and len(sub["validator"]) == 1
    assert score(REPO / "benchmarks" / "warehouse" / "world.yaml", {"goal": {"shelf3": {"product1": 7}}},
                 result.outputs)["success"]


def test_lamma_p_a_problem_still_broken_after_its_one_round_leaves_its_subtask_without_actions():
    good = warehouse_problems(WH01_GOLD, WORLD)[1]
    unclosed = good.replace("(= (carry robot4) 2))", "(= (carry robot4) 2)")
    with FakeOpenAI(lamma_p_script(unclosed, unclosed, good)) as server:
        result = run("lamma-p", server)
        prompts = server.prompts()
    assert len(prompts) == 5  # one validator round, as LaMMA-P's: the good third answer is never asked for
    assert "the (:init list opened on line 3, column 3 is never closed" in prompts[4], prompts[4][-800:]
    assert result.status == "succeeded"
    sub = result.outputs["subtasks"][0]
    assert sub["status"] == "not planned" and sub["actions"] == 0 and len(sub["validator"]) == 2
    assert result.outputs["plan"] == []
    assert not score(REPO / "benchmarks" / "warehouse" / "world.yaml", {"goal": {"shelf3": {"product1": 7}}},
                     result.outputs)["success"]


# ---------------------------------------------------------------------------------------------
# no model, wrong world
# ---------------------------------------------------------------------------------------------
@pytest.mark.parametrize("method", METHODS)
def test_a_baseline_without_a_language_model_is_a_user_error(method, capsys, tmp_path):
    from pipflow.engine.cli import main

    code = main(["run", method, "--runs-dir", str(tmp_path / "runs")])
    err = capsys.readouterr().err
    assert code == 2 and f"the {method} baseline is a language model's work" in err and "-i model=" in err


def test_a_household_world_given_to_the_warehouse_baseline_names_the_households_workflows():
    with FakeOpenAI(["never asked"]) as server:
        result = run("cot", server, world=str(HOME))
        assert not server.requests
    assert result.status == "failed"
    assert "household world" in result.error and "household-cot" in result.error


# ---------------------------------------------------------------------------------------------
# the readers alone
# ---------------------------------------------------------------------------------------------
def test_cot_steps_of_one_number_run_together_and_the_next_waits_for_all_of_them():
    steps = read_cot("PLAN:\n1. robot6: (open fridge)\n1. robot3: (switch-off tv tv)\n"
                     "2. robot4, robot5: (store pumpkin countertop fridge)\n3. robot6: (close fridge)\n", HOUSEHOLD_SKILLS)
    assert [(s.id, s.robots, s.after) for s in steps] == [
        ("a1", ["robot6"], []), ("a2", ["robot3"], []), ("a3", ["robot4", "robot5"], ["a1", "a2"]),
        ("a4", ["robot6"], ["a3"])]


def test_cot_reads_the_last_plan_of_an_answer_that_corrects_itself():
    answer = ("PLAN:\n1. robot0: (move-product shelf1 shelf3 product1 magnitude3)\nEND\nNo, robot0 carries 1.\n"
              "PLAN:\n1. robot8: (move-product shelf1 shelf3 product1 magnitude3)\nEND\nDone.")
    assert [s.robots for s in read_cot(answer, WAREHOUSE_SKILLS)] == [["robot8"]]


def test_smart_llm_threads_calls_and_joins_give_the_order():
    code = (VALID + "def other(robot_list):\n    MoveProduct(robot_list, 'shelf2', 'shelf4', 'product2', 'magnitude3')\n"
            "    MoveProduct(robot_list[1], 'shelf4', 'shelf1', 'product3', 'magnitude1')\n\n"
            "t1 = threading.Thread(target=move_two, args=([robots[4]],))\n"
            "t2 = threading.Thread(target=other, args=([robots[0], robots[5]],))\n"
            "t1.start()\nt2.start()\nt1.join()\nmove_two([robots[8]])\nt2.join()\n"
            "MoveProduct(robots[9], 'shelf3', 'shelf2', 'product4', 'magnitude2')\n")
    steps = read_smart_llm(code, WAREHOUSE_SKILLS, TEAM)
    assert [(s.id, s.robots, s.after) for s in steps] == [
        ("a1", ["robot4"], []),                # t1 starts
        ("a2", ["robot0", "robot5"], []),      # t2 starts beside it, its first action
        ("a3", ["robot5"], ["a2"]),            # its second, after its first
        ("a4", ["robot8"], ["a1"]),            # a plain call after t1.join()
        ("a5", ["robot9"], ["a3", "a4"])]      # after the call and t2.join()
    assert all(not s.problems for s in steps)


def test_smart_llm_robot_indices_past_the_team_are_the_worlds_business_not_the_formats():
    steps = read_smart_llm(VALID + "move_two([robots[12]])\n", WAREHOUSE_SKILLS, TEAM)
    assert steps[0].robots == [] and "robots[12] is past the 12 robots it indexes" in steps[0].problems[0]


def test_smart_llm_accepts_the_prelude_its_prompt_shows_and_refuses_other_imports():
    prelude = "from skills import MoveProduct\nimport time\nimport threading\n"
    assert len(read_smart_llm(prelude + VALID + "move_two([robots[4]])\ntime.sleep(5)\n", WAREHOUSE_SKILLS, TEAM)) == 1
    with pytest.raises(Unreadable, match=r"line 1, column 1: import subprocess"):
        read_smart_llm("import subprocess\n" + VALID + "move_two([robots[4]])\n", WAREHOUSE_SKILLS, TEAM)


def test_lamma_p_summary_reads_decorated_fields_and_refuses_a_circle():
    summary = ("Problem content summary:\n**SubTask 1**: open the fridge\n**Assigned Robot**: robot6\n"
               "The fridge is closed, so this comes first.\n**Objects Involved**: fridge\n**After**: none\n"
               "SubTask 2: melon in\nAssigned Robot: team of robot4 and robot5\nAfter: SubTask 1\n")
    read = read_summary(summary, ["robot4", "robot5", "robot6"])
    assert not read.issues
    assert [(s.number, s.robots, s.after) for s in read.subtasks] == [(1, ["robot6"], []), (2, ["robot4", "robot5"], [1])]
    circle = "SubTask 1: a\nAssigned Robot: robot4\nAfter: 2\nSubTask 2: b\nAssigned Robot: robot5\nAfter: 1\n"
    with pytest.raises(Unreadable, match="in a circle: SubTask 1 -> SubTask 2 -> SubTask 1"):
        read_summary(circle, ["robot4", "robot5"])


def test_lamma_p_merge_waits_through_a_subtask_that_got_no_actions():
    subtasks = [Subtask(1, "a", ["r1"]), Subtask(2, "b", ["r2"], after=[1]), Subtask(3, "c", ["r3"], after=[2])]
    plans = {1: [RobotStep("a1", "open", ["fridge"], ["r1"])],
             3: [RobotStep("a2", "close", ["fridge"], ["r3"]), RobotStep("a3", "open", ["fridge"], ["r3"], ["a2"])]}
    merged = merge_in_time(subtasks, plans)
    assert [(s.id, s.after) for s in merged] == [("a1", []), ("a2", ["a1"]), ("a3", ["a2"])]


def test_a_refusal_says_when_the_answer_was_cut_off_at_its_token_limit():
    error = Unreadable([Issue(3, 1, "expected ':' after the robots")])
    assert "cut off at the 512 tokens it may take (raise -i max_tokens)" in str(error.refusal("cot", "a plan", 512))
    assert "cut off" not in str(error.refusal("cot", "a plan"))


def test_the_schedule_records_an_action_the_world_cannot_place_as_refused_taking_no_time_and_no_travel():
    """A robot plan of three moves, the middle one from a shelf the world lacks: the schedule
    keeps it (refused, at the moment its predecessor ends, nobody drives for it), the move after
    it waits for it, and the simulation counts it as planned and failed."""
    from pipflow.baselines.robotplan import schedule_input
    from pipflow.steps.world import simulate
    from pipflow.engine.step import StepContext
    from pipflow.team.scheduling import build_schedule

    steps = [RobotStep("a1", "move-product", ["shelf1", "shelf3", "product1", "magnitude2"], ["robot4"]),
             RobotStep("a2", "move-product", ["shelf9", "shelf3", "product1", "magnitude1"], ["robot5"], ["a1"]),
             RobotStep("a3", "move-product", ["shelf2", "shelf4", "product2", "magnitude1"], ["robot5"], ["a2"])]
    domain = (REPO / "domains" / "warehouse.pddl").read_text()
    metadata = yaml.safe_load((REPO / "domains" / "warehouse.actions.yaml").read_text())
    got = schedule_input(steps, WORLD, domain, metadata, "cot")
    assert got["unexecutable"] == 1 and got["graph"]["edges"] == [["a1", "a2"], ["a2", "a3"]]
    schedule = build_schedule(got["graph"], got["allocation"], WORLD)
    first, refused, last = schedule["subtasks"]
    assert refused["refused"] and "'shelf9' is not in this world" in refused["refused"][0]
    assert refused["start"] == refused["end"] == first["end"] and last["ready"] == refused["end"]
    assert all(leg["subtask"] != "a2" for leg in schedule["robots"]["robot5"]["legs"])
    out = simulate.func(StepContext("simulate", Path("sim"), Path(".")), world=WORLD, schedule=schedule, graph=got["graph"])
    assert (out["executed"], out["failed"]) == (2, 1) and out["exe"] == pytest.approx(2 / 3)
    assert [f["subtask"] for f in out["failures"]] == ["a2"]


def test_cot_takes_a_line_that_ends_with_plan_as_the_marker_and_counts_a_broken_lines_step():
    """What SmolLM2 writes: "Here is the PLAN:", then lines of which some break the format. The
    broken lines are each said once; their step numbers still count, so the lines after them are
    not also blamed for the numbering."""
    answer = ("Here is the PLAN:\n1. robot4: (move-product shelf1 shelf3 product1 magnitude2)\n"
              "2. robot5: (carry 1 shelf1)\n3. robot6: (move-product shelf1 shelf3 product1 magnitude1)\n")
    with pytest.raises(Unreadable) as bad:
        read_cot(answer, WAREHOUSE_SKILLS)
    assert [str(i) for i in bad.value.issues] == [
        "line 3, column 19: expected ')' or a name, found '1'; a plan line is `N. ROBOT, ROBOT: (ACTION ARG ...)`"]

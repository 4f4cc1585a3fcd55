"""The refinement loop with a model that makes the mistakes real small models make (issue 17),
driven through a scripted OpenAI-compatible server on loopback (litellm's real HTTP path) and
the real workflow: debugger, planner, verifier, the second opinion (llm.check), SCIP, pybullet.

Each test replays answers of one kind: impossible counts, the wrong products, an unclosed
``(:objects`` list, the same answer again and again, an answer that never comes."""
from __future__ import annotations

import json
import re
from pathlib import Path

import pytest

import pipflow
from fake_openai import FakeOpenAI
from pipflow.language import agreement, feedback
from pipflow.pddl.writer import write_problem
from pipflow.warehouse.world import load_world

REPO = Path(__file__).resolve().parents[1]
WAREHOUSE = REPO / "workflows" / "warehouse.yaml"
WORLD = load_world(REPO / "benchmarks" / "warehouse" / "world.yaml")
# the paper's wh-04 and wh-05 (benchmarks/warehouse/tasks.yaml)
WH04 = ("There should be 2 product2, 7 product3, 8 product1 in shelf3, 3 product2, 5 product3, "
        "12 product1 in shelf2.")
WH04_GOAL = {"shelf3": {"product2": 2, "product3": 7, "product1": 8},
             "shelf2": {"product2": 3, "product3": 5, "product1": 12}}
WH05 = ("There should be 20 product1 in shelf2, 16 product1 in shelf4, 2 product1 in shelf3. But robot 0 "
        "should not be used to move product1 from one shelf to another.")
PDDL_FORMS = ("(define", "(= (stock", ":objects", "(:goal")
JSON_FORMS = ('"units"', '"shelf":', '{"goal"', '"op":', '"statements"')


@pytest.fixture(autouse=True)
def _env(engine_env, monkeypatch):
    monkeypatch.setenv("OPENAI_API_KEY", "sk-test-not-a-real-key-000")
    monkeypatch.delenv("PIPFLOW_MODEL", raising=False)


def grounded_answer(goal: dict, rules: list | None = None) -> str:
    """A grounded answer in the order form the prompt asks for: one ``set`` statement per count."""
    return json.dumps({"statements": [{"op": "set", "places": {"names": [s]}, "items": {"names": [p]},
                                       "amount": {"count": n}, "words": f"{n} {p} on {s}"}
                                      for s, items in goal.items() for p, n in items.items()],
                       "rules": rules or []})


def free_answer(goal: dict, rules: list | None = None) -> str:
    return (f"```pddl\n{write_problem(WORLD, goal)}\n```\n"
            f"```json\n{json.dumps({'constraints': rules or []})}\n```")


def feedback_of(prompt: str) -> list[str]:
    """The feedback lines of a rendered prompt (prompts/_warehouse_common.j2 feedback_part)."""
    m = re.search(r"Your previous answer was rejected:\n(.*?)\nFix these problems", prompt, re.DOTALL)
    return m.group(1).splitlines() if m else []


def run(tmp_path: Path, server: FakeOpenAI, command: str, **inputs):
    return pipflow.run(WAREHOUSE, command=command, model="openai/fake", api_base=server.api_base,
                       cache=False, runs_dir=tmp_path / "runs", **inputs)


def round_outputs(record: Path, n: int, step: str) -> dict:
    return json.loads((record / "steps" / "refine" / "iterations" / str(n) / step / "outputs.json").read_text())


def test_an_impossible_count_the_model_invented_is_feedback_not_a_refusal(tmp_path):
    """Grounded wh-04: 30 product2 where the command asks for 2. The verifier finds the goal
    impossible, but the command is not: the run goes on, in JSON terms, and succeeds."""
    wrong = {**WH04_GOAL, "shelf3": {**WH04_GOAL["shelf3"], "product2": 30}}
    with FakeOpenAI([grounded_answer(wrong), grounded_answer(WH04_GOAL)]) as server:
        result = run(tmp_path, server, WH04, grounded=True)
    assert result.status == "succeeded", result.error
    assert result.outputs["rounds"] == 2 and result.outputs["goal"] == WH04_GOAL
    assert result.outputs["disagreement"] == []
    second = feedback_of(server.prompts()[1])
    assert any("only 10 exist" in m for m in second)
    assert any('{"op": "set", "places": {"names": ["shelf3"]}, "items": {"names": ["product2"]}, '
               '"amount": {"count": 2}}' in m for m in second)
    assert not any(form in m for m in second for form in PDDL_FORMS)  # grounded: no PDDL-form feedback
    assert round_outputs(result.record, 1, "check")["refusal"] is None


def test_a_command_that_is_itself_impossible_is_refused_in_round_one(tmp_path):
    """The offline reading refuses the command (over capacity): the refusal is final whatever
    the model wrote, and no second round is asked for."""
    command = "shelf1 should hold 40 product1."
    with FakeOpenAI([grounded_answer({"shelf1": {"product1": 30}})]) as server:
        result = run(tmp_path, server, command, grounded=True)
        assert len(server.requests) == 1
    assert result.status == "refused"
    assert "capacity" in result.error


def test_wrong_products_are_never_accepted_and_repeated_prompts_are_varied(tmp_path):
    """Grounded wh-05 with the model's goal of product2/3/4 on the shelves, every round: each check
    passes but the goal is not the command's. The run fails (robots must not move) and says why;
    from round 3 on, where the feedback repeats, the prompt is varied one step further each
    round and the round records how."""
    wrong = {"shelf2": {"product2": 20}, "shelf4": {"product3": 16}, "shelf3": {"product4": 2}}
    with FakeOpenAI([grounded_answer(wrong, [{"mode": "never", "robots": {"names": ["robot0"]}, "product": "product1",
                                              "from": "any", "to": "any", "words": "robot 0 should not"}])]) as server:
        result = run(tmp_path, server, WH05, grounded=True, rounds=5)
        prompts, bodies = server.prompts(), server.requests
    assert result.status == "failed"
    assert "20 product1 on shelf2" in result.error  # the outcome names the disagreement
    assert len(prompts) == 5
    assert len(set(prompts)) == 5  # no round's prompt repeats an earlier one
    varied = [round_outputs(result.record, n, "generate")["varied"] for n in range(1, 6)]
    assert varied[:2] == ["", ""]
    assert varied[2] == "quoted previous answer"
    assert varied[3] == "quoted previous answer; added world facts"
    assert varied[4].startswith("quoted previous answer; added world facts; raised temperature to ")
    assert bodies[4]["temperature"] > 0 == bodies[3]["temperature"]
    quoted = prompts[2]
    assert '>> {"op": "set", "places": {"names": ["shelf2"]}, "items": {"names": ["product2"]}' in quoted  # marked
    assert "there are 38 product1 in all" in prompts[3]  # the world facts the answer got wrong
    for prompt in prompts[1:]:
        lines = feedback_of(prompt)
        assert any('"places": {"names": ["shelf2"]}, "items": {"names": ["product1"]}, "amount": {"count": 20}'
                   in m for m in lines)
        assert not any(form in m for m in lines for form in PDDL_FORMS)


def test_an_unclosed_objects_list_is_pointed_at_where_it_opened(tmp_path):
    """Free mode: a problem whose (:objects list never closes, once with a stray ')' at the end
    (so it parses as far as (:init: the debugger's case) and once without (the answer reader's
    case). Both times the feedback names the list and where it opened, not "Expected ':init'",
    and in PDDL terms only; the repaired answer succeeds."""
    goal = {"shelf3": {"product1": 7}}
    good = free_answer(goal)
    unbalanced = good.replace("magnitude6 - magnitude)", "magnitude6 - magnitude", 1)
    balanced = unbalanced.replace(")))\n", "))))\n", 1)
    assert good != unbalanced != balanced
    with FakeOpenAI([balanced, unbalanced, good]) as server:
        result = run(tmp_path, server, "There should be 7 product 1 in shelf 3.")
    assert result.status == "succeeded", result.error
    assert result.outputs["goal"] == goal and result.outputs["rounds"] == 3
    for prompt in server.prompts()[1:]:
        lines = feedback_of(prompt)
        assert any("the (:objects list opened on line 3, column 3 is never closed" in m and "(:init" in m
                   for m in lines), lines
        assert not any("Expected ':init'" in m for m in lines)
        assert not any(form in m for m in lines for form in JSON_FORMS)  # free: no JSON-form goal feedback


def test_a_wrong_goal_in_free_mode_is_feedback_in_pddl_terms(tmp_path):
    """Free mode wh-01 answered with 9 units instead of 7: a valid, solvable problem whose goal
    is not the command's. The disagreement is feedback phrased as a PDDL goal condition."""
    with FakeOpenAI([free_answer({"shelf3": {"product1": 9}}), free_answer({"shelf3": {"product1": 7}})]) as server:
        result = run(tmp_path, server, "There should be 7 product 1 in shelf 3.")
    assert result.status == "succeeded", result.error
    assert result.outputs["rounds"] == 2
    lines = feedback_of(server.prompts()[1])
    assert any("(= (stock shelf3 product1) 7)" in m for m in lines), lines
    assert not any(form in m for m in lines for form in JSON_FORMS)


def test_a_grounded_answer_that_is_not_json_gets_json_feedback_only(tmp_path):
    """A grounded model that answers in prose: the feedback is about the JSON answer; the
    debugger does not also ask it to "write a (define (problem ...) ...) form"."""
    with FakeOpenAI(["I would move some products around.", grounded_answer({"shelf3": {"product1": 7}})]) as server:
        result = run(tmp_path, server, "There should be 7 product 1 in shelf 3.", grounded=True)
    assert result.status == "succeeded", result.error
    lines = feedback_of(server.prompts()[1])
    assert lines and any("JSON" in m for m in lines)
    assert not any(form in m for m in lines for form in PDDL_FORMS), lines
    assert round_outputs(result.record, 1, "debug")["ok"] is None  # skipped: nothing to debug


def test_a_disagreement_with_the_command_words_is_accepted_last_with_a_warning(tmp_path):
    """A command the offline parser does not read: the model's goal is compared with the
    command's names and numbers. Its 5 where the command says 4 is feedback; in the last round
    the goal is accepted, and the run's outcome says it disagrees."""
    command = "Hmm, shelf2 ought to have 4 product3 please, zorbly glimwise."
    state, why = agreement.offline_reading(command, WORLD)
    assert state == "unread", (state, why)  # this test needs a command the parser does not read
    with FakeOpenAI([grounded_answer({"shelf2": {"product3": 5}})]) as server:
        result = run(tmp_path, server, command, grounded=True, rounds=2)
        prompts = server.prompts()
    assert result.status == "succeeded", result.error
    assert result.outputs["rounds"] == 2
    assert any("the command says 4" in m for m in feedback_of(prompts[1]))
    warning = result.outputs["disagreement"]
    assert warning and warning[0].startswith("warning: accepted after the last round") and "number 4" in warning[0]


def test_calls_carry_a_budget_and_stops_and_a_failed_round_keeps_its_prompt(tmp_path):
    """The token budget comes from the expected answer's size, a free answer has stop sequences,
    and an answer that does not come within the workflow's per-call deadline fails the round
    quickly, with the rendered prompt kept in the record."""
    with FakeOpenAI([free_answer({"shelf3": {"product1": 7}})]) as server:
        result = run(tmp_path, server, "There should be 7 product 1 in shelf 3.")
        free = server.requests[0]
    assert result.status == "succeeded", result.error
    assert 128 <= free["max_tokens"] < 1024 and "\nCommand:" in free["stop"]
    with FakeOpenAI([grounded_answer({"shelf3": {"product1": 7}})]) as server:
        run(tmp_path, server, "There should be 7 product 1 in shelf 3.", grounded=True)
        grounded = server.requests[0]
    assert grounded["max_tokens"] < free["max_tokens"] and "stop" not in grounded
    with FakeOpenAI([{"delay": 4, "text": "late"}]) as server:
        result = run(tmp_path, server, "There should be 7 product 1 in shelf 3.", llm_timeout=1, llm_deadline=2)
    assert result.status == "failed" and result.error_step == "generate", result.error
    assert "Timeout" in result.error and "deadline of 2 s" in result.error
    kept = result.record / "steps" / "refine" / "iterations" / "1" / "generate" / "artifacts" / "messages.json"
    messages = json.loads(kept.read_text())
    assert messages[-1]["role"] == "user" and "7 product 1 in shelf 3" in messages[-1]["content"]


# ---------------------------------------------------------------------------------------------
# the second opinion and the feedback forms on their own (no server, no planner)
# ---------------------------------------------------------------------------------------------
def test_the_second_opinion_compares_meaning_not_spelling():
    """Counts that stay as they are, robots in another order, a rule's source words, and an
    exact count inside the command's bound are agreements; a changed count elsewhere, a missing
    rule and a count outside the bound are not, each phrased in the mode's form."""
    command = "Robot 5 must not carry product1. shelf2 should hold 9 product1"
    state, reading = agreement.offline_reading(command, WORLD)
    assert state == "read"
    rule = {"never": ["robot5"], "product": "product1", "words": "Robot 5 must not carry product1"}
    same = agreement.second_opinion(command, WORLD, {"shelf2": {"product1": 9}, "shelf3": {"product4": 4}},
                                    [rule], None, grounded=False)
    assert same.disagreement == [] and same.refusal is None
    other = agreement.second_opinion(command, WORLD, {"shelf2": {"product1": 9}, "shelf3": {"product4": 7}},
                                     [], None, grounded=True)
    assert other.firm and len(other.disagreement) == 2
    assert any("shelf3" in m and "leave product4 on shelf3 out" in m for m in other.messages)
    assert any('"mode": "never", "robots": {"names": ["robot5"]}, "product": "product1"' in m for m in other.messages)
    bound = "shelf3 should hold at least 7 product1"
    assert agreement.second_opinion(bound, WORLD, {"shelf3": {"product1": 8}}, [], None, True).disagreement == []
    low = agreement.second_opinion(bound, WORLD, {"shelf3": {"product1": 6}}, [], None, False)
    assert low.messages == ["your goal asks for 6 product1 on shelf3, but the command asks for at least 7: "
                            "write (>= (stock shelf3 product1) 7)"]


def test_a_refusal_is_final_only_when_the_command_makes_the_goal_impossible():
    impossible_goal = {"shelf3": {"product2": 30}}
    invented = agreement.second_opinion("There should be 2 product2 in shelf3.", WORLD, impossible_goal, [],
                                        "the command cannot be done in this world: only 10 product2 exist", True)
    assert invented.refusal is None and invented.disagreement
    agreed = agreement.second_opinion("There should be 2 product2 in shelf3.", WORLD, {"shelf3": {"product2": 2}}, [],
                                      "the command cannot be done in this world: a reason", True)
    assert agreed.refusal == "the command cannot be done in this world: a reason"
    command = agreement.second_opinion("shelf1 should hold 40 product1.", WORLD, {"shelf1": {"product1": 30}}, [],
                                       None, True)
    assert command.refusal and "capacity" in command.refusal


def test_a_varied_prompt_adds_something_new_at_every_level():
    messages = ["your goal asks for 20 product2 on shelf2, but the command asks for 0"]
    answer = grounded_answer({"shelf2": {"product2": 20}, "shelf4": {"product3": 16}})
    texts = []
    for level in (1, 2, 3, 4):
        extra, temperature, done = feedback.vary(level, answer, messages, WORLD, True, 0.0)
        texts.append("\n".join(extra))
        assert (temperature > 0) == (level >= 3)
    assert len(set(texts)) == 4
    assert '>> {"op": "set", "places": {"names": ["shelf2"]}, "items": {"names": ["product2"]}' in texts[0]
    assert '   {"op": "set", "places": {"names": ["shelf4"]}, "items": {"names": ["product3"]}' in texts[0]  # not marked
    assert "- shelf2 holds 8 product1, 5 product2, 6 product3, 2 product4 now (21 units; capacity 30)" in texts[1]
    assert "- there are 10 product2 in all (shelf1 2, shelf2 5, shelf3 3)" in texts[1]


def test_household_an_impossible_goal_the_model_invented_is_feedback(tmp_path):
    """Household (goals not compared, refusals judged): the model adds "mug hot" (the mug is not
    heatable) to a command that can be done. Not a refusal: feedback, and the next answer runs."""
    from pipflow.household.problem import write_problem as household_problem
    from pipflow.household.world import load_world as load_home, select_team

    home = select_team(load_home(REPO / "benchmarks" / "household" / "world.yaml"), "lifters-handler-cook")
    good = {"in": {"sink": ["mug", "plate"]}, "state": {"mug": ["clean"], "plate": ["clean"]}}
    hot = {"in": {"sink": ["mug", "plate"]}, "state": {"mug": ["clean", "hot"], "plate": ["clean"]}}
    answers = [f"```pddl\n{household_problem(home, g)}\n```\n```json\n{{\"constraints\": []}}\n```" for g in (hot, good)]
    with FakeOpenAI(answers) as server:
        result = pipflow.run(REPO / "workflows" / "household.yaml", command="Put the dirty dishes in the sink and wash them.",
                             team="lifters-handler-cook", model="openai/fake", api_base=server.api_base, cache=False,
                             runs_dir=tmp_path / "runs")
        prompts = server.prompts()
    assert result.status == "succeeded", result.error
    assert len(prompts) == 2
    lines = feedback_of(prompts[1])
    assert any("not heatable" in m for m in lines) and any("your answer's, not the command's" in m for m in lines)


def test_feedback_that_cycles_back_is_varied_too(tmp_path):
    """Answers that alternate (prose, a broken problem, prose again) make the feedback cycle: the
    prompt of round 4 would be round 2's. It is varied, so no prompt of the run repeats."""
    prose = "I would move seven of product1 to shelf3."
    broken = free_answer({"shelf3": {"product1": 7}}).replace("magnitude6 - magnitude)", "magnitude6 - magnitude", 1)
    with FakeOpenAI([prose, broken, prose, prose]) as server:
        result = run(tmp_path, server, "There should be 7 product 1 in shelf 3.")
        prompts = server.prompts()
    assert result.status == "failed" and len(prompts) == 4
    assert feedback_of(prompts[3])[0] == feedback_of(prompts[1])[0]  # the same feedback again ...
    assert len(set(prompts)) == 4  # ... but not the same prompt
    assert round_outputs(result.record, 4, "generate")["varied"] == "quoted previous answer"
    assert "I would move seven of product1 to shelf3." in prompts[3]

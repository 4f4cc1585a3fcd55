"""The refinement loops with a model that makes the mistakes real small models make (issue 17),
driven through a scripted OpenAI-compatible server on loopback (litellm's real HTTP path) and
the real workflows: debugger, planner, verifier, SCIP, pybullet, and in the checked loop the
second opinion (llm.check).

Two loops (issue 20): ``pip-llm`` is the paper's (debugger and verifier, N rounds: whatever they
pass is accepted); ``pip-llm-checked`` adds the second opinion, whose feedback names what
disagrees and the command's words, never the parser's value. Each test replays answers of one
kind: impossible counts, the wrong products, an unclosed ``(:objects`` list, the same answer
again and again, an answer that never comes."""
from __future__ import annotations

import json
import re
from pathlib import Path

import pytest

import pipflow
from fake_openai import FakeOpenAI
from pipflow.language import agreement, feedback
from pipflow.warehouse.problem import write_problem
from pipflow.warehouse import agreement as warehouse_agreement
from pipflow.warehouse.world import load_world

REPO = Path(__file__).resolve().parents[1]
PAPER = REPO / "workflows" / "pip-llm.yaml"
CHECKED = REPO / "workflows" / "pip-llm-checked.yaml"
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
# issue 20's repro: a command the parser does not read, whose right goal (shelf4 holds 15
# product1: 8 on shelf3) names neither shelf4 nor 7, while a wrong one restates both
REPRO = "Whatever shelf4 has of product1, shelf3 should end up with 7 fewer than that."
REPRO_RIGHT = {"shelf3": {"product1": 8}}
REPRO_WRONG = {"shelf3": {"product1": 7}, "shelf4": {"product1": 15}}


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
    """The feedback lines of a rendered prompt (prompts/_warehouse_common.j2 feedback_part), each
    without its "- " bullet."""
    m = re.search(r"Your previous answer was rejected:\n(.*?)\nFix these problems", prompt, re.DOTALL)
    return [line.removeprefix("- ") for line in m.group(1).splitlines()] if m else []


def run(tmp_path: Path, server: FakeOpenAI, command: str, workflow: Path = CHECKED, **inputs):
    return pipflow.run(workflow, command=command, model="openai/fake", api_base=server.api_base,
                       cache=False, runs_dir=tmp_path / "runs", **inputs)


def round_outputs(record: Path, n: int, step: str) -> dict:
    return json.loads((record / "steps" / "refine" / "iterations" / str(n) / step / "outputs.json").read_text())


def recorded_prompts(record: Path) -> list[str]:
    """Every message sent to the model, round by round, as the run record keeps them."""
    folder = record / "steps" / "refine" / "iterations"
    rounds = sorted(folder.iterdir(), key=lambda p: int(p.name))
    return [m["content"] for it in rounds
            for m in json.loads((it / "generate" / "artifacts" / "messages.json").read_text())]


@pytest.mark.parametrize("workflow", [PAPER, CHECKED], ids=["pip-llm", "checked"])
def test_an_impossible_count_the_model_invented_is_feedback_not_a_refusal(tmp_path, workflow):
    """Grounded wh-04: 30 product2 where the command asks for 2. The verifier finds the goal
    impossible, but the command is not: in both loops the run goes on (the paper's loop feeds
    the verifier's finding back; the checked loop also says the count is not the command's,
    quoting the command's words and not the count), in JSON terms, and succeeds."""
    wrong = {**WH04_GOAL, "shelf3": {**WH04_GOAL["shelf3"], "product2": 30}}
    with FakeOpenAI([grounded_answer(wrong), grounded_answer(WH04_GOAL)]) as server:
        result = run(tmp_path, server, WH04, workflow, grounded=True)
    assert result.status == "succeeded", result.error
    assert result.outputs["rounds"] == 2 and result.outputs["goal"] == WH04_GOAL
    second = feedback_of(server.prompts()[1])
    assert any("only 10 exist" in m for m in second)
    assert not any(form in m for m in second for form in PDDL_FORMS + JSON_FORMS)  # no entry to paste
    if workflow == CHECKED:
        assert result.outputs["loop"] == "checked" and result.outputs["disagreement"] == []
        assert any("count of product2 on shelf3 is not what the command asks for" in m and "'2 product2" in m
                   for m in second), second
        assert round_outputs(result.record, 1, "check")["refusal"] is None
    else:
        assert result.outputs["loop"] == "pip-llm" and "disagreement" not in result.outputs
        assert not (result.record / "steps" / "refine" / "iterations" / "1" / "check").exists()


def test_a_command_that_is_itself_impossible_is_refused_in_round_one(tmp_path):
    """Checked loop: the offline reading refuses the command (over capacity): the refusal is
    final whatever the model wrote, and no second round is asked for."""
    command = "shelf1 should hold 40 product1."
    with FakeOpenAI([grounded_answer({"shelf1": {"product1": 30}})]) as server:
        result = run(tmp_path, server, command, grounded=True)
        assert len(server.requests) == 1
    assert result.status == "refused"
    assert "capacity" in result.error


def test_the_papers_loop_feeds_an_impossible_goal_back_and_refuses_only_in_the_last_round(tmp_path):
    """pip-llm: the verifier's finding that the goal cannot be done is feedback, as everything it
    finds is in the paper; a goal still impossible in the last round is a refusal (exit 3), not
    a failure, and robots never move."""
    impossible = {"shelf1": {"product1": 31}}  # over the shelf's capacity of 30
    with FakeOpenAI([grounded_answer(impossible)]) as server:
        result = run(tmp_path, server, "shelf1 should hold 40 product1.", PAPER, grounded=True, rounds=3)
        prompts = server.prompts()
    assert result.status == "refused" and "capacity" in result.error
    assert len(prompts) == 3 and any("capacity" in m for m in feedback_of(prompts[1]))
    assert not (result.record / "steps" / "simulate").exists()


def test_wrong_products_are_never_accepted_and_repeated_prompts_are_varied(tmp_path):
    """Checked loop, grounded wh-05 with the model's goal of product2/3/4 on the shelves, every
    round: each check of the paper's loop passes but the goal is not the command's. The run
    fails (robots must not move) and says why; from round 3 on, where the feedback repeats, the
    prompt is varied one step further each round and the round records how."""
    wrong = {"shelf2": {"product2": 20}, "shelf4": {"product3": 16}, "shelf3": {"product4": 2}}
    with FakeOpenAI([grounded_answer(wrong, [{"mode": "never", "robots": {"names": ["robot0"]}, "product": "product1",
                                              "from": "any", "to": "any", "words": "robot 0 should not"}])]) as server:
        result = run(tmp_path, server, WH05, grounded=True, rounds=5)
        prompts, bodies = server.prompts(), server.requests
    assert result.status == "failed"
    assert "product1 on shelf2" in result.error  # the outcome names the disagreement
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
        assert any("your goal leaves out product1 on shelf2" in m and "'20 product1" in m for m in lines), lines
        assert any("your goal changes product2 on shelf2, which the command does not ask for" in m for m in lines)
        checks = [m for m in lines if m.startswith("your")]  # the second opinion's lines (not a quoted answer)
        assert len(checks) == 6 and not any(form in m for m in checks for form in PDDL_FORMS + JSON_FORMS)


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


def test_the_papers_loop_accepts_what_debugger_and_verifier_pass(tmp_path):
    """wh-01 answered with 9 units instead of 7: a valid, solvable problem. The paper's loop
    accepts it in round 1 (nothing in it compares the goal with the command: what the paper's
    loop accepts, pip-llm accepts), and the record says which loop ran; the checked loop does not
    accept it, and its feedback names the count and quotes the command, with no entry to paste."""
    command = "There should be 7 product 1 in shelf 3."
    with FakeOpenAI([free_answer({"shelf3": {"product1": 9}})]) as server:
        paper = run(tmp_path, server, command, PAPER)
        assert len(server.requests) == 1
    assert paper.status == "succeeded", paper.error
    assert paper.outputs["goal"] == {"shelf3": {"product1": 9}} and paper.outputs["rounds"] == 1
    assert paper.outputs["loop"] == "pip-llm" and paper.outputs["reader"] == "model"
    assert sorted(p.name for p in (paper.record / "steps" / "refine" / "iterations" / "1").iterdir()) == \
        ["debug", "generate", "solve", "verify"]
    with FakeOpenAI([free_answer({"shelf3": {"product1": 9}}), free_answer({"shelf3": {"product1": 7}})]) as server:
        checked = run(tmp_path, server, command, CHECKED)
    assert checked.status == "succeeded", checked.error
    assert checked.outputs["rounds"] == 2 and checked.outputs["loop"] == "checked"
    lines = feedback_of(server.prompts()[1])
    assert lines == ["your goal's count of product1 on shelf3 is not what the command asks for "
                     "(the command's words: '7 product 1')"]


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


def test_doubts_from_the_command_words_are_warnings_never_feedback(tmp_path):
    """A command the offline parser does not read: the command's names and numbers are no
    reading, so the model's 5 where the command says 4 is not fed back (feedback would teach the
    model to restate numbers): it is accepted in round 1, and the run's outcome says what is
    doubtful."""
    command = "Hmm, shelf2 ought to have 4 product3 please, zorbly glimwise."
    state, why = agreement.offline_reading(command, WORLD)
    assert state == "unread", (state, why)  # this test needs a command the parser does not read
    with FakeOpenAI([grounded_answer({"shelf2": {"product3": 5}})]) as server:
        result = run(tmp_path, server, command, grounded=True, rounds=2)
        assert len(server.requests) == 1
    assert result.status == "succeeded", result.error
    assert result.outputs["rounds"] == 1
    warning = result.outputs["disagreement"]
    assert warning and warning[0].startswith("warning: accepted although the parser does not read the command")
    assert "number 4" in warning[0]


def test_the_repro_ends_with_the_right_goal_never_the_restated_wrong_one(tmp_path):
    """Issue 20's repro, scripted as reported: the right goal first (8 on shelf3), then a wrong one
    that restates the command's number (7) and names shelf4 at its count. The checked loop keeps
    the right goal (round 1: the words raise no doubt it could act on); a model that answers the
    wrong goal from the start gets it accepted only with a warning naming shelf4 (the paper's loop
    would accept it silently), and never because it restated anything."""
    assert agreement.offline_reading(REPRO, WORLD)[0] == "unread"
    with FakeOpenAI([free_answer(REPRO_RIGHT), free_answer(REPRO_WRONG)]) as server:
        result = run(tmp_path, server, REPRO)
        assert len(server.requests) == 1
    assert result.status == "succeeded", result.error
    assert result.outputs["goal"] == REPRO_RIGHT and result.outputs["disagreement"] == []
    with FakeOpenAI([free_answer(REPRO_WRONG)]) as server:
        wrong = run(tmp_path, server, REPRO)
    assert wrong.outputs["goal"] == {"shelf3": {"product1": 7}, "shelf4": {"product1": 15}}
    assert any("names shelf4" in w for w in wrong.outputs["disagreement"]), wrong.outputs["disagreement"]


def test_offline_first_reads_with_the_parser_and_asks_the_model_only_what_it_refuses(tmp_path):
    """reader=offline-first: a command the parser reads makes no model call (the record says the
    parser wrote the goal); one it does not read goes to the model, whose goal is executed when
    the command's words raise no doubt (the repro's right goal) and not executed, a clear failure,
    when they do (the repro's wrong goal, which leaves shelf4 unexplained)."""
    with FakeOpenAI([free_answer({"shelf3": {"product1": 9}})]) as server:
        read = run(tmp_path, server, "There should be 7 product 1 in shelf 3.", reader="offline-first")
        assert server.requests == []
    assert read.status == "succeeded" and read.outputs["goal"] == {"shelf3": {"product1": 7}}
    assert read.outputs["reader"] == "offline"
    with FakeOpenAI([free_answer(REPRO_RIGHT)]) as server:
        right = run(tmp_path, server, REPRO, reader="offline-first")
    assert right.status == "succeeded", right.error
    assert right.outputs["goal"] == REPRO_RIGHT and right.outputs["reader"] == "model"
    with FakeOpenAI([free_answer(REPRO_WRONG)]) as server:
        wrong = run(tmp_path, server, REPRO, reader="offline-first")
        assert len(server.requests) == 1
    assert wrong.status == "failed" and wrong.error_step == "check", wrong.error
    assert "not executed" in wrong.error and "shelf4" in wrong.error
    assert not (wrong.record / "steps" / "simulate").exists()
    with FakeOpenAI([free_answer({"shelf1": {"product1": 30}})]) as server:  # impossible: the parser's refusal stands
        refused = run(tmp_path, server, "shelf1 should hold 40 product1.", reader="offline-first")
        assert server.requests == []
    assert refused.status == "refused" and "capacity" in refused.error


@pytest.mark.parametrize("grounded", [False, True], ids=["free", "grounded"])
def test_the_checked_loop_never_puts_the_parsers_value_in_a_prompt(tmp_path, grounded):
    """A command whose count is arithmetic ("4 more" than shelf2's 5 product2: 9), with a robot
    rule. The model copies the command's 4, adds a change of its own and leaves the rule out; the
    feedback names each (which count, which change, which rule) and quotes the command, and no
    prompt of the run, as the run record keeps them, holds the parser's 9, its rule as an entry,
    or a goal entry to paste. The next answer, worked out by the model, is accepted."""
    command = "shelf2 should get 4 more product2. Robot 5 must not carry product1."
    state, reading = agreement.offline_reading(command, WORLD)
    assert state == "read" and reading["goal"] == {"shelf2": {"product2": 9}}  # the value to keep out
    assert not re.search(r"(?<![\w.])9(?![\w.])", command)
    rule = {"never": ["robot5"], "product": "product1"}
    if grounded:
        answers = [grounded_answer({"shelf2": {"product2": 4}, "shelf3": {"product4": 1}}),
                   grounded_answer({"shelf2": {"product2": 9}}, [{"mode": "never", "robots": {"names": ["robot5"]},
                                                                  "product": "product1", "from": "any", "to": "any",
                                                                  "words": "Robot 5 must not carry product1"}])]
    else:
        answers = [free_answer({"shelf2": {"product2": 4}, "shelf3": {"product4": 1}}),
                   free_answer({"shelf2": {"product2": 9}}, [rule])]
    with FakeOpenAI(answers) as server:
        result = run(tmp_path, server, command, grounded=grounded)
    assert result.status == "succeeded", result.error
    assert result.outputs["rounds"] == 2 and result.outputs["constraints"] == [rule]
    prompts = recorded_prompts(result.record)
    assert len(prompts) == 4  # system and user message of each round
    for text in prompts:
        assert not re.search(r"(?<![\w.])9(?![\w.])", text), text  # the parser's count, anywhere
        assert '"never": ["robot5"]' not in text  # nor its rule as an entry (the lines below: nor a goal entry)
    lines = feedback_of(prompts[3])
    assert lines == [
        "your goal's count of product2 on shelf2 is not what the command asks for (the command's words: "
        "'4 more product2')",
        "your goal changes product4 on shelf3, which the command does not ask for",
        "your rules leave out a rule the command states about which robots may move what (the command's "
        "words: 'Robot 5 must not carry product1')"]
    said = json.loads((result.record / "steps" / "refine" / "iterations" / "1" / "check" / "artifacts"
                       / "check.json").read_text())
    assert any("9 product2 on shelf2" in line for line in said["disagreement"])  # the record keeps the value


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
    rule and a count outside the bound are not, each named with the command's words and without
    the reading's value."""
    command = "Robot 5 must not carry product1. shelf2 should hold 9 product1"
    state, reading = agreement.offline_reading(command, WORLD)
    assert state == "read"
    rule = {"never": ["robot5"], "product": "product1", "words": "Robot 5 must not carry product1"}
    same = warehouse_agreement.second_opinion(command, WORLD, {"shelf2": {"product1": 9}, "shelf3": {"product4": 4}},
                                              [rule], None)
    assert same.disagreement == [] and same.refusal is None
    other = warehouse_agreement.second_opinion(command, WORLD, {"shelf2": {"product1": 9}, "shelf3": {"product4": 7}},
                                               [], None)
    assert other.firm and len(other.disagreement) == 2
    assert other.messages == ["your goal changes product4 on shelf3, which the command does not ask for",
                              "your rules leave out a rule the command states about which robots may move what "
                              "(the command's words: 'Robot 5 must not carry product1')"]
    bound = "shelf3 should hold at least 7 product1"
    assert warehouse_agreement.second_opinion(bound, WORLD, {"shelf3": {"product1": 8}}, [], None).disagreement == []
    low = warehouse_agreement.second_opinion(bound, WORLD, {"shelf3": {"product1": 6}}, [], None)
    assert low.messages == ["your goal's count of product1 on shelf3 is not what the command asks for "
                            "(the command's words: 'at least 7 product1')"]
    assert low.disagreement == ["the command asks for at least 7 product1 on shelf3; the model's goal says 6"]


def test_the_command_words_raise_doubts_that_restating_does_not_settle():
    """Where the parser does not read the command, the words only raise doubts (never feedback,
    never firm). The repro's right goal raises none: its 7 is the difference from shelf4's count,
    which it counts from. The wrong goal's restated shelf4 (kept at its count) does not make
    shelf4 used, and a goal that changes what the command does not name is doubtful too."""
    right = warehouse_agreement.second_opinion(REPRO, WORLD, REPRO_RIGHT, [], None)
    assert (right.basis, right.firm, right.disagreement, right.messages) == (agreement.WORDS, False, [], [])
    wrong = warehouse_agreement.second_opinion(REPRO, WORLD, REPRO_WRONG, [], None)
    assert not wrong.firm and wrong.messages == []
    assert wrong.disagreement == ["the command names shelf4; the goal neither changes it nor counts from it"]
    elsewhere = warehouse_agreement.doubts_from_words(REPRO, {"shelf3": {"product1": 8}, "shelf1": {"product2": 0}},
                                                      [], WORLD)
    assert elsewhere == ["the goal changes product2 on shelf1 (to 0), but the command names no shelf1 or product2"]


def test_a_refusal_is_final_only_when_the_command_makes_the_goal_impossible():
    impossible_goal = {"shelf3": {"product2": 30}}
    invented = warehouse_agreement.second_opinion("There should be 2 product2 in shelf3.", WORLD, impossible_goal, [],
                                                  "the command cannot be done in this world: only 10 product2 exist")
    assert invented.refusal is None and invented.disagreement
    agreed = warehouse_agreement.second_opinion("There should be 2 product2 in shelf3.", WORLD,
                                                {"shelf3": {"product2": 2}}, [],
                                                "the command cannot be done in this world: a reason")
    assert agreed.refusal == "the command cannot be done in this world: a reason"
    command = warehouse_agreement.second_opinion("shelf1 should hold 40 product1.", WORLD,
                                                 {"shelf1": {"product1": 30}}, [], None)
    assert command.refusal and "capacity" in command.refusal
    unread = "Hmm, shelf1 ought to hold 40 product1 please, zorbly glimwise."  # nothing tells whose it is
    refusal = "the command cannot be done in this world: over capacity"
    before = warehouse_agreement.second_opinion(unread, WORLD, {"shelf1": {"product1": 40}}, [], refusal)
    last = warehouse_agreement.second_opinion(unread, WORLD, {"shelf1": {"product1": 40}}, [], refusal, last=True)
    assert before.refusal is None and last.refusal == refusal


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


def _home(team: str) -> dict:
    from pipflow.household.world import load_world as load_home, select_team

    return select_team(load_home(REPO / "benchmarks" / "household" / "world.yaml"), team)


def _household_answers(home: dict, *goals: dict) -> list[str]:
    from pipflow.household.problem import write_problem as household_problem

    return [f"```pddl\n{household_problem(home, g)}\n```\n```json\n{{\"constraints\": []}}\n```" for g in goals]


def _household_run(tmp_path: Path, server: FakeOpenAI, workflow: str, command: str, team: str):
    return pipflow.run(REPO / "workflows" / workflow, command=command, team=team, model="openai/fake",
                       api_base=server.api_base, cache=False, runs_dir=tmp_path / "runs")


@pytest.mark.parametrize("workflow", ["household.yaml", "household-checked.yaml"])
def test_household_an_impossible_goal_the_model_invented_is_feedback(tmp_path, workflow):
    """The model adds "mug hot" (the mug is not heatable) to a command that can be done. In
    both loops not a refusal: the verifier's reason is feedback (and in the checked loop, that
    the goal is the answer's, not the command's), and the next answer runs."""
    home = _home("lifters-handler-cook")
    good = {"in": {"sink": ["mug", "plate"]}, "state": {"mug": ["clean"], "plate": ["clean"]}}
    hot = {"in": {"sink": ["mug", "plate"]}, "state": {"mug": ["clean", "hot"], "plate": ["clean"]}}
    with FakeOpenAI(_household_answers(home, hot, good)) as server:
        result = _household_run(tmp_path, server, workflow, "Put the dirty dishes in the sink and wash them.",
                                "lifters-handler-cook")
        prompts = server.prompts()
    assert result.status == "succeeded", result.error
    assert len(prompts) == 2
    lines = feedback_of(prompts[1])
    assert any("not heatable" in m for m in lines)
    if workflow == "household-checked.yaml":
        assert any("your answer's, not the command's" in m for m in lines)
        assert any("your goal makes the mug hot, which the command does not ask for" in m for m in lines)


def test_household_the_check_catches_the_missing_tomato(tmp_path):
    """"Put the apple and the tomato in the fridge." answered with the apple only: a valid problem
    that the paper's loop accepts in round 1 (the tomato stays out), and that the checked loop
    does not: its feedback names the tomato and quotes the command, without the place or a
    condition to paste; the answer with both is accepted."""
    command = "Put the apple and the tomato in the fridge."
    home = _home("homogeneous")
    apple = {"in": {"fridge": ["apple"]}, "state": {"fridge": ["closed"]}}
    both = {"in": {"fridge": ["apple", "tomato"]}, "state": {"fridge": ["closed"]}}
    with FakeOpenAI(_household_answers(home, apple)) as server:
        paper = _household_run(tmp_path, server, "household.yaml", command, "homogeneous")
    assert paper.status == "succeeded", paper.error
    assert paper.outputs["goal"]["in"] == {"fridge": ["apple"]} and paper.outputs["loop"] == "pip-llm"
    with FakeOpenAI(_household_answers(home, apple, both)) as server:
        checked = _household_run(tmp_path, server, "household-checked.yaml", command, "homogeneous")
        prompts = server.prompts()
    assert checked.status == "succeeded", checked.error
    assert checked.outputs["rounds"] == 2 and checked.outputs["loop"] == "checked"
    assert sorted(checked.outputs["goal"]["in"]["fridge"]) == ["apple", "tomato"]
    assert round_outputs(checked.record, 1, "check")["ok"] is False
    assert feedback_of(prompts[1]) == ["your goal does not put the tomato where the command asks "
                                       "(the command's words: 'put the apple and the tomato in the fridge')"]
    assert "(at tomato fridge)" not in prompts[1]


def test_household_second_opinion_names_what_differs_and_doubts_only_from_words():
    """The household check on its own: an object left out, another place, a state and a rule the
    command does not ask for are firm findings named without the reading's place or state; a
    condition that already holds is no difference; a command the translator does not read only
    raises doubts (never feedback), and restating a named thing settles them."""
    from pipflow.household import agreement as household_agreement

    home = _home("homogeneous")
    command = "Put the apple and the tomato in the fridge."
    state = agreement.remembered_reading(command, home, household_agreement._read, "household")[0]
    assert state == "read"
    fine = household_agreement.second_opinion(command, home, {"in": {"fridge": ["apple", "tomato"]},
                                                              "state": {"fridge": ["closed"], "apple": ["whole"]}},
                                              [], None)
    assert (fine.firm, fine.messages) == (False, [])  # "whole" holds already: a restatement
    off = household_agreement.second_opinion(command, home, {"in": {"fridge": ["apple"], "sink": ["tomato", "mug"]},
                                                             "state": {"fridge": ["open"]}},
                                             [{"never": ["robot1"]}], None)
    assert off.firm and off.messages == [
        "your goal does not put the tomato where the command asks (the command's words: "
        "'put the apple and the tomato in the fridge')",
        "your goal leaves out a condition the command asks of the fridge (the command's words: "
        "'Put the apple and the tomato in the fridge.')",
        "your goal moves the mug, which the command does not ask for",
        "your goal makes the fridge open, which the command does not ask for",
        "your rule 'never robot1' is not one the command states"]
    assert any("puts it in sink" in line for line in off.disagreement)  # the record keeps where
    unread = "Zorble the apple into the fridge pronto."
    doubt = household_agreement.second_opinion(unread, home, {"in": {"sink": ["mug"]}}, [], None)
    assert (doubt.basis, doubt.firm, doubt.messages) == (agreement.WORDS, False, [])
    assert doubt.disagreement == ["the command names the fridge; the goal says nothing of it",
                                  "the command names the apple; the goal says nothing of it"]


def test_offline_first_executes_no_model_reading_a_domain_cannot_check(tmp_path, monkeypatch):
    """A domain without a second opinion (a plugin may have none): in strict mode (offline-first)
    a model's reading of a command the parser does not read is not executed, since nothing can
    check it; without strict, only whether a refusal is final is decided, as before."""
    from pipflow import StepContext
    from pipflow.errors import TranslationError
    from pipflow.steps.llm import llm_check
    from pipflow.taskdomain import Capability
    from pipflow.warehouse.domain import WarehouseDomain

    offers = WarehouseDomain.supports  # the warehouse as a domain without the SecondOpinion capability
    monkeypatch.setattr(WarehouseDomain, "supports",
                        lambda self, capability: capability is not Capability.SECOND_OPINION and offers(self, capability))
    ctx = StepContext("check", tmp_path / "artifacts", base_dir=REPO)
    args = dict(command=REPRO, world=WORLD, goal=REPRO_WRONG, constraints=[], refusal=None, model="openai/fake",
                reader="model")
    assert llm_check.func(ctx, **args)["ok"] is True
    with pytest.raises(TranslationError, match="cannot check a model's reading"):
        llm_check.func(ctx, **args, strict=True)


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

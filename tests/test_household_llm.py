"""The LLM path of the household workflow: `llm.problem` on a household world renders
prompts/household_problem.j2, reads the model's problem (and its goal conditions back out of it),
and the debugger/verifier loop feeds precise messages to the next round.

Unit tests route the generator's calls through litellm's ``mock_response``; the last test runs
workflows/household.yaml against a REAL OpenAI-compatible server (llama-cpp-python's server with
SmolLM2-135M on loopback), which FAILS (never skips) when the server cannot start.
"""
from __future__ import annotations

import json
from pathlib import Path

import pytest

from conftest import local_model_server

from pipflow import StepContext
from pipflow.errors import InputError
from pipflow.household.domain import HouseholdDomain
from pipflow.language import asking, generator, llm
from pipflow.taskdomain import GOAL_PLACEHOLDER

ROOT = Path(__file__).resolve().parent.parent
WORLD = ROOT / "benchmarks" / "household" / "world.yaml"
DOMAIN = ROOT / "domains" / "household.pddl"
WORKFLOW = ROOT / "workflows" / "household.yaml"
COMMAND = "Put the apple in the fridge."


@pytest.fixture(scope="module")
def world():
    from pipflow.household.world import load_world, select_team

    return select_team(load_world(WORLD), "homogeneous")


def problem_for(world: dict, goal: dict) -> str:
    from pipflow.household.problem import write_problem

    return write_problem(world, goal)


def answer(problem: str, rules: str = '{"constraints": []}') -> str:
    return f"Here is the problem:\n```pddl\n{problem}```\n```json\n{rules}\n```\n"


GOOD_GOAL = {"in": {"fridge": ["apple"]}, "state": {"fridge": ["closed"]}}


def mock_answers(monkeypatch, answers: list[str]) -> list[list[dict]]:
    """The model answers ``answers`` in turn (the last one again when they run out), through
    litellm's mock_response; returns the messages of every call."""
    seen: list[list[dict]] = []

    def fake(messages, **kw):
        seen.append(messages)
        text = answers[min(len(seen), len(answers)) - 1]
        return llm.complete(messages, **{**kw, "extra": {**(kw.get("extra") or {}), "mock_response": text}})

    monkeypatch.setattr(asking, "complete", fake)
    return seen


def run_step(tmp_path: Path, world: dict, **args) -> tuple[dict, Path]:
    from pipflow.steps.llm import llm_problem

    art = tmp_path / "artifacts"
    ctx = StepContext("generate", art, base_dir=ROOT / "workflows")
    args = {"command": COMMAND, "world": world, "domain": str(DOMAIN), "model": "openai/mock",
            "cache_dir": str(tmp_path / "cache"), **args}
    return llm_problem.func(ctx, **args), art


def run_loop(tmp_path: Path, **inputs):
    """The workflow through the engine; callers use the ``engine_env`` fixture (a private working
    folder, so the response cache, and step cache), so no earlier answer is replayed."""
    from pipflow.engine.runner import run_workflow

    inputs = {"command": COMMAND, "team": "homogeneous", "model": "openai/mock", **inputs}
    return run_workflow(str(WORKFLOW), {k: str(v) for k, v in inputs.items()}, runs_dir=tmp_path / "runs",
                        inputs_from_text=True)


def iteration_file(result, n: int, step: str, name: str) -> Path:
    return Path(result.run_dir) / "steps" / "refine" / "iterations" / str(n) / step / name


def prompt_of(result, n: int) -> str:
    return json.loads(iteration_file(result, n, "generate", "artifacts/messages.json").read_text())[-1]["content"]


def outputs_of(result, n: int, step: str) -> dict:
    data = json.loads(iteration_file(result, n, step, "outputs.json").read_text())
    return data.get("outputs", data)


# ------------------------------------------------------------------------------ the prompt
def test_prompt_holds_command_world_facts_domain_and_example(tmp_path, monkeypatch, world):
    seen = mock_answers(monkeypatch, [answer(problem_for(world, GOOD_GOAL))])
    out, art = run_step(tmp_path, world)
    system, user = seen[0][0]["content"], seen[0][-1]["content"]
    assert "household command" in system
    assert user.endswith("Command: " + COMMAND)
    assert "(define (domain household)" in user                            # the domain text
    assert "- fridge: receptacle, openable; closed; category cold" in user  # places with state
    assert "- mug in diningtable: mass 1; pickupable, washable; dirty; category dish" in user
    assert "- fruit (home fridge): apple, watermelon" in user              # categories, homes
    assert "Robots: robot1, robot2, robot3." in user
    assert GOAL_PLACEHOLDER in user and "(at apple countertop)" in user  # the example's init
    assert "Your previous answer" not in user
    assert json.loads((art / "messages.json").read_text()) == out["messages"]


def test_good_answer_is_read_with_its_goal_and_rules(tmp_path, monkeypatch, world):
    rules = '{"constraints": [{"never": ["robot2"], "object": "apple", "to": "fridge"}]}'
    mock_answers(monkeypatch, [answer(problem_for(world, GOOD_GOAL), rules)])
    out, art = run_step(tmp_path, world)
    assert out["errors"] == [] and out["problem"].startswith("(define (problem task)")
    assert out["goal"] == {"in": {"fridge": ["apple"]}, "state": {"fridge": ["closed"]}}
    assert out["constraints"] == [{"never": ["robot2"], "object": "apple", "to": "fridge"}]
    assert json.loads((art / "goal.json").read_text()) == out["goal"]


def test_bad_rules_and_a_copied_example_are_precise_errors(tmp_path, monkeypatch, world):
    example = HouseholdDomain().example_problem(world, DOMAIN.read_text())
    mock_answers(monkeypatch, [answer(example, '{"constraints": [{"only": ["robot7"], "object": "banana"}]}')])
    out, _ = run_step(tmp_path, world)
    assert out["problem"] == "" and out["goal"] is None
    assert any("'robot7' is not a robot of this world; known: robot1, robot2, robot3" in e for e in out["errors"])
    assert any("(:goal ...) states no condition" in e for e in out["errors"])


def test_offline_dispatches_to_the_household_translator(tmp_path, world):
    out, art = run_step(tmp_path, world, model="offline", command="Put away the fruit.")
    assert out["goal"] == {"in": {"fridge": ["apple", "watermelon"]}, "state": {"fridge": ["closed"]}}
    assert out["concrete"] == out["goal"] and out["usage"]["calls"] == 0
    assert "(:domain household)" in out["problem"] and "(at watermelon fridge)" in out["problem"]
    assert (art / "problem.pddl").read_text() == out["problem"]


def test_grounded_household_is_a_clear_input_error(tmp_path, world):
    with pytest.raises(InputError, match="grounded decoding is not available for household"):
        run_step(tmp_path, world, grounded=True)


# ------------------------------------------------------------------------------ the loop
def test_good_answer_passes_the_loop_and_is_executed(engine_env, tmp_path, monkeypatch, world):
    mock_answers(monkeypatch, [answer(problem_for(world, GOOD_GOAL))])
    result = run_loop(tmp_path)
    assert result.status == "succeeded", result.error
    out = result.outputs
    assert out["rounds"] == 1 and out["goal"] == GOOD_GOAL
    assert [p["action"] for p in out["plan"]] == ["open", "store", "close"]
    assert out["goal_met"] is True and out["exe"] == 1.0


def test_bad_answers_get_precise_feedback_in_the_next_rounds_prompt(engine_env, tmp_path, monkeypatch, world):
    good = problem_for(world, GOOD_GOAL)
    arity = good.replace("    (at apple fridge)\n", "    (at apple)\n")          # wrong arity
    invented = good.replace("    (at apple fridge)\n", "    (at apple fridge2)\n")  # undeclared name
    declared = (good.replace(" - place\n", " fridge2 - place\n", 1)             # an invented object
                .replace("    (at apple countertop)\n", "    (at apple fridge2)\n"))  # and a wrong fact
    seen = mock_answers(monkeypatch, [answer(arity), answer(invented), answer(declared), answer(good)])
    result = run_loop(tmp_path)
    assert result.status == "succeeded", result.error
    assert result.outputs["rounds"] == 4 and len(seen) == 4
    assert "Your previous answer" not in prompt_of(result, 1)
    second, third, fourth = prompt_of(result, 2), prompt_of(result, 3), prompt_of(result, 4)
    assert "wrong arity in '(at apple)': at takes 2 argument(s) (at ?e - entity ?p - place), not 1" in second
    assert "undefined name 'fridge2': it is not an object of the problem; did you mean 'fridge'?" in third
    assert "object 'fridge2' (place) is not in the world; did you mean 'fridge'?" in fourth
    assert "the initial state lacks (at apple countertop), which holds in the world: add it to :init" in fourth
    assert "(at apple fridge2) is in :init but does not hold in the world" in fourth
    # the messages are exactly the previous round's debugger output
    for n, text in ((1, second), (2, third), (3, fourth)):
        debug = outputs_of(result, n, "debug")
        assert debug["ok"] is False and all(m in text for m in debug["messages"])


def test_no_problem_skips_the_debugger_and_the_loop_is_bounded(engine_env, tmp_path, monkeypatch):
    seen = mock_answers(monkeypatch, ["I would put the apple in the fridge."])
    result = run_loop(tmp_path, rounds=2)
    assert result.status == "failed" and "maximum of 2 iteration" in result.error, result.error
    assert len(seen) == 2
    assert "the answer contains no PDDL problem" in prompt_of(result, 2)
    assert outputs_of(result, 1, "debug")["ok"] is None  # skipped: nothing to debug


# ------------------------------------------------------------------------------ a real server
@pytest.fixture
def server():
    """The real model server with an 8k context (the household prompt is ~3.6k tokens)."""
    with local_model_server(n_ctx=8192) as (_, api_base):
        yield api_base


def test_household_workflow_with_a_real_model_is_bounded_and_ends_clearly(server, engine_env, tmp_path):
    result = run_loop(tmp_path, model="openai/smollm2", api_base=server, rounds=2, max_tokens=384,
                      command="Put away the fruit.")
    # whatever the 135M model writes: at most 2 rounds, and a clear end
    assert result.status in ("succeeded", "failed"), (result.status, result.error)
    rounds = sorted(p.name for p in (Path(result.run_dir) / "steps/refine/iterations").iterdir())
    assert rounds in (["1"], ["1", "2"])
    if result.status == "failed":
        assert "maximum of 2 iteration" in result.error, result.error
        assert rounds == ["1", "2"]
    first = outputs_of(result, 1, "generate")
    assert first["usage"]["prompt_tokens"] > 3000 and first["usage"]["completion_tokens"] > 0
    assert first["messages"][-1]["content"].endswith("Command: Put away the fruit.")
    assert (tmp_path / ".pipflow-cache" / "llm").is_dir()
    if len(rounds) == 2:
        # round 1's failures are round 2's feedback, word for word
        feedback = first["errors"] + (outputs_of(result, 1, "debug")["messages"] or [])
        second = prompt_of(result, 2)
        assert feedback and "Your previous answer was rejected" in second
        assert all(m in second for m in feedback[:12])

"""The language layer without a server: parsing, prompts, grounding, cache, retries (litellm's
``mock_response`` stands in for a provider here; tests/test_llm_server.py uses a real one)."""
from __future__ import annotations

import json
from pathlib import Path

import pytest
import yaml

from pipflow import StepContext
from pipflow.errors import InputError, LLMError
from pipflow.language import asking, generator
from pipflow.language import llm
from pipflow.warehouse import problem as pddl_writer
from pipflow.warehouse.language import grounding
from pipflow.warehouse.language.llm_orders import read_grounded
from pipflow.language.parsing import ParseIssue, extract_constraints, extract_problem, validate_constraints
from pipflow.language.prompting import render

REPO = Path(__file__).resolve().parents[1]
WORLD = yaml.safe_load((REPO / "benchmarks/warehouse/world.yaml").read_text())
DOMAIN = REPO / "domains/warehouse.pddl"
PROBLEM = """(define (problem p) (:domain warehouse)
  (:objects shelf3 - shelf product1 - product) ; a comment with a ) paren
  (:init (= (stock shelf3 product1) 5))
  (:goal (= (stock shelf3 product1) 7)))"""


def fake_writer(world: dict, goal: dict, **_names) -> str:
    """Stands in for pipflow.warehouse.problem.write_problem (the warehouse domain's writer): the goal, visibly."""
    return "(define (problem written) " + json.dumps(goal, sort_keys=True) + ")"


# --- parsing -------------------------------------------------------------------------------

def test_problem_is_cut_out_of_fences_and_prose():
    text = f"Sure! Here it is:\n```pddl\n{PROBLEM}\n```\nHope this helps (really)."
    assert extract_problem(text) == PROBLEM


def test_last_complete_problem_wins_and_cut_off_problem_is_reported_with_its_line():
    draft = PROBLEM.replace("7)))", "9)))")
    assert extract_problem(f"draft:\n{draft}\nfinal:\n{PROBLEM}").endswith("7)))")
    with pytest.raises(ParseIssue, match=r"line 2 .* cut off: 2 parentheses never closed"):
        extract_problem("Answer:\n" + PROBLEM[:-2])


def test_domain_instead_of_problem_is_named():
    with pytest.raises(ParseIssue, match="not a domain"):
        extract_problem("(define (domain warehouse))")


def test_constraints_from_json_fence_are_validated_against_the_world():
    text = 'x\n```json\n{"constraints": [{"never": ["robot0"], "product": "product1"}]}\n```'
    rules = validate_constraints(extract_constraints(text), WORLD)
    assert rules == [{"never": ["robot0"], "product": "product1"}]
    assert extract_constraints("no rules here") == []
    with pytest.raises(ParseIssue, match="'robot99' is not a robot"):
        validate_constraints([{"only": ["robot99"]}], WORLD)
    with pytest.raises(ParseIssue, match="exactly one of"):
        extract_constraints('```json\n[{"only": ["robot1"], "never": ["robot2"]}]\n```')
    with pytest.raises(ParseIssue, match="not valid JSON"):
        extract_constraints('```json\n{"constraints": [\n```')


def test_model_output_is_never_executed(tmp_path):
    marker = tmp_path / "pwned"
    text = f'```json\n__import__("pathlib").Path("{marker}").touch()\n```\n(define (problem x))'
    with pytest.raises(ParseIssue):
        extract_constraints(text)
    assert extract_problem(text) == "(define (problem x))"
    assert not marker.exists()


# --- prompts -------------------------------------------------------------------------------

def _vars(**over):
    v = {"command": "shelf4 has a dozen product3", "world": WORLD, "domain": DOMAIN.read_text(),
         "feedback": [], "grounded": False, "example": None}
    v.update(over)
    return v


def test_both_prompt_variants_render_world_domain_command_and_feedback():
    for name in ("warehouse_problem", "warehouse_problem_cot"):
        system, user = render(name, _vars(feedback=["unknown object prodcut3"]))
        assert system["role"] == "system" and user["role"] == "user"
        content = user["content"]
        assert "(define (domain warehouse)" in content and "shelf4 has a dozen product3" in content
        assert "shelf1: 10 product1, 2 product2, 3 product3" in content
        assert "unknown object prodcut3" in content


def test_strict_undefined_names_the_missing_variable(tmp_path):
    (tmp_path / "bad.j2").write_text("{% block user %}{{ comand }}{% endblock %}")
    with pytest.raises(InputError, match="bad.j2.*'comand' is undefined"):
        render("bad.j2", _vars(), base_dir=tmp_path)
    with pytest.raises(InputError, match="not found; built-in templates: .*warehouse_problem"):
        render("nope", _vars())


def test_templates_are_sandboxed(tmp_path):
    (tmp_path / "evil.j2").write_text("{{ command.__class__.__mro__[1].__subclasses__() }}")
    with pytest.raises(InputError, match="unsafe|not safely|access"):
        render("evil.j2", _vars(), base_dir=tmp_path)


# --- grounding -----------------------------------------------------------------------------

def test_schema_and_grammar_hold_only_world_names_and_counts():
    schema = grounding.json_schema(WORLD)
    statement = schema["properties"]["statements"]["items"]["anyOf"][0]["properties"]
    names = statement["items"]["anyOf"][0]["properties"]["names"]["items"]
    assert names["enum"] == ["product1", "product2", "product3", "product4"]
    assert statement["amount"]["anyOf"][0]["properties"]["count"]["maximum"] >= 30
    g = grounding.gbnf(WORLD)
    assert '"\\"product3\\""' in g and "prodcut3" not in g


def test_grammar_compiles_in_llama_cpp():
    from llama_cpp import LlamaGrammar

    LlamaGrammar.from_string(grounding.gbnf(WORLD), verbose=False)


def test_grounded_answer_becomes_goal_and_constraints():
    """The order form (tests/test_grounded_orders.py has more), and the earlier goal-triple form."""
    order = {"statements": [{"op": "set", "places": {"names": ["shelf4"]}, "items": {"names": ["product3"]},
                             "amount": {"count": 14}, "words": "14 product3 on shelf4"}],
             "rules": [{"mode": "never", "robots": {"names": ["robot0"]}, "product": "product1",
                        "from": "any", "to": "any", "words": "not robot0"}]}
    got = read_grounded(json.dumps(order), WORLD)
    assert got["goal"] == {"shelf4": {"product3": 14}}
    assert got["constraints"] == [{"never": ["robot0"], "product": "product1"}]
    legacy = json.dumps({"goal": [{"shelf": "shelf4", "product": "product3", "units": 14}],
                         "constraints": [{"rule": "never", "robots": ["robot0"], "product": "product1",
                                          "from": "any", "to": "any"}]})
    assert read_grounded(legacy, WORLD)["goal"] == got["goal"]
    with pytest.raises(ParseIssue, match='"prodcut3" is not a product of this world'):
        read_grounded('{"goal": [{"shelf": "shelf4", "product": "prodcut3", "units": 1}]}', WORLD)
    with pytest.raises(ParseIssue, match="not complete JSON"):
        read_grounded('{"statements": [{"op": "se', WORLD)


# --- calls, retries, secrets ---------------------------------------------------------------

def test_rate_limits_are_retried_with_backoff_then_fail_clearly():
    slept: list[float] = []
    with pytest.raises(LLMError, match="RateLimitError after 3 attempts"):
        llm.complete([{"role": "user", "content": "hi"}], model="gpt-4o-mini",
                     extra={"mock_response": "litellm.RateLimitError"}, retry=llm.Retry(retries=2, sleep=slept.append))
    assert slept == [1.0, 2.0]


def test_api_keys_never_appear_in_errors(monkeypatch):
    monkeypatch.setenv("SOMEPROVIDER_API_KEY", "sk-very-secret-value")
    with pytest.raises(LLMError) as info:
        llm.complete([{"role": "user", "content": "hi"}], model="gpt-4o-mini", retry=llm.Retry(retries=0),
                     extra={"mock_response": Exception("denied for sk-very-secret-value")})
    assert "sk-very-secret-value" not in str(info.value) and "***" in str(info.value)


def test_pipflow_model_overrides_only_the_default(monkeypatch):
    monkeypatch.setenv("PIPFLOW_MODEL", "openai/gpt-4o")
    assert llm.resolve_model(None) == "openai/gpt-4o"
    assert llm.resolve_model("ollama/llama3") == "ollama/llama3"
    monkeypatch.delenv("PIPFLOW_MODEL")
    assert llm.resolve_model(None) == "offline"


def test_usage_sums_and_unknown_cost_stays_unknown():
    total = llm.sum_usage([{"total_tokens": 10, "cost_usd": 0.5, "latency_s": 1},
                           {"total_tokens": 5, "cost_usd": None, "cached": True}])
    assert total["total_tokens"] == 15 and total["cost_usd"] is None and total["cached"] == 1


# --- the step, with a mocked provider ------------------------------------------------------

def mock_provider(monkeypatch, answer: str) -> list[dict]:
    """Route the generator's calls through litellm's mock_response; return the calls seen."""
    calls: list[dict] = []

    def fake(messages, **kw):
        calls.append(kw)
        return llm.complete(messages, **{**kw, "extra": {**(kw.get("extra") or {}),
                                                         "mock_response": answer}})

    monkeypatch.setattr(asking, "complete", fake)
    monkeypatch.setattr(pddl_writer, "write_problem", fake_writer)
    return calls


def run_step(tmp_path: Path, **args) -> tuple[dict, Path]:
    from pipflow.steps.llm import llm_problem

    art = tmp_path / "artifacts"
    ctx = StepContext("generate", art, base_dir=REPO / "workflows")
    args = {"command": "There should be 7 product 1 in shelf 3.", "world": WORLD,
            "domain": str(DOMAIN), "model": "gpt-4o-mini", "cache_dir": str(tmp_path / "cache"),
            **args}
    return llm_problem.func(ctx, **args), art


def test_step_parses_saves_artifacts_and_replays_from_cache(tmp_path, monkeypatch):
    answer = f"Here:\n```pddl\n{PROBLEM}\n```\n```json\n{{\"constraints\": []}}\n```"
    calls = mock_provider(monkeypatch, answer)
    out, art = run_step(tmp_path)
    assert out["problem"] == PROBLEM and out["constraints"] == [] and out["errors"] == []
    assert out["usage"]["total_tokens"] > 0 and out["usage"]["cached"] is False
    assert json.loads((art / "messages.json").read_text()) == out["messages"]
    assert (art / "response.txt").read_text() == answer
    again, _ = run_step(tmp_path)
    assert len(calls) == 1 and again["response"] == answer and again["usage"]["cached"] is True
    run_step(tmp_path, cache=False)
    assert len(calls) == 2
    fixed, _ = run_step(tmp_path, feedback=["(:goal) names unknown object prodcut3"])
    assert len(calls) == 3  # the feedback is in the prompt, so the key is new
    assert "unknown object prodcut3" in fixed["messages"][-1]["content"]


def test_step_turns_garbage_into_precise_feedback(tmp_path, monkeypatch):
    mock_provider(monkeypatch, "I like bread.")
    out, _ = run_step(tmp_path)
    assert out["problem"] == "" and out["errors"][0].startswith("the answer contains no PDDL problem")


def test_grounded_step_sends_schema_and_writes_problem_from_answer(tmp_path, monkeypatch):
    answer = json.dumps({"goal": [{"shelf": "shelf3", "product": "product1", "units": 7}],
                         "constraints": []})
    calls = mock_provider(monkeypatch, answer)
    out, _ = run_step(tmp_path, grounded=True)
    assert calls[0]["extra"]["response_format"]["type"] == "json_schema"
    assert out["goal"] == {"shelf3": {"product1": 7}}
    assert out["problem"] == fake_writer(WORLD, {"shelf3": {"product1": 7}})
    run_step(tmp_path, grounded=True, api_base="http://127.0.0.1:9/v1", model="openai/x")
    assert "grammar" in calls[1]["extra"]["extra_body"]


def test_offline_model_uses_translator_and_writer(tmp_path, monkeypatch):
    import sys
    import types

    fake = types.ModuleType("pipflow.warehouse.language.translator")
    fake.understand = lambda command, world: {"goal": {"shelf3": {"product1": 7}}, "constraints": [],
                                              "order": {"statements": [], "rules": []}, "explanation": []}
    monkeypatch.setitem(sys.modules, "pipflow.warehouse.language.translator", fake)
    monkeypatch.setattr(pddl_writer, "write_problem", fake_writer)
    out, art = run_step(tmp_path, model="offline")
    assert out["goal"] == {"shelf3": {"product1": 7}} and out["usage"]["calls"] == 0
    assert out["problem"] == fake_writer(WORLD, out["goal"])

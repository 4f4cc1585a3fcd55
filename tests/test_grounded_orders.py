"""The LLM path targets the same order as the offline parser (issue 12, item 6).

Grounded mode asks the model for an order whose names are the world's (a JSON schema for
providers with structured output, a GBNF grammar for llama.cpp servers); the answer is checked
against ``schemas/order.schema.json`` and the world, resolved, and written as PDDL by the problem
writer. The paper's mode reads the goal of the model's PDDL back into an order. Driven through a
scripted OpenAI-compatible server on loopback and the real workflow (ENHSP, SCIP, pybullet), and
once through a REAL local model (llama.cpp's server with SmolLM2).
"""
from __future__ import annotations

import copy
import json
from pathlib import Path

import jsonschema
import pytest

from conftest import local_model_server

import pipflow
from fake_openai import FakeOpenAI
from pipflow import StepContext
from pipflow.warehouse.language import grounding
from pipflow.warehouse.language.llm_orders import explain_goal, read_grounded
from pipflow.warehouse.language.order import order_schema, validate_order
from pipflow.language.parsing import ParseIssue
from pipflow.warehouse.problem import write_problem
from pipflow.warehouse.world import load_world

REPO = Path(__file__).resolve().parents[1]
WAREHOUSE = REPO / "workflows" / "warehouse.yaml"
DOMAIN = REPO / "domains" / "warehouse.pddl"
WORLD = load_world(REPO / "benchmarks" / "warehouse" / "world.yaml")
# a world of our own, with robot kinds and tags, for the names the schema must list
KINDS = copy.deepcopy(WORLD)
for _name, _robot in KINDS["robots"].items():
    _robot["kind"] = "forklift" if _robot["skills"].get("carry", 1) >= 2 else "tugger"
    _robot["tags"] = ["night"] if _name.endswith(("1", "3")) else []


def sel(*names: str) -> dict:
    return {"names": list(names)}


def statement(op: str, words: str, **keys) -> dict:
    return {"op": op, **keys, "words": words}


def rule(mode: str, robots: dict, words: str, product: str = "any", src: str = "any", dst: str = "any") -> dict:
    return {"mode": mode, "robots": robots, "product": product, "from": src, "to": dst, "words": words}


HAND_ORDERS = [
    {"statements": [statement("set", "7 product1 on shelf3", places=sel("shelf3"), items=sel("product1"),
                              amount={"count": 7})], "rules": []},
    {"statements": [statement("transfer", "move all product4 from shelf4 to shelf1", items=sel("product4"),
                              amount={"all": True}, **{"from": sel("shelf4"), "to": sel("shelf1")}),
                    statement("change", "two more of everything except product2 on shelf2", places=sel("shelf2"),
                              items={"all": True, "except": ["product2"]}, amount={"more": 2})],
     "rules": [rule("never", {"kind": "forklift"}, "no forklift for product1", product="product1")]},
    {"statements": [statement("bound", "at most 9 product3 on shelf1", places=sel("shelf1"), items=sel("product3"),
                              amount={"at_most": 9}),
                    statement("swap", "swap shelf2 and shelf3", places=sel("shelf2", "shelf3"))],
     "rules": [rule("only", {"tag": "night"}, "only the night robots"),
               rule("only", {"extreme": "max", "skill": "carry"}, "the strongest to shelf4", dst="shelf4")]},
]


def test_schema_from_the_world_validates_orders_and_rejects_wrong_names():
    schema = grounding.json_schema(KINDS)
    validator = jsonschema.Draft202012Validator(schema)
    jsonschema.Draft202012Validator.check_schema(schema)
    for order in HAND_ORDERS:
        validator.validate(order)
        # what the model may say is an order of the shared form once "any" scopes are dropped
        validate_order(read_grounded(json.dumps(order), KINDS)["order"])
    wrong = [("statements", 0, "places", "names", 0, "shelf9"), ("statements", 0, "items", "names", 0, "prodcut1")]
    for *path, name in wrong:
        order = copy.deepcopy(HAND_ORDERS[0])
        node = order
        for key in path[:-1]:
            node = node[key]
        node[path[-1]] = name
        assert not validator.is_valid(order), name
    robot_kind = copy.deepcopy(HAND_ORDERS[1])
    robot_kind["rules"][0]["robots"] = {"kind": "crane"}  # no crane in this world
    assert not validator.is_valid(robot_kind)
    # the paper's world has no kinds or tags: the schema offers none (an enum is never empty)
    plain = json.dumps(grounding.json_schema(WORLD))
    assert '"kind"' not in plain and '"tag"' not in plain and '"forklift"' in json.dumps(schema)
    with pytest.raises(jsonschema.ValidationError):
        jsonschema.validate(HAND_ORDERS[1], grounding.json_schema(WORLD))


def test_grammar_compiles_in_llama_cpp_and_names_only_the_worlds_words():
    from llama_cpp import LlamaGrammar

    g = grounding.gbnf(KINDS)
    LlamaGrammar.from_string(g, verbose=False)
    assert '"\\"forklift\\""' in g and '"\\"night\\""' in g and '"\\"shelf4\\""' in g
    assert "prodcut" not in g and "crane" not in g
    assert len(g) < 4000  # small enough for llama.cpp to compile at every request


def test_names_the_world_lacks_are_feedback_that_says_where_and_what_to_write():
    order = copy.deepcopy(HAND_ORDERS[1])
    order["statements"][1]["places"] = sel("shelf_2")
    order["rules"][0]["robots"] = {"kind": "crane"}
    with pytest.raises(ParseIssue) as info:
        read_grounded(json.dumps(order), KINDS)
    msg = str(info.value)
    assert 'statement 2 ("two more of everything except product2 on shelf2") "places": "shelf_2" is not a place' in msg
    assert '"shelf2"' in msg and '"crane" is not a robot kind of this world' in msg and '"forklift"' in msg
    with pytest.raises(ParseIssue, match="statements/0/amount"):
        read_grounded(json.dumps({"statements": [statement("set", "x", places=sel("shelf1"), items=sel("product1"),
                                                           amount={"count": -2})], "rules": []}), WORLD)
    with pytest.raises(ParseIssue, match="cannot be carried out.*shelf1"):  # the resolver's own refusal
        read_grounded(json.dumps({"statements": [statement("transfer", "move 40 product1 from shelf1 to shelf2",
                                                           items=sel("product1"), amount={"count": 40},
                                                           **{"from": sel("shelf1"), "to": sel("shelf2")})],
                                  "rules": []}), WORLD)


def test_an_order_resolves_to_goal_rules_and_arithmetic():
    got = read_grounded(json.dumps(HAND_ORDERS[1]), KINDS)
    stock = KINDS["stock"]
    assert got["goal"]["shelf1"]["product4"] == stock["shelf1"].get("product4", 0) + stock["shelf4"]["product4"]
    assert got["goal"]["shelf4"]["product4"] == 0
    assert got["goal"]["shelf2"]["product1"] == stock["shelf2"]["product1"] + 2
    assert "product2" not in got["goal"]["shelf2"]
    forklifts = sorted(n for n, r in KINDS["robots"].items() if r["kind"] == "forklift")
    assert got["constraints"] == [{"never": sorted(forklifts, key=list(KINDS["robots"]).index), "product": "product1"}]
    assert any("+2" in line and "two more" in line for line in got["explanation"])


@pytest.fixture
def env(engine_env, monkeypatch):
    monkeypatch.setenv("OPENAI_API_KEY", "sk-test-not-a-real-key-000")
    monkeypatch.delenv("PIPFLOW_MODEL", raising=False)
    return engine_env


COMMAND = "Move 3 product1 from shelf1 to shelf2."
ORDER = {"statements": [statement("transfer", "Move 3 product1 from shelf1 to shelf2", items=sel("product1"),
                                  amount={"count": 3}, **{"from": sel("shelf1"), "to": sel("shelf2")})],
         "rules": []}
GOAL = {"shelf1": {"product1": WORLD["stock"]["shelf1"]["product1"] - 3},
        "shelf2": {"product1": WORLD["stock"]["shelf2"]["product1"] + 3}}


def run(tmp_path: Path, server: FakeOpenAI, command: str = COMMAND, **inputs):
    return pipflow.run(WAREHOUSE, command=command, model="openai/fake", api_base=server.api_base,
                       cache=False, runs_dir=tmp_path / "runs", **inputs)


def outputs(record: Path, n: int, step: str) -> dict:
    data = json.loads((record / "steps" / "refine" / "iterations" / str(n) / step / "outputs.json").read_text())
    return data.get("outputs", data)


def test_a_model_answering_an_order_drives_the_workflow_to_the_resolved_goal(env, tmp_path):
    with FakeOpenAI([json.dumps(ORDER)]) as server:
        result = run(tmp_path, server, grounded=True)
        body = server.requests[0]
    assert result.status == "succeeded", result.error
    assert result.outputs["goal"] == GOAL and result.outputs["goal_met"] is True
    assert result.outputs["rounds"] == 1
    assert any("-3 moved out" in line and "Move 3 product1" in line for line in result.outputs["understood"])
    generated = outputs(result.record, 1, "generate")
    assert generated["order"]["statements"][0]["op"] == "transfer"
    # a self-hosted server gets the order grammar; the prompt shows the order form with this world's names
    assert "stmt ::=" in json.dumps(body) and '\\"statements\\"' in json.dumps(body)
    assert '"op": "set", "places": {"names": ["shelf1"]}' in server.prompts()[0]


def test_an_invalid_order_is_feedback_about_the_order_and_the_next_round_succeeds(env, tmp_path):
    bad = copy.deepcopy(ORDER)
    bad["statements"][0]["from"] = sel("shelf 1")
    with FakeOpenAI([json.dumps(bad), json.dumps(ORDER)]) as server:
        result = run(tmp_path, server, grounded=True)
        prompts = server.prompts()
    assert result.status == "succeeded", result.error
    assert result.outputs["rounds"] == 2 and result.outputs["goal"] == GOAL
    first = outputs(result.record, 1, "generate")
    assert first["problem"] == "" and '"shelf 1" is not a place of this world' in first["errors"][0]
    assert 'statement 1 ("Move 3 product1 from shelf1 to shelf2") \\"from\\"' in json.dumps(prompts[1]) \
        or 'statement 1 ("Move 3 product1 from shelf1 to shelf2") "from"' in prompts[1]
    assert "(define" not in first["errors"][0]  # feedback in the answer's form, not PDDL's


def test_the_papers_mode_reads_its_goal_back_into_an_order(env, tmp_path):
    answer = f"```pddl\n{write_problem(WORLD, GOAL)}\n```\n```json\n{{\"constraints\": [{{\"never\": [\"robot0\"]}}]}}\n```"
    with FakeOpenAI([answer]) as server:
        result = run(tmp_path, server, command=COMMAND + " Robot 0 should not be used.")
    assert result.status == "succeeded", result.error
    generated = outputs(result.record, 1, "generate")
    sets = {(s["places"]["names"][0], s["items"]["names"][0]): s["amount"]["count"]
            for s in generated["order"]["statements"] if s["op"] == "set"}
    assert sets == {("shelf1", "product1"): GOAL["shelf1"]["product1"], ("shelf2", "product1"): GOAL["shelf2"]["product1"]}
    validate_order(generated["order"])
    assert any("(= (stock shelf2 product1) 11)" in line for line in result.outputs["understood"])
    assert any("robot0: never" in line for line in result.outputs["understood"])


def test_bounds_in_a_pddl_goal_become_bound_statements():
    got = explain_goal({"shelf3": {"product2": {"at_least": 4, "at_most": 6}}}, [], WORLD)
    [s] = got["order"]["statements"]
    assert s["op"] == "bound" and s["amount"] == {"at_least": 4, "at_most": 6}
    assert got["explanation"][0].startswith("shelf3 product2: 3 now, >= 4 and <= 6")


# --- the REAL local model ------------------------------------------------------------------------

@pytest.fixture
def server():
    """The real model server (tests/conftest.py); yields the API base."""
    with local_model_server() as (_, api_base):
        yield api_base


def test_a_real_model_in_grounded_mode_answers_an_order_of_the_schema(server, tmp_path, monkeypatch):
    """Whatever SmolLM2 means (a 135M model is usually wrong), the grammar makes its answer an
    order: JSON of the order schema with only the world's names. One short command, bounded tokens."""
    from pipflow.steps.llm import llm_problem

    monkeypatch.setenv("OPENAI_API_KEY", "sk-local")
    ctx = StepContext("generate", tmp_path / "art", base_dir=REPO / "workflows")
    out = llm_problem.func(ctx, command="Put 3 product1 on shelf2.", world=WORLD, domain=str(DOMAIN),
                           model="openai/smollm2", api_base=server, grounded=True, max_tokens=400,
                           timeout=240, retries=0, cache=False)
    data = json.loads(out["response"])  # complete JSON: the grammar bounds every part of the answer
    jsonschema.validate(data, grounding.json_schema(WORLD))
    order = {**data, "rules": [{k: v for k, v in r.items() if v != "any"} for r in data["rules"]]}
    jsonschema.validate(order, order_schema())
    if not out["errors"]:  # the order resolved: the problem was written from it
        assert out["problem"].lstrip().startswith("(define") and out["order"]["statements"] == order["statements"]
    else:  # it did not: the feedback is about the order, never about PDDL
        assert all("(define" not in e for e in out["errors"])

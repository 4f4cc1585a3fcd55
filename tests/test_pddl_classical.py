"""A classical domain solved by the engine the workflow names: Fast Downward through UP, its plan
checked by the verifier (``pddl.solve`` is not tied to numeric domains or to ENHSP)."""
from __future__ import annotations

from pathlib import Path

from pipflow.engine.registry import default_registry
from pipflow.engine.step import StepContext

FIXTURES = Path(__file__).resolve().parent / "fixtures" / "classical"


def test_fast_downward_solves_a_classical_problem_and_the_plan_validates(tmp_path):
    solve, verify = default_registry().get("pddl.solve"), default_registry().get("pddl.verify")
    ctx = StepContext("solve", tmp_path / "artifacts", FIXTURES)
    problem = (FIXTURES / "problem.pddl").read_text()
    out = solve.func(ctx, problem=problem, domain="domain.pddl", engine="fast-downward", timeout=60, fallback="")
    assert out["status"] == "solved", out["message"]
    plan = out["plan"]
    assert len(plan) == 3  # a: hall->kitchen->store, b: kitchen->hall (the fewest carries)
    assert {step["action"] for step in plan} == {"carry"}
    checked = verify.func(ctx, problem=problem, domain="domain.pddl", plan=plan, world=None)
    assert checked["ok"], checked["messages"]

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


def test_a_loop_that_finds_no_plan_quotes_the_planners_reason(tmp_path):
    """A refinement loop that runs out of rounds because the planner found no plan names the
    planner's own reason in its error, not only what the steps after it said."""
    from pipflow.engine import run_workflow

    unreachable = (FIXTURES / "problem.pddl").read_text().replace("(connected store kitchen)", "")
    unreachable = unreachable.replace("(connected kitchen store)", "")
    (tmp_path / "problem.pddl").write_text(unreachable)
    (tmp_path / "domain.pddl").write_text((FIXTURES / "domain.pddl").read_text())
    (tmp_path / "wf.yaml").write_text(
        "pipflow: 1\nname: noplan\nsteps:\n  - id: refine\n    loop:\n      max: 2\n      until: ${solve.plan}\n"
        "      on_max: fail\n      steps:\n        - id: solve\n          uses: pddl.solve\n"
        "          with: {problem: \"${'" + unreachable.replace("\n", " ").replace("'", "") + "'}\", "
        "domain: domain.pddl, engine: fast-downward, timeout: 60}\n")
    result = run_workflow(tmp_path / "wf.yaml", runs_dir=tmp_path / "runs")
    assert result.status == "failed"
    assert "round 2 ended with: solve: " in str(result.error)
    assert "fast-downward" in str(result.error) or "no plan" in str(result.error).lower()

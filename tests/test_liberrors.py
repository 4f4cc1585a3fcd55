"""Errors of unified-planning, SCIP and litellm arrive as pipflow's own errors, naming the library
and the cause; pipflow's own bugs are never dressed up as a library's (or the user's) error."""
from __future__ import annotations

from pathlib import Path

import pytest
import yaml

from pipflow import StepContext
from pipflow.errors import AllocationError, InputError, PDDLError
from pipflow.liberrors import LITELLM, SCIP, UNIFIED_PLANNING, library_errors, raised_in
from pipflow.pddl.common import parse
from pipflow.pddl.solver import Status, solve_problem

ROOT = Path(__file__).resolve().parent.parent
DOMAIN = (ROOT / "domains" / "warehouse.pddl").read_text()
HEAD = "(define (problem p) (:domain warehouse) "

BAD_PROBLEMS = {  # what UP's reader raises for each: pyparsing, SyntaxError, KeyError
    "cut off": (HEAD + "(:objects a - shelf", "ParseException"),
    "not PDDL": ("hello", "ParseException"),
    "unknown object": (HEAD + "(:objects s1 - shelf) (:init (= (stock zz s1) 3)) (:goal (and)))", "SyntaxError"),
    "unknown predicate": (HEAD + "(:objects s1 - shelf) (:init (foo s1)) (:goal (and)))", "SyntaxError"),
    "unknown type": (HEAD + "(:objects s1 - nosuchtype) (:init) (:goal (and)))", "KeyError"),
}


@pytest.mark.parametrize("case", sorted(BAD_PROBLEMS))
def test_a_malformed_problem_is_a_pddl_error_naming_unified_planning(case):
    text, kind = BAD_PROBLEMS[case]
    with pytest.raises(PDDLError) as info:
        with library_errors(UNIFIED_PLANNING, PDDLError, "reading the problem"):
            parse(DOMAIN, text)
    message = str(info.value)
    assert message.startswith(f"unified-planning failed while reading the problem: {kind}: "), message
    assert "\n" not in message
    assert type(info.value.__cause__).__name__ == kind  # the original stays chained for -v
    assert isinstance(info.value, InputError) and info.value.exit_code == 2


def test_our_own_bug_inside_the_block_is_not_translated():
    with pytest.raises(ZeroDivisionError):
        with library_errors(UNIFIED_PLANNING, PDDLError, "reading the problem"):
            1 / 0  # noqa: B018 - a bug in pipflow's code, not UP's
    with pytest.raises(KeyError):  # the same builtin type UP raises, but raised here
        with library_errors(UNIFIED_PLANNING, PDDLError, "reading the problem"):
            {}["shelf"]


def test_a_pipflow_error_raised_inside_passes_unchanged():
    with pytest.raises(InputError, match="^the world has no robots$"):
        with library_errors(SCIP, AllocationError, "allocating"):
            raise InputError("the world has no robots")


def test_a_real_scip_error_is_an_allocation_error_naming_scip():
    from pyscipopt import Model

    model = Model()
    model.hideOutput()
    model.addVar(vtype="B")
    with pytest.raises(AllocationError) as info:
        with library_errors(SCIP, AllocationError, "allocating with scip"):
            model.getObjVal()  # no solution yet: pyscipopt raises a bare Warning
    assert str(info.value).startswith("SCIP (pyscipopt) failed while allocating with scip: Warning: ")
    with pytest.raises(AllocationError, match=r"SCIP \(pyscipopt\) failed while .*: ValueError: SCIP: the value is invalid"):
        with library_errors(SCIP, AllocationError, "setting the time limit"):
            model.setParam("limits/time", 1e30)
    assert raised_in(info.value.__cause__) == "pyscipopt"


def test_a_real_up_engine_error_is_an_error_outcome_naming_unified_planning():
    problem = parse(DOMAIN, HEAD + "(:objects s1 - shelf) (:init) (:goal (and)))")
    result = solve_problem(problem, "enhsp", params={"no_such_option": 1}, timeout=30)
    assert result.status is Status.ERROR and result.plan is None
    assert result.message.startswith("unified-planning failed while running the planner enhsp: TypeError: "), result.message
    assert "no_such_option" in result.message


def test_a_bug_in_pipflows_own_engine_is_not_an_error_outcome(monkeypatch):
    """pipflow-transport is pipflow's code: its bug must keep its traceback, not read as the
    planner's failure (a bare except would have hidden it)."""
    import pipflow.warehouse.planner as transport

    def broken(problem):
        raise ZeroDivisionError("a bug in the transport planner")

    monkeypatch.setattr(transport, "instance_from_problem", broken)
    problem = parse(DOMAIN, HEAD + "(:objects s1 - shelf) (:init) (:goal (and)))")
    with pytest.raises(ZeroDivisionError, match="a bug in the transport planner"):
        solve_problem(problem, "pipflow-transport", timeout=30)


def test_a_scip_error_inside_pipflows_own_engine_is_an_error_outcome(monkeypatch):
    """pipflow-transport solves integer programs with SCIP: SCIP failing there is the engine's
    failure (an error outcome naming SCIP), not a bug of pipflow's."""
    import pipflow.warehouse.planner as transport
    from pyscipopt import Model

    def scip_fails(problem):
        Model().getObjVal()  # no solution: pyscipopt raises a bare Warning

    monkeypatch.setattr(transport, "instance_from_problem", scip_fails)
    problem = parse(DOMAIN, HEAD + "(:objects s1 - shelf) (:init) (:goal (and)))")
    result = solve_problem(problem, "pipflow-transport", timeout=30)
    assert result.status is Status.ERROR
    assert result.message.startswith("SCIP (pyscipopt) failed while running the planner pipflow-transport: Warning: ")


def test_the_solve_and_verify_steps_answer_a_malformed_problem_softly(tmp_path):
    import pipflow.steps.pddl as steps

    ctx = StepContext("t", tmp_path, ROOT / "workflows")
    text = BAD_PROBLEMS["unknown object"][0]
    solved = steps.solve.func(ctx, problem=text, domain="../domains/warehouse.pddl", engine="enhsp")
    assert solved["status"] == "error" and solved["plan"] is None
    assert "does not parse (unified-planning failed while reading the problem: SyntaxError: " in solved["message"]
    verified = steps.verify.func(ctx, problem=text, domain="../domains/warehouse.pddl")
    assert verified["ok"] is False and "unified-planning failed while reading the problem" in verified["messages"][0]


def test_a_litellm_error_belongs_to_litellm_and_ours_does_not():
    from pipflow.language.llm import _import_litellm

    litellm = _import_litellm()
    with pytest.raises(Exception) as info:
        litellm.completion(model="openai/x", messages=[{"role": "user", "content": "hi"}],
                           mock_response="litellm.RateLimitError")
    assert LITELLM.owns(info.value) and not SCIP.owns(info.value)
    try:
        raise ValueError("ours")
    except ValueError as ours:
        assert not LITELLM.owns(ours) and raised_in(ours) not in LITELLM.packages


def test_step_allocate_reports_scip_errors_as_allocation_errors(tmp_path, monkeypatch):
    """The allocate steps translate a SCIP failure at their boundary (a real pyscipopt error,
    provoked by a time limit SCIP refuses, reached past the allocator's own check)."""
    import pipflow.team.allocation as allocation
    from pipflow.steps.allocate import scip

    real = allocation._scip
    monkeypatch.setattr(allocation, "_scip", lambda quiet=True, time_limit=None: _refused(real()))
    world, graph = _one_subtask()
    ctx = StepContext("a", tmp_path, ROOT / "tests" / "fixtures" / "robot")
    with pytest.raises(AllocationError, match=r"^SCIP \(pyscipopt\) failed while allocating with scip: ValueError"):
        scip.func(ctx, graph=graph, world=world, linear=[{"robots": "all", "coef": 1, "sense": "<=", "rhs": 1}])


def _one_subtask() -> tuple[dict, dict]:
    world = yaml.safe_load((ROOT / "tests" / "fixtures" / "robot" / "world.yaml").read_text())
    node = {"id": "s1", "index": 0, "action": "move-product", "args": ["shelfA", "shelfC", "red", "m2"],
            "skills": {"carry": 2.0}, "route": ["shelfA", "shelfC"],
            "fields": {"product": "red", "from": "shelfA", "to": "shelfC"}}
    return world, {"mode": "exact", "nodes": [node], "edges": []}


def _refused(model):
    model.setParam("limits/time", 1e30)  # beyond SCIP's range: pyscipopt raises ValueError
    return model


def test_nonfinite_numbers_in_linear_rules_are_refused():
    from pipflow.team.allocation import allocate

    world, graph = _one_subtask()
    for bad in ({"rhs": float("nan")}, {"rhs": float("inf")}, {"rhs": 1, "coef": float("nan")},
                {"rhs": 1, "coef": {"r1": 1e25}}):
        with pytest.raises(InputError, match="finite"):
            allocate(graph, world, linear=[{"robots": "all", "sense": "<=", **bad}])
    with pytest.raises(InputError, match="time_limit"):
        allocate(graph, world, mode="frontier", time_limit=float("nan"))


def test_the_dependency_graph_refuses_a_malformed_problem_naming_unified_planning():
    from pipflow.team.dependency import build_graph

    text, kind = BAD_PROBLEMS["unknown predicate"]
    with pytest.raises(PDDLError, match=f"^unified-planning failed while parsing the domain and problem for the "
                                        f"dependency graph: {kind}: Not able to handle: \\(foo s1\\)"):
        build_graph(DOMAIN, text, [], {})

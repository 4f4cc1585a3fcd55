"""Team-level PDDL steps: debug, solve, verify (the paper's Debugger, planner and Verifier).

Thin faces of :mod:`pipflow.pddl`; UP is imported inside the functions. Each step accepts
``None`` for an input whose producing step was skipped or failed softly, and then answers
``ok=False`` / ``status="error"`` with a message instead of crashing.
"""
from __future__ import annotations

from pipflow import Input, StepContext, step

DEFAULT_ENGINE = "pipflow-transport"  # see pipflow/pddl/transport.py for why


def _parse(ctx: StepContext, problem: str, domain: str):
    from pipflow.pddl.common import parse

    return parse(ctx.resolve_path(domain), problem)


@step("pddl.debug",
      doc="Parse a problem against the domain and check it against the world; explain every failure (line, column, token, closest names).",
      inputs={"problem": Input("string", doc="PDDL problem text"),
              "domain": Input("path", doc="PDDL domain file"),
              "world": Input("object", default=None, doc="world dict; when given, objects and initial state must be the world's")},
      outputs={"ok": "boolean", "messages": "array", "problem": "string"})
def debug(ctx: StepContext, problem: str | None, domain: str, world: dict | None = None) -> dict:
    """``problem`` out is the text when it is clean, ``None`` otherwise (so the planner is skipped
    and the messages go back to the generator)."""
    from pipflow.pddl.debugger import debug_problem

    if problem is not None:
        ctx.write_artifact("problem.pddl", problem)
    report = debug_problem(problem, str(ctx.resolve_path(domain)), world)
    for m in report.messages:
        ctx.log(f"debug: {m}")
    return {"ok": report.ok, "messages": report.messages, "problem": problem if report.ok else None}


@step("pddl.solve",
      doc="Solve a problem with a UP engine; status is solved, unsolvable, timeout or error, each with its message.",
      inputs={"problem": Input("string", doc="PDDL problem text"),
              "domain": Input("path", doc="PDDL domain file"),
              "engine": Input("string", default=DEFAULT_ENGINE,
                              doc="UP engine: pipflow-transport (fast, near-fewest moves), enhsp, enhsp-opt, fast-downward, ..."),
              "params": Input("object", default=None, doc="engine parameters, e.g. {params: '-h hmax -s WAStar'} for ENHSP"),
              "timeout": Input("number", default=60, doc="seconds"),
              "fallback": Input("string", default="enhsp",
                                doc="engine to try when the first cannot handle the problem (unsupported, gave up); empty = none"),
              "world": Input("object", default=None,
                             doc="world dict: the plan's names are then spelled as the world spells them (PDDL reads them in lower case)"),
              "constraints": Input("array", default=None,
                                   doc="only/never robot rules: with the world, pipflow-transport keeps each move within what its allowed robots carry")},
      outputs={"status": "string", "plan": "array", "message": "string", "time": "number"})
def solve(ctx: StepContext, problem: str | None, domain: str, engine: str = DEFAULT_ENGINE,
          params: dict | None = None, timeout: float = 60, fallback: str = "enhsp", world: dict | None = None,
          constraints: list | None = None) -> dict:
    from pipflow.pddl.common import format_plan
    from pipflow.pddl.names import plan_in_world_names
    from pipflow.pddl.solver import solve_problem

    if not problem:
        return {"status": "error", "plan": None, "message": "no problem to solve (the debugger rejected it or it was not written)",
                "time": 0.0}
    try:
        parsed = _parse(ctx, problem, domain)
    except Exception as exc:
        return {"status": "error", "plan": None, "message": f"the problem does not parse ({exc}); run pddl.debug first",
                "time": 0.0}
    if engine == DEFAULT_ENGINE and world and world.get("robots"):
        robots = {name: r.get("skills", {}).get("carry", 0) for name, r in world["robots"].items()}
        params = {"robots": robots, "rules": constraints or [], **(params or {})}
    result = solve_problem(parsed, engine, params, timeout)
    message = result.message
    if result.status == "error" and fallback and fallback != engine:
        ctx.log(f"solve: {message}; trying {fallback}")
        second = solve_problem(parsed, fallback, None, timeout)
        message = f"{message}; fell back to {fallback}: {second.message}"
        result = second
    ctx.log(f"solve: {message}")
    ctx.metrics.update({"solve_time": result.time, "engine": result.engine,
                        "plan_length": len(result.plan) if result.plan else None})
    plan = plan_in_world_names(result.plan, world)
    if plan is not None:
        ctx.write_artifact("plan.txt", format_plan(plan))
    return {"status": result.status, "plan": plan, "message": message, "time": result.time}


@step("pddl.verify",
      doc="Validate the plan with UP's sequential plan validator and check the goal against the world; an infeasible goal yields a refusal reason.",
      inputs={"problem": Input("string", doc="PDDL problem text"),
              "domain": Input("path", doc="PDDL domain file"),
              "plan": Input("array", default=None, doc="plan from pddl.solve"),
              "world": Input("object", default=None, doc="world dict for the goal checks")},
      outputs={"ok": "boolean", "messages": "array", "refusal": "string", "goal": "object"})
def verify(ctx: StepContext, problem: str | None, domain: str, plan: list | None = None,
           world: dict | None = None) -> dict:
    """``refusal`` is a reason string when no plan can satisfy the goal in this world (more units
    than exist, over capacity), else None; ``goal`` is the problem's goal as {shelf: {product: n}}."""
    from pipflow.pddl.verifier import verify_plan

    if not problem:
        return {"ok": False, "messages": ["no problem to verify"], "refusal": None, "goal": {}}
    try:
        parsed = _parse(ctx, problem, domain)
    except Exception as exc:
        return {"ok": False, "messages": [f"the problem does not parse ({exc}); run pddl.debug first"],
                "refusal": None, "goal": {}}
    report = verify_plan(parsed, plan, world)
    for m in report.messages:
        ctx.log(f"verify: {m}")
    ctx.write_artifact("verify.json", {"ok": report.ok, "messages": report.messages,
                                       "refusal": report.refusal, "goal": report.goal})
    return {"ok": report.ok, "messages": report.messages, "refusal": report.refusal, "goal": report.goal}

"""Team-level PDDL steps: debug, solve, verify (the paper's Debugger, planner and Verifier).

Thin faces of :mod:`pipflow.pddl`; UP is imported inside the functions. Each step accepts
``None`` for an input whose producing step was skipped or failed softly, and then answers
``ok=False`` / ``status="error"`` with a message instead of crashing.
"""
from __future__ import annotations

from typing import Annotated

from pipflow import Doc, PathStr, StepContext, step
from pipflow.errors import PDDLError, PlanningError
from pipflow.liberrors import UNIFIED_PLANNING, library_errors
from pipflow.pddl.common import format_plan, parse
from pipflow.pddl.debugger import debug_problem
from pipflow.pddl.names import plan_in_world_names
from pipflow.pddl.solver import check_engine, problem_digest, remember, remembered, solve_problem
from pipflow.pddl.verifier import verify_plan
from pipflow.taskdomain import Capability
from pipflow.taskdomains import task_domain
from pipflow.values import DebugOutputs, SolveOutputs, VerifyOutputs

DEFAULT_ENGINE = "pipflow-transport"  # see pipflow/warehouse/planner.py for why


def _parse(ctx: StepContext, problem: str, domain: str):
    """The parsed problem; UP's complaint about the text arrives as :class:`PDDLError` (any other
    exception is a bug and is not dressed up as bad input)."""
    with library_errors(UNIFIED_PLANNING, PDDLError, "reading the problem"):
        return parse(ctx.resolve_path(domain), problem)


@step("pddl.debug",
      doc="Parse a problem against the domain and check it against the world; explain every failure (line, column, token, closest names).")
def debug(
    ctx: StepContext,
    problem: Annotated[str | None, Doc("PDDL problem text")],
    domain: Annotated[PathStr, Doc("PDDL domain file")],
    world: Annotated[dict | None, Doc("world dict; when given, objects and initial state must be the world's")] = None,
) -> DebugOutputs:
    """``problem`` out is the text when it is clean, ``None`` otherwise (so the planner is skipped
    and the messages go back to the generator)."""
    if problem is not None:
        ctx.write_artifact("problem.pddl", problem)
    report = debug_problem(problem, str(ctx.resolve_path(domain)), world)
    for m in report.messages:
        ctx.log(f"debug: {m}")
    return {"ok": report.ok, "messages": report.messages, "problem": problem if report.ok else None}


@step("pddl.solve",
      doc="Solve a problem with a UP engine; status is solved, unsolvable or error, each with its message; a time-out fails the step.",
      version="2")  # 2: requested and fallback (cached answers of version 1 lack them)
def solve(
    ctx: StepContext,
    problem: Annotated[str | None, Doc("PDDL problem text")],
    domain: Annotated[PathStr, Doc("PDDL domain file")],
    engine: Annotated[str, Doc("UP engine: pipflow-transport (fast, near-fewest moves), enhsp, enhsp-opt, "
                               "fast-downward, ...")] = DEFAULT_ENGINE,
    params: Annotated[dict | None, Doc("engine parameters, e.g. {params: '-h hmax -s WAStar'} for ENHSP")] = None,
    timeout: Annotated[float, Doc("seconds")] = 60,
    fallback: Annotated[str | None, Doc("engine to try when the first cannot handle the problem (unsupported, "
                                        "gave up, timed out); unset: none. The outputs name the engine that "
                                        "answered")] = None,
    world: Annotated[dict | None, Doc("world dict: the plan's names are then spelled as the world spells them "
                                      "(PDDL reads them in lower case)")] = None,
    constraints: Annotated[list | None, Doc("only/never robot rules: with the world, pipflow-transport keeps "
                                            "each move within what its allowed robots carry")] = None,
) -> SolveOutputs:
    """An unknown engine (or fallback) is the user's error: exit 2, naming the installed planners,
    never a silent substitute. A problem that found no plan is remembered in this process by
    content (domain, problem, engine, params, timeout): an unchanged problem in the next round of
    a refinement loop is not solved again. A time-out (of the fallback too, if the workflow names
    one) fails the step with "the planner ... timed out after N s": another round would time out
    again. ``engine`` is the engine that answered, ``requested`` the one asked for, and
    ``fallback`` says, when they differ, why the first could not answer (null otherwise): a
    fallback is never silent (it is also a warning of the run)."""
    check_engine(engine)
    if fallback:
        check_engine(fallback)
    if not problem:
        return _outcome("error", None, "no problem to solve (the debugger rejected it or it was not written)",
                        0.0, engine, engine)
    try:
        parsed = _parse(ctx, problem, domain)
    except PDDLError as exc:
        return _outcome("error", None, f"the problem does not parse ({exc}); run pddl.debug first", 0.0, engine,
                        engine)
    domain_text = _read_text(ctx.resolve_path(domain))
    first_params = params
    if engine == DEFAULT_ENGINE and world and world.get("robots"):  # the robots' capacities: the domain knows them
        tdomain = task_domain(world)
        if tdomain.supports(Capability.TRANSPORT_PLANNER):
            first_params = {**tdomain.planner_params(world, constraints or []), **(params or {})}
    result = _solve_once(ctx, parsed, problem, domain_text, engine, first_params, timeout)
    message = result.message
    fell_back = None
    if result.status in ("error", "timeout") and fallback and fallback != engine:
        ctx.log(f"solve: {message}; trying the fallback {fallback}")
        second = _solve_once(ctx, parsed, problem, domain_text, fallback, None, timeout)
        message = f"{message}; fell back to {fallback}: {second.message}"
        ctx.metrics["fallback"] = fallback
        fell_back = (f"the planner {engine} could not answer ({_short(result.message)}); the workflow's fallback "
                     f"{fallback} answered instead")
        ctx.warn(fell_back)
        result = second
    ctx.log(f"solve: {message}")
    ctx.metrics.update({"solve_time": result.time, "engine": result.engine,
                        "plan_length": len(result.plan) if result.plan else None})
    if result.status == "timeout":
        raise PlanningError(message)
    plan = plan_in_world_names(result.plan, world)
    if plan is not None:
        ctx.write_artifact("plan.txt", format_plan(plan))
    return _outcome(result.status.value, plan, message, result.time, result.engine, engine, fell_back)


def _outcome(status: str, plan: list | None, message: str, time: float, engine: str, requested: str,
             fallback: str | None = None) -> SolveOutputs:
    """The step's outputs; ``messages`` (the checking steps' convention) holds the message when
    there is no plan, so a loop that runs out of rounds quotes the planner's reason too."""
    return {"status": status, "plan": plan, "message": message, "messages": [] if plan else [message],
            "time": time, "engine": engine, "requested": requested, "fallback": fallback}


def _short(message: str, limit: int = 160) -> str:
    """A planner's failure in one short line (Fast Downward's is its whole log)."""
    text = " ".join(str(message).split())
    if "Reason:" in text:  # the translator's own words: "Error in requirements. Reason: Invalid requirement..."
        text = text[text.index("Reason:") + len("Reason:"):].strip()
    return text if len(text) <= limit else text[: limit - 3] + "..."


def _read_text(path) -> str:
    try:
        return path.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError):
        return str(path)  # it parsed a moment ago; the path still tells the problems apart


def _solve_once(ctx: StepContext, parsed, problem: str, domain_text: str, engine: str, params, timeout):
    """One solver call, or the remembered outcome of an identical earlier one."""
    from dataclasses import replace


    digest = problem_digest(domain_text, problem, engine, params, timeout)
    earlier = remembered(digest)
    if earlier is not None:
        ctx.log(f"solve: {engine} already answered this exact problem in this process; not solved again")
        return replace(earlier, time=0.0, message=f"{earlier.message} (the same problem as before: not solved again)")
    result = solve_problem(parsed, engine, params, timeout)
    remember(digest, result)
    return result


@step("pddl.verify",
      doc="Validate the plan with UP's sequential plan validator and check the goal against the world; an infeasible goal yields a refusal reason.")
def verify(
    ctx: StepContext,
    problem: Annotated[str | None, Doc("PDDL problem text")],
    domain: Annotated[PathStr, Doc("PDDL domain file")],
    plan: Annotated[list | None, Doc("plan from pddl.solve")] = None,
    world: Annotated[dict | None, Doc("world dict for the goal checks")] = None,
    parse_details: Annotated[bool, Doc("say where a problem that does not parse goes wrong (the parser's "
                                       "message); false in a workflow without the debugger, whose job that "
                                       "is (the 'w/o B' ablation)")] = True,
) -> VerifyOutputs:
    """``refusal`` is a reason string when no plan can satisfy the goal in this world (more units
    than exist, over capacity), else None; ``goal`` is the problem's goal as {shelf: {product: n}}."""
    if not problem:
        return {"ok": False, "messages": ["no problem to verify"], "refusal": None, "goal": {}}
    try:
        parsed = _parse(ctx, problem, domain)
    except PDDLError as exc:
        why = (f"the problem does not parse ({exc}); run pddl.debug first" if parse_details else
               "the problem does not parse, so it has no plan to verify")
        return {"ok": False, "messages": [why], "refusal": None, "goal": {}}
    report = verify_plan(parsed, plan, world)
    for m in report.messages:
        ctx.log(f"verify: {m}")
    ctx.write_artifact("verify.json", {"ok": report.ok, "messages": report.messages,
                                       "refusal": report.refusal, "goal": report.goal})
    return {"ok": report.ok, "messages": report.messages, "refusal": report.refusal, "goal": report.goal}


@step("pddl.goal",
      doc="Read a problem's goal as data, without judging it (the verifier's reading minus its checks): for "
          "workflows without the verifier (the 'w/o B&V' ablation).",
      outputs={"goal": "object"})
def goal(
    ctx: StepContext,
    problem: Annotated[str | None, Doc("PDDL problem text")],
    domain: Annotated[PathStr, Doc("PDDL domain file")],
    world: Annotated[dict | None, Doc("world dict: its task domain reads the goal, in the world's spelling")] = None,
) -> dict:
    """``goal`` as the verifier's output ``goal`` (empty when there is no problem or it does not
    parse): what the run's summary and the bench's understanding read."""
    if not problem:
        return {"goal": {}}
    try:
        parsed = _parse(ctx, problem, domain)
    except PDDLError:
        return {"goal": {}}
    if world is None:
        return {"goal": {}}
    # the domain's reading of the goal; what its checks find is left out on purpose (no verifier)
    return {"goal": task_domain(world).check_goal(parsed, world).goal}

"""Recovery, cheapest first: the mechanics the executor chooses between.

* :func:`reallocate`: the remaining subtasks of the plan to the robots still working, with the
  run's own allocator, rules and skills (the paper's IP through
  :class:`pipflow.team.allocation.AllocationWalk`), from where everyone stands and when each is
  free (:class:`pipflow.team.scheduling.Standing`). A lost robot is kept out by one more rule,
  ``never``, so the run's own rules keep naming it without error.
* :func:`replan`: the observed state written as a new PDDL problem through the task domain's own
  writer, to the same goal, checked by the domain's verifier, solved by the run's planner (with
  its fallback), and turned into a dependency graph the same way (:func:`pipflow.team.dependency.build_graph`).
  A goal the verifier finds impossible, or a problem the planner proves unsolvable, is a
  :class:`Refused` with the reason.
"""
from __future__ import annotations

import time
from dataclasses import dataclass, field
from typing import Any

from pipflow.errors import InputError, PlanningError
from pipflow.liberrors import UNIFIED_PLANNING, library_errors
from pipflow.pddl.convert import data_to_plan
from pipflow.pddl.names import plan_in_world_names
from pipflow.pddl.solver import Status, solve_problem
from pipflow.taskdomain import Capability
from pipflow.team.allocation import METHODS, AllocationWalk
from pipflow.team.dependency import build_graph
from pipflow.team.scheduling import Standing

#: the planner pipflow ships for transport-shaped problems (its robots' capacities come from the
#: domain's ``planner_params``), as the ``pddl.solve`` step names it
TRANSPORT_PLANNER = "pipflow-transport"
#: the rule that keeps a lost robot out of every new coalition
OUT_OF_SERVICE = "out of service"


class Refused(Exception):
    """The goal cannot be reached any more; the message says why."""


@dataclass
class Planning:
    """How the run planned, so that a recovery plans the same way: the PDDL domain and its action
    metadata, the accepted problem (its goal is the goal), the planner and its settings, the
    dependency graph's mode, the allocator and its cost, the robot rules, speed and handling."""

    domain_text: str
    metadata: dict
    problem: str
    planner: str = TRANSPORT_PLANNER
    planner_params: dict | None = None
    fallback: str | None = None
    planner_timeout: float = 60.0
    graph_mode: str = "deorder"
    method: str = "scip"
    mode: str = "subtask"
    cost: str = "total"
    constraints: list = field(default_factory=list)
    speed: float = 1.0
    handling: float = 2.0
    time_limit: float = 10.0
    #: re-plan by repairing the old plan first (:func:`repair`); False: always a plan from scratch
    repair: bool = True


def rules_without(constraints: list, lost: list[str]) -> list:
    """The run's rules plus one that keeps ``lost`` robots out of every subtask."""
    return list(constraints or []) + ([{"never": sorted(lost), "words": OUT_OF_SERVICE}] if lost else [])


def cut_off(graph: dict, standing: Standing, robots: list[str], travel: Any) -> list[dict]:
    """Rules that keep each robot off the subtasks it can no longer reach (a closed passage walls
    a part of the floor off): one ``never`` rule per (robot, subtask), matched on the subtask's
    action and fields. Raises :class:`Refused` for a subtask whose own route is cut in two."""
    rules: list[dict] = []
    for node in graph["nodes"]:
        if node["id"] in standing.ended:
            continue
        route = list(node.get("route") or [])
        try:
            travel.route_length(route)
        except InputError as err:
            raise Refused(f"{node['id']} ({node.get('action')} {' '.join(map(str, node.get('args', [])))}) cannot be "
                          f"done any more: {err}") from None
        for r in robots:
            try:
                travel.distance(standing.pos.get(r, r), route[0])
            except InputError:
                rules.append({"never": [r], "action": node.get("action"), **(node.get("fields") or {}),
                              "words": f"{r} cannot reach {route[0]}"})
    return rules


def reallocate(graph: dict, world: dict, standing: Standing, planning: Planning, lost: list[str],
               travel: Any, extra: list[dict] | None = None) -> tuple[dict, Any]:
    """Allocate every subtask of ``graph`` that ``standing`` does not list as ended, from where
    the team stands (module docstring). Returns the allocation (its contract) and the timeline
    (its records and legs are the new part of the schedule). Raises AllocationError when a
    subtask finds no coalition among the robots still working. ``extra``: more rules (:func:`cut_off`)."""
    if planning.method not in METHODS:
        raise InputError(f"unknown allocation method {planning.method!r}; use one of {', '.join(METHODS)}")
    started = time.perf_counter()
    walk = AllocationWalk(graph, world, planning.method, rules_without(planning.constraints, lost) + list(extra or []), None,
                          travel=travel, speed=planning.speed, handling=planning.handling,
                          time_limit=planning.time_limit, cost=planning.cost, standing=standing)
    if planning.mode == "frontier" and planning.method == "scip":
        walk.run_by_waves()
    else:
        walk.run_per_subtask()
    return walk.result(planning.mode, time.perf_counter() - started), walk.timeline


@dataclass
class Replanned:
    """A new team plan from the observed state: its problem text, plan, graph, the planner's
    words; when it repaired the old plan, how many of its steps it kept and which it dropped."""

    problem: str
    plan: list[dict]
    graph: dict
    message: str
    seconds: float
    kept: int | None = None
    dropped: list[dict] = field(default_factory=list)


@dataclass
class Repaired:
    """The old plan's steps that still apply from the observed state, followed by a plan for
    what they leave undone (:func:`repair`)."""

    plan: list[dict]
    kept: int
    dropped: list[dict]
    message: str


def repair(parsed: Any, steps: list[dict], planning: Planning, params: dict | None) -> Repaired | None:
    """Plan repair, the cheaper re-plan: play the old plan's steps that were not begun (``steps``,
    ``{action, args}`` in plan order, any other keys kept in ``dropped``) from the observed state
    in UP's sequential simulator, keeping each that applies and dropping each that does not (a
    shelf short of the units it takes); then ask the
    run's planner for a plan from the state they reach to the same goal (usually a few moves:
    what the surprise or the lost load took away). The plan is the kept steps and that patch,
    valid from the observed state by construction (each kept step was applied in the
    simulator, the patch was planned from where they end). Why: a plan from scratch solves the
    whole goal again (at 100 shelves x 20 products, a program per product), where the fault
    changed one corner of it. None when the patch cannot be found (no plan from there: the
    kept steps may have used what the goal needs) or the steps use what this check does not
    model (conditional or universally quantified effects): the caller then plans anew."""
    with library_errors(UNIFIED_PLANNING, PlanningError, "repairing the plan"):
        try:
            up_plan = data_to_plan(parsed, steps)
        except ValueError:
            return None
        if any(e.is_conditional() or e.is_forall() for ai in up_plan.actions for e in getattr(ai.action, "effects", [])):
            return None
        keep, dropped, patch = _replay(parsed, steps, up_plan)
    result = solve_problem(patch, planning.planner, params, planning.planner_timeout)
    if result.status != Status.SOLVED or result.plan is None:
        return None
    words = (f"repaired the plan: kept {len(keep)} of its {len(steps)} steps not begun, dropped {len(dropped)}, "
             f"added {len(result.plan)} ({result.message})")
    bare = [{"action": x["action"], "args": list(x["args"])} for x in keep]
    return Repaired(bare + list(result.plan), len(keep), dropped, words)


def _replay(parsed: Any, steps: list[dict], up_plan: Any) -> tuple[list[dict], list[dict], Any]:
    """:func:`repair`'s first half: the steps kept and dropped, and the problem from the state
    the kept ones reach (a clone of ``parsed`` whose initial values of every fluent they change
    are that state's)."""
    # deferred: pulls unified_planning (only re-plans get here)
    from unified_planning.shortcuts import SequentialSimulator

    keep: list[dict] = []
    dropped: list[dict] = []
    changed: dict = {}
    env = parsed.environment
    with SequentialSimulator(problem=parsed) as sim:
        state = sim.get_initial_state()
        for step, ai in zip(steps, up_plan.actions):
            if not sim.is_applicable(state, ai):
                dropped.append(step)
                continue
            state = sim.apply(state, ai)
            keep.append(step)
            bind = {env.expression_manager.ParameterExp(p): a for p, a in zip(ai.action.parameters, ai.actual_parameters)}
            for e in ai.action.effects:
                changed[env.substituter.substitute(e.fluent, bind)] = None
        patch = parsed.clone()
        for fluent in changed:
            patch.set_initial_value(fluent, state.get_value(fluent))
    return keep, dropped, patch


def replan(domain: Any, world: dict, goal: Any, planning: Planning, problem: tuple[Any, str],
           kept: list[dict] | None = None) -> Replanned:
    """Solve ``problem`` (the observed state of ``world``, robots still working only, to ``goal``,
    parsed and as text: the domain's ``observed_problem``), after verifying its goal; build the
    graph (module docstring). ``kept``: the steps the old plan had not begun, in its order: the
    plan is first repaired from them (:func:`repair`), and made anew only when that fails.
    Raises :class:`Refused` when the goal is impossible or no plan exists, PlanningError when
    the planner times out."""
    started = time.perf_counter()
    parsed, text = problem
    judged = domain.check_goal(parsed, world)
    if judged.refusal:
        raise Refused(judged.refusal)
    params = planning.planner_params
    if planning.planner == TRANSPORT_PLANNER and domain.supports(Capability.TRANSPORT_PLANNER):
        params = {**domain.planner_params(world, planning.constraints), **(params or {})}
    try:
        repaired = repair(parsed, kept, planning, params) if kept and planning.repair else None
    except PlanningError:  # UP could not play the old steps: the plan is made anew
        repaired = None
    if repaired is not None:
        plan = plan_in_world_names(repaired.plan, world)
        graph = build_graph(planning.domain_text, text, plan, planning.metadata, mode=planning.graph_mode, parsed=parsed)
        return Replanned(text, plan, graph, repaired.message, time.perf_counter() - started, repaired.kept,
                         repaired.dropped)
    result = solve_problem(parsed, planning.planner, params, planning.planner_timeout)
    message = result.message
    if result.status in (Status.ERROR, Status.TIMEOUT) and planning.fallback and planning.fallback != planning.planner:
        second = solve_problem(parsed, planning.fallback, None, planning.planner_timeout)
        message = f"{message}; fell back to {planning.fallback}: {second.message}"
        result = second
    if result.status == Status.UNSOLVABLE:
        raise Refused(f"no plan reaches the goal from the observed state ({message})")
    if result.status == Status.TIMEOUT:
        raise PlanningError(message)
    if result.plan is None:
        raise PlanningError(f"re-planning failed: {message}")
    plan = plan_in_world_names(result.plan, world)
    graph = build_graph(planning.domain_text, text, plan, planning.metadata, mode=planning.graph_mode, parsed=parsed)
    return Replanned(text, plan, graph, message, time.perf_counter() - started)


def renamed(graph: dict, prefix: str, offset: int) -> dict:
    """A graph whose subtask ids carry ``prefix`` (``r1-s3``) and whose indices start at
    ``offset``: a re-planned part never shares an id or a position with the plan before it."""
    ids = {n["id"]: f"{prefix}{n['id']}" for n in graph["nodes"]}
    nodes = [{**n, "id": ids[n["id"]], "index": int(n["index"]) + offset} for n in graph["nodes"]]
    return {**graph, "nodes": nodes, "edges": [[ids[u], ids[v]] for u, v in graph["edges"]]}


def waits(running: list[dict], new: list[dict]) -> list[list[str]]:
    """Edges from each running subtask to each new one that visits a place it visits: a new plan
    starts from the state after the running subtasks end, so where they touch, it waits."""
    out = []
    for r in running:
        places = set(r.get("route") or [])
        out += [[r["id"], n["id"]] for n in new if places & set(n.get("route") or [])]
    return out

"""The robot plan: what every baseline's reader produces, and its conversion into the dependency
graph and allocation that the ``schedule`` step times (docs/architecture.md, "Data between steps").

A robot plan is a list of :class:`RobotStep`: one team-level action of the domain (``carry crate
dock bay``), the robots the model gave it, and the steps it must wait for (the order the
baseline's format gives: CoT's step numbers, SMART-LLM's sequential calls and thread joins,
LaMMA-P's sub-plans merged in time). PIP-LLM derives its order from the plan's read/write sets and
its robots from an IP; a baseline's plan brings both, and :func:`schedule_input` keeps them as the
model wrote them.

Names the world lacks are not the reader's business: an action on a place that does not exist,
an object of the wrong kind or a robot outside the team is a step the world cannot place. Its
node is marked ``unexecutable`` with the reasons; the schedule records it as refused, and the
simulation counts it as planned and not executed (Exe < 1), as the baselines' own papers count
an action their executor cannot run. A step whose robots lack a skill is placed and timed: the
simulation refuses it when it starts (the coalition's skills do not cover it), which counts the
same way.
"""
from __future__ import annotations

import heapq
from dataclasses import asdict, dataclass, field
from typing import Any

from pipflow.errors import InputError, PDDLError
from pipflow.liberrors import UNIFIED_PLANNING, library_errors
from pipflow.pddl.common import parse
from pipflow.pddl.names import world_spelling
from pipflow.suggest import did_you_mean_clause
from pipflow.taskdomain import pddl_domain_name
from pipflow.taskdomains import task_domain
from pipflow.team.dependency import ground_plan, subtask_node

#: the ``mode`` of a graph whose edges are the order a plan gives (not derived from the plan)
GIVEN = "given"


@dataclass
class RobotStep:
    """One action of a robot plan. ``after``: ids of the steps that must end before it starts;
    ``where``: where the model's answer says it (for messages); ``problems``: why the reader
    already knows the world cannot place it (a robot index past the team, say)."""

    id: str
    action: str
    args: list[str]
    robots: list[str]
    after: list[str] = field(default_factory=list)
    where: str = ""
    problems: list[str] = field(default_factory=list)

    def data(self) -> dict[str, Any]:
        return asdict(self)


def steps_from_data(items: list[Any]) -> list[RobotStep]:
    """Robot steps back from their JSON form (a step's output); InputError names a bad item."""
    steps = []
    for k, item in enumerate(items or []):
        if not isinstance(item, dict) or not {"id", "action", "args", "robots"} <= set(item):
            raise InputError(f"robot plan item {k + 1} is not {{id, action, args, robots, after?}}: {item!r}")
        steps.append(RobotStep(str(item["id"]), str(item["action"]), [str(a) for a in item["args"]],
                               [str(r) for r in item["robots"]], [str(a) for a in item.get("after") or []],
                               str(item.get("where") or ""), [str(p) for p in item.get("problems") or []]))
    return steps


def world_problem(world: dict, domain_text: str) -> str:
    """A team-level problem of this world (its objects and initial state), for reading a plan's
    actions against: the domain's example problem, or its problem for no goal."""
    domain = task_domain(world)
    text = domain.example_problem(world, domain_text)
    return text if text else domain.write_problem(world, {}, pddl_domain_name(domain_text, domain.name))


def _placement(step: RobotStep, problem: Any, world: dict, spelling: dict[str, str]) -> tuple[list[str], list[str], list[str]]:
    """The step's args and robots in the world's spelling, and why the world cannot place it."""
    reasons = list(step.problems)
    args = [spelling.get(a.lower(), a) for a in step.args]
    robots = [spelling.get(r.lower(), r) for r in step.robots]
    team = list((world.get("robots") or {}).keys())
    for r in robots:
        if r not in team:
            reasons.append(f"{r!r} is not a robot of the team ({', '.join(team)}){did_you_mean_clause(r, team)}")
    if not robots:
        reasons.append("no robot is given to do it")
    name = step.action if problem.has_action(step.action) else step.action.lower()
    if not problem.has_action(name):
        actions = [a.name for a in problem.actions]
        return args, robots, reasons + [f"{step.action!r} is not an action of the domain "
                                        f"({', '.join(actions)}){did_you_mean_clause(step.action, actions)}"]
    action = problem.action(name)
    if len(action.parameters) != len(args):
        return args, robots, reasons + [f"{name} takes {len(action.parameters)} arguments "
                                        f"({' '.join('?' + p.name for p in action.parameters)}), got {len(args)}"]
    from unified_planning.model.types import is_compatible_type  # deferred: pulls unified_planning (parsed above)

    names = [o.name for o in problem.all_objects]
    for p, a in zip(action.parameters, args):
        obj = next((problem.object(n) for n in (a, a.lower()) if problem.has_object(n)), None)
        if obj is None:
            reasons.append(f"{a!r} is not in this world{did_you_mean_clause(a, names)}")
        elif not is_compatible_type(p.type, obj.type):
            reasons.append(f"{a!r} is a {getattr(obj.type, 'name', obj.type)}, but ?{p.name} of {name} is a "
                           f"{getattr(p.type, 'name', p.type)}")
    return args, robots, reasons


def _topological(ids: list[str], edges: list[tuple[str, str]]) -> list[str]:
    """The steps in an order that respects ``edges``, earlier plan steps first among the ready."""
    rank = {i: k for k, i in enumerate(ids)}
    preds = {i: 0 for i in ids}
    succ: dict[str, list[str]] = {i: [] for i in ids}
    for u, v in edges:
        preds[v] += 1
        succ[u].append(v)
    ready = [(rank[i], i) for i in ids if not preds[i]]
    heapq.heapify(ready)
    out = []
    while ready:
        _, i = heapq.heappop(ready)
        out.append(i)
        for v in succ[i]:
            preds[v] -= 1
            if not preds[v]:
                heapq.heappush(ready, (rank[v], v))
    if len(out) != len(ids):
        raise InputError(f"the robot plan's order has a cycle among {sorted(set(ids) - set(out))}")
    return out


def schedule_input(steps: list[RobotStep], world: dict, domain_text: str, metadata: dict,
                   method: str) -> dict[str, Any]:
    """The ``graph`` (nodes with skills, route and fields from the action metadata; edges the
    plan's own order, ``mode`` :data:`GIVEN`) and the ``allocation`` (each step's robots as the
    model gave them, in an order that respects the edges) of a robot plan, plus ``unexecutable``:
    how many steps the world cannot place (their nodes say why)."""
    ids = [s.id for s in steps]
    if len(set(ids)) != len(ids):
        raise InputError(f"the robot plan repeats step ids: {sorted({i for i in ids if ids.count(i) > 1})}")
    with library_errors(UNIFIED_PLANNING, PDDLError, "reading the world's problem for a robot plan"):
        problem = parse(domain_text, world_problem(world, domain_text))
    actions_meta = (metadata or {}).get("actions", metadata or {})
    spelling = world_spelling(world)
    nodes, robots_of, edges, refused = [], {}, [], 0
    known = set(ids)
    for index, st in enumerate(steps):
        args, robots, reasons = _placement(st, problem, world, spelling)
        if reasons:
            refused += 1
            node = {"id": st.id, "index": index, "action": st.action, "args": args, "skills": {}, "route": [],
                    "fields": {}, "unexecutable": reasons}
        else:
            grounded = ground_plan(problem, [{"action": st.action, "args": args}])[0]
            node = subtask_node(grounded, problem, actions_meta, st.id, index)
        if st.where:
            node["where"] = st.where
        nodes.append(node)
        robots_of[st.id] = robots
        for before in st.after:
            if before not in known:
                raise InputError(f"robot plan step {st.id} waits for unknown step {before!r}")
            if (before, st.id) not in edges:
                edges.append((before, st.id))
    order = _topological(ids, edges)
    graph = {"mode": GIVEN, "nodes": nodes, "edges": [list(e) for e in edges]}
    allocation = {"method": method, "cost": None, "given": True,
                  "assignments": [{"subtask": i, "robots": robots_of[i], "costs": {}} for i in order],
                  "stats": {"mode": GIVEN, "subtasks": len(order), "unexecutable": refused}}
    return {"graph": graph, "allocation": allocation, "unexecutable": refused}

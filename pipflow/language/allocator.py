"""The paper's "w/o AS" ablation: allocation and scheduling by a language model instead of the IP.

The paper (Sec. V, Table III): "we replace our task allocation and scheduling module with a
purely LLM-based approach". The model is shown the dependency graph's subtasks (what each does,
the skills it needs, the places of its route, the subtasks that must end first), the robots
(their skills and where they stand) and the command's robot-use rules, and answers which robots
do each subtask, listing the subtasks in the order they are to be done (JSON, read as data:
:func:`check_answer`). The order and the coalitions are the model's; the timing is the one every
allocator's schedule gets (:class:`pipflow.team.scheduling.Timeline`: a subtask starts when its
predecessors have ended and its robots have arrived).

An answer is refused, with feedback that says where, when it names an unknown subtask or robot,
leaves a subtask out or lists one twice, gives a coalition whose summed skills fall short of a
subtask's needs, uses a robot a rule excludes, or lists a subtask before one that must end first.
The model then answers again, at most ``attempts`` times in all; an answer still refused ends the
run (:class:`pipflow.errors.AllocationError`, every problem named). Why refuse instead of
executing: a coalition that cannot lift the load or a robot the command forbids must not move,
whoever allocated it (the IP never proposes one).
"""
from __future__ import annotations

import time
from typing import Any

from pipflow.errors import AllocationError, InputError
from pipflow.language.asking import ModelCall, RoundRecord, ask
from pipflow.language.jsonanswer import json_object
from pipflow.language.parsing import ParseIssue
from pipflow.language.prompting import render
from pipflow.suggest import did_you_mean
from pipflow.team.allocation import Rules, need_vector, skill_matrix
from pipflow.team.scheduling import Timeline, predecessors

#: the method name the allocation contract records
METHOD = "llm"


def describe(graph: dict, world: dict, timeline: Timeline, constraints: list[dict]) -> dict[str, Any]:
    """What the prompt shows: subtasks, robots and their positions, the places' positions, rules."""
    preds = predecessors(graph)
    nodes = sorted(graph["nodes"], key=lambda n: n["index"])
    places: dict[str, list[float]] = {}
    subtasks = []
    for n in nodes:
        for p in n.get("route") or []:
            places.setdefault(p, _xy(timeline.travel.point(p)))
        subtasks.append({"id": n["id"], "action": n.get("action"), "args": list(n.get("args") or []),
                         "needs": dict(n.get("skills") or {}), "route": list(n.get("route") or []),
                         "after": sorted(preds[n["id"]], key=lambda s: _index(graph, s))})
    robots = [{"name": r, "skills": dict(spec.get("skills") or {}), "at": _xy(timeline.travel.point(r))}
              for r, spec in (world.get("robots") or {}).items()]
    return {"subtasks": subtasks, "robots": robots, "places": places, "rules": list(constraints or [])}


def _xy(point: Any) -> list[float]:
    return [round(float(point[0]), 2), round(float(point[1]), 2)]


def _index(graph: dict, sid: str) -> int:
    return next((n["index"] for n in graph["nodes"] if n["id"] == sid), 0)


def check_answer(data: dict, graph: dict, world: dict, constraints: list[dict]) -> tuple[list[dict], list[str]]:
    """The model's assignments in its order (``[{"subtask", "robots"}]``) and every problem with
    them, each located by the answer's entry number and its subtask (module docstring). No
    problem: the list is a valid allocation to commit in that order."""
    entries = data.get("assignments")
    if not isinstance(entries, list):
        return [], ['the answer must hold "assignments": a list of {"subtask": ID, "robots": [ROBOT, ...]} '
                    "in the order the subtasks are to be done"]
    nodes = {n["id"]: n for n in graph["nodes"]}
    preds = predecessors(graph)
    robots, skills, Q = skill_matrix(world, graph["nodes"])
    rules = Rules(robots, skills, Q, constraints, None, graph["nodes"])
    index = {r: i for i, r in enumerate(robots)}
    problems: list[str] = []
    out: list[dict] = []
    seen: dict[str, int] = {}
    for k, entry in enumerate(entries, 1):
        where = f"assignment {k}"
        if not isinstance(entry, dict):
            problems.append(f'{where}: must be an object {{"subtask": ID, "robots": [ROBOT, ...]}}, got {_short(entry)}')
            continue
        sid, names = entry.get("subtask"), entry.get("robots")
        if not isinstance(sid, str) or sid not in nodes:
            problems.append(f"{where}: no subtask {_short(sid)}{did_you_mean(str(sid), nodes)}; subtasks: "
                            f"{', '.join(nodes)}")
            continue
        where = f"{where} (subtask {sid})"
        if sid in seen:
            problems.append(f"{where}: {sid} is already assigned in assignment {seen[sid]}; assign each subtask once")
            continue
        seen[sid] = k
        if isinstance(names, str):
            names = [names]
        if not isinstance(names, list) or not names or not all(isinstance(r, str) for r in names):
            problems.append(f'{where}: "robots" must be a non-empty list of robot names, got {_short(names)}')
            continue
        unknown = [r for r in names if r not in index]
        if unknown:
            problems.append(f"{where}: no robot {_short(unknown[0])}{did_you_mean(unknown[0], robots)}")
            continue
        if len(set(names)) != len(names):
            problems.append(f"{where}: a robot is listed twice in {names}")
            continue
        node = nodes[sid]
        Y = need_vector(node, skills)
        have = Q[[index[r] for r in names]].sum(axis=0)
        short = [f"{skills[u]} {have[u]:g} < {Y[u]:g} needed" for u in range(len(skills)) if have[u] < Y[u] - 1e-9]
        if short:
            who = f"{names[0]} has" if len(names) == 1 else f"{', '.join(names)} together have"
            problems.append(f"{where}: {who} {'; '.join(short)}")
        allowed, why = rules.mask(node)
        barred = [r for r in names if not allowed[index[r]]]
        for r in barred:
            problems.append(f"{where}: {r} may not do {sid} ({why[r]})")
        early = [p for p in preds[sid] if p not in seen]
        if early:
            problems.append(f"{where}: listed before {', '.join(sorted(early))}, which must end before {sid} starts")
        out.append({"subtask": sid, "robots": list(names)})
    missing = [s for s in sorted(nodes, key=lambda s: nodes[s]["index"]) if s not in seen]
    if missing:
        problems.append(f"no assignment for subtask(s) {', '.join(missing)}: assign every subtask")
    return out, problems


def _short(value: Any) -> str:
    text = repr(value)
    return text if len(text) <= 60 else text[:57] + "..."


def allocate_by_model(graph: dict, world: dict, *, constraints: list[dict] | None, prompt: str, call: ModelCall,
                      record: RoundRecord = RoundRecord(), attempts: int = 3, **timing: Any) -> dict:
    """The allocation contract (docs/architecture.md) of the model's answer: ``method: llm``, the
    assignments in the model's order with each robot's cost c_i as ``timing["cost"]`` defines it
    (what the IP would have seen, for comparison), and ``stats`` (``attempts``, the problems of
    every refused answer). ``prompt``: the template's path; ``timing``: the
    :class:`~pipflow.team.scheduling.Timeline`'s ``speed``, ``handling`` and ``cost``. Raises
    :class:`AllocationError` when the last answer is still refused."""
    if attempts < 1:
        raise InputError(f"attempts must be at least 1, got {attempts}")
    started = time.perf_counter()
    constraints = list(constraints or [])
    shown = describe(graph, world, Timeline(world, **timing), constraints)
    history: list[dict] = []
    assignments: list[dict] = []
    if graph["nodes"]:  # nothing to allocate: no question
        assignments, history = _ask_until_valid(graph, world, constraints, shown, attempts, prompt, call, record)
    nodes = {n["id"]: n for n in graph["nodes"]}
    preds = predecessors(graph)
    timeline = Timeline(world, **timing)
    committed = []
    for a in assignments:
        node = nodes[a["subtask"]]
        costs = {r: float(timeline.cost(r, node)) for r in a["robots"]}
        timeline.commit(node, a["robots"], preds[a["subtask"]])
        committed.append({"subtask": a["subtask"], "robots": a["robots"], "costs": costs})
    predicted = timeline.result()
    return {"method": METHOD, "cost": timeline.cost_kind, "assignments": committed,
            "stats": {"subtasks": len(committed), "mode": METHOD, "cost": timeline.cost_kind,
                      "time_s": time.perf_counter() - started, "solve_median_ms": 0.0,
                      "attempts": len(history), "refused": [h["problems"] for h in history if h["problems"]],
                      "usage": [h["usage"] for h in history],
                      "predicted": {k: predicted[k] for k in ("makespan", "tc_max", "tc_avg")}}}


def _ask_until_valid(graph: dict, world: dict, constraints: list[dict], shown: dict, attempts: int, prompt: str,
                     call: ModelCall, record: RoundRecord) -> tuple[list[dict], list[dict]]:
    """Ask, check, and ask again with the problems as feedback, at most ``attempts`` times:
    (the valid assignments, the record of every attempt). Raises AllocationError."""
    history: list[dict] = []
    feedback: list[str] = []
    for attempt in range(1, attempts + 1):
        messages = render(prompt, {**shown, "feedback": feedback})
        answer = ask(messages, call=call, record=record, name=f"attempt{attempt}-")
        try:
            assignments, problems = check_answer(json_object(answer["text"]), graph, world, constraints)
        except ParseIssue as issue:
            assignments, problems = [], [str(issue)]
        history.append({"attempt": attempt, "problems": problems, "usage": answer["usage"]})
        if not problems:
            return assignments, history
        record.log(f"allocate.llm: answer {attempt} refused: {'; '.join(problems)}")
        feedback = problems
    raise AllocationError(f"the model's allocation was refused {attempts} time(s); the last answer: "
                          + "; ".join(history[-1]["problems"]))

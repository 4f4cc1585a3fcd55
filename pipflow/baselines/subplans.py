"""LaMMA-P's per-robot planning: one PDDL problem per subtask in the robot-level domain, checked
by the debugger (one validator round with its located messages, as LaMMA-P validates each problem
once), solved by a planner, and the sub-plans merged in time (:func:`lammap.merge_in_time`).

The model is asked through a function the caller gives (``ask(stage, name, variables)`` returns
the answer's text), so the loop knows nothing of prompts, providers or run records; the planner
is a unified-planning engine (ENHSP for numeric domains).
"""
from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Any, Callable

from pipflow.baselines.lammap import RobotAction, Subtask, merge_in_time, robot_actions, sub_plan_steps
from pipflow.baselines.robotplan import RobotStep
from pipflow.errors import PDDLError
from pipflow.language.parsing import ParseIssue, extract_problem
from pipflow.liberrors import UNIFIED_PLANNING, library_errors
from pipflow.pddl.common import parse
from pipflow.pddl.debugger import debug_problem, unclosed_section
from pipflow.pddl.names import plan_in_world_names
from pipflow.pddl.solver import solve_problem
from pipflow.pddl.textpos import find_word

#: ``ask(stage, name, variables)``: the model's answer to the template's ``stage`` (``problem``,
#: ``validate``), recorded under ``name``
Ask = Callable[[str, str, dict], str]


@dataclass(frozen=True)
class RobotLevel:
    """A robot-level domain: its text, its actions' team actions, each action's parameters (with
    ``?``) and the types its robots have."""

    text: str
    actions: dict[str, RobotAction]
    params_of: dict[str, list[str]]
    robot_types: frozenset[str]


def robot_level(robot_domain_text: str, metadata: dict, team_domain_text: str) -> RobotLevel:
    """The robot-level domain read and its mapping checked (:func:`lammap.robot_actions`)."""
    mapping = robot_actions(metadata, robot_domain_text, team_domain_text)
    with library_errors(UNIFIED_PLANNING, PDDLError, "reading the robot-level domain"):
        domain = parse(robot_domain_text, None)
    params_of = {a.name: ["?" + p.name for p in a.parameters] for a in domain.actions}
    robot_types = frozenset(getattr(p.type, "name", str(p.type)) for a in domain.actions for p in a.parameters
                            if "?" + p.name in mapping[a.name].robots)
    return RobotLevel(robot_domain_text, mapping, params_of, robot_types)


def checked_problem(text: str, level: RobotLevel, subtask: Subtask) -> tuple[str | None, str, list[str]]:
    """The problem in an answer (None if it has none), the text to show the validator (the
    problem, or the answer from its last ``(define``), and the debugger's messages ([] when the
    problem parses and names only the subtask's robots): located as the debugger locates them, an
    unclosed section by where it opened. A robot the summary did not assign is a message too:
    LaMMA-P writes each problem in its robot's own domain, where no other robot exists."""
    try:
        problem = extract_problem(text)
    except ParseIssue as issue:
        starts = [m.start() for m in re.finditer(r"\(\s*define\b", text, re.IGNORECASE)]
        body = text[starts[-1]:].split("```", 1)[0].strip() if starts else text.strip()
        hint = unclosed_section(body) if starts else ""
        return None, body, [str(issue) + (f" Counting lines from `(define`: {hint}" if hint else "")]
    report = debug_problem(problem, level.text, None)
    messages = list(report.messages)
    if report.problem is not None:
        assigned = {r.lower() for r in subtask.robots}
        for obj in report.problem.all_objects:
            if getattr(obj.type, "name", "") in level.robot_types and obj.name.lower() not in assigned:
                messages.append(f"{find_word(problem, obj.name)}the problem declares the robot {obj.name}, which the "
                                f"summary did not assign to {subtask.label()} (its robots: {', '.join(subtask.robots)})")
    return problem, problem, messages


@dataclass(frozen=True)
class Planning:
    """The planner each subtask's problem goes to: its name (a unified-planning engine), its
    parameters and the seconds it may take."""

    planner: str = "enhsp"
    params: dict | None = None
    timeout: float = 60.0


def plan_subtasks(subtasks: list[Subtask], level: RobotLevel, world: dict, ask: Ask, *, rounds: int = 1,
                  planning: Planning = Planning(), save: Callable[[str, Any], Any] | None = None,
                  log: Callable[[str], None] = lambda message: None) -> tuple[list[RobotStep], list[dict]]:
    """The merged robot plan of the subtasks and a report per subtask (its problem, the
    validator's messages round by round, the planner's outcome, how many actions it got). A
    subtask the summary could not read (``issues``) is skipped; one whose problem still fails
    after ``rounds`` validator rounds, or has no plan, gets no actions: LaMMA-P goes on without it."""
    report, sub_plans, next_id = [], {}, 1
    for sub in subtasks:
        if sub.issues:
            report.append({"subtask": sub.number, "robots": sub.robots, "problem": None, "validator": [],
                           "status": "skipped", "actions": 0, "message": "; ".join(sub.issues)})
            continue
        tag = f"subtask{sub.number}"
        variables = {"subtask": sub.data(), "previous": "", "feedback": []}
        problem, shown, messages = checked_problem(ask("problem", f"{tag}.problem", variables), level, sub)
        history = [messages] if messages else []
        for _ in range(rounds if messages else 0):  # the validator: the debugger's messages
            variables = {**variables, "previous": shown, "feedback": messages}
            problem, shown, messages = checked_problem(ask("validate", f"{tag}.validate", variables), level, sub)
            if not messages:
                break
            history.append(messages)
        entry: dict[str, Any] = {"subtask": sub.number, "robots": sub.robots, "problem": problem,
                                 "validator": history, "status": "not planned", "actions": 0}
        if problem and not messages:
            if save is not None:
                save(f"{tag}.pddl", problem)
            result = solve_problem(parse(level.text, problem), planning.planner, planning.params, planning.timeout)
            entry["status"], entry["message"] = str(result.status), result.message
            if result.plan is not None:
                steps = sub_plan_steps(plan_in_world_names(result.plan, world) or [], level.actions, sub, next_id,
                                       level.params_of)
                next_id += len(steps)
                sub_plans[sub.number] = steps
                entry["actions"] = len(steps)
        else:
            entry["message"] = "; ".join(messages) or "no problem"
        log(f"subtask {sub.number} ({', '.join(sub.robots)}): {entry['status']}, {entry['actions']} actions"
            + (f" ({entry['message']})" if entry["status"] != "solved" else ""))
        report.append(entry)
    return merge_in_time(subtasks, sub_plans), report

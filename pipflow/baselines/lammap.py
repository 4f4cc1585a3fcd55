"""The LaMMA-P baseline: its allocation summary, its per-robot PDDL problems and their merge in time.

LaMMA-P (Zhang et al., arXiv 2409.20560; code at tasl-lab/LaMMA-P) extends SMART-LLM with PDDL:
the model decomposes the task and identifies preconditions, allocates the subtasks to robots
(prose), sums the allocation up (each subtask's "Assigned Robot" and "Objects Involved", and the
sequence of operations), then writes one PDDL problem per subtask in the assigned robot's own
domain; an LLM validator checks each problem once; Fast Downward solves each; a combiner merges
the sub-plans in time, subtasks the sequence lets run in parallel at the same time.

pipflow's version (``workflows/lamma-p.yaml``, ``household-lamma-p.yaml``):

* the summary is read by :func:`read_summary`, one block per subtask::

      SubTask 2: carry the crate to the bay
      Assigned Robot: r4, r5
      Objects Involved: crate, dock, bay
      After: 1

  ``After`` is the sequence of operations, per subtask (``none``: it may start at once); lines
  that are none of these (the model's analysis) are prose and left alone. Every problem is
  located (line, column) and the run stops: LaMMA-P has no round that corrects a summary;
* the robot-level domain is one per task domain (``domains/*-robots.pddl``: the team's actions
  with the robot as a parameter, and a ``-together`` variant for two robots), with a mapping
  to the team action each one is (``domains/*-robots.actions.yaml``, read by
  :func:`robot_actions`);
* the validator is one round per problem, as LaMMA-P's is (their code has the model re-read
  every problem once, unprompted); pipflow's gives it the debugger's located messages, and only
  when the problem does not parse;
* a planner (ENHSP through unified-planning: the domains are numeric, Fast Downward is not)
  solves each problem; a problem that still fails, or has no plan, leaves its subtask without
  actions, as in LaMMA-P;
* the merge is :func:`merge_in_time`, code rather than a model: each sub-plan's actions one after
  another, a subtask after the last action of every subtask it comes ``After``, the others at
  once. LaMMA-P's combiner is asked for exactly that ("parallel tasks are performed at the same
  time"); unlike their combiner, pipflow never lets a model rewrite a plan the planner found.
"""
from __future__ import annotations

import re
from dataclasses import dataclass, field
from typing import Any

from pipflow.baselines.located import Issue, Unreadable, snippet
from pipflow.baselines.robotplan import RobotStep
from pipflow.errors import InputError, PDDLError
from pipflow.liberrors import UNIFIED_PLANNING, library_errors
from pipflow.pddl.common import parse
from pipflow.suggest import did_you_mean_clause

_DECOR = r"[ \t#>*\-]*\**[ \t]*"
HEADER = re.compile(_DECOR + r"sub[ \t_-]?task[ \t]*(\S*?)[ \t]*\**[ \t]*:\**[ \t]*(.*?)[ \t]*$", re.IGNORECASE)
FIELD = re.compile(_DECOR + r"(assigned[ \t]+robots?|objects[ \t]+involved|after)[ \t]*\**[ \t]*:\**[ \t]*(.*?)[ \t]*$",
                   re.IGNORECASE)
MARK = re.compile(r"^" + _DECOR + r"problem[ \t]+content[ \t]+summary[ \t]*\**[ \t]*:?", re.IGNORECASE | re.MULTILINE)
NONE_WORDS = ("none", "nothing", "-", "no", "n/a", "")
FORM = ("SubTask N: TITLE / Assigned Robot: ROBOT, ROBOT / Objects Involved: NAME, NAME / "
        "After: none (or the numbers of the subtasks it waits for)")


@dataclass
class Subtask:
    """One subtask of the summary: its number, title, robots, objects, the subtasks it waits for,
    the answer's line where it starts, and ``issues`` (located): a subtask with issues is skipped,
    as LaMMA-P skips a subtask whose structure it cannot read."""

    number: int
    title: str
    robots: list[str] = field(default_factory=list)
    objects: list[str] = field(default_factory=list)
    after: list[int] = field(default_factory=list)
    line: int = 0
    issues: list[str] = field(default_factory=list)

    def label(self) -> str:
        """``SubTask 3``, or where it is when its header gave no number of its own."""
        return f"SubTask {self.number}" if self.number > 0 else f"the subtask of line {self.line}"

    def data(self) -> dict[str, Any]:
        return {"number": self.number, "title": self.title, "robots": self.robots, "objects": self.objects,
                "after": self.after, "line": self.line, "issues": self.issues}


@dataclass
class Summary:
    """A summary as read: every subtask (those with issues are skipped) and every issue, located
    (the feedback of LaMMA-P's one structure-fixing round)."""

    subtasks: list[Subtask]
    issues: list[Issue]

    def readable(self) -> list[Subtask]:
        return [s for s in self.subtasks if not s.issues]


def subtasks_from_data(items: list[Any]) -> list[Subtask]:
    out = []
    for item in items or []:
        if not isinstance(item, dict) or "number" not in item or "robots" not in item:
            raise InputError(f"a subtask is {{number, title, robots, objects, after, issues}}, got {item!r}")
        out.append(Subtask(int(item["number"]), str(item.get("title") or ""), [str(r) for r in item["robots"]],
                           [str(o) for o in item.get("objects") or []], [int(a) for a in item.get("after") or []],
                           int(item.get("line") or 0), [str(i) for i in item.get("issues") or []]))
    return out


def _items(value: str) -> list[tuple[str, int]]:
    """The items of a field value separated by commas, semicolons or "and", each with its offset
    in the value (emphasis and a final full stop dropped)."""
    out, pos = [], 0
    for sep in [*re.finditer(r"[ \t]*(?:[,;&]|\band\b)[ \t]*", value, re.IGNORECASE), None]:
        end = sep.start() if sep else len(value)
        raw = value[pos:end]
        item = raw.strip().strip("*`").rstrip(".").strip()
        if item:
            out.append((item, pos + raw.index(item[0])))
        if sep:
            pos = sep.end()
    return out


def _robots(value: str, line: int, column: int, team: list[str], issues: list[Issue]) -> list[str]:
    value = re.sub(r"^(?:a[ \t]+)?team(?:[ \t]+of)?[ \t]*:?[ \t]*", "", value, flags=re.IGNORECASE)
    by_lower = {r.lower(): r for r in team}
    out = []
    for item, at in _items(value):
        name = by_lower.get(item.lower())
        if name is None:
            issues.append(Issue(line, column + at, f"{item!r} is not a robot of the team ({', '.join(team)})"
                                                   f"{did_you_mean_clause(item, team)}"))
        elif name not in out:
            out.append(name)
    if not out and not any(i.line == line for i in issues):
        issues.append(Issue(line, column, f"no robot assigned: write the robots' names ({', '.join(team)})"))
    return out


def _after(value: str, line: int, column: int, issues: list[Issue]) -> list[int]:
    if value.strip().lower().rstrip(".") in NONE_WORDS:
        return []
    out = []
    for item, at in _items(value):
        m = re.fullmatch(r"(?:sub[ \t_-]?task[ \t]*)?#?(\d+)\.?", item, flags=re.IGNORECASE)
        if m is None:
            issues.append(Issue(line, column + at, f"{item!r}: After lists subtask numbers (After: 1, 2) or none"))
        else:
            out.append(int(m.group(1)))
    return out


def read_summary(text: str, team: list[str]) -> Summary:
    """The subtasks of a summary answer (after its last "Problem content summary" line, if it has
    one), each problem located and charged to the subtask it is in. :class:`Unreadable` when no
    subtask can be read at all, or the subtasks wait for each other in a circle (nothing could
    start); otherwise the subtasks with issues are skipped, the others planned."""
    marks = list(MARK.finditer(text))
    start_line = text.count("\n", 0, marks[-1].start()) + 2 if marks else 1
    lines = text.split("\n")
    issues: list[Issue] = []
    subtasks: list[Subtask] = []
    seen_fields: set[str] = set()
    assigned: set[int] = set()

    def charge(subtask: Subtask | None, issue: Issue) -> None:
        issues.append(issue)
        if subtask is not None:
            subtask.issues.append(str(issue))

    for line_no in range(start_line, len(lines) + 1):
        line = lines[line_no - 1]
        head = HEADER.fullmatch(line)
        if head:
            raw, title = head.group(1).rstrip("."), head.group(2)
            current = Subtask(-len(subtasks) - 1, title, line=line_no)  # a number no After can name, until read
            subtasks.append(current)
            seen_fields = set()
            if not raw.isdigit() or int(raw) < 1:
                charge(current, Issue(line_no, head.start(1) + 1, f"{snippet(line.strip())}: a subtask is numbered "
                                                                   "SubTask 1, SubTask 2, ..."))
            elif any(s.number == int(raw) for s in subtasks):
                charge(current, Issue(line_no, head.start(1) + 1, f"a second SubTask {raw}: number each subtask once"))
            else:
                current.number = int(raw)
            continue
        got = FIELD.fullmatch(line)
        if not got:
            continue  # the model's analysis between the fields: prose
        key = got.group(1).lower().split()[0]
        column = got.start(2) + 1
        if not subtasks:
            charge(None, Issue(line_no, 1, f"{got.group(1)!r} before any `SubTask N:` line; the summary is: {FORM}"))
            continue
        current = subtasks[-1]
        if key in seen_fields:
            charge(current, Issue(line_no, 1, f"{current.label()} has a second {got.group(1)!r} line"))
            continue
        seen_fields.add(key)
        found: list[Issue] = []
        if key == "assigned":
            assigned.add(id(current))
            current.robots = _robots(got.group(2), line_no, column, team, found)
        elif key == "objects":
            current.objects = [item for item, _ in _items(got.group(2))]
        else:
            current.after = _after(got.group(2), line_no, column, found)
        for issue in found:
            charge(current, issue)
    if not subtasks:
        raise Unreadable(issues + [Issue(start_line, 1, f"the summary has no `SubTask 1:` line; the summary is: {FORM}")])
    numbers = {s.number for s in subtasks}
    for s in subtasks:
        if id(s) not in assigned:
            charge(s, Issue(s.line, 1, f"{s.label()} has no `Assigned Robot:` line"))
        for a in list(s.after):
            if a == s.number or a not in numbers:
                s.after.remove(a)
                charge(s, Issue(s.line, 1, f"{s.label()} comes after {a}, which is "
                                           f"{'itself' if a == s.number else 'not a subtask of the summary'}"))
    cycle = _cycle(subtasks)
    if cycle:
        first = next(s for s in subtasks if s.number == cycle[0])
        raise Unreadable(issues + [Issue(first.line, 1, "the subtasks wait for each other in a circle: "
                                                        + " -> ".join(f"SubTask {n}" for n in cycle))])
    summary = Summary(subtasks, issues)
    if not summary.readable():
        raise Unreadable(issues)
    return summary


def _cycle(subtasks: list[Subtask]) -> list[int]:
    """A circle of ``After`` references (first number repeated at the end), or []."""
    after = {s.number: s.after for s in subtasks}
    state: dict[int, int] = {}

    def visit(n: int, path: list[int]) -> list[int]:
        state[n] = 1
        for m in after.get(n, []):
            if state.get(m) == 1:
                return path[path.index(m):] + [m] if m in path else [n, m, n]
            if state.get(m) is None:
                found = visit(m, path + [m])
                if found:
                    return found
        state[n] = 2
        return []

    for s in subtasks:
        if state.get(s.number) is None:
            found = visit(s.number, [s.number])
            if found:
                return found
    return []


# ---------------------------------------------------------------------------------------------
# robot-level actions -> team actions
# ---------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class RobotAction:
    """A robot-level action: the team action it performs, which parameters are the robots and
    which (in order) are the team action's arguments."""

    name: str
    team: str
    robots: tuple[str, ...]
    args: tuple[str, ...]


def robot_actions(metadata: dict, robot_domain_text: str, team_domain_text: str) -> dict[str, RobotAction]:
    """The mapping file (``domains/*-robots.actions.yaml``) checked against both domains: every
    robot-level action is mapped, its robots and arguments are its own parameters, its team
    action exists and takes that many arguments. A mistake is the data's: InputError."""
    with library_errors(UNIFIED_PLANNING, PDDLError, "reading the robot-level domain"):
        robot_domain = parse(robot_domain_text, None)
    with library_errors(UNIFIED_PLANNING, PDDLError, "reading the team-level domain"):
        team_domain = parse(team_domain_text, None)
    table = (metadata or {}).get("actions", metadata or {})
    out: dict[str, RobotAction] = {}
    for action in robot_domain.actions:
        spec = table.get(action.name)
        if not isinstance(spec, dict):
            raise InputError(f"robot-level action {action.name!r} has no mapping to a team action "
                             f"(mapped: {', '.join(sorted(table)) or 'none'})")
        params = {"?" + p.name for p in action.parameters}
        robots, args = tuple(spec.get("robots") or ()), tuple(spec.get("args") or ())
        wrong = [p for p in robots + args if p not in params]
        if wrong or not robots:
            raise InputError(f"robot-level action {action.name}: robots {list(robots)} and args {list(args)} must be "
                             f"some of its parameters ({', '.join(sorted(params))})")
        team = str(spec.get("team") or "")
        if not team_domain.has_action(team) or len(team_domain.action(team).parameters) != len(args):
            raise InputError(f"robot-level action {action.name}: team action {team!r} is not an action of the team "
                             f"domain taking {len(args)} arguments")
        out[action.name] = RobotAction(action.name, team, robots, args)
    return out


def sub_plan_steps(plan: list[dict], actions: dict[str, RobotAction], subtask: Subtask, first_id: int,
                   params_of: dict[str, list[str]]) -> list[RobotStep]:
    """A planner's plan for one subtask as robot steps (one after another; the first waits for
    nothing yet: :func:`merge_in_time` adds what it waits for). ``params_of``: each robot-level
    action's parameter names, in order, with ``?``."""
    steps = []
    for k, item in enumerate(plan):
        act = actions.get(item["action"])
        if act is None:
            raise InputError(f"the planner's action {item['action']!r} is not a mapped robot-level action")
        binding = dict(zip(params_of[act.name], item["args"]))
        steps.append(RobotStep(f"a{first_id + k}", act.team, [binding[a] for a in act.args],
                               [binding[r] for r in act.robots], [steps[-1].id] if steps else [],
                               f"SubTask {subtask.number}, plan step {k + 1}"))
    return steps


def merge_in_time(subtasks: list[Subtask], sub_plans: dict[int, list[RobotStep]]) -> list[RobotStep]:
    """The sub-plans merged: a subtask's first action waits for the last action of every subtask
    it comes after (through subtasks that got no actions, to what they waited for); subtasks
    with nothing before them start at once, side by side."""
    by_number = {s.number: s for s in subtasks}
    done: dict[int, list[str]] = {}
    order: list[int] = []

    def finish(n: int) -> list[str]:
        if n in done:
            return done[n]
        before = sorted({sid for a in by_number[n].after for sid in finish(a)}, key=lambda i: int(i[1:]))
        steps = sub_plans.get(n) or []
        if steps:
            steps[0].after = sorted(set(steps[0].after) | set(before), key=lambda i: int(i[1:]))
        done[n] = [steps[-1].id] if steps else before
        order.append(n)
        return done[n]

    for s in subtasks:
        finish(s.number)
    return [st for s in subtasks for st in (sub_plans.get(s.number) or [])]

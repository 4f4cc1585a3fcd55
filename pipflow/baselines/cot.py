"""The CoT baseline's reader: a multi-robot plan the model writes itself, step by step.

The PIP-LLM paper's CoT baseline (Sec. V) is "a basic Chain of Thought": the model reasons and
writes the plan, robots included, with no planner, no allocator and no feedback. pipflow's prompt
(``prompts/*_cot.j2``) asks for the reasoning first, then the plan after a line ``PLAN:``, one
action per line, until a line ``END`` (or the end of the answer)::

    PLAN:
    1. r6: (open gate)
    2. r4, r5: (carry crate dock bay)
    2. r2: (switch-off light light)
    3. r6: (close gate)
    END

``N.`` is the step, then the robots that do the action, then the action of the team-level PDDL
domain with its arguments. Actions of one step run at the same time; step N+1 starts when every
action of step N has ended. Steps are numbered 1, 2, 3, ... (a number may repeat, never skip).

Each line is parsed with a small lark grammar (the grammar, not a regular expression, says what
was expected where); every line's problem is reported at once with its line and column in the
whole answer. Action names and arities are the format's (the domain's actions); the names of
places, objects and robots are the world's business (:mod:`pipflow.baselines.robotplan`).
"""
from __future__ import annotations

import re
from functools import lru_cache
from typing import Any

from pipflow.baselines.located import Issue, Unreadable, snippet
from pipflow.baselines.robotplan import RobotStep
from pipflow.baselines.skills import Skill
from pipflow.suggest import did_you_mean_clause

GRAMMAR = r"""
step: INT "." robots ":" action
robots: NAME ("," NAME)*
action: "(" NAME NAME* ")"
NAME: /[A-Za-z_][A-Za-z0-9_\-]*/
%import common.INT
%ignore /[ \t]+/
"""
#: how a terminal the grammar expected is said in a message
EXPECTED = {"INT": "a step number", "DOT": "'.' after the step number", "COLON": "':' after the robots",
            "NAME": "a name", "LPAR": "'(' before the action", "RPAR": "')'", "COMMA": "',' between robots",
            "$END": "the end of the line"}
#: the line that opens the plan (it ends with the word PLAN and a colon: "PLAN:", "Here is the plan:"),
#: and the one that may close it (markdown emphasis allowed around)
MARK = re.compile(r"^[^\n]*\bPLAN[ \t*]*:[ \t*]*$", re.IGNORECASE | re.MULTILINE)
END = re.compile(r"^[ \t#*]*END[ \t.*]*$", re.IGNORECASE)
FENCE = re.compile(r"^[ \t]*```")
LEADING_NUMBER = re.compile(r"^[ \t]*(\d+)[ \t]*\.")
FORM = "`N. ROBOT, ROBOT: (ACTION ARG ...)`"


@lru_cache(maxsize=1)
def _parser() -> Any:
    from lark import Lark  # deferred: pulls lark (only a CoT answer needs it)

    return Lark(GRAMMAR, start="step", parser="lalr")


def _expected(names: set[str]) -> str:
    said = sorted({EXPECTED.get(n, repr(n)) for n in names})
    return " or ".join(said) if said else "nothing more"


def _line_issue(exc: Exception, line_no: int, line: str) -> Issue:
    """A lark error on one line as an issue of the whole answer."""
    from lark.exceptions import UnexpectedCharacters, UnexpectedEOF, UnexpectedToken  # deferred: pulls lark

    column = int(getattr(exc, "column", 0) or 0)
    if isinstance(exc, UnexpectedToken):
        found = "the end of the line" if exc.token.type == "$END" else repr(str(exc.token))
        if exc.token.type == "$END":
            column = len(line.rstrip()) + 1
        return Issue(line_no, column, f"expected {_expected(set(exc.expected))}, found {found}; a plan line is {FORM}")
    if isinstance(exc, UnexpectedCharacters):
        return Issue(line_no, column, f"unexpected {line[column - 1]!r}: expected "
                                      f"{_expected(set(exc.allowed or ()))}; a plan line is {FORM}")
    if isinstance(exc, UnexpectedEOF):
        return Issue(line_no, len(line.rstrip()) + 1, f"the line ends early: expected "
                                                      f"{_expected(set(exc.expected))}; a plan line is {FORM}")
    return Issue(line_no, max(column, 1), f"{exc}; a plan line is {FORM}")


def read_cot(text: str, skills: list[Skill]) -> list[RobotStep]:
    """The robot plan of a CoT answer; :class:`Unreadable` lists every problem located."""
    from lark.exceptions import UnexpectedInput  # deferred: pulls lark

    marks = list(MARK.finditer(text))
    if not marks:
        raise Unreadable([Issue(1, 1, "the answer has no line `PLAN:`: write your reasoning, then a line PLAN: "
                                      f"and the plan, one action per line as {FORM}, then a line END")])
    mark = marks[-1]  # a model that drafts and corrects itself puts its answer last
    first_line = text.count("\n", 0, mark.start()) + 1
    lines = text.split("\n")
    by_name = {s.action.lower(): s for s in skills}
    issues: list[Issue] = []
    rows: list[tuple[int, int, int, list[str], str, list[str]]] = []  # line, column of N, N, robots, action, args
    for line_no in range(first_line + 1, len(lines) + 1):
        line = lines[line_no - 1]
        if END.match(line):
            break
        if not line.strip() or FENCE.match(line):
            continue
        try:
            tree = _parser().parse(line)
        except UnexpectedInput as exc:
            issues.append(_line_issue(exc, line_no, line))
            number = LEADING_NUMBER.match(line)  # its step still counts, so the numbering check does not
            if number:                            # repeat the problem on the lines after it
                rows.append((line_no, 0, int(number.group(1)), [], "", []))
            continue
        number, robots_tree, action_tree = tree.children
        names = [str(t) for t in action_tree.children]
        action, args = names[0], names[1:]
        skill = by_name.get(action.lower())
        at = line.index("(") + 2
        if skill is None:
            issues.append(Issue(line_no, at, f"{action!r} is not an action of the domain (its actions: "
                                             f"{', '.join(s.pddl() for s in skills)}){did_you_mean_clause(action, by_name)}"))
            continue
        if len(args) != len(skill.params):
            issues.append(Issue(line_no, at, f"{skill.pddl()} takes {len(skill.params)} argument"
                                             f"{'s' if len(skill.params) != 1 else ''}, got {len(args)}: "
                                             f"{snippet(line.strip())}"))
            continue
        rows.append((line_no, number.column, int(number), [str(r) for r in robots_tree.children], skill.action, args))
    rows_read = [r for r in rows if r[4]]
    if not rows_read and not issues:
        issues.append(Issue(first_line, 1, f"the plan after `PLAN:` has no step: write one action per line as {FORM}"))
    previous = 0
    for line_no, column, n, _, action, _ in rows:
        if not action:  # a line whose problem is said already: only its number counts
            previous = max(previous, n)
            continue
        if n not in (previous, previous + 1) or n == 0:
            want = "1" if previous == 0 else f"{previous} or {previous + 1}"
            issues.append(Issue(line_no, column, f"step {n} follows step {previous or 'nothing'}: expected step {want} "
                                                 "(number the steps 1, 2, 3, ...; repeat a number for actions at the "
                                                 "same time)"))
        previous = max(previous, n)
    if issues:
        raise Unreadable(issues)
    steps: list[RobotStep] = []
    by_step: dict[int, list[str]] = {}
    for k, (line_no, _, n, robots, action, args) in enumerate(rows_read, 1):
        sid = f"a{k}"
        steps.append(RobotStep(sid, action, args, robots, list(by_step.get(n - 1, [])), f"line {line_no}"))
        by_step.setdefault(n, []).append(sid)
    return steps

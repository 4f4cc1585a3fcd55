"""How much work a PDDL problem text asks of the parser, measured before any parser reads it.

Why: unified-planning's reader (pyparsing) and the checks after it take time in proportion to
what a text declares. A model's answer of 270 KB (under the 512 KB answer cap) with 40,000 extra
objects cost 32 s in ``generate`` and 156 s in ``debug`` per round of the refinement loop, and a
deep enough nesting of parentheses exhausts the parser's recursion. No problem of a world needs
more objects, facts or nesting than the world has: :func:`size_issues` compares one linear scan
of the text (:func:`measure`) with what a problem of this world holds (the domain's own example
problem, :meth:`pipflow.taskdomain.TaskDomain.example_problem`), and says, in words a model can
act on, what to leave out. The generator and the debugger refuse such a text without parsing it;
the message goes back to the model as feedback for its next round.
"""
from __future__ import annotations

import re
from dataclasses import dataclass
from decimal import Decimal, InvalidOperation

#: nesting of parentheses a problem may use (this domain's deepest form needs about 6)
MAX_NESTING = 40
#: a problem may declare this many times the objects and facts a problem of its world has ...
SLACK_FACTOR = 2
#: ... plus this many (room for a model's own names and an unusual goal)
SLACK = 100
#: without a world to compare with, the most objects, facts and goal forms a problem may have
ABSOLUTE = 200_000
#: the largest number a problem may state (as for world files: :data:`pipflow.worldfile.LARGEST_NUMBER`);
#: unified-planning reads ``1e400`` as an exact integer of 400 digits, which every later
#: conversion to a float overflows ("int too large to convert to float", a crash of the step)
MAX_NUMBER = 10**9
_NUMBER = re.compile(r"(?<![\w.?-])[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?(?![\w.])")


@dataclass(frozen=True)
class ProblemSize:
    """What a problem text declares: objects, facts of ``:init``, forms of ``:goal``, and the
    deepest nesting of parentheses."""

    objects: int = 0
    facts: int = 0
    goal: int = 0
    nesting: int = 0


_SECTION = re.compile(r"\(\s*:(objects|init|goal)\b", re.IGNORECASE)


def measure(text: str) -> ProblemSize:
    """One pass over ``text`` (comments dropped): no parser, no recursion, linear in its length."""
    text = re.sub(r";[^\n]*", "", text)
    depth = nesting = 0
    counts = {"objects": 0, "init": 0, "goal": 0}
    section: str | None = None   # the section open at depth ``section_depth``
    section_depth = 0
    typed = False                # the word after "-" in :objects is a type, not an object
    i, n = 0, len(text)
    while i < n:
        ch = text[i]
        if ch == "(":
            if section == "objects":  # no form inside (:objects: it was never closed (the parser says so)
                section = None
            m = _SECTION.match(text, i) if section is None else None
            depth += 1
            nesting = max(nesting, depth)
            if m:
                section, section_depth = m.group(1).lower(), depth
                i = m.end()
                continue
            if section in ("init", "goal") and (section == "goal" or depth == section_depth + 1):
                counts[section] += 1  # a fact of :init (its own parentheses), every form of :goal
        elif ch == ")":
            if section is not None and depth == section_depth:
                section = None
            depth -= 1
        elif section == "objects" and not ch.isspace():
            end = i
            while end < n and not text[end].isspace() and text[end] not in "()":
                end += 1
            word = text[i:end]
            if word == "-":
                typed = True
            elif typed:
                typed = False
            else:
                counts["objects"] += 1
            i = max(end, i + 1)
            continue
        i += 1
    return ProblemSize(counts["objects"], counts["init"], counts["goal"], nesting)


def expected_size(world: dict | None, example: str | None) -> ProblemSize | None:
    """What a problem of ``world`` holds: its domain's ``example`` problem measured; without one,
    the world's names (the entries of its sections) as objects, the facts and goal unbounded
    but by :data:`ABSOLUTE`; None without a world."""
    if example:
        return measure(example)
    if not isinstance(world, dict):
        return None
    names = sum(len(v) for v in world.values() if isinstance(v, dict))
    return ProblemSize(objects=names, facts=ABSOLUTE, goal=ABSOLUTE)


def number_issues(text: str, what: str = "your problem") -> list[str]:
    """Numbers of ``text`` larger than :data:`MAX_NUMBER` (``1e400``, a 30-digit count), as
    messages for the model; read as decimals, so no number overflows while it is checked."""
    out: list[str] = []
    for m in _NUMBER.finditer(re.sub(r";[^\n]*", "", text)):
        try:
            value = Decimal(m.group(0))
        except InvalidOperation:
            continue
        if not value.is_finite() or abs(value) > MAX_NUMBER:
            shown = m.group(0) if len(m.group(0)) <= 24 else m.group(0)[:20] + "..."
            out.append(f"{what} states the number {shown}; no count or amount in this world is larger than "
                       f"{MAX_NUMBER:,}: write the count the command asks for")
            if len(out) >= 3:
                break
    return out


def size_issues(text: str, expected: ProblemSize | None = None, what: str = "your problem") -> list[str]:
    """What is too large in ``text`` compared with ``expected`` (a problem of the same world),
    as messages for the model; ``[]`` when nothing is. Without ``expected``, only the nesting and
    the absolute bounds are checked. Numbers beyond :data:`MAX_NUMBER` are refused too
    (:func:`number_issues`)."""
    got = measure(text)
    out: list[str] = number_issues(text, what)
    if got.nesting > MAX_NESTING:
        out.append(f"{what} nests parentheses {got.nesting} deep; a problem of this domain needs at most "
                   f"{MAX_NESTING} levels: write each fact and goal condition flat")
    bound = (lambda k: ABSOLUTE) if expected is None else (lambda k: min(ABSOLUTE, SLACK_FACTOR * k + SLACK))
    need_objects = bound(expected.objects if expected else 0)
    if got.objects > need_objects:
        out.append(f"{what} declares {got.objects} objects; a problem of this world needs about "
                   f"{expected.objects if expected else 'far fewer'} (at most {need_objects}): declare only the "
                   "world's own names (its places, things and amounts)")
    need_facts = bound(expected.facts if expected else 0)
    if got.facts > need_facts:
        out.append(f"{what} states {got.facts} facts in :init; the world's state has about "
                   f"{expected.facts if expected else 'far fewer'} (at most {need_facts}): state only the world's "
                   "facts, each once")
    need_goal = bound((expected.facts + expected.objects) if expected else 0)
    if got.goal > need_goal:
        out.append(f"{what} has {got.goal} forms in :goal, more than any goal of this world needs (at most "
                   f"{need_goal}): state only what the command asks for")
    return out

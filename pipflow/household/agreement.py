"""The household's second opinion on a model's reading: its goal conditions (objects in places,
states of things) against the household translator's reading of the command, or, when the
translator does not read the command, the doubts the command's names raise about it.

A model that writes (at apple fridge) for "Put the apple and the tomato in the fridge." passes
the debugger, the planner and the verifier; only a reading of the command sees the tomato left
out. What is generic (firm versus loose, when a refusal is final, never handing the reading to the
model) is :mod:`pipflow.language.agreement`; this module knows conditions, categories and counts.
"""
from __future__ import annotations

import re
from typing import Any

from pipflow.household.scoring import holds
from pipflow.household.world import initial_state, members
from pipflow.language.agreement import Finding, Opinion, judge, remembered_reading, words_note


def _read(command: str, world: dict) -> dict:
    """The translator's reading: the goal as the command states it (counts kept) and the words
    each condition comes from."""
    # deferred: builds the lark parser (~150 ms; only a check of a model's reading needs it)
    from pipflow.household.language.translator import translate

    got = translate(command, world)
    return {"goal": got["goal"], "words": got.get("words") or {}}


def _where(goal: dict) -> dict[str, str]:
    """Object -> the place a goal puts it."""
    return {o: place for place, objs in (goal.get("in") or {}).items() for o in objs or []}


def _required_in(reading: dict, world: dict, obj: str, place: str) -> bool:
    """The reading asks for ``obj`` in ``place``: by name, or as one of a count of its category."""
    goal = reading["goal"]
    if obj in (goal.get("in") or {}).get(place, []):
        return True
    return any(c.get("in") == place and obj in members(world, c.get("category")) for c in goal.get("count") or [])


def _rule_in_words(rule: dict) -> str:
    """A rule of the model's own, in words (it is the model's value, not the reading's)."""
    kind = "only" if "only" in rule else "never"
    robots = rule.get(kind)
    robots = [robots] if isinstance(robots, str) else list(robots or [])
    scope = ", ".join(f"{k} {v}" for k, v in rule.items() if k not in (kind, "words") and v not in (None, "any"))
    return f"{kind} {', '.join(map(str, robots))}" + (f" ({scope})" if scope else "")


def compare_with_reading(command: str, goal: dict, constraints: list, reading: dict, world: dict) -> list[Finding]:
    """Where the model's goal conditions and rules differ from the reading. A condition the
    reading does not have is no disagreement when it already holds (a model may restate what
    stays). The messages name the object or thing and quote the command's words; the place or
    state the reading asks for stays in ``said``. The translator reads no robot rules, so a
    command it reads states none: every rule of the model's is one the command does not state."""
    want, words = reading["goal"], reading.get("words") or {}
    start = initial_state(world)
    placed = _where(goal)
    stated = {n: set(c or []) for n, c in (goal.get("state") or {}).items()}
    found: list[Finding] = []
    for place, objs in (want.get("in") or {}).items():
        for o in objs or []:
            if placed.get(o) == place:
                continue
            note = words_note((words.get("in") or {}).get(o) or command)
            found.append(Finding(
                f"the command puts {o} in {place}; the model's goal "
                + (f"puts it in {placed[o]}" if o in placed else "does not place it"),
                f"your goal does not put the {o} where the command asks {note}"))
    for name, conds in (want.get("state") or {}).items():
        for c in conds or []:
            if c in stated.get(name, set()):
                continue
            note = words_note(((words.get("state") or {}).get(name) or {}).get(c) or command)
            found.append(Finding(f"the command asks for {name} {c}; the model's goal does not",
                                 f"your goal leaves out a condition the command asks of the {name} {note}"))
    for count in want.get("count") or []:
        cat, place, least = count.get("category"), count.get("in"), int(count.get("at_least", 0))
        there = [o for o in members(world, cat) if placed.get(o, start["at"].get(o)) == place]
        if len(there) < least:
            found.append(Finding(f"the command asks for at least {least} {cat} in {place}; the model's goal "
                                 f"ends with {len(there)}",
                                 f"your goal puts fewer {cat} in the {place} than the command asks "
                                 f"{words_note(command)}"))
    asked = _where(want)
    for o, place in sorted(placed.items()):
        if o not in asked and start["at"].get(o) != place and not _required_in(reading, world, o, place):
            found.append(Finding(f"the model's goal moves {o} to {place}; the command does not ask for that",
                                 f"your goal moves the {o}, which the command does not ask for"))
    for name, conds in sorted(stated.items()):
        for c in sorted(conds - set((want.get("state") or {}).get(name) or [])):
            if not holds(start, name, c):
                found.append(Finding(f"the model's goal makes {name} {c}; the command does not ask for that",
                                     f"your goal makes the {name} {c}, which the command does not ask for"))
    for rule in constraints or []:
        found.append(Finding(f"the model's rule {rule} is not in the command",
                             f"your rule '{_rule_in_words(rule)}' is not one the command states"))
    return found


def _named(command: str, world: dict) -> list[str]:
    """The world's places and objects whose names the command spells (as whole words)."""
    text = command.lower()
    return [n for n in [*world.get("places", {}), *world.get("objects", {})]
            if re.search(rf"(?<![\w-]){re.escape(n.lower())}(?![\w-])", text)]


def doubts_from_words(command: str, goal: dict, world: dict) -> list[str]:
    """A place or object the command names that the goal says nothing of (neither where it ends,
    nor what is put in it, nor its state). Words are no reading (a named thing may be where
    something is taken from): doubts, never feedback."""
    mentioned = set(goal.get("state") or {}) | set(goal.get("in") or {}) | set(_where(goal))
    return [f"the command names the {n}; the goal says nothing of it" for n in _named(command, world)
            if n not in mentioned]


def second_opinion(command: str, world: dict, goal: Any, constraints: list | None, verifier_refusal: str | None,
                   last: bool = False) -> Opinion:
    """The model's goal conditions against the command's (see
    :func:`pipflow.language.agreement.judge`)."""
    goal = goal if isinstance(goal, dict) else {}
    reading = remembered_reading(command, world, _read, "household")
    return judge(reading, lambda data: compare_with_reading(command, goal, constraints or [], data, world),
                 lambda: doubts_from_words(command, goal, world), verifier_refusal, last)

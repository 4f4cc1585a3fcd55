"""Clauses that say where a thing already is ("heat the curry up, it's in the fridge", "slice the
cheese, cheese is in the fridge", "chuck the banana skin, it's on the high chair").

People tell the robots where to find a thing. Such a clause asks for nothing, but it is no
content-free aside: it names the world. It is set aside (and echoed) only when the world agrees:
the thing it is about (named, or "it"/"they": the things of the nearest clause before it that
names things) is in that place now. A clause the world does not agree with is kept, and the
command is asked about, never read as if the speaker had not said it.
"""
from __future__ import annotations

from pipflow.household.language.names import world_phrases

#: how a restating clause's subject is joined to its place: "it is in", "they are still on"
BE = {"is", "are"}
#: words between "is" and the place that do not change where the thing is said to be
STILL = {"still", "already", "just", "now", "all", "over", "sat", "sitting", "lying", "left", "in", "there"}
#: prepositions of where a thing lies
AT = {"in", "on", "inside", "at"}
#: words that open a noun phrase and name nothing
DETERMINERS = {"the", "my", "our", "your", "his", "her", "their", "that", "this", "those", "these"}
PRONOUNS = {"it", "they", "them", "those", "these"}
#: the longest name of a thing, in words
LONGEST = 4


def _things(words: tuple[str, ...], index: dict, kind: str) -> list[str]:
    """The names of ``kind`` ("object", "place") that a word sequence mentions (longest first)."""
    found: list[str] = []
    k = 0
    while k < len(words):
        for n in range(min(LONGEST, len(words) - k), 0, -1):
            readings = index.get(tuple(words[k:k + n]))
            if readings:
                found += [r["name"] for r in readings if r["kind"] == kind]
                k += n
                break
        else:
            k += 1
    return list(dict.fromkeys(found))


def _exactly(words: tuple[str, ...], index: dict, kind: str) -> list[str]:
    """The names of ``kind`` that a noun phrase names as a whole ("the high chair")."""
    while words and words[0] in DETERMINERS:
        words = words[1:]
    return [r["name"] for r in index.get(tuple(words), []) if r["kind"] == kind]


#: words of time that may close a restating clause ("... on the stove from yesterday")
SINCE = {"from", "since", "yesterday", "last", "night", "this", "morning", "earlier", "all", "day", "today",
         "tonight", "again", "week", "lunch", "breakfast", "dinner", "tea",
         "monday", "tuesday", "wednesday", "thursday", "friday", "saturday", "sunday", "weekend", "the"}


def _place(words: list[str], index: dict) -> list[str]:
    """The place a phrase names as a whole, allowing a closing phrase of time ("the stove from
    yesterday")."""
    for end in range(len(words), 0, -1):
        if all(w in SINCE for w in words[end:]):
            found = _exactly(tuple(words[:end]), index, "place")
            if found:
                return found
    return []


def leading_subject(clause: tuple[str, ...], world: dict) -> tuple[str, ...] | None:
    """The words naming the thing of a first clause that says where that thing is, as the world
    has it ("the frying pan is still sat on the stove, can you get it washed"): the next clause's
    "it" means it. None when the clause is no such restatement (its subject a pronoun, or the
    world disagrees)."""
    be = next((k for k, w in enumerate(clause) if w in BE), None)
    if not be or (be == 1 and clause[0] in PRONOUNS) or restates_location(clause, [], world) is None:
        return None
    return clause[:be]


def restates_location(clause: tuple[str, ...], before: list[tuple[str, ...]], world: dict) -> str | None:
    """What a clause restates ("curry is in fridge"), when it says where a thing is and the world
    agrees (module docstring); None otherwise. ``before``: the clauses before it, in order."""
    # "it is on the table", "it has been on the table since Sunday"
    be = next((k for k, w in enumerate(clause) if w in BE or (w == "been" and k and clause[k - 1] in ("has", "have"))),
              None)
    if not be:
        return None
    subject, rest = clause[:be - (clause[be] == "been")], list(clause[be + 1:])
    while len(rest) > 1 and rest[0] in STILL and rest[1] not in DETERMINERS:
        rest = rest[1:]
    if len(rest) < 2 or rest[0] not in AT:
        return None
    index = world_phrases(world)
    place = _place(rest[1:], index)
    if len(place) != 1:
        return None
    if len(subject) == 1 and subject[0] in PRONOUNS:
        things = next((t for t in (_things(c, index, "object") for c in reversed(before)) if t), [])
        holds = bool(things) and all(world["objects"][t]["in"] == place[0] for t in things)
    else:
        things = [t for t in _exactly(subject, index, "object") if world["objects"][t]["in"] == place[0]]
        holds = bool(things)
    return f"{', '.join(things)} in {place[0]}" if holds else None

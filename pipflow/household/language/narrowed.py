"""An order narrowed after it is said: "do the pots, just the plate and the saucepan" (issue 23).

"Just" before things is "only": the order is for those things alone. Dropped as talk, as "just"
before a verb is ("just wash it"), it would widen the order to every pot: a misreading. So "just"
opening a clause before things is read as "only" (:func:`just_as_only`), and "only" there narrows
the clause before it (:func:`narrowed_by_only`) where every thing it names is among what that
clause names (members of its category, or the things its words name); else the words stay as
said, and the command is refused on "only".
"""
from __future__ import annotations

from pipflow.household.language.names import name_end, objects_named
from pipflow.household.language.tokens import PUNCT

#: what may follow a clause-opening "just" that restricts ("..., just the plate and the pan")
_RESTRICTED = frozenset({"the", "my", "our", "that", "this", "those", "these", "his", "her", "a", "one"})
#: determiners before a thing's name
_DETERMINERS = frozenset({"the", "my", "our", "that", "this", "those", "these", "his", "her", "their", "your"})
#: words that may close the narrowing clause after its things ("just the plate mind", "... please")
_CLOSERS = frozenset({"mind", "please", "pls", "thanks", "ta", "then"})


def just_as_only(words: list[str], notes: list[str]) -> list[str]:
    """ "do the pots, just the plate and the saucepan": "just" opening a clause before things is
    "only", never talk to drop ("just wash it" stays a softener)."""
    out = list(words)
    for k, w in enumerate(words):
        if w == "just" and k and words[k - 1] in PUNCT and k + 1 < len(words) and words[k + 1] in _RESTRICTED:
            notes.append("'just' before the things of a clause: 'only'")
            out[k] = "only"
    return out


def narrowed_by_only(words: list[str], world: dict, index: dict, notes: list[str]) -> list[str]:
    """ "wash the pots, only the plate and the saucepan": a clause of "only" and things, after a
    clause whose words name a group they all belong to, is that clause for those things alone (the
    group's words replaced by theirs). Where the group is not found, or a thing is not in it, the
    words stay as said (refused on "only")."""
    k = next((i for i, w in enumerate(words) if w == "only" and i and words[i - 1] in PUNCT), None)
    if k is None:
        return words
    things, end = _listed(words, k + 1, index)
    if not things:
        return words
    start = max((i for i in range(k - 1) if words[i] in PUNCT), default=-1) + 1
    group = _group_of(words, start, k - 1, things, world, index)
    if group is None:
        return words
    a, b = group
    listed: list[str] = []
    for x, y in things:
        listed += (["and"] if listed else []) + ["the"] + words[x:y]
    notes.append(f"'{' '.join(words[a:b])}', only {' '.join(listed)}: read for those alone")
    return words[:a] + listed + words[b:k - 1] + words[end:]


def _listed(words: list[str], k: int, index: dict) -> tuple[list[tuple[int, int]], int]:
    """The things of a list at ``k`` ("the plate and the saucepan") as (start, end) of each name,
    and where the list ends (its clause's end, after any closing word); ([], k) where a word of it
    names nothing of the home."""
    found: list[tuple[int, int]] = []
    while k < len(words) and words[k] not in PUNCT and words[k] not in _CLOSERS:
        if words[k] in _DETERMINERS or (found and words[k] == "and"):
            k += 1
            continue
        end = name_end(words, k, index)
        if not end:
            return [], k
        found.append((k, end))
        k = end
    while k < len(words) and words[k] in _CLOSERS:
        k += 1
    return found, k


def _group_of(words: list[str], start: int, stop: int, things: list[tuple[int, int]], world: dict,
              index: dict) -> tuple[int, int] | None:
    """(start, end) of the one phrase of ``words[start:stop]`` that names a group every listed
    thing belongs to (with its determiners); None where there is no such phrase, or several."""
    members = [objects_named(index[tuple(words[x:y])], world) for x, y in things]
    found = []
    a = start
    while a < stop:
        b = name_end(words, a, index, stop)
        if not b:
            a += 1
            continue
        group = objects_named(index[tuple(words[a:b])], world)
        if len(group) > 1 and all(m and m <= group for m in members):
            first = a
            while first > start and words[first - 1] in _DETERMINERS | {"all"}:
                first -= 1
            found.append((first, b))
        a = b
    return found[0] if len(found) == 1 else None

"""A thing named by what it is and where it is, where the home's own word for it says both: "the
light in the kitchen" for the kitchen light, "the fan in the living room" for the living room fan,
"the water heater in the common toilet" for the common toilet water heater.

The home model has no rooms: a room lives only in the words of the things in it. A thing said with
a phrase of where after it ("in the kitchen") is its word with the where before it ("kitchen
light"), read so only where that word is the home's name of exactly one thing; anything else is
left as said ("the plate in the sink" stays the plate that lies in the sink).

A where said with whose room it is ("the water heater in our toilet", "the fan in ah ma's room")
is the thing the home calls by the owner and the thing ("our water heater", "ah ma's fan"), where
that is one thing, and the room's words are in another of its names ("master toilet water heater")
or are only "room" or "bedroom".

A room said as where one thing is taken from ("fetch me Barnsley mug through from the front room,
stick it on the side") names that thing's room, which the home model does not have: where the
thing said names exactly one thing, and the room's words open a longer name of the home ("front
room light"), the words are set aside (a note says so); they pick nothing out.
"""
from __future__ import annotations

from pipflow.household.language.names import one_thing
from pipflow.household.language.people import owner_at
from pipflow.household.language.restated import DETERMINERS

#: prepositions that say where a thing is
_WHERE = frozenset({"in", "at", "on", "from"})
#: the most words of the thing, and of its where
_LONGEST = 3
#: words that say whose room it is
_POSSESSIVES = frozenset({"my", "our", "your", "his", "her"})
#: words of a room that say no more than whose it is ("ah ma's room")
_ANY_ROOM = frozenset({("room",), ("bedroom",)})


def _owned_room(out: list[str], k: int, a: int, e: int, index: dict, people: dict) -> tuple[list[str], int] | None:
    """The home's name and the where's end for "<thing> in <owner> <room>" (module docstring), the
    thing ``out[a:e]``; or None."""
    n = 1 if k + 1 < len(out) and out[k + 1] in _POSSESSIVES else owner_at(out, k + 1, people)
    name = out[k + 1:k + 1 + n] + out[a:e]
    if not n or not one_thing(index, name):
        return None
    thing = index[tuple(name)][0]["name"]
    others = [key for key, refs in index.items() if any(ref["name"] == thing for ref in refs)]
    for m in (2, 1):
        room = tuple(out[k + 1 + n:k + 1 + n + m])
        if len(room) == m and (room in _ANY_ROOM or any(
                any(key[i:i + m] == room for i in range(len(key))) for key in others)):
            return name, k + 1 + n + m
    return None


def where_as_name(words: list[str], index: dict, notes: list[str], people: dict | None = None) -> list[str]:
    """The words with each "<thing> in <where>" that the home names as "<where> <thing>", or as
    "<owner> <thing>", said so (module docstring). ``index``: the home's phrases
    (:func:`~.names.world_phrases`); ``people``: its owners (:func:`~.people.owners`)."""
    out = list(words)
    k = 1
    while k < len(out):
        if out[k] not in _WHERE:
            k += 1
            continue
        j = k + 1 + (k + 1 < len(out) and out[k + 1] in DETERMINERS)   # "in our kitchen": the kitchen
        # a name of the home that opens the where is said whole ("from the coffee table" is no
        # "coffee" where a coffee mug is)
        whole = max((n for n in range(1, _LONGEST + 3) if tuple(out[j:j + n]) in index), default=0)
        # "turn the heater on in the lounge": the switch's particle between the thing and its where
        e = k - 1 if out[k] == "in" and out[k - 1] in ("on", "off") else k
        found = None
        for a in range(max(0, e - _LONGEST), e):   # the longest thing first
            owned = _owned_room(out, k, a, e, index, people or {})
            if owned:
                found = (a, owned[1], owned[0])
                break
            thing = out[a:e]
            for m in range(min(len(out), j + _LONGEST), max(j, j + whole - 1), -1):   # the longest where first
                if one_thing(index, out[j:m] + thing):
                    found = (a, m, out[j:m] + thing)
                    break
            if found:
                break
        if found is None:
            k += 1
            continue
        a, m, name = found
        whole = _said_whole(out, a, e, name, index)
        if whole is not None:   # "the big fan in the living room": the big fan, which is the living room fan
            notes.append(f"'{' '.join(out[whole:m])}' read as the {' '.join(out[whole:e])} (the where names it again)")
            out[whole:m] = out[whole:e] + out[e:k]   # what follows the where now stands at k
            continue
        if name[0] in _POSSESSIVES and a and out[a - 1] == "the":   # "the water heater in our toilet"
            a -= 1
        notes.append(f"'{' '.join(out[a:m])}' read as the {' '.join(name + out[e:k])} (the home's word for it)")
        out[a:m] = name + out[e:k]
        k = a + len(name) + k - e
    return out


def _said_whole(out: list[str], a: int, e: int, name: list[str], index: dict) -> int | None:
    """Where a longer name of the same thing opens before the thing's last words ``out[a:e]``
    ("the *big fan* in the living room", where the home calls its ceiling fan both "big fan" and
    "living room fan"): the where then names it again, and is left out; None where no such name
    is said (the where picks the thing out, and is read as its name)."""
    meant = {ref["name"] for ref in index.get(tuple(name), [])}
    for start in range(max(0, e - _LONGEST), a):
        said = out[start:e]
        if one_thing(index, said) and {ref["name"] for ref in index[tuple(said)]} == meant:
            return start
    return None


#: what may follow a room said as where a thing comes from: the clause goes on with where it goes,
#: or ends
_AFTER_A_ROOM = frozenset({",", ".", ";", "!", "?", "and", "then", "to", "into", "onto", "on", "in"})


def rooms_things_come_from(words: list[str], index: dict, notes: list[str]) -> list[str]:
    """The words without a room said as where one thing comes from (module docstring): "(through)
    from the <room>" after words that name exactly one thing, the room's words naming nothing here
    but opening a longer name of the home. Where the thing said may be several things, the room
    is left as said (it may be what picks one out), and refused."""
    out = list(words)
    k = 1
    while k < len(out):
        if out[k] != "from":
            k += 1
            continue
        j = k + 1 + (k + 1 < len(out) and out[k + 1] in DETERMINERS)
        room = next((m for m in (2, 1) if j + m <= len(out) and tuple(out[j:j + m]) not in index
                     and any(len(key) > m and key[:m] == tuple(out[j:j + m]) for key in index)
                     and (j + m == len(out) or out[j + m] in _AFTER_A_ROOM)), 0)
        start = k - (out[k - 1] == "through")
        thing = next((out[a:start] for a in range(max(0, start - _LONGEST), start) if one_thing(index, out[a:start])), None)
        if not room or thing is None:
            k += 1
            continue
        notes.append(f"'{' '.join(out[start:j + room])}' set aside: the room the {' '.join(thing)} is in "
                     "(the home model has no rooms)")
        del out[start:j + room]
        k = start
    return out

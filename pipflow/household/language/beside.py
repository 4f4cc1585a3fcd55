"""A thing put "beside" or "next to" another, as where that other thing lies (issue 23).

"put the bread out on the table beside the butter", "put it on the cooktop next to the pot": the
home model has places and what lies in them, no spot within a place, so where the other thing
lies is all that "beside" can say. After a place that holds it, the phrase says nothing more and
is set aside; said alone after a placing ("put his biscuits out beside the bowl"), it is read as
that thing's place. A thing that lies nowhere (a place: "beside the fridge") or in another place
than the one said leaves the words as they are, to be refused: nothing is guessed."""
from __future__ import annotations

from pipflow.household.language.lexicon import words_of
from pipflow.household.language.names import longest_name
from pipflow.household.language.restated import DETERMINERS
from pipflow.household.language.rewrites import PLACING, clause_before

#: how "beside" is said: the words, longest first
_BESIDE = (("next", "to"), ("beside",), ("by",), ("alongside",))
#: verbs after which "beside <thing>" says where a thing goes: those that place it, and setting or
#: leaving it ("leave the juice beside the novel")
_GOES = PLACING | {"set", "leave"}
#: prepositions of a place a thing is put in or on
_ONTO = {"on", "onto", "in", "into"}


def beside_as_where(words: list[str], world: dict, index: dict, notes: list[str]) -> list[str]:
    """The words with each "beside / next to <thing>" read as above (module docstring). ``index``:
    the world's phrases (:func:`pipflow.household.language.names.world_phrases`)."""
    objects = world.get("objects") or {}
    longest = longest_name(index)
    out: list[str] = []
    k = 0
    while k < len(words):
        said = next((b for b in _BESIDE if tuple(words[k:k + len(b)]) == b), None)
        thing = _thing_at(words, k + len(said), index, longest, objects) if said else None
        if thing is None:
            out.append(words[k])
            k += 1
            continue
        name, end = thing
        where = objects[name]["in"]
        before = _place_before(out, index, longest)
        if before == where:   # "on the table beside the butter": the table says it all
            notes.append(f"'{' '.join(words[k:end])}': {name} is in {where}; the home model has no spot "
                         f"within a place, so it says nothing more")
        elif before is None and _GOES & set(clause_before(out)):   # "put his biscuits out beside the bowl"
            notes.append(f"'{' '.join(words[k:end])}' read as in {where}, where {name} is")
            out += ["in", *words_of(where)]
        else:
            out.append(words[k])
            k += 1
            continue
        k = end
    return out


def _thing_at(words: list[str], i: int, index: dict, longest: int, objects: dict) -> tuple[str, int] | None:
    """(the one object the phrase at ``i`` names, where the phrase ends), else None."""
    while i < len(words) and words[i] in DETERMINERS:
        i += 1
    for n in range(min(longest, len(words) - i), 0, -1):
        readings = index.get(tuple(words[i:i + n]))
        if readings:
            names = {r["name"] for r in readings}
            if len(names) == 1 and next(iter(names)) in objects:
                return next(iter(names)), i + n
            return None
    return None


def _place_before(out: list[str], index: dict, longest: int) -> str | None:
    """The place named just before (after "on" / "in" and its determiners, at the clause's end),
    else None."""
    end = len(out)
    while end and out[end - 1] in (",", "out", "down"):
        end -= 1
    for n in range(min(longest, end), 0, -1):
        readings = index.get(tuple(out[end - n:end]))
        if not readings:
            continue
        start = end - n
        while start and out[start - 1] in DETERMINERS:
            start -= 1
        names = {r["name"] for r in readings if r.get("kind") == "place"}
        if start and out[start - 1] in _ONTO and len(names) == 1:
            return next(iter(names))
        return None
    return None


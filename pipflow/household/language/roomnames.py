"""A thing named by what it is and where it is, where the home's own word for it says both: "the
light in the kitchen" for the kitchen light, "the fan in the living room" for the living room fan,
"the water heater in the common toilet" for the common toilet water heater.

The home model has no rooms: a room lives only in the words of the things in it. A thing said with
a phrase of where after it ("in the kitchen") is its word with the where before it ("kitchen
light"), read so only where that word is the home's name of exactly one thing; anything else is
left as said ("the plate in the sink" stays the plate that lies in the sink).
"""
from __future__ import annotations

from pipflow.household.language.restated import DETERMINERS

#: prepositions that say where a thing is
_WHERE = frozenset({"in", "at", "on", "from"})
#: the most words of the thing, and of its where
_LONGEST = 3


def _one_thing(index: dict, words: list[str]) -> bool:
    """Whether the words are the home's name of one thing, said in the singular ("the lights in the
    kitchen" may be every light there: left as said, and asked)."""
    refs = index.get(tuple(words), [])
    return len({ref["name"] for ref in refs}) == 1 and not any(ref.get("plural") for ref in refs)


def where_as_name(words: list[str], index: dict, notes: list[str]) -> list[str]:
    """The words with each "<thing> in <where>" that the home names as "<where> <thing>" said so
    (module docstring). ``index``: the home's phrases (:func:`~.names.world_phrases`)."""
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
        found = None
        for a in range(max(0, k - _LONGEST), k):   # the longest thing first
            thing = out[a:k]
            for m in range(min(len(out), j + _LONGEST), max(j, j + whole - 1), -1):   # the longest where first
                if _one_thing(index, out[j:m] + thing):
                    found = (a, m)
                    break
            if found:
                break
        if found is None:
            k += 1
            continue
        a, m = found
        name = out[j:m] + out[a:k]
        notes.append(f"'{' '.join(out[a:m])}' read as the {' '.join(name)} (the home's word for it)")
        out[a:m] = name
        k = a + len(name)
    return out

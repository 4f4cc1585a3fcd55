""" "The big one", "the common toilet one", "papa one": a thing said by what sets it apart, with
"one" standing for the kind of thing said just before ("take the small umbrella and the big one",
"off our water heater, then on the common toilet one", "the mug there also wash, papa one").

The kind is the last word or two of a name of the home said before, where the home has a longer
name ending in them ("umbrella" of "small umbrella"), and the words with it name one thing; where
two kinds said before would each name a thing, it is left as said. "the <words> one" is read as "the
<words> <kind>"; "<owner> one" closing a clause, where the owner is one of the home's people
(:func:`~.people.owners`), says whose the thing just named is ("the mug, papa one": papa's mug).
Each only where the result is the home's name of exactly one thing said in the singular; anything
else is left as said ("the other one", "the blue one" where nothing is called blue: refused).
"the one in <where>" is "the <kind> in <where>" where one kind only was said before, and the where
says which (:mod:`~.roomnames`).
"""
from __future__ import annotations

from pipflow.household.language.names import one_thing
from pipflow.household.language.people import owner_at, owners
from pipflow.household.language.tokens import PUNCT

#: the most words said before "one" ("the common toilet one")
_LONGEST = 3
#: words before "one" that say which without naming anything of the home
_NOT_WHICH = frozenset({"the", "a", "an", "no", "each", "every", "which", "any", "that", "this", "another",
                        "other", "same", "only", "right", "wrong", "last", "first", "next", "new", "old"})
#: words that may close the clause after "<owner> one"
_CLOSING = frozenset({"and", "then", "too", "also", "pls", "please", "lah", "leh", "lor", "ah", "ok", "okay"})


def _kinds(index: dict) -> frozenset[tuple[str, ...]]:
    """The last one or two words of the home's longer names ("umbrella", "water heater")."""
    return frozenset(key[-n:] for key in index for n in (1, 2) if len(key) > n)


def _kinds_before(words: list[str], end: int, kinds: frozenset) -> list[tuple[int, int, tuple[str, ...]]]:
    """(start, stop, kind) of each kind said before ``end``, nearest first, the longer of two first;
    a plural says its kind ("all the lights except the verandah one": light)."""
    found = []
    for e in range(end - 1, -1, -1):
        for n in (2, 1):
            said = tuple(words[e - n + 1:e + 1]) if e - n + 1 >= 0 else ()
            for kind in (said[:-1] + (said[-1][:-1],) if said and said[-1].endswith("s") else (), said):
                if kind and kind in kinds:
                    found.append((e - n + 1, e + 1, kind))
                    break
    return found


def _the_thing(index: dict, said: list[str], spans: list[tuple[int, int, tuple[str, ...]]]) -> tuple[str, ...] | None:
    """The kind said before that makes ``said`` + it the name of one thing, where exactly one
    thing is so named (two kinds naming two things: left as said)."""
    named = {}
    for _, _, kind in spans:
        name = said + list(kind)
        if one_thing(index, name):
            named.setdefault(index[tuple(name)][0]["name"], kind)
    return next(iter(named.values())) if len(named) == 1 else None


def one_as_kind(words: list[str], world: dict, index: dict, notes: list[str]) -> list[str]:
    """The words with each "the <words> one" and "<owner> one" read as the thing (module
    docstring). ``index``: the home's phrases (:func:`~.names.world_phrases`)."""
    if "one" not in words:
        return words
    kinds, people = _kinds(index), owners(world, words)
    starts = {key[0] for key in index}
    out = list(words)
    k = 1
    while k < len(out):
        if out[k] != "one" or (k + 1 < len(out) and (out[k + 1] in starts or out[k + 1].isdigit())):
            k += 1
            continue
        done = _the_words_one(out, k, index, kinds, notes) or _owner_one(out, k, index, kinds, people, notes) \
            or _the_one_where(out, k, kinds, notes)
        k = done if done else k + 1
    return out


def _the_words_one(out: list[str], k: int, index: dict, kinds: frozenset, notes: list[str]) -> int:
    """ "the big one" -> "the big umbrella" in place; the position after it, or 0."""
    for n in range(min(_LONGEST, k - 1), 0, -1):
        said = out[k - n:k]
        if out[k - n - 1] != "the" or any(w in _NOT_WHICH or w in PUNCT or not w.isalpha() for w in said):
            continue
        kind = _the_thing(index, said, _kinds_before(out, k - n - 1, kinds))
        if kind:
            notes.append(f"'the {' '.join(said)} one' read as the {' '.join(said + list(kind))}")
            out[k:k + 1] = list(kind)
            return k + len(kind)
        return 0
    return 0


#: prepositions of where after "the one" ("the one in Amma's room")
_WHERE = frozenset({"in", "at", "on", "from", "by", "near"})


def _the_one_where(out: list[str], k: int, kinds: frozenset, notes: list[str]) -> int:
    """ "all the fans except the one in Amma's room" -> "the fan in Amma's room" in place, where
    one kind only was said before (which thing that is, the where decides after:
    :mod:`~.roomnames`; the position after it, or 0."""
    if out[k - 1] != "the" or k + 1 >= len(out) or out[k + 1] not in _WHERE:
        return 0
    said = {kind for _, _, kind in _kinds_before(out, k - 1, kinds) if not set(kind) & _NOT_WHICH}
    if len(said) != 1:
        return 0
    kind = list(next(iter(said)))
    notes.append(f"'the one {out[k + 1]} ...' read as the {' '.join(kind)} {out[k + 1]} ...")
    out[k:k + 1] = kind
    return k + len(kind)


def _owner_one(out: list[str], k: int, index: dict, kinds: frozenset, people: dict, notes: list[str]) -> int:
    """ "the mug, papa one": the name said before becomes papa's ("papa mug"), the apposition is
    dropped; the position after the change, or 0."""
    for n in range(min(_LONGEST, k), 0, -1):
        a = k - n
        if owner_at(out, a, people) != n or a == 0 or out[a - 1] != ",":
            continue
        if k + 1 < len(out) and out[k + 1] not in PUNCT and out[k + 1] not in _CLOSING:
            return 0
        # the apposition is of the name said last ("the cup and the saucer, dad one": the saucer)
        last = next((e for e in range(a - 2, -1, -1) if any(tuple(out[e - m + 1:e + 1]) in index
                                                            for m in (1, 2, 3) if e - m + 1 >= 0)), None)
        spans = [span for span in _kinds_before(out, a - 1, kinds) if span[1] == last + 1] if last is not None else []
        kind = _the_thing(index, out[a:k], spans)
        if not kind:
            return 0
        start, stop = next((s, e) for s, e, said in spans if said == kind)
        name = out[a:k] + list(kind)
        notes.append(f"'{' '.join(out[a:k])} one' says whose the {' '.join(kind)} is: read as the {' '.join(name)}")
        del out[a - 1:k + 1]
        out[start:stop] = name
        return a - 1 + len(name) - (stop - start)
    return 0

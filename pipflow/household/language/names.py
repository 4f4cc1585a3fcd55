"""The world's words: every object, place and category name of a home (and its ``words``), with
plurals, inversions ("bottle of water") and unshared head words ("kettle" of electric_kettle), as
word sequences -> the things they may name. Read by the tagger, the typo reader, the aside test and
the candidate readings; kept per world while its names are unchanged."""
from __future__ import annotations

import contextlib
import contextvars
import functools
from typing import Callable, Iterator, TypeVar

from pipflow.household.language.lexicon import (DEVICES, FILLER, FORM_HEADS, KIND_WORDS, PHRASES, WINDOWS, plurals,
                                                words_of)
from pipflow.household.world import members
from pipflow.language.asides import FUNCTION_WORDS
from pipflow.language.numbers import read_number


#: the index of the last worlds read: id -> (the world, what its names were, the index); a world
#: is read many times per command (tagging, the grammar's twins, asides, candidates)
_INDEXES: dict[int, tuple[dict, tuple, dict]] = {}
_KEPT = 16   # indexes (and facts of an index) kept at once
#: the world whose names stay as they are for the read in progress, and its index (:func:`held`)
_HELD: contextvars.ContextVar[tuple[dict, dict] | None] = contextvars.ContextVar("pipflow_household_names_held",
                                                                                 default=None)

T = TypeVar("T")


def per_index(fact: Callable[[dict], T]) -> Callable[[dict], T]:
    """``fact(index)`` computed once per index of :func:`world_phrases` (an index is read-only, and
    one object per world while the world's names are unchanged): the words of the home, the
    longest name, the vocabulary of typos are asked of every word of every reading, and a refused
    command is read dozens of times while its candidates are sought."""
    memo: dict[int, tuple[dict, T]] = {}

    @functools.wraps(fact)
    def of(index: dict) -> T:
        return _kept(memo, index, lambda: fact(index))
    return of


def per_world(fact: Callable[[dict], T]) -> Callable[[dict], T]:
    """``fact(world)`` of a world's names and ``words`` alone (what :func:`world_phrases` reads),
    computed once per index of the world, as :func:`per_index` does."""
    memo: dict[int, tuple[dict, T]] = {}

    @functools.wraps(fact)
    def of(world: dict) -> T:
        return _kept(memo, world_phrases(world), lambda: fact(world))
    return of


def _kept(memo: dict[int, tuple[dict, T]], index: dict, make: Callable[[], T]) -> T:
    """The memo's fact for this index, made if it has none (the index is kept in the memo with its
    fact, so its id is not reused by another while the entry stands)."""
    hit = memo.get(id(index))
    if hit is None or hit[0] is not index:
        if len(memo) >= _KEPT:
            memo.clear()
        hit = memo[id(index)] = (index, make())
    return hit[1]


@per_index
def home_words(index: dict) -> frozenset[str]:
    """Every word of every name of the home."""
    return frozenset(w for k in index for w in k)


def one_thing(index: dict, words: list[str]) -> bool:
    """Whether the words are the home's name of one thing, said in the singular ("the lights in the
    kitchen" may be every light there)."""
    refs = index.get(tuple(words), [])
    return len({ref["name"] for ref in refs}) == 1 and not any(ref.get("plural") for ref in refs)


@per_index
def first_words(index: dict) -> frozenset[str]:
    """The first words of the names of the home."""
    return frozenset(k[0] for k in index)


@per_index
def longest_name(index: dict) -> int:
    """The most words a name of the home has."""
    return max((len(k) for k in index), default=1)


#: the most words a name is looked for in, from where it may start ("the big chest of drawers")
_NAME_WORDS = 5


def name_end(words: list[str], k: int, index: dict, stop: int | None = None) -> int:
    """The index after the longest name of the home that starts at ``words[k]`` (and ends by
    ``stop``), or 0 where none starts there."""
    stop = len(words) if stop is None else stop
    return next((e for e in range(min(stop, k + _NAME_WORDS), k, -1) if tuple(words[k:e]) in index), 0)


def objects_named(refs: list[dict], world: dict) -> set[str]:
    """The objects of the home that references of the index name (a category: its member objects)."""
    objects = world.get("objects") or {}
    return {n for ref in refs for n in ([ref["name"]] if ref["kind"] == "object" else members(world, ref["name"])
                                        if ref["kind"] == "category" else []) if n in objects}


def _names_key(world: dict) -> tuple:
    """What :func:`world_phrases` reads of a world, cheaply: a changed name or word is a new index."""
    return tuple((kind, name, tuple((e or {}).get("words") or ()))
                 for kind in ("objects", "places", "categories") for name, e in (world.get(kind) or {}).items())


def doers(world: dict) -> frozenset[str]:
    """The names of the home's robots and teams, lower case: who may be addressed ("robot1,
    ..."), who may be asked to do something in a purpose ("so Bertie can get the plate out"), and
    so never a person of the command (the set-aside and the tagger ask the same question)."""
    return frozenset(str(r).lower() for key in ("robots", "teams") for r in world.get(key) or {})


@contextlib.contextmanager
def held(world: dict) -> Iterator[None]:
    """While one command is read (with its candidate readings), the world's names do not change:
    :func:`world_phrases` of this world then answers without checking them again. Reading a
    refused command asks for the index some three hundred times, and each check reads every name
    of the home (an eighth of the reading time of a refused household command)."""
    token = _HELD.set((world, world_phrases(world)))
    try:
        yield
    finally:
        _HELD.reset(token)


def world_phrases(world: dict) -> dict[tuple[str, ...], list[dict]]:
    """Word sequences -> the world things they name: every object, place and category name and
    ``words`` entry, with plural forms. A phrase may name several things ("lamp"). Read-only: the
    index of a world is kept while its names are unchanged."""
    now = _HELD.get()
    if now is not None and now[0] is world:
        return now[1]
    key = _names_key(world)
    hit = _INDEXES.get(id(world))
    if hit is not None and hit[0] is world and hit[1] == key:
        return hit[2]
    index = _world_phrases(world)
    if len(_INDEXES) >= _KEPT:
        _INDEXES.clear()
    _INDEXES[id(world)] = (world, key, index)
    return index


def _world_phrases(world: dict) -> dict[tuple[str, ...], list[dict]]:
    """:func:`world_phrases`, built."""
    index: dict[tuple[str, ...], list[dict]] = {}

    def add(phrase: str, kind: str, name: str, others: list[str]) -> None:
        base = words_of(phrase)
        if not base:
            return
        # a listed word is a plural when it is the plural of another listed word ("lamps" beside
        # "lamp"), or, for a category, ends in s ("school supplies", "electronics")
        listed_plural = any(" ".join(base) in plurals(" ".join(words_of(o))) for o in others) or \
            (kind == "category" and base[-1].endswith("s") and not base[-1].endswith("ss"))
        forms = [(tuple(base), listed_plural)] + [(tuple(words_of(p)), True) for p in plurals(" ".join(base))]
        if kind == "object" and len(base) == 2 and "of" not in base:
            # "water bottle" is also "a bottle of water", "bottles of water"
            forms += [((base[1], "of", base[0]), listed_plural)] + \
                [((p, "of", base[0]), True) for p in plurals(base[1])]
        for words, plural in forms:
            readings = index.setdefault(words, [])
            reading = {"kind": kind, "name": name, "plural": plural}
            if not any(r["kind"] == kind and r["name"] == name for r in readings):
                readings.append(reading)

    for kind, table in (("object", world.get("objects") or {}), ("place", world.get("places") or {})):
        for name, e in table.items():
            phrases = [name] + list(e.get("words") or [])
            for phrase in phrases:
                add(phrase, kind, name, phrases)
    for name, c in (world.get("categories") or {}).items():
        phrases = [name] + list((c or {}).get("words") or [])
        for phrase in phrases:
            add(phrase, "category", name, phrases)
    _add_parts(world, index)
    return index


def _add_parts(world: dict, index: dict[tuple[str, ...], list[dict]]) -> None:
    """The last word of a thing's name of two or more words, when no other thing's name has it
    ("kettle" of electric_kettle, "pot" of soup_pot), names that thing: people shorten names to
    their head noun. A modifier is not read alone ("kitchen" of kitchen_table is no room of the
    home, "coffee" of coffee_table no drink); a word two things share, a word the index already
    has, a word of the command lexicon or a function word names nothing alone (never a guess), nor
    does a kind word another thing of the home is of ("stove" beside a range: lexicon
    ``KIND_WORDS``).

    The plural of a last word that several things share names all of them ("both laptops" of
    maya_laptop and jordan_laptop, though a laptop charger has the word too, as a modifier; "the
    desks"), and so do things whose own name ends in that plural ("the plates" of big_plate,
    side_plate and good_plates): the singular stays unread (which one is asked)."""
    owners: dict[str, set[tuple[str, str]]] = {}
    heads: dict[str, set[tuple[str, str]]] = {}
    for kind, table in (("object", world.get("objects") or {}), ("place", world.get("places") or {})):
        for name, e in table.items():
            for phrase in [name] + list(e.get("words") or []):
                words = words_of(phrase)
                for w in words:
                    owners.setdefault(w, set()).add((kind, name))
                if len(words) >= 2:
                    heads.setdefault(words[-1], set()).add((kind, name))
    for w, things in heads.items():
        if len(things) < 2 or len(w) < 3 or not w.isalpha() or (w,) in index \
                or (w,) in PHRASES or w in FUNCTION_WORDS:
            continue
        for p in plurals(w):
            # a thing named in the plural by that word ("good plates" beside "big plate" and "side
            # plate"): one of them, not the only one "plates" names
            plural_heads = heads.get(p, set()) if owners.get(p) == heads.get(p) else None
            if p != w and (p,) not in index and (p,) not in PHRASES and (p not in owners or plural_heads):
                index[(p,)] = [{"kind": kind, "name": name, "plural": True}
                               for kind, name in sorted(things | (plural_heads or set()))]
    for w, things in owners.items():
        if w not in heads or len(things) != 1 or len(w) < 3 or not w.isalpha() or (w,) in index or (w,) in PHRASES \
                or w in FUNCTION_WORDS or any(w in key for key in FILLER) or read_number([w], 0):
            continue
        kind, name = next(iter(things))
        if any(thing != (kind, name) for k in KIND_WORDS.get(w, ()) for thing in owners.get(k, ())):
            continue   # "stove" of a camping stove, where the home has a range too: either
        index[(w,)] = [{"kind": kind, "name": name, "plural": False}]
        for p in plurals(w):
            if (p,) not in index and (p,) not in PHRASES and p not in owners:
                index[(p,)] = [{"kind": kind, "name": name, "plural": True}]


def named_by_first_word(world: dict, word: str) -> list[str]:
    """The things of the world a word names as the first word of a two-word name whose last word is
    a form of it (lexicon ``FORM_HEADS``: "my crossword" of crossword_book), also said in the
    plural ("the crosswords"); several things: each (the tagger then asks which). Read only for a
    word the tagger knows nowhere else: a world name or a word of the lexicon always wins."""
    forms = {word} | {word[:-len(end)] + repl for end, repl in (("ies", "y"), ("es", ""), ("s", ""))
                      if word.endswith(end) and len(word) > len(end) + 2}
    return [name for name, firsts in _form_named(world) if firsts & forms]


@per_world
def _form_named(world: dict) -> list[tuple[str, frozenset[str]]]:
    """The objects and places with a two-word name (or ``words`` entry) whose last word is a form
    (``FORM_HEADS``), each with the first words of those names, in the world's order."""
    firsts: dict[str, frozenset[str]] = {}
    for table in (world.get("objects") or {}, world.get("places") or {}):
        for name, e in table.items():
            firsts[name] = firsts.get(name, frozenset()) | frozenset(
                ws[0] for ws in (words_of(p) for p in [name] + list((e or {}).get("words") or []))
                if len(ws) == 2 and ws[1] in FORM_HEADS and ws[0] not in FUNCTION_WORDS)
    return [(n, f) for n, f in firsts.items() if f]


#: the kinds of thing the lexicon knows by a common word ("the heater", "a window", "the radio"):
#: the device lists (room heaters, sound makers, drink makers, screens, fans) and windows
KINDS = tuple(DEVICES.values()) + (WINDOWS,)


def things_of_kind(world: dict, word: str) -> tuple[list[str], bool]:
    """The things of the world of the kind a common word names ("window" -> the skylight, when the
    skylight is named or worded by a word of the same lexicon list, e.g. "skylight"), and whether
    the word is a plural. For a word the tagger knows nowhere else: "open a window" in a home whose
    window is called the skylight. No such thing: empty."""
    forms = {word: False} | {word[:-len(end)] + repl: True for end, repl in (("ies", "y"), ("es", ""), ("s", ""))
                             if word.endswith(end) and len(word) > len(end) + 2}
    for said, members in KIND_WORDS.items():   # "the stove": the range and the camping stove, asked
        if said in forms:
            found = [n for table in (world.get("objects") or {}, world.get("places") or {}) for n, e in table.items()
                     if {w for p in [n] + list((e or {}).get("words") or []) for w in words_of(p)} & members]
            if found:
                return found, forms[said]
    for kind in KINDS:
        phrases = {" ".join(words_of(p)) for p in kind}
        said = [f for f in forms if f in phrases]
        if not said:
            continue
        found = [n for table in (world.get("objects") or {}, world.get("places") or {}) for n, e in table.items()
                 if {" ".join(words_of(w)) for w in [n] + list((e or {}).get("words") or [])} & phrases]
        if found:
            return list(dict.fromkeys(found)), forms[said[0]]
    return [], False

"""The offline parser for household commands: command + world -> household orders.

Compositional, in three steps, and never by word position:

1. **tag**: the command's words become token classes: the world's names (longest match, with
   plurals, typo-tolerant: "fridgge" reads as "fridge" and a note says so), numbers, and the
   closed lexicon of :mod:`pipflow.household.language.lexicon`. A word in neither is a
   :class:`TranslationError` that quotes it: nothing is skipped silently (politeness words such
   as "please" carry no content and are listed in the lexicon).
2. **parse**: lark's Earley parser over the grammar of :mod:`pipflow.household.language.grammar` builds the
   sentence structure (clauses, coordination, gapping, pronouns, exceptions, relative clauses,
   state cues). Earley keeps every reading; all of them are returned.
3. **build**: each reading becomes an *order* (``schemas/household_order.schema.json``): a list
   of statements, each with the selectors of the things it is about and the words it came from.
   Which objects a selector means, and whether the request is possible, is the resolver's job
   (:mod:`pipflow.household.language.resolver`), not the parser's.
"""
from __future__ import annotations

import functools
import json
import re
from dataclasses import dataclass, field
from typing import Callable

from lark import Lark, Token, Tree
from lark.exceptions import UnexpectedInput
from lark.visitors import CollapseAmbiguities

from pipflow.errors import TranslationError
from pipflow.household.language.grammar import NOUN_DUAL, gated_classes, grammar_text
from pipflow.household.world import members
from pipflow.household.language.lexicon import (ACTIVITIES, COLD, DURATION_HEDGES, DURATION_UNITS, FILLER, FOUL_WORDS,
                                                LAUNDRY, FILLER_TYPO_TARGETS, LIGHT_CATEGORY_WORD, MANNER_OBJECTS,
                                                MANNERS, MARKS, MEALS, MEASURES, OPPOSITE, ORDER_WORDS, ORDINAL_DETERMINERS,
                                                PHRASES, PURPOSES, TEMPERATURE_ADJECTIVES, TIME_WORDS, UNIT_DETERMINERS, plurals,
                                                words_of)
from pipflow.language.asides import EXCLUSIVITY, FUNCTION_WORDS, NEGATION, clauses, content_free, said
from pipflow.language.characters import refuse_unread
from pipflow.language.earley import ListLexer
from pipflow.language.lookahead import with_lookahead
from pipflow.language.numbers import read_number
from pipflow.language.spelling import distance

#: the classes some gated line of the grammar needs
GATED = gated_classes()
#: the most readings of one ambiguous command that are compared (each is resolved); more is
#: refused, never cut short
MAX_READINGS = 64


@dataclass
class Tag:
    """One token for the grammar: its class, its meaning, and the words it stands for."""

    cls: str
    value: object
    words: str
    nouns: list[dict] = field(default_factory=list)   # world readings: {"kind", "name", "plural"}


# ---------------------------------------------------------------------------------------------
# the world's words
# ---------------------------------------------------------------------------------------------
#: the index of the last worlds read: id -> (the world, what its names were, the index); a world
#: is read many times per command (tagging, the grammar's twins, asides, candidates)
_INDEXES: dict[int, tuple[dict, tuple, dict]] = {}


def _names_key(world: dict) -> tuple:
    """What :func:`world_phrases` reads of a world, cheaply: a changed name or word is a new index."""
    return tuple((kind, name, tuple((e or {}).get("words") or ()))
                 for kind in ("objects", "places", "categories") for name, e in (world.get(kind) or {}).items())


def world_phrases(world: dict) -> dict[tuple[str, ...], list[dict]]:
    """Word sequences -> the world things they name: every object, place and category name and
    ``words`` entry, with plural forms. A phrase may name several things ("lamp"). Read-only: the
    index of a world is kept while its names are unchanged."""
    key = _names_key(world)
    hit = _INDEXES.get(id(world))
    if hit is not None and hit[0] is world and hit[1] == key:
        return hit[2]
    index = _world_phrases(world)
    if len(_INDEXES) >= 16:
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
    has, a word of the command lexicon or a function word names nothing alone (never a guess)."""
    owners: dict[str, set[tuple[str, str]]] = {}
    heads: set[str] = set()
    for kind, table in (("object", world.get("objects") or {}), ("place", world.get("places") or {})):
        for name, e in table.items():
            for phrase in [name] + list(e.get("words") or []):
                words = words_of(phrase)
                for w in words:
                    owners.setdefault(w, set()).add((kind, name))
                if len(words) >= 2:
                    heads.add(words[-1])
    for w, things in owners.items():
        if w not in heads or len(things) != 1 or len(w) < 3 or not w.isalpha() or (w,) in index or (w,) in PHRASES \
                or w in FUNCTION_WORDS or any(w in key for key in FILLER) or read_number([w], 0):
            continue
        kind, name = next(iter(things))
        index[(w,)] = [{"kind": kind, "name": name, "plural": False}]
        for p in plurals(w):
            if (p,) not in index and (p,) not in PHRASES and p not in owners:
                index[(p,)] = [{"kind": kind, "name": name, "plural": True}]


# ---------------------------------------------------------------------------------------------
# tagging
# ---------------------------------------------------------------------------------------------
PUNCT = {".": "END", ";": "END", "!": "END", "?": "END", ":": "END", ",": "COMMA"}


#: token classes whose words a typo may be read as: content words only. A function word is short
#: and close to many words ("fork" is not "for", "house" is not "those"), so it is never guessed.
CONTENT_CLASSES = {"V_STATE", "V_OPEN", "V_SHUT", "V_CLEAN", "V_WARM", "V_TOGGLE", "V_PUT", "V_THROW", "V_TRASH", "V_CHILL",
                   "V_TIDY", "V_LEAVE", "V_MAKE", "V_PREPARE", "ADJ", "ACTIVITY", "LIGHTCUE", "TOGGLED", "MEAL", "V_LIGHT",
                   "TEMPCUE", "V_TEND"}


def _vocabulary(world_index: dict) -> set[str]:
    """Words a misspelt word may be read as: the world's words, the lexicon's content words and
    the few politeness words of ``FILLER_TYPO_TARGETS`` ("plese")."""
    vocab = {w for k, (cls, _) in PHRASES.items() if cls in CONTENT_CLASSES and len(k) == 1 for w in k}
    vocab |= FILLER_TYPO_TARGETS
    vocab |= {w for k in world_index for w in k}
    return {w for w in vocab if len(w) >= 3}


def known_word(w: str, index: dict, vocab: set[str]) -> bool:
    """Whether the tagger reads ``w`` as it is: a word of the world, of the lexicon, of the
    politeness list, a number or a mark."""
    return w in vocab or w in PUNCT or w.isdigit() or any(w in key for key in PHRASES) or \
        any(w in key for key in index) or any(w in key for key in FILLER) or bool(read_number([w], 0))


#: endings of English inflection: a shared one says nothing of whether two words are one word
#: misspelt ("trying" and "tidying" share "ing"; what is left, "try" and "tidy", is two edits apart)
INFLECTIONS = ("ing", "ed", "es", "s")


def _stem(known: str, word: str) -> str:
    """``known`` without an inflectional ending it shares with ``word``: the length that earns a
    second edit is the stem's, so "starving" is not read as "stacking", nor "trying" as "tidying"."""
    for end in INFLECTIONS:
        if known.endswith(end) and word.endswith(end) and len(known) > len(end) + 2:
            return known[:-len(end)]
    return known


def _typo_of(word: str, vocab: set[str]) -> list[str]:
    """Known words ``word`` may be a misspelling of, closest first: the same first letter and one
    edit (two for words of 7 letters or more; a swap of neighbours is one). "toaster" is not
    "toast", "ones" is not "phones": a guess that names another thing would be a misreading."""
    near = [(distance(word, v), v) for v in vocab if v[0] == word[0] and abs(len(v) - len(word)) <= 2]
    near = [(d, v) for d, v in near if d <= (1 if len(_stem(v, word)) <= 6 else 2)]
    best = min((d for d, _ in near), default=None)
    return [v for d, v in sorted(near) if d == best]


def _meaning(word: str, world_index: dict) -> str:
    """What one known word stands for, so that two spellings of one thing ("tomato",
    "tomatoes") do not make a typo ambiguous."""
    names = sorted(r["name"] for r in world_index.get((word,), []))
    return f"{names}|{PHRASES.get((word,))}"


def _match(words: list[str], i: int, table: dict, longest: int) -> int:
    for n in range(min(longest, len(words) - i), 0, -1):
        if tuple(words[i:i + n]) in table:
            return n
    return 0


def _without_manner(words: list[str], notes: list[str]) -> list[str]:
    """The words without what says how the steps run, not what the home ends like (lexicon
    ``MANNERS``): a clause "do both in parallel", "one after the other", and "first" opening a
    clause ("first the mug, then the plate"). A note says what was read so."""
    out: list[str] = []
    start = 0
    for k, w in enumerate(words + ["."]):
        if w not in PUNCT:
            continue
        clause = words[start:k]
        body = clause[1:] if clause[:1] == ["do"] else clause
        manner = next((m for m in MANNERS if len(m) <= len(body) and tuple(body[len(body) - len(m):]) == m), None)
        if clause and manner is not None and tuple(body[:len(body) - len(manner)]) in MANNER_OBJECTS:
            notes.append(f"'{' '.join(clause)}' says how the steps run, not what the home should end like; "
                         "the plan decides the order")
            if k < len(words) and w != "," and out and out[-1] not in PUNCT:
                out.append(w)   # a sentence's end stays; a comma goes with the clause
            start = k + 1
            continue
        clause = _without_inner_manner(clause, notes)
        while len(clause) > 2 and clause[-1] in CLOSING_ORDER_WORDS and clause[-2] not in ("for", "until", "till"):
            # "bring them to the desk after" ("for later" is a purpose: _without_purpose)
            notes.append(f"'{clause[-1]}': the order of the steps; the plan decides it")
            clause = clause[:-1]
        kept = []
        for j, x in enumerate(clause):   # "wash the mug first", "first the mug, then the plate"
            if x in ORDER_WORDS and not (j and clause[j - 1] in ORDINAL_DETERMINERS) and \
                    not (j + 1 < len(clause) and clause[j + 1] == "of") and \
                    not (j + 1 < len(clause) and (x, clause[j + 1]) in TIME_WORDS):
                notes.append(f"'{x}': the order of the steps; the plan decides it")
                continue
            kept.append(x)
        clause = _without_purpose(kept, notes)
        out += clause + ([w] if k < len(words) else [])
        start = k + 1
    while out and out[-1] == ",":
        out.pop()
    return out


#: words after which a manner phrase closes what it says ("lift it in together and wash it")
_MANNER_ENDS = {"and", "then"}


def _without_inner_manner(clause: list[str], notes: list[str]) -> list[str]:
    """A clause that asks something, without a manner phrase (lexicon ``MANNERS``) closing it or
    one of its parts joined by "and" / "then" ("lift it into the sink together and wash it"):
    how, not what the home should end like."""
    out: list[str] = []
    j = 0
    while j < len(clause):
        m = next((m for m in sorted(MANNERS, key=len, reverse=True) if tuple(clause[j:j + len(m)]) == m), None)
        end = j + len(m) if m else j
        if m and out and (end == len(clause) or clause[end] in _MANNER_ENDS) and out[-1] not in _MANNER_ENDS:
            notes.append(f"'{' '.join(m)}' says how the steps run, not what the home should end like")
            j = end
            continue
        out.append(clause[j])
        j += 1
    return out


def without_duration(clause: list[str], notes: list[str]) -> list[str]:
    """Words without how long an action takes ("heat the curry for like two minutes", lexicon
    ``DURATION_UNITS``). Not done when reading: "leave the fridge open for five minutes" ends with
    it closed, so a duration is refused; a refusal offers the reading without it as a candidate
    (:mod:`pipflow.household.language.candidates`), for the user to choose."""
    for j, w in enumerate(clause):
        if w != "for":
            continue
        k = j + 1
        while k < len(clause) and clause[k] in DURATION_HEDGES:
            k += 1
        num = read_number(clause, k) if k < len(clause) else None
        end = num[1] if num else (k if k > j + 1 and clause[k - 1] in ("few", "couple", "of") else None)
        if end is not None and end < len(clause) and clause[end] in DURATION_UNITS:
            notes.append(f"'{' '.join(clause[j:end + 1])}' says how long, not what the home should end like")
            return clause[:j] + clause[end + 1:]
    return clause


def _without_purpose(clause: list[str], notes: list[str]) -> list[str]:
    """A clause without its closing purpose ("... for airing", "... for later": lexicon
    ``PURPOSES``, or "for" + an -ing word that is no verb of the lexicon): what for, not what the
    home should end like. "for washing" (a verb the home can do) is kept, and refused: it may ask
    for the washing too."""
    for n in (1, 2):
        if len(clause) > n + 1 and clause[-n - 1] == "for":
            tail = tuple(clause[-n:])
            if tail in PURPOSES or (n == 1 and tail[0].endswith("ing") and len(tail[0]) > 5
                                    and not any(tail[0] in key for key in PHRASES)):
                notes.append(f"'for {' '.join(tail)}' says what for, not what the home should end like")
                return clause[:-n - 1]
    return clause


def _measures(words: list[str], index: dict, notes: list[str]) -> list[str]:
    """ "a bowl of cherries" as "some cherries" (lexicon ``MEASURES``), unless the home has a thing
    named by the container word (then it stays, and is refused: the bowl may be meant too)."""
    out: list[str] = []
    k = 0
    while k < len(words):
        w = words[k]
        if w in ("a", "an", "one") and k + 3 < len(words) and words[k + 2] == "of" and \
                (words[k + 1] in MEASURES or words[k + 1] + "s" in MEASURES or words[k + 1].rstrip("s") in MEASURES) \
                and (words[k + 1],) not in index and words[k + 3] not in PUNCT:
            notes.append(f"'{w} {words[k + 1]} of' read as 'some' (an amount of what follows, not a thing of the home)")
            out.append("some")
            k += 3
            continue
        out.append(w)
        k += 1
    return out


def _located(tags: list["Tag"], world: dict, notes: list[str]) -> list["Tag"]:
    """ "the table lamp" where the home has no "table lamp" but a table and lamps: the lamp that
    is on the table, when the place word is followed at once by a name of objects and some of
    them are in that place; the other lamps are not meant. None there: left as said (refused)."""
    out: list[Tag] = []
    for t in tags:
        prev = out[-1] if out else None
        if t.cls == "NOUN" and prev is not None and prev.cls == "NOUN" and prev.nouns and \
                all(r["kind"] == "place" for r in prev.nouns):
            places = {r["name"] for r in prev.nouns}
            objects = [o for r in t.nouns for o in ([r["name"]] if r["kind"] == "object" else
                                                     members(world, r["name"]) if r["kind"] == "category" else [])]
            there = [o for o in dict.fromkeys(objects) if o in world["objects"] and world["objects"][o]["in"] in places]
            if there:
                plural = any(r.get("plural") for r in t.nouns)
                notes.append(f"read '{prev.words} {t.words}' as {', '.join(there)} (in {', '.join(sorted(places))})")
                out[-1] = Tag("NOUN", None, f"{prev.words} {t.words}",
                              [{"kind": "object", "name": o, "plural": plural} for o in there])
                continue
        out.append(t)
    return out


#: lexicon classes of phrases that name the home or a room of it ("in the kitchen", "all over the
#: flat"): a world name inside one is read as the name
HOME_CLASSES = {"HERE", "ALLOVER", "INROOM", "THEWASH", "ROOMSAID"}


#: words that put a step after the others, closing a clause ("... and bring them to the desk
#: after", "put it back afterwards"): the order of the steps, which the plan decides
CLOSING_ORDER_WORDS = {"after", "afterwards", "afterward", "later", "next"}


#: the tags a sentence that only restates the order of things has: "first the mug, then the plate"
_ORDER_ONLY = {"THE", "NOUN", "COMMA", "AND", "THEN"}


def _restated_order(tags: list[Tag], notes: list[str]) -> list[Tag]:
    """The tags without a sentence that only lists things already named, in an order ("wash the
    mug and the plate: first the mug, then the plate"): the order of the steps, which the plan
    decides. A sentence that names anything new is kept (and read, or refused)."""
    out: list[Tag] = []
    named: set[str] = set()
    start = 0
    for k in range(len(tags) + 1):
        if k < len(tags) and tags[k].cls != "END":
            continue
        sentence = tags[start:k]
        nouns = [t for t in sentence if t.cls == "NOUN" or t.cls.endswith(NOUN_DUAL)]
        names = {r["name"] for t in nouns for r in t.nouns}
        if out and nouns and names <= named and all(t.cls in _ORDER_ONLY or t.cls.endswith(NOUN_DUAL) for t in sentence):
            notes.append(f"'{' '.join(t.words for t in sentence)}': the order of the steps; the plan decides it")
        else:
            out += sentence + tags[k:k + 1]
        named |= names
        start = k + 1
    return out


def _act_before_noun(tags: list[Tag]) -> list[Tag]:
    """ "I need a clean mug": an action noun ("a clean", "a wash") before a name is a determiner and a
    state word, not the action ("give it a clean")."""
    out: list[Tag] = []
    for k, t in enumerate(tags):
        nxt = tags[k + 1] if k + 1 < len(tags) else None
        ws = t.words.split()
        if t.cls == "ACT" and len(ws) == 2 and nxt is not None and (nxt.cls == "NOUN" or nxt.cls.endswith(NOUN_DUAL)) \
                and (ws[1],) in PHRASES and PHRASES[(ws[1],)][0] in ("V_CLEAN", "ADJ"):
            out += [Tag("THE", None, ws[0]), Tag(PHRASES[(ws[1],)][0], PHRASES[(ws[1],)][1], ws[1])]
            continue
        out.append(t)
    return out


def _demonstratives(tags: list[Tag]) -> list[Tag]:
    """ "That leftover curry has gone off": "that" opening a clause before a name (or a state word
    and a name) is a determiner, like "the"; elsewhere it stays a relative ("the lamp that is on")
    or a conjunction ("make sure that ..."). Done here, not in the grammar: one more determiner
    there is one more alternative at every noun of every command."""
    out = list(tags)
    for k, t in enumerate(out):
        if t.cls == "THAT" and k and out[k - 1].cls.startswith("V_") and \
                (k + 1 == len(out) or out[k + 1].cls in ("END", "COMMA")):
            out[k] = Tag("IT", t.value, t.words)   # "the hob is still on, can you sort that": the thing said
            continue
        if t.cls != "THAT" or (k and out[k - 1].cls not in ("END", "COMMA")):
            continue
        j = k + 1
        while j < len(out) and out[j].cls in ("ADJ", "V_WARM", "V_CLEAN"):
            j += 1
        if j < len(out) and (out[j].cls == "NOUN" or out[j].cls.endswith(NOUN_DUAL)):
            out[k] = Tag("THE", t.value, t.words)
    return out


#: words that put what follows them in their sentence under a negation ("nobody is using X or Y")
_NEGATORS = {"nobody", "noone", "not", "never", "none"}


def _or_under_negation(words: list[str], notes: list[str]) -> list[str]:
    """ "nobody is using the tablet or the radio": under a negation, "or" lists both (neither is
    used), so it is read as "and". Elsewhere "or" is a choice, which this reader does not make
    (it stays unread, and is refused)."""
    out: list[str] = []
    negated = False
    for k, w in enumerate(words):
        if w in (".", "!", "?", ";"):
            negated = False
        elif w in _NEGATORS or (w == "no" and k + 1 < len(words) and words[k + 1] == "one"):
            negated = True
        elif w in ("or", "nor") and negated:
            notes.append(f"'{w}' after a negation lists both: read as 'and'")
            w = "and"
        out.append(w)
    return out


def tag(command: str, world: dict, notes: list[str] | None = None) -> list[Tag]:
    """The command as grammar tokens (module docstring, step 1)."""
    notes = notes if notes is not None else []
    index = world_phrases(world)
    words = _or_under_negation(_measures(_without_manner(words_of(command), notes), index, notes), notes)
    vocab = _vocabulary(index)
    said = list(words)   # as typed: a repair that still names nothing is quoted as typed
    # typos: a word known nowhere, close to exactly one known word, is read as that word
    for k, w in enumerate(words):
        if known_word(w, index, vocab) or len(w) < 4:
            continue
        close = _typo_of(w, vocab)
        if close and len({_meaning(c, index) for c in close}) == 1:
            notes.append(f"read {w!r} as {close[0]!r}")
            words[k] = close[0]
    longest_w = max((len(k) for k in index), default=1)
    longest_l = max(len(k) for k in PHRASES)
    longest_f = max(len(k) for k in FILLER)
    out: list[Tag] = []
    unknown: list[str] = []
    i = 0
    while i < len(words):
        w = words[i]
        if w in PUNCT:
            out.append(Tag(PUNCT[w], w, w))
            i += 1
            continue
        if w[0] == "-" or not w.isalnum():   # "-2", "3.5": no count of things; refused, never read as 2
            unknown.append(w)
            i += 1
            continue
        num = read_number([x if x not in PUNCT and x.isalnum() else None for x in words], i)
        nw, nl, nf = _match(words, i, index, longest_w), _match(words, i, PHRASES, longest_l), \
            _match(words, i, FILLER, longest_f)
        if nl > 1 and PHRASES[tuple(words[i:i + nl])][0] in HOME_CLASSES and \
                any(_match(words, j, index, longest_w) for j in range(i + 1, i + nl)):
            nl = 1 if (w,) in PHRASES else 0   # "in the kitchen" where the home has a thing named kitchen
        if num is not None and num[1] - i >= max(nw, nl, nf):
            out.append(Tag("NUM", num[0], " ".join(words[i:num[1]])))
            i = num[1]
            continue
        if nf and nf > max(nw, nl):
            i += nf
            continue
        if nw == 0 and nl == 0:
            unknown.append(said[i])
            i += 1
            continue
        n = max(nw, nl)
        text = " ".join(words[i:i + n])
        if nw == n and nl == n:
            cls, value = PHRASES[tuple(words[i:i + n])]
            out.append(Tag(cls + NOUN_DUAL, value, text, index[tuple(words[i:i + n])]))
        elif nw == n:
            out.append(Tag("NOUN", None, text, index[tuple(words[i:i + n])]))
        else:
            cls, value = PHRASES[tuple(words[i:i + n])]
            out.append(Tag(cls, value, text))
        i += n
    out = _restated_order(_located(_demonstratives(_act_before_noun(out)), world, notes), notes)
    if unknown:
        names = sorted(set(world.get("objects") or {}) | set(world.get("places") or {}))
        error = TranslationError(
            f"{', '.join(repr(u) for u in dict.fromkeys(unknown))} names nothing in this world and is no word the "
            f"offline parser knows (in {command.strip()!r}); things of this world: {', '.join(names)}")
        error.unread = list(dict.fromkeys(unknown))  # type: ignore[attr-defined]  # for candidate readings
        raise error
    return out


# ---------------------------------------------------------------------------------------------
# parsing
# ---------------------------------------------------------------------------------------------
def _terminals(tags: list[Tag]) -> list[Token]:
    """The tagger's tokens as lark's terminals; a token's value is its index in the tag list."""
    return [Token(t.cls, str(k), start_pos=k, end_pos=k + 1) for k, t in enumerate(tags)]


@functools.lru_cache(maxsize=64)
def _lark(dual: frozenset[str], present: frozenset[str] | None = None) -> Lark:
    """The Earley parser for commands whose dual tokens (a lexicon word that is also a name of the
    world) are of the classes ``dual``: one per world in practice (grammar_text says why), with the
    gated lines of the rules for the gated classes ``present`` in the command (None: all). It
    predicts with one terminal of lookahead (:mod:`pipflow.language.lookahead`: the same forests,
    less work)."""
    return with_lookahead(Lark(grammar_text(dual, present), parser="earley", lexer=ListLexer, ambiguity="explicit"))


def _parser_for(world: dict, tags: list[Tag]) -> Lark:
    """The parser for these tags in this world: only the gated rules their classes can use."""
    present = frozenset(t.cls[:-len(NOUN_DUAL)] if t.cls.endswith(NOUN_DUAL) else t.cls for t in tags)
    return _lark(_dual_classes(world), present & GATED)


def _dual_classes(world: dict) -> frozenset[str]:
    """The lexicon classes whose phrases are also names of this world ("trash", "microwave")."""
    index = world_phrases(world)
    return frozenset(PHRASES[k][0] for k in index if k in PHRASES)


def _words(tags: list[Tag], node: Tree | Token) -> str:
    toks = [node] if isinstance(node, Token) else list(node.scan_values(lambda v: isinstance(v, Token)))
    idx = sorted({int(t) for t in toks})
    return " ".join(tags[k].words for k in idx)


#: lexicon classes of function words: alone in a clause they carry nothing an order needs
#: (and words that only colour a cue or a time: "for the night", "in here", "late", "really")
GLUE_CLASSES = {"THE", "THAT", "IT", "IS", "SUBJ", "BE", "HAVE", "SHOULD", "INTENS", "OF", "AT", "IN", "ON", "OFF",
                "ANYMORE", "REASON", "HERE",
                "OUT", "UP", "TO", "FROM", "WITH", "AND", "SEE", "SURE"}
#: marks that end a clause, for setting content-free clauses aside
CLAUSE_MARKS = {",", ".", ";", "!", "?", ":"}


def _content(world: dict) -> Callable[[str], bool]:
    """The test :func:`pipflow.language.asides.content_free` asks of each word: a word of a
    world name (or a misspelling of one, or of a content word of the lexicon), a number, or a
    lexicon word that is no function word ("put", "off" with a verb is content by the verb)."""
    index = world_phrases(world)
    # the words that name something alone: a one-word name and the head (last word) of a longer
    # one; a modifier alone names nothing ("mooring" of mooring_line in "we're mooring up"), and
    # "of" of "bottle of water" is no name
    world_words = {k[-1] for k in index if "of" not in k} | {k[0] for k in index if "of" in k}
    world_words = {w for w in world_words if (w,) in index} - FUNCTION_WORDS
    lexicon_words = {w for k, (cls, _) in PHRASES.items() if cls not in GLUE_CLASSES for w in k} - FUNCTION_WORDS
    vocab = {w for w in _vocabulary(index) if w in world_words or w in lexicon_words or w in FILLER_TYPO_TARGETS}

    def content(w: str) -> bool:
        if w in world_words or w in lexicon_words or w.isdigit() or read_number([w], 0):
            return True
        if w in FUNCTION_WORDS:
            return False
        return len(w) >= 4 and bool(_typo_of(w, vocab))
    return content


#: how a clause opens when it says what the speaker will do ("I'll grab the milk myself", "I'm
#: about to unpack the shopping"): no order for the robots
SPEAKER_OPENERS = (("i", "will"), ("we", "will"), ("i", "am", "about", "to"), ("we", "are", "about", "to"),
                   ("i", "am", "going", "to"), ("we", "are", "going", "to"), ("i", "shall"), ("we", "shall"))
#: verbs after such an opener that make it a wish, not the speaker's doing ("I'll need the oven on",
#: "I'll take the tea in the cabin", "I'm going to want ..."): never set aside
WISH_VERBS = {"need", "want", "like", "have", "take", "be", "wish", "prefer", "love"}


def speaker_doing(words: tuple[str, ...]) -> bool:
    """Whether a clause says what the speaker will do ("I'll grab the milk myself"): it opens with
    :data:`SPEAKER_OPENERS`, its verb is no wish (:data:`WISH_VERBS`) and it has no negation or
    exclusivity ("I'll not ...", "I'll only ..."), which would bear on what the robots do."""
    for opener in SPEAKER_OPENERS:
        if words[:len(opener)] == opener and len(words) > len(opener):
            rest = words[len(opener):]
            return rest[0] not in WISH_VERBS and not any(w in NEGATION or w in EXCLUSIVITY for w in rest)
    return False


#: marks that set a part of a sentence off like commas: dashes, brackets
_PARENTHESES = re.compile(r"\s[-\u2010-\u2015]+\s|[\u2013\u2014\u2015()\[\]]")


def without_asides(command: str, world: dict) -> tuple[str, list[str], list[str]] | None:
    """The command without its content-free clauses (:mod:`pipflow.language.asides`) and its
    clauses that say what the speaker will do (:func:`speaker_doing`): (the rest, the words of
    the first, the words of the second), or None when it has none (or nothing else). Dashes and
    brackets set a clause off as commas do ("throw the fish away - it smells off - and ...")."""
    words = words_of(_PARENTHESES.sub(" , ", command))
    content = _content(world)
    free = [c for c in clauses(words, CLAUSE_MARKS) if content_free(c.words, content)]
    own = [c for c in clauses(words, CLAUSE_MARKS) if c not in free and speaker_doing(c.words)]
    if not free and not own:
        return None
    drop = {k for c in free + own for k in range(c.start, c.end)}
    kept = [w for k, w in enumerate(words) if k not in drop]
    # a clause mark left with nothing before it in its sentence goes too
    out: list[str] = []
    for w in kept:
        if w in CLAUSE_MARKS and (not out or out[-1] in CLAUSE_MARKS):
            if w not in (",", ":") and out:
                out[-1] = w
            continue
        out.append(w)
    if not [w for w in out if w not in CLAUSE_MARKS]:
        return None
    return " ".join(out), [" ".join(c.words) for c in free], [" ".join(c.words) for c in own]


def parse(command: str, world: dict, notes: list[str] | None = None) -> list[dict]:
    """Every reading of the command as an order (module docstring); TranslationError quoting the
    words where the command stops making sense to the grammar.

    A command that does not read as said is read again without its content-free clauses
    (greetings, thanks, asides: :mod:`pipflow.language.asides`); they are set aside, said in the
    notes and in each order's ``set_aside``. Every other clause still needs every word placed."""
    if not isinstance(command, str) or not command.strip():
        raise TranslationError("the command is empty")
    refuse_unread(command, MARKS)   # a character this reader does not read is refused, never skipped
    notes = notes if notes is not None else []
    try:
        return _parse(command, world, notes)
    except TranslationError:
        trimmed = without_asides(command, world)
        if trimmed is None:
            raise
        mine: list[str] = []
        try:
            readings = _parse(trimmed[0], world, mine)
        except TranslationError as again:
            # what is left after the talk is set aside is what does not read: say that
            error = TranslationError(f"{again} (set aside: {'; '.join(repr(a) for a in trimmed[1] + trimmed[2])})",
                                     candidates=again.candidates)
            for attr in ("unread", "unplaced", "choices"):   # what candidate readings are built from
                if hasattr(again, attr):
                    setattr(error, attr, getattr(again, attr))
            raise error from None
    notes += mine + ([said(trimmed[1])] if trimmed[1] else []) + [
        f"'{own}' says what the speaker will do: no order for the robots (set aside)" for own in trimmed[2]]
    extra = {**({"set_aside": trimmed[1]} if trimmed[1] else {}), **({"speaker_does": trimmed[2]} if trimmed[2] else {})}
    return [{**r, **extra} for r in readings]


def _parse(command: str, world: dict, notes: list[str]) -> list[dict]:
    """:func:`parse` of the command as said."""
    tags = tag(command, world, notes)
    if not [t for t in tags if t.cls not in ("END", "COMMA")]:
        raise TranslationError(f"{command.strip()!r} asks for nothing the offline parser can read")
    try:
        tree = _parser_for(world, tags).parse(_terminals(tags))
    except UnexpectedInput as exc:
        filled = _elided_objects(tags)
        if filled is not None:
            try:
                tree = _parser_for(world, filled).parse(_terminals(filled))
            except UnexpectedInput:
                filled = None
        if filled is not None:
            notes.append("a verb with its object left out ('" + "', '".join(
                f"{tags[k].words} {tags[k + 1].words}" for k in range(len(tags) - 1)
                if tags[k].cls in DROPPED_OBJECT_VERBS and tags[k + 1].cls in DESTINATIONS)
                + "') read as 'it': the thing named before")
            return _orders(filled, tree, command)
        k = getattr(exc, "pos_in_stream", None)
        k = k if isinstance(k, int) and 0 <= k < len(tags) else len(tags) - 1
        start = k
        while start > 0 and tags[start - 1].cls not in ("END",):
            start -= 1
        end = k
        while end + 1 < len(tags) and tags[end + 1].cls not in ("END",):
            end += 1
        clause = " ".join(t.words for t in tags[start:end + 1])
        here = " ".join(t.words for t in tags[k:min(end + 1, k + 4)])
        error = TranslationError(f"could not place the words '{here}' in '{clause}': the offline parser reads "
                                 "changes of state, moves, put-aways, trashing and state cues (docs/household.md); "
                                 "a language model may read it")
        # for candidate readings: the words where the grammar stopped (and the one before), each
        # of which a candidate may read the command without
        error.unplaced = [t.words for t in tags[max(start, k - 1):min(end + 1, k + 3)]  # type: ignore[attr-defined]
                          if t.cls not in ("END", "COMMA")]
        raise error from None
    return _orders(tags, tree, command)


#: verbs whose object goes somewhere, and the words that say where: "then put in the fridge"
#: drops the object "it" (the thing named before), as people do after naming it
DROPPED_OBJECT_VERBS = {"V_PUT", "V_THROW"}
DESTINATIONS = {"IN", "ON"}


def _elided_objects(tags: list[Tag]) -> list[Tag] | None:
    """The tags with "it" put back after a verb of :data:`DROPPED_OBJECT_VERBS` followed at once
    by a destination, when a thing was named before the verb ("slice the carrot, then put in the
    fridge"); None when there is no such verb. Tried only when the command does not parse as
    said; "it" then means what it always means (the resolver's pronoun: the thing before)."""
    out: list[Tag] = []
    changed = False
    for k, t in enumerate(tags):
        out.append(t)
        named_before = any(x.cls == "NOUN" or x.cls.endswith(NOUN_DUAL) for x in tags[:k])
        if (t.cls in DROPPED_OBJECT_VERBS and k + 1 < len(tags) and tags[k + 1].cls in DESTINATIONS
                and named_before):
            out.append(Tag("IT", None, "(it)"))
            changed = True
    return out if changed else None


def _orders(tags: list[Tag], tree: Tree, command: str) -> list[dict]:
    """Every distinct order the parse forest holds (module docstring, step 3)."""
    readings: list[dict] = []
    seen: set[str] = set()
    trees = CollapseAmbiguities().transform(tree)
    if len(trees) > MAX_READINGS:   # comparing only some readings could miss one that differs
        raise TranslationError(f"{command.strip()!r} can be read in {len(trees)} ways; say it in shorter sentences")
    for t in trees:
        order = Builder(tags, command).order(t)
        key = json.dumps(order, sort_keys=True)
        if key not in seen:
            seen.add(key)
            readings.append(order)
    return readings


# ---------------------------------------------------------------------------------------------
# parse tree -> order
# ---------------------------------------------------------------------------------------------
class Builder:
    """One parse tree -> one order (``schemas/household_order.schema.json``)."""

    def __init__(self, tags: list[Tag], command: str):
        self.tags = tags
        self.command = command

    # tokens ------------------------------------------------------------------------------
    def tag_of(self, tok: Token) -> Tag:
        return self.tags[int(tok)]

    def _cls(self, tok: Token) -> str:
        return tok.type[:-len(NOUN_DUAL)] if tok.type.endswith(NOUN_DUAL) else tok.type

    def _tokens(self, node: Tree | Token) -> list[Token]:
        if isinstance(node, Token):
            return [node]
        return [c for c in node.children if isinstance(c, Token)]

    def _sub(self, node: Tree, name: str) -> Tree | None:
        return next((c for c in node.children if isinstance(c, Tree) and c.data == name), None)

    def _subs(self, node: Tree, name: str) -> list[Tree]:
        return [c for c in node.children if isinstance(c, Tree) and c.data == name]

    def _has(self, node: Tree, cls: str) -> bool:
        return any(self._cls(t) == cls for t in self._tokens(node))

    # pieces ------------------------------------------------------------------------------
    def noun(self, node: Tree) -> dict:
        tok = node.children[0]
        t = self.tag_of(tok)
        return {"words": t.words, "readings": [dict(r) for r in t.nouns]}

    def place(self, node: Tree) -> dict:
        return {**self.noun(self._sub(node, "noun")), "words": _words(self.tags, node)}

    def state(self, node: Tree) -> str:
        onoff = self._sub(node, "onoff")
        if onoff is not None:
            node = onoff
        if self._sub(node, "on") is not None:
            return "on"
        if self._sub(node, "off") is not None or self._sub(node, "typo_off") is not None:   # "turn of the TV"
            return "off"
        tok = self._tokens(node)[-1]
        return str(self.tag_of(tok).value)

    def sel(self, node: Tree) -> dict:
        out: dict = {"words": _words(self.tags, node)}
        toks = [self._cls(t) for t in self._tokens(node)]
        quant = self._sub(node, "quant")
        if quant is not None:
            out["all"] = True
            if self._has(quant, "BOTH"):
                out["both"] = True
        if "DOOR" in toks:
            out["door"] = True
        count_node = self._sub(node, "count")
        det_words = [self.tag_of(t).words for t in self._tokens(node) if self._cls(t) == "THE"]
        if (count_node is not None and self._has(count_node, "UNIT")) or \
                any(d in UNIT_DETERMINERS for d in det_words):
            out["unit"] = True   # "a piece of fruit", "two pieces of fruit": only a kind may be counted in pieces
        if "ONES" in toks:
            out["ones"] = True   # "except the clean ones": of the things just named
        if "EVERYTHING" in toks or "THING" in toks:
            out["everything"] = True
        if "IT" in toks or toks == ["BOTH"]:   # "them", "put both on the table"
            out["pronoun"] = True
        if toks == ["BOTH"]:
            out.update(all=True, both=True)
        count = self._sub(node, "count")
        if count is not None:
            out["count"] = int(self.tag_of(count.children[0]).value)
        adjs = [str(self.tag_of(self._tokens(a)[0]).value) for a in self._subs(node, "adj")]
        noun = self._sub(node, "noun")
        if noun is not None:
            out.update(noun=self.noun(noun))
        det = [self.tag_of(t).words for t in self._tokens(node) if self._cls(t) == "THE"]
        if det:
            out["det"] = det[0]
        rel = self._sub(node, "rel")
        where = self._sub(node, "where") or (self._sub(rel, "where") if rel is not None else None)
        if rel is not None and self._sub(rel, "state") is not None:
            adjs.append(self.state(self._sub(rel, "state")))
        if rel is not None and self._sub(rel, "place") is not None:
            out["from"] = self.place(self._sub(rel, "place"))
        if where is not None:
            out["from"] = self.place(self._sub(where, "place"))
        if adjs:
            out["state"] = adjs
        return out

    def np(self, node: Tree) -> dict:
        out = self.sel(self._sub(node, "sel"))
        where = self._sub(node, "where")   # a switch's thing by where it is: "the lamp on the desk"
        if where is not None:
            out["from"] = self.place(self._sub(where, "place"))
            out["words"] = _words(self.tags, node)
        exc = self._sub(node, "exception")
        if exc is not None:
            out["except"] = self.things(self._sub(exc, "things"))
            out["words"] = _words(self.tags, node)
        return out

    def things(self, node: Tree) -> list[dict]:
        return [self.np(n) for n in self._subs(node, "np") + self._subs(node, "tnp") + self._subs(node, "snp")]

    def target(self, node: Tree) -> dict:
        p = self._sub(node, "place") or self._sub(node, "bare")
        if p is None and self._has(node, "THEWASH"):   # "put the clothes in the wash"
            return {"words": _words(self.tags, node), "quality": LAUNDRY}
        if p is None:   # "put the apple in it": the place said before
            return {"words": _words(self.tags, node), "pronoun": True}
        out = {**self.noun(self._sub(p, "noun")), "words": _words(self.tags, node)}
        if any(self._cls(t) == "ON" for t in self._tokens(node)):
            out["prep"] = "on"   # a surface: "on the fridge" is not "in the fridge"
        return out

    # statements --------------------------------------------------------------------------
    def statement(self, node: Tree) -> dict:
        kind = node.data
        words = _words(self.tags, node)
        th = self._sub(node, "things") or self._sub(node, "tthings") or self._sub(node, "sthings")
        things = self.things(th) if th is not None else []
        exc = self._sub(node, "exception")
        if kind == "change":
            toks = self._tokens(node)
            # the state comes from the verb, or from the action noun of "give the pot a scrub"
            act = next((t for t in toks if self._cls(t) == "ACT"), None)
            verb = act if act is not None else next(t for t in toks if self._cls(t).startswith("V_"))
            st = {"op": "change", "things": things, "to": str(self.tag_of(verb).value)}
            via = self._sub(node, "via")
            if via is not None and self._sub(via, "place") is not None:
                st["via"] = self.place(self._sub(via, "place"))
            elif via is not None:   # "heat the pan on it"
                st["via"] = {"words": _words(self.tags, via), "pronoun": True}
            elif act is None and self.verb_place(verb) is not None:   # "microwave the noodles"
                st["via"] = self.verb_place(verb)
        elif kind == "toggle" and self._has(node, "V_LIGHT"):   # "light the stove"
            st = {"op": "change", "things": things, "to": "on"}
        elif kind == "toggle":   # "turn the fire on and the kettle": the things after the particle too
            st = {"op": "change", "things": [t for sub in self._subs(node, "tthings") for t in self.things(sub)],
                  "to": self.state(node)}
        elif kind == "put":
            # "put it in the cabinet along with the bowl": the things after the place go there too
            subs = self._subs(node, "things") + self._subs(node, "sthings")
            st = {"op": "put", "things": [s for sub in subs for s in self.things(sub)]}
            src, tgt = self._sub(node, "source"), self._sub(node, "target")
            if src is None and tgt is None and self._has(node, "V_THROW") and len(self._tokens(node)) == 1:
                # "chuck the crisp packet", "toss the orange": thrown, and said nowhere else, is away
                st = {"op": "trash", "things": st["things"]}
            if src is not None:
                st["from"] = self.place(self._sub(src, "place"))
            if tgt is not None:
                st["to"] = self.target(tgt)
        elif kind == "gap":   # the verb is elided: "... and the pillow on the bed", "... and the stove on", "... and the cup too"
            st = {"op": "repeat", "things": things}
            if self._sub(node, "target") is not None:
                st["to"] = self.target(self._sub(node, "target"))
            elif self._sub(node, "onoff") is not None:
                st["state"] = self.state(node)
        elif kind == "away":
            st = {"op": "put_away", "things": things}
        elif kind == "trash":
            st = {"op": "trash", "things": things}
        elif kind == "chill":
            verb = next(t for t in self._tokens(node) if self._cls(t) == "V_CHILL")
            st = {"op": "put", "things": things, "to": {"words": self.tag_of(verb).words, "quality": COLD}}
        elif kind == "request" and self._has(node, "ACT"):   # "the saucepan wants a good scrub"
            act = next(t for t in self._tokens(node) if self._cls(t) == "ACT")
            st = {"op": "change", "things": things, "to": str(self.tag_of(act).value)}
        elif kind in ("request", "after"):   # "after": "once you have washed the pan, ..." (done first)
            st = {"op": "change", "things": things, "to": self.state(self._sub(node, "state"))}
        elif kind == "unwant":   # "don't leave the fridge open", "the TV shouldn't be on": the other polarity
            st = {"op": "change", "things": things, "to": OPPOSITE[self.state(self._sub(node, "state"))]}
        elif kind == "meal":
            named = next((t for t in self._tokens(node) if self._cls(t) == "MEAL"), None)
            if named is None:   # "make some toast": a meal whose word is a verb too
                said = self.tag_of(next(t for t in self._tokens(node)[1:] if self._cls(t) == "V_STATE")).words
                if said not in MEALS:
                    raise TranslationError(f"'{words}': '{said}' is no meal the offline parser knows")
                meal = said
            else:
                meal = str(self.tag_of(named).value)
            verb = self.tag_of(self._tokens(node)[0])
            if verb.value is not None and verb.value != MEALS[meal]["state"]:   # "cook breakfast", never "heat a salad"
                raise TranslationError(f"'{words}': a {meal} is not made by '{verb.words}' "
                                       f"(its foods end {MEALS[meal]['state']}); say what to do with which things")
            st = {"op": "meal", "meal": meal}
        elif kind == "cue":
            st = self.cue(node, things)
        elif kind in ("observe", "tend", "mess", "handling", "keep", "empty", "desire"):
            st = self.said_of_things(node, kind, things)
        else:  # a rule of the grammar without a statement: a bug, not a user error
            raise AssertionError(f"no statement for grammar rule {kind!r}")
        if exc is not None:   # "put all the fruit in the fridge but not the watermelon"
            st["except"] = self.things(self._sub(exc, "things"))
        st["words"] = words
        return st

    def verb_place(self, verb: Token) -> dict | None:
        """ "microwave the noodles": a verb that is a place of the home says where the action
        happens (a noun of the place's readings), else None."""
        places = [dict(r) for r in self.tag_of(verb).nouns if r["kind"] == "place"]
        return {"words": self.tag_of(verb).words, "readings": places} if places else None

    def said_of_things(self, node: Tree, kind: str, things: list[dict]) -> dict:
        """Statements that say something of things: an observation, what they need ("tend"),
        disorder said ("mess"), how a thing is handled, a thing to stay where it is, a place
        emptied, a thing wished for in a state."""
        if kind == "observe":
            state = self._sub(node, "state")
            st = {"op": "observe", "things": things, "is": self.state(state) if state is not None else "dirty"}
            said = _words(self.tags, state).split()[-1] if state is not None else ""
            if state is None or said in FOUL_WORDS:   # "the pizza box is starting to smell", "the mug is minging"
                st["foul"] = True
        elif kind == "tend":   # "deal with the dishes"
            st = {"op": "tend", "things": things}
        elif kind == "mess":   # "the bedding is all over the place": said, so a later clause may answer it
            place = self._sub(node, "place")
            if place is not None:   # "the sink is full of dishes": the dishes in the sink
                where = self.place(place)
                things = [{**t, "from": t.get("from") or where} for t in things]
            st = {"op": "tend", "things": things, "said": True}
        elif kind == "handling":   # "the wok is too heavy for one of you": how, for a later clause
            st = {"op": "handling", "things": things}
        elif kind == "keep":   # "leave the hoodie where it is"
            st = {"op": "keep", "things": things}
        elif kind == "empty":   # "empty the fridge onto the counter": everything in it
            place = self.place(self._sub(node, "place"))
            st = {"op": "put", "things": [{"words": f"everything in {place['words']}", "everything": True,
                                           "from": place}]}
            if self._sub(node, "target") is not None:
                st["to"] = self.target(self._sub(node, "target"))
        else:   # "desire": "I fancy a warm bagel": the thing in the state its adjective names
            noun = self._sub(node, "noun")
            adjs = [str(self.tag_of(self._tokens(a)[0]).value) for a in self._subs(node, "adj")]
            det = [self.tag_of(t).words for t in self._tokens(node) if self._cls(t) == "THE"]
            sel = {"words": _words(self.tags, noun), "noun": self.noun(noun), **({"det": det[0]} if det else {})}
            st = {"op": "change", "things": [sel], "to": adjs[-1]}
        return st

    def cue(self, node: Tree, things: list[dict]) -> dict:
        st: dict = {"op": "cue", "things": things}
        act, light = self._sub(node, "activity"), self._sub(node, "lightcue")
        warmth = self._sub(node, "tempcue") or self._sub(node, "tempadj")
        if warmth is not None:
            t = self.tag_of(self._tokens(warmth)[0])
            to = TEMPERATURE_ADJECTIVES.get(str(t.value)) if warmth.data == "tempadj" else str(t.value)
            if to is None:   # "it is dirty in here": no temperature, no cue
                raise TranslationError(f"'{t.words}' says nothing of how warm it is")
            st.update(to=to, cue=f"it is {t.words}", heating=True, device="heating")
        elif act is not None:
            word = self.tag_of(self._tokens(act)[0]).words
            st.update(to="off", cue=f"nobody is {word}")
            if ACTIVITIES.get(word):
                st["default"] = ACTIVITIES[word]
        elif light is not None:
            t = self.tag_of(self._tokens(light)[0])
            st.update(to=str(t.value), cue=f"it is {t.words}", default=LIGHT_CATEGORY_WORD)
        elif self._has(node, "DOACT") or (self._has(node, "SEE") and self._has(node, "TO")):
            # "I want to watch something": what the activity needs, on; "too dark to study": the light
            t = next(self.tag_of(x) for x in self._tokens(node) if self._cls(x) in ("DOACT", "SEE"))
            kind = t.value if self._cls(next(x for x in self._tokens(node) if self.tag_of(x) is t)) == "DOACT" else "light"
            if kind == "light" or light is not None:
                st.update(things=[] if light is not None else things, to="on", cue=f"to {t.words}",
                          **({"default": LIGHT_CATEGORY_WORD} if not things or light is not None else {}))
            elif things:   # "I want to watch the telly": that thing on
                st.update(to="on", cue=f"to {t.words}")
            else:
                st.update(to="on", cue=f"to {t.words}", device=str(kind))
        elif self._has(node, "SLEEPCUE"):   # "I'm trying to sleep": the lights off
            st.update(things=[], to="off", cue="sleep", default=LIGHT_CATEGORY_WORD)
        elif self._has(node, "SEE"):   # "I can't read my notes": what cannot be read is the reason
            st.update(things=[], to="on", cue="cannot see", default=LIGHT_CATEGORY_WORD)
        elif self._sub(node, "soundcue") is not None:   # "it's too quiet in here"
            t = self.tag_of(self._tokens(self._sub(node, "soundcue"))[0])
            st.update(to=str(t.value), cue=f"it is {t.words}", device="sound")
        elif self._has(node, "MUSIC"):   # "put some music on"
            st.update(to="on", cue="music wanted", device="sound")
        elif self._has(node, "HOTDRINK"):   # "could murder a cuppa"
            st.update(to="on", cue="a hot drink wanted", device="hot drink")
        else:
            st.update(to="off", cue="not needed")
        return st

    def where_instead(self, item: Tree, statements: list[dict], refused: dict | None) -> dict | None:
        """ "heat up the pie? not in the oven, use the hob": the place the change before happens,
        said after it; the place said not to use must not be the one it had. Returns the refused
        place still waiting for its replacement (None once said)."""
        if item.data == "notvia":
            via = self._sub(item, "via")
            return {"words": _words(self.tags, item), "place": self.place(self._sub(via, "place"))}
        last = statements[-1] if statements else None
        if last is None or last.get("op") != "change":
            raise TranslationError(f"'{_words(self.tags, item)}': use it for what? (no action before it)")
        place = self.place(self._sub(item, "place"))
        if refused is not None and {r["name"] for r in refused["place"]["readings"]} & \
                {r["name"] for r in place["readings"]}:
            raise TranslationError(f"'{refused['words']}' and '{_words(self.tags, item)}' name the same place")
        if "via" in last and refused is None:
            raise TranslationError(f"'{last['words']}' says where already; '{_words(self.tags, item)}' says another place")
        last["via"] = place
        last["words"] += " ; " + (refused["words"] + " , " if refused else "") + _words(self.tags, item)
        return None

    def ensure(self, node: Tree) -> list[dict]:
        """"make sure the oven is closed and the big light is off": one change per wish."""
        out = []
        for wish in self._subs(node, "wish"):
            to = self.state(self._sub(wish, "state"))
            if self._sub(wish, "not") is not None:   # "make sure the oven is not on"
                to = OPPOSITE[to]
            out.append({"op": "change", "things": self.things(self._sub(wish, "sthings")),
                        "to": to, "words": _words(self.tags, wish)})
        return out

    def order(self, tree: Tree) -> dict:
        items = [c for c in tree.children if isinstance(c, Tree)]
        statements: list[dict] = []
        refused_place: dict | None = None
        for item in items:
            if item.data == "reason":   # "it is late, ...": why, not what
                continue
            if item.data in ("notvia", "usevia"):
                refused_place = self.where_instead(item, statements, refused_place)
                continue
            statements += self.ensure(item) if item.data == "ensure" else [self.statement(item)]
        if refused_place is not None:   # "heat the pie, not in the oven": where then?
            raise TranslationError(f"'{refused_place['words']}': not there, but where? say where (e.g. 'use the hob')")
        if not statements:
            error = TranslationError(f"{self.command.strip()!r} gives a reason but asks for nothing; say what to do")
            error.reasons = [_words(self.tags, i) for i in items if i.data == "reason"]  # type: ignore[attr-defined]
            raise error
        return {"domain": "household", "command": self.command, "statements": statements}

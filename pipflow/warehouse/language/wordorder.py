"""Word order people use that the grammar reads in another order: a place name used as a noun
adjunct ("the north cave truckles": north cave's truckles), a topic said first and taken up by a
pronoun ("The wheels on P, double them"), a numbered place's sibling said by its number ("between
dock 1 and 2"), a list said without its commas, a product's own word said as its unit ("6 pockets
of cement"), a place the world calls by a word of where ("upstairs") said without a preposition,
and places listed after "evenly" and a comma. Each is a rewrite of a sentence's tokens; the topic
is read only where the sentence as said does not parse (``Lexed.dislocated``)."""
from __future__ import annotations

import re

from pipflow.warehouse.language.names import POSS_MARK, Tok
from pipflow.warehouse.language.roles import MOVING


def noun_adjuncts(toks: list[Tok]) -> list[Tok]:
    """A place name right before a product name is a noun adjunct, said as a possessive ("the
    north cave truckles", "one third of south cave truckles" = north cave's truckles): the
    possessive mark is put between them (with no text, so echoes quote the words as said). A
    name's "'s" before "to" is "is" ("Showroom's to hold 10 X"): nothing is possessed there."""
    out: list[Tok] = []
    for k, t in enumerate(toks):
        nxt = toks[k + 1] if k + 1 < len(toks) else None
        if (t.kind == "word" and t.value == POSS_MARK and k and toks[k - 1].kind == "name" and nxt is not None
                and nxt.kind == "word" and nxt.value == "to"):
            t = Tok("word", t.text, "is")   # "Showroom's to hold 10 X": is to, no possessive
        out.append(t)
        if t.kind == "name" and t.of == "shelf" and nxt is not None and nxt.kind == "name" and nxt.of == "product":
            out.append(Tok("word", "", POSS_MARK))
    return out


def unit_of_its_product(toks: list[Tok]) -> list[Tok]:
    """A product's word said as the unit of that same product ("6 pockets of cement" where the
    world calls cement "pocket"; "2 barrows of wheelbarrow"): one name, said in all its words.
    One product's word said as the unit of another ("3 pockets of paint") is left as said, and
    refused."""
    out: list[Tok] = []
    for t in toks:
        if (t.kind == "name" and t.of == "product" and len(out) >= 2 and out[-1].kind == "word"
                and out[-1].value == "of" and out[-2].kind == "name" and out[-2].of == "product"
                and out[-2].value == t.value):
            unit = out[-2]
            out[-2:] = [Tok("name", f"{unit.text} {out[-1].text} {t.text}", t.value, t.of)]
            continue
        out.append(t)
    return out


#: words of where that stand without a preposition ("the paint upstairs", "bring it outside"); a
#: world may call a place by one ("mezzanine": "upstairs")
WHERE_WORDS = frozenset({"upstairs", "downstairs", "outside", "inside", "outdoors", "indoors", "overhead", "downstair",
                         "upstair", "offsite", "onsite"})
#: words after which a place needs no preposition put in: it has one, or a determiner
_BEFORE_A_PLACE = frozenset({"to", "into", "onto", "in", "on", "at", "from", "off", "of", "by", "near", "up", "down",
                             "the", "a", "an", "this", "that", "out", "over", "under", "behind", "between", "and", "or",
                             "than", "via", "towards", "toward", "through", "across", "inside", "outside"})
#: what ends a sentence, or a clause with its own verb
_CLAUSE_ENDS = frozenset({".", ";", "!", "?", ":"})


def where_words_placed(toks: list[Tok]) -> list[Tok]:
    """A place said by a word of where, without a preposition (:data:`WHERE_WORDS`; "upstairs" for
    the mezzanine): where things go after a verb of moving with no "to" after it ("bring 4 barrows
    upstairs", "send 5 to the counter and the rest upstairs"), else where they are ("double the
    paint upstairs", "swap them with the ones upstairs", "no more than 3 barrows upstairs", "move the
    paint upstairs to the counter"). The preposition is put in with no text, so echoes quote the
    words as said. Said just before the place it names ("the ones upstairs in the loft", the loft
    called "upstairs"), it is that place said twice, and left out."""
    out: list[Tok] = []
    for k, t in enumerate(toks):
        before = out[-1] if out else None
        if t.kind == "name" and t.of == "shelf" and t.text.lower() in WHERE_WORDS and _said_again(toks, k):
            continue
        if (t.kind == "name" and t.of == "shelf" and t.text.lower() in WHERE_WORDS and before is not None
                and not (before.kind == "word" and before.value in _BEFORE_A_PLACE)):
            start = max((j for j in range(k) if toks[j].kind == "punct" and toks[j].value in _CLAUSE_ENDS), default=-1)
            moved = any(x.kind == "word" and x.value in MOVING for x in toks[start + 1:k])
            end = next((j for j in range(k + 1, len(toks)) if toks[j].kind == "punct"), len(toks))
            goes_on = any(x.kind == "word" and x.value in ("to", "into", "onto") for x in toks[k + 1:end])
            out.append(Tok("word", "", "to" if moved and not goes_on else "at"))
        out.append(t)
    return out


def _said_again(toks: list[Tok], k: int) -> bool:
    """Whether the place at ``k`` is named again right after it ("upstairs in the loft"; the
    Creole article is not read yet: "upstairs in de loft")."""
    j = k + 2 if k + 2 < len(toks) and toks[k + 2].kind == "word" and toks[k + 2].value in ("the", "de", "di") \
        else k + 1
    return k + 1 < len(toks) and toks[k + 1].kind == "word" and toks[k + 1].value in ("in", "on", "at") \
        and j + 1 < len(toks) and toks[j + 1].kind == "name" and toks[j + 1].value == toks[k].value


#: words of sharing out that a list of places may follow after a comma ("spread them evenly, P, Q and R")
_SHARED = frozenset({"evenly", "equally"})


def places_listed_after_sharing(toks: list[Tok]) -> list[Tok]:
    """ "spread them evenly, kontena, counter and the main shed": a list of two places or more after
    a word of sharing out and a comma, to the clause's end, is what they are shared between (the
    comma read as "between"). Anything else in the list (a product, a count) leaves it as said."""
    out = list(toks)
    for k in range(len(out) - 1):
        t, comma = out[k], out[k + 1]
        if not (t.kind == "word" and t.value in _SHARED and comma.kind == "punct" and comma.value == ","):
            continue
        end = next((j for j in range(k + 2, len(out)) if out[j].kind == "punct" and out[j].value != ","), len(out))
        listed = out[k + 2:end]
        places = [x for x in listed if x.kind == "name" and x.of == "shelf"]
        glue = all(x.kind == "name" and x.of == "shelf" or x.kind == "punct" or
                   (x.kind == "word" and x.value in ("and", "the", "&")) for x in listed)
        if len(places) >= 2 and glue:
            out[k + 1] = Tok("word", "", "between")
            break
    return out


def unmarked_lists(toks: list[Tok]) -> list[Tok]:
    """Names of one kind said one after another, the last joined by "and" / "or", are a list said
    without its commas, as dictation writes it ("between mezzanine overflow and cage"): the commas
    are put in. Two names side by side with no "and" after them are left as said (no list)."""
    out: list[Tok] = []
    k = 0
    while k < len(toks):
        run = k
        while run + 1 < len(toks) and toks[run].kind == toks[run + 1].kind == "name" and toks[run].of == toks[run + 1].of:
            run += 1
        last = run + 2 + (run + 2 < len(toks) and toks[run + 2].kind == "word" and toks[run + 2].value == "the")
        closed = (last < len(toks) and toks[run + 1].kind == "word" and toks[run + 1].value in ("and", "or")
                  and toks[last].kind == "name" and toks[last].of == toks[run].of)
        for j in range(k, run + 1):
            out.append(toks[j])
            if closed and j < run:
                out.append(Tok("punct", "", ","))
        k = run + 1
    return out


#: what may follow "dock 1 and 2" for the 2 to be dock2: the end of the clause, or words that ask
#: for a share ("between dock 1 and 2 evenly"); before anything else the number may be a count
_AFTER_SIBLING = frozenset({"evenly", "equally", "each", "both", "too"})


def numbered_siblings(toks: list[Tok], names: dict[str, str]) -> list[Tok]:
    """A bare number after a numbered place and "and" / "or" / "&" is the sibling place of that
    number ("between dock 1 and 2" = dock1 and dock2), when the world has it and the number ends
    the clause (or a share word follows: :data:`_AFTER_SIBLING`); ``names``: a place's
    letters + digits ("dock2") -> its name. Elsewhere the number stays a count ("4 to dock 1 and 2
    to dock 2")."""
    out = list(toks)
    for k in range(len(out) - 2):
        place, conj, num = out[k], out[k + 1], out[k + 2]
        if not (place.kind == "name" and place.of == "shelf" and conj.kind == "word"
                and conj.value in ("and", "or", "&") and num.kind == "word" and str(num.value).isdigit()):
            continue
        nxt = out[k + 3] if k + 3 < len(out) else None
        if nxt is not None and not (nxt.kind == "punct" or (nxt.kind == "word" and nxt.value in _AFTER_SIBLING)):
            continue
        stem = re.sub(r"\d+$", "", re.sub(r"[^a-z0-9]", "", str(place.value).lower()))
        sibling = names.get(stem + str(int(num.value)))
        if sibling is not None and stem and stem != str(place.value).lower():
            out[k + 2] = Tok("name", num.text, sibling, of="shelf")
    return out


#: what may open a fronted topic ("the wheels on P, ...", "6 logs of P, ...", "all the X on P, ...")
_TOPIC_OPENERS = frozenset({"the", "those", "these", "all"})
#: prepositions that tie a fronted topic's product to its place ("X of P", "X on P")
_TOPIC_PREPOSITIONS = frozenset({"of", "on", "in", "at", "from"})


def _topic_length(toks: list[Tok], k: int) -> int:
    """How many tokens from ``k`` make a fronted topic that names a product and its place: "[the |
    N] X [of | on | in | at | from] [the] P", "P ['s] X", or "[N] X" alone; 0 when they do not."""
    j = k
    while j < len(toks) and toks[j].kind == "word" and toks[j].value in _TOPIC_OPENERS:
        j += 1
    if j < len(toks) and toks[j].kind == "num":
        j += 1
    if j + 1 < len(toks) and toks[j].kind == "name" and toks[j].of == "shelf":
        j += 1 + (toks[j + 1].kind == "word" and toks[j + 1].value == POSS_MARK)
        return j + 1 - k if j < len(toks) and toks[j].kind == "name" and toks[j].of == "product" else 0
    if not (j < len(toks) and toks[j].kind == "name" and toks[j].of == "product"):
        return 0
    j += 1
    if j < len(toks) and toks[j].kind == "word" and toks[j].value in _TOPIC_PREPOSITIONS:
        at = j + 1 + (j + 1 < len(toks) and toks[j + 1].kind == "word" and toks[j + 1].value == "the")
        if at < len(toks) and toks[at].kind == "name" and toks[at].of == "shelf":
            j = at + 1
    return j - k


def left_dislocated(toks: list[Tok]) -> list[Tok]:
    """A sentence whose topic is said first and taken up by a pronoun ("The wheels on wax bench,
    double them", "6 logs of brine room, divide them between A and B"), with the topic put where
    the pronoun stands. Only where the sentence opens with the topic, a comma follows, and
    exactly one "them" / "it" / "those" comes after it; any other sentence is returned as it is.
    Read only when the sentence as said does not parse (``Lexed.dislocated``)."""
    n = _topic_length(toks, 0)
    if not n or n >= len(toks) or not (toks[n].kind == "punct" and toks[n].value in (",", ":")):
        return toks
    # "The litter on high bay, all fifteen of it, move it to door 22": the count said of the topic
    # goes with it, as "move the litter on high bay, all fifteen of it, to door 22" says it
    said = _apposition_end(toks, n + 1)
    topic = toks[:n] + (toks[n:said] if said else [])
    start = said or n + 1
    pronouns = [j for j in range(start, len(toks)) if toks[j].kind == "word" and toks[j].value in ("them", "it", "those")]
    if len(pronouns) != 1:
        return toks
    at = pronouns[0]
    return toks[start:at] + topic + toks[at + 1:]


def _apposition_end(toks: list[Tok], k: int) -> int:
    """The index after "all [N] [of it / of them] ," opening at ``k`` (its closing comma kept with
    it), or 0 where none opens there."""
    words = [str(t.value) if t.kind in ("word", "punct") else t.kind for t in toks[k:k + 6]]
    if words[:1] not in (["all"], ["both"]):
        return 0
    j = 1 + (words[1:2] == ["num"])
    j += j > 1 and words[j + 1:j + 3] in (["of", "it"], ["of", "them"])   # a unit between: "all 15 bags of it"
    j += 2 if words[j:j + 2] in (["of", "it"], ["of", "them"]) else 0
    return k + j + 1 if j > 1 and words[j:j + 1] == [","] else 0

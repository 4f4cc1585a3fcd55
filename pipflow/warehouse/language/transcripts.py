"""What speech to text writes for a spoken order, read as what was said (issue 23).

A lead who talks to the team through a headset reaches it as the transcriber heard her: a place
said and taken back at once ("to door 22 no wait to the cage"), and the spoken "them" of "them
crock pots" (those). Each is read only where nothing else can stand: a place taken back only with a
word that takes back ("wait", "sorry", "scratch that") and a place of the same kind of preposition
after it; "them" only before a name, never as the pronoun ("send them to P"). A count written as a
word that sounds like it ("move for cases": four) is never read so: it is offered as a candidate
reading (:data:`~.repairs.HOMOPHONES`), since a count is what must never be guessed.
"""
from __future__ import annotations

from pipflow.warehouse.language.names import Tok

#: words that take back what was just said; one of them must be said for a place to be taken back
#: ("no" alone may open a rule: "to P, no robots from Q")
_TAKING_BACK = frozenset({"wait", "sorry", "scratch", "actually", "oops", "correction"})
_TAKE_BACK_WORDS = _TAKING_BACK | {"no", "that", "i", "mean", "meant", "hold", "on"}
#: prepositions of a destination, and of a source: a place is taken back by one of its own kind
_TO = frozenset({"to", "into", "onto"})
_FROM = frozenset({"from", "off"})


def them_as_determiner(toks: list[Tok]) -> list[Tok]:
    """ "double them crock pots", "keep them amrs out": "them" before a name is "those", said as
    "the" (the pronoun "them" is never followed by a name: "send them to P")."""
    return [Tok("word", t.text, "the") if t.kind == "word" and t.value == "them" and k + 1 < len(toks)
            and toks[k + 1].kind in ("name", "kind") else t for k, t in enumerate(toks)]


def _place_at(toks: list[Tok], k: int) -> tuple[str, int] | None:
    """(its preposition, the index after it) of "<preposition> [the] <place>" at ``toks[k]``."""
    if k >= len(toks) or toks[k].kind != "word" or toks[k].value not in _TO | _FROM:
        return None
    j = k + 1 + (k + 1 < len(toks) and toks[k + 1].kind == "word" and toks[k + 1].value == "the")
    if j < len(toks) and toks[j].kind == "name" and toks[j].of == "shelf":
        return str(toks[k].value), j + 1
    return None


def places_taken_back(toks: list[Tok]) -> list[Tok]:
    """ "move 4 litter from receiving to door 22 no wait to the cage": a place said with its
    preposition, then words that take it back, then a place with a preposition of the same kind
    (to, or from): the first place and the words that took it back are not read."""
    out: list[Tok] = []
    k = 0
    while k < len(toks):
        said = _place_at(toks, k)
        if said is not None:
            j = said[1]
            words: list[str] = []
            while j < len(toks) and (toks[j].kind == "punct" and toks[j].value == "," or
                                     toks[j].kind == "word" and toks[j].value in _TAKE_BACK_WORDS):
                words += [str(toks[j].value)] if toks[j].kind == "word" else []
                j += 1
            again = _place_at(toks, j)
            if again is not None and set(words) & _TAKING_BACK and (said[0] in _TO) == (again[0] in _TO):
                k = j
                continue
        out.append(toks[k])
        k += 1
    return out

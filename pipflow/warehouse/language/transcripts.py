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

#: sounds of hesitation that may come before words that take back ("to P, ah no, to Q", "12, eh
#: sorry 15"): they take nothing back themselves
HESITATIONS = frozenset({"ah", "oh", "eh", "er", "erm", "um", "umm", "uh", "hmm", "ehm", "aah"})
#: words that take back what was just said; one of them must be said for a place to be taken back
#: ("no" alone may open a rule: "to P, no robots from Q")
_TAKING_BACK = frozenset({"wait", "sorry", "scratch", "actually", "oops", "correction"})
_TAKE_BACK_WORDS = _TAKING_BACK | {"no", "nah", "nope", "that", "i", "mean", "meant", "hold", "on"} | HESITATIONS
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
    (to, or from): the first place and the words that took it back are not read. The new place
    may be said alone where it ends its clause ("to rack 3, no, rack 1", "to rack 3... nah scratch
    that, rack 1 self"): it then stands where the place taken back stood, after its preposition."""
    out: list[Tok] = []
    k = 0
    while k < len(toks):
        said = _place_at(toks, k)
        if said is not None:
            j = said[1]
            words: list[str] = []
            stops = False
            while j < len(toks) and (toks[j].kind == "punct" and toks[j].value in _MARKS or
                                     toks[j].kind == "word" and toks[j].value in _TAKE_BACK_WORDS):
                words += [str(toks[j].value)] if toks[j].kind == "word" else []
                stops |= toks[j].kind == "punct" and toks[j].value != ","
                j += 1
            again = _place_at(toks, j)
            marked = set(words) & _TAKING_BACK
            # "no" alone set off by commas before the place said again with its preposition ("to P,
            # no, to Q"); "to P, no Q" may be a rule, and is left as said
            no_alone = bool(set(words) & _NO) and toks[j - 1].kind == "punct" and toks[said[1]].kind == "punct"
            if again is not None and (marked or no_alone) and not stops and (said[0] in _TO) == (again[0] in _TO):
                k = j
                continue
            alone = _place_alone(toks, j)
            # said alone, "no" is enough where a comma sets the place off ("to P, no, Q"): "to P, no Q"
            # may be a rule ("no robots from Q")
            if alone is not None and (marked or (set(words) & _NO and toks[j - 1].kind == "punct")):
                out += [toks[k], toks[alone[0]]]
                k = alone[1]
                continue
        out.append(toks[k])
        k += 1
    return out


#: what may stand between a place and the words that take it back ("to P... nah, scratch that")
_MARKS = frozenset({",", ".", ";", ":"})
#: a bare "no" taking a place back ("to P, no, Q"; Trinidadian, Australian "nah")
_NO = frozenset({"no", "nah", "nope"})
#: words that may follow a place said again alone ("rack 1 instead", Trinidadian "rack 1 self")
_AFTER_AGAIN = frozenset({"instead", "self", "then", "please", "pls"})


def _place_alone(toks: list[Tok], j: int) -> tuple[int, int] | None:
    """(the place's index, the index after it) of "[the] <place> [instead]" at ``toks[j]`` where
    its clause ends there; None where there is no such place."""
    j += j < len(toks) and toks[j].kind == "word" and toks[j].value == "the"
    if not (j < len(toks) and toks[j].kind == "name" and toks[j].of == "shelf"):
        return None
    end = j + 1
    while end < len(toks) and toks[end].kind == "word" and toks[end].value in _AFTER_AGAIN:
        end += 1
    if end < len(toks) and not (toks[end].kind == "punct" or toks[end].kind == "word" and toks[end].value in ("and", "then")):
        return None
    return j, end


#: words that take a whole order back ("..., no wait, cut it by a third"); one of them must be said
#: ("sorry" and "actually" alone may open another order: "Sorry, move 3 Y to Q")
_ORDER_TAKEN_BACK = frozenset({"no", "nah", "nope", "scratch", "correction"})
#: words that make the next order an addition, not a replacement ("no wait, also move ...")
_ADDING = frozenset({"also", "too", "again", "and", "plus", "as", "then"})
_SENTENCE_ENDS = frozenset({".", "!", "?", ";"})
#: pronouns of the order taken back, which the new order may say its things with
_PRONOUNS = frozenset({"it", "them", "those"})


def orders_taken_back(toks: list[Tok], verbs: frozenset[str]) -> list[Tok]:
    """ "halve the X on P, nah wait, cut it by a third": an order, then words that take it back,
    then an order in the same sentence: the first is not read, and the new order's "it" is the
    first order's things ("cut the X on P by a third"). Only where the taking back says no
    ("no", "nah", "scratch that", ...), both parts open with a verb of an order, and the
    new one adds nothing ("no wait, also move ...": both, left as said)."""
    k = 0
    while k < len(toks):
        if not (toks[k].kind == "punct" and toks[k].value in {",", ".", ":"}):
            k += 1
            continue
        j, said = k + 1, set()
        while j < len(toks) and (toks[j].kind == "word" and toks[j].value in _TAKE_BACK_WORDS | {"just"}
                                 or toks[j].kind == "punct" and toks[j].value in {",", "."}):
            said |= {str(toks[j].value)} if toks[j].kind == "word" else set()
            j += 1
        # the order taken back is the clause before the taking back, never an earlier one ("move 5 X to
        # P, then halve ..., no wait, ...": the move stays)
        start = max((i for i in range(k) if toks[i].kind == "punct"), default=-1) + 1
        start += start < k and toks[start].kind == "word" and toks[start].value in ("and", "then")
        end = next((i for i in range(j, len(toks)) if toks[i].kind == "punct" and toks[i].value in _SENTENCE_ENDS),
                   len(toks))
        new = toks[j:end]
        clause = new[:next((i for i, t in enumerate(new) if t.kind == "punct"), len(new))]
        if not (said & _ORDER_TAKEN_BACK and j > k + 1 and _opens_order(toks[start:k], verbs) and _opens_order(new, verbs)
                and not any(t.kind == "word" and t.value in _ADDING for t in clause)):
            k += 1
            continue
        pronoun = next((i for i, t in enumerate(new) if t.kind == "word" and t.value in _PRONOUNS), None)
        if pronoun is not None:   # the things after the first order's verb
            verb = start + next(i for i, t in enumerate(toks[start:k]) if not (t.kind == "word" and t.value == "just"))
            new = new[:pronoun] + toks[verb + 1:k] + new[pronoun + 1:]
        toks = toks[:start] + new + toks[end:]
        k = start + 1
    return toks


def _opens_order(part: list[Tok], verbs: frozenset[str]) -> bool:
    """Whether a part opens with a verb of an order (after "just"); "make that 6", "make it 6"
    restate a count, and are read as such (:func:`~.lexicon.corrected_later`)."""
    words = [t for t in part if not (t.kind == "word" and t.value == "just")]
    restates = len(words) > 1 and words[0].value == "make" and words[1].kind == "word" and words[1].value in ("that", "it")
    return bool(words) and words[0].kind == "word" and words[0].value in verbs and not restates

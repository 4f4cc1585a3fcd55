"""A sentence said as its parts, each marked for its role, in any order: read in the grammar's order.

Speakers of topic-comment and verb-final languages (Japanese, Korean, Turkish, Vietnamese) say the
place and the thing first and the verb last, or no verb at all: "bearing 6 case nyuka to A rack
please move", "B rack V belt seven case, to picking please move", "picking motor 3 case take out",
"B rack bearing total 10 case should be". Each part carries its own role there: a place after
"from" is where things come from, after "to" (or an arrow) where they go, a count stands next to
what it counts, and the verb names the operation. So a sentence (or a clause) made of nothing but
such parts reads one way whatever their order, and is read so; one with any other word, a second
operation, or a part whose role two readings could give is left as said for the grammar, which
reads or refuses it. Nothing is guessed: every word of the span is placed, or nothing is rewritten.
"""
from __future__ import annotations

from dataclasses import dataclass, field

from pipflow.warehouse.language.names import COUNT_UNITS, POSS_MARK, Tok
from pipflow.warehouse.language.reordered import said_at

#: words that mark where things come from, go to, or are, before a place
_FROM = frozenset({"from", "off"})
_TO = frozenset({"to", "into", "onto"})
_AT = frozenset({"at", "in", "on"})
#: words that carry nothing of the order in such a span ("wa": Japanese's topic particle)
_FILLERS = frozenset({"please", "pls", "plz", "kindly", "the", "wa", POSS_MARK, "now", "today"})
#: verbs of moving things from one place to another
MOVING = frozenset({"move", "bring", "send", "take", "carry", "transfer", "shift", "deliver", "relocate",
                    "ferry", "haul", "shuttle", "put"})
#: words said for taking things out of a place, longest first
_REMOVING = (("take", "out"), ("take", "away"), ("remove",), ("cut",), ("reduce",))
#: words said for what a place lacks ("is missing 6 X on B", Portuguese "está faltando"): add it
_LACKING = (("is", "missing"), ("are", "missing"), ("missing",))
#: words said for the count a place should end with ("should be", "total N")
_SETTING = (("should", "be"), ("must", "be"), ("should", "have"), ("must", "have"), ("make", "it", "total"),
            ("make", "total"), ("make", "it"), ("make",), ("total",))
#: what the speaker thinks of how much a place holds, said right after the thing ("rack A resistor
#: reel too many, take 6 off"): the reason for the order that follows, which says the count
_APPRAISALS = (("too", "many"), ("too", "much"), ("very", "many"), ("very", "much"))
#: verbs that change what a place holds of a thing, said with no count
_CHANGING = frozenset({"double", "triple", "halve"})
#: verbs that take everything out of a place
_EMPTYING = frozenset({"empty", "clear"})
#: verbs that exchange what two places hold
_SWAPPING = frozenset({"swap", "exchange", "switch", "interchange"})
#: how much of a thing, said for its count ("half of it", "all")
_SHARES = frozenset({"half", "all"})
#: parts said after a count ("one third of it")
_PARTS = frozenset({"third", "thirds", "quarter", "quarters"})
_PRONOUNS = frozenset({"it", "them"})


@dataclass
class _Said:
    """The parts of a span, by role."""

    items: list[tuple[list[Tok], Tok]] = field(default_factory=list)   # (amount, product)
    amounts: list[tuple[int, list[Tok]]] = field(default_factory=list)  # (position, amount) not yet paired
    products: list[tuple[int, Tok]] = field(default_factory=list)
    sources: list[Tok] = field(default_factory=list)
    targets: list[Tok] = field(default_factory=list)
    bare: list[Tok] = field(default_factory=list)       # places said with no word of role (or "at")
    verbs: list[tuple[str, Tok]] = field(default_factory=list)   # (operation, its first token)
    marks: dict[int, Tok] = field(default_factory=dict)   # id of a place -> the word said before it
    everything: bool = False
    joined: bool = False   # "and" said between two things
    both: bool = False     # "both to picking": the things said before
    only: bool = False     # "only" said right after a product


def read_by_roles(toks: list[Tok]) -> list[Tok]:
    """The tokens with each sentence, or else each clause, that is made only of parts marked for
    their role read in the grammar's order (see the module's docstring); everything else as said.
    A clause after a comma is read with no verb said only where nothing before it in its sentence
    names a count or a thing ("Send 5 logs, no wait, 4 logs from ..." takes a count back)."""
    out: list[Tok] = []
    k = 0
    while k < len(toks):
        end = next((j for j in range(k, len(toks)) if toks[j].kind == "punct" and toks[j].value in ".;!?:"), len(toks))
        out += _sentence(toks[k:end])
        if end < len(toks):
            out.append(toks[end])
        k = end + 1
    return out


def _sentence(sentence: list[Tok]) -> list[Tok]:
    """One sentence read by roles: whole (its commas set off a topic), or clause by clause."""
    whole = _read([t for t in sentence if not (t.kind == "punct" and t.value == ",")], verbless=True)
    if whole is not None and any(t.kind == "punct" for t in sentence) and _names_a_count_twice(sentence):
        whole = None   # "move 5 X, no, 4 X ...": two counts of one thing across a comma
    if whole is not None:
        return whole
    out: list[Tok] = []
    k = 0
    said_before = False
    wanted = False   # the clause before was read by roles as a count wanted
    while k <= len(sentence):
        end = next((j for j in range(k, len(sentence)) if sentence[j].kind == "punct"), len(sentence))
        clause = sentence[k:end]
        read = _read(clause, verbless=not said_before) if clause else None
        if read is None and wanted:
            read = _wanted_again(clause)
        wanted = read is not None and _wants(read)
        out += clause if read is None else read
        said_before = said_before or any(t.kind == "num" or t.kind == "name" and t.of == "product" for t in clause)
        if end < len(sentence):
            out.append(sentence[end])
        k = end + 1
    return out


def _wants(read: list[Tok]) -> bool:
    """Whether a span read by roles says the count a place should have."""
    return len(read) > 2 and read[1].value == "should" and read[2].value == "have"


def _wanted_again(clause: list[Tok]) -> list[Tok] | None:
    """ "dispatch fish sauce make it 6, and pickface snack 7": after a count wanted, a clause of one
    place, one product and one count (in either order, "and" before it or not) wants that count
    there too (the verb is shared, as the grammar reads "P should have 6 X, Q 7")."""
    words = clause[1:] if clause and clause[0].kind == "word" and clause[0].value == "and" else clause
    said = _parts(words)
    if said is None or said.verbs or said.sources or said.targets or len(said.bare) != 1 or not _paired(said) \
            or len(said.items) != 1 or not said.items[0][0] or said.items[0][0][0].kind != "num":
        return None
    return clause[:len(clause) - len(words)] + [said.bare[0], Tok("word", "", "should"), Tok("word", "", "have"),
                                                *_things(said)]


def _names_a_count_twice(sentence: list[Tok]) -> bool:
    """Whether a product is counted in two comma-parts of the sentence (a count taken back)."""
    counted: set[object] = set()
    part: set[object] = set()
    for t in sentence + [Tok("punct", ",", ",")]:
        if t.kind == "punct":
            if counted & part:
                return True
            counted |= part
            part = set()
        elif t.kind == "name" and t.of == "product":
            part.add(t.value)
    return False


def _read(span: list[Tok], verbless: bool) -> list[Tok] | None:
    """The span in the grammar's order, or None where it is not made only of parts with roles, or
    where those parts make no one order."""
    said = _parts(span)
    if said is None or not _paired(said):
        return None
    ops = {op for op, _ in said.verbs}
    if len(ops) > 1 or len(said.verbs) > 1 and ops != {"set"} or (not ops and not verbless):
        return None   # "total 10 case should be": one wanted count said twice
    if said.verbs and span[0] is said.verbs[0][1] and ops & {"move", "remove", "add", "empty", *_CHANGING} \
            or span[0].kind == "word" and span[0].value in _FROM | _TO:
        return None   # said in the grammar's order already: read as said
    op = next(iter(ops), "move" if said.targets else "")
    places = said.sources + said.bare
    if said.only and op != "swap":
        return None   # "only" says no more than a swap of one product does; elsewhere it is a rule
    if op == "swap":
        return _swap(said, span)
    if op == "move" and len(said.targets) == 1 and len(places) == 1 and (said.items or said.everything):
        verb = said.verbs[0][1] if said.verbs else Tok("word", "", "move")
        source, target = places[0], said.targets[0]
        return [_as(verb, "move"), *_things(said), _as(said.marks.get(id(source)), "from"), source,
                _as(said.marks.get(id(target)), "to"), target]
    if said.targets or said.sources and op != "remove" or len(places) != 1:
        return None
    place = places[0]
    verb = said.verbs[0][1] if said.verbs else None
    counted = bool(said.items) and all(amount and amount[0].kind == "num" for amount, _ in said.items)
    if op == "remove" and said.items and all(amount for amount, _ in said.items):
        return [_as(verb, "take"), Tok("word", "", "out"), *_things(said), Tok("word", "", "from"), place]
    if op in ("add", "lack") and counted:
        return [_as(verb, "add"), *_things(said), Tok("word", "", "to"), place]
    if op == "set" and counted:
        return [place, Tok("word", "", "should"), Tok("word", "", "have"), *_things(said)]
    if op in _CHANGING and len(said.items) == 1 and not said.items[0][0]:
        return [_as(verb, op), said.items[0][1], Tok("word", "", "on"), place]
    if op == "empty" and not said.items:
        return [_as(verb, "empty"), place]
    return None


def _swap(said: _Said, span: list[Tok]) -> list[Tok] | None:
    """ "P and Q, V belt only exchange", "P and Q, all contents exchange": two places said with
    "and", then one product (no count) or everything, as "swap <it> between P and Q"."""
    if len(said.bare) != 2 or said.sources or said.targets or not said.joined:
        return None
    if said.everything:
        what = Tok("word", "", "everything")
    elif len(said.items) == 1 and not said.items[0][0]:
        what = said.items[0][1]
    else:
        return None
    return [_as(said.verbs[0][1], "swap"), what, Tok("word", "", "between"), said.bare[0], Tok("word", "", "and"),
            said.bare[1]]


def _as(verb: Tok | None, value: str) -> Tok:
    """The verb token, read as ``value`` (its text kept for messages)."""
    return Tok("word", verb.text if verb is not None else "", value)


def _things(said: _Said) -> list[Tok]:
    """ "4 bearing and 5 vbelt", "half of motor", or "everything"."""
    if said.everything:
        return [Tok("word", "", "everything")]
    out: list[Tok] = []
    for amount, product in said.items:
        if out:
            out.append(Tok("word", "", "and"))
        of = bool(amount) and amount[-1].kind == "word" and amount[-1].value in _PARTS | {"half"}
        out += amount + [Tok("word", "", "of")] * of + [product]
    return out


def _paired(said: _Said) -> bool:
    """Pair each product with the amount said right before or right after it (all on one side);
    False where that is not one way."""
    if said.everything:
        return not said.products and not said.amounts
    if not said.products:   # "packing clear": a place emptied needs no thing named
        return not said.amounts and [op for op, _ in said.verbs] == ["empty"]
    if len(said.products) == 1:
        if len(said.amounts) > 1:
            return False
        said.items = [(said.amounts[0][1] if said.amounts else [], said.products[0][1])]
        return True
    if len(said.amounts) != len(said.products) or not said.joined:
        return False
    for side in (-1, 1):
        at = {pos: amount for pos, amount in said.amounts}
        pairs = [(at.get(pos + side), product) for pos, product in said.products]
        if all(amount is not None for amount, _ in pairs):
            said.items = [(amount, product) for amount, product in pairs if amount is not None]
            return True
    return False


def _parts(span: list[Tok]) -> _Said | None:
    """The span's parts by role; None where a word has no role here. Positions count parts, not
    tokens, so that "bearing 6 case" and "6 case bearing" pair the count with the thing."""
    said = _Said()
    k = part = 0
    while k < len(span):
        t = span[k]
        word = t.value if t.kind == "word" else None
        at = k + 1 + _word_in(span, k + 1, frozenset({"the"}))   # "on the B"
        nxt_place = at < len(span) and span[at].kind == "name" and span[at].of == "shelf"
        phrase = _phrase_at(span, k)
        if word in _FILLERS or word == "back" and said.verbs:
            k += 1
            continue
        if t.kind == "name" and t.of == "shelf":
            said.bare.append(t)
        elif t.kind == "name" and t.of == "product":
            said.products.append((part, t))
            # "connector ctn", "connector ctn 4": the thing's unit said after it, with its count or none
            k += _word_in(span, k + 1, COUNT_UNITS)
        elif said.products and not said.amounts and not said.verbs \
                and any(said_at(span, k, words) for words in _APPRAISALS):
            # "resistor reel too many (already)", "fish sauce in reserve too much": why, not how many
            # (no count and no verb said before it)
            k += 2 + _word_in(span, k + 2, frozenset({"already"}))
            continue
        elif word in _FROM and nxt_place:
            said.sources.append(span[at])
            said.marks[id(span[at])] = t
            k = at
        elif word in _TO and nxt_place:
            said.targets.append(span[at])
            said.marks[id(span[at])] = t
            k = at
        elif word in _AT and nxt_place and k:
            said.bare.append(span[at])
            k = at
        elif t.kind == "num":   # "6 case", "one third of it"
            n = 1 + _word_in(span, k + 1, _PARTS)
            amount = span[k:k + n]
            n += 2 * (n > 1 and _of_it(span, k + n))
            n += _word_in(span, k + n, COUNT_UNITS)
            said.amounts.append((part, amount))
            k += n
            part += 1
            continue
        elif word in _SHARES:   # "half of it", "all": how much, said for the count
            n = 1 + 2 * _of_it(span, k + 1)
            said.amounts.append((part, [Tok("word", t.text, word)]))
            k += n
            part += 1
            continue
        elif word in ("everything", "anything", "contents"):   # "all contents exchange"
            said.everything = True
        elif word == "only" and said.products and said.products[-1][0] == part - 1:
            said.only = True   # "V belt only exchange": that product, as a swap of it says
        elif word == "and":
            said.joined = True
        elif word == "both":
            said.both = True
        elif word in ("off", "out", "away") and said.amounts and said.amounts[-1][0] == part - 1 \
                and [(op, v.value) for op, v in said.verbs] in ([("move", "take")], [("remove", "cut")]):
            # "pickface sabun take 2 off": take 2 out; "cut one third away"
            said.verbs = [("remove", said.verbs[0][1])]
        elif word == "more" and said.amounts and said.amounts[-1][0] == part - 1:
            said.verbs.append(("add", t))
        elif phrase is not None:
            said.verbs.append((phrase[0], t))
            k += phrase[1]
            continue
        else:
            return None
        k += 1
        part += 1
    if not said.products and [a[0].value for _, a in said.amounts] == ["all"]:
        said.everything, said.amounts = True, []   # "shukka all to nyuka": all it holds
    if said.both and len(said.products) < 2:
        return None
    return said


def _phrase_at(span: list[Tok], k: int) -> tuple[str, int] | None:
    """The operation named by the words at ``k`` and how many words name it, or None."""
    for words in _REMOVING:
        if said_at(span, k, words):
            return "remove", len(words)
    for words in _SETTING:
        if said_at(span, k, words):
            return "set", len(words)
    for words in _LACKING:
        if said_at(span, k, words):
            return "lack", len(words)
    t = span[k]
    if t.kind != "word":
        return None
    if t.value in MOVING:
        return "move", 1
    if t.value == "add":
        return "add", 1
    if t.value in _CHANGING:
        return str(t.value), 1 + said_at(span, k + 1, ("it",))
    if t.value in _EMPTYING:
        return "empty", 1
    if t.value in _SWAPPING:
        return "swap", 1
    return None


def _word_in(span: list[Tok], k: int, words: frozenset[str]) -> bool:
    """Whether the token at ``k`` is a word of ``words``."""
    return k < len(span) and span[k].kind == "word" and span[k].value in words


def _of_it(span: list[Tok], k: int) -> bool:
    """Whether "of it" / "of them" is said at ``k``."""
    return said_at(span, k, ("of",)) and _word_in(span, k + 1, _PRONOUNS)

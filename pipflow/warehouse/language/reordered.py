"""Clauses said in another order than the grammar's, read in its order: the same words moved,
nothing guessed.

"P needs emptying" (the verb said of its object), "bay 3 to be emptied" (the passive of an order,
as office English writes it), "bay 2 gearbox should be 5" (the item as the subject of a wanted
count), "from rack B send 2 X to P" (a source said first without its comma). Each rewrite fires
only where its object opens the clause and names something of the world, and otherwise leaves the
tokens as they were, so the sentence is read, or refused, as said."""
from __future__ import annotations

from typing import Callable, Collection

from pipflow.language.asides import INTERJECTIONS
from pipflow.warehouse.language.names import COUNT_UNITS, POSS_MARK, Tok


def said_at(toks: list[Tok], k: int, words: tuple[str, ...]) -> bool:
    """Whether the words at ``k`` are ``words``."""
    return len(toks) >= k + len(words) and all(x.kind == "word" and x.value == w for x, w in zip(toks[k:], words))


def _word_in(toks: list[Tok], k: int, words: Collection[str]) -> bool:
    """Whether there is a token at ``k`` and it is a word of ``words``."""
    return 0 <= k < len(toks) and toks[k].kind == "word" and toks[k].value in words


def _name_at(toks: list[Tok], k: int, of: str) -> bool:
    """Whether there is a token at ``k`` and it names a thing of kind ``of`` ("shelf", "product")."""
    return 0 <= k < len(toks) and toks[k].kind == "name" and toks[k].of == of


def each_clause(toks: list[Tok], rewrite: Callable[[list[Tok]], list[Tok] | None],
                opens: Callable[[list[Tok], int], bool]) -> list[Tok]:
    """The tokens with ``rewrite`` applied to each clause (from where ``opens`` says one opens to
    the next mark) it rewrites; every other token as said."""
    out: list[Tok] = []
    k = 0
    while k < len(toks):
        end = next((j for j in range(k, len(toks)) if toks[j].kind == "punct"), len(toks))
        said = rewrite(toks[k:end]) if opens(toks, k) else None
        if said is None:
            out.append(toks[k])
            k += 1
            continue
        out += said
        k = end
    return out


def base_verb(word: str, verbs: Collection[str]) -> str | None:
    """The verb of :data:`verbs` that ``word`` is the "-ing" form of ("moving", "swapping",
    "bringing"), or None."""
    if not word.endswith("ing"):
        return None
    stem = word[:-3]
    return next((v for v in (stem, stem + "e", stem[:-1]) if v in verbs and len(v) > 1), None)


#: "P wants / needs <verb>ing ...": the verb said of its object ("intake's totes want moving to
#: cage", "dock 2 needs emptying"); British English, and general with "need"
_NEEDING = frozenset({"need", "needs", "want", "wants"})
#: the most words of the object said before :data:`_NEEDING`
_MOST_SUBJECT = 8


def _each_clause(toks: list[Tok], rewrite: Callable[[list[Tok], int], tuple[list[Tok], int] | None]) -> list[Tok]:
    """The tokens with each clause rewritten where ``rewrite(clause, k)`` says so: ``clause`` is the
    clause read so far (the tokens since the last mark), ``k`` the position of the next token; it
    returns the clause's new tokens and how many tokens from ``k`` on they take in, or None."""
    out: list[Tok] = []
    start, k = 0, 0
    while k < len(toks):
        said = rewrite(out[start:], k)
        if said is not None:
            out[start:], taken = said
            k += taken
            continue
        out.append(toks[k])
        if toks[k].kind == "punct":
            start = len(out)
        k += 1
    return out


def _names_an_object(subject: list[Tok]) -> bool:
    """Whether words before a verb may be its object: a few words, one of them a name of the world."""
    return 0 < len(subject) <= _MOST_SUBJECT and any(x.kind == "name" for x in subject)


def needs_doing(toks: list[Tok], verbs: Collection[str]) -> list[Tok]:
    """The tokens with each clause "<object> needs <verb>ing <rest>" read as "<verb> <object>
    <rest>", where the object opens the clause, names something of the world and holds no mark,
    and "<verb>ing" is the "-ing" form of a verb of ``verbs``. Nothing is added: the same words in
    the order of an order ("P needs emptying" is "empty P")."""
    def rewrite(subject: list[Tok], k: int) -> tuple[list[Tok], int] | None:
        if not (_word_in(toks, k, _NEEDING) and k + 1 < len(toks) and toks[k + 1].kind == "word"
                and _names_an_object(subject)):
            return None
        verb = base_verb(str(toks[k + 1].value), verbs)
        return ([Tok("word", toks[k + 1].text, verb), *subject], 2) if verb is not None else None

    return _each_clause(toks, rewrite)


#: words that join a clause to the one before and stay before its verb ("but P is to be left")
_CLAUSE_JOINS = frozenset({"but", "and", "then", "so", "or", "also", "plus"})
#: negations before "to be" ("R not to be used", "R isn't to be involved")
_NEGATIONS = frozenset({"not", "isnt", "arent", "wasnt", "werent"})
#: words before "to be" that make it no passive of an order but a modal the grammar reads
_MODAL_OF_PASSIVE = frozenset({"needs", "need", "has", "have", "must", "should", "will", "ought", "got", "wants", "want"})
#: past participles that do not end in "-ed" ("sent", "taken"), with their verbs
_IRREGULAR_PARTICIPLES = {"sent": "send", "taken": "take", "brought": "bring", "kept": "keep", "put": "put",
                          "given": "give", "got": "get", "gotten": "get", "held": "hold", "left": "leave",
                          "split": "split", "spread": "spread", "shut": "shut", "stuck": "stick", "cleared": "clear"}


def _verb_of_participle(word: str, verbs: Collection[str]) -> str | None:
    """The verb of ``verbs`` that ``word`` is the past participle of ("shifted", "emptied",
    "doubled", "swapped", "sent"), or None."""
    if word in _IRREGULAR_PARTICIPLES:
        verb = _IRREGULAR_PARTICIPLES[word]
        return verb if verb in verbs else None
    if not word.endswith("ed") or len(word) < 5:
        return None
    stem = word[:-2]
    candidates = (stem, word[:-1], stem[:-1] + "y" if stem.endswith("i") else "", stem[:-1] if stem[-1:] == stem[-2:-1] else "")
    return next((v for v in candidates if v and v in verbs), None)


def to_be_done(toks: list[Tok], verbs: Collection[str]) -> list[Tok]:
    """The tokens with each clause "<object> (is / are) (not) to be <verb>ed <rest>" read as
    "(don't) <verb> <object> <rest>": the passive of an order, as office English writes it ("half
    of the tyres in bay 1 to be shifted to bay 2", "bay 3 to be emptied", "bhavani not to be
    used"). As for :func:`needs_doing`, the object opens the clause, names something of the world
    and holds no mark, and the participle is of a verb of ``verbs``; nothing is added but "don't"
    where "not" was said.
    "<object> to be (made / kept at) N" is "<object> should be N", a count wanted (read by
    :func:`item_as_subject`)."""
    def rewrite(clause: list[Tok], k: int) -> tuple[list[Tok], int] | None:
        if not said_at(toks, k, ("to", "be")):
            return None
        joins = 0
        while joins < len(clause) and clause[joins].kind == "word" and clause[joins].value in _CLAUSE_JOINS:
            joins += 1   # "..., but showroom is to be left as it is": the "but" stays before the verb
        head, body = clause[:joins], clause[joins:]
        negated = bool(body) and body[-1].kind == "word" and body[-1].value in _NEGATIONS
        body = body[:-1] if negated else body
        while body and body[-1].kind == "word" and body[-1].value in ("is", "are"):
            body = body[:-1]
        if not _names_an_object(body) or (body[-1].kind == "word" and body[-1].value in _MODAL_OF_PASSIVE):
            return None   # "P needs to be emptied", "P has to be cleared": the grammar reads these as said
        count = k + 2 + (1 if said_at(toks, k + 2, ("made",)) else 2 if said_at(toks, k + 2, ("kept", "at")) else 0)
        if not negated and count < len(toks) and toks[count].kind == "num":
            # "radiators in bay 3 to be (made / kept at) 10": the count wanted, as "should be 10" says
            return [*clause, Tok("word", "to be", "should"), Tok("word", "", "be")], count - k
        # the participle as typed: a repair may have respelt it ("doubled" as "double")
        verb = _verb_of_participle(toks[k + 2].text.lower(), verbs) if k + 2 < len(toks) and toks[k + 2].kind == "word" else None
        if verb is None:
            return None
        dont = [Tok("word", "not", "dont")] if negated else []
        return [*head, *dont, Tok("word", toks[k + 2].text, verb), *body], 3

    return _each_clause(toks, rewrite)


#: words after "<place> <item>" that name its count ("bay 3 battery stock should ...")
_STOCK_WORDS = frozenset({"stock", "count", "qty", "quantity", "level", "levels", "inventory"})
#: modals of a wanted count, and the verbs after them that say where it ends
_NEGATED_MODALS = frozenset({"shouldnt", "mustnt"})
_WANTING_MODALS = frozenset({"should", "must", "shall", "shld", "shud"}) | _NEGATED_MODALS
_ENDING_VERBS = frozenset({"be", "go", "drop", "fall", "stay", "remain", "dip", "get"})


def item_as_subject(toks: list[Tok]) -> list[Tok]:
    """The tokens with a clause whose subject is an item on a place ("bay 2 gearbox should be
    between 4 to 6", "the tyres on bay 1 should be 10", "bay 3 battery stock should not go below
    6") read with the place as its subject and the item after the amount ("bay 2 should have
    between 4 and 6 gearbox", "bay 3 should not go below 6 battery"), as the grammar reads a
    wanted count. Only where the clause says a number after the verb and names no other item;
    "be" becomes "have"; a stock word ("stock", "count") and "on" / "in" / "at" between item and
    place are left out."""
    return each_clause(toks, _item_subject, lambda ts, k: k == 0 or ts[k - 1].kind == "punct")


def _item_subject(clause: list[Tok]) -> list[Tok] | None:
    """:func:`item_as_subject` of one clause, or None when it is no such clause."""
    j = 1 if _word_in(clause, 0, ("the",)) else 0
    poss = 1 if _word_in(clause, j + 1, (POSS_MARK,)) else 0   # "bay 2 gearbox" is read as "bay 2's gearbox"
    if _name_at(clause, j, "shelf") and _name_at(clause, j + 1 + poss, "product"):
        place, item, j = clause[j], clause[j + 1 + poss], j + 2 + poss
    elif _name_at(clause, j, "product") and _word_in(clause, j + 1, ("on", "in", "at")) and _name_at(clause, j + 2, "shelf"):
        item, place, j = clause[j], clause[j + 2], j + 3
    else:
        return None
    j += _word_in(clause, j, _STOCK_WORDS)
    if not _word_in(clause, j, _WANTING_MODALS):
        return None
    modal, j = clause[j], j + 1
    negation = [clause[j]] if _word_in(clause, j, ("not",)) else []
    j += len(negation)
    if modal.value in _NEGATED_MODALS:   # "shouldnt drop below 5": "should not"
        modal, negation = Tok("word", modal.text, "should"), [Tok("word", "", "not")]
    if not _word_in(clause, j, _ENDING_VERBS):
        return None
    verb = clause[j]
    rest = clause[j + 1:]
    if not any(x.kind == "num" for x in rest) or any(x.kind == "name" and x.of == "product" for x in rest):
        return None
    verb = Tok("word", verb.text, "have") if verb.value == "be" else verb
    last = max(n for n, x in enumerate(rest) if x.kind == "num") + 1   # the item right after the amount
    return [place, modal, *negation, verb, *rest[:last], item, *rest[last:]]


#: words that open a sentence with the place things come from, before the verb ("from rack B send 2
#: X to P", "off the cage take 3 X")
_SOURCES = frozenset({"from", "off"})


def fronted_source(toks: list[Tok], verbs: Collection[str]) -> list[Tok]:
    """The tokens with a comma after a source fronted without one: a sentence opened by "from" or
    "off" and one place, then a verb of ``verbs`` ("from rack B send 2 rooibos to the cage"), reads
    as "from rack B, send ...", which the grammar reads as it reads a fronted source said with its
    comma. Nothing is added but the comma. So also before two counted things or more ("From
    inbound 4 akü and 4 silecek to dispatch"; one is moved by :func:`count_after_item`)."""
    out: list[Tok] = []
    for k, t in enumerate(toks):
        out.append(t)
        j = k - 2 if _word_in(toks, k - 1, ("the",)) else k - 1   # "from the cage"
        if (_name_at(toks, k, "shelf") and _word_in(toks, j, _SOURCES) and (j == 0 or toks[j - 1].kind == "punct")
                and (_word_in(toks, k + 1, verbs) or _counted_things(toks, k + 1) > 1)):
            out.append(Tok("punct", ",", ","))
    return out


def source_after_verb(toks: list[Tok]) -> list[Tok]:
    """The tokens with a source said between a verb of moving and its counted things ("take from
    rack 3 4 rice and 2 soap to P", as Portuguese and Spanish order it) read as the source fronted
    with its comma: "from rack 3, take 4 rice and 2 soap to P". Only where the verb opens its
    clause and a count of a product follows the place; the words are only moved."""
    out: list[Tok] = []
    k = 0
    while k < len(toks):
        j = k + 3 if _word_in(toks, k + 2, ("the",)) else k + 2   # "take from the cais ..."
        if (_word_in(toks, k, _MOVING) and (k == 0 or toks[k - 1].kind == "punct") and _word_in(toks, k + 1, _SOURCES)
                and _name_at(toks, j, "shelf") and _counted_things(toks, j + 1)):
            out += toks[k + 1:j + 1] + [Tok("punct", ",", ","), toks[k]]
            k = j + 1
            continue
        out.append(toks[k])
        k += 1
    return out


def only_after_a_move(toks: list[Tok]) -> list[Tok]:
    """The tokens without an "only" / "just" between a verb of moving or swapping and the goods it
    names ("swap only the paint between A and B", "move just the rice to P"): a move or a swap
    touches only what it names, so the word restricts nothing more. Never before a count ("move
    only 5": a bound of its own), never after "keep" or "leave" ("keep only the rice on P" says
    all else goes), and only where a product's name follows (after "the" at most)."""
    out: list[Tok] = []
    for k, t in enumerate(toks):
        j = k + 2 if _word_in(toks, k + 1, ("the",)) else k + 1
        if _word_in(toks, k, ("only", "just")) and _word_in(toks, k - 1, _MOVING | {"swap", "exchange"}) \
                and _name_at(toks, j, "product"):
            continue
        out.append(t)
    return out


def _counted_things(toks: list[Tok], k: int) -> int:
    """How many "<count> (<unit>) (of) <product>" follow one another from ``k``, joined by "and" or a
    comma ("4 akü and 4 silecek")."""
    n = 0
    while k + 1 < len(toks) and toks[k].kind == "num":
        k += 1 + _word_in(toks, k + 1, _UNITS)
        k += _word_in(toks, k, ("of",))   # "4 (pallets) of rice"
        if not _name_at(toks, k, "product"):
            break
        n, k = n + 1, k + 1
        if not (_word_in(toks, k, ("and",)) or (k < len(toks) and toks[k].kind == "punct" and toks[k].value == ",")):
            break
        k += 1
    return n


#: verbs of moving things whose object may be said before them ("all charcoal bring to ramp 2")
_MOVING = frozenset({"move", "bring", "send", "take", "put", "carry", "shift", "transfer", "deliver", "ship",
                     "stage", "haul", "fetch", "dispatch", "relocate", "ferry", "cart", "shuttle", "divide", "split",
                     "distribute"})
#: verbs that keep a place as it is, said with "dont" after it ("rack B dont touch")
_KEEPING = frozenset({"touch", "use"})
#: what may follow a verb whose object was said first: where to, or the clause's end ("put back"
#: after its things is read by the lexicon's put_back_after_its_object)
_AFTER_VERB = frozenset({"to", "on", "onto", "into", "in", "over", "across", "up", "down", "evenly", "equally",
                         "equal"})
#: words of a noun phrase of things ("half of the water", "all charcoal", "4 of them")
_PHRASE_WORDS = frozenset({"all", "the", "of", "half", "them", "those", "these", "every", "each", "rest", "third",
                           "thirds", "quarter", "quarters"})
_SAID_NOT = frozenset({"dont", "never", "not"})
#: unit words said after a count ("5 pcs", "4 pallets"): no thing of their own
_UNITS = COUNT_UNITS

#: words that open a clause after its comma ("..., but rack B dont touch")
_JOINS = frozenset({"but", "and", "then", "so"})


def _object_phrase(clause: list[Tok]) -> int:
    """How many tokens open the clause as a noun phrase of things: counts, names of products, the
    words of :data:`_PHRASE_WORDS`, and "from" / "on" / "in" / "at" a place ("half of water from rack
    A"); 0 where none does, or where it names no product and says no "them"."""
    j = 0
    while j < len(clause):
        t = clause[j]
        if t.kind == "num" or _name_at(clause, j, "product") or _word_in(clause, j, _PHRASE_WORDS | _UNITS):
            j += 1
        elif _word_in(clause, j, ("from", "on", "in", "at")) and _name_at(clause, j + 1, "shelf") and j:
            j += 2
        else:
            break
    things = any(_name_at(clause, n, "product") or _word_in(clause, n, ("them", "those", "these")) for n in range(j))
    return j if things else 0


def object_before_verb(toks: list[Tok]) -> list[Tok]:
    """The tokens with a clause that names its things before their verb read in the grammar's order,
    as speakers of languages of free word order say it: "all charcoal bring to ramp 2 except ..." is
    "bring all charcoal to ramp 2 except ...", "half of water from rack A bring on ramp 2" is "bring
    half of water from rack A on ramp 2"; a place said before "dont touch" / "dont use" ("rack B dont
    touch") is "dont touch rack B". Only at a clause's start, with the verb right after the things
    (or after "dont" / "never") and no object after the verb (where to follows, or the clause
    ends); a clause opens after a mark, or after "but" / "and" / "then" / "so" right after one.
    Anything else is left as said."""
    out: list[Tok] = []
    k = 0
    while k < len(toks):
        if not _clause_opens(toks, k):
            out.append(toks[k])
            k += 1
            continue
        end = next((j for j in range(k, len(toks)) if toks[j].kind == "punct"), len(toks))
        if _word_in(toks, k, ("the",)) and _name_at(toks, k + 1, "shelf") and _word_in(toks, k + 2, _SAID_NOT):
            k += 1   # "the rack B dont touch": the place's article says nothing here
        clause = toks[k:end]
        n = _object_phrase(clause)
        if n == 0 and _name_at(clause, 0, "shelf") and _word_in(clause, 1, _SAID_NOT) and _word_in(clause, 2, _KEEPING):
            n, negated = 1, 1
        else:
            negated = 1 if n and _word_in(clause, n, _SAID_NOT) else 0
        v = n + negated
        verbs = _KEEPING if _name_at(clause, 0, "shelf") and n == 1 else _MOVING
        if n and _word_in(clause, v, verbs) and (v + 1 == len(clause) or _word_in(clause, v + 1, _AFTER_VERB)):
            out += clause[n:v + 1] + clause[:n] + clause[v + 1:]
            k = end
            continue
        out.append(toks[k])
        k += 1
    return out


#: verbs that change what a place holds, said after the place and its things ("bay 5 chargers
#: double it", "zone A dates reduce by a quarter", "QC area clear everything")
_CHANGING = frozenset({"double", "triple", "halve", "reduce", "cut", "increase", "empty", "clear"})
#: words after such a verb that add nothing to it: "make" / "do" said last, as Turkish closes a verb
#: with "yap" ("rack B silecek double make"), and when ("rack A dont touch today")
_SAID_LAST = frozenset({"make", "do", "today", "now", "tonight", "please"})
#: verbs that leave a place as it is ("shipping keep as it is", "rack 1 leave as is")
_LEAVING = frozenset({"keep", "leave"})
#: a pronoun taking up what was said first ("... double it"), or all of a place ("clear everything")
_RESUMING = frozenset({"it", "them"})
_EVERYTHING = frozenset({"everything", "anything", "all"})


def place_first(toks: list[Tok]) -> list[Tok]:
    """The tokens with a clause that names a place (and its things) before the verb read in the
    grammar's order: "bay 5 chargers double it" is "double chargers on bay 5", "zone A dates reduce
    by a quarter" is "reduce dates on zone A by a quarter", "zone A dates send to bay 3" is "send
    dates from zone A to bay 3", "zone B chargers dont touch" is "dont touch chargers on zone B"; "QC
    area clear everything" is "clear QC area", "zone B dont touch anything" is "dont touch zone B";
    "shipping keep as it is" is "keep shipping as it is";
    "rack 1 LCD make 40 (box) total" and "rack 2 pin total 30 box" are "rack 1 should have 40 LCD"; "shipping add 5 cable more" is "add 5
    cable more to shipping", "rack 1 send ten cable back to receiving" is "send ten cable back to
    receiving from rack 1" (a count after the verb, and where to with a verb of moving). Only at a
    clause's start, the place first, then its products (no count: a count is read by
    :func:`count_after_item`; nor one after a verb of moving), then the verb; a pronoun after the
    verb is what was said first. Anything else is left as said."""
    return each_clause(toks, _place_first, _clause_opens)


def place_set_off(toks: list[Tok]) -> list[Tok]:
    """The tokens without the comma that sets off a place said first, where the clause after it
    leaves, keeps or changes that place by "it" ("But the returns cage, leave it as it is", "Rack
    B, don't touch it"): read as said without the comma (:func:`place_first`). Anything else
    keeps its comma."""
    out: list[Tok] = []
    for k, t in enumerate(toks):
        if t.kind == "punct" and t.value == "," and k and _name_at(toks, k - 1, "shelf"):
            the = k > 1 and _word_in(toks, k - 2, ("the",))
            if _clause_opens(toks, k - 1 - the) and _takes_it_up(toks, k + 1 + _word_in(toks, k + 1, _SAID_NOT)):
                continue
        out.append(t)
    return out


def _takes_it_up(toks: list[Tok], v: int) -> bool:
    """Whether a verb that keeps, leaves or changes a place stands at ``v`` with "it" after it
    ("leave it as it is", "don't touch it"): "it" then takes up the place said first."""
    return _word_in(toks, v, _CHANGING | _KEEPING | _LEAVING) and _word_in(toks, v + 1, ("it",))


def _place_first(clause: list[Tok]) -> list[Tok] | None:
    """:func:`place_first` of one clause, or None."""
    clause = clause[1:] if _word_in(clause, 0, ("the",)) and _name_at(clause, 1, "shelf") else clause
    if not _name_at(clause, 0, "shelf"):
        return None
    j = 1 + _word_in(clause, 1, (POSS_MARK,))   # "zone A dates": zone A's dates
    while _name_at(clause, j, "product") or (_word_in(clause, j, ("and",)) and _name_at(clause, j + 1, "product")):
        j += 1
    place, things = clause[:1], [t for t in clause[1:j] if t.value != POSS_MARK]
    negated = _word_in(clause, j, _SAID_NOT)
    v = j + negated
    # "rack A leave it as it is", "rack B dont touch it": "it" takes up the place said first
    resumed = not things and _takes_it_up(clause, v)
    if resumed:
        clause = clause[:v + 1] + clause[v + 2:]
    rest = clause[v + 1:]
    done = _word_in(clause, v, ("do", "make")) and _word_in(clause, v + 1, _CHANGING)
    if done:   # "vozvrat do empty" (Russian "сделать пустым"): empty it
        clause = clause[:v] + clause[v + 1:]
        rest = clause[v + 1:]
    said_last = _word_in(clause, v, _CHANGING | _KEEPING) and bool(rest) and all(
        _word_in(rest, n, _SAID_LAST) for n in range(len(rest)))
    said_last = said_last or (resumed and not rest)
    if said_last:   # "rack B silecek double make" (Turkish "yap"), "rack A dont touch today"
        rest = []
    moving = _word_in(clause, v, _MOVING)
    if things and (_word_in(clause, v, _CHANGING | _KEEPING) or moving and not any(t.kind == "num" for t in rest)):
        # a count after a verb of moving is read by the rules of a count said late ("OB connector
        # take away 10 ctn")
        rest = rest[1:] if _word_in(rest, 0, _RESUMING) else rest
        join = "from" if moving else "on"
        return clause[j:v + 1] + things + [Tok("word", join, join)] + place + rest
    if not things and _word_in(clause, v, _CHANGING | _KEEPING) and len(rest) == 1 and _word_in(rest, 0, _EVERYTHING):
        return clause[j:v + 1] + place
    if not things and not negated and _word_in(clause, v, ("fill",)) and _word_in(rest, _word_in(rest, 0, ("full",)),
                                                                                   ("with", "up")):
        # "mezzanine fill with silecek", "karantin fill full with X": fill it with X
        return clause[v:v + 1] + place + rest[_word_in(rest, 0, ("full",)):]
    if not things and not negated and _word_in(clause, v, _LEAVING) and rest \
            and not any(t.kind in ("num", "name") for t in rest):
        # "shipping keep as it is", "rack 1 leave as is": keep shipping as it is
        return clause[v:v + 1] + place + rest
    if things and not negated and _word_in(clause, v, ("make", "total")) and rest[:1] and rest[0].kind == "num":
        # "rack 1 LCD make 40 (box) (total)", "rack 2 pin total 30 box": rack 1 should have 40 LCD
        k = 1 + _word_in(rest, 1, _UNITS)
        k += _word_in(rest, k, ("total",))
        return place + [Tok("word", "should", "should"), Tok("word", "have", "have"), rest[0]] + things + rest[k:]
    if not things and not negated and any(t.kind == "num" for t in rest):
        if _word_in(clause, v, ("add",)):    # "shipping add 5 cable more": add them to shipping
            return clause[v:v + 1] + rest + [Tok("word", "to", "to")] + place
        if moving and any(_word_in(rest, n, ("to",)) for n in range(len(rest))):
            # "rack 1 send ten cable back to receiving": from rack 1
            return clause[v:v + 1] + rest + [Tok("word", "from", "from")] + place
    if (said_last or done and not rest) and not things:
        # "asma kat empty make", "vozvrat do empty", "rack A dont touch today": as said without them
        return clause[v:v + 1] + place if not negated else clause[:v + 1]
    return None


def destination_first(toks: list[Tok]) -> list[Tok]:
    """The tokens with where to said right after a verb of moving, before the count ("put in dock 2 8
    chicken from chamber 2", as Portuguese and Spanish may order it: "pôr na doca 2 oito frangos") read
    as "put 8 chicken from chamber 2 to dock 2": only at a clause's start, the verb, "in" / "on" /
    "to" / "into" and a place, then a count; anything else is left as said."""
    return each_clause(toks, _destination_first, _clause_opens)


def _destination_first(clause: list[Tok]) -> list[Tok] | None:
    """:func:`destination_first` of one clause, or None."""
    p = 2 + _word_in(clause, 2, ("the",))   # "put in the dock 2 8 ..."
    if _word_in(clause, 0, _MOVING) and _word_in(clause, 1, ("in", "on", "to", "into")) \
            and _name_at(clause, p, "shelf") and len(clause) > p + 2 and clause[p + 1].kind == "num":
        return clause[:1] + clause[p + 1:] + [Tok("word", "to", "to")] + clause[p:p + 1]
    return None


def on_as_to(toks: list[Tok]) -> list[Tok]:
    """The tokens with "on" (and "in", "into") read as "to" where a clause moves things from (or off)
    a place it names and then says "on" another place ("bring half of water from rack A on ramp 2":
    to ramp 2, as "na" says it in Polish and "на", "в" in Russian; "move 4 X from P in Q"); only
    after the source, with a verb of moving before it or, in a clause that counts things and says no
    verb, none ("5 ibuprofen from komplektovka on otgruzka"). Where no source is said "on P" may say
    where the things are, and is left as said."""
    out = list(toks)
    start = 0
    for k in range(len(toks) + 1):
        if k < len(toks) and toks[k].kind != "punct":
            continue
        moving = counted = source = False
        for j in range(start, k):
            if _word_in(out, j, _MOVING):
                moving = True
            elif out[j].kind == "num" or _name_at(out, j, "product"):
                counted = True
            elif _word_in(out, j, ("from", "off")) and _name_at(out, j + 1, "shelf"):
                # with a verb of moving, or none said ("5 ibuprofen from komplektovka on otgruzka")
                source = moving or (counted and not any(_word_in(out, n, _VERBS_SAID) for n in range(start, k)))
            elif source and _word_in(out, j, ("on", "in", "into")) and _name_at(out, j + 1 + _word_in(out, j + 1, ("the",)),
                                                                               "shelf"):
                out[j] = Tok("word", out[j].text, "to")
        start = k + 1
    return out


#: verbs of sharing things out among places ("divide them by P, Q and R")
_SHARING = frozenset({"split", "divide", "distribute", "share", "spread"})


def by_as_among(toks: list[Tok]) -> list[Tok]:
    """The tokens with "by" before a place read as "among" in a clause that shares things out
    ("divide them equal by the cais, the expedicao and the quarentena": Portuguese and Spanish
    "por", Romanian "pe"); "divide by 2" and "by 5pm" name no place and are left as said."""
    out = list(toks)
    start = 0
    for k, t in enumerate(toks):
        if t.kind == "punct" and t.value in (".", ";", "!", "?"):
            start = k + 1
        elif _word_in(toks, k, ("by",)) and _name_at(toks, k + 1 + _word_in(toks, k + 1, ("the",)), "shelf") \
                and any(_word_in(toks, j, _SHARING) for j in range(start, k)):
            out[k] = Tok("word", t.text, "among")
    return out


def _place_list(toks: list[Tok], k: int) -> int:
    """Where a list of two places or more said from ``k`` ends ("the rack 1 and the rack 2", "P, Q
    and R"), or ``k`` where none is said there."""
    j, names = k, 0
    while True:
        j += _word_in(toks, j, ("the",))
        if not _name_at(toks, j, "shelf"):
            return k
        j, names = j + 1, names + 1
        joined = _word_in(toks, j, ("and",)) or (j < len(toks) and toks[j].kind == "punct" and toks[j].value == ",")
        if joined and (_name_at(toks, j + 1, "shelf") or _word_in(toks, j + 1, ("the",))):
            j += 1
            continue
        return j if names > 1 else k


def places_then_each(toks: list[Tok]) -> list[Tok]:
    """The tokens with places listed first and then what each gets read in the grammar's order:
    "P and Q, each (one) with 25 X" is "P and Q should each have 25 X"; "P and Q, 2 X less (more)
    in each" is "remove (add) 2 X from (to) each of P and Q". Only at a sentence's start and where
    the clause after the comma is only that."""
    out: list[Tok] = []
    start = 0
    for k in range(len(toks) + 1):
        if k == len(toks) or (toks[k].kind == "punct" and toks[k].value in (".", ";", "!", "?")):
            out += _places_then_each(toks[start:k]) + toks[k:k + 1]
            start = k + 1
    return out


def _places_then_each(toks: list[Tok]) -> list[Tok]:
    """:func:`places_then_each` of one sentence (after a word of talk set off by a comma: "Olha, ...")."""
    k = 2 if len(toks) > 2 and _word_in(toks, 0, INTERJECTIONS) and toks[1].kind == "punct" else 0
    j = _place_list(toks, k)
    if j == k or not (j < len(toks) and toks[j].kind == "punct" and toks[j].value == ","):
        return toks
    places, rest = toks[k:j], toks[j + 1:]
    end = next((n for n, t in enumerate(rest) if t.kind == "punct"), len(rest))
    clause, after = rest[:end], rest[end:]
    if _word_in(clause, 0, ("each",)):
        w = 1 + (len(clause) > 1 and clause[1].text.lower() == "one")   # "each one": a count, as tokens go
        if _word_in(clause, w, ("with",)) and _counted_things(clause, w + 1):
            said = [Tok("word", "", "should"), Tok("word", "", "each"), Tok("word", clause[w].text, "have")]
            return toks[:k] + places + said + clause[w + 1:] + after
    n = _counted_things(clause, 0)
    j = next((m for m in range(len(clause)) if _word_in(clause, m, ("less", "more"))), -1)
    if n and j > 0 and _word_in(clause, j + 1, ("in", "on", "at")) and _word_in(clause, j + 2, ("each",)) \
            and j + 3 == len(clause):
        less = clause[j].value == "less"
        verb = Tok("word", clause[j].text, "remove" if less else "add")
        to = [Tok("word", clause[j + 1].text, "from" if less else "to"), Tok("word", "each", "each"),
              Tok("word", "", "of")]
        return toks[:k] + [verb] + clause[:j] + to + places + after
    return toks


def of_as_from(toks: list[Tok]) -> list[Tok]:
    """The tokens with "of" read as "from" between a product and a place ("the arroz of the estante
    um", "half of the azeite of rack 1": the product there, as "de" says it in Portuguese, Spanish
    and Romanian); "from" is how the grammar says where things are taken from, "on" where its
    clause swaps them ("swap the arroz of rack 1 with the arroz of rack 3")."""
    out = list(toks)
    start = 0
    for k in range(1, len(toks) - 1):
        if toks[k].kind == "punct":
            start = k + 1
        elif _name_at(toks, k - 1, "product") and _word_in(toks, k, ("of",)) \
                and _name_at(toks, k + 1 + _word_in(toks, k + 1, ("the",)), "shelf"):
            end = next((j for j in range(k, len(toks)) if toks[j].kind == "punct"), len(toks))
            swaps = any(_word_in(toks, j, _SWAPPING) for j in range(start, end))
            out[k] = Tok("word", toks[k].text, "on" if swaps else "from")
    return out


#: verbs that make a clause no bare move ("5 X from P on Q" with none of them is one)
_VERBS_SAID = frozenset({"put", "leave", "keep", "count", "check", "have", "has", "is", "are", "be", "stay", "stays"})


def _clause_opens(toks: list[Tok], k: int) -> bool:
    """Whether a clause opens at ``k``: the start, after a mark, or after "and" / "but" / "then" /
    "so" right after one."""
    return k == 0 or toks[k - 1].kind == "punct" or (
        _word_in(toks, k - 1, _JOINS) and (k == 1 or toks[k - 2].kind == "punct"))


def count_after_item(toks: list[Tok]) -> list[Tok]:
    """The tokens with the count said after what it counts read before it, as learners of English
    order it (the thing first, then how many): "charcoal 5 from rack B to ramp 2" is "5 charcoal from
    rack B ...", "rack B water 5 to ramp 1" is "5 water from rack B to ramp 1" (the place said first
    is where they come from only where "to" follows the count), "from rack B detergent: 4 to ramp 2"
    is "from rack B, 4 detergent to ramp 2", "from rack A 2 detergent to returns" is "2 detergent
    from rack A to returns"; and "3 juice more on ramp 1" is "3 more juice ...".
    Only at a clause's start, with one product and one count; anything else is left as said."""
    out: list[Tok] = []
    k = 0
    while k < len(toks):
        if _clause_opens(toks, k):
            said = _item_count(toks, k)
            if said is not None:
                words, taken = said
                out += words
                k += taken
                continue
        if toks[k].kind == "num" and _name_at(toks, k + 1, "product") and _word_in(toks, k + 2, ("more",)):
            out += [toks[k], toks[k + 2], toks[k + 1]]
            k += 3
            continue
        out.append(toks[k])
        k += 1
    return out


def _item_count(toks: list[Tok], k: int) -> tuple[list[Tok], int] | None:
    """:func:`count_after_item` at a clause opening at ``k``: the tokens said instead and how many
    they replace, or None."""
    said_from = _word_in(toks, k, ("from",)) and _name_at(toks, k + 1, "shelf")
    place = toks[k + 1] if said_from else toks[k] if _name_at(toks, k, "shelf") else None
    j = k + (2 if said_from else 1 if place is not None else 0)
    # a source said first; one said without "from" gets it, unsaid (no text of its own)
    source = [toks[k] if said_from else Tok("word", "", "from"), place] if place is not None else []
    j += _word_in(toks, j, (POSS_MARK,))   # "rack B water": read as "rack B's water"
    if said_from and j + 1 < len(toks) and toks[j].kind == "num" and _name_at(toks, j + 1, "product"):
        # "from rack A 2 detergent to returns": the source said first, without its comma
        end = j + 2 + _word_in(toks, j + 2, _UNITS)
        return ([*toks[j:j + 2], *source], end - k) if _word_in(toks, end, ("to",)) else None
    if not _name_at(toks, j, "product"):
        return None
    item = toks[j]
    # a colon only after "from P" ("from rack B detergent: 4 to ..."); "tote bags: 1 on the mezz,
    # rest to packing" says a topic whose rest is asked about, and is left as said
    colon = 1 if said_from and j + 1 < len(toks) and toks[j + 1].kind == "punct" and toks[j + 1].value == ":" else 0
    n = j + 1 + colon
    if n >= len(toks) or toks[n].kind != "num":
        return None
    count = toks[n]
    n += _word_in(toks, n + 1, _UNITS)   # "5 pcs", "4 pal.": the unit goes
    if source and not _word_in(toks, n + 1, ("to", "on", "onto", "into")):
        return None          # "rack A juice 5": the place's own count, read as said
    if said_from:            # "from rack B detergent: 4 to ...": the source stays first
        return [*source, Tok("punct", ",", ","), count, item], n + 1 - k
    return [count, item, *source], n + 1 - k   # "5 water from rack B to ...", "5 charcoal from ..."


def place_must_be(toks: list[Tok]) -> list[Tok]:
    """The tokens with "(on) rack A must be 15 water" read as "rack A must have 15 water", as
    speakers of languages that say what is on a place with "be" order it ("na regale musi być"):
    only at a clause's start, a place (after "on" / "in" / "at" or not), "must" or "should", "be"
    and a count. "in P needs ..." is "P needs ..." (the place the subject, its preposition left out)."""
    out: list[Tok] = []
    k = 0
    while k < len(toks):
        j = k + _word_in(toks, k, ("on", "in", "at"))
        if (_clause_opens(toks, k) and _name_at(toks, j, "shelf") and _word_in(toks, j + 1, ("must", "should"))
                and _word_in(toks, j + 2, ("be",)) and j + 3 < len(toks) and toks[j + 3].kind == "num"):
            out += [toks[j], toks[j + 1], Tok("word", toks[j + 2].text, "have")]
            k = j + 3
            continue
        if _clause_opens(toks, k) and j > k and _name_at(toks, j, "shelf") and _word_in(toks, j + 1, _PLACE_VERBS):
            k = j   # "in karantin needs 4 more X" ("в карантине нужно"): karantin needs
            continue
        out.append(toks[k])
        k += 1
    return out


#: verbs whose object is a place: a place said first as a topic may be their "it" ("the dock, empty it")
_PLACE_OBJECT_VERBS = frozenset({"empty", "clear", "fill", "complete", "top", "clean", "restock", "refill"})


def place_as_it(toks: list[Tok]) -> list[Tok]:
    """The tokens with a place said first as a topic, set off by a comma or colon, and then "it"
    after a verb whose object is a place ("the quarentena, complete it with arroz", "dock: empty
    it"), read as that verb of the place ("complete the quarentena with arroz"). Only where the
    topic is the place alone and "it" is the verb's object."""
    out: list[Tok] = []
    k = 0
    while k < len(toks):
        j = k + _word_in(toks, k, ("the",))
        if (_clause_opens(toks, k) and _name_at(toks, j, "shelf") and j + 3 < len(toks)
                and toks[j + 1].kind == "punct" and toks[j + 1].value in (",", ":")
                and _word_in(toks, j + 2, _PLACE_OBJECT_VERBS) and _word_in(toks, j + 3, ("it",))):
            out += [toks[j + 2], toks[j]]
            k = j + 4
            continue
        out.append(toks[k])
        k += 1
    return out


#: verbs a place said first with "in" / "on" may have as its subject ("in P needs 4 X")
_PLACE_VERBS = frozenset({"needs", "need", "wants", "has", "have", "gets", "holds"})


#: where a place said in a topic stands: "LCD from rack 1", "LCD at shipping", "pin in rack 1"
_TOPIC_PLACE_WORDS = frozenset({"from", "at", "in", "on"})
#: what may say where to after a verb of moving ("to", "back to", "into"; "back iqc": back to iqc)
_WHERE_TO = frozenset({"to", "into", "onto"})


def topic_first(toks: list[Tok]) -> list[Tok]:
    """The tokens with a clause that says its things, their place and their count before a verb of
    moving read in the grammar's order, as speakers of topic-first languages (Vietnamese, Chinese,
    Korean, Turkish) order it: "6 cable receiving bring to shipping" is "bring 6 cable from
    receiving to shipping", "rack 2 sac 9 box move to receiving" is "move 9 sac from rack 2 to
    receiving", "LCD from rack 1 send 4 box to shipping" is "send 4 LCD from rack 1 to shipping",
    "3 box LCD NG area bring back iqc" is "bring 3 LCD from NG area back to iqc"; and "LCD at
    shipping double it" is "double LCD on shipping" (a verb that changes what a place holds); "mal
    kabul akü all to rack A" (no verb said) is "move all akü from mal kabul to rack A"; "iqc
    and NG area swap the cable" is "swap the cable between iqc and NG area".
    Only at a clause's start, with one product, one place (where the things are) and at most one
    count, before the verb or right after it; a verb of moving must then say where to. Anything
    else is left as said."""
    toks = each_clause(toks, _topic_first, _clause_opens)
    return each_clause(toks, lambda clause: _topic_first(clause, verbless=True), _sentence_opens)


def _sentence_opens(toks: list[Tok], k: int) -> bool:
    """Whether a sentence opens at ``k``: the start, or after . ; ! ? or a colon (a list's line)."""
    return k == 0 or (toks[k - 1].kind == "punct" and toks[k - 1].value in (".", ";", "!", "?", ":"))


#: verbs of exchanging what two places hold ("iqc and NG area swap the cable")
_SWAPPING = frozenset({"swap", "exchange", "switch", "interchange"})


def _two_places_swap(clause: list[Tok]) -> list[Tok] | None:
    """ "iqc and NG area swap the cable (only)" as "swap the cable between iqc and NG area", "rack 1
    and rack 2 swap everything" as "swap everything between rack 1 and rack 2": the two places
    first, then the verb and one product (or everything); "only" after the product says no more
    than the swap of that product does, and goes."""
    if not (_name_at(clause, 0, "shelf") and _word_in(clause, 1, ("and",)) and _name_at(clause, 2, "shelf")
            and _word_in(clause, 3, _SWAPPING)):
        return None
    rest = clause[4:]
    rest = rest[1:] if _word_in(rest, 0, ("the",)) else rest
    return _swap_of(clause[3], rest, clause[:3])


def _swap_said_after(clause: list[Tok]) -> list[Tok] | None:
    """ "iade and sevkiyat akü swap", "rack A and rack B everything change places", "P and Q change by
    places": the two places, then the product (or everything, or nothing: all they hold), then the
    verb ("swap", "change (by) places") closing the clause."""
    if not (_name_at(clause, 0, "shelf") and _word_in(clause, 1, ("and",)) and _name_at(clause, 2, "shelf")):
        return None
    clause = [t for t in clause if t.value not in (POSS_MARK, "please")]   # "sevkiyat akü": sevkiyat's akü
    said = next((n for n, words in ((3, ("change", "by", "places")), (2, ("change", "places")))
                 if said_at(clause, len(clause) - n, words)), 0)
    end = len(clause) - (said or 1)
    if end < 3 or not (said or _word_in(clause, end, _SWAPPING)) or (end == 3 and not said):
        return None
    verb = Tok("word", " ".join(t.text for t in clause[end:]), "swap")
    # "P and Q change by places" (Russian "поменять местами"): all they hold
    return _swap_of(verb, clause[3:end] or [Tok("word", "", "everything")], clause[:3])


def _swap_of(verb: Tok, rest: list[Tok], places: list[Tok]) -> list[Tok] | None:
    """"<verb> <the product or everything> between <the two places>", from what was said of it."""
    if len(rest) == 2 and _name_at(rest, 0, "product") and _word_in(rest, 1, ("only",)):
        rest = rest[:1]
    if not (len(rest) == 1 and (_name_at(rest, 0, "product") or _word_in(rest, 0, _EVERYTHING))):
        return None
    what = rest[0] if rest[0].kind == "name" else Tok("word", rest[0].text, "everything")
    return [verb, what, Tok("word", "between", "between"), *places]


def _topic_first(clause: list[Tok], verbless: bool = False) -> list[Tok] | None:
    """:func:`topic_first` of one clause, or None; ``verbless``: the clause says no verb, and opens
    a sentence (after a comma it may take a count back: "Send 5 logs, no wait, 4 logs from ...")."""
    swapped = _two_places_swap(clause) or _swap_said_after(clause)
    if swapped is not None:
        return swapped
    products: list[Tok] = []
    places: list[Tok] = []
    counts: list[Tok] = []
    share: list[Tok] = []   # "half of them", "all of them": how much of it, said as the count
    j = 0
    while j < len(clause):
        if _name_at(clause, j, "product"):
            products.append(clause[j])
        elif _word_in(clause, j, _SHARES) and not share:
            share = [clause[j]]
            j += 2 if _word_in(clause, j + 1, ("of",)) and _word_in(clause, j + 2, ("them", "it", "those")) else 0
        elif _name_at(clause, j, "shelf"):
            places.append(clause[j])
        elif _word_in(clause, j, _TOPIC_PLACE_WORDS) and _name_at(clause, j + 1, "shelf") and j:
            places.append(clause[j + 1])
            j += 1
        elif clause[j].kind == "num":
            counts.append(clause[j])
            j += _word_in(clause, j + 1, _UNITS)
        elif not _word_in(clause, j, (POSS_MARK, "the")):
            break
        j += 1
    if len(products) != 1 or len(places) != 1 or len(counts) + bool(share) > 1 or j == len(clause):
        return None
    if share:   # "rack A balata half of them send to sevkiyat": half of the balata
        counts = share + ([Tok("word", "", "of")] if share[0].value != "all" else [])
    verb, rest = clause[j], clause[j + 1:]
    if verbless != (_word_in(clause, j, ("to",)) and _name_at(clause, j + 1, "shelf")):
        return None
    if verbless:
        verb, rest = Tok("word", "", "move"), clause[j:]   # "mal kabul akü all to rack A": no verb said
    if _word_in(clause, j, _CHANGING) and not counts:
        rest = rest[1:] if _word_in(rest, 0, _RESUMING) else rest
        return [verb, *products, Tok("word", "on", "on"), *places, *rest]
    if not _word_in([verb], 0, _MOVING - {"divide", "split", "distribute"}):
        return None
    if rest and rest[0].kind == "num":   # "LCD from rack 1 send 4 box to shipping"
        if counts:
            return None
        counts, rest = [rest[0]], rest[1 + _word_in(rest, 1, _UNITS):]
    back = _word_in(rest, 0, ("back",))
    if back and _word_in(clause, j, ("put",)):
        return None   # "X from P put back Q": read by the lexicon's put_back_after_its_object
    if back and _name_at(rest, 1, "shelf"):   # "bring back iqc": back to iqc
        rest = [rest[0], Tok("word", "", "to"), *rest[1:]]
    if not (_word_in(rest, back, _WHERE_TO) and _name_at(rest, back + 1, "shelf")):
        return None
    if any(t.kind == "num" for t in rest):
        return None
    return [verb, *counts, *products, Tok("word", "from", "from"), *places, *rest]


#: how much of a thing said in a topic in place of a count ("rack A balata half of them to P send")
_SHARES = frozenset({"half", "quarter", "third", "all"})
#: modals and verbs that close a clause of a wanted count said verb last ("Rack A 10 oil filter
#: should be", "Sevkiyat 25 akü must have", "Rack B balata maximum 3 should stay")
_LAST_MODALS = frozenset({"should", "must", "shall"})
_LAST_VERBS = frozenset({"be", "have", "stay", "remain"})
#: words that may stand in such a clause's middle besides its count and product: bounds and sums
_AMOUNT_WORDS = frozenset({"minimum", "maximum", "min", "max", "at", "least", "most", "between", "and", "more",
                           "less", "fewer", "than", "times", "double", "triple", "half", "the", "only", "exactly"})
#: the words before "place" that make it every place ("every place minimum 2 X must be")
_EVERY = frozenset({"every", "each", "all"})
_PLACE_WORDS = frozenset({"place", "places", "location", "locations", "shelf", "shelves", "rack", "racks"})


def verb_last(toks: list[Tok]) -> list[Tok]:
    """The tokens with a clause said verb last, as Turkish, Korean and Japanese order it, read in the
    grammar's order: a wanted count, "Rack A 10 oil filter should be", "Dispatch minimum 8 akü must
    be", "Sevkiyat 25 akü must have", "Rack B balata maximum 3 should stay", "Every place minimum 2
    akü must be", as "<place> should have <amount> <product>"; a verb of moving said last after
    where to, "5 koli hava filtresi from rack B to dispatch carry", "rack B 6 oil filter to sevkiyat
    take", as said before where to (then read by :func:`topic_first`). Only at a clause's start,
    with one place and one product and nothing else but amounts; anything else is left as said."""
    return each_clause(toks, _verb_last, _clause_opens)


def _verb_last(clause: list[Tok]) -> list[Tok] | None:
    """:func:`verb_last` of one clause, or None."""
    if len(clause) < 3:
        return None
    removed = _removed_last(clause)
    if removed is not None:
        return removed
    if _word_in(clause, len(clause) - 1, _MOVING) and not any(_word_in(clause, j, _MOVING) for j in range(len(clause) - 1)):
        to = max((j for j in range(len(clause) - 2) if _word_in(clause, j, _WHERE_TO)), default=None)
        if to is None or to + 3 != len(clause) or not _name_at(clause, to + 1, "shelf"):
            return None
        return clause[:to] + clause[-1:] + clause[to:to + 2]
    last = len(clause) - 1
    k = last - 1 if _word_in(clause, last, _LAST_VERBS) and _word_in(clause, last - 1, _LAST_MODALS) else \
        last if _word_in(clause, last, _LAST_MODALS) else None
    bound_only = k is None
    if bound_only:   # "NG area LCD maximum 2 box only", "rack 1 cable between 10 and 12 box is ok": no verb
        k = len(clause) - next((n for n, said in ((2, ("is", "ok")), (1, ("ok",)), (1, ("is",)), (1, ("only",)), (0, ()))
                                if said_at(clause, len(clause) - n, said)), 0)
        clause = [*clause[:k], Tok("word", "", "should")]
    if _name_at(clause, 0, "product") and _word_in(clause, 1, ("on", "in", "at")) and _name_at(clause, 2, "shelf"):
        # "shampoo on otgruzka not less than 8 must be": the product first, then where it is
        clause, k = [clause[2], clause[0], *clause[3:]], k - 1
    if _name_at(clause, 0, "shelf"):
        place, j = clause[:1], 1
    elif _word_in(clause, 0, _EVERY) and len(clause) > 1 and clause[1].kind in ("word", "kind") \
            and clause[1].text.lower() in _PLACE_WORDS:   # "every place", "all location" (a kind word)
        place, j = clause[:2], 2
    else:
        return None
    middle = [t for t in clause[j:k] if t.value != POSS_MARK]   # "Rack B balata": rack B's balata
    products = [t for t in middle if _name_at([t], 0, "product")]
    if len(products) != 1 or not any(t.kind == "num" for t in middle) or not all(
            t.kind == "num" or t is products[0] or _word_in([t], 0, _AMOUNT_WORDS | _UNITS | {"not", "over", "under", "below"})
            for t in middle):
        return None
    amount = [t for t in middle if t is not products[0]]
    amount = _bounds_said_with_not(amount)
    if amount is None or bound_only and not any(_word_in([t], 0, _BOUND_WORDS) for t in amount):
        return None
    return [*place, Tok("word", clause[k].text, "should"), Tok("word", "", "have"), *amount, products[0]]


#: words of a bound: a clause said without a verb states a wanted count only with one of them
_BOUND_WORDS = frozenset({"minimum", "maximum", "min", "max", "least", "most", "between"})


#: a bound said with "not": how many words, the words, and the bound it is
_NOT_BOUNDS = ((2, ("not", "over"), "most"), (3, ("not", "more", "than"), "most"), (3, ("not", "less", "than"), "least"),
               (3, ("not", "fewer", "than"), "least"), (2, ("not", "under"), "least"), (2, ("not", "below"), "least"))


def _bounds_said_with_not(amount: list[Tok]) -> list[Tok] | None:
    """The amount with "not over N" and "not more than N" read as "at most N", "not less than N" as
    "at least N" ("all location sac not over 15 box", "not less than 8 must be"); None where "over"
    or "not" is said otherwise (a bound the other way is not guessed)."""
    out: list[Tok] = []
    k = 0
    while k < len(amount):
        said = next(((n, bound) for n, words, bound in _NOT_BOUNDS if said_at(amount, k, words)), None)
        if said is not None:   # "not over 15", "not less than 8": at most 15, at least 8
            out += [Tok("word", amount[k].text, "at"), Tok("word", "", said[1])]
            k += said[0]
            continue
        if _word_in(amount, k, ("not", "over")):
            return None
        out.append(amount[k])
        k += 1
    return out


def _removed_last(clause: list[Tok]) -> list[Tok] | None:
    """ "Rack B 10 hava filtresi take out", "rack A 4 silecek take away": a place, a count and a
    product, then "take out" / "take away" / "remove" closing the clause, as "take out 10 hava
    filtresi from rack B"; None for anything else."""
    n = 2 if said_at(clause, len(clause) - 2, ("take", "out")) or said_at(clause, len(clause) - 2, ("take", "away")) \
        else 1 if _word_in(clause, len(clause) - 1, ("remove",)) else 0
    topic = [t for t in clause[:len(clause) - n] if t.value != POSS_MARK and not _word_in([t], 0, _UNITS)]
    topic = topic[1:] if _word_in(topic, 0, ("from",)) else topic   # "Rack A'dan 4 silecek take out": from rack A
    if not n or len(topic) != 3 or not _name_at(topic, 0, "shelf"):
        return None
    count, item = (topic[1], topic[2]) if topic[1].kind == "num" else (topic[2], topic[1])
    if count.kind != "num" or not _name_at([item], 0, "product"):
        return None
    return [*clause[len(clause) - n:], count, item, Tok("word", "from", "from"), topic[0]]

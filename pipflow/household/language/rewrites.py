"""The command's words rewritten before tagging, where a word-level rule says what the grammar need
not: how the steps run ("do both in parallel", "first", "afterwards"), how long ("for two
minutes", offered only as a candidate), what for ("for later"), amounts of a thing ("a bowl of
cherries"), and "or" under a negation ("nobody is using X or Y"). Each rewrite leaves a note."""
from __future__ import annotations

import re

from pipflow.household.language.lexicon import (DURATION_HEDGES, DURATION_UNITS, FILLER, GRADED, HOT_DRINKS, MANNER_OBJECTS,
                                                MANNERS, MEALS, MEASURES, ORDER_VERB_WORDS, ORDER_WORDS, ORDINAL_DETERMINERS,
                                                PHRASES, PURPOSE_INFINITIVES, PURPOSE_WORDS, PURPOSES, TIME_WORDS)
from pipflow.household.language.names import name_end
from pipflow.household.language.tokens import PUNCT
from pipflow.language.asides import DETERMINERS, VOCATIVES, near_operative
from pipflow.language.numbers import read_number


#: words that put a step after the others, closing a clause ("... and bring them to the desk
#: after", "put it back afterwards"): the order of the steps, which the plan decides
CLOSING_ORDER_WORDS = {"after", "afterwards", "afterward", "later", "next"}


def without_manner(words: list[str], notes: list[str]) -> list[str]:
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
        manner = next((m for m in _MANNERS_LONGEST_FIRST if len(m) <= len(body) and tuple(body[len(body) - len(m):]) == m),
                      None)
        if clause and manner is not None and tuple(body[:len(body) - len(manner)]) in MANNER_OBJECTS:
            notes.append(f"'{' '.join(clause)}' says how the steps run, not what the home should end like; "
                         "the plan decides the order")
            if k < len(words) and w != "," and out and out[-1] not in PUNCT:
                out.append(w)   # a sentence's end stays; a comma goes with the clause
            start = k + 1
            continue
        if len(clause) > 1 and clause[0] in ("after", "afterwards") and (clause[1],) in PHRASES \
                and PHRASES[(clause[1],)][0].startswith("V_"):
            # "After close the oven" (Turkish "sonra kapat"): then; the order of the steps
            notes.append(f"'{clause[0]}' before '{clause[1]}': the order of the steps; the plan decides it")
            clause = clause[1:]
        clause = _without_inner_manner(clause, notes)
        # "close the pantry after lol": a filler closing the clause does not hide the word before it
        said_last = next((j for j in range(len(clause), 0, -1) if (clause[j - 1],) not in FILLER), 0)
        clause, closing = clause[:said_last], clause[said_last:]
        while len(clause) > 2 and clause[-1] in CLOSING_ORDER_WORDS and clause[-2] not in ("for", "until", "till"):
            # "bring them to the desk after" ("for later" is a purpose: _without_purpose)
            notes.append(f"'{clause[-1]}': the order of the steps; the plan decides it")
            clause = clause[:-1]
        clause += closing
        kept = []
        for j, x in enumerate(clause):   # "wash the mug first", "first the mug, then the plate"
            if x in ORDER_WORDS and not (j and clause[j - 1] in ORDINAL_DETERMINERS) and \
                    not (j + 1 < len(clause) and clause[j + 1] == "of") and \
                    not (j + 1 < len(clause) and (x, clause[j + 1]) in TIME_WORDS):
                notes.append(f"'{x}': the order of the steps; the plan decides it")
                continue
            kept.append(x)
        clause = _without_inner_purposes(kept, notes)
        out += clause + ([w] if k < len(words) else [])
        start = k + 1
    while out and out[-1] == ",":
        out.pop()
    return out


#: words after which a manner phrase closes what it says ("lift it in together and wash it")
_MANNER_ENDS = {"and", "then", "to", "into", "onto", "over", "across", "back"}


#: the manner phrases, the longest first (a longer phrase wins where two start at one word)
_MANNERS_LONGEST_FIRST = sorted(MANNERS, key=len, reverse=True)


def _without_inner_manner(clause: list[str], notes: list[str]) -> list[str]:
    """A clause that asks something, without a manner phrase (lexicon ``MANNERS``) closing it or
    one of its parts joined by "and" / "then" ("lift it into the sink together and wash it"):
    how, not what the home should end like."""
    out: list[str] = []
    j = 0
    while j < len(clause):
        m = next((m for m in _MANNERS_LONGEST_FIRST if tuple(clause[j:j + len(m)]) == m), None)
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


#: a request's closing tag, after which a purpose may still close the clause before it
CLOSING_TAGS = (("would", "you"), ("will", "you"), ("could", "you"), ("please",), ("thanks",), ("ta",), ("pls",))
#: whose a purpose is ("for my breakfast", "for the little one")
BENEFICIARY_DETERMINERS = {"the", "my", "our", "your", "his", "her", "their"}


def _without_inner_purposes(clause: list[str], notes: list[str]) -> list[str]:
    """:func:`_without_purpose` at the end of the clause and before each "and", "then" or "but" in it:
    speech to text writes no commas ("warm up the stew for lunch and slice the tomato")."""
    out: list[str] = []
    start = 0
    for j, x in enumerate(clause + ["and"]):
        if PHRASES.get((x,), ("",))[0] in ("AND", "THEN", "BUT") and j > start:
            out += _without_purpose(clause[start:j], notes) + clause[j:j + 1]
            start = j + 1
    return out


def _leading_purpose(clause: list[str]) -> int:
    """How many words open the clause as a purpose said first: "for" and words of
    ``PURPOSE_WORDS`` (after a possessive or none), the whole clause or up to a verb of the
    lexicon; 0 where it opens otherwise."""
    if len(clause) < 2 or clause[0] != "for":
        return 0
    j = 2 if clause[1] in BENEFICIARY_DETERMINERS else 1
    while j < len(clause) and clause[j] in PURPOSE_WORDS:
        j += 1
    if j == 1 or clause[j - 1] not in PURPOSE_WORDS:
        return 0
    if j == len(clause) or str(PHRASES.get((clause[j],), ("",))[0]).startswith("V_"):
        return j
    return 0


def _without_purpose(clause: list[str], notes: list[str]) -> list[str]:
    """A clause without its closing purpose ("... for airing", "... for later": lexicon
    ``PURPOSES``, words of ``PURPOSE_WORDS`` after a possessive or none ("for tea tonight", "for
    the little one"), "for" + an -ing word that is no verb of the lexicon, or "to" + a verb of
    ``PURPOSE_INFINITIVES``: "to dry"): what for, not what the
    home should end like. "for washing" (a verb the home can do) is kept, and refused: it may ask
    for the washing too."""
    lead = _leading_purpose(clause)
    if lead:   # "For dinner, cut the tomatoes", "for the kids heat the pasties": what for, said first
        notes.append(f"'{' '.join(clause[:lead])}' says what for, not what the home should end like")
        return _without_purpose(clause[lead:], notes) if lead < len(clause) else []
    tag = next((len(t) for t in CLOSING_TAGS if tuple(clause[-len(t):]) == t and len(clause) > len(t) + 2), 0)
    if tag:   # "heat the pasty for my lunch would you": the purpose before a closing tag
        return _without_purpose(clause[:-tag], notes) + clause[-tag:]
    if len(clause) > 3 and clause[-2] == "to" and clause[-1] in PURPOSE_INFINITIVES:
        notes.append(f"'to {clause[-1]}' says what for, not what the home should end like")
        return clause[:-2]
    for n in (1, 2, 3, 4):
        if len(clause) > n + 1 and clause[-n - 1] == "for":
            tail = tuple(clause[-n:])
            whom = tail[1:] if tail[0] in BENEFICIARY_DETERMINERS else tail
            if tail in PURPOSES or (whom and all(w in PURPOSE_WORDS for w in whom)) or \
                    (n == 1 and tail[0].endswith("ing") and len(tail[0]) > 5 and not any(tail[0] in key for key in PHRASES)):
                notes.append(f"'for {' '.join(tail)}' says what for, not what the home should end like")
                return clause[:-n - 1]
    return clause


#: determiners of a measure of a thing said before ("that bottle of pop", "me bag of crisps"): the thing
_MEASURED_BEFORE = frozenset({"the", "that", "this", "those", "these", "my", "me", "her", "his", "our", "your",
                              "their"})


def measures(words: list[str], index: dict, notes: list[str]) -> list[str]:
    """ "a bowl of cherries" as "some cherries" (lexicon ``MEASURES``), "that bottle of pop" as
    "that pop" (the thing in it, which the home model names), unless the home has a thing named by
    the container word (then it stays, and is refused: the bowl may be meant too)."""
    out: list[str] = []
    k = 0
    while k < len(words):
        w = words[k]
        measured = k + 3 < len(words) and words[k + 2] == "of" and \
            (words[k + 1] in MEASURES or words[k + 1] + "s" in MEASURES or words[k + 1].rstrip("s") in MEASURES) \
            and (words[k + 1],) not in index and words[k + 3] not in PUNCT
        if measured and w in ("a", "an", "one"):
            notes.append(f"'{w} {words[k + 1]} of' read as 'some' (an amount of what follows, not a thing of the home)")
            out.append("some")
            k += 3
            continue
        # "the box of the pizza" (the pizza box, where the home names one): a thing of its own
        inverted = measured and ((words[k + 3], words[k + 1]) in index or words[k + 3] in _MEASURED_BEFORE)
        if measured and w in _MEASURED_BEFORE and not inverted:
            notes.append(f"'{w} {words[k + 1]} of' read as '{w}' (the thing in it, not a thing of the home)")
            out.append(w)
            k += 3
            continue
        out.append(w)
        k += 1
    return out


#: words that put what follows them in their sentence under a negation ("nobody is using X or Y")
_NEGATORS = {"nobody", "noone", "not", "never", "none"}


def or_under_negation(words: list[str], notes: list[str]) -> list[str]:
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


#: "leave them both out", "put them all away": a pronoun with a quantifier after it, as the
#: quantifier before it ("both of them", "all of them")
_FLOATED = {("them", "both"): ["both", "of", "them"], ("them", "all"): ["all", "of", "them"],
            ("it", "all"): ["all", "of", "it"]}
#: particles of completion after warming ("warm the pie through"): how, not what
_THROUGH_AFTER = {"warm", "warming", "heat", "heating", "warmed", "heated", "cook", "cooking", "cooked", "reheat",
                  "reheating", "defrost", "thaw"}
#: "so bertie can get the plate out": "so" + one word + these opens a clause of what is done
_ENABLING = {"can", "could", "will", "may"}


#: "get the avocado sliced", "have the pans washed": a thing and what should be done to it, said
#: with "get" / "have" (participle -> the verb of the lexicon that does it)
CAUSED = {"sliced": "slice", "chopped": "chop", "diced": "dice", "washed": "wash", "cleaned": "clean",
          "scrubbed": "scrub", "rinsed": "rinse", "heated": "heat", "warmed": "warm", "cooked": "cook",
          "toasted": "toast", "put": "put"}
#: what may end the clause of such a participle (what follows it is read as ever: "get the
#: leftovers heated up for him", "get the garden truck put away before it wilts")
_CLAUSE_ENDS = set(PUNCT) | {"and", "then", "please", "for", "before", "so"}
#: particles a participle may have after it ("heated up", "put away", "washed out")
_CAUSED_PARTICLES = {"up", "out", "away", "through", "down"}


def caused(words: list[str], notes: list[str]) -> list[str]:
    """ "get the avocado sliced" as "slice the avocado", "get them leftovers heated up" as "heat
    them leftovers up" (:data:`CAUSED`): "get" or "have", then at most five words of no clause
    mark, then the participle (with a particle, :data:`_CAUSED_PARTICLES`) closing the clause;
    "put" only as "put away". A participle inside the phrase ("get the sliced bread") is no such
    thing."""
    out = list(words)
    for i, w in enumerate(words):
        if w not in ("get", "have") or (i and words[i - 1] not in _CLAUSE_ENDS | {"you", "u", "someone", "to"}):
            continue
        for j in range(i + 2, min(i + 7, len(words))):
            if words[j] in PUNCT:
                break
            end = j + 1 + (j + 1 < len(words) and words[j + 1] in _CAUSED_PARTICLES)
            if words[j] in CAUSED and (end == len(words) or words[end] in _CLAUSE_ENDS) \
                    and (words[j] != "put" or words[j + 1:end] == ["away"]):
                verb, thing = CAUSED[words[j]], words[i + 1:j] + words[j + 1:end]
                notes.append(f"'{w} {' '.join(words[i + 1:end])}' read as '{verb} {' '.join(thing)}'")
                return out[:i] + [verb] + out[i + 1:j] + out[j + 1:end] + caused(out[end:], notes)
    return out


#: what a thing is given ("give the pan a wash"): the verb that does it
GIVEN = {"wash": "wash", "clean": "wash", "scrub": "wash", "rinse": "wash", "wipe": "wash", "warm": "warm",
         "heat": "heat", "chop": "slice", "slice": "slice"}
#: how much of it, said between "a" and the noun ("a proper wash", "a good scrub")
_HOW_MUCH = {"good", "proper", "quick", "thorough", "decent", "little", "bit", "of", "a", "nice", "real"}


def given(words: list[str], notes: list[str]) -> list[str]:
    """ "give the sippy cup a proper wash" as "wash the sippy cup" (:data:`GIVEN`): "give", at most
    five words of no clause mark, then "a", words of :data:`_HOW_MUCH`, and the noun closing the
    clause."""
    for i, w in enumerate(words):
        if w != "give":
            continue
        for j in range(i + 2, min(i + 8, len(words))):
            if words[j] in PUNCT:
                break
            if words[j] != "a":
                continue
            k = j + 1
            while k < len(words) and words[k] in _HOW_MUCH:
                k += 1
            if k < len(words) and words[k] in GIVEN and (k + 1 == len(words) or words[k + 1] in _CLAUSE_ENDS):
                notes.append(f"'{' '.join(words[i:k + 1])}' read as '{GIVEN[words[k]]} {' '.join(words[i + 1:j])}'")
                return words[:i] + [GIVEN[words[k]]] + words[i + 1:j] + given(words[k + 1:], notes)
    return list(words)


#: what a thing is put in a heater for, said as a purpose ("pop it in the microwave to warm through",
#: "in the oven to cook")
_HEAT_PURPOSES = {"warm", "heat", "cook", "bake", "fry", "toast"}


def heat_purpose(words: list[str], notes: list[str]) -> list[str]:
    """ "pop the loaf in the oven to warm (up / through)" as "... and warm it (through)": the
    purpose is the heating asked for (the thing ends hot), closing a clause that puts it somewhere
    (or before what it is for: "in the oven to cook for supper")."""
    out: list[str] = []
    k = 0
    while k < len(words):
        w = words[k]
        nxt = words[k + 1] if k + 1 < len(words) else None
        after = k + 2 + (k + 2 < len(words) and words[k + 2] in ("up", "through"))
        if w == "to" and nxt in _HEAT_PURPOSES and out and out[-1] not in _CLAUSE_ENDS \
                and (after >= len(words) or words[after] in _CLAUSE_ENDS or words[after] == "for"):
            notes.append(f"'to {' '.join(words[k + 1:after])}' read as 'and {nxt} it'")
            out += ["and", nxt, "it"] + (["through"] if after > k + 2 else [])
            k = after
            continue
        out.append(w)
        k += 1
    return out


#: particles that close a clause and say nothing of the order: Singapore English "ah", Vietnamese
#: "a" (politeness), Japanese "ne", "yo" ("nha", "nhe" are fillers anywhere: lexicon ``FILLER``)
_CLOSING_PARTICLES = {"ah", "a", "ne", "yo"}


def particles(words: list[str], names_nothing, notes: list[str], doers: frozenset[str] = frozenset()) -> list[str]:
    """Particles and small constructions read as the grammar's words (docs/household.md):
    "them both" / "them all" as "both of them" / "all of them"; "ah" closing a clause left out (a
    particle, as "lah"); "through to P" as "to P" and
    "through from P" as "from P" (to or from another room: the home model has none); "warm X
    through" without "through" (heated all the way: hot); "put X inside" (or "in") ending its
    clause as "put X in it"; "so W can ..." as "and ..." when W is a robot or team of the home
    (``doers``: who does a step is the plan's choice; a person's "so Virgil can ..." is their
    doing, set aside: :func:`pipflow.household.language.setaside.speaker_doing`).
    ``names_nothing(word)``: the word is no name of the world."""
    out: list[str] = []
    k = 0
    while k < len(words):
        w = words[k]
        pair = tuple(words[k:k + 2])
        if pair in _FLOATED:
            out += _FLOATED[pair]
            notes.append(f"'{' '.join(pair)}' read as '{' '.join(_FLOATED[pair])}'")
            k += 2
            continue
        if w in _CLOSING_PARTICLES and out and out[-1] not in PUNCT and (k + 1 == len(words) or words[k + 1] in PUNCT):
            # Singapore and Malaysian English "ah" closing a clause ("don't touch ah"), a particle as
            # "lah" is; "ah ma" (a person) goes on, and is left alone. Vietnamese "a" (politeness:
            # "... in the cupboard a"): an article never closes a clause
            k += 1
            continue
        if w == "through" and k + 1 < len(words) and words[k + 1] in ("to", "into", "onto", "in", "on", "from") and out \
                and out[-1] not in PUNCT:
            notes.append(f"'through {words[k + 1]}' read as '{words[k + 1]}' (the home model has no rooms to go through)")
            k += 1
            continue
        if w == "through" and any(x in _THROUGH_AFTER for x in clause_before(out)):
            notes.append("'through' after warming: heated through, read as hot")
            k += 1
            continue
        if w == "so" and out and out[-1] == "," and k + 1 < len(words) and words[k + 1] not in ("that", "much", "many") \
                and PHRASES.get((words[k + 1],), ("",))[0] not in GRADED:
            # "the melon is too heavy for one of you, so carry it ...": a consequence, a clause of its own
            notes.append("', so' opens a clause of what is done: read as ','")
            k += 1
            continue
        n = _purpose(words, k, names_nothing) if w == "for" and out and out[-1] not in PUNCT \
            and not _wish_before(out) else 0
        if n:
            # "slice the ham for sandwiches", "warm the milk for my cocoa": what for, when the words
            # name nothing of the home (or a drink or a meal, which no home model holds)
            notes.append(f"'{' '.join(words[k:k + n])}' says what for, not what the home should end like")
            k += n
            continue
        if w in ("inside", "in") and (k + 1 >= len(words) or words[k + 1] in _AFTER_A_PARTICLE) \
                and any(x in PLACING for x in clause_before(out)) and out[-1] not in PLACING:
            # "open the trunk, put the doll inside and close it": in the thing just named or opened
            notes.append(f"'put ... {w}' read as 'put ... in it'")
            out += ["in", "it"]
            k += 1
            continue
        if w == "so" and k + 2 < len(words) and words[k + 2] in _ENABLING and words[k + 1] in doers \
                and out and out[-1] not in PUNCT:
            notes.append(f"'so {words[k + 1]} {words[k + 2]}': who does a step is the plan's choice; read as 'and'")
            out.append("and")
            k += 3
            continue
        out.append(w)
        k += 1
    return out


#: verbs that place a thing ("put the doll inside")
PLACING = {"put", "pop", "stick", "place", "throw", "chuck", "toss", "drop", "pack", "tuck", "shove", "lay"}
#: what may follow a particle said without its place: its clause ends there
_AFTER_A_PARTICLE = set(PUNCT) | {"and", "then", "too", "please", "now", "for", "again"}
#: possessives and determiners a purpose may open with ("for my cocoa", "for our supper")
_PURPOSE_DETERMINERS = {"the", "my", "our", "your", "his", "her", "their", "a", "some"}
#: what a purpose may name though the lexicon knows it: a hot drink or a meal, in the singular
#: or the plural ("for hot chocolates"), which no home model holds as a thing
CONSUMED = {tuple(p.split()) for p in HOT_DRINKS + tuple(MEALS)} | {
    tuple(p.split()[:-1] + [p.split()[-1] + "s"]) for p in HOT_DRINKS + tuple(MEALS)}


def _wish_before(out: list[str]) -> bool:
    """Whether the words before a "for" end a wish that takes it ("I'm dying for", "could kill
    for", "gasping for": lexicon ``WANT``): what follows is what is wished for, no purpose."""
    return any(PHRASES.get(tuple(out[-n:]) + ("for",), ("",))[0] == "WANT" for n in range(1, min(4, len(out)) + 1))


def _purpose(words: list[str], k: int, names_nothing) -> int:
    """How many words at ``k`` ("for") close the clause as a purpose: "for" + a possessive or
    determiner (optional) + one word that names nothing of the home, or a hot drink or a meal
    (:data:`CONSUMED`); 0 when they do not (a name of the home after "for" may be meant)."""
    j = k + 1
    if j < len(words) and words[j] in _PURPOSE_DETERMINERS:
        j += 1
    for end in range(j + 1, min(j + 4, len(words) + 1)):
        if end < len(words) and words[end] not in PUNCT:
            continue
        said = tuple(words[j:end])
        if said in CONSUMED or (len(said) == 1 and names_nothing(said[0])):
            return end - k
        break
    return 0


def clause_before(out: list[str]) -> list[str]:
    """The words of the clause being read (since the last mark)."""
    k = len(out)
    while k and out[k - 1] not in PUNCT:
        k -= 1
    return out[k:]


def _said_as(words: list[str], k: int, shape: tuple[set[str] | tuple[str, ...], ...]) -> bool:
    """Whether the words from ``k`` on are one of each of ``shape``'s word sets, in order."""
    return all(k + j < len(words) and words[k + j] in s for j, s in enumerate(shape))


#: "wherever they live / belong / go": a thing's home, as "where they belong" says
_WHEREVER = ({"wherever"}, {"they", "it"}, {"live", "lives", "belong", "belongs", "go", "goes"})
#: verbs that already say where a clause's things go
_PUTTING = {"put", "move", "take", "bring", "get", "stick", "pop", "return", "carry", "place", "stash"}


def wherever_they_belong(words: list[str], notes: list[str]) -> list[str]:
    """ "shoes to wherever they live" (an arrow, or a clause with no verb) and "put the clothes
    wherever they belong" are "put them where they belong": the things' home. A note says so."""
    out: list[str] = []
    start = 0
    k = 0
    while k < len(words):
        w = words[k]
        if w in PUNCT:
            out.append(w)
            start = len(out)
            k += 1
            continue
        at = k + (words[k] == "to")
        if _said_as(words, at, _WHEREVER):
            clause = out[start:]
            if clause and clause[0] not in _PUTTING:
                out[start:start] = ["put"]
            out += ["where", "they", "belong"]
            notes.append(f"'{' '.join(words[k:at + 3])}': where they belong (their home)")
            k = at + 3
            continue
        out.append(w)
        k += 1
    return out


#: "close whatever you opened (after)": what is done anyway
_OPENED = (("close", "shut"), ("whatever", "everything", "anything", "what"), ("you",), ("opened", "open"))


def closed_again(words: list[str], notes: list[str]) -> list[str]:
    """The words without "close / shut whatever you opened (after, afterwards)": a container a plan
    opens is closed again anyway (benchmarks/README.md), so the clause asks for nothing more. A
    note says so. Anything else said in it keeps the clause read."""
    for k in range(len(words)):
        if _said_as(words, k, _OPENED):
            end = k + len(_OPENED)
            end += words[end:end + 1] in (["up"],)
            end += words[end:end + 1] in (["after"], ["afterwards"])
            if (k == 0 or words[k - 1] in PUNCT or words[k - 1] in ("and", "then")) and (end == len(words) or words[end] in PUNCT):
                notes.append(f"'{' '.join(words[k:end])}': a container a plan opens is closed again anyway")
                start = k - 1 if k and words[k - 1] in ("and", "then") else k
                return closed_again(words[:start] + words[end:], notes)
    return words


#: verbs of closing that "back" may follow as "again" ("close it back": Nigerian, Indian and
#: Ethiopian English)
_CLOSING = frozenset({"close", "shut", "lock", "cover"})


def closed_back(words: list[str], notes: list[str]) -> list[str]:
    """The words with "back" after "close / shut / lock / cover it (them)" left out: "close it back"
    is closing it again, which closing it is; "put it back" and "bring them back" keep theirs."""
    out: list[str] = []
    for k, w in enumerate(words):
        if w == "back" and k >= 2 and words[k - 1] in ("it", "them") and words[k - 2] in _CLOSING:
            notes.append(f"'{' '.join(words[k - 2:k + 1])}': closing it again, read as closing it")
            continue
        out.append(w)
    return out


#: what says "that again, for another thing" ("same for the saucepan", "do the same with the bowl"),
#: longest first
_SAME = sorted((("same",), ("the", "same"), ("do", "the", "same"), ("same", "again"), ("same", "goes"),
                ("the", "same", "goes"), ("ditto",)), key=len, reverse=True)
#: the marks a clause of its own may open after
_SAME_AFTER = {".", ",", ";", "!", "?"}


def same_for(words: list[str], notes: list[str]) -> list[str]:
    """ "give the pan a scrub. same for the saucepan": the clause before, again, for the thing
    named, as "..., and the saucepan too" says it. Only a clause of its own (after a mark, "and" or
    "then" allowed before it) that is nothing but the "same" words, "for" / "with" and the thing, up
    to the sentence's end or a "then" that opens the next order, after a clause: "the same for the
    plates, only into the press" says more, and stays unread."""
    out: list[str] = []
    k = 0
    while k < len(words):
        after_a_clause = k > 0 and words[k - 1] in _SAME_AFTER and any(w not in PUNCT for w in out)
        end = (_same_for_at(words, k) or _same_after(words, k)) if after_a_clause else None
        if end is not None:
            thing = words[end[0]:end[1]]
            notes.append(f"'{' '.join(words[k:end[2]])}': the clause before, again, for {' '.join(thing)}")
            out = out[:-1] + [",", "and", *thing, "too"]
            k = end[2]
            continue
        out.append(words[k])
        k += 1
    return out


def _same_after(words: list[str], k: int) -> tuple[int, int, int] | None:
    """ "the tau kwa also same", "the saucepan the same (lah)": the thing first, then "(also /
    too) (the) same" closing its sentence; where the thing's words start and end and where the
    clause ends, or None."""
    start = k + (1 if words[k] in ("and", "then") else 0)
    end = next((j for j in range(start, len(words)) if words[j] in PUNCT), len(words))
    said = end
    while said > start and words[said - 1] in CLOSING_PARTICLES:
        said -= 1
    comma = 0
    if said == end and end + 2 < len(words) and words[end] == "," and tuple(words[end + 1:end + 3]) in _SAME_AFTER_THING:
        # "jaden bag on the settee, same thing": the "same" set off by a comma
        comma = 1
        words = words[:end] + words[end + 1:]
        said = end = next((j for j in range(end, len(words)) if words[j] in PUNCT), len(words))
    tail = next((n for n in (3, 2, 1) if said - n > start and tuple(words[said - n:said]) in _SAME_AFTER_THING), 0)
    if not tail or (end < len(words) and words[end] not in (".", "!", ";")) or said - tail - start > 5:
        return None
    return start, said - tail, end + comma


#: particles and thanks that may close such a clause ("the tau kwa also same lor")
CLOSING_PARTICLES = {"lah", "leh", "lor", "ah", "hor", "meh", "pls", "please", "ok", "okay", "thanks"}


#: what says "that again" after the thing ("the tau kwa also same", "the pan the same")
_SAME_AFTER_THING = {("same",), ("the", "same"), ("also", "same"), ("too", "same"), ("also", "the", "same"),
                     ("same", "too"), ("same", "also"), ("as", "well"), ("same", "thing"), ("the", "same", "thing"),
                     ("same", "same"), ("same", "way"), ("the", "same", "way")}


def _same_for_at(words: list[str], k: int) -> tuple[int, int, int] | None:
    """Where the thing of a "same for X" clause opening at ``k`` starts and ends (the end of its
    sentence, twice: the clause ends there too), or None when no such clause opens there."""
    start = k + (1 if words[k] in ("and", "then") else 0)
    same = next((s for s in _SAME if tuple(words[start:start + len(s)]) == s), None)
    if same is None or start + len(same) >= len(words) or words[start + len(same)] not in ("for", "with"):
        return None
    thing = start + len(same) + 1
    # its sentence ends it, or "then" opening the next order ("... same with the knife and then
    # put it away")
    end = next((j for j in range(thing, len(words)) if words[j] in PUNCT or words[j] == "then"
                or words[j:j + 2] == ["and", "then"]), len(words))
    if end == thing or (end < len(words) and words[end] not in (".", "!", ";", "then", "and")):
        return None
    return thing, end, end


#: words an order's object opens with: "so" before a verb and one of these is an order ("so wash
#: it", "so close the door"); "ever so close in here" is a degree
_OBJECT_OPENERS = {"the", "it", "them", "my", "your", "his", "her", "our", "their", "that", "this", "those", "these",
                   "a", "an", "some", "all", "both", "everything", "up", "down", "off", "on", "out", "away"}
#: the pronouns and verbs of being of a result said after "so" ("so they are cold")
_RESULT_SUBJECTS = {"it", "they", "its", "theyre", "that"}
_RESULT_BE = {"is", "are", "s", "stays", "stay", "keeps", "keep", "will", "gets", "get"}


def so_before_an_order(words: list[str], notes: list[str]) -> list[str]:
    """ "so" as speech joins clauses: opening a sentence it says nothing ("so grab my hoodie ...");
    before a verb of the lexicon and its object it joins a reason to the order it leads to, read as
    a clause mark ("the pan is still dirty so wash it": the reason is then the order's topic or
    cue, as "the pan is dirty, wash it" is; "ever so close in here" is a degree); "so (that) it is
    / they are ..." closing a clause after an order is what the order is for ("put the wine in the
    fridge so they are cold"), set aside."""
    out: list[str] = []
    k = 0
    while k < len(words):
        w, nxt = words[k], words[k + 1] if k + 1 < len(words) else ""
        if w != "so" or out[-1:] in (["and"], ["but"], ["or"]):
            out.append(w)
            k += 1
            continue
        result = k + 1 + (nxt == "that")
        end = next((j for j in range(k + 1, len(words)) if words[j] in PUNCT), len(words))
        if not out or out[-1] in (".", "!", "?", ";"):
            notes.append("'so' opening a sentence says nothing of the order")
        elif str(PHRASES.get((nxt,), ("",))[0]).startswith("V") and words[k + 2:k + 3] and \
                words[k + 2] in _OBJECT_OPENERS:
            out += [] if out[-1] in PUNCT else [","]
            notes.append(f"'so {nxt}': the order the words before it lead to")
        elif out[-1] not in PUNCT and result + 1 < end and words[result] in _RESULT_SUBJECTS \
                and words[result + 1] in _RESULT_BE and not any(near_operative(x) for x in words[k + 1:end]):
            notes.append(f"'{' '.join(words[k:end])}' says what for, not what the home should end like")
            k = end
            continue
        else:
            out.append(w)
        k += 1
    return out


#: particles said after "back" before where a thing goes ("put the jam back down in the cellar")
_BACK_PARTICLES = {"down", "up", "over", "out", "round", "around"}
#: prepositions of where a thing goes
_DESTINATIONS = {"to", "into", "onto", "in", "on"}


def back_before_a_destination(words: list[str], notes: list[str]) -> list[str]:
    """ "put the jam back down in the cellar house" as "put the jam back in the cellar house", and
    "bring me back a jar of apple butter to the table" as "bring me a jar of apple butter to the
    table": "back" (and a particle after it) right after a verb of the lexicon, where the clause
    then says where the thing goes, says it is returned there, which the place says; where no
    place follows, "back" is where it belongs, and is left as said."""
    out = list(words)
    for k, w in enumerate(words):
        if w != "back" or not k:
            continue
        verb = words[k - 1] in ORDER_VERB_WORDS or (words[k - 1] == "me" and k > 1 and words[k - 2] in ORDER_VERB_WORDS)
        end = next((j for j in range(k + 1, len(words)) if words[j] in PUNCT or words[j] in ("and", "then")), len(words))
        if words[k + 1:k + 2] and words[k + 1] in _BACK_PARTICLES and words[k + 2:k + 3] and words[k + 2] in _DESTINATIONS:
            notes.append(f"'back {words[k + 1]}' read as 'back'")
            return out[:k + 1] + back_before_a_destination(out[k + 2:], notes)
        if verb and words[k - 1] != "put" and k + 1 < end and words[k + 1] not in _DESTINATIONS \
                and any(x in _DESTINATIONS for x in words[k + 2:end]):
            notes.append("'back' before what is brought and where it goes: where it goes says it")
            return out[:k] + back_before_a_destination(out[k + 1:], notes)
    return out


#: who an order may be said to before its verb ("you all slice up the cornbread", "you two
#: carry the table"): the robots asked, no part of what they are asked
_YOU_ALL = {"all", "two", "both", "guys", "lot", "lads", "folks", "robots"}
#: what an order said to someone may open after: the start, a clause mark, a joiner
_ORDER_OPENS = set(PUNCT) | {"and", "then", "now"}


def you_before_an_order(words: list[str], notes: list[str], index: dict) -> list[str]:
    """ "Y'all slice up that cornbread", "you tote it to the feed bin" (Southern US and
    Appalachian English, and anyone giving an order to a group): "you" (with "all", "two", ...)
    opening a clause before a verb of the lexicon says who is asked, and is left out, as an
    order to the robots is read anyway. So is a word said to the one asked ("bab put the kettle
    on", "love, fetch the post": :data:`~pipflow.language.asides.VOCATIVES`), with its comma, or
    before "and" / "then" that join the next order ("warm it up bab and bring it through"), where
    the home names nothing by it (``index``: "duck, put it in the fridge" may be the roast)."""
    out: list[str] = []
    k = 0
    while k < len(words):
        n = 2 if words[k:k + 1] == ["you"] and k + 1 < len(words) and words[k + 1] in _YOU_ALL else 1
        vocative = words[k] in VOCATIVES and (words[k],) not in index
        joined = words[k + 1:k + 2] in (["and"], ["then"])
        if vocative and joined and out and out[-1] not in PUNCT and out[-1] not in DETERMINERS:
            notes.append(f"'{words[k]}' before '{words[k + 1]}' says who is asked")
            k += 1
            continue
        n += vocative and words[k + 1:k + 2] == [","]
        if (words[k] == "you" or vocative) and (not out or out[-1] in _ORDER_OPENS) and k + n < len(words) \
                and words[k + n] in ORDER_VERB_WORDS:
            notes.append(f"'{' '.join(words[k:k + n])}' before an order says who is asked")
            k += n
            continue
        out.append(words[k])
        k += 1
    return out


#: what may follow "instead" closing a clause ("put the standard lamp on instead, ...", "... instead
#: and ...")
_AFTER_INSTEAD = frozenset(PUNCT) | {"and", "then", "please", "now"}


def instead_closing(words: list[str], notes: list[str]) -> list[str]:
    """ "switch the big light off and put the standard lamp on instead": the order replaces one
    the speaker had in mind; "instead" closing a clause adds nothing to it ("instead of the desk"
    names what is replaced and is left as said)."""
    out: list[str] = []
    for k, w in enumerate(words):
        nxt = words[k + 1] if k + 1 < len(words) else "."
        if w == "instead" and k > 0 and (nxt in _AFTER_INSTEAD or (nxt,) in FILLER):   # "... instead hinny,"
            notes.append("'instead' closing the clause adds nothing to what it asks")
            continue
        out.append(w)
    return out


#: the whole home or the room the speaker is in, said as what to warm ("warm the place up")
_THE_HOME = {("the", "place"), ("the", "house"), ("the", "room"), ("the", "flat"), ("in", "here")}
#: the verbs that warm it
_WARMING = {"warm", "heat"}


def warm_the_place(words: list[str], notes: list[str]) -> list[str]:
    """ "warm the place up (a bit)", "heat up the house": the cue that it is cold here, which the
    reader reads as the heaters of the room on ("it's freezing in here"); only where what is
    warmed is the home or the room itself, never a thing of it ("warm the soup up")."""
    out: list[str] = []
    k = 0
    while k < len(words):
        m = k + 1 if words[k] in _WARMING else None
        if m is not None and m < len(words) and words[m] == "up":
            m += 1
        if m is not None and tuple(words[m:m + 2]) in _THE_HOME:
            end = m + 2
            end += words[end:end + 1] == ["up"]
            end += 2 * (words[end:end + 2] == ["a", "bit"])
            notes.append(f"'{' '.join(words[k:end])}' read as the cue 'it is cold in here'")
            out += ["it", "is", "cold", "in", "here"]
            k = end
            continue
        out.append(words[k])
        k += 1
    return out


#: what a thing does if left ("... before it goes off", "so they don't go stale", "before it goes like
#: soup"): said as the reason for the order, never a state asked for
_SPOILING = ("off", "stale", "bad", "cold", "soggy", "mouldy", "moldy", "rotten", "hard", "warm", "flat", "manky",
             "brown", "dry", "limp")
_SPOILS = re.compile(r"\b(?:before|so|or\s+else|or)\s+(?:it|they|that|them)\s+(?:(?:does|do|will|would)\s+not\s+|"
                     r"(?:will|ll|would)\s+)?(?:go|goes|get|gets|turn|turns|be)\s+(?:all\s+)?(?:(?:"
                     + "|".join(_SPOILING) + r")\b|like\s+[a-z]+\b(?!\s+(?:of|in|on|at)\b))"
                     r"|\bbefore\s+(?:it|they)\s+(?:spoils?|melts?|rots?|dries\s+out|dry\s+out)\b")


#: words that say where a thing lies, after "still" ("the clothes still on the line")
_STILL_WHERE = {"on", "in", "at", "inside", "under", "by", "sat", "sitting", "lying", "stood", "standing", "left"}
#: verbs that keep a thing where it is, or say it is there: "keep them still in the fridge"
_KEEPING_OR_BEING = {"keep", "leave", "is", "are", "was", "were", "be", "been", "s", "re"}


def still_as_a_report(words: list[str], notes: list[str]) -> list[str]:
    """ "the clothes still on the line", "di clothes dem still pon di line": a clause with no verb
    that says a thing is still where it lies reports how things are (read as "are still", which
    the reader never takes for an order, and may set aside where the world agrees); without it
    the verbless clause read as "put the clothes on the line", a goal already met, in place of the
    cue that was meant."""
    out: list[str] = []
    for k, w in enumerate(words):
        if w == "still" and k + 1 < len(words) and words[k + 1] in _STILL_WHERE:
            start = max((j + 1 for j, x in enumerate(out) if x in PUNCT or x in ("and", "but", "so")), default=0)
            clause = out[start:]
            if clause and not any(x in ORDER_VERB_WORDS or x in _KEEPING_OR_BEING for x in clause):
                notes.append(f"'{' '.join(clause)} still ...' read as '... are still ...' (how things are)")
                out.append("are")
        out.append(w)
    return out


def spoiling_as_reason(words: list[str], notes: list[str]) -> list[str]:
    """ "put the bread back in the bread bin before it goes stale", "... so it doesn't go off": what
    the thing will do if left is why the order is given; the words are left out (a note says so),
    and what the order asks is read as said."""
    said = " ".join(words)
    if not _SPOILS.search(said):
        return words
    notes.append("; ".join(f"'{m.group(0)}' is why, not what is asked" for m in _SPOILS.finditer(said)))
    return _SPOILS.sub(" ", said).split()


#: the copulas after which "covered in ..." says what a thing is like ("the knife is covered in jam")
_BE = frozenset({"is", "are", "s", "was", "were", "been", "got", "gets", "get"})


def covered_in(words: list[str], index: dict, notes: list[str]) -> list[str]:
    """ "the knife is covered in marge", "left on the side all covered in jam": a thing covered in
    what names nothing of the home, or an object of the home covered in anything, is dirty: after
    a copula the words read as "dirty" (a state a later clause may answer, or the cue to wash it);
    after anything else ("left on the side all covered in jam") they say how it was left, and are
    left out (a note says so). A place covered in things of the home ("the table is covered in
    books") stays as said."""
    out: list[str] = []
    k = 0
    while k < len(words):
        j = k + (words[k] == "all")
        if words[j:j + 1] == ["covered"] and j + 1 < len(words) and words[j + 1] in ("in", "with"):
            end = next((e for e in range(j + 2, len(words)) if words[e] in PUNCT or words[e] in ("and", "so", "but")),
                       len(words))
            what = [w for w in words[j + 2:end] if w not in ("the", "a", "some", "all", "that", "this")]
            if 0 < len(what) <= 3 and (not any((w,) in index for w in what) or _object_covered(out, index)):
                notes.append(f"'{' '.join(words[k:end])}': dirty")
                if out and out[-1] in _BE:
                    out.append("dirty")
                k = end
                continue
        out.append(words[k])
        k += 1
    return out


def _object_covered(before: list[str], index: dict) -> bool:
    """Whether the first thing the clause before "covered" names is an object of the home alone
    (a place covered in things is cluttered: "the table is covered in books")."""
    start = max((i for i, w in enumerate(before) if w in PUNCT), default=-1) + 1
    for a in range(start, len(before)):
        b = name_end(before, a, index)
        if b:
            return all(ref["kind"] == "object" for ref in index[tuple(before[a:b])])
    return False

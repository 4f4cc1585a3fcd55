"""Talk set aside: the clauses of a command that name nothing of the world, have no number and no
operative word (greetings, thanks, asides: :mod:`pipflow.language.asides`), and the clauses that
say what the speaker will do ("I'll grab the milk myself"). The parser reads a command again
without them when it does not read as said."""
from __future__ import annotations

import re
from typing import Callable, NamedTuple

from pipflow.household.language.lexicon import (DURATION_UNITS, FILLER, FILLER_TYPO_TARGETS, PHRASES, PURPOSE_WORDS,
                                                words_of)
from pipflow.household.language.names import doers, home_words, per_index, world_phrases
from pipflow.household.language.people import KIN
from pipflow.household.language.restated import leading_subject, restates_location
from pipflow.household.language.typos import typo_of, vocabulary
from pipflow.household.language.unseen import unseen
from pipflow.language.asides import (BOUNDS, EXCLUSIVITY, FUNCTION_WORDS, NEGATION, OPERATIVE, QUANTITIES, SELECTION, TEMPORAL,
                                     PLEASANTRIES, THANKS, Clause, clauses, content_free, is_opener, near_operative,
                                     opens_changed_plan,
                                     signature, trailing_adjunct, trailing_thanks, trailing_vocatives,
                                     unmarked_statement)
from pipflow.language.english import common_word
from pipflow.language.numbers import read_number, reads_as_count


#: lexicon classes of function words: alone in a clause they carry nothing an order needs
#: (and words that only colour a cue or a time: "for the night", "in here", "late", "really")
GLUE_CLASSES = {"THE", "THAT", "IT", "IS", "SUBJ", "BE", "HAVE", "SHOULD", "INTENS", "OF", "AT", "IN", "ON", "OFF",
                "ANYMORE", "REASON", "HERE", "HEDGE", "EXCL",
                "OUT", "UP", "TO", "FROM", "WITH", "AND", "SEE", "SURE"}
#: marks that end a clause, for setting content-free clauses aside
CLAUSE_MARKS = {",", ".", ";", "!", "?", ":"}


#: the lexicon's words that are no glue and no function word: content wherever they are said
_LEXICON_CONTENT = frozenset(w for k, (cls, _) in PHRASES.items() if cls not in GLUE_CLASSES for w in k) - FUNCTION_WORDS


@per_index
def _naming_words(index: dict) -> tuple[frozenset[str], frozenset[str]]:
    """The words that name something of the home alone, and the words a misspelt content word may
    be read as (:func:`_content`). A one-word name and the head (last word) of a longer one name
    alone; a modifier alone names nothing ("mooring" of mooring_line in "we're mooring up"), and
    "of" of "bottle of water" is no name."""
    heads = {k[-1] for k in index if "of" not in k} | {k[0] for k in index if "of" in k}
    world_words = frozenset(w for w in heads if (w,) in index) - FUNCTION_WORDS
    vocab = frozenset(w for w in vocabulary(index)
                      if w in world_words or w in _LEXICON_CONTENT or w in FILLER_TYPO_TARGETS)
    return world_words, vocab


def _misspelt(w: str, vocab: frozenset[str], home: frozenset[str]) -> bool:
    """Whether ``w`` is read as a slip of a word of ``vocab``: a common English word as written is
    not, unless it is a word of the home's names ("sore" is no "store", "party" no "pantry":
    :func:`pipflow.language.english.common_word`), so a remark made of everyday words may be set
    aside, as in the warehouse; "rack" of the shoe rack is judged as before."""
    return len(w) >= 4 and (w in home or not common_word(w)) and bool(typo_of(w, vocab))


def _content(world: dict) -> Callable[[str], bool]:
    """The test :func:`pipflow.language.asides.content_free` asks of each word: a word of a
    world name (or a misspelling of one, or of a content word of the lexicon), a number, or a
    lexicon word that is no function word ("put", "off" with a verb is content by the verb)."""
    index = world_phrases(world)
    world_words, vocab = _naming_words(index)
    home = home_words(index)

    def content(w: str) -> bool:
        if w in world_words or w in _LEXICON_CONTENT or w.isdigit() or reads_as_count(w):
            return True
        if w in FUNCTION_WORDS:
            return False
        return _misspelt(w, vocab, home)
    return content


def reads_as_word(world: dict) -> Callable[[str], bool]:
    """Whether this reader reads a word as one of its own in this world: a word of the lexicon
    (grammar words too), a word of a world name, a number, or a misspelling of one (what an
    accented word may never be read as: :func:`pipflow.language.characters.accents_folded`)."""
    content = _content(world)
    lexicon = {w for k in PHRASES for w in k}
    return lambda w: w in lexicon or content(w)


#: how a clause opens when it says what the speaker will do ("I'll grab the milk myself", "I'm
#: about to unpack the shopping"): no order for the robots
SPEAKER_OPENERS = (("i", "will"), ("we", "will"), ("i", "am", "about", "to"), ("we", "are", "about", "to"),
                   ("i", "am", "going", "to"), ("we", "are", "going", "to"), ("i", "shall"), ("we", "shall"),
                   # "gonna make tea after this call": "I'm" left out
                   ("going", "to"))
#: what the speaker is doing now ("I'm eating between meetings"): "I am" / "we are" and a word
#: in -ing that is no word of the lexicon ("I'm starving", "I'm leaving" are cues and reasons)
SPEAKER_NOW = (("i", "am"), ("we", "are"))
#: what the speaker will do as the purpose of an order ("bring the lobster pot in so I can mend
#: it"): "so" (+ "that") + one of these; it ends the order's clause like a comma
PURPOSE_OPENERS = tuple(("so",) + that + who for that in ((), ("that",))
                        for who in (("i", "can"), ("we", "can"), ("i", "could"), ("we", "could")))
#: verbs after such an opener that make it a wish, not the speaker's doing ("I'll need the oven on",
#: "I'll take the tea in the cabin", "I'm going to want ..."): never set aside
WISH_VERBS = {"need", "want", "like", "have", "take", "be", "wish", "prefer", "love"}


#: what the speaker will have what the order makes with, or for ("I'll have it with my tea"):
#: a wish verb with a pronoun, then one of these, is the speaker's use of it, no wish
USE_LINKS = {"with", "for", "at", "in", "by", "before", "after", "later", "when", "once", "tonight"}


#: who else may be said to be about to do something ("she'll make the sabzi after her class", "my
#: wife will cook later", "madam will make bhurji"): what another person will do is no order for
#: the robots. "they" is left out: it is as often the robots, or things
OTHER_PEOPLE = {"he", "she"}
FAMILY = KIN | {"father", "sister", "brother", "maid", "madam", "neighbour", "neighbor"}
#: how such a clause goes on after its subject
OTHERS_OPENERS = (("will",), ("shall",), ("is", "going", "to"), ("is", "about", "to"))


#: what another person can or will do, said as the purpose of an order ("so he can hear himself
#: think", "so Virgil can watch his ballgame", "so he'll take them with his dinner")
PURPOSE_MODALS = ("can", "could", "will", "would")


def people_named(command: str, world: dict, content: Callable[[str], bool]) -> frozenset[str]:
    """The names of people in a command ("Virgil", "Dusty"): words written with a capital inside a
    sentence (any first word has one) that name nothing of the home (``content``: :func:`_content`
    of the world), no robot or team ("so Bertie can get the plate out": Bertie is asked to) and
    are no word of the reader."""
    robots = {w for name in doers(world) for w in re.split(r"[\s_-]+", name)}
    said = re.findall(r"(?<=[a-z0-9,;:'\u2019]\s)[A-Z][a-z]+", command)
    return frozenset(w for w in (x.lower() for x in said)
                     if not content(w) and w not in _PHRASE_WORDS and w not in FUNCTION_WORDS and w not in robots)


def _other_person(words: tuple[str, ...], people: frozenset[str] = frozenset()) -> int:
    """How many words of a clause's opening name another person (:data:`OTHER_PEOPLE`, "my
    wife", "madam", a name of :func:`people_named`), 0 if none."""
    if words[:1] and (words[0] in OTHER_PEOPLE or words[0] in FAMILY or words[0] in people):
        return 1
    return 2 if len(words) > 1 and words[0] in ("my", "our", "the") and words[1] in FAMILY else 0


def speaker_doing(words: tuple[str, ...], people: frozenset[str] = frozenset()) -> bool:
    """Whether a clause says what the speaker, or another person (:data:`OTHERS_OPENERS`), will
    do ("I'll grab the milk myself", "she'll make the sabzi later"): it opens with
    :data:`SPEAKER_OPENERS`, its verb is no wish (:data:`WISH_VERBS`) and it has no negation or
    exclusivity ("I'll not ...", "I'll only ..."), which would bear on what the robots do. A wish
    verb taking a pronoun and then how or when the speaker uses it ("I'll have it with my tea",
    "we'll have them for supper") is the speaker's doing too: "it" is what the order is about.
    What another person can or will do, as the purpose of the order ("so he can hear himself
    think": :data:`PURPOSE_MODALS`), is theirs too. ``people``: the names of :func:`people_named`."""
    who = _other_person(words, people)
    openers = [tuple(words[:who]) + o for o in OTHERS_OPENERS] if who else []
    if words[:1] == ("so",):
        k = 2 if words[1:2] == ("that",) else 1
        them = _other_person(words[k:], people)
        openers += [tuple(words[:k + them]) + (m,) for m in PURPOSE_MODALS] if them else []
    for opener in list(SPEAKER_OPENERS + PURPOSE_OPENERS) + openers:
        if words[:len(opener)] == opener and len(words) > len(opener):
            rest = words[len(opener):]
            if any(w in NEGATION or w in EXCLUSIVITY for w in rest):
                return False
            using = len(rest) > 3 and rest[0] in ("have", "take") and rest[1] in ("it", "them") \
                and rest[2] in USE_LINKS
            if rest[0] not in WISH_VERBS or using:
                return True
            break   # "I'll need it for supper": a wish, which may still be what the order is for
    return speaker_needing(words) or speaker_busy(words)


def speaker_busy(words: tuple[str, ...]) -> bool:
    """Whether a clause says what the speaker is busy with now (:data:`SPEAKER_NOW`): no order for
    the robots, and nothing operative in it."""
    for opener in SPEAKER_NOW:
        rest = words[len(opener):]
        # "I'm gagging for a brew" is a wish of the lexicon ("am gagging for"), not what the speaker is doing
        wish = tuple(words[len(opener) - 1:len(opener) + 2]) in PHRASES
        if words[:len(opener)] == opener and rest and rest[0].endswith("ing") and len(rest[0]) > 5 \
                and (rest[0],) not in PHRASES and not wish and not any(w in NEGATION or w in EXCLUSIVITY for w in rest):
            return True
    return False


#: words before a number that make it a time of day ("a call at 2", "back by 6"), and after it
#: ("10 am", "15 min"): a time is no count of things, so a clause may still be talk
_TIME_BEFORE = {"at", "by", "until", "till", "before", "after", "around", "about"}
_TIME_AFTER = {"am", "pm", "oclock", "o"} | DURATION_UNITS


def _without_talk(words: tuple[str, ...]) -> tuple[str, ...]:
    """The words with each word of talk the parser drops (lexicon ``FILLER``: "khalas", "yalla")
    left out, so that what is said around it is judged as said ("Khalas, that's all"); never an
    operative word ("again", "just"), nor a thanks the talk tests read with its words ("thanks very much")."""
    return tuple("" if (w,) in FILLER and w not in OPERATIVE | THANKS | PLEASANTRIES and not near_operative(w) else w
                 for w in words)


def _without_times(words: tuple[str, ...]) -> tuple[str, ...]:
    """The words with each number that says a time or how long left out (:data:`_TIME_BEFORE`,
    :data:`_TIME_AFTER`; a time of day is at most 12, or 24 with am/pm or a duration after it)."""
    out = list(words)
    for k, w in enumerate(words):
        n = read_number([w], 0)
        value = n[0] if n else None
        if not isinstance(value, int):
            continue
        after = words[k + 1] if k + 1 < len(words) else ""
        if after in _TIME_AFTER or (k and words[k - 1] in _TIME_BEFORE and 0 < value <= 12):
            out[k] = ""
    return tuple(out)


#: "I need them tonight", "we'll want it later": the speaker needing what the order is about, said
#: after the order as its reason; only a pronoun and words of time may follow the verb ("I need
#: them washed" asks for a state, and is read)
NEEDING = (("i", "need"), ("i", "will", "need"), ("we", "need"), ("we", "will", "need"), ("i", "want"),
           ("i", "will", "want"), ("i", "am", "going", "to", "need"))


def speaker_needing(words: tuple[str, ...]) -> bool:
    """Whether a clause says the speaker needs what the order is about (:data:`NEEDING`)."""
    for opener in NEEDING:
        rest = words[len(opener):]
        if not (words[:len(opener)] == opener and rest and rest[0] in ("it", "them", "those", "these")):
            continue
        # "I need them scrubs for tonight": a demonstrative points back at things the order names
        # (words of no state or verb: "I need them washed for tonight" asks for a state)
        n = next((j for j in range(1, min(len(rest), 4)) if rest[j] in _NEEDED_WHEN), 1) if rest[0] != "it" else 1
        if all((w,) not in PHRASES for w in rest[1:n]) and all(w in PURPOSE_WORDS or w in _NEEDED_WHEN for w in rest[n:]):
            return True
    return False


#: what may follow what the speaker needs, saying when ("I need them later", "for tonight")
_NEEDED_WHEN = frozenset({"later", "on", "for", "in", "the", "a", "bit", "while", "first", "thing", "tonight",
                          "tomorrow", "today", "morning", "now", "soon"})


#: marks that set a part of a sentence off like commas: dashes, brackets
_PARENTHESES = re.compile(r"\s[-\u2010-\u2015]+\s|[\u2013\u2014\u2015()\[\]]")


def _purposes_apart(words: list[str], people: frozenset[str] = frozenset()) -> list[str]:
    """The words with a comma before a purpose that says what the speaker will do ("... so I
    can mend it": :data:`PURPOSE_OPENERS`), and before "otherwise", so that each is a clause of
    its own (what "otherwise" opens is judged there: :func:`prediction`)."""
    out: list[str] = []
    for k, w in enumerate(words):
        if w == "otherwise" and out and out[-1] not in CLAUSE_MARKS:   # "... otherwise she will forget"
            out.append(",")
        if w == "so" and out and out[-1] not in CLAUSE_MARKS:
            end = next((j for j in range(k, len(words)) if words[j] in CLAUSE_MARKS), len(words))
            if speaker_doing(tuple(words[k:end]), people):
                out.append(",")
        out.append(w)
    return out


#: lexicon classes a remark may not hold: the cues, wishes and needs a vague command is read from
#: ("I'm freezing", "we want some music", "I need a cuppa"), the states a thing is asked to be in
#: ("dirty", "hot") and what says how a thing is to be handled
CUE_CLASSES = {"ADJ", "AIRCUE", "CLUTTER", "DOACT", "ACTIVITY", "FOULS", "FRESHAIR", "FULLOF", "HANDLING",
               "HEARCUE", "HOTDRINK", "LIGHTCUE", "MEAL", "MESS", "MORE", "MUSIC", "NEED", "NEEDED", "SHOULD",
               "SLEEPCUE", "SOUNDCUE", "TEMPCUE", "WANT", "TAKESTWO", "FORONE", "GOING", "LYING", "LEFT", "STAY",
               "EVERYTHING", "ALLOVER", "HERE", "INROOM", "ROOMSAID", "SOMEWHERE", "AWAY", "GOES", "DONE",
               "FINISHED", "TOGGLED", "SEE", "V_USE", "NOBODY", "DONOT", "CANNOT", "EXCEPT", "EVERY", "ALL", "BOTH"}
#: the verbs after which "back" says someone comes home ("she'll be back at nine", "gets back")
_RETURNING = {"be", "is", "are", "s", "get", "gets", "got", "come", "comes", "coming", "was", "were", "been"}
#: who a remark is about, opening it: the speaker, another person, something the speaker has
REMARK_SUBJECTS = {"i", "im", "we", "he", "she", "my", "our", "his", "her"}
#: words that point back at what an order is about, or at a place: a clause with one may say
#: what that thing must be ("it should be hot", "leave them there"), so it is never a remark
POINTING = {"it", "its", "them", "they", "their", "there", "here", "those", "these", "that", "this", "one", "ones",
            "em", "thing", "things", "stuff"}
#: words that bear on what the robots do, in any clause (:mod:`pipflow.language.asides`)
_BEARING = NEGATION | EXCLUSIVITY | BOUNDS | QUANTITIES | SELECTION


#: what follows a name that opens a remark ("Pastor Jones is coming", "Shanice a come", "the
#: twins are coming round"): a verb of being or an auxiliary, so the name is its subject
SUBJECT_LINKS = {"is", "are", "was", "were", "will", "would", "has", "have", "had", "can", "could", "a", "s",
                 "ll", "d", "re", "ve"}


#: the words of the cues, wishes and states a vague command is read from; every word of the lexicon
_CUE_WORDS = frozenset(w for k, (cls, _) in PHRASES.items() if cls in CUE_CLASSES for w in k) - FUNCTION_WORDS
_PHRASE_WORDS = frozenset(w for k in PHRASES for w in k)


@per_index
def _home_vocabulary(index: dict) -> tuple[frozenset[str], frozenset[str]]:
    """The words of the home's names (no function word), and those a typo may be read as."""
    world_words = home_words(index) - FUNCTION_WORDS
    return world_words, frozenset(w for w in vocabulary(index) if w in world_words)


def _names(world: dict) -> Callable[[str], bool]:
    """Whether a word names something of the home (a word of a name, or a misspelling of one) or
    is a number: what a statement or an adjunct of talk may never hold."""
    index = world_phrases(world)
    world_words, vocab = _home_vocabulary(index)
    home = home_words(index)
    return lambda w: w in world_words or w.isdigit() or reads_as_count(w) or _misspelt(w, vocab, home)


def run_on_talk(kept: list[Clause], content: Callable[[str], bool], names: Callable[[str], bool]) -> list[Clause]:
    """Talk said at the end of a clause that carries an order, without a comma between, as people
    dictating do ("hang it in the closet would ya doreen had a fit", "put the bread away before the
    cat gets at it"): a thanks or request tag closing the last clause, a statement run on
    (:func:`pipflow.language.asides.unmarked_statement`: no name, number or operative word in it),
    then an adjunct of time or reason that names nothing of the home
    (:func:`pipflow.language.asides.trailing_adjunct`; a purpose said with a verb and "since" are
    this reader's own: :func:`_adjunct`). The warehouse's tests, on the clauses not already set
    aside (``kept``)."""
    out: list[Clause] = []
    last = kept[-1] if kept else None
    for c in kept:
        words = list(c.words)
        while True:   # a thanks may close the order before a statement: "... would ya doreen had a fit"
            n = (trailing_thanks(words, names) if c is last else trailing_vocatives(words, names)) \
                or unmarked_statement(words, names) \
                or _adjunct(words, content, names)
            if not n:
                break
            if n < len(words) - 1 and words[-n] in TEMPORAL and words[-n - 1] == "for":
                n += 1   # "for when she wakes up": what for, a time
            end = c.start + len(words)
            out.append(Clause(end - n, end, tuple(words[-n:])))
            words = words[:-n]
    return out


def _adjunct(words: list[str], content: Callable[[str], bool], names: Callable[[str], bool]) -> int:
    """:func:`pipflow.language.asides.trailing_adjunct`, but never what this reader reads by rules
    of its own: a purpose said with a verb ("for washing" may ask for the washing: :mod:`.rewrites`;
    "for me and my boy" says who for, and is talk) and "since" (a time when something began: "since
    the party" in an order is refused)."""
    n = trailing_adjunct(words, content, names)
    if not n:
        return 0
    opening, rest = words[-n], words[-n + 1:]
    # "since" after "been" says how long a thing has lain ("it's been on the table since Sunday")
    if (opening == "since" and "been" not in words[:-n]) \
            or (opening == "for" and any(w.endswith("ing") and len(w) > 4 for w in rest[:2])):
        return 0
    if opening == "for" and any(PHRASES.get(tuple(words[-n - m:-n + 1]), ("",))[0] == "WANT" for m in (1, 2)):
        return 0   # "I'm dying for a brew": what is wished for, no purpose
    return n


#: the subjects of what a thing will do by itself ("it'll turn", "they'll be going up to bed")
_PREDICTED = {"it", "they", "that", "this", "she", "he"}
#: words after "will" that ask for something ("it will need washing", "it will want a wipe")
_ASKS = {"need", "needs", "want", "wants", "have", "has", "must", "should", "got"}


def prediction(words: tuple[str, ...], names: Callable[[str], bool]) -> bool:
    """ "..., it'll turn", "the cricket will be starting": what will happen by itself, said as a
    reason; talk, set aside. A clause of it, they, that (or a person) and "will", and after it no
    name of the home, no number, no "you", no word that bears on an order or asks ("it will need
    washing" asks)."""
    ws = list(words)
    while ws[:1] and ws[0] in ("and", "so", "cos", "because", "or", "otherwise", "else"):   # "..., and it'll turn"
        ws = ws[1:]
    if len(ws) < 3 or ws[0] not in _PREDICTED or ws[1] not in ("will", "ll"):
        return False
    rest = ws[2:]
    return not any(names(w) or w in ("you", "your") or w in _ASKS or any(ch.isdigit() for ch in w)
                   or w in _BEARING for w in rest)


def _remark(world: dict, content: Callable[[str], bool]) -> Callable[[tuple[str, ...]], bool]:
    """The test of a remark: a clause about the speaker or other people ("my granddaughter is
    coming for lunch after service", "Pastor Jones is coming by at 4"), talk though it has words of
    the lexicon ("coming", "after") that :func:`content_free` counts. It opens with its subject:
    :data:`REMARK_SUBJECTS`, or one or two words that are no word of the world, the lexicon or a
    misspelling of one (a name: "the twins", "pastor jones") with a verb of being or an auxiliary
    after them (:data:`SUBJECT_LINKS`), so that a verb the reader lacks ("frob the ...") is never
    taken for a name. It names nothing of the world (nor a misspelling of it), has no number but a
    time, no word that bears on an order (negation, exclusivity, bounds, quantities), no word that
    points back (:data:`POINTING`) and no word of the cues, wishes and states a vague command is
    read from (:data:`CUE_CLASSES`). ``content``: :func:`_content` of the world, made once by the
    caller."""
    index = world_phrases(world)
    world_words, vocab = _home_vocabulary(index)
    home = home_words(index)

    def names(w: str) -> bool:
        return w in world_words or _misspelt(w, vocab, home)

    def a_name(w: str) -> bool:
        return not (w in FUNCTION_WORDS or w in _PHRASE_WORDS or content(w))

    def remark(words: tuple[str, ...]) -> bool:
        ws = [w for w in _without_times(words) if w]
        # "our lass will be back from bingo": "back" after "be" is a person coming home, no "put back"
        ws = [w for k, w in enumerate(ws) if not (w == "back" and k and ws[k - 1] in _RETURNING)]
        while ws and ws[0] in ("and", "cause", "because", "cos", "coz", "cuz", "as", "since"):
            ws = ws[1:]
        subject = ws[1:] if ws[:1] in (["the"], ["a"], ["an"]) else ws
        opens = bool(ws) and ws[0] in REMARK_SUBJECTS or any(
            all(a_name(w) for w in subject[:n]) and subject[n:n + 1] and subject[n] in SUBJECT_LINKS for n in (1, 2))
        return opens and not any(w in _BEARING or w in POINTING or w in _CUE_WORDS or names(w) or w.isdigit()
                                 or reads_as_count(w) for w in ws)
    return remark


class Trimmed(NamedTuple):
    """A command without the talk :func:`without_asides` sets aside, and that talk."""

    rest: str
    free: list[str]        # content-free clauses
    own: list[str]         # what the speaker will do
    restated: list[str]    # where a thing is, as the world has it (:mod:`.restated`)


def _topic_restated(words: list[str], parts: list, world: dict) -> tuple[list[str], list, list]:
    """A first clause that says where a thing is, as the world has it, followed by a clause that
    takes it up with "it" / "them" ("the frying pan is on the stove, wash it"): the thing's words
    stand for the pronoun, and the first clause is set aside as a restatement. (words, clauses,
    [(the first clause, what it restates)]); unchanged where there is no such pair."""
    if len(parts) < 2:
        return words, parts, []
    subject = leading_subject(parts[0].words, world)
    second = parts[1]
    at = next((k for k, w in enumerate(second.words) if w in ("it", "them")), None)
    if subject is None or at is None or sum(w in ("it", "them") for w in second.words) != 1:
        return words, parts, []
    k = second.start + at
    words = words[:k] + list(subject) + words[k + 1:]
    said = (parts[0], f"{' '.join(subject)} where it is")
    return words, clauses(words, CLAUSE_MARKS), [said]


#: words that join a remark to an order without a mark ("johan is coming home and his beers are
#: still warm in the pantry"), as speech to text writes it
_JOINERS = ("and", "so", "but")


def remarks_joined(kept: list[Clause], remark: Callable[[tuple[str, ...]], bool]) -> list[Clause]:
    """The remarks (:func:`_remark`) joined to a clause with "and", "so" or "but" and no mark:
    each stretch of a clause from its start or a joiner to the next joiner or its end that is a
    remark by itself, set aside with its joiner (the one after it, for a remark that opens the
    clause), where something else of the clause is left."""
    out: list[Clause] = []
    for c in kept:
        cuts = [0] + [j for j, w in enumerate(c.words) if w in _JOINERS and j] + [len(c.words)]
        for a, b in zip(cuts, cuts[1:]):
            if b - a < len(c.words) and remark(c.words[a + (a > 0):b]):
                b += a == 0   # a remark first goes with the joiner after it ("xander is out so ...")
                out.append(Clause(c.start + a, c.start + b, c.words[a:b]))
    return out


def without_asides(command: str, world: dict) -> Trimmed | None:
    """The command without its content-free clauses (:mod:`pipflow.language.asides`), its
    clauses that say what the speaker will do (:func:`speaker_doing`) and those that say where a
    thing already is (:func:`pipflow.household.language.restated.restates_location`), or None
    when it has none (or nothing else). Dashes and brackets set a clause off as commas do
    ("throw the fish away - it smells off - and ..."). A first clause is never a restatement."""
    content = _content(world)
    people = people_named(command, world, content)
    words = _purposes_apart(words_of(_PARENTHESES.sub(" , ", command)), people)
    parts = clauses(words, CLAUSE_MARKS)
    words, parts, topic = _topic_restated(words, parts, world)
    robots = doers(world)   # who may be addressed
    remark = _remark(world, content)
    free = [c for c in parts if content_free(_without_talk(_without_times(c.words)), content, content, reports=True,
                                             robot=robots.__contains__) or remark(c.words)
            # "Two things: ...", "Quick one, ...", "Change of plan: ..."
            or (c is parts[0] and (is_opener(c.words) or opens_changed_plan(c.words)))]
    if len(parts) > 1 and parts[-1] not in free and signature(parts[-2].words, parts[-1].words):
        free.append(parts[-1])   # "Regards, Tom": the writer's name
    own = [c for c in parts if c not in free and speaker_doing(c.words, people)]
    known = [(c, restates_location(c.words, [b.words for b in parts[:k]], world)) for k, c in enumerate(parts)
             if k and c not in free and c not in own]
    known = [(c, what) for c, what in known if what] + topic
    taken = set(free) | set(own) | {c for c, _ in known}
    names = _names(world)
    free += run_on_talk([c for c in parts if c not in taken], content, names)
    free += remarks_joined([c for c in parts if c not in taken and c not in free], remark)
    free += [c for c in parts if c not in taken and c not in free and prediction(c.words, names)]
    free += unseen([c for c in parts if c not in taken and c not in free], names)
    if not free and not own and not known:
        return None
    drop = {k for c in free + own + [c for c, _ in known] for k in range(c.start, c.end)}
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
    return Trimmed(" ".join(out), [" ".join(c.words) for c in free], [" ".join(c.words) for c in own],
                   [f"'{' '.join(c.words)}' ({what} now)" for c, what in known])

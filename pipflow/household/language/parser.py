"""The offline parser for household commands: command + world -> household orders.

Compositional, in three steps, and never by word position:

1. **tag** (:mod:`~pipflow.household.language.tagger`, with :mod:`~.names`, :mod:`~.typos`,
   :mod:`~.rewrites` and :mod:`~.retag`): the command's words become token classes: the world's names (longest match, with
   plurals, typo-tolerant: "fridgge" reads as "fridge" and a note says so), numbers, and the
   closed lexicon of :mod:`pipflow.household.language.lexicon`. A word in neither is a
   :class:`TranslationError` that quotes it: nothing is skipped silently (politeness words such
   as "please" carry no content and are listed in the lexicon).
2. **parse**: lark's Earley parser over the grammar of :mod:`pipflow.household.language.grammar` builds the
   sentence structure (clauses, coordination, gapping, pronouns, exceptions, relative clauses,
   state cues). Earley keeps every reading; all of them are returned.
3. **build** (:mod:`~pipflow.household.language.builder`): each reading becomes an *order* (``schemas/household_order.schema.json``): a list
   of statements, each with the selectors of the things it is about and the words it came from.
   Which objects a selector means, and whether the request is possible, is the resolver's job
   (:mod:`pipflow.household.language.resolver`), not the parser's.

A command that does not read as said is read again with a verb's object left out read as "it",
and with things named before their verb (:mod:`~.fronted`) read after it; and without the talk
:mod:`~.setaside` finds.
"""
from __future__ import annotations

import functools
import json
import re
from typing import Callable, Iterator

from lark import Lark, Token, Tree
from lark.exceptions import UnexpectedInput
from lark.visitors import CollapseAmbiguities

from pipflow.errors import TranslationError
from pipflow.household.language.builder import Builder
from pipflow.household.language.conditions import conditions_read
from pipflow.household.language.fronted import fronted_objects, topic_too
from pipflow.household.language.gendered import things_called_him
from pipflow.household.language.grammar import NOUN_DUAL, grammar_text
from pipflow.household.language.lacking import lacking
from pipflow.household.language.lexicon import ARROW, MARKS, PHRASES, arrows_said_as
from pipflow.household.language.names import per_index, world_phrases
from pipflow.household.language.people import about_people
from pipflow.household.language.setaside import reads_as_word, without_asides
from pipflow.household.language.tagger import owners_as_the, tag
from pipflow.household.language.tokens import Tag
from pipflow.language.arabizi import spelt_in_letters
from pipflow.language.asides import said
from pipflow.language.characters import (accents_folded, declared_spellings, digit_words, non_ascii_words,
                                         refuse_unread, turkish_i, without_expressions)
from pipflow.language.english import common_word
from pipflow.language.listing import inline_numbering
from pipflow.language.earley import ListLexer, earley_parser
from pipflow.language.lookahead import with_lookahead
from pipflow.language.optionals import nullable_optionals

#: the most readings of one ambiguous command that are compared (each is resolved); more is
#: refused, never cut short
MAX_READINGS = 64


def parse(command: str, world: dict, notes: list[str] | None = None) -> list[dict]:
    """Every reading of the command as an order (module docstring); TranslationError quoting the
    words where the command stops making sense to the grammar.

    A command that does not read as said is read again without its content-free clauses
    (greetings, thanks, asides: :mod:`pipflow.language.asides`); they are set aside, said in the
    notes and in each order's ``set_aside``. Every other clause still needs every word placed."""
    if not isinstance(command, str) or not command.strip():
        raise TranslationError("the command is empty")
    notes = notes if notes is not None else []
    if not ARROW.search(command):
        return _parse_said(command, world, notes)
    # "bowl + wine glass -> dishwasher": an arrow says "to"; after a clause that says what to do
    # or asks ("tv on? -> turn it off"), it says "then". The reading with "to" is tried first.
    # A reading refused as impossible (Refusal) is not read again.
    first: TranslationError | None = None
    for said_as in ("to", ", then"):
        mine: list[str] = []
        try:
            readings = _parse_said(arrows_said_as(command, said_as), world, mine)
        except TranslationError as exc:
            first = first or exc
            continue
        notes += mine
        return readings
    raise first


def _parse_said(command: str, world: dict, notes: list[str]) -> list[dict]:
    """:func:`parse` of a command whose arrows are said in words."""
    # "... before Nana wakes 🙏": a face or a gesture ends a sentence, and is said as set aside
    command, feelings = without_expressions(inline_numbering(command))   # "1) ... 2) ...": a job each
    if feelings:
        notes.append(said(feelings))
    if not command.isascii():   # "the Québec cousins are coming": an accented word that can only be talk
        command, declared = declared_spellings(command, non_ascii_words(world, ("places", "objects")))
        command, keyboard = turkish_i(command)
        declared += keyboard
        command, accented = accents_folded(command, reads_as_word(world))
        notes += declared + accented
    refuse_unread(command, MARKS)   # a character this reader does not read is refused, never skipped
    command, spelt = declared_spellings(command, digit_words(world, ("places", "objects")))   # "the old fa7m"
    notes += spelt
    if _LETTER_BY_DIGIT.search(command):   # "ya3ni", "el gaw 7ar" (the home's words are read only then)
        command = spelt_in_letters(command, _english_or_read(world), notes)
    refuse_digits_in_words(command)
    command = owners_as_the(command, world, notes)
    command = conditions_read(command, world, notes)   # "if the lamp is on, switch it off"
    command = things_called_him(command, world, notes)   # "the veranda light is on, off him"
    try:
        return _parse_with_people(command, world, notes)
    except TranslationError as exc:
        impossible = lacking(command, exc)   # "switch on the dishwasher" where there is none
        if impossible is not None:
            raise impossible from None
        raise


#: what may follow a number written together with it: a time of day, an ordinal, a duration, a unit
_NUMBER_SUFFIXES = {"am", "pm", "st", "nd", "rd", "th", "h", "hr", "hrs", "min", "mins", "s", "x", "kg", "g", "ml",
                    "l", "cm", "mm", "m", "ish"}
_GLUED = re.compile(r"(?<![A-Za-z0-9])(\d+)([A-Za-z]+[A-Za-z0-9]*)")
#: a letter and a digit side by side: where Arabizi may be written
_LETTER_BY_DIGIT = re.compile(r"[A-Za-z]\d|\d[A-Za-z]")


def _english_or_read(world: dict) -> Callable[[str], bool]:
    """Whether a word is one this reader or this home reads, a unit said with a number, or an
    English word of three letters or more: a digit glued to it is a count, never Arabizi."""
    reads = reads_as_word(world)
    return lambda w: w in _NUMBER_SUFFIXES or reads(w) or (len(w) >= 3 and common_word(w))


def refuse_digits_in_words(command: str) -> None:
    """Refuse a command with a number written into a word ("3ala", "7oto", "e5salo": Arabizi, where
    digits stand for letters): the reader splits words from numbers, and would read the digit as a
    count of what follows; never a guess. A time, an ordinal or a unit written with its number
    ("8pm", "2nd", "2x") is no such word."""
    glued = [m.group(0) for m in _GLUED.finditer(command) if m.group(2).lower() not in _NUMBER_SUFFIXES]
    glued += [w for w in re.findall(r"\b[A-Za-z]+\d+[A-Za-z]+\w*\b", command)]
    if glued:
        raise TranslationError(f"{', '.join(repr(w) for w in dict.fromkeys(glued))}: a number written into a word "
                               "is never read as a count; write the number apart from the word, or the word in letters")


def _parse_with_people(command: str, world: dict, notes: list[str]) -> list[dict]:
    """:func:`parse` of the command as said, else with its third persons read (:mod:`~.people`:
    where they are, what is for them, talk about them). When that does not read either, the
    command's own refusal stands (a person's place not said is refused as such)."""
    first: list[str] = []
    try:
        readings = _parse_with_asides(command, world, first)
    except TranslationError as exc:
        notes += first
        mine: list[str] = []
        read = about_people(command, world, mine)   # refused where a person's place is not said
        if read is None:
            raise
        try:
            readings = _parse_with_asides(read, world, mine)
        except TranslationError as again:
            # the command as said is refused; the wording with its people read is where candidate
            # readings start too (it may stop only at a choice of which thing is meant)
            exc.reworded = (read, again, mine)
            raise exc from None
        del notes[len(notes) - len(first):]   # the notes of the reading that failed
        notes += mine
        return readings
    notes += first
    return readings


def _parse_with_asides(command: str, world: dict, notes: list[str]) -> list[dict]:
    """:func:`parse` of the command as said, else without the talk it sets aside."""
    said_before = len(notes)
    try:
        return _parse(command, world, notes)
    except TranslationError:
        del notes[said_before:]   # what the reading that failed noted is no part of the echo
        trimmed = without_asides(command, world)
        if trimmed is None:
            raise
        mine: list[str] = []
        try:
            readings = _parse(trimmed.rest, world, mine)
        except TranslationError as again:
            # what is left after the talk is set aside is what does not read: say that
            error = TranslationError(f"{again} (set aside: "
                                     + "; ".join([repr(a) for a in trimmed.free + trimmed.own] + trimmed.restated) + ")",
                                     candidates=again.candidates)
            for attr in ("unread", "unplaced", "choices"):   # what candidate readings are built from
                if hasattr(again, attr):
                    setattr(error, attr, getattr(again, attr))
            raise error from None
    notes += mine + ([said(trimmed.free)] if trimmed.free else []) + [
        f"'{own}' says what the speaker will do: no order for the robots (set aside)" for own in trimmed.own] + [
        f"{r} says where a thing is, as this home has it: set aside" for r in trimmed.restated]
    extra = {**({"set_aside": trimmed.free} if trimmed.free else {}), **({"speaker_does": trimmed.own} if trimmed.own else {}),
             **({"restated": trimmed.restated} if trimmed.restated else {})}
    return [{**r, **extra} for r in readings]


def _parse(command: str, world: dict, notes: list[str]) -> list[dict]:
    """:func:`parse` of the command as said."""
    tags, topics = topic_too(tag(command, world, notes))
    notes += topics
    if not [t for t in tags if t.cls not in ("END", "COMMA")]:
        raise TranslationError(f"{command.strip()!r} asks for nothing the offline parser can read")
    try:
        tree = _parser_for(world).parse(_terminals(tags))
    except UnexpectedInput as exc:
        for repaired, said in _repairs(tags):
            try:
                tree = _parser_for(world).parse(_terminals(repaired))
            except UnexpectedInput:
                continue
            notes += said
            return _orders(repaired, tree, command)
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
#: drops the object "it" (the thing named before), as people do after naming it; "keep in the
#: vessel stand" (Indian English "keep": put) with the leaving verbs
DROPPED_OBJECT_VERBS = {"V_PUT", "V_THROW", "V_LEAVE"}
DESTINATIONS = {"IN", "ON", "AT"}


def _repairs(tags: list[Tag]) -> Iterator[tuple[list[Tag], list[str]]]:
    """The tags of a command that does not parse as said, worded as the grammar's English, each
    with the notes that say so, in this order (the first that parses is read): a verb's object
    left out read as "it" (:func:`_elided_objects`); things named before their verb moved after it
    (:mod:`~.fronted`); both ("soup and cheese take out of the fridge and put on the table"); a
    verb said after a place with no joiner as a step of its own (:func:`_serial_verbs`), and with
    its object left out; both of the last two at once."""
    elided = _elided_objects(tags)
    if elided is not None:
        yield elided, [_elided_note(tags)]
    fronted = fronted_objects(tags)
    if fronted is not None:
        moved, words = fronted
        said = ["'" + "', '".join(words) + "': the thing named before its verb, read after it"]
        yield moved, said
        both = _elided_objects(moved)
        if both is not None:
            yield both, said + [_elided_note(moved)]
    serial = _serial_verbs(tags)
    if serial is not None:
        said = ["a verb said after a place with no 'and' or comma before it: read as a step of its own"]
        yield serial, said
        both = _elided_objects(serial)
        if both is not None:
            yield both, said + [_elided_note(serial)]
    if fronted is not None and (serial := _serial_verbs(fronted[0])) is not None:
        # "bring the orchid from the balcony put on the table, then the dumbbell keep in the shelter"
        said = ["'" + "', '".join(fronted[1]) + "': the thing named before its verb, read after it",
                "a verb said after a place with no 'and' or comma before it: read as a step of its own"]
        yield serial, said
        both = _elided_objects(serial)
        if both is not None:
            yield both, said + [_elided_note(serial)]


def _destination_at(tags: list[Tag], k: int) -> bool:
    """Whether a destination opens at ``tags[k]``: "in", "on", or "back" before one ("then put back
    in the fridge")."""
    return k < len(tags) and (tags[k].cls in DESTINATIONS or (
        tags[k].cls == "BACK" and k + 1 < len(tags) and tags[k + 1].cls in DESTINATIONS | {"TO"}))


def _is_name(t: Tag) -> bool:
    return t.cls == "NOUN" or t.cls.endswith(NOUN_DUAL)


#: prepositions of a place a step may end on ("from the fridge", "on the table")
_PLACE_PREPOSITIONS = {"FROM", "IN", "ON", "AT", "TO", "OUT", "OFF", "OF"}


def _ends_with_a_place(out: list[Tag]) -> bool:
    """Whether the tags end with a preposition and a name ("... from [the] fridge"): a place, never
    a thing that could go on a list ("wash the jug and the platter put in the basin" stays asked)."""
    k = len(out) - 1
    if k < 1 or not _is_name(out[k]):
        return False
    k -= out[k - 1].cls == "THE"
    return k >= 1 and out[k - 1].cls in _PLACE_PREPOSITIONS


def _serial_verbs(tags: list[Tag]) -> list[Tag] | None:
    """ "take out the chicken wings from the fridge put on the counter": a verb of putting or
    throwing said straight after a place (a preposition and a name), or after any name with its own
    object ("wash the mug put it on the rack"), in a sentence that has had a verb already, opens a
    step of its own, as if a comma stood before it; None when there is no such verb. Tried only
    when the command does not parse as said."""
    out: list[Tag] = []
    verb_before = False
    changed = False
    for k, t in enumerate(tags):
        if t.cls in ("END", "EXCL"):
            verb_before = False
        # after a name that is no place, only a verb with its own object ("wash the mug put it on
        # the rack"): one without could take the name as its object too
        own_object = k + 1 < len(tags) and tags[k + 1].cls == "IT" and bool(out) and _is_name(out[-1])
        if t.cls in DROPPED_OBJECT_VERBS and verb_before and (_ends_with_a_place(out) or own_object):
            out.append(Tag("COMMA", None, ","))
            changed = True
        verb_before = verb_before or t.cls.startswith("V_")
        out.append(t)
    return out if changed else None


def _elided_note(tags: list[Tag]) -> str:
    return ("a verb with its object left out ('" + "', '".join(
        f"{tags[k].words} {tags[k + 1].words}" for k in range(len(tags) - 1)
        if tags[k].cls in DROPPED_OBJECT_VERBS and _destination_at(tags, k + 1))
        + "') read as 'it': the thing named before")


def _elided_objects(tags: list[Tag]) -> list[Tag] | None:
    """The tags with "it" put back after a verb of :data:`DROPPED_OBJECT_VERBS` followed at once
    by a destination, or by "away" closing its clause, when a thing was named before the verb
    ("slice the carrot, then put in the fridge", "wash the teapot and put away"); None when there
    is no such verb. Tried only when the command does not parse as
    said; "it" then means what it always means (the resolver's pronoun: the thing before)."""
    out: list[Tag] = []
    changed = False
    for k, t in enumerate(tags):
        out.append(t)
        named_before = any(_is_name(x) for x in tags[:k])
        # the destination must name where: "hang on" (wait) drops no object; a name right before the
        # verb is its object said first ("and plum put back on the trestle": :mod:`~.fronted`)
        # "wash the teapot and put away": "away" closing the clause is where it goes, too
        away = k + 1 < len(tags) and tags[k + 1].cls == "AWAY" and (k + 2 >= len(tags) or tags[k + 2].cls in ("END", "COMMA"))
        if (t.cls in DROPPED_OBJECT_VERBS and (k + 2 < len(tags) and _destination_at(tags, k + 1)
                                               and tags[k + 2].cls not in ("END", "COMMA") or away)
                and named_before and not _is_name(tags[k - 1])):
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


def _terminals(tags: list[Tag]) -> list[Token]:
    """The tagger's tokens as lark's terminals; a token's value is its index in the tag list."""
    return [Token(t.cls, str(k), start_pos=k, end_pos=k + 1) for k, t in enumerate(tags)]


@functools.lru_cache(maxsize=16)
def _lark(dual: frozenset[str]) -> Lark:
    """The Earley parser for commands whose dual tokens (a lexicon word that is also a name of the
    world) are of the classes ``dual``: one per world in practice (grammar_text says why). Built
    once, then loaded from the disk cache (:mod:`pipflow.language.earley`: a build costs about as
    much as reading forty commands, and every ``pipflow run`` is a new process); it predicts with
    one terminal of lookahead (:mod:`pipflow.language.lookahead`: the same forests, less work), over
    the grammar with its optional words as nullable rules (:mod:`pipflow.language.optionals`: the
    same readings from half the rules, built and loaded in about half the time)."""
    return with_lookahead(earley_parser(nullable_optionals(grammar_text(dual)), lexer=ListLexer,
                                        ambiguity="explicit"))


def _parser_for(world: dict) -> Lark:
    """The parser for commands in this world."""
    return _lark(_dual_classes(world))


def _dual_classes(world: dict) -> frozenset[str]:
    """The lexicon classes whose phrases are also names of this world ("trash", "microwave")."""
    return _dual_of(world_phrases(world))


@per_index
def _dual_of(index: dict) -> frozenset[str]:
    return frozenset(PHRASES[k][0] for k in index if k in PHRASES)

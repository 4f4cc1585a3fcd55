"""One reading of a command: its sentences lexed (remembered for the last few commands), each
read to its one meaning with what the sentences before it said, the content-free parts set
aside, and the user's picks applied (a reading chosen among candidates, words left out)."""
from __future__ import annotations

from collections import OrderedDict

from lark.exceptions import UnexpectedInput

from pipflow.errors import TranslationError
from pipflow.warehouse.language.forest import failure, keywords, said, without
from pipflow.warehouse.language.goals import Choice, leaving_out_what_stays, quote
from pipflow.warehouse.language.lexicon import Lexed, Lexicon
from pipflow.warehouse.language.readings import one_meaning
from pipflow.warehouse.language.robots import RobotSelector
from pipflow.warehouse.language.salvage import salvage as partial
from pipflow.warehouse.language.sentence import SentenceReader

#: the most terminals one sentence may have: Earley's time grows faster than the length on
#: ambiguous lists, so a bound per sentence keeps a whole command's parse linear in its length
MAX_SENTENCE_WORDS = 120

#: candidate readings re-read the same command up to a dozen times (each with another pick), and
#: tokenising it took a quarter of a refusal's time. Lexed sentences are never changed in place
#: (a partial parse builds new ones), so one serves every reading.
_LEXED: "OrderedDict[tuple, tuple[dict, Lexicon, RobotSelector, list[Lexed]]]" = OrderedDict()
_LEXED_KEPT = 8


def names_of(world: dict) -> tuple:
    """What the lexicon reads of a world: its names and the words declared for them, and the
    robots' kinds, tags and skills."""
    robots = world.get("robots") or {}
    declared = tuple((key, str(n), repr(e.get("words"))) for key in ("shelves", "products", "robots")
                     for n, e in (world.get(key) or {}).items() if isinstance(e, dict) and e.get("words"))
    return (tuple(world.get("shelves") or ()), tuple(world.get("products") or ()),
            tuple((str(r), repr(v.get("kind")), repr(v.get("tags")), tuple(v.get("skills") or ()))
                  if isinstance(v, dict) else (str(r),) for r, v in robots.items()), declared)


def lexed_command(command: str, world: dict, stops: frozenset[int] = frozenset()
                  ) -> tuple[Lexicon, RobotSelector, list[Lexed]]:
    """(lexicon, robot selector, sentences) of ``command`` in ``world`` (with a stop before each
    recognised token at ``stops``: :mod:`runon`), remembered for the last :data:`_LEXED_KEPT`
    commands (the same world object only: a changed world is a new object)."""
    key = (command, stops, id(world), names_of(world))
    hit = _LEXED.get(key)
    if hit is not None and hit[0] is world:
        _LEXED.move_to_end(key)
        return hit[1], hit[2], hit[3]
    if stops:
        lex, selector, _ = lexed_command(command, world)
        lex, sentences = lex.stopped(stops)
    else:
        lex = Lexicon(world, keywords())
        selector = RobotSelector(world, lex.index)
        sentences = lex.sentences(command)
    _LEXED[key] = (world, lex, selector, sentences)
    if len(_LEXED) > _LEXED_KEPT:
        _LEXED.popitem(last=False)
    return lex, selector, sentences


def _dislocated(lexed: Lexed, lex: Lexicon, selector: RobotSelector, world: dict, memory: dict,
                pick: dict) -> tuple[SentenceReader, list[str]] | None:
    """A sentence that does not read as said, read with its fronted topic where its pronoun stands
    ("The wheels on P, double them": :func:`wordorder.left_dislocated`), with or without its
    content-free clauses; the reader and the clauses set aside, or None where neither reads."""
    moved = lexed.dislocated
    if moved is None:
        return None
    for form, talk in ((moved, []), (moved.trimmed, list(moved.aside))):
        if form is None:
            continue
        try:
            return one_meaning(form, lex, selector, world, memory, pick), talk
        except (UnexpectedInput, TranslationError):
            continue
    return None


def _as_said(lexed: Lexed, lex: Lexicon, selector: RobotSelector, world: dict, memory: dict,
             pick: dict) -> SentenceReader:
    """The sentence's one meaning as said (:func:`one_meaning`), but a sentence that opens with
    counted things taken up by a pronoun only with them where the pronoun stands (:func:`_counted_topic`);
    so also read without its talk (:func:`_second_reading`)."""
    if lexed.dislocated is not None and lexed.tokens[0].type == "NUM":
        return _counted_topic(lexed, lex, selector, world, memory, pick)
    return one_meaning(lexed, lex, selector, world, memory, pick)


def _counted_topic(lexed: Lexed, lex: Lexicon, selector: RobotSelector, world: dict, memory: dict,
                   pick: dict) -> SentenceReader:
    """ "The 12 coils in the Hochregal, bring 4 of them to the Versand": things named first with
    their count, then taken up by a pronoun, are what the pronoun says; read as said, the first
    clause would be a count wanted there and "4 of them" a count added with no place it comes from
    (a misreading). So the sentence is read only with the topic where its pronoun stands
    (:func:`_dislocated`), and refused where that does not read."""
    moved = _dislocated(lexed, lex, selector, world, memory, pick)
    if moved is None or moved[1]:
        raise TranslationError(f"'{' '.join(t.text for t in lexed.source if t.text)}': the things named first with "
                               "their count are taken up by a pronoun; read with them in its place the sentence "
                               "does not read, so nothing is guessed")
    return moved[0]


def _second_reading(lexed: Lexed, error: TranslationError, lex: Lexicon, selector: RobotSelector, world: dict,
                    memory: dict, pick: dict, droppable: bool) -> tuple[SentenceReader, list[str]] | None:
    """A sentence that does not read as said, read again: with its fronted topic where its pronoun
    stands (:func:`_dislocated`), else without its content-free clauses (``trimmed``: they are set
    aside and said aloud, the rest still needs every word). The reader and the words set aside;
    None where the sentence may be left out instead (``droppable``: a candidate reading without
    it, never for competing meanings); else the error that says what does not read is raised."""
    moved = None if isinstance(error, Choice) else _dislocated(lexed, lex, selector, world, memory, pick)
    if moved is not None:
        return moved
    if lexed.trimmed is not None:
        try:
            return _as_said(lexed.trimmed, lex, selector, world, memory, pick), list(lexed.aside)
        except (UnexpectedInput, TranslationError) as again:
            # what is left after the talk is set aside is what does not read: say that
            trimmed = failure(again, lexed.trimmed, lex) if isinstance(again, UnexpectedInput) else again
            trimmed.sentence, trimmed.trimmed = error.sentence, True  # type: ignore[attr-defined]
            _locate(trimmed, lexed.trimmed, lex)
            trimmed.args = (f"{trimmed.args[0]} (set aside: {'; '.join(repr(a) for a in lexed.aside)})",)
            error = trimmed
    if droppable and not isinstance(error, Choice):
        return None
    raise error from None


def parse_reading(command: str, world: dict, picks: dict | None = None) -> dict:
    """:func:`parse` of one reading of the line breaks. ``picks``: for a sentence (its index), the
    reading a user chose among candidates: ``{"reading": k}``, ``{"scope": ...}``, or ``{"drop":
    [token indexes]}`` (words left out of it); none in an ordinary run. ``picks["*"]``: for the
    whole command, ``salvage`` (a partial parse) or ``stops`` (recognised tokens a stop is put
    before: :mod:`runon`)."""
    picks = picks or {}
    stops = frozenset((picks.get("*") or {}).get("stops") or ())
    lex, selector, sentences = lexed_command(command, world, stops)
    statements: list[dict] = []
    rules: list[dict] = []
    memory: dict = {}
    set_aside: list[str] = []
    unread: list[str] = []  # words a candidate reading left out (salvage mode only)
    observed: list[tuple[str, list[str]]] = []  # complaints with no count ("P has too many X")
    for index, lexed in enumerate(sentences):
        if not lexed.tokens:
            continue
        pick = picks.get(index) or {}
        if pick.get("trimmed") and lexed.trimmed is not None:
            set_aside += list(lexed.aside)
            lexed = lexed.trimmed
        if pick.get("drop"):
            lexed = without(lexed, pick["drop"])
            if not lexed.tokens:
                continue
        _not_too_long(lexed)
        salvage = (picks.get("*") or {}).get("salvage")
        try:
            if salvage and salvage != "sentence":
                reader, left_out = partial(lexed.trimmed or lexed, lex, selector, world, memory, pick, salvage)
                unread += left_out
                set_aside += list(lexed.aside) if lexed.trimmed is not None else []
            else:
                reader = _as_said(lexed, lex, selector, world, memory, pick)
        except (UnexpectedInput, TranslationError) as exc:
            # the sentence as said does not read; read again it may (_second_reading)
            error = failure(exc, lexed, lex) if isinstance(exc, UnexpectedInput) else exc
            error.sentence = index  # type: ignore[attr-defined]  # for the candidates (parse)
            _locate(error, lexed, lex)
            if salvage and salvage != "sentence":
                # the partial parse read the sentence without its talk already; in a command of
                # several sentences, the others' partial parses are offered without this one
                if len(sentences) > 1 and not isinstance(error, Choice):
                    unread.append(said(lexed))
                    continue
                raise error from None
            again = _second_reading(lexed, error, lex, selector, world, memory, pick,
                                    droppable=salvage == "sentence" and len(sentences) > 1)
            if again is None:
                # a candidate reading without this sentence (one that reads, with competing
                # meanings, is offered with each of them instead: never dropped)
                unread.append(said(lexed))
                continue
            reader, talk = again
            set_aside += talk
        if stops and not (reader.statements or reader.rules or reader.updates):
            # a stop put into a command said without them (runon) must end a sentence that asks for
            # something: "... from roll store too / cutting room" is no reading of a move
            raise TranslationError(f"'{said(lexed)}' asks for nothing by itself")
        for k, new in reader.updates.items():
            statements[k] = new
        _complaints(reader, observed)
        statements += reader.statements
        observed += reader.observed
        rules += reader.rules
        memory = {"statements": list(statements), "last": list(reader.statements) or memory.get("last", []),
                  "item": reader.last_item, "places": reader.last_places, "named": reader.named_places,
                  "received": reader.received | set(memory.get("received") or ()),
                  "observed": list(reader.observed),
                  "item_first": bool(lexed.tokens) and lexed.tokens[0].type in ("ITEM", "ITEMWORD")}
    if not statements and not rules:
        _nothing_asked(command, lex, observed)
    # "final" marks a count said place first while a source after it may still come; no part of the order
    statements = [{k: v for k, v in st.items() if k != "final"} for st in emptied_last(statements)]
    set_aside = lex.aside + set_aside
    return {"command": command, "statements": statements, "rules": rules,
            **({"corrected": list(lex.corrected)} if lex.corrected else {}),
            **({"set_aside": set_aside} if set_aside else {}), **({"unread": unread} if unread else {})}


def _locate(error: TranslationError, lexed: Lexed, lex: Lexicon) -> None:
    """Where the sentence that does not read stands among the command's recognised tokens
    (``span``, None where its words were made anew) and where its word that no rule places does
    (``at``; None where it ends before it reads): where a stop may be put (:mod:`runon`)."""
    first, last = (lex.position(lexed.source[0]), lex.position(lexed.source[-1])) if lexed.source else (None, None)
    k = getattr(error, "unplaced", None)
    error.span = (first, last + 1) if first is not None and last is not None else None  # type: ignore[attr-defined]
    error.at = lex.position(lexed.source[k]) if k is not None and k < len(lexed.source) else None  # type: ignore[attr-defined]


def _complaints(reader: SentenceReader, observed: list[tuple[str, list[str]]]) -> None:
    """The sentence's complaints ("P has too many X") with the command's before it, read with what
    follows them (:func:`_about_the_complaint`). "P too many X" said without a verb reaches the
    statements as a count with no count: it is the same complaint (it was refused as an order the
    schema rejects)."""
    for st in [st for st in reader.statements if (st.get("amount") or {}).get("observed")]:
        reader.statements.remove(st)
        reader.observed.append((st["words"], list(st["places"]["names"])))
    if observed or reader.observed:
        _about_the_complaint(reader, observed + reader.observed)


def _about_the_complaint(reader: SentenceReader, observed: list[tuple[str, list[str]]]) -> None:
    """After "P has too many X", a statement that does not name P ("move 2 to Q": from P, or from
    anywhere?) is refused: the complaint suggests P, the words do not say it, nothing is guessed.
    A statement that says where its units come from ("move the cement from the mezz to bay three,
    bay one is too full") guesses nothing."""
    words, places = observed[-1]
    for st in reader.statements:
        said = set((st.get("places") or {}).get("names") or []) | set((st.get("from") or {}).get("names") or [])
        if not said & set(places) and not (st.get("from") or {}).get("names"):
            raise TranslationError(f"{quote(st['words'])} after {quote(words)}: from there, or from "
                                   f"anywhere? say where the units come from")


def _not_too_long(lexed: Lexed) -> None:
    """A sentence of more than :data:`MAX_SENTENCE_WORDS` terminals is refused (Earley's time)."""
    if len(lexed.tokens) > MAX_SENTENCE_WORDS:
        shown = " ".join(t.text for t in lexed.source[:12])
        raise TranslationError(f"the sentence '{shown} ...' has {len(lexed.tokens)} words; sentences "
                               f"are read up to {MAX_SENTENCE_WORDS} words (end it with a full stop "
                               f"and go on in a new one)")


def _nothing_asked(command: str, lex: Lexicon, observed: list[tuple[str, list[str]]]) -> None:
    """A command with no goal and no rule is refused; a complaint alone says it gives no count."""
    if observed:
        raise TranslationError(f"{quote(observed[0][0])} asks for nothing by itself (it says no count): say "
                               f"how many there should be (e.g. 'no more than 3') or how many to take away")
    raise TranslationError(f"found no goal and no robot rule in '{command}' "
                           f"(shelves: {lex.index.candidates('shelf')}; "
                           f"products: {lex.index.candidates('product')})")


def emptied_last(statements: list[dict]) -> list[dict]:
    """ "Empty aisle 1. Everything on it goes to aisle 2.": what leaves an emptied place, said in a
    later sentence, goes first and the emptying after it (else the move would find the place
    already empty and move nothing: a misreading). The sentence reader does the same inside one
    sentence (:meth:`RuleScope.finish`). What the emptying leaves out, the move of everything on it
    leaves out too ("Empty the kaai except the pigment. Everything to the hoogbouw": the pigment
    stays; it was moved with the rest, a misreading)."""
    out = list(statements)
    for st in [s for s in statements if s["op"] == "empty"]:
        emptied = set(st["places"].get("names") or [])
        k = out.index(st)
        # only a move of all of it somewhere ("everything on it goes to P", "its X to P"): a count
        # taken after the emptying stays in its place (and is refused: nothing is left to take)
        later = [t for t in out[k + 1:] if t["op"] == "transfer" and t.get("to")
                 and {"all", "all_held"} & set(t.get("amount") or {})
                 and emptied & set((t.get("from") or {}).get("names") or [])]
        later = leaving_out_what_stays(st, later, out)
        if later:
            out.remove(st)
            out.insert(out.index(later[-1]) + 1, st)
    return out

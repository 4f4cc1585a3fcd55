"""Partial parses: a sentence that does not read, read again without the word no rule places,
its clause, or the word that opens the clause, while another still does not fit. They are only
ever offered as candidate readings (:mod:`candidates`), never acted on unchosen."""
from __future__ import annotations

from lark.exceptions import UnexpectedInput

from pipflow.errors import TranslationError
from pipflow.language.asides import ADJUNCTS
from pipflow.warehouse.language.forest import failure, without
from pipflow.warehouse.language.lexicon import Lexed, Lexicon
from pipflow.warehouse.language.readings import one_meaning
from pipflow.warehouse.language.robots import RobotSelector
from pipflow.warehouse.language.sentence import SentenceReader

SALVAGE = ("clause", "word", "tail", "lead", "sentence")


MAX_SALVAGED = 3


def salvage(lexed: Lexed, lex: Lexicon, selector: RobotSelector, world: dict, memory: dict,
             pick: dict, how: str) -> tuple[SentenceReader, list[str]]:
    """A candidate reading of a sentence that does not read: the word no rule places (``how`` =
    "word") or its clause ("clause") left out, again while another word cannot be placed, up to
    :data:`MAX_SALVAGED` times; returns the reading and the words left out (named in the
    candidate's echo). Only ever offered, never acted on unchosen."""
    unread: list[str] = []
    for _ in range(MAX_SALVAGED + 1):
        try:
            return one_meaning(lexed, lex, selector, world, memory, pick), unread
        except UnexpectedInput as exc:
            error = failure(exc, lexed, lex)
            if getattr(error, "unplaced", None) is None:
                # it ends before it says what to do: the last word is the one that does not fit
                error.unplaced, error.clause = len(lexed.tokens) - 1, [len(lexed.tokens) - 1]  # type: ignore[attr-defined]
        except TranslationError as exc:
            error = exc
        k = getattr(error, "unplaced", None)
        if k is None or len(unread) >= MAX_SALVAGED:
            raise error
        drop = dropped(how, k, list(error.clause), lexed)  # type: ignore[attr-defined]
        unread.append(" ".join(lexed.source[j].text for j in drop if j < len(lexed.source)
                               and lexed.tokens[j].type != ",").replace(" zzposs", "'s"))
        lexed = without(lexed, drop)
        if not lexed.tokens:
            raise error
    raise TranslationError("nothing left to read")


def dropped(how: str, k: int, clause: list[int], lexed: Lexed) -> list[int]:
    """The terminals a partial parse leaves out for the word at ``k`` that no rule places: the
    word ("word"), its clause ("clause"), or the word that opens its clause ("lead": what led the
    parser astray, as "could" in "could two more X go to P"; again while the next still does not
    read, up to :data:`MAX_SALVAGED`; the word itself when it opens its clause)."""
    if how == "word":
        return [k]
    if how == "tail":
        # the end of the clause from the word (or from the adjunct's opening word just before it:
        # "... in it before the coach turns up at eleven"), as if it were an adjunct
        marks = (",", ":")
        start = next((j for j in range(k, max(k - 4, clause[0]) - 1, -1)
                      if str(lexed.source[j].value) in ADJUNCTS), k) if k < len(lexed.source) else k
        return [j for j in clause if j >= start and str(lexed.tokens[j].value) not in marks]
    if how == "lead":
        opening = [j for j in clause if j < k and str(lexed.tokens[j].value) not in (",", ":")]
        return opening[:1] or [k]
    return clause

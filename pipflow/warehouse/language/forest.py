"""Earley over one sentence's terminals: the parser that keeps every reading, the forests of
recent sentences remembered, the budget of new parses a refusal's candidates may spend, and a
parse error said in words (the word no rule places, its clause).

Split out of :mod:`pipflow.warehouse.language.parser` (one job: driving lark); the reading of a
forest is :mod:`pipflow.warehouse.language.readings`.
"""
from __future__ import annotations

import functools
from collections import OrderedDict
from typing import Any

from lark import Lark, Token, Tree
from lark.common import ParserConf
from lark.exceptions import UnexpectedInput, UnexpectedToken
from lark.grammar import NonTerminal, Rule
from lark.parsers.grammar_analysis import GrammarAnalyzer

from pipflow.errors import TranslationError
from pipflow.language.earley import ListLexer, earley_parser
from pipflow.language.lookahead import with_lookahead
from pipflow.language.optionals import nullable_optionals
from pipflow.language.spelling import normalize
from pipflow.warehouse.language.grammar import GRAMMAR
from pipflow.warehouse.language.lexicon import Lexed, Lexicon


@functools.lru_cache(maxsize=1)
def all_readings_parser() -> Lark:
    """Earley over the command grammar, keeping every reading (``_ambig`` nodes) so that they
    can be checked to agree. Built once per process (about a second: the one parser a run
    builds; cached on disk by :mod:`pipflow.language.earley`), predicting with one terminal of
    lookahead (:mod:`pipflow.language.lookahead`: the same forests, about a sixth of the time)."""
    return with_lookahead(earley_parser(nullable_optionals(GRAMMAR), lexer=ListLexer, keep_all_tokens=True,
                                        ambiguity="explicit"))


@functools.lru_cache(maxsize=1)
def sentence_edges() -> tuple[frozenset[str], frozenset[str]]:
    """The terminals a sentence may open with and those it may end with (lark's FIRST sets of the
    grammar and of the grammar read backwards): where a stop may stand (:mod:`runon`)."""
    parser = all_readings_parser()
    start = NonTerminal(parser.options.start[0])
    backwards = [Rule(r.origin, list(reversed(r.expansion)), r.order, r.alias, r.options) for r in parser.rules]
    first, last = (GrammarAnalyzer(ParserConf(rules, None, parser.options.start)).FIRST[start]
                   for rules in (parser.rules, backwards))
    return frozenset(t.name for t in first), frozenset(t.name for t in last)


@functools.lru_cache(maxsize=1)
def keywords() -> dict[str, str]:
    """Keyword text -> terminal name, from the grammar's anonymous terminals."""
    out = {}
    for t in all_readings_parser().terminals:
        if t.pattern.type == "str":
            out[t.pattern.value] = t.name
    return out


_FORESTS: "OrderedDict[tuple, tuple[bool, Any]]" = OrderedDict()
_FORESTS_KEPT = 256
#: new sentence parses one refusal may spend on its candidate readings (a parse of a sentence read
#: before is remembered and free): the candidates of a refused command cost at most this many
#: parses more than the refusal itself. With the lookahead predictor a parse costs a sixth of what
#: it did, so a refusal may try four partial parses of up to three words each (9 parses) and still
#: read faster than a344570 (benchmarks/parse_speed.py)
CANDIDATE_PARSES = 9
CANDIDATE_BUDGET: dict[str, int | None] = {"left": None}


def forest(tokens: list[Token]) -> Tree:
    """The Earley forest of a sentence's terminals (every reading), or the parse error it raised,
    remembered for the last :data:`_FORESTS_KEPT` sentences. Readers only read the forest (lark's
    Interpreter and CollapseAmbiguities build new trees), so one forest serves every reading."""
    key = tuple((t.type, repr(t.value)) for t in tokens)
    hit = _FORESTS.get(key)
    if hit is None:
        if CANDIDATE_BUDGET["left"] is not None:
            if CANDIDATE_BUDGET["left"] <= 0:
                raise TranslationError("no parse left for candidate readings")
            CANDIDATE_BUDGET["left"] -= 1
        try:
            hit = (True, all_readings_parser().parse(tokens))
        except UnexpectedInput as exc:
            hit = (False, exc)
        _FORESTS[key] = hit
        if len(_FORESTS) > _FORESTS_KEPT:
            _FORESTS.popitem(last=False)
    else:
        _FORESTS.move_to_end(key)
    if not hit[0]:
        raise hit[1]
    return hit[1]


def clause_of(lexed: Lexed, k: int) -> list[int]:
    """The terminals of the clause (between commas or colons) that holds terminal ``k``."""
    marks = {",", ":"}
    start = k
    while start > 0 and str(lexed.tokens[start - 1].value) not in marks:
        start -= 1
    end = k
    while end + 1 < len(lexed.tokens) and str(lexed.tokens[end + 1].value) not in marks:
        end += 1
    if end + 1 < len(lexed.tokens):
        end += 1  # its comma goes with it
    elif start > 0:
        start -= 1
    return list(range(start, end + 1))


def without(lexed: Lexed, drop: list[int]) -> Lexed:
    """The sentence with the terminals at ``drop`` left out (a candidate reading that does not
    read them; offered, never acted on unchosen)."""
    keep = [k for k in range(len(lexed.tokens)) if k not in set(drop)]
    tokens = [Token(lexed.tokens[k].type, lexed.tokens[k].value, start_pos=j) for j, k in enumerate(keep)]
    exact = frozenset(j for j, k in enumerate(keep) if k in lexed.exact)
    return Lexed(tokens, [lexed.source[k] for k in keep], exact)


def failure(exc: UnexpectedInput, lexed: Lexed, lex: Lexicon) -> TranslationError:
    """The parse error said in words (``unread``: no rule of the grammar reads the sentence, as
    opposed to a sentence read and refused for what it means)."""
    error = _failure(exc, lexed, lex)
    error.unread = True  # type: ignore[attr-defined]
    return error


def _said_near(lexed: Lexed, k: int) -> str:
    """The word said where the reader's own word at ``k`` stands (one it put in, unsaid: the "from"
    of "rack A X 6 to P"), so that a refusal quotes the user's words."""
    after = [t.text for t in lexed.source[k + 1:] if t.text]
    before = [t.text for t in lexed.source[:k] if t.text]
    return (after or before[-1:] or [""])[0]


def _failure(exc: UnexpectedInput, lexed: Lexed, lex: Lexicon) -> TranslationError:
    sentence = " ".join(t.text for t in lexed.source if t.text).replace(" zzposs", "'s")
    where = ""
    if isinstance(exc, UnexpectedToken) and exc.token.type != "$END":
        k = exc.token.start_pos
        word = lexed.source[k].text.replace("zzposs", "'s") or _said_near(lexed, k)
        prev = lexed.source[k - 1] if k > 0 else None
        shared = lex.index.shared_parts.get(normalize(word)) if lexed.tokens[k].type == "UNKNOWN" else None
        if shared:
            # a word of several names ("white" of white_case and white_keg) names none alone
            error = TranslationError(f"'{word}' in '{sentence}' may be any of {', '.join(shared)}: "
                                     f"nothing is guessed, say which")
            error.unplaced, error.word = k, word  # type: ignore[attr-defined]
            error.clause = clause_of(lexed, k)  # type: ignore[attr-defined]
            return error
        if prev is not None and prev.kind == "num" and lexed.tokens[k].type == "UNKNOWN":
            error = TranslationError(f"'{prev.text} {word}': cannot tell which product this count is for "
                                     f"(candidates: {lex.index.candidates('product')})")
            error.unplaced, error.word = k, word  # type: ignore[attr-defined]
            error.clause = clause_of(lexed, k)  # type: ignore[attr-defined]
            return error
        where = f"cannot place '{word}' in '{sentence}'"
        error = TranslationError(f"{where}: the command is not understood, so nothing is guessed "
                                 f"(shelves: {lex.index.candidates('shelf')}; products: "
                                 f"{lex.index.candidates('product')}; robots: {lex.index.candidates('robot')}; "
                                 f"robot groups: {lex.group_names()})")
        error.unplaced, error.word = k, word  # type: ignore[attr-defined]
        error.clause = clause_of(lexed, k)  # type: ignore[attr-defined]
        return error
    else:
        kinds = [t.type for t in lexed.tokens]
        if "PLACE" not in kinds and "ITEM" in kinds and "ROBOT" not in kinds:
            first = kinds.index("ITEM")
            start = first - 1 if first > 0 and kinds[first - 1] == "NUM" else first
            shown = " ".join(t.text for t in lexed.source[start:first + 1])
            return TranslationError(f"'{shown}': the command does not say which shelf "
                                    f"(candidates: {lex.index.candidates('shelf')})")
        where = f"'{sentence}' ends before it says what to do"
    return TranslationError(f"{where}: the command is not understood, so nothing is guessed "
                            f"(shelves: {lex.index.candidates('shelf')}; products: "
                            f"{lex.index.candidates('product')}; robots: {lex.index.candidates('robot')}; "
                            f"robot groups: {lex.group_names()})")


def said(lexed: Lexed) -> str:
    """A sentence's words as the user wrote them (for an echo)."""
    return " ".join(t.text for t in lexed.source if t.text).replace(" zzposs", "'s")

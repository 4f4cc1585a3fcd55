"""One token of lookahead for lark's Earley predictor: the same parses, a fraction of the work.

Why: lark's Earley parser predicts, at every position, every rule that the expected
non-terminals can begin with (its precomputed prediction closure), whatever the next word is. In
a command grammar of about 2,300 rules most of those predictions are dead on arrival: a rule
that must begin with a place name is predicted before a verb, and then carried, completed and
compared in every column. The parser's whole input is known before it starts (the lexicon hands
it a list of terminals), so the next terminal is known at each prediction.

:func:`with_lookahead` makes a built parser predict, at position ``i``, only the rules that can
derive a string beginning with the terminal at ``i`` (by lark's own FIRST and NULLABLE sets),
and the rules that derive the empty string (they complete in place, and what follows them is
predicted again where it is needed). At the end of the input only the latter. Nothing else of
lark's algorithm changes: a rule left out could never have matched the next terminal, so it could
never have completed or contributed a node, and the forest (every reading, ``_ambig`` nodes
included) and the errors (the same token, the same position) are the same as without the filter
(``tests/test_lookahead.py`` checks that on warehouse and household command sets). On the
warehouse command sets the Earley parse takes about a sixth of the time
(``benchmarks/parse_speed.py``); both domains' readers use it.

A parse that fails is remembered by the terminals it read up to and including the one it failed
on (:class:`_DeadPrefixes`): the Earley sets up to a position depend on the terminals up to it
and on nothing after it (the predictor here looks at the terminal at its own position, never
further), so any later input that begins with those terminals fails on the same terminal with the
same expected terminals, and is refused at once without parsing. The candidate readings of a
refused command try many wordings that keep the words up to where it stopped: in the household
sets about six failures in ten are such repeats. Only the error's ``token``, position, ``expected``
and ``state`` are given again (``considered_rules`` would keep the failed parse's items alive; no
caller reads it). Unexpected ends of input depend on the whole input and are not remembered.

The filter works through the one attribute lark's predictor reads (``predictions``) and the one
method it calls per position (``predict_and_complete``); the terminals of the parse in progress
are kept per thread, so one parser serves parallel steps. Only parsers whose lexer hands over a
finished list of terminals (:class:`pipflow.language.earley.ListLexer`) may use it.
"""
from __future__ import annotations

import threading
from typing import Any

from lark import Lark
from lark.exceptions import UnexpectedToken
from lark.parsers import earley

#: failed prefixes kept per parser (about 60 bytes a terminal); all are forgotten when full
DEAD_PREFIXES_KEPT = 4096


class _Predictions:
    """What lark's predictor sees as ``predictions``: the rules of a non-terminal's prediction
    closure that can start with the next terminal of the parse in progress (all of them when no
    parse is in progress)."""

    def __init__(self, parser: "LookaheadEarley", every: dict):
        self._parser = parser
        self._every = every
        self._kept: dict[tuple[Any, str | None], list] = {}

    def __getitem__(self, symbol: Any) -> list:
        state = self._parser._lookahead
        types = getattr(state, "types", None)
        if types is None:
            return self._every[symbol]
        i = state.i
        following = types[i] if i < len(types) else None
        key = (symbol, following)
        kept = self._kept.get(key)
        if kept is None:
            kept = self._kept[key] = [rule for rule in self._every[symbol]
                                      if _can_begin(self._parser, rule, following)]
        return kept

    def __contains__(self, symbol: Any) -> bool:
        return symbol in self._every


def _can_begin(parser: earley.Parser, rule: Any, terminal: str | None) -> bool:
    """Whether ``rule`` derives a string that begins with ``terminal`` (None: the end of the
    input), or derives the empty string (it completes where it is predicted)."""
    for symbol in rule.expansion:
        if symbol.is_term:
            return symbol.name == terminal
        if terminal is not None and any(t.name == terminal for t in parser.FIRST.get(symbol, ())):
            return True
        if symbol not in parser.NULLABLE:
            return False
    return True


class _DeadPrefixes:
    """Terminal sequences known to fail, each with what its error said (see the module)."""

    def __init__(self) -> None:
        self._errors: dict[tuple, tuple[int, Any, Any]] = {}   # (start, *types[:k + 1]) -> (k, expected, state)
        self._lengths: set[int] = set()
        self._lock = threading.Lock()

    def error_for(self, start: Any, tokens: list) -> UnexpectedToken | None:
        """The error a parse of ``tokens`` would end in, if a remembered prefix begins them."""
        types = tuple(token.type for token in tokens)
        with self._lock:
            lengths = sorted(self._lengths)
        for length in lengths:
            if length > len(types):
                break
            known = self._errors.get((start, *types[:length]))
            if known is not None:
                k, expected, state = known
                return UnexpectedToken(tokens[k], set(expected), state=state)
        return None

    def remember(self, start: Any, tokens: list, error: UnexpectedToken) -> None:
        """Keep the prefix up to the terminal ``error`` failed on (one of ``tokens``)."""
        k = next((i for i, token in enumerate(tokens) if token is error.token), None)
        if k is None:
            return
        with self._lock:
            if len(self._errors) >= DEAD_PREFIXES_KEPT:
                self._errors.clear()
                self._lengths.clear()
            self._errors[(start, *(token.type for token in tokens[:k + 1]))] = (k, frozenset(error.expected), error.state)
            self._lengths.add(k + 1)


class LookaheadEarley(earley.Parser):
    """lark's Earley parser whose predictor looks at the next terminal, and which refuses at once
    an input that begins like one that failed (see the module)."""

    _lookahead: threading.local
    _dead: _DeadPrefixes

    def parse(self, lexer: Any, start: Any) -> Any:  # noqa: D102 - lark's own signature
        tokens = list(lexer.lex(None))
        known = self._dead.error_for(start, tokens)
        if known is not None:
            raise known
        state = self._lookahead
        outer = (getattr(state, "types", None), getattr(state, "i", 0))
        state.types, state.i = [token.type for token in tokens], 0
        try:
            return super().parse(lexer, start)
        except UnexpectedToken as error:
            self._dead.remember(start, tokens, error)
            raise
        finally:
            state.types, state.i = outer

    def predict_and_complete(self, i, *rest):  # type: ignore[no-untyped-def]
        # lark 1.3 passes a node cache that 1.2 does not: whatever follows the position goes on as given
        self._lookahead.i = i
        return super().predict_and_complete(i, *rest)


def with_lookahead(parser: Lark) -> Lark:
    """``parser`` (a built Earley :class:`~lark.Lark` over a list lexer) with the lookahead
    predictor; idempotent. The object is changed in place (lark offers no constructor argument
    for it): call it on a parser after it has been stored in the disk cache."""
    inner = parser.parser.parser
    if isinstance(inner, LookaheadEarley):
        return parser
    if type(inner) is not earley.Parser:
        raise TypeError(f"lookahead needs lark's plain Earley parser, not {type(inner).__name__}")
    every = inner.predictions
    inner.__class__ = LookaheadEarley
    inner._lookahead = threading.local()
    inner._dead = _DeadPrefixes()
    inner.predictions = _Predictions(inner, every)
    return parser

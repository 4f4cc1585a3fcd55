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

The filter works through the one attribute lark's predictor reads (``predictions``) and the one
method it calls per position (``predict_and_complete``); the terminals of the parse in progress
are kept per thread, so one parser serves parallel steps. Only parsers whose lexer hands over a
finished list of terminals (:class:`pipflow.language.earley.ListLexer`) may use it.
"""
from __future__ import annotations

import threading
from typing import Any

from lark import Lark
from lark.parsers import earley


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


class LookaheadEarley(earley.Parser):
    """lark's Earley parser whose predictor looks at the next terminal (see the module)."""

    _lookahead: threading.local

    def parse(self, lexer: Any, start: Any) -> Any:  # noqa: D102 - lark's own signature
        state = self._lookahead
        outer = (getattr(state, "types", None), getattr(state, "i", 0))
        state.types, state.i = [token.type for token in lexer.lex(None)], 0
        try:
            return super().parse(lexer, start)
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
    inner.predictions = _Predictions(inner, every)
    return parser

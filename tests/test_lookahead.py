"""The lookahead predictor (pipflow.language.lookahead) changes the work, never the parse: the
same forest (every reading) and the same error (token and position) as lark's own Earley parser,
on a small grammar exhaustively and on the warehouse command sets' sentences."""
from __future__ import annotations

import itertools
from pathlib import Path

import pytest
from lark import Lark, Token
from lark.exceptions import UnexpectedInput

from pipflow.language.earley import ListLexer
from pipflow.language.lookahead import LookaheadEarley, with_lookahead
from pipflow.language.optionals import nullable_optionals
from pipflow.warehouse.language.grammar import GRAMMAR
from pipflow.warehouse.language.lexicon import Lexicon
from pipflow.warehouse.language.forest import all_readings_parser as _all_readings_parser, keywords
from pipflow.warehouse.world import load_tasks

ROOT = Path(__file__).resolve().parent.parent

#: ambiguous (two ways to attach "c"), with empty rules at the start, middle and end, and a rule
#: whose first symbol is nullable: the cases where a filter on the next terminal could go wrong
SMALL = r"""
start: s
s: pre x post | s C | x x
x: A | A y | y B | x C x
y: B? C? | A
pre: | D
post: | D | D D
%declare A B C D
"""


def _parser(grammar: str) -> Lark:
    return Lark(grammar, parser="earley", lexer=ListLexer, keep_all_tokens=True, ambiguity="explicit")


def _outcome(parser: Lark, types: tuple[str, ...]) -> str:
    tokens = [Token(t, t.lower(), start_pos=k) for k, t in enumerate(types)]
    try:
        return str(parser.parse(tokens))
    except UnexpectedInput as exc:
        token = getattr(exc, "token", None)
        return f"{type(exc).__name__} at {getattr(token, 'start_pos', None)}"


def test_every_short_input_parses_the_same_with_lookahead():
    plain, ahead = _parser(SMALL), with_lookahead(_parser(SMALL))
    assert isinstance(ahead.parser.parser, LookaheadEarley)
    parsed = 0
    for n in range(0, 6):
        for types in itertools.product("ABCD", repeat=n):
            want = _outcome(plain, types)
            assert _outcome(ahead, types) == want, types
            parsed += not want.startswith("Unexpected")
    assert parsed > 100  # the grammar accepts many of them (ambiguously): the comparison is not vacuous


def _error(parser: Lark, types: tuple[str, ...]) -> tuple | None:
    """What a failed parse says (its class, the position and the text of its token, the expected
    terminals), or None when it parses."""
    tokens = [Token(t, f"{t.lower()}{k}", start_pos=k) for k, t in enumerate(types)]
    try:
        parser.parse(tokens)
    except UnexpectedInput as exc:
        token = getattr(exc, "token", None)
        return (type(exc).__name__, getattr(token, "start_pos", None), str(token),
                sorted(getattr(exc, "expected", None) or ()))
    return None


class _Forgetful:
    """A memory of failures that remembers nothing: the lookahead parser as it was before it."""

    def error_for(self, start, tokens):
        return None

    def remember(self, start, tokens, error):
        pass


def test_an_input_that_begins_like_a_failed_one_fails_alike_without_parsing(monkeypatch):
    plain, ahead = with_lookahead(_parser(SMALL)), with_lookahead(_parser(SMALL))
    plain.parser.parser._dead = _Forgetful()
    inputs = [types for n in range(1, 6) for types in itertools.product("ABCD", repeat=n)]
    # the longer inputs first, then again the other way round: each failure is met both before
    # and after the failures that share its beginning
    for types in sorted(inputs, key=len, reverse=True) + inputs:
        assert _error(ahead, types) == _error(plain, types), types
    dead = ahead.parser.parser._dead
    assert dead._errors, "no failure was remembered"
    # a remembered beginning is answered without running lark's parser at all
    failing = next(types for types in inputs if (_error(plain, types) or ("",))[0] == "UnexpectedToken")
    longer = failing + ("A", "B")
    want = _error(plain, longer)
    monkeypatch.setattr(LookaheadEarley.__mro__[1], "parse", lambda *a, **k: pytest.fail("parsed again"))
    assert _error(ahead, longer) == want
    assert want[1] < len(failing)


def test_with_lookahead_is_idempotent_and_filters_only_during_a_parse():
    parser = with_lookahead(_parser(SMALL))
    assert with_lookahead(parser) is parser
    inner = parser.parser.parser
    # outside a parse the predictor's table is lark's own, every rule of each closure
    plain = _parser(SMALL).parser.parser
    for symbol, rules in plain.predictions.items():
        assert [str(r) for r in inner.predictions[symbol]] == [str(r) for r in rules]
    assert _outcome(parser, ("A", "C", "A")) == _outcome(_parser(SMALL), ("A", "C", "A"))


@pytest.mark.parametrize("name", ["warehouse-foodbank.yaml", "warehouse-props.yaml", "warehouse-racks.yaml"])
def test_command_sentences_parse_the_same_with_lookahead(name):
    plain = _parser(nullable_optionals(GRAMMAR))
    ahead = _all_readings_parser()
    assert isinstance(ahead.parser.parser, LookaheadEarley)
    loaded = load_tasks(ROOT / "benchmarks" / "language" / name)
    lex = Lexicon(loaded["world"], keywords())
    compared = 0
    for task in loaded["tasks"][::3]:
        try:
            sentences = lex.sentences(str(task["command"]))
        except Exception:  # noqa: BLE001 - refused by the lexicon: nothing reaches the parser
            continue
        for lexed in sentences:
            if not lexed.tokens:
                continue
            types = [(t.type, t.value) for t in lexed.tokens]
            outcomes = []
            for parser in (plain, ahead):
                tokens = [Token(t, v, start_pos=k) for k, (t, v) in enumerate(types)]
                try:
                    outcomes.append(str(parser.parse(tokens)))
                except UnexpectedInput as exc:
                    outcomes.append(f"{type(exc).__name__} at {getattr(getattr(exc, 'token', None), 'start_pos', None)}")
            assert outcomes[0] == outcomes[1], types
            compared += 1
    assert compared >= 10


def _household_outcome(parser: Lark, tags: list) -> str:
    """A household parser's forest for the tags, or where it stopped."""
    from pipflow.household.language import parser as household

    try:
        return str(parser.parse(household._terminals(tags)))
    except UnexpectedInput as exc:
        return f"{type(exc).__name__} at {getattr(getattr(exc, 'token', None), 'start_pos', None)}"


@pytest.mark.parametrize("name", ["household-loft.yaml", "household-studenthouse.yaml", "household-bungalow.yaml"])
def test_household_commands_parse_the_same_with_lookahead(name):
    """The household reader's parsers predict with lookahead too: the same forests and errors as
    lark's plain parser over the same grammar, on a household set's commands."""
    from pipflow.household.language import parser as household
    from pipflow.household.language.grammar import grammar_text
    from pipflow.household.scoring import load_tasks as load_home_tasks

    loaded = load_home_tasks(ROOT / "benchmarks" / "language" / name)
    world = loaded["world"]
    ahead = household._parser_for(world)
    assert isinstance(ahead.parser.parser, LookaheadEarley)
    plain = Lark(nullable_optionals(grammar_text(household._dual_classes(world))), parser="earley", lexer=ListLexer, ambiguity="explicit")
    compared = 0
    for task in loaded["tasks"][::2]:
        try:
            tags = household.tag(str(task["command"]), world, [])
        except Exception:  # noqa: BLE001 - refused by the tagger: nothing reaches the parser
            continue
        assert _household_outcome(plain, tags) == _household_outcome(ahead, tags), task["command"]
        compared += 1
    assert compared >= 10

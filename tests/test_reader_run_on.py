"""Orders said as people dictate or type fast, without commas (issue 23's tenth round): a
statement run on after the order ("... theyre sticking out", "... hes got a flat tyre"), a closing
word ("... please mate", "... forklifts only mind"), a discourse word opening it ("right the bay
should have ..."), a rule closing it ("... forklifts only"). Each is set aside or read as said with
the comma; anything that carries content still sinks the command."""
from __future__ import annotations

import pytest

from pipflow.errors import TranslationError
from pipflow.language.asides import trailing_thanks, unmarked_statement
from pipflow.warehouse.language.translator import translate, understand

#: a timber yard, a world no benchmark uses
YARD = {
    "name": "timberyard",
    "floor": {"width": 30, "height": 20},
    "shelves": {
        "long_rack": {"x": 2, "y": 14, "width": 6, "depth": 2, "capacity": 20, "access": [5, 13]},
        "saw_bench": {"x": 12, "y": 14, "width": 4, "depth": 2, "capacity": 10, "access": [14, 13]},
        "loading_lane": {"x": 20, "y": 4, "width": 6, "depth": 2, "capacity": 16, "access": [23, 6]},
    },
    "products": {"plank": {"color": "brown"}, "batten": {"color": "yellow"}},
    "stock": {"long_rack": {"plank": 9, "batten": 4}, "saw_bench": {"plank": 1}, "loading_lane": {"batten": 2}},
    "robots": {
        "flint": {"kind": "forklift", "start": [1, 8], "skills": {"carry": 3}},
        "moss": {"kind": "forklift", "start": [5, 8], "skills": {"carry": 2}},
        "wren": {"kind": "amr", "start": [9, 8], "skills": {"carry": 1}},
    },
}

MOVE_TWO = {"long_rack": {"plank": 7}, "saw_bench": {"plank": 3}}


@pytest.mark.parametrize("tail", ["theyre sticking out into the aisle", "its starting to sag",
                                  "his forks are playing up", "theres customers about",
                                  "lads are relaying concrete under there this afternoon",
                                  "the lads are waiting"])
def test_a_statement_run_on_without_a_comma_is_set_aside_and_said(tail: str) -> None:
    got = understand(f"move 2 planks from the long rack to the saw bench {tail}", YARD)
    assert got["goal"] == MOVE_TWO and got["constraints"] == []
    assert got["order"]["set_aside"] == [tail]


def test_a_run_on_statement_never_takes_a_rule_with_it() -> None:
    """"dont use flint hes got a flat tyre": the rule stays, the reason goes; "flat" is no misspelt
    flint (two edits on a four-letter word)."""
    got = translate("move 2 planks from the long rack to the saw bench and dont use flint hes got a flat tyre", YARD)
    assert got["goal"] == MOVE_TWO
    assert [r["never"] for r in got["constraints"]] == [["flint"]]


@pytest.mark.parametrize("command", [
    "move 2 planks from the long rack to the saw bench theyre only on the loading lane",   # operative
    "move 2 planks from the long rack to the saw bench theyre 4 short",                    # a number
    "move 2 planks from the long rack to the saw bench theyre for the loading lane",       # a name
])
def test_a_run_on_clause_that_carries_content_still_sinks_the_command(command: str) -> None:
    with pytest.raises(TranslationError):
        translate(command, YARD)


def test_unmarked_statement_needs_two_words_of_order_before_it() -> None:
    names = lambda w: False  # noqa: E731
    assert unmarked_statement("move it hes tired".split(), names) == 2
    assert unmarked_statement("hes tired".split(), names) == 0
    assert unmarked_statement("put it there".split(), names) == 0   # "it" opens no statement here


@pytest.mark.parametrize("command", [
    "move 2 planks from the long rack to the saw bench please mate",
    "move 2 planks from the long rack to the saw bench cheers lads",
    "right move 2 planks from the long rack to the saw bench",
    "ok move 2 planks from the long rack to the saw bench thank you",
])
def test_a_closing_word_or_an_opening_discourse_word_is_no_content(command: str) -> None:
    assert translate(command, YARD)["goal"] == MOVE_TWO


def test_never_mind_at_the_end_is_not_talk() -> None:
    """Only "mind" closes an order; "never" is operative, so "..., never mind" sinks it."""
    assert trailing_thanks("move it never mind".split(), lambda w: False) == 1
    with pytest.raises(TranslationError):
        translate("move 2 planks from the long rack to the saw bench never mind", YARD)


def test_a_rule_closing_the_sentence_without_a_comma_holds_for_the_whole_command() -> None:
    for command in ("move 2 planks from the long rack to the saw bench forklifts only mind",
                    "move 2 planks from the long rack to the saw bench, forklifts only"):
        got = translate(command, YARD)
        assert got["goal"] == MOVE_TWO
        assert got["constraints"] == [{"only": ["flint", "moss"]}], command


@pytest.mark.parametrize("command, goal", [
    ("move all the battens onto the saw bench except whats on the loading lane",
     {"saw_bench": {"batten": 4}, "long_rack": {"batten": 0}, "loading_lane": {"batten": 2}}),
    ("give the saw bench as many planks as the long rack's got now", {"saw_bench": {"plank": 9}}),
    ("every location in the yard wants at least 1 batten",
     {"long_rack": {"batten": {"at_least": 1}}, "saw_bench": {"batten": {"at_least": 1}},
      "loading_lane": {"batten": {"at_least": 1}}}),
])
def test_phrases_typed_or_said_loosely(command: str, goal: dict) -> None:
    assert translate(command, YARD)["goal"] == goal


def test_a_greeting_that_opens_with_a_kind_word_and_a_time_said_in_a_statement() -> None:
    """"Good" is a kind word of products ("goods"), and "before" orders things elsewhere; "Good
    morning team!" is a greeting and "the truck is coming before lunch" says when."""
    got = understand("Good morning team! move 2 planks from the long rack to the saw bench, "
                     "the truck is coming before lunch", YARD)
    assert got["goal"] == MOVE_TWO
    assert got["order"]["set_aside"] == ["Good morning team", "the truck is coming before lunch"]


def test_before_a_move_in_a_statement_is_still_operative() -> None:
    with pytest.raises(TranslationError):
        translate("move 2 planks from the long rack to the saw bench, the truck is coming before you move them", YARD)

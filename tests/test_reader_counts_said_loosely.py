"""Counts as people say them in passing (issue 23's tenth round): a time of day is no count ("for
the 2 o'clock wagon", "by 3pm"), "3 lots of 5" is 15, a count taken back without a comma ("move 5
no sorry 6"), and "P needs N X" where P already holds some is asked, as "put N" is (it says N in
all as often as N more: benchmarks/language/README.md, conventions of the gold, 2)."""
from __future__ import annotations

import pytest

from pipflow.errors import TranslationError
from pipflow.language.numbers import read_number
from pipflow.warehouse.language.translator import translate
from tests.test_reader_run_on import YARD

# YARD stock: long_rack {plank 9, batten 4}, saw_bench {plank 1}, loading_lane {batten 2}


@pytest.mark.parametrize("tail", ["for the 2 o'clock wagon", "for the 2oclock wagon", "by 3pm", "for the 10am pickup"])
def test_a_time_of_day_is_no_count(tail: str) -> None:
    got = translate(f"move 2 planks from the long rack to the saw bench {tail}", YARD)
    assert got["goal"] == {"long_rack": {"plank": 7}, "saw_bench": {"plank": 3}}


def test_a_count_in_a_trailing_reason_still_sinks_the_command() -> None:
    with pytest.raises(TranslationError):
        translate("move 2 planks from the long rack to the saw bench for the 2 wagons", YARD)


@pytest.mark.parametrize("words, value", [("3 lots of 5 planks", 15), ("two batches of six planks", 12),
                                          ("3 sets of 2 planks", 6), ("3 lots of planks", 3)])
def test_groups_of_a_count_multiply(words: str, value: int) -> None:
    assert read_number(words.split(), 0)[0] == value


def test_groups_of_a_count_in_a_command() -> None:
    assert translate("get the long rack up to 3 lots of 2 battens", YARD)["goal"] == {"long_rack": {"batten": 6}}


@pytest.mark.parametrize("command", ["move 5 no sorry 3 planks from the long rack to the saw bench",
                                     "move 5 sorry 3 planks from the long rack to the saw bench",
                                     "move 5 no wait 3 planks from the long rack to the saw bench",
                                     # aloud, as dictated (twelfth round): "no" before a count in
                                     # words, or before a restatement
                                     "move five no three planks from the long rack to the saw bench",
                                     "move 5 no make that 3 planks from the long rack to the saw bench",
                                     "move five no i mean three planks from the long rack to the saw bench"])
def test_a_count_taken_back_without_a_comma_is_the_second(command: str) -> None:
    assert translate(command, YARD)["goal"] == {"long_rack": {"plank": 6}, "saw_bench": {"plank": 4}}


def test_a_bare_no_between_two_counts_in_digits_is_no_taking_back() -> None:
    """Written, "no" before digits may abbreviate "number" ("No. 3")."""
    with pytest.raises(TranslationError):
        translate("move 5 no 3 planks from the long rack to the saw bench", YARD)


def test_needs_n_where_the_place_holds_some_is_asked_with_both_readings() -> None:
    with pytest.raises(TranslationError) as err:
        translate("the saw bench needs 4 planks", YARD)
    goals = [c["goal"] for c in err.value.candidates]
    assert {"saw_bench": {"plank": 4}} in goals and {"saw_bench": {"plank": 5}} in goals


@pytest.mark.parametrize("command, goal", [
    ("the saw bench needs 4 battens", {"saw_bench": {"batten": 4}}),          # holds none: the same either way
    ("the saw bench needs 4 planks in total", {"saw_bench": {"plank": 4}}),   # said in all
    ("the saw bench should have 4 planks", {"saw_bench": {"plank": 4}}),
])
def test_needs_n_is_read_where_it_can_mean_one_thing(command: str, goal: dict) -> None:
    assert translate(command, YARD)["goal"] == goal

"""Issue 23, warehouse: a numbered place's sibling said by its number alone ("between dock 1 and
2", "empty bay 3 and 4") is that place, where the world has it and the number ends the clause;
before anything else the number stays a count. Worlds of our own."""
from __future__ import annotations

import pytest

from pipflow.errors import PipflowError
from pipflow.warehouse.language.translator import understand

WORLD = {
    "shelves": {"pen1": {"x": 0, "y": 0, "capacity": 30}, "pen2": {"x": 5, "y": 0, "capacity": 30},
                "pen3": {"x": 10, "y": 0, "capacity": 30}, "loft": {"x": 0, "y": 8, "capacity": 30}},
    "products": {"hay_bale": {}, "feed_sack": {}},
    "stock": {"loft": {"hay_bale": 8, "feed_sack": 4}, "pen1": {"hay_bale": 1}, "pen2": {"feed_sack": 2},
              "pen3": {"hay_bale": 2}},
    "robots": {"r1": {"start": [0, 4], "skills": {"carry": 2}}, "r2": {"start": [5, 4], "skills": {"carry": 2}}},
}


def test_between_a_numbered_place_and_a_number_is_its_sibling() -> None:
    got = understand("Split the 8 hay bales on the loft evenly between pen 1 and 3", WORLD)
    assert got["goal"] == {"loft": {"hay_bale": 0}, "pen1": {"hay_bale": 5}, "pen3": {"hay_bale": 6}}


def test_a_numbered_place_and_a_number_ending_the_clause() -> None:
    got = understand("Empty pen 1 and 3.", WORLD)
    assert got["goal"] == {"pen1": {"hay_bale": 0, "feed_sack": 0}, "pen3": {"hay_bale": 0, "feed_sack": 0}}


def test_a_number_before_more_words_stays_a_count() -> None:
    # "and 2 to pen 2" is a count of 2 going to pen2, never pen2 itself
    try:
        got = understand("Move 3 hay bales from the loft to pen 1 and 2 to pen 2", WORLD)
    except PipflowError:
        return
    assert got["goal"].get("pen2", {}).get("hay_bale") == 2


def test_a_number_with_no_such_sibling_is_not_a_place() -> None:
    with pytest.raises(PipflowError):
        understand("Empty pen 1 and 7.", WORLD)

"""Issue 23, from pair PP's warehouse set (the leading hand of a building-supplies yard in Brisbane,
texting the robots from the floor): "P wants to end up with N X", "we need to move ...", "I'd
like to move ...", "Anyway ..." opening a sentence, "b4" for before, "N X, P to Q" as a ticket
says a transfer, and Scots words read by both readers. In a world of our own (a garden centre),
through the real reader."""
from __future__ import annotations

import pytest

from pipflow.errors import TranslationError
from pipflow.warehouse.language.translator import understand

CENTRE = {
    "name": "gardencentre",
    "floor": {"width": 30, "height": 20},
    "shelves": {
        "polytunnel": {"x": 2, "y": 14, "width": 4, "depth": 2, "capacity": 30, "access": [4, 13]},
        "yard": {"x": 10, "y": 14, "width": 4, "depth": 2, "capacity": 30, "access": [12, 13]},
        "tills": {"x": 20, "y": 14, "width": 4, "depth": 2, "capacity": 20, "access": [22, 13]},
    },
    "products": {"compost": {"color": "brown"}, "bark": {"color": "tan"}, "gravel": {"color": "gray"}},
    "stock": {"polytunnel": {"compost": 8, "bark": 2}, "yard": {"compost": 4, "gravel": 9}, "tills": {"bark": 1}},
    "robots": {"mule": {"kind": "tugger", "start": [1, 8], "skills": {"carry": 4}},
               "ant": {"kind": "amr", "start": [15, 8], "skills": {"carry": 1}}},
}
MOVE = {"polytunnel": {"compost": 5}, "tills": {"compost": 3}}


def _goal(said: str) -> dict:
    return understand(said, CENTRE)["goal"]


@pytest.mark.parametrize("said", ["the tills wants to end up with 3 bark", "tills want to end up with 3 of bark"])
def test_wants_to_end_up_with_sets_the_count(said: str) -> None:
    assert _goal(said) == {"tills": {"bark": 3}}


@pytest.mark.parametrize("said", [
    "we need to move 3 compost from the polytunnel to the tills",
    "I want to move 3 compost from the polytunnel to the tills",
    "I'd like to move 3 compost from the polytunnel to the tills",
    "Anyway move 3 compost from the polytunnel to the tills",
    "3 compost, polytunnel to tills",
    "move 3 compost from the polytunnel to the tills b4 smoko",
    "move 3 compost fae the polytunnel tae the tills",
])
def test_a_move_said_as_the_yard_texts_it(said: str) -> None:
    assert _goal(said) == MOVE


def test_b4_says_when_and_is_never_a_name_or_a_count() -> None:
    """ "b4" is before: a time after it orders nothing; it is no count of 4."""
    got = understand("take 2 gravel off the yard b4 the storm", CENTRE)
    assert got["goal"] == {"yard": {"gravel": 7}}


def test_we_need_to_does_not_make_a_remark_an_order() -> None:
    with pytest.raises(TranslationError):
        understand("we need to talk about the yard", CENTRE)


def test_an_unknown_word_before_a_one_word_name_is_offered_without_it_never_read() -> None:
    """ "the front tills" where the world's only tills are "tills": offered as the tills, asked."""
    with pytest.raises(TranslationError) as caught:
        understand("move 1 bark from the polytunnel to the front tills", CENTRE)
    offered = caught.value.candidates
    assert offered[0]["goal"] == {"polytunnel": {"bark": 1}, "tills": {"bark": 2}}
    assert "read 'front tills' as 'tills'" in offered[0]["reading"]

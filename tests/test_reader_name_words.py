"""Names said the way staff shorten them, found in held-out pair E: what a container product of
three words holds ("4 of bird seed" for bird_seed_bag), and a place whose one word is also a verb
of the grammar ("from return to the front till" for return_bay) where a place stands. Either is
refused where two names share the words."""
from __future__ import annotations

import pytest

from pipflow.errors import TranslationError
from pipflow.warehouse.language.translator import translate

GARDEN = {
    "name": "garden-centre",
    "floor": {"width": 30, "height": 20},
    "shelves": {
        "potting_shed": {"x": 2, "y": 14, "width": 4, "depth": 2, "capacity": 12, "access": [4, 13]},
        "return_bay": {"x": 10, "y": 14, "width": 4, "depth": 2, "capacity": 12, "access": [12, 13]},
        "front_till": {"x": 20, "y": 14, "width": 6, "depth": 2, "capacity": 10, "access": [23, 13]},
    },
    "products": {"bird_seed_bag": {"color": "yellow"}, "lawn_feed_box": {"color": "green"},
                 "trowel": {"color": "gray"}, "seed_tray": {"color": "black"}},
    "stock": {"potting_shed": {"bird_seed_bag": 4, "lawn_feed_box": 2, "seed_tray": 3}, "return_bay": {"trowel": 3, "bird_seed_bag": 1},
              "front_till": {"lawn_feed_box": 1}},
    "robots": {"mule": {"kind": "forklift", "start": [1, 8], "skills": {"carry": 3}},
               "wren": {"kind": "amr", "start": [15, 8], "skills": {"carry": 1}}},
}


@pytest.mark.parametrize("command, goal", [
    ("The front till should have 2 of bird seed", {"front_till": {"bird_seed_bag": 2}}),
    ("move 2 lawn feed from the potting shed to the front till",
     {"potting_shed": {"lawn_feed_box": 0}, "front_till": {"lawn_feed_box": 3}}),
])
def test_what_a_container_product_holds_names_it(command: str, goal: dict) -> None:
    assert translate(command, GARDEN)["goal"] == goal


def test_what_two_container_products_hold_alike_names_neither() -> None:
    both = {**GARDEN, "products": {**GARDEN["products"], "bird_seed_tin": {"color": "red"}}}
    with pytest.raises(TranslationError):
        translate("The front till should have 2 of bird seed", both)


@pytest.mark.parametrize("command, goal", [
    ("Move 2 trowels from return to the front till", {"return_bay": {"trowel": 1}, "front_till": {"trowel": 2}}),
    ("Take 1 trowel off return.", {"return_bay": {"trowel": 2}}),
    ("send 1 lawn feed box off the potting shed to return", {"potting_shed": {"lawn_feed_box": 1},
                                                             "return_bay": {"lawn_feed_box": 1}}),
])
def test_a_place_by_a_word_that_is_also_a_verb_where_a_place_stands(command: str, goal: dict) -> None:
    assert translate(command, GARDEN)["goal"] == goal


@pytest.mark.parametrize("command, goal", [
    ("Return should have 2 trowels", {"return_bay": {"trowel": 2}}),
    ("The front till needs 2 trowels and return wants 1 more lawn feed box",
     {"front_till": {"trowel": 2}, "return_bay": {"lawn_feed_box": 1}}),
])
def test_a_place_by_a_verb_word_as_the_subject(command: str, goal: dict) -> None:
    assert translate(command, GARDEN)["goal"] == goal


def test_the_verb_before_a_count_stays_a_verb() -> None:
    assert translate("return 2 trowels to the potting shed", GARDEN)["goal"] == {"potting_shed": {"trowel": 2}}


def test_a_two_word_name_in_the_plural_with_two_letters_swapped() -> None:
    """"seed tarys": one edit (a swap) from the plural "trays", two from "tray"."""
    assert translate("Take 2 seed tarys off the potting shed", GARDEN)["goal"] == {"potting_shed": {"seed_tray": 1}}

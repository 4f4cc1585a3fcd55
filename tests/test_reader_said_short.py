"""Moves and counts said short, as a team leader types them between jobs (issue 23's eleventh
round): "out" for "out of", a move without "from", a count brought "down to" N without a verb,
and "the weakest one". Each was refused on a word; none may be read wider than it was said."""
from __future__ import annotations

import copy

import pytest

from pipflow.errors import TranslationError
from pipflow.warehouse.language.translator import translate, understand
from tests.tannery_world import TANNERY

# tannery stock: drying_loft {cart_wheel 6, belt_round 2}, vat_east {cart_wheel 1, dye_drum 4},
# vat_west {belt_round 5}, finishing_table {dye_drum 1}; carry: crane 4, mule1 2, mule2 2, flea 1

TWO_FROM_THE_LOFT = {"drying_loft": {"cart_wheel": 4}, "vat_west": {"cart_wheel": 2}}


@pytest.mark.parametrize("command", ["take 2 cart wheels out the drying loft and drop them at vat west",
                                     "2 cart wheels drying loft to vat west",
                                     "move 2 cart wheels drying loft to vat west"])
def test_a_move_said_without_from(command: str) -> None:
    assert translate(command, TANNERY)["goal"] == TWO_FROM_THE_LOFT


def test_moves_said_without_from_in_a_list() -> None:
    got = translate("2 cart wheels drying loft to vat west and 1 vat west to vat east", TANNERY)
    assert got["goal"] == {"drying_loft": {"cart_wheel": 4}, "vat_west": {"cart_wheel": 1}, "vat_east": {"cart_wheel": 2}}


def test_out_alone_still_needs_a_destination() -> None:
    with pytest.raises(TranslationError, match="where these go"):
        translate("2 cart wheels out the drying loft", TANNERY)


@pytest.mark.parametrize("command", ["belt rounds on vat west down to 2", "vat west belt rounds down to 2"])
def test_down_to_without_a_verb_sets_the_count(command: str) -> None:
    assert translate(command, TANNERY)["goal"] == {"vat_west": {"belt_round": 2}}


@pytest.mark.parametrize("command", ["belt rounds on vat west up to 2",   # "up to N" alone is a bound, not read here
                                     "belt rounds on vat west down 2"])   # down by 2, or to 2? not guessed
def test_up_to_and_down_without_to_are_not_read_as_a_count(command: str) -> None:
    with pytest.raises(TranslationError):
        translate(command, TANNERY)


def test_the_weakest_one_is_the_one_weakest_robot() -> None:
    got = translate("2 cart wheels from drying loft to vat west, leave the weakest one out of it", TANNERY)
    assert got["goal"] == TWO_FROM_THE_LOFT
    assert got["constraints"] == [{"never": ["flea"]}]
    assert translate("2 cart wheels from drying loft to vat west, only the strongest one", TANNERY)["constraints"][0]["only"] == ["crane"]


def test_the_weakest_one_where_three_tie_is_asked() -> None:
    tie = copy.deepcopy(TANNERY)
    tie["robots"]["flea"]["skills"]["carry"] = 2
    with pytest.raises(TranslationError, match="3 robots tie"):
        translate("2 cart wheels from drying loft to vat west, leave the weakest one out of it", tie)


def test_a_number_after_strongest_other_than_one_is_refused() -> None:
    with pytest.raises(TranslationError, match="a number after 'strongest'"):
        translate("2 cart wheels from drying loft to vat west, only the strongest 2", TANNERY)


def _with_packing(extra_dock: bool = False) -> dict:
    """The tannery with its finishing table called "packing" (a one-word place), and a place
    called "dock" when asked."""
    world = copy.deepcopy(TANNERY)
    world["shelves"]["packing"] = world["shelves"].pop("finishing_table")
    world["stock"]["packing"] = world["stock"].pop("finishing_table")
    if extra_dock:
        world["shelves"]["dock"] = {"x": 20, "y": 3, "width": 4, "depth": 2, "capacity": 10, "access": [22, 6]}
    return world


@pytest.mark.parametrize("said", ["packing staging", "the packing area", "packing zone", "the packing dock"])
def test_a_noun_for_a_place_after_a_place_name_is_that_place(said: str) -> None:
    got = translate(f"move 2 dye drums from vat east to {said}", _with_packing())
    assert got["goal"] == {"vat_east": {"dye_drum": 2}, "packing": {"dye_drum": 3}}


def test_a_noun_that_names_a_place_of_its_own_is_not_read_into_the_name_before_it() -> None:
    with pytest.raises(TranslationError):
        translate("move 2 dye drums from vat east to the packing dock", _with_packing(extra_dock=True))


@pytest.mark.parametrize(("command", "courtesy"), [
    ("At your earliest convenience, please move 2 dye drums from vat east to the finishing table.",
     "At your earliest convenience"),
    ("Please move 2 dye drums from vat east to the finishing table at your earliest convenience.",
     "at your earliest convenience"),
    ("Move 2 dye drums from vat east to the finishing table when you have a moment.", "when you have a moment"),
    ("Move 2 dye drums from vat east to the finishing table when youve got a sec", "when youve got a sec"),
    ("Per our discussion this morning, move 2 dye drums from vat east to the finishing table.",
     "Per our discussion this morning"),
])
def test_courtesies_of_time_and_what_the_order_follows_are_set_aside_and_said(command: str, courtesy: str) -> None:
    """They read like a time or a reason the plan would keep: the echo says they were not kept."""
    got = understand(command, TANNERY)
    assert got["goal"] == {"vat_east": {"dye_drum": 2}, "finishing_table": {"dye_drum": 3}}
    aside = [line for line in got["explanation"] if line.startswith("set aside")]
    assert len(aside) == 1 and f"'{courtesy}'" in aside[0] and "lease" not in aside[0]


@pytest.mark.parametrize("command", [
    "Per trip, move 2 dye drums from vat east to the finishing table",          # a rate, not what the order follows
    "Per our plan only crane, move 2 dye drums from vat east to the finishing table",   # an operative word in it
])
def test_per_is_set_aside_only_before_whose_and_with_nothing_operative(command: str) -> None:
    with pytest.raises(TranslationError):
        translate(command, TANNERY)


@pytest.mark.parametrize("command", [
    "Please move 2 dye drums from vat east to the finishing table overnight.",
    "Please move 2 dye drums from vat east to the finishing table ahead of the audit.",
])
def test_a_time_said_after_the_order_is_set_aside(command: str) -> None:
    assert translate(command, TANNERY)["goal"] == {"vat_east": {"dye_drum": 2}, "finishing_table": {"dye_drum": 3}}


def test_office_phrasings_of_the_grammars_own_words() -> None:
    """ "with the exception of" is except; "in their entirety" adds nothing to a swap of all;
    "at any given time" adds nothing to a bound; "maintain" keeps."""
    assert translate("Move all of the cart wheels to vat west, with the exception of those on vat east.", TANNERY)["goal"] == \
        translate("Move all of the cart wheels to vat west, except those on vat east.", TANNERY)["goal"]
    assert translate("Swap vat east and vat west in their entirety.", TANNERY)["goal"] == \
        translate("Swap vat east and vat west.", TANNERY)["goal"]
    assert translate("Vat west should have no more than 4 belt rounds at any given time.", TANNERY)["goal"] == \
        {"vat_west": {"belt_round": {"at_most": 4}}}
    assert translate("Maintain between 2 and 4 belt rounds at vat west.", TANNERY)["goal"] == \
        {"vat_west": {"belt_round": {"at_least": 2, "at_most": 4}}}


def test_a_noun_for_a_place_with_a_number_after_it_is_not_read_into_the_name() -> None:
    """ "the packing dock 2": "dock 2" may be a place of its own; never read as packing."""
    with pytest.raises(TranslationError):
        translate("move 2 dye drums from vat east to the packing dock 2", _with_packing())

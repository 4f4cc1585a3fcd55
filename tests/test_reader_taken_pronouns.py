""""them" after a take, and particles of emptying: "take 4 X off P and split them evenly between
Q and R" shares the taken units out (it was refused on "them"); "P's got too many X. Cut them by
a third." cuts the X of the complaint; "cut P's X down by a third"; "clear P right out"."""
from __future__ import annotations

import pytest

from pipflow.errors import TranslationError
from pipflow.warehouse.language.translator import translate
from tests.tannery_world import TANNERY


def test_taken_units_split_evenly_between_two_places() -> None:
    got = translate("Take 4 cart wheels off the drying loft and split them evenly between vat east and vat west",
                    TANNERY)
    assert got["goal"] == {"drying_loft": {"cart_wheel": 2}, "vat_east": {"cart_wheel": 3}, "vat_west": {"cart_wheel": 2}}


def test_taken_units_that_do_not_split_evenly_are_refused() -> None:
    with pytest.raises(TranslationError, match="split evenly"):
        translate("Take 3 cart wheels off the drying loft and split them evenly between vat east and vat west", TANNERY)


def test_split_them_with_nothing_taken_is_refused() -> None:
    with pytest.raises(TranslationError):
        translate("Split them evenly between vat east and vat west", TANNERY)


@pytest.mark.parametrize("command", ["Vat west has got too many belt rounds. Cut them by a fifth.",
                                     "Cut vat west's belt rounds down by a fifth"])
def test_cut_by_a_fraction(command: str) -> None:
    assert translate(command, TANNERY)["goal"] == {"vat_west": {"belt_round": 4}}


def test_cut_them_without_a_complaint_is_refused() -> None:
    with pytest.raises(TranslationError):
        translate("Cut them by a fifth", TANNERY)


def test_clear_right_out_empties_the_place() -> None:
    assert translate("Clear the drying loft right out", TANNERY)["goal"] == {
        "drying_loft": {"cart_wheel": 0, "belt_round": 0, "dye_drum": 0}}

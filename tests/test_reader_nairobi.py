"""Issue 23's thirtieth round, from pair KK's first measurement (a Nairobi fulfilment centre's shift
supervisor writing Kenyan English with Swahili and Sheng): "sasa", "sawa" and "asante" as greeting
and thanks, "kabisa", "haraka", "tafadhali" and "bana" anywhere, "the same" as the thing just named
in a remark ("the same is blocking the door"), and "not more not less". Through the real warehouse
reader, in the ferry terminal of our own."""
from __future__ import annotations

import pytest

from pipflow.errors import TranslationError
from pipflow.warehouse.language.translator import understand
from tests.terminal_world import TERMINAL, with_ramp_called

MOVE = {"quay": {"crate": 11}, "shed": {"crate": 5}}


@pytest.mark.parametrize("command", [
    "Sasa team, move 3 crates from quay to shed",
    "Sawa wasee. Move 3 crates from quay to shed. Asante",
    "Move 3 crates from quay to shed haraka tafadhali",
    "move 3 crates from quay to shed bana",
    "Poa, move 3 crates from quay to shed asante mzee",
])
def test_kenyan_english_read_as_the_order_it_says(command: str) -> None:
    assert understand(command, TERMINAL)["goal"] == MOVE


def test_kabisa_clears_as_completely_does() -> None:
    assert understand("Clear the ramp kabisa", TERMINAL)["goal"] == understand("Clear the ramp completely",
                                                                              TERMINAL)["goal"]


@pytest.mark.parametrize("remark", ["the same is blocking the roller door", "the same has a battery issue"])
def test_the_same_opening_a_remark_is_the_thing_named(remark: str) -> None:
    got = understand(f"Halve the crates on quay, {remark}", TERMINAL)
    assert got["goal"] == {"quay": {"crate": 7}}
    assert any("set aside" in line and "same" in line for line in got["explanation"]), got["explanation"]


@pytest.mark.parametrize("command", [
    # "the same" repeating an order stays operative: never set aside as talk
    "Halve the crates on quay, the same is needed on shed",
    "Halve the crates on quay, the same has to happen on shed",
    # a remark that names a place of the world is kept in, and must read
    "Halve the crates on quay, the same is blocking the ramp",
])
def test_the_same_that_repeats_or_names_is_never_set_aside(command: str) -> None:
    with pytest.raises(TranslationError):
        understand(command, TERMINAL)


def test_the_same_goes_for_another_place_repeats_the_order() -> None:
    assert understand("Halve the crates on quay, the same goes for shed", TERMINAL)["goal"] == \
        {"quay": {"crate": 7}, "shed": {"crate": 1}}


def test_not_more_not_less_says_exactly() -> None:
    assert understand("Shed should have 9 crates, not more not less", TERMINAL)["goal"] == {"shed": {"crate": 9}}
    assert understand("Shed should have 9 crates, not more, not less", TERMINAL)["goal"] == {"shed": {"crate": 9}}


def test_a_swahili_word_that_names_a_place_stays_its_name() -> None:
    world = with_ramp_called("sasa")
    assert understand("move 3 crates from quay to sasa", world)["goal"] == {"quay": {"crate": 11}, "sasa": {"crate": 3}}

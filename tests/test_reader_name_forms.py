"""How staff shorten and compound the world's names: a two-word name with its first word cut
short ("dry loft" for drying_loft), a product called by the plural of a head noun that is also a
verb of the grammar ("wheels" of cart_wheel, "rounds" of belt_round), and a place name used as a
noun adjunct ("the vat west rounds"). Each was refused; none may be guessed where two names fit."""
from __future__ import annotations

import pytest

from pipflow.errors import TranslationError
from pipflow.warehouse.language.translator import translate
from tests.tannery_world import TANNERY


def test_a_two_word_name_with_its_first_word_cut_short_is_read() -> None:
    got = translate("Move 2 cart wheels from the dry loft to the fin table", TANNERY)
    assert got["goal"] == {"drying_loft": {"cart_wheel": 4}, "finishing_table": {"cart_wheel": 2}}


def test_a_shortened_word_that_fits_two_names_is_refused() -> None:
    """"va" is too short, and "vat" alone names both vats: refused, never the nearer one."""
    with pytest.raises(TranslationError):
        translate("Move 2 belt rounds from the vat to the drying loft", TANNERY)


@pytest.mark.parametrize("command, goal", [
    ("Move 4 wheels from the drying loft to vat west", {"drying_loft": {"cart_wheel": 2}, "vat_west": {"cart_wheel": 4}}),
    ("2 more rounds on the finishing table", {"finishing_table": {"belt_round": 2}}),
])
def test_the_plural_of_a_head_noun_the_grammar_reads_as_a_verb_names_the_product(command: str, goal: dict) -> None:
    assert translate(command, TANNERY)["goal"] == goal


def test_the_verb_itself_stays_a_verb() -> None:
    """"wheel" (the verb) still moves things: "wheel 2 belt rounds to vat east"."""
    got = translate("Wheel 2 belt rounds from vat west to vat east", TANNERY)
    assert got["goal"] == {"vat_west": {"belt_round": 3}, "vat_east": {"belt_round": 2}}


@pytest.mark.parametrize("command, goal", [
    ("Bring half of the drying loft wheels to vat west", {"drying_loft": {"cart_wheel": 3}, "vat_west": {"cart_wheel": 3}}),
    ("Halve the drying loft wheels", {"drying_loft": {"cart_wheel": 3}}),
])
def test_a_place_name_before_a_product_name_is_read_as_its_possessive(command: str, goal: dict) -> None:
    assert translate(command, TANNERY)["goal"] == goal


def test_a_word_sharing_a_names_start_is_offered_as_that_name() -> None:
    """"belting" is no name, but it shares its start with belt_round: the reading with it is
    offered (the count said as set and as added), never acted on."""
    with pytest.raises(TranslationError) as err:
        translate("Put 2 belting on the drying loft", TANNERY)
    assert {"drying_loft": {"belt_round": 4}} in [c["goal"] for c in err.value.candidates]


def test_an_unknown_word_before_the_last_word_of_one_name_is_offered_as_that_name() -> None:
    """"the top loft" where the one loft is drying_loft: refused ("top" may name a loft the world
    has not), with the reading as drying_loft offered first."""
    with pytest.raises(TranslationError) as err:
        translate("Move 2 cart wheels from the top loft to the finishing table", TANNERY)
    offered = err.value.candidates
    assert offered and offered[0]["goal"] == {"drying_loft": {"cart_wheel": 4}, "finishing_table": {"cart_wheel": 2}}
    assert "read 'top loft' as 'drying loft'" in offered[0]["reading"]


def test_an_unknown_word_before_a_word_two_names_end_with_offers_neither() -> None:
    # with a hay loft beside the drying loft, "the top loft" may be either: neither is offered as it
    world = {**TANNERY, "shelves": {**TANNERY["shelves"],
                                    "hay_loft": {"x": 20, "y": 3, "width": 4, "depth": 2, "capacity": 10, "access": [22, 6]}}}
    with pytest.raises(TranslationError) as err:
        translate("Move 2 cart wheels from the top loft to the finishing table", world)
    assert all("read 'top loft'" not in c["reading"] for c in err.value.candidates)


#: a cold store, a world no benchmark uses: two numbered rooms named by letters and a number
COLD = {
    "name": "coldstore",
    "floor": {"width": 30, "height": 20},
    "shelves": {
        "freeze1": {"x": 2, "y": 14, "width": 4, "depth": 2, "capacity": 20, "access": [4, 13]},
        "freeze2": {"x": 10, "y": 14, "width": 4, "depth": 2, "capacity": 20, "access": [12, 13]},
        "pack_line": {"x": 20, "y": 4, "width": 6, "depth": 2, "capacity": 12, "access": [23, 6]},
    },
    "products": {"peas": {"color": "green"}},
    "stock": {"freeze1": {"peas": 6}, "freeze2": {"peas": 2}},
    "robots": {"yeti": {"start": [1, 8], "skills": {"carry": 3}}},
}


@pytest.mark.parametrize("command, goal", [
    ("move 2 peas from freeze room 1 to the pack line", {"freeze1": {"peas": 4}, "pack_line": {"peas": 2}}),
    ("freeze store two should have 5 peas", {"freeze2": {"peas": 5}}),
])
def test_a_numbered_place_said_with_a_place_noun_before_its_number(command: str, goal: dict) -> None:
    assert translate(command, COLD)["goal"] == goal


@pytest.mark.parametrize("command", ["move 2 peas from freeze room 3 to the pack line",     # no such place
                                     "move 2 peas from freeze thing 1 to the pack line"])   # no place noun
def test_a_place_noun_never_makes_a_place_the_world_has_not(command: str) -> None:
    with pytest.raises(TranslationError):
        translate(command, COLD)

"""Issue 23's twenty-fourth round, from pair EE's first measurement (an engineer's ticket-style
notes to her home robots): an arrow says "to" between a thing and a place ("bowl + glass ->
dishwasher") and "then" after a clause ("tv on? -> turn it off"); a condition on where a thing is
("if the laptop is on the couch, ...") is read as its place even where the thing also switches
on; a word that names both a place and a category ("trash": the can and the rubbish) names the
category where the statement moves things, since no place is carried; "to wherever they live" is
their home; "close whatever you opened" asks for what is done anyway; "fyi" carries nothing.
Through the real household reader, in the studio flat."""
from __future__ import annotations

import copy

import pytest

from pipflow.errors import TranslationError
from pipflow.household.language.translator import translate
from tests.studio_world import STUDIO


def goal(command: str, world: dict = STUDIO) -> dict:
    return {k: v for k, v in translate(command, world)["goal"].items() if v}


@pytest.mark.parametrize("command, wanted", [
    ("soda -> recycling bin", {"in": {"recycling": ["soda"]}}),
    ("teacup + saucer \u2192 pantry", {"in": {"pantry": ["teacup", "saucer"]}, "state": {"pantry": ["closed"]}}),
    ("teacup => basin", {"in": {"basin": ["teacup"]}}),
    ("- teacup --> basin\n- soda -> recycling bin", {"in": {"basin": ["teacup"], "recycling": ["soda"]}}),
    ("radio on? -> turn it off", {"state": {"radio": ["off"]}}),
    ("turn off the radio -> then the main light", {"state": {"radio": ["off"], "overhead_light": ["off"]}}),
])
def test_an_arrow_says_to_or_then(command: str, wanted: dict) -> None:
    assert goal(command) == wanted


def test_an_arrow_that_reads_neither_way_is_refused() -> None:
    """A chain of waypoints says an order of places the reader does not keep: refused, never a
    guess of which place is meant."""
    with pytest.raises(TranslationError):
        translate("soda: coffee table -> worktop -> icebox", STUDIO)


@pytest.mark.parametrize("command, wanted", [
    ("if the tablet is on the coffee table, put it on the nightstand", {"in": {"nightstand": ["tablet"]}}),
    ("if the tablet is still on the coffee table -> put it on the nightstand", {"in": {"nightstand": ["tablet"]}}),
    ("if the teacup is on the coffee table, put it in the basin", {"in": {"basin": ["teacup"]}}),
    ("if the tablet is still on, put it on the nightstand", {"in": {"nightstand": ["tablet"]}}),   # its switch
])
def test_a_condition_on_where_a_thing_is_is_its_place_not_its_switch(command: str, wanted: dict) -> None:
    """The tablet switches and lies on the coffee table: "on the coffee table" is where it is.
    The order's "it" is the tablet, never the coffee table (which had been moved)."""
    assert goal(command) == wanted


def test_a_condition_on_a_place_that_does_not_hold_asks_nothing() -> None:
    with pytest.raises(TranslationError, match="does not hold now"):
        translate("if the tablet is on the armchair, put it on the nightstand", STUDIO)


@pytest.fixture(scope="module")
def rubbish() -> dict:
    """The studio whose bin is also called "trash", with a category "rubbish" called "trash" too:
    the soda can and the magazine."""
    world = copy.deepcopy(STUDIO)
    world["places"]["recycling"]["words"] = [*world["places"]["recycling"]["words"], "trash"]
    world["categories"]["rubbish"] = {"words": ["trash", "rubbish"], "home": None}
    for name in ("soda", "magazine"):
        world["objects"][name]["categories"] = [*world["objects"][name].get("categories", []), "rubbish"]
    return world


def test_a_word_of_a_place_and_a_category_names_the_category_where_things_are_moved(rubbish: dict) -> None:
    assert goal("put the trash on the nightstand", rubbish) == {"in": {"nightstand": ["soda", "magazine"]}}
    assert goal("throw away the trash", rubbish) == {"in": {"recycling": ["soda", "magazine"]}}


def test_the_bins_word_in_an_observation_then_an_order_is_never_read_as_the_bin(rubbish: dict) -> None:
    """"trash on the coffee table again. bin it": the bin itself was read as the thing, and a
    doable order refused as impossible (a misreading). Now the word is the rubbish, and the
    two sentences (a wish that they lie there, an order to bin them) are refused as conflicting."""
    with pytest.raises(TranslationError, match="both in"):
        translate("ugh, trash on the coffee table again. bin it", rubbish)


@pytest.mark.parametrize("command", ["clothes -> wherever they live", "put the clothes wherever they belong"])
def test_wherever_they_live_is_their_home(command: str) -> None:
    got = translate(command, STUDIO)
    assert {k: v for k, v in got["goal"].items() if v} == {"in": {"wardrobe": ["sweater", "scarf"]},
                                                           "state": {"wardrobe": ["closed"]}}
    assert any("where they belong" in n for n in got["notes"])


def test_close_whatever_you_opened_asks_for_what_is_done_anyway_and_is_said() -> None:
    got = translate("teacup -> pantry, and close whatever you opened after", STUDIO)
    assert {k: v for k, v in got["goal"].items() if v} == {"in": {"pantry": ["teacup"]}, "state": {"pantry": ["closed"]}}
    assert any("closed again anyway" in n for n in got["notes"])
    with pytest.raises(TranslationError):   # more said in the clause: read, and refused here
        translate("teacup -> pantry. close whatever you opened in the kitchen", STUDIO)
    with pytest.raises(TranslationError):   # nothing else asked
        translate("close whatever you opened", STUDIO)


def test_fyi_carries_nothing() -> None:
    assert goal("fyi the radio is on, turn it off") == {"state": {"radio": ["off"]}}

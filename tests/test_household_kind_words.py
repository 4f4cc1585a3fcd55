"""A word that names a kind as well as a thing ("stove" of a camping stove) names that thing only
where no other thing of the home is of the kind. In held-out pair F's first measurement, "heat the
X on the stove" in a home with a range oven and a primus stove was read as the primus (a
misreading by the writer's gold: "the stove" is either); now it is asked, each stove offered that
can do what is asked. In a galley of our own."""
from __future__ import annotations

import pytest

from pipflow.errors import TranslationError
from pipflow.household.language.translator import translate
from pipflow.household.world import world_from_text

GALLEY = """
domain: household
name: galley
floor: {width: 6, height: 4}
places:
  iron_range:   {x: 0.2, y: 3.0, width: 0.8, depth: 0.8, access: [0.6, 2.4], properties: [receptacle, openable, heater], state: {open: false}, words: [range]}
  spirit_stove: {x: 1.4, y: 3.0, width: 0.6, depth: 0.6, access: [1.7, 2.4], properties: [receptacle, heater, toggleable], state: {on: false}, words: [spirit stove, meths stove]}
  chart_table:  {x: 3.0, y: 1.0, width: 1.2, depth: 0.8, access: [3.6, 0.5], properties: [receptacle], words: [table]}
objects:
  kipper:       {in: chart_table, mass: 1, properties: [pickupable, heatable, sliceable]}
robots:
  bosun: {start: [1.0, 1.0], skills: {pickup: 1, open: 1, toggle: 1, slice: 1, heat: 1}}
"""


@pytest.fixture()
def galley() -> dict:
    return world_from_text(GALLEY, "galley.yaml")


def test_the_stove_with_a_range_beside_it_is_asked(galley: dict) -> None:
    with pytest.raises(TranslationError, match="range") as err:
        translate("Heat the kipper on the stove.", galley)
    places = [next(iter(c["goal"]["in"])) for c in err.value.candidates if c["goal"].get("in")]
    assert set(places) == {"iron_range", "spirit_stove"}


def test_a_stove_that_can_be_switched_is_the_only_one_offered_for_switching(galley: dict) -> None:
    with pytest.raises(TranslationError) as err:
        translate("turn the stove on", galley)
    assert [c["goal"]["state"] for c in err.value.candidates] == [{"spirit_stove": ["on"]}]


def test_the_stove_alone_in_its_kind_is_read() -> None:
    lone = world_from_text(GALLEY.replace("words: [range]", "words: [chart chest]").replace("iron_range", "sea_chest"), "galley.yaml")
    assert translate("turn the stove on", lone)["goal"]["state"] == {"spirit_stove": ["on"]}

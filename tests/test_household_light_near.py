"""Issue 23, household reader: a light cue felt by a place ("it's dark over by the settle") means
the one light nearest that place by the floor plan, in a bothy of our own; two lights as near are
asked, a nearest light already on is refused, and a place word that says no nearness ("under")
is refused."""
from __future__ import annotations

import pytest

from pipflow.errors import TranslationError
from pipflow.household.language.translator import translate
from pipflow.household.world import world_from_text

BOTHY = """
domain: household
name: lit bothy
floor: {width: 10, height: 6}
categories:
  lamps: {words: [lamps, lights]}
places:
  settle:    {x: 1.0, y: 1.0, width: 1.2, depth: 0.8, access: [1.6, 2.2], properties: [receptacle]}
  desk:      {x: 8.0, y: 1.0, width: 1.2, depth: 0.6, access: [8.6, 2.0], properties: [receptacle]}
  loom:      {x: 4.4, y: 4.0, width: 1.2, depth: 0.8, access: [5.0, 3.5], properties: [receptacle]}
  floor_lamp: {x: 2.6, y: 1.0, width: 0.3, depth: 0.3, access: [2.75, 2.0], properties: [toggleable], state: {on: false}, categories: [lamps]}
  desk_light: {x: 8.2, y: 2.0, width: 0.2, depth: 0.2, access: [8.3, 2.6], properties: [toggleable], state: {on: true}, categories: [lamps]}
objects:
  lantern:   {in: loom, mass: 1, properties: [pickupable, toggleable], state: {on: false}, categories: [lamps]}
  shawl:     {in: settle, mass: 1, properties: [pickupable]}
robots:
  r1: {start: [1.0, 3.0], skills: {pickup: 1, open: 1, toggle: 1}}
"""


@pytest.fixture(scope="module")
def bothy() -> dict:
    return world_from_text(BOTHY, "lit-bothy.yaml")


def test_a_light_cue_by_a_place_is_the_light_nearest_it(bothy):
    assert translate("It's a bit dark over by the settle.", bothy)["goal"]["state"] == {"floor_lamp": ["on"]}
    # the lantern sits on the loom: an object is where its place is
    assert translate("It's awfully gloomy near the loom.", bothy)["goal"]["state"] == {"lantern": ["on"]}
    # "it's dark in here" says no place: with two lights off, which one is asked (each offered)
    with pytest.raises(TranslationError, match="does not say where") as asked:
        translate("It's dark in here.", bothy)
    assert sorted(next(iter(c["goal"]["state"])) for c in asked.value.candidates) == ["floor_lamp", "lantern"]


def test_the_nearest_light_already_on_is_refused_not_another_and_no_nearness_is_refused(bothy):
    with pytest.raises(TranslationError, match="already"):
        translate("It's dim by the desk.", bothy)
    with pytest.raises(TranslationError):   # "under" says where, not near what
        translate("It's dark under the settle.", bothy)

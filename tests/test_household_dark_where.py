"""Issue 23, household reader: "it's so dark in here" wants light where the speaker is, which the
command does not say and the home model cannot know. With one light off that one is meant; with
several it is asked, each light offered, never every light of the home (held-out writers refused
it so, four sets to one: docs/household.md, cues). What the speaker cannot see ("I can't see a
thing", "my hand in front of my face", "where I'm going") names nothing of the home and is set
aside as the reason; what names a thing of the home, a negation or "only" never is. A bothy of our
own."""
from __future__ import annotations

import pytest

from pipflow.errors import TranslationError
from pipflow.household.language.translator import translate
from pipflow.household.world import world_from_text

BOTHY = """
domain: household
name: dark bothy
floor: {width: 10, height: 6}
categories:
  lamps: {words: [lamps, lights]}
places:
  settle:     {x: 1.0, y: 1.0, width: 1.2, depth: 0.8, access: [1.6, 2.2], properties: [receptacle]}
  desk:       {x: 8.0, y: 1.0, width: 1.2, depth: 0.6, access: [8.6, 2.0], properties: [receptacle]}
  floor_lamp: {x: 2.6, y: 1.0, width: 0.3, depth: 0.3, access: [2.75, 2.0], properties: [toggleable], state: {on: false}, categories: [lamps]}
  desk_light: {x: 8.2, y: 2.0, width: 0.2, depth: 0.2, access: [8.3, 2.6], properties: [toggleable], state: {on: false}, categories: [lamps]}
  radio:      {x: 5.0, y: 1.0, width: 0.3, depth: 0.3, access: [5.1, 2.0], properties: [toggleable], state: {on: false}}
objects:
  shawl:      {in: settle, mass: 1, properties: [pickupable]}
robots:
  r1: {start: [1.0, 3.0], skills: {pickup: 1, open: 1, toggle: 1}}
"""


@pytest.fixture(scope="module")
def two_off() -> dict:
    return world_from_text(BOTHY, "dark-bothy.yaml")


@pytest.fixture(scope="module")
def one_off() -> dict:
    return world_from_text(BOTHY.replace("state: {on: false}, categories: [lamps]}\n  radio",
                                         "state: {on: true}, categories: [lamps]}\n  radio"), "dark-bothy-1.yaml")


def state(command: str, world: dict) -> dict:
    return {n: sorted(v) for n, v in translate(command, world)["goal"]["state"].items() if v}


def asked(command: str, world: dict) -> list[str]:
    """The lights a refusal offers, one per candidate reading."""
    with pytest.raises(TranslationError, match="does not say where") as refused:
        translate(command, world)
    return sorted(n for c in refused.value.candidates for n in c["goal"]["state"])


@pytest.mark.parametrize("command", [
    "It's so dark in here, I can't see a thing.",
    "It is so dark here, I cannot see anything.",
    "it's too dark in here I can't see my hand in front of me",
    "it's so dark in here i can't see what i'm doing",
    "It's getting dark.",
    "I can't see my hand in front of my face",
])
def test_dark_with_two_lights_off_asks_which_and_offers_each(command, two_off):
    assert asked(command, two_off) == ["desk_light", "floor_lamp"]


@pytest.mark.parametrize("command", [
    "It's so dark in here, I can't see a thing.",
    "it's so dark in here i can't even see where i'm going",
    "so dark in here cannot see anything",
])
def test_dark_with_one_light_off_is_that_light(command, one_off):
    assert state(command, one_off) == {"floor_lamp": ["on"]}


def test_what_cannot_be_seen_is_said_as_set_aside(one_off):
    got = translate("It's so dark in here I can't see my hand in front of my face.", one_off)
    assert got["order"]["set_aside"] == ["i can not see my hand in front of my face"]


def test_the_cue_with_a_request_of_the_lights_is_its_reason(two_off):
    assert state("Is getting dark already, put all the lights on.", two_off) == \
        {"desk_light": ["on"], "floor_lamp": ["on"]}
    assert state("It's getting dark, turn on the floor lamp.", two_off) == {"floor_lamp": ["on"]}
    # a place said with the cue says where: the light nearest it
    assert state("It's a bit dark over by the desk.", two_off) == {"desk_light": ["on"]}


def test_what_names_a_thing_or_bears_on_the_order_is_never_set_aside(one_off):
    with pytest.raises(TranslationError) as refused:
        translate("It's dark in here, I can't see, only the floor lamp on", one_off)
    assert "only" in str(refused.value)
    with pytest.raises(TranslationError, match="see the radio"):   # the radio is a thing of the home
        translate("It's so dark in here I can't see the radio.", one_off)

"""Pair LL's household set (a Quezon City nurse texting in Filipino English) had "close all the
lights" refused as impossible: a command the home can do, so a misreading by the metric. In
Philippine and South Asian English "open / close the light" is switching it on / off. Read so only
before things that switch and cannot be opened in the home; before a thing that opens, "open" and
"close" keep their meaning. In the bothy of our own (tests/test_household_reader_needs.py)."""
from __future__ import annotations

import pytest

from pipflow.errors import Refusal
from pipflow.household.world import world_from_text
from test_household_reader_needs import BOTHY, goal


@pytest.fixture(scope="module")
def bothy() -> dict:
    return world_from_text(BOTHY, "bothy.yaml")


@pytest.mark.parametrize("command,state", [
    ("Pls close the lamp", {"lamp": ["off"]}),
    ("open the wood stove", {"wood_stove": ["on"]}),
    ("close all the lights na", {"lamp": ["off"], "lantern": ["off"]}),
    ("Close the wireless and the lamp, I'm off to bed", {"wireless": ["off"], "lamp": ["off"]}),
])
def test_open_and_close_switch_a_thing_that_does_not_open(bothy, command, state):
    assert goal(command, bothy) == ({}, state)


def test_open_and_close_keep_their_meaning_for_a_thing_that_opens(bothy):
    assert goal("close the icebox", bothy) == ({}, {"icebox": ["closed"]})
    assert goal("open the dresser", bothy) == ({}, {"dresser": ["open"]})
    # a stove with a door: "open" is its door, never a guess that it means on
    doored = world_from_text(BOTHY.replace("properties: [toggleable], state: {on: false}}\n  pail",
                                           "properties: [toggleable, openable], state: {on: false, open: false}}\n  pail"),
                             "bothy.yaml")
    assert goal("open the wood stove", doored) == ({}, {"wood_stove": ["open"]})


def test_a_thing_that_neither_opens_nor_switches_is_still_impossible_to_open(bothy):
    with pytest.raises(Refusal):
        goal("open the jug", bothy)


@pytest.mark.parametrize("command,state", [
    # round 32: a list that names a thing that opens and one that only switches, each read by what it is
    ("close the icebox and the lamp", {"icebox": ["closed"], "lamp": ["off"]}),
    ("close the lamp and the icebox", {"lamp": ["off"], "icebox": ["closed"]}),
    ("open the dresser, the wood stove and the icebox", {"dresser": ["open"], "wood_stove": ["on"],
                                                         "icebox": ["open"]}),
])
def test_a_list_of_things_that_open_and_things_that_switch_is_read_item_by_item(bothy, command, state):
    assert goal(command, bothy) == ({}, state)


def test_a_list_with_a_thing_that_neither_opens_nor_switches_is_still_impossible(bothy):
    with pytest.raises(Refusal):
        goal("close the lamp and the jug", bothy)

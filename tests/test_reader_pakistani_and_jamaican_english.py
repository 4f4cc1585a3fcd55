"""Issue 23, from pair FF's sets (a shift in-charge at Port Qasim writing Pakistani English, a nurse
in Kingston writing Jamaican English and Patwa), after their first measurement. Warehouse: a move
whose source is its own destination ("the rest upstairs to the mezz" where "upstairs" is the
mezzanine's word) is refused, never read as a move that asks nothing (it was: a misreading); Urdu
talk ("AoA", "yaar", "theek hai", "Jumma Mubarak", "shukriya"); Urdu postpositions after a place
("rack A se 9 bolts ...": from rack A); "come" as "go" for where things end up; a product and its
place said first and shared out by counts ("intake's bolts, 4 to outbound and the rest to rack
B"); "P never has less than N"; "nothing should remain on P"; "not less not more" after a count;
"also same"; "N things/jobs:" announcing a list (both domains); "should not do any of this", "for
any of it" (a rule for the whole command); "those are ..." reporting, never selecting. Household: more Patwa ("tun", "lef", "mek", "dutty", "weh", "di" alone), Jamaican
talk ("Lawd", "cho", "eeh", "bless"), "wash off", "the place (is) hot" as the cue "it is hot in
here". Worlds of our own, through the real reader; each rule with what stays as said or refused."""
from __future__ import annotations

import pytest

from pipflow.errors import PipflowError
from pipflow.household.world import world_from_text
from pipflow.warehouse.language.translator import understand
from tests.readings import assert_warehouse_alike, household_goal as goal

STORE = {
    "name": "nutstore",
    "floor": {"width": 40, "height": 20},
    "shelves": {
        "intake": {"x": 2, "y": 14, "width": 4, "depth": 2, "capacity": 40, "access": [4, 13]},
        "racka": {"x": 10, "y": 14, "width": 4, "depth": 2, "capacity": 40, "access": [12, 13], "words": ["rack A"]},
        # "upstairs" is this place's word: the misreading's shape
        "loft": {"x": 18, "y": 14, "width": 4, "depth": 2, "capacity": 40, "access": [20, 13],
                 "words": ["upstairs"]},
        "outbound": {"x": 26, "y": 14, "width": 4, "depth": 2, "capacity": 40, "access": [28, 13]},
    },
    "products": {"bolt": {"color": "grey"}, "washer": {"color": "black"}, "nut": {"color": "blue"}},
    "stock": {"intake": {"bolt": 10, "washer": 4, "nut": 6}, "racka": {"bolt": 12, "nut": 6},
              "loft": {"washer": 9, "nut": 9}, "outbound": {"bolt": 2, "nut": 3}},
    "robots": {"fk1": {"kind": "forklift", "start": [1, 8], "skills": {"carry": 8}},
               "amr1": {"kind": "amr", "start": [33, 8], "skills": {"carry": 2}}},
}


def _same(said: str, plain: str) -> None:
    assert_warehouse_alike(said, plain, STORE)


@pytest.mark.parametrize("said, plain", [
    ("AoA team. Outbound should have 8 nut.", "outbound should have 8 nut"),
    ("Yaar double the nut on outbound", "double the nut on outbound"),
    ("Double the nut on outbound yaar. Theek hai?", "double the nut on outbound"),
    ("Jumma Mubarak everyone. Empty outbound. Shukriya.", "empty outbound"),
    ("rack A se 9 bolts should come to intake", "move 9 bolt from rack A to intake"),
    ("rack A se nine bolts intake ko", "move 9 bolt from rack A to intake"),
    ("9 bolts should come to outbound", "add 9 bolt to outbound"),
    ("intake's bolts, 4 to outbound and the rest to rack A", "move 4 bolt from intake to outbound, "
     "and move the rest of the bolt from intake to rack A"),
    ("From intake's bolts, 4 to outbound", "move 4 bolt from intake to outbound"),
    ("the bolts on intake, 4 to outbound", "move 4 bolt from intake to outbound"),
    ("outbound never has less than 5 nut", "outbound should have at least 5 nut"),
    ("Clear out outbound completely, nothing should remain on it.", "empty outbound"),
    ("nothing should be left on outbound", "empty outbound"),
    ("Keep between 4 and 6 nut on outbound, not less not more", "outbound should have between 4 and 6 nut"),
    ("outbound should have 6 nut, no more no less", "outbound should have 6 nut"),
    ("outbound should hold 5 bolts, intake also same", "outbound and intake should each have 5 bolt"),
    ("outbound should hold 5 bolts, intake the same also", "outbound and intake should each have 5 bolt"),
    ("Two jobs plz: empty outbound, and double the nut on rack A", "empty outbound, and double the nut on rack A"),
    ("Double the nut on rack A. Robots that carry less than 4 should not do any of this",
     "Double the nut on rack A. Don't use robots that carry less than 4"),
    ("Double the nut on rack A. Dont use fk1 for any of it.", "Double the nut on rack A. Don't use fk1"),
    ("Bring all the nut to outbound, those are booked", "bring all the nut to outbound"),
])
def test_pakistani_english_orders_read_as_their_plain_english(said: str, plain: str) -> None:
    _same(said, plain)


@pytest.mark.parametrize("said", [
    # "upstairs" is the loft's word: the rest of what, from the loft to the loft? Never a move that
    # asks for nothing
    "From intake bolts: 4 to outbound and rest upstairs to the loft",
    "move the nut from the loft to upstairs",
    # a postposition after no place stays as written, and is refused unread
    "se 9 bolts to intake",
    # "those" that selects stays operative: never set aside
    "Bring all the nut to outbound, those on rack A",
])
def test_a_move_to_its_own_source_and_a_stray_postposition_are_refused(said: str) -> None:
    with pytest.raises(PipflowError):
        understand(said, STORE)


def test_every_place_to_one_of_them_moves_from_the_others() -> None:
    """The place things go to is no source of its own move ("all the nut from every place to the
    loft"), as before the own-source rule."""
    got = understand("move all the nut from every place to the loft", STORE)["goal"]
    assert got["loft"]["nut"] == 24 and got["intake"]["nut"] == 0


def test_one_bound_said_after_a_count_keeps_its_meaning() -> None:
    """Only the two together ("not less not more") restate the count; "no more than 8" stays a bound."""
    got = understand("outbound should have no less than 4 nut, no more than 8", STORE)["goal"]
    assert got == {"outbound": {"nut": {"at_least": 4, "at_most": 8}}}


HOUSE = """
domain: household
name: yard house
floor: {width: 14, height: 8}
places:
  sink:    {x: 1.0, y: 1.0, width: 1.0, depth: 0.6, access: [1.5, 1.8], properties: [receptacle, sink]}
  table:   {x: 7.5, y: 1.0, width: 1.5, depth: 0.9, access: [8.2, 2.2], properties: [receptacle]}
  counter: {x: 4.0, y: 5.0, width: 2.0, depth: 0.6, access: [5.0, 4.4], properties: [receptacle]}
  fridge:  {x: 11.0, y: 1.0, width: 1.0, depth: 0.8, access: [11.5, 2.0], properties: [receptacle, openable],
            state: {open: false}}
  tv:      {x: 10.0, y: 6.5, width: 0.3, depth: 0.3, access: [10.0, 5.8], properties: [toggleable], state: {on: true}}
  fan:     {x: 8.0, y: 6.0, width: 0.3, depth: 0.3, access: [8.0, 5.4], properties: [toggleable], state: {on: false},
            words: [big fan, living room fan]}
  hamper:  {x: 1.0, y: 6.5, width: 0.6, depth: 0.6, access: [1.5, 5.8], properties: [receptacle]}
objects:
  boots:   {in: table, mass: 1, properties: [pickupable, washable], state: {dirty: true}, words: [football boots]}
  cup:     {in: table, mass: 1, properties: [pickupable, washable], state: {dirty: true}, words: [enamel cup]}
  chicken: {in: fridge, mass: 1, properties: [pickupable, sliceable]}
  socks:   {in: table, mass: 1, properties: [pickupable]}
robots:
  r1: {start: [1.0, 3.0], skills: {pickup: 1, open: 1, toggle: 1, slice: 1, wash: 1, heat: 1}}
"""


@pytest.fixture(scope="module")
def house() -> dict:
    return world_from_text(HOUSE, "yard-house.yaml")


@pytest.mark.parametrize("said, plain", [
    ("Tun off di TV", "switch off the tv"),
    ("tek di chicken outta di fridge an lef it pon di counter", "take the chicken out of the fridge and put it on the counter"),
    ("Lawd, di place hot eeh.", "switch on the fan"),
    ("the place is too hot", "switch on the fan"),
    ("wash off di football boots, bless", "wash the football boots"),
    ("Close back di fridge eeh", "close the fridge"),
    ("put di socks dem inna di hamper, seen?", "put the socks in the hamper"),
    ("wipe down the enamel cup", "wash the enamel cup"),
    ("Two ting: wash out di enamel cup, an close di fridge", "wash the enamel cup and close the fridge"),
    ("Two things: wash the enamel cup, and close the fridge", "wash the enamel cup and close the fridge"),
    # the where names the thing again: "the big fan" is the living room fan
    ("Tun on di big fan inna di living room", "switch on the fan"),
])
def test_jamaican_english_reads_as_its_plain_english(house: dict, said: str, plain: str) -> None:
    assert goal(said, house) == goal(plain, house)


def test_the_place_said_of_a_thing_keeps_its_reading(house: dict) -> None:
    """Only how it feels in the home is a cue: "the place is a mess" asks for nothing named."""
    with pytest.raises(PipflowError):
        goal("the place is a mess", house)


def test_lef_after_its_doer_is_what_was_done_never_an_order(house: dict) -> None:
    """"lef it pon di counter" asks to leave it; "unu lef di fridge open again" says what was done:
    read as an order it would keep the fridge open, the opposite of what is meant."""
    assert goal("lef di chicken pon di counter", house) == goal("put the chicken on the counter", house)
    try:
        got = goal("unu lef di fridge open again", house)
    except PipflowError:
        return
    assert "open" not in got.get("state", {}).get("fridge", [])

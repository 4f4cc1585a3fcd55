"""Issue 23, from the sixty-sixth sets (the dispatch supervisor of a mining-supplies warehouse in
Lusaka writing Zambian English, a grandmother in St. Philip, Barbados, speaking Bajan), after their
first measurements. Warehouse: a count said after a statement that changed it to another count is
refused, never read as the last word ("take 4 off P (it has 7 now)" had read as P holding 7: the
robots would have taken nothing off); Bemba and Nyanja greetings and thanks ("Mwaiseni!",
"natotela", "zikomo") set aside, and a word said only to the one asked opening a sentence without its
comma ("boss the counter shouldn't drop below 10"). Household: Bajan function words ("pun", "een", "doan", "muh",
"wunna", "gine", "all two", "out" for switch off, "he" / "she" as his / her and him / her, "nuh"
closing an order) and "cuhdear"; a name written as a name ("for Michelle", "Jamal coming home")
that the home's own words put before one thing ("michelle bed") is a person. Worlds of our own,
through the real readers; each rule with what stays as said or refused."""
from __future__ import annotations

import pytest

from pipflow.errors import PipflowError
from pipflow.household.world import world_from_text
from tests.readings import assert_warehouse_alike, household_goal as goal, read_warehouse

#: a mining-supplies depot
MATERO = {
    "name": "matero",
    "floor": {"width": 40, "height": 20},
    "shelves": {
        "front": {"x": 2, "y": 14, "width": 6, "depth": 2, "capacity": 60, "access": [5, 13], "words": ["front rack"]},
        "back": {"x": 12, "y": 14, "width": 6, "depth": 2, "capacity": 60, "access": [15, 13], "words": ["back rack"]},
        "yard": {"x": 26, "y": 14, "width": 4, "depth": 2, "capacity": 30, "access": [28, 13], "words": ["ramp"]},
    },
    "products": {"meal": {"color": "white", "words": ["mealie meal"]}, "oil": {"color": "yellow"},
                 "helmet": {"color": "red", "words": ["hard hat"]}},
    "stock": {"front": {"meal": 20, "oil": 6, "helmet": 4}, "back": {"meal": 4, "oil": 2, "helmet": 0},
              "yard": {"meal": 7, "oil": 0, "helmet": 5}},
    "robots": {"fork1": {"kind": "forklift", "start": [1, 8], "skills": {"carry": 8}},
               "amr1": {"kind": "amr", "start": [33, 8], "skills": {"carry": 2}}},
}


@pytest.mark.parametrize("said", [
    # a count said after the statement that changed it, as a remark or as an order: which is meant?
    "Take 4 mealie meal off the ramp (it has 7 bags of mealie meal now)",
    "take 4 mealie meal off the ramp, it has 7 mealie meal now",
    "Take 4 mealie meal off the ramp and the ramp should have 7 mealie meal",
    "Double the hard hats on the front rack, the front rack should have 6 hard hats",
    "Move 3 hard hats from the ramp to the back rack, the ramp should have 5 hard hats",
])
def test_a_count_that_would_undo_a_change_of_it_is_refused(said: str) -> None:
    with pytest.raises(PipflowError):
        read_warehouse(said, MATERO)


@pytest.mark.parametrize("said, plain", [
    # a count that agrees with the change says it again
    ("Move 3 oil from the front rack to the back rack and the back rack should have 5 oil",
     "move 3 oil from front to back"),
    # a count set first, then changed, is read in turn (empty, then bring)
    ("Clear the ramp, then bring 4 hard hats to it", "empty yard, then add 4 helmet to yard"),
    # Bemba and Nyanja greetings and thanks
    ("Mwaiseni! please kindly add 4 more oil on the back rack", "add 4 more oil to back"),
    ("Shani team, take 2 mealie meal off the front rack", "take 2 meal off front"),
    ("Clear the ramp. natotela", "empty yard"),
    ("Zikomo, send 5 mealie meal to the ramp", "send 5 meal to yard"),
    # a word said only to the one asked, opening a sentence without its comma
    ("boss the front rack shouldn't drop below 10 mealie meal", "front should have at least 10 meal"),
    ("Boss move 3 oil from the front rack to the back rack", "move 3 oil from front to back"),
])
def test_zambian_english_orders_read_as_their_plain_english(said: str, plain: str) -> None:
    assert_warehouse_alike(said, plain, MATERO)


#: a chattel house whose home names Michelle's bed and Jamal's desk and bed by their owners
CHATTEL = """
domain: household
name: chattel house
floor: {width: 16, height: 10}
places:
  counter:      {x: 3.0, y: 1.0, width: 1.5, depth: 0.6, access: [3.7, 1.8], properties: [receptacle]}
  fridge:       {x: 6.0, y: 1.0, width: 1.0, depth: 0.8, access: [6.5, 2.0], properties: [receptacle, openable],
                 state: {open: false}}
  cupboard:     {x: 1.0, y: 1.0, width: 1.0, depth: 0.6, access: [1.5, 1.8], properties: [receptacle, openable],
                 state: {open: false}}
  microwave:    {x: 8.0, y: 1.0, width: 0.6, depth: 0.6, access: [8.3, 1.8], properties: [receptacle, openable, heater],
                 state: {open: false}}
  kitchentable: {x: 8.0, y: 5.0, width: 1.0, depth: 0.6, access: [8.4, 4.4], properties: [receptacle],
                 words: [kitchen table]}
  centretable:  {x: 11.0, y: 5.0, width: 1.0, depth: 0.6, access: [11.4, 4.4], properties: [receptacle],
                 words: [centre table]}
  desk:         {x: 13.0, y: 8.0, width: 1.0, depth: 0.6, access: [13.4, 7.4], properties: [receptacle],
                 words: [jamal desk]}
  daybed:       {x: 10.0, y: 8.0, width: 1.6, depth: 0.8, access: [10.8, 7.4], properties: [receptacle],
                 words: [day bed]}
  bed:          {x: 14.0, y: 1.0, width: 1.6, depth: 1.0, access: [14.8, 2.2], properties: [receptacle],
                 words: [michelle bed]}
  kitchenlight: {x: 5.0, y: 9.0, width: 0.1, depth: 0.2, access: [5.0, 8.5], properties: [toggleable],
                 state: {on: true}, words: [kitchen light]}
objects:
  remote:     {in: daybed, mass: 1, properties: [pickupable]}
  plate:      {in: counter, mass: 1, properties: [pickupable, washable], state: {dirty: true}}
  cup:        {in: counter, mass: 1, properties: [pickupable, washable], state: {dirty: true}, words: [enamel cup]}
  schoolbag:  {in: daybed, mass: 1, properties: [pickupable], words: [school bag]}
  flyingfish: {in: fridge, mass: 1, properties: [pickupable, heatable], words: [flying fish]}
robots:
  wes: {start: [4.0, 3.0], skills: {pickup: 1, open: 1, toggle: 1, slice: 1, wash: 1, heat: 1}}
"""


@pytest.fixture(scope="module")
def chattel() -> dict:
    return world_from_text(CHATTEL, "chattel.yaml")


@pytest.mark.parametrize("said, plain", [
    ("put de remote pun de centre table", "put the remote on the centre table"),
    ("Tek de plate off de counter and put it een de cupboard", "put the plate in the cupboard"),
    ("Out de kitchen light", "switch off the kitchen light"),
    ("Cuhdear, out de kitchen light", "switch off the kitchen light"),
    ("wash de plate, cuhdear.", "wash the plate"),
    ("Wunna wash de plate and de enamel cup and put dem back pun de counter, nuh.",
     "wash the plate and the cup and put them on the counter"),
    ("Heat up de flying fish fuh he and put it pun de kitchen table",
     "heat up the flying fish and put it on the kitchen table"),
    # a name written as one, that the home puts before one thing's name, is a person
    ("Heat up the flying fish for Michelle", "heat up the flying fish"),
    ("Jamal coming home fuh lunch. Heat up de flying fish and put it pun de kitchen table.",
     "heat up the flying fish and put it on the kitchen table"),
    # each thing said with where it is taken off (the sixty-seventh round)
    ("Tek de school bag off de day bed and de plate off de counter and put all two pun de centre table",
     "put the school bag and the plate on the centre table"),
    # a capitalised word after "the" is a thing's name
    ("Turn off the Kitchen light", "switch off the kitchen light"),
    # "uh" in English is a hesitation
    ("Uh, put the plate in the cupboard", "put the plate in the cupboard"),
])
def test_bajan_reads_as_its_plain_english(chattel: dict, said: str, plain: str) -> None:
    assert goal(said, chattel) == goal(plain, chattel)


@pytest.mark.parametrize("said", [
    # a name in lower case before one thing's name may be a word of the thing: not taken for a person
    "Heat up the flying fish for michelle",
    # "doan" is don't: a negated order is not read as the order
    "Doan put de plate een de cupboard",
])
def test_what_the_bajan_rules_do_not_cover_stays_refused(chattel: dict, said: str) -> None:
    with pytest.raises(PipflowError):
        goal(said, chattel)

"""Issue 23, from pair RR's sixty-fifth sets (the shift supervisor of a drinks distributor's
warehouse in Kampala writing Ugandan English, a retired bus driver in Birmingham speaking Brummie),
after their first measurements. Both readers: words said only to the one asked ("bab", "duck",
Luganda "sebo", "nnyabo", "bambi") wherever a clause opens or closes with them, unless the world
names something by them. Warehouse: a place taken back by "no" set off by commas before the place
said again with its preposition ("to P, no, to Q"), sounds of hesitation before words that take
back a place or a count ("to P, ah no, to Q", "12, eh sorry 15"), a place said first and taken up
by "it" ("But the returns cage, leave it as it is") and "don't touch those ones" after a clause
that leaves something out. Household: Brummie "yow", "dow", "they'm" and "ta-ra-a-bit"; a word of
address before "and" that joins the next order, "though" closing a clause, and "bring it to me on
the armchair" (to the armchair). Worlds of our own, through the real readers; each rule with what
stays as said or refused."""
from __future__ import annotations

import pytest

from pipflow.errors import PipflowError
from pipflow.household.world import world_from_text
from pipflow.language.english import spoken_forms
from tests.readings import assert_warehouse_alike, household_goal as goal, read_warehouse

#: a drinks depot whose stock includes a product called "duck" (so "duck" is no word of address here)
KATWE = {
    "name": "katwe",
    "floor": {"width": 40, "height": 20},
    "shelves": {
        "front": {"x": 2, "y": 14, "width": 6, "depth": 2, "capacity": 60, "access": [5, 13], "words": ["front bay"]},
        "back": {"x": 12, "y": 14, "width": 6, "depth": 2, "capacity": 60, "access": [15, 13], "words": ["back bay"]},
        "yard": {"x": 26, "y": 14, "width": 4, "depth": 2, "capacity": 30, "access": [28, 13],
                 "words": ["loading yard"]},
    },
    "products": {"juice": {"color": "orange"}, "salt": {"color": "white"}, "duck": {"color": "brown"}},
    "stock": {"front": {"juice": 20, "salt": 6, "duck": 4}, "back": {"juice": 4, "salt": 2, "duck": 0},
              "yard": {"juice": 3, "salt": 0, "duck": 5}},
    "robots": {"fork1": {"kind": "forklift", "start": [1, 8], "skills": {"carry": 8}},
               "amr1": {"kind": "amr", "start": [33, 8], "skills": {"carry": 2}}},
}


@pytest.mark.parametrize("said, plain", [
    # Luganda words of address and asking, said in Ugandan English: "sebo" (sir), "nnyabo"
    # (madam), "bambi" (please); and a word of address closing a clause that is not the last
    ("Sebo, halve the juice in the front bay", "halve the juice on front"),
    ("Take 2 salt off the back bay bambi", "take 2 salt off back"),
    ("Send 7 juice to the back bay, nnyabo, and 2 salt to the yard", "send 7 juice to back and 2 salt to yard"),
    ("Move 3 salt to the yard, mate", "move 3 salt to yard"),
    # a place taken back: "no" set off by commas, or a hesitation before the words that take back
    ("Send 7 juice from the front bay to the back bay, no, to the yard", "send 7 juice from front to yard"),
    ("Send 7 juice from the front bay to the back bay, ah no, to the yard", "send 7 juice from front to yard"),
    ("Send 7 juice from the front bay to the back bay, um sorry, to the yard", "send 7 juice from front to yard"),
    # a count taken back after a hesitation
    ("Move 12, eh sorry 15 juice from the front bay to the yard", "move 15 juice from front to yard"),
    # a place said first and taken up by "it", with or without the comma; "don't touch those ones"
    # after a clause that leaves it as it is says it again
    ("Move 3 salt to the yard. The back bay, leave it as it is.", "move 3 salt to yard, leave back as it is"),
    ("Move 3 salt to the yard. But the back bay leave it as it is, don't touch those ones.",
     "move 3 salt to yard, leave back as it is"),
    ("The back bay, don't touch it. Move 3 salt to the yard", "leave back as it is, move 3 salt to yard"),
])
def test_ugandan_english_orders_read_as_their_plain_english(said: str, plain: str) -> None:
    assert_warehouse_alike(said, plain, KATWE)


@pytest.mark.parametrize("said", [
    # "duck" names a product here: no word of address, so the clause is no talk
    "Move 3 salt to the yard, duck",
    # "no" without a comma after it may open a rule ("no robots to Q"): left as said
    "Send 7 juice from the front bay to the back bay, no to the yard",
    # a hesitation alone takes nothing back
    "Send 7 juice from the front bay to the back bay, oh, to the yard",
    "Move 12, eh 15 juice from the front bay to the yard",
    # a place of another kind of preposition is no place taken back
    "Send 7 juice from the front bay to the back bay, no, from the yard",
    # a place said first is taken up only by a verb that leaves, keeps or changes it
    "Move 3 salt to the yard. The back bay, move it to the yard.",
    # "don't touch those ones" after a clause that leaves nothing out: which is not said
    "Move 3 salt to the yard, don't touch those ones.",
])
def test_what_the_ugandan_rules_do_not_cover_stays_refused(said: str) -> None:
    with pytest.raises(PipflowError):
        read_warehouse(said, KATWE)


@pytest.mark.parametrize("said, written", [
    ("they'm in the pantry", "they are in the pantry"),
    ("we\u2019m off out", "we are off out"),
    ("Put the kettle on. Ta-ra-a-bit.", "Put the kettle on. tara."),
    # "them" is no "they"; "I'm" stays
    ("them'm", "them'm"),
    ("I'm off", "I'm off"),
])
def test_brummie_spoken_forms_are_written_out(said: str, written: str) -> None:
    assert spoken_forms(said) == written


#: a semi whose fridge holds a roast duck (so "duck" names a thing of this home)
SEMI = """
domain: household
name: erdington semi
floor: {width: 16, height: 10}
places:
  side:      {x: 3.0, y: 1.0, width: 1.5, depth: 0.6, access: [3.7, 1.8], properties: [receptacle], words: [worktop]}
  fridge:    {x: 6.0, y: 1.0, width: 1.0, depth: 0.8, access: [6.5, 2.0], properties: [receptacle, openable],
              state: {open: true}}
  table:     {x: 8.0, y: 5.0, width: 1.0, depth: 0.6, access: [8.4, 4.4], properties: [receptacle],
              words: [kitchen table]}
  telly:     {x: 12.0, y: 8.0, width: 1.0, depth: 0.3, access: [12.5, 7.5], properties: [toggleable],
              state: {on: true}, words: [tv]}
  kettle:    {x: 5.0, y: 3.0, width: 0.3, depth: 0.3, access: [5.2, 3.8], properties: [toggleable],
              state: {on: false}}
objects:
  beans:     {in: side, mass: 1, properties: [pickupable]}
  duck:      {in: fridge, mass: 1, properties: [pickupable], words: [roast duck]}
  mug:       {in: table, mass: 1, properties: [pickupable, washable]}
robots:
  alf: {start: [4.0, 3.0], skills: {pickup: 1, open: 1, toggle: 1, slice: 1, wash: 1, heat: 1}}
"""


@pytest.fixture(scope="module")
def semi() -> dict:
    return world_from_text(SEMI, "erdington-semi.yaml")


@pytest.mark.parametrize("said, plain", [
    ("bab put the kettle on", "switch the kettle on"),
    ("bab, put the kettle on", "switch the kettle on"),
    ("love, put the kettle on", "switch the kettle on"),
    ("Put the kettle on bab, and switch the telly off", "switch the kettle on and switch the telly off"),
    ("Sling the beans on the table bab, and shut the fridge, ta", "put the beans on the table and close the fridge"),
    ("Mind yow shut the fridge after", "close the fridge"),
    ("Dow leave the fridge open", "close the fridge"),
    ("Put the beans in the fridge, they'm on the side", "put the beans in the fridge"),
    ("Put the kettle on. Ta-ra-a-bit.", "switch the kettle on"),
    # a word of address before "and" / "then" that join the next order; "though" closing a clause
    ("switch the kettle on bab and put the beans on the table",
     "switch the kettle on and put the beans on the table"),
    ("put the beans in the fridge love then switch the kettle on",
     "put the beans in the fridge, then switch the kettle on"),
    ("switch the kettle on, leave the mug on the table though", "switch the kettle on and put the mug on the table"),
    # where the speaker is, said after "to me", is where the thing goes
    ("bring the mug through to me on the table", "bring the mug to the table"),
])
def test_brummie_reads_as_its_plain_english(semi: dict, said: str, plain: str) -> None:
    assert goal(said, semi) == goal(plain, semi)


@pytest.mark.parametrize("said", [
    # the home names its roast "duck": never left out as a word of address
    "duck, put the kettle on",
    "Put the kettle on, duck",
    # "dow" is "don't": a negated order is not read as the order
    "Dow switch the telly off",
    # "duck" before "and" names the roast here
    "put the mug on the table duck and switch the kettle on",
    # "to me" and a place the home lacks: where is not said
    "bring the mug to me on the floor",
])
def test_what_the_brummie_rules_do_not_cover_stays_refused(semi: dict, said: str) -> None:
    with pytest.raises(PipflowError):
        goal(said, semi)

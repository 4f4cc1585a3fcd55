"""Issue 23, from pair JJ's sets (a night-shift lead in western Sydney writing Australian English, a
pharmacist in Beirut writing English with Lebanese Arabic and French), after their first
measurements. Warehouse: Australian talk ("G'day team", "too easy", "reckon that'll do"); "and can
you", "someone" asked to do it; "the whole P"; "swap P with Q"; "its" typed for "it's"; "this week"
as a time; "'s gotta", "has got to", "'s not to"; a time said before a place; "all night"; a hyphened
product word at the end never a signature; a count sent from one place to each of several. Household: a move said without its verb after a change;
"burning" of a light; a light cue in a home with no category of lights, and in a room the home's
words place another light in; a person the home's words say owns things with "'s"; a purpose said
first; "bas" for but; Lebanese and French talk; a thing kept where it is opens no container. Worlds of our own, through the real readers; each
rule with what stays as said or refused."""
from __future__ import annotations

import pytest

from pipflow.errors import PipflowError
from pipflow.household.world import world_from_text
from pipflow.warehouse.language.translator import understand
from tests.readings import assert_warehouse_alike, household_goal as goal

YARD = {
    "name": "ringwood",
    "floor": {"width": 40, "height": 20},
    "shelves": {
        "cage": {"x": 2, "y": 14, "width": 4, "depth": 2, "capacity": 60, "access": [4, 13], "words": ["grog cage"]},
        "face": {"x": 10, "y": 14, "width": 4, "depth": 2, "capacity": 60, "access": [12, 13], "words": ["pick face"]},
        "dock": {"x": 26, "y": 14, "width": 4, "depth": 2, "capacity": 40, "access": [28, 13], "words": ["loading dock"]},
    },
    "products": {"cider": {"color": "gold", "words": ["cider slab"]},
                 "biscuit": {"color": "brown", "words": ["Arno-Bix", "bikkie"]}},
    "stock": {"cage": {"cider": 10, "biscuit": 6}, "face": {"cider": 4, "biscuit": 8}, "dock": {"cider": 2, "biscuit": 3}},
    "robots": {"fork1": {"kind": "forklift", "start": [1, 8], "skills": {"carry": 8}},
               "amr1": {"kind": "amr", "start": [33, 8], "skills": {"carry": 2}}},
}


@pytest.mark.parametrize("said, plain", [
    ("Gday team. move 3 cider from grog cage to pick face", "move 3 cider from cage to face"),
    ("move 3 cider from grog cage to pick face, too easy", "move 3 cider from cage to face"),
    ("move 3 cider from grog cage to pick face, reckon thatll do", "move 3 cider from cage to face"),
    ("And can you bring 2 bikkie to the loading dock", "bring 2 biscuit to dock"),
    ("And someone bring 2 bikkie to the loading dock", "bring 2 biscuit to dock"),
    ("move 1 cider from grog cage to pick face and someone bring 2 bikkie to the loading dock",
     "move 1 cider from cage to face and bring 2 biscuit to dock"),
    ("Clear the whole loading dock out", "empty dock"),
    ("swap pick face with the loading dock", "swap face and dock"),
    ("swap whole pick face with grog cage , everything on em", "swap face and cage"),
    ("move half the cider in grog cage over to pick face , its friday and the pub will be chockers",
     "move half the cider from cage to face"),
    ("heaps of orders this week with school hols , can we double bikkie at pick face", "double biscuit at face"),
    ("pick face's gotta hold 5 cider", "face should have 5 cider"),
    ("pick face has got to hold 5 cider", "face should have 5 cider"),
    ("the weakest robot's not to go near grog cage", "the weakest robot is not to go near cage"),
    ("Tonight pick face wants at least 6 cider", "face should have at least 6 cider"),
    ("pick face shouldnt drop below 6 cider all night", "face should have at least 6 cider"),
    ("bring 2 bikkie to the loading dock , after smoko is fine", "bring 2 biscuit to dock"),
    ("pick face should have 5 Arno-Bix", "face should have 5 biscuit"),
    # a count sent from one place to each of several
    ("send 3 cider from grog cage to each of pick face and the loading dock",
     "move 3 cider from cage to face and move 3 cider from cage to dock"),
    ("send 2 cider to each of pick face and the loading dock, out of the grog cage",
     "move 2 cider from cage to face and move 2 cider from cage to dock"),
    ("leave the pick face as is tho", "keep face as it is"),
])
def test_australian_english_orders_read_as_their_plain_english(said: str, plain: str) -> None:
    assert_warehouse_alike(said, plain, YARD)


def test_a_hyphened_word_closing_the_command_is_no_signature() -> None:
    """ "... 5 Arno-Bix": a word joined by a hyphen is one word, never "- Bix" signing the message."""
    echo = " ".join(understand("pick face should have 5 Arno-Bix", YARD).get("explanation") or [])
    assert "signed" not in echo


@pytest.mark.parametrize("said", [
    # an instruction about a thing in a verb the reader lacks: never set aside as talk
    "move 2 cider from grog cage to pick face, recount them",
    # a report of what someone did is no order to anyone
    "someone moved 2 cider to the loading dock",
    # a swap names exactly two places
    "swap pick face with grog cage and the loading dock",
    # "its" before a thing of the world attaches to what was said
    "move 2 cider from grog cage to pick face, its bikkie",
    # all of a product cannot go to each of two places
    "send all the cider from grog cage to each of pick face and the loading dock",
])
def test_what_the_rules_do_not_cover_stays_refused(said: str) -> None:
    with pytest.raises(PipflowError):
        understand(said, YARD)


FLAT = """
domain: household
name: achrafieh flat
floor: {width: 16, height: 10}
places:
  sink:    {x: 1.0, y: 1.0, width: 1.0, depth: 0.6, access: [1.5, 1.8], properties: [receptacle, sink]}
  counter: {x: 3.0, y: 1.0, width: 1.5, depth: 0.6, access: [3.7, 1.8], properties: [receptacle]}
  fridge:  {x: 6.0, y: 1.0, width: 1.0, depth: 0.8, access: [6.5, 2.0], properties: [receptacle, openable],
            state: {open: false}, words: [frigo, le frigo]}
  oven:    {x: 8.0, y: 1.0, width: 1.0, depth: 0.8, access: [8.5, 2.0], properties: [receptacle, heater]}
  desk:    {x: 14.0, y: 1.0, width: 1.2, depth: 0.6, access: [14.6, 1.8], properties: [receptacle]}
  nightstand: {x: 14.0, y: 7.0, width: 0.6, depth: 0.6, access: [14.3, 6.5], properties: [receptacle],
               words: ["Rose's table", table de nuit]}
  kitchen_light: {x: 4.0, y: 3.0, width: 0.3, depth: 0.3, access: [4.2, 3.6], properties: [toggleable],
                  state: {on: true}}
  lustre: {x: 11.0, y: 6.0, width: 0.5, depth: 0.5, access: [11.2, 5.5], properties: [toggleable],
           state: {on: false}, words: [lounge light]}
objects:
  mug:     {in: sink, mass: 1, properties: [pickupable, washable], state: {dirty: true}}
  cup:     {in: counter, mass: 1, properties: [pickupable, washable], state: {dirty: true}}
  milk:    {in: fridge, mass: 1, properties: [pickupable]}
  tomato:  {in: counter, mass: 1, properties: [pickupable, sliceable]}
  pie:     {in: counter, mass: 1, properties: [pickupable, heatable]}
  rose_phone: {in: desk, mass: 1, properties: [pickupable], words: ["Rose's phone"]}
  rose_blanket: {in: desk, mass: 1, properties: [pickupable]}
  charcoal: {in: counter, mass: 1, properties: [pickupable], words: [fa7m]}
robots:
  r1: {start: [1.0, 3.0], skills: {pickup: 1, open: 1, toggle: 1, slice: 1, wash: 1, heat: 1}}
"""


@pytest.fixture(scope="module")
def flat() -> dict:
    return world_from_text(FLAT, "achrafieh-flat.yaml")


@pytest.mark.parametrize("said, plain", [
    # a move said without its verb, after a change no place makes or with "to"
    ("open the fridge, the milk to the counter", "open the fridge and put the milk on the counter"),
    ("wash the mug, the cup to the desk", "wash the mug and put the cup on the desk"),
    ("heat the pie, the tomato from the counter on the desk", "heat the pie and put the tomato on the desk"),
    ("the kitchen light is burning, switch it off", "switch off the kitchen light"),
    # a light cue where the home has no category of lights: the things named as lights
    ("the lounge is too dark", "switch on the lounge light"),
    ("it is too bright in the kitchen", "switch off the kitchen light"),
    # "Rose's phone", "Rose's table": Rose is a person though "rose" is an English word
    ("Rose is sleeping. switch off the kitchen light", "switch off the kitchen light"),
    ("take rose phone to her table de nuit", "take the rose phone to the table de nuit"),
    # what for, said first
    ("For dinner, cut the tomato", "cut the tomato"),
    ("for the kids heat the pie", "heat the pie"),
    ("For Rose's dinner, cut the tomato", "cut the tomato"),
    ("for rose cut the tomato", "cut the tomato"),
    # Lebanese Arabic and French talk; "bas": but
    ("heat the pie for the kids bas do not touch the milk", "heat the pie but do not touch the milk"),
    ("cut the tomato. Khalas that's all", "cut the tomato"),
    ("yalla, wash the mug s'il te plait, tayyeb?", "wash the mug"),
    ("close the fridge, don't leave it open like last time", "close the fridge"),
    ("wash the mug, Karim passed his exam \U0001F389", "wash the mug"),
    # a word the home declares with a digit among its letters (Arabic in Latin letters) is that thing
    ("put the fa7m on the desk", "put the charcoal on the desk"),
])
def test_levantine_english_reads_as_its_plain_english(flat: dict, said: str, plain: str) -> None:
    assert goal(said, flat) == goal(plain, flat)


def test_a_thing_kept_where_it_is_leaves_its_container_as_it_is(flat: dict) -> None:
    """ "don't touch the milk" keeps the milk in the closed fridge: no plan opens the fridge, so the
    goal asks nothing of its door; a thing taken out of it has the fridge closed again."""
    assert goal("do not touch the milk", flat) == {"in": {"fridge": ["milk"]}}
    assert goal("take the milk out of the fridge and put it on the counter", flat) == {
        "in": {"counter": ["milk"]}, "state": {"fridge": ["closed"]}}


def test_a_place_said_after_an_elided_change_is_where_the_change_is_made(flat: dict) -> None:
    """ "wash the mug, the cup in the sink": the sink washes, so both are washed there."""
    assert goal("wash the mug, the cup in the sink", flat) == goal("wash the mug and the cup in the sink", flat)


@pytest.mark.parametrize("said", [
    # the one light that is off is the lounge's by the home's words: never it, for the kitchen
    "it is too dark in the kitchen",
    # a purpose that names a thing of the home is no aside
    "for the fridge cut the tomato",
    # a number written into a word the home does not declare so is never read
    "put the m2g on the desk",
])
def test_what_the_rules_do_not_cover_in_the_flat_stays_refused(flat: dict, said: str) -> None:
    with pytest.raises(PipflowError):
        goal(said, flat)

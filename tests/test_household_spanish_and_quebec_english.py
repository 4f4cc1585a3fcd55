"""Issue 23, from pairs XX and YY's household sets (an architect in Bogotá writing Spanish English,
a nurse in Montréal writing Québec English): a word
the home spells both with and without its accent ("bed of zoë" beside "bed of zoe") is one word, so
"the Zoë bed" reads where the home says "zoe bed", and the plural of a declared word ("the empanadas" where
the home declares "empanada" with its accent) reads too; any other accented word stays under the
accent rule (refused where it could be a word the reader reads). "put the light of the hall" (a
fixed thing that switches, no place said: Spanish "poner la luz") is switching it on; a thing that
can be picked up, or a place said after it, keeps "put" as placing. Québec French words said in
English ("pis": then, "ferme": close, "réchauffe": heat) and its talk ("câline", "tsé", "bon"); "por
favor"; where a thing is said with "of" ("the blanket of the sofa to the table": from the sofa); an
adjective of colour or dirt said after the thing ("the mugs dirty of the table"), but never one the
verb may make so ("wash the mugs clean ..."). In
a house of our own, through the real reader."""
from __future__ import annotations

import pytest

from pipflow.errors import PipflowError
from pipflow.household.language.translator import translate
from pipflow.household.world import world_from_text
from tests.readings import household_goal as goal

HOUSE = """
domain: household
name: accents house
floor: {width: 14, height: 8}
places:
  sofa:      {x: 1.0, y: 1.0, width: 2.0, depth: 0.9, access: [2.0, 2.2], properties: [receptacle], words: [sofá, couch]}
  table:     {x: 7.5, y: 1.0, width: 1.5, depth: 0.9, access: [8.2, 2.2], properties: [receptacle]}
  oven:      {x: 9.5, y: 1.0, width: 0.8, depth: 0.6, access: [9.9, 1.8], properties: [receptacle, heater]}
  zoe_bed:   {x: 11.0, y: 5.0, width: 2.0, depth: 1.0, access: [12.0, 4.5], properties: [receptacle],
              words: [bed of zoe, bed of zoë, zoe bed]}
  hall_light: {x: 6.0, y: 6.0, width: 0.3, depth: 0.3, access: [6.0, 5.4], properties: [toggleable],
               state: {on: false}, words: [light of the hall]}
objects:
  empanada:  {in: table, mass: 1, properties: [pickupable, heatable], words: [empanadá]}
  blanket:   {in: sofa, mass: 1, properties: [pickupable]}
  desk_lamp: {in: table, mass: 1, properties: [pickupable, toggleable], state: {on: false}, words: [desk lamp]}
  red_mug:   {in: table, mass: 1, properties: [pickupable, washable], state: {dirty: true}, color: red, words: [red mug]}
  blue_mug:  {in: table, mass: 1, properties: [pickupable, washable], color: blue, words: [blue mug]}
  green_mug: {in: sofa, mass: 1, properties: [pickupable, washable], state: {dirty: true}, color: green,
              words: [green mug]}
robots:
  r1: {start: [1.0, 3.0], skills: {pickup: 1, open: 1, toggle: 1, slice: 1, wash: 1, heat: 1}}
"""


@pytest.fixture(scope="module")
def house() -> dict:
    return world_from_text(HOUSE, "accents-house.yaml")


@pytest.mark.parametrize("said, plain", [
    ("take the blanket to the Zoë bed", "take the blanket to the bed of zoe"),
    ("take the blanket from the sofá to the bed of zoe", "take the blanket from the sofa to the bed of zoe"),
    ("heat the empanadás", "heat the empanada"),
    ("put the light of the hall", "switch on the light of the hall"),
    ("put the light of the hall and take the blanket to the bed of zoe",
     "switch on the light of the hall and take the blanket to the bed of zoe"),
    ("put the light of the hall pis take the blanket to the bed of zoe",
     "switch on the light of the hall, then take the blanket to the bed of zoe"),
    ("ferme the light of the hall", "switch off the light of the hall"),
    ("réchauffe the empanada, câline", "heat the empanada"),
    ("Bon. take the blanket to the table, tsé", "take the blanket to the table"),
    ("take the blanket to the table por favor", "take the blanket to the table"),
    ("Ay, take the blanket to the table, listo?", "take the blanket to the table"),
    ("Allora, take the blanket to the table. Grazie", "take the blanket to the table"),
    ("Ela, take the blanket to the table, efharisto", "take the blanket to the table"),
    ("Re paidia, take the blanket to the table. Endaxi?", "take the blanket to the table"),
    # a setting given to a thing that switches ("put the oven at 180": Italian "metti il forno a 180")
    ("put the light of the hall at 3", "switch on the light of the hall"),
    ("set the light of the hall to 20 degrees", "switch on the light of the hall"),
    # a thing named first and taken up by "it" at once after its verb, with no comma ("il frigo chiudilo")
    ("the blanket take it to the table", "take the blanket to the table"),
    ("The light of the hall switch it on", "switch on the light of the hall"),
    # where a thing is, said with "of" (Spanish "de")
    ("take the blanket of the sofa to the bed of zoe", "take the blanket from the sofa to the bed of zoe"),
    ("the blanket of the sofa to the table", "take the blanket from the sofa to the table"),
    ("put the blanket of the sofa on the table", "put the blanket from the sofa on the table"),
    ("heat the empanada of the table", "heat the empanada on the table"),
    # an adjective of colour or dirt said after the thing
    ("wash the mugs dirty of the table", "wash the dirty mugs on the table"),
    ("take the mug blue of the table to the sofa", "take the blue mug from the table to the sofa"),
])
def test_read_as_the_plain_words(house: dict, said: str, plain: str) -> None:
    assert goal(said, house) == goal(plain, house)


def test_put_of_a_thing_that_can_be_picked_up_still_asks_where(house: dict) -> None:
    with pytest.raises(PipflowError, match="where"):
        translate("put the desk lamp", house)


def test_put_a_fixed_light_with_a_place_is_no_switching(house: dict) -> None:
    with pytest.raises(PipflowError):
        translate("put the light of the hall on the table", house)


def test_an_accent_the_home_does_not_declare_stays_refused(house: dict) -> None:
    """"blánket" is spelled so nowhere in the home: an accent may make it another word."""
    with pytest.raises(PipflowError, match="LATIN SMALL LETTER A WITH ACUTE"):
        translate("take the blánket to the table", house)


def test_of_before_no_place_keeps_its_meaning(house: dict) -> None:
    """"the blanket of zoe" says whose, not where: "of" is read as before (the home names no such
    owner, so the command is refused, never read as a where)."""
    with pytest.raises(PipflowError):
        translate("take the blanket of zoe to the table", house)


def test_an_adjective_the_verb_may_make_so_stays_after_the_thing(house: dict) -> None:
    """"wash the mugs clean in ..." may say what washing does: never read as "the clean mugs"."""
    try:
        got = goal("wash the mugs clean of the table", house)
    except PipflowError:
        return
    assert got != goal("wash the clean mugs on the table", house)


def test_a_setting_of_what_does_not_switch_is_no_switching(house: dict) -> None:
    with pytest.raises(PipflowError):
        translate("put the blanket at 3", house)

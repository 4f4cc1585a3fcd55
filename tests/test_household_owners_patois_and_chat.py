"""Issue 23, from pairs UU and VV's household sets (a mother in Seoul writing Konglish, a
grandmother in Portmore writing Jamaican Creole): whose a thing is said without "'s" ("Jiho robot
on sofa take to his bed"), a thing's place said with it before its verb (where it comes from),
Korean chat's "ㅠㅠ", "ㅋㅋ", "please~" and "Fighting!", "after washing," (then), Jamaican Creole's
function words ("tek di cup outa di sink", "di plate dem", "mi cup", "pon"), "yuh hear?", "wash
out", "the two plates" where the home has two, "when it hot" (the copula left out) and a
condition said in Creole; a number written into a word (Arabizi, pair WW) is never a count. In a house of our own, through the real reader; each rule with what
stays refused."""
from __future__ import annotations

import pytest

from pipflow.errors import PipflowError
from pipflow.household.language.translator import translate
from pipflow.household.world import world_from_text
from tests.readings import household_goal as goal

HOUSE = """
domain: household
name: owners house
floor: {width: 14, height: 8}
categories:
  plate: {words: [plate, plates]}
  toy: {words: [toy, toys]}
places:
  sofa:      {x: 1.0, y: 1.0, width: 2.0, depth: 0.9, access: [2.0, 2.2], properties: [receptacle]}
  sink:      {x: 4.0, y: 1.0, width: 0.8, depth: 0.6, access: [4.4, 1.8], properties: [receptacle, sink]}
  cupboard:  {x: 5.5, y: 1.0, width: 1.0, depth: 0.6, access: [6.0, 1.8], properties: [receptacle, openable], state: {open: false}}
  table:     {x: 7.5, y: 1.0, width: 1.5, depth: 0.9, access: [8.2, 2.2], properties: [receptacle]}
  stove:     {x: 9.5, y: 1.0, width: 0.8, depth: 0.6, access: [9.9, 1.8], properties: [receptacle, heater]}
  jiho_bed:  {x: 11.0, y: 5.0, width: 2.0, depth: 1.0, access: [12.0, 4.5], properties: [receptacle], words: [Jiho bed]}
  jiho_desk: {x: 11.0, y: 2.0, width: 1.2, depth: 0.6, access: [11.6, 2.8], properties: [receptacle], words: [Jiho desk]}
  nan_bed:   {x: 1.0, y: 5.0, width: 2.0, depth: 1.0, access: [2.0, 4.5], properties: [receptacle], words: [grandmother bed]}
  lamp:      {x: 6.0, y: 6.0, width: 0.3, depth: 0.3, access: [6.0, 5.4], properties: [toggleable], state: {on: true}}
objects:
  robot_toy:   {in: sofa, mass: 1, properties: [pickupable], categories: [toy], words: [robot toy, Jiho robot]}
  doll:        {in: sofa, mass: 1, properties: [pickupable], categories: [toy], words: [Elsa doll]}
  glasses:     {in: sofa, mass: 1, properties: [pickupable], words: [reading glasses]}
  mug:         {in: table, mass: 1, properties: [pickupable, washable], state: {dirty: true}, words: [husband mug]}
  cup:         {in: sink, mass: 1, properties: [pickupable, washable], state: {dirty: true}}
  spoon:       {in: sink, mass: 1, properties: [pickupable, washable], state: {dirty: true}}
  white_plate: {in: sink, mass: 1, properties: [pickupable, washable], state: {dirty: true}, categories: [plate], words: [white plate]}
  blue_plate:  {in: sink, mass: 1, properties: [pickupable, washable], state: {dirty: true}, categories: [plate], words: [blue plate]}
  soup:        {in: table, mass: 1, properties: [pickupable, heatable]}
robots:
  r1: {start: [1.0, 3.0], skills: {pickup: 1, open: 1, toggle: 1, slice: 1, wash: 1, heat: 1}}
  r2: {start: [8.0, 3.0], skills: {pickup: 1, open: 1, toggle: 1, slice: 1, wash: 1, heat: 1}}
"""


@pytest.fixture(scope="module")
def house() -> dict:
    return world_from_text(HOUSE, "owners-house.yaml")


@pytest.mark.parametrize("said, plain", [
    # whose, said without "'s": a name that owns two things of the home, or a kinship word
    ("Jiho robot on sofa take to his bed", "take the robot toy from the sofa to Jiho bed"),
    ("put husband glasses on the table", "put the reading glasses on the table"),
    ("the cup on the sink bring to the table", "bring the cup from the sink to the table"),
    # Korean chat
    ("wash the cup please~ ㅠㅠ", "wash the cup"),
    ("wash the cup ㅋㅋ", "wash the cup"),
    ("wash the cup. Fighting!", "wash the cup"),
    ("wash the spoon. After washing, put it in the cupboard", "wash the spoon, then put it in the cupboard"),
    # Jamaican Creole
    ("tek di cup outa di sink an put it pon di sofa", "take the cup out of the sink and put it on the sofa"),
    ("wash di plate dem", "wash the plates"),
    ("wash the cup, yuh hear?", "wash the cup"),
    ("wash out the spoon", "wash the spoon"),
    ("wash the two plates", "wash the white plate and the blue plate"),
    ("heat the soup an when it hot put it pon di table", "heat the soup, then put it on the table"),
    ("If di lamp on, turn it off, yuh hear?", "turn off the lamp"),
])
def test_read_as_the_plain_order(house: dict, said: str, plain: str) -> None:
    assert goal(said, house) == goal(plain, house)


@pytest.mark.parametrize("said", [
    "put Elsa cup in the sink",            # a capital before one thing's name is no owner: no such cup
    "wash the three plates",               # the home has two
    "wash the spoon. after drying, put it in the cupboard",   # no drying said before: no step to wait for
    "put the cup in the den",              # one English "den" is no Creole "then"; the home has no den
    "wash the cup ㅠ",                     # one jamo alone may be a slip of a word
])
def test_what_stays_refused(house: dict, said: str) -> None:
    with pytest.raises(PipflowError):
        translate(said, house)


@pytest.mark.parametrize("said, word", [("7oto the cup 3al table", "hoto"), ("wash the cup e5salo", "ekhsalo")])
def test_a_number_written_into_a_word_is_never_a_count(house: dict, said: str, word: str) -> None:
    """Arabizi writes digits for letters ("3al": on, "5alas": done); split from its word, the digit
    would be read as a count of what follows. Since pair GG the word is spelt in letters first
    (:mod:`pipflow.language.arabizi`): a word no lexicon knows is refused, quoted as spelt, and no
    count is read."""
    with pytest.raises(PipflowError, match=word):
        translate(said, house)


def test_arabizi_talk_spelt_in_letters_is_talk(house: dict) -> None:
    """ "ma3lesh" (maalesh: never mind) spelt in letters is the talk it is; "5alas" stays refused:
    its letters are an English word ("alas"), so the 5 may be a count glued to it."""
    assert goal("wash the cup ma3lesh", house) == goal("wash the cup", house)
    with pytest.raises(PipflowError, match="number written into a word"):
        translate("wash the cup 5alas", house)


def test_a_time_or_ordinal_written_with_its_number_is_no_such_word(house: dict) -> None:
    assert goal("wash the cup, guests come at 8pm", house) == goal("wash the cup", house)

"""Issue 23, from pairs SS and TT's household sets (a retired teacher in Hamburg who learned English
at school, a working mother in Chennai writing in Indian English): "keep in the cupboard" with its
object left out; "only after that" and "after that only" (then); "the one in Nana's room" after the kind it stands for; German's
"make the kettle on", "make out the light", "the kettle make on"; "..., only X not" and "..., only X
stays on" after a selection of all (except X); "be so kind as to"; a two-word signature; "nobody
watches"; "..., otherwise she will forget". In a flat of our own, through the real reader; each
rule with what stays refused."""
from __future__ import annotations

import pytest

from pipflow.errors import TranslationError
from pipflow.household.language.translator import translate
from pipflow.household.world import world_from_text
from tests.readings import household_goal as goal

FLAT = """
domain: household
name: learned flat
floor: {width: 12, height: 6}
categories:
  fan: {words: [fan, fans]}
places:
  worktop:    {x: 1.0, y: 1.0, width: 1.5, depth: 0.6, access: [1.75, 1.8], properties: [receptacle]}
  cupboard:   {x: 3.0, y: 1.0, width: 1.0, depth: 0.6, access: [3.5, 1.8], properties: [receptacle, openable], state: {open: false}}
  fridge:     {x: 5.0, y: 1.0, width: 0.8, depth: 0.7, access: [5.4, 1.9], properties: [receptacle, openable], state: {open: false}}
  microwave:  {x: 6.5, y: 1.0, width: 0.5, depth: 0.5, access: [6.7, 1.8], properties: [receptacle, openable, heater], state: {open: false}}
  hall_fan:   {x: 8.0, y: 5.8, width: 0.1, depth: 0.1, access: [8.0, 5.2], properties: [toggleable], state: {on: true}, categories: [fan], words: [hall fan]}
  dining_fan: {x: 9.5, y: 5.8, width: 0.1, depth: 0.1, access: [9.5, 5.2], properties: [toggleable], state: {on: true}, categories: [fan], words: [dining fan]}
  nana_fan:   {x: 11.0, y: 5.8, width: 0.1, depth: 0.1, access: [11.0, 5.2], properties: [toggleable], state: {on: true}, categories: [fan], words: [nana's fan, nana's room fan]}
  radio:      {x: 7.0, y: 3.0, width: 0.3, depth: 0.3, access: [7.2, 3.6], properties: [toggleable], state: {on: true}}
objects:
  cup:    {in: worktop, mass: 1, properties: [pickupable, washable], state: {dirty: true}}
  pan:    {in: worktop, mass: 1, properties: [pickupable, washable], state: {dirty: true}}
  onion:  {in: worktop, mass: 1, properties: [pickupable, sliceable]}
  curry:  {in: fridge, mass: 1, properties: [pickupable, heatable]}
  milk:   {in: fridge, mass: 1, properties: [pickupable, heatable]}
  kettle: {in: worktop, mass: 1, properties: [pickupable, toggleable], state: {on: false}}
robots:
  r1: {start: [1.0, 4.0], skills: {pickup: 1, open: 1, toggle: 1, slice: 1, wash: 1, heat: 1}}
  r2: {start: [6.0, 4.0], skills: {pickup: 1, open: 1, toggle: 1, slice: 1, wash: 1, heat: 1}}
"""


@pytest.fixture(scope="module")
def flat() -> dict:
    return world_from_text(FLAT, "learned-flat.yaml")


@pytest.mark.parametrize("said, plain", [
    ("wash the cup and keep in the cupboard", "wash the cup and put it in the cupboard"),
    ("first put the cup in the cupboard, only after that put the pan on the worktop",
     "put the cup in the cupboard, then put the pan on the worktop"),
    ("put the cup in the cupboard, after that only put the pan on the worktop",
     "put the cup in the cupboard, then put the pan on the worktop"),
    ("switch off all the fans except the one in Nana's room", "switch off all the fans except nana's fan"),
    ("make the kettle on", "switch on the kettle"),
    ("make out the hall fan", "switch off the hall fan"),
    ("wash the pan, and the kettle make on please", "wash the pan and switch on the kettle"),
    ("make all the fans out, only the hall fan stays on", "switch off all the fans except the hall fan"),
    ("switch off all the fans, only the dining fan not", "switch off all the fans except the dining fan"),
    ("would you be so kind as to wash the cup", "wash the cup"),
    ("please wash the cup. With kind regards, Ingrid Thode.", "wash the cup"),
    ("switch off the radio, nobody listens", "switch off the radio, nobody is listening"),
    ("keep the cup on the worktop otherwise she will forget", "put the cup on the worktop"),
])
def test_said_as_learned(said: str, plain: str, flat) -> None:
    assert goal(said, flat) == goal(plain, flat)


@pytest.mark.parametrize("said", [
    "switch off the dining fan, only the hall fan not",    # no selection of all: "only" as always
    "put the cup for the fridge",                          # "for" after a move may say where: refused
    "heat the milk for the worktop",                       # "for" a place may say where it goes: refused
    "cut the onion for the curry",                         # "for" a thing of the home: kept, refused
    "make the bed",                                        # "make" of what does not switch
    "keep the cup on the worktop otherwise leave it",      # what "otherwise" opens is no prediction
])
def test_what_stays_refused(said: str, flat) -> None:
    with pytest.raises(TranslationError):
        translate(said, flat)


def test_the_echo_says_how_each_was_read(flat) -> None:
    notes = " ".join(translate("make all the fans out, only the hall fan stays on", flat)["notes"])
    assert "read as 'switch ... off' (German" in notes and "read as 'except the hall fan'" in notes

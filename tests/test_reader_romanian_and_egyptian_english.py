"""Issue 23, from pair GG's sets (a night-shift coordinator near Bucharest writing Romanian English,
a pharmacist in Cairo writing English with Egyptian Arabic in Latin letters), after their first
measurement. Warehouse: a word the world declares for a place that looks like a kind word and a
number ("rack 2" for raft2) names that place, where it was looked up as a place numbered 2 and
refused (35 of the set's 45 refusals); "palettes" as pallets; Romanian talk ("te rog", "frate",
"gata", "hai", "mersi"); "nobody touches P" (keep it). Household: Arabizi, Arabic typed with digits
for letters ("ya3ni", "ma3lesh"), spelt in letters before numbers are split from words, so a digit
inside a word is never a count; "el" the article and "w" (and) in a command that speaks Arabic;
Egyptian talk ("yalla", "khalas", "mashi", "shokran"). Worlds of our own, through the real readers;
each rule with what stays as said or refused."""
from __future__ import annotations

import pytest

from pipflow.errors import PipflowError
from pipflow.household.world import world_from_text
from pipflow.language.arabizi import spelt_in_letters
from pipflow.warehouse.language.translator import understand
from tests.readings import assert_warehouse_alike, household_goal as goal

STORE = {
    "name": "regalstore",
    "floor": {"width": 40, "height": 20},
    "shelves": {
        "regal1": {"x": 2, "y": 14, "width": 4, "depth": 2, "capacity": 60, "access": [4, 13], "words": ["rack 1"]},
        "regal2": {"x": 10, "y": 14, "width": 4, "depth": 2, "capacity": 60, "access": [12, 13], "words": ["rack 2"]},
        "rampa": {"x": 26, "y": 14, "width": 4, "depth": 2, "capacity": 60, "access": [28, 13], "words": ["dock"]},
    },
    "products": {"faina": {"color": "white", "words": ["flour"]}, "apa": {"color": "blue", "words": ["water"]}},
    "stock": {"regal1": {"faina": 10, "apa": 4}, "regal2": {"faina": 6, "apa": 6}, "rampa": {"faina": 2, "apa": 3}},
    "robots": {"ursu": {"kind": "forklift", "start": [1, 8], "skills": {"carry": 8}},
               "costel": {"kind": "amr", "start": [33, 8], "skills": {"carry": 2}}},
}


@pytest.mark.parametrize("said, plain", [
    ("move 3 flour from rack 2 to dock", "move 3 faina from regal2 to rampa"),
    ("rack one should have 12 flour", "regal1 should have 12 faina"),
    ("Move 5 palettes of flour from rack 1 to dock, gata", "move 5 faina from regal1 to rampa"),
    ("te rog add 6 more palettes of water on dock", "add 6 apa to rampa"),
    ("Hai, double the water on dock. Mersi!", "double the apa on rampa"),
    ("frate, empty the dock", "empty rampa"),
    ("nobody touches rack 2", "keep regal2 as it is"),
    ("Rack 2 nobody touches tonight", "keep regal2 as it is"),
])
def test_romanian_english_orders_read_as_their_plain_english(said: str, plain: str) -> None:
    assert_warehouse_alike(said, plain, STORE)


@pytest.mark.parametrize("said", [
    "move 3 flour from rack 3 to dock",   # no place is called so: refused, never another rack
    "move 3 flour from rack 2, rack 2 nobody",
])
def test_a_place_the_world_does_not_declare_stays_refused(said: str) -> None:
    with pytest.raises(PipflowError):
        understand(said, STORE)


@pytest.mark.parametrize("typed, spelt", [
    ("ya3ni", "yaani"), ("ma3lesh", "maalesh"), ("wes5a", "weskha"), ("3ashan", "aashan"), ("2ahwa", "ahwa"),
    # a count glued to a unit, a time or an ordinal, and a name with a digit in it, stay as typed
    ("3boxes", "3boxes"), ("8pm", "8pm"), ("3am", "3am"), ("22nd", "22nd"), ("bay2a", "bay2a"), ("10x", "10x"),
])
def test_arabizi_is_spelt_in_letters_and_counts_stay_counts(typed: str, spelt: str) -> None:
    english = {"boxes", "pm", "am", "nd", "bay2a", "x"}.__contains__
    assert spelt_in_letters(f"put it there {typed}", english, []) == f"put it there {spelt}"


HOUSE = """
domain: household
name: balcony flat
floor: {width: 14, height: 8}
places:
  sink:    {x: 1.0, y: 1.0, width: 1.0, depth: 0.6, access: [1.5, 1.8], properties: [receptacle, sink]}
  table:   {x: 7.5, y: 1.0, width: 1.5, depth: 0.9, access: [8.2, 2.2], properties: [receptacle]}
  fridge:  {x: 11.0, y: 1.0, width: 1.0, depth: 0.8, access: [11.5, 2.0], properties: [receptacle, openable],
            state: {open: false}, words: [talaga]}
objects:
  cup:     {in: table, mass: 1, properties: [pickupable, washable], state: {dirty: true}}
  plate:   {in: table, mass: 1, properties: [pickupable, washable], state: {dirty: true}}
  melon:   {in: table, mass: 1, properties: [pickupable, sliceable], words: [batikha]}
robots:
  r1: {start: [1.0, 3.0], skills: {pickup: 1, open: 1, toggle: 1, slice: 1, wash: 1, heat: 1}}
"""


@pytest.fixture(scope="module")
def house() -> dict:
    return world_from_text(HOUSE, "balcony-flat.yaml")


@pytest.mark.parametrize("said, plain", [
    ("put el cup in el sink ya3ni", "put the cup in the sink"),
    ("yalla wash el cup w close el talaga, khalas", "wash the cup and close the fridge"),
    ("slice el batikha w put it in el talaga, shokran", "slice the melon and put it in the fridge"),
    ("ma3lesh, put the plate in the sink", "put the plate in the sink"),
])
def test_egyptian_english_reads_as_its_plain_english(house: dict, said: str, plain: str) -> None:
    assert goal(said, house) == goal(plain, house)


def test_w_is_with_where_the_command_speaks_no_arabic(house: dict) -> None:
    """ "w" is "and" only in a command that says an Arabic word; in English chat it is "with"."""
    with pytest.raises(PipflowError):
        goal("put the cup w the plate in the sink", house)


def test_a_digit_glued_to_a_word_is_still_refused_where_it_may_be_a_count(house: dict) -> None:
    with pytest.raises(PipflowError, match="number written into a word"):
        goal("put 2cups in the sink", house)

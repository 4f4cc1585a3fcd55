"""Issue 23, from pairs SS and TT's warehouse sets (a supervisor in the Gulf, a night-shift lead
writing English with Portuguese beside it): a spelling with accents that the world itself declares
("açaí", "câmara 1") is that thing, while every other accented word stays talk or refused; a
numbered place's declared word said with its number apart ("loading bay 3"); chat's slashed
abbreviations ("w/o", "w/", "p/"); "cx" for boxes; "P must stay with 6 X", "P cannot stay with less
than 8 X"; "swap P and Q, everything"; "divide ... between P and Q, half half"; "the robots must
take ..."; thanks, greetings and laughter of Brazilian Portuguese and Gulf Arabic chat. In a world
of our own (a fruit cold store), through the real reader; each rule with what stays refused."""
from __future__ import annotations

import pytest

from pipflow.errors import TranslationError
from pipflow.warehouse.language.translator import understand

COLDSTORE = {
    "name": "coldstore",
    "floor": {"width": 40, "height": 20},
    "shelves": {
        "room1": {"x": 2, "y": 14, "width": 4, "depth": 2, "capacity": 30, "access": [4, 13],
                  "words": ["câmara 1", "camara 1"]},
        "room2": {"x": 10, "y": 14, "width": 4, "depth": 2, "capacity": 30, "access": [12, 13]},
        "bay4": {"x": 18, "y": 14, "width": 4, "depth": 2, "capacity": 30, "access": [20, 13],
                 "words": ["loading bay 4"]},
        "bay6": {"x": 28, "y": 14, "width": 4, "depth": 2, "capacity": 30, "access": [30, 13],
                 "words": ["loading bay 6"]},
    },
    "products": {"acai": {"color": "purple", "words": ["açaí"]}, "mango": {"color": "orange"},
                 "guava": {"color": "pink"}},
    "stock": {"room1": {"acai": 10, "mango": 4}, "room2": {"acai": 6, "guava": 8},
              "bay4": {"acai": 1}, "bay6": {"mango": 2}},
    "robots": {"fork1": {"kind": "forklift", "start": [1, 8], "skills": {"carry": 8}},
               "fork2": {"kind": "forklift", "start": [15, 8], "skills": {"carry": 6}},
               "amr1": {"kind": "amr", "start": [25, 8], "skills": {"carry": 2}}},
}


def _read(said: str) -> dict:
    return understand(said, COLDSTORE)


@pytest.mark.parametrize("said, plain", [
    ("move 4 açaí from câmara 1 to bay 4", "move 4 acai from room1 to bay4"),
    ("move 4 AÇAÍ from Câmara 1 to bay 4", "move 4 acai from room1 to bay4"),
    ("move 4 mango from room 1 to loading bay 6", "move 4 mango from room1 to bay6"),
    ("Loading bay 6 should have 5 mango", "bay6 should have 5 mango"),
    ("move 3 mango to bay 6 w/o fork1", "move 3 mango to bay6 without fork1"),
    ("move 4 cx mango from room 1 to bay 6", "move 4 mango from room1 to bay6"),
    ("move 3 guava to bay 6 p/ the morning truck", "move 3 guava to bay6"),
    ("bay 4 must to stay with 3 guava, bay 6 too", "bay4 should have 3 guava and bay6 should have 3 guava"),
    ("room 2 cannot stay with less than 3 guava", "room2 should have at least 3 guava"),
    ("attention! swap bay 4 and bay 6, everything, the trucks changed doors kkkk",
     "swap everything between bay4 and bay6"),
    ("divide 6 guava of room 2 between bay 4 and bay 6, half half",
     "split 6 guava from room2 evenly between bay4 and bay6"),
    ("the robots must to take 2 mango from room 1 to bay 4", "move 2 mango from room1 to bay4"),
    ("bom dia pessoal, take 2 mango from room 1 to bay 4, valeu", "move 2 mango from room1 to bay4"),
    ("take 2 guava off room 2, the client cancelled rsrs vlw", "take 2 guava off room2"),
    ("yalla, move 2 mango from room 1 to bay 4 inshallah", "move 2 mango from room1 to bay4"),
    ("move 2 mango from room 1 to bay 4, beleza?", "move 2 mango from room1 to bay4"),
    ("Anh em, move 2 mango from room 1 to bay 4 nha", "move 2 mango from room1 to bay4"),
])
def test_said_as_the_floor_writes_it(said: str, plain: str) -> None:
    assert _read(said)["goal"] == _read(plain)["goal"]
    assert _read(said).get("constraints") == _read(plain).get("constraints")


def test_a_declared_spelling_is_said_in_the_echo() -> None:
    said = _read("move 4 açaí from câmara 1 to bay 4")
    assert said["order"]["corrected"] == ["'câmara 1' read as room1 (a spelling this world declares)",
                                          "'açaí' read as acai (a spelling this world declares)"]
    assert said["explanation"][:2] == said["order"]["corrected"]


@pytest.mark.parametrize("said, why", [
    ("move 4 açai from room 1 to bay 4", "not one of the letters"),     # an accent the world did not declare
    ("swap só the guava between room 2 and bay 4", "not one of the letters"),  # "só" is no "so"
    ("move 4 mango from room 1 to loading bay 5", "names no shelf"),   # no bay 5
    ("move 4 mango from room 1 to bay 4 and/or bay 6", "symbol '/'"),   # any other slash: refused
    ("2 mango p/ bay 4 from room 1", "cannot place"),                  # "for" a place is no "to"
])
def test_what_stays_refused(said: str, why: str) -> None:
    with pytest.raises(TranslationError, match=why):
        _read(said)


def test_a_count_after_a_declared_numbered_place_is_still_a_count() -> None:
    """ "loading bay 4 3 mango more": bay4, then a count of 3; the declared word takes only its own
    number."""
    assert _read("move 3 mango from room 1 to loading bay 4")["goal"] == {"room1": {"mango": 1}, "bay4": {"mango": 3}}
    assert _read("loading bay 4 3 mango more")["goal"] == {"bay4": {"mango": 3}}


KITCHEN = """
domain: household
name: accented kitchen
floor: {width: 8, height: 5}
places:
  worktop: {x: 1.0, y: 1.0, width: 1.5, depth: 0.6, access: [1.75, 1.8], properties: [receptacle]}
  cupboard: {x: 4.0, y: 1.0, width: 1.0, depth: 0.6, access: [4.5, 1.8], properties: [receptacle, openable], state: {open: false}}
objects:
  muesli: {in: worktop, mass: 1, properties: [pickupable], words: [müsli, muesli]}
robots:
  r1: {start: [1.0, 3.0], skills: {pickup: 1, open: 1}}
"""


def test_a_home_reads_its_own_accented_words_and_no_other() -> None:
    from pipflow.household.language.translator import translate
    from pipflow.household.world import world_from_text
    home = world_from_text(KITCHEN, "accented-kitchen.yaml")
    assert translate("Put the Müsli in the cupboard.", home)["goal"]["in"] == {"cupboard": ["muesli"]}
    with pytest.raises(TranslationError, match="not one of the letters"):
        translate("Put the müslí in the cupboard.", home)   # an accent the home did not declare

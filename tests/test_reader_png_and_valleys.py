"""Issue 23, from the sixty-seventh sets (the storeman-supervisor of a hardware warehouse at Lae
writing Papua New Guinea English with Tok Pisin; a grandmother in a terraced house in Treorchy
speaking Valleys English), after their first measurements. Warehouse: a
word for people ("boys", "boi", "lads") after a robot kind, tag or superlative, or before "that
carry ...", names those robots ("the night shift boys keep out of P"); said alone it is no robot
group. Tok Pisin words that are no English word ("tekim", "wanpela", "plis", "orait", "emi") read
as their English words. "Change of plan" opening a command is set aside; after an order it is
refused (it would take the order back). "P keeps its X as it is" keeps them; a sentence's only
goods said again at its end ("..., just the simen") narrow nothing and are set aside. Household:
Welsh words of talk ("cariad", "mun", "duw") are set aside; a list whose every thing is said with
"off" a place is read as "from" is. Worlds of our own,
through the real readers; each rule with what stays as said or refused."""
from __future__ import annotations

import pytest

from pipflow.errors import PipflowError
from pipflow.household.world import world_from_text
from tests.readings import assert_warehouse_alike, household_goal, read_warehouse
from tests.test_reader_zambian_and_bajan import CHATTEL

#: a hardware depot whose robots have shifts, a backup tag and nicknames
BUTIBUM = {
    "name": "butibum",
    "floor": {"width": 40, "height": 20},
    "shelves": {
        "north": {"x": 2, "y": 14, "width": 6, "depth": 2, "capacity": 60, "access": [5, 13], "words": ["north dock"]},
        "south": {"x": 12, "y": 14, "width": 6, "depth": 2, "capacity": 60, "access": [15, 13],
                  "words": ["south dock"]},
        "cage": {"x": 26, "y": 14, "width": 4, "depth": 2, "capacity": 30, "access": [28, 13], "words": ["lock up"]},
    },
    "products": {"cement": {"color": "grey", "words": ["simen"]}, "rice": {"color": "white", "words": ["rais"]},
                 "nails": {"color": "brown"}},
    "stock": {"north": {"cement": 12, "rice": 10, "nails": 4}, "south": {"cement": 9, "rice": 6, "nails": 7},
              "cage": {"cement": 0, "rice": 0, "nails": 12}},
    "robots": {"fork1": {"kind": "forklift", "start": [1, 8], "skills": {"carry": 8}, "tags": ["day_shift"]},
               "fork2": {"kind": "forklift", "start": [4, 8], "skills": {"carry": 6}, "tags": ["night_shift"]},
               "amr1": {"kind": "amr", "start": [30, 8], "skills": {"carry": 3}, "tags": ["day_shift"]},
               "amr2": {"kind": "amr", "start": [33, 8], "skills": {"carry": 1}, "tags": ["night_shift", "backup"],
                        "words": ["binatang"]}},
}


@pytest.mark.parametrize("said, plain", [
    # a word for people after a robot tag, kind or superlative names those robots
    ("bring 6 nails into the lock up, and the night shift boys keep out of the lock up",
     "bring 6 nails into the lock up, and the night shift robots keep out of the lock up"),
    ("dont use the backup bois today. move 4 rice from north to south",
     "dont use the backup robots today. move 4 rice from north to south"),
    ("move 10 cement from north to south, only the strongest boi carries the cement",
     "move 10 cement from north to south, only the strongest robot carries the cement"),
    ("move 9 rice from north to south. only boys that carry 4 or more",
     "move 9 rice from north to south. only robots that carry 4 or more"),
    ("the forklift guys cant take simen", "the forklift robots cant take simen"),
    ("empty the south dock, and only the day shift lads in the lock up",
     "empty the south dock, and only the day shift robots in the lock up"),
    # before a word for robots, the word for people is the tag's ("the night shift crew robots")
    ("dont use the night shift crew robots", "dont use the night shift robots"),
    # after a plural group, a word for people is said to the one asked, as before
    ("use the forklifts lads, move 3 simen to the south dock", "use the forklifts, move 3 simen to the south dock"),
    # Tok Pisin words that are no English word
    ("tekim 10 rais from the north dock and share them evenly between the south dock and the lock up",
     "take 10 rice from north and share them evenly between south and cage"),
    ("put wanpela more of each product on the south dock", "put one more of each product on south"),
    ("south dock needs 4 more rais plis, hariap", "south needs 4 more rice"),
    ("morning boi. north dock shud have 15 simen", "north should have 15 cement"),
    ("take 4 simen off the south dock, and dont use binatang today emi too slow",
     "take 4 cement off south, and dont use amr2"),
    # a changed plan said first asks nothing
    ("orait change of plan. north dock shud have 14 rais", "north should have 14 rice"),
    ("Change of plan: north dock should have 14 rais", "north should have 14 rice"),
    ("ok new plan, move 3 nails from the lock up to north", "move 3 nails from cage to north"),
    # the sentence's only goods said again at its end narrow nothing
    ("swap the simen on the north dock and the south dock, just the simen",
     "swap the cement on north and south"),
    ("move 3 rais from north to south, only the rais. move 2 nails to north",
     "move 3 rice from north to south. move 2 nails to north"),
    # a place keeping its own goods, in the third person
    ("the south dock keeps its rais as it is", "leave the rice on south as it is"),
    ("move 2 nails from the lock up to north. south dock keeps its simen",
     "move 2 nails from cage to north. leave the cement on south as it is"),
])
def test_png_english_orders_read_as_their_plain_english(said: str, plain: str) -> None:
    assert_warehouse_alike(said, plain, BUTIBUM)


@pytest.mark.parametrize("said", [
    # a word for people said alone names no robots: never every robot
    "move 3 rice from north to south, the boys keep out of the lock up",
    "move 3 rice from north to south, only boys in the lock up",
    # "just the X" after an order on other goods too narrows it: not set aside
    "swap the north dock and the south dock, just the simen",
    # "change of plan" after an order takes that order back: which is meant is not guessed
    "north dock should have 14 rais. change of plan, move 3 simen to the south dock",
])
def test_what_the_png_rules_do_not_cover_stays_refused(said: str) -> None:
    with pytest.raises(PipflowError):
        read_warehouse(said, BUTIBUM)


@pytest.fixture(scope="module")
def home() -> dict:
    return world_from_text(CHATTEL, "chattel.yaml")


@pytest.mark.parametrize("said, plain", [
    ("put the plate in the cupboard, cariad", "put the plate in the cupboard"),
    ("Duw, wash the plate and the enamel cup, mun.", "wash the plate and the cup"),
    ("Duw duw, switch the kitchen light off", "switch off the kitchen light"),
    ("take the school bag off the day bed and the plate off the counter, put both on the desk",
     "put the school bag and the plate on the desk"),
    # "off" said once after a list is where all of it comes from, as before
    ("take the plate and the enamel cup off the counter and put both in the cupboard",
     "put the plate and the cup in the cupboard"),
])
def test_valleys_english_reads_as_its_plain_english(home: dict, said: str, plain: str) -> None:
    assert household_goal(said, home) == household_goal(plain, home)


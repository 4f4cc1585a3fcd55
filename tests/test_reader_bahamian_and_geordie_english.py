"""Issue 23, from pair RR's sets (a supervisor of a wholesale warehouse in Nassau writing Bahamian
English, a retired welder in Byker writing Geordie), after their first measurements. Warehouse:
Caribbean spellings of grammar words ("wit", "nuttin", "dere", "da", "ting"), a word said with "in"
for "ing" and typed without its apostrophe ("mornin", "comin", "chargin"), a remark in them set
aside as its plain English is ("dey chargin"), "ain't touchin nothing" (a rule), "P same thing", "each
thing we carry", "to P where it belongs", a time of day after a verb of arriving ("comin at 11").
Household: a place said after a change, without a verb, for the things just changed ("wash the
teapot. Teapot in the cupboard": put there), and Geordie ("howay", "hinny", "divvent", "wor lass's",
"the bairn", "an aal", "ah'm"). The worlds of the Australian and Levantine tests, through the real
readers; each rule with what stays as said or refused."""
from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from pipflow.errors import PipflowError, Refusal, TranslationError
from pipflow.household.language.translator import translate
from pipflow.language.english import dropped_g
from pipflow.warehouse.language.translator import understand
from tests.readings import assert_warehouse_alike, household_goal as goal
from tests.test_reader_australian_and_levantine_english import YARD, flat  # noqa: F401 (a fixture)


@pytest.mark.parametrize("said, plain", [
    ("Mornin team! Move 3 cider from grog cage to pick face", "move 3 cider from cage to face"),
    ("move 3 cider from grog cage to pick face, dey chargin", "move 3 cider from cage to face"),
    ("Pick face need to end up wit 5 cider. Loading dock same ting", "face should have 5 cider. dock should have 5 cider"),
    ("Give the loading dock one more of each ting we carry", "give the loading dock one more of each product"),
    ("amr1 ain't touchin nuttin today. Move 3 cider from grog cage to pick face",
     "amr1 don't touch anything. move 3 cider from cage to face"),
    ("Don't touch nuttin on pick face, move 3 cider from grog cage to da loading dock",
     "don't touch anything on face, move 3 cider from cage to dock"),
    ("Bring all the cider to pick face where it belong", "move all the cider to face"),
    ("Bring 5 bikkie to the loading dock, the truck is comin at 11", "bring 5 biscuit to dock"),
    ("take 2 cider off da loading dock bey", "take 2 cider off dock"),
    ("Move 3 cider from grog cage to pick face, Tom Knowles comin fa his order bout 9", "move 3 cider from cage to face"),
    ("Boss say switch round pick face and the loading dock", "swap face and dock"),
    ("Only robots dat could carry 4 or more. Move 3 cider from grog cage to pick face",
     "only robots that can carry 4 or more. move 3 cider from cage to face"),
    ("Fa the audit, each section need to have 2 bikkie", "each place should have 2 biscuit"),
    ("Pick face should have 5 cider fa the Abaco boat", "face should have 5 cider"),
])
def test_bahamian_english_orders_read_as_their_plain_english(said: str, plain: str) -> None:
    assert_warehouse_alike(said, plain, YARD)


def test_in_for_ing_is_read_only_where_the_ing_word_is_far_more_common() -> None:
    """ "runnin" is "running"; "raisin", "basin", "cabin" and "thin" are words as written."""
    assert dropped_g("runnin") == "running" and dropped_g("chargin") == "charging"
    assert all(dropped_g(w) is None for w in ("raisin", "basin", "cabin", "thin", "in", "pin"))


def test_a_name_of_the_world_said_with_in_keeps_its_meaning() -> None:
    """A product called "pickin crate" stays that product: names are read before any respelling."""
    world = {**YARD, "products": {**YARD["products"], "crate": {"color": "red", "words": ["pickin crate"]}},
             "stock": {**YARD["stock"], "cage": {**YARD["stock"]["cage"], "crate": 4}}}
    assert understand("move 2 pickin crate from grog cage to pick face", world)["goal"] == \
        understand("move 2 crate from cage to face", world)["goal"]


@pytest.mark.parametrize("said", [
    # "where it belongs" with no place before it: which place is not said
    "Bring all the cider back where it belongs",
    # a bare number after "at" with a count after it is no time of day
    "the truck is comin at 11 cider",
    # "same thing" without a place to repeat it for
    "Pick face need to end up wit 5 cider. Same ting",
    # a report of what the boss said is no order ("the boss says pick face is full")
    "the boss says pick face is full",
])
def test_what_the_bahamian_rules_do_not_cover_stays_refused(said: str) -> None:
    with pytest.raises(PipflowError):
        understand(said, YARD)


def test_a_place_said_after_a_change_for_the_things_just_changed_is_where_they_go(flat: dict) -> None:
    """ "wash the mug. Mug on the desk": the desk makes nothing clean and the mug was just
    washed; the elided verb is a move (it was refused as impossible: washing on the desk). For
    other things, with no place said for the washing, it stays as it was: washed there,
    impossible (tests/test_reader_kiwi_and_tejano_english.py)."""
    assert goal("wash the mug and the cup. Mug on the desk, cup on the counter", flat) == \
        goal("wash the mug and the cup, put the mug on the desk and the cup on the counter", flat)
    with pytest.raises(Refusal):
        goal("wash the mug, the pie on the desk", flat)


@pytest.mark.parametrize("said, plain", [
    ("Howay, wash the mug hinny", "wash the mug"),
    ("Divvent touch the milk, wash the mug", "do not touch the milk, wash the mug"),
    ("put wor lass's cup on the desk", "put the cup on the desk"),
    ("put aal the cups on the desk", "put all the cups on the desk"),
    ("wash the mug and the cup an aal", "wash the mug and the cup too"),
    ("put the cup on the desk before the bairn gets yem", "put the cup on the desk"),
    ("ah'm off to bed, wash the mug", "wash the mug"),
    ("Switch the lounge light off and put the kitchen light on instead hinny", "switch off the lounge light and switch on the kitchen light"),
    ("gan up and wash the mug", "wash the mug"),
    ("put the pie on the desk oot the road", "put the pie on the desk"),
    ("Divvent ye dare touch the milk, wash the mug", "do not touch the milk, wash the mug"),
])
def test_geordie_reads_as_its_plain_english(flat: dict, said: str, plain: str) -> None:
    assert goal(said, flat) == goal(plain, flat)


def test_warming_the_place_is_the_cue_that_it_is_cold(flat: dict) -> None:
    """ "warm the place up a bit": the home's heaters on, as "it's freezing in here" is; a thing
    warmed up stays that thing heated."""
    heater = {**flat, "places": {**flat["places"], "radiator": {
        "x": 11.0, "y": 8.0, "width": 0.5, "depth": 0.3, "access": [11.2, 7.5], "properties": ["toggleable"],
        "state": {"on": False}, "categories": ["heating"]}}}
    assert goal("warm the place up a bit", heater) == goal("it is freezing in here", heater)
    assert goal("warm the pie up", flat) == goal("heat the pie", flat)


def test_instead_of_a_thing_is_not_dropped(flat: dict) -> None:
    """Only "instead" closing a clause adds nothing; "instead of the lounge light" names what is
    replaced, which this reader does not read: refused, never read as both."""
    with pytest.raises(PipflowError):
        goal("switch the kitchen light on instead of the lounge light", flat)


def test_a_part_whose_unread_words_lie_in_a_tail_of_what_for_keeps_the_rest(flat: dict) -> None:
    """ "boil the pie for me tea hinny, ..., ah cannot stand that fella": the first part keeps
    the pie (only its tail "for me tea" is not understood), the speaker's own "cannot" is left
    out; offered, never acted on."""
    with pytest.raises(TranslationError) as caught:
        translate("boil the pie for me tea hinny, and switch the lounge light on, ah cannot stand that fella", flat)
    assert goal("heat the pie and switch the lounge light on", flat) in _offered(caught.value)


def test_a_remark_run_on_without_a_comma_is_offered_left_out(flat: dict) -> None:
    """ "slice the tomato pls johnny doin a wedding": from the first word not understood to the
    clause's end, where it names nothing of the home and holds no operative word; where it says
    no, it is kept (the pie is never offered sliced)."""
    with pytest.raises(TranslationError) as caught:
        translate("slice the tomato pls johnny doin a wedding", flat)
    assert goal("slice the tomato", flat) in _offered(caught.value)
    with pytest.raises(TranslationError) as caught:
        translate("slice the tomato johnny not the pie", flat)
    assert not any("pie" in (g.get("state") or {}) for g in _offered(caught.value))


def _offered(error: TranslationError) -> list[dict]:
    """The goals a refusal offers, without their empty parts (as :func:`household_goal` gives them)."""
    return [{k: v for k, v in c["goal"].items() if v} for c in error.candidates]


def test_a_command_whose_every_word_is_placed_loads_no_list_of_english_words() -> None:
    """The list of common English words (a second's load) is read only for a word that may need
    it: "in" for "ing" is asked of a word ending in "in" only. The main job reads one such command
    in each domain; it must not pay for the list."""
    code = (
        "import sys\n"
        "from pipflow.language.generator import offline\n"
        "from pipflow.warehouse.world import load_world as warehouse\n"
        "from pipflow.household.world import load_world as household\n"
        "offline('There should be 7 product 1 in shelf 3.', warehouse(sys.argv[1]))\n"
        "offline('Slice the lettuce, trash the mug and switch off the floor lamp.', household(sys.argv[2]))\n"
        "print('spellchecker' in sys.modules)\n")
    papers = Path(__file__).resolve().parent.parent / "benchmarks"
    out = subprocess.run([sys.executable, "-c", code, str(papers / "warehouse" / "world.yaml"),
                          str(papers / "household" / "world.yaml")], capture_output=True, text=True, check=True).stdout
    assert out.strip() == "False"

"""Issue 23, from pair QQ's sets (a day-shift lead of a seafood warehouse in south Louisiana writing
Cajun English, a grandmother in St. John's writing Newfoundland English), after their first
measurements. Warehouse: Cajun talk ("mais", "cher", "ah non"), "th" said as "d" ("dat", "dis",
"dem"), "them" before what it points at ("dem sacks": those), negative concord after a verb that
places or takes ("don't touch nothing", "don't put none"), "out the P" (out of), "pass by P and grab
N X" (from P), "P got N" for a place named by its words ("the pick line got 8"), "put as many X on P
as Q has", "bring X down to N", "put it wherever", "okay, last thing:". Household: "me" before a
thing of the home ("me cup": my cup), "some" before how a thing is ("some dirty": very), and
Newfoundland talk ("luh", "b'y", "where ye to?"), "in the oven to cook" (heat it), and a refused
command offered without a tail that says what for or why ("... before the rain comes"). The worlds of the Australian and Levantine tests,
through the real readers; each rule with what stays as said or refused."""
from __future__ import annotations

import pytest

from pipflow.errors import PipflowError, TranslationError
from pipflow.household.language.tagger import tag
from pipflow.household.language.translator import translate
from pipflow.warehouse.language.translator import understand
from tests.readings import assert_warehouse_alike, household_goal as goal
from tests.test_reader_australian_and_levantine_english import YARD, flat  # noqa: F401 (a fixture)


@pytest.mark.parametrize("said, plain", [
    ("Mais, move 3 cider from grog cage to pick face, cher", "move 3 cider from cage to face"),
    ("Ah non, I got it backwards. Move 3 cider from grog cage to pick face", "move 3 cider from cage to face"),
    ("Okay last thing, move 3 cider from grog cage to pick face", "move 3 cider from cage to face"),
    ("Only forklifts on dis one. Move 3 cider from grog cage to pick face",
     "only forklifts on this one. move 3 cider from cage to face"),
    # negative concord after a verb that places or takes
    ("Don't touch nothing on pick face, move 3 cider from grog cage to the loading dock",
     "don't touch anything on face, move 3 cider from cage to dock"),
    ("Get all the bikkie out the grog cage. Put it wherever, but don't put none on pick face",
     "move all the biscuit off cage but don't put any on face"),
    ("Keep amr1 out the grog cage. Move 2 bikkie from pick face to the loading dock",
     "keep amr1 out of cage. move 2 biscuit from face to dock"),
    ("Pass by the grog cage and grab 3 cider, bring dem to pick face", "move 3 cider from cage to face"),
    ("Put as many bikkie on the loading dock as pick face got right now",
     "put as many biscuit as face has now on dock"),
    ("Bring the cider on grog cage down to 4", "cage should have 4 cider"),
    ("The boss wants pick face to have 6 cider. Don't ask me why", "face should have 6 cider"),
    ("Move 3 cider from grog cage to pick face. Only forklifts on dat",
     "move 3 cider from cage to face. only forklifts on this one"),
    # older sets' causes, seen again: "evenly to" for "evenly between"; a rule said after its thing
    ("split 4 cider from grog cage evenly to pick face and the loading dock",
     "split 4 cider from cage evenly between face and dock"),
    ("cider only forklifts can carry. move 2 cider from grog cage to pick face",
     "only forklifts can carry cider. move 2 cider from cage to face"),
])
def test_cajun_english_orders_read_as_their_plain_english(said: str, plain: str) -> None:
    assert_warehouse_alike(said, plain, YARD)


def test_got_after_a_place_named_by_its_words_is_has() -> None:
    """ "the forward pick got at least 6": a place's own words, not only its name, before "got"."""
    shelves = {**YARD["shelves"], "face": {**YARD["shelves"]["face"], "words": ["pick face", "forward pick"]}}
    world = {**YARD, "shelves": shelves}
    assert_warehouse_alike("Make sure the forward pick got at least 6 cider", "face should have at least 6 cider", world)


def test_out_the_after_a_verb_it_completes_stays_that_verb() -> None:
    """ "clear out the P" is the verb "clear out", never "clear out of the P"."""
    assert understand("clear out the grog cage", YARD)["goal"] == understand("empty the grog cage", YARD)["goal"]


@pytest.mark.parametrize("said", [
    # "don't leave P with no X" may mean the opposite of "don't leave any": no concord after "leave"
    "Don't leave nothing on pick face",
    # "them" before a thing without a place it points at: no guess at which
    "move them bikkie to the loading dock",
    # "oh no" after a count takes it back only where the reader reads a correction; never dropped
    "move 3 cider to the loading dock, oh no, 5",
])
def test_what_the_cajun_rules_do_not_cover_stays_refused(said: str) -> None:
    with pytest.raises(PipflowError):
        understand(said, YARD)


@pytest.mark.parametrize("said, plain", [
    ("me cup is some dirty", "the cup is dirty"),
    ("wash me mug", "wash the mug"),
    ("put me cup on the desk", "put the cup on the desk"),
    ("bring me cup over to the desk", "put the cup on the desk"),
    ("Luh, wash the mug, yes b'y", "wash the mug"),
    ("Where ye to? wash the mug", "wash the mug"),
])
def test_newfoundland_english_reads_as_its_plain_english(flat: dict, said: str, plain: str) -> None:
    assert goal(said, flat) == goal(plain, flat)


def test_me_after_a_verb_of_bringing_stays_who_it_is_for(flat: dict) -> None:
    """ "bring me cup" with no place may be "bring me (the) cup": "me" stays the speaker, and the
    reader asks where; with a place after it both readings move the cup there."""
    notes: list[str] = []
    tag("bring me cup", flat, notes)
    assert not any("'my cup'" in n for n in notes)
    with pytest.raises(PipflowError):
        goal("bring me cup", flat)


def test_some_before_a_thing_stays_a_quantity(flat: dict) -> None:
    notes: list[str] = []
    tag("put some milk in the fridge", flat, notes)
    assert not any("very" in n for n in notes)
    assert goal("put some milk in the fridge", flat) == {"in": {"fridge": ["milk"]}}


def test_heating_said_as_what_a_thing_is_put_in_a_heater_for(flat: dict) -> None:
    """ "put it in the oven to cook (for supper)": the heating asked for, as "to warm" was."""
    assert goal("put the pie in the oven to cook for supper", flat) == goal("put the pie in the oven and heat it", flat)


def test_a_tail_saying_why_is_offered_without_it_and_never_acted_on(flat: dict) -> None:
    """ "... before the rain comes and wash the mug": refused (the tail is not placed), with the
    command without the tail offered; a tail that says no is never left out of a candidate."""
    with pytest.raises(TranslationError) as caught:
        translate("put the cup on the desk before the rain comes and wash the mug", flat)
    assert goal("put the cup on the desk and wash the mug", flat) in [c["goal"] for c in caught.value.candidates]
    with pytest.raises(TranslationError) as caught:
        translate("put the cup on the desk so nobody knocks it over", flat)
    assert not caught.value.candidates


def test_too_many_said_without_a_verb_is_the_complaint_has_too_many_is() -> None:
    """ "P too many X. Pull 3 out of there": the complaint says what "there" means, as "P has too
    many X" does; it reached the order as a count without a count and was refused by the order's
    schema ("the order is not valid at statements/0/amount")."""
    assert_warehouse_alike("pick face too many bikkie. Pull out 3 from there",
                           "pick face has too many bikkie. Pull out 3 from there", YARD)
    with pytest.raises(PipflowError, match="asks for nothing by itself"):
        understand("pick face too many bikkie.", YARD)

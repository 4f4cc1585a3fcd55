"""Issue 23, from pair NN's sets (a night-shift team leader in Wiri writing New Zealand English with
te reo words, a school counsellor in San Antonio writing Tejano English with Spanish), after their
first measurements. Warehouse: a robot addressed and then asked ("Ruru, can you ..."), "when ur
free", "clear" as a place's state, "whatever's on P", "from P out to Q", "rn", "dont mind where
from", "from wherever", a rule opened by "only" and closed by "on this". Household: the people of the
home and what is for them ("there" where a person is; "her X" brought to a place; "for Rose (to
...)" once the place is said; a person's need passed on by the speaker; talk about a person that
stops where a clause of where they are begins), an elided verb after a change made at a place
of its own, and Spanish talk and states ("porfa", "ay", "sucio"). The worlds of the Australian and Levantine tests,
through the real readers; each rule with what stays as said or refused."""
from __future__ import annotations

import copy

import pytest

from pipflow.errors import PipflowError, Refusal, TranslationError
from pipflow.warehouse.language.translator import understand
from tests.readings import assert_warehouse_alike, household_goal as goal
from tests.test_reader_australian_and_levantine_english import YARD, flat  # noqa: F401 (a fixture)


@pytest.mark.parametrize("said, plain", [
    ("fork1, can you move 3 cider from grog cage to pick face", "fork1, move 3 cider from cage to face"),
    ("fork1: could you move 3 cider from grog cage to pick face", "fork1, move 3 cider from cage to face"),
    ("3 cider from grog cage out to pick face", "move 3 cider from cage to face"),
    ("the loading dock should be clear", "empty dock"),
    ("I want the loading dock clear", "empty dock"),
    ("Move all the cider into the grog cage except whatever's on the loading dock",
     "Move all the cider into the cage except what is on the dock"),
    ("pick face needs at least 6 cider, dont mind where from", "pick face needs at least 6 cider"),
    ("send 3 cider to the loading dock from wherever", "send 3 cider to dock"),
    ("Move 3 cider from grog cage to pick face. Only robots that carry 5 or more on this",
     "Move 3 cider from grog cage to pick face. Only robots that carry 5 or more on this one"),
    ("pick face should have as many cider as grog cage has rn", "pick face should have as many cider as cage has now"),
])
def test_kiwi_english_orders_read_as_their_plain_english(said: str, plain: str) -> None:
    assert_warehouse_alike(said, plain, YARD)


#: the yard with a freezer: "free" is then a near miss of a place's name, so "when ur free" is no
#: clause without content (it is set aside only as a courtesy of time)
FREEZER_YARD = copy.deepcopy(YARD)
FREEZER_YARD["shelves"]["freezer"] = {**YARD["shelves"]["face"], "x": 30, "words": []}


@pytest.mark.parametrize("said", [
    "move 3 cider from grog cage to the loading dock when ur free",
    "move 3 cider from grog cage to the loading dock whenever you're free",
])
def test_when_you_are_free_is_a_courtesy_even_beside_a_freezer(said: str) -> None:
    assert_warehouse_alike(said, "move 3 cider from cage to dock", FREEZER_YARD)


@pytest.mark.parametrize("said", [
    # "dont mind" of a thing, not of where or which: no courtesy, an order not read
    "move 3 cider to the loading dock, dont mind the bikkie",
    # "from wherever it is": a clause follows, not the courtesy
    "send 3 cider to the loading dock from wherever it is",
    # asked without the comma of address: the robot is no vocative
    "fork1 can you move 3 cider from grog cage to pick face",
])
def test_what_the_kiwi_rules_do_not_cover_stays_refused(said: str) -> None:
    with pytest.raises(PipflowError):
        understand(said, YARD)


@pytest.mark.parametrize("said, plain", [
    # "there" after a verb of bringing, where the command says where the person is
    ("Rose is at the desk. Bring the pie there", "bring the pie to the desk"),
    ("Rose is at the desk, so bring the pie there", "bring the pie to the desk"),
    # a clause about the person stops where the clause of where they are begins
    ("Rose's back is bad today so she is staying at the desk. bring the pie there", "bring the pie to the desk"),
    # "her X ... there": whose the things are, in a clause that says where they go
    ("Rose is at the desk. Bring her blanket and her phone there", "bring the blanket and the phone to the desk"),
    ("take her phone to the nightstand", "take the phone to the nightstand"),
    # who it is for, once the place is said (and what they will do with it)
    ("bring the mug to the counter for Rose", "bring the mug to the counter"),
    ("bring the mug to the counter for Rose to use when she is back", "bring the mug to the counter"),
    # a person's need, passed on by the speaker
    ("Rose can't see", "i can not see"),
    ("Rose wants the lounge light on", "switch on the lounge light"),
])
def test_people_and_what_is_for_them_read_as_their_plain_english(flat: dict, said: str, plain: str) -> None:
    assert goal(said, flat) == goal(plain, flat)


@pytest.mark.parametrize("said", [
    # brought to a person whose place is not said: never guessed
    "bring the mug to Rose",
    # what they will do names a thing of the home: an order of its own, not read
    "bring the mug to the counter for Rose to put in the oven",
    # "her phone there" with no one said to be anywhere: "there" is nowhere
    "bring her phone there",
])
def test_what_the_people_rules_do_not_cover_stays_refused(flat: dict, said: str) -> None:
    with pytest.raises(PipflowError):
        goal(said, flat)


def test_an_elided_verb_after_a_change_made_at_a_place_is_asked_where_the_place_makes_nothing(flat: dict) -> None:
    """ "heat the pie in the oven, and the milk on the counter": the counter heats nothing and the
    milk is not on it, so heated there is impossible and put there likely: which is asked (not
    understood), never refused as impossible (a feasible command called impossible is a misreading)
    nor guessed. Said with no place for the heating, both are to be heated on the counter: impossible."""
    with pytest.raises(TranslationError) as asked:
        goal("heat the pie in the oven, and the milk on the counter", flat)
    assert "or put in counter" in str(asked.value)
    with pytest.raises(Refusal):
        goal("heat the pie and the milk on the counter", flat)


@pytest.mark.parametrize("said, plain", [
    ("ay, the mug is sucio, wash it porfa", "wash the mug"),
    ("Buenos dias! porfa cut the tomato, gracias", "cut the tomato"),
    ("wash the sucia cup ahorita", "wash the dirty cup"),
])
def test_tejano_english_reads_as_its_plain_english(flat: dict, said: str, plain: str) -> None:
    assert goal(said, flat) == goal(plain, flat)

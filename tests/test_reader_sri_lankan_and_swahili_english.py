"""Issue 23, from pair MM's sets (a shift supervisor at the Katunayake export zone writing Sri Lankan
English with Sinhala words, a bank manager in Dar es Salaam writing English with Swahili), after
their first measurements. Warehouse: Sinhala words of address and talk ("machan", "aney", "hari",
"ikmanata"), "already" closing an order, "both" as an apposition (the two there). Household: Swahili
talk ("tafadhali", "sawa", "jamani", "kweli") and the home's states said in the family's other
language ("chafu", "kasif": dirty; "baridi", "sard": cold). The worlds of the Australian and
Levantine tests, through the real readers; each rule with what stays as said or refused."""
from __future__ import annotations

import pytest

from pipflow.errors import PipflowError
from pipflow.warehouse.language.translator import understand
from tests.readings import assert_warehouse_alike, household_goal as goal
from tests.test_reader_australian_and_levantine_english import YARD, flat  # noqa: F401 (a fixture)


@pytest.mark.parametrize("said, plain", [
    ("Move 3 cider from grog cage to pick face , hari", "move 3 cider from cage to face"),
    ("aney move 3 cider from grog cage to pick face ikmanata", "move 3 cider from cage to face"),
    ("machan bring 2 bikkie to the loading dock", "bring 2 biscuit to dock"),
    ("swap cider on grog cage and pick face machan", "swap cider on cage and face"),
    ("Send one more of each product to the loading dock already", "add one more of each product to dock"),
    # "both": the two there (the loading dock holds 2 cider)
    ("Take the loading dock 's cider , both , to pick face", "move all cider from dock to face"),
])
def test_sri_lankan_english_orders_read_as_their_plain_english(said: str, plain: str) -> None:
    assert_warehouse_alike(said, plain, YARD)


@pytest.mark.parametrize("said", [
    # "both" of what is not two: which is meant is asked
    "Take grog cage 's cider , both , to pick face",
    # a word of address before no verb is no order
    "machan 3 cider from grog cage to pick face",
])
def test_what_the_rules_do_not_cover_stays_refused(said: str) -> None:
    with pytest.raises(PipflowError):
        understand(said, YARD)


@pytest.mark.parametrize("said, plain", [
    ("tafadhali wash the mug , asante sana", "wash the mug"),
    ("sawa, cut the tomato haraka", "cut the tomato"),
    ("Kweli, the cup is chafu, wash it jamani", "wash the cup"),
    ("wash the kasif mug", "wash the mug"),
])
def test_swahili_and_persian_english_read_as_their_plain_english(flat: dict, said: str, plain: str) -> None:
    assert goal(said, flat) == goal(plain, flat)


def test_a_state_said_in_the_other_language_selects_as_the_english_does(flat: dict) -> None:
    """ "the baridi pie": a state of the home said in Swahili is the state, never dropped: the pie is
    cold, so it is the one meant, as "the cold pie" is; "the hot pie" names none."""
    assert goal("heat the baridi pie", flat) == goal("heat the cold pie", flat)
    with pytest.raises(PipflowError):
        goal("heat the hot pie", flat)
    with pytest.raises(PipflowError):
        goal("wash the chafu pie", flat)   # the pie is not dirty (nor washable): no such pie

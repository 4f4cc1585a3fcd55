"""Issue 23, from pair MM's sets (a shift supervisor at the Katunayake export zone writing Sri Lankan
English with Sinhala words, a bank manager in Dar es Salaam writing English with Swahili), after
their first measurements. Warehouse: Sinhala words of address and talk ("machan", "aney", "hari",
"ikmanata"), "already", "fully" and "do it" closing an order, "need N X at P", "both" as an
apposition (the two there), and an order with "is" in it never set aside as a report. Household: Swahili
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
    # "fully" after "clear P"; "do it" closing an order urges it; "need N X at P" (who needs left out)
    ("Clear the loading dock fully", "empty dock"),
    ("pick face should have 6 cider , do it", "pick face should have 6 cider"),
    ("need 6 cider at pick face", "pick face should have 6 cider"),
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
    # "do it" with more than an urging is an order in a verb not read
    "send 2 cider to pick face , do it twice",
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


@pytest.mark.parametrize("said", [
    "need 2 cider at the loading dock , cheers. leave whats already in there as it is",
    "add 2 cider to the loading dock , leave what is in there as it is",
])
def test_an_order_with_is_in_it_is_never_set_aside_as_a_report(said: str) -> None:
    """ "leave what is in there as it is" opens as an order (a verb, then what it acts on): its "is"
    is no report's, so it is never set aside; read, it keeps the dock's biscuits, else it is refused.
    Set aside, the robots would be free to move them (the widening the issue forbids)."""
    try:
        got = understand(said, YARD)
    except PipflowError:
        return
    assert (got["goal"].get("dock") or {}).get("biscuit") == 3

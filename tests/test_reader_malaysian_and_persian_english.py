"""Issue 23, from pair KK's sets (a warehouse supervisor at Port Klang writing Malaysian English, a
dentist in Tehran writing English with Persian in Latin letters), after their first measurements.
Warehouse: Malay words of address and talk ("Abang", "Boss", "paiseh", "walao"), "can ... or not",
"jangan" for don't, "dont touch anything at P", "Need you all to ...", "last week" a time. Household:
Persian talk ("lotfan", "mamnoon", "azizam"), kinship words and titles of other languages ("Maman",
"Khaleh Mahin"), a move said without its verb after a change, with where the thing comes from. The
worlds of the Australian and Levantine tests, through the real readers; each rule with what stays
as said or refused."""
from __future__ import annotations

import pytest

from pipflow.errors import PipflowError
from pipflow.warehouse.language.translator import understand
from tests.readings import assert_warehouse_alike, household_goal as goal
from tests.test_reader_australian_and_levantine_english import YARD, flat  # noqa: F401 (a fixture)


@pytest.mark.parametrize("said, plain", [
    ("Abang , can add 2 more cider to the loading dock or not", "add 2 more cider to dock"),
    ("Boss send 3 cider to the loading dock", "send 3 cider to dock"),
    ("can move 3 cider from grog cage to the loading dock or not?", "move 3 cider from cage to dock"),
    ("Paiseh , move 3 cider from grog cage to the loading dock", "move 3 cider from cage to dock"),
    ("Alamak, move 3 cider from grog cage to the loading dock", "move 3 cider from cage to dock"),
    ("Jangan touch anything at pick face", "keep face as it is"),
    ("dont touch anything on pick face", "keep face as it is"),
    ("Need you all to shift 2 cider from grog cage to pick face", "move 2 cider from cage to face"),
    ("move 2 cider from grog cage to pick face , last week it hit the fence already",
     "move 2 cider from cage to face"),
])
def test_malaysian_english_orders_read_as_their_plain_english(said: str, plain: str) -> None:
    assert_warehouse_alike(said, plain, YARD)


@pytest.mark.parametrize("said", [
    # "or not" after an order that asks nothing: no question's tag
    "move 2 cider from grog cage to pick face or not",
    # "last" before a thing of the world selects: never a time
    "move the last cider from grog cage to pick face",
    # a word of address before no verb is no order
    "Boss cider to the loading dock",
])
def test_what_the_rules_do_not_cover_stays_refused(said: str) -> None:
    with pytest.raises(PipflowError):
        understand(said, YARD)


@pytest.mark.parametrize("said, plain", [
    ("salam azizam , lotfan wash the mug , mamnoon", "wash the mug"),
    ("khob, cut the tomato zood", "cut the tomato"),
    ("maman is sleeping, switch off the kitchen light", "switch off the kitchen light"),
    ("khaleh mahin is sleeping, switch off the kitchen light", "switch off the kitchen light"),
])
def test_persian_english_reads_as_its_plain_english(flat: dict, said: str, plain: str) -> None:
    assert goal(said, flat) == goal(plain, flat)


def test_a_thing_said_after_a_change_without_a_source_is_the_thing_there(flat: dict) -> None:
    """ "heat the pie, the tomato on the desk": with no "from", "on the desk" may say which tomato,
    so the change is what is repeated (and refused: the desk heats nothing), never a move."""
    with pytest.raises(PipflowError):
        goal("heat the pie, the tomato on the desk", flat)

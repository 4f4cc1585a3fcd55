"""Issue 23, from pair OO's sets (an early-shift supervisor in Ballycoolin writing Irish English with
Irish words, a pharmacist in Brampton writing Punjabi-Canadian English), after their first
measurements. Warehouse: Irish talk ("dia duit", "a chara", "GRMA", "go raibh maith agat", "mo
bhuachaill", "sláinte", "slán"), Dublin words ("giz": give us, "ye", "deadly", "grand
job", "so it is"), "instead" closing an order, "every X to P except the ones in Q" without a verb,
and a bracketed remark before a comma. Household: Punjabi and Hindi talk ("sat sri akal", "ji",
"acha", "haye", "chalo", "theek hai", "beta", "yaar", "jaldi") and states ("garam": hot, "thanda":
cold, "ganda": dirty, "saaf": clean), a degree word between "is" and a state ("the cup is so
dirty"), and "his" / "her" before a name the home says with its owner ("his side table"). The worlds of the Australian and Levantine tests, through the real readers; each rule
with what stays as said or refused."""
from __future__ import annotations

import pytest

from pipflow.errors import PipflowError
from pipflow.warehouse.language.translator import understand
from tests.readings import assert_warehouse_alike, household_goal as goal
from pipflow.household.world import world_from_text
from tests.test_reader_australian_and_levantine_english import FLAT, YARD, flat  # noqa: F401 (a fixture)


@pytest.mark.parametrize("said, plain", [
    ("dia duit! giz 4 more bikkie on the loading dock pls", "get 4 more biscuit on dock"),
    ("Dia duit a chara. move 3 cider from grog cage to pick face. GRMA", "move 3 cider from cage to face"),
    ("move 3 cider from grog cage to pick face, go raibh maith agat", "move 3 cider from cage to face"),
    ("move 3 cider from grog cage to pick face, deadly", "move 3 cider from cage to face"),
    ("fork1, move 3 cider from grog cage to pick face, good lad", "fork1, move 3 cider from cage to face"),
    ("move 3 cider from grog cage to pick face when ye get a sec", "move 3 cider from cage to face"),
    ("put 4 more bikkie on the loading dock so it is", "put 4 more biscuit on dock"),
    ("bring 3 cider to the loading dock instead, from wherever", "bring 3 cider to dock"),
    ("Every cider to the loading dock except the ones in the grog cage",
     "move every cider to dock except the ones in cage"),
    # a bracketed remark, then a comma: one mark, where the remark is set aside
    ("move 3 cider from grog cage to the loading dock (the lorry is early), and 2 bikkie from pick face to the loading dock",
     "move 3 cider from cage to dock and 2 biscuit from face to dock"),
])
def test_irish_english_orders_read_as_their_plain_english(said: str, plain: str) -> None:
    assert_warehouse_alike(said, plain, YARD)


@pytest.mark.parametrize("said", [
    # "so it is" with more after it is no stress: a clause the grammar does not read
    "keep the loading dock so it is empty",
    # "except" needs all of a product, with a verb or without
    "3 cider to the loading dock except the ones in the grog cage",
])
def test_what_the_irish_rules_do_not_cover_stays_refused(said: str) -> None:
    with pytest.raises(PipflowError):
        understand(said, YARD)


@pytest.mark.parametrize("said, plain", [
    ("sat sri akal ji! wash the mug", "wash the mug"),
    ("acha, cut the tomato jaldi", "cut the tomato"),
    ("the mug is so ganda, wash it", "wash the mug"),
    ("heat the pie, I want it garam", "heat the pie"),
    # a degree word between "is" and a state ("so", "very", "way too")
    ("the cup is very dirty, wash it", "the cup is dirty, wash it"),
    ("the cup is way too dirty, wash it", "wash the cup"),
])
def test_punjabi_english_reads_as_its_plain_english(flat: dict, said: str, plain: str) -> None:
    assert goal(said, flat) == goal(plain, flat)


#: the flat, its nightstand called only by whose it is and two words ("Rose's bedside table")
BEDSIDE = FLAT.replace('words: ["Rose\'s table", table de nuit]', 'words: ["Rose\'s bedside table", table de nuit]')


def test_his_or_her_before_a_name_is_the_one_person_said_whose_it_can_be() -> None:
    """ "Bauji's knee is paining, bring his stick to his side table" where the home says "Bauji's
    side table": the pronoun is the one person the command names whose words make a name of the
    home; said of nobody, "her bedside table" names nothing and stays refused."""
    world = world_from_text(BEDSIDE, "bedside.yaml")
    assert goal("Rose is asleep, put the blanket on her bedside table", world) == \
        goal("put the blanket on Rose's bedside table", world)
    with pytest.raises(PipflowError):
        goal("put the blanket on her bedside table", world)


def test_a_state_said_in_punjabi_selects_as_the_english_does(flat: dict) -> None:
    """ "the ganda cup": dirty, as "the dirty cup"; "saaf" (clean) names no cup here (both are dirty)."""
    assert goal("wash the ganda mug", flat) == goal("wash the dirty mug", flat)
    with pytest.raises(PipflowError):
        goal("wash the saaf mug", flat)

"""Issue 23, from pair LL's sets (a shift supervisor by the Kingston Freezone writing Jamaican English
with Patois words, an architect in Addis Ababa writing English with Amharic in Latin letters), after
their first measurements. Warehouse: the Jamaican Creole function words the household reader read
("mi", "dem", "fi", "yuh", "pon": :func:`pipflow.language.patois.english_of`) read by the warehouse
reader too, "fi" after a subject as "should"; a robot addressed, then "you (should)"; remarks of
"all over" and of a demonstrative's state ("that one bruk", "those dent up"); "nothing / none of
them from P" keeps P's stock; "R must not go near X", "let only R handle X", "stay off this job";
"P needs N X added", "send the excess"; a plural noun and a verb in -ing as a report. Household:
Amharic talk as others type it; things said first taken up by "both", "all three", "switch on it";
a kinship word with "'s" says whose; a condition's thing "sitting" on its place. The worlds of the Australian and Levantine tests, through the real readers;
each rule with what stays as said or refused."""
from __future__ import annotations

import pytest

from pipflow.errors import PipflowError
from pipflow.language.patois import english_of
from pipflow.warehouse.language.translator import understand
from tests.readings import assert_warehouse_alike, household_goal as goal
from tests.test_reader_australian_and_levantine_english import YARD, flat  # noqa: F401 (a fixture)


@pytest.mark.parametrize("said, plain", [
    ("mi want 12 cider at pick face", "pick face should have 12 cider"),
    ("pick face fi hold 5 cider", "pick face should hold 5 cider"),
    ("fork1 , yuh fi take 2 cider from grog cage to pick face", "fork1 take 2 cider from cage to face"),
    ("fork1, you should take 2 cider from grog cage to pick face", "fork1 take 2 cider from cage to face"),
    ("fork1, you take 2 cider from grog cage to pick face", "fork1 take 2 cider from cage to face"),
    ("take grog cage 's cider , all 10 of dem , to pick face", "move all cider from cage to face"),
    ("move every cider to pick face except the one on the loading dock , that one bruk",
     "move every cider to pick face except the one on dock"),
    ("add 2 cider to the loading dock , those dent up", "add 2 cider to dock"),
    ("add 2 cider to the loading dock , this one is cracked", "add 2 cider to dock"),
    ("add 2 cider to the loading dock , grease all over mi phone", "add 2 cider to dock"),
])
def test_jamaican_english_orders_read_as_their_plain_english(said: str, plain: str) -> None:
    assert_warehouse_alike(said, plain, YARD)


@pytest.mark.parametrize("said", [
    # a demonstrative with a word of an order's tail still asks something of it
    "add 2 cider to the loading dock , that one too",
    "add 2 cider to the loading dock , those as well",
    # "all over" a place of the world names it
    "add 2 cider to the loading dock , grease all over the pick face",
    # a demonstrative with a place of the world after it says which
    "move every cider to pick face except the one on the loading dock , that one on grog cage",
])
def test_what_the_rules_do_not_cover_stays_refused(said: str) -> None:
    with pytest.raises(PipflowError):
        understand(said, YARD)


def test_patois_is_read_only_where_the_command_shows_it() -> None:
    """One word that English has too ("den", "an") reads as typed; a word that names a thing of the
    world is never read as patois; "fi" is "for" before whom, "to" after a verb of needing."""
    def read(text: str, names: frozenset[str] = frozenset()) -> list[str]:
        words = text.split()
        said = english_of(words, lambda w: w in names, lambda w: w in names)
        return [w if s is None else s for w, s in zip(words, said)]
    assert read("go to the den and wait") == ["go", "to", "the", "den", "and", "wait"]
    assert read("mi need fi pack it") == ["i", "need", "to", "pack", "it"]
    assert read("bring it fi mi") == ["bring", "it", "for", "me"]
    assert read("yuh fi take it") == ["you", "should", "take", "it"]
    assert read("put di mi pon di shelf", frozenset({"mi", "shelf"})) == ["put", "the", "mi", "on", "the", "shelf"]


@pytest.mark.parametrize("said, plain", [
    ("tenastelign! wash the mug ameseginalehu", "wash the mug"),
    ("wey gud, cut the tomato tolo", "cut the tomato"),
    ("ebakachihu , wash the mug . yikirta", "wash the mug"),
])
def test_amharic_english_reads_as_its_plain_english(flat: dict, said: str, plain: str) -> None:
    assert goal(said, flat) == goal(plain, flat)


@pytest.mark.parametrize("said, plain", [
    # a source kept out of a move: it keeps what it has of the things moved
    ("Send 2 cider to pick face but nothing from grog cage", "send 2 cider to pick face, and grog cage should have 10 cider"),
    ("send 2 cider to pick face , not from the grog cage", "send 2 cider to pick face, and grog cage should have 10 cider"),
    # a product a robot must not go near, and "let only" before the robots
    ("add 2 cider to the loading dock , and amr1 must not go near bikkie at all",
     "add 2 cider to dock, amr1 must not touch biscuit"),
    ("let only fork1 handle the cider. move 2 cider from grog cage to pick face",
     "only fork1 may move cider. move 2 cider from cage to face"),
    ("send 2 cider to pick face , none of them should come out of the grog cage",
     "send 2 cider to pick face, and grog cage should have 10 cider"),
    ("add 8 cider to the loading dock , but AMRs arent to go near bikkie", "add 8 cider to dock, amr1 must not touch biscuit"),
    # "P needs N X added": N more; "send (the) extra / excess to Q": the rest
    ("the loading dock needs 6 cider added", "add 6 cider to dock"),
    ("bring grog cage down to 4 cider and send the excess to pick face",
     "bring grog cage down to 4 cider and send the rest to pick face"),
    # robots addressed, then told to stay off the job
    ("add 2 cider to the loading dock. amr1 , stay off this job", "add 2 cider to dock. dont use amr1"),
    ("add 2 cider to the loading dock. forklifts stay out of this one", "add 2 cider to dock. dont use fork1"),
    # a noun of several words, its last a plural, with a verb in -ing and no "is": a report
    ("Friday fish fry orders coming in nuff , add 2 cider to the loading dock", "add 2 cider to dock"),
])
def test_more_orders_of_pair_ll_read_as_their_plain_english(said: str, plain: str) -> None:
    assert_warehouse_alike(said, plain, YARD)


@pytest.mark.parametrize("said", [
    # the source kept out is the one the move is from: which is meant is asked
    "move 2 cider from grog cage to pick face but nothing from grog cage",
    # a report of several words whose last is no plural may be an order in a verb not read
    "add 2 cider to the loading dock , keep cases moving",
])
def test_more_of_what_stays_refused(said: str) -> None:
    with pytest.raises(PipflowError):
        understand(said, YARD)


@pytest.mark.parametrize("said, plain", [
    # a thing said first, then the verb, "on" / "off" and the pronoun
    ("the kitchen light, switch off it", "switch off the kitchen light"),
    ("the lounge light, switch on it", "switch on the lounge light"),
    # things said first, taken up by "both", "all three", "them all", "all of them"
    ("the mug and the cup, wash both", "wash the mug and the cup"),
    ("the mug and the cup, wash them all", "wash the mug and the cup"),
    ("the mug, the cup and the tomato, put all three on the desk", "put the mug, the cup and the tomato on the desk"),
    # a kinship word with "'s" says whose a thing is, with the determiner before it
    ("put my husband's mug on the desk", "put the mug on the desk"),
    # a thing "sitting" on a place, and a machine "going", in a condition
    ("if the pie is still sitting on the counter, heat it in the oven", "heat the pie in the oven"),
    ("if the kitchen light is going, switch it off", "switch off the kitchen light"),
])
def test_household_orders_of_pair_ll_read_as_their_plain_english(flat: dict, said: str, plain: str) -> None:
    assert goal(said, flat) == goal(plain, flat)


@pytest.mark.parametrize("said", [
    # "all three" of two things: the count does not match
    "the mug and the cup, wash all three",
    # a condition that does not hold asks nothing
    "if the pie is sitting on the desk, heat it in the oven",
])
def test_household_what_stays_refused(flat: dict, said: str) -> None:
    with pytest.raises(PipflowError):
        goal(said, flat)

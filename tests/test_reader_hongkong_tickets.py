"""Issue 23, from pair OO's first measurement (an inventory controller in a Hong Kong components
warehouse writing job tickets): a place said by its initials ("OB" for outbound), a place's name
with a noun for a place after it ("kitting table"), unit words between a count and the item ("3
trays MCU"), asking with "can help ..." and "pls arrange ...", Cantonese clause particles ("la",
"ar"), the place and the item said first and what to do with them after ("OB connector max 4
only"), "P and Q both should have ...", and remarks made of words the grammar reads only as
asides ("tmr morning"). Through the real warehouse reader, in a bakery supply store of our own."""
from __future__ import annotations

import copy

import pytest

from pipflow.errors import TranslationError
from pipflow.warehouse.language.translator import understand

STORE = {
    "floor": {"width": 30, "height": 20},
    "shelves": {
        "backroom": {"x": 2, "y": 14, "width": 6, "depth": 2, "capacity": 40, "access": [5, 13]},
        "cold_store": {"x": 12, "y": 14, "width": 6, "depth": 2, "capacity": 30, "access": [15, 13]},
        "packing": {"x": 22, "y": 14, "width": 6, "depth": 2, "capacity": 30, "access": [25, 13]},
        "dock": {"x": 12, "y": 4, "width": 6, "depth": 2, "capacity": 20, "access": [15, 3]},
    },
    "products": {"flour": {"color": "white"}, "yeast": {"color": "yellow"}, "seed_tray": {"color": "green"}},
    "stock": {"backroom": {"flour": 10, "yeast": 4, "seed_tray": 3},
              "cold_store": {"flour": 2, "yeast": 6},
              "packing": {"flour": 5, "yeast": 1, "seed_tray": 2},
              "dock": {"flour": 1}},
    "robots": {
        "mule": {"start": [1, 1], "skills": {"carry": 4}, "kind": "forklift", "tags": []},
        "ant": {"start": [28, 1], "skills": {"carry": 2}, "kind": "amr", "tags": []},
    },
}


def goal(command: str, world: dict = STORE) -> dict:
    return understand(command, world)["goal"]


@pytest.mark.parametrize("said, plain", [
    ("move 3 yeast from CS to BR", "move 3 yeast from cold_store to backroom"),   # cold_store; back + room
    ("BR should have 12 flour", "backroom should have 12 flour"),
])
def test_a_place_said_by_its_initials_in_capitals_is_that_place(said: str, plain: str) -> None:
    assert goal(said) == goal(plain)


def test_initials_in_lower_case_or_shared_by_two_places_are_never_guessed() -> None:
    with pytest.raises(TranslationError):
        understand("move 3 yeast from cs to backroom", STORE)   # lower case: a word, not initials
    twins = copy.deepcopy(STORE)
    twins["shelves"]["cool_shelf"] = twins["shelves"].pop("dock")   # cold_store and cool_shelf: both "CS"
    twins["stock"]["cool_shelf"] = twins["stock"].pop("dock")
    with pytest.raises(TranslationError):
        understand("move 3 yeast from CS to backroom", twins)


def test_a_noun_for_a_place_after_its_name_is_that_place() -> None:
    assert goal("clear the packing table") == goal("clear packing")


@pytest.mark.parametrize("said, plain", [
    ("send 3 trays yeast from cold_store to packing", "send 3 yeast from cold_store to packing"),
    ("move 2 pc flour from backroom to dock", "move 2 flour from backroom to dock"),
])
def test_unit_words_between_a_count_and_the_item_count_the_item(said: str, plain: str) -> None:
    plain_store = copy.deepcopy(STORE)   # no product named with "tray"
    del plain_store["products"]["seed_tray"]
    for stock in plain_store["stock"].values():
        stock.pop("seed_tray", None)
    assert goal(said, plain_store) == goal(plain, plain_store)


def test_a_unit_word_that_is_a_word_of_a_name_is_that_name() -> None:
    """ "2 trays" where seed_tray is a product: the trays, not a unit of the flour moved before."""
    assert goal("move 3 flour from backroom to packing and 2 trays the other way") == \
        goal("move 3 flour from backroom to packing and 2 seed_tray from packing to backroom")


@pytest.mark.parametrize("said", [
    "Can help move 3 flour from backroom to dock",
    "pls help move 3 flour from backroom to dock",
    "help to move 3 flour from backroom to dock",
    "move 3 flour from backroom to dock, can help",
    "move 3 flour from backroom to dock la",
    "move 3 flour from backroom to dock ar, thx",
])
def test_asking_and_clause_particles_of_hong_kong_english(said: str) -> None:
    assert goal(said) == goal("move 3 flour from backroom to dock")


@pytest.mark.parametrize("said, plain", [
    ("dock flour max 4 only", "dock should have at most 4 flour"),
    ("packing yeast cannot lower than 3", "packing should have at least 3 yeast"),
    ("packing yeast at least 3", "packing should have at least 3 yeast"),
    ("backroom flour cannot go above 12", "backroom should have at most 12 flour"),
    ("backroom flour take away 4", "take 4 flour off backroom"),
    ("backroom flour add 2", "add 2 flour to backroom"),
])
def test_the_place_and_the_item_said_first_then_what_to_do(said: str, plain: str) -> None:
    assert goal(said) == goal(plain)


@pytest.mark.parametrize("said", ["arrange dock to have 6 flour", "pls arrange for dock to have 6 flour"])
def test_arrange_asks_for_what_follows(said: str) -> None:
    assert goal(said) == {"dock": {"flour": 6}}


def test_kindly_arrange_alone_asks_for_nothing_more() -> None:
    assert goal("dock should have 6 flour. Kindly arrange.") == {"dock": {"flour": 6}}


def test_two_places_that_both_should_have_a_count() -> None:
    assert goal("dock and packing both should have 4 yeast") == {"dock": {"yeast": 4}, "packing": {"yeast": 4}}


def test_a_remark_of_aside_words_only_is_set_aside() -> None:
    """ "morning", "tonight", "later": words the grammar reads only as asides are no content."""
    got = understand("Stocktake guys later tonight. dock should have 6 flour", STORE)
    assert got["goal"] == {"dock": {"flour": 6}}


@pytest.mark.parametrize("said", [
    "Ive been asked to get dock up to 6 flour",
    "I've been told to get dock up to 6 flour",
    "we were asked to get dock up to 6 flour",
])
def test_a_request_passed_on_is_the_request(said: str) -> None:
    assert goal(said) == {"dock": {"flour": 6}}


def test_a_rule_passed_on_is_the_rule() -> None:
    got = understand("Ive been told that only forklifts are to be used. move 3 flour from backroom to dock", STORE)
    assert got["constraints"] == understand("only forklifts. move 3 flour from backroom to dock", STORE)["constraints"]


@pytest.mark.parametrize("said, plain", [
    ("3 flour from packing put back backroom", "move 3 flour from packing to backroom"),
    ("all yeast put back to cold_store except the ones on backroom",
     "all yeast go to cold_store except the ones on backroom"),
])
def test_put_back_after_the_things_and_before_a_place_is_where_they_go(said: str, plain: str) -> None:
    assert goal(said) == goal(plain)


@pytest.mark.parametrize("said", ["backroom flour: 3 to dock, rest to packing", "backroom flour 3 to dock, rest to packing"])
def test_counts_sent_on_from_a_place_and_item_said_first(said: str) -> None:
    assert goal(said) == goal("move 3 flour from backroom to dock, rest to packing")


def test_robots_of_a_tag_are_the_tag_s_robots() -> None:
    tagged = copy.deepcopy(STORE)
    tagged["robots"]["mule"]["tags"] = ["night_shift"]
    tagged["robots"]["ox"] = {"start": [5, 1], "skills": {"carry": 3}, "kind": "forklift", "tags": ["night_shift"]}
    assert understand("move 3 flour from backroom to dock, robots of night_shift only", tagged)["constraints"] == \
        understand("move 3 flour from backroom to dock, night_shift robots only", tagged)["constraints"]


def test_at_the_end_of_the_day_is_when() -> None:
    assert goal("dock must have 6 flour at end of day") == {"dock": {"flour": 6}}


def test_tag_ones_and_robot_can_carry_are_robot_groups() -> None:
    tagged = copy.deepcopy(STORE)
    tagged["robots"]["mule"]["tags"] = ["esd_safe"]
    move = "move 3 flour from backroom to dock"
    assert understand(f"{move}, use esd_safe ones only", tagged)["constraints"] == \
        understand(f"{move}, esd_safe robots only", tagged)["constraints"]
    assert understand(f"{move}. Only robot can carry 3 or above", tagged)["constraints"] == \
        understand(f"{move}. only robots that can carry 3 or more", tagged)["constraints"]


def test_a_robot_said_first_then_dont_use_is_never_that_robot() -> None:
    got = understand("mule dun use. move 3 flour from backroom to dock", STORE)
    assert got["constraints"] == understand("dont use mule. move 3 flour from backroom to dock", STORE)["constraints"]

"""Issue 23, second step (warehouse reader): constructions the held-out writers used that no rule
read, each by class (not phrase), in a world of its own (the bike shop of
test_reader_candidates), through the real reader."""
from __future__ import annotations

import pytest

from pipflow.errors import TranslationError
from pipflow.warehouse.language.translator import translate
from tests.test_reader_candidates import BIKES

ALL_HELMETS_BUT_HOOKS = {"front_rack": {"helmet": 0}, "back_room": {"helmet": 2}, "repair_bench": {"helmet": 0},
                         "wall_hooks": {"helmet": 3}}


@pytest.mark.parametrize("command", [
    "Send all the helmets to the back room, except the ones on the wall hooks.",
    "Bring every helmet to the back room, apart from those on the wall hooks",
    "Every helmet goes to the back room, except the ones up on the wall hooks.",
])
def test_except_places_after_a_comma_and_after_go(command: str) -> None:
    """"all X to P, except the ones on Q": the exception after a comma (it was read only without
    one), after "X goes to P", and with a particle ("up on Q")."""
    assert translate(command, BIKES)["goal"] == ALL_HELMETS_BUT_HOOKS


def test_every_item_goes_to_a_place_gathers_it_there() -> None:
    assert translate("Every chain goes to the front rack", BIKES)["goal"] == {
        "front_rack": {"chain": 3}, "back_room": {"chain": 0}, "wall_hooks": {"chain": 0}, "repair_bench": {"chain": 0}}


TRAYS = {**BIKES, "shelves": {**BIKES["shelves"],
                              "tray-a": {"x": 14, "y": 3, "width": 3, "depth": 2, "capacity": 6, "access": [15, 6]},
                              "tray-b": {"x": 20, "y": 3, "width": 3, "depth": 2, "capacity": 6, "access": [21, 6]}}}


@pytest.mark.parametrize("command", [
    "Every tray should have 2 inner tubes.", "Each tray should have 2 inner tubes", "both trays should have 2 inner tubes",
    "all trays should have 2 inner tubes",
])
def test_the_head_noun_two_places_share_is_their_group_not_a_tie(command: str) -> None:
    """"tray" of tray-a and tray-b was refused as equally close to both (a misspelling of
    either); after every / each / both / all, or as a plural, it is the group of the trays."""
    assert translate(command, TRAYS)["goal"] == {"tray-a": {"inner_tube": 2}, "tray-b": {"inner_tube": 2}}


def test_the_shared_head_noun_alone_is_still_refused_naming_no_guess() -> None:
    with pytest.raises(TranslationError, match="which shelf"):
        translate("the tray should have 2 pumps", TRAYS)


MOVE_PUMPS = {"back_room": {"pump": 1}, "front_rack": {"pump": 2}}


@pytest.mark.parametrize("rule, want", [
    ("The amr robots aren't to be used today.", [{"never": ["zip_1", "zip_2"]}]),
    ("Porter isn't to be involved.", [{"never": ["porter"]}]),
    ("zip_1 isn't allowed to take anything out of the back room.", [{"never": ["zip_1"], "from": "back_room"}]),
    ("Leave the strongest robot out.", [{"never": ["porter"]}]),
    ("Keep porter out.", [{"never": ["porter"]}]),
    ("Porter mustn't carry any pumps.", [{"never": ["porter"], "product": "pump"}]),
    ("zip_2 must not carry any pumps or chains.", [{"never": ["zip_2"], "product": "pump"},
                                                  {"never": ["zip_2"], "product": "chain"}]),
])
def test_robot_rules_said_as_not_to_be_used_not_allowed_left_out_or_any_item(rule: str, want) -> None:
    """Rule phrasings the held-out writers used: "X aren't to be used", "X isn't allowed to V",
    "leave / keep X out", "X mustn't carry any ITEM"; each read with the move it goes with."""
    command = f"{rule} Move 2 pumps from the back room to the front rack."
    got = translate(command, BIKES)
    assert got["goal"] == MOVE_PUMPS
    assert sorted(got["constraints"], key=str) == sorted(want, key=str)


@pytest.mark.parametrize("command, goal", [
    ("Repair bench, three pumps please.", {"repair_bench": {"pump": 3}}),
    ("the back room, 2 helmets and 1 chain", {"back_room": {"helmet": 2, "chain": 1}}),
    ("Wall hooks, helmets 1, chains 2", {"wall_hooks": {"helmet": 1, "chain": 2}}),
])
def test_a_place_then_a_comma_then_counts_reads_as_with_a_colon(command: str, goal: dict) -> None:
    """"P, N X" is "P: N X" (the place is the topic; the counts are what it should hold)."""
    assert translate(command, BIKES)["goal"] == goal


@pytest.mark.parametrize("command, goal", [
    # keeping one item where it is, said after the clause that names the place, or with its owner
    ("The front rack should have 1 inner tube, helmets stay as is.", {"front_rack": {"inner_tube": 1, "helmet": 2}}),
    ("The back room's pumps stay where they are, and it should have 3 inner tubes.",
     {"back_room": {"pump": 3, "inner_tube": 3}}),
    # swapping all of two places, each said with its own phrase
    ("Swap everything on the wall hooks with everything on the repair bench.",
     {"wall_hooks": {"helmet": 0, "chain": 2}, "repair_bench": {"helmet": 3, "chain": 1}}),
    ("Swap what's on the wall hooks with what's on the repair bench",
     {"wall_hooks": {"helmet": 0, "chain": 2}, "repair_bench": {"helmet": 3, "chain": 1}}),
    # "any X" after a negated "there be" is none of it
    ("There shouldn't be any helmets left on the front rack.", {"front_rack": {"helmet": 0}}),
    ("There mustn't be any pumps or inner tubes in the back room", {"back_room": {"pump": 0, "inner_tube": 0}}),
    # a range said with the item after its first bound
    ("The wall hooks need at least 2 helmets but no more than 4.", {"wall_hooks": {"helmet": {"at_least": 2, "at_most": 4}}}),
    # "leave" a place with a count, and "just N"
    ("Leave the front rack with 2 inner tubes", {"front_rack": {"inner_tube": 2}}),
    ("Leave just one helmet on the wall hooks", {"wall_hooks": {"helmet": 1}}),
])
def test_keep_swap_all_none_left_ranges_and_leave_with(command: str, goal: dict) -> None:
    assert translate(command, BIKES)["goal"] == goal


CARTS = {**BIKES, "robots": {"porter": BIKES["robots"]["porter"],
                             "cart_a": {"start": [15, 8], "skills": {"carry": 1}},
                             "cart_b": {"start": [18, 8], "skills": {"carry": 1}}}}


def test_robots_named_by_a_shared_stem_and_a_label_are_a_group() -> None:
    """Robots cart_a and cart_b (no kind): "the carts" are those two, as "the tugs" are tug1..tug4
    (it was refused as equally close to both names)."""
    got = translate("Keep the carts off the front rack. Move 2 pumps from the back room to the front rack.", CARTS)
    assert got["goal"] == MOVE_PUMPS
    assert sorted(map(str, got["constraints"])) == sorted(map(str, [
        {"never": ["cart_a", "cart_b"], "from": "front_rack"}, {"never": ["cart_a", "cart_b"], "to": "front_rack"}]))


def test_the_shared_stem_of_robots_said_as_one_is_refused_naming_them() -> None:
    with pytest.raises(TranslationError, match="cart_a, cart_b"):
        translate("The cart should move 2 pumps from the back room to the front rack.", CARTS)


@pytest.mark.parametrize("command", [
    "Tell zip_1 to move 2 pumps from the back room to the front rack.",
    "can yous get zip_1 to move 2 pumps from the back room to the front rack",
])
def test_a_robot_told_to_do_a_move_and_chat_spellings_of_you(command: str) -> None:
    """"tell R to <move>" is R addressed with the move, as "ask R to" is; "yous" is "you"."""
    got = translate(command, BIKES)
    assert got["goal"] == MOVE_PUMPS
    assert got["constraints"] == [{"only": ["zip_1"], "product": "pump", "from": "back_room", "to": "front_rack"}]


def test_em_is_them() -> None:
    got = translate("Take 2 pumps off the back room and put 'em on the front rack.", BIKES)
    assert got["goal"] == MOVE_PUMPS

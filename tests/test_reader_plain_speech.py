"""Plain and non-native English for bounds, corrections and robot skills: "P never under 6 X",
"P X: not less than 3, not more than 5", "Send 5 X, no wait, 4 X from P to Q", "robots who
carry 3 or more", "split them equal". Each was refused on a word."""
from __future__ import annotations

import pytest

from pipflow.errors import TranslationError
from pipflow.warehouse.language.translator import translate
from tests.tannery_world import TANNERY

# tannery stock: drying_loft {cart_wheel 6, belt_round 2}, vat_east {cart_wheel 1, dye_drum 4},
# vat_west {belt_round 5}, finishing_table {dye_drum 1}


@pytest.mark.parametrize("command, amount", [
    ("Vat west never under 3 belt rounds", {"at_least": 3}),
    ("Vat west never below 3 belt rounds", {"at_least": 3}),
    ("Vat west never more than 4 belt rounds", {"at_most": 4}),
    ("Vat west belt rounds: not less than 3, not more than 4", {"at_least": 3, "at_most": 4}),
])
def test_bounds_said_plainly(command: str, amount: dict) -> None:
    assert translate(command, TANNERY)["goal"] == {"vat_west": {"belt_round": amount}}


@pytest.mark.parametrize("command", ["Send 5 dye drums, no wait, 3 dye drums from vat east to the finishing table",
                                     "Send 5 dye drums, no wait, 3 from vat east to the finishing table",
                                     "Send 5 dye drums - no sorry, make that 3 - from vat east to the finishing table",
                                     "Send 5, no sorry 3, dye drums from vat east to the finishing table"])
def test_a_count_taken_back_with_its_product_is_the_new_count(command: str) -> None:
    assert translate(command, TANNERY)["goal"] == {"vat_east": {"dye_drum": 1}, "finishing_table": {"dye_drum": 4}}


def test_a_count_corrected_before_a_product_with_a_comma_after_is_still_a_count_to_finish() -> None:
    """"Send 5, no sorry 3, to the table": no product follows the correction, nothing is guessed."""
    with pytest.raises(TranslationError):
        translate("Send 5, no sorry 3, to the finishing table", TANNERY)


def test_a_correction_that_names_another_product_is_refused() -> None:
    with pytest.raises(TranslationError):
        translate("Send 5 dye drums, no wait, 3 belt rounds from vat east to the finishing table", TANNERY)


def test_robots_who_carry() -> None:
    got = translate("Move 2 cart wheels from the drying loft to vat west using only robots who carry 2 or more", TANNERY)
    assert got["constraints"] == [{"only": ["mule1", "mule2", "crane"], "product": "cart_wheel",
                                   "from": "drying_loft", "to": "vat_west"}]


def test_split_them_equal() -> None:
    got = translate("Take 4 cart wheels off the drying loft and split them equal between vat east and vat west", TANNERY)
    assert got["goal"] == {"drying_loft": {"cart_wheel": 2}, "vat_east": {"cart_wheel": 3}, "vat_west": {"cart_wheel": 2}}


@pytest.mark.parametrize("command", ["Vat west, no more than 4 belt rounds in there",
                                     "Vat west: no more than 4 belt rounds in it"])
def test_a_fronted_place_said_again_by_a_pronoun(command: str) -> None:
    assert translate(command, TANNERY)["goal"] == {"vat_west": {"belt_round": {"at_most": 4}}}


@pytest.mark.parametrize("command", ["Mules only on belt rounds", "Only the mules on belt rounds"])
def test_robots_only_on_a_product_is_a_rule_scoped_to_it(command: str) -> None:
    assert translate(command, TANNERY)["constraints"] == [{"only": ["mule1", "mule2"], "product": "belt_round"}]


def test_robots_are_not_to_handle_a_product() -> None:
    assert translate("The mules aren't to handle dye drums", TANNERY)["constraints"] == [
        {"never": ["mule1", "mule2"], "product": "dye_drum"}]


@pytest.mark.parametrize("command", ["The drying loft's cart wheels should come down to 2",
                                     "the cart wheels on the drying loft should go down to 2"])
def test_a_count_that_comes_down_to_n_is_set_to_n(command: str) -> None:
    assert translate(command, TANNERY)["goal"] == {"drying_loft": {"cart_wheel": 2}}


def test_leave_it_be_keeps_it_as_it_is() -> None:
    got = translate("Leave the drying loft's belt rounds be and move 1 dye drum from vat east to vat west", TANNERY)
    assert got["goal"] == {"drying_loft": {"belt_round": 2}, "vat_east": {"dye_drum": 3}, "vat_west": {"dye_drum": 1}}


def test_restock_a_place_with_units_from_another_is_a_move() -> None:
    got = translate("Restock the finishing table with 2 dye drums from vat east", TANNERY)
    assert got["goal"] == {"vat_east": {"dye_drum": 2}, "finishing_table": {"dye_drum": 3}}


def test_i_want_a_place_holding_n() -> None:
    assert translate("I want vat west holding 3 belt rounds", TANNERY)["goal"] == {"vat_west": {"belt_round": 3}}


@pytest.mark.parametrize("command, goal", [
    ("The belt rounds on vat west, move them to vat east", {"vat_west": {"belt_round": 0}, "vat_east": {"belt_round": 5}}),
    ("4 cart wheels of the drying loft, split them evenly between vat east and vat west",
     {"drying_loft": {"cart_wheel": 2}, "vat_east": {"cart_wheel": 3}, "vat_west": {"cart_wheel": 2}}),
    ("Drying loft wheels, halve them", {"drying_loft": {"cart_wheel": 3}}),
])
def test_a_fronted_topic_taken_up_by_a_pronoun(command: str, goal: dict) -> None:
    assert translate(command, TANNERY)["goal"] == goal


def test_a_sentence_that_reads_as_said_is_not_rearranged() -> None:
    """"P's X - make it 2" reads as said (set to 2); the topic is moved only where it does not."""
    assert translate("The drying loft's cart wheels - make it 2", TANNERY)["goal"] == {"drying_loft": {"cart_wheel": 2}}


def test_a_product_called_by_what_its_container_holds() -> None:
    """"strings" of string_spool: a spool (like a set, kit, reel or roll) holds what it is named for."""
    from tests.test_reader_group_words import SHOP
    got = translate("Move 3 strings from the rod rack to the till counter", SHOP)
    assert got["goal"] == {"rod_rack": {"string_spool": 5}, "till_counter": {"string_spool": 4}}


def test_except_what_is_sitting_on_a_place() -> None:
    got = translate("Move all the belt rounds to vat east except what's sitting on the drying loft", TANNERY)
    assert got["goal"] == {"vat_east": {"belt_round": 5}, "drying_loft": {"belt_round": 2}, "vat_west": {"belt_round": 0},
                           "finishing_table": {"belt_round": 0}}


def test_a_list_announced_is_talk() -> None:
    got = translate("Two things: vat east should have 2 belt rounds, and 1 dye drum from vat east to vat west", TANNERY)
    assert got["goal"] == {"vat_east": {"belt_round": 2, "dye_drum": 3}, "vat_west": {"dye_drum": 1}}


def test_a_place_is_to_hold() -> None:
    assert translate("Vat west's to hold 3 belt rounds", TANNERY)["goal"] == {"vat_west": {"belt_round": 3}}


def test_a_list_line_that_opens_the_command_sets_the_count() -> None:
    assert translate("Vat west 3 belt rounds, drying loft 1.", TANNERY)["goal"] == {
        "vat_west": {"belt_round": 3}, "drying_loft": {"belt_round": 1}}


def test_a_list_line_after_another_sentence_is_still_asked() -> None:
    """After "Add 2 X to P." a bare "Q 3." may continue the adding: never read as a set."""
    with pytest.raises(TranslationError):
        translate("Add 2 belt rounds to vat east. Drying loft 3.", TANNERY)


@pytest.mark.parametrize("command", ["Every location in here should end up with one dye drum",
                                     "Every location in the building should end up with one dye drum"])
def test_every_place_in_the_building_is_every_place(command: str) -> None:
    assert translate(command, TANNERY)["goal"] == {p: {"dye_drum": 1} for p in TANNERY["shelves"]}


def test_swap_round_everything_on_them() -> None:
    got = translate("Swap vat east and vat west round, everything on them", TANNERY)
    assert got["goal"] == {"vat_east": {"cart_wheel": 0, "belt_round": 5, "dye_drum": 0},
                           "vat_west": {"cart_wheel": 1, "belt_round": 0, "dye_drum": 4}}


def test_could_do_with_on_top_of_what_it_has_adds() -> None:
    got = translate("The finishing table could do with one of each, on top of what's already there", TANNERY)
    assert got["goal"] == {"finishing_table": {"cart_wheel": 1, "belt_round": 1, "dye_drum": 2}}


@pytest.mark.parametrize("command", ["While you're at it, move 1 dye drum from vat east to vat west",
                                     "hiya, while ur at it move 1 dye drum from vat east to vat west"])
def test_while_you_are_at_it_says_nothing_more(command: str) -> None:
    assert translate(command, TANNERY)["goal"] == {"vat_east": {"dye_drum": 3}, "vat_west": {"dye_drum": 1}}


def test_a_place_that_could_take_another_n() -> None:
    assert translate("Vat west could take another 2 dye drums", TANNERY)["goal"] == {"vat_west": {"dye_drum": 2}}


def test_a_place_brought_to_a_count_without_a_verb() -> None:
    """"vat west to 3 belt rounds, drying loft to 1": a set, the second with its product elided."""
    got = translate("vat west to 3 belt rounds, drying loft to 1", TANNERY)
    assert got["goal"] == {"vat_west": {"belt_round": 3}, "drying_loft": {"belt_round": 1}}


@pytest.mark.parametrize("command", ["Need 2 dye drums moving from vat east to the finishing table",
                                     "We need 2 dye drums taking to the finishing table from vat east"])
def test_a_move_said_as_a_need(command: str) -> None:
    assert translate(command, TANNERY)["goal"] == {"vat_east": {"dye_drum": 2}, "finishing_table": {"dye_drum": 3}}


def test_sort_it_so_opens_the_order() -> None:
    assert translate("Sort it so vat west has 3 belt rounds", TANNERY)["goal"] == {"vat_west": {"belt_round": 3}}


def test_sort_it_so_with_nothing_after_is_no_order() -> None:
    with pytest.raises(TranslationError):
        translate("Sort it so.", TANNERY)


@pytest.mark.parametrize("rule", ["Only robots with a cold pass", "Only robots that have a cold pass",
                                  "Only robots with cold_pass"])
def test_robots_said_to_carry_a_tag(rule: str) -> None:
    world = {**TANNERY, "robots": {**TANNERY["robots"],
                                   "crane": {**TANNERY["robots"]["crane"], "tags": ["cold_pass"]}}}
    got = translate(f"Move 2 dye drums from vat east to the finishing table. {rule}.", world)
    assert got["constraints"] == [{"only": ["crane"]}]


@pytest.mark.parametrize("command", ["vat west: no belt rounds by end of shift",
                                     "vat west: no belt rounds by the end of the day please"])
def test_a_deadline_said_with_by_is_set_aside(command: str) -> None:
    assert translate(command, TANNERY)["goal"] == {"vat_west": {"belt_round": 0}}


def test_by_with_a_count_or_a_fraction_is_read() -> None:
    assert translate("Cut vat west's belt rounds by a fifth", TANNERY)["goal"] == {"vat_west": {"belt_round": 4}}

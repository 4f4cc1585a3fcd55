"""Commands said without stops, as a speech recogniser writes what a team leader dictates (issue
23's twelfth round): read with a stop where the next word cannot continue the sentence before it,
every word still placed, the stops said in the echo; two placings that ask for different things
are refused with each offered."""
from __future__ import annotations

import pytest

from pipflow.errors import TranslationError
from pipflow.warehouse.language.parser import parse
from pipflow.warehouse.language.runon import RunOnChoice
from pipflow.warehouse.language.translator import translate, understand
from tests.tannery_world import TANNERY

# tannery stock: drying_loft {cart_wheel 6, belt_round 2}, vat_east {cart_wheel 1, dye_drum 4},
# vat_west {belt_round 5}, finishing_table {dye_drum 1}; carry: crane 4 (gantry), mule1 2, mule2 2, flea 1 (amr)

TWO_DRUMS = {"vat_east": {"dye_drum": 2}, "finishing_table": {"dye_drum": 3}}


def test_two_orders_said_without_a_stop_are_both_read_and_the_stop_is_said() -> None:
    got = understand("clear out the finishing table vat west should end up with 3 belt rounds", TANNERY)
    assert got["goal"] == {"finishing_table": {"cart_wheel": 0, "belt_round": 0, "dye_drum": 0},
                           "vat_west": {"belt_round": 3}}
    assert got["explanation"][0] == ("said without stops, read as: 'clear out the finishing table' / "
                                     "'vat west should end up with 3 belt rounds'")


def test_a_rule_said_before_an_order_without_a_stop_holds_for_the_command() -> None:
    got = translate("gantries only on this one move 2 dye drums from vat east to the finishing table", TANNERY)
    assert got["goal"] == TWO_DRUMS and got["constraints"] == [{"only": ["crane"]}]


@pytest.mark.parametrize("tail", ["thats all for now", "thats it", "cheers mate"])
def test_talk_run_on_after_an_order_is_set_aside_and_said(tail: str) -> None:
    got = understand(f"move 2 dye drums from vat east to the finishing table {tail}", TANNERY)
    assert got["goal"] == TWO_DRUMS
    assert any(line.startswith("set aside") and f"'{tail}'" in line for line in got["explanation"])


def test_a_part_that_asks_for_nothing_is_no_sentence_of_its_own() -> None:
    """ "too" read as "also" would leave "finishing table" a sentence that asks for nothing: the
    move would lose where it goes."""
    with pytest.raises(TranslationError, match="cannot place 'finishing table'"):
        translate("move 2 dye drums from vat east too finishing table", TANNERY)


def test_a_stop_never_sets_aside_a_part_that_does_not_read() -> None:
    with pytest.raises(TranslationError, match="frobnicate"):
        translate("move 2 dye drums from vat east to the finishing table frobnicate vat west", TANNERY)


def test_two_placings_of_the_stop_that_ask_for_different_things_are_offered_not_chosen() -> None:
    """ "with crane" ends the first order or opens the second: which move the rule binds is not said."""
    with pytest.raises(RunOnChoice) as err:
        parse("move 2 dye drums from vat east to the finishing table with crane move 1 cart wheel "
              "from the drying loft to vat west", TANNERY)
    scopes = [c["constraints"][0].get("product") for c in err.value.candidates if c["constraints"]]
    assert "dye_drum" in scopes and "cart_wheel" in scopes
    assert "end each sentence with a full stop" in str(err.value)


@pytest.mark.parametrize("closing", ["that's all", "thats it for now", "that is all for today"])
def test_a_closing_clause_is_set_aside(closing: str) -> None:
    got = understand(f"Move 2 dye drums from vat east to the finishing table, {closing}.", TANNERY)
    assert got["goal"] == TWO_DRUMS and got["explanation"][-1].startswith("set aside")


def test_a_closing_with_more_words_is_read_as_words() -> None:
    with pytest.raises(TranslationError):
        translate("Move 2 dye drums from vat east to the finishing table, that's all of them.", TANNERY)


def test_a_list_of_places_said_without_commas_is_a_list() -> None:
    got = translate("split 3 dye drums on vat east evenly between vat west drying loft and the finishing table", TANNERY)
    assert got["goal"] == translate("split 3 dye drums on vat east evenly between vat west, drying loft and "
                                    "the finishing table", TANNERY)["goal"]


def test_two_places_side_by_side_without_and_are_no_list() -> None:
    with pytest.raises(TranslationError):
        translate("move 2 dye drums from vat east vat west", TANNERY)


@pytest.mark.parametrize("command", ["leave vat west how it is", "leave vat west exactly how it is"])
def test_how_it_is_keeps_a_place_as_it_is(command: str) -> None:
    assert translate(command, TANNERY)["goal"] == {"vat_west": {"cart_wheel": 0, "belt_round": 5, "dye_drum": 0}}


def test_a_place_taken_up_again_by_in_it_after_make_sure() -> None:
    assert translate("make sure vat west has got at least 6 belt rounds in it", TANNERY)["goal"] == \
        {"vat_west": {"belt_round": {"at_least": 6}}}


@pytest.mark.parametrize("command", ["put 2 more dye drums on the finishing table 1 on vat east",
                                     "put 2 more dye drums on the finishing table. 1 on vat east",
                                     "put 2 more dye drums on the finishing table and 1 on vat east"])
def test_a_bare_count_after_n_more_is_asked_with_a_stop_or_without(command: str) -> None:
    """Vat east holds dye drums: "1 on vat east" after "2 more" is 1 more or 1 in all; a stop, said
    or put in, does not make it either (it was read as 1 in all after a full stop: a misreading)."""
    with pytest.raises(TranslationError):
        translate(command, TANNERY)


@pytest.mark.parametrize("command, goal", [
    ("move won dye drum from vat east to the finishing table", {"vat_east": {"dye_drum": 3}, "finishing_table": {"dye_drum": 2}}),
    ("take for dye drums off vat east", {"vat_east": {"dye_drum": 0}}),
])
def test_a_number_misheard_as_a_word_is_offered_never_read(command: str, goal: dict) -> None:
    """ "won", "for", "ate" as a recogniser writes a count said aloud: a candidate reading that says
    which word it read as which; the command itself is refused."""
    with pytest.raises(TranslationError) as err:
        parse(command, TANNERY)
    offered = [c for c in err.value.candidates if c["goal"] == goal]
    assert offered and offered[0]["reading"].startswith("read '")


def test_should_be_sitting_at_is_a_final_count_and_is_sitting_at_no_new_wish() -> None:
    assert translate("vat west should be sitting at 3 belt rounds", TANNERY)["goal"] == {"vat_west": {"belt_round": 3}}
    with pytest.raises(TranslationError):
        translate("vat west is sitting at 3 belt rounds", TANNERY)   # a report of the stock, not asked


@pytest.mark.parametrize("tail", ["far as itll go", "as far as it will go", ", as much as it takes", "as much as will fit"])
def test_a_fill_said_to_go_as_far_as_it_can_is_a_fill(tail: str) -> None:
    assert translate(f"fill vat west up with cart wheels {tail}", TANNERY)["goal"] == {"vat_west": {"cart_wheel": 7}}


@pytest.mark.parametrize("said", ["whatevers", "whatever's", "whatever is", "whatever"])
def test_swap_with_whatever_is_on_a_place(said: str) -> None:
    assert translate(f"swap everything on vat east with {said} on vat west", TANNERY)["goal"] == \
        translate("swap vat east and vat west", TANNERY)["goal"]


def test_a_filler_before_a_stop_is_echoed_with_the_sentence_after_it() -> None:
    got = understand("swap everything on vat east with whatever is on vat west please thats all", TANNERY)
    assert got["explanation"][0] == ("said without stops, read as: 'swap everything on vat east with whatever is "
                                     "on vat west' / 'please thats all'")


@pytest.mark.parametrize("tail", ["yonder", "and the blorp", "5", "the whole lot"])
def test_a_part_that_is_no_talk_by_what_it_is_is_never_set_aside_by_a_stop(tail: str) -> None:
    """Words no rule reads that lack content are not talk for that alone: a stop put in sets a part
    aside only when it is a greeting, a closing, thanks or a statement with its subject."""
    with pytest.raises(TranslationError):
        translate(f"move 2 dye drums from vat east to the finishing table {tail}", TANNERY)

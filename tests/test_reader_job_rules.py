"""Robot rules said of "this one" (the job): "Gantries only on this one: ...", "the mules stay off
this one", "the mules sit this one out". The lexer reads "one" as a count, so the grammar's
literal "one" never matched and such commands were refused; a rule for the whole command that
restates an addressed robot's rule over the command's one move is that rule, not a second one."""
from __future__ import annotations

import pytest

from pipflow.warehouse.language.translator import translate
from tests.tannery_world import TANNERY

MOVE = "3 belt rounds from vat west to the drying loft"
GOAL = {"vat_west": {"belt_round": 2}, "drying_loft": {"belt_round": 5}}


@pytest.mark.parametrize("command, rule", [
    (f"Gantries only on this one: {MOVE}", {"only": ["crane"]}),
    (f"Only the gantry for this one: move {MOVE}", {"only": ["crane"]}),
    (f"The mules stay off this one: move {MOVE}", {"never": ["mule1", "mule2"]}),
    (f"The mules sit this one out. Move {MOVE}", {"never": ["mule1", "mule2"]}),
])
def test_a_rule_for_this_one_holds_for_the_whole_command(command: str, rule: dict) -> None:
    got = translate(command, TANNERY)
    assert got["goal"] == GOAL
    assert got["constraints"] == [rule]


def test_a_whole_command_rule_that_restates_the_addressed_move_is_one_rule() -> None:
    got = translate("Have flea bring 1 dye drum from vat east to the finishing table. Just flea on this one.",
                    TANNERY)
    assert got["constraints"] == [{"only": ["flea"], "product": "dye_drum", "from": "vat_east",
                                   "to": "finishing_table"}]


def test_a_whole_command_rule_over_two_moves_stays_a_rule_of_its_own() -> None:
    """With two moves the addressed robot's rule covers one of them: "only flea" for the whole
    command says more, so both are kept."""
    got = translate("Have flea bring 1 dye drum from vat east to the finishing table. Move 2 belt rounds "
                    "from vat west to the drying loft. Just flea on this one.", TANNERY)
    assert sorted(got["constraints"], key=len) == [
        {"only": ["flea"]}, {"only": ["flea"], "product": "dye_drum", "from": "vat_east", "to": "finishing_table"}]


@pytest.mark.parametrize("command", [
    "Move 2 belt rounds from vat west to vat east, 1 dye drum from vat east to the finishing table, and keep flea out of it",
    "Move 2 belt rounds from vat west to vat east. Keep flea out of it."])
def test_keep_a_robot_out_of_it_is_the_job_never_a_place(command: str) -> None:
    """"out of it" is the idiom for the job; read as a place "it" stands for, it had been asked
    with one place per candidate, and the job's reading was never offered."""
    assert translate(command, TANNERY)["constraints"] == [{"never": ["flea"]}]


def test_keep_a_robot_out_of_a_named_place_is_that_place() -> None:
    assert translate("Keep flea out of vat east", TANNERY)["constraints"] == [
        {"never": ["flea"], "from": "vat_east"}, {"never": ["flea"], "to": "vat_east"}]


@pytest.mark.parametrize("command, rule", [
    (f"Move {MOVE}. The mules not to be used", {"never": ["mule1", "mule2"]}),
    (f"Move {MOVE}. Only the gantry to be used", {"only": ["crane"]}),
])
def test_a_rule_said_as_a_notice_without_its_is(command: str, rule: dict) -> None:
    """"Queenie not to be used", "Only tuggers to be used": a notice's "is" / "are" left out."""
    got = translate(command, TANNERY)
    assert got["goal"] == GOAL
    assert got["constraints"] == [rule]

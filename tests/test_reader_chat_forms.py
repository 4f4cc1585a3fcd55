"""Chat forms read as the plain words the grammar has (issue 23's fifteenth round, from the
Singapore English of the loyang set): clause-closing particles ("lah", "ah", "liao"), a "can" /
"ok" / "can or not" tag, "go and <verb>", "<item> go <place>", "<place> got" for "has". Through
the real warehouse reader, in a ferry terminal of our own."""
from __future__ import annotations

import copy

import pytest

from pipflow.errors import TranslationError
from pipflow.warehouse.language.translator import understand
from tests.terminal_world import TERMINAL


@pytest.mark.parametrize("command, goal", [
    ("Move 3 crates from quay to shed lah", {"quay": {"crate": 11}, "shed": {"crate": 5}}),
    ("quay got too many crates liao, take 4 off can", {"quay": {"crate": 10}}),
    ("Shed should have 6 barrels by 3pm ok. can or not?", {"shed": {"barrel": 6}}),
    ("go and shift 3 crates from quay to shed", {"quay": {"crate": 11}, "shed": {"crate": 5}}),
    ("Move 3 crates from quay to shed thanks ah (thumbs up)", {"quay": {"crate": 11}, "shed": {"crate": 5}}),
    ("from quay, 3 crates go shed", {"quay": {"crate": 11}, "shed": {"crate": 5}}),
])
def test_chat_forms_read_as_their_plain_words(command: str, goal: dict) -> None:
    assert understand(command, TERMINAL)["goal"] == goal


def test_a_robot_sent_with_go_and_does_the_move() -> None:
    got = understand("titan go and bring 2 barrels from shed to ramp", TERMINAL)
    assert got["goal"] == {"shed": {"barrel": 4}, "ramp": {"barrel": 3}}
    assert got["constraints"] and got["constraints"][0]["only"] == ["titan"]


def test_a_word_of_the_world_is_never_a_particle_or_a_tag() -> None:
    """Where a product is called "can", "... 3 can" is its count, never a tag left out."""
    world = copy.deepcopy(TERMINAL)
    world["products"]["can"] = world["products"].pop("barrel")
    for stock in world["stock"].values():
        if "barrel" in stock:
            stock["can"] = stock.pop("barrel")
    got = understand("Move 3 crates from quay to shed and bring the ramp up to 3 can", world)
    assert got["goal"]["ramp"] == {"can": 3}


def test_a_particle_inside_a_clause_stays_unread() -> None:
    """Only a particle closing a clause is left out: "ah" inside one must still be placed."""
    with pytest.raises(TranslationError):
        understand("Move ah 3 crates from quay to shed", TERMINAL)


def test_a_common_word_is_no_slip_of_a_name_that_is_no_word() -> None:
    """First measurement of pair W: "Use just the pallet jacks ..." in a world without pallet jacks
    read "jacks" as a slip of the robot jacu, and the bench executed it. A common English word
    as written is a slip only of a name that is a word too, spelt another way ("dispatch" of
    despatch); an uncommon slip ("jaku") still reads as the name."""
    world = copy.deepcopy(TERMINAL)
    world["robots"]["jacu"] = world["robots"].pop("wasp")
    world["shelves"]["despatch"] = world["shelves"].pop("ramp")
    world["stock"]["despatch"] = world["stock"].pop("ramp")
    with pytest.raises(TranslationError, match="jacks"):
        understand("Use just the jacks to move 2 crates from quay to shed", world)
    for said in ("jacu", "jaku"):
        got = understand(f"Use only {said} to move 2 crates from quay to shed", world)
        assert got["constraints"][0]["only"] == ["jacu"]
    assert understand("Move 2 crates from quay to dispatch", world)["goal"] == \
        {"quay": {"crate": 12}, "despatch": {"crate": 2}}

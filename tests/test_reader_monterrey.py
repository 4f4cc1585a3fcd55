"""Issue 23's thirty-second round, from pair MM's first measurement (an auto-parts centre's
coordinator near Monterrey writing English as a native Spanish speaker): "must to have" (a modal
with a stray "to"), "each one" closing a clause, "stays like it is", Spanish openers and thanks ("oye", "bueno", "porfa", "ahorita", "gracias
jefe"), Spanish counts ("cinco"), "the ones of P" for the ones on P, and a report whose subject
is a bare noun with where it is from ("customer in Lisbon rejected them"). Through the real
warehouse reader, in the ferry terminal of our own."""
from __future__ import annotations

import copy

import pytest

from pipflow.errors import TranslationError
from pipflow.warehouse.language.translator import understand
from tests.terminal_world import TERMINAL

MOVE = {"quay": {"crate": 9}, "shed": {"crate": 7}}


def goal(command: str, world: dict = TERMINAL) -> dict:
    return understand(command, world)["goal"]


@pytest.mark.parametrize("command", [
    "porfa move cinco crates from quay to shed",
    "Oye, move 5 crates from quay to shed",
    "Bueno, move 5 crates from quay to shed, gracias jefe",
    "ahorita move 5 crates from quay to shed",
    "move 5 crates from quay to shed porfavor",
])
def test_spanish_openers_thanks_and_counts_around_an_english_order(command: str) -> None:
    assert goal(command) == MOVE


@pytest.mark.parametrize("said, plain", [
    ("shed must to have 7 crates", "shed must have 7 crates"),
    ("the ramp should to hold dos barrels", "the ramp should hold 2 barrels"),
    ("titan can to not touch barrels", "titan can not touch barrels"),
    ("quay and shed should have 6 barrels each one", "quay and shed should have 6 barrels each"),
    ("move 2 barrels to ramp but quay stays like it is", "move 2 barrels to ramp but quay stays as it is"),
])
def test_second_language_forms_read_as_the_plain_english(said: str, plain: str) -> None:
    assert understand(said, TERMINAL)["goal"] == understand(plain, TERMINAL)["goal"]
    assert understand(said, TERMINAL)["constraints"] == understand(plain, TERMINAL)["constraints"]


def test_to_after_can_the_noun_is_kept() -> None:
    """Only before a verb is the "to" stray: "move 1 can to shed" moves a can there."""
    world = copy.deepcopy(TERMINAL)
    world["products"]["can"] = world["products"].pop("crate")
    world["stock"] = {p: {("can" if k == "crate" else k): n for k, n in row.items()} for p, row in world["stock"].items()}
    assert goal("move 1 can to shed", world) == {"shed": {"can": 3}}


def test_the_ones_of_a_place_are_the_ones_on_it() -> None:
    assert goal("move every barrel to quay except the ones of shed") == \
        goal("move every barrel to quay except the ones on shed")


@pytest.mark.parametrize("remark", ["customer in Lisbon rejected them for scratches",
                                    "the truck from the port arrived late"])
def test_a_report_of_a_bare_noun_from_somewhere_is_set_aside(remark: str) -> None:
    got = understand(f"Move 5 crates from quay to shed, {remark}", TERMINAL)
    assert got["goal"] == MOVE
    assert any("set aside" in line and remark.split()[1] in line for line in got["explanation"]), got["explanation"]


@pytest.mark.parametrize("remark", [
    "customer in Lisbon rejected 3",         # a number
    "the truck from ramp arrived late",      # a name of the world
    "driver at the gate said not the barrels",   # an operative word
])
def test_such_a_report_with_a_number_a_name_or_an_operative_word_is_kept(remark: str) -> None:
    with pytest.raises(TranslationError):
        understand(f"Move 5 crates from quay to shed, {remark}", TERMINAL)

"""Issue 23's twenty-fourth round, from pair EE's first measurement (a night-shift lead at a
Manchester parcel hub, in blunt northern English): "P wants / needs <verb>ing" as the order it
says, urgency and insistence that carry nothing ("sharpish", "no excuses"), indifference that fixes
nothing ("not fussed where"), "at the (very) least", "an' all", "on this lot", "every shelf in the
place", "all them X", "and P same", "a dozen less two", "give us N more", "share X out even
between", "fill P up, as many as it'll take", a sentence with no verb "All the X into P, bar the
ones on Q", "except those on Q", "one of each, on top of what's already there", "has N X on.". Through the real warehouse reader, in the ferry
terminal of our own."""
from __future__ import annotations

import pytest

from pipflow.errors import TranslationError
from pipflow.warehouse.language.translator import understand
from tests.terminal_world import TERMINAL

MOVE = {"quay": {"crate": 11}, "shed": {"crate": 5}}


@pytest.mark.parametrize("command, goal", [
    # quay has 14 crates and 5 barrels, shed 2 crates and 6 barrels, ramp 1 barrel (capacity 12)
    ("Move 3 crates from quay to shed, sharpish", MOVE),
    ("Half of quay's crates want moving to shed", {"quay": {"crate": 7}, "shed": {"crate": 9}}),
    ("The 3 crates on quay need moving to shed, ta", MOVE),
    ("Shed needs emptying", {"shed": {"crate": 0, "barrel": 0}}),
    ("Fill ramp up with crates, as many as itll take", {"ramp": {"crate": 11}}),
    ("Each shelf wants 2 barrels at the very least",
     {s: {"barrel": {"at_least": 2}} for s in ("quay", "shed", "ramp")}),
    ("Shed wants somewhere between 4 and 6 crates, I'm not fussed which",
     {"shed": {"crate": {"at_least": 4, "at_most": 6}}}),
    ("Get shed up to 8 barrels, no excuses", {"shed": {"barrel": 8}}),
    ("Ramp wants at least 2 barrels an all", {"ramp": {"barrel": {"at_least": 2}}}),
    ("Every shelf in the place should have 3 barrels", {s: {"barrel": 3} for s in ("quay", "shed", "ramp")}),
    ("Share all them barrels on shed out even between quay and ramp",
     {"shed": {"barrel": 0}, "quay": {"barrel": 8}, "ramp": {"barrel": 4}}),
    ("Shed to hold 4 barrels, and ramp same", {"shed": {"barrel": 4}, "ramp": {"barrel": 4}}),
    ("Ramp should have a dozen less two barrels", {"ramp": {"barrel": 10}}),
    ("Give us 2 more barrels on ramp", {"ramp": {"barrel": 3}}),
    # a sentence with no verb, "All the X into P": a move (the excepted stock stays, listed)
    ("All the barrels into quay, bar the ones on shed", {"ramp": {"barrel": 0}, "quay": {"barrel": 6}, "shed": {"barrel": 6}}),
    ("All the crates into shed except those on quay", {"ramp": {"crate": 0}, "shed": {"crate": 2}, "quay": {"crate": 14}}),
    ("Every shelf to 4 barrels", {s: {"barrel": 4} for s in ("quay", "shed", "ramp")}),   # a count: no move
    ("Stick one of each on ramp, on top of what's already there", {"ramp": {"crate": 1, "barrel": 2}}),
    ("Make sure shed has at least 3 crates on.", {"shed": {"crate": {"at_least": 3}}}),
])
def test_northern_english_read_as_the_order_it_says(command: str, goal: dict) -> None:
    assert understand(command, TERMINAL)["goal"] == goal


def test_a_rule_on_this_lot_holds_for_the_job_as_on_this_one_does() -> None:
    for said in ("on this lot", "on this one", "on this"):
        got = understand(f"Move 3 crates from quay to shed. Tuggers only {said}", TERMINAL)
        assert got["goal"] == MOVE and got["constraints"] == [{"only": ["ox"]}], said


def test_indifference_and_insistence_never_take_a_rule_or_a_count_with_them() -> None:
    got = understand("Move 3 crates from quay to shed, not fussed which, and don't use titan", TERMINAL)
    assert got["goal"] == MOVE and got["constraints"] == [{"never": ["titan"]}]


@pytest.mark.parametrize("command", [
    "Put as many crates as it will take on ramp",     # "as many as" away from a fill is a count
    "Move all those on shed to quay",                 # "all those" before a place: what, is not said
    "Shed wants moving",                              # a place is not moved
])
def test_what_the_idioms_do_not_cover_is_still_refused(command: str) -> None:
    with pytest.raises(TranslationError):
        understand(command, TERMINAL)

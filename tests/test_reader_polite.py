"""Issue 23's twenty-third round, from pair DD's first measurement (an intern's over-polite
requests): the hedged frames of asking ("Could I trouble you to", "I was wondering whether you
could", "Would you be so kind as to", "Could you possibly", "Would you mind (terribly) <verb>ing"),
a place asked to end up so ("Would it be possible for P to ...", "I was wondering whether P might
..."), courtesies that are no condition ("if it isn't too much trouble", "if at all possible"),
and thanks said warmly ("Thank you ever so much", "Many thanks in advance"). Through the real
warehouse reader, in the ferry terminal of our own."""
from __future__ import annotations

import copy

import pytest

from pipflow.errors import TranslationError
from pipflow.warehouse.language.translator import understand
from tests.terminal_world import TERMINAL

MOVE = {"quay": {"crate": 11}, "shed": {"crate": 5}}


@pytest.mark.parametrize("command, goal", [
    # quay has 14 crates and 5 barrels, shed 2 crates and 6 barrels, ramp 1 barrel
    ("Could I trouble you to move 3 crates from quay to shed when you have a spare moment", MOVE),
    ("I was wondering whether you could move 3 crates from quay to shed", MOVE),
    ("If it isn't too much trouble, would you be so kind as to move 3 crates from quay to shed", MOVE),
    ("Could you possibly move 3 crates from quay to shed? Many thanks in advance", MOVE),
    ("Would you mind moving 3 crates from quay to shed. Thank you ever so much", MOVE),
    ("Would you mind terribly swapping the barrels on shed with the ones on ramp",
     {"shed": {"barrel": 1}, "ramp": {"barrel": 6}}),
    ("Would it be possible for ramp to end up with 4 barrels", {"ramp": {"barrel": 4}}),
    ("I was wondering whether shed might have no more than 3 barrels", {"shed": {"barrel": {"at_most": 3}}}),
    ("If at all possible, could ramp have 4 barrels", {"ramp": {"barrel": 4}}),
])
def test_polite_frames_read_as_the_request(command: str, goal: dict) -> None:
    assert understand(command, TERMINAL)["goal"] == goal


def test_a_courtesy_sets_no_condition_but_a_negation_after_thanks_is_read() -> None:
    got = understand("If it is no bother, could you move 3 crates from quay to shed, and don't use titan", TERMINAL)
    assert got["goal"] == MOVE and got["constraints"] == [{"never": ["titan"]}]
    with pytest.raises(TranslationError):
        understand("move 3 crates from quay to shed. Thanks so much for 3 more", TERMINAL)


def test_a_word_of_a_frame_is_never_read_as_a_robots_name() -> None:
    """'Would you mind ...' where a robot is called mink: "mind" is the frame's word."""
    world = copy.deepcopy(TERMINAL)
    world["robots"]["mink"] = world["robots"].pop("moth")
    got = understand("Would you mind moving 3 crates from quay to shed", world)
    assert got["goal"] == MOVE and not got["constraints"]

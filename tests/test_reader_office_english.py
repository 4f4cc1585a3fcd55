"""Issue 23's twenty-sixth round, from pair GG's first measurement (a third-party warehouse's
coordinator near Chennai, writing Indian English in the warehouse system's chat box): a list
numbered inline ("Today's plan: 1) ... 2) ..."), the passive of an order ("X to be shifted to P",
"P to be emptied", "R not to be used", "X in P to be made 10"), an item as the subject of a
wanted count ("bay 2 gearbox should be between 4 to 6 nos", "bay 3 battery stock should not go
below 6"), "remaining" for the rest, "&" and "b/w", "do the needful" and "revert back once done",
openers that say what the order follows from ("As discussed on call:"), Hindi and Tamil assent
("Achha", "Seri"), and reasons said with no "is" ("truck coming at 4 pm") or with a noun of two
words ("Maersk vehicle reached early"). Through the real warehouse reader, in the ferry terminal
of our own; each reading here was refused before the round."""
from __future__ import annotations

import pytest

from pipflow.errors import TranslationError
from pipflow.warehouse.language.translator import understand
from tests.terminal_world import TERMINAL

MOVE = {"quay": {"crate": 11}, "shed": {"crate": 5}}


@pytest.mark.parametrize("command, goal", [
    # quay has 14 crates and 5 barrels, shed 2 crates and 6 barrels, ramp 1 barrel (capacity 12)
    ("Half of the crates on quay to be shifted to shed", {"quay": {"crate": 7}, "shed": {"crate": 9}}),
    ("Shed to be emptied", {"shed": {"crate": 0, "barrel": 0}}),
    ("crates in quay to be made 10", {"quay": {"crate": 10}}),
    ("quay crates to be kept at 10", {"quay": {"crate": 10}}),
    ("crates on quay not to be moved", {"quay": {"crate": 14}}),
    ("shed barrel stock should not go below 4 nos", {"shed": {"barrel": {"at_least": 4}}}),
    ("shed crate should be between 4 to 6", {"shed": {"crate": {"at_least": 4, "at_most": 6}}}),
    ("the crates on quay should be 10", {"quay": {"crate": 10}}),
    ("From quay, send 3 crates to shed and remaining to ramp", {"quay": {"crate": 0}, "shed": {"crate": 5}, "ramp": {"crate": 11}}),
    ("Achha, move 3 crates from quay to shed. Pls do the needful. Kindly revert back once done.", MOVE),
    ("move 2 crates & 3 barrels from quay to shed",
     {"quay": {"crate": 12, "barrel": 2}, "shed": {"crate": 4, "barrel": 9}}),
    ("split 6 crates from quay b/w shed and ramp", {"quay": {"crate": 8}, "shed": {"crate": 5}, "ramp": {"crate": 3}}),
    ("Meanwhile move 3 crates from quay to shed", MOVE),
    ("move 3 crates from quay to shed, truck coming at 4 pm", MOVE),
    ("move 3 crates from quay to shed, Maersk vehicle reached early", MOVE),
    ("As discussed on call: move 3 crates from quay to shed", MOVE),
])
def test_office_english_read_as_the_order_it_says(command: str, goal: dict) -> None:
    assert understand(command, TERMINAL)["goal"] == goal


def test_a_list_numbered_inline_is_a_job_per_number() -> None:
    got = understand("Today's plan: 1) shed should have 4 crates 2) take 2 barrels off shed 3) moth not to be used", TERMINAL)
    assert got["goal"] == {"shed": {"crate": 4, "barrel": 4}} and got["constraints"] == [{"never": ["moth"]}]
    got = understand("1) move 3 crates from quay to shed 2) dont use moth", TERMINAL)
    assert got["goal"] == MOVE and got["constraints"] == [{"never": ["moth"]}]
    # numbered with a slash, as Vietnamese and French lists are, one job a line or not
    got = understand("1/ move 3 crates from quay to shed\n2/ dont use moth", TERMINAL)
    assert got["goal"] == MOVE and got["constraints"] == [{"never": ["moth"]}]


def test_a_slash_between_numbers_is_no_list() -> None:
    """ "1/2 of the crates": a fraction, refused as a symbol as before; never a list number."""
    with pytest.raises(TranslationError, match="'/'"):
        understand("move 1/2 of the crates from quay to shed", TERMINAL)


def test_numbers_out_of_order_are_no_list() -> None:
    """ "2) ... 3) ...": no list opens at 2; the ")" is no word of an order, and is refused."""
    with pytest.raises(TranslationError, match=r"'\)'"):
        understand("2) move 3 crates from quay to shed 3) dont use moth", TERMINAL)


def test_an_order_to_stop_doing_something_is_never_a_reason() -> None:
    with pytest.raises(TranslationError, match="stop"):
        understand("move 3 crates from quay to shed, stop sending them", TERMINAL)


def test_a_refusal_quotes_the_possessive_as_written() -> None:
    with pytest.raises(TranslationError) as refused:
        understand("Today's crate plan blorp: move 3 crates from quay to shed", TERMINAL)
    assert "zzposs" not in str(refused.value) and "'s" in str(refused.value)

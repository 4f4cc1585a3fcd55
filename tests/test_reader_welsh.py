"""Issue 23's twenty-seventh round, from pair HH's first measurement (a builders' merchant's
stores supervisor outside Cardiff, in Welsh English): "Morning bud", "will you butt" and "diolch"
closing an order, "isn't it" as a tag, "by the counter" for at it, "tidy", the trade's measures
("lengths", "sheets") before an item, and "P's X shouldn't drop below N" with the item as the
subject. Through the real warehouse reader, in the ferry terminal of our own; each reading here
was refused before the round."""
from __future__ import annotations

import pytest

from pipflow.errors import TranslationError
from pipflow.warehouse.language.translator import understand
from tests.terminal_world import TERMINAL

MOVE = {"quay": {"crate": 11}, "shed": {"crate": 5}}


@pytest.mark.parametrize("command, goal", [
    # quay has 14 crates and 5 barrels, shed 2 crates and 6 barrels, ramp 1 barrel (capacity 12)
    ("Morning bud! Shed wants 4 crates on it", {"shed": {"crate": 4}}),
    ("move 3 crates from quay to shed will you butt", MOVE),
    ("move 3 crates from quay to shed, diolch", MOVE),
    ("Double the barrels by the shed", {"shed": {"barrel": 12}}),
    ("I want 10 lengths of crate by the quay, tidy", {"quay": {"crate": 10}}),
    ("Shed's crates shouldn't drop below 3 today bud", {"shed": {"crate": {"at_least": 3}}}),
])
def test_welsh_english_read_as_the_order_it_says(command: str, goal: dict) -> None:
    assert understand(command, TERMINAL)["goal"] == goal


def test_by_before_anything_but_a_place_is_left_as_said() -> None:
    """ "by 5pm" is when; "by hand" is how, and is no word of an order here: refused, never "at"."""
    assert understand("move 3 crates from quay to shed by 5pm", TERMINAL)["goal"] == MOVE
    with pytest.raises(TranslationError, match="'by'"):
        understand("move 3 crates by hand from quay to shed", TERMINAL)

"""Issue 23's twenty-ninth round, from pair JJ's first measurement (a Lagos pharma distributor's
store supervisor writing Nigerian English and Pidgin): "una" (you all) and "oga" greeted,
"abeg" and "biko" (please) anywhere, and the logistics abbreviations "ctns" and "plts" as units.
Through the real warehouse reader, in the ferry terminal of our own."""
from __future__ import annotations

import pytest

from pipflow.errors import TranslationError
from pipflow.warehouse.language.translator import understand
from tests.terminal_world import TERMINAL

MOVE = {"quay": {"crate": 11}, "shed": {"crate": 5}}


@pytest.mark.parametrize("command", [
    "Good morning una. Move 3 crates from quay to shed",
    "Morning oga, move 3 crates from quay to shed",
    "Abeg move 3 crates from quay to shed",
    "move 3 crates from quay to shed biko",
    "move 3 ctns of crates from quay to shed",
])
def test_nigerian_english_read_as_the_order_it_says(command: str) -> None:
    got = understand(command, TERMINAL)
    assert got["goal"] == MOVE


def test_a_greeting_alone_asks_for_nothing() -> None:
    with pytest.raises(TranslationError, match="no goal"):
        understand("Good morning una", TERMINAL)

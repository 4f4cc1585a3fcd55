"""Issue 23's twenty-fifth round, from pair FF's first measurement (a Durban supervisor on the
site's WhatsApp group, in South African English): greetings and exclamations of the register
("Howzit team", "ag", "eish", "ja so", "yebo", "hayibo", "shame", "sharp sharp", "baie dankie"),
faces and gestures as emoji, reasons in clauses of their own ("the client collecting just now",
"her battery is finished shame", "the truck is late again eish"), "check P, it needs ...", "sort it
out", a source said first without its comma ("from quay send 3 crates to shed"), "as many X as
it has Y", and "swap P and Q, the whole lot, everything on them". Through the real warehouse
reader, in the ferry terminal of our own; each reading here was refused before the round."""
from __future__ import annotations

import pytest

from pipflow.errors import TranslationError
from pipflow.warehouse.language.translator import understand
from tests.terminal_world import TERMINAL

MOVE = {"quay": {"crate": 11}, "shed": {"crate": 5}}


@pytest.mark.parametrize("command, goal", [
    # quay has 14 crates and 5 barrels, shed 2 crates and 6 barrels, ramp 1 barrel (capacity 12)
    ("Howzit team. shed should have 4 crates pls, ta", {"shed": {"crate": 4}}),
    ("eish the truck is late again \U0001F644 send 2 more crates to shed now now", {"shed": {"crate": 4}}),
    ("ag move 3 crates from quay to shed, they expired", MOVE),
    ("ja so swap quay and shed. the whole lot, everything on them",
     {"quay": {"crate": 2, "barrel": 6}, "shed": {"crate": 14, "barrel": 5}}),
    ("from quay send 3 crates to shed", MOVE),
    ("From the quay move 3 crates to shed", MOVE),
    ("check shed pls, it needs between 4 and 6 crates. sort it out", {"shed": {"crate": {"at_least": 4, "at_most": 6}}}),
    ("shed must have as many crates as it has barrels", {"shed": {"crate": 6}}),
    ("shed should have twice as many barrels as it has now", {"shed": {"barrel": 12}}),   # its own count, as said
    ("Take all the barrels to quay, the client collecting just now",
     {"quay": {"barrel": 12}, "shed": {"barrel": 0}, "ramp": {"barrel": 0}}),
    ("Morning all. The truck is late again eish. shed should have 4 crates", {"shed": {"crate": 4}}),
    ("yebo. move 3 crates from quay to shed, baie dankie", MOVE),
    ("hayibo move 3 crates from quay to shed sharp sharp", MOVE),
])
def test_south_african_english_read_as_the_order_it_says(command: str, goal: dict) -> None:
    assert understand(command, TERMINAL)["goal"] == goal


def test_a_reason_after_a_rule_is_set_aside_and_the_rule_kept() -> None:
    got = understand("move 3 crates from quay to shed. dont use moth, her battery is finished shame", TERMINAL)
    assert got["goal"] == MOVE and got["constraints"] == [{"never": ["moth"]}]


def test_a_face_or_gesture_is_said_as_set_aside() -> None:
    got = understand("move 3 crates from quay to shed \U0001F64F\U0001F3FD", TERMINAL)
    assert got["goal"] == MOVE
    assert any("set aside" in line and "\U0001F64F" in line for line in got["explanation"])


def test_a_pictograph_that_could_name_a_thing_is_still_refused() -> None:
    """Only faces, hands and hearts are set aside: a cheese, a boxed digit or a tick could say
    what or how many."""
    for symbol in ("\U0001F9C0", "3\ufe0f\u20e3", "\u2705"):
        with pytest.raises(TranslationError, match="is not read in commands|is not one of the"):
            understand(f"move 3 {symbol} crates from quay to shed", TERMINAL)


def test_a_face_ends_a_sentence_so_a_count_is_never_joined_across_it() -> None:
    """ "move 3 <face> crates": the face is a stop, the count is left without its product, refused."""
    with pytest.raises(TranslationError):
        understand("move 3 \U0001F605 crates from quay to shed", TERMINAL)


def test_a_statement_that_names_a_place_is_still_read() -> None:
    """ "again" closing a statement is no repeat; a statement that names a place still must read."""
    with pytest.raises(TranslationError):
        understand("Quay is full again. move 3 crates from quay to shed", TERMINAL)


def test_a_swap_with_a_restriction_after_it_is_not_read_as_a_whole_swap() -> None:
    with pytest.raises(TranslationError):
        understand("swap quay and shed, everything but the barrels", TERMINAL)


"""Issue 23's twenty-eighth round, from pair II's first measurement (a Montreal warehouse lead
writing English as a second language): accented words in talk ("the truck for Québec is late",
"ok là", "Montréal-Nord") had refused the whole command at the alphabet rule. An accented word
is now spelled without its accents when no part of it, spelled so, is a word the reader reads,
so it can only be set aside as talk or be quoted in a refusal; a word that would read as one of
the reader's own ("à" as "a", a name with an accent) is refused as before. With them, French
said in English chat: "svp", "merci", "bonjour", and the 24-hour clock written "15h" or "3h30";
and a number that labels something of the talk ("truck 14 is late", "the Costco truck is at door
3"), which had kept a reason in as if it held a count; and the request "I want you to ..." (with
its calque "I want that you ...", as French, Spanish and Italian say it).
Through the real warehouse and household readers, in worlds of our own."""
from __future__ import annotations

import pytest

from pipflow.errors import TranslationError
from pipflow.household.language.translator import translate
from pipflow.language.characters import accents_folded
from pipflow.warehouse.language.translator import understand
from tests.studio_world import STUDIO
from tests.terminal_world import TERMINAL, with_ramp_called

MOVE = {"quay": {"crate": 11}, "shed": {"crate": 5}}


def test_accented_talk_is_set_aside_and_said() -> None:
    got = understand("move 3 crates from quay to shed, the truck for Québec is late", TERMINAL)
    assert got["goal"] == MOVE
    assert any("'Québec' read as 'Quebec'" in line for line in got["explanation"])
    assert any("set aside" in line and "Quebec is late" in line for line in got["explanation"])


@pytest.mark.parametrize("command, character", [
    ("move 3 crates from quay à shed", "LATIN SMALL LETTER A WITH GRAVE"),        # a grammar word ("a")
    ("move 3 crätes from quay to shed", "LATIN SMALL LETTER A WITH DIAERESIS"),   # a product's name
    ("move 3 crates from qüay to shed", "LATIN SMALL LETTER U WITH DIAERESIS"),   # a place's name
    ("move 3 crates from quay to shed, the truck from Bærum is late", "LATIN SMALL LETTER AE"),  # no accent
])
def test_an_accented_word_the_reader_would_read_is_refused(command: str, character: str) -> None:
    with pytest.raises(TranslationError, match=character):
        understand(command, TERMINAL)


def test_an_accented_word_in_a_clause_with_content_is_still_placed_or_refused() -> None:
    """Spelled without accents it is an unknown word like any other: never skipped."""
    with pytest.raises(TranslationError, match="'Montreal'"):
        understand("move 3 crates from quay Montréal to shed", TERMINAL)


def test_household_accented_talk_is_set_aside_and_said() -> None:
    got = translate("wash the teacup, my cousins from Québec are coming", STUDIO)
    assert {k: v for k, v in got["goal"].items() if v} == {"state": {"teacup": ["clean"]}}
    assert any("'Québec' read as 'Quebec'" in n for n in got["notes"])
    with pytest.raises(TranslationError, match="LATIN SMALL LETTER E WITH ACUTE"):
        translate("wash the teacupé", STUDIO)


def test_the_fold_asks_the_reader_only_about_accented_words() -> None:
    asked: list[str] = []
    text, notes = accents_folded("Ça va, dépôt à 3h", lambda w: asked.append(w) or w == "a")
    assert text == "Ca va, depot à 3h" and len(notes) == 2
    assert asked == ["ca", "depot", "a"]


@pytest.mark.parametrize("command", [
    "move 3 crates from quay to shed svp",
    "Bonjour, move 3 crates from quay to shed, merci",
    "move 3 crates from quay to shed, the truck is at 15h",
    "move 3 crates from quay to shed by 3h30",
    "I want you to move 3 crates from quay to shed",
    "I want that you move 3 crates from quay to shed",
    "we need you to move 3 crates from quay to shed",
    "I'd like you to move 3 crates from quay to shed",
])
def test_french_chat_the_clock_and_wants_read_as_the_order_they_frame(command: str) -> None:
    assert understand(command, TERMINAL)["goal"] == MOVE


def test_a_clock_time_is_never_a_count() -> None:
    with pytest.raises(TranslationError):
        understand("move 3h crates from quay to shed", TERMINAL)


@pytest.mark.parametrize("command, talk", [
    ("move 3 crates from quay to shed, truck 14 is late", "truck 14 is late"),
    ("move 3 crates from quay to shed, the Costco truck is at door 3", "the Costco truck is at door 3"),
])
def test_a_number_that_labels_talk_is_no_count(command: str, talk: str) -> None:
    got = understand(command, TERMINAL)
    assert got["goal"] == MOVE
    assert any(f"'{talk}'" in line for line in got["explanation"] if line.startswith("set aside"))


@pytest.mark.parametrize("command, world", [
    ("move 3 crates from quay to shed, trailer 4 pallets", TERMINAL),   # a unit after it: a count
    ("move 3 crates from quay to shed, we are expecting 4", TERMINAL),   # after a verb: a count
    ("move 3 crates from quay to shed, dock 2 is late", with_ramp_called("dock1")),   # a word of a name
])
def test_a_number_after_a_verb_or_a_word_of_the_world_or_before_a_unit_stays_a_count(command: str, world: dict) -> None:
    with pytest.raises(TranslationError):
        understand(command, world)


def test_a_want_frame_takes_nothing_of_the_order_after_it() -> None:
    """The frame is only the asking: "I want you to not move ..." is refused, never read as a move."""
    with pytest.raises(TranslationError):
        understand("I want you to not move crates from quay to shed", TERMINAL)

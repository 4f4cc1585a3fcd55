""""it" / "there" as a place means the place just named only where nothing else named in the
sentence (or, when it names none, the one before) could be meant. After a move out of one place
and into another, "only the AMRs in there" was read as the last place named (a misreading found
in held-out pair E's first measurement after the fourth round of reader changes); now each place
is offered and nothing is guessed."""
from __future__ import annotations

import pytest

from pipflow.errors import TranslationError
from pipflow.warehouse.language.translator import translate
from tests.test_reader_candidates import BIKES

AMRS = ["zip_1", "zip_2"]


def _scoped(place: str) -> list[dict]:
    return [{"only": AMRS, "from": place}, {"only": AMRS, "to": place}]


def _rules(reading: dict) -> list[dict]:
    return [{k: v for k, v in r.items() if k != "words"} for r in reading.get("constraints") or []]


@pytest.mark.parametrize("command", [
    "take 2 inner tubes out of the front rack and into the back room, amrs only in there",
    "Move 2 inner tubes from the front rack to the back room. Only the amrs in there.",
])
def test_there_after_a_move_between_two_places_is_asked_with_each_offered(command: str) -> None:
    with pytest.raises(TranslationError, match="which place") as err:
        translate(command, BIKES)
    offered = [_rules(c) for c in err.value.candidates]
    assert _scoped("front_rack") in offered
    assert _scoped("back_room") in offered


@pytest.mark.parametrize("command", [
    "Clear the repair bench, and keep the amrs out of there",
    "The repair bench. Keep the amrs out of there.",
])
def test_there_with_one_place_named_is_that_place(command: str) -> None:
    reading = translate(command, BIKES)
    assert _rules(reading) == [{"never": AMRS, "from": "repair_bench"}, {"never": AMRS, "to": "repair_bench"}]


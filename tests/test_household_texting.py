"""Issue 23's twenty-ninth round, from pair JJ's first measurement (a Melbourne teenager texting
the home robots): a letter stretched for feeling ("pleaseee", "sooo") read once, "ur" before
where one is as "you are" ("while ur there") and else "your", "r" as "are", "w" before a noun
phrase as "with", and "tho", "ty", "tysm", "lowkey" as talk. Through the real household reader, in
the studio flat."""
from __future__ import annotations

import pytest

from pipflow.household.language.lexicon import normalize
from pipflow.household.language.translator import translate
from tests.studio_world import STUDIO


def goal(command: str) -> dict:
    return {k: v for k, v in translate(command, STUDIO)["goal"].items() if v}


@pytest.mark.parametrize("command, wanted", [
    ("wash the teacup pleaseee", {"state": {"teacup": ["clean"]}}),
    ("put the teacup in the basin while ur there", {"in": {"basin": ["teacup"]}}),
    ("the teacup and the glass r dirty, wash them", {"state": {"teacup": ["clean"], "glass": ["clean"]}}),
    ("wash the teacup tho ty", {"state": {"teacup": ["clean"]}}),
])
def test_texting_read_as_the_order_it_says(command: str, wanted: dict) -> None:
    assert goal(command) == wanted


@pytest.mark.parametrize("typed, written", [
    ("while ur there", "while you are there"),
    ("wash ur mug", "wash your mug"),
    ("toast w the jam", "toast with the jam"),
    ("sooo hot", "so hot"),
    ("w", "w"),              # alone, before nothing: left as typed
    ("bookkeeper", "bookkeeper"),   # a letter twice is no stretch
])
def test_texting_forms_written_out(typed: str, written: str) -> None:
    assert normalize(typed) == written

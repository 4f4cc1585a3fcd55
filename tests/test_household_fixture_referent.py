"""A pronoun whose referent is a fixture of the home ("something's gone off in the fridge, just get
rid of it": "it" is the fridge) was put in the bin as if it were a thing, and the reader crashed
with a KeyError (held-out set mews, first measurement). It is refused, asking which thing."""
from __future__ import annotations

from pathlib import Path

import pytest

from pipflow.errors import TranslationError
from pipflow.household.language.translator import translate
from pipflow.household.world import load_world

HOME = load_world(Path(__file__).resolve().parent.parent / "benchmarks" / "household" / "world.yaml")


@pytest.mark.parametrize("command", ["The fridge smells, just get rid of it", "Open the fridge and throw it away"])
def test_a_fixture_named_by_a_pronoun_is_never_thrown_away(command: str) -> None:
    with pytest.raises(TranslationError):
        translate(command, HOME)

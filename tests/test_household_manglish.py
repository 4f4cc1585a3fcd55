"""Issue 23's twenty-seventh round, from pair HH's first measurement (a retired teacher in Penang
voice-typing Malaysian English to her home robots): the particles and exclamations "lah", "leh",
"lor", "aiyo", "alamak", "tq", "still" and "later" beside the request, "close back the X" and
"close the X back" (close it again; "put it back" stays where it belongs), and a common English
word as written never read as a slip of a thing's name ("sofa" is no "soda", "scar" no "scarf").
Through the real household reader, in the studio flat."""
from __future__ import annotations

import pytest

from pipflow.errors import TranslationError
from pipflow.household.language.translator import translate
from tests.studio_world import STUDIO


def goal(command: str) -> dict:
    return {k: v for k, v in translate(command, STUDIO)["goal"].items() if v}


@pytest.mark.parametrize("command, wanted", [
    ("wash the teacup lah", {"state": {"teacup": ["clean"]}}),
    ("aiyo, switch off the tablet", {"state": {"tablet": ["off"]}}),
    ("alamak the tablet still on, off it", {"state": {"tablet": ["off"]}}),
    ("tq, wash the glass", {"state": {"glass": ["clean"]}}),
    ("close back the pantry", {"state": {"pantry": ["closed"]}}),
    ("close the pantry back", {"state": {"pantry": ["closed"]}}),
    ("put the teacup back", {"in": {"pantry": ["teacup"]}, "state": {"pantry": ["closed"]}}),
])
def test_malaysian_english_read_as_the_order_it_says(command: str, wanted: dict) -> None:
    assert goal(command) == wanted


@pytest.mark.parametrize("command, word", [("put the teacup on the sofa", "sofa"), ("wash the scar", "scar")])
def test_a_common_word_is_no_slip_of_a_name(command: str, word: str) -> None:
    """Refused on the word as typed: it had been read as the soda (then refused as no place) or
    the scarf (then refused as impossible to wash, a doable-sounding command called impossible)."""
    with pytest.raises(TranslationError, match=f"'{word}' names nothing"):
        translate(command, STUDIO)


def test_a_typo_that_is_no_english_word_is_still_repaired() -> None:
    assert goal("wash the glas") == {"state": {"glass": ["clean"]}}
    assert goal("put the novle on the nightstand") == {"in": {"nightstand": ["novel"]}}

"""Issue 23, from pair OO's household set (a mother in Pretoria talking to the house robots through
her phone's voice assistant: no capitals, no apostrophes, Afrikaans interjections): South African
interjections beside the request ("ag", "ja", "nee man", "shame"), the team told to do it ("tell
the robots to ..."), and a person's name as whose a thing is, typed in lower case with or without
its apostrophe ("xander's novel", "johans novel"). Through the real household reader, in the
studio flat."""
from __future__ import annotations

import pytest

from pipflow.errors import TranslationError
from pipflow.household.language.translator import translate
from tests.studio_world import STUDIO, studio_goal

PLAIN = "put the novel on the nightstand"


@pytest.mark.parametrize("said", [
    "ag put the novel on the nightstand",
    "put the novel on the nightstand ja",
    "nee man put the novel on the nightstand",
    "ja nee put the novel on the nightstand shame",
    "tell the robots to put the novel on the nightstand",
    "ok um ask them to put the novel on the nightstand",
])
def test_interjections_and_the_team_told_are_the_request(said: str) -> None:
    assert studio_goal(said) == studio_goal(PLAIN)


@pytest.mark.parametrize("said", ["put xander's novel on the nightstand", "put xanders novel on the nightstand"])
def test_a_person_in_lower_case_as_whose_a_thing_is(said: str) -> None:
    got = translate(said, STUDIO)
    assert {k: v for k, v in got["goal"].items() if v} == studio_goal(PLAIN)
    assert any("says whose it is" in n for n in got["notes"])


@pytest.mark.parametrize("said", [
    "put tom's novel on the nightstand",     # an English word ("tom") may be a slip: never an owner
    "put toms novel on the nightstand",
])
def test_an_english_word_before_a_thing_is_never_taken_for_its_owner(said: str) -> None:
    with pytest.raises(TranslationError):
        translate(said, STUDIO)


@pytest.mark.parametrize("said", [
    "wash the teacup. same with the glass and then put the novel on the nightstand",
    "wash the teacup, same for the glass then put the novel on the nightstand",
])
def test_the_same_for_a_thing_then_another_order(said: str) -> None:
    assert studio_goal(said) == studio_goal("wash the teacup and the glass and then put the novel on the nightstand")

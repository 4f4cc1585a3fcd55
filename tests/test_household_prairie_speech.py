"""Issue 23's thirty-second round, from pair MM's household set (a Winnipeg retiree's speech to
text): a request tag said "would ya" or "can ya", and "outa" / "outta" for "out of". Through the
real household reader, in the studio flat."""
from __future__ import annotations

import pytest

from pipflow.household.language.translator import translate
from tests.studio_world import STUDIO


def goal(command: str) -> dict:
    return {k: v for k, v in translate(command, STUDIO)["goal"].items() if v}


@pytest.mark.parametrize("said, plain", [
    ("put the novel on the nightstand would ya", "put the novel on the nightstand would you"),
    ("can ya wash the teacup", "can you wash the teacup"),
    ("take the juice outa the icebox and put it on the worktop",
     "take the juice out of the icebox and put it on the worktop"),
    ("grab the soup pot outta the oven and put it on the worktop",
     "grab the soup pot out of the oven and put it on the worktop"),
])
def test_spoken_forms_read_as_written_out(said: str, plain: str) -> None:
    assert goal(said) == goal(plain)
    assert goal(said)


def test_a_remark_of_everyday_words_is_set_aside() -> None:
    """ "sore" is an English word as written, no slip of "store": the remark names nothing."""
    got = translate("wash the teacup, my knee is sore", STUDIO)
    assert {k: v for k, v in got["goal"].items() if v} == {"state": {"teacup": ["clean"]}}
    assert any("set aside" in line and "knee is sore" in line for line in got["explain"])


def test_a_correction_naming_a_thing_by_everyday_words_is_read() -> None:
    """The words of a name of the home ("low table", said of the coffee table) are never talk,
    common words or not: "I mean on the low table" is a correction, read."""
    assert goal("put the magazine in the wardrobe. sorry, i mean on the low table") == \
        {"in": {"coffee_table": ["magazine"]}}

"""Issue 23's twentieth round, from pair AA's first measurement (a grandmother in Birmingham whose
orders come with news of her family and her church): a remark about people ("my sister is coming
for dinner after her class", "the neighbours are coming round after church") is talk, set aside
and said, though it has words the lexicon knows ("coming", "after"). Anything that could bear on
the order keeps it read, and so refused here: a name of the home, a count, a negation, a word that
points back at the thing ordered, a cue or a wish a vague command is read from. Through the real
household reader, in the studio flat."""
from __future__ import annotations

import pytest

from pipflow.errors import TranslationError
from pipflow.household.language.translator import translate
from tests.studio_world import STUDIO


@pytest.mark.parametrize("command, remark", [
    ("turn off the radio. my sister is coming for dinner after her class.",
     "my sister is coming for dinner after her class"),
    ("turn off the radio. the neighbours are coming round after church", "the neighbours are coming round after church"),
    ("and the twins are coming round after church, turn off the radio", "and the twins are coming round after church"),
])
def test_a_remark_about_people_is_set_aside_and_said(command: str, remark: str) -> None:
    got = translate(command, STUDIO)
    assert {k: v for k, v in got["goal"].items() if v} == {"state": {"radio": ["off"]}}
    assert got["order"]["set_aside"] == [remark]
    assert any(remark in note for note in got["notes"])


@pytest.mark.parametrize("command", [
    "turn off the radio. my sister is coming for the teacup",       # a thing of the home
    "turn off the radio. my sister is coming with 2 friends",       # a count
    "turn off the radio. my sister is not coming",                  # a negation
    "turn off the radio. my sister wants it hot",                   # points back, and a state
    "turn off the radio. my sister finds the place dark",           # a cue of light
    "turn off the radio. my sister wants everything off",           # a quantity
])
def test_what_could_bear_on_the_order_is_never_a_remark(command: str) -> None:
    with pytest.raises(TranslationError):
        translate(command, STUDIO)


def test_an_order_without_a_name_of_the_home_is_no_remark() -> None:
    """A clause that opens with a verb is an order ("tidy up after her class"), read or refused,
    never set aside as talk."""
    try:
        got = translate("turn off the radio. tidy up after her class", STUDIO)
    except TranslationError:
        return
    assert not got["order"].get("set_aside")


def test_the_echo_keeps_no_note_of_a_reading_that_failed() -> None:
    """The command is read whole first; when that fails and it is read again without its talk, the
    echo says only what the reading that stands noted."""
    got = translate("wash the teacup, pastor jones is coming by at 4", STUDIO)
    assert got["order"]["set_aside"] == ["pastor jones is coming by at 4"]
    assert not any("leaves its subject out" in note for note in got["notes"])


@pytest.mark.parametrize("command, goal", [
    # said aloud: hesitations, "em" for them, "like" hedging after a preposition
    ("um turn off the radio uh please", {"state": {"radio": ["off"]}}),
    ("wash the teacup and put em in the sink", None),
    ("put the teacup in like the sink", {"in": {"basin": ["teacup"]}}),
])
def test_speech_fillers_read_as_the_order(command: str, goal: dict | None) -> None:
    got = {k: v for k, v in translate(command, STUDIO)["goal"].items() if v}
    if goal is None:
        goal = {k: v for k, v in translate(command.replace(" em ", " it "), STUDIO)["goal"].items() if v}
    assert got == goal


def test_a_condition_after_and_governs_only_what_follows_it() -> None:
    """'wash the teacup and if the radio is still on turn it off': the wash unconditionally, the
    radio on the condition, which holds in the studio (the radio is on)."""
    got = translate("wash the teacup and if the radio is still on turn it off", STUDIO)
    goal = {k: v for k, v in got["goal"].items() if v}
    assert goal == {k: v for k, v in translate("wash the teacup. turn off the radio", STUDIO)["goal"].items() if v}
    assert any("holds now" in n for n in got["notes"])
    got = translate("wash the teacup and if the radio is off turn it on", STUDIO)
    assert {k: v for k, v in got["goal"].items() if v} == \
        {k: v for k, v in translate("wash the teacup", STUDIO)["goal"].items() if v}


def test_i_mean_opening_a_sentence_takes_back_the_place() -> None:
    """Issue 23's twenty-second round: "put the teacup in the sink. I mean in the icebox!" puts it
    in the icebox; "I mean it." takes nothing back."""
    got = translate("put the teacup in the sink. I mean in the icebox!", STUDIO)
    assert got["goal"]["in"] == {"icebox": ["teacup"]}
    got = translate("put the teacup in the sink. I mean it.", STUDIO)
    assert got["goal"]["in"] == {"basin": ["teacup"]}


def test_new_zealand_thanks_and_approval_carry_nothing() -> None:
    plain = {k: v for k, v in translate("wash the teacup", STUDIO)["goal"].items() if v}
    for command in ("wash the teacup. Thanks heaps, sweet as", "wash the teacup, ka pai"):
        assert {k: v for k, v in translate(command, STUDIO)["goal"].items() if v} == plain

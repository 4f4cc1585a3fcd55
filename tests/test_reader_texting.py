"""Issue 23's seventeenth round, from pair X's first measurement (an Australian foreman texting, a
retired Indian bank manager talking): texting's one-letter words ("n", "w") and "atm"; corrections
sent as "*word"; "can one of yous ..."; "bunkers got" for "bunker's got"; "N too many, pull em
off"; "no worries"; robots told to "stay off" a place; and, in the home, Indian English openers
and closers ("do one thing", "na"), "itself" after a place, manner adverbs ("nicely"), and what
another person will do ("she'll make the sabzi later"). Through the real readers, in worlds of our
own (the ferry terminal; the studio flat)."""
from __future__ import annotations

import pytest

from pipflow.errors import TranslationError
from pipflow.household.language.translator import translate
from pipflow.warehouse.language.translator import understand
from tests.studio_world import STUDIO, studio_goal
from tests.terminal_world import TERMINAL


@pytest.mark.parametrize("command, goal", [
    # quay has 14 crates and 5 barrels, shed 2 crates and 6 barrels, ramp 1 barrel
    ("quay n shed should both have 4 barrels", {"quay": {"barrel": 4}, "shed": {"barrel": 4}}),
    ("shed should end up w a dozen crates", {"shed": {"crate": 12}}),
    ("ramp has 1 barrel atm, make it 3", {"ramp": {"barrel": 3}}),
    ("oi shed should have 9 barrels", {"shed": {"barrel": 9}}),
    ("can one of yous shift 4 crates off quay over to shed", {"quay": {"crate": 10}, "shed": {"crate": 6}}),
    ("quays got 4 crates too many, pull em off", {"quay": {"crate": 10}}),
    ("shed wants between 3 and 5 crates, no worries", {"shed": {"crate": {"at_least": 3, "at_most": 5}}}),
])
def test_texting_forms(command: str, goal: dict) -> None:
    assert understand(command, TERMINAL)["goal"] == goal


def test_a_capital_n_is_no_and() -> None:
    """ "N" is as often north ("N cage"): only "n" as typed in lower case is "and"."""
    with pytest.raises(TranslationError):
        understand("quay N shed should both have 4 barrels", TERMINAL)


@pytest.mark.parametrize("command, goal", [
    # a word: the one nearest in spelling before it
    ("move 3 crates from quay to shad\n*shed bloody autocorrect", {"quay": {"crate": 11}, "shed": {"crate": 5}}),
    # a number: the one number before it; the line that only says the correction again goes with it
    ("shift 5 crates off quay to shed\n*6 sorry, 6 crates", {"quay": {"crate": 8}, "shed": {"crate": 8}}),
])
def test_a_star_correction_replaces_the_word_it_corrects(command: str, goal: dict) -> None:
    got = understand(command, TERMINAL)
    assert got["goal"] == goal


def test_a_star_correction_is_said_in_the_echo() -> None:
    got = understand("move 3 crates from quay to shad\n*shed", TERMINAL)
    assert got["explanation"][0] == "'*shed': read 'shad' as 'shed'"
    assert got["order"]["corrected"] == ["'*shed': read 'shad' as 'shed'"]
    assert "set_aside" not in got["order"]


@pytest.mark.parametrize("command", ["move 3 crates from quay to shed, then 4 to ramp\n*5",
                                     "move 3 crates from quay to shed\n*barrows"])
def test_a_star_correction_that_could_mean_two_words_or_none_is_refused(command: str) -> None:
    with pytest.raises(TranslationError, match="which word"):
        understand(command, TERMINAL)


def test_robots_told_to_stay_off_a_place() -> None:
    got = understand("moth n wasp stay off ramp", TERMINAL)
    assert {"never": ["moth", "wasp"], "to": "ramp"} in got["constraints"]
    assert {"never": ["moth", "wasp"], "from": "ramp"} in got["constraints"]


@pytest.mark.parametrize("command, goal", [
    # (the juice already lies in the shut icebox: nothing opens it, so its door is no condition)
    ("Do one thing, put the juice in the icebox itself, na.",
     {"in": {"icebox": ["juice"]}}),
    ("wash the teacup nicely", {"state": {"teacup": ["clean"]}}),
    ("put the juice in the icebox, she will drink it after her class",
     {"in": {"icebox": ["juice"]}}),
    ("put the juice in the icebox. My wife will make the tea later.",
     {"in": {"icebox": ["juice"]}}),
])
def test_household_indian_english_and_what_others_will_do(command: str, goal: dict) -> None:
    assert studio_goal(command) == goal


@pytest.mark.parametrize("command", ["put the juice in the icebox, she will not drink it",
                                     "put the juice in the icebox, she will only drink it cold"])
def test_what_another_person_will_not_or_only_do_is_never_set_aside(command: str) -> None:
    with pytest.raises(TranslationError):
        translate(command, STUDIO)

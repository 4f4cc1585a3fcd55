"""Orders given over a two-way radio (issue 23): the call, the prowords, "I say again", numbers
said digit by digit and "unit" for a robot are voice procedure, set aside and said; the message
is read as any command. Only a transmission is read so. Through the real warehouse reader, in a
ferry terminal of our own."""
from __future__ import annotations

import copy

import pytest

from pipflow.errors import TranslationError
from pipflow.language.radio import transmission
from pipflow.warehouse.language.translator import understand
from tests.terminal_world import TERMINAL



@pytest.mark.parametrize("command, goal", [
    # the station calls everyone, the message, "over"
    ("Base to all units. Move 3 crates from quay to shed. Over.", {"quay": {"crate": 11}, "shed": {"crate": 5}}),
    ("All units, all units, harbour control. 3 crates quay to shed, over.", {"quay": {"crate": 11}, "shed": {"crate": 5}}),
    ("Harbour control. All units. Three more barrels on the ramp please, over.", {"ramp": {"barrel": 4}}),
    ("Harbour control. Fill the ramp up with crates. Over and out.", {"ramp": {"crate": 11}}),
    # "over" inside the message is the preposition
    ("Base to all units. Send 3 crates from quay over to the shed. Over.", {"quay": {"crate": 11}, "shed": {"crate": 5}}),
    # "copy?" and "over" closing; "break" between two messages, each with its call
    ("All units, take four crates off the quay. Copy? Over.", {"quay": {"crate": 10}}),
    ("Base to all units. Break. Ramp wants two more barrels. Break. Shed to hold at least one-two crates. Over.",
     {"ramp": {"barrel": 3}, "shed": {"crate": {"at_least": 12}}}),
    # numbers said digit by digit, "niner"
    ("Base to all units. Quay crates down to one-zero. Over.", {"quay": {"crate": 10}}),
    ("Base to all units. Bring the barrels on shed up to niner. Over.", {"shed": {"barrel": 9}}),
    # "I say again" with a word-for-word repeat
    ("Base to all units. No fewer than 4 barrels on the ramp, I say again, no fewer than 4. Over.",
     {"ramp": {"barrel": {"at_least": 4}}}),
])
def test_a_transmission_reads_as_its_message(command: str, goal: dict) -> None:
    got = understand(command, TERMINAL)
    assert got["goal"] == goal
    assert not got.get("constraints")
    assert got["order"]["set_aside"]   # the procedure is said in the echo
    assert any("set aside" in line for line in got["explanation"])


def test_a_robot_called_by_name_does_the_work_of_its_message() -> None:
    got = understand("Titan, Titan, this is base. 2 barrels from shed to ramp, over.", TERMINAL)
    assert got["goal"] == {"shed": {"barrel": 4}, "ramp": {"barrel": 3}}
    assert got["constraints"] == [{"only": ["titan"], "product": "barrel", "from": "shed", "to": "ramp"}]
    assert "Titan" not in " ".join(got["order"]["set_aside"])   # the one called is read, not set aside


def test_each_message_keeps_its_own_call() -> None:
    """The robot called in the first message does that message's move; "all units" in the second
    calls everyone, so its goal has no rule."""
    got = understand("Ox, harbour control. 2 crates quay to shed, over. Break. "
                     "All units, ramp to hold at most 3 barrels. Over.", TERMINAL)
    assert got["goal"] == {"quay": {"crate": 12}, "shed": {"crate": 4}, "ramp": {"barrel": {"at_most": 3}}}
    assert got["constraints"] == [{"only": ["ox"], "product": "crate", "from": "quay", "to": "shed"}]


@pytest.mark.parametrize("command, words", [
    # a call sign the world lacks is a robot that is not there: refused, never given to the others
    ("Hornet, base. 2 barrels from shed to ramp, over.", "Hornet"),
    # a repeat that says something else is no repeat
    ("Base to all units. No fewer than 4 barrels on the ramp, I say again, no fewer than 5. Over.", "say"),
])
def test_what_the_procedure_cannot_account_for_is_refused(command: str, words: str) -> None:
    with pytest.raises(TranslationError, match=words):
        understand(command, TERMINAL)


def test_unit_is_a_robot_in_a_transmission() -> None:
    got = understand("Base to all units. Move 2 crates from quay to shed, strongest unit only. Over.", TERMINAL)
    assert got["constraints"] and got["constraints"][0]["only"] == ["titan"]
    with pytest.raises(TranslationError):   # moth and wasp tie as the weakest: which one is not said
        understand("Base to all units. Move 2 crates from quay to shed, weakest unit only. Over.", TERMINAL)


def test_only_a_transmission_is_read_as_one() -> None:
    """Without a call or a closing proword, "one-two" is no 12 and "over" no proword."""
    with pytest.raises(TranslationError, match="one-two"):
        understand("Move one-two crates from quay to shed.", TERMINAL)
    assert transmission("Send 3 crates over to the shed", lambda w: False, lambda w: False, str.isdigit) is None
    assert transmission("Move one-two crates", lambda w: False, lambda w: False, str.isdigit) is None


def test_a_place_of_the_world_is_no_station() -> None:
    """Where "base" names a place, "Base to all units" is no call: it must read, and does not."""
    world = copy.deepcopy(TERMINAL)
    world["shelves"]["base"] = world["shelves"].pop("ramp")
    world["stock"]["base"] = world["stock"].pop("ramp")
    with pytest.raises(TranslationError):
        understand("Base to all units. Move 3 crates from quay to shed. Over.", world)
    assert understand("Harbour control to all units. Move 3 crates from quay to base. Over.", world)["goal"] == \
        {"quay": {"crate": 11}, "base": {"crate": 3}}


@pytest.mark.parametrize("command, goal, rules", [
    # "she" for a place, as trades say it
    ("Move 3 crates from quay to shed and leave the ramp as she is.",
     {"quay": {"crate": 11}, "shed": {"crate": 5}, "ramp": {"crate": 0, "barrel": 1}}, []),
    ("Shed wants 12 crates all told.", {"shed": {"crate": 12}}, []),
    ("Move 3 crates from quay to shed and keep moth well away from the ramp.",
     {"quay": {"crate": 11}, "shed": {"crate": 5}},
     [{"never": ["moth"], "from": "ramp"}, {"never": ["moth"], "to": "ramp"}]),
])
def test_trade_idioms_read_as_their_plain_words(command: str, goal: dict, rules: list) -> None:
    got = understand(command, TERMINAL)
    assert got["goal"] == goal
    assert (got.get("constraints") or []) == rules


def test_she_of_a_person_is_not_read_as_a_place() -> None:
    """Only "as she is" / "what she has" are idioms of a thing; "she" elsewhere stays unread."""
    with pytest.raises(TranslationError):
        understand("Move 3 crates from quay to shed, she has to take them.", TERMINAL)

"""Issue 23's nineteenth round, from pair Z's first measurement (a Glasgow supervisor dictating):
Scots spellings of the grammar's own words ("fae", "tae", "aff", "oot", "wi", "ower", "dinnae", "nae
mair", "bar" for except), "aye", "ken", "the now", read only where the word is no word of the
world's names. Through the real warehouse reader, in the ferry terminal of our own."""
from __future__ import annotations

import copy

import pytest

from pipflow.warehouse.language.translator import understand
from tests.terminal_world import TERMINAL, with_ramp_called


@pytest.mark.parametrize("command, goal", [
    # quay has 14 crates and 5 barrels, shed 2 crates and 6 barrels, ramp 1 barrel
    ("shift 5 crates fae quay tae shed", {"quay": {"crate": 9}, "shed": {"crate": 7}}),
    ("aye take 2 barrels aff shed the now, ken", {"shed": {"barrel": 4}}),
    ("ramp should end up wi 3 barrels", {"ramp": {"barrel": 3}}),
    ("move 4 crates fae quay ower tae ramp", {"quay": {"crate": 10}, "ramp": {"crate": 4}}),
    ("i want nae mair than 4 crates on shed", {"shed": {"crate": {"at_most": 4}}}),
    ("shed should hae 6 crates", {"shed": {"crate": 6}}),
])
def test_scots_spellings_read_as_the_grammar_words(command: str, goal: dict) -> None:
    assert understand(command, TERMINAL)["goal"] == goal


def test_dinnae_is_a_negation_never_dropped() -> None:
    got = understand("move 3 crates fae quay tae shed and dinnae use titan", TERMINAL)
    assert got["constraints"] == [{"never": ["titan"]}]


@pytest.mark.parametrize("negated", ["mustnae", "disnae"])
def test_scots_negated_modals_are_negations(negated: str) -> None:
    assert understand(f"titan {negated} touch barrels", TERMINAL)["constraints"] == \
        [{"never": ["titan"], "product": "barrel"}]


def test_a_name_of_the_world_is_never_read_as_scots() -> None:
    """A place called "tae" is that place, never "to"."""
    got = understand("move 2 barrels from shed to tae", with_ramp_called("tae"))
    assert got["goal"] == {"shed": {"barrel": 4}, "tae": {"barrel": 3}}


def test_a_scots_spelling_is_no_slip_of_a_robot_name_one_edit_away() -> None:
    """Round 32, from pair LL's first cause: "tae" (to) was read as a misspelling of a robot
    "tam", so no move read. A spelling of a grammar word is reserved from the fuzzy name match;
    a name spelt so exactly is still the name (the ramp called "tae", above)."""
    world = copy.deepcopy(TERMINAL)
    world["robots"]["tam"] = world["robots"].pop("moth")
    assert understand("shift 4 crates fae quay tae shed", world)["goal"] == {"quay": {"crate": 10},
                                                                           "shed": {"crate": 6}}

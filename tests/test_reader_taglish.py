"""Issue 23's twentieth round, from pair AA's first measurement (a Manila coordinator's group chat
in Taglish): Tagalog's honorific and softening particles ("po", "naman", a closing "ha") and its
request prefixes on an English verb the grammar knows ("paki-move", "pakimove", "pa-add", "pa
move", "i-transfer") and its object marker before a count ("ng 3"), read as the English order.
Tagalog's own verbs stay unknown, so a command built on one is refused. Through the real
warehouse reader, in the ferry terminal of our own."""
from __future__ import annotations

import pytest

from pipflow.errors import TranslationError
from pipflow.warehouse.language.translator import understand
from tests.terminal_world import TERMINAL, with_ramp_called


@pytest.mark.parametrize("command, goal", [
    # quay has 14 crates and 5 barrels, shed 2 crates and 6 barrels, ramp 1 barrel
    ("paki-move po 3 crates from quay to shed", {"quay": {"crate": 11}, "shed": {"crate": 5}}),
    ("pakimove naman ng 3 crates from quay to shed ha", {"quay": {"crate": 11}, "shed": {"crate": 5}}),
    ("pa move 3 crates from quay to shed po", {"quay": {"crate": 11}, "shed": {"crate": 5}}),
    ("i-transfer 2 barrels from shed to ramp po", {"shed": {"barrel": 4}, "ramp": {"barrel": 3}}),
    ("Pa-add po ng 4 barrels to ramp", {"ramp": {"barrel": 5}}),
])
def test_taglish_particles_and_request_prefixes_read_as_the_order(command: str, goal: dict) -> None:
    assert understand(command, TERMINAL)["goal"] == goal


def test_a_negation_beside_the_particles_is_kept() -> None:
    got = understand("paki-move po 3 crates from quay to shed, don't use titan po", TERMINAL)
    assert got["constraints"] == [{"never": ["titan"]}]


@pytest.mark.parametrize("command", [
    "pakiayos po yung shed",            # a Tagalog verb ("ayos": tidy) is never guessed
    "paki-frobnicate po 3 crates from quay to shed",   # a prefix on a word the grammar lacks
])
def test_a_verb_the_grammar_lacks_is_refused_with_or_without_a_prefix(command: str) -> None:
    with pytest.raises(TranslationError):
        understand(command, TERMINAL)


def test_a_name_of_the_world_is_never_read_as_a_particle() -> None:
    """A place called "po" is that place."""
    got = understand("move 2 barrels from shed to po", with_ramp_called("po"))
    assert got["goal"] == {"shed": {"barrel": 4}, "po": {"barrel": 3}}

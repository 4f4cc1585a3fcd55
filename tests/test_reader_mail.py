"""Issue 23's eighteenth round, from pair Y's first measurement (a logistics manager's work
e-mails): a mail's form set aside and said (its subject line when it asks for nothing, a greeting
line, the sender's name), list markers left out, "w/", "by EOD", "qty", "FYI". Through the real
warehouse reader, in the ferry terminal of our own."""
from __future__ import annotations

import pytest

from pipflow.errors import TranslationError
from pipflow.language.mail import without_mail_form
from pipflow.warehouse.language.translator import understand
from tests.terminal_world import TERMINAL

MAIL = """Subject: RE: quay crates

Hi all,
- Move qty 3 crates from quay to shed by EOD
- Shed should end up w/ 7 barrels, FYI

Thx,
Deb"""


def test_a_mail_reads_as_its_orders() -> None:
    got = understand(MAIL, TERMINAL)
    assert got["goal"] == {"quay": {"crate": 11}, "shed": {"crate": 5, "barrel": 7}}
    aside = got["order"]["set_aside"]
    assert "subject line: RE: quay crates" in aside and "signed: Deb" in aside and "Hi all," in aside


def test_numbered_items_are_no_counts() -> None:
    got = understand("Team,\n1. Move 3 crates from quay to shed\n2) Ramp should have 4 barrels\n\n-D", TERMINAL)
    assert got["goal"] == {"quay": {"crate": 11}, "shed": {"crate": 5}, "ramp": {"barrel": 4}}


def test_a_subject_with_an_operative_word_is_read() -> None:
    """ "Subject: no titan" bears on what the robots do: it is read as a line, never set aside."""
    got = understand("Subject: no titan\n\nMove 3 crates from quay to shed", TERMINAL)
    assert {"never": ["titan"]} in got["constraints"]


def test_a_subject_that_does_not_read_and_asks_something_is_refused() -> None:
    with pytest.raises(TranslationError):
        understand("Subject: only 2 crates lol\n\nMove 3 crates from quay to shed", TERMINAL)


def test_a_robot_named_at_the_end_is_no_signature() -> None:
    """ "- Titan" closing a line may hand the job to the robot titan: never set aside as a name."""
    text, aside = without_mail_form("move 3 crates to shed - Titan", frozenset({"titan"}))
    assert text == "move 3 crates to shed - Titan" and aside == []
    text, aside = without_mail_form("move 3 crates to shed\n\nDeb", frozenset({"titan"}))
    assert text == "move 3 crates to shed" and aside == ["signed: Deb"]


def test_a_closing_line_with_an_operative_word_is_no_signature() -> None:
    """ "Not Bob" after a blank line is a rule about a robot the world may lack: read (and
    refused), never set aside as the sender's name."""
    assert without_mail_form("move 3 crates to shed\n\nNot Bob", frozenset())[1] == []
    with pytest.raises(TranslationError):
        understand("Move 3 crates from quay to shed\n\nNot Bob", TERMINAL)

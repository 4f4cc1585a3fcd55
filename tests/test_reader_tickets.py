"""Issue 23's twenty-first round, from pair BB's first measurement (a Dutch cross-dock lead's
job-board tickets): a ticket's title line set aside when it sums up the body below it, and only
then; Dutch English "for the rest", "N X too much", "prio", "graag", "toch"; "as far as it goes"
after a fill and "on top of what's there" after "more" / "extra". Through the real warehouse
reader, in the paper's world (shelf1..shelf4: names with a number, said "shelf 2") and the ferry
terminal of our own."""
from __future__ import annotations

import pytest

from pipflow.errors import PipflowError, TranslationError
from pipflow.warehouse.language.translator import understand
from tests.terminal_world import TERMINAL
from tests.test_reader_asides import PAPER


@pytest.mark.parametrize("command, goal", [
    # shelf2 holds 8 product1, 5 product2, 6 product3, 2 product4; shelf1 10, 2, 3
    ("Product1 shelf 2\nPls bring shelf 2 to 12 product1. thx", {"shelf2": {"product1": 12}}),
    ("Product2 shelf1 -> shelf2\n2 product2 from shelf 1 to shelf 2", None),
    ("Product3 shelves\n2 product3 from shelf 2 to shelf 1", None),
])
def test_a_title_that_sums_up_the_body_is_set_aside_and_said(command: str, goal: dict | None) -> None:
    got = understand(command, PAPER)
    title = command.split("\n")[0]
    assert f"title line: {title}" in got["order"]["set_aside"]
    body = understand(command.split("\n", 1)[1], PAPER)
    assert got["goal"] == (goal or body["goal"]) == body["goal"]


@pytest.mark.parametrize("command", [
    "Shelf2 empty\nmove 2 product1 from shelf 2 to shelf 1",      # an operative word: read, and the move cannot follow
    "5 product1 shelf2\nmove 3 product2 from shelf 2 to shelf 1",  # a count
    "Product1 shelf 2\nmove 3 product2 from shelf 2 to shelf 1",   # product1 is not said below
    "Product1 rebalancing\nmove 3 product1 from shelf 2 to shelf 1",  # a word no name has
])
def test_a_title_that_says_more_than_the_body_is_read_and_refused(command: str) -> None:
    with pytest.raises(PipflowError):
        understand(command, PAPER)


def test_a_first_line_that_is_an_order_is_read_as_one() -> None:
    got = understand("move 2 product1 from shelf1 to shelf2\nmove 1 product3 from shelf1 to shelf2", PAPER)
    assert got["goal"] == {"shelf1": {"product1": 8, "product3": 2}, "shelf2": {"product1": 10, "product3": 7}}
    assert not got["order"].get("set_aside")


@pytest.mark.parametrize("command, goal", [
    # quay has 14 crates and 5 barrels, shed 2 crates and 6 barrels, ramp 1 barrel (capacity 12)
    ("4 crates from quay to shed, for the rest all to ramp", {"quay": {"crate": 0}, "shed": {"crate": 6},
                                                              "ramp": {"crate": 10}}),
    ("Shed has 2 barrels too much, prio", {"shed": {"barrel": 4}}),
    ("Fill up ramp with barrels, as far as it goes, graag", {"ramp": {"barrel": 12}}),
    ("Ramp: two extra barrels, on top of what's there. toch", {"ramp": {"barrel": 3}}),
])
def test_dutch_english_reads_as_the_order(command: str, goal: dict) -> None:
    assert understand(command, TERMINAL)["goal"] == goal


def test_too_much_without_a_count_still_asks_how_many() -> None:
    with pytest.raises(TranslationError, match="how many"):
        understand("too much barrels on shed", TERMINAL)


@pytest.mark.parametrize("command, goal", [
    # issue 23's twenty-second round, from pair CC (a Chicago shift manager's notebook)
    ("Go ahead and move 3 crates from quay to shed", {"quay": {"crate": 11}, "shed": {"crate": 5}}),
    ("I'd like to see 4 crates on ramp", {"ramp": {"crate": 4}}),
])
def test_careful_american_english_reads_as_the_order(command: str, goal: dict) -> None:
    assert understand(command, TERMINAL)["goal"] == goal


def test_none_of_a_group_to_be_used_keeps_them_off() -> None:
    got = understand("move 3 crates from quay to shed. None of the forklifts are to be used", TERMINAL)
    forklifts = sorted(r for r, v in TERMINAL["robots"].items() if v.get("kind") == "forklift")
    assert forklifts and got["constraints"] == [{"never": forklifts}]


def test_none_of_all_robots_to_be_used_is_refused() -> None:
    with pytest.raises(TranslationError):
        understand("move 3 crates from quay to shed. None of the robots are to be used", TERMINAL)

"""A keep said after a change of the same stock: "but not the X" excepts X from "everything",
and a "don't touch" that contradicts a change said before it is refused, never resolved as a keep
of the count the change leaves (that read "Move everything from P to Q but not the pears" as
moving the pears, and kept them at 0 where they had gone from). The paper's world:
shelf1 {p1 10, p2 2, p3 3}, shelf2 {p1 8, p2 5, p3 6, p4 2}."""
from __future__ import annotations

from pathlib import Path

import pytest
import yaml

from pipflow.errors import TranslationError
from pipflow.warehouse.language.translator import understand

ROOT = Path(__file__).resolve().parent.parent
PAPER = yaml.safe_load((ROOT / "benchmarks" / "warehouse" / "world.yaml").read_text())


@pytest.mark.parametrize("command", [
    "Move everything from shelf1 to shelf2 but not the product2",
    "Move everything from shelf1 to shelf2, not the product2",
    "Move everything from shelf1 to shelf2 except the product2",
])
def test_but_not_after_everything_excepts_those_items(command: str) -> None:
    got = understand(command, PAPER)
    assert got["goal"] == {"shelf1": {"product1": 0, "product3": 0, "product2": 2},
                           "shelf2": {"product1": 18, "product3": 9}}


def test_emptying_but_not_some_items_leaves_them() -> None:
    assert understand("Empty shelf1 but not the product2", PAPER)["goal"] == \
        understand("Empty shelf1 except the product2", PAPER)["goal"]
    assert understand("Empty shelf1 but not the product2", PAPER)["goal"]["shelf1"]["product2"] == 2


@pytest.mark.parametrize("command, words", [
    ("Move everything from shelf1 to shelf2. Don't touch the product2.", "product2 on shelf1"),
    ("Move all the product1 from shelf1 to shelf2. Dont touch shelf1.", "product1 on shelf1"),
])
def test_a_keep_that_contradicts_a_change_said_before_is_refused(command: str, words: str) -> None:
    with pytest.raises(TranslationError, match=f"keeps {words} as it is .*cannot tell which is meant"):
        understand(command, PAPER)


def test_a_keep_of_stock_nothing_changed_still_reads() -> None:
    got = understand("Move 2 product1 from shelf1 to shelf2. Dont touch the product3.", PAPER)
    assert got["goal"]["shelf1"] == {"product1": 8, "product3": 3}
    assert got["goal"]["shelf2"]["product3"] == 6

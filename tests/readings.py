"""Helpers the reader tests share: what a command reads as, compared with its plain English."""
from __future__ import annotations

from pipflow.household.language.translator import translate as read_household
from pipflow.warehouse.language.translator import understand as read_warehouse


def household_goal(command: str, world: dict) -> dict:
    """The household goal the command reads as, its empty parts left out."""
    return {k: v for k, v in read_household(command, world)["goal"].items() if v}


def assert_warehouse_alike(said: str, plain: str, world: dict) -> None:
    """The command as said reads as its plain English does: the same goal and the same rules."""
    got, want = read_warehouse(said, world), read_warehouse(plain, world)
    assert got["goal"] == want["goal"]
    assert got.get("constraints") == want.get("constraints")

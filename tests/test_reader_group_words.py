"""A robot kind or tag said in the plural is that group, never a misspelt robot name, and a
superlative is a word of robot rules, never a misspelt product: "only the dollies" was read as
"only dottie" (a robot one typo's reach from "dollies") and "the strongest robot" as a product
string_set. Both are misreadings of the class issue 23 names (robot groups read by the wrong
rule); they are read as the group and the rule now. Also "get R on it", "R are to be moving
stock", "any robot that carries fewer than 3 at a time", "lose a quarter of them"."""
from __future__ import annotations

import pytest

from pipflow.warehouse.language.translator import translate

SHOP = {
    "name": "tackle_shop",
    "floor": {"width": 30, "height": 20},
    "shelves": {
        "rod_rack": {"x": 2, "y": 14, "width": 4, "depth": 2, "capacity": 14, "access": [4, 13]},
        "bait_fridge": {"x": 10, "y": 14, "width": 4, "depth": 2, "capacity": 12, "access": [12, 13]},
        "till_counter": {"x": 20, "y": 14, "width": 6, "depth": 2, "capacity": 12, "access": [23, 13]},
    },
    "products": {"string_spool": {"color": "white"}, "lure_box": {"color": "red"}},
    "stock": {"rod_rack": {"string_spool": 8, "lure_box": 2}, "bait_fridge": {"lure_box": 4},
              "till_counter": {"string_spool": 1}},
    "robots": {
        "dottie": {"kind": "amr", "start": [1, 8], "skills": {"carry": 1}},
        "polly1": {"kind": "dolly", "start": [5, 8], "skills": {"carry": 2}},
        "polly2": {"kind": "dolly", "start": [9, 8], "skills": {"carry": 3}},
        "hulk": {"kind": "hoist", "start": [15, 8], "skills": {"carry": 5}},
    },
}
MOVE = "Move 2 string spools from the rod rack to the till counter"
GOAL = {"rod_rack": {"string_spool": 6}, "till_counter": {"string_spool": 3}}


@pytest.mark.parametrize("command", [f"Only the dollies. {MOVE}.", f"{MOVE}, dollies only",
                                     f"Only the dollies are to be moving stock today. {MOVE}."])
def test_a_kind_in_the_plural_is_the_group_never_a_robot_one_typo_away(command: str) -> None:
    got = translate(command, SHOP)
    assert got["goal"] == GOAL
    assert got["constraints"] == [{"only": ["polly1", "polly2"]}]


@pytest.mark.parametrize("command", [f"Get the strongest robot on it: {MOVE}.",
                                     f"The strongest robot should do it: {MOVE}."])
def test_a_superlative_is_no_misspelt_product(command: str) -> None:
    got = translate(command, SHOP)
    assert got["goal"] == GOAL
    assert [c["only"] for c in got["constraints"]] == [["hulk"]]


def test_get_the_robot_on_it_holds_for_the_whole_command() -> None:
    assert translate(f"Get the strongest robot on it: {MOVE}.", SHOP)["constraints"] == [{"only": ["hulk"]}]


def test_any_robot_that_carries_fewer_than_n_at_a_time() -> None:
    got = translate(f"{MOVE}. Any robot that carries fewer than 2 at a time stays off this one.", SHOP)
    assert got["constraints"] == [{"never": ["dottie"]}]


def test_lose_a_quarter_of_them_after_a_complaint() -> None:
    got = translate("The rod rack has too many string spools. Lose a quarter of them.", SHOP)
    assert got["goal"] == {"rod_rack": {"string_spool": 6}}

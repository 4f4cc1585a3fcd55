""""R can't go to P": R cannot be at P, so it takes nothing from P either (as "keep R away from
P"). It was also read as "R never delivers to P", and the command was asked between the two
with one echo for both readings."""
from __future__ import annotations

import pytest

from pipflow.warehouse.language.translator import translate
from tests.test_reader_candidates import BIKES


def _rules(reading: dict) -> list[dict]:
    return [{k: v for k, v in r.items() if k != "words"} for r in reading.get("constraints") or []]


@pytest.mark.parametrize("command", ["zip_1 can't go to the repair bench", "zip_1 mustn't go into the repair bench"])
def test_a_robot_that_cannot_go_to_a_place_is_kept_out_of_it(command: str) -> None:
    assert _rules(translate(command, BIKES)) == [{"never": ["zip_1"], "from": "repair_bench"},
                                                 {"never": ["zip_1"], "to": "repair_bench"}]


def test_a_robot_that_cannot_go_from_one_place_to_another_keeps_the_route() -> None:
    assert _rules(translate("zip_1 can't go from the front rack to the repair bench", BIKES)) == [
        {"never": ["zip_1"], "from": "front_rack", "to": "repair_bench"}]

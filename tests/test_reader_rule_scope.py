"""A robot rule said with "for this" / "for that" after a move: the whole job, or that move?
Readers differ (two of our held-out sets' authors wrote opposite golds for it), and the two rules
allow different plans (the second lets the robot do any other move the planner needs), so the
reader asks with both readings offered; "for the whole job" and "for that move" say which. In the
print shop of test_reader_repairs, through the real reader."""
from __future__ import annotations

import pytest

from pipflow.errors import TranslationError
from pipflow.warehouse.language.translator import understand
from test_reader_repairs import MOVE_2, SHOP

MOVE = {"product": "ream", "from": "bin_4", "to": "bin_5"}


@pytest.mark.parametrize("rule, mode", [("Don't use crane for this.", "never"),
                                        ("Use the AMRs for that.", "only")])
def test_for_this_after_a_move_is_asked_with_both_scopes_offered(rule: str, mode: str) -> None:
    with pytest.raises(TranslationError, match="whole command or only for this move") as refused:
        understand(f"Move 2 reams from bin 4 to bin 5. {rule}", SHOP)
    offered = [c["constraints"] for c in refused.value.candidates]
    robots = ["crane"] if mode == "never" else ["ant_1", "ant_2"]
    unscoped = [{mode: robots}]
    scoped = [{mode: robots, **MOVE}]
    assert sorted(map(_rules, offered)) == sorted([_rules(unscoped), _rules(scoped)])
    assert all(c["goal"] == MOVE_2 for c in refused.value.candidates)


def test_the_whole_job_and_that_move_say_which() -> None:
    whole = understand("Move 2 reams from bin 4 to bin 5. Don't use crane for the whole job.", SHOP)
    assert whole["constraints"] == [{"never": ["crane"]}]
    move = understand("Move 2 reams from bin 4 to bin 5. Don't use crane for that move.", SHOP)
    assert _rules(move["constraints"]) == _rules([{"never": ["crane"], **MOVE}])


def test_a_rule_before_any_goal_holds_for_the_whole_command() -> None:
    got = understand("Don't use crane for this. Move 2 reams from bin 4 to bin 5.", SHOP)
    assert got["goal"] == MOVE_2 and got["constraints"] == [{"never": ["crane"]}]


def _rules(rules: list[dict]) -> list[tuple]:
    return sorted(tuple(sorted((k, tuple(sorted(v)) if isinstance(v, list) else v) for k, v in r.items()
                               if k != "words")) for r in rules)

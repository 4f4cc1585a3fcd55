"""A count sent "to" a place with no verb ("2 pumps to the back room") was read as the place's
final count, so where the place already held some of the item the robots would have taken units
away from it. "to" says where units go: where the place holds none, the count is the same either
way and is read; where it holds some, the command is asked (2 in all, or 2 more) with both
readings offered. A count "on" a place stays a final count (a listing: "2 pumps on the back room")."""
from __future__ import annotations

import pytest

from pipflow.errors import TranslationError
from pipflow.warehouse.language.translator import translate
from tests.test_reader_candidates import BIKES


@pytest.mark.parametrize("command", ["2 inner tubes to the back room", "2 inner tubes onto the back room",
                                     "morning! 2 inner tubes into the back room please",
                                     "2x inner tube -> back room"])
def test_a_count_sent_to_a_place_that_holds_some_is_asked_never_set(command: str) -> None:
    with pytest.raises(TranslationError) as err:
        translate(command, BIKES)            # back_room holds 1 inner tube
    goals = [c["goal"] for c in err.value.candidates]
    assert {"back_room": {"inner_tube": 3}} in goals      # 2 more
    assert {"back_room": {"inner_tube": 2}} in goals      # 2 in all


def test_a_count_sent_to_a_place_that_holds_none_is_read() -> None:
    assert translate("2 pumps to the front rack", BIKES)["goal"] == {"front_rack": {"pump": 2}}
    assert translate("2 pumps over to the wall hooks", BIKES)["goal"] == {"wall_hooks": {"pump": 2}}


def test_a_count_over_to_a_place_adds() -> None:
    assert translate("2 inner tubes over to the back room", BIKES)["goal"] == {"back_room": {"inner_tube": 3}}


def test_a_count_on_a_place_is_its_final_count() -> None:
    assert translate("2 inner tubes on the back room", BIKES)["goal"] == {"back_room": {"inner_tube": 2}}

"""A count taken from several named places ("take 2 inner tubes off the front rack and the back
room") was read as 2 from each, although it may be 2 in all: a guess. It is asked, with the
"each" reading offered; "from each of", "off every ..." still read as each."""
from __future__ import annotations

import pytest

from pipflow.errors import TranslationError
from pipflow.warehouse.language.translator import translate
from tests.test_reader_candidates import BIKES

EACH = {"front_rack": {"helmet": 0}, "wall_hooks": {"helmet": 1}}


@pytest.mark.parametrize("command", ["take 2 helmets off the front rack and the wall hooks",
                                     "remove 2 helmets from the front rack and wall hooks"])
def test_a_count_from_two_places_is_asked_with_each_offered(command: str) -> None:
    with pytest.raises(TranslationError, match="from each") as err:
        translate(command, BIKES)
    assert EACH in [c["goal"] for c in err.value.candidates]


def test_a_count_moved_from_two_places_to_a_third_is_asked() -> None:
    with pytest.raises(TranslationError, match="from each") as err:
        translate("move 2 helmets from the front rack and the wall hooks to the back room", BIKES)
    assert {**EACH, "back_room": {"helmet": 4}} in [c["goal"] for c in err.value.candidates]


def test_from_each_of_two_places_is_read() -> None:
    assert translate("take 2 helmets off each of the front rack and the wall hooks", BIKES)["goal"] == EACH


def test_all_of_an_item_from_two_places_needs_no_each() -> None:
    assert translate("take all the helmets off the front rack and the wall hooks", BIKES)["goal"] == {
        "front_rack": {"helmet": 0}, "wall_hooks": {"helmet": 0}}

"""Issue 23's twenty-eighth round, from pair II's first measurement (a Brooklyn bookkeeper's
dictated New York English): "put on the radio" with the particle before the thing (as "put the
radio on" was read; "put off the fan" too), and a place said, then one said not to use ("heat the kugel in the
microwave, not on the stove"), which had been asked about as if no place had been said. "put on"
said of a thing with no switch (a sweater, a scarf) is not understood, where it had been refused
as impossible: putting on a sweater is possible, only not a switch. Through the real household
reader, in the studio flat."""
from __future__ import annotations

import pytest

from pipflow.errors import Refusal, TranslationError
from pipflow.household.language.translator import translate
from tests.studio_world import STUDIO


def goal(command: str) -> dict:
    return {k: v for k, v in translate(command, STUDIO)["goal"].items() if v}


def test_put_on_before_the_thing_switches_it_on() -> None:
    assert goal("switch off the radio. later put on the radio") == {"state": {"radio": ["on"]}}
    assert goal("switch off the radio and the tablet, then put on the tablet") == \
        {"state": {"radio": ["off"], "tablet": ["on"]}}


@pytest.mark.parametrize("command", ["put on the sweater", "put the scarf on"])
def test_put_on_a_thing_with_no_switch_is_not_understood_never_impossible(command: str) -> None:
    with pytest.raises(TranslationError) as caught:
        translate(command, STUDIO)
    assert not isinstance(caught.value, Refusal)


def test_put_on_a_place_keeps_put_as_placing() -> None:
    """ "... and put on the worktop": the thing said before goes there; no switch is read."""
    assert goal("take the teacup and the saucer off the coffee table and put on the worktop")["in"] == \
        {"worktop": ["teacup", "saucer"]}


@pytest.mark.parametrize("command", [
    "heat the leftovers in the oven, not on the worktop",
    "heat the leftovers, not on the worktop, use the oven",
])
def test_a_place_said_and_one_said_not_to_use_reads_as_the_place_said(command: str) -> None:
    assert goal(command)["in"] == {"oven": ["leftovers"]}


def test_a_place_said_not_to_use_alone_or_twice_is_still_asked() -> None:
    with pytest.raises(TranslationError, match="not there, but where"):
        translate("heat the leftovers, not on the worktop", STUDIO)
    with pytest.raises(TranslationError, match="name the same place"):
        translate("put the teacup in the basin, not in the basin", STUDIO)

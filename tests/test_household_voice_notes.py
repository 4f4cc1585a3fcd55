"""Issue 23's twenty-fifth round, from pair FF's first measurement (a nurse's voice notes to her
home robots in Accra, in Ghanaian English): exclamations and Twi "please" beside the request
("Ei", "Chale", "abi", "mepa wo kyew", "yoo"), "o" closing a clause for emphasis, a state said
twice ("hot hot"), a face or a gesture as emoji, "don't touch X" (X stays where and as it is, as
"leave X alone" now says too), and "X too, <it is somewhere>, take it to P" (the thing named
first, with its own verb later, not the verb before said again for it). Through the real household
reader, in the studio flat."""
from __future__ import annotations

import pytest

from pipflow.errors import TranslationError
from pipflow.household.language.translator import translate
from tests.studio_world import STUDIO


def goal(command: str) -> dict:
    return {k: v for k, v in translate(command, STUDIO)["goal"].items() if v}


@pytest.mark.parametrize("command, wanted", [
    # the teacup and the glass are dirty, the tablet is on, the novel and the teacup lie on the coffee table
    ("Ei wash the teacup", {"state": {"teacup": ["clean"]}}),
    ("Chale switch off the tablet o", {"state": {"tablet": ["off"]}}),
    ("Mepa wo kyew wash the glass, abi", {"state": {"glass": ["clean"]}}),
    ("Thank you oo. wash the glass", {"state": {"glass": ["clean"]}}),
    ("Yoo, close the pantry o", {"state": {"pantry": ["closed"]}}),
    ("make the leftovers hot hot", {"state": {"leftovers": ["hot"], "icebox": ["closed"], "oven": ["closed"]}}),
    ("wash the teacup \U0001F64F", {"state": {"teacup": ["clean"]}}),
])
def test_ghanaian_english_read_as_the_order_it_says(command: str, wanted: dict) -> None:
    assert goal(command) == wanted


def test_an_o_inside_a_clause_is_no_particle() -> None:
    """Only before a stop or a comma is "o" emphasis; "put the novel o the nightstand" is refused."""
    with pytest.raises(TranslationError, match="'o'"):
        translate("put the novel o the nightstand", STUDIO)


def test_dont_touch_keeps_the_thing_where_and_as_it_is() -> None:
    assert goal("wash the soup pot but don't touch the teacup") == {
        "in": {"coffee_table": ["teacup"]}, "state": {"soup_pot": ["clean"], "teacup": ["dirty"], "oven": ["closed"]}}


def test_leave_it_alone_keeps_its_states_and_where_it_is_only_its_place() -> None:
    assert goal("leave the teacup alone") == {"in": {"coffee_table": ["teacup"]}, "state": {"teacup": ["dirty"]}}
    assert goal("leave the teacup where it is") == {"in": {"coffee_table": ["teacup"]}}


def test_a_thing_to_change_and_to_leave_untouched_is_refused() -> None:
    with pytest.raises(TranslationError, match="left as it is"):
        translate("wash the teacup, don't touch it", STUDIO)


def test_a_thing_named_first_with_too_takes_its_own_verb_later() -> None:
    said = "Put the soda in the recycling bin. The novel too, it's on the coffee table, take it to the nightstand"
    assert goal(said) == {"in": {"recycling": ["soda"], "nightstand": ["novel"]}}
    assert goal("Put the soda in the recycling bin. The novel too") == {"in": {"recycling": ["soda", "novel"]}}


def test_a_further_step_after_too_keeps_too_and_is_refused_as_a_conflict() -> None:
    """ "The novel too, then take it ...": "then" makes the clause a further step; the novel would
    go to two places, which is refused."""
    with pytest.raises(TranslationError, match="both in recycling"):
        translate("Put the soda in the recycling bin. The novel too, then take it to the nightstand", STUDIO)

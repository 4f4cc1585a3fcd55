"""Issue 23's twenty-sixth round, from pair GG's first measurement (a Kerry farmer dictating to
her phone) and pair GG's warehouse writer: Irish and archaic "'tis" / "'twas" are "it is" / "it
was", and a list numbered inline ("1) ... 2) ...") is a job per number in the household reader as
in the warehouse one. Through the real household reader, in the studio flat."""
from __future__ import annotations

import pytest

from pipflow.errors import TranslationError
from pipflow.household.language.lexicon import normalize
from pipflow.household.language.translator import translate
from tests.studio_world import STUDIO


def goal(command: str) -> dict:
    return {k: v for k, v in translate(command, STUDIO)["goal"].items() if v}


@pytest.mark.parametrize("said, spelt", [("'tis freezing", "it is freezing"), ("'Twas cold", "it was cold"),
                                         ("tis soft", "it is soft"), ("this is", "this is"), ("artist is", "artist is")])
def test_tis_is_it_is(said: str, spelt: str) -> None:
    assert normalize(said) == spelt


def test_a_list_numbered_inline_is_a_job_per_number() -> None:
    assert goal("1) switch off the radio 2) wash the teacup") == {"state": {"radio": ["off"], "teacup": ["clean"]}}


def test_numbers_out_of_order_are_no_list() -> None:
    with pytest.raises(TranslationError):
        translate("2) switch off the radio 3) wash the teacup", STUDIO)

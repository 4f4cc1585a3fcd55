"""Issue 23, from pair SS's warehouse set (a supervisor in Dubai who names the place first, then its
stock, then what to do): "bay 5 chargers double it", "zone A dates reduce by one quarter", "zone A
dates send to bay 3", "zone B chargers dont touch", "QC area clear everything", "zone B dont touch
anything", "bay 3 belts make 5 total", "zone B add 2 pads more", "zone A send 3 filters back to
bay 3" (pair UU's Vietnamese English, after its first measurement); where to said before the
count ("put in the bay 3 4 filters from zone A", pair TT's Portuguese order); and "robots that
carry 5 and up" (or more). In a world of our own (a spares depot), through the real reader; each
rule with what stays as said or refused."""
from __future__ import annotations

import pytest

from pipflow.errors import TranslationError
from pipflow.warehouse.language.translator import understand

DEPOT = {
    "name": "depot",
    "floor": {"width": 40, "height": 20},
    "shelves": {
        "zonea": {"x": 2, "y": 14, "width": 4, "depth": 2, "capacity": 40, "access": [4, 13], "words": ["zone A"]},
        "zoneb": {"x": 10, "y": 14, "width": 4, "depth": 2, "capacity": 40, "access": [12, 13], "words": ["zone B"]},
        "bay3": {"x": 18, "y": 14, "width": 4, "depth": 2, "capacity": 40, "access": [20, 13]},
        "qc": {"x": 28, "y": 14, "width": 4, "depth": 2, "capacity": 40, "access": [30, 13], "words": ["QC area"]},
    },
    "products": {"filters": {"color": "grey"}, "belts": {"color": "black"}, "pads": {"color": "red"}},
    "stock": {"zonea": {"filters": 8, "belts": 4}, "zoneb": {"filters": 2, "pads": 6},
              "bay3": {"belts": 3}, "qc": {"pads": 2, "belts": 1}},
    "robots": {"fk1": {"kind": "forklift", "start": [1, 8], "skills": {"carry": 8}},
               "fk2": {"kind": "forklift", "start": [15, 8], "skills": {"carry": 5}},
               "amr1": {"kind": "amr", "start": [25, 8], "skills": {"carry": 2}}},
}


def _read(said: str) -> dict:
    return understand(said, DEPOT)


@pytest.mark.parametrize("said, plain", [
    ("bay 3 belts double it", "double the belts on bay 3"),
    ("zone A filters reduce by one quarter", "reduce the filters on zone A by one quarter"),
    ("zone A filters send to bay 3", "send the filters from zone A to bay 3"),
    ("zone A filters and belts send to bay 3", "send the filters and the belts from zone A to bay 3"),
    ("zone B pads dont touch", "dont touch the pads on zone B"),
    ("QC area clear everything", "clear the QC area"),
    ("move 2 belts from zone A to bay 3, zone B dont touch anything",
     "move 2 belts from zone A to bay 3, dont touch zone B"),
    ("put in the bay 3 4 filters from zone A", "move 4 filters from zone A to bay 3"),
    ("bay 3 belts make 5 total", "bay 3 should have 5 belts"),
    ("zone B pads make 4", "zone B should have 4 pads"),
    ("zone B add 2 pads more", "add 2 more pads to zone B"),
    ("zone A send 3 filters back to bay 3", "send 3 filters from zone A back to bay 3"),
    ("move 4 filters from zone A to bay 3 using only robots that carry 5 and up",
     "move 4 filters from zone A to bay 3 using only robots that carry 5 or more"),
])
def test_the_place_said_first(said: str, plain: str) -> None:
    assert _read(said)["goal"] == _read(plain)["goal"]
    assert _read(said).get("constraints") == _read(plain).get("constraints")


@pytest.mark.parametrize("said", [
    "zone A 4 filters double it",          # a count after the place: not this rule's
    "double it zone A filters",            # the verb first: no place said first
    "zone A clear the belts",              # an object after the verb that is no "everything"
    "put in bay 3 the filters from zone A",   # where to first, but no count after it
    "zone A dont send 3 filters to bay 3",    # a negation: never moved about
    "bay 3 belts make more",                  # "make" without a count
])
def test_what_stays_refused(said: str) -> None:
    with pytest.raises(TranslationError):
        _read(said)

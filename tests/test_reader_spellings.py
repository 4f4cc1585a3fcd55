"""A name said in its other accepted spelling ("dispatch" for a place the world spells
"despatch", "gray" for grey, "center" for centre) is that name; a word of the grammar spelt so
("dispatch", a verb) is the place only where a place stands. And the verb "place" is a word of its
own: a place's name never reads as it (issue 23's tenth round)."""
from __future__ import annotations

import pytest

from pipflow.errors import Refusal, TranslationError
from pipflow.language.spelling import other_spellings
from pipflow.warehouse.language.forest import keywords
from pipflow.warehouse.language.grammar import GRAMMAR
from pipflow.warehouse.language.translator import translate

#: a tile merchant's store, a world no benchmark uses
TILES = {
    "name": "tiles",
    "floor": {"width": 30, "height": 20},
    "shelves": {
        "despatch": {"x": 2, "y": 14, "width": 4, "depth": 2, "capacity": 20, "access": [4, 13]},
        "tyre_rack": {"x": 10, "y": 14, "width": 4, "depth": 2, "capacity": 12, "access": [12, 13]},
        "centre_bay": {"x": 20, "y": 14, "width": 6, "depth": 2, "capacity": 16, "access": [23, 13]},
    },
    "products": {"grey_tile": {"color": "grey"}, "colour_tin": {"color": "red"}},
    "stock": {"despatch": {"grey_tile": 2}, "tyre_rack": {"colour_tin": 3},
              "centre_bay": {"grey_tile": 6, "colour_tin": 1}},
    "robots": {"hod1": {"start": [1, 8], "skills": {"carry": 2}}, "hod2": {"start": [5, 8], "skills": {"carry": 3}}},
}


@pytest.mark.parametrize("word, others", [
    ("despatch", {"dispatch"}), ("dispatch", {"despatch"}), ("grey", {"gray"}), ("colour", {"color"}),
    ("color", {"colour"}), ("centre", {"center"}), ("center", {"centre"}), ("organise", {"organize"}),
    ("catalogue", {"catalog"}), ("travelled", {"traveled"}), ("tyre", {"tire"}),
])
def test_other_spellings_of_one_word(word: str, others: set[str]) -> None:
    assert other_spellings(word) == others


@pytest.mark.parametrize("word", ["four", "hour", "acre", "store", "more", "rise", "size", "sealed", "filled", "dog"])
def test_a_word_whose_ending_is_no_suffix_has_no_other_spelling(word: str) -> None:
    assert other_spellings(word) == set()


@pytest.mark.parametrize("command, goal", [
    ("Move 2 gray tiles from the center bay to dispatch", {"centre_bay": {"grey_tile": 4}, "despatch": {"grey_tile": 4}}),
    ("the tire rack should have 1 color tin", {"tyre_rack": {"colour_tin": 1}}),
    ("dispatch should have 5 grey tiles", {"despatch": {"grey_tile": 5}}),
    ("move the 2 grey tiles off dispatch onto the tyre rack",
     {"despatch": {"grey_tile": 0}, "tyre_rack": {"grey_tile": 2}}),
])
def test_a_name_in_its_other_spelling_is_that_name(command: str, goal: dict) -> None:
    assert translate(command, TILES)["goal"] == goal


def test_the_verb_spelt_as_a_place_stays_a_verb_where_no_place_stands() -> None:
    """"dispatch 2 colour tins to the centre bay": the verb (2 more there), not the place."""
    assert translate("dispatch 2 colour tins to the centre bay", TILES)["goal"] == {"centre_bay": {"colour_tin": 3}}


def test_a_place_name_never_reads_as_the_verb_place() -> None:
    """Written as a string in the grammar, "place" was named PLACE by lark, the terminal of a
    world's place: "despatch 2 grey tiles to the centre bay" read as "place 2 grey tiles to the
    centre bay" (set to 2), the first place dropped without a word. Said with no verb, the place
    said first is where the tiles come from (issue 23's reading by roles), never dropped: the tyre
    rack holds none, so the move is refused as impossible."""
    with pytest.raises(Refusal, match="from tyre_rack, which holds 0"):
        translate("tyre rack 2 grey tiles to the centre bay", TILES)
    assert translate("place 2 colour tins onto the despatch", TILES)["goal"] == {"despatch": {"colour_tin": 2}}
    declared = next(line for line in GRAMMAR.splitlines() if line.startswith("%declare")).split()[1:]
    assert not {name for name in keywords().values()} & set(declared), "a keyword shares a world terminal's name"


@pytest.mark.parametrize("command, goal", [
    ("the centre bay and dispatch should both have 4 grey tiles", {"centre_bay": {"grey_tile": 4}, "despatch": {"grey_tile": 4}}),
    ("dispatch and the tyre rack should both have 2 grey tiles", {"despatch": {"grey_tile": 2}, "tyre_rack": {"grey_tile": 2}}),
])
def test_the_verb_spelt_as_a_place_is_the_place_in_a_list_of_places(command: str, goal: dict) -> None:
    assert translate(command, TILES)["goal"] == goal


def test_the_verb_after_and_with_what_it_sends_stays_a_verb() -> None:
    got = translate("move 1 colour tin to the centre bay and dispatch 2 grey tiles to the tyre rack", TILES)
    assert got["goal"] == {"centre_bay": {"colour_tin": 2}, "tyre_rack": {"grey_tile": 2}}


@pytest.mark.parametrize("command", [
    "Take 2 grey tiles outta the centre bay and over to despatch",
    "Take 2 grey tiles out of the centre bay and over to despatch",
])
def test_two_words_run_together_as_said_are_those_words(command: str) -> None:
    """"outta" is "out of" (as "gotta" is "got to"): read as the two words."""
    got = translate(command, TILES)
    assert got["goal"] == {"centre_bay": {"grey_tile": 4}, "despatch": {"grey_tile": 4}}

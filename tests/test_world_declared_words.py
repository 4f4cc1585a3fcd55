"""What a warehouse world says its things are called (``words`` on a shelf, product or robot: the
trade's and the floor's own vocabulary, as a household world's ``words``): the offline reader
reads each as the name, in the singular and plural, written apart or together; a word two things
claim is refused where the file says it. In a world of our own (a timber yard), through the real
loader and reader."""
from __future__ import annotations

import pytest
import yaml

from pipflow.errors import TranslationError, WorldError
from pipflow.language.prompting import render
from pipflow.warehouse.language.translator import understand
from pipflow.warehouse.world import world_from_text

YARD = {
    "name": "timberyard",
    "floor": {"width": 30, "height": 20},
    "shelves": {
        "counter": {"x": 2, "y": 14, "width": 4, "depth": 2, "capacity": 20, "access": [4, 13],
                    "words": ["trade counter"]},
        "lean_to": {"x": 10, "y": 14, "width": 4, "depth": 2, "capacity": 20, "access": [12, 13],
                    "words": ["the shed out back"]},
        "gate": {"x": 20, "y": 14, "width": 4, "depth": 2, "capacity": 20, "access": [22, 13]},
    },
    "products": {"decking": {"color": "brown", "words": ["deck board"]}, "batten": {"color": "tan"}},
    "stock": {"counter": {"decking": 4, "batten": 2}, "lean_to": {"decking": 6}, "gate": {"batten": 3}},
    "robots": {"bigred": {"start": [1, 8], "skills": {"carry": 4}, "words": ["the old girl"]},
               "tug": {"start": [15, 8], "skills": {"carry": 2}}},
}


def _world(data: dict) -> dict:
    return world_from_text(yaml.safe_dump(data), "timberyard.yaml")


@pytest.mark.parametrize("said, goal", [
    ("move 2 deck boards from the lean to to the trade counter", {"lean_to": {"decking": 4}, "counter": {"decking": 6}}),
    ("the trade counter should have 1 batten", {"counter": {"batten": 1}}),
    ("bring 2 deckboards to the gate", {"gate": {"decking": 2}}),   # written together; from anywhere
])
def test_a_declared_word_is_read_as_its_name(said: str, goal: dict) -> None:
    assert understand(said, _world(YARD))["goal"] == goal


def test_a_declared_word_of_a_robot_names_it_in_a_rule() -> None:
    got = understand("dont use the old girl. move 1 batten from the gate to the counter", _world(YARD))
    assert got["constraints"] == [{"never": ["bigred"]}]


def test_without_its_declared_words_the_same_world_refuses_them() -> None:
    bare = {**YARD, "shelves": {k: {f: v for f, v in s.items() if f != "words"} for k, s in YARD["shelves"].items()}}
    with pytest.raises(TranslationError):
        understand("the trade counter should have 1 batten", _world(bare))
    assert "words" not in _world(bare)["shelves"]["counter"]   # a world without them is as before


def test_a_word_two_things_claim_is_refused_where_the_file_says_it() -> None:
    clash = {**YARD, "products": {**YARD["products"], "batten": {"color": "tan", "words": ["Trade Counter"]}}}
    with pytest.raises(WorldError) as info:
        _world(clash)
    [problem] = info.value.diagnostics
    assert "'Trade Counter' is said of 'batten' and of 'counter'" in problem.message
    assert problem.location.line is not None


def test_a_declared_word_of_the_grammar_names_the_shelf_only_where_a_shelf_stands() -> None:
    world = _world({**YARD, "shelves": {**YARD["shelves"], "gate": {**YARD["shelves"]["gate"], "words": ["dispatch"]}}})
    assert understand("move 1 batten from the counter to dispatch", world)["goal"] == {"counter": {"batten": 1},
                                                                                        "gate": {"batten": 4}}
    assert understand("dispatch 1 batten from the gate to the counter", world)["goal"] == {"gate": {"batten": 2},
                                                                                            "counter": {"batten": 3}}


def test_a_model_is_told_the_declared_words_and_a_world_without_them_is_prompted_as_before(tmp_path) -> None:
    """The language model path reads the same world: its prompt says what things are called; the
    paper's world (no words) renders the facts exactly as before the words existed."""
    (tmp_path / "facts.j2").write_text('{% import "_warehouse_common.j2" as c %}{{ c.facts(world) }}')
    said = render(str(tmp_path / "facts.j2"), {"world": _world(YARD)})[0]["content"]
    assert "What people here call them: counter: trade counter; lean_to: the shed out back; " \
           "decking: deck board; bigred: the old girl." in said
    bare = {**YARD, "shelves": {k: {f: v for f, v in s.items() if f != "words"} for k, s in YARD["shelves"].items()},
            "products": {k: {"color": p["color"]} for k, p in YARD["products"].items()},
            "robots": {k: {f: v for f, v in r.items() if f != "words"} for k, r in YARD["robots"].items()}}
    assert "call them" not in render(str(tmp_path / "facts.j2"), {"world": _world(bare)})[0]["content"]

"""Issue 23, point 4 (warehouse reader): more candidate readings for a refused command, each
offered (never acted on) with the words it did not read named: the words of a clause before the
one no rule places left out ("could" in "could two more X go to P"), and a whole sentence that
does not read left out of a command of several. In a world of its own (a bike shop), through the
real reader."""
from __future__ import annotations

import pytest

from pipflow.errors import TranslationError
from pipflow.warehouse.language.translator import understand

BIKES = {
    "name": "bikeshop",
    "floor": {"width": 30, "height": 20},
    "shelves": {
        "front_rack": {"x": 2, "y": 14, "width": 4, "depth": 2, "capacity": 12, "access": [4, 13]},
        "back_room": {"x": 10, "y": 14, "width": 4, "depth": 2, "capacity": 12, "access": [12, 13]},
        "wall_hooks": {"x": 20, "y": 14, "width": 6, "depth": 2, "capacity": 10, "access": [23, 13]},
        "repair_bench": {"x": 4, "y": 3, "width": 6, "depth": 2, "capacity": 10, "access": [7, 6]},
    },
    "products": {"inner_tube": {"color": "black"}, "helmet": {"color": "red"}, "pump": {"color": "blue"},
                 "chain": {"color": "gray"}},
    "stock": {"front_rack": {"inner_tube": 5, "helmet": 2}, "back_room": {"inner_tube": 1, "pump": 3},
              "wall_hooks": {"helmet": 3, "chain": 1}, "repair_bench": {"chain": 2}},
    "robots": {
        "porter": {"kind": "forklift", "start": [1, 8], "skills": {"carry": 4}},
        "zip_1": {"kind": "amr", "start": [15, 8], "skills": {"carry": 1}},
        "zip_2": {"kind": "amr", "start": [18, 8], "skills": {"carry": 1}},
    },
}


def _offered(command: str) -> list[dict]:
    with pytest.raises(TranslationError) as err:
        understand(command, BIKES)
    assert len(err.value.candidates) <= 3
    return err.value.candidates


def test_the_words_that_lead_a_clause_astray_are_left_out_in_a_candidate() -> None:
    """'might' before the count is what no rule reads here ("could two more X go to P" is read
    now); the reading without it is offered, and says that 'might' was not read."""
    offered = _offered("might two more pumps go to the wall hooks")
    hit = [c for c in offered if c["goal"] == {"wall_hooks": {"pump": 2}}]
    assert hit, offered
    assert hit[0]["unread"] == ["might"] and "not read: 'might'" in hit[0]["reading"]


def test_a_sentence_that_does_not_read_is_left_out_in_a_candidate_and_named() -> None:
    offered = _offered("Can porter bring the helmets from the wall hooks to the back room? All three.")
    hit = [c for c in offered if c["goal"] == {"wall_hooks": {"helmet": 0}, "back_room": {"helmet": 3}}]
    assert hit, offered
    assert [r["only"] for r in hit[0]["constraints"]] == [["porter"]]
    assert hit[0]["unread"] == ["All three"]


def test_a_single_sentence_is_never_left_out_whole() -> None:
    """Nothing would be left to offer: the refusal offers no empty reading."""
    offered = _offered("the wall hooks are looking bare")
    assert all(c["goal"] or c["constraints"] for c in offered)


@pytest.mark.parametrize("command, wrong, right", [
    ("move 2 pumps fro the back room to the front rack", "fro", "from"),       # for, or from?
    # a name's word two edits away (one edit, "fornt rack", is read: names._misspelt_apart)
    ("move 2 pumps from the back room to the fornot rack", "fornot", "front"),
])
def test_a_near_miss_word_is_offered_respelt_and_the_repair_is_said(command: str, wrong: str, right: str) -> None:
    """The lexicon repairs only a word with one near repair (it acts on it); a candidate may
    offer the reading with the word respelt, saying so, for the user to choose."""
    offered = _offered(command)
    hit = [c for c in offered if c["goal"] == {"back_room": {"pump": 1}, "front_rack": {"pump": 2}}]
    assert hit, offered
    assert f"read '{wrong}' as '{right}'" in hit[0]["reading"]


def test_a_respelt_reading_is_only_offered_when_the_whole_command_then_reads() -> None:
    """'zorp' is near no word that has a place: no repair is offered for it."""
    offered = _offered("move 2 pumps zorp the back room to the front rack")
    assert not any("read 'zorp'" in c["reading"] for c in offered)


def test_could_do_with_n_offers_both_the_count_to_end_with_and_the_count_to_add() -> None:
    """"P could do with 3 X" where P holds some: 3 in all, or 3 more? Refused, both offered."""
    goals = [c["goal"] for c in _offered("the front rack could do with 3 helmets")]
    assert {"front_rack": {"helmet": 3}} in goals and {"front_rack": {"helmet": 5}} in goals


def test_a_partial_reading_that_meets_competing_readings_offers_each() -> None:
    """Words left out, and then a sentence with two readings: each reading is offered, with the
    words left out named."""
    offered = _offered("Blorp one - the front rack could do with 3 helmets")
    goals = [c["goal"] for c in offered]
    assert {"front_rack": {"helmet": 3}} in goals and {"front_rack": {"helmet": 5}} in goals
    assert all("Blorp" in " ".join(c["unread"]) for c in offered)


def test_a_command_read_again_after_its_world_gained_a_name_sees_the_name() -> None:
    """The reader remembers the tokens of recent commands (candidates re-read them); a world
    object changed in place since is read afresh, never through the old names."""
    import copy
    world = copy.deepcopy(BIKES)
    with pytest.raises(TranslationError):
        understand("put 2 pumps on the loft", world)
    world["shelves"]["loft"] = {"x": 14, "y": 3, "width": 3, "depth": 2, "capacity": 6, "access": [15, 6]}
    assert understand("put 2 pumps on the loft", world)["goal"] == {"loft": {"pump": 2}}


def test_a_sentence_whose_clause_does_not_read_is_offered_with_another_sentence_left_out() -> None:
    """Two sentences, neither reads whole: the first without its talking clause ("we need space")
    and the second left out (no rule places its words) make one candidate, both named."""
    offered = _offered("Move 2 inner tubes from the front rack to the wall hooks, we need space for the van. "
                       "Ta ever so kindly squire.")
    hit = [c for c in offered if c["goal"] == {"front_rack": {"inner_tube": 3}, "wall_hooks": {"inner_tube": 2}}]
    assert hit, offered
    assert hit[0]["unread"] == [", we need space", "Ta ever so squire"]

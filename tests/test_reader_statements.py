"""A clause that states what is so, its subject a pronoun other than "you" ("..., he makes a
strange noise", "..., tomorrow we wash it with vinegar", "..., they are ripe now"), asks for
nothing: it is set aside and said aloud, like a greeting. One that names anything of the world,
holds a number or an operative word, or wants or must something ("we want it cleared", "they
must go to shelf3") is never set aside: it is read, or the command refused."""
from __future__ import annotations

from pathlib import Path

import pytest
import yaml

from pipflow.errors import TranslationError
from pipflow.language.asides import is_statement
from pipflow.warehouse.language.translator import understand

ROOT = Path(__file__).resolve().parent.parent
PAPER = yaml.safe_load((ROOT / "benchmarks" / "warehouse" / "world.yaml").read_text())
# paper stock: shelf1 {p1 10, p2 2, p3 3}, shelf2 {p1 8, p2 5, p3 6, p4 2}


@pytest.mark.parametrize("tail", ["tomorrow we wash it with vinegar", "they are ripe now",
                                  "she makes a strange noise", "we clean it on fridays",
                                  "he still has a dodgy wheel"])
def test_a_statement_after_the_order_is_set_aside_and_said(tail: str) -> None:
    got = understand(f"Take 2 product1 off shelf2, {tail}", PAPER)
    assert got["goal"] == {"shelf2": {"product1": 6}}
    assert got["order"]["set_aside"] == [tail]


@pytest.mark.parametrize("tail", ["they go to shelf3", "it takes 2 more", "they must not go back",
                                  "we only want one", "it should be empty after", "it has to go back",
                                  "they've got to be moved"])
def test_a_statement_with_content_is_never_set_aside(tail: str) -> None:
    try:
        got = understand(f"Take 2 product1 off shelf2, {tail}", PAPER)
    except TranslationError:
        return
    assert tail not in (got["order"].get("set_aside") or [])


@pytest.mark.parametrize("words, statement", [
    ("he make a strange noise", True), ("tomorrow we wash it with vinegar", True),
    ("we want it cleared", False), ("they must go in the cooler", False), ("you move them", False),
    ("there is no room", False), ("it is 3 deep", False), ("they never fit", False), ("empty it", False),
])
def test_what_a_statement_is(words: str, statement: bool) -> None:
    assert is_statement(words.split(), lambda w: any(ch.isdigit() for ch in w)) is statement


@pytest.mark.parametrize("tail", ["the auditors are in", "her wheel's squeaking", "the kids keep climbing on it",
                                  "he's still got a dodgy wheel"])
def test_a_statement_with_a_noun_subject_is_set_aside(tail: str) -> None:
    got = understand(f"Take 2 product1 off shelf2, {tail}", PAPER)
    assert got["goal"] == {"shelf2": {"product1": 6}}
    assert len(got["order"]["set_aside"]) == 1


def test_a_statement_about_robots_is_never_set_aside() -> None:
    """"the strongest robot is busy" may be a rule said as a fact: read or refused, never dropped."""
    with pytest.raises(TranslationError):
        understand("Take 2 product1 off shelf2, the strongest robot is busy", PAPER)


@pytest.mark.parametrize("command", ["Shelf2 needs 3 more product1 before the van comes",
                                     "Shelf2 needs 3 more product1 until the van comes"])
def test_a_clause_of_time_is_set_aside_though_its_verb_is_a_grammar_word(command: str) -> None:
    got = understand(command, PAPER)
    assert got["goal"] == {"shelf2": {"product1": 11}}
    assert got["order"]["set_aside"]


@pytest.mark.parametrize("command", ["Shelf2 needs 3 more product1 before 4 go to shelf3",
                                     "Shelf2 needs 3 more product1 before the van brings 10 more",
                                     "Shelf2 needs 3 more product1 before you move them",
                                     "Shelf2 needs 3 more product1 before shelf1 is emptied"])
def test_a_clause_of_time_with_a_count_a_name_or_an_order_is_never_set_aside(command: str) -> None:
    try:
        got = understand(command, PAPER)
    except TranslationError:
        return
    assert not got["order"].get("set_aside")


@pytest.mark.parametrize("when", ["at 10am", "at 10 am", "at 2 o'clock"])
def test_a_clause_of_time_with_a_time_of_day_is_set_aside(when: str) -> None:
    """A time of day is no count (issue 23's tenth round): "... before the van comes at 10am"."""
    got = understand(f"Shelf2 needs 3 more product1 before the van comes {when}", PAPER)
    assert got["goal"] == {"shelf2": {"product1": 11}} and got["order"]["set_aside"]


def test_a_reason_that_opens_the_sentence_before_so_is_set_aside() -> None:
    got = understand("We're doing a sale on shelf4 this afternoon, so move 2 product2 from shelf2 to shelf1", PAPER)
    assert got["goal"] == {"shelf2": {"product2": 3}, "shelf1": {"product2": 4}}
    assert len(got["order"]["set_aside"]) == 2   # the reason and its "so"


@pytest.mark.parametrize("command", ["We're closing shelf4 tomorrow, so clear it out",
                                     "We're not using shelf4 today, so move 2 product2 from shelf2 to shelf1",
                                     "We're expecting 3 pallets on shelf4, so move 2 product2 from shelf2 to shelf1"])
def test_a_reason_the_order_points_back_to_or_with_a_count_or_a_negation_is_kept(command: str) -> None:
    try:
        got = understand(command, PAPER)
    except TranslationError:
        return
    assert not got["order"].get("set_aside")


@pytest.mark.parametrize("command", ["Shelf2 should end up with 6 product1 for the Hadleys order",
                                     "Shelf2 should end up with 6 product1 because the delivery is due"])
def test_a_purpose_or_reason_is_set_aside_though_it_holds_grammar_words(command: str) -> None:
    """"order" and "delivery" are words of the grammar; after "for" or "because" they say what
    for, and order nothing."""
    got = understand(command, PAPER)
    assert got["goal"] == {"shelf2": {"product1": 6}}
    assert got["order"]["set_aside"]


@pytest.mark.parametrize("command", ["Shelf2 should end up with 6 product1 for shelf3",
                                     "Shelf2 should end up with 6 product1 for 2 of them",
                                     "Shelf2 should end up with 6 product1 for every order",
                                     "Shelf2 should end up with 6 product1 because you move them"])
def test_a_purpose_with_a_name_a_count_an_operative_word_or_the_robots_is_never_set_aside(command: str) -> None:
    try:
        got = understand(command, PAPER)
    except TranslationError:
        return
    assert not got["order"].get("set_aside")

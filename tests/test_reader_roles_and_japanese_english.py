"""Issue 23, from pairs XX and YY's warehouse sets (a floor leader in Higashi-Osaka writing Japanese
English, a night supervisor in Cajamar writing Brazilian English): a sentence made only of parts
marked for their role read whatever their order (:mod:`pipflow.warehouse.language.roles`: "chain 6
case inbound to dock please move", "rack B saddle seven case, to dock move", "dock tyre 3 case take
out", "rack A chain total 10 case should be", "is missing 6 tyre on rack B"), the two places of a
swap said first with a comma ("inbound and dock, saddle only exchange"), Japanese politeness and
honorifics ("onegaishimasu", "yoroshiku ne", "OK desu", "Taro-kun, ..."), the topic particle "wa",
"push" as a verb of moving, "in this one:" before the job it announces, "galera" opening a
message, and Québec French's "pis" (then) from pair YY's household writer; and, from pair ZZ's
Indonesian English (after its first measurement), the closing "ya" ("... ya pak"; "would ya" stays
a request tag), "tolong", "dus", "minimal", "take 2 off"; and from pair AA's Flemish English, "aub",
"dank u", "stuks", "st." and Flemish talk. In a world of our own (a bicycle-parts depot), through the real reader; each rule with what
stays as said or refused."""
from __future__ import annotations

import pytest

from pipflow.errors import PipflowError
from pipflow.warehouse.language.translator import understand
from tests.readings import assert_warehouse_alike

DEPOT = {
    "name": "cycledepot",
    "floor": {"width": 40, "height": 20},
    "shelves": {
        "inbound": {"x": 2, "y": 14, "width": 4, "depth": 2, "capacity": 40, "access": [4, 13]},
        "racka": {"x": 10, "y": 14, "width": 4, "depth": 2, "capacity": 40, "access": [12, 13], "words": ["rack A"]},
        "rackb": {"x": 18, "y": 14, "width": 4, "depth": 2, "capacity": 40, "access": [20, 13], "words": ["rack B"]},
        "dock": {"x": 26, "y": 14, "width": 4, "depth": 2, "capacity": 40, "access": [28, 13]},
    },
    "products": {"chain": {"color": "grey"}, "saddle": {"color": "black"}, "tyre": {"color": "blue"}},
    "stock": {"inbound": {"chain": 10, "saddle": 4, "tyre": 6}, "racka": {"chain": 12, "tyre": 6},
              "rackb": {"saddle": 9, "tyre": 8}, "dock": {"chain": 2, "tyre": 3}},
    "robots": {"fk1": {"kind": "forklift", "start": [1, 8], "skills": {"carry": 8}, "words": ["Taro"]},
               "fk2": {"kind": "forklift", "start": [9, 8], "skills": {"carry": 6}},
               "tg1": {"kind": "tugger", "start": [17, 8], "skills": {"carry": 4}},
               "amr1": {"kind": "amr", "start": [33, 8], "skills": {"carry": 2}}},
}


def _read(said: str) -> dict:
    return understand(said, DEPOT)


def _same(said: str, plain: str) -> None:
    assert_warehouse_alike(said, plain, DEPOT)


@pytest.mark.parametrize("said, plain", [
    ("chain 6 case inbound to rack A please move", "move 6 chain from inbound to rack A"),
    ("6 chain inbound to rack A move", "move 6 chain from inbound to rack A"),
    ("rack B saddle seven case, to dock please move", "move 7 saddle from rack B to dock"),
    ("inbound tyre 4 case → dock", "move 4 tyre from inbound to dock"),
    ("rack A chain 6 case to dock please", "move 6 chain from rack A to dock"),
    ("rack B tyre, half of it to dock please move", "move half of the tyre from rack B to dock"),
    ("rack B saddle 4 case and tyre 5 case, both to dock please", "move 4 saddle and 5 tyre from rack B to dock"),
    ("inbound chain 4 case to dock, rest to rack A", "move 4 chain from inbound to dock, rest to rack A"),
    ("dock tyre 2 case take out please", "take out 2 tyre from dock"),
    ("rack A chain, one third of it please take away", "take away a third of the chain from rack A"),
    ("rack A chain total 10 case should be", "rack A should have 10 chain"),
    ("dock saddle 3 case more please", "add 3 saddle to dock"),
    ("dock chain please double", "double the chain on dock"),
    ("is missing 6 tyre on rack B", "add 6 tyre to rack B"),
    ("rack B is missing 6 tyre", "add 6 tyre to rack B"),
    ("inbound and dock, saddle only please exchange", "swap the saddle between inbound and dock"),
    ("rack A and rack B, all contents exchange", "swap everything between rack A and rack B"),
])
def test_a_sentence_read_by_the_roles_of_its_parts(said: str, plain: str) -> None:
    _same(said, plain)


@pytest.mark.parametrize("said", [
    "inbound chain 6 case rack A move",                # where to is not said ("to")
    "inbound chain 6 case, 3 case to dock",            # two counts of one thing
    "inbound chain 6 case not to dock",                # a negation is never read by roles
    "inbound and rack A chain 6 case to dock",         # two places it could come from
    "inbound chain 6 case to dock and rack A",         # two places it could go to
    "rack A chain 10 case should be and move",         # two operations
])
def test_parts_without_one_reading_are_not_read_by_roles(said: str) -> None:
    with pytest.raises(PipflowError):
        _read(said)


def test_a_count_taken_back_after_a_comma_is_no_second_order() -> None:
    """A clause after a comma is read with no verb only where nothing before it counts a thing:
    "Send 5 chain ..., no wait, 4 chain ..." asks once, never for 9."""
    with pytest.raises(PipflowError):
        _read("send 5 chain from inbound to dock, no wait, 4 chain from inbound to dock")


def test_a_refusal_quotes_a_word_said_never_one_the_reader_put_in() -> None:
    with pytest.raises(PipflowError, match="cannot place 'chain'"):
        _read("inbound and rack A chain 6 case to dock")


def test_english_order_is_read_by_the_grammar_as_before() -> None:
    got = _read("move 6 chain from inbound to rack A")
    assert got["goal"] == {"inbound": {"chain": 4}, "racka": {"chain": 18}}


@pytest.mark.parametrize("said, plain", [
    ("Sumimasen, dock saddle 3 case more please. onegaishimasu", "add 3 saddle to dock"),
    ("move 2 tyre from inbound to dock. yoroshiku ne.", "move 2 tyre from inbound to dock"),
    ("move 2 tyre from inbound to dock. OK desu", "move 2 tyre from inbound to dock"),
    ("Ohayo gozaimasu. move 2 tyre from inbound to dock, hai", "move 2 tyre from inbound to dock"),
    ("Taro-kun, move 3 chain from inbound to dock", "Taro, move 3 chain from inbound to dock"),
    ("dock wa tyre maximum 1 case", "dock should have at most 1 tyre"),
    ("push 6 chain from inbound to dock", "move 6 chain from inbound to dock"),
    ("pull 6 chain from inbound to dock", "move 6 chain from inbound to dock"),
    ("only the forklifts in this one: 4 chain from inbound to rack B",
     "only the forklifts for this one: 4 chain from inbound to rack B"),
    ("galera I want minimum 2 tyre in all the places", "I want minimum 2 tyre in all the places"),
    ("move 2 tyre from inbound to dock rapidinho pfv", "move 2 tyre from inbound to dock"),
    ("move 2 tyre from inbound to dock pis empty rack A", "move 2 tyre from inbound to dock, then empty rack A"),
    ("move 2 tyre from inbound to dock por favor", "move 2 tyre from inbound to dock"),
    # Indonesian English (pair ZZ): the closing "ya" ("ya pak", "ya kak"), "tolong", "dus", "minimal"
    ("kak tolong add 6 dus chain to dock ya", "add 6 chain to dock"),
    ("move 5 chain from inbound to dock ya pak. makasih", "move 5 chain from inbound to dock"),
    ("dock tyre minimal 4 ya bu", "dock should have at least 4 tyre"),
    ("dock tyre take 2 off ya", "take 2 tyre off dock"),
    ("pagi pak, siap. move 5 chain from inbound to dock wkwk", "move 5 chain from inbound to dock"),
    # Flemish English (pair AA): "aub" / "a.u.b." (please), "dank u", "ff", "seffens", "allez", "stuks", "st."
    ("ff 4 chain from inbound to dock aub", "move 4 chain from inbound to dock"),
    ("empty rack A a.u.b.", "empty rack A"),
    ("Allez, move 2 st. chain from inbound to dock, seffens. dank u", "move 2 chain from inbound to dock"),
    ("move 4 stuks chain from inbound to dock", "move 4 chain from inbound to dock"),
])
def test_japanese_and_brazilian_talk_and_forms(said: str, plain: str) -> None:
    _same(said, plain)


def test_an_honorific_on_a_robot_is_that_robot_only() -> None:
    rules = _read("Taro-kun, move 3 chain from inbound to dock")["constraints"]
    assert [r["only"] for r in rules] == [["fk1"]]


def test_wa_after_no_name_stays_unread() -> None:
    with pytest.raises(PipflowError, match="wa"):
        _read("move wa 3 chain from inbound to dock")


def test_would_ya_stays_a_request_tag() -> None:
    _same("move 5 chain from inbound to dock would ya", "move 5 chain from inbound to dock")

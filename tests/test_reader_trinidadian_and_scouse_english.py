"""Issue 23, from pair RR's sixty-first sets (the night lead of a drinks warehouse in Chaguanas
writing Trinidadian English, a nurse in Walton writing Scouse), after their first measurements.
Warehouse: "doh" (don't), "allyuh", "Boy ..." opening an order, a place taken back and said again
alone ("to P... nah scratch dat, Q self"), "every last thing", "all of it", "each and every", "more
is fine", "at all", "now for now", "by the time ...", "is so dem want it", "don't leave more than N
X on P" (a bound), an order taken back whole ("halve X, nah wait, cut it by a third"), an apposition that says
what a place holds now before the count it must come to, and "dat" never a shortening of a name.
Household: "youse", "me mam", "the arl fella('s)", "do the pots", "..., just the plate" (only:
never dropped as talk, which widened the order), a room said to be a tip as the
reason for the orders, a thing brought "in", "before it goes stale", a thing "covered in" jam (dirty), a cue of warmth no heater
answers as the reason for what is asked, a thing switched "in the front room", the title of what
someone watches, "they" in a remark standing for what it stood for then, where the speaker has
just come in from ("Just in off nights"), "some divvy's left" (someone), "gagging for a brew"
(a wish, never what the speaker is busy with), and a count taking
first what lies in no closed container. Worlds of our own, through the real readers; each rule
with what stays as said or refused."""
from __future__ import annotations

import pytest

from pipflow.errors import PipflowError, TranslationError
from pipflow.household.world import world_from_text
from tests.readings import assert_warehouse_alike, household_goal as goal
from tests.test_reader_australian_and_levantine_english import YARD

#: the yard with a place called dispatch ("dat" holds its letters in order)
DISPATCH = {**YARD, "shelves": {**YARD["shelves"], "dispatch": {
    "x": 34, "y": 14, "width": 4, "depth": 2, "capacity": 40, "access": [36, 13]}},
    "stock": {**YARD["stock"], "dispatch": {"cider": 1, "biscuit": 0}}}


@pytest.mark.parametrize("said, plain", [
    ("doh touch pick face at all, move 3 cider from grog cage to the loading dock",
     "don't touch face, move 3 cider from cage to dock"),
    ("Boy move 3 cider from grog cage to pick face", "move 3 cider from cage to face"),
    ("Evening allyuh. Move 3 cider from grog cage to pick face", "move 3 cider from cage to face"),
    ("move 3 cider from grog cage to pick face... nah scratch dat, the loading dock self",
     "move 3 cider from cage to dock"),
    ("move 3 cider from grog cage to pick face, no, loading dock", "move 3 cider from cage to dock"),
    ("move 3 cider from grog cage to pick face, no wait, the loading dock", "move 3 cider from cage to dock"),
    ("Clear out pick face tonight, every last ting", "empty face"),
    ("swap everything on pick face with the loading dock, all of it", "swap face and dock"),
    ("each and every place should have at least 2 bikkie", "every place should have at least 2 biscuit"),
    ("the loading dock should have at least 5 cider, more is fine", "dock should have at least 5 cider"),
    ("pick face, which has 4 cider right now, needs to come down to 2", "face should have 2 cider"),
    ("empty pick face for me now for now", "empty face"),
    ("move 3 cider from grog cage to pick face, doh ask me why", "move 3 cider from cage to face"),
    ("Dont ask. Move 3 cider from grog cage to pick face", "move 3 cider from cage to face"),
    ("the loading dock should have 5 cider by the time the Main Road truck reach",
     "dock should have 5 cider"),
    ("move 3 cider from grog cage to pick face, is so dem want it", "move 3 cider from cage to face"),
    ("Empty pick face. Dey coming first thing in the morning to fix the racking", "empty face"),
    ("doh leave more than 5 cider on the loading dock", "no more than 5 cider on dock"),
    ("never keep over 5 cider on the loading dock", "no more than 5 cider on dock"),
    # an order taken back whole, the new one's "it" the old one's things
    ("halve the bikkie on grog cage, nah wait, jus cut it by a third", "cut the biscuit on cage by a third"),
    # a remark after the new order is set aside; "nah wait" is never talk to set aside with it
    ("halve the bikkie on grog cage, nah wait, cut it by a third, it too heavy up top",
     "cut the biscuit on cage by a third"),
    # only the clause before the taking back is taken back
    ("move 2 cider from grog cage to the loading dock, then halve the bikkie on pick face, nah wait, cut it by a quarter",
     "move 2 cider from cage to dock, then cut the biscuit on face by a quarter"),
    ("move 3 cider from grog cage to pick face. No, move 2 bikkie from grog cage to the loading dock",
     "move 2 biscuit from cage to dock"),
    # an order after "sorry" or with "also" is another order, not the first taken back
    ("move 3 cider from grog cage to pick face. Sorry, move 2 bikkie from grog cage to the loading dock",
     "move 3 cider from cage to face and move 2 biscuit from cage to dock"),
    ("yeah nah, move 3 cider from grog cage to pick face", "move 3 cider from cage to face"),
    ("add 2 more bikkie to the loading dock nah", "add 2 biscuit to dock"),
    # "no more no less" after a count is no order taken back
    ("pick face should have 4 cider. no more no less", "face should have 4 cider"),
])
def test_trinidadian_english_orders_read_as_their_plain_english(said: str, plain: str) -> None:
    assert_warehouse_alike(said, plain, YARD)


def test_a_spelling_of_a_grammar_word_shortens_no_name() -> None:
    """ "dat" (that) has the letters of "dispatch" in order, but a spelling of a grammar word is
    never read as a shortened name: "make dat 4" takes the count back."""
    assert_warehouse_alike("move 3 cider from grog cage to dispatch... nah make dat 4",
                           "move 4 cider from cage to dispatch", DISPATCH)


@pytest.mark.parametrize("said", [
    # "no" before a place without a comma may open a rule ("no robots from Q"): never a take-back
    "move 3 cider from grog cage to pick face, no loading dock",
    # "every last" with nothing that says all before it and no thing after it
    "move 3 cider from grog cage to pick face, every last one",
    # a place said after the taking back that does not end its clause
    "move 3 cider from grog cage to pick face, no, loading dock bikkie",
    # an order taken back for one that adds to it: which is meant is not said
    "move 3 cider from grog cage to pick face, no wait, also move 2 bikkie to the loading dock",
    # "don't put more than N" may bound what is moved or what the place ends with: not read
    "dont put more than 5 cider on the loading dock",
])
def test_what_the_trinidadian_rules_do_not_cover_stays_refused(said: str) -> None:
    with pytest.raises(PipflowError):
        assert_warehouse_alike(said, "move 3 cider from cage to face", YARD)


def test_no_before_a_rule_still_opens_the_rule() -> None:
    """ "..., no robots from P" is a rule, not a place taken back."""
    assert_warehouse_alike("move 3 cider from grog cage to pick face, no robots from the loading dock",
                           "move 3 cider from cage to face, no robots from dock", YARD)


TERRACE = """
domain: household
name: kirkdale terrace
floor: {width: 16, height: 10}
categories:
  crockery: {words: [pots, dishes], home: cupboard}
  fruit: {words: [fruit]}
places:
  sink:     {x: 1.0, y: 1.0, width: 1.0, depth: 0.6, access: [1.5, 1.8], properties: [receptacle, sink]}
  worktop:  {x: 3.0, y: 1.0, width: 1.5, depth: 0.6, access: [3.7, 1.8], properties: [receptacle], words: [the side]}
  fridge:   {x: 6.0, y: 1.0, width: 1.0, depth: 0.8, access: [6.5, 2.0], properties: [receptacle, openable],
             state: {open: false}}
  breadbin: {x: 8.0, y: 1.0, width: 0.6, depth: 0.4, access: [8.3, 1.8], properties: [receptacle, openable],
             state: {open: false}, words: [bread bin]}
  cupboard: {x: 10.0, y: 1.0, width: 1.0, depth: 0.5, access: [10.5, 1.8], properties: [receptacle, openable],
             state: {open: false}}
  table:    {x: 6.0, y: 5.0, width: 1.2, depth: 0.8, access: [6.6, 4.5], properties: [receptacle]}
  settee:   {x: 12.0, y: 5.0, width: 2.0, depth: 0.9, access: [13.0, 4.5], properties: [receptacle]}
  nansbed:  {x: 14.0, y: 8.0, width: 1.6, depth: 1.2, access: [14.8, 7.0], properties: [receptacle],
             words: [nan's bed]}
  line:     {x: 1.0, y: 8.5, width: 2.0, depth: 0.1, access: [2.0, 8.0], properties: [receptacle],
             words: [washing line]}
  washer:   {x: 1.0, y: 4.0, width: 0.8, depth: 0.7, access: [1.4, 4.8], properties: [receptacle, openable],
             state: {open: false}}
  standardlamp: {x: 15.0, y: 5.0, width: 0.3, depth: 0.3, access: [15.0, 4.5], properties: [toggleable],
                 state: {on: false}, words: [standard lamp]}
  biglight: {x: 8.0, y: 5.0, width: 0.3, depth: 0.3, access: [8.0, 4.5], properties: [toggleable],
             state: {on: false}, words: [big light]}
  kettle:   {x: 4.8, y: 1.0, width: 0.3, depth: 0.3, access: [4.9, 1.8], properties: [toggleable],
             state: {on: false}}
objects:
  mug:     {in: table, mass: 1, properties: [pickupable, washable], state: {dirty: true}, categories: [crockery]}
  plate:   {in: table, mass: 1, properties: [pickupable, washable], state: {dirty: true}, categories: [crockery]}
  bowl:    {in: sink, mass: 1, properties: [pickupable, washable], categories: [crockery]}
  apple:   {in: fridge, mass: 1, properties: [pickupable], categories: [fruit]}
  pear:    {in: worktop, mass: 1, properties: [pickupable], categories: [fruit]}
  orange:  {in: settee, mass: 1, properties: [pickupable], categories: [fruit]}
  bread:   {in: worktop, mass: 1, properties: [pickupable]}
  throw:   {in: settee, mass: 1, properties: [pickupable]}
  towel:   {in: line, mass: 1, properties: [pickupable]}
  sheets:  {in: washer, mass: 1, properties: [pickupable]}
  specs:   {in: table, mass: 1, properties: [pickupable], words: [nan's glasses, glasses]}
  cans:    {in: worktop, mass: 1, properties: [pickupable]}
robots:
  r1: {start: [4.0, 3.0], skills: {pickup: 1, open: 1, toggle: 1, slice: 1, wash: 1, heat: 1}}
"""


@pytest.fixture(scope="module")
def terrace() -> dict:
    return world_from_text(TERRACE, "kirkdale-terrace.yaml")


@pytest.mark.parametrize("said, plain", [
    ("Giz a hand will youse, wash the mug", "wash the mug"),
    ("Ey can one of youse peg the sheets out on the line", "put the sheets on the line"),
    ("Do the pots will youse, I haven't got it in me today", "wash the crockery"),
    ("Put two bits of fruit on the table for me nan", "put two bits of fruit on the table"),
    ("put the arl fella's cans in the fridge", "put the cans in the fridge"),
    ("the front room's like a tip, put the mug in the sink", "put the mug in the sink"),
    ("Bring the towel in from the line and put it on the settee", "put the towel on the settee"),
    ("Bring the towel in while your out there and just stick it on the settee, ta la",
     "put the towel on the settee"),
    ("Put the bread back in the bread bin before it goes stale", "put the bread in the bread bin"),
    ("put the bread in the bread bin so it doesn't go stale", "put the bread in the bread bin"),
    ("put the standard lamp on in the front room, its dead gloomy in there", "switch on the standard lamp"),
    ("Put me nan's glasses on her bed for when she wakes up", "put the glasses on nan's bed"),
    ("wash the mug, it's been on the table since Sunday", "wash the mug"),
    ("put the standard lamp on for me nan, she's watching Homes Under the Hammer", "switch on the standard lamp"),
    ("Me nan's freezing. Put the throw on her bed", "put the throw on nan's bed"),
    ("Do the pots will youse, just the mug and the plate mind", "wash the mug and the plate"),
    ("wash the crockery, only the mug", "wash the mug"),
    ("put the fruit on the table, just the pear", "put the pear on the table"),
    ("That mug's been left on the table all covered in jam, can youse wash it and put it in the cupboard",
     "wash the mug and put it in the cupboard"),
    ("the mug is covered in bread", "wash the mug"),
    ("Just in off nights and I'm dead on me feet. Some divvy's left the bread out on the side, put it in the bread bin",
     "put the bread in the bread bin"),
    ("Just in from a 12 hour shift at the Royal, ward was mental. I'm gagging for a brew la", "put the kettle on"),
    ("ward was mental. I'm dying for a brew", "put the kettle on"),
    # what the speaker needs pointed back at is why; a state after it is asked for
    ("put the towel on the settee, I need them towels for tonight", "put the towel on the settee"),
    ("put the mug and the plate in the sink, I need them washed for tonight",
     "put the mug and the plate in the sink and wash them"),
])
def test_scouse_reads_as_its_plain_english(terrace: dict, said: str, plain: str) -> None:
    assert goal(said, terrace) == goal(plain, terrace)


def test_they_in_a_remark_stands_for_what_it_stood_for_when_said(terrace: dict) -> None:
    """ "peg the sheets out, they've been sat in the washer. Bring the towel in ...": the remark's
    "they" is the sheets, said before it, not the towel said after; read at the end, it took the
    towel, and the command was refused as impossible (the towel is not in the washer)."""
    assert goal("peg the sheets out on the line, they've been sat in the washer. Bring the towel in "
                "and stick it on the settee", terrace) == goal("put the sheets on the line and put the towel on the settee",
                                                               terrace)


def test_a_count_takes_first_what_lies_in_no_closed_container(terrace: dict) -> None:
    """Two fruit lie out (the pear, the orange): the plan need not open the fridge, so the goal asks
    nothing of its door; a third is in the fridge, which the plan opens and closes again."""
    assert goal("put two bits of fruit on the table", terrace) == \
        {"count": [{"category": "fruit", "in": "table", "at_least": 2}]}
    assert goal("put three bits of fruit on the table", terrace)["state"] == {"fridge": ["closed"]}


@pytest.mark.parametrize("said", [
    # a room's disorder said alone asks for nothing it names
    "the front room is a tip",
    # "do" before things that do not wash
    "do the standard lamp",
    # a cue of warmth alone, in a home with no heater: asked
    "me nan's freezing",
    # where the speaker has come from, with a thing of the home in it, is no remark to drop
    "Just back from the settee. Put the kettle on",
    # a room said after words that name two lights: which one is not said
    "switch the light on in the front room",
    # "just" before things narrows the order, never dropped as talk ("wash the crockery" would
    # wash all); a thing outside what the order names narrows nothing: refused on "only"
    "wash the crockery, just the pear",
    "wash the crockery, only the mug or the plate",
])
def test_what_the_scouse_rules_do_not_cover_stays_refused(terrace: dict, said: str) -> None:
    with pytest.raises(PipflowError):
        goal(said, terrace)


def test_a_cue_of_warmth_a_heater_could_answer_is_not_made_a_reason(terrace: dict) -> None:
    """In a home with a room heater that is off, "me nan's freezing" asks for it on, as before:
    only where the home has none is the cue the reason for the rest."""
    heated = dict(terrace, places={**terrace["places"], "radiator": {
        "x": 11.0, "y": 8.0, "width": 0.5, "depth": 0.3, "access": [11.2, 7.5], "properties": ["toggleable"],
        "state": {"on": False}, "categories": ["heating"]}})
    assert goal("Me nan's freezing. Put the throw on her bed", heated)["state"] == {"radiator": ["on"]}


def test_a_remark_of_the_speaker_too_tired_is_no_order(terrace: dict) -> None:
    """ "I haven't got it in me today" says why; with no order beside it, nothing is asked."""
    with pytest.raises(TranslationError):
        goal("I haven't got it in me today", terrace)

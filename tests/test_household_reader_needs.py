"""Issue 23, second step, household reader: the general causes of the held-out houseboat set's
refusals, in a bothy of our own (names no benchmark uses): a thing lit ("light the stove"), texting
words ("pls", "n"), "where they go", a thing cleared off a place, a switch named by its button,
a thing picked out by where it is in a subject ("the jug on the trestle needs washing"), what
things need ("deal with the crocks", "the veg is all over the place", "X is filthy") and the
warmth of the room ("it's freezing in here", "I'm cold"). Each read right, or refused where two
people would not agree."""
from __future__ import annotations

import pytest

from pipflow.errors import Refusal, TranslationError
from pipflow.household.language.translator import translate
from pipflow.household.world import world_from_text

BOTHY = """
domain: household
name: bothy
floor: {width: 6, height: 5}
categories:
  crocks: {words: [crocks, crockery, dishes], home: dresser}
  lamps: {words: [lamps, lights]}
  veg: {words: [veg, vegetables], home: larder}
  fruit: {words: [fruit], home: bench}
places:
  icebox:   {x: 0.2, y: 4.0, width: 0.8, depth: 0.8, access: [0.6, 3.5], properties: [receptacle, openable], state: {open: false}}
  bench:    {x: 1.4, y: 4.2, width: 1.5, depth: 0.6, access: [2.1, 3.6], properties: [receptacle], words: [worktop]}
  griddle:  {x: 3.2, y: 4.2, width: 0.7, depth: 0.6, access: [3.5, 3.6], properties: [receptacle, heater, toggleable], state: {on: false}}
  basin:    {x: 0.2, y: 2.0, width: 0.7, depth: 0.7, access: [1.2, 2.3], properties: [receptacle, sink]}
  dresser:  {x: 0.2, y: 0.2, width: 1.0, depth: 0.5, access: [0.7, 1.0], properties: [receptacle, openable], state: {open: false}}
  larder:   {x: 4.2, y: 0.2, width: 1.0, depth: 0.5, access: [4.7, 1.0], properties: [receptacle, openable], state: {open: false}}
  trestle:  {x: 2.5, y: 2.0, width: 1.2, depth: 0.8, access: [3.1, 1.5], properties: [receptacle], words: [table, trestle table]}
  lamp:     {x: 4.0, y: 2.2, width: 0.2, depth: 0.2, access: [4.3, 1.5], properties: [toggleable], state: {on: false}, categories: [lamps]}
  wood_stove: {x: 5.3, y: 2.2, width: 0.5, depth: 0.5, access: [5.0, 1.5], properties: [toggleable], state: {on: false}}
  pail:     {x: 5.2, y: 4.2, width: 0.4, depth: 0.4, access: [5.0, 3.6], properties: [garbage], words: [bin]}
objects:
  jug:      {in: trestle, mass: 1, properties: [pickupable, washable], state: {dirty: true}, categories: [crocks]}
  platter:  {in: trestle, mass: 1, properties: [pickupable, washable], state: {dirty: true}, categories: [crocks]}
  beaker:   {in: bench, mass: 1, properties: [pickupable, washable], categories: [crocks]}
  turnip:   {in: bench, mass: 1, properties: [pickupable, sliceable, heatable], categories: [veg]}
  swede:    {in: larder, mass: 1, properties: [pickupable, sliceable, heatable], categories: [veg]}
  plum:     {in: bench, mass: 1, properties: [pickupable, sliceable], categories: [fruit]}
  lantern:  {in: trestle, mass: 1, properties: [pickupable, toggleable], state: {on: true}, categories: [lamps]}
  wireless: {in: dresser, mass: 1, properties: [pickupable, toggleable], state: {on: false}}
robots:
  r1: {start: [1.0, 1.0], skills: {pickup: 1, open: 1, toggle: 1, slice: 1, wash: 1, heat: 1}}
  r2: {start: [3.0, 1.0], skills: {pickup: 1, open: 1, toggle: 1, slice: 1, wash: 1, heat: 1}}
"""


@pytest.fixture(scope="module")
def bothy() -> dict:
    return world_from_text(BOTHY, "bothy.yaml")


def goal(command: str, world: dict) -> tuple[dict, dict]:
    g = translate(command, world)["goal"]
    return ({p: sorted(v) for p, v in g.get("in", {}).items() if v},
            {n: sorted(v) for n, v in g.get("state", {}).items() if v})


def test_a_thing_lit_is_switched_on(bothy):
    assert goal("Light the wood stove and switch the lantern off.", bothy) == \
        ({}, {"wood_stove": ["on"], "lantern": ["off"]})
    with pytest.raises(Refusal):   # a jug does not switch: lighting it is impossible, never a guess
        goal("Light the jug.", bothy)


def test_texting_words_and_where_things_go(bothy):
    assert goal("Wash the jug n the platter pls", bothy) == ({}, {"jug": ["clean"], "platter": ["clean"]})
    assert goal("turn on the lamp plz", bothy) == ({}, {"lamp": ["on"]})
    assert goal("Clear the crocks and the veg off the bench, put them where they go.", bothy) == \
        ({"dresser": ["beaker"], "larder": ["turnip"]}, {"dresser": ["closed"], "larder": ["closed"]})
    assert goal("Put the plum away where it belongs.", bothy) == ({"bench": ["plum"]}, {})


def test_a_switch_named_by_its_button(bothy):
    assert goal("Turn on the wireless power button.", bothy) == ({}, {"wireless": ["on"], "dresser": ["closed"]})
    assert goal("Switch the lamp switch on.", bothy) == ({}, {"lamp": ["on"]})


def test_a_subject_picked_out_by_where_it_is(bothy):
    assert goal("The jug on the trestle needs washing, and put the plum in the basin.", bothy) == \
        ({"basin": ["plum"]}, {"jug": ["clean"]})
    with pytest.raises(Refusal):   # the jug is on the trestle, not in the basin: never another jug
        goal("The jug in the basin needs washing.", bothy)


def test_what_things_need(bothy):
    # dirt first: the dirty crocks washed, the clean beaker left as found
    assert goal("The dishes are piling up, can someone deal with them?", bothy) == \
        ({}, {"jug": ["clean"], "platter": ["clean"]})
    assert goal("The crocks on the trestle are filthy.", bothy) == ({}, {"jug": ["clean"], "platter": ["clean"]})
    # nothing dirty: things away from their kind's home put there (the swede is home already)
    assert goal("The veg is all over the place.", bothy) == \
        ({"larder": ["swede", "turnip"]}, {"larder": ["closed"]})
    assert goal("Sort the veg out.", bothy) == ({"larder": ["swede", "turnip"]}, {"larder": ["closed"]})
    with pytest.raises(TranslationError, match="what should be done"):   # home, clean: nothing two people agree on
        goal("Deal with the swede.", bothy)
    with pytest.raises(TranslationError):   # the wireless has no home and is clean
        goal("Can you deal with the wireless?", bothy)


def test_the_warmth_of_the_room(bothy, tmp_path):
    # the wood stove warms the room; the griddle is a heater for food, never the heating
    assert goal("Brr, it's freezing in here.", bothy) == ({}, {"wood_stove": ["on"]})
    assert goal("I'm cold.", bothy) == ({}, {"wood_stove": ["on"]})
    assert goal("It's cold in here, light the lamp.", bothy) == ({}, {"lamp": ["on"], "wood_stove": ["on"]})
    with pytest.raises(TranslationError, match="room heater that is on"):   # nothing heating is on
        goal("It's roasting in here.", bothy)
    with pytest.raises(TranslationError):   # "it is cold" of the thing said before, or of the room: not read
        goal("Put the plum in the icebox, it is cold.", bothy)
    no_stove = world_from_text(BOTHY.replace("wood_stove", "stool"), "bothy.yaml")
    with pytest.raises(TranslationError, match="no room heater"):
        goal("It's freezing in here.", no_stove)


def test_what_the_speaker_will_do_is_set_aside_and_said(bothy):
    got = translate("Can you open the icebox? I'll grab the plum myself.", bothy)
    assert got["goal"]["state"] == {"icebox": ["open"]} and got["goal"]["in"] == {}
    assert got["order"]["speaker_does"] == ["i will grab the plum myself"]
    assert any("what the speaker will do" in line for line in got["explain"])
    # a wish is no doing of the speaker's, and negation or "only" bear on the robots: never set aside
    # (the wish is read as one: "I'll need X hot" is "I need X hot", tests/test_household_homely.py)
    assert translate("Open the icebox. I'll need the turnip hot.", bothy)["goal"]["state"]["turnip"] == ["hot"]
    for tail in ("I'll not touch the plum.", "I'll only wash the jug."):
        with pytest.raises(TranslationError):
            translate(f"Open the icebox. {tail}", bothy)


def test_dashes_and_brackets_set_an_aside_off(bothy):
    got = translate("Bin the plum \u2014 it has seen better days \u2014 and switch on the lamp.", bothy)
    assert got["goal"]["in"] == {"pail": ["plum"]} and got["goal"]["state"] == {"lamp": ["on"]}
    assert got["order"]["set_aside"] == ["it has seen better days"]
    got = translate("Bin the plum (it has seen better days) and switch on the lamp.", bothy)
    assert got["order"]["set_aside"] == ["it has seen better days"]
    # a part set off that says something of the thing is read: foulness, the reason for binning it
    got = translate("Bin the plum \u2014 it smells off \u2014 and switch on the lamp.", bothy)
    assert got["goal"]["in"] == {"pail": ["plum"]} and got["goal"]["state"] == {"lamp": ["on"]}
    assert "set_aside" not in got["order"] and any("reason" in n for n in got["notes"])
    with pytest.raises(TranslationError):   # a part set off that names something is still read, and refused
        translate("Bin the plum (and the wobbly jug) and switch on the lamp.", bothy)


def test_a_modifier_alone_names_nothing_so_talk_with_it_is_set_aside(bothy, tmp_path):
    """ "wood" of wood_stove names nothing alone: "off to the wood yard" is talk; "the" is no slip of
    "then" (a word in its own right), so a clause with "the" can be talk."""
    got = translate("Lights out, we're off to the wood yard for the night.", bothy)
    assert got["goal"]["state"] == {"lamp": ["off"], "lantern": ["off"]}
    assert got["order"]["set_aside"] == ["we are off to the wood yard for the night"]


def test_a_cue_asks_for_a_change(bothy):
    """ "it's getting dark": the lights that are off go on; one on already is no condition."""
    assert goal("It's getting a bit dark in here.", bothy) == ({}, {"lamp": ["on"]})
    lit = world_from_text(BOTHY.replace("state: {on: false}, categories: [lamps]", "state: {on: true}, categories: [lamps]"),
                          "bothy.yaml")
    with pytest.raises(TranslationError, match="already"):
        goal("It's getting a bit dark in here.", lit)


def test_a_function_word_is_no_slip_of_an_operative_word():
    """pipflow.language.asides: "the" is a word, not "then" typed with a slip; "on" is not "no".
    A misspelling that is no word of its own still is one ("nto", "olny")."""
    from pipflow.language.asides import near_operative

    assert not near_operative("the") and not near_operative("on")
    assert near_operative("nto") and near_operative("olny") and near_operative("not")


def test_idioms_of_the_home(bothy):
    """"put the X on" switches a thing that switches (not understood for one that does not, never
    impossible: "put the jug on" boils the kettle in Australia, and a jug may be put on); "be a dear
    and", "while you're at it" are framing; "X wants a scrub"; "chopped up"; "two of the X"; "put X in
    P along with Y"; "I'm off to bed" is a reason; "with that X going" names what a cue speaks of."""
    assert goal("Pop the wireless on.", bothy) == ({}, {"wireless": ["on"], "dresser": ["closed"]})
    with pytest.raises(TranslationError, match="'put on' is read only as switching on") as caught:
        goal("Put the jug on.", bothy)
    assert not isinstance(caught.value, Refusal)
    assert goal("Be a dear and slice the plum, and wash the jug while you're at it.", bothy) == \
        ({}, {"plum": ["sliced"], "jug": ["clean"]})
    assert goal("The platter wants a good scrub.", bothy) == ({}, {"platter": ["clean"]})
    assert goal("I would like the turnip chopped up.", bothy) == ({}, {"turnip": ["sliced"]})
    assert goal("Put the jug in the basin along with the platter.", bothy) == ({"basin": ["jug", "platter"]}, {})
    assert goal("I'm off to bed, turn the lantern off.", bothy) == ({}, {"lantern": ["off"]})
    lit = world_from_text(BOTHY.replace("properties: [toggleable], state: {on: false}}",
                                        "properties: [toggleable], state: {on: true}}"), "bothy.yaml")
    assert goal("It's freezing in here with that lantern going.", lit) == ({}, {"lantern": ["off"]})


def test_a_count_taken_out_of_a_closed_container_closes_it_again(bothy):
    """"bring two of the veg to the bench": the one at hand is the turnip; the second comes out of
    the closed larder, which is closed again (the gold of every set says so)."""
    got = translate("Bring two of the veg to the bench.", bothy)
    assert got["goal"]["count"] == [{"category": "veg", "in": "bench", "at_least": 2}]
    assert got["goal"]["state"] == {"larder": ["closed"]}


def test_how_and_in_what_order_is_the_plans_choice(bothy):
    """Issue 23's household causes: an adverb of order anywhere in a clause ("first", "last") and a
    sentence that only restates the order of things already named say how the steps run; an
    ordinal after a determiner ("the first jug") is no such word, and a sentence that names
    something new is read (or refused), never dropped."""
    both = ({}, {"jug": ["clean"], "platter": ["clean"]})
    assert goal("Wash the jug first, then the platter.", bothy) == both
    assert goal("Wash the jug and the platter: first the jug, then the platter.", bothy) == both
    assert goal("Wash the jug and slice the plum, do both in parallel.", bothy) == ({}, {"jug": ["clean"], "plum": ["sliced"]})
    with pytest.raises(TranslationError):
        goal("Wash the first jug.", bothy)
    with pytest.raises(TranslationError):
        goal("Wash the jug and the platter. First the jug, then the beaker.", bothy)


def test_a_thing_named_by_where_it_is_and_what_it_is(bothy):
    """ "the trestle lantern": the home has no such name, but a trestle and a lantern on it; "the
    bench lantern" (none there) is refused, never another lantern; the object left out after a
    verb is the thing named before."""
    assert goal("Turn off the trestle lantern.", bothy) == ({}, {"lantern": ["off"]})
    assert goal("Switch the table lantern switch off.", bothy) == ({}, {"lantern": ["off"]})
    with pytest.raises(TranslationError):
        goal("Turn off the bench lantern.", bothy)
    assert goal("Slice the turnip, then put in the icebox.", bothy) == \
        ({"icebox": ["turnip"]}, {"turnip": ["sliced"], "icebox": ["closed"]})


def test_an_amount_in_a_container_is_some_of_it(bothy):
    """ "a bowl of plums" is the plums (no thing of the home holds another); "a bowl of fruit" of a
    kind does not say how many (asked); where the home has a bowl, "a bowl of X" may mean it too
    (refused)."""
    assert goal("Put a bowl of plums on the trestle.", bothy) == ({"trestle": ["plum"]}, {})
    with pytest.raises(TranslationError, match="how many"):
        goal("Put a bowl of fruit on the trestle.", bothy)
    with_bowl = world_from_text(BOTHY.replace("  beaker:", "  bowl:"), "bothy.yaml")
    with pytest.raises(TranslationError):
        goal("Put a bowl of plums on the trestle.", with_bowl)


def test_a_purpose_is_not_part_of_the_goal(bothy):
    assert goal("The lantern goes on the bench for airing.", bothy) == ({"bench": ["lantern"]}, {})
    assert goal("Put the plum in the icebox for later.", bothy) == ({"icebox": ["plum"]}, {"icebox": ["closed"]})
    with pytest.raises(TranslationError):   # "for washing": the washing may be asked too
        goal("Put the jug in the basin for washing.", bothy)


def test_toast_is_made_of_the_homes_bread(bothy):
    loafy = world_from_text(BOTHY.replace("  plum:", "  loaf:     {in: larder, mass: 1, properties: [pickupable, sliceable, "
                                          "heatable], words: [bread]}\n  plum:"), "bothy.yaml")
    assert goal("Make some toast.", loafy) == ({}, {"loaf": ["hot", "sliced"], "larder": ["closed"]})
    with pytest.raises(Refusal):   # no bread in the bothy: no toast is guessed from a turnip
        goal("Make some toast.", bothy)


# ------------------------------------------------------------------------------ candidate readings
def offered(command: str, world: dict) -> list[dict]:
    with pytest.raises(TranslationError) as refused:
        translate(command, world)
    return refused.value.candidates


def _goals(cands: list[dict]) -> list[tuple[dict, dict]]:
    return [({p: sorted(v) for p, v in c["goal"].get("in", {}).items() if v},
             {n: sorted(v) for n, v in c["goal"].get("state", {}).items() if v}) for c in cands]


def test_a_refusal_offers_readings_from_repairs_and_the_parts_that_parse(bothy):
    """Issue 23 point 4: up to three candidate readings, each in plain words with the words it rests
    on; never acted on unchosen (translate still refuses)."""
    # a misspelling two edits away (the reader repairs only one)
    cands = offered("Slice the tunrpi.", bothy)
    assert ({}, {"turnip": ["sliced"]}) in _goals(cands)
    assert any("'tunrpi' read as 'turnip'" in c["reading"] and c["words"] == "turnip" for c in cands)
    # a word it cannot place, left out; the rest read
    cands = offered("Wash the jug and blorp the platter.", bothy)
    assert _goals(cands)[0] == ({}, {"jug": ["clean"], "platter": ["clean"]})
    assert "read without 'blorp'" in cands[0]["reading"]
    # a clause of talk it could not set aside (a word near a name), left out
    cands = offered("Light the lamp, we're lantrn spotting.", bothy)
    assert ({}, {"lamp": ["on"]}) in _goals(cands)
    # a list said with "or" (under a negation it is read as both: test_or_under_a_negation_lists_both)
    cands = offered("Switch off the lantern or the wireless.", bothy)
    # (the wireless is already off: the dresser that holds it need not be opened, so it is not
    # listed closed again: benchmarks/README.md, tests/test_household_homely.py)
    assert ({}, {"lantern": ["off"], "wireless": ["off"]}) in _goals(cands)
    # the choice a singular asks for: each thing it could be
    cands = offered("Turn on the lamp.", lamps(bothy))
    assert sorted(_goals(cands), key=str) == [({}, {"lamp": ["on"]}), ({}, {"lantern": ["on"]})]
    assert all(c["words"] in ("lamp", "lantern") for c in cands)


def lamps(bothy: dict) -> dict:
    """The bothy with its lantern worded a lamp too: "the lamp" is then two things."""
    return world_from_text(BOTHY.replace("categories: [lamps]}\n  wireless", "categories: [lamps], words: [lamp]}\n  wireless"),
                           "bothy.yaml")


def test_no_candidate_drops_an_operative_word(bothy):
    """Dropping "not", "only", "except" would widen what the robots do: never offered."""
    for command in ("Wash the jug but nott the platter.", "Wash only the jug, not the platter, blorp."):
        for c in offered(command, bothy):
            assert c["goal"]["state"] != {"jug": ["clean"], "platter": ["clean"]}, c["reading"]
    # two letters of "not" swapped, no other word it can be: read as "not", never dropped
    got = goal("Wash the jug but nto the platter.", bothy)
    assert got[1]["jug"] == ["clean"] and "clean" not in got[1].get("platter", [])


def test_where_an_action_happens_said_after_it(bothy):
    """ "heat the turnip? not on the griddle, use the X": the place said after the action (a
    correction); "not on X" alone, "use X" with no action before, or the same place refused and
    used, are asked."""
    hob = world_from_text(BOTHY.replace("  basin:", "  range:    {x: 1.4, y: 2.9, width: 0.5, depth: 0.5, access: [1.65, 2.6], "
                                        "properties: [receptacle, heater]}\n  basin:"), "bothy.yaml")
    assert goal("Could you heat up the turnip? Not on the griddle, use the range.", hob) == \
        ({"range": ["turnip"]}, {"turnip": ["hot"]})
    assert goal("Heat up the turnip, use the griddle.", hob) == ({"griddle": ["turnip"]}, {"turnip": ["hot"]})
    for command in ("Heat up the turnip, not on the griddle.", "Use the range.",
                    "Heat the turnip, not on the range, use the range."):
        with pytest.raises(TranslationError):
            goal(command, hob)


def test_a_world_whose_names_change_is_read_with_its_new_names(bothy):
    """The phrase index of a world is kept between commands (reading time): a changed name must
    not be read with the old index."""
    home = world_from_text(BOTHY, "bothy.yaml")
    assert goal("Turn on the lamp.", home) == ({}, {"lamp": ["on"]})
    home["places"]["lamp"]["words"] = ["glowstick"]
    assert goal("Turn on the glowstick.", home) == ({}, {"lamp": ["on"]})


def test_a_candidate_may_take_two_changes(bothy):
    """A wording that still does not read is worded again from its own refusal: a misspelling two
    edits away repaired, then a clause of talk left out. Each change is said in the echo; with
    one change at a time neither reads. (Where the clause holds a word not understood as well,
    "we're lantrn spotting", the repaired wording is not read: it keeps that word, and such
    wordings are refused the same way.)"""
    command = "Slice the tunrpi, the lantern is dim."
    cands = offered(command, bothy)
    assert ({}, {"turnip": ["sliced"]}) in _goals(cands)
    two = next(c for c in cands if _goals([c])[0] == ({}, {"turnip": ["sliced"]}))
    assert "'tunrpi' read as 'turnip'" in two["reading"] and "read without 'the lantern is dim'" in two["reading"]


def test_robots_addressed_by_name_are_offered_without_their_names(bothy):
    """The household order has no robot rules: "Moss, wash the jug, and Wren, you slice the turnip"
    is refused (reading the names away would drop who the speaker chose), and offered without the
    names, the echo saying who does what is left to the team."""
    named = world_from_text(BOTHY.replace("  r1:", "  moss:").replace("  r2:", "  wren:"), "bothy.yaml")
    for command in ("Moss, wash the jug, and Wren, you slice the turnip.",
                    "Wash the jug, then Moss can slice the turnip."):
        cands = offered(command, named)
        assert ({}, {"jug": ["clean"], "turnip": ["sliced"]}) in _goals(cands)
        assert "robots named" in cands[0]["reading"] and "left to the team" in cands[0]["reading"]
    # a robot named like a thing of the home is that thing, not an address
    lamp_named = world_from_text(BOTHY.replace("  r1:", "  lantern:"), "bothy.yaml")
    assert not any("robots named" in c["reading"] for c in offered("Lantern, wash the jug blorp.", lamp_named))


def test_the_words_of_a_command_are_a_fresh_list_each_time():
    """words_of is kept between calls (reading time); a caller that changes its list must not change
    the next caller's."""
    from pipflow.household.language.lexicon import words_of
    first = words_of("Wash the jug, it's grubby.")
    first.append("blorp")
    assert words_of("Wash the jug, it's grubby.") == ["wash", "the", "jug", ",", "it", "is", "grubby", "."]


def test_a_later_change_never_takes_out_a_word_an_earlier_one_put_in(bothy, monkeypatch):
    """ "The jug smells fine": were "fine" repaired to a word the reading then stops at, leaving
    that word out would drop "fine" in two changes, which no single change may do (the rest says
    the opposite). The first wording is forced here; the search must not build on it that way."""
    from pipflow.household.language import candidates

    real = candidates._wordings

    def forced(said, world, error):
        if "fine" in said:
            return [("the jug smells fix .", "'fine' read as 'fix'", "fix", {})]
        return real(said, world, error)

    assert goal("The jug smells.", bothy) == ({}, {"jug": ["clean"]})   # what dropping it would read
    monkeypatch.setattr(candidates, "_wordings", forced)
    assert ({}, {"jug": ["clean"]}) not in _goals(offered("The jug smells fine.", bothy))
    monkeypatch.setattr(candidates, "_wordings", real)
    assert not offered("The jug smells fine.", bothy)   # "fine" is an appraisal: never repaired, never dropped


def test_where_the_speaker_is_is_where_me_is(bothy):
    """ "I'm sat at the trestle, bring me the turnip": the home model has no person; the clause
    that says where the speaker is gives "me" a place, and is said in the notes. Without a "bring
    me" after it, or with more in it than where, the clause is not read so."""
    assert goal("I'm sat at the trestle, bring me the turnip.", bothy) == ({"trestle": ["turnip"]}, {})
    assert goal("I'm at the trestle, fetch me the turnip and the plum, and wash the jug.", bothy) == \
        ({"trestle": ["plum", "turnip"]}, {"jug": ["clean"]})
    notes = translate("I'm just sitting at the trestle, can you bring me the turnip?", bothy)["notes"]
    assert any("where you are" in n for n in notes), notes
    for command in ("I'm at the trestle, bring the turnip.",            # no "me": not guessed to be there
                    "I'm at the trestle with a cold, bring me the turnip."):   # more than where
        with pytest.raises(TranslationError):
            translate(command, bothy)


def test_a_step_closed_by_when_it_is_done_is_the_order_of_the_steps(bothy):
    assert goal("Wash the jug and put it in the dresser when it's done.", bothy) == \
        ({"dresser": ["jug"]}, {"dresser": ["closed"], "jug": ["clean"]})
    assert goal("Wash the jug and put it in the dresser once you're finished.", bothy) == \
        ({"dresser": ["jug"]}, {"dresser": ["closed"], "jug": ["clean"]})
    assert goal("Wash the jug and put it in the dresser when its done.", bothy) == \
        ({"dresser": ["jug"]}, {"dresser": ["closed"], "jug": ["clean"]})


def test_that_before_how_the_room_is_is_a_degree(bothy):
    """ "It's that dark in here": "so dark"; "wash the jug, is that dirty?" has "that" as a subject."""
    assert goal("It's that dark in here.", bothy) == goal("It's so dark in here.", bothy)
    assert goal("It's that dark in here.", bothy)[1] == {"lamp": ["on"]}
    notes = translate("It's that dark in here.", bothy)["notes"]
    assert any("'that' grades 'dark'" in n for n in notes), notes
    with pytest.raises(TranslationError):
        translate("Wash the jug, is that dirty?", bothy)


def test_sat_and_stood_say_where_a_thing_lies_about(bothy):
    for verb in ("sat", "sitting", "stood"):
        assert goal(f"The turnip's been {verb} out on the bench all day. Put it back in the larder.", bothy) == \
            ({"larder": ["turnip"]}, {"larder": ["closed"]})


def test_what_the_speaker_will_have_it_with_is_set_aside(bothy):
    assert goal("Slice the turnip, I'll have it with my tea.", bothy) == ({}, {"turnip": ["sliced"]})
    # a wish with no pronoun is a wish: not set aside
    with pytest.raises(TranslationError):
        translate("Slice the turnip, I'll have the plum with it.", bothy)


def test_a_place_that_cannot_wash_but_holds_the_thing_says_which(bothy):
    """ "wash the jug on the trestle": the trestle is no sink, and the jug is on it: it says which
    jug (as "the jug that is on the trestle"), not where it is washed. A thing not there is still
    refused as impossible there; a sink is still where."""
    assert goal("Wash the jug on the trestle.", bothy) == ({}, {"jug": ["clean"]})
    assert goal("Wash the crocks on the trestle and put them in the dresser.", bothy) == \
        ({"dresser": ["jug", "platter"]}, {"dresser": ["closed"], "jug": ["clean"], "platter": ["clean"]})
    assert any("says which" in n for n in translate("Wash the jug on the trestle.", bothy)["notes"])
    with pytest.raises(Refusal, match="not a sink"):
        translate("Wash the beaker on the trestle.", bothy)   # the beaker is on the bench
    # the things are read once: what the echo says of an exception is said once
    notes = translate("Wash the crocks on the trestle, but not the beaker.", bothy)["notes"]
    assert sum("'the beaker' was not asked for" in n for n in notes) == 1, notes
    assert goal("Wash the jug in the basin.", bothy) == ({"basin": ["jug"]}, {"jug": ["clean"]})


def test_texting_words_grade_or_frame_nothing(bothy):
    for command in ("wash the jug real quick lol", "can u wash the jug rn", "literally just wash the jug pls"):
        assert goal(command, bothy) == ({}, {"jug": ["clean"]}), command
    assert goal("it's kinda dark in here", bothy)[1] == {"lamp": ["on"]}
    assert goal("it's super dark in here", bothy)[1] == {"lamp": ["on"]}


def test_an_owner_typed_in_lower_case_is_one_the_homes_names_use(bothy):
    """ "wash ewan's jug": lower case, an owner only where a name of the home says "ewan's ..."."""
    home = world_from_text(BOTHY.replace("words: [table, trestle table]", "words: [table, trestle table, ewan's table]"),
                           "bothy.yaml")
    assert goal("wash ewan's jug", home) == ({}, {"jug": ["clean"]})
    assert goal("Wash Ewan's jug", home) == ({}, {"jug": ["clean"]})
    with pytest.raises(TranslationError, match="'bob'"):
        translate("wash bob's jug", home)


def test_a_word_of_a_place_and_a_category_said_as_lying_in_a_place_is_the_category(bothy):
    """ "there's rubbish all over the trestle" where "rubbish" is also a word of the pail: no place
    lies in another, so it is the rubbish."""
    home = world_from_text(
        BOTHY.replace("words: [bin]}", "words: [bin, rubbish]}")
        .replace("  fruit: {words: [fruit], home: bench}", "  fruit: {words: [fruit], home: bench}\n  rubbish: {words: [rubbish]}")
        .replace("objects:\n", "objects:\n  wrapper:  {in: trestle, mass: 1, properties: [pickupable], categories: [rubbish]}\n"),
        "bothy.yaml")
    assert goal("There's rubbish all over the trestle.", home) == ({"pail": ["wrapper"]}, {})
    assert goal("Put the jug in the rubbish.", home) == ({"pail": ["jug"]}, {})   # where a thing goes: the pail


def test_what_the_speaker_is_busy_with_and_when_is_talk(bothy):
    """ "she's got a call at 2", "I'm eating between meetings", "gonna make tea after this call",
    "we're done for the day": about people, no order; a time of day or how long is no count."""
    for command in ("Slice the turnip, she's got a call at 2.", "Slice the turnip, I'm eating between meetings.",
                    "Slice the turnip, gonna make tea after this call.", "We're done for the day, slice the turnip.",
                    "Slice the turnip, she has a meeting at 10."):
        assert goal(command, bothy) == ({}, {"turnip": ["sliced"]}), command
    # a count is no time: "2 mugs" is never set aside; "I'm not eating" has a negation in it
    for command in ("Slice the turnip, she's got 2 calls.", "Slice the turnip, I'm not eating it."):
        with pytest.raises(TranslationError):
            translate(command, bothy)


def test_the_only_heater_when_it_opens_is_closed_again(bothy):
    """A thing heated where the command does not say, in a home whose one heater opens: the plan
    opens it to put the thing in, so it is listed closed again, as a fridge is."""
    oven = world_from_text(BOTHY.replace("properties: [receptacle, heater, toggleable], state: {on: false}}",
                                         "properties: [receptacle, heater, openable], state: {open: false}}"), "bothy.yaml")
    assert goal("Heat the turnip.", oven) == ({}, {"griddle": ["closed"], "turnip": ["hot"]})
    assert goal("Heat the turnip.", bothy) == ({}, {"turnip": ["hot"]})   # a griddle that does not open


def test_the_plural_of_a_shared_last_word_is_all_of_them(bothy):
    """ "wash both jugs" where a milk jug and a water jug are the home's jugs (a jug rack has the
    word too, as a modifier): both; "the jug" alone is asked."""
    home = world_from_text(BOTHY.replace("  jug:      {in: trestle,", "  milk_jug: {in: trestle,")
                           .replace("  beaker:   {in: bench,", "  water_jug: {in: bench,")
                           .replace("words: [table, trestle table]", "words: [table, trestle table, jug rack]"),
                           "bothy.yaml")
    assert goal("Wash both jugs.", home) == ({}, {"milk_jug": ["clean"], "water_jug": ["clean"]})
    assert goal("Wash the jugs.", home) == ({}, {"milk_jug": ["clean"], "water_jug": ["clean"]})
    with pytest.raises(TranslationError):
        translate("Wash the jug.", home)


def test_a_device_started_is_switched_on(bothy):
    # (the wireless is in the dresser, which is opened for it and closed again)
    assert goal("Start the wireless.", bothy) == ({}, {"wireless": ["on"], "dresser": ["closed"]})
    assert goal("Wash the jug, then fire up the wireless.", bothy) == \
        ({}, {"jug": ["clean"], "wireless": ["on"], "dresser": ["closed"]})
    with pytest.raises(Refusal):
        translate("Start the jug.", bothy)


def test_scots_negatives_and_thon(bothy):
    """ "cannae", "wasnae", "no'" are "can not", "was not", "not"; "thon" is "that": "no" without
    its apostrophe stays the quantifier."""
    from pipflow.household.language.lexicon import words_of
    assert words_of("I cannae see, it wasnae me, I'm no' sleeping, thon jug, no jugs") == \
        ["i", "can", "not", "see", ",", "it", "was", "not", "me", ",", "i", "am", "not", "sleeping", ",",
         "that", "jug", ",", "no", "jugs"]
    assert goal("Wash thon jug on the trestle.", bothy) == ({}, {"jug": ["clean"]})
    # a negated order is refused, never read without its negation: "dinnae" is "do not"
    with pytest.raises(TranslationError, match="in 'do not turn on the lamp'"):
        translate("Dinnae turn on the lamp.", bothy)


def test_a_filler_closing_a_clause_does_not_hide_after(bothy):
    assert goal("Put the swede on the bench, and close the larder after lol", bothy) == \
        ({"bench": ["swede"]}, {"larder": ["closed"]})
    assert goal("Slice the turnip and close the larder after please", bothy) == \
        ({}, {"turnip": ["sliced"], "larder": ["closed"]})


def _same(command: str, with_it: str, world: dict) -> tuple[dict, dict]:
    """The goal of a command, asserted equal to that of its wording with "it" said."""
    got = goal(command, world)
    assert got == goal(with_it, world)
    return got


def test_a_clause_that_leaves_out_it_is_read_as_with_it(bothy):
    """Pro-drop (as speakers of Polish, Spanish or Italian write English): a clause opening with
    "is" and what is said of it is read as "it is ..." would be: a cue, a reason, talk set aside."""
    radio = world_from_text(BOTHY.replace(
        "wireless: {in: dresser, mass: 1, properties: [pickupable, toggleable], state: {on: false}}",
        "radio:    {in: bench, mass: 1, properties: [pickupable, toggleable], state: {on: true}}"), "bothy.yaml")
    assert _same("Turn off the radio, is too loud, and switch on the lamp.",
                 "Turn off the radio, it's too loud, and switch on the lamp.", radio) == \
        ({}, {"radio": ["off"], "lamp": ["on"]})
    assert _same("Is getting dark, put all lights on.", "It's getting dark, put all lights on.", bothy) == \
        ({}, {"lamp": ["on"], "lantern": ["on"]})
    assert _same("Wash the crockery, is all dirty.", "Wash the crockery, it's all dirty.", bothy) == \
        ({}, {"jug": ["clean"], "platter": ["clean"], "beaker": ["clean"]})
    assert _same("Put the plum in the icebox, is for dinner.", "Put the plum in the icebox, it's for dinner.",
                 bothy) == ({"icebox": ["plum"]}, {"icebox": ["closed"]})
    assert _same("Is freezing in here.", "It's freezing in here.", bothy) == ({}, {"wood_stove": ["on"]})
    # refused where "it is" is: the room or the plum?
    with pytest.raises(TranslationError):
        goal("Put the plum in the icebox, is cold.", bothy)
    # asked, or "is" before a subject: a question, never a clause without its subject
    with pytest.raises(TranslationError):
        goal("Is too loud?", radio)
    with pytest.raises(TranslationError):
        goal("Is getting dark?", bothy)
    with pytest.raises(TranslationError):
        goal("Is the lamp on, switch it off.", bothy)
    # after "when" / "once", a step closed: the clause opens there too
    assert _same("Slice the turnip and when is sliced, put it on the trestle.",
                 "Slice the turnip and when it is sliced, put it on the trestle.", bothy) == \
        ({"trestle": ["turnip"]}, {"turnip": ["sliced"]})
    with pytest.raises(TranslationError):
        goal("When is the jug clean, put it in the dresser.", bothy)


def test_a_thing_named_before_its_verb_is_its_object(bothy):
    """Topic first (free word order: "butter put in fridge"): a noun phrase of the home opening a
    clause, then a verb that lacks its object, is that verb's object; with a pronoun taking it up
    ("the jug, wash it") too."""
    assert goal("Plum put in icebox please. And lamp switch on.", bothy) == \
        ({"icebox": ["plum"]}, {"lamp": ["on"], "icebox": ["closed"]})
    assert goal("Wash the jug and the platter, and lantern switch off.", bothy) == \
        ({}, {"jug": ["clean"], "platter": ["clean"], "lantern": ["off"]})
    assert goal("The veg from the bench put where it belongs.", bothy) == \
        ({"larder": ["turnip"]}, {"larder": ["closed"]})
    assert goal("Turnip and plum take out from bench and put on trestle.", bothy) == \
        ({"trestle": ["plum", "turnip"]}, {})
    assert goal("The jug and the platter, wash them.", bothy) == ({}, {"jug": ["clean"], "platter": ["clean"]})
    assert goal("Switch the lamp on and plum put back on trestle.", bothy) == ({"trestle": ["plum"]}, {"lamp": ["on"]})
    # after a name, the words may go on the list of the clause before: asked, never picked
    for said in ("Wash the jug and the platter put in the basin.", "Wash the jug, the platter put in the basin."):
        with pytest.raises(TranslationError):
            goal(said, bothy)
    # a verb that has its object, or that is an adjective too, takes nothing fronted
    for said in ("Jug clean.", "Icebox open.", "The plum put the jug in the basin."):
        with pytest.raises(TranslationError):
            goal(said, bothy)
    # the fronted thing may say where it lies (issue 23, pair QQ); where it does not lie there, the
    # command is refused as said, never another thing washed
    assert goal("The jug on the trestle wash.", bothy) == ({}, {"jug": ["clean"]})
    with pytest.raises((Refusal, TranslationError)):
        goal("The jug on the bench wash.", bothy)


def test_a_thing_not_needed_that_the_command_acts_on_is_the_reason(bothy):
    """ "Put the veg away, I don't need it today": said of things the command already acts on and
    that cannot be switched off, not needing them is the reason, never an impossible switch."""
    assert goal("Put the plum in the icebox, I don't need it.", bothy) == ({"icebox": ["plum"]}, {"icebox": ["closed"]})
    assert goal("Turn the lamp off, I don't need it.", bothy) == ({}, {"lamp": ["off"]})
    with pytest.raises(Refusal):   # said alone, it still asks for the impossible
        goal("I don't need the plum.", bothy)


def test_a_third_person_somewhere_is_where_him_is(bothy):
    """ "Father Tom is at the trestle, bring him the plum": as for "me", where a person is said to
    be gives "him" / "her" / the person's name a place (pipflow/household/language/people.py); a
    lower-case name only after a title ("for father tom"). Where the words do not say where the
    person is, the command is refused saying so, never guessed; two persons at two places, or a
    thing named that already lies on the place said, are refused too."""
    assert goal("Father Tom is at the trestle, bring him his wireless.", bothy) == \
        ({"trestle": ["wireless"]}, {"dresser": ["closed"]})
    assert goal("Bring the plum to Mrs Patel at the trestle.", bothy) == ({"trestle": ["plum"]}, {})
    assert goal("plum bring for uncle bert, he is at trestle.", bothy) == ({"trestle": ["plum"]}, {})
    assert goal("give him beaker at trestle", bothy) == ({"trestle": ["beaker"]}, {})
    assert goal("Hand Auntie Jo the plum, she's on the bench.", bothy) == ({"bench": ["plum"]}, {})
    assert goal("The baby sits the whole day at the trestle. Bring her the plum.", bothy) == ({"trestle": ["plum"]}, {})
    notes = translate("Father Tom is sleeping at the trestle, bring him the plum.", bothy)["notes"]
    assert any("where they are" in n for n in notes) and any("'him'" in n for n in notes), notes
    for command in ("Bring the plum to Grandad.",                      # where he is is not said
                    "Bring Grandad the plum.",
                    "give him jug at trestle",                         # the jug is at the trestle: which jug
                    "Give him the crocks on the trestle.",             # some crocks are there: which
                    "She is at the bench and he is at the trestle, bring him the plum.",   # two places
                    "Father Tom is at the trestle, he wants the plum."):   # a wish about him: no order read
        with pytest.raises(TranslationError):
            translate(command, bothy)
    with pytest.raises(TranslationError, match="is not said"):
        translate("Bring the plum to Grandad.", bothy)


def test_what_is_for_a_person_and_talk_about_them_is_set_aside(bothy):
    """ "slice the turnip for Father Tom", "switch on the lamp for him", "wash the beaker, I need it
    for sugar" (no sugar in the bothy): who or what it is for is set aside, said in the notes;
    "he can't sleep", "Father Tom always forgets": talk about a person, set aside. A clause about
    a person that may ask something ("he wants it warm", "she is cold", "he can't see") is never set
    aside: it is their need, passed on by the speaker (read as "I want it warm", "I am cold", "I
    can't see", said in the notes), and a purpose that names a thing of the home stays (refused)."""
    assert goal("Slice turnip for Father Tom.", bothy) == ({}, {"turnip": ["sliced"]})
    assert goal("Switch on the lamp for him.", bothy) == ({}, {"lamp": ["on"]})
    assert goal("Slice the turnip for Father Tom and wash the jug.", bothy) == \
        ({}, {"turnip": ["sliced"], "jug": ["clean"]})
    assert goal("Wash the beaker, I need it for sugar.", bothy) == ({}, {"beaker": ["clean"]})
    assert goal("Father Tom always forgets. Switch on the lamp.", bothy) == ({}, {"lamp": ["on"]})
    assert goal("He can't sleep, switch on the lamp.", bothy) == ({}, {"lamp": ["on"]})
    notes = translate("Mrs Patel is sleeping, switch on the lamp.", bothy)["notes"]
    assert any("talk about someone" in n for n in notes), notes
    assert goal("Switch on the lamp, he can't see.", bothy) == goal("Switch on the lamp, I can't see.", bothy)
    assert goal("She is cold, switch on the lamp.", bothy) == goal("I am cold, switch on the lamp.", bothy)
    notes = translate("Switch on the lamp, he can't see.", bothy)["notes"]
    assert any("'he can' read as 'i can'" in n for n in notes), notes
    with pytest.raises(Refusal, match="jug cannot be hot"):   # the jug is not heatable: asked the impossible
        translate("Wash the jug, he wants it warm.", bothy)
    for command in ("Slice the turnip for Father Tom and the baby.", "Slice the turnip for the plum.",
                    "Father Tom is sleeping."):
        with pytest.raises(TranslationError):
            translate(command, bothy)


def test_the_candidate_search_reads_no_wording_that_keeps_a_word_its_refusal_could_not_read(bothy):
    """A wording that still holds a word the reader could not read is refused the same way, and
    reading such wordings was half of what a refusal cost: the search does not read them, and
    spends its bounded readings on the others (the repair is still found)."""
    from pipflow.household.language import candidates
    from pipflow.household.language.translator import _translate

    command = "Slice the tunrpi, and wash the jug, we're off."
    with pytest.raises(TranslationError) as refused:
        _translate(command, bothy)
    assert "tunrpi" in refused.value.unread
    read: list[str] = []

    def reading(text, world, choose):
        read.append(text)
        return _translate(text, world, choose)

    cands = candidates.candidate_readings(command, bothy, refused.value, reading)
    assert read
    for text in read:
        assert "tunrpi" not in text.split(), text
    assert ({}, {"turnip": ["sliced"], "jug": ["clean"]}) in _goals(cands)

"""Household orders: the lark parser, the order schema, the resolver, per construction; the
generalization set's commands against their gold; a property test (random orders rendered to
English and read back); the scorer's handling of infeasible tasks; one new construction run end
to end (ENHSP, SCIP, the home executor)."""
from __future__ import annotations

from pathlib import Path

import pytest
import yaml
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from pipflow.errors import Refusal, TranslationError

ROOT = Path(__file__).resolve().parent.parent
WORLD = ROOT / "benchmarks" / "household" / "world.yaml"
LANGUAGE = ROOT / "benchmarks" / "language"
SETS = [LANGUAGE / "household.yaml", LANGUAGE / "household-studio.yaml", LANGUAGE / "household-fresh.yaml",
        LANGUAGE / "household-fresh2.yaml", LANGUAGE / "household-fresh3.yaml"]


@pytest.fixture(scope="module")
def world():
    from pipflow.household.world import load_world

    return load_world(WORLD)


def _norm(goal: dict) -> tuple:
    return ({k: sorted(v) for k, v in (goal.get("in") or {}).items() if v},
            {k: sorted(v) for k, v in (goal.get("state") or {}).items() if v},
            sorted((c["category"], c["in"], c["at_least"]) for c in goal.get("count") or []))


def goal_of(command: str, world: dict) -> tuple:
    from pipflow.household.language.translator import translate

    return _norm(translate(command, world)["goal"])


# ------------------------------------------------------------------------------ per construction
def test_state_change_verbs_and_particles(world):
    assert goal_of("Chop up the lettuce and rinse the pan.", world) == \
        ({}, {"lettuce": ["sliced"], "pan": ["clean"]}, [])
    assert goal_of("Turn the TV off and switch on the stove.", world) == ({}, {"tv": ["off"], "stove": ["on"]}, [])
    assert goal_of("Shut off the floor lamp.", world) == ({}, {"floorlamp": ["off"]}, [])


def test_a_thing_said_after_the_particle_takes_the_same_switch(world):
    """ "turn the TV on and the stove": the stove goes on too (it was refused, or read with what
    followed it)."""
    assert goal_of("Turn the TV on and the stove.", world) == ({}, {"tv": ["on"], "stove": ["on"]}, [])
    assert goal_of("Switch the TV off and the floor lamp, please.", world) == \
        ({}, {"tv": ["off"], "floorlamp": ["off"]}, [])
    assert goal_of("Turn the TV on and the stove off.", world) == ({}, {"tv": ["on"], "stove": ["off"]}, [])


def test_a_thing_between_a_switch_and_a_clause_of_its_own_is_asked_never_guessed(world):
    """ "put the TV on and the stove, and the desk lamp can go off": the stove goes with the TV
    (on) or with the lamp (off); the reader turned it off. Both readings are offered, none is taken."""
    from pipflow.household.language.translator import translate

    with pytest.raises(TranslationError) as refused:
        translate("Put the TV on and the stove, and the desk lamp can go off.", world)
    offered = " | ".join(c["reading"] for c in refused.value.candidates)
    assert "stove on" in offered and "stove off" in offered


def test_heating_in_a_named_heater_keeps_the_thing_there(world):
    """'heat the egg in the microwave' was refused as 'microwave cannot be hot'; the egg must be
    heated there, so it ends in the (closed) microwave, and the fridge it came from is closed."""
    assert goal_of("Heat the egg in the microwave.", world) == \
        ({"microwave": ["egg"]}, {"egg": ["hot"], "fridge": ["closed"], "microwave": ["closed"]}, [])
    assert goal_of("Warm up the bread in the microwave.", world) == \
        ({"microwave": ["bread"]}, {"bread": ["hot"], "microwave": ["closed"]}, [])
    with pytest.raises(Refusal, match="not a heater"):
        goal_of("Heat the bread in the fridge.", world)   # the bread is not in the fridge
    # the egg is: "the egg in the fridge" says which egg, not where it is heated
    assert goal_of("Heat the egg in the fridge.", world) == ({}, {"egg": ["hot"], "fridge": ["closed"]}, [])
    with pytest.raises(Refusal, match="not a sink"):
        goal_of("Wash the mug in the microwave.", world)


def test_selection_by_state_and_pronouns(world):
    assert goal_of("Wash the dirty plate and put it in the cabinet.", world) == \
        ({"cabinet": ["plate"]}, {"plate": ["clean"], "cabinet": ["closed"]}, [])
    # the dishes that are dirty: the bowl is clean, the pan is cookware
    assert goal_of("Put the dirty dishes in the sink and wash them.", world) == \
        ({"sink": ["mug", "plate"]}, {"mug": ["clean"], "plate": ["clean"]}, [])
    with pytest.raises(Refusal, match="bowl is clean"):
        goal_of("Wash the dirty bowl.", world)
    with pytest.raises(TranslationError, match="refers to nothing"):
        goal_of("Put it in the fridge.", world)


def test_selection_by_place(world):
    assert goal_of("Put everything from the sofa on the bed.", world) == \
        ({"bed": ["blanket", "notebook", "pen", "pillow"]}, {}, [])
    with pytest.raises(Refusal, match="milk is in fridge"):
        goal_of("Take the milk from the sofa and put it on the bed.", world)


def test_categories_counts_homes(world):
    assert goal_of("Wash the dishes.", world) == ({}, {"bowl": ["clean"], "mug": ["clean"], "plate": ["clean"]}, [])
    assert goal_of("Put a drink on the desk.", world) == ({}, {}, [("drink", "desk", 1)])
    assert goal_of("Bring three dishes to the sink.", world) == ({}, {}, [("dish", "sink", 3)])
    assert goal_of("Put away the fruit.", world) == ({"fridge": ["apple", "watermelon"]}, {"fridge": ["closed"]}, [])
    # a count noun in the singular names one thing: asked back, never all of them
    with pytest.raises(TranslationError, match="say which"):
        goal_of("Turn off the lamp.", world)
    with pytest.raises(Refusal, match="only 3 drink|only 2 drink"):
        goal_of("Put five drinks in the fridge.", world)


def test_chilling_means_the_homes_cold_place(world):
    assert goal_of("Chill the milk and the bottle.", world) == \
        ({"fridge": ["bottle", "milk"]}, {"fridge": ["closed"]}, [])
    assert goal_of("Open the fridge and leave it open.", world) == ({}, {"fridge": ["open"]}, [])


def test_exceptions_and_overrides(world):
    # the excepted thing is left alone: where it is, as its world entry writes (benchmarks/README.md)
    assert goal_of("Switch off all the lights except the desk lamp.", world) == \
        ({"desk": ["desklamp"]}, {"desklamp": ["on"], "floorlamp": ["off"], "lightswitch": ["off"]}, [])
    assert goal_of("Put all the fruit in the fridge but not the watermelon.", world) == \
        ({"diningtable": ["watermelon"], "fridge": ["apple"]}, {"fridge": ["closed"]}, [])
    assert goal_of("Switch off the lights but leave the desk lamp on.", world) == \
        ({}, {"desklamp": ["on"], "floorlamp": ["off"], "lightswitch": ["off"]}, [])
    with pytest.raises(TranslationError, match="is not one of"):
        goal_of("Switch off the lights except the TV.", world)
    # a sequence ends in its last state, and says so
    from pipflow.household.language.translator import translate

    out = translate("Open the fridge, take out the milk, put it on the table and close the fridge.", world)
    assert _norm(out["goal"]) == ({"diningtable": ["milk"]}, {"fridge": ["closed"]}, [])
    assert any("comes after 'open the fridge'" in n for n in out["notes"])


def test_state_cues(world):
    assert goal_of("Nobody is watching the TV.", world) == ({}, {"tv": ["off"]}, [])
    assert goal_of("The desk lamp is on and nobody is reading.", world) == ({}, {"desklamp": ["off"]}, [])
    assert goal_of("The TV is on but nobody is watching it.", world) == ({}, {"tv": ["off"]}, [])
    assert goal_of("It is very bright and we do not need light.", world) == \
        ({}, {"desklamp": ["off"], "floorlamp": ["off"], "lightswitch": ["off"]}, [])
    assert goal_of("We don't need the laptop anymore.", world) == ({}, {"laptop": ["off"]}, [])
    # an observation alone asks nothing; a cue with nothing to switch asks which
    with pytest.raises(TranslationError, match="asks for nothing"):
        goal_of("The fridge is open.", world)
    with pytest.raises(TranslationError, match="which thing"):
        goal_of("Nobody is watching.", world)


def test_wanted_states_and_ellipsis(world):
    assert goal_of("Put the apple in the fridge and leave the fridge open.", world) == \
        ({"fridge": ["apple"]}, {"fridge": ["open"]}, [])
    assert goal_of("Make sure the stove is on and the TV is off.", world) == ({}, {"stove": ["on"], "tv": ["off"]}, [])
    assert goal_of("Turn the floor lamp off and the stove on.", world) == ({}, {"floorlamp": ["off"], "stove": ["on"]}, [])
    assert goal_of("Heat the bread and the egg too.", world) == \
        ({}, {"bread": ["hot"], "egg": ["hot"], "fridge": ["closed"]}, [])
    assert goal_of("Put the pen on the desk and the pillow on the bed.", world) == \
        ({"bed": ["pillow"], "desk": ["pen"]}, {}, [])


def test_pronouns_mean_what_the_action_applies_to(world):
    """'close it' after putting the apple in the fridge is the fridge (the apple cannot close);
    'in it' is the place named before; a place nobody named is asked."""
    assert goal_of("Put the apple in the fridge, then close it.", world) == \
        ({"fridge": ["apple"]}, {"fridge": ["closed"]}, [])
    assert goal_of("Open the fridge door and put the apple in it.", world) == ({"fridge": ["apple"]}, {"fridge": ["open"]}, [])
    with pytest.raises(TranslationError, match="which place"):
        goal_of("Put the apple in it.", world)
    assert goal_of("Put the book on the bed and turn off the lamp on the desk.", world) == \
        ({"bed": ["book"]}, {"desklamp": ["off"]}, [])
    assert goal_of("Clean the mug, then the plate.", world) == ({}, {"mug": ["clean"], "plate": ["clean"]}, [])
    # "the door": of the place that opens named last; asked when none or two were named
    assert goal_of("Take the egg out of the fridge, put it on the counter and close the door.", world) == \
        ({"countertop": ["egg"]}, {"fridge": ["closed"]}, [])
    for command in ("Close the door.", "Open the fridge and the cabinet, then close the door."):
        with pytest.raises(TranslationError, match="which door"):
            goal_of(command, world)


def test_never_a_silent_misreading(world):
    """What the home model cannot hold is refused with the words, not read as something near it."""
    for command, words in [("Put the apple next to the fridge.", "next to the fridge"),
                           ("Don't turn off the TV.", "turn off the tv"),
                           ("Heat the egg for 2 minutes.", "'for'"),
                           ("Put the apple or the tomato in the fridge.", "'or'"),
                           ("Put the banana in the fridge.", "'banana'"),
                           ("Put the fork in the sink.", "'fork'")]:   # never read as the word "for"
        with pytest.raises(TranslationError, match=words):
            goal_of(command, world)
    with pytest.raises(TranslationError, match="not on it"):
        goal_of("Put the book on the fridge.", world)
    # signs and fractions are never dropped: "-2" is not 2, "3.5" is no count, 0 asks nothing
    for command, words in [("Put -2 school supplies on the bed.", "'-2'"), ("Put 3.5 dishes in the sink.", "'3.5'"),
                           ("Put 0 school supplies on the bed.", "count of 0")]:
        with pytest.raises(TranslationError, match=words):
            goal_of(command, world)
    with pytest.raises(Refusal, match="mug cannot be sliced"):
        goal_of("Slice the mug.", world)


def test_typos_are_read_and_said(world):
    from pipflow.household.language.translator import translate

    out = translate("Put the tomatoe in the fridgge.", world)
    assert _norm(out["goal"]) == ({"fridge": ["tomato"]}, {"fridge": ["closed"]}, [])
    assert any("'fridgge' as 'fridge'" in n for n in out["notes"])


def test_typos_are_only_read_as_a_near_word_of_one_meaning(world):
    """One edit (two for long words) from one known thing, first letter kept: 'toaster' is not
    'toast' (a verb); 'bred' is as near to 'bed' as to 'bread', so it is not read at all. (A
    toaster this home lacks, asked of, makes the command impossible: lacking.py.)"""
    with pytest.raises(Refusal, match="this home has no toaster"):
        goal_of("Put the bread in the toaster.", world)
    assert goal_of("Slise the bread.", world) == ({}, {"bread": ["sliced"]}, [])
    with pytest.raises(TranslationError, match="'bred' names nothing"):   # bed or bread? not guessed
        goal_of("Slice the bred.", world)


def test_exception_by_state_both_and_a_heater_named_by_pronoun(world):
    assert goal_of("Put all the dishes in the sink, but not the clean ones.", world) == \
        ({"sink": ["mug", "plate"]}, {}, [])
    assert goal_of("Slice both the apple and the tomato.", world) == ({}, {"apple": ["sliced"], "tomato": ["sliced"]}, [])
    assert goal_of("Turn on the stove and heat the potato on it.", world) == \
        ({"stove": ["potato"]}, {"potato": ["hot"], "stove": ["on"]}, [])


def test_explain_names_the_words_of_each_condition(world):
    from pipflow.household.language.translator import translate

    out = translate("Heat the egg in the microwave and nobody is watching the TV.", world)
    assert "egg hot, from 'heat the egg in the microwave'" in out["explain"]
    assert "tv off, from 'nobody is watching the tv'" in out["explain"]


# ------------------------------------------------------------------------------ orders as data
def test_every_reading_validates_against_the_schema(world):
    from pipflow.household.language.order import order_problems
    from pipflow.household.language.parser import parse

    for command in ["Slice the lettuce, trash the mug and switch off the floor lamp.",
                    "Take the milk out of the fridge and put it on the dining table.",
                    "Switch off all the lights except the desk lamp.", "Put a drink on the desk.",
                    "The desk lamp is on and nobody is reading.", "Put the apple in the fridge, the tomato too.",
                    "Make sure the stove is on and the TV is off.", "Put everything from the sofa on the bed."]:
        readings = parse(command, world)
        assert readings
        for order in readings:
            assert order_problems(order) == [], (command, order)


def test_a_malformed_order_is_refused_by_the_resolver(world):
    from pipflow.household.language.order import order_problems
    from pipflow.household.language.resolver import resolve

    bad = {"domain": "household", "statements": [{"op": "change", "things": [], "to": "purple", "words": "x"}]}
    assert len(order_problems(bad)) >= 1
    with pytest.raises(TranslationError, match="invalid household order"):
        resolve(bad, world)


def test_ambiguous_readings_that_differ_are_refused(world):
    """'put everything on the sofa' is a take-from (then where?) or a put-onto; the grammar keeps
    both readings and the translator does not pick one silently."""
    from pipflow.household.language.parser import parse

    assert len(parse("Put everything on the sofa on the bed.", world)) >= 1
    with pytest.raises(TranslationError):
        goal_of("Put everything on the sofa.", world)


# ------------------------------------------------------------------------------ the generalization set
def _set_tasks():
    from pipflow.household.scoring import load_tasks

    out = []
    for path in SETS:
        loaded = load_tasks(path)
        # `expect: refuse` (ambiguous here) is read from the file itself, as benchmarks/translator.py does
        written = {str(t["id"]): t for t in yaml.safe_load(path.read_text(encoding="utf-8"))["tasks"]}
        out += [pytest.param(loaded["world"], {**t, "expect": written[t["id"]].get("expect")},
                             id=f"{path.stem}:{t['id']}:{t.get('construction')}")
                for t in loaded["tasks"]]
    return out


#: clear commands of the probes that the offline reading still refuses, and why (docs/household.md);
#: refused, never misread: when one becomes understood, take it out of here
STILL_REFUSED: dict[str, str] = {}


@pytest.mark.parametrize("w,task", _set_tasks())
def test_generalization_set_is_understood(w, task):
    from pipflow.household.language.translator import translate

    assert task.get("construction"), "every command of the set names its construction"
    if task["feasible"] is False:
        with pytest.raises(Refusal):
            translate(task["command"], w)
        return
    if task["expect"] == "refuse" or task["id"] in STILL_REFUSED:   # asked back, never a goal
        with pytest.raises(TranslationError):
            translate(task["command"], w)
        return
    assert _norm(translate(task["command"], w)["goal"]) == _norm(task["goal"])


def _held_out_tasks():
    """Every task of the household sets of benchmarks/language/ that are not in SETS (the held-out
    sets: cottage, farmhouse, fresh4, houseboat, and any added later), as (set, world, task)."""
    from pipflow.household.scoring import load_tasks

    out = []
    for path in sorted(LANGUAGE.glob("household*.yaml")):
        written = yaml.safe_load(path.read_text(encoding="utf-8"))
        if path in SETS or "tasks" not in (written or {}):
            continue
        loaded = load_tasks(path)   # the data check: the world loads, every name of a gold exists
        expect = {str(t["id"]): t.get("expect") for t in written["tasks"]}
        out += [pytest.param(loaded["world"], {**t, "expect": expect[t["id"]]}, id=f"{path.stem}:{t['id']}")
                for t in loaded["tasks"]]
    return out


@pytest.mark.parametrize("w,task", _held_out_tasks())
def test_held_out_sets_are_never_misread(w, task):
    """The held-out sets are measured, not fitted: a refusal is allowed (it is counted by
    benchmarks/translator.py), a goal other than the gold never is, and a command whose right
    answer is a refusal is never given a goal (one impossible only for its team has its literal
    goal written, and may be read as that)."""
    from pipflow.household.language.translator import translate

    # a held-out set's author may not see the construction labels (they would read the other
    # sets to learn them): the paper's category is required, a construction label is not
    assert task.get("category") in ("compound", "complex", "vague")
    try:
        got = translate(task["command"], w)
    except (TranslationError, Refusal):
        return
    assert task["expect"] != "refuse", f"{task['id']}: {got['goal']}"
    # impossible for its team, not in its words ("You two, warm the kippers" for a pair that can
    # only lift): the gold writes the literal goal for the allocator to refuse, as in the warehouse
    assert task["feasible"] is not False or task.get("goal"), f"{task['id']}: {got['goal']}"
    assert _norm(got["goal"]) == _norm(task["goal"])


def test_generalization_set_covers_every_construction():
    from pipflow.household.scoring import load_tasks

    tasks = [t for p in SETS for t in load_tasks(p)["tasks"]]
    assert len(tasks) >= 50
    have = {t["construction"] for t in tasks}
    assert {"clauses", "coordination", "gapping", "pronoun", "toggle", "open-close", "wanted-state", "via",
            "state-selection", "place-selection", "category", "count", "put-away", "trash", "exception",
            "cue-activity", "cue-observation", "cue-need", "cue-light", "typo", "impossible"} <= have


# ------------------------------------------------------------------------------ issue 12 probe causes
# A cottage whose things have names no benchmark uses, so that these tests check the general
# rules (meals, gerunds, politeness, cues, negated wishes, "everything that is on", a heated thing
# moved on), not the benchmark's words.
COTTAGE = """
domain: household
name: cottage
floor: {width: 6, height: 5}
categories:
  greens: {words: [greens]}
  crocks: {words: [crocks, crockery], home: dresser}
  lamps: {words: [lamp, lamps, light, lights]}
  snacks: {words: [snack, snacks]}
  orchard: {words: [fruit]}
places:
  coolbox:   {x: 0.2, y: 4.0, width: 0.8, depth: 0.8, access: [0.6, 3.5], properties: [receptacle, openable], state: {open: false}}
  bench:     {x: 1.4, y: 4.2, width: 1.5, depth: 0.6, access: [2.1, 3.6], properties: [receptacle], words: [worktop]}
  hob:       {x: 3.2, y: 4.2, width: 0.7, depth: 0.6, access: [3.5, 3.6], properties: [receptacle, heater, toggleable], state: {on: false}}
  range:     {x: 4.2, y: 4.2, width: 0.7, depth: 0.6, access: [4.5, 3.6], properties: [receptacle, heater, openable], state: {open: false}}
  basin:     {x: 0.2, y: 2.0, width: 0.7, depth: 0.7, access: [1.2, 2.3], properties: [receptacle, sink]}
  dresser:   {x: 0.2, y: 0.2, width: 1.0, depth: 0.5, access: [0.7, 1.0], properties: [receptacle, openable], state: {open: false}}
  sideboard: {x: 2.5, y: 0.2, width: 1.2, depth: 0.5, access: [3.1, 1.0], properties: [receptacle]}
  bucket:    {x: 4.5, y: 0.2, width: 0.4, depth: 0.4, access: [4.7, 1.0], properties: [garbage]}
  wireless:  {x: 5.3, y: 2.5, width: 0.3, depth: 0.3, access: [5.0, 2.6], properties: [toggleable], state: {on: true}, words: [radio]}
objects:
  spinach:  {in: bench, mass: 1, properties: [pickupable, sliceable], categories: [greens]}
  cucumber: {in: bench, mass: 1, properties: [pickupable, sliceable], categories: [greens]}
  beetroot: {in: bench, mass: 1, properties: [pickupable, sliceable, heatable]}
  sausage:  {in: coolbox, mass: 1, properties: [pickupable, heatable], categories: [snacks]}
  bagel:    {in: sideboard, mass: 1, properties: [pickupable, sliceable, heatable], categories: [snacks]}
  kiwi:     {in: sideboard, mass: 1, properties: [pickupable, sliceable], categories: [snacks, orchard]}
  saucepan: {in: hob, mass: 1, properties: [pickupable, washable], state: {dirty: true}}
  tumbler:  {in: sideboard, mass: 1, properties: [pickupable, washable], state: {dirty: true}, categories: [crocks]}
  beaker:   {in: sideboard, mass: 1, properties: [pickupable, washable], categories: [crocks]}
  tablet:   {in: sideboard, mass: 1, properties: [pickupable, toggleable], state: {on: true}}
  lantern:  {in: sideboard, mass: 1, properties: [pickupable, toggleable], state: {on: true}, categories: [lamps]}
  almanac:  {in: bench, mass: 1, properties: [pickupable]}
robots:
  pip: {start: [2.5, 2.5], skills: {pickup: 1, open: 1, toggle: 1, slice: 1, wash: 1, heat: 1}}
teams:
  solo: [pip]
"""


def _cottage(tmp_path_factory, text: str = COTTAGE) -> dict:
    from pipflow.household.world import load_world

    path = tmp_path_factory.mktemp("cottage") / "world.yaml"
    path.write_text(text, encoding="utf-8")
    return load_world(path)


@pytest.fixture(scope="module")
def cottage(tmp_path_factory):
    return _cottage(tmp_path_factory)


def test_meals_read_through_the_lexicon_and_the_homes_affordances(cottage, tmp_path_factory):
    """'make a salad': the home's salad foods sliced (spinach, cucumber; beetroot is no salad
    food of the lexicon); 'breakfast': its breakfast foods hot (the sausage comes out of the
    coolbox, which is closed again). Without a salad base the meal is refused, never guessed."""
    assert goal_of("Whip up a salad, please.", cottage) == ({}, {"cucumber": ["sliced"], "spinach": ["sliced"]}, [])
    assert goal_of("Fix us some breakfast.", cottage) == \
        ({}, {"bagel": ["hot"], "sausage": ["hot"], "coolbox": ["closed"]}, [])
    assert goal_of("Make a fruit salad.", cottage) == ({}, {"kiwi": ["sliced"]}, [])
    assert goal_of("Cook breakfast.", cottage) == ({}, {"bagel": ["hot"], "sausage": ["hot"], "coolbox": ["closed"]}, [])
    with pytest.raises(TranslationError, match="not made by 'heat'"):   # a verb that contradicts the meal
        goal_of("Heat a salad.", cottage)
    with pytest.raises(TranslationError):   # a meal of no lexicon is unknown words, quoted
        goal_of("Make a sandwich.", cottage)
    no_greens = COTTAGE.replace("  spinach:  {in: bench, mass: 1, properties: [pickupable, sliceable], categories: [greens]}\n", "")
    with pytest.raises(Refusal, match="no lettuce"):
        goal_of("Make a salad.", _cottage(tmp_path_factory, no_greens))
    # a home that says what its salad is: its own category wins over the lexicon
    own = COTTAGE.replace("  greens: {words: [greens]}", "  greens: {words: [greens, salad]}")
    assert goal_of("Prepare a salad.", _cottage(tmp_path_factory, own)) == \
        ({}, {"cucumber": ["sliced"], "spinach": ["sliced"]}, [])
    # a world object called like a meal is still that object where the sentence names a thing
    dish = COTTAGE.replace("  almanac:", "  salad:    {in: coolbox, mass: 1, properties: [pickupable]}\n  almanac:")
    assert goal_of("Put the salad on the sideboard.", _cottage(tmp_path_factory, dish)) == \
        ({"sideboard": ["salad"]}, {"coolbox": ["closed"]}, [])


def test_gerunds_and_politeness(cottage):
    assert goal_of("Would you mind putting the almanac on the sideboard? Thanks!", cottage) == \
        ({"sideboard": ["almanac"]}, {}, [])
    assert goal_of("The tumbler needs washing.", cottage) == ({}, {"tumbler": ["clean"]}, [])
    assert goal_of("The wireless needs switching off.", cottage) == ({}, {"wireless": ["off"]}, [])
    assert goal_of("Plese turn of the wireless.", cottage) == ({}, {"wireless": ["off"]}, [])
    assert goal_of("Warm up some sausage.", cottage) == ({}, {"sausage": ["hot"], "coolbox": ["closed"]}, [])
    # 'washing' is a word of its own now, never a misspelt 'watching' (a cue that switches off)
    with pytest.raises(TranslationError):
        goal_of("Nobody is washing the tablet.", cottage)
    # 'some' of a kind does not say how many: asked, never all of them
    with pytest.raises(TranslationError, match="how many"):
        goal_of("Put some snacks in the coolbox.", cottage)


def test_cues_of_need(cottage):
    assert goal_of("Nobody needs the tablet anymore.", cottage) == ({}, {"tablet": ["off"]}, [])
    assert goal_of("I'm done with the radio.", cottage) == ({}, {"wireless": ["off"]}, [])
    assert goal_of("We are finished with the lantern, turn it off.", cottage) == ({}, {"lantern": ["off"]}, [])
    with pytest.raises(Refusal, match="cannot be off"):
        goal_of("We're done with the almanac.", cottage)


def test_negated_wishes_ask_for_the_other_polarity(cottage):
    assert goal_of("Don't leave the coolbox open.", cottage) == ({}, {"coolbox": ["closed"]}, [])
    assert goal_of("The wireless shouldn't be on.", cottage) == ({}, {"wireless": ["off"]}, [])
    assert goal_of("Make sure the hob is not on and the dresser is closed.", cottage) == \
        ({}, {"hob": ["off"], "dresser": ["closed"]}, [])
    assert goal_of("Don't leave the tumbler dirty.", cottage) == ({}, {"tumbler": ["clean"]}, [])


def test_everything_in_a_state(cottage):
    assert goal_of("Switch off everything that is on.", cottage) == \
        ({}, {"lantern": ["off"], "tablet": ["off"], "wireless": ["off"]}, [])
    assert goal_of("Put everything that is dirty in the basin.", cottage) == ({"basin": ["saucepan", "tumbler"]}, {}, [])
    with pytest.raises(TranslationError, match="needs a place or a state"):   # only on/off read "everything" alone
        goal_of("Open everything.", cottage)


def test_a_thing_heated_somewhere_then_moved_ends_where_it_is_moved(cottage):
    """'heat X in P, then bring it to Q': X hot in Q, and P (which opens) left closed; a thing put
    in two places by two moves is still asked."""
    assert goal_of("Heat the bagel in the range, then bring it to the bench.", cottage) == \
        ({"bench": ["bagel"]}, {"bagel": ["hot"], "range": ["closed"]}, [])
    assert goal_of("Heat the sausage on the hob and put it on the sideboard.", cottage) == \
        ({"sideboard": ["sausage"]}, {"sausage": ["hot"], "coolbox": ["closed"]}, [])
    with pytest.raises(TranslationError, match="both in"):
        goal_of("Put the bagel on the bench and put it on the sideboard.", cottage)


def test_probe_b_causes(cottage):
    """The second probe's causes, in general: an action noun ("give it a scrub"), "shut down", an
    observation answered by the action on its thing, "'s" before a state word, "away in P", a
    shared move ("out of P and onto Q"), "can go off", "let's", and pieces of a kind."""
    assert goal_of("Give the tumbler a good scrub.", cottage) == ({}, {"tumbler": ["clean"]}, [])
    with pytest.raises(Refusal, match="not washable"):
        goal_of("Give the wireless a wash.", cottage)
    assert goal_of("Shut down the tablet.", cottage) == ({}, {"tablet": ["off"]}, [])
    assert goal_of("The saucepan's dirty, wash it.", cottage) == ({}, {"saucepan": ["clean"]}, [])
    with pytest.raises(TranslationError, match="asks for nothing"):   # an observation nothing answers
        goal_of("The wireless is on, put the almanac on the bench.", cottage)
    assert goal_of("Put the almanac away in the dresser.", cottage) == ({"dresser": ["almanac"]}, {"dresser": ["closed"]}, [])
    assert goal_of("Get the sausage out of the coolbox and onto the bench.", cottage) == \
        ({"bench": ["sausage"]}, {"coolbox": ["closed"]}, [])
    with pytest.raises(TranslationError, match="asks for nothing"):   # the tablet's state is not answered
        goal_of("The tablet is on and the lantern can go off too.", cottage)
    assert goal_of("The lantern can go off.", cottage) == ({}, {"lantern": ["off"]}, [])
    assert goal_of("Let's turn off the tablet.", cottage) == ({}, {"tablet": ["off"]}, [])
    assert goal_of("Put a piece of fruit in the basin.", cottage) == ({}, {}, [("orchard", "basin", 1)])
    with pytest.raises(TranslationError, match="pieces of one thing"):
        goal_of("Put a piece of bagel on the bench.", cottage)
    with pytest.raises(TranslationError):   # a volume is no state of the home model
        goal_of("Turn the wireless down.", cottage)


def test_probe_c_causes(cottage):
    """The third probe's causes, in general: "'ve", "don't forget to", a clause done first ("once
    you've washed X, ..."), "both" after two clauses, "a B of A" for an "A B" name, "X goes in P",
    a finished activity as a cue, a reason that asks nothing by itself."""
    assert goal_of("Once you've washed the tumbler, put it in the dresser.", cottage) == \
        ({"dresser": ["tumbler"]}, {"tumbler": ["clean"], "dresser": ["closed"]}, [])
    assert goal_of("Don't forget to close the coolbox.", cottage) == ({}, {"coolbox": ["closed"]}, [])
    assert goal_of("Heat up the sausage and slice the kiwi, then put both on the bench.", cottage) == \
        ({"bench": ["kiwi", "sausage"]}, {"sausage": ["hot"], "kiwi": ["sliced"], "coolbox": ["closed"]}, [])
    with pytest.raises(TranslationError, match="which two"):
        goal_of("Slice the kiwi, the bagel and the beetroot, then put both on the bench.", cottage)
    assert goal_of("The saucepan goes on the sideboard.", cottage) == ({"sideboard": ["saucepan"]}, {}, [])
    assert goal_of("The tablet should be in the dresser.", cottage) == ({"dresser": ["tablet"]}, {"dresser": ["closed"]}, [])
    assert goal_of("We've finished listening, you can switch off the wireless.", cottage) == ({}, {"wireless": ["off"]}, [])
    assert goal_of("It's getting late, turn off the lantern.", cottage) == ({}, {"lantern": ["off"]}, [])
    with pytest.raises(TranslationError, match="asks for nothing"):
        goal_of("It's late.", cottage)
    # conditions on the home stay refused: "once the tablet is off" is not a clause done first
    with pytest.raises(TranslationError):
        goal_of("Once the tablet is off, put it on the bench.", cottage)
    with pytest.raises(TranslationError):   # "you can not" is no permission
        goal_of("You can not turn off the wireless.", cottage)


def test_a_two_word_name_inverted_with_of(tmp_path_factory):
    """"water jug" is also "a jug of water"; the inversion names only that thing."""
    text = COTTAGE.replace("  almanac:  {in: bench, mass: 1, properties: [pickupable]}",
                           "  almanac:  {in: bench, mass: 1, properties: [pickupable]}\n"
                           "  jug:      {in: bench, mass: 1, properties: [pickupable], words: [water jug]}")
    home = _cottage(tmp_path_factory, text)
    assert goal_of("Put the jug of water in the coolbox.", home) == ({"coolbox": ["jug"]}, {"coolbox": ["closed"]}, [])
    assert goal_of("Put the jugs of water on the sideboard.", home) == ({"sideboard": ["jug"]}, {}, [])
    with pytest.raises(TranslationError):
        goal_of("Put the jug of milk in the coolbox.", home)


def test_probe_d_causes(cottage):
    """Probe D (held out) refused three clear commands for general reasons fixed after it: "tidy X
    away", "turn everything off" (every thing that switches; other states still ask for a place or
    state), and a "but not X" of a thing the clause did not name (a reminder: nothing is done to X;
    an exception inside a selector of something not in it is still asked)."""
    assert goal_of("Tidy the crocks away.", cottage) == ({"dresser": ["beaker", "tumbler"]}, {"dresser": ["closed"]}, [])
    assert goal_of("Turn everything off.", cottage) == \
        ({}, {"lantern": ["off"], "tablet": ["off"], "wireless": ["off"], "hob": ["off"]}, [])
    with pytest.raises(TranslationError, match="needs a place or a state"):
        goal_of("Wash everything.", cottage)
    got = goal_of("Wash the tumbler, but not the saucepan.", cottage)
    # nothing is done to the saucepan: it is left alone where it is (benchmarks/README.md)
    assert got[0] == {"hob": ["saucepan"]} and got[1]["tumbler"] == ["clean"] and "clean" not in got[1].get("saucepan", [])
    with pytest.raises(TranslationError, match="is not one of"):
        goal_of("Switch off the lamps except the tablet.", cottage)


# ------------------------------------------------------------------------------ property test
VERB = {"sliced": ["slice", "cut", "chop"], "clean": ["wash", "rinse", "scrub"], "hot": ["heat", "warm up"],
        "on": ["turn on", "switch on"], "off": ["turn off", "switch off"], "open": ["open"], "closed": ["close", "shut"]}
PREP = ["in", "on", "into"]


def _statement(world: dict):
    """A random statement over the world's names, as (english, apply(goal))."""
    from pipflow.household.problem import CONDITIONS

    objects, places = world["objects"], world["places"]
    changes = [(n, c) for c in VERB for n, e in {**objects, **places}.items() if CONDITIONS[c][2] in e["properties"]]
    targets = sorted(p for p, e in places.items() if "receptacle" in e["properties"] and "openable" not in e["properties"])
    movable = sorted(n for n, e in objects.items() if "pickupable" in e["properties"])
    change = st.tuples(st.sampled_from(sorted(changes)), st.integers(0, 2)).map(
        lambda t: (f"{VERB[t[0][1]][t[1] % len(VERB[t[0][1]])]} the {t[0][0]}", ("state", t[0][0], t[0][1])))
    put = st.tuples(st.sampled_from(movable), st.sampled_from(targets), st.sampled_from(PREP)).map(
        lambda t: (f"put the {t[0]} {t[2]} the {t[1]}", ("in", t[0], t[1])))
    return st.one_of(change, put)


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(data=st.data())
def test_random_orders_read_back(world, data):
    """Random orders (a few statements over distinct things), rendered to English with varying
    verbs, prepositions and joiners, parse back to the same goal."""
    from pipflow.household.language.translator import _leave_closed

    picked = data.draw(st.lists(_statement(world), min_size=1, max_size=3, unique_by=lambda s: s[1][1]))
    joiners = [data.draw(st.sampled_from([", ", " and ", ", then ", ". "])) for _ in picked[1:]]
    text = picked[0][0]
    for j, (words, _) in zip(joiners, picked[1:]):
        text += j + (words[0].upper() + words[1:] if j == ". " else words)
    text = text[0].upper() + text[1:] + "."
    goal: dict = {"in": {}, "state": {}}
    for _, (kind, name, value) in picked:
        if kind == "in":
            goal["in"].setdefault(value, []).append(name)
        else:
            goal["state"].setdefault(name, []).append(value)
    _leave_closed(world, goal)
    assert goal_of(text, world) == _norm(goal), text


# ------------------------------------------------------------------------------ scoring
def test_scorer_honours_infeasible_tasks(world):
    from pipflow.household.domain import HouseholdDomain

    score_run = HouseholdDomain().score

    ok = score_run(world, {}, feasible=False, refusal="mug cannot be hot: it is not heatable")
    assert ok["success"] and ok["gcr"] == 1.0 and ok["violations"] == []
    silent = score_run(world, {}, feasible=False, error="the planner timed out")
    assert not silent["success"] and silent["violations"] == ["infeasible command was not refused"]
    moved = score_run(world, {}, feasible=False, refusal="x", schedule={"subtasks": [{"id": "s1"}]},
                      simulation={"executed": 1, "exe": 1.0})
    assert not moved["success"] and moved["violations"] == ["actions were executed"]
    feasible = score_run(world, {"in": {"fridge": ["apple"]}, "state": {}}, refusal="no")
    assert not feasible["success"]


def test_benchmark_split_and_infeasible_tasks_load():
    from pipflow.household.scoring import load_tasks

    tasks = load_tasks(ROOT / "benchmarks" / "household" / "tasks.yaml")["tasks"]
    cats = [t["category"] for t in tasks]
    assert (cats.count("compound"), cats.count("complex"), cats.count("vague")) == (41, 23, 25)
    assert {t["id"] for t in tasks if t["feasible"] is False} == {"hx-23", "hv-25"}


# ------------------------------------------------------------------------------ end to end
def test_heating_in_the_microwave_runs_end_to_end(tmp_path):
    """The once-refused command runs with a team where no robot can do it alone: lifters carry,
    the handler opens and closes, the cook heats; the executor's final state meets the goal."""
    from pipflow.engine.runner import run_workflow

    result = run_workflow(str(ROOT / "workflows" / "household.yaml"),
                          {"command": "Heat the egg in the microwave.", "team": "lifters-handler-cook"},
                          runs_dir=tmp_path, inputs_from_text=True)
    assert result.status == "succeeded", result.error
    out = result.outputs
    assert out["goal"] == {"in": {"microwave": ["egg"]}, "state": {"egg": ["hot"], "fridge": ["closed"],
                                                                   "microwave": ["closed"]}}
    assert out["goal_met"] is True and out["exe"] == 1.0
    by = {a["subtask"]: a["robots"] for a in out["allocation"]["assignments"]}
    heat = [n["id"] for n in out["graph"]["nodes"] if n["action"] == "heat"]
    assert heat and by[heat[0]] == ["robot7"]


def test_bench_understanding_of_household_runs():
    """What `pipflow bench` reports per run: understood when the run's goal is the gold (lists as
    sets) or a refusal was right; misread when a run executed another goal."""
    from pipflow.household.domain import HouseholdDomain

    understanding = HouseholdDomain().understand  # no world: goals and rules compared as written

    task = {"goal": {"in": {"fridge": ["apple", "tomato"]}, "state": {"fridge": ["closed"]}}}
    same = {"goal": {"in": {"fridge": ["tomato", "apple"]}, "state": {"fridge": ["closed"]}, "count": []}}
    assert understanding(task, same, "succeeded", None)["understood"] is True
    other = {"goal": {"in": {"fridge": ["apple"]}, "state": {"fridge": ["closed"]}}}
    wrong = understanding(task, other, "succeeded", None)
    assert wrong["understood"] is False and wrong["misread"] is True
    refused = understanding(task, {}, "failed", "TranslationError")
    assert refused["understood"] is False and refused["misread"] is False
    infeasible = {"feasible": False}
    assert understanding(infeasible, {}, "refused", "Refusal")["understood"] is True
    assert understanding(infeasible, other, "succeeded", None)["misread"] is True

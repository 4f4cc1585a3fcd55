"""Issue 23, from pair QQ's household set (a mother in Singapore messaging the house robots): "the
bedside one" and "dad one" for a thing of the kind said before, the thing in someone's room ("the
lamp in nan's room", "the light in our bedroom"), "bring in X" (indoors), "off our light", and a
thing named before its verb after a step said without "and". Through the real household reader,
in the studio flat with a few words of our own added."""
from __future__ import annotations

import copy

import pytest

from pipflow.errors import TranslationError
from pipflow.household.language.translator import translate
from tests.studio_world import STUDIO

HOME = copy.deepcopy(STUDIO)
HOME["objects"]["teacup"]["words"] = list(HOME["objects"]["teacup"]["words"]) + ["dad's cup"]
HOME["places"]["overhead_light"]["words"] = list(HOME["places"]["overhead_light"]["words"]) + [
    "our light", "bedroom light"]
HOME["objects"]["reading_light"]["words"] = list(HOME["objects"]["reading_light"]["words"]) + ["nan's lamp"]


def _goal(said: str) -> dict:
    return translate(said, HOME)["goal"]


#: what is said, and the plain English it reads as
SAID_AS = [
    # "the <words> one": the words with the kind said before name one thing
    ("put the cup on the low table and the glass on the bedside one",
     "put the cup on the low table and the glass on the bedside table"),
    # "<owner> one" closing a clause says whose the thing just named is
    ("wash the cup, dad one", "wash dad's cup"),
    ("the cup there also wash, dad one", "wash the teacup"),
    # the thing in someone's room: the owner's thing, the room's word in another of its names
    ("switch off the lamp in nan's room", "switch off the reading lamp"),
    ("switch off the lamp in nan room", "switch off the reading lamp"),
    ("switch off the light in our bedroom", "switch off the main light"),
    ("off our light", "switch off the main light"),
    # "bring in" (indoors) before a thing
    ("bring in the scarf from the low table, put in the closet", "put the scarf in the closet"),
    # a thing named before its verb after a step said without "and"
    ("take the juice out of the fridge put on the counter, then the scarf keep in the closet",
     "take the juice out of the fridge and put it on the counter, then put the scarf in the closet"),
]


@pytest.mark.parametrize("said, plain", SAID_AS)
def test_said_as_plain_english(said: str, plain: str) -> None:
    assert _goal(said) == _goal(plain)


@pytest.mark.parametrize("said", [
    # "bedside light" is no name of this home: which one is not guessed
    "switch on the main light, then off the bedside one",
    # "dad glass" is no name: the glass is not dad's by this home's words
    "wash the glass, dad one",
    # the apposition is of the name said last (the low table), never of a thing further back
    "put the saucer and the cup on the low table, dad one",
    # "kitchen" is in none of the main light's names: not read as "our light"
    "switch off the light in our kitchen",
    # whose room is not said
    "switch off the lamp in their room",
    "the other one wash",
])
def test_not_read_where_the_homes_words_do_not_decide(said: str) -> None:
    with pytest.raises(TranslationError):
        translate(said, HOME)


def test_bring_in_still_asks_where_to() -> None:
    """ "bring in the scarf": indoors is no place of the home model; where to is asked."""
    with pytest.raises(TranslationError, match="where to"):
        translate("bring in the scarf", HOME)


def test_two_kinds_said_before_that_each_name_a_thing_are_asked() -> None:
    """ "the small one" where both a small glass and a small cup are things of the home: which kind
    "one" stands for is not guessed."""
    home = copy.deepcopy(HOME)
    home["objects"]["glass"]["words"] = list(home["objects"]["glass"]["words"]) + ["small glass"]
    home["objects"]["saucer"]["words"] = ["small cup"]
    with pytest.raises(TranslationError):
        translate("put the drinking glass and the tea cup in the sink, and the small one too", home)
    assert translate("put the tea cup in the sink, and the small one too", home)["goal"]["in"] == {
        "basin": ["teacup", "saucer"]}


#: a home whose words name its people: "kai's bed", "kai's ball", "mum's mug", "mum's bed"
FAMILY = copy.deepcopy(STUDIO)
FAMILY["places"]["armchair"]["words"] = list(FAMILY["places"]["armchair"]["words"]) + ["kai's bed"]
FAMILY["places"]["nightstand"]["words"] = list(FAMILY["places"]["nightstand"]["words"]) + ["mum's bed"]
FAMILY["objects"]["teacup"]["words"] = list(FAMILY["objects"]["teacup"]["words"]) + ["mum's mug"]
FAMILY["objects"]["scarf"]["words"] = list(FAMILY["objects"]["scarf"]["words"]) + ["kai's scarf"]


@pytest.mark.parametrize("said, plain", [
    # the "'s" typed without its apostrophe
    ("wash mums mug", "wash the teacup"),
    # "his" / "her": the one person named before who owns such a thing
    ("put kais scarf on his bed", "put the scarf on the armchair"),
    ("wash mums mug and put the scarf on her bed", "wash the teacup and put the scarf on the bedside table"),
    # talk about a person, with a span of time, or "he" / "she" opening a clause without a comma
    ("wash the teacup, shes up from night shift in like 10 min", "wash the teacup"),
    ("switch the radio off hes asleep", "switch the radio off"),
    # what it is for, after whose: a meal, or a word that names nothing of the home
    ("wash the teacup for mums lunch pls", "wash the teacup"),
])
def test_the_homes_people_as_a_teenager_texts_them(said: str, plain: str) -> None:
    assert translate(said, FAMILY)["goal"] == translate(plain, FAMILY)["goal"]


@pytest.mark.parametrize("said", [
    # two people named before who both have a bed: whose is not guessed
    "put kais scarf and mums mug on his bed",
    # no one named before: "his bed" is no thing of this home
    "put the scarf on his bed",
    # a count of things in talk about a person keeps it in, unread
    "wash the teacup, shes bringing 2 glasses",
    # "for kais scarf" names a thing of the home: never set aside as what it is for
    "wash the teacup for kais scarf",
])
def test_whose_it_is_is_not_guessed(said: str) -> None:
    with pytest.raises(TranslationError):
        translate(said, FAMILY)


def test_a_cue_felt_in_my_room_is_what_the_home_calls_mine() -> None:
    """ "so hot in our room": the fan the home calls "our fan"; where nothing that answers the cue
    is called ours, the home's other fans are never taken for it (refused, naming them)."""
    home = copy.deepcopy(STUDIO)
    home["places"]["desk_fan"] = {"x": 1.0, "y": 1.0, "width": 0.3, "depth": 0.3, "access": [1.2, 1.6],
                                  "properties": ["toggleable"], "state": {"on": False}, "categories": ["fan"],
                                  "words": ["our fan"]}
    home["places"]["hall_fan"] = {"x": 3.0, "y": 1.0, "width": 0.3, "depth": 0.3, "access": [3.2, 1.6],
                                  "properties": ["toggleable"], "state": {"on": False}, "categories": ["fan"],
                                  "words": ["hall fan"]}
    home.setdefault("categories", {})["fan"] = {"words": ["fan", "fans"], "home": None}
    assert translate("so hot in our room", home)["goal"]["state"] == {"desk_fan": ["on"]}
    home["places"]["desk_fan"]["words"] = ["desk fan"]
    with pytest.raises(TranslationError, match="our"):
        translate("so hot in our room", home)


def test_a_thing_left_out_of_a_selection_is_left_alone() -> None:
    """ "all the clothes except the scarf": the scarf is listed where it is, as "don't touch it"
    lists a thing (benchmarks/README.md); a fixture that switches is held in its state now."""
    goal = translate("put all the clothes in the closet except the scarf", HOME)["goal"]
    assert goal["in"] == {"wardrobe": ["sweater"], "coffee_table": ["scarf"]}
    goal = translate("switch off all the lights except the main light", HOME)["goal"]
    assert goal["state"]["overhead_light"] == ["on"] and goal["state"]["reading_light"] == ["off"]
    # asked of it elsewhere in the command: that is what it ends as
    goal = translate("put all the clothes in the closet except the scarf, and put the scarf on the chair", HOME)["goal"]
    assert goal["in"]["armchair"] == ["scarf"]

"""Issue 23, point 1: content-free parts of a command are set aside, not parsed, and said aloud;
operative words (negation, only/except, bounds, quantities, a number) are never set aside, even
misspelt. Through the real readers of both domains (warehouse and household)."""
from __future__ import annotations

from pathlib import Path

import pytest
import yaml

from pipflow.errors import TranslationError
from pipflow.household.language.translator import translate as household
from pipflow.household.world import load_world as load_home
from pipflow.language.asides import content_free, near_operative
from pipflow.warehouse.language.translator import understand

ROOT = Path(__file__).resolve().parent.parent
PAPER = yaml.safe_load((ROOT / "benchmarks" / "warehouse" / "world.yaml").read_text())
STUDIO = load_home(ROOT / "benchmarks" / "language" / "household-studio-world.yaml")
# paper stock: shelf1 {p1 10, p2 2, p3 3}, shelf2 {p1 8, p2 5, p3 6, p4 2}


@pytest.mark.parametrize("command, aside", [
    ("Morning all, shelf2 needs 3 more product1", "Morning all"),
    ("Hi team! Shelf2 needs 3 more product1", "Hi team"),
    ("Shelf2 needs 3 more product1. Cheers", "Cheers"),
    ("I'm off out, shelf2 needs 3 more product1", "Im off out"),
    ("Shelf2 needs 3 more product1, thanks so much", "thanks so much"),
    # "for" is a function word, no misspelt "four": a reason with it is still talk
    ("Shelf2 needs 3 more product1. She is booked for the lorry.", "She is booked for the lorry"),
    # a thanks closing the order without a comma
    ("Shelf2 needs 3 more product1 ta", "ta"),
    ("Shelf2 needs 3 more product1 cheers!", "cheers"),
    ("Shelf2 needs 3 more product1, it's for the van", "it is for the van"),
])
def test_warehouse_talk_is_set_aside_and_said(command: str, aside: str) -> None:
    got = understand(command, PAPER)
    assert got["goal"] == {"shelf2": {"product1": 11}}
    assert got["order"]["set_aside"] == [aside]
    assert any("set aside" in line and aside in line for line in got["explanation"])


@pytest.mark.parametrize("tail", [
    "not shelf3",            # negation naming a place: content anyway
    "no more than that",     # a bound with no name and no number
    "except",                # exclusivity alone
    "5",                     # a bare number
    "nto that",              # a misspelt negation
    "olny",                  # a misspelt "only"
    "all of it",             # a quantity
    "and the prodcut",       # a misspelt name is never talk
])
def test_warehouse_operative_clauses_are_never_set_aside(tail: str) -> None:
    with pytest.raises(TranslationError):
        understand(f"Move 2 product1 from shelf1 to shelf2, {tail}", PAPER)


def test_a_content_clause_still_needs_every_word() -> None:
    """Only a clause with no content is set aside; a stray word inside a clause that names
    something still sinks the command."""
    with pytest.raises(TranslationError, match="blorp"):
        understand("Morning all, shelf2 needs 3 more blorp product1", PAPER)


def test_household_talk_is_set_aside_and_said() -> None:
    got = household("Toss the orange in the recycling, it's seen better days", STUDIO)
    assert got["goal"]["in"] == {"recycling": ["orange"]}
    assert got["order"]["set_aside"] == ["it is seen better days"]
    assert "set aside" in got["explain"][-1]
    got = household("Morning! I'm off out, turn the radio off", STUDIO)
    assert got["goal"]["state"] == {"radio": ["off"]}
    assert got["order"]["set_aside"] == ["morning", "i am off out"]


@pytest.mark.parametrize("tail", ["not the pantry", "except", "then the rest", "2", "olny"])
def test_household_operative_clauses_are_never_set_aside(tail: str) -> None:
    with pytest.raises(TranslationError):
        household(f"Put the banana in the icebox, {tail}", STUDIO)


def test_household_a_misspelt_name_after_a_move_is_read_never_set_aside() -> None:
    """ "..., and the oragne" names a thing (misspelt): it goes where the move puts the banana
    ("put X in P along with Y"), it is never set aside."""
    got = household("Put the banana in the icebox, and the oragne", STUDIO)
    assert sorted(got["goal"]["in"]["icebox"]) == ["banana", "orange"]
    assert "set_aside" not in got["order"]


def test_operative_words_by_definition() -> None:
    never = lambda w: False  # noqa: E731 - a domain that knows no word
    for clause in (["not"], ["never"], ["only"], ["except"], ["no", "more", "than"], ["at", "least"],
                   ["all"], ["both"], ["half"], ["the", "rest"], ["too"], ["nto"], ["exept"]):
        assert not content_free(clause, never), clause
    for clause in (["it", "is", "broken"], ["cheers"], ["morning", "all"], ["hi", "everyone"]):
        assert content_free(clause, never), clause
    assert not near_operative("gone") and not near_operative("out")  # far keys: no slip of "none", "but"


# -- issue 23, point 3: robot groups from the world ----------------------------------------------
FOODBANK = yaml.safe_load((ROOT / "benchmarks" / "language" / "foodbank.yaml").read_text())
TUGS = ["tug1", "tug2", "tug3", "tug4"]


def _never(rules: list[dict]) -> set[str]:
    return {r for rule in rules if "never" in rule for r in rule["never"]}


@pytest.mark.parametrize("command", [
    "Move 2 rice sacks from aisle 1 to cooler, no tugs",
    "No tug may carry rice sacks. Move 2 rice sacks from aisle 1 to cooler",
])
def test_a_name_stem_plural_is_that_group_never_every_robot(command: str) -> None:
    """ "tugs" where robots are tug1..tug4 (no kind declared) means those four: it was read as
    "robots", so "no tugs" forbade every robot (a misreading)."""
    got = understand(command, FOODBANK)
    assert _never(got["constraints"]) == set(TUGS)


@pytest.mark.parametrize("command", [
    "Move 2 rice sacks from aisle 1 to cooler, tugs only",
    "Move 2 rice sacks from aisle 1 to cooler, only the tugs",
    "Only tugs may move rice sacks. Move 2 rice sacks from aisle 1 to cooler",
])
def test_only_the_stem_group(command: str) -> None:
    got = understand(command, FOODBANK)
    assert [sorted(r["only"]) for r in got["constraints"] if "only" in r] == [TUGS]


def test_the_stem_said_in_the_singular_is_refused_naming_them() -> None:
    with pytest.raises(TranslationError, match="tug1, tug2, tug3, tug4"):
        understand("The tug must not carry diapers. Move 2 rice sacks from aisle 1 to cooler", FOODBANK)


@pytest.mark.parametrize("command", [
    "Move 2 rice sacks from aisle 1 to cooler, no gantries",
    "No gantries. Move 2 rice sacks from aisle 1 to cooler",
])
def test_a_declared_kind_in_its_plural_in_ies_is_that_kind(command: str) -> None:
    """ "gantries" of kind gantry (a plural in -ies, like "batteries" of a product) was refused."""
    world = {**FOODBANK, "robots": {**FOODBANK["robots"],
                                    "heron": {**FOODBANK["robots"]["lifty"], "kind": "gantry"}}}
    got = understand(command, world)
    assert _never(got["constraints"]) == {"heron"}


def test_declared_kinds_come_before_stems_and_a_numbered_robot_stays_one() -> None:
    got = understand("Robot tug 3 must not carry diapers. Move 2 rice sacks from aisle 1 to cooler", FOODBANK)
    assert _never(got["constraints"]) == {"tug3"}
    got = understand("No forklifts. Move 2 rice sacks from aisle 1 to cooler", FOODBANK)
    assert _never(got["constraints"]) == {"lifty"}


def test_a_group_word_that_matches_nothing_is_refused_naming_the_groups() -> None:
    with pytest.raises(TranslationError, match=r"robot groups: kind amr, .*tugs \(tug1, tug2, tug3, tug4\)"):
        understand("Move 2 rice sacks from aisle 1 to cooler, no drones", FOODBANK)


def test_a_plural_place_head_is_that_group_of_places() -> None:
    """ "the docks" where inbound_dock and outbound_dock share the head: those two, never every
    place; the singular stays refused (which one?), a count still needs "each" or a total."""
    got = understand("Empty the docks", FOODBANK)
    assert set(got["goal"]) == {"inbound_dock", "outbound_dock"}
    got = understand("Move all the diapers from the aisles to the cooler", FOODBANK)
    assert got["goal"] == {"aisle-1": {"diapers": 0}, "aisle-2": {"diapers": 0}, "cooler": {"diapers": 6}}
    with pytest.raises(TranslationError):
        understand("Empty the dock", FOODBANK)
    with pytest.raises(TranslationError, match="each"):
        understand("Put 1 diapers on the docks", FOODBANK)


# -- issue 23: the swap misreading, spurious ambiguity, typos of grammar words -------------------
def test_swapping_two_items_between_two_places_exchanges_those_units() -> None:
    """ "Swap the product1 on shelf 1 with the product3 on shelf 2": shelf1's product1 goes to
    shelf2 and shelf2's product3 to shelf1. It was read as swapping each product's count between
    the shelves (shelf1 product1 8, product3 6): a misreading that executes."""
    got = understand("Swap the product1 on shelf 1 with the product3 on shelf 2", PAPER)
    assert got["goal"] == {"shelf1": {"product1": 0, "product3": 9}, "shelf2": {"product1": 18, "product3": 0}}
    # one item on both sides is that item's counts exchanged, as before
    got = understand("Swap the product1 on shelf 1 with the product1 on shelf 2", PAPER)
    assert got["goal"] == {"shelf1": {"product1": 8}, "shelf2": {"product1": 10}}


def test_the_same_rules_in_another_order_or_said_twice_are_one_meaning() -> None:
    from pipflow.warehouse.language.parser import canonical
    a = canonical({"s1": {"p": 1}, "s2": {"p": 2}}, [{"never": ["r1", "r2"], "product": "p", "words": "x"},
                                                     {"only": ["r3", "r4"]}])
    b = canonical({"s2": {"p": 2}, "s1": {"p": 1}}, [{"only": ["r4", "r3"], "words": "y"}, {"never": ["r2"], "product": "p"},
                                                     {"never": ["r1"], "product": "p"}, {"only": ["r3", "r4"]}])
    assert a == b
    assert a != canonical({"s1": {"p": 1}, "s2": {"p": 2}}, [{"never": ["r1"], "product": "p"}, {"only": ["r3", "r4"]}])


@pytest.mark.parametrize("command", ["Mvoe 3 product1 from shelf1 to shelf2", "Move 3 product1 form shelf1 to shelf2"])
def test_a_slip_in_a_grammar_word_is_repaired(command: str) -> None:
    assert understand(command, PAPER)["goal"] == {"shelf1": {"product1": 7}, "shelf2": {"product1": 11}}


def test_two_repairs_that_compete_are_refused() -> None:
    with pytest.raises(TranslationError, match="fro"):   # "for" or "from"?
        understand("Move 3 product1 fro shelf1 to shelf2", PAPER)


@pytest.mark.parametrize("command, goal", [
    ("stage 6 product2 at shelf3", {"shelf3": {"product2": 9}}),
    # all of an item on one place: the places it leaves are listed at 0 (benchmarks/language/README.md,
    # conventions 1 and 7)
    ("gather every product3 at shelf2", {"shelf2": {"product3": 15}, "shelf1": {"product3": 0},
                                         "shelf3": {"product3": 0}, "shelf4": {"product3": 0}}),
    ("Consolidate all product4 on shelf1", {"shelf1": {"product4": 12}, "shelf2": {"product4": 0},
                                            "shelf3": {"product4": 0}, "shelf4": {"product4": 0}}),
])
def test_gathering_and_staging_verbs_are_move_verbs(command: str, goal: dict) -> None:
    assert understand(command, PAPER)["goal"] == goal


def test_an_unknown_verb_is_never_guessed() -> None:
    with pytest.raises(TranslationError, match="yeet"):
        understand("yeet 6 product2 at shelf3", PAPER)


@pytest.mark.parametrize("command", [
    "First put the banana in the icebox, then put the orange in the pantry",
    "Put the banana in the icebox and the orange in the pantry, do both in parallel",
    "Put the banana in the icebox and the orange in the pantry. Do them at the same time.",
])
def test_household_manner_and_order_adverbs_are_no_condition(command: str) -> None:
    got = household(command, STUDIO)
    assert got["goal"]["in"] == {"icebox": ["banana"], "pantry": ["orange"]}
    assert any("plan decides" in n for n in got["notes"])


def test_household_manner_words_inside_a_content_clause_are_not_dropped() -> None:
    with pytest.raises(TranslationError):
        household("Put the first banana in the icebox", STUDIO)


# -- issue 23: a thing named by one word of its name ---------------------------------------------
@pytest.mark.parametrize("command, goal", [
    ("Double formula on aisle 2", {"aisle-2": {"baby-formula": 6}}),
    ("Move 3 rice from inbound to outbound", {"inbound_dock": {"rice_sack": 1}, "outbound_dock": {"rice_sack": 4}}),
])
def test_warehouse_one_word_of_a_name_that_no_other_name_has(command: str, goal: dict) -> None:
    assert understand(command, FOODBANK)["goal"] == goal


def test_warehouse_a_word_two_names_share_or_a_robot_word_is_no_name() -> None:
    with pytest.raises(TranslationError):
        understand("Empty the dock", FOODBANK)           # inbound_dock or outbound_dock
    cold = yaml.safe_load((ROOT / "benchmarks" / "language" / "cold.yaml").read_text())
    from pipflow.warehouse.language.names import NameIndex
    assert "big" not in NameIndex(cold).parts           # big_lift is a robot: "big" stays English


def test_household_the_head_of_a_two_word_name_names_the_thing() -> None:
    got = household("Wash the pot", STUDIO)
    assert got["goal"]["state"]["soup_pot"] == ["clean"]
    with pytest.raises(TranslationError, match="coffee"):   # a modifier is not read alone
        household("Put the magazine on the coffee", STUDIO)


# -- issue 23, point 5 (part): a refusal offers candidate readings, never acts on one ------------
def test_an_ambiguous_rule_scope_is_refused_with_both_readings_offered() -> None:
    command = "Move all the rice from the inbound dock to aisle 2, and only the forklift should handle it."
    with pytest.raises(TranslationError) as caught:
        understand(command, FOODBANK)
    offered = caught.value.candidates
    assert [c["constraints"] for c in offered] == [
        [{"only": ["lifty"], "product": "rice_sack"}],
        [{"only": ["lifty"], "product": "rice_sack", "from": "inbound_dock", "to": "aisle-2"}]]
    assert all(c["goal"] == {"inbound_dock": {"rice_sack": 0}, "aisle-2": {"rice_sack": 4}} for c in offered)
    assert "Did you mean: (1)" in str(caught.value) and "only forklift should handle it" in offered[0]["words"]


def test_a_word_no_rule_places_offers_the_reading_without_it() -> None:
    with pytest.raises(TranslationError, match="cannot place 'yonder'") as caught:
        understand("Send 2 rice sacks to aisle 1 yonder", FOODBANK)
    assert [c["goal"] for c in caught.value.candidates] == [{"aisle-1": {"rice_sack": 7}}]
    assert caught.value.candidates[0]["words"] == "2 rice sacks"   # what the reading rests on


def test_no_candidate_where_nothing_else_reads() -> None:
    with pytest.raises(TranslationError) as caught:
        understand("blorp", PAPER)
    assert caught.value.candidates == []


def test_household_an_object_dropped_after_a_verb_is_it() -> None:
    """ "slice the carrot, then put in the icebox" reads like "put it in the icebox"; with no
    thing named before, there is nothing for "it" to be, and it stays refused."""
    got = household("Slice the carrot, then put in the icebox", STUDIO)
    assert got["goal"]["in"] == {"icebox": ["carrot"]} and got["goal"]["state"]["carrot"] == ["sliced"]
    assert got["goal"] == household("Slice the carrot, then put it in the icebox", STUDIO)["goal"]
    assert "put (it) in the icebox" in got["explain"][0] and any("read as 'it'" in n for n in got["notes"])
    with pytest.raises(TranslationError):
        household("Put in the icebox", STUDIO)


@pytest.mark.parametrize("tail", ["those on the left", "from the top", "on the left", "which are old",
                                  "the old ones", "and the blorp"])
def test_a_clause_that_narrows_the_order_is_never_set_aside(tail: str) -> None:
    """Setting aside "..., those on the left" would widen what the robots do: refused instead."""
    with pytest.raises(TranslationError):
        understand(f"Move 2 product1 from shelf1 to shelf2, {tail}", PAPER)
    with pytest.raises(TranslationError):
        household(f"Put the banana in the icebox, {tail}", STUDIO)


def test_a_product_modifier_names_it_only_when_it_is_what_the_container_holds() -> None:
    """ "rice" of rice_sack is the rice in the sacks; "oil" of oil-filter or "plants" of plant_pot
    name something else, and are never read as those products."""
    from pipflow.warehouse.language.names import NameIndex

    spares = yaml.safe_load((ROOT / "benchmarks" / "language" / "spares.yaml").read_text())
    nursery = yaml.safe_load((ROOT / "benchmarks" / "language" / "nursery.yaml").read_text())
    assert "oil" not in NameIndex(spares).parts and NameIndex(spares).parts["filter"].name == "oil-filter"
    assert "plant" not in NameIndex(nursery).parts and "plants" not in NameIndex(nursery).parts
    assert NameIndex(FOODBANK).parts["rice"].name == "rice_sack"


def test_household_a_function_word_of_a_name_is_no_content_and_the_error_is_what_is_left() -> None:
    """ "of" of "bottle of water" is no name: "it's years out of date" is talk. When the rest
    still does not read, the refusal quotes the rest and says what was set aside."""
    farm = load_home(ROOT / "benchmarks" / "language" / "household-farmhouse-world.yaml")
    got = household("Throw away the almanac, it's years out of date", farm)
    assert got["order"]["set_aside"] == ["it is years out of date"]
    with pytest.raises(TranslationError, match=r"blorp.*\(set aside: 'morning'\)"):
        household("Morning! Slice the pear, and blorp the kettle", farm)


def test_an_unknown_verb_on_a_thing_is_an_instruction_never_talk() -> None:
    with pytest.raises(TranslationError, match="recount"):
        understand("Shelf2 needs 3 more product1, recount them", PAPER)


@pytest.mark.parametrize("command", [
    "Hornet, move 2 product1 from shelf1 to shelf2",
    "Hi Hornet, move 2 product1 from shelf1 to shelf2",
    "Thanks Hornet: move 2 product1 from shelf1 to shelf2",
    "Move 2 product1 from shelf1 to shelf2, Hornet",
])
def test_warehouse_a_robot_the_world_lacks_addressed_by_name_is_refused(command: str) -> None:
    """Said alone, a word that is no interjection or addressee is someone addressed by name: a
    robot the world lacks is asked to do it, so no robot there may (it had been set aside as talk
    and the move given to any robot)."""
    with pytest.raises(TranslationError, match="Hornet"):
        understand(command, PAPER)


@pytest.mark.parametrize("opener", ["Brr", "Separately", "Right", "Morning, loves", "Ugh"])
def test_warehouse_interjections_said_alone_are_still_talk(opener: str) -> None:
    got = understand(f"{opener}, move 2 product1 from shelf1 to shelf2", PAPER)
    assert got["goal"] == {"shelf1": {"product1": 8}, "shelf2": {"product1": 10}}
    assert not got["constraints"]


def test_warehouse_a_robot_of_the_world_addressed_is_asked_to_do_it() -> None:
    got = understand("robot4, move 2 product1 from shelf1 to shelf2", PAPER)
    assert [c["only"] for c in got["constraints"]] == [["robot4"]]


def test_household_a_robot_addressed_by_name_must_be_one_of_the_home() -> None:
    with pytest.raises(TranslationError, match="(?i)hornet"):
        household("Hornet, turn the radio off", STUDIO)
    assert household("Ada, turn the radio off", STUDIO)["goal"]["state"] == {"radio": ["off"]}
    assert household("Trio, turn the radio off", STUDIO)["goal"]["state"] == {"radio": ["off"]}


@pytest.mark.parametrize("tail, aside", [
    ("he is covered in grease", "he is covered in grease"),          # "grease" is no slip of "areas"
    ("boss reckons customers like seeing samples", "boss reckons customers like seeing samples"),
    ("theyve been scuffing the floor", "theyve been scuffing the floor"),  # no slip of "shelve"
])
def test_warehouse_a_common_word_near_a_name_is_no_slip_of_it(tail: str, aside: str) -> None:
    """A word people write as itself is not taken for a misspelt name because it is one or two
    edits from one ("grease" from "areas", "boss" from "bots"): the clause is talk."""
    got = understand(f"Shelf2 needs 3 more product1, {tail}", PAPER)
    assert got["goal"] == {"shelf2": {"product1": 11}}
    assert got["order"]["set_aside"] == [aside]


def test_warehouse_a_slip_of_a_name_that_is_no_common_word_still_keeps_its_clause() -> None:
    with pytest.raises(TranslationError):
        understand("Shelf2 needs 3 more product1, the shlef", PAPER)


@pytest.mark.parametrize("command, goal", [
    ("Dear team, ensure shelf2 is having 11 product1", {"shelf2": {"product1": 11}}),
    ("shelf1 and shelf2 should both be having 3 product4", {"shelf1": {"product4": 3}, "shelf2": {"product4": 3}}),
    ("shelf1 should have as many product3 as shelf2 is having now", {"shelf1": {"product3": 6}}),
])
def test_warehouse_the_progressive_of_have_is_have(command: str, goal: dict) -> None:
    """"P is having N X" (Indian English and others) is "P has N X"; a letter opens "Dear team"."""
    assert understand(command, PAPER)["goal"] == goal


@pytest.mark.parametrize("command, aside", [
    ("As per the fire officer, shelf1 should have no more than 5 product1", "As per the fire officer"),
    ("Shelf1 should have no more than 5 product1, as per safety rules", "as per safety rules"),
])
def test_warehouse_an_as_per_clause_says_what_the_order_follows(command: str, aside: str) -> None:
    got = understand(command, PAPER)
    assert got["goal"] == {"shelf1": {"product1": {"at_most": 5}}}
    assert got["order"]["set_aside"] == [aside]


def test_warehouse_an_as_per_clause_with_a_name_or_count_is_read() -> None:
    for command in ("As per shelf3, move 2 product1 from shelf1 to shelf2",
                    "As per 2 shelves, move 2 product1 from shelf1 to shelf2"):
        with pytest.raises(TranslationError):
            understand(command, PAPER)


def test_warehouse_a_common_word_is_never_read_as_a_misspelt_number() -> None:
    """"fire" is one edit from "five", "tree" from "three": words written as themselves, never a
    count ("fiv" and "thre" are slips, and are read)."""
    for word in ("fire", "tree"):
        with pytest.raises(TranslationError, match=word):
            understand(f"Move {word} product1 from shelf1 to shelf2", PAPER)
    assert understand("Move fiv product1 from shelf1 to shelf2", PAPER)["goal"]["shelf2"] == {"product1": 13}


def test_a_letters_signature_is_the_writer_never_an_addressee() -> None:
    """"Regards, Ramesh" closes a letter: the writer signs. "Thanks, Ramesh" may thank a robot
    by name, so it is still refused where the world has no Ramesh."""
    got = understand("Move 2 product1 from shelf1 to shelf2. Kind regards, Ramesh", PAPER)
    assert got["goal"] == {"shelf1": {"product1": 8}, "shelf2": {"product1": 10}}
    assert got["order"]["set_aside"] == ["Kind regards , Ramesh"]
    with pytest.raises(TranslationError, match="Ramesh"):
        understand("Move 2 product1 from shelf1 to shelf2. Thanks, Ramesh", PAPER)
    with pytest.raises(TranslationError, match="Ramesh"):
        understand("Regards, Ramesh, move 2 product1 from shelf1 to shelf2", PAPER)
    assert household("Turn the radio off. Regards, Tom", STUDIO)["goal"]["state"] == {"radio": ["off"]}


@pytest.mark.parametrize("command, aside", [
    ("Move 2 product1 from shelf1 to shelf2 would ya", ["would ya"]),
    ("Move 2 product1 from shelf1 to shelf2 could you, its raining", ["could you", "its raining"]),
])
def test_warehouse_a_request_tag_after_the_order_is_set_aside(command: str, aside: list[str]) -> None:
    got = understand(command, PAPER)
    assert got["goal"] == {"shelf1": {"product1": 8}, "shelf2": {"product1": 10}}
    assert got["order"]["set_aside"] == aside


def test_warehouse_a_request_tag_never_hides_a_word_of_the_order() -> None:
    with pytest.raises(TranslationError):
        understand("Move 2 product1 from shelf1 to shelf2 would you not", PAPER)


@pytest.mark.parametrize("command, aside", [
    ("As discussed in the morning meeting, move 2 product1 from shelf1 to shelf2", ["As discussed in the morning meeting"]),
    ("As agreed, move 2 product1 from shelf1 to shelf2", ["As agreed"]),
    ("Move 2 product1 from shelf1 to shelf2 at the earliest", ["at the earliest"]),
    ("Move 2 product1 from shelf1 to shelf2, urgent basis", ["urgent basis"]),
])
def test_warehouse_office_phrasings_of_what_the_order_follows_and_when(command: str, aside: list[str]) -> None:
    got = understand(command, PAPER)
    assert got["goal"] == {"shelf1": {"product1": 8}, "shelf2": {"product1": 10}}
    assert got["order"]["set_aside"] == aside


@pytest.mark.parametrize("tail", ["the labels got mixed up it seems", "spinners cleaned us out", "the truck came early"])
def test_warehouse_a_noun_and_a_verb_in_the_past_report_what_happened(tail: str) -> None:
    got = understand(f"Shelf2 needs 3 more product1, {tail}", PAPER)
    assert got["goal"] == {"shelf2": {"product1": 11}}
    assert got["order"]["set_aside"] == [tail]


@pytest.mark.parametrize("tail", ["stack cleaned ones", "move cleaned stuff", "boxes moved to the back"])
def test_warehouse_an_order_or_a_report_that_picks_things_out_is_never_set_aside(tail: str) -> None:
    with pytest.raises(TranslationError):
        understand(f"Shelf2 needs 3 more product1, {tail}", PAPER)

"""Issue 23, from pair PP's sets (a floor manager at Ħal Far writing Maltese English with Maltese
words, a nurse in Kalihi writing local Hawai'i English with Pidgin), after their first measurements.
Warehouse: Maltese talk ("bonġu", "grazzi", "mela", "allura", "insomma", "iva", "ħabib", "ċaw",
"jekk jogħġbok", "mhux hekk?"), letters with a stroke ("ħ") spelt without it where the word can only
be talk, "k" for OK, asides that add nothing ("from now on", "on top of what's in there", "every
single one" after "all", "wherever there's space"), robots that "stay on charge", and a final count
with a source ("get P to 10 X, taking them from Q": what P lacks of 10, not 10 more, which was
read and would have moved). Household: Hawai'i Pidgin read as English in a command written in it
("da", "fo'", "um" after a verb, "stay" for is, "no" before a verb), Hawaiian talk ("mahalo",
"shoots", "aloha"), and "wash X in the sink and Y too" asked where X lies in the sink already. The
worlds of the Australian and Levantine tests, through the real readers; each rule with what stays
as said or refused."""
from __future__ import annotations

import pytest

from pipflow.errors import PipflowError, TranslationError
from pipflow.household.language.tagger import tag, tags_kept
from pipflow.warehouse.language.translator import understand
from tests.readings import assert_warehouse_alike, household_goal as goal
from tests.test_reader_australian_and_levantine_english import YARD, flat  # noqa: F401 (a fixture)


@pytest.mark.parametrize("said, plain", [
    ("Bonġu ħabib! move 3 cider from grog cage to pick face, grazzi", "move 3 cider from cage to face"),
    ("Mela, move 3 cider from grog cage to pick face. Ċaw", "move 3 cider from cage to face"),
    ("Allura, move 3 cider from grog cage to pick face, insomma", "move 3 cider from cage to face"),
    ("move 3 cider from grog cage to pick face jekk jogħġbok, mhux hekk?", "move 3 cider from cage to face"),
    ("k move 3 cider from grog cage to pick face", "move 3 cider from cage to face"),
    ("Move 3 cider from grog cage to pick face, iva", "move 3 cider from cage to face"),
    ("each place max 5 bikkie from now on", "each place max 5 biscuit"),
    ("I need one more bikkie on the loading dock, on top of what's in there already",
     "I need one more biscuit on dock"),
    ("bring all the cider to the loading dock, every single slab", "bring all the cider to dock"),
    ("move 4 cider off the grog cage, wherever there's space, but none of them go to pick face",
     "move 4 cider off cage but none of them go to face"),
    ("move 3 cider from grog cage to pick face, the forklifts stay on charge",
     "move 3 cider from cage to face, dont use the forklifts"),
    # the robots before "stay on charge" are the words just before it, never the order before them
    ("move 3 cider from grog cage to the loading dock and amr1 stays on charge",
     "move 3 cider from cage to dock, dont use amr1"),
])
def test_maltese_english_orders_read_as_their_plain_english(said: str, plain: str) -> None:
    assert_warehouse_alike(said, plain, YARD)


def test_a_final_count_with_a_source_moves_what_is_missing() -> None:
    """ "get P to N X, taking them from Q" is N there in all: Q gives what P lacks (it was read as N
    more, moved from Q: robots would have moved the wrong count); "N X to P, taking them from Q"
    still moves N."""
    assert understand("get the loading dock to 5 cider", YARD)["goal"] == {"dock": {"cider": 5}}
    got = understand("get the loading dock to 5 cider, taking them from grog cage", YARD)["goal"]
    assert got["dock"]["cider"] == 5 and got["cage"]["cider"] == 10 - 3
    got = understand("the loading dock should have 5 cider, taking them from grog cage", YARD)["goal"]
    assert got["dock"]["cider"] == 5 and got["cage"]["cider"] == 7
    got = understand("4 cider to the loading dock, taking them from grog cage", YARD)["goal"]
    assert got["dock"]["cider"] == 6 and got["cage"]["cider"] == 6
    # a count under what the place holds cannot be reached by taking more there: asked
    with pytest.raises(TranslationError, match="more than 1"):
        understand("get the loading dock to 1 cider, taking them from grog cage", YARD)


@pytest.mark.parametrize("said", [
    # a stroke taken off would make a word of the reader's ("møve": move): never read so
    "møve 3 cider from grog cage to pick face",
    # "mhux" (not) is read only in the tag "mhux hekk"
    "move 3 cider from grog cage to pick face, mhux pick face",
])
def test_what_the_maltese_rules_do_not_cover_stays_refused(said: str) -> None:
    with pytest.raises(PipflowError):
        understand(said, YARD)


@pytest.mark.parametrize("said, plain", [
    ("put da cup in da sink fo' me, mahalo", "put the cup in the sink"),
    ("shoots, take da milk out da fridge and put um on da counter",
     "take the milk out of the fridge and put it on the counter"),
    ("aloha! da cup stay all dirty, wash um", "wash the cup"),
    ("no touch da pie, wash da cup fo' me", "wash the cup, leave the pie alone"),
])
def test_pidgin_reads_as_its_plain_english(flat: dict, said: str, plain: str) -> None:
    assert goal(said, flat) == goal(plain, flat)


def test_pidgin_words_read_are_said_in_the_notes_once(flat: dict) -> None:
    """The echo says how each Pidgin word was read; "no can" is one reading, "can not"."""
    notes: list[str] = []
    tag("da cup, no can wash um fo me", flat, notes)
    assert "'no' read as 'can not' (Hawai'i Pidgin)" in notes and "'fo' read as 'for' (Hawai'i Pidgin)" in notes
    assert not any(note.startswith("'can'") for note in notes)


def test_english_stay_and_um_keep_their_english_readings(flat: dict) -> None:
    """Without Pidgin markers, "stay" is the verb of keeping and "um" a hesitation; with them, "can
    stay" is still the verb."""
    assert goal("the mug stays in the sink, wash the cup", flat)["in"] == {"sink": ["mug"]}
    assert goal("da mug can stay in da sink, wash da cup fo' me", flat)["in"] == {"sink": ["mug"]}
    assert goal("um, wash the mug", flat) == goal("wash the mug", flat)


def test_a_place_that_may_say_which_thing_is_asked_before_it_carries_over(flat: dict) -> None:
    """ "wash the mug in the sink and the cup too", the mug in the sink already: "in the sink" may
    say which mug or where to wash, and the cup (on the counter) would be put in the sink by one
    reading only: asked. Where the first thing is elsewhere the place is where, as before."""
    with pytest.raises(TranslationError, match="or only made clean"):
        goal("wash the mug in the sink and the cup too", flat)
    assert goal("wash the cup in the sink and the mug too", flat)["in"] == {"sink": ["cup", "mug"]}


def test_a_wording_tagged_twice_while_one_command_is_read_answers_alike(flat: dict) -> None:
    """The tags of a wording are kept while one command is read; its notes are said again and a
    refusal is raised anew (a reader may add to it: the copy kept is never the one raised), also
    with ``distributed`` imported (its tblib makes copies of an exception share one dictionary:
    this test failed so in the full suite)."""
    import distributed.utils  # noqa: F401  # deferred: the engine imports it; here only for its side effect
    with tags_kept(flat):
        notes_a: list[str] = []
        notes_b: list[str] = []
        assert tag("put da cup in da sink fo me", flat, notes_a) == tag("put da cup in da sink fo me", flat, notes_b)
        assert notes_a == notes_b and notes_a
        refusals = []
        for _ in range(2):
            with pytest.raises(TranslationError) as caught:
                tag("put the zorblax in the sink", flat)
            refusals.append(caught.value)
        first, second = refusals
        assert first is not second and str(first) == str(second)
        first.unread.append("added")
        first.reworded = ("another wording", None, [])
        assert "added" not in second.unread and not hasattr(second, "reworded")

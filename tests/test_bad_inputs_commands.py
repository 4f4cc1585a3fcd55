"""Bad inputs in the command itself (issue 21, "a misreading from bad input"): characters a
reader does not read, line breaks between sentences, fullwidth and look-alike letters.

A reader that stepped over what it did not know read ``shelf2 holds 2³ product1`` as "holds 2"
and exited 0; ``3½`` and ``²3`` were both 3, and the error messages of the rest quoted a command
the user never wrote. Now every character outside a reader's alphabet is a refusal that quotes
the user's own word and names the character (pipflow/language/characters.py), in both domains'
readers, through the CLI and the API; a line break ends a sentence.
"""
from __future__ import annotations

import json
import unicodedata
from pathlib import Path

import pytest

from pipflow.engine.cli import main

REPO = Path(__file__).resolve().parents[1]


def cli(capsys, *argv: str) -> tuple[int, str, str]:
    code = main([str(a) for a in argv])
    out, err = capsys.readouterr()
    assert "Traceback" not in out + err, out + err
    return code, out, err


def run_command(capsys, runs: Path, workflow: str, command: str) -> tuple[int, str, dict]:
    """``pipflow run WORKFLOW -i command=...`` in-process; (exit code, stderr, outputs.json or {})."""
    code, _, err = cli(capsys, "run", workflow, "-i", f"command={command}", "--no-cache", "-q",
                       "--runs-dir", runs)
    (run,) = sorted(runs.iterdir())[-1:]
    outputs = json.loads((run / "outputs.json").read_text()) if (run / "outputs.json").exists() else {}
    return code, err, outputs


# (command, the word quoted, the character named): every one was read (or misread) on the code
# before this change; a * marks the ones that exited 0 with a wrong count
UNREAD = {
    "superscript after a digit*": ("shelf2 holds 2³ product1", "2³", "SUPERSCRIPT THREE"),
    "superscript before a digit*": ("shelf2 holds ²3 product1", "²3", "SUPERSCRIPT TWO"),
    "a fraction after a digit*": ("shelf2 holds 3½ product1", "3½", "VULGAR FRACTION ONE HALF"),
    "a quarter*": ("shelf2 holds 7¼ product1", "7¼", "VULGAR FRACTION ONE QUARTER"),
    "arabic-indic digit after a digit*": ("shelf2 holds 1٣ product1", "1٣", "ARABIC-INDIC DIGIT THREE"),
    "devanagari digit after a digit*": ("shelf2 holds 1३ product1", "1३", "DEVANAGARI DIGIT THREE"),
    "fullwidth digit after a digit*": ("shelf2 holds 2３ product1", "2３", "FULLWIDTH DIGIT THREE"),
    "bengali digit": ("shelf2 holds ৩ product1", "৩", "BENGALI DIGIT THREE"),
    "circled digit": ("shelf2 holds ③ product1", "③", "CIRCLED DIGIT THREE"),
    "roman numeral": ("shelf2 holds Ⅲ product1", "Ⅲ", "ROMAN NUMERAL THREE"),
    "fraction slash": ("shelf2 holds 3⁄4 product1", "3⁄4", "FRACTION SLASH"),
    "subscript in a name": ("shelf2 holds 3 product₁", "product₁", "SUBSCRIPT ONE"),
    "cyrillic look-alike letter": ("shelf2 holds 3 \u0440roduct1", "\u0440roduct1", "CYRILLIC SMALL LETTER ER"),
    "greek look-alike in a shelf": ("sh\u03bflf2 holds 3 product1", "sh\u03bflf2", "GREEK SMALL LETTER OMICRON"),
    "an accented letter": ("shelf2 holds 3 prodüct1", "prodüct1", "LATIN SMALL LETTER U WITH DIAERESIS"),
    "an emoji": ("shelf2 holds 3 product1 \U0001f4e6", "\U0001f4e6", "PACKAGE"),
    "an at sign": ("shelf2 holds 3 product1 @ 2 product3", "@", "symbol '@'"),
    "a slash": ("Move 3/4 of product1 from shelf1 to shelf2", "3/4", "symbol '/'"),
}


@pytest.mark.parametrize("case", sorted(UNREAD))
def test_a_character_the_warehouse_reader_does_not_read_is_refused_and_quoted(tmp_path, capsys, case):
    command, word, name = UNREAD[case]
    code, err, outputs = run_command(capsys, tmp_path / "runs", "warehouse", command)
    assert code != 0 and "goal" not in outputs, (err, outputs)  # nothing was read, nothing moved
    assert f"'{word}'" in err and name in err, err


def test_an_invisible_character_is_named_and_the_word_shown_without_it(tmp_path, capsys):
    code, err, _ = run_command(capsys, tmp_path / "runs", "warehouse", "shelf\u200b2 holds 3 product1")
    assert code != 0 and "U+200B ZERO WIDTH SPACE" in err and "'shelf2'" in err and "delete it" in err


def test_fullwidth_letters_quote_the_users_own_word_with_the_ascii_spelling_as_a_suggestion(tmp_path, capsys):
    """Before: 'cannot place 'holds' in 'holds 3 productx'': the fullwidth shelf was skipped and
    the message quoted words the user wrote elsewhere."""
    code, err, _ = run_command(capsys, tmp_path / "runs", "warehouse", "ｓｈｅｌｆ２ holds 3 productx")
    assert code != 0
    assert "'ｓｈｅｌｆ２'" in err and "FULLWIDTH LATIN SMALL LETTER S" in err and "did you mean 'shelf2'?" in err
    assert "holds 3 productx" not in err


def test_every_word_with_an_unread_character_is_listed_at_once():
    from pipflow.errors import TranslationError
    from pipflow.warehouse.language.translator import understand
    from pipflow.warehouse.world import load_world

    world = load_world(REPO / "benchmarks/warehouse/world.yaml")
    with pytest.raises(TranslationError) as info:
        understand("shelf2 holds 2³ product1 and ½ product3 on shelf٣", world)
    message = str(info.value)
    assert "'2³'" in message and "'½'" in message and "'shelf٣'" in message


def test_characters_the_readers_do_read_keep_their_reading():
    """Typography that was always read stays read (a regression guard for the alphabet)."""
    from pipflow.warehouse.language.translator import understand
    from pipflow.warehouse.world import load_world

    world = load_world(REPO / "benchmarks/warehouse/world.yaml")
    read = {
        "shelf2 holds\u00a03 product1": {"shelf2": {"product1": 3}},                       # no-break space
        "shelf2 holds 3 \u201cproduct1\u201d": {"shelf2": {"product1": 3}},                # curly quotes
        "shelf2\u2019s product1 should be 3": None,                                          # apostrophe (read)
        "shelf2 should have 8\u201311 product1": {"shelf2": {"product1": {"at_least": 8, "at_most": 11}}},
        "Move 2 product1 from shelf1 \u2192 shelf2": {"shelf1": {"product1": 8}, "shelf2": {"product1": 10}},
        "shelf2 holds 3 \u00d7 product1": {"shelf2": {"product1": 3}},
        "shelf #2 holds 3 product1": {"shelf2": {"product1": 3}},
    }
    for command, goal in read.items():
        if goal is None:
            continue
        assert understand(command, world)["goal"] == goal, command
    ellipsis = understand("shelf2 holds 3 product1\u2026 shelf3 holds 2 product2", world)["goal"]
    assert ellipsis == {"shelf2": {"product1": 3}, "shelf3": {"product2": 2}}  # an ellipsis ends a sentence


def test_a_stray_number_mark_is_refused_not_skipped():
    from pipflow.errors import TranslationError
    from pipflow.warehouse.language.translator import understand
    from pipflow.warehouse.world import load_world

    world = load_world(REPO / "benchmarks/warehouse/world.yaml")
    with pytest.raises(TranslationError, match="cannot place '#'"):
        understand("shelf2 holds 3 product1 #2", world)


# --- line breaks ---------------------------------------------------------------------------
def test_a_line_break_between_two_sentences_ends_the_first(tmp_path, capsys):
    """Before: 'cannot place 'shelf3' in 'shelf2 should have 3 product1 shelf3 ...''."""
    code, err, outputs = run_command(capsys, tmp_path / "runs", "warehouse",
                                     "shelf2 should have 3 product1\nshelf3 should have 4 product2")
    assert code == 0, err
    assert outputs["goal"] == {"shelf2": {"product1": 3}, "shelf3": {"product2": 4}}


@pytest.mark.parametrize("command, goal", [
    ("Move 2 product3 from shelf1 to shelf4\r\nshelf2 should have 3 product1",
     {"shelf1": {"product3": 1}, "shelf4": {"product3": 4}, "shelf2": {"product1": 3}}),
    ("shelf2 should have 3 product1\u2028Put 2 product4 on shelf1", {"shelf2": {"product1": 3}, "shelf1": {"product4": 2}}),
    # ("put N X on P" where P holds none of X: a final count; where it holds some, add or set? refused)
    ("Put 3 product4 on shelf1\nrobot1 must not help", {"shelf1": {"product4": 3}}),
    ("Put 3 product4\non shelf1", {"shelf1": {"product4": 3}}),   # a wrapped sentence still reads
    ("Put 3 product4 on shelf1.\n\nPut 2 product2 on shelf4.", {"shelf1": {"product4": 3}, "shelf4": {"product2": 2}}),
])
def test_line_breaks_in_warehouse_commands(command, goal):
    from pipflow.warehouse.language.translator import understand
    from pipflow.warehouse.world import load_world

    world = load_world(REPO / "benchmarks/warehouse/world.yaml")
    assert understand(command, world)["goal"] == goal


def test_a_line_break_that_changes_the_meaning_either_way_is_refused():
    """"Move 2 product1 to shelf2 / and 3 to shelf3" means one thing as two sentences and another
    as one: neither is picked."""
    from pipflow.errors import TranslationError
    from pipflow.warehouse.language.translator import understand
    from pipflow.warehouse.world import load_world

    world = load_world(REPO / "benchmarks/warehouse/world.yaml")
    with pytest.raises(TranslationError, match="line breaks .* can end sentences .* or continue them"):
        understand("Move 2 product1 to shelf2\nand 3 to shelf3", world)


# --- the household reader: the same rule --------------------------------------------------------
HOUSEHOLD = {
    "superscript*": ("Put 2³ apples in the fridge.", "2³", "SUPERSCRIPT THREE"),
    "a fraction*": ("Put 2½ apples in the fridge.", "2½", "VULGAR FRACTION ONE HALF"),
    "fullwidth digit": ("Put ２ apples in the fridge.", "２", "FULLWIDTH DIGIT TWO"),
    "arabic-indic digit": ("Put ٢ apples in the fridge.", "٢", "ARABIC-INDIC DIGIT TWO"),
    "fullwidth verb*": ("Ｐｕｔ the apple in the fridge.", "Ｐｕｔ", "FULLWIDTH LATIN CAPITAL LETTER P"),
    "an emoji*": ("Put the apple in the fridge \U0001f34e", "\U0001f34e", "RED APPLE"),
    "cyrillic look-alike": ("Put the \u0430pple in the fridge.", "\u0430pple", "CYRILLIC SMALL LETTER A"),
}


@pytest.mark.parametrize("case", sorted(HOUSEHOLD))
def test_a_character_the_household_reader_does_not_read_is_refused_and_quoted(tmp_path, capsys, case):
    command, word, name = HOUSEHOLD[case]
    code, err, outputs = run_command(capsys, tmp_path / "runs", "household", command)
    assert code != 0 and "goal" not in outputs, (err, outputs)
    assert f"'{word}'" in err and name in err, err


def test_household_line_breaks():
    from pipflow.household.language.translator import translate
    from pipflow.household.world import load_world

    world = load_world(REPO / "benchmarks/household/world.yaml")
    both = translate("Put the apple in the fridge\nTrash the mug", world)
    assert both["goal"]["in"] == {"fridge": ["apple"], "garbagecan": ["mug"]}
    wrapped = translate("Put the apple\nin the fridge", world)
    assert wrapped["goal"]["in"] == {"fridge": ["apple"]}
    assert wrapped["order"]["command"] == "Put the apple\nin the fridge"  # the user's own text


# --- the API: the same refusals come back as a failed Run ------------------------------------------
@pytest.mark.parametrize("workflow, command, word", [
    ("warehouse", "shelf2 holds 4² product1", "4²"),
    ("household", "Put ３ apples in the fridge.", "３"),
])
def test_the_api_returns_the_refusal(tmp_path, workflow, command, word):
    import pipflow

    run = pipflow.run(workflow, runs_dir=tmp_path / "runs", cache=False, command=command)
    assert run.status == "failed" and run.error_step == "generate"
    assert f"'{word}'" in run.error and unicodedata.name(word[-1]) in run.error
    assert "goal" not in run.outputs


def test_the_alphabet_rule_itself():
    from pipflow.language.characters import line_readings, unread

    assert unread("shelf2 holds 3 product1", "") == []
    assert unread("a 2³ b ½ c", "") == [("2³", "³"), ("½", "½")]
    assert unread("a\u00a0b\tc\nd", "") == []  # any white space is a space
    assert line_readings("a b") == ["a b"]
    assert line_readings("a b\nc d") == ["a b. c d", "a b c d"]
    assert line_readings("a b.\n\nc d") == ["a b. c d"]  # the break adds nothing to a full stop

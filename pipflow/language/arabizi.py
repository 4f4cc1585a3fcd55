"""Arabizi: Arabic typed in Latin letters with digits for the sounds Latin lacks ("ya3ni",
"ma3lesh", "3ashan", "el gaw 7ar"), as people in Egypt, the Levant and the Gulf type their English
chat too. The readers split numbers from words, so such a word would give a count ("ya3ni": 3)
and is refused whole. Here it is spelt again in letters (3 -> a, 7 -> h, 5 -> kh, 2 -> nothing,
8 -> gh, 9 -> q, 6 -> t) before that split, so its digit is never a count: only where the digit
stands between letters, or opens a word whose letters are no English word and no unit ("7ar",
"3ashan"); "3boxes", "8pm", "2nd" stay as written, and are read or refused as before. The word
spelt so is then a word like any other: read where a lexicon knows it ("yaani", "maalesh" as talk),
else refused as unknown, or set aside with a clause that asks for nothing."""
from __future__ import annotations

import re
from typing import Callable

#: the digits Arabizi writes for letters, and the letters they are spelt with here
LETTERS = {"2": "", "3": "a", "5": "kh", "6": "t", "7": "h", "8": "gh", "9": "q"}
#: a word with one of those digits inside it, or opening it
_WORD = re.compile(r"(?<![\w'])([A-Za-z]*)([235-9][A-Za-z0-9]*)(?![\w'])")


def spelt_in_letters(command: str, english: Callable[[str], bool], notes: list[str]) -> str:
    """The command with its Arabizi words spelt in letters (module docstring); ``english(word)``
    says whether a word is a word of the reader or the world, English or a unit: a count glued to
    one stays a count ("3boxes"), and a name of the world with a digit in it stays that name. Each
    word spelt so is noted."""
    def spell(m: re.Match) -> str:
        lead, rest = m.group(1), m.group(2)
        word = m.group(0)
        letters = re.sub(r"\d", "", rest)
        if not re.search(r"[A-Za-z]", rest) or re.search(r"[014]", word) or english(word.lower()):
            return word   # a plain number, a digit Arabizi does not write for a letter, a name
        if not lead and (len(letters) < 2 or english(letters.lower()) or not rest[1:2].isalpha()):
            return word   # "3boxes", "8pm", "22nd": a count glued to a word
        said = lead + "".join(LETTERS.get(c, c) for c in rest)
        notes.append(f"'{word}' read as '{said}' (Arabic in Latin letters, a digit for a letter)")
        return said
    return _WORD.sub(spell, command)

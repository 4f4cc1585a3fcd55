"""Spelling of names in commands: one normal form, edit distance, plurals.

Every domain's reader matches the words of a command against the names of its world, and people
write those names apart, joined or hyphenated ("cold store", "cold-store"), in the plural, and
misspelt ("prodcut3"). The rules for that are the same in any world: a normal form in which
those spellings compare equal, an edit distance that counts a swap of neighbours as one edit,
how many edits a word of a given length may carry, and the plural forms of a name. Which names
a domain has, and when a near-match is a guess to refuse, stay with the domain's reader.
"""
from __future__ import annotations

import re
from collections.abc import Iterable

from rapidfuzz.distance import OSA


def normalize(text: str) -> str:
    """Lower-case letters and digits only: "Cold-Store" and "cold store" compare equal."""
    return re.sub(r"[^a-z0-9]", "", text.lower())


def split_digits(norm: str) -> tuple[str, str]:
    """("bay4" -> "bay", "4"); names without a trailing number keep it all as letters."""
    m = re.fullmatch(r"(.*?[a-z])(\d+)", norm)
    return (m.group(1), m.group(2)) if m else (norm, "")


def distance(a: str, b: str) -> int:
    """Edit distance counting a swap of neighbours as one edit ("prodcut" is 1 from "product"): the
    optimal string alignment distance. rapidfuzz computes it in C++, about 250 times faster than
    the same recurrence in Python; a refused household command compares each unknown word with
    every word of the world and of the lexicon, so this was a third of its reading time."""
    return OSA.distance(a, b)


#: letters spelt two ways for one sound ("alfa" and "alpha")
_SOUNDS = (("ph", "f"),)


def sounded(word: str) -> str:
    """A word with letters that spell one sound written one way (:data:`_SOUNDS`), for comparing
    a name spelt by ear with the world's spelling."""
    for written, said in _SOUNDS:
        word = word.replace(written, said)
    return word


def tolerance(length: int) -> int:
    """Edits allowed against a stem of this length: none for very short words, 2 from 5 letters."""
    return 0 if length <= 2 else 1 if length <= 4 else 2


def variants(alpha: str) -> list[str]:
    """The word and its singular forms ("apples" -> "apple"), to forgive plurals."""
    out = [alpha]
    if len(alpha) > 3 and alpha.endswith("s"):
        out.append(alpha[:-1])
        if alpha.endswith("es"):
            out.append(alpha[:-2])
    return out


def plural_forms(norm: str) -> list[str]:
    """The plural spellings of a normalised name: its last word inflected ("labelroll" ->
    "labelrolls", "sku220" -> "sku220s", "battery" -> "batteries", "box" -> "boxes"). People
    pluralise multi-word and coded names as they do any noun, and write them apart, joined,
    hyphenated or underscored; :func:`normalize` already makes those four spellings one."""
    out = [norm + "s", norm + "es"]
    if len(norm) > 2 and norm.endswith("y") and norm[-2] not in "aeiou":
        out.append(norm[:-1] + "ies")
    return out


#: the letters next to each letter on a QWERTY keyboard (a finger that slipped)
_ROWS = ("qwertyuiop", "asdfghjkl", "zxcvbnm")
KEY_NEIGHBOURS: dict[str, set[str]] = {}
for _r, _row in enumerate(_ROWS):
    for _c, _ch in enumerate(_row):
        near = {_row[k] for k in (_c - 1, _c + 1) if 0 <= k < len(_row)}
        # the rows are staggered: the row above is shifted right (g is under t and y), the row below left
        for _other, _cols in ((_r - 1, (_c, _c + 1)), (_r + 1, (_c - 1, _c))):
            if 0 <= _other < len(_ROWS):
                near |= {_ROWS[_other][k] for k in _cols if 0 <= k < len(_ROWS[_other])}
        KEY_NEIGHBOURS[_ch] = near


def slip(word: str, target: str) -> bool:
    """Whether ``word`` is ``target`` typed with one slip: two neighbouring letters swapped
    ("mvoe", "form"), one letter left out or doubled in ("evry", "onnly"; targets of four letters
    or more), or one letter replaced by a key next to it ("onlu"). A letter replaced by a far key
    is no slip: "gone" is not "none", "out" is not "but"."""
    if word == target:
        return False
    a, b = word, target
    if len(a) == len(b):
        diff = [k for k in range(len(a)) if a[k] != b[k]]
        if len(diff) == 2 and diff[1] == diff[0] + 1 and a[diff[0]] == b[diff[1]] and a[diff[1]] == b[diff[0]]:
            return True
        return len(diff) == 1 and b[diff[0]] in KEY_NEIGHBOURS.get(a[diff[0]], set())
    if len(b) < 4 or abs(len(a) - len(b)) != 1:
        return False
    short, long_ = (a, b) if len(a) < len(b) else (b, a)
    return any(long_[:k] + long_[k + 1:] == short for k in range(len(long_)))


class Slips:
    """The targets a word is one slip from (:func:`slip`), found by lookup instead of comparing the
    word with every target: the reader asks this of every word it does not know, against every
    grammar word, and the comparisons were a tenth of the reading time of a refused command."""

    def __init__(self, targets: Iterable[str]) -> None:
        self._same: dict[str, set[str]] = {}      # a swap of neighbours, or a key next to it
        self._dropped: dict[str, set[str]] = {}   # a letter left out (targets of four letters or more)
        self._long: set[str] = set()              # targets a letter may be doubled into
        for t in set(targets):
            for k in range(len(t)):
                if k + 1 < len(t):
                    self._add(self._same, t[:k] + t[k + 1] + t[k] + t[k + 2:], t)
                for c in KEY_NEIGHBOURS.get(t[k], ()):
                    self._add(self._same, t[:k] + c + t[k + 1:], t)
                if len(t) >= 4:
                    self._add(self._dropped, t[:k] + t[k + 1:], t)
            if len(t) >= 4:
                self._long.add(t)

    @staticmethod
    def _add(table: dict[str, set[str]], variant: str, target: str) -> None:
        table.setdefault(variant, set()).add(target)

    def of(self, word: str) -> set[str]:
        """The targets ``word`` is one slip from: ``{t for t in targets if slip(word, t)}``."""
        out = self._same.get(word, set()) | self._dropped.get(word, set())
        out |= {d for d in (word[:k] + word[k + 1:] for k in range(len(word))) if d in self._long}
        out.discard(word)
        return out


#: one English word with two accepted spellings (British and American, or old and new), where no
#: rule of endings covers the pair; each pair is the same word, never two words that look alike
_SPELLING_PAIRS = (("despatch", "dispatch"), ("grey", "gray"), ("tyre", "tire"), ("kerb", "curb"),
                   ("aluminium", "aluminum"), ("programme", "program"), ("plough", "plow"),
                   ("mould", "mold"), ("doughnut", "donut"), ("pyjamas", "pajamas"),
                   ("jewellery", "jewelry"), ("manoeuvre", "maneuver"), ("sceptic", "skeptic"),
                   ("moustache", "mustache"), ("cosy", "cozy"), ("storey", "story"), ("sulphur", "sulfur"),
                   ("yoghurt", "yogurt"), ("yoghourt", "yogurt"), ("whisky", "whiskey"), ("axe", "ax"),
                   ("pallette", "pallet"), ("licence", "license"), ("defence", "defense"))
_OTHER: dict[str, set[str]] = {}
for _a, _b in _SPELLING_PAIRS:
    _OTHER.setdefault(_a, set()).add(_b)
    _OTHER.setdefault(_b, set()).add(_a)
#: a word of a place's name and the word of the same sound speech to text writes for it ("isle
#: twelve" for aisle 12): one way only, so a world's "isle" is never read as an aisle
_OTHER.setdefault("aisle", set()).add("isle")

#: endings spelt two ways (British, American): "colour", "centre", "organise", "catalogue",
#: "travelled"; only after enough letters that the ending is a suffix ("four", "acre", "rise" are not)
_ENDINGS = ((r"(?<=[a-z]{2})our$", "or"), (r"(?<=[a-z]{2}[^aeiou])re$", "er"), (r"(?<=[a-z]{3})ise$", "ize"),
            (r"(?<=[a-z]{3})isation$", "ization"), (r"(?<=[a-z]{3})yse$", "yze"), (r"(?<=[a-z]{3})ogue$", "og"),
            (r"(?<=[a-z]{3}[aeiou])lled$", "led"), (r"(?<=[a-z]{3}[aeiou])lling$", "ling"))


def other_spellings(word: str) -> set[str]:
    """The other accepted spellings of an English word ("despatch" -> "dispatch", "colour" ->
    "color", "center" -> "centre"): the same word, so a name spelt one way is the name spelt the
    other. Why not typo tolerance: the other spelling is often a word of its own ("dispatch" is a
    verb too), and a real word is never repaired into a name; a spelling is no repair."""
    word = word.lower()
    out = set(_OTHER.get(word, ()))
    for british, american in _ENDINGS:
        if re.search(british, word):
            out.add(re.sub(british, american, word))
        back = british.replace("$", "").split(")")[-1]
        if word.endswith(american) and len(word) >= len(american) + 3:
            candidate = word[: -len(american)] + back
            if re.search(british, candidate):
                out.add(candidate)
    out.discard(word)
    return out

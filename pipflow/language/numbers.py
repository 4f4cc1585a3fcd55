"""Read counts written as digits, words, collective nouns or small sums.

Commands say "ten plus seven", "a quartet of", "a hundred and five", "half a dozen": an LLM reads
these without effort, so the offline translator must too, or it would be a poorer default than the
model it stands in for. Only whole numbers are counts; anything else is left for the caller to
reject, so a phrase that is not a number never becomes one by accident.
"""
from __future__ import annotations

import functools
from collections.abc import Sequence

UNITS: dict[str, int] = {
    "zero": 0, "one": 1, "two": 2, "three": 3, "four": 4, "five": 5, "six": 6, "seven": 7,
    "eight": 8, "nine": 9, "ten": 10, "eleven": 11, "twelve": 12, "thirteen": 13,
    "fourteen": 14, "fifteen": 15, "sixteen": 16, "seventeen": 17, "eighteen": 18, "nineteen": 19,
    # Spanish counts said in English orders ("move cinco radiators"), none of them an English word
    # ("uno" and "una" are left out: "una" is Nigerian Pidgin for you all; "once" is English)
    "dos": 2, "tres": 3, "cuatro": 4, "cinco": 5, "seis": 6, "siete": 7, "ocho": 8, "nueve": 9, "diez": 10,
    "doce": 12, "quince": 15, "veinte": 20,
}
TENS: dict[str, int] = {
    "twenty": 20, "thirty": 30, "forty": 40, "fourty": 40, "fifty": 50, "sixty": 60,
    "seventy": 70, "eighty": 80, "ninety": 90,
}
SCALES: dict[str, int] = {"hundred": 100, "thousand": 1000}
# Collective nouns: a word that stands for a fixed count ("a trio of product3").
COLLECTIVES: dict[str, int] = {
    "pair": 2, "couple": 2, "brace": 2, "duo": 2, "trio": 3, "triplet": 3, "quartet": 4,
    "quintet": 5, "sextet": 6, "septet": 7, "octet": 8, "nonet": 9, "dozen": 12, "score": 20,
    "gross": 144,
}
# Written between two counts, these combine them; multiplication binds tighter, as in school.
ADDITIVE = {"plus": 1, "minus": -1}
#: the most words one count may span ("two thousand three hundred and forty five plus ...")
WINDOW = 24
MULTIPLICATIVE = {"times", "multiplied", "divided"}
#: "3 lots of 5", "two batches of six": N groups of M is N times M (read only when M is a count)
GROUPS_OF = frozenset({"lots", "batches", "sets"})

NUMBER_WORDS = set(UNITS) | set(TENS) | set(SCALES) | set(COLLECTIVES) | set(ADDITIVE) | {
    "times", "multiplied", "divided", "half", "dozens", "pairs", "couples", "trios", "quartets",
    "quintets", "sextets", "septets", "octets", "nonets", "scores", "bakers",
}
#: the words a count can begin with (besides digits): the readers ask :func:`read_number` at every
#: word of every wording they try, and almost none begins one
_FIRST_WORDS = frozenset(UNITS) | frozenset(TENS) | frozenset(COLLECTIVES) | {"a", "an", "half"}


def is_number(word: str) -> bool:
    """Whether a word (in lower case) is a count as written: digits, or a word of a number."""
    return word.isdigit() or word in NUMBER_WORDS


def _collective(word: str, plural_ok: bool) -> int | None:
    """The count a collective noun stands for ("trio" -> 3); plurals only after a count."""
    if word in COLLECTIVES:
        return COLLECTIVES[word]
    if plural_ok and word.endswith("s") and word[:-1] in COLLECTIVES:
        return COLLECTIVES[word[:-1]]
    return None


def word_value(word: str) -> int | None:
    """The value of one token that is a whole number by itself ("7", "seven", "twenty-five").

    Used where a number is part of a name written apart ("shelf three"), so it accepts no
    collectives and no arithmetic.
    """
    if word.isdigit():
        return int(word)
    parts = word.split("-")
    if len(parts) == 1:
        return UNITS.get(word, TENS.get(word))
    if len(parts) == 2 and parts[0] in TENS and parts[1] in UNITS and 0 < UNITS[parts[1]] < 10:
        return TENS[parts[0]] + UNITS[parts[1]]
    return None


class _Parts:
    """The words from a start index on, hyphenated tokens split, each part knowing its token.

    Counts may be hyphenated ("twenty-five", "half-dozen"); a reading must end on a token
    boundary, so "twenty-foo" is never read as twenty.
    """

    def __init__(self, words: Sequence[str | None], start: int):
        self.parts: list[str] = []
        self.token_end: list[int] = []  # index of the token after this part, or -1 mid-token
        j = start
        # A count is a few words long; looking further would make reading a command quadratic.
        end = min(len(words), start + WINDOW)
        while j < end and words[j] is not None:
            pieces = [p for p in words[j].split("-") if p] or [words[j]]
            for k, piece in enumerate(pieces):
                self.parts.append(piece)
                self.token_end.append(j + 1 if k == len(pieces) - 1 else -1)
            j += 1

    def get(self, k: int) -> str:
        return self.parts[k] if k < len(self.parts) else ""


def _cardinal(p: _Parts, k: int) -> tuple[int, int] | None:
    """Read a count in digits or words from part ``k``; returns (value, next part)."""
    w = p.get(k)
    if w.isdigit():
        return int(w), k + 1
    total, current, seen, last = 0, 0, False, ""
    j = k
    if w in ("a", "an") and p.get(k + 1) in SCALES:
        current, seen, last, j = 1, True, "unit", k + 1
    while j < len(p.parts):
        w = p.get(j)
        if w in UNITS:
            if last in ("unit", "teen") or (last == "tens" and not 0 < UNITS[w] < 10):
                break
            current += UNITS[w]
            last = "unit" if UNITS[w] < 10 else "teen"
        elif w in TENS:
            if last in ("unit", "teen", "tens"):
                break
            current += TENS[w]
            last = "tens"
        elif w in SCALES and seen:
            if w == "hundred":
                current = (current or 1) * 100
            else:
                total += (current or 1) * SCALES[w]
                current = 0
            last = "scale"
        elif w == "and" and last == "scale" and (p.get(j + 1) in UNITS or p.get(j + 1) in TENS):
            last = "and"
        else:
            break
        seen = True
        j += 1
    if not seen:
        return None
    if last == "and":  # "a hundred and" with nothing after: give the "and" back
        j -= 1
    return total + current, j


def _and_a_half(p: _Parts, k: int, value: int, c: int) -> tuple[int, int]:
    """ "two dozen and a half" (30): half a collective more, when that is whole."""
    if p.get(k) == "and" and p.get(k + 1) in ("a", "an") and p.get(k + 2) == "half" and c % 2 == 0:
        return value + c // 2, k + 3
    return value, k


def _term(p: _Parts, k: int) -> tuple[int, int] | None:
    """A count optionally scaled by a collective: "7", "two dozen", "a trio", "half a dozen"."""
    w = p.get(k)
    if w == "half" or (w in ("a", "an") and p.get(k + 1) == "half"):
        j = k + (1 if w == "half" else 2)
        if p.get(j) in ("a", "an"):
            j += 1
        c = _collective(p.get(j), plural_ok=False)
        if c is not None and c % 2 == 0:
            return c // 2, j + 1
        return None
    if w in ("a", "an") and p.get(k + 1) in ("bakers", "baker") and p.get(k + 2) == "dozen":
        return 13, k + 3
    if w in ("a", "an"):
        c = _collective(p.get(k + 1), plural_ok=False)
        if c is not None:
            return _and_a_half(p, k + 2, c, c)
    c = _collective(w, plural_ok=False)
    if c is not None and w not in ("score", "gross", "couple"):  # bare "dozen product3"
        return c, k + 1
    card = _cardinal(p, k)
    if card is None:
        return None
    value, j = card
    c = _collective(p.get(j), plural_ok=True)
    if c is not None:
        return _and_a_half(p, j + 1, value * c, c)
    return value, j


def read_number(words: Sequence[str | None], start: int) -> tuple[int, int] | None:
    """Read a count at ``words[start]``; returns (value, index of the next token) or None.

    ``words`` holds lower-case tokens, ``None`` where a token is not a plain word (a name,
    punctuation): a count never runs across those. Sums and products of counts are evaluated
    with the usual precedence; a division that leaves a remainder is not a count, so it is not
    read as one.
    """
    if start >= len(words) or words[start] is None:
        return None
    head = next((piece for piece in words[start].split("-") if piece), "")
    if not (head.isdigit() or head in _FIRST_WORDS):
        return None
    p = _Parts(words, start)
    first = _term(p, 0)
    if first is None:
        return None
    values, ops, k = [first[0]], [], first[1]
    best = (first[0], k) if p.token_end[k - 1] != -1 else None
    while True:
        w = p.get(k)
        if w in ADDITIVE:
            op, nxt = w, k + 1
        elif w == "times":
            op, nxt = "times", k + 1
        elif w in GROUPS_OF and p.get(k + 1) == "of":   # "3 lots of 5": a product, when a count follows
            op, nxt = "times", k + 2
        elif w in ("multiplied", "divided") and p.get(k + 1) == "by":
            op, nxt = w, k + 2
        else:
            break
        term = _term(p, nxt)
        if term is None:
            break
        values.append(term[0])
        ops.append(op)
        k = term[1]
        value = _evaluate(values, ops)
        if value is not None and p.token_end[k - 1] != -1:
            best = (value, k)
    if best is None:
        return None
    return best[0], p.token_end[best[1] - 1]


def _evaluate(values: list[int], ops: list[str]) -> int | None:
    """Evaluate a flat sum of products; None when a division is not exact or the result < 0."""
    sums: list[int] = [values[0]]
    signs: list[int] = [1]
    for op, v in zip(ops, values[1:]):
        if op == "times" or op == "multiplied":
            sums[-1] *= v
        elif op == "divided":
            if v == 0 or sums[-1] % v:
                return None
            sums[-1] //= v
        else:
            sums.append(v)
            signs.append(ADDITIVE[op])
    result = sum(s * v for s, v in zip(signs, sums))
    return result if result >= 0 else None


@functools.lru_cache(maxsize=8192)
def reads_as_count(word: str) -> bool:
    """Whether one word alone is read as a count (:func:`read_number` of that word): the readers
    ask it of every word of every wording of a refused command."""
    return read_number([word], 0) is not None

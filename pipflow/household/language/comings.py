"""The speaker's comings and the people blamed, said around an order (issue 23).

"Just in off nights and I'm dead on me feet", "Just back from a 12 hour shift at Aintree": where
the speaker has come from opens a message as "Morning" does, and asks nothing of the home; it is
left out, said in the notes, where it names nothing of the home and its only number is how long
("a 12 hour shift"). "Some divvy's left the milk out": whoever is blamed, by a word the reader does
not know, is "someone", as "someone's left the milk out" is read.
"""
from __future__ import annotations

from pipflow.household.language.tokens import PUNCT
from pipflow.language.asides import duration_at

#: how a sentence of the speaker's coming opens ("just in off nights", "I'm just back from work")
_COMING = (("just", "in"), ("just", "back"), ("just", "home"), ("just", "got", "in"), ("just", "got", "back"),
           ("just", "got", "home"))
_FROM = frozenset({"from", "off", "after"})
_SPEAKER = (("i", "am"), ("im",), ())
#: who may be blamed before "has left" ("some divvy's left", "some idiot has left")
_BLAMED_BEFORE = frozenset({"has", "have", "s"})


def just_come_in(words: list[str], index: dict, notes: list[str]) -> list[str]:
    """The words without a sentence (or its first clause) that says where the speaker has just
    come in from: "just in off nights", "I'm just back from a 12 hour shift at Aintree"."""
    out: list[str] = []
    k = 0
    while k < len(words):
        if k == 0 or words[k - 1] in (".", "!", "?", ";"):
            end = _coming_end(words, k, index)
            if end:
                notes.append(f"'{' '.join(words[k:end])}': where the speaker has come from, no order (set aside)")
                k = end + (end < len(words) and words[end] in PUNCT)
                continue
        out.append(words[k])
        k += 1
    return out


def _coming_end(words: list[str], k: int, index: dict) -> int:
    """Where a clause of the speaker's coming at ``k`` ends (0: none there)."""
    for who in _SPEAKER:
        for coming in _COMING:
            opener = who + coming
            j = k + len(opener)
            if tuple(words[k:j]) != opener or j >= len(words) or words[j] not in _FROM:
                continue
            end = next((e for e in range(j, len(words)) if words[e] in PUNCT or words[e] in ("and", "so", "but")),
                       len(words))
            rest = words[j + 1:end]
            if rest and not any((w,) in index or (w.isdigit() and not duration_at(rest, i)) for i, w in enumerate(rest)):
                return end
    return 0


def someone_blamed(words: list[str], index: dict, notes: list[str]) -> list[str]:
    """ "some divvy's left the milk out": "some" and a word that names nothing of the home, before
    "has left", is "someone" (who is blamed is no part of what is asked)."""
    out = list(words)
    k = 0
    while k + 3 < len(out):
        if out[k] == "some" and out[k + 2] in _BLAMED_BEFORE and out[k + 3] == "left" and out[k + 1].isalpha() \
                and (out[k + 1],) not in index:
            notes.append(f"'some {out[k + 1]}': someone")
            out[k:k + 2] = ["someone"]
        k += 1
    return out

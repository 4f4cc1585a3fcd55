"""A self-correction inside a sentence ("get the quilt, sorry, the wool blanket out of the box",
"put the mug in the sink, I mean the cupboard"): the noun phrase after the marker replaces the
last noun phrase before it (docs/household.md, "homely English"). Without this, the marker is
talk set aside and both things would be read (a misreading).

Only between commas (or a comma before and a determiner after), only when the words after the
marker open with a determiner and the clause before has one; "no" is never a marker here (it
is a negation, operative)."""
from __future__ import annotations

from pipflow.household.language.tokens import PUNCT

#: words that take back the noun phrase just said
MARKERS = (("sorry", "i", "mean"), ("or", "rather"), ("i", "mean"), ("i", "meant"), ("sorry",), ("rather",))
#: words that open a noun phrase
DETERMINERS = {"the", "a", "an", "my", "our", "your", "that", "this", "those", "these", "some", "his", "her"}


def corrected(words: list[str], notes: list[str]) -> list[str]:
    """The words with each self-correction (module docstring) made: the noun phrase before the
    marker, from its determiner to the comma, gives way to the words after the marker."""
    out: list[str] = []
    k = 0
    while k < len(words):
        marker = next((m for m in MARKERS if k and words[k - 1] == "," and tuple(words[k:k + len(m)]) == m), None)
        if marker is not None:
            after = k + len(marker) + (1 if k + len(marker) < len(words) and words[k + len(marker)] == "," else 0)
            start = _last_determiner(out[:-1])
            if after < len(words) and words[after] in DETERMINERS and start is not None:
                taken = " ".join(out[start:-1])
                notes.append(f"'{taken}, {' '.join(marker)}': a self-correction; read as what follows it")
                out = out[:start]
                k = after
                continue
        out.append(words[k])
        k += 1
    return out


def _last_determiner(words: list[str]) -> int | None:
    """Where the last noun phrase of the clause being read opens (its determiner), or None."""
    for j in range(len(words) - 1, -1, -1):
        if words[j] in PUNCT:
            return None
        if words[j] in DETERMINERS:
            return j
    return None

"""A thing named again by the head of its name ("get the quilt out of the blanket box, and shut
the box after"): after "the" (or "that", "this"), a word that is the last word of the name of a
thing already said in full earlier in the command means that thing (docs/household.md, "homely
English"), as a definite noun phrase points back to the one thing of its kind said before. Only
when the word names nothing by itself here (it is the head of several names, or of none alone),
and only when the names said before that end in it are of exactly one thing; else the word is
left as said (refused, never guessed)."""
from __future__ import annotations

from pipflow.household.language.names import per_index
from pipflow.household.language.tokens import PUNCT

#: determiners that point back at a thing said before
_DEFINITE = {"the", "that", "this"}


@per_index
def _names_by_last_word(index: dict) -> dict[str, list[tuple[str, ...]]]:
    """The home's names of two or more words, by their last word."""
    out: dict[str, list[tuple[str, ...]]] = {}
    for key in index:
        if len(key) > 1:
            out.setdefault(key[-1], []).append(key)
    return out


def named_again(words: list[str], index: dict, notes: list[str]) -> list[str]:
    """The words with each head word that points back (module docstring) replaced by the whole
    name it points back to. ``index``: the world's phrases
    (:func:`pipflow.household.language.names.world_phrases`)."""
    out: list[str] = []
    for k, w in enumerate(words):
        if k and words[k - 1] in _DEFINITE and w not in PUNCT and (w,) not in index \
                and (k + 1 == len(words) or (words[k + 1],) not in index):
            said = {key for key in _names_by_last_word(index).get(w, ()) if _said_in(key, words[:k - 1])}
            things = {tuple(sorted(r["name"] for r in index[key])) for key in said}
            if len(things) == 1:
                key = max(said, key=len)
                notes.append(f"'the {w}' read as the {' '.join(key)} said before")
                out += list(key)
                continue
        out.append(w)
    return out


def _said_in(key: tuple[str, ...], words: list[str]) -> bool:
    """Whether the phrase ``key`` is said in ``words``."""
    n = len(key)
    return any(tuple(words[j:j + n]) == key for j in range(len(words) - n + 1))

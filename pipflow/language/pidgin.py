"""Hawai'i Pidgin (Hawai'i Creole English) words, as typed in the islands ("put um on da counter",
"da rice stay all dry", "fo' Tutu", "no touch her lei"): each read as the English word the grammars
have. Read only in a command that uses a marker that is no English word (:data:`STRONG_MARKERS`) or
two markers (:data:`MARKERS`), so a single "stay" or "um" in English keeps its English reading ("the
keys stay on the table" keeps them there; "um" alone is a hesitation), and only where the word is no
name of the world's things alone.

Read by its grammar, not word for word: "stay" is "is" only after a subject and before how or what a
thing is ("stay all wrinkled", "stay charging", "stay on da table again"); after a modal or a
command ("can stay", "always stay", "stay in the kitchen") it is the English verb. "um" is "them"
after a verb or a preposition ("put um", "without um"); elsewhere a hesitation. "no" before a verb
is "do not" ("no touch um"), "no can" "can not"."""
from __future__ import annotations

from typing import Callable

#: Pidgin word -> the English word; "stay", "um" and "no" depend on the words around them (:func:`english_of`)
PIDGIN = {"da": "the", "fo": "for", "wit": "with", "dat": "that", "dis": "this", "mo": "more", "afta": "after",
          "bumbye": "later", "dem": "them"}
#: words that show a command is in Pidgin: two different ones and the words are read so
MARKERS = frozenset(PIDGIN) | {"stay", "um", "kine", "pau", "brah", "lidat", "buggah", "shoots"}
#: markers that are no English word: one alone is enough ("da" before a word: Vietnamese "da", yes,
#: stands alone before a comma, :func:`english_of`)
STRONG_MARKERS = frozenset({"da", "fo", "bumbye", "buggah", "lidat", "afta"})
#: words before "stay" that make it the English verb: a modal, "to", an order's opening, an adverb of
#: how often ("da remote can stay", "make it stay", "always stay open")
_VERB_STAY_AFTER = frozenset({"can", "could", "should", "must", "will", "would", "may", "might", "to", "let", "lets",
                              "gotta", "please", "just", "and", "then", "you", "u", "always", "never", "not", "no",
                              "dont", "make", "it", "shall"})
#: words after "stay" that say how a thing is ("stay all wrinkled", "stay so hot", "stay full of sand")
_HOW_IT_IS = frozenset({"all", "so", "too", "still", "full", "kinda", "real", "really", "pretty", "very", "stink",
                        "super", "mad", "way"})
#: words after "stay" that say where a thing is; "is" only with "again", "already" or "still" in its
#: clause ("stay on da table again": it is there; "the keys stay on the table" may be an order)
_WHERE = frozenset({"on", "in", "at", "by", "inside", "outside", "under", "upstairs", "downstairs", "out", "over"})
_ALREADY = frozenset({"again", "already", "still"})
#: prepositions after which "um" is "them" ("without um", "out of um")
_BEFORE_THEM = frozenset({"of", "with", "without", "for", "on", "in", "from", "to", "at", "by", "fo", "wit"})
#: verbs after "no" for which "no" is "do not" besides the domain's (``verb``)
_NO_VERBS = frozenset({"like", "need", "want", "forget", "touch", "eat", "go", "move", "let", "use", "throw", "leave"})
#: a word read together with the one before it ("no can": "can not"), which has none of its own
SAID_BEFORE = ""
#: where a clause ends
_ENDS = frozenset({",", ".", ";", ":", "!", "?"})


def english_of(words: list[str], known: Callable[[str], bool], verb: Callable[[str], bool]) -> list[str | None]:
    """The English of each word of a command in Hawai'i Pidgin (None: read as typed), in a command
    that uses two of :data:`MARKERS` or one of :data:`STRONG_MARKERS`; never of a word that is a
    name of the world's things alone (``known``). ``verb(word)``: whether a word is a verb of the
    domain's orders (module docstring); :data:`SAID_BEFORE` for a word read with the one before it."""
    said = {w for w in words if not known(w)}
    out: list[str | None] = [None] * len(words)
    if len(MARKERS & said) < 2 and not STRONG_MARKERS & said:
        return out
    for k, w in enumerate(words):
        if known(w):
            continue
        before = words[k - 1] if k else "."
        nxt = words[k + 1] if k + 1 < len(words) else "."
        if w == "stay":
            out[k] = "is" if _is_stay(words, k) else None
        elif w == "um":
            out[k] = "them" if k and (verb(before) or before in _BEFORE_THEM) else None
        elif w == "no" and nxt == "can":   # "no can get up"
            out[k], out[k + 1] = "can not", SAID_BEFORE
        elif w == "no" and (verb(nxt) or nxt in _NO_VERBS):
            out[k] = "do not"
        elif w == "da" and nxt in _ENDS:   # "da," alone is no article (Vietnamese "da": yes)
            continue
        elif w in PIDGIN:
            out[k] = PIDGIN[w]
    return out


def _is_stay(words: list[str], k: int) -> bool:
    """Whether "stay" at ``k`` is Pidgin's "is" (module docstring)."""
    if not k or words[k - 1] in _ENDS or words[k - 1] in _VERB_STAY_AFTER or k + 1 >= len(words):
        return False
    nxt = words[k + 1]
    if nxt in _HOW_IT_IS or (nxt.endswith("ing") and len(nxt) > 5):
        return True
    if nxt in _WHERE:
        end = next((j for j in range(k + 1, len(words)) if words[j] in _ENDS), len(words))
        return any(w in _ALREADY for w in words[k + 1:end])
    return False

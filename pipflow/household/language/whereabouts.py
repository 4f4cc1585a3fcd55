"""Where the speaker says they are, as where "me" is (issue 23's eleventh round).

"I'm sat in my chair, bring me the butter": the home model has no person, so "bring me X" has
no place to go; the clause that says where the speaker is gives it one. The clause is read as
that place and set aside (said in the notes), and each "bring me" / "fetch me" after it is read
as "bring ... to <that place>". Only a clause that is nothing but where the speaker is ("I am",
words of posture or time, a preposition of place, a place of the home) is read so; anything else
in it leaves the command as it was, to be read or refused whole.
"""
from __future__ import annotations

from pipflow.household.language.lexicon import PHRASES
from pipflow.household.language.tokens import PUNCT

#: words between "I am" and where: posture and time ("I'm sat here in my chair", "I'm just on the sofa")
POSTURE = {"sat", "sitting", "lying", "stood", "standing", "settled", "here", "there", "now", "just", "still",
           "over", "back", "all", "comfy", "down", "up", "curled"}
#: prepositions of where the speaker is
AT = {"in", "on", "at", "by", "beside", "next"}
#: what may come between the preposition and the place ("to him in his easy chair": a third
#: person's own place)
DETERMINERS = {"my", "the", "our", "to", "his", "her", "their"}
#: verbs that take "me" as where the thing goes
BRING = {"bring", "fetch", "get", "hand", "pass", "carry"}


#: words that open a negated order after a joining word ("... but do not touch the labneh")
_NEGATED_ORDER = frozenset({"do", "dont", "never", "not", "please"})


def clause_end(words: list[str], k: int) -> int:
    """Where the clause at ``k`` ends: a mark, or a joining word ("and", "then", "but" and their
    synonyms of the lexicon) before a verb of the lexicon or a negated order."""
    for j in range(k, len(words)):
        if words[j] in PUNCT:
            return j
        if PHRASES.get((words[j],), ("",))[0] in ("AND", "THEN", "BUT") and j + 1 < len(words) and (
                str(PHRASES.get((words[j + 1],), ("",))[0]).startswith("V") or words[j + 1] in _NEGATED_ORDER):
            return j
    return len(words)


def _speaker_place(words: list[str], i: int, index: dict) -> tuple[int, list[str]] | None:
    """(end of the clause, the words of the place) of a clause at ``i`` that says only where the
    speaker is, or None."""
    if words[i:i + 2] != ["i", "am"] or (i and words[i - 1] not in PUNCT and words[i - 1] not in ("and", "so")):
        return None
    return place_said(words, i + 2, index)


def place_said(words: list[str], j: int, index: dict, posture: frozenset[str] = frozenset(POSTURE)) \
        -> tuple[int, list[str]] | None:
    """(end of the clause, the words of the place) where the words from ``j`` on are only where
    someone is: words of ``posture``, a preposition of place, a place of the home, to the clause's
    end; else None. Shared by "I am ..." here and a third person's whereabouts (:mod:`.people`)."""
    while j < len(words) and words[j] in posture:
        j += 1
    if j >= len(words) or words[j] not in AT:
        return None
    k = j + 1
    while k < len(words) and words[k] in DETERMINERS:
        k += 1
    n = max((n for n in range(1, min(5, len(words) - k + 1))   # a place that ends the command too
             if any(r["kind"] == "place" for r in index.get(tuple(words[k:k + n]), []))), default=0)
    end = k + n
    while end < len(words) and words[end] in posture:
        end += 1
    if not n or (end < len(words) and words[end] not in PUNCT and words[end] != "and"):
        return None
    return end, words[k:k + n]


def to_me_there(words: list[str], index: dict, notes: list[str]) -> list[str]:
    """ "bring it through to me on the armchair", "fetch the mug to me in the kitchen": where the
    speaker is, said after "to me", is where the thing goes ("to the armchair"). Only where a
    place of the home follows the preposition and ends the clause (:func:`place_said`)."""
    out: list[str] = []
    k = 0
    while k < len(words):
        if words[k:k + 2] == ["to", "me"] and k and words[k - 1] not in PUNCT \
                and place_said(words, k + 2, index, frozenset()) is not None:
            notes.append(f"'to me {words[k + 2]}': to where you are")
            out.append("to")
            k += 3
            continue
        out.append(words[k])
        k += 1
    return out


def me_as_where_the_speaker_is(words: list[str], index: dict, notes: list[str]) -> list[str]:
    """The words with the clause of where the speaker is set aside and each "bring me X" after it
    read as "bring X to <there>" (module docstring); unchanged where no "bring me" follows. "to
    me on the P" is "to the P" first (:func:`to_me_there`)."""
    words = to_me_there(words, index, notes)
    for i in range(len(words)):
        found = _speaker_place(words, i, index)
        if found is None:
            continue
        end, place = found
        after = words[end:]
        if not any(w in BRING and after[k + 1:k + 2] == ["me"] for k, w in enumerate(after)):
            continue
        out: list[str] = []
        k = 0
        while k < len(after):
            if after[k] in BRING and after[k + 1:k + 2] == ["me"]:
                stop = clause_end(after, k + 2)
                out += [after[k]] + after[k + 2:stop] + ["to", "the"] + place
                k = stop
                continue
            out.append(after[k])
            k += 1
        while out and out[0] in (",", "and", "so"):
            out.pop(0)
        notes.append(f"'{' '.join(words[i:end])}': where you are; 'me' read as the {' '.join(place)}")
        return words[:i] + out
    return words

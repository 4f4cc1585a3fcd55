"""What the speaker cannot see, said as the reason for wanting light ("it's so dark in here I can't
see a thing", "I can hardly see my hand in front of my face", "so dark in the kitchen, can't even
see where I'm going"): talk, set aside, as other clauses that name nothing of the home are
(:mod:`.setaside`). What cannot be seen names nothing here, has no number and no operative word;
"I can't see the paper", where the paper is a thing of the home, is left to the grammar, which
reads it as the cue it is."""
from __future__ import annotations

from typing import Callable

from pipflow.household.language.lexicon import LIGHT_CUES, PHRASES
from pipflow.language.asides import EXCLUSIVITY, NEGATION, Clause

#: "can not", "can hardly", "could barely" ...: the lexicon's words for not being able to
_CANNOT = sorted((k for k, (cls, _) in PHRASES.items() if cls == "CANNOT"), key=len, reverse=True)
_SUBJECTS = {"i", "we"}
_BETWEEN = {"even", "really", "properly", "actually"}   # "I can't even see ..."
_SEEING = {"see", "read"}
_LIGHT_CUE_WORDS = frozenset(cue.split()[-1] for cue in LIGHT_CUES)   # "pitch dark": "dark"
#: what may never be set aside (:mod:`pipflow.language.asides`): what cannot be seen names nothing
#: of the home, so its quantities and selections ("a thing", "anything", "where I'm going") select
#: nothing; a negation or "only" may still bear on an order, but a "nothing" seen does not
_BEARING = (NEGATION | EXCLUSIVITY) - {"nothing"}


def _seeing_at(words: tuple[str, ...], k: int) -> int:
    """The index after "see" of a "(I) can't (even) see" said from ``k``, or 0."""
    j = k + (words[k] in _SUBJECTS)
    said = next((c for c in _CANNOT if words[j:j + len(c)] == c), None)
    if said is None:
        return 0
    j += len(said)
    j += j < len(words) and words[j] in _BETWEEN
    return j + 1 if j < len(words) and words[j] in _SEEING else 0


def unseen(kept: list[Clause], names: Callable[[str], bool]) -> list[Clause]:
    """Of each clause, what the speaker says cannot be seen, where it names nothing of the home
    (``names``: a word of the home's names, a slip of one, or a number) and bears on no order: the
    words after "see"; or the whole "I can't see ..." where a cue for light comes before it in the
    clause ("it's so dark in here I can't see a thing": the reason for the cue said first)."""
    out: list[Clause] = []
    for c in kept:
        ws = c.words
        for k in range(len(ws)):
            after = _seeing_at(ws, k)
            if not after or (k and ws[k - 1] in _SUBJECTS):
                continue
            rest = ws[after:]
            if any(names(w) or w in _BEARING for w in rest):
                break
            if k and _LIGHT_CUE_WORDS & set(ws[:k]):
                out.append(Clause(c.start + k, c.end, ws[k:]))
            elif rest and ws[k] in _SUBJECTS:
                out.append(Clause(c.start + after, c.end, rest))
            break
    return out

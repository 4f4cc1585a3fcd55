"""A self-correction inside a sentence ("get the quilt, sorry, the wool blanket out of the box",
"put the mug in the sink, I mean the cupboard"): the noun phrase after the marker replaces the
last noun phrase before it (docs/household.md, "homely English"). Without this, the marker is
talk set aside and both things would be read (a misreading).

Only between commas (or a comma before and a determiner after; or, for "I mean", "no wait",
after a sentence's end: :data:`ACROSS_SENTENCES`), only when the words after the
marker open with a determiner and the clause before has one, or open with a preposition of place
and the clause before has one (the place is taken back: "put the scrubs in the sink - no wait
sorry, on the boot bench"); "no" alone is never a marker here (it is a negation, operative), only
with "wait", "sorry", "hold on" or "hang on".

A whole order taken back ("turn the wireless down - nay, turn it off", "put the mug on the table,
no, put it in the sink"): after a marker of taking back between commas (:data:`TAKING_BACK`, "no"
alone too, as it stands there between commas before an order), a clause that opens with a verb
replaces the clause before the marker, and its "it" / "them" is the first thing that clause
named. Never where the new clause adds ("no, also ...", "... too"): both are then read."""
from __future__ import annotations

from pipflow.household.language.lexicon import ORDER_VERB_WORDS
from pipflow.household.language.tokens import PUNCT

#: words that take back the noun phrase just said
MARKERS = (("no", "wait", "sorry"), ("no", "sorry", "i", "mean"), ("sorry", "i", "mean"), ("no", "wait"),
           ("no", "sorry"), ("wait", "sorry"), ("sorry", "no"), ("or", "rather"), ("i", "mean"), ("i", "meant"),
           ("sorry",), ("rather",),
           # "no, hold on", "hang on": the speaker stops and says it again
           *((*no, hold, "on") for no in ((), ("no",)) for hold in ("hold", "hang")))
#: markers that take back what was said even across a sentence's end ("put my slippers in the
#: wardrobe. I mean on the shoe rack!"); "sorry" or "rather" alone opening a sentence may begin
#: anything, so only these
ACROSS_SENTENCES = {("i", "mean"), ("i", "meant"), ("no", "wait"), ("no", "wait", "sorry"), ("sorry", "i", "mean"),
                    ("no", "sorry", "i", "mean"), ("no", "hold", "on"), ("no", "hang", "on"), ("no", "sorry")}
#: the words after "no" that make it a marker
_AFTER_NO = {m[1] for m in MARKERS if m[:1] == ("no",) and len(m) > 1}
#: the marks a sentence ends with
_ENDS = {".", "!", "?", ";"}
#: words that open where a thing goes: a correction that opens with one takes back the place said
#: last ("in the sink - no wait sorry, on the boot bench")
PLACE_PREPOSITIONS = {"in", "on", "into", "onto", "inside", "to", "under"}
#: words that open a noun phrase
DETERMINERS = {"the", "a", "an", "my", "our", "your", "that", "this", "those", "these", "some", "his", "her"}


def corrected(words: list[str], notes: list[str]) -> list[str]:
    """The words with each self-correction (module docstring) made: the noun phrase before the
    marker, from its determiner to the comma, gives way to the words after the marker."""
    words = _no_said_once(words)
    out: list[str] = []
    k = 0
    while k < len(words):
        marker = next((m for m in MARKERS if k and (words[k - 1] == "," or words[k - 1] in _ENDS and m in ACROSS_SENTENCES)
                       and tuple(words[k:k + len(m)]) == m), None)
        if marker is not None:
            after = k + len(marker) + (1 if k + len(marker) < len(words) and words[k + len(marker)] == "," else 0)
            place = after < len(words) and words[after] in PLACE_PREPOSITIONS
            said = len(out)
            while said and out[said - 1] in PUNCT:   # the marks before the marker ("... no, sorry")
                said -= 1
            start = _last_opened_by(out[:said], PLACE_PREPOSITIONS if place else DETERMINERS)
            if after < len(words) and (place or words[after] in DETERMINERS) and start is not None:
                taken = " ".join(out[start:said])
                notes.append(f"'{taken}, {' '.join(marker)}': a self-correction; read as what follows it")
                out = out[:start]
                k = after
                continue
        out.append(words[k])
        k += 1
    return out


def _no_said_once(words: list[str]) -> list[str]:
    """ "no, no, sorry, on the dressing table", "no no wait": a "no" said again is one "no", and a
    comma between it and the word that makes it a marker ("no, sorry") is none."""
    out: list[str] = []
    for w in words:
        if w == "no" and (out[-1:] == ["no"] or out[-2:] == ["no", ","]):
            out = out[:-1] if out[-1] == "," else out
            continue
        if w in _AFTER_NO and out[-2:] == ["no", ","]:
            out = out[:-1]
        out.append(w)
    return out


def _last_opened_by(words: list[str], openers: set[str]) -> int | None:
    """Where the last phrase of the clause being read opens (its determiner, or its preposition of
    place), or None."""
    for j in range(len(words) - 1, -1, -1):
        if words[j] in PUNCT:
            return None
        if words[j] in openers:
            return j
    return None


#: markers that take back a whole order when a verb follows them (module docstring)
TAKING_BACK = (("no", "wait"), ("no", "actually"), ("scratch", "that"), ("no",), ("nay",), ("nope",), ("actually",),
               ("wait",))
#: words that make the new clause an addition, not a replacement
_ADDING = {"also", "too", "and", "plus", "again"}


def orders_taken_back(words: list[str], index: dict, notes: list[str]) -> list[str]:
    """The words with each order taken back whole (module docstring) left out. ``index``: the
    home's phrases (:func:`~.names.world_phrases`), for what the old order named."""
    k = 0
    while k < len(words):
        marker = next((m for m in TAKING_BACK if k and words[k - 1] == "," and tuple(words[k:k + len(m)]) == m), None)
        after = k + len(marker) + 1 if marker else 0
        if marker is None or words[after - 1:after] != [","] or after >= len(words) or words[after] not in ORDER_VERB_WORDS:
            k += 1
            continue
        end = next((j for j in range(after, len(words)) if words[j] in PUNCT), len(words))
        start = max((j + 1 for j in range(k - 1) if words[j] in PUNCT), default=0)
        old, new = words[start:k - 1], words[after:end]
        if not old or old[0] not in ORDER_VERB_WORDS or set(new) & _ADDING:
            k += 1
            continue
        thing = next((old[a:b] for a in range(len(old)) for b in range(len(old), a, -1) if tuple(old[a:b]) in index), None)
        pronoun = next((j for j, w in enumerate(new) if w in ("it", "them")), None)
        if pronoun is not None and thing is not None:
            new = new[:pronoun] + ["the", *thing] + new[pronoun + 1:]
        notes.append(f"'{' '.join(old)}, {' '.join(marker)}': taken back; read as '{' '.join(new)}'")
        words = words[:start] + new + words[end:]
        k = start + len(new)
    return words

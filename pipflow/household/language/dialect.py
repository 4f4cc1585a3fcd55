"""Dialect words read as the standard English the grammar is written in, each by a rule that holds
in any home (docs/household.md, "dialect"): "them" before the name of a thing is the
demonstrative "those" ("them tea things want washing", northern and Scots English). A note says
what was read so."""
from __future__ import annotations

from pipflow.household.language.tokens import PUNCT

#: verbs that take two objects ("bring them tea", "get them cups": for them): after one, "them"
#: may be who the thing is for, so it is not read as "those" (the command is refused, not guessed)
TWO_OBJECT_VERBS = {"give", "bring", "get", "fetch", "hand", "pass", "make", "send", "take", "show", "buy", "pour",
                    "find", "cook", "fix", "leave", "grab", "heat", "warm", "do", "serve", "lend", "set", "save"}


def them_as_those(words: list[str], index: dict, notes: list[str]) -> list[str]:
    """The words with "them" read as "those" where a name of the home follows it at once ("wash
    them mugs", "them tea things on the table"): as a pronoun, "them" is never followed by a noun.
    ``index``: the world's phrases (:func:`pipflow.household.language.names.world_phrases`)."""
    firsts = {k[0] for k in index}
    out: list[str] = []
    for k, w in enumerate(words):
        nxt = words[k + 1] if k + 1 < len(words) else "."
        before = out[-1] if out else "."
        if w == "them" and nxt not in PUNCT and nxt in firsts and before not in TWO_OBJECT_VERBS:
            notes.append(f"'them {nxt}' read as 'those {nxt}' (dialect)")
            w = "those"
        out.append(w)
    return out


#: the particles that make "cut" a switch ("cut the light off", "cut on the fan": American South)
_SWITCH_PARTICLES = {"on", "off"}
#: what may follow "cut X on" for it to be a switch: the clause ends there
_CLAUSE_END = set(PUNCT) | {"and", "then", "first", "please", "now", "for", "too", "again"}


def cut_as_switch(words: list[str], world: dict, index: dict, notes: list[str]) -> list[str]:
    """The words with "cut" read as "switch" where a thing that switches, or "it" / "them", and
    then "on" or "off" follow it ("cut that kitchen light off", "cut it on first"), or "on" /
    "off" and then such a thing ("cut off the fan"): a knife is never "cut ... on", and what
    switches is no thing to slice. A thing that does not switch keeps "cut" as slicing."""
    def switches(k: int) -> int:
        """The index after a phrase at ``k`` naming only things that switch, else 0."""
        for end in range(min(len(words), k + 5), k, -1):
            things = index.get(tuple(words[k:end])) or []
            entries = [(world.get("objects") or {}).get(t["name"]) or (world.get("places") or {}).get(t["name"]) or {}
                       for t in things if t["kind"] in ("object", "place")]
            if entries and all("toggleable" in (e.get("properties") or []) for e in entries):
                return end
        return 0
    out = list(words)
    for k, w in enumerate(words):
        if w != "cut":
            continue
        j = k + 1 + (words[k + 1:k + 2] in (["the"], ["that"], ["this"], ["my"], ["those"], ["them"]))
        if words[k + 1:k + 2] and words[k + 1] in _SWITCH_PARTICLES:   # "cut off the fan"
            j = k + 2 + (words[k + 2:k + 3] in (["the"], ["that"], ["my"], ["all"]))
            end = switches(j) and k + 1
        else:   # "cut the light off", "cut it on": the particle ends the clause ("cut it on the board" slices)
            end = k + 2 if words[k + 1:k + 2] in (["it"], ["them"]) else switches(j)
            if end and words[end + 1:end + 2] and words[end + 1] not in _CLAUSE_END:
                end = 0
        if end and words[end:end + 1] and words[end] in _SWITCH_PARTICLES:
            out[k] = "switch"
            notes.append(f"'cut ... {words[end]}' read as 'switch ... {words[end]}' (dialect)")
    return out

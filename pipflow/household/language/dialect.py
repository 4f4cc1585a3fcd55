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

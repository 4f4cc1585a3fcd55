"""A sentence's goods said again at its end as "just the X" ("swap the cement on P and Q, just the
cement", "move the rice from P to Q, only the rice"): the order already names only X, so the last
clause narrows nothing and is set aside (said so in the echo). Where the sentence names other goods
too ("swap P and Q, just the cement") it narrows what the order does, and is left to be read or
refused as said."""
from __future__ import annotations

from pipflow.warehouse.language.names import Tok

#: words that say only the goods named are meant
_JUST = frozenset({"just", "only"})
#: words that may close such a clause
_CLOSING = frozenset({"please", "pls", "plz"})
#: marks that end a sentence
_ENDS = frozenset({".", ";", "!", "?"})


def item_scope_restated(toks: list[Tok]) -> tuple[list[Tok], list[str]]:
    """The tokens without each clause that says a sentence's only goods again (module docstring),
    and the words of those clauses, to be said as set aside."""
    out: list[Tok] = []
    said: list[str] = []
    start = 0   # where the sentence being read opens in ``out``
    k = 0
    while k < len(toks):
        t = toks[k]
        comma = t.kind == "punct" and t.value == ","
        end = _restating_clause_end(toks, k, out[start:]) if comma else None
        if end is not None:
            said.append(" ".join(x.text for x in toks[k + 1:end] if x.text))
            k = end
            continue
        out.append(t)
        if t.kind == "punct" and t.value in _ENDS:
            start = len(out)
        k += 1
    return out, said


def _restating_clause_end(toks: list[Tok], k: int, before: list[Tok]) -> int | None:
    """Where a clause that opens with the comma at ``k`` and says the goods of ``before`` (the
    sentence so far) again ends (the index of the sentence's end), or None."""
    j = k + 1
    if j >= len(toks) or toks[j].kind != "word" or toks[j].value not in _JUST:
        return None
    j += 1
    if j < len(toks) and toks[j].kind == "word" and toks[j].value == "the":
        j += 1
    if j >= len(toks) or toks[j].kind != "name" or toks[j].of != "product":
        return None
    item = toks[j].value
    j += 1
    while j < len(toks) and toks[j].kind == "word" and toks[j].value in _CLOSING:
        j += 1
    if j < len(toks) and not (toks[j].kind == "punct" and toks[j].value in _ENDS):
        return None
    goods = {t.value for t in before if t.kind == "name" and t.of == "product"}
    return j if goods == {item} else None

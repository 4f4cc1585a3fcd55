"""Noun phrases said in the order of Spanish, Portuguese, French and Italian.

Where a thing is, said with "of" as those languages say it ("the dishes of the dining table", "the
ruana of the sofa to our bed": "los platos de la mesa", "la ruana del sofá"): the place a thing lies
in or on, named after it with "of", read as the where English says. In a move that then says where
to ("to" after the place, or "in" / "on" after a verb of moving), the place is where the thing comes
from ("take the ruana of the sofa to our bed": from the sofa); elsewhere it is where the thing is
("wash the dishes of the dining table": on it). Only after a name of a thing or a category of the
home and before a place that holds things, and never inside a name the home itself has ("the bed of
sofia", "the light of the dining"): "the ruana of my mother" (a person) keeps its "of".

An adjective of colour or of dirt said after the thing ("the dishes dirty of the table", "the towels
white in the line": "los platos sucios") is read before it, where English says it, only where a
where or a relative clause follows it in the noun phrase, and never where the clause's verb could
make the thing so or keep it so ("wash the plates clean in the sink", "leave the cups dirty"):
there the adjective may be what the verb does, and it stays as said."""
from __future__ import annotations

from pipflow.household.language.names import longest_name
from pipflow.household.language.rewrites import PLACING, clause_before

#: verbs of moving a thing from one place to another (with :data:`PLACING`)
_MOVING = PLACING | {"take", "bring", "carry", "move", "get", "fetch", "pass", "hang"}
#: adjectives read before the thing when said after it: colours, and dirt
_ADJECTIVES = {"dirty", "clean", "white", "black", "red", "blue", "green", "yellow", "pink", "grey", "gray", "brown",
               "orange", "purple"}
#: what follows such an adjective inside the noun phrase: a where, or a relative clause
_MODIFIERS = {"of", "that", "which", "from", "in", "on"}
#: verbs that may make a thing what the adjective says, or keep it so, or say how it is handed
#: ("wash the plates clean", "leave the cups dirty", "paint the box blue"): the adjective stays
_RESULTS = {"wash": {"clean"}, "wipe": {"clean"}, "rinse": {"clean"}, "scrub": {"clean"}, "clean": {"clean"}}
_HOLDING = {"leave", "keep", "make", "get", "let", "have", "want", "need", "like", "find", "serve", "paint", "dye",
            "colour", "color", "turn", "set"}
#: words that say where to after the place the thing comes from
_WHERE_TO = {"to", "in", "into", "on", "onto", "inside", "back"}


def of_as_where(words: list[str], world: dict, index: dict, notes: list[str]) -> list[str]:
    """The words with "of" before a place that holds things, after the name of a thing or category,
    read as "from" (in a move that says where to after it) or "in" (module docstring)."""
    places = world.get("places") or {}
    longest = longest_name(index)
    out = list(words)
    for k, w in enumerate(words):
        if w != "of" or not k:
            continue
        j = k + 1 + (words[k + 1:k + 2] == ["the"])
        n = _receptacle_at(words, j, index, places, longest)
        thing = next((a for a in range(max(0, k - longest), k) if _names_things(index, words[a:k])), None)
        if not n or thing is None or any(tuple(words[a:j + n]) in index for a in range(max(0, k - longest), k)):
            continue
        after = words[j + n] if j + n < len(words) else "."
        # "... of P to Q" moves it (said with no verb too: "the towel of the bed to the washer");
        # "... of P in Q" only after a verb of moving ("wash the cup of the sink in ..." is no move)
        moving = after in ("to", "into") or after in _WHERE_TO and any(x in _MOVING for x in clause_before(words[:k]))
        said = "from" if moving else "in"
        out[k] = said
        notes.append(f"'{' '.join(words[thing:j + n])}' read with '{said}' for 'of' (where it is, as Spanish "
                     f"'de' says it)")
    return out


def _receptacle_at(words: list[str], j: int, index: dict, places: dict, longest: int) -> int:
    """How many words at ``j`` name one place that holds things (0 if none)."""
    for n in range(min(longest, len(words) - j), 0, -1):
        refs = index.get(tuple(words[j:j + n])) or []
        if refs and all(r["kind"] == "place" and "receptacle" in (places.get(r["name"], {}).get("properties") or [])
                        for r in refs):
            return n
    return 0


def _names_things(index: dict, words: list[str]) -> bool:
    """Whether the words name objects or a category of the home."""
    refs = index.get(tuple(words)) or []
    return bool(refs) and all(r["kind"] in ("object", "category") for r in refs)


def adjective_after(words: list[str], index: dict, notes: list[str]) -> list[str]:
    """The words with an adjective of colour or dirt said after the name of a thing read before it
    (module docstring)."""
    longest = longest_name(index)
    out = list(words)
    for k in range(1, len(words) - 1):
        adjective = words[k]
        if adjective not in _ADJECTIVES or words[k + 1] not in _MODIFIERS:
            continue
        # the thing: its name, or the home's name with the adjective before it ("mug blue": the blue mug)
        head = next((a for a in range(max(0, k - longest), k)
                     if _names_things(index, words[a:k]) or _names_things(index, [adjective, *words[a:k]])), None)
        if head is None or any(tuple(words[a:k + 1]) in index for a in range(max(0, k - longest), k)):
            continue   # "the cup blue" the home names so: read as its name
        verbs = clause_before(out[:head])
        if any(v in _HOLDING or adjective in _RESULTS.get(v, ()) for v in verbs):
            continue
        out[head:k + 1] = [adjective, *out[head:k]]
        notes.append(f"'{' '.join(words[head:k + 1])}' read as '{adjective} {' '.join(words[head:k])}' "
                     f"(the adjective after the thing)")
    return out

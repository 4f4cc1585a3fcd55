"""Orders on a condition of the home as it is now: "if the porch light's still on, switch it off",
"switch the heater on if it's off", "If the cup is dirty, wash it". "If not, ..." and
"otherwise, ..." after one read it the other way.

A condition names one thing of the home and a state it can be in (on, off, open, closed, dirty,
clean, hot, cold, sliced, whole) or the place it is in ("if the mug is in the sink"), and is read
against the home as it is when the command is given:

- it holds: the order is read, its "it" / "them" the thing of the condition (unless the order
  names a thing before the pronoun, which is then what the pronoun means, as anywhere);
- it does not hold: the order is not read.

The echo says which, and why. A condition that names no thing, several things, or a state the thing
cannot be in is left as said, and the command is refused as before: never a guess.
"""
from __future__ import annotations

from typing import NamedTuple

from pipflow.errors import TranslationError
from pipflow.household.language.dialect import patois_in_home
from pipflow.household.language.lexicon import words_of
from pipflow.household.language.names import world_phrases
from pipflow.household.language.restated import AT, BE, DETERMINERS

#: state words of a condition -> (the state key, the value that makes it hold)
STATES = {"on": ("on", True), "off": ("on", False), "open": ("open", True), "closed": ("open", False),
          "shut": ("open", False), "dirty": ("dirty", True), "clean": ("dirty", False), "hot": ("hot", True),
          "warm": ("hot", True), "cold": ("hot", False), "sliced": ("sliced", True), "whole": ("sliced", False),
          # a light or a fire "still burning", a lamp "lit", a machine "running" or "going": on
          "burning": ("on", True), "lit": ("on", True), "running": ("on", True), "going": ("on", True)}
#: the property a thing needs for a state key to be read of it
NEEDS = {"on": "toggleable", "open": "openable", "dirty": "washable", "hot": "heatable", "sliced": "sliceable"}
#: words between the thing and its state that say nothing of it ("is still on", "is already off")
_HEDGES = {"still", "already", "currently", "now", "left", "been", "switched", "turned"}
#: how a thing stands where it is, before that place ("if the pot is still sitting on the cooker")
_POSTURES = {"sitting", "lying", "standing", "sat", "sits", "lies", "stands", "hanging", "waiting"}
#: words before a thing's name; "them" too, as dialect says it ("if them socks are dirty")
_DETERMINERS = DETERMINERS | {"them"}
_PRONOUNS = {"it", "them"}
_ENDS = {".", "!", "?", ";"}
#: how an order on the other branch of the last condition opens
_ELSE = (("if", "not"), ("if", "it", "is", "not"), ("if", "they", "are", "not"), ("otherwise",), ("else",),
         ("if", "it", "does", "not"), ("if", "not", "then"),
         # Scots "no" for not ("if its no, hang it up")
         ("if", "no"), ("if", "it", "is", "no"), ("if", "its", "no"), ("if", "they", "are", "no"))


class Condition(NamedTuple):
    """A condition read: the thing's words and name, whether it holds now, and how it was said."""

    words: tuple[str, ...]
    name: str
    holds: bool
    said: str


def conditions_read(command: str, world: dict, notes: list[str]) -> str:
    """The command with each order on a condition kept or left out as the condition holds now
    (module docstring), the condition itself dropped; unchanged when it has none that reads.
    Raises :class:`TranslationError` when no order is left: nothing is asked."""
    words = words_of(command)
    if "if" not in words and "otherwise" not in words:
        return command
    patois: list[str] = []   # "if di stove on, turn it off": the condition read in English
    words = patois_in_home(words, world_phrases(world), patois)
    sentences: list[list[str]] = [[]]
    for w in words:
        sentences[-1].append(w)
        if w in _ENDS:
            sentences.append([])
    out: list[list[str]] = []
    last: Condition | None = None
    changed = False
    for sentence in (part for s in sentences if s for part in _at_later_condition(s, world)):
        read = _conditional(sentence, world, last)
        if read is None:
            out.append(sentence)
            continue
        condition, order = read
        last = condition
        changed = True
        state = "holds" if condition.holds else "does not hold"
        if condition.holds:
            out.append(order)
            notes.append(f"'{condition.said}' {state} now: '{' '.join(w for w in order if w not in _ENDS)}' is read")
        else:
            said = " ".join(w for w in order if w not in _ENDS)
            if any(w in (",", "then") for w in order):
                # "if the hob is on turn it off, then put the kettle on": whether the condition
                # reaches past the first clause is not said, and it decides what is done
                raise TranslationError(f"'{condition.said}' does not hold now, and it is not clear whether "
                                       f"it governs all of '{said}' or only its first part: say it in two sentences")
            notes.append(f"'{condition.said}' {state} now: '{said}' is not done")
    if not changed:
        return command
    notes[:0] = patois
    left = [w for s in out for w in s]
    if not [w for w in left if w not in _ENDS and w != ","]:
        raise TranslationError(f"{command.strip()!r} asks nothing now: " + "; ".join(notes[-2:]))
    return " ".join(left)


def _at_later_condition(sentence: list[str], world: dict) -> list[list[str]]:
    """The sentence split where a condition opens a later part of it ("put the pills away and if
    the telly's still on, switch it off"): what comes before is said without condition, what
    follows on it, as two sentences would say. Only where "and" or a comma comes before "if" and
    a condition of the home reads after it with an order after that; else the sentence as it is."""
    for k in range(2, len(sentence) - 1):
        if sentence[k] != "if" or sentence[k - 1] not in ("and", ","):
            continue
        read = _condition(sentence[k + 1:], world)
        if read is not None and [w for w in sentence[k + 1 + read[1]:] if w not in (",", "then", *_ENDS)]:
            first = sentence[:k - 1]
            first = first[:-1] if first[-1:] == [","] else first
            return [first + ["."], sentence[k:]]
    return [sentence]


def _conditional(sentence: list[str], world: dict, last: Condition | None) -> tuple[Condition, list[str]] | None:
    """(the condition, the order) of a sentence that is an order on a condition, else None."""
    end = sentence[-1:] if sentence[-1] in _ENDS else []
    body = sentence[:-1] if end else sentence
    while body[:1] in (["and"], ["but"], ["oh"], ["so"]) and "if" in body[1:3]:   # "And if the fire's on, ..."
        body = body[1:]
    for opener in _ELSE:
        if last is not None and tuple(body[:len(opener)]) == opener:
            rest = body[len(opener):]
            rest = rest[1:] if rest[:1] == [","] else rest
            if rest and not any(w == "if" for w in rest):
                flipped = Condition(last.words, last.name, not last.holds, " ".join(body[:len(opener)]))
                return flipped, _with_thing(rest, flipped, world) + end
    if body[:1] == ["if"]:
        # the condition ends where its state or place does, said with a comma or "then" after it
        # or not ("if the bathroom light's off turn it on")
        read = _condition(body[1:], world)
        if read is None:
            return None
        condition, n = read
        order = body[1 + n:]
        while order[:1] in ([","], ["then"]):
            order = order[1:]
    elif "if" in body and body.index("if") > 1:
        k = body.index("if")
        rest = [w for w in body[k + 1:] if w != ","]
        read = _condition(rest, world, before=body[:k])
        if read is None or read[1] != len(rest):
            return None
        condition = read[0]
        order = body[:k]
        order = order[:-1] if order[-1:] == [","] else order
    else:
        return None
    if not order:
        return None
    return condition, _with_thing(order, condition, world) + end


def _condition(words: list[str], world: dict, before: list[str] | None = None) -> tuple[Condition, int] | None:
    """A condition of one thing and a state or place at the head of ``words`` (module docstring),
    with the number of words it takes, else None. ``before``: the order said before a trailing
    condition, whose thing "it" may mean ("switch the heater on if it's off")."""
    k = 1 if words[:1] and words[0] in _DETERMINERS else 0
    found = _thing(words, k, world)
    if found is None and before is not None and words[:1] and words[0] in _PRONOUNS:
        named = [t for j in range(len(before)) if (t := _thing(before, j, world)) is not None]
        if len(named) != 1:
            return None
        found = (named[0][0], named[0][1], 1)
    if found is None:
        return None
    thing_words, name, k = found
    if words[k:k + 1] and words[k] in BE:
        k += 1
    elif not (words[k:k + 1] and (words[k] in _HEDGES or words[k] in STATES or words[k] in _POSTURES)):
        return None   # "is" may be left out ("if the water heater still on"), nothing else
    while k < len(words) and (words[k] in _HEDGES or (words[k] in _POSTURES and words[k + 1:k + 2]
                                                      and words[k + 1] in AT)):
        k += 1
    negated = words[k:k + 1] == ["not"]
    k += negated
    entry = (world.get("objects") or {}).get(name) or (world.get("places") or {}).get(name) or {}
    # "on" / "in" followed by a place is where the thing is ("if the laptop is on the couch"), never
    # its switch; without a place after it, "on" is the state ("if the laptop is still on")
    place = None
    if words[k:k + 1] and words[k] in AT and name in (world.get("objects") or {}):
        place = _thing(words, k + 2 if words[k + 1:k + 2] and words[k + 1] in _DETERMINERS else k + 1, world)
        place = place if place is not None and place[1] in (world.get("places") or {}) else None
    if place is not None:
        holds = entry.get("in") == place[1]
        k = place[2]
    elif k < len(words) and words[k] in STATES:
        key, value = STATES[words[k]]
        if NEEDS[key] not in (entry.get("properties") or []):
            return None   # "if the cup is on": a state it cannot be in is no condition read here
        holds = bool((entry.get("state") or {}).get(key, False)) == value
        k += 1
    else:
        return None
    return Condition(thing_words, name, holds != negated, "if " + " ".join(words[:k])), k


def _thing(words: list[str], k: int, world: dict) -> tuple[tuple[str, ...], str, int] | None:
    """(the words, the name, the index after them) of the longest phrase at ``k`` that names one
    object or place of the world; None when none does, or it names several."""
    index = world_phrases(world)
    for end in range(len(words), k, -1):
        things = index.get(tuple(words[k:end]))
        if things:
            named = {t["name"] for t in things if t["kind"] in ("object", "place")}
            return (tuple(words[k:end]), named.pop(), end) if len(named) == 1 and len(things) == 1 else None
    return None


def _with_thing(order: list[str], condition: Condition, world: dict) -> list[str]:
    """The order with its pronouns read as the condition's thing, unless it names a thing of its
    own before them (then "it" is that thing, as anywhere)."""
    out: list[str] = []
    for k, w in enumerate(order):
        if w in _PRONOUNS and not any(_thing(order, j, world) for j in range(k)):
            out += ["the", *condition.words]
        else:
            out.append(w)
    return out

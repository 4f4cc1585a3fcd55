"""Things named before their verb (topic first): "butter put in fridge", "kettle switch on", "the
veg from the worktop put where it belongs", and with a pronoun taking the thing up, "the mug, wash
it" (left dislocation).

Speakers of languages whose word order is free (Polish, Russian, and topic-first speech in any
language) name the thing first and then say what to do with it; in English the object follows its
verb. The grammar reads only that order, so a command that does not parse as said is tried again
(:mod:`~pipflow.household.language.parser`) with the things moved after the verb. Only where the
reading is one two people would agree on:

* the fronted words are a noun phrase of the home and nothing else (names of the home,
  determiners, quantities, state adjectives, "and", "from <place>", "on / in / at <place>" after a
  name, or "there" after it), ending in a name, and "also" or "too" may stand between them and the verb, or "don't"
  before a verb that keeps a thing as it is ("the luggage don't touch");
* they open a sentence, or a clause after ", and", or after a comma or "and" that does not follow
  a name (after one, the words could go on the clause before's list of things: "wash the jug and
  the plum put in the bowl" is refused);
* the verb comes at once after them, is one that takes a thing (and is no adjective as well:
  "jug clean" may say how the jug is), and lacks its object: what follows it is a particle, a
  place word or the clause's end, never a thing; with a pronoun, the clause is only the thing and
  a comma (or nothing: "the frigo close it", Italian "il frigo chiudilo"), and the pronoun is "it" or
  "them" at once after the verb (or after "on" / "off": "the radio, switch on it"), the thing
  opening its sentence.

Anything else is left as said, and refused as before.
"""
from __future__ import annotations

from pipflow.household.language.grammar import NOUN_DUAL, base_class
from pipflow.household.language.tokens import Tag

#: classes of the words of a noun phrase of the home ("all the dirty cups and the plate from the
#: table")
PHRASE = {"THE", "NOUN", "ADJ", "ALL", "EVERY", "BOTH", "NUM", "OF", "AND", "COMMA", "FROM"}
#: what a noun phrase may open with besides a name
OPENERS = {"THE", "ALL", "EVERY", "BOTH", "NUM", "ADJ"}
#: verbs that take a thing as their object, and are no adjective too ("clean", "open", "shut",
#: "warm" after a thing say how it is)
VERBS = {"V_PUT", "V_THROW", "V_TOGGLE", "V_STATE", "V_TRASH", "V_CHILL", "V_TIDY", "V_LIGHT", "V_SHUTDOWN",
         # "papa dumbbell keep in the bomb shelter" (Singapore English "keep": put away)
         "V_LEAVE"}
#: verbs that, said with "don't", keep a thing as it is ("the luggage don't touch")
NEGATED_VERBS = {"V_TOUCH", "V_LEAVE"}
#: where a thing of the fronted phrase lies, after its name ("the mug on the coffee table wash")
WHERE = {"ON", "IN", "AT"}
#: verbs that move a thing, and the words after them that say where to ("the doll on the sofa take to
#: her bed": where it lies is where it comes from)
MOVING = {"V_PUT", "V_THROW", "V_LEAVE"}
TARGETS = {"TO", "IN", "ON", "INTO", "ONTO"}
#: "as well" between the fronted phrase and its verb ("the mug also wash"): said after the thing
AS_WELL = {"also", "too"}
#: what may follow a verb whose object was fronted: a particle, a word of where, the clause's end
LACKING = {"ON", "OFF", "OUT", "IN", "TO", "AT", "BACK", "AWAY", "UP", "DOWN", "FROM", "SOMEWHERE",
           "END", "COMMA", "AND", "THEN",
           # "the lemon tree leave where it is", "the towels leave there"
           "STAY", "THERE"}
#: what ends the clause before: a fronted phrase opens a clause after one of these
BREAKS = {"END", "EXCL"}
#: particles of switching that may stand before a pronoun ("switch on it")
_TURNED = {"ON", "OFF"}
JOINS = {"COMMA", "AND", "THEN"}


def _named(t: Tag) -> bool:
    return t.cls == "NOUN" or t.cls.endswith(NOUN_DUAL)


def _opens(tags: list[Tag], k: int) -> bool:
    """Whether a fronted phrase may open at ``k`` (module docstring): a sentence's start, after
    ", and" (or ". And"), or after a comma or "and" that does not follow a name."""
    if k == 0 or tags[k - 1].cls in BREAKS:
        return True
    if tags[k - 1].cls not in JOINS:
        return False
    before = tags[k - 2] if k >= 2 else None
    if before is None or before.cls in BREAKS or (before.cls == "COMMA" and tags[k - 1].cls != "COMMA"):
        return True
    return not _named(before)


def _phrase_end(tags: list[Tag], k: int) -> int | None:
    """The end of the noun phrase of the home that opens at ``k`` (its last word a name), or None."""
    end = None
    j = k
    while j < len(tags):
        if end is not None and tags[j].cls in WHERE:   # "the mug on the coffee table wash"
            at = j + 1 + (j + 1 < len(tags) and tags[j + 1].cls == "THE")
            if at < len(tags) and _named(tags[at]):
                j = at
                continue
        if end == j and tags[j].cls == "THERE":   # "the mug there also wash": where the place said before is
            end = j = j + 1
            continue
        if not (base_class(tags[j].cls) in PHRASE or _named(tags[j])):
            break
        if _named(tags[j]):
            end = j + 1
        j += 1
    if end is None or not (_named(tags[k]) or tags[k].cls in OPENERS):
        return None
    return end


def _resumed(tags: list[Tag], j: int, phrase: list[Tag]) -> int:
    """How many tags from ``j`` take up the things of ``phrase`` again ("it", "them", "them all",
    "all of them", "both" of two things, "all three" of three); 0 where none do."""
    said = [t.words for t in tags[j:j + 3]]
    named = sum(_named(t) for t in phrase)
    if said[:3] == ["all", "of", "them"]:
        return 3
    if said[:2] == ["them", "all"]:
        return 2
    if said[:1] in (["it"], ["them"]) and tags[j].cls == "IT":
        return 1
    if said[:1] == ["both"] and named == 2:
        return 1
    if said[:1] == ["all"] and len(tags) > j + 1 and tags[j + 1].cls == "NUM" and tags[j + 1].value == named:
        return 2
    return 0


def _lacks_object(tags: list[Tag], v: int) -> bool:
    return v + 1 >= len(tags) or tags[v + 1].cls in LACKING


def _where_as_source(phrase: list[Tag]) -> list[Tag]:
    """The phrase with where its things lie ("the doll on the sofa") said as where they come from
    ("from the sofa"), for a verb of moving with where to after it ("the doll on the sofa take to
    her bed": take the doll from the sofa to her bed); where is only the last place of the phrase."""
    k = max((j for j, t in enumerate(phrase) if t.cls in WHERE), default=None)
    if k is None or not any(_named(t) for t in phrase[:k]):
        return phrase
    return phrase[:k] + [Tag("FROM", None, phrase[k].words)] + phrase[k + 1:]


def fronted_objects(tags: list[Tag]) -> tuple[list[Tag], list[str]] | None:
    """The tags with each thing named before its verb moved after the verb, and the words moved
    ("butter put" read as "put butter"); None when there is none (module docstring)."""
    out = list(tags)
    moved: list[str] = []
    k = 0
    while k < len(out):
        end = _phrase_end(out, k) if _opens(out, k) else None
        if end is None:
            k += 1
            continue
        phrase = out[k:end]
        words = " ".join(t.words for t in phrase)
        also = end < len(out) and out[end].words in AS_WELL   # "the mug also wash": as well
        v = end + also
        negated = v < len(out) and out[v].cls == "DONOT"      # "the luggage don't touch"
        v += negated
        takes = v < len(out) and (out[v].cls in VERBS or (negated and out[v].cls in NEGATED_VERBS))
        if takes and _lacks_object(out, v):
            said = " ".join(t.words for t in out[k:v + 1])
            if out[v].cls in MOVING and v + 1 < len(out) and out[v + 1].cls in TARGETS:
                phrase = _where_as_source(phrase)
            out[k:v + 1] = out[v - negated:v + 1] + phrase + out[end:end + also]
            moved.append(said)
        elif (takes and not negated and not also and v + 1 < len(out) and out[v + 1].cls == "IT"
              and out[v + 1].words in ("it", "them") and (k == 0 or out[k - 1].cls in BREAKS)
              and _lacks_object(out, v + 1)):
            # "The frigo close it after", "the pallone bring it to his bed" (Italian "il frigo chiudilo"):
            # the pronoun at once after the verb stands for the thing named first, as with a comma
            moved.append(f"{words} {out[v].words} {out[v + 1].words}")
            if out[v].cls in MOVING and v + 2 < len(out) and out[v + 2].cls in TARGETS:
                phrase = _where_as_source(phrase)
            out[k:v + 2] = [out[v]] + phrase
        elif (v + 2 < len(out) and out[v].cls == "COMMA" and out[v + 1].cls in VERBS
              and (n := _resumed(out, v + 2, phrase)) and (k == 0 or out[k - 1].cls in BREAKS)
              and _lacks_object(out, v + 1 + n)):
            # "the mug, wash it", "the mug and the plate, wash both": the pronoun stands for the
            # things named before
            moved.append(f"{words}, {out[v + 1].words} " + " ".join(t.words for t in out[v + 2:v + 2 + n]))
            out[k:v + 2 + n] = [out[v + 1]] + phrase
        elif (v + 3 < len(out) and out[v].cls == "COMMA" and out[v + 1].cls in VERBS and out[v + 2].cls in _TURNED
              and out[v + 3].cls == "IT" and out[v + 3].words in ("it", "them") and (k == 0 or out[k - 1].cls in BREAKS)
              and _lacks_object(out, v + 3)):
            # "the radio, switch on it": the particle said before the pronoun, as learners say it
            moved.append(f"{words}, {out[v + 1].words} {out[v + 2].words} {out[v + 3].words}")
            out[k:v + 4] = [out[v + 1], out[v + 2]] + phrase
        k = end
    return (out, moved) if moved else None


def topic_too(tags: list[Tag]) -> tuple[list[Tag], list[str]]:
    """The tags without the "too" of a thing named first, as well as the things before, whose verb
    comes later in its sentence with a pronoun for it: "The school bag too, it's on the settee,
    take it to the study desk" is the school bag, taken to the desk; not the verb before said again
    for it ("close the school bag"), which the clause's own verb contradicts. Only where a clause of
    that sentence opens with a verb that takes a thing, right after a comma, and "it" or "them"
    follows the verb at once; with "then" or "and" before it the clause is a further step, and
    "too" keeps its reading. Returns the tags and a note for each "too" so read."""
    out = list(tags)
    said: list[str] = []
    k = 0
    while k < len(out):
        end = _phrase_end(out, k) if (k == 0 or out[k - 1].cls in BREAKS) else None
        if end is None or end + 1 >= len(out) or out[end].cls != "TOO" or out[end + 1].cls != "COMMA":
            k += 1
            continue
        stop = next((j for j in range(end + 2, len(out)) if out[j].cls in BREAKS), len(out))
        verb = next((j for j in range(end + 1, stop - 2) if out[j].cls == "COMMA" and out[j + 1].cls in VERBS
                     and out[j + 2].cls == "IT" and out[j + 2].words in ("it", "them")), None)
        if verb is not None:
            said.append(f"'{' '.join(t.words for t in out[k:end + 1])}, ... {out[verb + 1].words} "
                        f"{out[verb + 2].words}': the thing named first, with its own verb later ('too': as well)")
            del out[end]
        k = end
    return out, said

"""The tagger's tokens rewritten where a token's class depends on its neighbours, which the grammar
would otherwise try at every noun of every command: a place word before a name of objects ("the
table lamp": the lamp on the table), a sentence that only restates an order, an action noun before
a name ("a clean mug"), "that" as a determiner ("that curry has gone off")."""
from __future__ import annotations

from pipflow.household.language.grammar import NOUN_DUAL, base_class
from pipflow.household.language.lexicon import GRADED, PHRASES, TEMPERATURE_ADJECTIVES
from pipflow.household.language.tokens import Tag
from pipflow.household.world import members


def located(tags: list["Tag"], world: dict, notes: list[str]) -> list["Tag"]:
    """ "the table lamp" where the home has no "table lamp" but a table and lamps: the lamp that
    is on the table, when the place word is followed at once by a name of objects and some of
    them are in that place; the other lamps are not meant. None there: left as said (refused)."""
    out: list[Tag] = []
    for t in tags:
        prev = out[-1] if out else None
        if t.cls == "NOUN" and prev is not None and prev.cls == "NOUN" and prev.nouns and \
                all(r["kind"] == "place" for r in prev.nouns):
            places = {r["name"] for r in prev.nouns}
            objects = [o for r in t.nouns for o in ([r["name"]] if r["kind"] == "object" else
                                                     members(world, r["name"]) if r["kind"] == "category" else [])]
            there = [o for o in dict.fromkeys(objects) if o in world["objects"] and world["objects"][o]["in"] in places]
            if there:
                plural = any(r.get("plural") for r in t.nouns)
                notes.append(f"read '{prev.words} {t.words}' as {', '.join(there)} (in {', '.join(sorted(places))})")
                out[-1] = Tag("NOUN", None, f"{prev.words} {t.words}",
                              [{"kind": "object", "name": o, "plural": plural} for o in there])
                continue
        out.append(t)
    return out


#: the tags a sentence that only restates the order of things has: "first the mug, then the plate"
_ORDER_ONLY = {"THE", "NOUN", "COMMA", "AND", "THEN"}


def restated_order(tags: list[Tag], notes: list[str]) -> list[Tag]:
    """The tags without a sentence that only lists things already named, in an order ("wash the
    mug and the plate: first the mug, then the plate"): the order of the steps, which the plan
    decides. A sentence that names anything new is kept (and read, or refused)."""
    out: list[Tag] = []
    named: set[str] = set()
    start = 0
    for k in range(len(tags) + 1):
        if k < len(tags) and tags[k].cls != "END":
            continue
        sentence = tags[start:k]
        nouns = [t for t in sentence if t.cls == "NOUN" or t.cls.endswith(NOUN_DUAL)]
        names = {r["name"] for t in nouns for r in t.nouns}
        if out and nouns and names <= named and all(t.cls in _ORDER_ONLY or t.cls.endswith(NOUN_DUAL) for t in sentence):
            notes.append(f"'{' '.join(t.words for t in sentence)}': the order of the steps; the plan decides it")
        else:
            out += sentence + tags[k:k + 1]
        named |= names
        start = k + 1
    return out


def act_before_noun(tags: list[Tag]) -> list[Tag]:
    """ "I need a clean mug": an action noun ("a clean", "a wash") before a name is a determiner and a
    state word, not the action ("give it a clean")."""
    out: list[Tag] = []
    for k, t in enumerate(tags):
        nxt = tags[k + 1] if k + 1 < len(tags) else None
        ws = t.words.split()
        if t.cls == "ACT" and len(ws) == 2 and nxt is not None and (nxt.cls == "NOUN" or nxt.cls.endswith(NOUN_DUAL)) \
                and (ws[1],) in PHRASES and PHRASES[(ws[1],)][0] in ("V_CLEAN", "ADJ"):
            out += [Tag("THE", None, ws[0]), Tag(PHRASES[(ws[1],)][0], PHRASES[(ws[1],)][1], ws[1])]
            continue
        out.append(t)
    return out


def demonstratives(tags: list[Tag]) -> list[Tag]:
    """ "That leftover curry has gone off": "that" opening a clause, or after a verb or "and", before
    a name (or a state word and a name) is a determiner, like "the"; elsewhere it stays a relative ("the lamp that is on")
    or a conjunction ("make sure that ..."). Done here, not in the grammar: one more determiner
    there is one more alternative at every noun of every command."""
    out = list(tags)
    for k, t in enumerate(out):
        if t.cls == "THAT" and k and out[k - 1].cls.startswith("V_") and \
                (k + 1 == len(out) or out[k + 1].cls in ("END", "COMMA")):
            out[k] = Tag("IT", t.value, t.words)   # "the hob is still on, can you sort that": the thing said
            continue
        if t.cls != "THAT" or (k and out[k - 1].cls not in ("END", "COMMA", "AND") and not out[k - 1].cls.startswith("V_")):
            continue   # "bin that scone": after a verb too, before a name; "the cup and that pan"
        j = k + 1
        while j < len(out) and out[j].cls in ("ADJ", "V_WARM", "V_CLEAN"):
            j += 1
        if j < len(out) and (out[j].cls == "NOUN" or out[j].cls.endswith(NOUN_DUAL)):
            out[k] = Tag("THE", t.value, t.words)
    return out


#: classes of a wish, before which an intensifier of the lexicon ("really") grades the wish only
_WISHES = {"WANT", "NEED"}


def without_hedges(tags: list[Tag], notes: list[str]) -> list[Tag]:
    """The tags without the intensifiers and hedges (lexicon ``HEDGES``) that grade the word after
    them ("ever so dark", "absolutely freezing", "I could really go for", "the plates are all
    mucky": lexicon ``GRADED``): how much, not what. A hedge before anything else stays, and is
    refused unplaced (no word is dropped that could carry what is wanted)."""
    out: list[Tag] = []
    for k, t in enumerate(tags):
        nxt = base_class(tags[k + 1].cls) if k + 1 < len(tags) else ""
        prev = base_class(out[-1].cls) if out else ""
        if (t.cls == "HEDGE" and nxt in GRADED) or (t.cls == "INTENS" and nxt in _WISHES) or \
                (t.cls == "ALL" and prev == "IS" and nxt == "ADJ"):
            notes.append(f"'{t.words}' says how much, not what: read as nothing")
            continue
        out.append(t)
    return out


def left_lying(tags: list[Tag]) -> list[Tag]:
    """ "the dishes have been left on the table": a thing said to have been left in a place is
    disorder said of it, as "lying on the table" (lexicon ``LYING``); "the fridge has been left
    open", "the lights were left on": a complaint, asking for the other state (as "someone left
    the fridge open": the grammar's ``unwant``)."""
    out = list(tags)
    for k, t in enumerate(out[:-1]):
        if t.cls != "IS" or t.words.split()[-1] != "left":
            continue
        nxt = base_class(out[k + 1].cls)
        if nxt in ("ON", "IN") and k + 2 < len(out) and out[k + 2].cls not in ("END", "COMMA"):
            out[k] = Tag("LYING", t.value, t.words)
        elif nxt in ("ADJ", "ON", "OFF", "V_OPEN", "V_SHUT", "V_CLEAN", "V_WARM"):
            out[k] = Tag("LEFTAS", t.value, t.words)   # "the fridge has been left open": a complaint
    return out


#: what a sentence that leaves out "it's" opens with: how much, then how the room feels ("bit dark
#: in here", "too loud", "freezing in here")
_FELT = {"INTENS", "TOO", "TEMPCUE", "LIGHTCUE", "SOUNDCUE", "AIRCUE"}
_CUES = {"TEMPCUE", "LIGHTCUE", "SOUNDCUE", "AIRCUE"}
#: what may open the subject of a clause: after "is", one of these makes it a question ("is the
#: kettle on"), never a clause that left its subject out
_SUBJECT_OPENERS = {"THE", "NOUN", "IT", "THAT", "THERE", "SUBJ", "NUM"}


def _opens_clause(out: list[Tag]) -> bool:
    """Whether the next tag opens a clause: at a sentence's start, after a comma, or after "when",
    "once", "after" (a step closed: "when is sliced, put it on the table")."""
    return not out or out[-1].cls in ("END", "COMMA", "EXCL", "ONCE")


def _asked(tags: list[Tag], k: int) -> bool:
    """Whether the sentence of tag ``k`` ends with a question mark."""
    end = next((t for t in tags[k:] if t.cls == "END"), None)
    return end is not None and end.words == "?"


def _subject_dropped(tags: list[Tag], k: int) -> bool:
    """ "Turn off the radio, is too loud", "is getting dark, put the lights on": a clause that
    opens with "is" (pro-drop, as speakers of Polish, Spanish or Italian write English) and goes on
    with what is said of it has left out "it"; a sentence asked ("is the kettle on?", "is it
    cold?") or "is" before the opening of a subject is a question, never read so."""
    t = tags[k]
    nxt = base_class(tags[k + 1].cls) if k + 1 < len(tags) else "END"
    return t.cls == "IS" and t.words.split()[0] == "is" and nxt not in _SUBJECT_OPENERS | {"END", "COMMA"} \
        and not tags[k + 1].cls.endswith(NOUN_DUAL) and not _asked(tags, k)


#: what may stand before the thing of a clause whose "is" is left out ("the rice cold")
_BEFORE_THE_THING = {"THE"}


def copula_dropped(tags: list[Tag], notes: list[str]) -> list[Tag]:
    """ "mochi's bowl smelly already", "the rice cold": a clause that is only a thing of the home and
    what it is like has left out "is", as Singapore and Malaysian English, and many a text, say it;
    read with it, and so as "the bowl is smelly" would be (a cue, or a description that asks for
    nothing). Only a clause of nothing else: one name, then one word of state, then the clause's end."""
    out: list[Tag] = []
    for k, t in enumerate(tags):
        out.append(t)
        start = len(out) - 1
        while start > 0 and out[start - 1].cls in _BEFORE_THE_THING:
            start -= 1
        if (t.cls == "NOUN" and _opens_clause(out[:start]) and k + 1 < len(tags) and tags[k + 1].cls == "ADJ"
                and (k + 2 == len(tags) or tags[k + 2].cls in ("END", "COMMA", "EXCL"))):
            notes.append(f"'{t.words} {tags[k + 1].words}': read as '{t.words} is {tags[k + 1].words}'")
            out.append(Tag("IS", None, "(is)"))
    return out


def _warmth_felt(tags: list[Tag], k: int) -> bool:
    """ "hot in the living room", "so cold in here": a word of warmth said of where it is felt (a
    room or "here" after it), which is how the room feels, not a thing's state."""
    return (k + 1 < len(tags) and tags[k].cls == "ADJ" and tags[k].words in TEMPERATURE_ADJECTIVES
            and tags[k + 1].cls in ("HERE", "INROOM"))


def elided_it_is(tags: list[Tag], notes: list[str]) -> list[Tag]:
    """ "Bit dark in here", "freezing in here!": a sentence that opens with how the room feels has
    left out "it's"; read with it (only when a cue word of the room follows). A clause that opens
    with "is" and what is said of it ("..., is too loud", :func:`_subject_dropped`) has left out
    "it": read with it, and so as "it is ..." would be (a reason, a cue, or talk set aside)."""
    out: list[Tag] = []
    k = 0
    while k < len(tags):
        t = tags[k]
        if _opens_clause(out) and (t.cls in _FELT or _warmth_felt(tags, k)):
            j = k
            while j < len(tags) and tags[j].cls in ("INTENS", "TOO"):
                j += 1
            if j < len(tags) and (tags[j].cls in _CUES or _warmth_felt(tags, j)):
                notes.append(f"'{' '.join(x.words for x in tags[k:j + 1])}': read as 'it is ...'")
                out += [Tag("IT", None, "(it)"), Tag("IS", None, "(is)")]
        elif _opens_clause(out) and _subject_dropped(tags, k):
            end = next((j for j in range(k, len(tags)) if tags[j].cls in ("END", "COMMA")), len(tags))
            notes.append(f"'{' '.join(x.words for x in tags[k:end])}' leaves its subject out: read as 'it {t.words} ...'")
            out.append(Tag("IT", None, "(it)"))
        out.append(t)
        k += 1
    return out

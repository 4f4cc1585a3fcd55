"""Candidate readings for a household command the reader refuses as not understood (issue 23).

A refusal that only says "not understood" leaves the user to guess what to change. Where the
reader can see near readings it offers up to three, each in plain words with the words it rests
on, and acts on none unchosen (``TranslationError.candidates``; ``pipflow run`` asks, the bench
counts ``candidate_recall``). They are built, in this order of preference, from:

* **the choice the refusal asks for**: "'the lamp' could be any of desk_lamp, floor_lamp" offers
  the command with each of them named;
* **repairs of a word the reader does not know**: a misspelling one edit away with another first
  letter, or two edits away with the same one (the reader itself repairs only one edit, same
  first letter, one meaning: "tunrpi" is offered as turnip, "kettle" never as bottle); a word
  speech to text heard wrong, offered as a word of the home that sounds the same ("cattle" as
  kettle: the same Metaphone code, :func:`_said_alike`); a modifier said alone ("the mobile" of
  mobile_phone) read as its thing's whole name;
* **the parts that did parse**: the command without one word it could not place, or without one
  clause, when that word or clause has no operative word (negation, only/except, bounds,
  quantities: :func:`pipflow.language.asides.near_operative`), since dropping one would widen
  what the robots do.

* **a part of a name said alone**: a last word several names share ("the cupboard": each), a
  modifier in the plural ("the leftovers");
* **where the reading stopped**: a known word there that names nothing and is not operative, left
  out ("that *empty* pizza box"); a duration left out ("for two minutes": never read, since "leave
  the fridge open for five minutes" ends closed); every word not understood left out at once;
* **the senses of a cue**: a reason of leaving or going to bed said alone offers the lights off and
  everything that is on off; a thing "dealt with" that is on or open offers it off or closed; a cue
  that may mean several sound or drink makers offers each (the resolver's choice).

Each candidate is read by the same translator as any command, so it is a reading of this world
(impossible ones are not offered). The search is bounded (:data:`MAX_TRIES` readings).
"""
from __future__ import annotations

import json
import re
from collections import Counter
from typing import Callable

from jellyfish import metaphone

from pipflow.errors import PipflowError, Refusal, TranslationError
from pipflow.household.language.dialect import AFTER_I
from pipflow.household.language.lexicon import HUNGRY, LEAVING_REASONS, NEEDS_OFFERED, ORDER_VERB_WORDS, words_of
from pipflow.household.language.names import home_words, per_world, world_phrases
from pipflow.household.language.rewrites import without_duration
from pipflow.household.language.setaside import REMARK_SUBJECTS
from pipflow.household.language.tagger import tag
from pipflow.household.language.typos import known_word, vocabulary
from pipflow.language.asides import BOUNDS, EXCLUSIVITY, FUNCTION_WORDS, NEGATION, near_operative
from pipflow.language.scots import SCOTS
from pipflow.language.spelling import distance

#: at most this many candidate readings are offered
MAX_CANDIDATES = 3
#: at most this many other wordings are read while looking for them
MAX_TRIES = 18
#: at most this many changes make one wording (a repair, then a word left out, ...)
MAX_CHANGES = 3
#: words the reader refuses that join a list, and the joiner a candidate reads them as ("or" is
#: a choice where the reader refuses it; in "nobody is using X or Y" it lists both)
JOINERS = {"or": "and", "nor": "and"}
#: operative words whose loss widens nothing when they describe a thing ("that empty box"): a
#: candidate may read without them (it is only offered, never acted on unchosen)
FREE_TO_DROP = {"empty", "full", "whole", "single", "first", "then", "after", "back"}
#: words that say a thing is all right ("the milk smells fine"): left out, the rest would say the
#: opposite, so no candidate reads without them
APPRAISALS = {"fine", "ok", "okay", "good", "nice", "great", "alright", "normal", "perfect", "lovely"}
#: clause marks of the command (dashes and brackets set a clause off too)
_CLAUSE_SPLIT = re.compile(r"[,.;:!?()\[\]\u2013\u2014]|\s-\s")
def _about_the_speaker(words: list[str]) -> bool:
    """A part that opens with the speaker as its subject ("i do not want ...", "we can not ..."),
    with no only, except or bound in it: what it denies is the speaker's, not the robots' work
    (northern English "ah" for I too: "ah cannot stand that fella")."""
    said_i = words[:1] in (["i"], ["we"]) or (words[:1] == ["ah"] and len(words) > 1 and words[1] in AFTER_I)
    return said_i and not set(words) & (EXCLUSIVITY | BOUNDS)


#: words that point at a thing the order is about ("not that one", "only the ones on the left"):
#: a part with one may narrow it
_POINTING_AT_THINGS = {"that", "this", "those", "these", "one", "ones", "them", "they", "which"}


#: how a remark about someone, or about what there is, opens: the set-aside's remark subjects, and
#: "me" ("me knees are killing me"), "there" ("there is nowt clean")
_SOMEONE = REMARK_SUBJECTS | {"me", "there"}


def _remark_of_someone(words: list[str], index: dict) -> bool:
    """A part said of the speaker (:func:`_about_the_speaker`), or one that opens with a person or
    "there" as its subject and names no word of the home, no verb of the robots' work, no count,
    no only or except and no thing pointed at ("our Kirsty says I never have it on", "she won't
    touch her dinner"): its "no" is said of people or of what there is, and narrows none of the
    robots' work ("the grandchildren never tidy a thing", "she never washes them" are kept). Left
    out only in a reading offered, whose words say so."""
    if _about_the_speaker(words):
        return True
    home = home_words(index)
    return bool(words) and words[0] in _SOMEONE and not any(
        w in home or w in ORDER_VERB_WORDS or w.isdigit() or w in _POINTING_AT_THINGS or w in BOUNDS or w in EXCLUSIVITY
        for w in words)


#: where a sentence ends (its mark kept with it) or a line breaks
_SENTENCE_SPLIT = re.compile(r"(?<=[.!?])\s+|\n")
#: words that narrow what is asked (no, only, except, bounds): a part that holds one is never left
#: out of a candidate reading, which would then ask for more than was said
_NARROWING = NEGATION | EXCLUSIVITY | BOUNDS


def _goal_key(goal: dict) -> str:
    return json.dumps({"in": {p: sorted(v) for p, v in (goal.get("in") or {}).items() if v},
                       "state": {n: sorted(v) for n, v in (goal.get("state") or {}).items() if v},
                       "count": goal.get("count") or []}, sort_keys=True)


def _singulars(word: str) -> list[str]:
    """Singular spellings a plural may have ("leftovers" -> "leftover", "dishes" -> "dish")."""
    out = []
    for end, repl in (("ies", "y"), ("es", ""), ("s", "")):
        if word.endswith(end) and len(word) > len(end) + 2:
            out.append(word[:-len(end)] + repl)
    return out


@per_world
def _first_word_names(world: dict) -> dict[str, list[str]]:
    """First words of the names of two or more words -> one name of each thing they are part of
    ("mobile" -> ["mobile phone"]), for a modifier said alone."""
    return _part_names(world, 0)


@per_world
def _last_word_names(world: dict) -> dict[str, list[str]]:
    """Last words of the names of two or more words -> one name of each thing they are part of
    ("cupboard" -> ["food cupboard", "wall cupboard"]), for a head word said alone."""
    return _part_names(world, -1)


def _part_names(world: dict, at: int) -> dict[str, list[str]]:
    """The words at ``at`` (0 first, -1 last) of the names of two or more words -> one name of
    each thing they are part of."""
    out: dict[str, list[str]] = {}
    for table in (world.get("objects") or {}, world.get("places") or {}):
        for name, e in table.items():
            for phrase in [name] + list(e.get("words") or []):
                ws = words_of(phrase)
                if len(ws) >= 2 and ws[at] not in FUNCTION_WORDS:
                    full = " ".join(ws)
                    names = out.setdefault(ws[at], [])
                    if full not in names and not any(n.startswith(f"{name}\0") for n in names):
                        names.append(f"{name}\0{full}")
    return {w: [n.split("\0")[1] for n in names] for w, names in out.items()}


def _said_alike(word: str, vocab: set[str]) -> list[str]:
    """Words of this home that sound like ``word`` (the same Metaphone code of two sounds or more;
    four letters or more, so "hit" is never "hot"), at most :data:`MAX_CANDIDATES`: what speech to
    text may have heard wrong ("cattle" for kettle, "bucky" for bakkie)."""
    if len(word) < 4 or not word.isalpha():
        return []
    code = metaphone(word)
    if len(code) < 2:
        return []
    return sorted(v for v in vocab if v != word and len(v) >= 4 and v.isalpha() and metaphone(v) == code)[:MAX_CANDIDATES]


def _stopped_wordings(words: list[str], index: dict, error: TranslationError) -> list[tuple[str, str, str, dict]]:
    """Wordings from where the reading stopped, how long an action takes, and a reason said alone
    (module docstring)."""
    out: list[tuple[str, str, str, dict]] = []
    said_how_long: list[str] = []
    timed = without_duration(words, said_how_long)
    if said_how_long:   # "heat the curry for two minutes": the end state, without how long
        out.append((" ".join(timed), f"read without {said_how_long[0].split(' says')[0]} (how long)", " ".join(timed), {}))
    # a known word where the grammar stopped, that no world name has and that is not operative: the
    # rest may read whole ("that empty pizza box ... is starting to smell")
    for phrase in getattr(error, "unplaced", []) or []:
        ws = phrase.split()
        if tuple(ws) in index or any(near_operative(x) and x not in FREE_TO_DROP for x in ws):
            continue
        at = next((k for k in range(len(words) - len(ws) + 1) if words[k:k + len(ws)] == ws), None)
        if at is not None:
            rest = " ".join(words[:at] + words[at + len(ws):])
            out.append((rest, f"read without '{phrase}' (where the reading stopped)", rest, {}))
    # a reason of leaving or going to bed, said alone: the lights off, or everything that is on off
    left = [r for r in getattr(error, "reasons", []) or [] if any(x in r for x in LEAVING_REASONS)]
    if left:
        out.append(("it is too bright", f"'{left[0]}' read as the lights off", left[0], {}))
        out.append(("switch off everything that is on", f"'{left[0]}' read as everything that is on switched off",
                    left[0], {}))
    return out


def _needs(error: TranslationError, world: dict) -> list[tuple[str, str, str, dict]]:
    """ "I'm shattered", "I'm parched", "I'm starving" said alone: what answers it in this home
    (lexicon ``NEEDS_OFFERED``; hungry: each food that heats, named), offered, never acted on."""
    out: list[tuple[str, str, str, dict]] = []
    for reason in getattr(error, "reasons", []) or []:
        said = [w for w in NEEDS_OFFERED if f" {w} " in f" {reason} "]
        for w in said:
            texts = list(NEEDS_OFFERED[w])
            if w in HUNGRY:
                texts += [f"heat up the {' '.join(words_of(n))}" for n, e in (world.get("objects") or {}).items()
                          if "heatable" in (e.get("properties") or [])][:MAX_CANDIDATES]
            out += [(t, f"'{reason}' read as '{t}'", reason, {}) for t in texts]
    return out


def _tags_and_unknown(command: str, world: dict, error: TranslationError, words: list[str], index: dict,
                      vocab: frozenset[str]) -> tuple[list, list[str]]:
    """The command's tags (none where the tagger refuses it), and its words not understood as said:
    those the tagger could not read (after its own repairs), a word it read as a misspelling of a
    word that names nothing alone ("leftovers" as "leftover"), and a dialect word read as an English
    word the reader then could not place ("nowt" as "nothing")."""
    try:
        tags = tag(command, world, [])
        unknown: list[str] = []
    except TranslationError as exc:
        tags, unknown = [], [w for w in getattr(exc, "unread", []) if w in words]
        unknown += [x for w in getattr(exc, "unread", []) if w not in words
                    for x in dict.fromkeys(words) if x not in unknown and x.isalpha() and distance(x, w) <= 2
                    and not known_word(x, index, vocab)][:1]
    unread = getattr(error, "unread", None) or ()
    unknown += [x for x in dict.fromkeys(words) if x not in unknown and SCOTS.get(x) in unread]
    return tags, unknown


def _wordings(command: str, world: dict, error: TranslationError) -> list[tuple[str, str, str, dict]]:
    """(other wording, how it differs in plain words, the words it rests on, the choice of a
    thing among several it makes), best first."""
    out: list[tuple[str, str, str, dict]] = []
    choices = getattr(error, "choices", None)
    if choices:
        said, names = choices
        out += [(command, f"'{said}' read as {name}", name, {said: name}) for name in names]
    words = words_of(command)
    index = world_phrases(world)
    vocab = vocabulary(index)
    modifiers = _first_word_names(world)
    heads = {w: names for w, names in _last_word_names(world).items() if len(names) > 1}
    tags, unknown = _tags_and_unknown(command, world, error, words, index, vocab)
    # one edit with any first letter ("vowl" for bowl), two with the same first letter ("tunrpi"):
    # "kettle" is never offered as "bottle"
    near: dict[str, list[tuple[int, str]]] = {
        w: sorted((d, v) for d, v in ((distance(w, v), v) for v in vocab if len(w) >= 4 and abs(len(v) - len(w)) <= 2)
                  if d == 1 or (d == 2 and v[0] == w[0]))[:3] for w in unknown if w not in APPRAISALS}
    def swap(w: str, by: str) -> str:
        return " ".join(by if x == w else x for x in words)

    out += _robots_addressed(command, world, index)

    for w in near:   # one edit first, then a modifier's whole name, then two edits
        out += [(swap(w, v), f"'{w}' read as '{v}'", v, {}) for d, v in near[w] if d == 1]
    for w in unknown:   # "the cupboard" where two things are cupboards: each of them
        fulls = heads.get(w) or next((heads[s] for s in _singulars(w) if s in heads), [])
        out += [(swap(w, full), f"'{w}' read as '{full}'", full, {}) for full in fulls]
    for w in unknown:   # "the leftovers" of leftover_curry: a modifier said alone, in the plural too
        fulls = modifiers.get(w) or next((modifiers[s] for s in _singulars(w) if s in modifiers), [])
        out += [(swap(w, full), f"'{w}' read as '{full}'", full, {}) for full in fulls]
    for w in near:
        out += [(swap(w, v), f"'{w}' read as '{v}'", v, {}) for d, v in near[w] if d == 2]
    if not unknown:   # "the table lamp" where no lamp is on the table: the thing its last word names
        text = " ".join(words)
        for a, b in zip(tags, tags[1:]):
            pair = f"{a.words} {b.words}"
            if a.cls == "NOUN" and b.cls == "NOUN" and pair in text:
                out.append((text.replace(pair, b.words, 1), f"'{pair}' read as '{b.words}'", b.words, {}))
    for w in unknown:   # "nobody is using the tablet or the radio": a list said with "or"
        if w in JOINERS:
            out.append((swap(w, JOINERS[w]), f"'{w}' read as '{JOINERS[w]}'", swap(w, JOINERS[w]), {}))
    droppable = [w for w in dict.fromkeys(unknown) if not near_operative(w) and w not in JOINERS and w not in APPRAISALS]
    if len(droppable) > 1:   # "chop up the cucumber sharpish pronto": every word not understood, at once
        rest = " ".join(x for x in words if x not in droppable)
        out.append((rest, "read without " + ", ".join(f"'{w}'" for w in droppable) + " (not understood)", rest, {}))
    for w in droppable:
        rest = " ".join(x for x in words if x != w)
        out.append((rest, f"read without '{w}' (not understood)", rest, {}))
    out += _without_unread_end(words, unknown, index)
    out += _place_phrases(words, unknown)
    out += _needs(error, world)
    out += _topics([p.strip() for p in _CLAUSE_SPLIT.split(command) if p.strip()], index)
    out += _stopped_wordings(words, index, error)
    parts = [p.strip() for p in _CLAUSE_SPLIT.split(command) if p.strip()]
    out += _without_unread_parts(command, parts, unknown, index)
    if len(parts) > 1:
        for part in parts:
            ws = words_of(part)
            if ws and not any(near_operative(x) for x in ws):
                rest = _CLAUSE_SPLIT.sub(" , ", command.replace(part, " ", 1))
                out.append((rest, f"read without '{' '.join(ws)}' (not understood)", " ".join(words_of(rest)), {}))
    out += _without_tails(words)
    for w in unknown:   # "put the cattle on": speech to text's word for one that sounds the same (last: it
        # must not take the tries of the wordings above, which find more)
        out += [(swap(w, v), f"'{w}' read as '{v}' (said alike)", v, {}) for v in _said_alike(w, vocab)]
    return out


def _without_unread_parts(command: str, clauses: list[str], unknown: list[str],
                          index: dict) -> list[tuple[str, str, str, dict]]:
    """ "Open the toy trunk, put the doll inside. Whole week the grandchildren's things are lying
    everywhere.": the command without every clause, then without every sentence, that holds a word
    not understood, at once (one at a time, the others' words would still be in the way). A part
    that says no, only, except or a bound is kept: dropped, the rest would ask for more; but a
    "no" said of people or of what there is (:func:`_remark_of_someone`: "I can't even walk", "our
    Kirsty says I never have it on") narrows nothing the robots do."""
    unread = set(unknown)
    out: list[tuple[str, str, str, dict]] = []
    for parts, joiner in ((clauses, " , "), ([p.strip() for p in _SENTENCE_SPLIT.split(command) if p.strip()], " ")):
        # a part whose words not understood all lie in a tail of what for or why keeps the rest
        # ("boil the eggs for me tea hinny": the eggs boiled)
        parts = [_tails_cut(p, unread) for p in parts]
        dropped = [p for p in parts if set(words_of(p)) & unread and (not set(words_of(p)) & _NARROWING
                                                                       or _remark_of_someone(words_of(p), index))]
        if not dropped or len(dropped) == len(parts):
            continue
        rest = joiner.join(p for p in parts if p not in dropped)
        said = "; ".join(p.strip(" .!?") for p in dropped)
        out.append((rest, f"read without '{said}' (not understood)", " ".join(words_of(rest)), {}))
    return out


def _without_unread_end(words: list[str], unknown: list[str], index: dict) -> list[tuple[str, str, str, dict]]:
    """ "slice the melon and the bread pls mums doin a picnic": a remark run on without a comma,
    from the first word not understood to the clause's end, left out where it names nothing of
    the home and holds no operative word (negation, only, except, a bound, a quantity), no word
    that says a thing is all right ("the kipper smells fine": left out, the rest says the opposite)
    and no "or"."""
    unread = set(unknown)
    start = next((k for k, w in enumerate(words) if w in unread), None)
    while start and words[start - 1] in _DETERMINERS:   # "the cricket will be starting": from "the"
        start -= 1
    if not start or words[start - 1] in _TAIL_ENDS:   # a whole clause: left out by _without_unread_parts
        return []
    end = next((j for j in range(start, len(words)) if words[j] in _TAIL_ENDS - {"and", "then", "but"}), len(words))
    tail = words[start:end]
    # a word of a name said alone names nothing ("a picnic" of the picnic blanket); "a"
    # quantifies only what it names, and the tail names nothing of the home
    if any((w,) in index or w in APPRAISALS or w in JOINERS for w in tail) \
            or any(near_operative(w) for w in tail if w not in ("a", "an")):
        return []
    rest = " ".join(words[:start] + words[end:])
    return [(rest, f"read without '{' '.join(tail)}' (not understood)", rest, {})]


#: words that open what a thing is for or why ("... on the table for the scones", "... so it's
#: soft", "... before the rain comes", "... because ..."): a tail of the clause the order is in
_TAIL_LEADS = {"for", "so", "before", "because", "cause", "cos", "coz", "since", "as"}
#: where such a tail ends: the clause's end, or a word that joins the next order to it
_TAIL_ENDS = {",", ".", ";", ":", "!", "?", "and", "then", "but"}


def _tail_spans(words: list[str]) -> list[tuple[int, int]]:
    """Where the tails of what for or why lie ((start, end) of each): from a word of
    :data:`_TAIL_LEADS` not opening its clause to the clause's end or the next joining word; a
    tail that says no, only, except or a bound is none (dropped, the rest would ask for more)."""
    tails: list[tuple[int, int]] = []
    k = 1
    while k < len(words):
        if words[k] in _TAIL_LEADS and words[k - 1] not in _TAIL_ENDS:
            end = next((j for j in range(k + 1, len(words)) if words[j] in _TAIL_ENDS), len(words))
            if end > k + 1 and not set(words[k:end]) & _NARROWING:
                tails.append((k, end))
            k = end
        k += 1
    return tails


def _tails_cut(part: str, unread: set[str]) -> str:
    """A part without its tails of what for or why where every word of it not understood lies in
    them; else the part as said."""
    words = words_of(part)
    tails = _tail_spans(words)
    inside = {i for a, b in tails for i in range(a, b)}
    held = [i for i, w in enumerate(words) if w in unread]
    if not held or any(i not in inside for i in held):
        return part
    return " ".join(w for i, w in enumerate(words) if i not in inside)


def _without_tails(words: list[str]) -> list[tuple[str, str, str, dict]]:
    """ "put the butter out on the table so it's soft for the scones", "bring the doll in off the
    step before the rain comes": the command without what an order is for or why, said after it
    in words the reader does not place (:func:`_tail_spans`); all such tails at once, then each
    alone. Offered only: why a thing is done may change what is meant."""
    tails = _tail_spans(words)
    out: list[tuple[str, str, str, dict]] = []
    for chosen in ([tails] if len(tails) > 1 else []) + [[t] for t in tails]:
        cut = {i for a, b in chosen for i in range(a, b)}
        rest = " ".join(w for i, w in enumerate(words) if i not in cut)
        said = "; ".join(" ".join(words[a:b]) for a, b in chosen)
        out.append((rest, f"read without '{said}' (what for, or why)", rest, {}))
    return out


#: words that lead a phrase of where ("over by the piano", "out in the orangery"): a phrase whose
#: last word names nothing says where a cue is felt, or where a thing is, in words the home lacks
_WHERE_LEADS = {"by", "over", "near", "beside", "next", "to", "in", "at", "on", "behind", "under", "out", "up", "down",
                "round", "around", "from"}
_DETERMINERS = {"the", "a", "an", "my", "our", "your", "that", "this", "his", "her", "their"}


def _place_phrases(words: list[str], unknown: list[str]) -> list[tuple[str, str, str, dict]]:
    """ "it's a bit gloomy over by the piano": a word not understood, with the words of where that
    lead to it, left out (the rest may read whole). Offered only: the place may change what is meant."""
    out: list[tuple[str, str, str, dict]] = []
    for w in dict.fromkeys(unknown):
        if w not in words:
            continue
        end = words.index(w)
        start = end
        while start and words[start - 1] in _DETERMINERS:
            start -= 1
        lead = start
        while lead and words[lead - 1] in _WHERE_LEADS:
            lead -= 1
        if lead == start or any(near_operative(x) for x in words[start:end + 1]):
            continue
        rest = " ".join(words[:lead] + words[end + 1:])
        phrase = " ".join(words[lead:end + 1])
        out.append((rest, f"read without '{phrase}' (where, in words this home model lacks)", rest, {}))
    return out


#: words after a robot's name that make it the one addressed ("Ladle, you slice it", "then Ladle
#: can give it a scrub"): left out with the name
_ADDRESSED_BY = r"(?:,\s*)?(?:(?:you|can|will|could|would|please|love|dear)\b[\s,]*)*"


def _robots_addressed(command: str, world: dict, index: dict) -> list[tuple[str, str, str, dict]]:
    """ "Clover, fetch the bread, and Ladle, you slice it": the household order has no robot rules,
    so the reader refuses a command that says who does what. Offered: the command without the
    robots' names (and the "you", "can" or "will" that follow one), the echo saying that who does
    what is left to the team's allocation. A name that is also a thing of the home is left alone."""
    names = [r.lower() for r in (world.get("robots") or {}) if tuple(words_of(r)) not in index]
    if not names:
        return []
    # "zip_1" said "zip 1" or "zip-1"
    one = "(?:" + "|".join(re.escape(n).replace("_", "[ _-]?") for n in sorted(names, key=len, reverse=True)) + ")"
    pattern = re.compile(rf"\b{one}(?:\s*(?:,|and|&)\s*{one})*\b\s*{_ADDRESSED_BY}", re.IGNORECASE)
    said = [m.group(0) for m in pattern.finditer(command)]
    if not said:
        return []
    rest = re.sub(r"\s*,(\s*,)+", ",", pattern.sub(" ", command)).strip(" ,")
    who = sorted({n for n in names if any(re.search(rf"\b{re.escape(n).replace('_', '[ _-]?')}\b", m, re.IGNORECASE)
                                          for m in said)})
    return [(rest, "read without the robots named (" + ", ".join(who) + "): who does what is left to the team",
             " ".join(who), {})]


def _topics(parts: list[str], index: dict) -> list[tuple[str, str, str, dict]]:
    """ "Shepherd's pie for tea tonight - it just wants warming through": a clause that names a thing
    and reads as nothing else, then a clause about "it": the thing in place of the pronoun."""
    out: list[tuple[str, str, str, dict]] = []
    for k in range(len(parts) - 1):
        ws, nxt = words_of(parts[k]), words_of(parts[k + 1])
        names = [" ".join(ws[i:j]) for i in range(len(ws)) for j in range(len(ws), i, -1) if tuple(ws[i:j]) in index]
        pronoun = next((i for i, x in enumerate(nxt) if x in ("it", "they", "them")), None)
        if not names or pronoun is None or any(near_operative(x) and (x,) not in index for x in ws):
            continue
        thing = max(names, key=len)
        said = nxt[:pronoun] + ["the"] + thing.split() + nxt[pronoun + 1:]
        rest = " , ".join(" ".join(words_of(p)) for p in parts[:k]) + (" , " if k else "") + " ".join(said) + \
            "".join(" , " + " ".join(words_of(p)) for p in parts[k + 2:])
        out.append((rest, f"'{nxt[pronoun]}' read as '{thing}' (the thing the clause before names)", thing, {}))
    return out


def candidate_readings(command: str, world: dict, error: TranslationError,
                       read: Callable[[str, dict, dict], dict]) -> list[dict]:
    """Up to :data:`MAX_CANDIDATES` readings to offer for a refused command (module docstring),
    after those the error already offers. ``read(text, world, choose)`` is the translator without
    candidates (a wording that does not read is skipped, never offered).

    A wording that is still not understood is worded again from its own refusal, up to
    :data:`MAX_CHANGES` changes in all ("draning" read as "draining", then "to dry" where the
    reading stopped left out): one change at a time often leaves the next word in the way. The
    search is breadth first (every wording of one change before any of two), so the fewest
    changes are offered first, and bounded by :data:`MAX_TRIES` readings. A word one change puts in
    is never taken out by a later one: "fine" read as "fix" and then "fix" left out would drop the
    word that said the opposite, which no single change may do. A wording that still holds a word
    its refusal could not read (no name, no word of the reader) is not read: it would be refused
    the same way (over the household sets, 9 of 1779 such wordings read, against 63 of 1104
    others), and reading them cost half of the search. (Wording again, unread, one that mends one
    of two such words cost four times the whole search and found fewer golds.)"""
    offered = list(error.candidates)
    seen = {_goal_key(c.get("goal") or {}) for c in offered}
    tried: set[tuple[str, str]] = set()
    tries = 0
    # (wording, its refusal, how it differs so far, the words it rests on so far, its choices,
    # changes, the words the changes put in)
    frontier: list[tuple[str, TranslationError, list[str], list[str], dict, int, Counter]] = \
        [(command, error, [], [], {}, 0, Counter())]
    if getattr(error, "reworded", None):
        # the command with its people read (:mod:`.people`) got further than as said: it is worded
        # again instead, as one change (also wording the command as said found 2 more golds over the
        # household sets and cost a tenth more of the search: parse time, the bound)
        text, refusal, people_said = error.reworded
        frontier = [(text, refusal, ["; ".join(people_said)], [], {}, 1, Counter())]
    while frontier and len(offered) < MAX_CANDIDATES and tries < MAX_TRIES:
        said, refusal, hows, rests, chosen, changes, put_in = frontier.pop(0)
        said_words = Counter(words_of(said))
        unread = set(getattr(refusal, "unread", None) or ())
        for text, how, rests_on, choose in _wordings(said, world, refusal):
            if len(offered) >= MAX_CANDIDATES or tries >= MAX_TRIES:
                break
            text_words = Counter(words_of(text))
            if any(text_words[w] < said_words[w] for w in put_in):
                continue
            choose = {**chosen, **choose}
            key = (text, json.dumps(choose, sort_keys=True))
            if key in tried:
                continue
            tried.add(key)
            if unread & text_words.keys():   # refused the same way: not read
                continue
            tries += 1
            try:
                got = read(text, world, choose)
            except Refusal:   # impossible as worded: never offered, never worded again
                continue
            except TranslationError as exc:
                if changes + 1 < MAX_CHANGES:
                    frontier.append((text, exc, hows + [how], rests + [rests_on], choose, changes + 1,
                                     put_in + (text_words - said_words)))
                continue
            except PipflowError:
                continue
            key_goal = _goal_key(got["goal"])
            if key_goal in seen or not any(got["goal"].get(k) for k in ("in", "state", "count")):
                continue
            seen.add(key_goal)
            offered.append({"reading": "; ".join(hows + [how]) + ": " + "; ".join(got["explain"]), "goal": got["goal"],
                            "order": got["order"], "words": "; ".join(rests + [rests_on])})
    return offered[:MAX_CANDIDATES]

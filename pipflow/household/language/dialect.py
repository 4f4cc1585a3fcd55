"""Dialect words read as the standard English the grammar is written in, each by a rule that holds
in any home (docs/household.md, "dialect"): "them" before the name of a thing is the
demonstrative "those" ("them tea things want washing", northern and Scots English). A note says
what was read so."""
from __future__ import annotations

from typing import Callable

from pipflow.household.language.lexicon import PHRASES, ROOM_WORDS
from pipflow.household.language.names import first_words, home_words, name_end, objects_named
from pipflow.household.language.restated import DETERMINERS
from pipflow.household.language.tokens import PUNCT
from pipflow.language import pidgin
from pipflow.language.english import dropped_g
from pipflow.language.patois import LEFT_OUT, PARTICLES, PLURAL, english_of
from pipflow.language.quebec import QUEBEC
from pipflow.language.scots import SCOTS
from pipflow.language.tokpisin import TOK_PISIN

#: Québec French words said in English at home: the shared ones and the verbs of chores ("ferme the
#: TV": close, so off; "réchauffe the soup": heat)
_QUEBEC = QUEBEC | {"ferme": "close", "fermer": "close", "ouvre": "open", "ouvrir": "open", "rechauffe": "heat",
                    "rechauffer": "heat", "lave": "wash", "laver": "wash"}
#: Scots words the household reader leaves alone: English words with another meaning at home ("a bar
#: of soap", "ma" for mother, "whit") and "ye", read already (lexicon.normalize)
_SCOTS_ALSO_ENGLISH = {"bar", "ma", "whit", "ye"}
#: the grammar's negatives, written out as the household reader writes them ("dont" -> "do not")
_WRITTEN_OUT = {"dont": "do not", "cant": "can not", "wont": "will not", "doesnt": "does not",
                "shouldnt": "should not", "mustnt": "must not"}
#: words after Scots "aw" that make it "all" ("aw the lights", "aw my stuff", "aw night")
_ALL_OF = DETERMINERS | {"them", "these", "those", "o", "of", "night", "day", "morning", "afternoon", "evening",
                         "week", "weekend"}


def patois_as_english(words: list[str], known: Callable[[str], bool], noun: Callable[[str], bool],
                      notes: list[str]) -> list[str]:
    """The words with Jamaican Creole function words read as English
    (:func:`pipflow.language.patois.english_of`), each only where it is no name of a thing of the
    home alone (``known``); "dem" after a thing (``noun``) is its plural ("di plate dem": the plates)."""
    out: list[str] = []
    for w, said in zip(words, english_of(words, known, noun, _PATOIS_AT_HOME)):
        if said == PLURAL and out:
            plural = out[-1] if out[-1].endswith("s") and noun(out[-1]) else \
                next((out[-1] + end for end in ("s", "es") if noun(out[-1] + end)), None)   # "boots dem": boots
            notes.append(f"'{out[-1]} dem' read as '{plural or out[-1]}' (Jamaican Creole: a plural)")
            out[-1] = plural or out[-1]
            continue
        if said == LEFT_OUT:   # "all two": both, said already
            continue
        _said_as(out, w, said, "Jamaican Creole", notes)
    return out


#: patois words of the home's states ("it dutty", "wash di dutty plate dem")
_PATOIS_AT_HOME = {"dutty": "dirty"}


def _said_as(out: list[str], word: str, said: str | None, language: str, notes: list[str]) -> None:
    """Add ``word`` to ``out`` read as the English ``said`` (noted, with its ``language``), or as it
    is where ``said`` is None."""
    if said is None:
        out.append(word)
        return
    notes.append(f"'{word}' read as '{said}' ({language})")
    out += said.split()


#: Egyptian and Levantine Arabic words said in English at home, read as the English word ("put el
#: mug in el sink", "3ashan Teta", "el gaw 7ar"): the article, "because", "tomorrow", "now", the feel
#: of the air ("awi", very, is a filler: lexicon ``FILLER``)
_ARABIC = {"el": "the", "il": "the", "aashan": "because", "ashan": "because", "alashan": "because",
           "bokra": "tomorrow", "delwaqty": "now",
           # how it feels ("el gaw 7ar": the air is hot; "bard": cold; "dalma": dark)
           "gaw": "place", "har": "hot", "bard": "cold", "dalma": "dark"}


def arabic_as_english(words: list[str], known: Callable[[str], bool], notes: list[str]) -> list[str]:
    """The words with Arabic words said in English read as English (:data:`_ARABIC`), each only
    where it is no name of the home alone (``known``), in a command that says one of them; there "w"
    (Arabic "and", written on the next word in Arabic script) is "and"."""
    french = {k for k, w in enumerate(words) if w == "il" and k and words[k - 1] == "s"}   # "s'il te plait"
    arabic = any(w in _ARABIC and not known(w) and k not in french for k, w in enumerate(words))
    out: list[str] = []
    for k, w in enumerate(words):
        said = None if known(w) or not arabic or k in french else _ARABIC.get(w)
        if w == "w" and arabic:
            said = "and"
        _said_as(out, w, said, "Arabic", notes)
    return out


def patois_in_home(words: list[str], index: dict, notes: list[str]) -> list[str]:
    """:func:`patois_as_english` with the home's names (``index``: the world's phrases) saying which
    words are its things' names alone (never read as patois) and which may be part of one."""
    home = home_words(index)
    return patois_as_english(words, lambda w: (w,) in index, lambda w: w in home, notes)


#: verbs that "um" after them makes "them" of besides the grammar's own ("open um up", "start um":
#: lexicon ``PHRASES``; "shake um out", "iron um", "no forget um": these)
_PIDGIN_VERBS = frozenset({"shake", "iron", "forget", "fold", "plug", "pass", "check", "air", "soak"})


def pidgin_in_home(words: list[str], index: dict, notes: list[str]) -> list[str]:
    """The words with Hawai'i Pidgin read as English (:func:`pipflow.language.pidgin.english_of`),
    never a word that names a thing of the home alone; a verb is a verb of the grammar's orders or
    of :data:`_PIDGIN_VERBS`."""
    def verb(w: str) -> bool:
        return w in _PIDGIN_VERBS or str((PHRASES.get((w,)) or ("",))[0]).startswith("V_")
    out: list[str] = []
    for w, said in zip(words, pidgin.english_of(words, lambda w: (w,) in index, verb)):
        if said != pidgin.SAID_BEFORE:
            _said_as(out, w, said, "Hawai'i Pidgin", notes)
    return out


#: "aal ower the shop": all over (Geordie "aal" is read as "all" only before what it quantifies or
#: "over": Arabizi spells "3al", on, the same way)
_OVER = frozenset({"ower", "over"})
#: words that follow "ah" where it is "I" (Scots and northern English), never where it is a sigh
AFTER_I = frozenset({"have", "m", "am", "will", "ll", "can", "cannot", "cant", "could", "do", "dont", "did", "had",
                      "was", "would", "need", "want", "think", "know", "just", "never", "d", "ve"})
#: what is left of a verb after "ah'" ("ah'm", "ah'll", "ah've", "ah'd")
_CONTRACTED = {"m": ("am",), "ll": ("will",), "ve": ("have",), "d": ("would",)}


def scots_as_english(words: list[str], known: Callable[[str], bool], notes: list[str]) -> list[str]:
    """The words with Scots words read as English (:data:`pipflow.language.scots.SCOTS`: "switch
    aff the telly", "bring my specs ben", "that yin as well") where the word is no word of the home
    or of the reader (``known``); "aw", "aal" are "all" before what they quantify ("aw the lights") and
    "too" after "an" at a clause's end ("the big sheet an aw", "an aal"); "the morn" is tomorrow; a
    word said with "in" for "ing" is the "ing" word (:func:`pipflow.language.english.dropped_g`)."""
    out: list[str] = []
    k = 0
    while k < len(words):
        w, nxt = words[k], (words[k + 1] if k + 1 < len(words) else ".")
        if w == "the" and nxt == "morn":
            out.append("tomorrow")
            k += 2
            continue
        if w == "ah" and nxt in AFTER_I and not known(w):   # "ah have read it", "ah'm not fussy"
            notes.append("'ah' read as 'I'")
            out += ["i", *_CONTRACTED.get(nxt, (nxt,))]
            k += 2
            continue
        if w in ("an", "and") and nxt in ("aw", "aal") and (k + 2 >= len(words) or words[k + 2] in PUNCT):
            notes.append(f"'an {nxt}' read as 'too'")
            out.append("too")
            k += 2
            continue
        said = "all" if (w == "aw" and nxt in _ALL_OF or w == "aal" and nxt in _ALL_OF | _OVER) and not known(w) else \
            (SCOTS.get(w) or TOK_PISIN.get(w)) if w not in _SCOTS_ALSO_ENGLISH and not known(w) else None
        if said is None and not known(w):
            said = dropped_g(w)   # "washin", "gettin", "comin"
        if said is not None:
            notes.append(f"'{w}' read as '{said}'")
            out += _WRITTEN_OUT.get(said, said).split()
        else:
            out.append(w)
        k += 1
    return out


def romance_words_as_english(words: list[str], known: Callable[[str], bool], notes: list[str]) -> list[str]:
    """The words with Québec French words said in English read as English (:data:`_QUEBEC`: "wash
    the pan pis put it away", "ferme the TV", "réchauffe the soup") and Spanish and Portuguese "por
    favor" as "please", where the word is no word of the home or of the reader (``known``)."""
    out: list[str] = []
    k = 0
    while k < len(words):
        w, nxt = words[k], (words[k + 1] if k + 1 < len(words) else ".")
        if w == "por" and nxt in ("favor", "favour") and not known(w):
            out.append("please")
            k += 2
            continue
        said = _QUEBEC.get(w) if not known(w) else None
        if said is not None:
            notes.append(f"'{w}' read as '{said}' (Québec French)")
        out.append(said or w)
        k += 1
    return out


#: words that tell "some" before them is "very" ("tis some cold", "me cup is some dirty"): how a
#: thing or the air is, never a thing of the home (those are checked against the home's names)
_SOME_AS_VERY = frozenset({"cold", "hot", "warm", "dirty", "heavy", "dark", "wet", "soft", "full", "filthy", "messy",
                           "sticky", "greasy", "mucky", "chilly", "freezing", "mild", "stuffy", "cluttered", "loud",
                           "bright", "big", "small", "late", "tired", "hungry", "starved", "foul", "smelly", "gross"})
#: what may close the clause after "some" + how ("some cold today", "some heavy so ...")
_AFTER_HOW = frozenset(PUNCT) | {"and", "so", "today", "tonight", "now", "out", "in", "here", "there", "again",
                                 "too", "but", "then", "already", "still"}
#: words that may stand between "me" and the thing it owns ("me good afghan", "me old cup")
_BEFORE_A_THING = _SOME_AS_VERY | {"good", "old", "new", "best", "little"}
#: where the thing "me" owns is taken, after a verb that may also take who it is for
_WHERE_TO = frozenset({"to", "into", "onto", "on", "in", "over", "back"})


def newfoundland_as_english(words: list[str], index: dict, notes: list[str]) -> list[str]:
    """Newfoundland (and Irish, Scots, northern English) forms read as English, never a word that
    names a thing of the home alone: "me" before a thing of the home (an adjective between) is
    "my" ("wash me cup", "me good afghan"); after a verb that may take who a thing is for ("bring
    me knitting") only where the clause then says where it goes, so "me" as "for me" and as "my"
    move it alike; "some" before how a thing or the air is, with no thing after it, is "very"
    ("tis some cold"); "is after" + a verb in -ing is the "after" perfect ("I'm after washing
    it": I have just washed it), read as "is" + the verb (what was just done is said as a remark)."""
    firsts = first_words(index)
    out: list[str] = []
    for k, w in enumerate(words):
        nxt = words[k + 1] if k + 1 < len(words) else "."
        before = out[-1] if out else "."
        if w == "me" and (w,) not in index:
            j = k + 1
            while j < len(words) and words[j] not in firsts and words[j] in _BEFORE_A_THING:
                j += 1
            rest = words[j + 1:k + 9]
            clause = rest[:next((i for i, x in enumerate(rest) if x in PUNCT), len(rest))]
            if (j < len(words) and words[j] in firsts
                    and (before not in TWO_OBJECT_VERBS or any(x in _WHERE_TO for x in clause))):
                notes.append(f"'me {words[j]}' read as 'my {words[j]}' (dialect)")
                w = "my"
        elif w == "some" and nxt in _SOME_AS_VERY and (nxt,) not in index:
            after = words[k + 2] if k + 2 < len(words) else "."
            if after in _AFTER_HOW:
                notes.append(f"'some {nxt}' read as 'very {nxt}' (dialect)")
                continue
        elif (w == "after" and before in {"is", "are", "am", "s", "m", "re", "was", "were"}
              and nxt.endswith("ing") and len(nxt) > 4 and (nxt,) not in index):
            notes.append(f"'{before} after {nxt}' read as '{before} {nxt}' (dialect: just done)")
            continue
        out.append(w)
    return out


#: verbs that take two objects ("bring them tea", "get them cups": for them): after one, "them"
#: may be who the thing is for, so it is not read as "those" (the command is refused, not guessed)
TWO_OBJECT_VERBS = {"give", "bring", "get", "fetch", "hand", "pass", "make", "send", "take", "show", "buy", "pour",
                    "find", "cook", "fix", "leave", "grab", "heat", "warm", "do", "serve", "lend", "set", "save"}


def them_as_those(words: list[str], index: dict, notes: list[str]) -> list[str]:
    """The words with "them" read as "those" where a name of the home follows it at once ("wash
    them mugs", "them tea things on the table"): as a pronoun, "them" is never followed by a noun,
    but it is by a particle that may also begin a name ("put them back", where a "back room light" is).
    ``index``: the world's phrases (:func:`pipflow.household.language.names.world_phrases`)."""
    firsts = first_words(index)
    out: list[str] = []
    for k, w in enumerate(words):
        nxt = words[k + 1] if k + 1 < len(words) else "."
        before = out[-1] if out else "."
        if w == "them" and nxt not in PUNCT and nxt in firsts and before not in TWO_OBJECT_VERBS \
                and (nxt not in PARTICLES or _name_at(words, k + 1, index)):   # "put them back in the fridge"
            notes.append(f"'them {nxt}' read as 'those {nxt}' (dialect)")
            w = "those"
        out.append(w)
    return out


def _name_at(words: list[str], at: int, index: dict) -> bool:
    """Whether a whole name of the home (a phrase of ``index``) begins at ``at``: "back room light"
    in "switch off them back room lights", not "back" alone in "put them back in the fridge"."""
    spans = [words[at:at + n] for n in range(2, 5) if at + n <= len(words)]
    return any(tuple(span) in index or tuple(span[:-1] + [span[-1].rstrip("s")]) in index for span in spans)


#: words before the name of a thing that switches ("off all the lights")
_DETERMINERS = DETERMINERS | {"all"}
#: the particles that make "cut" a switch ("cut the light off", "cut on the fan": American South)
_SWITCH_PARTICLES = {"on", "off"}
#: what may follow "cut X on" for it to be a switch: the clause ends there
_CLAUSE_END = set(PUNCT) | {"and", "then", "first", "please", "now", "for", "too", "again"}


def cut_as_switch(words: list[str], world: dict, index: dict, notes: list[str]) -> list[str]:
    """The words with "cut" read as "switch" where a thing that switches, or "it" / "them", and
    then "on" or "off" follow it ("cut that kitchen light off", "cut it on first"), or "on" /
    "off" and then such a thing ("cut off the fan"): a knife is never "cut ... on", and what
    switches is no thing to slice. A thing that does not switch keeps "cut" as slicing."""
    out = list(words)
    for k, w in enumerate(words):
        if w != "cut" or k + 1 >= len(words):
            continue
        if words[k + 1] in _SWITCH_PARTICLES:   # "cut off the fan"
            particle = k + 1 if _switching_phrase(words, _after_determiners(words, k + 2), world, index) else 0
        else:   # "cut the light off", "cut it on": the particle ends the clause ("cut it on the board" slices)
            end = k + 2 if words[k + 1] in ("it", "them") else \
                _switching_phrase(words, _after_determiners(words, k + 1), world, index)
            ends_clause = end + 1 >= len(words) or words[end + 1] in _CLAUSE_END
            particle = end if end and words[end:end + 1] and words[end] in _SWITCH_PARTICLES and ends_clause else 0
        if particle:
            out[k] = "switch"
            notes.append(f"'cut ... {words[particle]}' read as 'switch ... {words[particle]}' (dialect)")
    return out


#: particles that say how a thing is done to it, closing the clause after it ("cut a breadcake open",
#: "wash the bowl out"): particle -> (the verbs, the property the thing must have)
_HOW_PARTICLES = {"open": ({"cut", "slice", "split"}, "sliceable"), "out": ({"wash", "rinse", "scrub"}, "washable")}
#: who a thing is done for, said between the verb and the thing ("cut us a breadcake open")
_FOR_WHOM = {"me", "us", "him", "her"}


def how_particles(words: list[str], world: dict, index: dict, notes: list[str]) -> list[str]:
    """The words without a particle that says how a thing is done to it (:data:`_HOW_PARTICLES`:
    "cut us a breadcake open", "wash the dog bowl out"), said of things with the property the
    verb needs (or of "it" / "them"), the clause ending after it. "cut the bag open" (a thing that
    opens) is left as said: there "open" is what is asked."""
    out = list(words)
    for k, w in enumerate(words):
        said = [p for p, (verbs, _) in _HOW_PARTICLES.items() if w in verbs]
        if not said or k + 1 >= len(words):
            continue
        particle, (_, prop) = said[0], _HOW_PARTICLES[said[0]]
        start = k + 1 + (words[k + 1] in _FOR_WHOM)
        start = _after_determiners(words, start)
        start += words[start:start + 1] == ["a"]
        end = start + 1 if words[start:start + 1] in (["it"], ["them"]) else \
            _phrase_of(words, start, world, index, prop, receptacles=particle != "open")
        if end and words[end:end + 1] == [particle] and (end + 1 >= len(words) or words[end + 1] in _CLAUSE_END) \
                and not (particle == "open" and _phrase_of(words, start, world, index, "openable")):
            out[end] = ""
            notes.append(f"'{w} ... {particle}' read as '{w} ...' (how it is done)")
    return [w for w in out if w]


def put_on_as_switch(words: list[str], world: dict, index: dict, notes: list[str]) -> list[str]:
    """The words with "put" read as "switch" where "on" or "off" and then a thing that switches
    follow it ("put on the radio", "put off the fan" as Indian and Nigerian English say it):
    "put the radio on" is read already, "put the telly off" (the clause ending there) is switching
    it off too, "put the light" (a fixed thing that switches, no place said; Spanish "poner la
    luz") is switching it on, and "put on the sweater" (no switch) or "put on the trestle" (a
    place, with its thing said before) keep "put" as placing. A note says so."""
    out = list(words)
    for k, w in enumerate(words):
        if w == "put" and k + 1 < len(words) and words[k + 1] in _SWITCH_PARTICLES \
                and _switching_phrase(words, _after_determiners(words, k + 2), world, index):
            out[k] = "switch"
            notes.append(f"'put {words[k + 1]}' read as 'switch {words[k + 1]}'")
        elif w in ("put", "putting") and k + 1 < len(words):   # "put the telly off": nothing is put off a telly
            end = _switching_phrase(words, _after_determiners(words, k + 1), world, index)
            if end and words[end:end + 1] == ["off"] and (end + 1 >= len(words) or words[end + 1] in _CLAUSE_END):
                out[k] = "switch" if w == "put" else "switching"
                notes.append("'put ... off' read as 'switch ... off'")
            elif w == "put" and end and (end >= len(words) or words[end] in _CLAUSE_END | {","}) \
                    and _fixed(words[_after_determiners(words, k + 1):end], world, index):
                # "put the light of the dining": Spanish and Italian "poner / mettere la luce"
                out[k:k + 1] = ["switch", "on"]
                notes.append("'put' read as 'switch on' (of a fixed thing that switches, with no place said)")
    return out


#: units said after a setting's number ("put the oven at 180 degrees", "at 22 gradi")
_SETTING_UNITS = {"degrees", "degree", "gradi", "c", "celsius"}


def setting_as_switch(words: list[str], world: dict, index: dict, notes: list[str]) -> list[str]:
    """The words with "put / set / turn <a thing that switches> at / to <number>" ("put the oven at
    180", "set the aircon to 22 degrees": Italian "metti il forno a 180") read as switching it on: a
    setting is given to a thing that is on, and the home model has on and off, no dial. Only where
    the clause ends after the number (and its unit)."""
    out: list[str] = []
    k = 0
    while k < len(words):
        w = words[k]
        end = _switching_phrase(words, _after_determiners(words, k + 1), world, index) \
            if w in ("put", "set", "turn") else 0
        at = end + 1 if end and words[end:end + 1] in (["at"], ["to"]) else 0
        stop = at + 1 + (at + 1 < len(words) and words[at + 1] in _SETTING_UNITS) if at and words[at:at + 1] \
            and words[at].isdigit() else 0
        if stop and (stop >= len(words) or words[stop] in _CLAUSE_END | {","}):
            out += ["switch", "on"] + words[k + 1:end]
            notes.append(f"'{' '.join(words[k:stop])}' read as switching it on (a setting is given to what is on)")
            k = stop
            continue
        out.append(w)
        k += 1
    return out


def _fixed(name: list[str], world: dict, index: dict) -> bool:
    """Whether the words name only things that stay where they are (none may be picked up)."""
    things = index.get(tuple(name)) or []
    entries = [(world.get("objects") or {}).get(t["name"]) or (world.get("places") or {}).get(t["name"]) or {}
               for t in things if t["kind"] in ("object", "place")]
    return bool(entries) and len(entries) == len(things) and not any(
        "pickupable" in (e.get("properties") or []) for e in entries)


#: "make the light out", "make the kettle on", "the washing machine make on" (German "mach ... an /
#: aus"): switch on, off
_MAKE_PARTICLES = {"on": "on", "off": "off", "out": "off"}
#: what may follow the particle of "make ... out" ("make all the lights out except the lamp")
_MAKE_CLOSES = _CLAUSE_END | {"except", "but", "apart"}


def make_as_switch(words: list[str], world: dict, index: dict, notes: list[str]) -> list[str]:
    """The words with "make" read as "switch" where it is said with "on", "off" or "out" and a
    phrase that names only things that switch, in any of German's orders ("make the light out",
    "make out the light", "the washing machine make on": switch on the washing machine), the
    particle closing the clause where it comes after the thing: what switches cannot be "made"
    anything else. "out" is "off". "make the bed", "make the tea" and "make it warm" keep their
    meaning. A note says so."""
    out = list(words)
    for k in [k for k, w in enumerate(words) if w == "make"]:   # each rewrite keeps the words' number
        said = out[k + 1] if k + 1 < len(out) else "."
        closes = k + 2 >= len(out) or out[k + 2] in _MAKE_CLOSES
        end = _switching_name(out, _after_determiners(out, k + 1), world, index)
        if said in _MAKE_PARTICLES and _switching_name(out, _after_determiners(out, k + 2), world, index):
            out[k:k + 2] = ["switch", _MAKE_PARTICLES[said]]   # "make out the light"
        elif said in _MAKE_PARTICLES and closes and (start := _switching_before(out, k, world, index)) is not None:
            out[start:k + 2] = ["switch", _MAKE_PARTICLES[said]] + out[start:k]   # "the washing machine make on"
        elif end and out[end:end + 1] and out[end] in _MAKE_PARTICLES and (
                end + 1 >= len(out) or out[end + 1] in _MAKE_CLOSES):
            said = out[end]
            out[k], out[end] = "switch", _MAKE_PARTICLES[said]   # "make the light out"
        else:
            continue
        notes.append(f"'make ... {said}' read as 'switch ... {_MAKE_PARTICLES[said]}' (German 'machen ... an / aus')")
    return out


def _switching_before(words: list[str], k: int, world: dict, index: dict) -> int | None:
    """Where the clause before ``k`` opens, when all of it (after "and", "then" or a mark) is a
    phrase naming only things that switch ("..., and the washing machine make on"); else None."""
    start = k
    while start and words[start - 1] not in _CLAUSE_END:
        start -= 1
    return start if start < k and _switching_name(words, _after_determiners(words, start), world, index) == k else None


def _switching_name(words: list[str], k: int, world: dict, index: dict) -> int:
    """The index after a name at ``k`` of things that switch: a category ("the lights") whose
    members switch and none opens, or things that switch (:func:`_switching_phrase`); else 0."""
    end, switch_only = _named(words, k, world, index)
    return end if end is not None and switch_only else _switching_phrase(words, k, world, index)


#: "open the light", "close the aircon" (Philippine and South Asian English): switch on, off
_OPEN_CLOSE = {"open": "on", "close": "off"}


def open_close_as_switch(words: list[str], world: dict, index: dict, notes: list[str]) -> list[str]:
    """The words with "open" / "close" read as "switch on" / "switch off" before a phrase that
    names only things that switch and cannot be opened in this home ("close all the lights",
    "open the aircon", as Philippine and South Asian English say it): of such a thing, opening
    and closing can mean nothing else. Before a thing that opens ("close the fridge", "open the
    washing machine", which may switch too) they keep their meaning. In a list that names both
    ("close the ref and the tv"), each item is read by what it is: "close the ref and switch off
    the tv". A note says so."""
    out: list[str] = []
    k = 0
    while k < len(words):
        w = words[k]
        items = _listed(words, k + 1, world, index) if w in _OPEN_CLOSE else []
        kinds = {switch_only for _, _, switch_only in items}
        if w in _OPEN_CLOSE and not items and _switches_said_before(words, k, world, index):
            # "Deniz's lamp close please" (the verb after its thing, Turkish and Korean order)
            out += ["switch", _OPEN_CLOSE[w]]
            notes.append(f"'{w}' read as 'switch {_OPEN_CLOSE[w]}' (of a thing that switches and does not open, "
                         "named before it)")
        elif items and kinds == {True}:
            out += ["switch", _OPEN_CLOSE[w]]
            notes.append(f"'{w}' read as 'switch {_OPEN_CLOSE[w]}' (of a thing that switches and does not open)")
        elif len(kinds) == 2:   # each item with the verb its thing takes
            said = {True: ["switch", _OPEN_CLOSE[w]], False: [w]}
            for n, (start, end, switch_only) in enumerate(items):
                if n:
                    out += words[items[n - 1][1]:start]   # the joiner
                out += (said[switch_only] if n == 0 or switch_only != items[n - 1][2] else []) + words[start:end]
            notes.append(f"'{w}' read item by item: 'switch {_OPEN_CLOSE[w]}' of the things that switch and do "
                         f"not open, '{w}' of the others")
            k = items[-1][1]
            continue
        else:
            out.append(w)
        k += 1
    return out


#: what may close a clause after its verb ("the lamp close please", "the tv close, ...")
_CLAUSE_ENDS = {",", ".", ";", "!", "?", "please", "pls", "and", "then", "also", "too", "now"}


def _switches_said_before(words: list[str], k: int, world: dict, index: dict) -> bool:
    """Whether the clause before ``k`` is only a list of things that switch and cannot be opened
    (:func:`_listed`), and the clause ends after the word at ``k``."""
    if k + 1 < len(words) and words[k + 1] not in _CLAUSE_ENDS:
        return False
    start = k
    while start and words[start - 1] not in (",", ".", ";", "!", "?", "then"):
        start -= 1
    while start < k and words[start] in ("please", "pls", "and"):
        start += 1
    items = _listed(words, start, world, index) if start < k else []
    return bool(items) and items[-1][1] == k and all(switch_only for _, _, switch_only in items)


def _listed(words: list[str], k: int, world: dict, index: dict) -> list[tuple[int, int, bool]]:
    """The things named from ``k`` on as a list ("the ref and the tv", "the fan, the lamp and the
    window"): each item's first word (after the joiner), the end of its name, and whether it
    switches and cannot be opened. The list ends before a joiner followed by what names nothing;
    empty when the phrase at ``k`` names nothing."""
    items: list[tuple[int, int, bool]] = []
    start = k
    while True:
        end, switch_only = _named(words, _after_determiners(words, start), world, index)
        if end is None:   # the list ends before what names nothing ("... and go to bed")
            return items
        items.append((start, end, switch_only))
        if end < len(words) and words[end] in ("and", ","):
            start = end + 1 + (end + 1 < len(words) and words[end] == "," and words[end + 1] == "and")
            continue
        return items


def _named(words: list[str], k: int, world: dict, index: dict) -> tuple[int | None, bool]:
    """The end of the longest name at ``k`` and whether all it names switch and none opens (None
    when no name of an object, place or category stands there)."""
    tables = [world.get("objects") or {}, world.get("places") or {}]
    for end in range(min(len(words), k + 5), k, -1):
        things = index.get(tuple(words[k:end])) or []
        if not things:
            continue
        entries = []
        for t in things:
            if t["kind"] in ("object", "place"):
                entries += [table[t["name"]] for table in tables if t["name"] in table]
            elif t["kind"] == "category":
                entries += [e for table in tables for e in table.values() if t["name"] in (e.get("categories") or [])]
            else:
                return None, False
        if not entries:
            return None, False
        return end, all("toggleable" in (e.get("properties") or []) and
                        "openable" not in (e.get("properties") or []) for e in entries)
    return None, False


def _after_determiners(words: list[str], k: int) -> int:
    """The index of the first word at or after ``k`` that is no determiner ("the", "that", "all")."""
    while k < len(words) and words[k] in _DETERMINERS:
        k += 1
    return k


#: words after which a clause may open with "on" / "off" as its verb
_POLITE = {"please", "kindly", "abeg", "biko", "pls"}
_ENDS = {w for w, cls in PUNCT.items() if cls == "END"}
_OPENERS = set(PUNCT) | _POLITE | {"and", "then", "just", "also"}


def on_off_as_verbs(words: list[str], world: dict, index: dict, notes: list[str]) -> list[str]:
    """The words with "switch" put before "on" / "off" that open a clause as its verb, as West
    African and South Asian English say it ("on the corridor light", "abeg off the fan", "off it"):
    only before a thing that switches (or "it" / "them"), so "on the table" and "off the shelf"
    stay places."""
    out: list[str] = []
    for k, w in enumerate(words):
        before = out[-1] if out else "."
        if w in _SWITCH_PARTICLES and before in _OPENERS:
            j = _after_determiners(words, k + 1)
            pronoun = j == k + 1 and words[j:j + 1] in (["it"], ["them"])
            # a thing that switches and holds things (a hob) after "and" or a comma may be where
            # the thing before goes ("put the pan in the sink, and on the hob ..."): only at the
            # head of a sentence or after a "please" is its "on" a verb
            heading = before in _ENDS or before in _POLITE
            # a name may open with a determiner ("our water heater")
            if pronoun or any(_switching_phrase(words, i, world, index, receptacles=heading)
                              for i in range(k + 1, j + 1)):
                out.append("switch")
                notes.append(f"'{w} {' '.join(words[k + 1:j + 1])}' read as 'switch {w} ...' (dialect)")
        out.append(w)
    return out


def _switching_phrase(words: list[str], k: int, world: dict, index: dict, receptacles: bool = True) -> int:
    """The index after a phrase at ``k`` that names only things that switch (and hold nothing,
    unless ``receptacles``), else 0."""
    return _phrase_of(words, k, world, index, "toggleable", receptacles)


def _phrase_of(words: list[str], k: int, world: dict, index: dict, prop: str, receptacles: bool = True) -> int:
    """The index after a phrase at ``k`` that names only things with the property ``prop`` (and
    that hold nothing, unless ``receptacles``), else 0. A category ("all the lights") names its
    members, objects and places."""
    every = {**(world.get("places") or {}), **(world.get("objects") or {})}
    for end in range(min(len(words), k + 5), k, -1):
        things = index.get(tuple(words[k:end])) or []
        entries = [every.get(t["name"]) or {} for t in things if t["kind"] in ("object", "place")]
        entries += [e or {} for t in things if t["kind"] == "category"
                    for e in every.values() if t["name"] in ((e or {}).get("categories") or [])]
        if entries and all(prop in (e.get("properties") or []) and (
                receptacles or "receptacle" not in (e.get("properties") or [])) for e in entries):
            return end
        if things:
            return 0
    return 0


#: verbs whose "in" before the thing says indoors ("bring in the washing")
_BRING_IN = {"bring", "take", "carry", "fetch", "get"}


def bring_in(words: list[str], index: dict, notes: list[str]) -> list[str]:
    """The words without the "in" of "bring in the orchid from the balcony": before things that are
    only objects of the home (never a place: "take in the fridge" is left as said), "in" says
    indoors, and the home model has no outdoors; where the thing goes is still to be said ("bring
    in the orchid": where to? is asked, as for "bring the orchid")."""
    out = list(words)
    k = 0
    while k + 2 < len(out):
        if out[k] in _BRING_IN and out[k + 1] == "in":
            j = _after_determiners(out, k + 2)
            refs = next((index[tuple(out[j:e])] for e in range(min(len(out), j + 5), j, -1)
                         if tuple(out[j:e]) in index), [])
            if refs and all(ref["kind"] == "object" for ref in refs):
                notes.append(f"'{out[k]} in' says indoors (the home model has no outdoors): read as '{out[k]}'")
                del out[k + 1]
        elif out[k] in _BRING_IN and (end := name_end(out, j := _after_determiners(out, k + 1), index)) \
                and all(ref["kind"] == "object" for ref in index[tuple(out[j:end])]) and end < len(out) \
                and out[end] == "in" and (end + 1 == len(out) or out[end + 1] in _AFTER_IN):
            # "bring the towel in (from the line) and ...": the "in" after the thing, the same
            notes.append(f"'{out[k]} ... in' says indoors (the home model has no outdoors): read as '{out[k]}'")
            del out[end]
        k += 1
    return out


#: what may follow the "in" of "bring the towel in": the clause's end, where from, the next order
_AFTER_IN = frozenset(PUNCT) | {"from", "and", "then", "while", "please", "now", "for"}


#: verbs of switching whose particle may stand after the things ("turn all the lights off")
_SWITCH_VERBS = {"turn", "switch", "flip", "flick"}
#: words a clause's verb may follow ("pls turn ...", "and turn ...")
_BEFORE_VERB = {"and", "then", "pls", "please", "can", "u", "you"}
#: what opens an exception after the things ("except", "but not", "apart from")
_EXCEPT_OPENERS = (("except",), ("but", "not"), ("apart", "from"), ("other", "than"), ("bar",))


def particle_before_exception(words: list[str], notes: list[str]) -> list[str]:
    """The words with the "on" / "off" of "turn all the lights off except the verandah one" said
    right after its verb ("turn off all the lights except ..."), where the grammar reads the
    exception: only where a verb of switching opens the clause, "on" / "off" follows its things
    and an exception follows the particle at once."""
    out = list(words)
    for k, w in enumerate(out):
        if w not in _SWITCH_VERBS or (k and out[k - 1] not in PUNCT and out[k - 1] not in _BEFORE_VERB):
            continue
        end = next((j for j in range(k + 1, len(out)) if out[j] in PUNCT), len(out))
        p = next((j for j in range(k + 2, end) if out[j] in ("on", "off")), None)
        if p is not None and any(tuple(out[p + 1:p + 1 + len(o)]) == o for o in _EXCEPT_OPENERS):
            notes.append(f"'{w} ... {out[p]} except' read as '{w} {out[p]} ... except'")
            out[k + 1:p + 1] = [out[p]] + out[k + 1:p]
    return out


def do_as_wash(words: list[str], world: dict, index: dict, notes: list[str]) -> list[str]:
    """ "do the pots", "do the dishes": "do" opening a clause before things that are all washing
    (objects that wash, or a category whose every member does) asks for them washed, as "wash the
    pots" does; before anything else ("do the lights", "do the bed") it is left as said."""
    out = list(words)
    for k, w in enumerate(words):
        if w != "do" or (k and words[k - 1] not in PUNCT and words[k - 1] not in _BEFORE_VERB | {"just"}):
            continue
        j = _after_determiners(words, k + 1)
        if j == k + 1:   # "do it", "do both": no thing named
            continue
        end = name_end(words, j, index)
        refs = index[tuple(words[j:end])] if end else []
        named = objects_named(refs, world)
        if named and all(ref["kind"] in ("object", "category") for ref in refs) \
                and all("washable" in world["objects"][n]["properties"] for n in named):
            notes.append(f"'do the {words[j]}' read as washing them")
            out[k] = "wash"
    return out


#: rooms said after a thing switched ("put the standard lamp on in the front room")
_ROOMS_SAID = sorted((tuple(r.split()) for r in ROOM_WORDS), key=len, reverse=True)


def room_of_a_switched_thing(words: list[str], index: dict, notes: list[str]) -> list[str]:
    """ "put the standard lamp on in the front room", "switch off the big light in the back room":
    the room where a thing switched stands, said after it, where the words name one thing of the
    home: the home model has no rooms, and one thing named needs none to be found, so the room
    is left out (a note says so). After words that name several things ("the light in the
    kitchen") it is left as said, and refused: reading it as any light would widen the order."""
    out = list(words)
    k = 0
    while k < len(out):
        room = next((r for r in _ROOMS_SAID if out[k:k + 2] == ["in", "the"] and tuple(out[k + 2:k + 2 + len(r)]) == r),
                    None)
        if room is not None and _one_thing_switched_before(out, k, index):
            notes.append(f"'in the {' '.join(room)}': where {out[k - 2] if out[k - 1] in _SWITCH_PARTICLES else out[k - 1]} "
                         "is; one thing is named, so the room adds nothing")
            del out[k:k + 2 + len(room)]
            continue
        k += 1
    return out


def _one_thing_switched_before(words: list[str], k: int, index: dict) -> bool:
    """Whether the words before ``k`` end with one thing of the home switched: "<thing> on|off" or
    "<switch verb> on|off [the] <thing>"."""
    end = k - 1 if k and words[k - 1] in _SWITCH_PARTICLES else k
    for start in range(max(0, end - 4), end):
        refs = index.get(tuple(words[start:end]))
        if not refs or len(refs) != 1 or refs[0]["kind"] not in ("object", "place"):
            continue
        j = start - (start and words[start - 1] in _DETERMINERS)
        if end < k or (j >= 2 and words[j - 1] in _SWITCH_PARTICLES and words[j - 2] in _SWITCH_VERBS | {"put"}):
            return True
    return False

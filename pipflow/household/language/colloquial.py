"""Colloquial phrases read as the grammar's words before tagging, each by a rule of English that
holds in any home (docs/household.md, "colloquial phrases"): "an' all" closing a clause is
"too"; "the pair of them" is "both of them"; "all" between a verb of becoming and the word after
it is a degree ("it's gone all soft"); "when it's done" after a step is "then"; an exchange
spelled out after a colon is that spelling out. Each rewrite
leaves a note, so the echo says what was read so."""
from __future__ import annotations

from pipflow.household.language.lexicon import FILLER, HOME_WORDS, LIGHT_CUES, PHRASES, TEMPERATURE_CUES
from pipflow.household.language.tokens import PUNCT

#: "and the torch an' all": a thing added to what the clause before did ("too"); only closing a
#: clause ("and all the mugs" opens a noun phrase and stays)
_ALSO = {("an", "all"): ["too"], ("and", "all"): ["too"]}
#: "slice the pair of them": the two things before, as "both of them" (which asks when they are
#: not exactly two)
_PAIR = {("the", "pair", "of", "them"): ["both", "of", "them"], ("the", "two", "of", "them"): ["both", "of", "them"],
         ("the", "pair"): ["both"]}
#: verbs of becoming, after which "all" grades the word that follows ("gone all soft", "getting
#: all dusty"), not a quantity of things
BECOMING = {"gone", "going", "went", "turned", "turning", "turns", "got", "getting", "gets", "looks", "looking"}
#: "when it's done", "once that's ready": the step before is finished, the order of the steps
#: (which the plan decides); the pronoun points back, so a command that opens with it is refused
_DONE = {"done", "ready", "finished"}
#: states a step makes, which "when it <state>" (the copula left out, as Caribbean and African
#: American English say it) waits for: "heat it up, an when it hot put it on the table"
_MADE = {"hot", "clean", "warm", "dry", "cooked", "washed", "sliced"}
_WHEN = {"when", "once", "after"}
_BACK = {"it", "they", "that", "this", "those", "these", "you"}
_COPULA = {("is",), ("are",), ("has", "been"), ("have", "been"), ("have",)}
#: the pronoun and its copula typed as one word ("when its done", "once youre finished")
_BACK_IS = {"its", "thats", "theyre", "youre"}


#: "first take out the bedsheet, only after that put the uniform in", "after that only" (Indian
#: English puts "only" after what it stresses): the order of the steps, as "then"
_ONLY_THEN = {("only", "after", "that"), ("after", "that", "only"), ("only", "after", "this"),
              ("after", "this", "only"), ("only", "then"), ("then", "only")}


#: "it's that dark in here", "the soup's that cold": "that" before how a thing or the room is,
#: after a copula that has a subject before it, is a degree ("so"); "wash the mug, is that dirty?"
#: (the copula opens the clause: "that" is its subject) stays
_DEGREE_AFTER = {"is", "are", "was", "were", "been", "getting", "gone"}
_DEGREE_OF = {"ADJ", "LIGHTCUE", "TEMPCUE", "SOUNDCUE", "AIRCUE"}


def _that_as_degree(words: list[str], k: int, out: list[str]) -> bool:
    """Whether "that" at ``k`` grades the word after it (:data:`_DEGREE_AFTER`)."""
    return words[k] == "that" and len(out) >= 2 and out[-1] in _DEGREE_AFTER and out[-2] not in PUNCT \
        and k + 1 < len(words) and PHRASES.get((words[k + 1],), ("",))[0] in _DEGREE_OF


#: verbs of an exchange, and the particles that may close one ("swap the mug and the jug over")
_SWAPS = {"swap", "exchange", "switch"}
_SWAP_PARTICLES = {"over", "round", "around", "about"}
#: words of the things of an exchange that need not be said again after the colon
_SWAP_GLUE = {"the", "a", "an", "my", "our", "your", "and", ","} | _SWAP_PARTICLES


def spelled_out_swap(words: list[str], notes: list[str]) -> list[str]:
    """ "swap the mug and the jug over: mug in the cupboard, jug in the fridge": an exchange whose
    sentence spells out after a colon where each thing goes is read as that spelling out ("put the
    mug in the cupboard, jug in the fridge"); every word of the things swapped must be said again
    after the colon, else the words stay as said (an exchange alone is refused: where each goes is
    not said)."""
    out: list[str] = []
    k = 0
    while k < len(words):
        start = k == 0 or words[k - 1] in (".", "!", "?", ";")
        colon = next((j for j in range(k, len(words)) if words[j] in PUNCT and words[j] != ","), None)
        if start and words[k] in _SWAPS and colon is not None and words[colon] == ":" and colon > k + 1:
            swapped = [w for w in words[k + 1:colon] if w not in _SWAP_GLUE]
            end = next((j for j in range(colon + 1, len(words)) if words[j] in (".", "!", "?", ";")), len(words))
            told = set(words[colon + 1:end])
            if swapped and all(w in told for w in swapped) and len(swapped) >= 2:
                notes.append(f"'{' '.join(words[k:colon])}' is spelled out after the colon: read as where each goes")
                out.append("put")
                k = colon + 1
                continue
        out.append(words[k])
        k += 1
    return out


#: verbs after which "back" says "again" ("close back the fridge", "shut the door back"), never
#: where a thing goes ("put it back" stays as said)
_CLOSING_VERBS = {"close", "shut", "lock"}


def _closed_back(out: list[str], after: str) -> str:
    """The verb of closing a "back" says "again" of, or "": the word right before it ("close back
    the X"), or, where "back" ends its clause, the clause's first word ("close the X back")."""
    if out and out[-1] in _CLOSING_VERBS:
        return out[-1]
    k = len(out)
    while k and out[k - 1] not in PUNCT:
        k -= 1
    first = out[k] if k < len(out) else ""
    return first if after in PUNCT and first in _CLOSING_VERBS else ""


#: particles that close a clause for emphasis in West African English ("do it fast o", "close the
#: fridge back o", "thank you oo"): only before a stop or a comma, where no word of an order stands
_CLOSING_PARTICLES = {"o", "oo", "ooo"}
#: "you hear?" closing a sentence
_HEAR_TAGS = {(you, "hear") for you in ("you", "ya", "yuh", "yu")}


def _after(words: list[str], k: int) -> str:
    """The word after ``k``, or "." at the end."""
    return words[k + 1] if k + 1 < len(words) else "."


#: what "only X" is said to do after a selection of all, where German says "nur X nicht" / "nur X
#: bleibt an": "all the fruit in the fridge, only the banana not" (except the banana)
_STAYS = {"stays", "stay", "remains", "remain"}
_KEPT_STATES = {"on", "off", "open", "closed", "shut"}


def only_not_as_except(words: list[str], notes: list[str]) -> list[str]:
    """The words with ", only X not" and ", only X stays on" after a clause that selects "all" read
    as ", except X" and ", except X, leave X on": the one thing left out of the selection (German
    "nur X nicht", "nur X bleibt an"). Only closing a clause, X at most five words with no mark,
    number or operative word of its own; anywhere else "only" is read as it always is."""
    out: list[str] = []
    k = 0
    while k < len(words):
        end = next((j for j in range(k + 2, min(k + 8, len(words) + 1)) if j == len(words) or words[j] in PUNCT),
                   None) if words[k] == "only" and out[-1:] == [","] else None
        said = words[k + 1:end] if end is not None else []
        opened = max((j + 1 for j, w in enumerate(out) if w in PUNCT and w != ","), default=0) if said else 0
        thing, tail = _left_out(said) if said and "all" in out[opened:] else ([], [])
        if thing:
            notes.append(f"'only {' '.join(said)}' after a selection of all: read as 'except {' '.join(thing)}'")
            out[-1:] = ["except", *thing, *tail]   # the comma goes: the exception closes the selection
            k = end
            continue
        out.append(words[k])
        k += 1
    return out


def _left_out(said: list[str]) -> tuple[list[str], list[str]]:
    """What ``said`` ("the saucer not", "the lamp stays on") leaves out, and what it asks of it after
    (", leave the lamp on"); ([], []) where it is no such phrase or holds an operative word."""
    if said[-1:] == ["not"]:
        thing, tail = said[:-1], []
    elif len(said) > 2 and said[-2] in _STAYS and said[-1] in _KEPT_STATES:
        thing, tail = said[:-2], [",", "leave", *said[:-2], said[-1]]
    else:
        return [], []
    if not thing or not all(w.isalpha() and w not in ("not", "no", "only", "all", "every") for w in thing):
        return [], []
    return thing, tail


#: "nobody watches", "no one reads" (the simple present, as German and other languages say "is
#: watching"): the activity cue, as "nobody is watching" is
_NOBODY = {"nobody", "noone"}
_SIMPLE_ACTIVITIES = {"watches": "watching", "reads": "reading", "uses": "using", "listens": "listening",
                      "plays": "playing", "works": "working", "looks": "looking", "studies": "studying",
                      "cooks": "cooking"}


def _nobody_does(words: list[str], k: int, out: list[str]) -> bool:
    """Whether ``words[k]`` is an activity in the simple present after "nobody" / "no one"."""
    return words[k] in _SIMPLE_ACTIVITIES and (out[-1:] and out[-1] in _NOBODY or out[-2:] == ["no", "one"])


#: words of how it feels in a room ("the place is dark", "di place hot"), said of the home itself
_FELT = {w for w in (*LIGHT_CUES, *TEMPERATURE_CUES) if " " not in w} | {"hot", "cold", "warm"}
#: words between the home and how it feels in it ("the place is too hot", "the flat feels cold")
_FEELS = {"is", "s", "feels", "feel", "getting", "gets", "so", "too", "very", "really", "well"}


def the_place_as_here(words: list[str], notes: list[str]) -> list[str]:
    """ "the place is dark", "di place hot" (the copula left out), "this flat feels cold": how it
    feels in the home, said of the home, read as "it is ... in here", the cue the grammar has. Only
    the home's own words (``HOME_WORDS``, "place") at a clause's start (after talk: "Lawd di place
    hot"); a room or a thing keeps its reading."""
    out: list[str] = []
    k = 0
    while k < len(words):
        start = not out or out[-1] in PUNCT or out[-1] in ("and", "but") or (out[-1],) in FILLER
        if start and words[k] in ("the", "this", "dis", "dat", "that") and k + 1 < len(words) \
                and words[k + 1] in (*HOME_WORDS, "place"):
            j = k + 2
            while j < len(words) and words[j] in _FEELS:
                j += 1
            if j < len(words) and words[j] in _FELT:
                said = ["it", "is", *(w for w in words[k + 2:j] if w not in ("is", "s", "feels", "feel", "gets")),
                        words[j], "in", "here"]
                notes.append(f"'{' '.join(words[k:j + 1])}' read as '{' '.join(said)}'")
                out += said
                k = j + 1
                continue
        out.append(words[k])
        k += 1
    return out


def colloquial(words: list[str], notes: list[str]) -> list[str]:
    """The words with the colloquial phrases of the module docstring read as the grammar's words."""
    words = the_place_as_here(only_not_as_except(spelled_out_swap(words, notes), notes), notes)
    out: list[str] = []
    k = 0
    while k < len(words):
        pair = tuple(words[k:k + 2])
        after = words[k + 2] if k + 2 < len(words) else "."
        if pair in _ALSO and after in PUNCT and out and out[-1] not in PUNCT:
            notes.append(f"'{' '.join(pair)}' closing a clause read as 'too'")
            out += _ALSO[pair]
            k += 2
            continue
        if words[k] == "back" and (verb := _closed_back(out, _after(words, k))):
            # "close back the washing machine", "close the fridge back" (Malaysian, West African English): close it again
            notes.append(f"'{verb} ... back': {verb} it again")
            k += 1
            continue
        if pair in _HEAR_TAGS and after in PUNCT and out:
            # "..., yuh hear?" (Jamaican, Southern US English): a tag asking for assent, no order
            notes.append(f"'{' '.join(pair)}' closing a sentence: a tag asking for assent, no word of the order")
            k += 2
            continue
        if words[k] in _CLOSING_PARTICLES and _after(words, k) in PUNCT and out and out[-1] not in PUNCT:
            notes.append(f"'{words[k]}' closing a clause: a particle of emphasis (West African English), no word of the order")
            k += 1
            continue
        if pair[:1] == pair[1:] and PHRASES.get(pair[:1], ("",))[0] == "ADJ" and out and out[-1] not in PUNCT:
            notes.append(f"'{' '.join(pair)}': the state said twice for emphasis, read once")
            out.append(words[k])
            k += 2
            continue
        four = tuple(words[k:k + 4])
        pairs = four if four in _PAIR else pair if pair in _PAIR and after in PUNCT else None
        if pairs is not None and out and out[-1] not in PUNCT:
            notes.append(f"'{' '.join(pairs)}' read as '{' '.join(_PAIR[pairs])}'")
            out += _PAIR[pairs]
            k += len(pairs)
            continue
        if words[k] == "all" and out and out[-1] in BECOMING and k + 1 < len(words) and words[k + 1] not in PUNCT \
                and (k + 2 == len(words) or words[k + 2] in PUNCT):
            notes.append(f"'{out[-1]} all {words[k + 1]}': 'all' grades '{words[k + 1]}' (no quantity of things)")
            k += 1
            continue
        if _that_as_degree(words, k, out):
            notes.append(f"'that {words[k + 1]}': 'that' grades '{words[k + 1]}', read as 'so'")
            out.append("so")
            k += 1
            continue
        if _nobody_does(words, k, out):
            notes.append(f"'{words[k]}' after nobody read as 'is {_SIMPLE_ACTIVITIES[words[k]]}'")
            out += ["is", _SIMPLE_ACTIVITIES[words[k]]]
            k += 1
            continue
        # "when it's done", "only after that", "after washing,": the order of the steps, after a step
        done = _when_done(words, k) or next((n for n in (3, 2) if tuple(words[k:k + n]) in _ONLY_THEN), 0) \
            or _after_doing(words, k, out)
        if done and any(w not in PUNCT and w not in ("and", "then") for w in out):
            notes.append(f"'{' '.join(words[k:k + done])}': the next step once the one before is done; read as 'then'")
            out.append("then")
            k += done
            continue
        out.append(words[k])
        k += 1
    return out


def _after_doing(words: list[str], k: int, said: list[str]) -> int:
    """2 where the words at ``k`` are "after" and the "-ing" form of a verb said before in the
    command, then a mark ("wash the pan and the spoons. After washing, spoons put in the cupboard"):
    after that step, as "then"; 0 otherwise (a verb not said before may be a new step: "after
    drying, fold it" is left as said)."""
    if words[k] != "after" or k + 2 >= len(words) or words[k + 2] not in PUNCT or not words[k + 1].endswith("ing"):
        return 0
    stem = words[k + 1][:-3]
    return 2 if any(v in said for v in (stem, stem + "e", stem[:-1]) if len(v) > 1) else 0


def _when_done(words: list[str], k: int) -> int:
    """How many words at ``k`` say "when it is done" ("once that's ready", "after they've been
    cooked"), 0 when they do not."""
    if words[k] not in _WHEN or k + 1 >= len(words):
        return 0
    if words[k + 1] in _BACK_IS:
        return 3 if k + 2 < len(words) and words[k + 2] in _DONE else 0
    if words[k + 1] not in _BACK:
        return 0
    for cop in _COPULA:
        j = k + 2 + len(cop)
        if tuple(words[k + 2:j]) == cop and j < len(words) and words[j] in _DONE:
            return j + 1 - k
    j = k + 2   # "when it hot den put it ...", "when it clean put it back": the copula left out
    if j < len(words) and words[j] in _DONE | _MADE and words[k + 1] in ("it", "they"):
        return j + 1 - k + (j + 1 < len(words) and words[j + 1] == "then")
    return 0

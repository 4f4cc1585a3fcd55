"""Third persons in a command: where they are, what is for them, and talk about them.

The home model has no people, so "bring Grandad his tea" has no place to go. A carer's commands
talk about the person cared for all the time ("Father Tom is in the armchair, bring him his
medicines", "he can't sleep", "boil an egg for Mrs Patel"). This module reads such a command
again, as :mod:`.whereabouts` does for "me":

1. a clause that is only where a person is ("Father Tom is in the armchair", "he sits the whole
   day in the armchair") is set aside and gives that person a place; "bring / give <person> X",
   "bring X to / for <person>" and "... <person> on the P" are then "bring X to the P". Where the
   command does not say where the person is, it is refused saying so: never guessed. Two persons
   said at two places leave the command as it was (refused).
2. "for <person>" elsewhere ("switch on the lamp for him"), and "for" + words that name nothing of
   the home closing a clause ("slice the onion for soup"), is what for: set aside, said in the notes.
   A purpose that names a thing of the home stays, to be read or refused.
3. a clause whose subject is a person and which names nothing of the home and no number ("Father
   Tom is sleeping", "he can't sleep") is talk about them: set aside, said in the notes.

Who is a person (never a word of the home's names or of the reader's lexicon, nor a typo of one):
"he", "she", "him" (and "her" after a verb of bringing, "for" or "to"); a kinship word alone
("Grandad", "Nan", "the baby": :data:`KIN`), with a capitalised name after it or not ("Grandad
Jones"); a title with a name after it ("Father Tom", "Mrs Patel", typed in lower case too:
"father tom": after a title, a word of no name of the home and of no lexicon is the name); a
capitalised word (or run of them) that is nobody's word ("Tom"); who the home's own words say owns
a thing ("papa" of "papa's mug", "ah ma" of "ah ma's bed": :func:`owners`), in lower case too, and
a word the home's words put before one thing's name ("michelle bed") where the command writes it as
a name ("for Michelle": :func:`proper_names`). Any other lower-case word alone is never a name:
"tom" may be a typo, "for tom" is at most a purpose. People are read after the command's Creole
words ("fuh he": for him).

The parser tries this only when a command does not read as said, so nothing that read before
reads otherwise; the rewritten command must still read whole, every word placed.
"""
from __future__ import annotations

import re
from typing import Collection

from pipflow.errors import TranslationError
from pipflow.household.language.dialect import TWO_OBJECT_VERBS, patois_in_home
from pipflow.household.language.lexicon import (AIR_CUES, FILLER, LIGHT_CUES, PHRASES, PURPOSE_WORDS, ROOM_WORDS,
                                                TEMPERATURE_ADJECTIVES, TEMPERATURE_CUES, words_of)
from pipflow.household.language.names import home_words, per_world, world_phrases
from pipflow.household.language.rewrites import CLOSING_PARTICLES, CONSUMED
from pipflow.household.language.tokens import PUNCT
from pipflow.household.language.typos import typo_of, vocabulary
from pipflow.household.language.whereabouts import BRING, POSTURE, clause_end, place_said
from pipflow.language.asides import FUNCTION_WORDS, duration_at, near_operative
from pipflow.language.english import common_word

#: titles before a name ("Father Tom", "Mrs Patel", "Auntie Jo"; "father tom" typed in lower case)
TITLES = {"father", "mrs", "mr", "ms", "miss", "dr", "doctor", "auntie", "aunty", "aunt", "uncle", "sister",
          "brother", "nurse", "lady", "sir",
          # aunts and uncles said in other languages ("Khaleh Mahin", "Tante Ria", "Tia Lupe", "Teyze")
          "khaleh", "khale", "ammeh", "amme", "amoo", "amu", "dayi", "tante", "tia", "tio", "zia", "zio",
          "teyze", "amca", "khala", "khalti", "ammo"}
#: words that name a person alone ("bring Grandad his tea", "the baby is asleep")
KIN = {"grandad", "granddad", "grandpa", "grandma", "granny", "gran", "nan", "nana", "nanna", "grandmother",
       "grandfather", "baby", "husband", "hubby", "wife", "son", "daughter", "grandson", "granddaughter",
       "mum", "mom", "mummy", "mommy", "dad", "daddy", "children", "kids", "grandchildren", "grandkids",
       "pickney", "pickneys", "grandpickney", "grandpickneys",
       # Newfoundland, Irish and American ("the youngsters": the children; "young'uns"; "Nanny", "Pops")
       "youngsters", "youngster", "youngins", "younguns", "grandchild", "mother", "nanny", "pops",
       # Geordie and Scots ("the bairn": the child; "wor lass", "the missus": the wife)
       "bairn", "bairns", "lass", "missus",
       # northern English, Irish and Scouse ("me mam", "me nan", "the arl fella": the old man)
       "mam", "mammy", "fella", "fellow",
       # the same said in the family's other language ("Maman is sleeping", "bring Jeddo his tea")
       "maman", "mamani", "madar", "pedar", "baba", "mama", "papa", "jeddo", "teta", "dadi", "dada", "nani",
       "abuela", "abuelo", "abuelita", "abuelito", "oma", "opa", "nonna", "nonno", "yaya", "babcia", "dziadek",
       "bibi", "ammi", "abbu", "amma", "appa", "lola", "lolo", "nanay", "tatay", "ouma", "oupa", "gogo",
       "bubbe", "zayde", "anneanne", "babaanne", "dede", "halmeoni", "harabeoji"}
#: pronouns that are a person; "her" only where an object is ("bring her the tea"); "them" and
#: "they" are left to things ("put them away")
PERSON_PRONOUNS = {"he", "she", "him", "hes", "shes"}   # "hes": he's, typed without its apostrophe
#: pronouns that can only be a clause's subject
_SUBJECT_PRONOUNS = frozenset({"he", "she", "hes", "shes"})
#: verbs that take a person as where the thing goes ("give him the tea")
TO_PERSON = BRING | {"give", "take"}
#: words that take up a thing ("he wants it warm"): a clause with one is about the thing, never talk
THING_WORDS = {"it", "them", "those", "these", "this", "that", "one", "ones"}
#: lexicon classes that ask something of the home (a verb, a wish, a state, a cue of warmth, light,
#: sound or air): a clause about a person with one may ask for it, so it is never set aside
#: ("he wants the heating on", "she is cold"); a sleeping person is talk ("Father Tom is sleeping")
ASKING = {"NEED", "WANT", "ADJ", "SEE", "TEMPCUE", "LIGHTCUE", "SOUNDCUE", "AIRCUE", "HEARCUE", "TOO", "NEAR"}
#: "give him the tea" is bringing it to where he is: the verb the grammar reads with "to P"
GIVE_AS = {"give": "bring"}
#: verbs that say a person is somewhere ("he sits in the armchair", "Tom's in bed")
BEING = {"is", "are", "sits", "sit", "sat", "lies", "stays", "was", "were"}
#: words between such a verb and where: posture, how long, and what a person does there that takes no
#: object ("he sits the whole day in the armchair", "Abiye is reading in the salon")
THIRD_POSTURE = frozenset(POSTURE | {"the", "whole", "day", "always", "usually", "mostly", "morning", "afternoon",
                                      "sleeping", "asleep", "dozing", "napping", "resting", "reading", "studying",
                                      "working", "praying", "waiting", "sweating", "relaxing", "playing", "awake",
                                      "staying", "lounging", "chilling", "today", "tonight"})


#: what a person does with a thing where they are ("Abiye is reading the gazeta in the salon")
DOING = frozenset({"reading", "watching", "using", "eating", "drinking", "playing"})
#: small words inside a title ("Homes Under the Hammer", "Lord of the Rings")
_TITLE_GLUE = frozenset({"the", "of", "and", "in", "on", "under", "a", "an", "to", "at", "for", "with", "from", "by"})
#: what a thing's own word says is someone's ("jun hao's bag", "ah ma's bed", "the kids' aircon")
_OWNER = re.compile(r"^(?:the\s+)?(.+?)(?:['\u2019]s|(?<=s)['\u2019])\s")


def owners(world: dict, words: list[str],
           proper: Collection[str] = frozenset()) -> dict[tuple[str, ...], list[tuple[str, ...]]]:
    """The home's people (:func:`_owner_candidates`) for a command of ``words``: a name said
    without "'s" ("minjun bed") counts only where the command says it and it is no common English
    word ("kitchen" of "kitchen sink", "kitchen table" is none), or where the command writes it as
    a name (``proper``: :func:`proper_names`; "for Michelle" where the home has a "michelle bed",
    "Jamal coming home" where it has a "jamal desk", names an English word list holds too). Only the
    reading of people (:class:`_Reader`) passes ``proper``: a name said before a thing ("put Elsa
    cup in the sink" where the home has an "Elsa doll") is never taken for its owner by it, as it
    may be the thing's make or character. The English word list is asked only then: loading it
    costs a second and some 16 MB, which most commands never need."""
    people, named, once = _owner_candidates(world)
    if not named and not once:
        return people
    said = set(words)
    return {who: names for who, names in people.items()
            if (who not in named and who not in once) or who[0] in said and (
                who[0] in proper or who in named and not common_word(who[0]))}


def proper_names(command: str) -> frozenset[str]:
    """The words a command writes as names, lower-cased: capitalised, after no article or
    possessive, and no word of a room ("heat it for Michelle", "Jamal coming home"; never "Turn off
    the Kitchen light"). Only a word the home's own names put before a thing's name is then taken
    for a person (:func:`owners`), and never where it and what follows are a name of the home
    themselves ("Gallery light on")."""
    found = set()
    for m in re.finditer(r"(?:(\w+)\W*\s+|^\W*)([A-Z][a-z]+)\b", command):
        before, word = (m.group(1) or "").lower(), m.group(2).lower()
        if before not in _BEFORE_NO_NAME and word not in ROOM_WORDS:
            found.add(word)
    return frozenset(found)


#: words after which a capitalised word is a thing's name, not a person's ("the Kitchen light")
_BEFORE_NO_NAME = frozenset({"the", "de", "di", "da", "a", "an", "this", "that", "dat", "dis", "my", "our", "your",
                             "his", "her", "their", "muh", "mi"})


@per_world
def _owner_candidates(world: dict) -> tuple[dict[tuple[str, ...], list[tuple[str, ...]]],
                                           frozenset[tuple[str, ...]], frozenset[tuple[str, ...]]]:
    """The people of the home as its own words name them, who own its things ("papa's mug", "ah
    ma's bed", "jun hao's bag": papa, ah ma, jun hao; also without "'s": :func:`_owner_unmarked`), and
    of those the names said without "'s" before two things' names or more, which :func:`owners`
    checks against English words, and before one, which it takes only as written as a name; each
    with the names of the home that open with their words ("ah ma bed"), where those words name a
    thing and no person. A thing of the home is never an owner ("the fridge's door")."""
    index = world_phrases(world)
    found: set[tuple[str, ...]] = set()
    unmarked: dict[tuple[str, ...], set[str]] = {}
    for table in (world.get("places") or {}, world.get("objects") or {}):
        for name, entry in table.items():
            # the thing's own name too ("dwayne_boots", "dwayne_khaki": Dwayne's, said "dwayne boots")
            said = (entry.get("words") or []) if isinstance(entry, dict) else []
            for phrase in [*said, name.replace("_", " ")]:
                m = _OWNER.match(str(phrase).strip().lower() + " ")
                who = tuple(words_of(m.group(1))) if m else ()
                if who and who not in index:
                    found.add(who)
                elif not m and (kin := _owner_unmarked(str(phrase).strip())):
                    unmarked.setdefault(kin, set()).add(name)
    # an owner said without "'s": a kinship word, or a name (no English word) that opens the names
    # of two things or more ("minjun bed", "minjun tumbler"); a word before one thing's name is as
    # likely its make or its character ("elsa doll"), and an English word its kind ("winter ibul")
    found |= {who for who, things in unmarked.items() if who not in index and who[0] in KIN}
    # (checked as English by :func:`owners`; a name the home's words also say with "'s", "Baba's
    # glasses", is a person whatever it is in English)
    maybe = {who: things for who, things in unmarked.items() if who not in index and who[0] not in KIN
             and who not in found and (who[0],) not in PHRASES}
    named = frozenset(who for who, things in maybe.items() if len(things) > 1)
    # a word before one thing's name ("michelle bed") is a person only where a command writes it
    # as a name (:func:`owners`)
    once = frozenset(maybe) - named
    return {who: [key for key in index if len(key) > len(who) and key[:len(who)] == who]
            for who in found | named | once}, named, once


def _owner_unmarked(phrase: str) -> tuple[str, ...]:
    """Who may own the thing a home's word names without "'s" ("minjun bed", "husband desk"): its
    first word where more words follow, a word of letters (the caller keeps only names and kinship
    words); () for a phrase of one word."""
    words = phrase.lower().split()
    return (words[0],) if len(words) > 1 and words[0].isalpha() else ()


def owners_before_names(words: list[str], world: dict, notes: list[str]) -> list[str]:
    """ "papa office shirts", "jun hao school bag": one of the home's people (:func:`owners`) said
    before a thing's name without "'s" says whose it is, read as "the", as "Rosie's cup" is
    (:func:`~.tagger.owners_as_the`): which thing is meant is the home's one such thing, or it is
    asked. Never where the owner's words with what follows are a name of the home themselves ("ah
    ma bed"), nor before words that name nothing ("for ah ma lunch")."""
    index = world_phrases(world)
    people = owners(world, words)
    out = owner_s_as_name(words, world)
    k = 0
    while k < len(out):
        n = owner_at(out, k, people)
        if n and any(tuple(out[k + n:k + n + m]) in index for m in (1, 2, 3)):
            notes.append(f"'{' '.join(out[k:k + n])}' says whose it is: read as 'the'")
            out[k:k + n] = [] if k and out[k - 1] in ("the", "my", "our", "his", "her") else ["the"]
        k += 1
    return out


#: pronouns that say whose a thing is
_POSSESSIVE_PRONOUNS = frozenset({"his", "her", "their"})
#: words that begin a new clause, after which the people named before it are no longer its own
_CLAUSE_BOUNDS = frozenset({",", ".", ";", "!", "?", "then", "but"})


#: possessives a thing's owner is said by, before "own" ("his own bed", "my own cup")
_OWN_AFTER = frozenset({"his", "her", "their", "my", "our", "your", "its"})


def own_as_owned(words: list[str], world: dict, notes: list[str]) -> list[str]:
    """ "Tunde's own plate", "his own bed": "own" after a possessive or one of the home's people
    stresses whose the thing is and says nothing more; the words without it (a note says so)."""
    if "own" not in words:
        return words
    people = owners(world, words)
    out: list[str] = []
    for k, w in enumerate(words):
        if w == "own" and k and k + 1 < len(words) and (
                words[k - 1] in _OWN_AFTER
                or any(owner_said(words, k - len(who), people) == who for who in people if k >= len(who))):
            notes.append(f"'{words[k - 1]} own': 'own' stresses whose it is (read as '{words[k - 1]}')")
            continue
        out.append(w)
    return out


def pronouns_as_owners(words: list[str], world: dict, notes: list[str]) -> list[str]:
    """ "wash kais lunchbox and put his footy on his bed": "his" / "her" / "their" before a thing
    is one of the home's people said before it in the command (:func:`owners`) where exactly one of
    them owns a thing so named by the home's own words ("kai's footy", "kai's bed"), or where
    exactly one of those who do is named in its own clause ("Tolu's uniform on her bed, Tunde's
    jersey on his bed"); anything else is left as said ("his bed" where no one was named, or where
    two of those named have a bed and its clause names neither or both)."""
    if not _POSSESSIVE_PRONOUNS & set(words):
        return words
    index = world_phrases(world)
    people = owners(world, words)
    out = list(words)
    named: list[tuple[str, ...]] = []
    in_clause: list[tuple[str, ...]] = []   # the people named since the clause began
    k = 0
    while k < len(out):
        who = owner_said(out, k, people)
        if who is not None:
            named.append(who)
            in_clause.append(who)
            k += len(who)
            continue
        if out[k] in _CLAUSE_BOUNDS:
            in_clause = []
        if out[k] in _POSSESSIVE_PRONOUNS:
            things = {(who, m) for who in set(named) for m in (3, 2, 1)
                      if tuple(who) + tuple(out[k + 1:k + 1 + m]) in index and k + m < len(out)}
            longest = max((m for _, m in things), default=0)
            whose = {who for who, m in things if m == longest}
            if len(whose) > 1 and len(whose & set(in_clause)) == 1:
                # "Tolu's uniform on her bed, Tunde's jersey on his bed": the one of them its own clause names
                whose &= set(in_clause)
            if len(whose) == 1 and _said_whole(out, k, next(iter(whose)), longest, index):
                # "baba glasses to his table de nuit": the home's longer name of that same thing follows
                notes.append(f"'{out[k]}' before '{out[k + 1]}...': whose it is, as the home's name says; read as 'the'")
                out[k] = "the"
            elif len(whose) == 1:
                who = next(iter(whose))
                notes.append(f"'{out[k]} {' '.join(out[k + 1:k + 1 + longest])}' read as {' '.join(who)}'s")
                out[k:k + 1] = list(who)
                k += len(who)
                continue
            if not whose and _owned_by_none(out, k, index, people):
                # "her mood lamp" where the home has one mood lamp and no one's: whose says nothing
                notes.append(f"'{out[k]}' before '{out[k + 1]}...': no one's own in this home; read as 'the'")
                out[k] = "the"
        k += 1
    return out


def _said_whole(words: list[str], k: int, who: tuple[str, ...], owned: int, index: dict) -> bool:
    """Whether the possessive at ``k`` stands before a longer name of the home than the ``owned``
    words its owner ``who`` is said with, and both name the same things ("his table de nuit",
    where the home calls the thing "baba table" and "table de nuit")."""
    longer = next((tuple(words[k + 1:k + 1 + m]) for m in (3, 2) if m > owned and k + m < len(words)
                   and tuple(words[k + 1:k + 1 + m]) in index), None)
    if longer is None:
        return False
    things = {ref["name"] for ref in index[longer]}
    return things == {ref["name"] for ref in index[tuple(who) + tuple(words[k + 1:k + 1 + owned])]}


def _owned_by_none(words: list[str], k: int, index: dict, people: dict[tuple[str, ...], list[tuple[str, ...]]]) -> bool:
    """Whether the possessive at ``k`` stands before a name of the home (one to three words) that no
    one of the home owns by its words ("her mood lamp", where no "seoyeon mood lamp" is named), and
    not after a verb that takes a person ("give her tea": to her)."""
    if k and words[k - 1] in TWO_OBJECT_VERBS:
        return False
    said = next((tuple(words[k + 1:k + 1 + m]) for m in (3, 2, 1) if tuple(words[k + 1:k + 1 + m]) in index
                 and k + m < len(words)), None)
    return said is not None and not any(tuple(who) + said in index for who in people)


def owner_at(words: list[str], k: int, people: dict[tuple[str, ...], list[tuple[str, ...]]]) -> int:
    """How many words from ``k`` name one of the home's people (``people``: :func:`owners`), also
    with the "s" of a possessive typed without its apostrophe ("kais"), where they are not the
    start of a thing's name ("ah ma bed", "kais bed"); 0 where none does."""
    who = owner_said(words, k, people)
    if who is None:
        return 0
    meant = list(who) + words[k + len(who):]
    return 0 if any(tuple(meant[:len(name)]) == name for name in people[who]) else len(who)


def owner_said(words: list[str], k: int,
               people: dict[tuple[str, ...], list[tuple[str, ...]]]) -> tuple[str, ...] | None:
    """The one of the home's people whose words stand at ``k``, also with the "s" of a possessive
    typed without its apostrophe ("kais ipad", "mums mug"), the longest first; None where none."""
    for who in sorted(people, key=len, reverse=True):
        said = tuple(words[k:k + len(who)])
        if said == who or said == who[:-1] + (who[-1] + "s",):
            return who
    return None


def owner_s_as_name(words: list[str], world: dict) -> list[str]:
    """The words with an owner's "s" typed without its apostrophe taken off where the owner and
    what follows are a name of the home ("mochis bowl" where the home says "mochi's bowl": the
    bowl so named, not any bowl)."""
    index = world_phrases(world)
    people = owners(world, words)
    out = list(words)
    for k in range(len(out)):
        for who in people:
            n = len(who)
            if tuple(out[k:k + n]) == who[:-1] + (who[-1] + "s",) and any(
                    tuple(list(who) + out[k + n:k + n + m]) in index for m in (1, 2, 3)):
                out[k + n - 1] = who[-1]
    return out


#: every word of the lexicon's phrases and fillers, and the function words
_LEXICON = frozenset(w for key in PHRASES for w in key) | frozenset(w for key in FILLER for w in key) | FUNCTION_WORDS


class _Reader:
    """The words of one command, with who in it is a person (module docstring)."""

    def __init__(self, command: str, world: dict) -> None:
        self.index = world_phrases(world)
        #: what the words were read as before the people in them ("fuh he": for him, in patois)
        self.read_as: list[str] = []
        self.words = patois_in_home(words_of(command), self.index, self.read_as)
        self.capitalised = {w.lower() for w in re.findall(r"(?<![\w'’])[A-Z][a-z]+", command)}
        self.world = world
        self.home = home_words(self.index)
        self.vocab = vocabulary(self.index)
        self.owners = owners(world, self.words, proper_names(command))

    def known(self, w: str, typos: bool = True) -> bool:
        """Whether a word is a word of the home's names, of the lexicon or its fillers, a function
        word, or (``typos``) a typo of a word of the home: no person's name."""
        return w in self.home or w in _LEXICON or (typos and len(w) >= 4 and bool(typo_of(w, self.vocab)))

    def person(self, k: int, objective: bool = False) -> int:
        """How many words from ``k`` name a person (0: none); ``objective``: where "her" is one."""
        words = self.words
        w = words[k] if k < len(words) else ""
        if w in _OWN_AFTER | {"me"} and k + 1 < len(words) and words[k + 1] not in PERSON_PRONOUNS | {"her"}:
            # "for me mam", "our Kyle", "her nan": whose person, then the person
            n = self.person(k + 1)
            if n:
                return 1 + n
        if w in PERSON_PRONOUNS or (objective and w == "her"):
            return 1
        owner = owner_at(words, k, self.owners)
        if owner:
            return owner
        if w == "the" and k + 1 < len(words) and words[k + 1] in KIN and not self.known(words[k + 1]):
            return 2
        if w == "the" and words[k + 1:k + 2] == ["old"] and k + 2 < len(words) and words[k + 2] in KIN | {"man"} \
                and not self.known(words[k + 2]):   # "the old fella", "the old man"
            return 3
        if w == "the" and owner_at(words, k + 1, self.owners):   # "the twins" of "the twins' desk"
            return 1 + owner_at(words, k + 1, self.owners)
        if w in TITLES and w not in self.home and k + 1 < len(words) and words[k + 1].isalpha() \
                and not self.known(words[k + 1], typos=False):
            return 2 + self._capitalised_run(k + 2)
        if w in KIN and not self.known(w):
            return 1 + self._capitalised_run(k + 1)
        return self._capitalised_run(k)

    def _capitalised_run(self, k: int) -> int:
        """How many capitalised words from ``k`` are nobody's word ("Tom", "Patel")."""
        n = 0
        while k + n < len(self.words) and self.words[k + n] in self.capitalised and not self.known(self.words[k + n]):
            n += 1
        return n

    def _keeps(self, rest: list[str], j: int) -> bool:
        """Whether the word at ``j`` of a clause about a person keeps the clause in: a word of the
        home's names (a function word in one, "fold up chairs", names nothing by itself), a number
        (of minutes or hours it says when: "she's up in 10 min"), a word taking up a thing, or one
        that may ask something (no "shift" of work: "up from night shift")."""
        w = rest[j]
        if w in DOING and j and rest[j - 1] in BEING:   # "she is reading": what she does ("reading glasses" aside)
            return False
        return ((w in self.home and w not in FUNCTION_WORDS) or (w.isdigit() and not duration_at(rest, j))
                or w in THING_WORDS or (_asks(w) and not _work_shift(rest, j)))

    def clause_end(self, k: int) -> int:
        return next((j for j in range(k, len(self.words)) if self.words[j] in PUNCT), len(self.words))

    def clause_start(self, k: int) -> bool:
        return k == 0 or self.words[k - 1] in PUNCT or self.words[k - 1] in ("and", "so", "but")

    def whereabouts(self) -> tuple[list[tuple[int, int]], list[str] | None, bool]:
        """The clauses that are only where a person is ((start, end) each), the place they say
        (None: none), and whether they say two different places."""
        spans, places = [], []
        for i in range(len(self.words)):
            n = self.person(i) if self.clause_start(i) else 0
            if not n or i + n >= len(self.words):
                continue
            # "he's at the trestle" is read without its "is"
            j = i + n + (self.words[i + n] in BEING)
            found = place_said(self.words, j, self.index, THIRD_POSTURE) or \
                place_said(self.words, self._past_what_they_do(j), self.index, THIRD_POSTURE)
            if found is not None:   # "... so she is on the sofa": the joiner goes with the clause
                spans.append((i - (i > 0 and self.words[i - 1] in ("and", "so", "but")), found[0]))
                places.append(found[1])
        distinct = {tuple(p) for p in places}
        return spans, (places[0] if places else None), len(distinct) > 1

    def _past_what_they_do(self, j: int) -> int:
        """Where the words after what a person does with a thing end ("reading the gazeta", "watching
        the telly": a thing of the home that they read or watch is no order about it), from ``j``;
        ``j`` where the clause says no such doing."""
        k = j
        while k < len(self.words) and self.words[k] in THIRD_POSTURE and self.words[k] not in DOING:
            k += 1
        if k >= len(self.words) or self.words[k] not in DOING:
            return j
        k += 1
        while k < len(self.words) and self.words[k] in ("the", "his", "her", "their", "a", "some"):
            k += 1
        n = max((m for m in range(1, 4)
                 if any(r["kind"] == "object" for r in self.index.get(tuple(self.words[k:k + m]), []))), default=0)
        return k + n if n else j

    def talk(self, i: int, stop: int | None = None) -> int:
        """The end of a clause at ``i`` that is talk about a person (module docstring, 3), or 0;
        ``stop``: where the clause ends at the latest (a clause of where someone is begins there)."""
        # "he" and "she" open a clause of their own wherever they stand ("... in the lounge shes always cold")
        n = self.person(i) if self.clause_start(i) or self.words[i] in _SUBJECT_PRONOUNS else 0
        if not n:
            return 0
        end = min(self.clause_end(i), stop if stop is not None and stop > i else len(self.words))
        rest = self.words[i + n:end]
        title = self._title_done(rest)
        if not rest or any(self._keeps(rest, j) for j in range(len(rest)) if j not in title):
            return 0
        return end

    def _title_done(self, rest: list[str]) -> set[int]:
        """Where in a clause about a person the title of what they read or watch stands ("she's
        watching Homes Under the Hammer", "reading her Catherine Cookson"): capitalised words
        after a verb of :data:`DOING` (and the small words between them), which name nothing
        of the home however their words read ("under" is no word of where here)."""
        out: set[int] = set()
        for j, w in enumerate(rest):
            if w not in DOING:
                continue
            k = j + 1 + (j + 1 < len(rest) and rest[j + 1] in ("her", "his", "their", "my", "the"))
            run = [m for m in range(k, len(rest)) if rest[m] in _TITLE_GLUE
                   or (rest[m] in self.capitalised and rest[m] not in self.home)]   # "the Telly" is the telly
            run = run[:next((x for x, m in enumerate(run) if m != k + x), len(run))]   # contiguous from k
            while run and rest[run[-1]] in _TITLE_GLUE:
                run.pop()
            if run and rest[run[0]] not in _TITLE_GLUE:
                out |= set(run)
        return out

    def whose_pronoun(self, k: int) -> tuple[str, ...] | None:
        """The person a possessive pronoun at ``k`` stands for ("his side table" where the home
        says "Bauji's side table"): the one person the command names whose words, put before the
        words after the pronoun, make a name of the home that those words alone are not; None where
        no person, or more than one, does so."""
        said = {who for j in range(len(self.words)) for who in [owner_said(self.words, j, self.owners)] if who}
        after = self.words[k + 1:k + 5]
        whose = {who for who in said for n in range(1, len(after) + 1)
                 if who + tuple(after[:n]) in self.index and tuple(after[:n]) not in self.index}
        return next(iter(whose)) if len(whose) == 1 else None

    def need_passed_on(self, i: int) -> tuple[int, str] | None:
        """(how many words name the person, the speaker's verb) where a person at ``i`` is the
        subject of a clause that may ask something (:func:`_asks`: "Bibi can't read", "he wants
        the fan on", "Neema is cold") and a verb of :data:`AS_SPEAKER` follows them: the home
        knows no people, so their need is read as the speaker's, said in the notes. None
        elsewhere, and where the clause says where someone is (set aside before)."""
        n = self.person(i) if self.clause_start(i) or self.words[i] in _SUBJECT_PRONOUNS else 0
        if not n or i + n >= len(self.words) or self.words[i + n] not in AS_SPEAKER:
            return None
        rest = self.words[i + n:self.clause_end(i)]
        if not any(_asks(w) and not _work_shift(rest, j) for j, w in enumerate(rest)):
            return None
        return n, AS_SPEAKER[self.words[i + n]]


#: pronouns that say whose a thing is
_POSSESSIVE_PRONOUNS = frozenset({"his", "her", "their"})
#: verbs after a person whose need the speaker passes on, and the speaker's form of each
AS_SPEAKER = {"wants": "want", "needs": "need", "is": "am", "feels": "feel", "can": "can", "cannot": "cannot",
              "could": "could", "does": "do", "would": "would", "likes": "like", "has": "have",
              "hes": "am", "shes": "am"}


#: words before "shift" that make it a spell of work ("up from night shift"), no verb of moving
_SHIFTS = frozenset({"night", "day", "late", "early", "morning", "evening", "double", "back", "long", "afternoon"})


def _work_shift(words: list[str], j: int) -> bool:
    return words[j] in ("shift", "shifts") and j > 0 and words[j - 1] in _SHIFTS


def _asks(word: str) -> bool:
    """Whether a word may ask something of the home in a clause about a person (:data:`ASKING`)."""
    cls = str(PHRASES.get((word,), ("",))[0])
    return cls.startswith("V_") or cls in ASKING


def person_named(command: str, world: dict, but: Collection[str] = frozenset()) -> bool:
    """Whether the command names a person (module docstring: who is a person), the words of
    ``but`` aside."""
    r = _Reader(command, world)
    return any(w not in but and r.person(k) for k, w in enumerate(r.words))


def about_people(command: str, world: dict, notes: list[str]) -> str | None:
    """The command with its third persons read (module docstring), or None where it has none to
    read. TranslationError where a thing is to be brought to a person whose place is not said."""
    r = _Reader(command, world)
    words = r.words
    spans, place, two = r.whereabouts()
    if two:
        return None
    said = [f"'{' '.join(words[a:b])}': where they are; read as the {' '.join(place or [])}" for a, b in spans]
    dropped = {k for a, b in spans for k in range(a, b)}
    out: list[str] = []
    changed = bool(spans)
    verb_at = -1      # where the clause's verb of bringing is, in ``out``
    brought = False   # whether the sentence has a verb of bringing so far (a list of things may follow it)
    k = 0
    while k < len(words):
        if k in dropped:
            k += 1
            continue
        w = words[k]
        if w in PUNCT:
            verb_at = -1
            brought = brought and PUNCT[w] != "END"
        elif w in TO_PERSON:
            verb_at = len(out)
            brought = True
        read = _pronoun_read(r, k, brought and bool(spans), place)
        if read:   # "his side table" (Bauji's side table), "bring her glasses there" (where she is)
            out += read[0]
            said.append(read[1])
            changed, k = True, k + 1
            continue
        if w in TO_PERSON and r.person(k + 1, objective=True) and not _her_own(r, k + 1, out):
            n = r.person(k + 1, objective=True)
            end = r.clause_end(k + 1 + n)
            there = _said_there(r, k + 1 + n, end) or (place, end, end)
            if there[0] is None:
                raise _nowhere(words[k + 1:k + 1 + n], command)
            out += [GIVE_AS.get(w, w)] + words[k + 1 + n:there[1]] + ["to", "the"] + there[0]
            said.append(f"'{' '.join(words[k + 1:k + 1 + n])}' read as where the {' '.join(there[0])} is")
            changed, k = True, end
            continue
        # "to her bedside table": "her" before a name of the home is whose it is, no person
        n = r.person(k + 1, objective=True) if w in ("to", "for") and not _her_before_a_name(r, k + 1) else 0
        aside = _for_whom_end(r, k, n) if w == "for" and verb_at >= 0 and _destination_said(r, out, verb_at) else 0
        if aside:   # "bring them back to the table for him (to eat)": the place is said; who for is an aside
            said.append(f"'{' '.join(words[k:aside])}': who it is for (set aside)")
            changed, k = True, aside
            continue
        if n and verb_at >= 0:
            end = r.clause_end(k + 1 + n)
            there = _said_there(r, k + 1 + n, end) or (place, k + 1 + n, k + 1 + n)
            if there[0] is None:
                raise _nowhere(words[k + 1:k + 1 + n], command)
            out += ["to", "the"] + there[0]
            said.append(f"'{' '.join(words[k + 1:k + 1 + n])}' read as where the {' '.join(there[0])} is")
            changed, k = True, there[2]
            continue
        aside = _for_aside(r, k, n, out) if w == "for" else None
        if aside:   # "... for him, and ...", "For Baba's dinner, cut ...", "slice the onion for soup"
            said.append(aside[1])
            changed, k = True, aside[0]
            continue
        end = r.talk(k, next((a for a, _ in spans if a > k), None))
        if end:
            said.append(f"'{' '.join(words[k:end])}': talk about someone, no order (set aside)")
            changed, k = True, end
            continue
        speaker = r.need_passed_on(k)
        if speaker:   # "Bibi can't read", "he wants the fan on": their need, passed on by the speaker
            out += ["i", speaker[1]]
            said.append(f"'{' '.join(words[k:k + speaker[0] + 1])}' read as 'i {speaker[1]}': their need, passed on")
            changed, k = True, k + speaker[0] + 1
            continue
        out.append(w)
        k += 1
    if not changed:
        return None
    notes += r.read_as + said
    return " ".join(_tidied(out, place if spans else None))


def _tidied(out: list[str], place: list[str] | None) -> list[str]:
    """The words read with a clause mark left with nothing before it in its sentence, and a
    joining word left first, taken out; a cue of how it feels is felt at ``place`` (where the
    person said is), if any."""
    cleaned: list[str] = []
    for w in out:
        if w in PUNCT and (not cleaned or cleaned[-1] in PUNCT):
            continue
        cleaned.append(w)
    while cleaned and cleaned[0] in ("and", "so", "but"):
        cleaned.pop(0)
    return _felt_where_they_are(cleaned, place) if place else cleaned


def _pronoun_read(r: _Reader, k: int, brought_to_someone: bool, place: list[str] | None) \
        -> tuple[list[str], str] | None:
    """(the words read, the note) for a possessive pronoun that stands for the one person said
    whose it can be (:meth:`_Reader.whose_pronoun`), or for "there" closing a clause of bringing
    in a command that says where a person is (``brought_to_someone``): their ``place``."""
    w = r.words[k]
    whose = r.whose_pronoun(k) if w in _POSSESSIVE_PRONOUNS else None
    if whose:
        return list(whose), f"'{w} {r.words[k + 1]}' read as {' '.join(whose)}'s (the one person said whose it can be)"
    if w == "there" and brought_to_someone and place and r.clause_end(k + 1) == k + 1:
        return ["to", "the"] + place, f"'there' read as the {' '.join(place)}, where they are"
    return None


def _for_aside(r: _Reader, k: int, n: int, out: list[str]) -> tuple[int, str] | None:
    """(where it ends, the note) of "for" at ``k`` set aside: "for <person>" closing a clause
    (``n``: the person's words), "for <person>('s dinner)" opening one, or what it is for, naming
    nothing of this home (:func:`_purpose`); None otherwise."""
    words = r.words
    if n and clause_end(words, k + 1 + n) == k + 1 + n:   # "... for him, and ..."
        return k + 1 + n, f"'for {' '.join(words[k + 1:k + 1 + n])}': who it is for (set aside)"
    first = _said_first_for(words, k, n) if n and (not out or out[-1] in PUNCT) else 0
    if first:   # "For Baba's dinner, cut the tomatoes", "for baba cut the tomatoes"
        return first, f"'{' '.join(words[k:first])}': who it is for, said first (set aside)"
    dish = _purpose(r, k + 1) if out and out[-1] not in PUNCT else 0
    if dish:
        return dish, f"'for {' '.join(words[k + 1:dish])}': what it is for, nothing of this home (set aside)"
    return None


#: one-word cues of how a room feels ("dark", "hot", "stuffy")
_FELT = frozenset(w for w in [*LIGHT_CUES, *TEMPERATURE_CUES, *TEMPERATURE_ADJECTIVES, *AIR_CUES] if " " not in w)
#: words between "it is" and such a cue ("it is so very hot", "it is a bit dark"): the lexicon's
#: intensifiers and "too", word by word
_DEGREE = frozenset(w for phrase, (cls, _) in PHRASES.items() if cls in ("INTENS", "TOO") for w in phrase)


def _felt_where_they_are(words: list[str], place: list[str]) -> list[str]:
    """ "Abiye is in the salon and it is so hot": a cue said as "it is ..." with no where, in a
    command that says where the person is, is felt where they are: "in the salon" said after it."""
    out: list[str] = []
    for k, w in enumerate(words):
        out.append(w)
        ends = k + 1 == len(words) or words[k + 1] in PUNCT or words[k + 1] in ("and", "so", "but", "then")
        if w in _FELT and ends:
            j = k - 1
            while j >= 0 and words[j] in _DEGREE:
                j -= 1
            if j >= 1 and words[j] in ("is", "s") and words[j - 1] == "it":
                out += ["in", "the"] + place
    return out


def _said_there(r: _Reader, k: int, end: int) -> tuple[list[str], int, int] | None:
    """(the place, where its preposition is, the clause's end) of "on / in / at [the] P" closing
    the clause from ``k`` to ``end`` ("give him the tea on the armchair"), or None. None too where
    the words before it may pick things out by that place: a thing named that lies there ("give
    him the jug on the trestle" where the jug is: which jug, not where he is), or a name of
    anything but one object (a category: some of its things may lie there)."""
    objects = r.world.get("objects") or {}
    for j in range(k, end):
        found = place_said(r.words, j, r.index, frozenset())
        if found is None or found[0] != end:
            continue
        places = {ref["name"] for ref in r.index.get(tuple(found[1]), []) if ref["kind"] == "place"}
        named = [ref for a in range(k, j) for b in range(a + 1, j + 1) for ref in r.index.get(tuple(r.words[a:b]), [])]
        if any(ref["kind"] != "object" or objects[ref["name"]].get("in") in places for ref in named):
            return None
        return found[1], j, end
    return None


#: words before "back" that say someone comes back ("when he's back", "once she gets back")
_COMES = frozenset({"is", "s", "are", "he", "she", "they", "hes", "shes", "gets", "get", "comes", "come"})
#: words after which a sentence goes on to another order
_SENTENCE_GOES_ON = frozenset({".", "!", "?", ";", "but", "then", "so"})
#: words after which "on" or "in" says where a thing goes
_PUT_BEFORE = frozenset({"put", "place", "set", "leave", "keep", "it", "them", "back"})
#: prepositions that say where a thing brought goes
_DESTINATION = frozenset({"to", "into", "onto"})


def _destination_said(r: _Reader, out: list[str], verb_at: int) -> bool:
    """Whether the clause read so far (``out`` from its verb of bringing at ``verb_at``) says where
    the thing goes: "to", "into" or "onto" and a place of the home ("bring them back to the table"),
    or "on" / "in" after a verb of putting or what is put ("put it on the counter")."""
    for j in range(verb_at + 1, len(out)):
        # "on" / "in" after what is put ("put it on the counter", "them back in the box"); after a
        # thing's name it may say which thing ("the tea on the tray")
        if out[j] in _DESTINATION or out[j] in ("on", "in") and out[j - 1] in _PUT_BEFORE:
            k = j + 1
            while k < len(out) and out[k] in ("the", "my", "our", "his", "her", "their"):
                k += 1
            # a place's name, or its last words ("back to the table" said before, "to her side
            # table" of "Bauji's side table")
            if any(tuple(out[k:k + n]) in _place_tails(r.world) for n in range(1, 5)):
                return True
    return False


@per_world
def _place_tails(world: dict) -> frozenset[tuple[str, ...]]:
    """The names of the home's places and their last words ("dining table", "table")."""
    return frozenset(key[i:] for key, refs in world_phrases(world).items() if any(r["kind"] == "place" for r in refs)
                     for i in range(len(key)))


def _her_before_a_name(r: _Reader, k: int) -> bool:
    """Whether "her" at ``k`` stands before a name of the home or its last words ("her bedside table")."""
    return r.words[k:k + 1] == ["her"] and any(tuple(r.words[k + 1:k + 1 + n]) in r.index
                                               or tuple(r.words[k + 1:k + 1 + n]) in _place_tails(r.world)
                                               for n in range(1, 5))


def _her_own(r: _Reader, k: int, out: list[str]) -> bool:
    """ "bring her glasses there", "take her mug to the sink": "her" before a thing's name, in a
    clause that says where the thing goes ("there", "to P"), is whose the thing is, not whom it is
    brought to."""
    if r.words[k] != "her" or k + 1 >= len(r.words) or r.words[k + 1] in PUNCT:
        return False
    # the things listed ("her knee cream, her glasses and her book there") to where the sentence
    # goes on to another order
    end = k + 1
    while end < len(r.words) and r.words[end] not in _SENTENCE_GOES_ON:
        end += 1
    rest = r.words[k + 1:end]
    return "there" in rest or _destination_said(r, ["bring"] + rest, 0)


def _for_whom_end(r: _Reader, k: int, n: int) -> int:
    """The end of "for" + a person (``n`` words) at ``k`` closing its clause, or with "to" and what
    they will do after it to the clause's end where those words name nothing of the home, hold no
    number and no operative word ("for Baba to connect when he is back"); 0 otherwise ("for Rose to
    put in the oven" is an order of its own, left to be read or refused)."""
    if not n:
        return 0
    j = k + 1 + n
    end = r.clause_end(j)
    if j == end:
        return j
    rest = r.words[j:end]
    # "back" of someone coming back ("when he is back") is no order to put a thing back
    operative = [w for i, w in enumerate(rest) if near_operative(w) and not (w == "back" and rest[i - 1:i] and rest[i - 1] in _COMES)]
    named = [w for w in rest if not w.isalpha() or (w in r.home and w not in FUNCTION_WORDS)]
    return end if rest[0] == "to" and not operative and not named else 0


def _said_first_for(words: list[str], k: int, n: int) -> int:
    """The end of "for" + a person (``n`` words) + "'s" and words of a purpose (lexicon
    ``PURPOSE_WORDS``: "dinner", "breakfast") opening a clause, where a mark or a verb of the
    lexicon follows; 0 otherwise."""
    j = k + 1 + n
    if j < len(words) and words[j] == "s":
        j += 1
    while j < len(words) and words[j] in PURPOSE_WORDS:
        j += 1
    if j < len(words) and (words[j] in PUNCT or str(PHRASES.get((words[j],), ("",))[0]).startswith("V_")):
        return j + (words[j] == ",")
    return 0


def _purpose(r: _Reader, k: int) -> int:
    """The end of "for" + [a determiner, or one of the home's people] + one or two words that name
    nothing of the home or the lexicon, closing a clause at ``k`` ("for soup", "for sugar", "for ah
    ma lunch pls": a particle or "please" may close the clause after them), or 0."""
    j = k + (k < len(r.words) and r.words[k] in ("a", "the", "his", "her", "my", "some"))
    j = j if j > k else k + owner_at(r.words, k, r.owners)
    end = r.clause_end(j)
    while end > j and r.words[end - 1] in CLOSING_PARTICLES:
        end -= 1
    if tuple(r.words[j:end]) in CONSUMED:   # "for his cocoa": a meal or a hot drink
        return end
    # after one of the home's people, a word of the reader's may say what for ("for ah ma lunch")
    # where the words are no name of the home and no operative word
    owned = j > k and r.words[k] not in ("a", "the", "some")
    said = r.words[j:end]
    if not 0 < len(said) <= 2 or not all(w.isalpha() for w in said):
        return 0
    if owned:
        return 0 if tuple(said) in r.index or any(near_operative(w) for w in said) else end
    return 0 if any(r.known(w) for w in said) else end


def _nowhere(person: list[str], command: str) -> TranslationError:
    return TranslationError(f"where {' '.join(person)!r} is is not said in {command.strip()!r}: say where to "
                            "bring it (the home knows no people)")

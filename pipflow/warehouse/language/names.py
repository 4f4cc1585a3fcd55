"""Turn a command into tokens, recognising the world's shelves, products and robots in it.

A misspelling keeps its first letter ("prodcut", "shelve"), so "help" is never a shelf.
Every name comes from the world file, so a world with racks called ``rack_a`` or ``cold-store``
works as well as the benchmark's ``shelf1``. People write names apart ("product 1", "shelf three")
and misspell them ("prodcut3", "shelve4"); those are matched by edit distance, but only when one
name is clearly closest: a near-tie, or a kind word with a number the world lacks ("product 9"),
is a :class:`TranslationError` that quotes the words and lists the candidates, never a guess.
The spelling rules any domain's reader shares (normal form, edit distance, plurals) are
:mod:`pipflow.language.spelling`; this module knows the warehouse's kinds of names.
"""
from __future__ import annotations

import functools
import re
from dataclasses import dataclass
from typing import Callable, Collection

from pipflow.errors import TranslationError
from pipflow.language.asides import TALK
from pipflow.language.english import common_word
from pipflow.language.numbers import NUMBER_WORDS, TENS, UNITS, read_number, word_value
from pipflow.language.spelling import (Slips, distance, normalize, other_spellings, plural_forms, sounded, split_digits,
                                      tolerance, variants)

#: the possessive "'s" as the lexer marks it ("rack A's" -> "rack A zzposs")
POSS_MARK = "zzposs"
KINDS: tuple[str, ...] = ("shelf", "product", "robot")
WORLD_KEYS: dict[str, str] = {"shelf": "shelves", "product": "products", "robot": "robots"}
# English words for a kind, on top of the stems the world's own names share ("bin" of bin7).
KIND_WORDS: dict[str, set[str]] = {
    "shelf": {"shelf", "shelves", "shelve", "rack", "racks", "bin", "bins", "location", "locations",
              "spot", "spots", "area", "areas", "zone", "zones", "bay", "bays", "dock", "docks", "section",
              "sections"},
    "product": {"product", "products", "item", "items", "good", "goods"},
    "robot": {"robot", "robots", "bot", "bots", "agent", "agents"},
}
# Grammar and filler words: matched to a name only when spelled exactly like it, so that "in 3"
# never becomes bin3 and "able" never becomes a misspelt "table".
STOPWORDS: set[str] = {
    "a", "an", "the", "in", "on", "at", "to", "of", "off", "out", "into", "onto", "inside", "for",
    "from", "by", "with", "and", "or", "but", "not", "no", "nor", "be", "is", "are", "was", "were",
    "been", "being", "am", "it", "its", "there", "their", "theyre", "they", "them", "this", "that",
    "these", "those", "i", "we", "you", "he", "she", "me", "us", "my", "our", "your", "should",
    "shall", "must", "may", "might", "can", "could", "would", "will", "ought", "oughta", "gotta",
    "have", "has", "had", "having", "do", "does", "did", "dont", "doesnt", "cant", "cannot",
    "wont", "shouldnt", "mustnt", "use", "used", "using", "move", "moves", "moved", "moving",
    "put", "place", "add", "take", "bring", "carry", "carries", "stock", "stocks", "store",
    "stores", "hold", "holds", "keep", "keeps", "contain", "contains", "make", "want", "need",
    "all", "every", "each", "any", "some", "none", "only", "just", "more", "fewer", "less",
    "extra", "many", "much", "as", "than", "then", "so", "too", "also", "please", "think",
    "supposed", "like", "about", "please", "one", "another", "other", "others", "same", "between",
    "among", "across", "evenly", "equally", "double", "twice", "triple", "thrice", "half",
    "empty", "full", "fill", "clear", "nothing", "everything", "anything", "units", "unit",
    "pieces", "piece", "boxes", "box", "what", "which", "who", "where", "here", "now", "up",
    "down", "over", "under", "after", "before", "while", "when", "if", "else", "except",
    "besides", "without", "never", "always", "broken", "able", "let", "get", "got", "go", "goes",
    "new", "old", "number", "amount", "count", "total", "remove", "split", "divide", "share",
    "spread", "distribute", "send", "deliver", "transfer", "shift", "ship", "set", "end",
} | NUMBER_WORDS

#: container nouns: a product named "<content> <container>" (rice_sack, soup_can) may be called by
#: its content alone
CONTAINERS = {"sack", "can", "bag", "box", "tin", "jar", "bottle", "carton", "crate", "case", "pack", "packet",
              "tub", "drum", "tote", "pallet", "keg", "barrel", "bucket", "pail", "cask", "basket", "tray",
              "set", "kit", "bundle", "reel", "spool", "roll", "pouch", "sleeve"}
#: packaging and measure nouns: "5 cartons of tape", "2 rolls of shrink wrap" count the item after
#: "of". A world that names a product so ("carton") recognises it as that product first.
PACKAGING_WORDS = frozenset({
    "carton", "cartons", "roll", "rolls", "pack", "packs", "packet", "packets", "bundle", "bundles", "bag", "bags",
    "tub", "tubs", "bottle", "bottles", "reel", "reels", "tote", "totes", "drum", "drums", "tin", "tins", "jar",
    "jars", "sack", "sacks", "crates", "jug", "jugs", "sheet", "sheets", "length", "lengths", "coil", "coils",
    "tray", "trays", "pc", "spool", "spools", "pail", "pails", "bucket", "buckets",
    # the logistics abbreviations ("4 ctns", "2 plts"; "cx", Portuguese caixa and Spanish caja: box)
    "ctn", "ctns", "plt", "plts", "cx", "cxs",
    # Turkish "koli" (carton), "palet"; Russian "korobka" (box, "5 korobok", "2 korobki"), "sht" (pieces)
    "koli", "palet", "korobka", "korobki", "korobok", "sht",
    # Indonesian "dus" (a carton); Dutch "stuks", "st." (pieces)
    "dus", "stuks", "stuk", "st",
    # German "Stk." (Stück: pieces), "Palette(n)", "Kiste(n)" (crates)
    "stk", "stck", "palette", "paletten", "kiste", "kisten",
    # bales (of textiles, "3 bales of t-shirts")
    "bale", "bales",
    # pallets said the French and Romanian way ("20 palettes of flour"; Romanian "paleti", "palete")
    "palettes", "paleti", "palete",
    # Swedish, Norwegian and Danish pallets and packages ("3 pallar kaffe", "2 kolli"); Italian
    # "bancale", "bancali"; Polish and Czech "palety"; Spanish "paletas"
    "pall", "pallar", "pallarna", "paller", "pallene", "kolli", "kollin", "kartong", "kartonger", "bancale",
    "bancali", "paleta", "palety", "paletas"})
#: each of them in the English plural too, as it is typed in English orders ("10 palets", "3 kolis")
PACKAGING_WORDS |= {w + "s" for w in PACKAGING_WORDS if w.isalpha() and len(w) >= 4 and not w.endswith("s")}
#: every word said after a count for its unit ("5 pcs", "4 pallets", "6 case"): no thing of its own
COUNT_UNITS = PACKAGING_WORDS | {"units", "unit", "pieces", "piece", "boxes", "box", "crate", "crates", "case",
                                 "cases", "pcs", "pallets", "pallet"}
NUMBER_MARKS = {"number", "no", "nr", "num", "#"}
ORDINALS: dict[str, int] = {
    w: k for k, w in enumerate(
        "first second third fourth fifth sixth seventh eighth ninth tenth eleventh twelfth".split(), 1)
} | {f"{k}{'st' if k % 10 == 1 and k != 11 else 'nd' if k % 10 == 2 and k != 12 else 'rd' if k % 10 == 3 and k != 13 else 'th'}": k
     for k in range(1, 40)}

#: the words, counts and marks of a command; the characters it steps over are the ones the reader
#: reads as nothing (quotes, square brackets, white space): every other one was refused before
#: (:func:`pipflow.warehouse.language.lexicon.check_text`). "#" is a word of its own: a number mark after a
#: kind word ("shelf #2"), an unknown word anywhere else.
_TOKEN = re.compile(r"[0-9]+\.[0-9]+|[A-Za-z0-9]+(?:['’][A-Za-z]+)?(?:[-_][A-Za-z0-9]+)*|[,.;:!?()]|#")


@dataclass(frozen=True)
class Tok:
    """One unit of a command after recognition.

    ``kind`` is "word" (``value`` the lower-case word), "num" (``value`` an int), "name"
    (``value`` a world name, ``of`` its kind), "kind" (a kind word alone such as "shelf",
    ``of`` the kind) or "punct". ``text`` keeps the words as written, for error messages.
    """

    kind: str
    text: str
    value: object = None
    of: str = ""


@dataclass(frozen=True)
class _Name:
    name: str
    kind: str
    alpha: str
    digits: str


def found_shelves(world: dict) -> list[str]:
    return [str(n) for n in (world.get("shelves") or {})]


def name_stem(name: str) -> str | None:
    """The stem a robot name shares with its siblings: its letters before a number ("tug" of
    tug3) or before a short label ("skiff" of skiff_a, "cart" of cart-b); None otherwise."""
    alpha, digits = split_digits(normalize(name))
    if digits and alpha:
        return alpha
    parts = [p for p in re.split(r"[-_\s]+", name.lower()) if p]
    if len(parts) >= 2 and len(parts[-1]) <= 2 and parts[-1].isalpha():
        return normalize("".join(parts[:-1]))
    return None


def stem_groups(names: list[str]) -> dict[str, list[str]]:
    """Stems two or more of ``names`` share (:func:`name_stem`), each with its names: "the tugs"
    where robots are tug1..tug4, "the skiffs" where they are skiff_a..skiff_c."""
    groups: dict[str, list[str]] = {}
    for n in names:
        stem = name_stem(n)
        if stem and len(stem) > 2 and stem not in STOPWORDS:
            groups.setdefault(stem, []).append(n)
    return {stem: members for stem, members in groups.items() if len(members) >= 2}


def _robot_labels(world: dict) -> set[str]:
    """The robots' kinds and tags and their plurals ("dolly", "dollies"): words of groups, never
    read as a misspelt name ("dollies" is no typo of the robot dottie: it read "only the
    dollies" as "only dottie")."""
    out: set[str] = set()
    for robot in (world.get("robots") or {}).values():
        labels = [robot.get("kind")] + list(robot.get("tags") or []) if isinstance(robot, dict) else []
        for label in labels:
            if label:
                word = normalize(str(label))
                out |= {word, *plural_forms(word)}
    return out


def _heads(name: str) -> set[str]:
    """The class nouns a place name carries: "bay" of bay3, "cage" of north_cage, "freezer" of
    freezer-a (a short label after the noun), none of a one-word name without a number."""
    out: set[str] = set()
    alpha, digits = split_digits(normalize(name))
    if digits and alpha:
        out.add(alpha)
    parts = [p for p in re.split(r"[-_\s]+", name.lower()) if p]
    if len(parts) >= 2:
        last = parts[-1]
        if len(last) <= 2 or last.isdigit():
            out.add(normalize("".join(parts[:-1])))
        elif last.isalpha():
            out.add(last)
    return out


def _quote(text: str) -> str:
    return f"'{text}'"


def _starts(names: list["_Name"], by_name: dict[str, "_Name"], alone: Callable[[str], bool],
            words_of_names: dict[str, set[str]]) -> dict[str, "_Name"]:
    """A name shortened to the start of one of its words ("mezz" of mezzanine): a prefix of four
    letters or more, two or more letters short of a word of six or more, that starts a word of
    one place or product only and is no word of the grammar (``alone``) nor a whole word of a name
    (``words_of_names``). The reader reads it only where nothing else (an exact or misspelt name, a
    word of a name) matches: a shortening never outranks a typo of another name."""
    starts: dict[str, set[str]] = {}
    for n in names:
        if n.kind == "robot":
            continue
        for w in re.split(r"[-_\s]+", n.name.lower()):
            if w.isalpha() and len(w) >= 6:
                for size in range(4, len(w) - 1):
                    starts.setdefault(w[:size], set()).add(n.name)
    return {form: by_name[next(iter(owners))] for form, owners in starts.items()
            if len(owners) == 1 and alone(form) and form not in words_of_names}


class _Shortenings:
    """A name's word shortened the way people shorten names on a shop floor: the start of a word
    (:func:`_starts`: "mezz" of mezzanine), or its first letter and then some of its other letters
    in order ("inb" of inbound, "shz" of shiraz, "lgr" of lager).

    Read as that name only where nothing else reads the word, and only when it is such a
    shortening of one word of exactly one place or product, has three letters or more, is two or
    more short of that word, and is no common English word, no word of the grammar and no whole
    word of a name: "car" is never cardboard, and "shr" names neither shiraz nor sherry. Nor is it
    one slip from a word the reader never takes for a name (:data:`STOPWORDS`: its grammar and
    filler words, numbers; :func:`pipflow.language.spelling.slip`): "thre" is a misspelt "three",
    never a thresher ("disp" may still be dispatch, though "dips" is a verb the grammar knows).
    Checked when a word reaches it, and remembered."""

    def __init__(self, names: list["_Name"], alone: Callable[[str], bool], words_of_names: Collection[str],
                 prefixes: dict[str, "_Name"]):
        self._words = [(w, n) for n in names if n.kind != "robot"
                       for w in re.split(r"[-_\s]+", n.name.lower()) if w.isalpha() and len(w) >= 5]
        self._alone = alone
        self._taken = words_of_names
        self._prefixes = prefixes   # the start of a word (:func:`_starts`), read first
        self._found: dict[str, _Name | None] = {}

    def __call__(self, form: str) -> "_Name | None":
        if form not in self._found:
            self._found[form] = self._of(form)
        return self._found[form]

    def _of(self, form: str) -> "_Name | None":
        if len(form) < 3 or not form.isalpha():
            return None
        if _stopword_slips().of(form):
            return None
        if form in self._prefixes:
            return self._prefixes[form]
        if form in self._taken or not self._alone(form) or common_word(form):
            return None
        owners = {n.name: n for w, n in self._words
                  if w[0] == form[0] and len(form) <= len(w) - 2 and _in_order(form[1:], w[1:])}
        return next(iter(owners.values())) if len(owners) == 1 else None


@functools.cache
def _stopword_slips() -> Slips:
    """The slips of :data:`STOPWORDS`, made once per process (a lookup table of ~10^5 entries)."""
    return Slips(w for w in STOPWORDS if w.isalpha())


def _in_order(letters: str, word: str) -> bool:
    """Whether the letters occur in the word in this order (not necessarily together)."""
    rest = iter(word)
    return all(letter in rest for letter in letters)


def _word_parts(names: list["_Name"], by_name: dict[str, "_Name"], alone: Callable[[str], bool],
                english: Callable[[str], bool]) -> tuple[
        dict[str, set[str]], dict[str, "_Name"], dict[str, list[str]], dict[str, list[str]]]:
    """The words of the world's multi-word names, read alone: (every name each word belongs to,
    the words that name one thing, the words several names share, a product's modifiers that are
    only offered). ``english``: a word the grammar reads (a verb), whose plural may still be a name.
    See :class:`NameIndex`."""
    having: dict[str, set[str]] = {}   # every name with the word, read alone or not
    readable: set[tuple[str, str]] = set()
    for n in names:
        words = [w for w in re.split(r"[-_\s]+", n.name.lower()) if w]
        # robots go by name, kind or tag: a word of a robot's name ("big" of big_lift) is English
        if n.kind == "robot" or len([w for w in words if w.isalpha()]) < 2:
            continue
        for k, w in enumerate(words):
            if not (w.isalpha() and len(w) >= 3 and (alone(w) or english(w))):
                continue
            # the plural of the last word, and of a product's modifier ("corks" of cork-sack:
            # the sacks of cork, counted; "tastings" is no noun of tasting_room). A word the
            # grammar reads ("wheel", "round": verbs) is no name, but its plural may be one
            # ("wheels" of cheddar_wheel): each form is read alone only when it is no grammar word
            plural = k == len(words) - 1 or n.kind == "product"
            forms = [f for f in [w] + (plural_forms(w)[:1] if plural else []) if alone(f)]
            # a product goes by its head noun ("formula" of baby-formula), or by what its
            # container holds ("rice" of rice_sack, "soup" of soup_can); another modifier may
            # name something else ("oil" is no oil filter, "plants" no plant pots). A place goes
            # by any word of its own ("inbound" of inbound_dock, "paint" of paint-shop)
            read = not (n.kind == "product" and k < len(words) - 1 and words[-1] not in CONTAINERS)
            for form in forms:
                having.setdefault(form, set()).add(n.name)
                if read:
                    readable.add((form, n.name))
    # a word of exactly one name, read as it where the name may go by that word
    parts: dict[str, _Name] = {form: by_name[next(iter(owners))] for form, owners in having.items()
                 if len(owners) == 1 and (form, next(iter(owners))) in readable}
    # a word two or more names have ("milk" of milk_crate and milk-churn, wherever it stands in
    # them): it names none of them alone, and a command that uses it is refused naming them
    # all (never the nearest by typo tolerance, never a guess)
    shared: dict[str, list[str]] = {form: sorted(owners) for form, owners in having.items()
                 if len(owners) > 1}
    # a product's modifier where the head is no container ("oil" of oil-filter): never read as
    # the product (it may name something else), only offered as a candidate reading's repair
    loose: dict[str, list[str]] = {form: sorted(owners) for form, owners in having.items()
                 if len(owners) == 1 and form not in parts
                 and by_name[next(iter(owners))].kind == "product"}
    return having, parts, shared, loose


def _contents(names: list["_Name"]) -> dict[str, "_Name | None"]:
    """What a container product of three or more words holds, said in its own words: "dog food"
    of dog_food_sack ("4 of dog food", "the dog food"), as one word of a two-word name is read
    alone ("rice" of rice_sack). Keyed by the words run together; None where two products hold
    the same (refused, never a guess)."""
    out: dict[str, _Name | None] = {}
    for n in names:
        words = [w for w in re.split(r"[-_\s]+", n.name.lower()) if w]
        if n.kind != "product" or len(words) < 3 or words[-1] not in CONTAINERS or not all(
                w.isalpha() for w in words):
            continue
        held = "".join(words[:-1])
        out[held] = None if held in out else n
    return out


def _compound_parts(word: str) -> list[list[str]]:
    """The ways a one-word name splits into two common English words ("outbound": out + bound,
    "drycab": dry + cab), each of two letters or more."""
    return [[word[:k], word[k:]] for k in range(2, len(word) - 1)
            if common_word(word[:k]) and common_word(word[k:])]


def _initials(names: list["_Name"], taken: Collection[str]) -> dict[str, "_Name"]:
    """A place or product said by the initials of its words, in capitals, as floors shorten names
    ("OB" of outbound, "PF" of pickface, "CS" of cold_store): the initials of the words of a name
    of two or more words, or of the two English words a one-word name is made of. Keyed by the
    lower-case initials; never initials two names have (refused, never a guess) nor a word of
    ``taken`` (the grammar's and filler words, the world's own spellings)."""
    out: dict[str, _Name | None] = {}
    for n in names:
        if n.kind == "robot":
            continue
        words = [w for w in re.split(r"[-_\s]+", n.name.lower()) if w.isalpha()]
        splits = [words] if len(words) >= 2 else _compound_parts(words[0]) if words else []
        for parts in splits:
            key = "".join(w[0] for w in parts)
            out[key] = None if key in out and out[key] is not n else n
    return {k: n for k, n in out.items() if n is not None and k not in taken}


#: nouns for a place said between a numbered place's letters and its number ("chill room 1")
PLACE_NOUNS = KIND_WORDS["shelf"] | {"room", "rooms", "store", "cage", "line", "shed", "hall", "unit", "pen", "lane",
                                     "aisle", "bench", "dock", "cell", "chamber", "vault", "section", "row"}
#: nouns said after a place's whole name that add nothing ("Outbound staging", "the receiving
#: area"): read with it as the place (:meth:`NameIndex._place_noun_after`)
SAID_AFTER_A_PLACE = {"staging", "area", "zone", "location", "bay", "table", "station", "cabinet", "counter", "desk"}
_NOUNS_AFTER_A_NAME = PLACE_NOUNS | SAID_AFTER_A_PLACE
#: words after which a place is said ("to dispatch", "off dispatch"), and words that may follow a
#: place said there; a grammar verb that is a word of one place's name is that place only between
#: the two ("from dispatch to intake", "in dispatch."), never before a count ("to dispatch 3 X")
PLACE_PREPOSITIONS = {"to", "into", "onto", "in", "on", "at", "from", "off", "inside"}
AFTER_A_PLACE = {"to", "into", "onto", "from", "and", "or", "but", "please", "though", "then", "now",
                 "too", "by", "for", "today", "tonight", "first", "asap", "instead", "except", "using", "only",
                 "as", "so", "because", "before", "after", "until", "while", "when", "if", "unless"}
#: words after which such a word is a place as the subject ("dispatch should have 5 X", "...
#: and dispatch wants 3 more"): a verb of the grammar is never followed by one of them
PLACE_SUBJECT_VERBS = {"should", "shouldnt", "needs", "wants", "has", "hasnt", "is", "isnt", "must",
                       "mustnt", "gets", "ought", "will", "wont"}


def _verb_places(names: list["_Name"], reserved: set[str]) -> dict[str, "_Name"]:
    """Words of one place's name that the grammar also reads as a verb ("dispatch" of
    dispatch_cage, "return" of return_bay): read as that place only where a place stands (see
    :data:`PLACE_PREPOSITIONS`, :data:`PLACE_SUBJECT_VERBS`); a word of two names is never read."""
    owners: dict[str, list[_Name]] = {}
    for n in names:
        words = [w for w in re.split(r"[-_\s]+", n.name.lower()) if w]
        for w in set(words):
            owners.setdefault(w, []).append(n)
    return {w: ns[0] for w, ns in owners.items()
            if w in reserved and len(w) >= 4 and len(ns) == 1 and ns[0].kind == "shelf"
            and len([x for x in re.split(r"[-_\s]+", ns[0].name) if x]) >= 2}


def _declared(world: dict, names: list["_Name"]) -> dict["_Name", set[str]]:
    """The normal forms of the words each name's entry declares (``words``: the world's own
    vocabulary, "back row", "Big Red", "rads"), and their plurals."""
    out: dict[_Name, set[str]] = {}
    for n in names:
        entry = (world.get(WORLD_KEYS[n.kind]) or {}).get(n.name)
        for phrase in (entry.get("words") or []) if isinstance(entry, dict) else []:
            form = normalize(str(phrase))
            if form:
                out.setdefault(n, set()).update({form, *plural_forms(form)})
    return out


def _two_word_sayings(world: dict, names: list["_Name"]) -> list[tuple[list[str], "_Name"]]:
    """The two words of each place's or product's name of two words, and of each two-word word
    the world declares for one ("receiving dock" for receiving): what a slip in one of them
    (:meth:`NameIndex._misspelt_apart`) is measured against."""
    out = []
    for n in names:
        if n.kind == "robot":
            continue
        entry = (world.get(WORLD_KEYS[n.kind]) or {}).get(n.name)
        declared = [str(p) for p in entry.get("words") or []] if isinstance(entry, dict) else []
        for phrase in [n.name, *declared]:
            words = [w for w in re.split(r"[-_\s]+", phrase.lower()) if w]
            if len(words) == 2:
                out.append((words, n))
    return out


@functools.lru_cache(maxsize=4096)
def _spellings(alpha: str) -> frozenset[str]:
    """The letters of a name and their other accepted spellings ("isle" of aisle12: "isle twelve")."""
    return frozenset({alpha, *other_spellings(alpha)})


def _spelt_otherwise(n: "_Name") -> set[str]:
    """The normal forms of a name with one of its words in another accepted spelling, and their
    plurals ("despatch" -> "dispatch", "dispatches")."""
    words = [w for w in re.split(r"[-_\s]+", n.name.lower()) if w]
    out: set[str] = set()
    for k, word in enumerate(words):
        for other in other_spellings(word):
            form = normalize("".join(words[:k] + [other] + words[k + 1:]))
            out |= {form, *plural_forms(form)}
    return out


class NameIndex:
    """The world's names by kind, and the rules for deciding which one a word means. ``respelt``:
    other spellings of grammar words ("tae", to), never a misspelt one-word name ("tam") said
    alone; as a word of a longer name one may be ("cold roon")."""

    def __init__(self, world: dict, reserved: Collection[str] = frozenset(), respelt: Collection[str] = frozenset()):
        self.names: list[_Name] = []
        self.by_kind: dict[str, list[str]] = {}
        # words the command grammar reads as English ("haul", "stick", "knock"): a misspelling is
        # never guessed from one of them, or "Haul three" would become a robot hauler3
        self.reserved = set(reserved) | _robot_labels(world)
        self.respelt = frozenset(respelt)   # spellings of grammar words ("tae"): never a fuzzy one-word name
        for kind in KINDS:
            found = list((world.get(WORLD_KEYS[kind]) or {}).keys())
            self.by_kind[kind] = [str(n) for n in found]
            for n in found:
                alpha, digits = split_digits(normalize(str(n)))
                self.names.append(_Name(str(n), kind, alpha, digits))
        # every exact spelling of a name, and its plurals where no other name claims them
        self.forms: dict[str, _Name | None] = {n.alpha + n.digits: n for n in self.names}
        for n in self.names:
            for form in plural_forms(n.alpha + n.digits):
                if form in self.forms and self.forms[form] is not n:
                    if form not in {x.alpha + x.digits for x in self.names}:
                        self.forms[form] = None  # two names share this plural: neither gets it
                    continue
                self.forms[form] = n
        spelt_as_verbs = self._other_forms(world)
        self.said_apart = _two_word_sayings(world, self.names)
        # Stems the world's own names share ("bin" of bin7) forgive misspellings; the English
        # kind words must be spelled right, or "gets" would pass for a misspelt "agents".
        # A stem must be a real word: "a" of A1 or "r" of r7 would turn the article "a" or a
        # stray letter into a kind word.
        self.stems: dict[str, set[str]] = {
            kind: {n.alpha for n in self.names if n.kind == kind and n.digits
                   and len(n.alpha) > 2 and n.alpha not in STOPWORDS} for kind in KINDS
        }

        # Head nouns that several places share ("cage" of north_cage and south_cage, "freezer" of
        # freezer-a and freezer-b): "every cage" means those places, not every place of the world.
        self.groups: dict[str, list[str]] = {}
        for n in found_shelves(world):
            for head in _heads(n):
                self.groups.setdefault(head, []).append(n)
        for head, members in list(self.groups.items()):
            alpha_stem = any(x.alpha == head and x.digits for x in self.names if x.kind == "shelf")
            if (len(members) < 2 and not alpha_stem) or head in STOPWORDS or len(head) <= 2 or any(
                    x.kind != "shelf" and x.alpha == head for x in self.names):
                del self.groups[head]
        self.stems["shelf"] |= set(self.groups)
        # stems robots share before a number or a short label: "the skiffs" (skiff_a, skiff_b)
        self.robot_groups = stem_groups([n.name for n in self.names if n.kind == "robot"])
        self.stems["robot"] |= set(self.robot_groups)

        # One word of a name of two or more words that no other name has ("formula" of
        # baby-formula, "inbound" of inbound_dock, "rice" of rice_sack) names that thing: people
        # shorten names. A word two names share ("dock" of two docks), a grammar or filler word
        # ("sack", "can"), a kind word, a head several places share or a number word names nothing
        # alone (a group, a word of the grammar, or refused: never a guess between names).
        by_name = {n.name: n for n in self.names}

        def english(word: str) -> bool:   # a word of the grammar (a verb: "wheel", "round"), only that
            return word in self.reserved and word not in STOPWORDS and word not in NUMBER_WORDS

        def alone(word: str) -> bool:
            return (word not in STOPWORDS and word not in self.reserved and word not in self.forms
                    and word not in NUMBER_WORDS and word not in self.groups
                    and not any(word in KIND_WORDS[k] or word in self.stems[k] for k in KINDS))
        owners, self.parts, self.shared_parts, self.loose_parts = _word_parts(self.names, by_name, alone, english)

        # a spelling of a grammar word shortens no name: "dat" (that) is no "dispatch"
        self.shortened = _Shortenings(self.names, lambda w: alone(w) and w not in self.respelt, owners,
                                      _starts(self.names, by_name, alone, owners))
        self.contents = _contents(self.names)
        self.initials = _initials(self.names, STOPWORDS | self.reserved | set(self.forms))
        self.verb_places = _verb_places(self.names, self.reserved)
        self.verb_places.update({w: n for w, n in spelt_as_verbs.items()
                                 if n is not None and n.kind == "shelf" and w not in self.verb_places})

    def _other_forms(self, world: dict) -> dict[str, "_Name | None"]:
        """Add to :attr:`forms` the other forms of each name, and return those that are words of
        the grammar (a place only where a place stands: verb_places). First what the world says
        people call a thing ("words": "trade counter" for counter, "rads" for radiator), then a name
        spelt the other accepted way ("dispatch" for despatch, "tire bay" for tyre_bay:
        spelling.other_spellings); each with its plurals, never a form a name already has, and
        one two names would have is neither's (refused, the names offered)."""
        spelt_as_verbs: dict[str, _Name | None] = {}
        for forms_of in (_declared(world, self.names), {n: _spelt_otherwise(n) for n in self.names}):
            taken = set(self.forms)
            for n, forms in forms_of.items():
                for form in forms:
                    into = spelt_as_verbs if form in self.reserved else self.forms
                    if form not in taken:
                        into[form] = None if form in into and into[form] is not n else n
        return spelt_as_verbs

    def group(self, word: str) -> list[str] | None:
        """The places a plural or class word selects ("cages" -> the places whose head is cage).

        None when the word is no head of the world's place names ("places", "areas"): then it
        stands for every place.
        """
        for v in variants(normalize(word)):
            if v in self.groups:
                return list(self.groups[v])
        return None

    def _unnumbered_class(self, alpha: str) -> bool:
        """True for a class word of places that carry no numbers ("cage" of north_cage): a number
        after it is a count ("each cage 1 more"), never a label."""
        if any(v in KIND_WORDS["shelf"] for v in variants(alpha)):
            return False
        members = self.group(alpha)
        return members is not None and not any(split_digits(normalize(m))[1] for m in members)

    def candidates(self, kind: str) -> str:
        """The names of a kind, for an error message."""
        return ", ".join(self.by_kind[kind]) or f"(the world has no {kind})"

    def with_digits(self, kind: str, digits: str, word: str | None = None) -> list[str]:
        """Names of a kind whose trailing number is ``digits`` ("robot 3" -> robot3 or r3).

        With ``word`` (the kind word the command used), only names whose letters could abbreviate
        it or are the kind's own words: "robot 3" finds r3, but "rack 1" never finds A1 (a row
        label, not a rack) and "robot 2" never finds forklift-2.
        """
        out = []
        for n in self.names:
            if n.kind != kind or not n.digits or int(n.digits) != int(digits):
                continue
            if word is not None and n.alpha and not any(
                    w.startswith(n.alpha) or n.alpha in KIND_WORDS[kind] for w in variants(word)):
                continue
            out.append(n.name)
        return out

    def kind_of_word(self, alpha: str) -> str | None:
        """The kind a bare word names ("shelves", "prodcut" -> product), if any."""
        hits, near = set(), set()
        for kind in KINDS:
            for v in variants(alpha):
                if v in KIND_WORDS[kind] or v in self.stems[kind]:
                    hits.add(kind)
                elif alpha not in STOPWORDS and alpha not in self.reserved and any(
                        v[:1] == stem[:1] and distance(v, stem) <= tolerance(len(stem))
                        for stem in self.stems[kind]):
                    near.add(kind)
        hits = hits or near   # a kind word as said wins over a near miss of a stem ("racks", robots reach1, reach2)
        if len(hits) > 1:
            raise TranslationError(f"{_quote(alpha)} could name a {' or a '.join(sorted(hits))}")
        return hits.pop() if hits else None

    def lookup(self, alpha: str, digits: str, text: str, fuzzy: bool = True) -> Tok | None:
        """Resolve letters + number to a name or a kind word; raise when it cannot be told."""
        for v in variants(alpha):
            # another spelling only with a number ("isle 12"): alone, "dispatch" may be the verb
            exact = [n for n in self.names if n.digits == digits and (v == n.alpha or digits and v in _spellings(n.alpha))]
            if exact:
                return Tok("name", text, exact[0].name, exact[0].kind)
        # a word the world declares in the shape of a word and a number ("rack 2" for raft2): that
        # name, before a kind word and a number look for a place numbered so and find none
        declared = self.forms.get(alpha + digits) if digits else None
        if declared is not None:
            return Tok("name", text, declared.name, declared.kind)
        if not digits and any(v in KIND_WORDS[k] or v in self.groups or v in self.robot_groups
                              for k in KINDS for v in variants(alpha)):
            # "racks" is the kind word, not a misspelt rack_a (nor a tie of all racks); "row" of
            # row-a and row-b is the head noun they share (a group: "every row"), not a tie
            fuzzy = False
        if fuzzy and alpha not in STOPWORDS and alpha not in self.reserved and alpha not in self.respelt \
                and alpha not in TALK and alpha:   # "cheers" is talk, never a misspelt cider
            scored = []
            for n in self.names:
                if n.digits != digits:
                    continue
                # a word's edits are counted against the shorter of the two ("flat" is no flint),
                # and a spelling by sound costs nothing ("alfa" for alpha)
                d = min(min(distance(v, n.alpha), distance(sounded(v), sounded(n.alpha))) for v in variants(alpha))
                if d <= tolerance(min(len(n.alpha), len(alpha))) and alpha[:1] == n.alpha[:1]:
                    scored.append((d, n))
            if scored and common_word(alpha.lower()):
                # a common English word as written ("jacks", "forks") is no slip of a name that is
                # no English word ("jacu"): only of one that is, spelt another way ("dispatch" of
                # despatch, "ballots" of ballast)
                scored = [(d, n) for d, n in scored if d == 0 or common_word(n.alpha.lower())]
            if scored:
                best = min(d for d, _ in scored)
                top = [n for d, n in scored if d == best]
                if len(top) > 1:
                    raise TranslationError(
                        f"cannot tell which name {_quote(text)} means: it is equally close to "
                        f"{', '.join(n.name for n in top)} (candidates: {', '.join(n.name for n in top)})")
                return Tok("name", text, top[0].name, top[0].kind)
        kind = self.kind_of_word(alpha) if alpha else None
        if kind is None:
            return None
        if not digits:
            return Tok("kind", text, kind, kind)
        same = self.with_digits(kind, digits, alpha)
        if len(same) == 1:
            return Tok("name", text, same[0], kind)
        raise TranslationError(
            f"{_quote(text)} names no {kind} in this world (candidates: {self.candidates(kind)})")

    def ordinal(self, kind: str, n: int, text: str) -> Tok:
        """"the third shelf": only when the world's order and its numbering agree on one name."""
        listed = self.by_kind[kind]
        numbered = self.with_digits(kind, str(n))
        if 0 < n <= len(listed) and numbered == [listed[n - 1]]:
            return Tok("name", text, listed[n - 1], kind)
        raise TranslationError(
            f"{_quote(text)}: cannot tell which {kind} is meant by position "
            f"(candidates: {self.candidates(kind)})")

    def listed(self, raw: list[str], i: int) -> tuple[list[Tok], int] | None:
        """ "racks A, B and E", "bays 2 and 4": a plural kind word and the labels it shares out.

        Only shelves (robots have ranges of their own); every label must name exactly one
        place, or nothing is read here and the words go their usual way.
        """
        low = raw[i].lower()
        if not low.endswith("s") or low[:-1] not in KIND_WORDS["shelf"] | self.stems["shelf"]:
            return None
        stem = low[:-1]
        out: list[Tok] = []
        j = i + 1
        while j < len(raw):
            label = raw[j].lower()
            n = word_value(label)
            key = stem + (str(n) if n is not None else label)
            hit = [x.name for x in self.names if x.kind == "shelf" and x.alpha + x.digits == normalize(key)]
            if n is not None and not hit:
                hit = self.with_digits("shelf", str(n), stem)
            if len(hit) != 1 or (n is None and len(label) > 2):
                break
            out.append(Tok("name", raw[j] if out else f"{raw[i]} {raw[j]}", hit[0], "shelf"))
            j += 1
            if j + 1 < len(raw) and raw[j].lower() in (",", "and", "or", "&"):
                nxt = raw[j + 1].lower()
                if nxt in ("and", "or") and j + 2 < len(raw):
                    out.append(Tok("punct", raw[j], raw[j]) if raw[j] == "," else Tok("word", raw[j], raw[j].lower()))
                    j += 1
                out.append(Tok("punct", raw[j], raw[j]) if raw[j] == "," else Tok("word", raw[j], raw[j].lower()))
                j += 1
                continue
            break
        names = [t for t in out if t.kind == "name"]
        if len(names) < 2:
            return None
        while out and out[-1].kind != "name":  # a separator read past the last label goes back
            out.pop()
            j -= 1
        return out, j

    def _with_place_noun(self, raw: list[str], i: int) -> Tok | None:
        """A numbered place said with a place noun between its letters and its number ("chill
        room 1" for chill1, "cold store two" for cold2): read only where the letters and the
        number name exactly one place, the noun is a word for a place (:data:`PLACE_NOUNS`), and
        the letters with the noun name nothing else."""
        if i + 2 >= len(raw) or raw[i + 1].lower() not in PLACE_NOUNS:
            return None
        alpha, digits = split_digits(normalize(raw[i]))
        n = word_value(raw[i + 2].lower())
        if digits or not alpha or n is None or alpha in STOPWORDS or normalize(raw[i] + raw[i + 1]) in self.forms:
            return None
        hits = [x for x in self.names if x.kind == "shelf" and x.alpha == alpha and x.digits
                and int(x.digits) == n]
        return Tok("name", " ".join(raw[i:i + 3]), hits[0].name, "shelf") if len(hits) == 1 else None

    def _place_noun_after(self, whole: "_Name", raw: list[str], i: int) -> bool:
        """Whether a place's whole name at ``raw[i]`` is followed by a noun for a place that the
        world does not have as a word of its own ("Outbound staging", "the receiving area" for
        outbound, receiving): read as the place. Not where the noun names or is part of another
        name ("outbound dock" where a dock is a place), where a number follows it ("outbound dock
        2"), nor where the two words are a name."""
        if whole.kind != "shelf" or i + 1 >= len(raw):
            return False
        noun = raw[i + 1].lower()
        if noun not in _NOUNS_AFTER_A_NAME:
            return False
        if i + 2 < len(raw) and word_value(raw[i + 2].lower()) is not None:
            return False   # "outbound dock 2": the noun and its number may name a place of their own
        return not any(normalize(x) in self.forms or normalize(x) in self.parts for x in (noun, raw[i] + raw[i + 1]))

    def written_apart(self, raw: list[str], i: int) -> tuple[Tok, int] | None:
        """A name of two or three words starting at ``raw[i]``, in any of its spellings and
        plurals ("cable spools" for cable_spool, "paint shop" for paint-shop); the longest wins.
        Words that are numbers after the first are left to the count reader, but for the number
        that ends a numbered place's name as the world declares it ("loading bay 3" for bay3: its
        number, in digits, as "bay 3" is read)."""
        for size in (3, 2):
            part = raw[i:i + size]
            if len(part) < size or not all(_TOKEN.fullmatch(w) and w[0].isalnum() for w in part):
                continue
            numbered = self._declared_number(part)
            if numbered is not None:
                return Tok("name", " ".join(part), numbered.name, numbered.kind), i + size
            hit = self.forms.get(normalize("".join(part)))
            if any(word_value(w.lower()) is not None for w in part[1:]):
                if hit is None:   # a number word in a name the world has ("estante tres") is that name
                    continue
            hit = hit or self.contents.get(normalize("".join(part)))
            if hit is not None:
                return Tok("name", " ".join(part), hit.name, hit.kind), i + size
        hit = self._misspelt_apart(raw[i:i + 2]) or self._shortened_apart(raw[i:i + 2])
        return (Tok("name", " ".join(raw[i:i + 2]), hit.name, hit.kind), i + 2) if hit is not None else None

    def _declared_number(self, part: list[str]) -> "_Name | None":
        """The place whose declared word is ``part`` with its last word a number in digits that is
        the place's own ("loading bay 3" for bay3), the other words no number."""
        if not part[-1].isdigit() or any(word_value(w.lower()) is not None for w in part[:-1]):
            return None
        hit = self.forms.get(normalize("".join(part)))
        return hit if hit is not None and hit.kind == "shelf" and hit.digits \
            and int(hit.digits) == int(part[-1]) else None

    def _misspelt_part(self, word: str) -> "_Name | None":
        """A word of a name read alone (:attr:`parts`) misspelt by one edit, same first letter, five
        letters or more ("formla" for the formula of baby-formula): read only where exactly one
        such word is near, it names one thing, and the word is nothing else (no grammar word, no
        name, no word several names share)."""
        if (len(word) < 5 or not word.isalpha() or word in self.reserved or word in STOPWORDS
                or word in self.forms or word in self.shared_parts or word in self.loose_parts
                or self.lookup(*split_digits(word), word, fuzzy=False) is not None):
            return None
        near = {self.parts[p].name: self.parts[p] for p in self.parts
                if p[:1] == word[:1] and abs(len(p) - len(word)) <= 1 and distance(p, word) <= 1}
        return next(iter(near.values())) if len(near) == 1 else None

    def _misspelt_apart(self, pair: list[str]) -> "_Name | None":
        """A two-word name written apart, or a two-word word the world declares for it, with one of
        its words misspelt or misheard by one edit ("tastng room" for tasting_room, "receiving duck"
        for the receiving dock), the other right: read only where exactly one name fits, and never from a
        word of the grammar (``reserved``) or a short word."""
        if len(pair) < 2 or not all(w.isalpha() for w in pair):
            return None
        a, b = (normalize(w) for w in pair)
        if any(w in self.reserved or w in STOPWORDS or w in NUMBER_WORDS for w in (a, b)):
            return None

        def near(said: str, word: str) -> bool:
            return said != word and len(word) >= 4 and said[:1] == word[:1] and distance(said, word) <= 1

        hits = []
        for words, n in self.said_apart:
            last = set(variants(b)) & ({words[1]} | set(plural_forms(words[1])))
            plural_near = any(near(b, w) for w in [words[1], *plural_forms(words[1])])   # "chew tyos"
            if ((a == words[0] and not last and plural_near) or (last and near(a, words[0]))) and n not in hits:
                hits.append(n)
        return hits[0] if len(hits) == 1 else None

    def _shortened_apart(self, pair: list[str]) -> "_Name | None":
        """A two-word place or product written apart with its first word cut short and its second
        as it is ("mag A" for magazine_a, "disp cage" for dispatch_cage): the short word is the
        start, three letters or more and two or more short, of the name's first word, and no
        word of the grammar or a name. Read only where exactly one name fits (with magazine_a
        and magazine_b, "mag" alone fits neither, "mag B" one)."""
        if len(pair) < 2 or not all(w.isalnum() for w in pair):
            return None
        a, b = pair[0].lower(), normalize(pair[1])
        if (not a.isalpha() or len(a) < 3 or a in self.reserved or a in STOPWORDS or a in NUMBER_WORDS
                or a in self.forms):
            return None
        hits = []
        for n in self.names:
            words = [w for w in re.split(r"[-_\s]+", n.name.lower()) if w]
            if n.kind == "robot" or len(words) != 2 or len(a) > len(words[0]) - 2:
                continue
            if words[0].startswith(a) and b in {words[1], *plural_forms(words[1])}:
                hits.append(n)
        return hits[0] if len(hits) == 1 else None

    def _inverted(self, raw: list[str], i: int) -> Tok | None:
        """A two-word product said "<head> of <modifier>" ("crates of bottles" for bottle_crate,
        "sacks of malt" for malt-sack): read only where the two words are exactly the words of one
        product's name (in the singular or a plural)."""
        if i + 2 >= len(raw) or raw[i + 1].lower() != "of" or not raw[i].isalpha() or not raw[i + 2].isalpha():
            return None
        head, mod = set(variants(normalize(raw[i]))), set(variants(normalize(raw[i + 2])))
        hits = [n for n in self.names if n.kind == "product" and len(ws := [w for w in re.split(r"[-_\s]+", n.name.lower())
                                                                       if w]) == 2
                and ws[1] in head and ws[0] in mod]
        if len(hits) != 1:
            return None
        return Tok("name", " ".join(raw[i:i + 3]), hits[0].name, "product")

    def _tens_and_units(self, raw: list[str], i: int) -> Tok | None:
        """ "door twenty two" for door22: a name whose number is said as tens and units, in two
        words (speech to text writes "twenty two", not "twenty-two"). Only a name the world has is
        read so; otherwise "door twenty" and a count "two" are left to the shorter reading."""
        if i + 2 >= len(raw) or raw[i + 1].lower() not in TENS or not 0 < UNITS.get(raw[i + 2].lower(), 0) < 10:
            return None
        alpha, digits = split_digits(normalize(raw[i].lower()))
        if digits or not alpha or self._unnumbered_class(alpha):
            return None
        number = TENS[raw[i + 1].lower()] + UNITS[raw[i + 2].lower()]
        for v in variants(alpha):
            exact = [n for n in self.names if n.alpha == v and n.digits == str(number)]
            if exact:
                return Tok("name", " ".join(raw[i:i + 3]), exact[0].name, exact[0].kind)
        return None

    def at(self, raw: list[str], i: int) -> tuple[Tok, int] | None:
        """The name or kind word starting at ``raw[i]``, longest reading first."""
        low = raw[i].lower()
        spoken = self._tens_and_units(raw, i)
        if spoken is not None:
            return spoken, i + 3
        if low in ORDINALS and i + 1 < len(raw) and raw[i + 1][0].isalpha():
            kind = self.kind_of_word(normalize(raw[i + 1]))
            if kind is not None and raw[i + 1].lower() in KIND_WORDS[kind] | self.stems[kind] | {
                    w + "s" for w in self.stems[kind]}:
                return self.ordinal(kind, ORDINALS[low], f"{raw[i]} {raw[i + 1]}"), i + 2
        inverted = self._inverted(raw, i)
        if inverted is not None:
            return inverted, i + 3
        if i + 2 < len(raw) and raw[i + 1].lower() in NUMBER_MARKS and word_value(raw[i + 2].lower()) is not None:
            alpha, digits = split_digits(normalize(low))
            if not digits and self.kind_of_word(alpha):  # "shelf number 3", "robot no 4"
                found = self.lookup(alpha, str(word_value(raw[i + 2].lower())),
                                    " ".join(raw[i:i + 3]))
                if found is not None:
                    return found, i + 3
        found = self._with_place_noun(raw, i)
        if found is not None:
            return found, i + 3
        if i + 1 < len(raw) and _TOKEN.fullmatch(raw[i + 1]) and raw[i + 1][0].isalnum():
            nxt = raw[i + 1].lower()
            text = f"{raw[i]} {raw[i + 1]}"
            alpha, digits = split_digits(normalize(low))
            n = word_value(nxt)
            if not digits and alpha and n is not None and not self._unnumbered_class(alpha) and (
                    alpha not in STOPWORDS or self.kind_of_word(alpha)) and normalize(low + nxt) not in self.forms:
                found = self.lookup(alpha, str(n), text)
                if found is not None:
                    return found, i + 2
            # a name written apart ("cold store", "rack a", "label rolls"): no typos; with a number
            # word only as a word the world declares ("estante tres")
            if not n or normalize(low + nxt) in self.forms:
                found = self.written_apart(raw, i)
                if found is not None:
                    return found
        norm = normalize(low)
        if not norm or norm.isdigit() or low in NUMBER_WORDS:
            return None
        whole = self.forms.get(norm)
        if whole is not None and not (norm != whole.alpha + whole.digits and low in STOPWORDS):
            if self._place_noun_after(whole, raw, i):   # "Outbound staging" for outbound
                return Tok("name", f"{raw[i]} {raw[i + 1]}", whole.name, whole.kind), i + 2
            return Tok("name", raw[i], whole.name, whole.kind), i + 1  # "sku-220s", "label_rolls"
        part = self.parts.get(norm)
        if part is not None:
            return Tok("name", raw[i], part.name, part.kind), i + 1  # "formula" for baby-formula
        near = self._misspelt_part(norm)
        if near is not None:
            return Tok("name", raw[i], near.name, near.kind), i + 1  # "formla" for baby-formula
        if norm in self.shared_parts or norm in self.loose_parts:
            # a word of several names ("milk" of milk_crate and milk-churn), or a modifier that may
            # name something else ("oil" of oil-filter): never read as the nearest name by typo
            # tolerance ("milks" is no misspelt milk_crate); the command is refused, the names offered
            return None
        alpha, digits = split_digits(norm)
        found = self.lookup(alpha, digits, raw[i])
        short = self.shortened(norm) if found is None else None
        if short is not None:
            found = Tok("name", raw[i], short.name, short.kind)  # "mezz" for mezzanine, "shz" for shiraz
        if found is None and raw[i].isalpha() and raw[i].isupper() and 2 <= len(raw[i]) <= 4 and norm in self.initials:
            said = self.initials[norm]   # "OB" for outbound: initials, said in capitals
            found = Tok("name", raw[i], said.name, said.kind)
        after = raw[i + 1].lower().replace("'", "").replace("’", "") if i + 1 < len(raw) else ""
        where = i > 0 and raw[i - 1].lower() in PLACE_PREPOSITIONS and (
            not after or not after[0].isalnum() or after in AFTER_A_PLACE)
        if found is None and norm in self.verb_places and (where or after in PLACE_SUBJECT_VERBS):
            place = self.verb_places[norm]
            found = Tok("name", raw[i], place.name, place.kind)   # "from dispatch to intake"
        return (found, i + 1) if found is not None else None


def tokenize(command: str, index: NameIndex) -> list[Tok]:
    """:func:`recognize`, then :func:`read_counts`."""
    return read_counts(recognize(command, index))


def recognize(command: str, index: NameIndex) -> list[Tok]:
    """Split a command into words, names, counts and punctuation.

    Names are recognised before counts, so "product 1" is one product and not a count of 1.
    Apostrophes are dropped ("don't" -> "dont"); a range written "8-11" reads as "8 to 11".
    """
    raw: list[str] = []
    command = re.sub(r"-+>|→|=>", " to ", command)
    command = re.sub(r"\b(\d+)\s*[x×]\b", r"\1 x", command)  # "5x product1"
    for m in _TOKEN.finditer(command):
        t = m.group(0).replace("'", "").replace("’", "")
        if re.fullmatch(r"\d+-\d+", t) or (
                re.fullmatch(r"[A-Za-z]+\d+-[A-Za-z]+\d+", t)
                and not any(normalize(t) == x.alpha + x.digits for x in index.names)):
            a, b = t.split("-")  # "8-11", "r2-r4": a range
            raw += [a, "to", b]
        else:
            raw.append(t)
    toks: list[Tok | None] = []
    i = 0
    while i < len(raw):
        t = raw[i]
        if t == "#":  # not consumed as a number mark by the name before it
            toks.append(Tok("word", t, t))
            i += 1
            continue
        if not t[0].isalnum():
            toks.append(Tok("punct", t, t))
            i += 1
            continue
        if re.fullmatch(r"\d+\.\d+", t):
            raise TranslationError(f"'{t}' is not a whole number of units")
        listed = index.listed(raw, i)
        if listed is not None:
            toks += listed[0]
            i = listed[1]
            continue
        found = index.at(raw, i)
        if found is not None:
            toks.append(found[0])
            i = found[1]
            continue
        toks.append(Tok("word", "'s" if t == POSS_MARK else t, t.lower()))   # the mark is quoted as written
        i += 1
    return _listed_verb_places([t for t in toks if t is not None], index)


def _listed_verb_places(toks: list[Tok], index: NameIndex) -> list[Tok]:
    """A word of the grammar that is one place's word (:attr:`NameIndex.verb_places`: "dispatch")
    listed with other places ("the canopy and dispatch", "dispatch, canopy and the counter"): that
    place. A verb never stands between "and" / "or" / a comma and a place's name."""
    out = list(toks)
    joins = {"and", "or", ","}
    for k, t in enumerate(out):
        if t.kind != "word" or t.value not in index.verb_places:
            continue
        nxt = out[k + 1] if k + 1 < len(out) else None
        if nxt is not None and nxt.kind != "punct" and str(nxt.value) not in AFTER_A_PLACE | PLACE_SUBJECT_VERBS:
            continue   # "... and dispatch 3 X to P": the verb, with what it sends after it
        before = out[k - 2] if k >= 2 and str(out[k - 1].value) in joins else None
        after = next((x for x in out[k + 2:k + 4] if str(x.value) != "the"), None) \
            if k + 2 < len(out) and str(out[k + 1].value) in joins else None
        if any(x is not None and x.kind == "name" and x.of == "shelf" for x in (before, after)):
            place = index.verb_places[str(t.value)]
            out[k] = Tok("name", t.text, place.name, place.kind)
    return out


def read_counts(toks: list[Tok]) -> list[Tok]:
    """Merge runs of plain words that spell a count ("ten plus seven") into one "num" token.

    Counts are read over plain words only, so a name never becomes part of a count.
    """
    out: list[Tok] = []
    words = [t.value if t.kind == "word" else None for t in toks]
    i = 0
    while i < len(toks):
        got = read_number(words, i) if words[i] is not None else None
        if got is not None:
            value, end = got
            out.append(Tok("num", " ".join(t.text for t in toks[i:end]), value))
            i = end
        else:
            out.append(toks[i])
            i += 1
    return out

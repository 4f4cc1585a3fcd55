"""Misspelt words: which known words (the world's words, the lexicon's content words, a few
politeness words) a word known nowhere may be a slip of. A guess that could name another thing is
never made: one edit (two for long stems), the same first letter, content words only."""
from __future__ import annotations

from pipflow.household.language.lexicon import FILLER, FILLER_TYPO_TARGETS, PHRASES, STATES_SAID_OTHERWISE
from pipflow.household.language.names import home_words, per_index
from pipflow.household.language.tokens import PUNCT
from pipflow.language.asides import FUNCTION_WORDS
from pipflow.language.numbers import reads_as_count
from pipflow.language.spelling import distance


#: token classes whose words a typo may be read as: content words only. A function word is short
#: and close to many words ("fork" is not "for", "house" is not "those"), so it is never guessed.
CONTENT_CLASSES = {"V_STATE", "V_OPEN", "V_SHUT", "V_CLEAN", "V_WARM", "V_TOGGLE", "V_PUT", "V_THROW", "V_TRASH", "V_CHILL",
                   "V_TIDY", "V_LEAVE", "V_MAKE", "V_PREPARE", "ADJ", "ACTIVITY", "LIGHTCUE", "TOGGLED", "MEAL", "V_LIGHT",
                   "TEMPCUE", "V_TEND"}


#: the lexicon's one-word content words, and every word of its phrases and fillers (the lexicon is
#: complete once imported; these are asked of every word of every reading)
_CONTENT_WORDS = frozenset(w for k, (cls, _) in PHRASES.items() if cls in CONTENT_CLASSES and len(k) == 1 for w in k)
_LEXICON_WORDS = frozenset(w for key in PHRASES for w in key) | frozenset(w for key in FILLER for w in key)


@per_index
def vocabulary(world_index: dict) -> frozenset[str]:
    """Words a misspelt word may be read as: the world's words, the lexicon's content words and
    the few politeness words of ``FILLER_TYPO_TARGETS`` ("plese")."""
    return frozenset(w for w in (_CONTENT_WORDS - STATES_SAID_OTHERWISE.keys()) | FILLER_TYPO_TARGETS
                     | home_words(world_index) if len(w) >= 3)


def known_word(w: str, index: dict, vocab: frozenset[str]) -> bool:
    """Whether the tagger reads ``w`` as it is: a word of the world, of the lexicon, of the
    politeness list, a number or a mark."""
    return w in vocab or w in PUNCT or w.isdigit() or w in _LEXICON_WORDS or \
        w in home_words(index) or reads_as_count(w)


#: endings of English inflection: a shared one says nothing of whether two words are one word
#: misspelt ("trying" and "tidying" share "ing"; what is left, "try" and "tidy", is two edits apart)
INFLECTIONS = ("ing", "ed", "es", "s")


def _stem(known: str, word: str) -> str:
    """``known`` without an inflectional ending it shares with ``word``: the length that earns a
    second edit is the stem's, so "starving" is not read as "stacking", nor "trying" as "tidying"."""
    for end in INFLECTIONS:
        if known.endswith(end) and word.endswith(end) and len(known) > len(end) + 2:
            return known[:-len(end)]
    return known


def typo_of(word: str, vocab: set[str]) -> list[str]:
    """Known words ``word`` may be a misspelling of, closest first: the same first letter and one
    edit (two for words of 7 letters or more; a swap of neighbours is one). "toaster" is not
    "toast", "ones" is not "phones": a guess that names another thing would be a misreading."""
    near = [(distance(word, v), v) for v in vocab if v[0] == word[0] and abs(len(v) - len(word)) <= 2]
    near = [(d, v) for d, v in near if d <= (1 if len(_stem(v, word)) <= 6 else 2)]
    best = min((d for d, _ in near), default=None)
    return [v for d, v in sorted(near) if d == best]


def meaning_of(word: str, world_index: dict) -> str:
    """What one known word stands for, so that two spellings of one thing ("tomato",
    "tomatoes") do not make a typo ambiguous."""
    names = sorted(r["name"] for r in world_index.get((word,), []))
    return f"{names}|{PHRASES.get((word,))}"


def _swapped(word: str, known: str) -> bool:
    """Whether ``word`` is ``known`` with two neighbouring letters swapped ("teh", "adn", "form")."""
    if len(word) != len(known) or word == known:
        return False
    diff = [k for k in range(len(word)) if word[k] != known[k]]
    return len(diff) == 2 and diff[1] == diff[0] + 1 and word[diff[0]] == known[diff[1]] and \
        word[diff[1]] == known[diff[0]]


def _swaps(word: str) -> set[str]:
    """Every spelling of ``word`` with two neighbouring (different) letters swapped."""
    return {word[:k] + word[k + 1] + word[k] + word[k + 2:] for k in range(len(word) - 1) if word[k] != word[k + 1]}


#: the words of the grammar (one-word phrases of the lexicon), by each of their swapped spellings,
#: for :func:`transposition_of`
_GRAMMAR_SWAPS: dict[str, list[str]] = {}
for _k in sorted({k[0] for k in PHRASES if len(k) == 1 and len(k[0]) >= 3}):
    for _v in _swaps(_k):
        _GRAMMAR_SWAPS.setdefault(_v, []).append(_k)


def transposition_of(word: str) -> list[str]:
    """Words of the grammar (function words too) that ``word`` is a swap of two neighbouring
    letters of ("teh" -> the, "adn" -> and): a slip of typing fast, which no other spelling is.
    The tagger reads the word so only when there is exactly one such word."""
    return list(_GRAMMAR_SWAPS.get(word, ()))


#: the definite determiners: before the name of a thing each picks that thing ("the", "that" or
#: "this" bun is the one bun named)
DEFINITE = ("the", "that", "this")


def determiner_slip(word: str, before_name: bool) -> str | None:
    """ "teh", "tht", "hte" before the name of a thing: one slip (an edit, or a swap of neighbours)
    from a definite determiner (:data:`DEFINITE`), read as "the". Between a verb and a name only a
    determiner fits, and the definite ones pick the same thing, so "teh" is not "tea" there
    ("wash teh wine glass"); elsewhere the word is left to the other repairs. None when it is no
    such slip."""
    if not before_name or len(word) > 5 or not word.isalpha() or word in FUNCTION_WORDS or word.isdigit():
        return None   # "what mug", "she": words of their own, never a slip
    near = [d for d in DEFINITE if (word[0] == "t" and distance(word, d) <= 1) or _swapped(word, d)]
    return "the" if near else None

"""Common English words, for telling a word written as itself from a slip of a name.

A word one or two edits from a name of the world is taken for a misspelt name, so a clause that
holds one is never talk to set aside ("..., the shlef"). But ordinary words are often that close
to a name: "big" to "bin", "boss" to "bots", "left" to "loft", "grease" to "areas". A word people
write often as itself is no slip of a name; the test is a frequency list of English as written
(pyspellchecker's, from subtitles and the web), not a list we keep. The list is loaded on first
use: a command whose every word is placed never needs it.

Spoken forms whose apostrophe marks what is left out ("burnin'", "'em", "ain't") are written out
here too (:func:`spoken_forms`): whether "burnin'" is "burning" is whether that is common English.
"""
from __future__ import annotations

import functools
import re

#: how often a word must occur in the list (of some 10^9 words) to count as written as itself:
#: slips ("shlef", "fourty", "olny") and rare coinages stay below it, "tho" (262) and "arvo"
#: (50) are on either side
COMMON = 100


#: contractions as people type them without the apostrophe ("theyve", "hes"): the list has them
#: only with it
CONTRACTIONS = frozenset(f"{who}{tail}" for who, tails in (
    ("i", ("m", "ve", "ll", "d")), ("you", ("re", "ve", "ll", "d")), ("we", ("re", "ve", "ll", "d")),
    ("they", ("re", "ve", "ll", "d")), ("he", ("s", "ll", "d")), ("she", ("s", "ll", "d")),
    ("it", ("s", "ll", "d")), ("that", ("s", "ll", "d")), ("there", ("s", "re", "ll", "d")),
    ("who", ("s", "ll", "d", "ve")), ("what", ("s", "ll", "d", "ve")))
    for tail in tails) | frozenset(f"{verb}nt" for verb in (
        "is", "are", "was", "were", "do", "does", "did", "have", "has", "had", "could", "would", "should",
        "must", "need", "ca", "wo", "ai", "might"))


@functools.cache
def _frequencies() -> object:
    from spellchecker import SpellChecker  # deferred on purpose: a second's load, rarely needed
    return SpellChecker(language="en", distance=1).word_frequency


def common_word(word: str) -> bool:
    """Whether a lower-case word is a common English word as written (:data:`COMMON`), or a
    contraction typed without its apostrophe (:data:`CONTRACTIONS`)."""
    if word in CONTRACTIONS:
        return True
    frequencies = _frequencies()
    return word in frequencies and frequencies[word] >= COMMON


#: "in'" for "ing" as it is said ("burnin'", "settin'", "nothin'"): the apostrophe marks the
#: dropped g, and the word with it must be a common English word ("cabin'" is no "cabing")
_DROPPED_G = re.compile(r"\b([A-Za-z]{2,}in)['\u2019](?=[\s.,;:!?]|$)")


def dropped_g(word: str) -> str | None:
    """ "runnin", "comin", "gettin": a word said with its "ing" as "in" and typed so, without the
    apostrophe that marks it: the word with its g where that is common English and the word as
    written is at most a hundredth as common ("raisin", "basin", "thin" stay themselves); else None.
    Callers ask only about words that are no word of the world's names ("a singin hinny"). The
    list of words is loaded only for a word of four letters or more ending in "in"."""
    if len(word) < 4 or not word.endswith("in"):
        return None
    frequencies = _frequencies()
    full = word + "g"
    return full if frequencies[full] >= COMMON and frequencies[word] * 100 < frequencies[full] else None


#: spoken forms whose apostrophe marks what is left out, read as written out in full
_SPOKEN = ((re.compile(r"(?<![A-Za-z])['\u2019]em\b", re.IGNORECASE), "them"),
           # Yorkshire and Lancashire: "t'kettle", "th'owd chair" (the), "a sack o' spuds" (of),
           # "wi' us tea" (with), "fish an' chips" (and); never "o'clock", "don't", "isn't"
           (re.compile(r"(?<![A-Za-z'\u2019])th?['\u2019]\s*(?=[A-Za-z])", re.IGNORECASE), "the "),
           (re.compile(r"(?<![A-Za-z'\u2019])o['\u2019](?=\s|$)", re.IGNORECASE), "of"),
           (re.compile(r"(?<![A-Za-z'\u2019])wi['\u2019](?=\s|$)", re.IGNORECASE), "with"),
           (re.compile(r"(?<![A-Za-z'\u2019])an['\u2019](?=\s|$)", re.IGNORECASE), "and"),
           (re.compile(r"\by['\u2019]all\b", re.IGNORECASE), "you all"),
           # Brummie "ta-ra", "ta-ra-a-bit" (goodbye, bye for now): one word, its "a bit" no quantity
           (re.compile(r"\bta-ra(?:-a-bit)?\b", re.IGNORECASE), "tara"),
           # Brummie and Black Country "they'm", "we'm", "yow'm" (they are, we are, you are)
           (re.compile(r"\b(they|we|you|yow)['\u2019]m\b", re.IGNORECASE), r"\1 are"),
           (re.compile(r"\bain['\u2019]?t(?=\s+(?:got|been|had|done|seen)\b)", re.IGNORECASE), "has not"),
           (re.compile(r"\bain['\u2019]?t\b", re.IGNORECASE), "is not"))


#: "'ob", "'is", "'orse" for "hob", "his", "horse" (Cockney, and most of England's speech): the
#: apostrophe before a vowel marks the dropped h; "'em" (them) is read first (:data:`_SPOKEN`)
_DROPPED_H = re.compile(r"(?<![A-Za-z0-9'\u2019])['\u2019]([AEIOUaeiou][a-z]*)\b(?!['\u2019](?![A-Za-z]))")


def spoken_forms(text: str) -> str:
    """The text with the spoken forms an apostrophe marks written out ("burnin'" -> "burning",
    "'em" -> "them", "'ob" -> "hob", "y'all" -> "you all", "ain't" -> "is not"). Only the
    apostrophe tells them: "in" without one ("cabin", "basin") and "orse" without one are never
    touched; the word written out must be common English ("'til" stays)."""
    def g(m: re.Match) -> str:
        word = m.group(1) + "g"
        return word if common_word(word.lower()) else m.group(0)

    def h(m: re.Match) -> str:
        said = m.group(1)
        word = ("H" if said[0].isupper() else "h") + said.lower()
        return word if common_word(word.lower()) else m.group(0)
    if "in'" in text or "in\u2019" in text:
        text = _DROPPED_G.sub(g, text)
    for pattern, written in _SPOKEN:
        text = pattern.sub(written, text)
    return _DROPPED_H.sub(h, text)

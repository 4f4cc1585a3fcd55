"""Near-miss words for a refused command's candidate readings: what a word no rule places may
have been meant as ("fiev" -> five, "sackle" -> shackle, "formla" -> formula).

Why apart from the lexicon's own repair: the lexicon repairs a word only when exactly one
repair is near (two that compete leave the word unknown and the command refused), because what
it repairs is acted on. A candidate reading is only offered, and says which word it read as
which, so here every near word is a reading to offer: the user chooses, or the run refuses.
"""
from __future__ import annotations

import re
from os.path import commonprefix

from pipflow.language.numbers import NUMBER_WORDS
from pipflow.language.spelling import distance, normalize
from pipflow.warehouse.language.lexicon import Lexicon

#: repairs offered for one word, at most (each costs a reading of the command)
MAX_REPAIRS = 3
#: words a speech recogniser writes for a number word said aloud ("send ate reams", "add won more",
#: "move for zips"): offered as that number where the word is one no rule places, never read so
HOMOPHONES = {"ate": "eight", "won": "one", "for": "four", "fore": "four", "to": "two", "too": "two"}
#: prepositions people put for one another, in a second language above all ("take 4 of the
#: mezzanine" for from, "bring 2 from returns for picking" for to, "divide them for P and Q" for
#: between): where a preposition is the word no rule places, the command read with each of these
#: in its place is offered, most likely first (never acted on unchosen)
PREPOSITION_SWAPS = {"of": ("from", "on", "in"), "for": ("to", "between", "on"), "in": ("into", "on", "at"),
                     "on": ("in", "to", "onto"), "at": ("on", "in", "to"), "to": ("on", "in", "from"),
                     "from": ("of", "off", "on"), "into": ("to", "in"), "onto": ("to", "on"), "with": ("to", "of")}


def near_words(word: str, lex: Lexicon) -> list[str]:
    """Grammar words, number words and words of the world's names within one edit of ``word``
    (a swap of neighbours is one edit), or two for words of five letters or more that keep
    their first letter; nearest first; a number word it sounds like first (:data:`HOMOPHONES`),
    then the prepositions put for it (:data:`PREPOSITION_SWAPS`).
    None for a word of fewer than three letters, a number or a name of several words."""
    low = word.lower()
    sounds = [HOMOPHONES[low]] if low in HOMOPHONES else []
    sounds += PREPOSITION_SWAPS.get(low, ())
    if len(low) < 3 or not low.isalpha() or low in PREPOSITION_SWAPS:
        return sounds[:MAX_REPAIRS]
    # a word of a name that the reader does not read alone: shared by several names ("white" of
    # white_case and white_keg: each offered), or a product's modifier ("oil" of oil-filter)
    index = lex.index
    named = index.shared_parts.get(normalize(low)) or index.loose_parts.get(normalize(low))
    if named:
        return (sounds + list(named))[:MAX_REPAIRS]
    vocabulary = ({k for k in lex.keywords if k.isalpha() and len(k) >= 2} | set(NUMBER_WORDS)
                  | {w for w in lex._name_words if w.isalpha()})
    near = []
    letters = set(low)
    for w in vocabulary:
        # each edit adds or removes at most two letters from the set of letters: a cheap test
        # first, the edit distance only for words that pass it
        if w == low or abs(len(w) - len(low)) > 2 or len(letters ^ set(w)) > 4:
            continue
        d = distance(low, w)
        if d == 1 or (d == 2 and len(low) >= 5 and w[0] == low[0]):
            near.append((d, w))
    found = [w for _, w in sorted(near)]
    # a word of a name said short ("mag" of magazine, "disp" of dispatch) or by another ending
    # ("hardbacks" for hardcover): a name word it starts, or one that shares its first four
    # letters and half the word; after the near misses, the longest shared start first
    shared = sorted((-len(commonprefix([low, w])), w) for w in lex._name_words if w.isalpha() and w not in found
                    and (w.startswith(low) or len(commonprefix([low, w])) >= max(4, len(low) // 2)))
    return (sounds + [w for w in found + [w for _, w in shared] if w not in sounds])[:MAX_REPAIRS]


def with_word(command: str, wrong: str, right: str) -> str | None:
    """``command`` with the word ``wrong`` (as a whole word, any case) written ``right``; None
    when the command does not contain it as written (it was respelt before it was read)."""
    pattern = re.compile(rf"(?<![\w-]){re.escape(wrong)}(?![\w-])", re.IGNORECASE)
    if not pattern.search(command):
        return None
    return pattern.sub(right, command)


def by_head_word(command: str, word: str, lex: Lexicon) -> list[tuple[str, str]]:
    """ "the big rack" where the world's one rack is high_rack, "the trade counter" where it is
    counter: an unknown word right before the last word of exactly one name (or the whole of a
    one-word name), as (the two words as written, that name's words). Only offered: "big" may
    name a rack the world does not have."""
    m = re.search(rf"(?<![\w-])({re.escape(word)})\s+([A-Za-z]+)(?![\w-])", command, re.IGNORECASE)
    if m is None:
        return []
    head = normalize(m.group(2))
    owners = [n.name for n in lex.index.names if re.split(r"[-_\s]+", n.name.lower())[-1] == head]
    if len(owners) != 1 or normalize(word) in re.split(r"[-_\s]+", owners[0].lower()):
        return []
    return [(m.group(0), re.sub(r"[-_]+", " ", owners[0]))]


def heard_counts(lex: Lexicon) -> list[tuple[str, str]]:
    """ "move for cases of litter", "and too crock pots": a word a recogniser writes for a count
    (:data:`HOMOPHONES`) right before what is counted (a product, after fillers), as (the
    words as written, the same with the number): offered, never read, wherever the grammar put
    the word ("too" may have read as "also")."""
    toks = lex.tokens
    out = []
    for k, t in enumerate(toks):
        if t.kind != "word" or str(t.value) not in HOMOPHONES or t.text.lower() not in HOMOPHONES:
            continue
        j = k + 1
        # unit words and "of" between ("for cases of litter"): what the grammar reads as nothing
        while j < len(toks) and toks[j].kind == "word" and (lex.terminal(toks[j]) is None or toks[j].value == "of"):
            j += 1
        if j < len(toks) and toks[j].kind == "name" and toks[j].of == "product":
            said = " ".join(x.text for x in toks[k:j + 1])
            out.append((said, " ".join([HOMOPHONES[t.text.lower()]] + [x.text for x in toks[k + 1:j + 1]])))
    return out


def with_phrase(command: str, wrong: str, right: str) -> str:
    """``command`` with the words ``wrong`` (as written) replaced by ``right``."""
    return command.replace(wrong, right)

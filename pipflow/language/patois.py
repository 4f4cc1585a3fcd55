"""Jamaican Creole (patois) function words, as typed in Jamaica and its diaspora ("put di sorrel
pon di table", "tek it outa di freezer", "di plate dem", "mi need fi pack it"): each read as the
English word the grammars have. Read only in a command that uses at least two of them
(:data:`MARKERS`) or one that is no English word (:data:`STRONG_MARKERS`), so a single "den" or
"dat" in English stays as typed, and only where the word is no name of the world's things alone."""
from __future__ import annotations

from typing import Callable, Mapping

#: patois word -> the English word(s); "mi", "dem", "fi", "him" depend on what follows (:func:`english_of`)
PATOIS = {"di": "the", "de": "the", "pon": "on", "inna": "in", "ina": "in", "eena": "in", "outa": "out of",
          "offa": "off", "den": "then", "dat": "that", "dis": "this", "tek": "take", "yuh": "you", "unu": "you",
          "nuh": "do not", "nah": "not", "cyaan": "can not", "caan": "can not", "ting": "thing", "tings": "things",
          "everyting": "everything", "anyting": "anything", "nutten": "nothing", "likkle": "little", "seh": "say",
          "wid": "with", "bout": "about", "cause": "because", "fimi": "for me",
          # verbs and words of chores ("tun off di TV", "lef it pon di counter", "mek sure", "outta di
          # fridge", "gi mi", "mi haffi go", "soh", "waan", "smaddy"; "dutty", dirty, is the household's)
          "tun": "turn", "lef": "leave", "mek": "make", "outta": "out of", "gi": "give",
          "haffi": "have to", "soh": "so", "waan": "want", "smaddy": "somebody", "wi": "we",
          # Guyanese Creole's own ("leh we move ...": let; "gotta"; "fuh" is "fi")
          "leh": "let", "gotta": "have to",
          # Bajan's own ("put it pun de table", "put dem een de fridge", "doan touch it", "wunna wash
          # dem": you all; "uh gine cook": I am going to; "ent": is not)
          "pun": "on", "een": "in", "doan": "do not", "wunna": "you", "gine": "going to", "ent": "is not"}
#: words that show a command is in patois: two different ones and the map applies
MARKERS = frozenset({"di", "pon", "inna", "dem", "fi", "mi", "nuh", "tek", "weh", "deh", "cyaan", "yuh", "dat",
                     "den", "outa", "tings", "ting", "unu", "tun", "lef", "mek", "outta", "dutty", "gi", "haffi",
                     "soh", "waan", "smaddy", "an", "de", "fuh", "wid", "wha", "leh", "pun", "een", "muh", "doan",
                     "wunna", "gine", "ent", "dey"})
#: markers that are no English word: one of them alone is enough ("put it back pon him study desk",
#: "tun off di TV", "mi want 40 X in P", "shift 6 of dem over")
STRONG_MARKERS = frozenset({"mi", "dem", "di", "pon", "inna", "cyaan", "outa", "tek", "yuh", "nuh", "fi", "unu", "weh",
                            "lef", "mek", "outta", "dutty", "haffi", "soh", "waan", "smaddy", "fuh", "pun", "een",
                            "muh", "doan", "wunna", "gine"})
#: every word the patois read may give an English word of its own
CREOLE_WORDS = frozenset(PATOIS) | MARKERS | {"wha", "ah", "weh", "deh", "got", "he", "she", "uh", "all", "out"}
#: words after "fi" that make it "for" (who or what for: "fi mi", "fi di children"); before
#: anything else "fi" is "to" ("mi need fi pack it")
FOR_WHOM = frozenset({"mi", "di", "de", "dem", "him", "yuh", "unu", "we", "she", "he", "dat", "dis", "me", "the",
                      "my", "her", "his", "them", "you"})

#: words that "dem" after them makes plural besides the world's ("di school tings dem", "di children dem")
_PLURAL_AFTER = frozenset({"things", "thing", "ones", "children", "pickney", "kids", "grandchildren", "clothes"})
#: words after which "mi" is "me" (an object: "bring mi", "fi mi", "pon mi")
_BEFORE_ME = frozenset({"for", "to", "on", "in", "with", "from", "bring", "give", "pass", "show", "tell", "help", "let",
                        "make", "get", "call", "wake", "of", "hear", "see"})
#: words after which a verb is an order ("an lef it", "please lef it"), not a report of what was done
_BEFORE_AN_ORDER = frozenset({"and", "then", "to", "please", "just", "so", "can", "could", "will", "would", "not", "do",
                              "dont"})   # never "you": "unu lef it open again" is what was done, no order
#: verbs of putting that may follow a serial "come" ("carry it come put it pon di counter")
_PUTTING = frozenset({"put", "lay", "set", "rest", "leave", "place"})
#: subjects after which "fi" before a verb is "should" ("yuh fi take 4 ...", "staging fi hold 5 ...");
#: after a verb of wanting or needing it is "to" ("mi need fi pack it")
_SUBJECTS = frozenset({"yuh", "you", "unu", "mi", "i", "we", "wi", "him", "he", "she", "dem", "they", "it"})
#: where a clause ends
_ENDS = frozenset({",", ".", ";", ":", "!", "?"})
#: words that open a clause, after which Bajan "uh" is I and "dey" they ("when uh come", "before dey spoil")
_CLAUSE_OPENERS = frozenset({"and", "but", "so", "when", "before", "after", "till", "until", "because", "cause",
                             "where", "while", "if", "since", "that"})
#: particles of a verb, after which "dem" is its object ("put dem back een de fridge"), even where a
#: thing's name holds the word ("back room light")
PARTICLES = frozenset({"back", "up", "down", "away", "out", "in", "off", "on", "over", "round", "inside"})
#: articles and demonstratives, after which Bajan "out" at the head of an order is "turn off"
_ARTICLES = frozenset({"de", "di", "the", "dat", "dis", "that", "this", "all"})

#: a stand-in for "dem" after a thing: its plural, no word of its own (the caller makes the thing plural)
PLURAL = ""
#: a stand-in for a word that is part of the English word read before it ("all two": both)
LEFT_OUT = "\x00"


def english_of(words: list[str], known: Callable[[str], bool], noun: Callable[[str], bool],
               domain: Mapping[str, str] | None = None) -> list[str | None]:
    """The English of each word of a command in Jamaican Creole (None: read as typed), in a command
    that uses two of :data:`MARKERS` or more, or one of :data:`STRONG_MARKERS`; never of a word that
    is a name of the world's things alone (``known``). "mi" is "my" before a word of a thing's name
    (``noun``), "me" after a verb or a preposition, else "I"; "him" is "his" before such a word;
    "dem" after a thing is its plural (:data:`PLURAL`: "di plate dem", the plates), "those" before
    one, "they" opening a clause, else "them"; "fi" is "for" before who or what for, "should" after a subject ("yuh fi take
    it", "staging fi hold 5"), else "to" ("mi need fi pack it"); "weh deh" is "that is", "weh"
    elsewhere "where"; "come" between a thing and a verb of putting ("bring mi specs come put pon di
    chair") is "and"; "nah" alone before a pause is "no" ("nah, mek it 8"). A "de" alone between
    a word that is no thing and a name ("to de counter", "cut de cement") is enough to read the
    command so: the Romance "de" follows a thing or a count ("the azeite de rack 1"). ``domain``:
    patois words of a domain's own ("dutty" of the home), read so too."""
    unknown = {w for w in words if not known(w)}
    out: list[str | None] = [None] * len(words)
    if len(MARKERS & unknown) < 2 and not STRONG_MARKERS & unknown and not _article_before_a_name(words, known, noun):
        return out
    for k, w in enumerate(words):
        if known(w):
            continue
        said_before = out[k - 1] if k and out[k - 1] else words[k - 1] if k else "."
        before = said_before.split()[-1]   # the word before, as read ("pon mi": on me)
        nxt = words[k + 1] if k + 1 < len(words) else "."
        if w in ("mi", "muh"):   # Jamaican "mi", Bajan "muh"
            said = "my" if noun(nxt) else "me" if k and before in _BEFORE_ME else "i"
        elif w in ("him", "he", "she"):   # "tek he school bag", "she macaroni pie", "fuh she": his, her
            objective = {"she": "her", "he": "him"}.get(w) if k and before in _BEFORE_ME else None
            said = objective if objective and (nxt in _ENDS or nxt in _CLAUSE_OPENERS) else \
                {"she": "her"}.get(w, "his") if noun(nxt) else objective
        elif w == "uh" and (not k or before in _ENDS or before in _CLAUSE_OPENERS) and nxt not in _ENDS:
            said = "i"   # Bajan "uh gine cook", "when uh come back": I
        elif w == "dey":   # Bajan "leave dem right dey": there; "dey is fuh Jamal", "before dey spoil": they
            said = "they" if not k or before in _ENDS or before in _CLAUSE_OPENERS else "there"
        elif w == "all" and nxt == "two" and (k + 2 >= len(words) or not words[k + 2][:1].isdigit()):
            said = "both"   # Bajan "wash all two o' dem": both (the "two" is left out below)
        elif w == "two" and before == "both":
            said = LEFT_OUT
        elif w == "out" and (not k or before in _ENDS or before in _BEFORE_AN_ORDER) and nxt in _ARTICLES:
            said = "turn off"   # Bajan "out de light": switch it off
        elif w == "nuh" and nxt in _ENDS and k and before not in _BEFORE_AN_ORDER:
            said = "please"   # "put dem back, nuh.": a tag that urges, no negation
        elif w == "dem" and k and before not in _BEFORE_ME and (noun(before) or before in _PLURAL_AFTER):
            said = PLURAL
        elif w == "dem":   # "dem painting de floor": they (a subject, opening its clause)
            said = "those" if noun(nxt) and nxt not in PARTICLES else "they" if not k or before in _ENDS else "them"
        elif w in ("fi", "fuh"):   # Jamaican "fi", Guyanese "fuh"
            said = "for" if nxt in FOR_WHOM or noun(nxt) else \
                "should" if k and (before in _SUBJECTS or noun(before)) and nxt not in _ENDS else "to"
        elif w == "wha":   # "robots wha could carry 4": that; "wha deh deh": what is there
            said = "that" if k and noun(before) or before in _PLURAL_AFTER or before == "robots" else "what"
        elif w in ("we", "wi") and before == "let":   # "leh we move ...": let us
            said = "us"
        elif w == "nah" and nxt in _ENDS:   # "nah, mek it 8": no
            said = "no"
        elif w == "nah" and (not k or before in _ENDS or before in _BEFORE_AN_ORDER or before == "but"):
            said = "do not"   # "but nah use Tanty": an order not to; "de floor nah so strong": not
        elif w == "ah" and nxt == "dem":   # "all 14 ah dem": of them
            said = "of"
        elif w == "got" and _after_a_modal(out, words, k):   # "must always got at least 10": have
            said = "have"
        elif w == "weh" and nxt == "deh":
            said = "that"
        elif w == "weh":   # "put it back weh it belong": where
            said = "where"
        elif w == "belong" and before == "it":   # no "-s" in the third person
            said = "belongs"
        elif w == "lef":   # "lef it pon di counter": leave; "di pickney dem lef dem toys": left
            said = "leave" if not k or before in _ENDS or before in _BEFORE_AN_ORDER else "left"
        elif w == "deh":
            said = "is" if before == "that" else "there"
        elif w == "come" and nxt in _PUTTING and k and before not in _ENDS:
            said = "and"
        elif w == "an" and nxt not in _ENDS and nxt[:1] not in "aeiou":
            said = "and"
        else:
            said = PATOIS.get(w) or (domain or {}).get(w)
        out[k] = said
    return out


def _article_before_a_name(words: list[str], known: Callable[[str], bool], noun: Callable[[str], bool]) -> bool:
    """Whether "de" stands before a name of the world's things (or a word of one: "out de kitchen
    light") after a word that is no thing and no count ("send 6 to de counter"): the Creole
    article, not the Romance "of"."""
    return any(w == "de" and k + 1 < len(words) and (known(words[k + 1]) or noun(words[k + 1]))
               and (not k or not noun(words[k - 1]) and not known(words[k - 1]) and not words[k - 1][:1].isdigit())
               for k, w in enumerate(words))


#: words after which "got" is "have" ("de counter must got 10 box", "fuh got"), an adverb between
_MODALS = frozenset({"must", "should", "to", "can", "will", "would", "could"})


def _after_a_modal(out: list[str | None], words: list[str], k: int) -> bool:
    """Whether the word at ``k`` follows a modal as read so far (one adverb between:
    "must always got")."""
    said = [(o or w).split()[-1] for o, w in zip(out[:k], words[:k]) if (o or w)]
    return bool(said) and (said[-1] in _MODALS or len(said) > 1 and said[-1] in ("always", "still", "never")
                           and said[-2] in _MODALS)

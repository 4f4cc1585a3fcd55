"""Tagging (step 1 of :mod:`pipflow.household.language.parser`): a command's words become the
grammar's tokens: the world's names (longest match, with plurals, typo-tolerant: "fridgge" reads as
"fridge" and a note says so), numbers, and the closed lexicon of
:mod:`pipflow.household.language.lexicon`. A word in neither is a :class:`TranslationError` that
quotes it: nothing is skipped silently (politeness words such as "please" carry no content and are
listed in the lexicon)."""
from __future__ import annotations

import contextlib
import re
from contextvars import ContextVar
from typing import Iterator

from pipflow.errors import TranslationError
from pipflow.language.asides import FUNCTION_WORDS
from pipflow.language.english import common_word
from pipflow.household.language.beside import beside_as_where
from pipflow.household.language.colloquial import colloquial
from pipflow.household.language.comings import just_come_in, someone_blamed
from pipflow.household.language.corrections import corrected, orders_taken_back
from pipflow.household.language.dialect import (arabic_as_english, bring_in, cut_as_switch, do_as_wash, how_particles,
                                                make_as_switch, room_of_a_switched_thing,
                                                newfoundland_as_english, on_off_as_verbs, open_close_as_switch,
                                                particle_before_exception, patois_in_home, pidgin_in_home,
                                                put_on_as_switch, romance_words_as_english, scots_as_english,
                                                setting_as_switch, them_as_those)
from pipflow.household.language.headwords import named_again
from pipflow.household.language.grammar import NOUN_DUAL
from pipflow.household.language.lexicon import FILLER, PHRASES, words_of
from pipflow.household.language.names import (doers, first_words, longest_name, named_by_first_word, per_index,
                                              things_of_kind, world_phrases)
from pipflow.household.language.people import KIN, owners, owners_before_names, own_as_owned, pronouns_as_owners
from pipflow.household.language.retag import (act_before_noun, copula_dropped, demonstratives, elided_it_is, left_lying,
                                              located, restated_order, without_hedges)
from pipflow.household.language.rewrites import (back_before_a_destination, caused, closed_again, closed_back, given, heat_purpose,
                                                 covered_in, instead_closing, measures, spoiling_as_reason, or_under_negation, particles, same_for,
                                                 so_before_an_order, still_as_a_report, warm_the_place, wherever_they_belong,
                                                 without_manner, you_before_an_order)
from pipflow.household.language.narrowed import just_as_only, narrowed_by_only
from pipflow.household.language.ones import one_as_kind
from pipflow.household.language.romance import adjective_after, of_as_where
from pipflow.household.language.roomnames import rooms_things_come_from, where_as_name
from pipflow.household.language.tokens import PUNCT, Tag
from pipflow.household.language.typos import (determiner_slip, known_word, meaning_of, transposition_of, typo_of,
                                              vocabulary)
from pipflow.household.language.whereabouts import me_as_where_the_speaker_is
from pipflow.language.numbers import read_number


#: lexicon classes of phrases that name the home or a room of it ("in the kitchen", "all over the
#: flat"): a world name inside one is read as the name
HOME_CLASSES = {"HERE", "ALLOVER", "INROOM", "THEWASH", "ROOMSAID"}


def _match(words: list[str], i: int, table: dict, longest: int) -> int:
    for n in range(min(longest, len(words) - i), 0, -1):
        if tuple(words[i:i + n]) in table:
            return n
    return 0


def repaired(words: list[str], index: dict, vocab: set[str], notes: list[str], world: dict) -> list[str]:
    """The words with their typos read: a word known nowhere that is two neighbouring letters of
    exactly one grammar word swapped ("adn"), or close to exactly one known word ("fridgge"), is
    read as that word (a note says so); two competing repairs: left as typed (refused, offered). A
    word that names a kind of thing of this home ("heater", :func:`things_of_kind`) is no typo."""
    words = list(words)
    firsts = first_words(index)
    for k, w in enumerate(words):
        if known_word(w, index, vocab) or len(w) < 3 or not w.isalpha() or things_of_kind(world, w)[0]:
            continue
        slip = determiner_slip(w, k + 1 < len(words) and words[k + 1] in firsts)
        if slip is not None:   # "wash teh wine glass": only a determiner fits before a name
            notes.append(f"read {w!r} as {slip!r} (a determiner before a name)")
            words[k] = slip
            continue
        swapped = transposition_of(w)
        if len(swapped) == 1 and set(typo_of(w, vocab)) <= set(swapped):
            notes.append(f"read {w!r} as {swapped[0]!r} (two letters swapped)")
            words[k] = swapped[0]
            continue
        if len(w) < 4:
            continue
        close = typo_of(w, vocab)
        if common_word(w) and k and words[k - 1] == "to":
            continue   # "leave the pan in the sink to drip": an English verb as written, no slip of "drop"
        if close and common_word(w) and any(c in key and c not in (w + "s", w + "es") for c in close for key in index):
            continue   # a common English word as written ("ripe") is no slip of a thing's name ("rice"), only its plural
        if close and len({meaning_of(c, index) for c in close}) == 1:
            notes.append(f"read {w!r} as {close[0]!r}")
            words[k] = close[0]
    return words


@per_index
def _first_words_of_long_names(index: dict) -> frozenset[str]:
    """The first words of the home's names of two or more words ("jordan" of jordan's desk)."""
    return frozenset(key[0] for key in index if len(key) > 1)


def owners_as_the(command: str, world: dict, notes: list[str]) -> str:
    """A person's name said as whose a thing is ("Rosie's sippy cup", "put Alfie's wellies
    away"): a capitalised word with "'s" before the first word of a thing of the home, that is no
    word of this home or of the reader, stands as "the": which thing is meant is the home's one
    such thing, or it is asked.
    The home does not know who owns what, so the owner picks nothing out. Typed in lower case
    ("jordan's mug"; speech to text writes no capitals), the name is an owner where the home's
    own names use it ("jordan's desk"), or where it is no English word and no word of this home
    or of the reader, nor a slip of one ("xander's cars"), or a word of kin ("my husband's shirt",
    :data:`~.people.KIN`): "the dog's bowl" says no owner."""
    index = world_phrases(world)
    owners = _first_words_of_long_names(index)
    vocab = vocabulary(index)

    def unknown(word: str) -> bool:   # no English word, no word of this home or of the reader
        return not (common_word(word) or known_word(word, index, vocab) or typo_of(word, vocab))

    def owner(m: re.Match) -> str:
        word, after = m.group(1).lower(), m.group(2).lower()
        if m.group(1)[0].islower() and word not in owners and word not in KIN and not unknown(word):
            return m.group(0)
        if word in FUNCTION_WORDS or (word,) in PHRASES or any(key[:2] == (word, after) for key in index) or (
                (word,) in index and not any(len(key) > 1 and key[0] == word for key in index)) \
                or not any(key[0] == after for key in index):
            # "It's", a word of the reader, a name of the home said so ("Rosie's cup"), or no thing
            # of the home after it ("Someone's left ...": "has")
            return m.group(0)
        notes.append(f"'{m.group(1)}'s' says whose it is: read as 'the'")
        return _OWNED + m.group(2)
    command = re.sub(r"(?<![\w'’])([A-Za-z][a-z]+)['’]s\s+([A-Za-z]+)", owner, command)
    # the apostrophe unwritten ("johans beers", speech to text): only where neither the word nor
    # the word without its "s" is known
    command = re.sub(r"(?<![\w'’])([A-Za-z][a-z]+)s\s+([A-Za-z]+)",
                     lambda m: owner(m) if unknown(m.group(1).lower() + "s") else m.group(0), command)
    # "my husband's shirt", Geordie "wor lass's mug": the determiner before the owner goes with it
    # ("the arl fella's bevvies": old, in Scouse; "me old dad's chair")
    command = re.sub(r"\b(?:my|our|wor|your|his|her|their|the)\s+(?:(?:old|arl|auld|owd)\s+)?" + _OWNED, _OWNED, command,
                     flags=re.IGNORECASE)
    return command.replace(_OWNED, "the ")


#: what an owner said with "'s" stands as, until the determiner before it is dropped
_OWNED = "\0the "


def _rewritten(command: str, world: dict, index: dict, vocab: set[str], notes: list[str]) -> list[str]:
    """The command's words with its colloquial forms, constructions and particles read as the
    grammar's words (each rewrite notes what it read)."""
    words = pidgin_in_home(patois_in_home(words_of(command), index, notes), index, notes)
    words = still_as_a_report(newfoundland_as_english(words, index, notes), notes)

    def known(word: str) -> bool:   # a word of the home or of the reader
        return known_word(word, index, vocab)

    words = arabic_as_english(words, lambda w: (w,) in index, notes)   # a name alone keeps its meaning
    words = romance_words_as_english(scots_as_english(words, known, notes), known, notes)
    words = of_as_where(adjective_after(words, index, notes), world, index, notes)
    words = rooms_things_come_from(where_as_name(one_as_kind(words, world, index, notes), index, notes,
                                                 owners(world, words)), index, notes)
    words = owners_before_names(pronouns_as_owners(own_as_owned(words, world, notes), world, notes), world, notes)
    words = so_before_an_order(same_for(colloquial(corrected(orders_taken_back(words, index, notes), notes), notes),
                                        notes), notes)
    words = back_before_a_destination(you_before_an_order(words, notes, index), notes)
    words = or_under_negation(measures(without_manner(words, notes), index, notes), notes)
    words = heat_purpose(caused(given(me_as_where_the_speaker_is(words, index, notes), notes), notes), notes)
    words = just_as_only(spoiling_as_reason(warm_the_place(instead_closing(words, notes), notes), notes), notes)
    words = narrowed_by_only(covered_in(words, index, notes), world, index, notes)
    words = someone_blamed(just_come_in(words, index, notes), index, notes)
    words = closed_back(closed_again(wherever_they_belong(words, notes), notes), notes)
    words = room_of_a_switched_thing(words, index, notes)
    words = make_as_switch(cut_as_switch(do_as_wash(words, world, index, notes), world, index, notes), world, index, notes)
    words = how_particles(words, world, index, notes)
    words = on_off_as_verbs(put_on_as_switch(setting_as_switch(words, world, index, notes), world, index, notes),
                            world, index, notes)
    words = bring_in(open_close_as_switch(particle_before_exception(words, notes), world, index, notes), index, notes)
    words = beside_as_where(named_again(them_as_those(words, index, notes), index, notes), world, index, notes)
    return particles(words, lambda x: x.isalpha() and not known_word(x, index, vocab), notes, doers(world))


#: the most words a phrase and a filler of the lexicon have
_LONGEST_PHRASE = max(len(k) for k in PHRASES)
_LONGEST_FILLER = max(len(k) for k in FILLER)


#: (the world, wording -> (its tags, what tagging it noted, its refusal)) while one command is read
_KEPT: ContextVar[tuple[dict, dict[str, tuple[list[Tag] | None, list[str], TranslationError | None]]] | None] = \
    ContextVar("household_tags_kept", default=None)


@contextlib.contextmanager
def tags_kept(world: dict) -> Iterator[None]:
    """While one command is read, each wording of it is tagged once: the parser tags a wording
    with and without its asides and people, and the candidate search comes back to wordings it
    has tagged (over people-heavy household sets a fifth of the tagging repeated one done before)."""
    token = _KEPT.set((world, {}))
    try:
        yield
    finally:
        _KEPT.reset(token)


def tag(command: str, world: dict, notes: list[str] | None = None) -> list[Tag]:
    """The command as grammar tokens (module docstring, step 1); inside :func:`tags_kept`, a
    wording tagged before answers as it did then (its notes said again, its refusal raised anew)."""
    notes = notes if notes is not None else []
    kept = _KEPT.get()
    if kept is None or kept[0] is not world:
        return _tag(command, world, notes)
    if command not in kept[1]:
        said: list[str] = []
        try:
            kept[1][command] = (_tag(command, world, said), said, None)
        except TranslationError as exc:
            kept[1][command] = (None, said, exc)
    tags, said, refusal = kept[1][command]
    notes.extend(said)
    if refusal is not None:
        raise _anew(refusal)
    return list(tags or [])


def _anew(refusal: TranslationError) -> TranslationError:
    """A kept refusal as a new one, with a dictionary and lists of its own: a reader may add to a
    refusal (its candidates, its rewording). Not :func:`copy.copy`: with ``distributed`` imported,
    tblib registers a reducer for every exception class, and its copies share one ``__dict__``."""
    again = type(refusal).__new__(type(refusal), *refusal.args)
    again.args = refusal.args
    again.__dict__.update({k: list(v) if isinstance(v, list) else v for k, v in vars(refusal).items()})
    return again


def _tag(command: str, world: dict, notes: list[str]) -> list[Tag]:
    """:func:`tag`, done."""
    index = world_phrases(world)
    vocab = vocabulary(index)
    words = _rewritten(command, world, index, vocab, notes)
    said = list(words)   # as typed: a repair that still names nothing is quoted as typed
    words = repaired(words, index, vocab, notes, world)
    longest_w = longest_name(index)
    out: list[Tag] = []
    unknown: list[str] = []
    shared: dict[str, list[str]] = {}   # a word that is the first word of several things' names
    countable = [x if x not in PUNCT and x.isalnum() else None for x in words]   # a count runs across neither
    i = 0
    while i < len(words):
        w = words[i]
        if w in PUNCT:
            out.append(Tag(PUNCT[w], w, w))
            i += 1
            continue
        if w[0] == "-" or not w.isalnum():   # "-2", "3.5": no count of things; refused, never read as 2
            unknown.append(w)
            i += 1
            continue
        num = read_number(countable, i)
        nw, nl, nf = _match(words, i, index, longest_w), _match(words, i, PHRASES, _LONGEST_PHRASE), \
            _match(words, i, FILLER, _LONGEST_FILLER)
        if nl > 1 and PHRASES[tuple(words[i:i + nl])][0] in HOME_CLASSES and \
                any(_match(words, j, index, longest_w) for j in range(i + 1, i + nl)):
            nl = 1 if (w,) in PHRASES else 0   # "in the kitchen" where the home has a thing named kitchen
        if nw > 1 and (w,) in PHRASES and 1 + _match(words, i + 1, index, longest_w) > nw:
            # "the side table" where "the side" names the worktop: the name that covers more words
            nw = 0
        if num is not None and num[1] - i >= max(nw, nl, nf):
            out.append(Tag("NUM", num[0], " ".join(words[i:num[1]])))
            i = num[1]
            continue
        if nf and nf > max(nw, nl):
            i += nf
            continue
        if nw == 0 and nl == 0:
            kind, plural = things_of_kind(world, w) if w.isalpha() and len(w) >= 3 else ([], False)
            if kind:   # "open a window" where the window is the skylight: the things of that kind
                notes.append(f"read {w!r} as {', '.join(kind)} (of its kind)")
                out.append(Tag("NOUN", None, w, [{"kind": "object" if n in (world.get("objects") or {}) else "place",
                                                   "name": n, "plural": plural} for n in kind]))
                i += 1
                continue
            whole = named_by_first_word(world, w) if w.isalpha() and len(w) >= 3 else []
            if len(whole) == 1:   # "my crossword" of crossword_book: the one thing it is the form of
                notes.append(f"read {w!r} as {whole[0]} (the first word of its name)")
                out.append(Tag("NOUN", None, w, [{"kind": "object" if whole[0] in (world.get("objects") or {})
                                                  else "place", "name": whole[0], "plural": False}]))
            else:
                unknown.append(said[i])
                shared.update({said[i]: whole} if whole else {})
            i += 1
            continue
        n = max(nw, nl)
        text = " ".join(words[i:i + n])
        if nw == n and nl == n:
            cls, value = PHRASES[tuple(words[i:i + n])]
            out.append(Tag(cls + NOUN_DUAL, value, text, index[tuple(words[i:i + n])]))
        elif nw == n:
            out.append(Tag("NOUN", None, text, index[tuple(words[i:i + n])]))
        else:
            cls, value = PHRASES[tuple(words[i:i + n])]
            out.append(Tag(cls, value, text))
        i += n
    out = elided_it_is(copula_dropped(left_lying(without_hedges(out, notes)), notes), notes)
    out = restated_order(located(demonstratives(act_before_noun(out)), world, notes), notes)
    if unknown:
        raise _unplaced(command, world, unknown, shared)
    return out


def _unplaced(command: str, world: dict, unknown: list[str], shared: dict[str, list[str]]) -> TranslationError:
    """The refusal of a command with words the reader could not place: quoting them, listing the
    world's things, and saying which things a word is part of the names of; the words are kept
    (``unread``) for the candidate readings."""
    names = sorted(set(world.get("objects") or {}) | set(world.get("places") or {}))
    error = TranslationError(
        f"{', '.join(repr(u) for u in dict.fromkeys(unknown))} names nothing in this world and is no word the "
        f"offline parser knows (in {command.strip()!r}); things of this world: {', '.join(names)}"
        + "".join(f"; '{w}' is part of the names of {', '.join(ns)}: say which" for w, ns in shared.items()))
    error.unread = list(dict.fromkeys(unknown))  # type: ignore[attr-defined]  # for candidate readings
    return error

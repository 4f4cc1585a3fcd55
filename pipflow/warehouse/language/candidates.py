"""Candidate readings of a refused command (issue 23: ask rather than refuse): the competing
readings of an ambiguous sentence, near-miss respellings of a word no rule places, and partial
parses; each the whole command read with one choice and resolved. Offered, never acted on."""
from __future__ import annotations

import functools
from typing import Callable

from pipflow.errors import PipflowError, TranslationError
from pipflow.language.asides import said
from pipflow.warehouse.language.command import lexed_command, parse_reading
from pipflow.warehouse.language.forest import CANDIDATE_BUDGET, CANDIDATE_PARSES
from pipflow.warehouse.language.goals import Choice
from pipflow.warehouse.language.readings import MAX_CANDIDATES, canonical
from pipflow.warehouse.language.repairs import by_head_word, heard_counts, near_words, with_phrase, with_word
from pipflow.warehouse.language.resolver import resolve
from pipflow.warehouse.language.runon import RunOnChoice
from pipflow.warehouse.language.salvage import SALVAGE

def candidates(command: str, world: dict, exc: TranslationError) -> list[dict]:
    """Up to :data:`MAX_CANDIDATES` readings to offer for a command refused as not understood or
    ambiguous (issue 23: ask rather than refuse), each ``{"reading", "words", "goal",
    "constraints", "order"}``: the competing readings of an ambiguous sentence, and for a word no
    rule places, the sentence without that word, without its clause, without the words that open
    its clause, and (in a command of several sentences) without the sentence. Each is the whole
    command read with that one choice and resolved against the world; readings that do not
    resolve, or repeat another's meaning, are not offered. Nothing here is acted on: a user (or
    the bench) chooses."""
    sentence = getattr(exc, "sentence", None)
    if isinstance(exc, RunOnChoice):
        picks: list[dict] = [{"*": {"stops": stops}} for stops in exc.stops]
    elif sentence is None:
        picks = []
    elif isinstance(exc, Choice):
        picks = [{sentence: {exc.key: option}} for option in exc.options]
    else:
        picks = []  # a word no rule places: the partial parses below leave it (or its clause) out first
    if getattr(exc, "trimmed", False):
        picks = [{k: {**p, "trimmed": True} for k, p in pick.items()} for pick in picks]
    # partial parses: in every sentence, the words no rule places (or their clauses) left out one
    # after another, the clauses that do parse kept, the words left out named
    picks += [{"*": {"salvage": how}} for how in SALVAGE]
    out: list[dict] = []
    seen: set[str] = set()
    CANDIDATE_BUDGET["left"] = CANDIDATE_PARSES
    word = getattr(exc, "word", None)
    lexed = lexed_command(command, world)[0] if word else None
    # a count a recogniser wrote as a word, before what is counted ("too crock pots"); a word no
    # rule places may be a near miss of a word that has a place: the command read with it
    # respelt, once for each near word, the repair said in the echo; and an unknown word before
    # the last word of one name ("the big rack": high_rack)
    repaired = [(with_phrase(command, wrong, right), f"read '{wrong}' as '{right}'")
                for wrong, right in (heard_counts(lexed) if word else []) if wrong in command]
    repaired += [(text, f"read '{word}' as '{right}'") for right in (near_words(word, lexed) if word else [])
                 for text in [with_word(command, word, right)] if text is not None]
    repaired += [(with_phrase(command, wrong, right), f"read '{wrong}' as '{right}'")
                 for wrong, right in (by_head_word(command, word, lexed) if word else [])]
    salvages = picks[-len(SALVAGE):]
    # the readings to try, in order; the first three that resolve to different meanings are
    # offered, so the search stops there (what it would find later is never offered)
    tries: list[Callable[[], None]] = [
        *(functools.partial(candidate, command, world, pick, out, seen) for pick in picks[:-len(SALVAGE)]),
        *(functools.partial(with_choices, text, world, {}, out, seen, note=note) for text, note in repaired),
        *(functools.partial(with_choices, command, world, pick, out, seen) for pick in salvages),
        # a repair that leaves another word in the way: the repaired command's partial parses
        *(functools.partial(with_choices, text, world, pick, out, seen, note=note)
          for text, note in repaired for pick in salvages),
    ]
    try:
        for attempt in tries:
            if len(out) >= MAX_CANDIDATES:
                break
            attempt()
    finally:
        CANDIDATE_BUDGET["left"] = None
    return out[:MAX_CANDIDATES]


def with_choices(command: str, world: dict, pick: dict, out: list[dict], seen: set[str], note: str = "") -> None:
    """:func:`_candidate`, and where that reading stops at a sentence with competing readings (a
    :class:`Choice`: "put 3" in all or more?), the reading once with each of them."""
    error = candidate(command, world, pick, out, seen, note)
    sentence = getattr(error, "sentence", None)
    if isinstance(error, Choice) and sentence is not None and error.key not in (pick.get(sentence) or {}):
        for option in error.options:
            if len(out) >= MAX_CANDIDATES:
                return
            candidate(command, world, {**pick, sentence: {**(pick.get(sentence) or {}), error.key: option}},
                       out, seen, note)


def candidate(command: str, world: dict, pick: dict, out: list[dict], seen: set[str],
               note: str = "") -> PipflowError | None:
    """The command read with one pick, resolved, added to ``out`` unless it fails (the error is
    returned) or repeats a meaning already offered; ``note`` (a repair made to the command) is
    said in its echo."""
    try:
        order = parse_reading(command, world, pick)
        got = resolve(order, world)
    except PipflowError as exc:
        return exc
    meaning = canonical(got.goal, got.constraints)
    if meaning in seen:
        return
    seen.add(meaning)
    unread = order.get("unread") or []
    aside = order.get("set_aside") or []
    explanation = (([note] if note else []) + list(got.explanation)
                   + ([f"not read: {', '.join(repr(w) for w in unread)}"] if unread else [])
                   + ([said(aside)] if aside else []))
    out.append({"reading": "; ".join(explanation), "explanation": explanation,
                "goal": got.goal, "constraints": got.constraints, "unread": unread,
                "words": "; ".join(x["words"] for x in order["statements"] + order["rules"]), "order": order})

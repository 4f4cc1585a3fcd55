"""The offline parser: a command and a world in, an order (:mod:`pipflow.warehouse.language.order`) out.

Each sentence is parsed with lark's Earley parser over the grammar of
:mod:`pipflow.warehouse.language.grammar` and read into statements and robot rules; what is
resolved here and what is left to the resolver is said in :mod:`sentence`. A word the grammar
cannot place is a :class:`TranslationError` that quotes it.

The command is read in modules of one job each: :mod:`forest` (Earley over a sentence's
terminals), :mod:`sentence` (a tree read into statements, with :mod:`goals`, :mod:`tails` and
:mod:`rulescope`), :mod:`readings` (a sentence's readings compared), :mod:`command` (a command's
sentences, one reading of its line breaks), :mod:`salvage` and :mod:`candidates` (what a refusal
offers). This module is the face: :func:`parse`.
"""
from __future__ import annotations

import re

from pipflow.errors import Refusal, TranslationError
from pipflow.language.characters import line_readings
from pipflow.language.listing import inline_numbering
from pipflow.language.mail import without_mail_form
from pipflow.warehouse.language.candidates import candidates
from pipflow.warehouse.language.command import parse_reading
from pipflow.warehouse.language.forest import keywords
from pipflow.warehouse.language.goals import Asked, Choice
from pipflow.warehouse.language.readings import canonical, meaning_of
from pipflow.warehouse.language.runon import RunOnChoice, with_stops

__all__ = ["parse", "candidates", "canonical", "keywords"]


def parse(command: str, world: dict) -> dict:
    """The order of a command: ``{"statements": [...], "rules": [...], "command": command}``.

    Raises :class:`TranslationError` quoting the words it cannot place (or a character it does
    not read: :mod:`pipflow.language.characters`), :class:`InputError` for a command too long to
    be one, and :class:`Refusal` for counts that cannot exist (negative).

    A line break ends a sentence; a command whose lines only make sense joined (a sentence
    wrapped onto the next line) is read joined, and one that makes sense both ways with two
    different meanings (or one way with several of its own: a sentence asked) is refused, quoting
    both (:func:`pipflow.language.characters.line_readings`). A sentence no rule reads may be
    several said without stops: read again with stops put in (:mod:`runon`), else refused with
    candidate readings (:mod:`candidates`). An e-mail's subject line (when it asks for nothing) and
    list markers are its form: left out first, the subject said as set aside (:mod:`pipflow.language.mail`).
    """
    # "Today's plan: 1) ... 2) ...": each number opens a job (before a line's own list marker is read)
    text, headed = without_mail_form(inline_numbering(command), _name_words(world))
    order = _parse(text, world)
    if headed:
        order["set_aside"] = headed + list(order.get("set_aside") or [])
    return {**order, "command": command}


def _name_words(world: dict) -> frozenset[str]:
    """The words of the world's place, product and robot names, robot kinds and tags, in lower case."""
    robots = (world.get("robots") or {}).values()
    names = [str(n) for key in ("shelves", "products", "robots") for n in world.get(key) or {}]
    names += [str(r.get("kind") or "") for r in robots] + [str(t) for r in robots for t in r.get("tags") or []]
    return frozenset(w for n in names for w in re.split(r"[^a-z0-9]+", n.lower()) if w)


def _parse(command: str, world: dict) -> dict:
    """:func:`parse` of a command without its mail form."""
    readings = line_readings(command)
    if len(readings) == 1:
        try:
            return {**parse_reading(readings[0], world), "command": command}
        except TranslationError as exc:
            try:
                read = with_stops(readings[0], world, exc)   # only a sentence no rule reads
            except RunOnChoice as either:
                exc, read = either, None
            if read is not None:
                return {**read, "command": command}
            exc.candidates = candidates(readings[0], world, exc)
            if exc.candidates:
                exc.args = (f"{exc.args[0]}. Did you mean: " + "; or ".join(
                    f"({k}) {c['reading']} [from '{c['words']}']" for k, c in enumerate(exc.candidates, 1))
                    + "? Say it so, or choose one",)
            raise exc from None
    broken, joined = readings
    try:
        first = parse_reading(broken, world)
    except (TranslationError, Refusal) as exc:
        try:
            second = parse_reading(joined, world)
        except (TranslationError, Refusal):
            raise exc from None
        if isinstance(exc, (Choice, Asked)):   # read as sentences it has meanings of its own: asked there
            raise _either_way(broken, f"{exc.args[0]}", _words(second)) from None
        return {**second, "command": command}
    try:
        second = parse_reading(joined, world)
    except Choice as exc:
        raise _either_way(broken, _words(first), f"{exc.args[0]}") from None
    except (TranslationError, Refusal):
        return {**first, "command": command}
    a, b = meaning_of(first, world), meaning_of(second, world)
    if b is not None and a != b:
        if a is None:
            return {**second, "command": command}
        raise _either_way(broken, _words(first), _words(second))
    return {**first, "command": command}


def _words(order: dict) -> str:
    return "; ".join(s["words"] for s in order["statements"] + order["rules"])


def _either_way(broken: str, as_sentences: str, joined: str) -> TranslationError:
    """A command whose line breaks may end sentences or continue them, read with different
    meanings (or, one way, with several of its own): nothing is guessed."""
    return TranslationError(f"the line breaks of '{broken}' can end sentences ('{as_sentences}') or continue "
                            f"them ('{joined}'), and the two readings ask for different things; nothing is "
                            f"guessed: end each sentence with a full stop")

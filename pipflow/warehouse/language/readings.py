"""A sentence's readings: every tree of its forest read (:mod:`sentence`), the meanings
compared in one form (:func:`canonical`), and the one meaning kept, or the sentence refused as
read two ways (a :class:`Choice` offering each)."""
from __future__ import annotations

import json

from lark import Tree
from lark.visitors import CollapseAmbiguities

from pipflow.errors import PipflowError, TranslationError
from pipflow.warehouse.language.forest import forest
from pipflow.warehouse.language.goals import Asked, Choice
from pipflow.warehouse.language.lexicon import Lexed, Lexicon
from pipflow.warehouse.language.resolver import resolve
from pipflow.warehouse.language.robots import RobotSelector
from pipflow.warehouse.language.sentence import SentenceReader


def read_tree(tree: Tree, lexed: Lexed, lex: Lexicon, selector: RobotSelector, memory: dict,
          picks: dict | None = None) -> SentenceReader:
    reader = SentenceReader(lexed, lex, selector, memory, picks)
    if tree.children[0].data == "topic_sentence":   # "Back shed." (a place said alone)
        reader.g_topic(tree.children[0])
        reader.finish()
        return reader
    for part in tree.children[0].children:
        if isinstance(part, Tree) and part.data not in ("sep", "lead"):
            reader.part(part)
    reader.finish()
    return reader


#: readings of one sentence compared at most; beyond, the sentence is refused as too ambiguous
MAX_READINGS = 64
#: readings offered at most when a command is refused (issue 23: ask rather than refuse)
MAX_CANDIDATES = 3


def canonical(goal: dict, constraints: list[dict]) -> str:
    """A meaning in one form, so that two readings that ask for the same thing compare equal: the
    goal's places and items in sorted order; the rules as a set (a conjunction: order and
    repetition do not matter), robot lists as sets, a ``never`` rule one rule per robot (never
    [a, b] forbids what never [a] and never [b] forbid), and a rule's source words left out.
    Two readings that are the same rule said twice are one reading, never "two ways"."""
    rules: set[str] = set()
    for rule in constraints:
        scope = {k: v for k, v in rule.items() if k not in ("only", "never", "words")}
        if "never" in rule:
            rules |= {json.dumps({**scope, "never": r}, sort_keys=True, default=str) for r in rule["never"]}
        else:
            rules.add(json.dumps({**scope, "only": sorted(rule.get("only") or [])}, sort_keys=True, default=str))
    return json.dumps([goal, sorted(rules)], sort_keys=True, default=str)


def meaning(reader: SentenceReader, world: dict) -> str | None:
    """What a reading asks for, for comparison: its resolved goal and rules in one form
    (:func:`canonical`; None when the reading does not resolve on its own: it is then no
    meaning to compare)."""
    try:
        r = resolve({"statements": reader.statements, "rules": reader.rules}, world, check=False)
    except PipflowError:
        return None
    return canonical(r.goal, r.constraints)


def parts(tree: Tree) -> int:
    return sum(1 for p in tree.children[0].children if isinstance(p, Tree) and p.data not in ("sep", "lead"))


#: parse forests of recent sentences, by their terminals (the grammar is the same in every world,
#: and a sentence's terminals are all the parse sees): a candidate reading re-reads the sentences

def one_meaning(lexed: Lexed, lex: Lexicon, selector: RobotSelector, world: dict, memory: dict,
                 picks: dict | None = None) -> SentenceReader:
    """Read a sentence in every way the grammar allows, and keep its meaning only if there is one.

    Readings that make no sense (an error, or nothing that resolves) are not meanings; a reading
    that is itself asked (:class:`Asked`: "1 more or 1 in all?") is the sentence's question. Of the
    rest, all must ask for the same goal and rules, or the sentence is refused with two of
    them: the grammar's preferences never choose between meanings silently. The reading kept
    is the one with the fewest, longest parts.
    """
    picks = picks or {}
    tree = forest(lexed.tokens)
    if not any(t.data == "_ambig" for t in tree.iter_subtrees()):
        return read_tree(tree, lexed, lex, selector, memory, picks)
    sentence = " ".join(t.text for t in lexed.source if t.text).replace(" zzposs", "'s")
    readings: list[tuple[int, SentenceReader, str | None]] = []
    errors: list[tuple[int, PipflowError]] = []
    for k, alt in enumerate(CollapseAmbiguities().transform(tree)):
        if k >= MAX_READINGS:
            raise TranslationError(f"'{sentence}' can be read in too many ways to be sure of one; "
                                   f"say it in shorter sentences")
        try:
            reader = read_tree(alt, lexed, lex, selector, memory, picks)
        except Asked:
            raise   # a reading with two meanings of its own: the other readings must not win unasked
        except Choice as exc:
            if exc.key != "place_it":
                errors.append((parts(alt), exc))
                continue
            # a pronoun that could mean several places is a meaning not yet settled, not a reading
            # that makes no sense: each place it could mean is a reading of its own, so another
            # reading of the sentence ("out of it": the job) does not win over it unasked
            for option in exc.options:
                try:
                    reader = read_tree(alt, lexed, lex, selector, memory, {**picks, "place_it": option})
                except PipflowError as again:
                    errors.append((parts(alt), again))
                    continue
                readings.append((parts(alt), reader, meaning(reader, world)))
            continue
        except PipflowError as exc:
            errors.append((parts(alt), exc))
            continue
        readings.append((parts(alt), reader, meaning(reader, world)))
    if not readings:
        raise min(errors, key=lambda e: e[0])[1]
    meant = [(n, r, m) for n, r, m in readings if m is not None]
    distinct = list(dict.fromkeys(m for _, _, m in meant))
    if len(distinct) > 1:
        if picks.get("reading") is not None:   # chosen by the user among the candidates
            return min((x for x in meant if x[2] == distinct[picks["reading"]]), key=lambda x: x[0])[1]
        (_, a, _), (_, b, _) = meant[0], next(x for x in meant if x[2] != meant[0][2])
        wa = "; ".join(s["words"] for s in a.statements + a.rules)
        wb = "; ".join(s["words"] for s in b.statements + b.rules)
        which = f"'{wa}' or '{wb}'" if wa != wb else f"'{wa}' says two things"  # the candidates show what
        raise Choice("reading", tuple(range(min(len(distinct), MAX_CANDIDATES))),
                      f"'{sentence}' can be read in two ways that ask for different things "
                      f"({which}); nothing is guessed: say it another way")
    return min(meant or readings, key=lambda x: x[0])[1]

def meaning_of(order: dict, world: dict) -> str | None:
    """What an order asks for, for comparing two readings (None: it does not resolve)."""
    try:
        r = resolve(order, world, check=False)
    except PipflowError:
        return None
    return canonical(r.goal, r.constraints)



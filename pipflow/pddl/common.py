"""Shared unified-planning plumbing: one quiet environment, parsing, plan conversion.

Every PDDL parse, solve and validation in pipflow goes through unified-planning (UP); this module
keeps the few conversions between UP objects and pipflow's JSON-like data in one place.
A plan, between steps, is ``[{"action": "move-product", "args": ["shelf1", "shelf3", ...]}]``.
"""
from __future__ import annotations

import hashlib
import threading
from collections import OrderedDict
from contextlib import contextmanager
from fractions import Fraction
from functools import lru_cache
from importlib.metadata import entry_points
from pathlib import Path
from typing import Any, Iterator

from pipflow.errors import UserError
from pipflow.pddl.deferred_configspace import defer as _defer_configspace
from pipflow.pddl.upconfig import install as _cheap_config_lookup

_PARSED: OrderedDict[str, Any] = OrderedDict()  # content hash -> parsed UP problem (read-only)
_PARSED_MAX = 4  # a run needs one problem (plus the domain alone); a refinement loop a few
_PARSED_LOCK = threading.Lock()
#: entry-point group of planners: ``NAME = "module:EngineClass"``, a unified-planning engine that
#: :func:`environment` adds to UP's factory under NAME (as ``pipflow.steps`` adds steps)
PLANNERS = "pipflow.planners"

@lru_cache(maxsize=1)
def environment() -> Any:
    """UP's global environment with the credits banner silenced and pipflow's engines added.

    UP is imported here, not at module top, on purpose: it is heavy and many pipflow commands
    never plan. ConfigSpace (scipy.stats) is deferred first: see :mod:`.deferred_configspace`."""
    _defer_configspace()
    _cheap_config_lookup()  # before the factory exists: see pipflow.pddl.upconfig
    from unified_planning.environment import get_environment

    env = get_environment()
    env.credits_stream = None
    env.error_used_name = True
    add_planners(env)
    return env


def add_planners(env: Any) -> None:
    """Add the planners registered in the entry-point group :data:`PLANNERS` to UP's engine
    factory (a task domain's own planner, such as the warehouse's ``pipflow-transport``; a plugin
    adds one the same way). UP imports each engine's module as it adds it. A planner whose module
    fails to load is the plugin's error, said with its name, never a traceback."""
    for ep in entry_points(group=PLANNERS):
        if ep.name in env.factory.engines:
            continue
        try:
            env.factory.add_engine(ep.name, ep.module, ep.attr)
        except Exception as err:  # a broken plugin: say which
            raise UserError(f"planner {ep.name!r} ({ep.value}) of entry-point group {PLANNERS} failed to load: "
                            f"{type(err).__name__}: {err}") from None


def read_domain_text(domain: str | Path) -> str:
    """The domain's text; ``domain`` is a path (PDDL text itself is accepted too)."""
    s = str(domain)
    if "(define" in s:
        return s
    return Path(s).read_text()


def parse(domain: str | Path, problem_text: str | None) -> Any:
    """Parse ``problem_text`` against ``domain`` with UP's PDDLReader (``None``: the domain
    alone); exceptions propagate (the debugger turns them into messages).

    Why memoised: UP's reader is slow (pyparsing; 15 s for a 200-shelf x 20-product problem) and
    a run reads the same text in debug, solve, verify and graph. The memo is keyed by a hash of
    the domain's and the problem's text, holds the last few parses, and keeps no failures. The
    problem returned is SHARED: callers must treat it as read-only (``problem.clone()`` before
    changing anything); planners, validators and the graph builder only read it."""
    domain_text = read_domain_text(domain)
    key = _key(domain_text, problem_text)
    with _PARSED_LOCK:
        hit = _PARSED.get(key)
        if hit is not None:
            _PARSED.move_to_end(key)
            return hit
    from unified_planning.io import PDDLReader  # heavy: deferred on purpose (see environment)

    environment()
    with _PARSING_LOCK, _without_packrat():
        problem = PDDLReader().parse_problem_string(domain_text, problem_text)
    with _PARSED_LOCK:
        _PARSED[key] = problem
        while len(_PARSED) > _PARSED_MAX:
            _PARSED.popitem(last=False)
    return problem


def _key(domain_text: str, problem_text: str | None) -> str:
    return hashlib.sha256(f"{len(domain_text)}:{domain_text}\0{problem_text}".encode()).hexdigest()


def share(domain: str | Path, problem_text: str, problem: Any) -> None:
    """Hand :func:`parse` the problem ``problem_text`` stands for, built by its writer with UP's
    API, so that no step parses the text again: a later ``parse(domain, problem_text)`` returns
    ``problem`` (shared, read-only, as every parse).

    Why: a task domain's own writer knows what its text says; for a 400 x 40 warehouse the
    reader takes 16 s and the API 0.4 s. Only a writer may call this, with an object its tests
    show equal (``==``) to the parse of its text: a text from anywhere else (a model's answer) is
    parsed as always, and a text changed by one character is another key."""
    key = _key(read_domain_text(domain), problem_text)
    with _PARSED_LOCK:
        _PARSED[key] = problem
        _PARSED.move_to_end(key)
        while len(_PARSED) > _PARSED_MAX:
            _PARSED.popitem(last=False)


_PARSING_LOCK = threading.Lock()  # one PDDL parse at a time: _without_packrat toggles a global


@contextmanager
def _without_packrat() -> Iterator[None]:
    """pyparsing's packrat memo off for the duration (and back on after, if it was on).

    Why: importing UP's ANML grammar switches packrat on for every pyparsing grammar in the
    process; UP's PDDL grammar does not backtrack enough to gain from it, and the memo's
    bookkeeping doubled the CPU time of a parse (3.9 s -> 1.9 s for a 100-shelf x 20-product
    problem, 0.07 s -> 0.04 s for the paper's). Memoisation changes speed, never the result."""
    from pyparsing import ParserElement  # comes with UP; deferred with it

    was_on = bool(getattr(ParserElement, "_packratEnabled", False))
    if was_on:
        ParserElement.disable_memoization()
    try:
        yield
    finally:
        if was_on:
            ParserElement.enable_packrat()


def format_plan(plan: list[dict]) -> str:
    """The plan as PDDL-style lines, ``(move-product shelf1 shelf3 product1 magnitude2)``."""
    return "".join(f"({p['action']} {' '.join(p['args'])})\n" for p in plan)


def goal_conditions(problem: Any) -> list[Any]:
    """The problem's goal as a flat list of conditions (nested ``and`` opened, order kept)."""
    out: list[Any] = []
    stack = list(problem.goals)
    while stack:
        g = stack.pop(0)
        if g.is_and():
            stack[:0] = list(g.args)
        else:
            out.append(g)
    return out


def goal_atoms(problem: Any) -> list[Any]:
    """The conditions a problem's goal states: :func:`goal_conditions` without the constant
    ``true`` an empty ``(and)`` parses to. A domain's reader uses it to tell a goal that asks for
    nothing (a model that copied its example unchanged) from one that asks for something."""
    return [g for g in goal_conditions(problem) if not (g.is_bool_constant() and g.bool_constant_value())]


def fluent_call(node: Any) -> tuple[str, tuple[str, ...]] | None:
    """``(name, (object names...))`` of a fluent expression such as ``(stored shed tomato)``;
    None for any other node. How a domain reads the goal and initial state of a parsed problem."""
    if node.is_fluent_exp():
        return node.fluent().name, tuple(a.object().name for a in node.args)
    return None


def number_value(node: Any) -> int | None:
    """The whole number a constant node states (``3``, ``3.0``); None for a fraction or any other
    node (a count of units is whole)."""
    if node.is_int_constant() or node.is_real_constant():
        v = Fraction(str(node.constant_value()))
        return int(v) if v.denominator == 1 else None
    return None

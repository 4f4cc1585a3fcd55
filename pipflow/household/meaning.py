"""When two household goals mean the same: they accept exactly the same final states of the home.

Why not compare the texts: a goal may state a condition that every reachable final state meets
anyway (a mug that cannot be sliced stays ``whole``), and two goals written alike may not mean
the same. Never calling two different meanings equal is the point (a missed misreading is the
worst error of the bench's ``misread``), so the comparison is exact over a space that contains
every final state the home can reach:

* where an object can end: where it lies now, or, when it can be picked up, any receptacle or
  garbage can (``store`` and ``trash`` are the only actions that move things);
* each flag (open, on, sliced, dirty, hot) keeps its value, or takes the values an action of the
  domain can give it: an openable place opens and closes, a toggleable thing switches both ways,
  a sliceable object can become sliced (never whole again), a dirty washable one clean (never
  dirty again), a heatable one hot (never cold again).

Robots' skills are left out (a team too weak to lift the watermelon reaches fewer states), so the
space may be larger than what a team reaches: two goals equal on it are equal on any smaller one,
so no different meanings are called equal; two goals that differ only in states no team reaches
are called different.

A goal's conditions fix a set of places per object and a set of values per flag, and its counts
("any 3 school supplies on the bed") bind objects together; equality of two goals is decided
condition by condition: every state the one accepts must meet each condition of the other. With
counts that is a small 0-1 program per condition (scipy's ``milp``, HiGHS); without, a comparison
of sets.
"""
from __future__ import annotations

import json
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from scipy.optimize import Bounds, LinearConstraint, milp

from pipflow.household.problem import CONDITIONS, STATE_FLUENT

#: flag -> (property that lets an action change it, the values that action can give)
CHANGES = {"is-open": ("openable", (True, False)), "is-on": ("toggleable", (True, False)),
           "sliced": ("sliceable", (True,)), "dirty": ("washable", (False,)), "hot": ("heatable", (True,))}
STATE_KEY = {fluent: key for key, fluent in STATE_FLUENT.items()}


class Unreadable(Exception):
    """A goal that names what the world lacks or has an unknown shape: compared as written."""


@dataclass
class Reading:
    """What one goal allows: places per object, values per flag, and its counts."""

    places: dict[str, set[str]] = field(default_factory=dict)
    flags: dict[tuple[str, str], set[bool]] = field(default_factory=dict)
    counts: list[tuple[tuple[str, ...], str, int]] = field(default_factory=list)
    words: dict[str, str] = field(default_factory=dict)  # object -> how the goal places it


def canonical(goal: Any) -> str | None:
    """A goal as sorted JSON (lists are sets; empty entries dropped), None if malformed."""
    if not isinstance(goal, dict):
        return None
    try:
        out = {"in": {p: sorted(v) for p, v in (goal.get("in") or {}).items() if v},
               "state": {n: sorted(v) for n, v in (goal.get("state") or {}).items() if v},
               "count": sorted(json.dumps(c, sort_keys=True) for c in goal.get("count") or [])}
    except (AttributeError, TypeError):
        return None
    return json.dumps(out, sort_keys=True)


class Home:
    """The reachable final states of one home (module docstring)."""

    def __init__(self, world: dict):
        self.world = world
        self.objects, self.places = world["objects"], world["places"]
        movable_to = sorted(p for p, e in self.places.items()
                            if {"receptacle", "garbage"} & set(e["properties"]))
        self.reach = {o: ({e["in"], *movable_to} if "pickupable" in e["properties"] else {e["in"]})
                      for o, e in self.objects.items()}

    def flag_values(self, name: str, fluent: str) -> set[bool]:
        entity = self.places.get(name) or self.objects[name]
        now = bool(entity["state"].get(STATE_KEY[fluent]))
        prop, values = CHANGES[fluent]
        return {now, *values} if prop in entity["properties"] else {now}

    def members(self, category: str) -> tuple[str, ...]:
        return tuple(o for o, e in self.objects.items() if category in e["categories"])

    def read(self, goal: Any) -> Reading:
        """The goal's conditions over this home; :class:`Unreadable` when it names what the home
        lacks or has another shape."""
        if not isinstance(goal, dict) or set(goal) - {"in", "state", "count"}:
            raise Unreadable
        r = Reading()
        try:
            for place, items in (goal.get("in") or {}).items():
                if place not in self.places:
                    raise Unreadable
                for o in items or []:
                    if o not in self.objects:
                        raise Unreadable
                    r.places[o] = r.places.get(o, set(self.reach[o])) & {place}
                    r.words[o] = f"{o} in {place}"
            for name, conds in (goal.get("state") or {}).items():
                if name not in self.places and name not in self.objects:
                    raise Unreadable
                for c in conds or []:
                    if c not in CONDITIONS:
                        raise Unreadable
                    fluent, positive, _ = CONDITIONS[c]
                    key = (name, fluent)
                    r.flags[key] = r.flags.get(key, self.flag_values(name, fluent)) & {positive}
            for c in goal.get("count") or []:
                if (not isinstance(c, dict) or set(c) != {"category", "in", "at_least"}
                        or c["in"] not in self.places or c["category"] not in self.world["categories"]
                        or not isinstance(c["at_least"], int) or isinstance(c["at_least"], bool)):
                    raise Unreadable
                r.counts.append((self.members(c["category"]), c["in"], int(c["at_least"])))
        except (AttributeError, TypeError, KeyError):
            raise Unreadable from None
        return r


class _Program:
    """The object placements one reading accepts, over ``objects``, as 0-1 variables y[o, place]."""

    def __init__(self, home: Home, reading: Reading, objects: list[str]):
        self.pairs = [(o, q) for o in objects for q in sorted(reading.places.get(o, home.reach[o]))]
        self.index = {pair: i for i, pair in enumerate(self.pairs)}
        rows, lows, highs = [], [], []
        for o in objects:
            rows.append([1.0 if p[0] == o else 0.0 for p in self.pairs])
            lows.append(1.0)
            highs.append(1.0)
        for members, place, n in reading.counts:
            rows.append([1.0 if p[1] == place and p[0] in members else 0.0 for p in self.pairs])
            lows.append(float(n))
            highs.append(np.inf)
        self.rows, self.lows, self.highs = rows, lows, highs
        self.empty_object = any(not reading.places.get(o, home.reach[o]) for o in objects)

    def least(self, pairs: set[tuple[str, str]]) -> int | None:
        """The fewest of ``pairs`` that hold in an accepted placement; None when none is accepted."""
        if self.empty_object:
            return None
        if not self.pairs:
            return 0 if all(low <= 0 for low in self.lows) else None
        cost = np.array([1.0 if p in pairs else 0.0 for p in self.pairs])
        result = milp(cost, constraints=LinearConstraint(np.array(self.rows), self.lows, self.highs),
                      integrality=np.ones(len(self.pairs)), bounds=Bounds(0, 1))
        if result.status == 2:  # infeasible
            return None
        if result.status != 0:
            raise RuntimeError(f"the 0-1 program of a goal comparison did not finish: {result.message}")
        return int(round(result.fun))


def goal_difference(world: dict, gold: Any, run: Any) -> str | None:
    """None when ``gold`` and ``run`` accept the same final states of ``world`` (module
    docstring); otherwise what differs, in words."""
    a, b = canonical(gold), canonical(run)
    if a is not None and a == b:
        return None
    home = Home(world)
    try:
        g, r = home.read(gold), home.read(run)
    except Unreadable:
        return f"goal {b}, gold {a}"
    objects = sorted(set(g.places) | set(r.places)
                     | {o for rd in (g, r) for members, _, _ in rd.counts for o in members})
    pg, pr = _Program(home, g, objects), _Program(home, r, objects)
    gold_ok = pg.least(set()) is not None and all(g.flags.values())
    run_ok = pr.least(set()) is not None and all(r.flags.values())
    if not (gold_ok and run_ok):
        if not gold_ok and not run_ok:
            return f"goal {b}, gold {a} (no final state meets either)"
        return (f"goal: no final state meets the run's goal {b}; the gold {a} can be met" if gold_ok else
                f"goal: the run's goal {b} can be met, the gold {a} cannot")
    out = []
    for name, fluent in sorted(set(g.flags) | set(r.flags)):
        dom = home.flag_values(name, fluent)
        vg, vr = g.flags.get((name, fluent), dom), r.flags.get((name, fluent), dom)
        if vg != vr:
            out.append(f"{name}: the gold allows {_said(fluent, vg)}, the run's goal {_said(fluent, vr)}")
    out += _placements_differ(home, g, pr, "the gold", "the run's goal")
    out += _placements_differ(home, r, pg, "the run's goal", "the gold")
    if not out:
        return None
    return "goal: " + "; ".join(out[:4]) + (" ..." if len(out) > 4 else "")


def _said(fluent: str, values: set[bool]) -> str:
    """A flag's allowed values in the conditions' words: ``closed``, ``open or closed``."""
    words = {positive: c for c, (f, positive, _) in CONDITIONS.items() if f == fluent}
    return " or ".join(words[v] for v in sorted(values, reverse=True))


def _placements_differ(home: Home, stated: Reading, other: _Program, by: str, other_name: str) -> list[str]:
    """The placement conditions of ``stated`` that some state ``other`` accepts does not meet."""
    out = []
    for o, allowed in sorted(stated.places.items()):
        if allowed == home.reach[o]:
            continue
        if other.least({(o, q) for q in allowed}) != 1:
            out.append(f"{stated.words.get(o, o)}: required by {by}, not by {other_name}")
    for members, place, n in stated.counts:
        if n <= 0:
            continue
        least = other.least({(o, place) for o in members})
        if least is None or least < n:
            out.append(f"at least {n} of {', '.join(members) or '(none)'} in {place}: required by {by}, "
                       f"{other_name} accepts {least}")
    return out

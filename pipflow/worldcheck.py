"""A located checker for a world file written section by section: what a domain's world loader
needs besides its own sections (names, numbers, unknown keys, the floor, footprints and access
points, the robot team), every problem collected with file:line:column and reported at once.

Why here: every world file has a floor, fixtures robots drive between and a robot team; a domain
plugin should write only what its world has of its own (beds and crops, say) and not a second
copy of these checks. A domain subclasses :class:`WorldChecker` (or calls it), builds its world
while the checker collects problems, then :meth:`WorldChecker.raise_problems` once.
"""
from __future__ import annotations

import re
from typing import Any, Iterable, Mapping

from pipflow.errors import Diagnostic, WorldError
from pipflow.floorplan import footprint, inside_footprint
from pipflow.suggest import did_you_mean
from pipflow.worldfile import Locate, is_point

#: names become PDDL objects: lower case, a letter first (PDDL reads names without case)
NAME = re.compile(r"^[a-z][a-z0-9_-]*$")
#: the keys of a fixture's footprint and the point a robot stands at to use it
PLACE_KEYS = ("x", "y", "width", "depth", "access")
#: the keys of a robot of the team
ROBOT_KEYS = ("start", "skills", "kind", "tags")


class WorldChecker:
    """Collects located problems while a world is built from a parsed file (``data`` and its
    ``locate``) of task domain ``domain``. ``reserved``: words a name may not take (the domain's
    PDDL's own)."""

    def __init__(self, data: Mapping[str, Any], locate: Locate, *, domain: str, reserved: Iterable[str] = ()):
        self.data, self.locate, self.domain = data, locate, domain
        self.reserved = tuple(reserved)
        self.diags: list[Diagnostic] = []
        self.seen: dict[str, str] = {}  # name -> what it names (one name, one thing)

    def problem(self, path: tuple, message: str, key: bool = False) -> None:
        self.diags.append(Diagnostic(self.locate(path, key=key), message))

    def raise_problems(self, message: str) -> None:
        """Raise :class:`WorldError` with every problem found, if any."""
        if self.diags:
            raise WorldError(self.diags, message)

    # -- values --------------------------------------------------------------------------------
    def mapping(self, path: tuple, value: Any, what: str) -> dict:
        """``value`` if it is a mapping; ``{}`` for none (and a problem for anything else)."""
        if value is None:
            return {}
        if not isinstance(value, dict):
            self.problem(path, f"{what} must be a mapping")
            return {}
        return value

    def number(self, path: tuple, value: Any, what: str, minimum: float = 0.0, integer: bool = False) -> float | None:
        """``value`` if it is a number (whole, with ``integer``) of at least ``minimum``, else None."""
        ok = isinstance(value, int) if integer else isinstance(value, (int, float))
        if isinstance(value, bool) or not ok or value < minimum:
            kind = "a whole number" if integer else "a number"
            self.problem(path, f"{what} must be {kind} >= {minimum:g}, got {value!r}")
            return None
        return value

    def flag(self, path: tuple, value: Any, what: str) -> bool:
        """``value`` if it is true or false (absent: false)."""
        if value is None:
            return False
        if not isinstance(value, bool):
            self.problem(path, f"{what} must be true or false, got {value!r}")
            return False
        return value

    def keys(self, path: tuple, value: Mapping, allowed: Iterable[str], what: str) -> None:
        """Each key of ``value`` is one of ``allowed`` (an unknown one: "did you mean")."""
        allowed = tuple(allowed)
        for k in value:
            if k not in allowed:
                self.problem(path + (k,), f"{what}: unknown key {k!r}{did_you_mean(k, allowed)}; "
                                          f"keys: {', '.join(allowed)}", key=True)

    def name(self, path: tuple, name: Any, what: str) -> bool:
        """Whether ``name`` may name a ``what``: lower case, not a reserved word, not the name of
        anything else of the world (it is then taken)."""
        if not isinstance(name, str) or not NAME.match(name):
            self.problem(path, f"{what} name {name!r} must be lower case letters, digits, '-' or '_', "
                               f"a letter first", key=True)
            return False
        if name in self.reserved:
            self.problem(path, f"{what} name {name!r} is a word of the {self.domain}'s PDDL domain; reserved: "
                               f"{', '.join(self.reserved)}", key=True)
            return False
        if name in self.seen:
            self.problem(path, f"{what} name {name!r} is already the name of a {self.seen[name]}", key=True)
            return False
        self.seen[name] = what
        return True

    def section(self, key: str, what: str) -> Iterable[tuple[str, tuple, dict]]:
        """``(name, path, spec)`` of each named entry of the top-level section ``key`` whose name
        is free (:meth:`name`) and whose spec is a mapping."""
        for name, spec in self.mapping((key,), self.data.get(key), key).items():
            path = (key, name)
            if self.name(path, name, what):
                yield name, path, self.mapping(path, spec, f"{what} {name}")

    # -- the floor plan ------------------------------------------------------------------------
    def floor(self) -> dict:
        """``floor: {width, height}`` in metres (at least 1 each)."""
        floor = self.mapping(("floor",), self.data.get("floor"), "floor")
        out = {}
        for k in ("width", "height"):
            v = self.number(("floor", k), floor.get(k), f"floor {k}", minimum=1.0)
            out[k] = float(v) if v is not None else 1.0
        return out

    def place(self, path: tuple, spec: Mapping, what: str, floor: Mapping[str, float]) -> dict | None:
        """A fixture's footprint (``x, y, width, depth``) and ``access`` point, on the floor, the
        access point outside the footprint; None when a value is missing or wrong."""
        vals = {k: self.number(path + (k,), spec.get(k), f"{what}: {k}", minimum=0.0 if k in "xy" else 0.1)
                for k in ("x", "y", "width", "depth")}
        access = spec.get("access")
        if not is_point(access):
            self.problem(path + ("access",), f"{what}: access must be a point [x, y], got {access!r}")
            return None
        if None in vals.values():
            return None
        if vals["x"] + vals["width"] > floor["width"] or vals["y"] + vals["depth"] > floor["height"]:
            self.problem(path, f"{what} lies outside the floor ({floor['width']:g} x {floor['height']:g} m)")
        ax, ay = access
        if not (0 <= ax <= floor["width"] and 0 <= ay <= floor["height"]):
            self.problem(path + ("access",), f"{what}: access point {access} lies outside the floor")
        elif vals["x"] < ax < vals["x"] + vals["width"] and vals["y"] < ay < vals["y"] + vals["depth"]:
            self.problem(path + ("access",), f"{what}: access point {access} lies inside its own footprint")
        return {**{k: float(v) for k, v in vals.items()}, "access": [float(ax), float(ay)]}

    def layout(self, places: Mapping[str, Mapping[str, Any]], robots: Mapping[str, Mapping[str, Any]],
               sections: Mapping[str, str]) -> None:
        """Across the fixtures (each with its ``role``; ``sections``: the top-level section each is
        in): no two footprints overlap, no access point and no robot start lies in a footprint."""
        names = list(places)
        for i, a in enumerate(names):
            for b in names[i + 1:]:
                ax0, ay0, ax1, ay1 = footprint(places[a])
                bx0, by0, bx1, by1 = footprint(places[b])
                if ax0 < bx1 and bx0 < ax1 and ay0 < by1 and by0 < ay1:
                    self.problem((sections[b], b), f"{places[b]['role']} {b} overlaps {places[a]['role']} {a}",
                                 key=True)
            for b in names:
                if b != a and inside_footprint(places[a]["access"], places[b]):
                    self.problem((sections[a], a, "access"), f"{places[a]['role']} {a}: access point "
                                                             f"{places[a]['access']} lies in {places[b]['role']} {b}")
        for r, spec in robots.items():
            for b, place in places.items():
                if inside_footprint(spec["start"], place):
                    self.problem(("robots", r, "start"), f"robot {r} starts inside {place['role']} {b}")

    # -- the team ------------------------------------------------------------------------------
    def robots(self, floor: Mapping[str, float], skills: Iterable[str]) -> dict:
        """``robots: {name: {start, skills, kind, tags}}``: a start on the floor, skills of the
        domain (``skills``) with their levels, a kind (one word) and tags (words) to select them
        by in commands."""
        known = tuple(skills)
        out = {}
        for name, path, spec in self.section("robots", "robot"):
            self.keys(path, spec, ROBOT_KEYS, f"robot {name}")
            start = spec.get("start")
            if not is_point(start) or not (0 <= start[0] <= floor["width"] and 0 <= start[1] <= floor["height"]):
                self.problem(path + ("start",), f"robot {name}: start must be a point [x, y] on the floor, got {start!r}")
                start = [0.0, 0.0]
            levels = {}
            for skill, level in self.mapping(path + ("skills",), spec.get("skills"), f"robot {name}: skills").items():
                if skill not in known:
                    self.problem(path + ("skills", skill), f"robot {name}: unknown skill {skill!r}"
                                                           f"{did_you_mean(skill, known)}; skills: {', '.join(known)}",
                                 key=True)
                    continue
                v = self.number(path + ("skills", skill), level, f"robot {name}: skill {skill}")
                if v is not None:
                    levels[skill] = v
            kind, tags = spec.get("kind"), spec.get("tags") or []
            if kind is not None and (not isinstance(kind, str) or not NAME.match(kind)):
                self.problem(path + ("kind",), f"robot {name}: kind must be one lower-case word, got {kind!r}")
                kind = None
            if not isinstance(tags, list) or not all(isinstance(t, str) and NAME.match(t) for t in tags):
                self.problem(path + ("tags",), f"robot {name}: tags must be a list of lower-case words, got {tags!r}")
                tags = []
            out[name] = {"start": [float(start[0]), float(start[1])], "skills": levels, "kind": kind, "tags": list(tags)}
        return out

"""The garden world file: beds with ripe crops, taps, stores, crops and a robot team.

Why a format of its own: a garden is not a warehouse. Its places are beds (which can be watered,
be overgrown and hold ripe crops), taps (where water is fetched) and stores (sheds, crates with
a limited room); its items are crops with a weight (the carry skill one unit needs). Every problem
in a file is reported at once, each with file:line:column, through pipflow's neutral helpers
(``pipflow.worldfile``, ``pipflow.suggest``), so a user fixes the file in one pass.

The loaded world keeps pipflow's generic contract where generic steps read it: ``floor``,
``places`` (every bed, tap and store: footprint ``x, y, width, depth`` and an ``access`` point, as
travel and scheduling expect) and ``robots`` (``start``, ``skills``, ``kind``, ``tags``). The
garden's own facts sit beside them: ``beds``, ``taps``, ``stores``, ``crops``.
"""
from __future__ import annotations

import re
from pathlib import Path
from typing import Any

from pipflow.errors import Diagnostic, WorldError
from pipflow.floorplan import footprint, inside_footprint, seeded_starts
from pipflow.suggest import did_you_mean
from pipflow.worldfile import is_point, parse_mapping, read_world_file

DOMAIN = "garden"
#: names become PDDL objects: lower case, a letter first (PDDL reads names without case)
NAME = re.compile(r"^[a-z][a-z0-9_-]*$")
TOP_KEYS = ("domain", "name", "floor", "crops", "beds", "taps", "stores", "robots")
SHAPE_KEYS = ("x", "y", "width", "depth", "access")
BED_KEYS = SHAPE_KEYS + ("ripe", "overgrown", "watered")
STORE_KEYS = SHAPE_KEYS + ("room", "holds")
ROBOT_KEYS = ("start", "skills", "kind", "tags")
#: words of garden.pddl (types, predicates, functions, actions): an object of the same name would
#: clash with them in the problem
RESERVED = ("object", "bed", "tap", "store", "crop", "watered", "overgrown", "clear", "ripe", "stored",
            "room", "weight", "water", "prune", "harvest")
#: the skills the garden's actions ask for (garden.actions.yaml)
SKILLS = ("water", "cut", "carry")


def load_world(path: str | Path) -> dict:
    """Load and check a garden world file; :class:`WorldError` lists every problem located."""
    p, text = read_world_file(path)
    return world_from_text(text, str(p))


def world_from_text(text: str, file: str) -> dict:
    """The checked, normalized world of a garden world file's text (``file`` names it in messages)."""
    data, locate = parse_mapping(text, file, "garden world")
    check = _Checker(data, locate)
    world = check.world(file)
    if check.diags:
        raise WorldError(check.diags, f"invalid garden world {file}")
    return world


class _Checker:
    """Collects located problems while building the world (one pass, every problem)."""

    def __init__(self, data: dict, locate):
        self.data, self.locate, self.diags = data, locate, []

    def problem(self, path: tuple, message: str, key: bool = False) -> None:
        self.diags.append(Diagnostic(self.locate(path, key=key), message))

    def mapping(self, path: tuple, value: Any, what: str) -> dict:
        if value is None:
            return {}
        if not isinstance(value, dict):
            self.problem(path, f"{what} must be a mapping")
            return {}
        return value

    def number(self, path: tuple, value: Any, what: str, minimum: float = 0.0, integer: bool = False) -> float | None:
        ok = isinstance(value, int) if integer else isinstance(value, (int, float))
        if isinstance(value, bool) or not ok or value < minimum:
            kind = "a whole number" if integer else "a number"
            self.problem(path, f"{what} must be {kind} >= {minimum:g}, got {value!r}")
            return None
        return value

    def keys(self, path: tuple, value: dict, allowed: tuple, what: str) -> None:
        for k in value:
            if k not in allowed:
                self.problem(path + (k,), f"{what}: unknown key {k!r}{did_you_mean(k, allowed)}; "
                                          f"keys: {', '.join(allowed)}", key=True)

    def name(self, path: tuple, name: Any, what: str, seen: dict) -> bool:
        if not isinstance(name, str) or not NAME.match(name):
            self.problem(path, f"{what} name {name!r} must be lower case letters, digits, '-' or '_', "
                               f"a letter first", key=True)
            return False
        if name in RESERVED:
            self.problem(path, f"{what} name {name!r} is a word of the garden's PDDL domain; reserved: "
                               f"{', '.join(RESERVED)}", key=True)
            return False
        if name in seen:
            self.problem(path, f"{what} name {name!r} is already the name of a {seen[name]}", key=True)
            return False
        seen[name] = what
        return True

    # ------------------------------------------------------------------------------- sections
    def world(self, file: str) -> dict:
        data = self.data
        self.keys((), data, TOP_KEYS, "garden world")
        if data.get("domain") != DOMAIN:
            self.problem(("domain",), f"a garden world says `domain: {DOMAIN}`, got {data.get('domain')!r}")
        floor = self.floor()
        seen: dict[str, str] = {}
        crops = self.crops(seen)
        places: dict[str, dict] = {}
        beds = self.beds(seen, crops, places, floor)
        taps = self.taps(seen, places, floor)
        stores = self.stores(seen, crops, places, floor)
        robots = self.robots(seen, floor)
        self.layout(places, robots)
        for section, items in (("beds", beds), ("taps", taps), ("stores", stores), ("robots", robots)):
            if not items and section not in data:
                self.problem((), f"a garden world needs `{section}`")
        return {"domain": DOMAIN, "name": str(data.get("name") or Path(file).stem), "path": file,
                "floor": floor, "crops": crops, "beds": beds, "taps": taps, "stores": stores,
                "places": places, "robots": robots}

    def floor(self) -> dict:
        floor = self.mapping(("floor",), self.data.get("floor"), "floor")
        out = {}
        for k in ("width", "height"):
            v = self.number(("floor", k), floor.get(k), f"floor {k}", minimum=1.0)
            out[k] = float(v) if v is not None else 1.0
        return out

    def crops(self, seen: dict) -> dict:
        out = {}
        for name, spec in self.mapping(("crops",), self.data.get("crops"), "crops").items():
            path = ("crops", name)
            if not self.name(path, name, "crop", seen):
                continue
            spec = self.mapping(path, spec, f"crop {name}")
            self.keys(path, spec, ("weight",), f"crop {name}")
            w = self.number(path + ("weight",), spec.get("weight", 1), f"crop {name}: weight", minimum=1, integer=True)
            out[name] = {"weight": w or 1}
        return out

    def shape(self, path: tuple, spec: dict, what: str, floor: dict) -> dict | None:
        vals = {}
        for k in ("x", "y", "width", "depth"):
            vals[k] = self.number(path + (k,), spec.get(k), f"{what}: {k}", minimum=0.0 if k in "xy" else 0.1)
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

    def layout(self, places: dict, robots: dict) -> None:
        """Across beds, taps and stores: no two footprints overlap, no access point and no robot
        start lies in a footprint (robots could not stand there)."""
        path = {name: (p["role"] + "s", name) for name, p in places.items()}
        names = list(places)
        for i, a in enumerate(names):
            ax0, ay0, ax1, ay1 = footprint(places[a])
            for b in names[i + 1:]:
                bx0, by0, bx1, by1 = footprint(places[b])
                if ax0 < bx1 and bx0 < ax1 and ay0 < by1 and by0 < ay1:
                    self.problem(path[b], f"{places[b]['role']} {b} overlaps {places[a]['role']} {a}", key=True)
            for b in names:
                if b != a and inside_footprint(places[a]["access"], places[b]):
                    self.problem(path[a] + ("access",), f"{places[a]['role']} {a}: access point "
                                                        f"{places[a]['access']} lies in {places[b]['role']} {b}")
        for r, spec in robots.items():
            for b, place in places.items():
                if inside_footprint(spec["start"], place):
                    self.problem(("robots", r, "start"), f"robot {r} starts inside {place['role']} {b}")

    def counts(self, path: tuple, value: Any, crops: dict, what: str) -> dict:
        out = {}
        for crop, n in self.mapping(path, value, what).items():
            if crop not in crops:
                self.problem(path + (crop,), f"{what}: unknown crop {crop!r}{did_you_mean(crop, crops)}", key=True)
                continue
            n = self.number(path + (crop,), n, f"{what}: {crop}", integer=True)
            if n:
                out[crop] = n
        return out

    def beds(self, seen: dict, crops: dict, places: dict, floor: dict) -> dict:
        out = {}
        for name, spec in self.mapping(("beds",), self.data.get("beds"), "beds").items():
            path = ("beds", name)
            if not self.name(path, name, "bed", seen):
                continue
            spec = self.mapping(path, spec, f"bed {name}")
            self.keys(path, spec, BED_KEYS, f"bed {name}")
            shape = self.shape(path, spec, f"bed {name}", floor)
            flags = {}
            for flag in ("overgrown", "watered"):
                v = spec.get(flag, False)
                if not isinstance(v, bool):
                    self.problem(path + (flag,), f"bed {name}: {flag} must be true or false, got {v!r}")
                flags[flag] = bool(v) if isinstance(v, bool) else False
            out[name] = {"ripe": self.counts(path + ("ripe",), spec.get("ripe"), crops, f"bed {name}: ripe"), **flags}
            if shape:
                places[name] = {**shape, "role": "bed"}
        return out

    def taps(self, seen: dict, places: dict, floor: dict) -> list[str]:
        out = []
        for name, spec in self.mapping(("taps",), self.data.get("taps"), "taps").items():
            path = ("taps", name)
            if not self.name(path, name, "tap", seen):
                continue
            spec = self.mapping(path, spec, f"tap {name}")
            self.keys(path, spec, SHAPE_KEYS, f"tap {name}")
            shape = self.shape(path, spec, f"tap {name}", floor)
            out.append(name)
            if shape:
                places[name] = {**shape, "role": "tap"}
        return out

    def stores(self, seen: dict, crops: dict, places: dict, floor: dict) -> dict:
        out = {}
        for name, spec in self.mapping(("stores",), self.data.get("stores"), "stores").items():
            path = ("stores", name)
            if not self.name(path, name, "store", seen):
                continue
            spec = self.mapping(path, spec, f"store {name}")
            self.keys(path, spec, STORE_KEYS, f"store {name}")
            shape = self.shape(path, spec, f"store {name}", floor)
            room = self.number(path + ("room",), spec.get("room"), f"store {name}: room", integer=True)
            holds = self.counts(path + ("holds",), spec.get("holds"), crops, f"store {name}: holds")
            if room is not None and sum(holds.values()) > room:
                self.problem(path + ("holds",), f"store {name} holds {sum(holds.values())} units, more than its "
                                                f"room of {room}")
            out[name] = {"room": room or 0, "holds": holds}
            if shape:
                places[name] = {**shape, "role": "store"}
        return out

    def robots(self, seen: dict, floor: dict) -> dict:
        out = {}
        for name, spec in self.mapping(("robots",), self.data.get("robots"), "robots").items():
            path = ("robots", name)
            if not self.name(path, name, "robot", seen):
                continue
            spec = self.mapping(path, spec, f"robot {name}")
            self.keys(path, spec, ROBOT_KEYS, f"robot {name}")
            start = spec.get("start")
            if not is_point(start) or not (0 <= start[0] <= floor["width"] and 0 <= start[1] <= floor["height"]):
                self.problem(path + ("start",), f"robot {name}: start must be a point [x, y] on the floor, got {start!r}")
                start = [0.0, 0.0]
            skills = {}
            for skill, level in self.mapping(path + ("skills",), spec.get("skills"), f"robot {name}: skills").items():
                if skill not in SKILLS:
                    self.problem(path + ("skills", skill), f"robot {name}: unknown skill {skill!r}"
                                                           f"{did_you_mean(skill, SKILLS)}; skills: {', '.join(SKILLS)}", key=True)
                    continue
                v = self.number(path + ("skills", skill), level, f"robot {name}: skill {skill}")
                if v is not None:
                    skills[skill] = v
            kind, tags = spec.get("kind"), spec.get("tags") or []
            if kind is not None and (not isinstance(kind, str) or not NAME.match(kind)):
                self.problem(path + ("kind",), f"robot {name}: kind must be one lower-case word, got {kind!r}")
                kind = None
            if not isinstance(tags, list) or not all(isinstance(t, str) and NAME.match(t) for t in tags):
                self.problem(path + ("tags",), f"robot {name}: tags must be a list of lower-case words, got {tags!r}")
                tags = []
            out[name] = {"start": [float(start[0]), float(start[1])], "skills": skills, "kind": kind, "tags": list(tags)}
        return out


def ripe_total(world: dict, crop: str, bed: str | None = None) -> int:
    """Ripe units of ``crop`` in ``bed`` (every bed when None)."""
    beds = [bed] if bed else list(world["beds"])
    return sum(world["beds"][b]["ripe"].get(crop, 0) for b in beds)


def vary_starts(world: dict, seed: int | None, clearance: float = 0.6, spacing: float = 1.0) -> dict:
    """A copy of the world whose robots start at seeded random free points of a 0.5 m grid (clear
    of every footprint and access point, apart from each other); ``seed=None``: unchanged. The
    rule is pipflow's, shared by every domain (:func:`pipflow.floorplan.seeded_starts`)."""
    return seeded_starts(world, seed, world["places"].values(), label="pipflow-garden-starts",
                         clearance=clearance, spacing=spacing, margin=0.5)

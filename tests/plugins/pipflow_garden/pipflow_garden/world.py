"""The garden world file: beds with ripe crops, taps, stores, crops and a robot team.

Why a format of its own: a garden is not a warehouse. Its places are beds (which can be watered,
be overgrown and hold ripe crops), taps (where water is fetched) and stores (sheds, crates with
a limited room); its items are crops with a weight (the carry skill one unit needs). Every problem
in a file is reported at once, each with file:line:column, through pipflow's world checker
(:class:`pipflow.plugin.WorldChecker`: names, numbers, the floor, footprints, the robot team), so a
user fixes the file in one pass; this module checks what only a garden has.

The loaded world keeps pipflow's generic contract where generic steps read it: ``floor``,
``places`` (every bed, tap and store: footprint ``x, y, width, depth`` and an ``access`` point, as
travel and scheduling expect) and ``robots`` (``start``, ``skills``, ``kind``, ``tags``). The
garden's own facts sit beside them: ``beds``, ``taps``, ``stores``, ``crops``.
"""
from __future__ import annotations

from pathlib import Path
from typing import Any

from pipflow.plugin import WorldChecker, did_you_mean, parse_mapping, read_world_file, seeded_starts

DOMAIN = "garden"
TOP_KEYS = ("domain", "name", "floor", "crops", "beds", "taps", "stores", "robots")
SHAPE_KEYS = ("x", "y", "width", "depth", "access")
SECTIONS = {"bed": "beds", "tap": "taps", "store": "stores"}
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
    check = _Garden(data, locate, domain=DOMAIN, reserved=RESERVED)
    world = check.world(file)
    check.raise_problems(f"invalid garden world {file}")
    return world


class _Garden(WorldChecker):
    """The garden's sections, checked while the world is built."""

    def world(self, file: str) -> dict:
        data = self.data
        self.keys((), data, TOP_KEYS, "garden world")
        if data.get("domain") != DOMAIN:
            self.problem(("domain",), f"a garden world says `domain: {DOMAIN}`, got {data.get('domain')!r}")
        floor = self.floor()
        crops = {name: self.crop(name, path, spec) for name, path, spec in self.section("crops", "crop")}
        places: dict[str, dict] = {}
        beds = {name: self.bed(name, path, spec, crops, places, floor) for name, path, spec in self.section("beds", "bed")}
        taps = [self.place_of(name, path, spec, "tap", places, floor) for name, path, spec in self.section("taps", "tap")]
        stores = {name: self.store(name, path, spec, crops, places, floor)
                  for name, path, spec in self.section("stores", "store")}
        robots = self.robots(floor, SKILLS)
        self.layout(places, robots, {name: SECTIONS[p["role"]] for name, p in places.items()})
        for section, items in (("beds", beds), ("taps", taps), ("stores", stores), ("robots", robots)):
            if not items and section not in data:
                self.problem((), f"a garden world needs `{section}`")
        return {"domain": DOMAIN, "name": str(data.get("name") or Path(file).stem), "path": file,
                "floor": floor, "crops": crops, "beds": beds, "taps": taps, "stores": stores,
                "places": places, "robots": robots}

    def place_of(self, name: str, path: tuple, spec: dict, role: str, places: dict, floor: dict,
                 keys: tuple = SHAPE_KEYS) -> str:
        """Check a bed's, tap's or store's keys and footprint; file its footprint under ``places``."""
        self.keys(path, spec, keys, f"{role} {name}")
        shape = self.place(path, spec, f"{role} {name}", floor)
        if shape:
            places[name] = {**shape, "role": role}
        return name

    def crop(self, name: str, path: tuple, spec: dict) -> dict:
        self.keys(path, spec, ("weight",), f"crop {name}")
        return {"weight": self.number(path + ("weight",), spec.get("weight", 1), f"crop {name}: weight",
                                      minimum=1, integer=True) or 1}

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

    def bed(self, name: str, path: tuple, spec: dict, crops: dict, places: dict, floor: dict) -> dict:
        self.place_of(name, path, spec, "bed", places, floor, SHAPE_KEYS + ("ripe", "overgrown", "watered"))
        flags = {flag: self.flag(path + (flag,), spec.get(flag), f"bed {name}: {flag}") for flag in ("overgrown", "watered")}
        return {"ripe": self.counts(path + ("ripe",), spec.get("ripe"), crops, f"bed {name}: ripe"), **flags}

    def store(self, name: str, path: tuple, spec: dict, crops: dict, places: dict, floor: dict) -> dict:
        self.place_of(name, path, spec, "store", places, floor, SHAPE_KEYS + ("room", "holds"))
        room = self.number(path + ("room",), spec.get("room"), f"store {name}: room", integer=True)
        holds = self.counts(path + ("holds",), spec.get("holds"), crops, f"store {name}: holds")
        if room is not None and sum(holds.values()) > room:
            self.problem(path + ("holds",), f"store {name} holds {sum(holds.values())} units, more than its room of {room}")
        return {"room": room or 0, "holds": holds}


def ripe_total(world: dict, crop: str, bed: str | None = None) -> int:
    """Ripe units of ``crop`` in ``bed`` (every bed when None)."""
    beds = [bed] if bed else list(world["beds"])
    return sum(world["beds"][b]["ripe"].get(crop, 0) for b in beds)


def vary_starts(world: dict, seed: int | None, clearance: float = 0.6, spacing: float = 1.0) -> dict:
    """A copy of the world whose robots start at seeded random free points of a 0.5 m grid (clear
    of every footprint and access point, apart from each other); ``seed=None``: unchanged. The
    rule is pipflow's, shared by every domain (:func:`pipflow.plugin.seeded_starts`)."""
    return seeded_starts(world, seed, world["places"].values(), label="pipflow-garden-starts",
                         clearance=clearance, spacing=spacing, margin=0.5)

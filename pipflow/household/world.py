"""Household world files: load, validate with located errors, normalize, pick a robot team.

Same two passes as the warehouse world (and the neutral helpers of :mod:`pipflow.worldfile`, :mod:`pipflow.floorplan`: YAML with locations, JSON-Schema
diagnostics, "did you mean"), because a user fixing a file wants every problem at once with its
line and column:

1. JSON Schema ``schemas/household.schema.json`` (structure, property names, states);
2. meaning: an object lies in a place that exists and can hold it; a state is only given where
   the property allows it (``open`` needs ``openable``...); categories named by objects exist and
   a category's ``home`` is a receptacle; footprints and access points lie on the floor and access
   points and robot starts outside every footprint; names do not clash with one another or with
   the domain's own words (UP refuses a problem whose object is called like a predicate).

The normalized world (``domain: household``) keeps the places under ``places`` with footprints
and access points, which :class:`pipflow.team.travel.TravelMap` reads like shelves, so allocation,
scheduling and travel work unchanged on the floor plan.
"""
from __future__ import annotations

import copy
from pathlib import Path
from typing import Any

from pipflow.errors import Diagnostic, InputError
from pipflow.floorplan import FootprintGrid, layout_diagnostics, on_floor, seeded_starts
from pipflow.suggest import did_you_mean
from pipflow.worldfile import Locate, checked_yaml, is_point, read_world_file

DOMAIN = "household"
#: words of domains/household.pddl that may not name an object (UP: "name already defined")
RESERVED = {"at", "is-receptacle", "is-garbage", "is-sink", "is-heater", "openable", "is-open",
            "accessible", "toggleable", "is-on", "pickupable", "sliceable", "sliced", "washable",
            "dirty", "heatable", "hot", "mass", "store", "trash", "open", "close", "switch-on",
            "switch-off", "slice", "wash", "heat", "place", "item", "entity", "object"}
#: which property a state needs (a state of an entity without it makes no sense)
STATE_NEEDS = {"open": "openable", "on": "toggleable", "dirty": "washable", "sliced": "sliceable",
               "hot": "heatable"}


#: entries a household world may hold per section (over :data:`pipflow.worldfile.SECTION_LIMIT`'s
#: default for the others); settable with PIPFLOW_WORLD_LIMITS, e.g. ``places=30000``
SIZE_LIMITS = {"robots": 20_000, "places": 10_000, "objects": 20_000}


def _dicts(data: dict, key: str) -> dict[str, dict]:
    value = data.get(key)
    return {k: v for k, v in value.items() if isinstance(v, dict)} if isinstance(value, dict) else {}


def semantic_diagnostics(data: dict, locate: Locate) -> list[Diagnostic]:
    """Checks the schema cannot express; each guards its own types so that one bad field does not
    hide the others' problems."""
    out: list[Diagnostic] = []
    floor = data.get("floor") if isinstance(data.get("floor"), dict) else None
    if floor and not all(isinstance(floor.get(k), (int, float)) for k in ("width", "height")):
        floor = None
    places, objects, robots = _dicts(data, "places"), _dicts(data, "objects"), _dicts(data, "robots")
    categories = data.get("categories") if isinstance(data.get("categories"), dict) else {}
    geo = {k: v for k, v in places.items() if all(isinstance(v.get(f), (int, float)) for f in ("x", "y", "width", "depth"))}

    for kind, names in (("place", places), ("object", objects), ("robot", robots)):
        for n in names:
            if n in RESERVED:
                out.append(Diagnostic(locate((kind + "s", n), key=True),
                                      f"{kind} name {n!r} is a word of the household domain; choose another name"))
    for n in objects:
        if n in places:
            out.append(Diagnostic(locate(("objects", n), key=True), f"object {n!r} has the name of a place"))

    out += layout_diagnostics(geo, floor, locate, "places", "place")

    for kind, table in (("places", places), ("objects", objects)):
        for name, ent in table.items():
            props = set(ent.get("properties") or []) if isinstance(ent.get("properties"), list) else set()
            for st in (ent.get("state") or {}) if isinstance(ent.get("state"), dict) else {}:
                need = STATE_NEEDS.get(st)
                if need and need not in props:
                    out.append(Diagnostic(locate((kind, name, "state", st), key=True),
                                          f"{name!r} has state {st!r} but not the property {need!r}"))
            for k, cat in enumerate(ent.get("categories") or []):
                if cat not in categories:
                    out.append(Diagnostic(locate((kind, name, "categories", k)),
                                          f"{name!r} names unknown category {cat!r}{did_you_mean(cat, categories)}; "
                                          "declare it under `categories`"))
    for name, obj in objects.items():
        where = obj.get("in")
        if not isinstance(where, str):
            continue
        if where not in places:
            out.append(Diagnostic(locate(("objects", name, "in")),
                                  f"object {name!r} lies in unknown place {where!r}{did_you_mean(where, places)}"))
            continue
        props = places[where].get("properties") or []
        if "receptacle" not in props and "garbage" not in props:
            out.append(Diagnostic(locate(("objects", name, "in")),
                                  f"object {name!r} lies in {where!r}, which is not a receptacle"))
    for cname, cat in categories.items():
        home = (cat or {}).get("home") if isinstance(cat, dict) else None
        if isinstance(home, str):
            if home not in places:
                out.append(Diagnostic(locate(("categories", cname, "home")),
                                      f"category {cname!r} has unknown home {home!r}{did_you_mean(home, places)}"))
            elif "receptacle" not in (places[home].get("properties") or []):
                out.append(Diagnostic(locate(("categories", cname, "home")),
                                      f"category {cname!r} has home {home!r}, which is not a receptacle"))

    grid = FootprintGrid(geo)  # a robot's start against the places near it, not every place
    for rname, robot in robots.items():
        start = robot.get("start")
        if not is_point(start):
            continue
        if floor and not on_floor(start, floor):
            out.append(Diagnostic(locate(("robots", rname, "start")), f"robot {rname!r} starts at {start}, off the floor"))
        for pname in grid.containing(start, geo):
            out.append(Diagnostic(locate(("robots", rname, "start")),
                                  f"robot {rname!r} starts at {start}, inside the footprint of {pname!r}"))
    for tname, members in (data.get("teams") or {}).items() if isinstance(data.get("teams"), dict) else ():
        for k, r in enumerate(members or []):
            if r not in robots:
                out.append(Diagnostic(locate(("teams", tname, k)),
                                      f"team {tname!r} names unknown robot {r!r}{did_you_mean(r, robots)}"))
    return out


def _entity(e: dict, kind: str) -> dict:
    out: dict[str, Any] = {"properties": list(e.get("properties") or []), "categories": list(e.get("categories") or []),
                           "words": [str(w).lower() for w in e.get("words") or []],
                           "state": {k: bool(v) for k, v in (e.get("state") or {}).items()}}
    if e.get("color"):
        out["color"] = e["color"]
    if kind == "place":
        out.update({"x": e["x"], "y": e["y"], "width": e["width"], "depth": e["depth"], "access": list(e["access"])})
    else:
        out.update({"in": e["in"], "mass": e["mass"]})
    return out


def normalize(data: dict, path: Path) -> dict:
    """The household world dict (benchmarks/README.md, household section): every key present."""
    cats = {name: {"words": [str(w).lower() for w in (c or {}).get("words") or []], "home": (c or {}).get("home")}
            for name, c in (data.get("categories") or {}).items()}
    return {
        "domain": DOMAIN,
        "name": data.get("name") or path.stem,
        "path": str(path),
        "floor": {"width": data["floor"]["width"], "height": data["floor"]["height"]},
        "categories": cats,
        "places": {n: _entity(p, "place") for n, p in data["places"].items()},
        "objects": {n: _entity(o, "object") for n, o in (data.get("objects") or {}).items()},
        "robots": {n: {"start": list(r["start"]), "skills": dict(r["skills"])} for n, r in data["robots"].items()},
        "teams": {n: list(m) for n, m in (data.get("teams") or {}).items()},
    }


def _fix_on_keys(data: dict) -> None:
    """YAML 1.1 (PyYAML) reads the key ``on`` as the boolean true; ``state: {on: true}`` is what
    a user writes, so the key is restored before validation (the locator still finds "on")."""
    for key in ("places", "objects"):
        for ent in (data.get(key) or {}).values() if isinstance(data.get(key), dict) else ():
            state = ent.get("state") if isinstance(ent, dict) else None
            if isinstance(state, dict) and True in state:
                state["on"] = state.pop(True)


def world_from_text(text: str, file: str) -> dict:
    """Validate and normalize household world YAML ``text`` (``file`` names it in messages)."""
    data = checked_yaml(text, file, "household world", "household.schema.json", semantic_diagnostics,
                        prepare=_fix_on_keys, limits=SIZE_LIMITS)
    return normalize(data, Path(file))


def load_world(path: str | Path) -> dict:
    """Load a household world file; :class:`WorldError` lists every problem with its location."""
    p, text = read_world_file(path)
    return world_from_text(text, str(p))


# ---------------------------------------------------------------------------------------------
# teams and starts
# ---------------------------------------------------------------------------------------------
def team_members(world: dict, team: str | list | None) -> list[str]:
    """Robot names of ``team``: a team name of the world, a list, or "a,b,c"; None = all robots."""
    if team is None or team == "" or team == []:
        return list(world["robots"])
    if isinstance(team, str):
        team = world["teams"].get(team) or [t.strip() for t in team.split(",") if t.strip()]
    unknown = [r for r in team if r not in world["robots"]]
    if unknown:
        raise InputError(f"team names unknown robots or team {unknown}; teams: {', '.join(world['teams']) or 'none'}; "
                         f"robots: {', '.join(world['robots'])}")
    return list(team)


def select_team(world: dict, team: str | list | None) -> dict:
    """A copy of the world with only the team's robots (the paper runs each task with its team)."""
    members = team_members(world, team)
    return {**world, "robots": {r: copy.deepcopy(world["robots"][r]) for r in members}}


def vary_starts(world: dict, seed: int | None, clearance: float = 0.4, spacing: float = 0.8) -> dict:
    """Seeded random free start points, 0.5 m inside the walls, ``clearance`` from every place's
    footprint, ``spacing`` from access points and from each other (:func:`seeded_starts`, shared
    by every domain); None = unchanged."""
    return seeded_starts(world, seed, world["places"].values(), label="pipflow-household-starts",
                         clearance=clearance, spacing=spacing, margin=0.5)


# ---------------------------------------------------------------------------------------------
# facts
# ---------------------------------------------------------------------------------------------
def entity(world: dict, name: str) -> dict:
    """A place or an object by name."""
    return world["places"].get(name) or world["objects"][name]


def members(world: dict, category: str) -> list[str]:
    """Places and objects of a category, in world order."""
    return [n for n, e in {**world["places"], **world["objects"]}.items() if category in e["categories"]]


def initial_state(world: dict) -> dict:
    """The world's state in the simulation's terms: where objects are and which flags hold."""
    flags: dict[str, set[str]] = {k: set() for k in STATE_NEEDS}
    for name, e in {**world["places"], **world["objects"]}.items():
        for k, v in e["state"].items():
            if v:
                flags[k].add(name)
    return {"at": {n: o["in"] for n, o in world["objects"].items()}, **flags}

"""Floor plans: footprints on a floor and the access points robots stand at.

A neutral module below every domain: warehouse shelves and household places are both a footprint
(``x``, ``y``, ``width``, ``depth``) with an ``access`` point, and both world checkers use these
geometry checks rather than one borrowing them from the other."""
from __future__ import annotations

import copy
import math
import random
from typing import Any, Iterable, Mapping

from pipflow.errors import Diagnostic, Location, WorldError
from pipflow.worldfile import Locate, is_point


def footprint(fixture: dict) -> tuple[float, float, float, float]:
    """(x0, y0, x1, y1) of a fixture's footprint."""
    return fixture["x"], fixture["y"], fixture["x"] + fixture["width"], fixture["y"] + fixture["depth"]


def inside_footprint(point: list[float], fixture: dict) -> bool:
    """True when ``point`` lies in the fixture's footprint, border included (a robot touching a
    fixture collides with it)."""
    x0, y0, x1, y1 = footprint(fixture)
    return x0 <= point[0] <= x1 and y0 <= point[1] <= y1


def on_floor(point: list[float], floor: dict) -> bool:
    return 0 <= point[0] <= floor["width"] and 0 <= point[1] <= floor["height"]


def layout_diagnostics(geo: dict, floor: dict | None, locate: Locate, section: str, kind: str) -> list[Diagnostic]:
    """Footprints on the floor, access points on the floor and outside every footprint, no two
    footprints overlapping: the geometry checks of every world file (shelves, household places)."""
    out: list[Diagnostic] = []
    for name, item in geo.items():
        x0, y0, x1, y1 = footprint(item)
        if floor and not (x0 >= 0 and y0 >= 0 and x1 <= floor["width"] and y1 <= floor["height"]):
            out.append(Diagnostic(locate((section, name), key=True),
                                  f"{kind} {name!r} footprint ({x0}, {y0})-({x1}, {y1}) is not on the "
                                  f"floor (0, 0)-({floor['width']}, {floor['height']})"))
        access = item.get("access")
        if is_point(access):
            if floor and not on_floor(access, floor):
                out.append(Diagnostic(locate((section, name, "access")),
                                      f"access point {access} of {kind} {name!r} is off the floor"))
            for other, o in geo.items():
                if inside_footprint(access, o):
                    out.append(Diagnostic(locate((section, name, "access")),
                                          f"access point {access} of {kind} {name!r} lies inside the "
                                          f"footprint of {kind} {other!r}; robots must be able to stand there"))
    names = list(geo)
    for i, a in enumerate(names):
        for b in names[i + 1:]:
            ax0, ay0, ax1, ay1 = footprint(geo[a])
            bx0, by0, bx1, by1 = footprint(geo[b])
            if ax0 < bx1 and bx0 < ax1 and ay0 < by1 and by0 < ay1:
                out.append(Diagnostic(locate((section, b), key=True), f"{kind} {b!r} overlaps {kind} {a!r}"))
    return out


#: metres between candidate start points (a lattice keeps seeded runs easy to read)
START_GRID = 0.5


def seeded_starts(world: dict, seed: int | None, footprints: Iterable[Mapping[str, Any]], *, label: str,
                  clearance: float, spacing: float, margin: float) -> dict:
    """A copy of ``world`` whose robots start at seeded random free points (``seed=None``: the
    world unchanged): the paper runs each task "from varied initial robot locations".

    Why one function for every domain: the variation must be reproducible and fair (no robot
    inside furniture or in another's way), which is the same rule whatever the footprints are.
    The candidates are the points of a :data:`START_GRID` lattice at least ``margin`` inside the
    floor, outside every footprint grown by ``clearance``, at least ``spacing`` from every access
    point; they are shuffled by ``random.Random(f"{label}-{seed}")`` (the label keeps each domain's
    sequence its own) and given to the robots in name order, each ``spacing`` apart from those
    placed before. Raises WorldError (located at the world file) when a robot finds no point."""
    if seed is None:
        return world
    rng = random.Random(f"{label}-{seed}")
    places = list(footprints)

    def free(x: float, y: float) -> bool:
        return all(not (p["x"] - clearance <= x <= p["x"] + p["width"] + clearance
                        and p["y"] - clearance <= y <= p["y"] + p["depth"] + clearance)
                   and math.dist(p["access"], (x, y)) >= spacing for p in places)

    width, height = world["floor"]["width"], world["floor"]["height"]
    candidates = [(i * START_GRID, j * START_GRID)
                  for i in range(int(margin / START_GRID), int((width - margin) / START_GRID) + 1)
                  for j in range(int(margin / START_GRID), int((height - margin) / START_GRID) + 1)]
    candidates = [q for q in candidates if free(*q)]
    rng.shuffle(candidates)
    varied = copy.deepcopy(world)
    taken: list[tuple[float, float]] = []
    for name in sorted(varied["robots"]):
        point = next((q for q in candidates if all(math.dist(q, t) >= spacing for t in taken)), None)
        if point is None:
            raise WorldError([Diagnostic(Location(str(world.get("path", ""))),
                                         f"seed {seed}: no free start left on the floor for robot {name!r} "
                                         f"({len(taken)} robots placed)")])
        taken.append(point)
        varied["robots"][name]["start"] = [point[0], point[1]]
    return varied

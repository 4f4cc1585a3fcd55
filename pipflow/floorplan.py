"""Floor plans: footprints on a floor and the access points robots stand at.

A neutral module below every domain: warehouse shelves and household places are both a footprint
(``x``, ``y``, ``width``, ``depth``) with an ``access`` point, and both world checkers use these
geometry checks rather than one borrowing them from the other."""
from __future__ import annotations

import copy
import math
import random
from typing import Any, Iterable, Mapping

from pipflow.errors import Diagnostic, Location, UserError, WorldError
from pipflow.worldfile import Locate, is_point
from pipflow.yamlsource import read_source, section_sizes


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
#: lattice points of a floor listed at most (a 500 x 500 m floor); a larger floor is sampled
#: point by point, so no floor's size is ever allocated for
MAX_LATTICE = 1_000_000
#: random lattice points tried per robot on a sampled floor before the floor is called full
SAMPLE_TRIES = 5000


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
    placed before.

    Whether the robots fit does not depend on the seed: when the shuffled order leaves a robot
    without a point, the floor is packed in lattice order (row by row, the densest this rule
    allows) and the seed only decides who stands where; when even that packing has fewer points
    than robots, every seed would fail alike, and the WorldError says so at the world file's
    ``robots`` (how many fit, how many there are, and the rule). A floor of more than
    :data:`MAX_LATTICE` lattice points is sampled instead of listed."""
    if seed is None:
        return world
    rng = random.Random(f"{label}-{seed}")
    places = list(footprints)

    def free(x: float, y: float) -> bool:
        return all(not (p["x"] - clearance <= x <= p["x"] + p["width"] + clearance
                        and p["y"] - clearance <= y <= p["y"] + p["depth"] + clearance)
                   and math.dist(p["access"], (x, y)) >= spacing for p in places)

    width, height = world["floor"]["width"], world["floor"]["height"]
    cols = range(int(margin / START_GRID), int((width - margin) / START_GRID) + 1)
    rows = range(int(margin / START_GRID), int((height - margin) / START_GRID) + 1)
    names = sorted(world["robots"])
    if len(cols) * len(rows) <= MAX_LATTICE:
        candidates = [(i * START_GRID, j * START_GRID) for i in cols for j in rows]
        candidates = [q for q in candidates if free(*q)]
        lattice_order = list(candidates)
        rng.shuffle(candidates)
        points = _spaced(candidates, len(names), spacing)
        if len(points) < len(names):
            points = _spaced(lattice_order, len(lattice_order), spacing)
            if len(points) < len(names):
                raise _no_room(world, seed, len(points), len(names), clearance, spacing, margin)
            rng.shuffle(points)
    else:
        points = _sampled(rng, cols, rows, free, len(names), spacing)
        if len(points) < len(names):
            raise _no_room(world, seed, len(points), len(names), clearance, spacing, margin, sampled=True)
    varied = copy.deepcopy(world)
    for name, point in zip(names, points):
        varied["robots"][name]["start"] = [point[0], point[1]]
    return varied


class _Spacing:
    """Points taken so far, each ``spacing`` from the others; a new point is compared only with
    the taken points of its neighbouring grid cells (a cell is ``spacing`` wide), so taking n
    points costs O(n), not O(n^2)."""

    def __init__(self, spacing: float):
        self.spacing, self.cell = spacing, max(spacing, 1e-9)
        self.taken: list[tuple[float, float]] = []
        self._grid: dict[tuple[int, int], list[tuple[float, float]]] = {}

    def fits(self, q: tuple[float, float]) -> bool:
        cx, cy = int(q[0] // self.cell), int(q[1] // self.cell)
        return all(math.dist(q, t) >= self.spacing for dx in (-1, 0, 1) for dy in (-1, 0, 1)
                   for t in self._grid.get((cx + dx, cy + dy), ()))

    def add(self, q: tuple[float, float]) -> None:
        self.taken.append(q)
        self._grid.setdefault((int(q[0] // self.cell), int(q[1] // self.cell)), []).append(q)


def _spaced(candidates: list[tuple[float, float]], wanted: int, spacing: float) -> list[tuple[float, float]]:
    """The candidates, in their order, that are ``spacing`` apart from every one taken before,
    up to ``wanted`` of them."""
    spaced = _Spacing(spacing)
    for q in candidates:
        if len(spaced.taken) >= wanted:
            break
        if spaced.fits(q):
            spaced.add(q)
    return spaced.taken


def _sampled(rng: random.Random, cols: range, rows: range, free: Any, wanted: int,
             spacing: float) -> list[tuple[float, float]]:
    """Seeded random lattice points of a floor too large to list, free and ``spacing`` apart."""
    spaced = _Spacing(spacing)
    for _ in range(wanted):
        for _ in range(SAMPLE_TRIES):
            q = (rng.choice(cols) * START_GRID, rng.choice(rows) * START_GRID)
            if free(*q) and spaced.fits(q):
                spaced.add(q)
                break
        else:
            break
    return spaced.taken


def _no_room(world: dict, seed: int, room: int, robots: int, clearance: float, spacing: float, margin: float,
             sampled: bool = False) -> WorldError:
    """The refusal of a floor that cannot hold the robots' seeded starts, at the world file's
    ``robots`` key: the same for every seed."""
    path = str(world.get("path", ""))
    where = Location(path)
    try:
        found = section_sizes(read_source(path, "world file")).get("robots") if path else None
    except UserError:
        found = None
    if found:
        where = Location(path, found[1], found[2])
    found_how = (f"no free point was found for robot {room + 1} in {SAMPLE_TRIES} tries" if sampled
                 else f"the floor has room for {room} seeded start{'s' if room != 1 else ''}")
    return WorldError([Diagnostic(where, f"seed {seed}: {found_how}, and the world has {robots} robots (seeded starts "
                                         f"lie on a {START_GRID} m grid, {margin:g} m inside the walls, {clearance:g} m "
                                         f"from every footprint, {spacing:g} m from access points and from each other; "
                                         "every seed is alike): make the floor larger or use fewer robots")])

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


class FootprintGrid:
    """Footprints by the cells of a uniform grid they cover: which footprints may hold a point,
    which pairs may overlap, without comparing every pair (25,000 shelves: 312 million pairs).

    Why a grid: footprints on a floor are many, alike in size and spread out, so a grid of cells
    about one typical footprint wide puts a handful in each cell, and a query costs the footprints
    of one cell. Building it costs the cells each footprint covers; a footprint that would cover
    more than :data:`BIG_CELLS` cells (a hall among cupboards), or whose numbers are not finite,
    is kept in a short list that every query checks. The grid only narrows the candidates: every
    answer is decided by the same comparison as before (:func:`inside_footprint`, the strict
    overlap test), so the results are exactly those of the all-pairs loops."""

    #: most cells one footprint is registered in; a larger one is checked against every query
    BIG_CELLS = 64

    def __init__(self, geo: Mapping[str, dict]):
        self.names = list(geo)
        self.boxes = [footprint(geo[n]) for n in self.names]
        sides = sorted(max(b[2] - b[0], b[3] - b[1]) for b in self.boxes
                       if all(math.isfinite(v) for v in b) and b[2] - b[0] > 0 and b[3] - b[1] > 0)
        self.cell = float(sides[len(sides) // 2]) if sides else 1.0  # the median footprint's side
        self.cells: dict[tuple[int, int], list[int]] = {}
        self.big: list[int] = []
        for i, (x0, y0, x1, y1) in enumerate(self.boxes):
            span = self._span(x0, y0, x1, y1)
            if span is None:
                self.big.append(i)
                continue
            (cx0, cy0), (cx1, cy1) = span
            for cx in range(cx0, cx1 + 1):
                for cy in range(cy0, cy1 + 1):
                    self.cells.setdefault((cx, cy), []).append(i)

    def _span(self, x0: float, y0: float, x1: float, y1: float) -> tuple[tuple[int, int], tuple[int, int]] | None:
        """The first and last cell of a box, or None for a box of too many cells (or not finite)."""
        if not all(math.isfinite(v) for v in (x0, y0, x1, y1)) or x1 < x0 or y1 < y0:
            return None
        c = self.cell
        cx0, cy0, cx1, cy1 = math.floor(x0 / c), math.floor(y0 / c), math.floor(x1 / c), math.floor(y1 / c)
        if (cx1 - cx0 + 1) * (cy1 - cy0 + 1) > self.BIG_CELLS:
            return None
        return (cx0, cy0), (cx1, cy1)

    def _near_point(self, p: list[float]) -> list[int]:
        if not all(math.isfinite(v) for v in p):
            return list(range(len(self.names)))
        here = self.cells.get((math.floor(p[0] / self.cell), math.floor(p[1] / self.cell)), [])
        return sorted(set(here).union(self.big))

    def containing(self, point: list[float], geo: Mapping[str, dict]) -> list[str]:
        """The footprints holding ``point`` (border included), in ``geo``'s order."""
        return [self.names[i] for i in self._near_point(point) if inside_footprint(point, geo[self.names[i]])]

    def overlapping_pairs(self) -> list[tuple[int, int]]:
        """Index pairs ``(i, j)``, i < j, of footprints whose interiors overlap, sorted."""
        out: set[tuple[int, int]] = set()
        boxes = self.boxes
        candidates: set[tuple[int, int]] = set()
        for members in self.cells.values():
            for a in range(len(members)):
                for b in range(a + 1, len(members)):
                    candidates.add((members[a], members[b]))
        for i in self.big:
            candidates.update((min(i, j), max(i, j)) for j in range(len(boxes)) if j != i)
        for i, j in candidates:
            ax0, ay0, ax1, ay1 = boxes[i]
            bx0, by0, bx1, by1 = boxes[j]
            if ax0 < bx1 and bx0 < ax1 and ay0 < by1 and by0 < ay1:
                out.add((i, j))
        return sorted(out)


def layout_diagnostics(geo: dict, floor: dict | None, locate: Locate, section: str, kind: str) -> list[Diagnostic]:
    """Footprints on the floor, access points on the floor and outside every footprint, no two
    footprints overlapping: the geometry checks of every world file (shelves, household places).
    Through a :class:`FootprintGrid`, so a world of n footprints costs about n, not n squared."""
    out: list[Diagnostic] = []
    grid = FootprintGrid(geo)
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
            for other in grid.containing(access, geo):
                out.append(Diagnostic(locate((section, name, "access")),
                                      f"access point {access} of {kind} {name!r} lies inside the "
                                      f"footprint of {kind} {other!r}; robots must be able to stand there"))
    names = grid.names
    for i, j in grid.overlapping_pairs():
        out.append(Diagnostic(locate((section, names[j]), key=True), f"{kind} {names[j]!r} overlaps {kind} {names[i]!r}"))
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

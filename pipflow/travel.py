"""Travel on the floor: exact obstacle-free shortest paths between places and robot starts.

Why not straight lines: the paper's cost ``c_i`` is a robot's travel distance, and robots cannot
drive through shelves. A straight-line distance would make a robot behind a shelf look as cheap
as one in front of it, so allocation and TC-max/TC-avg would be wrong.

Shelf footprints, inflated by a small margin (robot radius), are rectangular obstacles. Among
convex polygonal obstacles a shortest path bends only at obstacle corners, so the **visibility
graph** (nodes: the free corners of the inflated rectangles plus the places; edges: pairs that
see each other) holds every shortest path, and Dijkstra on it (networkx) gives exact any-angle
geodesics. It is far smaller than a floor grid (a few hundred nodes for fifty shelves), and
visibility is tested for many segments at once with numpy. ``distance`` is always the length of
the path ``path`` returns, so allocation costs and schedule legs agree.

Everything a run needs (distances and paths between every shelf access point and every place) is
computed once per world and cached in memory, and optionally on disk keyed by a hash of the
world's geometry, so the many allocation calls of a run, and repeated runs, are cheap.
"""
from __future__ import annotations

import hashlib
import json
import math
from pathlib import Path
from typing import Any, Sequence, Union

from pipflow.errors import InputError

Point = tuple[float, float]
Place = Union[str, Sequence[float]]

_MEMORY_CACHE: dict[str, dict[str, Any]] = {}
_FORMAT = 2  # 2: exact visibility-graph paths


def _rect_hits_segment(rect: tuple[float, float, float, float], a: Point, b: Point) -> bool:
    """True when segment a-b passes through the open rectangle (x0, y0, x1, y1).

    Liang-Barsky clipping; touching the boundary does not count, so paths may graze the
    inflated footprint (the inflation already keeps robots off the real shelf)."""
    x0, y0, x1, y1 = rect
    dx, dy = b[0] - a[0], b[1] - a[1]
    t0, t1 = 0.0, 1.0
    for p, q in ((-dx, a[0] - x0), (dx, x1 - a[0]), (-dy, a[1] - y0), (dy, y1 - a[1])):
        if abs(p) < 1e-12:
            if q <= 1e-9:
                return False
        else:
            t = q / p
            if p < 0:
                t0 = max(t0, t)
            else:
                t1 = min(t1, t)
            if t0 >= t1 - 1e-9:
                return False
    # the clipped piece must have positive length strictly inside
    mx, my = a[0] + dx * (t0 + t1) / 2, a[1] + dy * (t0 + t1) / 2
    eps = 1e-9
    return x0 + eps < mx < x1 - eps and y0 + eps < my < y1 - eps


def _length(path: Sequence[Sequence[float]]) -> float:
    return sum(math.dist(path[k], path[k + 1]) for k in range(len(path) - 1))


class TravelMap:
    """Shortest obstacle-free travel between points or named places of one world.

    Places are shelf names (standing at the shelf's ``access`` point) and robot names (the
    robot's ``start``); points are ``[x, y]`` in metres.

    >>> tm = TravelMap(world)                       # doctest: +SKIP
    >>> tm.distance("robot0", "shelf3"), tm.path("shelf1", [20, 2])   # doctest: +SKIP
    """

    def __init__(self, world: dict, inflate: float = 0.3, cache_dir: str | Path | None = None):
        self.world = world
        self.inflate = float(inflate)
        floor = world.get("floor") or {}
        try:
            self.width = float(floor["width"])
            self.height = float(floor["height"])
        except (KeyError, TypeError) as exc:
            raise InputError("world has no floor {width, height}") from exc
        # shelves (warehouse) and places (household floor plans) are both footprint + access point
        fixtures = {**(world.get("shelves") or {}), **(world.get("places") or {})}
        self.footprints = {
            name: (float(s["x"]), float(s["y"]), float(s["x"]) + float(s["width"]),
                   float(s["y"]) + float(s["depth"]))
            for name, s in fixtures.items()
        }
        self.obstacles = [
            (x0 - self.inflate, y0 - self.inflate, x1 + self.inflate, y1 + self.inflate)
            for (x0, y0, x1, y1) in self.footprints.values()
        ]
        self._cores = list(self.footprints.values())  # same order as self.obstacles
        self.places: dict[str, Point] = {}
        for name, s in fixtures.items():
            self.places[name] = (float(s["access"][0]), float(s["access"][1]))
        for name, r in (world.get("robots") or {}).items():
            self.places[name] = (float(r["start"][0]), float(r["start"][1]))
        for name, p in self.places.items():
            self._check_point(p, name)
        self.key = self._key()
        self._graph = None
        self._pairs: dict[tuple[Point, Point], tuple[float, list[list[float]]]] = {}
        self._load(cache_dir)

    # ------------------------------------------------------------------ public API
    def point(self, a: Place) -> Point:
        """The floor point of a place name or an ``[x, y]`` point."""
        if isinstance(a, str):
            if a not in self.places:
                raise InputError(
                    f"unknown place {a!r}; places are shelves and robots: {', '.join(sorted(self.places))}")
            return self.places[a]
        try:
            x, y = float(a[0]), float(a[1])
        except (TypeError, ValueError, IndexError) as exc:
            raise InputError(f"not a place name or [x, y] point: {a!r}") from exc
        return (x, y)

    def distance(self, a: Place, b: Place) -> float:
        """Length in metres of the shortest obstacle-free path from a to b."""
        return self._pair(self.point(a), self.point(b))[0]

    def path(self, a: Place, b: Place) -> list[list[float]]:
        """Waypoints ``[[x, y], ...]`` from a to b (both ends included)."""
        return [list(p) for p in self._pair(self.point(a), self.point(b))[1]]

    def route_length(self, places: Sequence[Place]) -> float:
        """Length of visiting ``places`` in order."""
        return sum(self.distance(places[k], places[k + 1]) for k in range(len(places) - 1))

    # ------------------------------------------------------------------ cache
    def _key(self) -> str:
        content = {
            "format": _FORMAT,
            "floor": [self.width, self.height],
            "shelves": sorted((n, list(r)) for n, r in self.footprints.items()),
            "places": sorted((n, list(p)) for n, p in self.places.items()),
            "inflate": self.inflate,
        }
        return hashlib.sha256(json.dumps(content, sort_keys=True).encode()).hexdigest()[:24]

    def _load(self, cache_dir: str | Path | None) -> None:
        """Fill the table of named-place pairs from memory, disk, or by computing it."""
        table = _MEMORY_CACHE.get(self.key)
        file = Path(cache_dir) / f"travel-{self.key}.json" if cache_dir else None
        if table is None and file is not None and file.is_file():
            try:
                table = json.loads(file.read_text())
            except (OSError, ValueError):
                table = None
        if table is None:
            table = self._compute_table()
            if file is not None:
                file.parent.mkdir(parents=True, exist_ok=True)
                tmp = file.with_suffix(".tmp")
                tmp.write_text(json.dumps(table))
                tmp.replace(file)
        _MEMORY_CACHE[self.key] = table
        for a, b, dist, path in table["pairs"]:
            pa, pb = tuple(a), tuple(b)
            pts = [tuple(p) for p in path]
            self._pairs[(pa, pb)] = (dist, pts)
            self._pairs[(pb, pa)] = (dist, pts[::-1])

    def _compute_table(self) -> dict:
        """Distances and paths from every shelf access point to every place.

        Robots only ever travel start -> access point and access point -> access point, so one
        Dijkstra per shelf over the visibility graph covers every leg a schedule can contain."""
        import networkx as nx

        g = self._graph_with(list(self.places.values()))
        shelves = [n for n in self.places if n in self.footprints]
        points = sorted(set(self.places.values()))
        pairs = []
        done: set[tuple[Point, Point]] = set()
        for s in shelves:
            src = self.places[s]
            dist, paths = nx.single_source_dijkstra(g, src, weight="weight")
            for p in points:
                if (src, p) in done or (p, src) in done:
                    continue
                done.add((src, p))
                if p not in paths:
                    raise InputError(f"no obstacle-free path from {s} to {list(p)}")
                pairs.append([list(src), list(p), dist[p], [list(q) for q in paths[p]]])
        return {"key": self.key, "pairs": pairs}

    # ------------------------------------------------------------------ geometry
    def _check_point(self, p: Point, name: str) -> None:
        if not (0 <= p[0] <= self.width and 0 <= p[1] <= self.height):
            raise InputError(f"{name} at {list(p)} is off the floor ({self.width} x {self.height} m)")
        for shelf, (x0, y0, x1, y1) in self.footprints.items():
            if x0 < p[0] < x1 and y0 < p[1] < y1:
                raise InputError(f"{name} at {list(p)} is inside the footprint of {shelf}")

    def _visible(self, a: Point, b: Point) -> bool:
        return bool(_visible_from(a, [b], self.obstacles, self._cores)[0])

    def _corners(self) -> list[Point]:
        """Corners of the inflated footprints that a robot can stand on: on the floor and not
        strictly inside another inflated footprint."""
        out = []
        for (x0, y0, x1, y1) in self.obstacles:
            for c in ((x0, y0), (x0, y1), (x1, y0), (x1, y1)):
                if not (0 <= c[0] <= self.width and 0 <= c[1] <= self.height):
                    continue
                if any(a < c[0] < b and d < c[1] < e for (a, d, b, e) in self.obstacles):
                    continue
                out.append(c)
        return sorted(set(out))

    def _visibility(self):
        """The visibility graph among the free corners (built lazily: a warm cache never needs it)."""
        if self._graph is None:
            import networkx as nx

            g = nx.Graph()
            corners = self._corners()
            g.add_nodes_from(corners)
            _connect(g, corners, corners, self.obstacles, self._cores)
            self._graph = g
        return self._graph

    def _graph_with(self, points: list[Point]):
        """A copy of the visibility graph with ``points`` added and joined to what they see."""
        g = self._visibility().copy()
        extra = [p for p in dict.fromkeys(points) if p not in g]
        g.add_nodes_from(extra)
        _connect(g, extra, list(g.nodes), self.obstacles, self._cores)
        return g

    def _pair(self, a: Point, b: Point) -> tuple[float, list[Point]]:
        hit = self._pairs.get((a, b))
        if hit is not None:
            return hit
        import networkx as nx

        self._check_point(a, "point")
        self._check_point(b, "point")
        if a == b:
            res = (0.0, [a, b])
        elif self._visible(a, b):
            res = (math.dist(a, b), [a, b])
        else:
            try:
                d, nodes = nx.single_source_dijkstra(self._graph_with([a, b]), a, b, weight="weight")
            except nx.NetworkXNoPath:
                raise InputError(f"no obstacle-free path from {list(a)} to {list(b)}") from None
            res = (d, [tuple(q) for q in nodes])
        self._pairs[(a, b)] = res
        self._pairs[(b, a)] = (res[0], res[1][::-1])
        return res


def _hits(a: Point, b: Any, r: Any) -> Any:
    """(targets x rects) matrix: whether the segment from ``a`` to each target passes through
    the open interior of each rectangle (Liang-Barsky clipping, as :func:`_rect_hits_segment`,
    for all pairs at once)."""
    import numpy as np

    dx = (b[:, 0] - a[0])[:, None]
    dy = (b[:, 1] - a[1])[:, None]
    t0 = np.zeros((len(b), len(r)))
    t1 = np.ones((len(b), len(r)))
    miss = np.zeros((len(b), len(r)), dtype=bool)
    for p, q in ((-dx, a[0] - r[:, 0]), (dx, r[:, 2] - a[0]), (-dy, a[1] - r[:, 1]), (dy, r[:, 3] - a[1])):
        q = np.broadcast_to(q, t0.shape)
        p = np.broadcast_to(p, t0.shape)
        parallel = np.abs(p) < 1e-12
        miss |= parallel & (q <= 1e-9)
        with np.errstate(divide="ignore", invalid="ignore"):
            t = np.where(parallel, 0.0, q / np.where(parallel, 1.0, p))
        t0 = np.where(~parallel & (p < 0), np.maximum(t0, t), t0)
        t1 = np.where(~parallel & (p > 0), np.minimum(t1, t), t1)
    tm = (t0 + t1) / 2
    mx, my = a[0] + dx * tm, a[1] + dy * tm
    eps = 1e-9
    inside = (r[:, 0] + eps < mx) & (mx < r[:, 2] - eps) & (r[:, 1] + eps < my) & (my < r[:, 3] - eps)
    return ~miss & (t0 < t1 - 1e-9) & inside


def _visible_from(a: Point, targets: Sequence[Point], rects: Sequence[tuple], cores: Sequence[tuple]) -> Any:
    """For each target, whether the segment from ``a`` keeps out of every inflated footprint
    (``rects``). An end point within a footprint's safety margin (a robot parked close to a
    shelf) may leave or reach it: for that footprint only the real one (``cores``) blocks."""
    import numpy as np

    b = np.asarray(targets, dtype=float).reshape(-1, 2)
    if not len(rects):
        return np.ones(len(b), dtype=bool)
    r, c = np.asarray(rects, dtype=float), np.asarray(cores, dtype=float)
    in_a = (r[:, 0] < a[0]) & (a[0] < r[:, 2]) & (r[:, 1] < a[1]) & (a[1] < r[:, 3])
    bx, by = b[:, 0][:, None], b[:, 1][:, None]
    in_b = (r[:, 0] < bx) & (bx < r[:, 2]) & (r[:, 1] < by) & (by < r[:, 3])
    hits = np.where(in_a | in_b, _hits(a, b, c), _hits(a, b, r))
    return ~hits.any(axis=1)


def _connect(g: Any, sources: list[Point], targets: list[Point], rects: Sequence[tuple],
             cores: Sequence[tuple]) -> None:
    """Add an edge, weighted by length, between every source and every target it can see."""
    if not targets:
        return
    for a in sources:
        seen = _visible_from(a, targets, rects, cores)
        for b, ok in zip(targets, seen):
            if ok and b != a:
                g.add_edge(a, b, weight=math.dist(a, b))

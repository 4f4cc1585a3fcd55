"""Travel on the warehouse floor: obstacle-free shortest paths between places and robot starts.

Why a grid and not straight lines: the paper's cost ``c_i`` is a robot's travel distance, and
robots cannot drive through shelves. A straight-line distance would make a robot behind a shelf
look as cheap as one in front of it, so allocation and TC-max/TC-avg would be wrong.

The floor is sampled as an 8-connected grid (default 0.5 m). Shelf footprints, inflated by a
small margin (robot radius), block the cells inside them; diagonal steps may not cut a blocked
corner. Paths found on the grid are then shortened by string pulling against the exact inflated
rectangles (optional, default on), so distances are close to the true any-angle geodesic rather
than carrying the grid's up-to-8% zig-zag overhead. ``distance`` is always the length of the
path ``path`` returns, so allocation costs and schedule legs agree.

Everything a run needs (distances and paths between every shelf access point and every robot
start) is computed once per world and cached in memory, and optionally on disk keyed by a hash
of the world's geometry, so the many allocation calls of a run, and repeated runs, are cheap.
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
_FORMAT = 1


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

    def __init__(
        self,
        world: dict,
        resolution: float = 0.5,
        inflate: float = 0.3,
        smooth: bool = True,
        cache_dir: str | Path | None = None,
    ):
        if resolution <= 0:
            raise InputError(f"travel grid resolution must be positive, got {resolution}")
        self.world = world
        self.resolution = float(resolution)
        self.inflate = float(inflate)
        self.smooth = bool(smooth)
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
            "resolution": self.resolution, "inflate": self.inflate, "smooth": self.smooth,
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
        Dijkstra per shelf covers every leg a schedule can contain."""
        import networkx as nx

        g = self._grid()
        shelves = [n for n in self.places if n in self.footprints]
        points = sorted(set(self.places.values()))
        pairs = []
        done: set[tuple[Point, Point]] = set()
        for s in shelves:
            src = self.places[s]
            src_node = self._snap(src)
            dist, paths = nx.single_source_dijkstra(g, src_node, weight="weight")
            for p in points:
                if (src, p) in done or (p, src) in done:
                    continue
                done.add((src, p))
                d, path = self._finish(src, p, paths.get(self._snap(p)))
                pairs.append([list(src), list(p), d, [list(q) for q in path]])
        return {"key": self.key, "pairs": pairs}

    # ------------------------------------------------------------------ geometry
    def _check_point(self, p: Point, name: str) -> None:
        if not (0 <= p[0] <= self.width and 0 <= p[1] <= self.height):
            raise InputError(f"{name} at {list(p)} is off the floor ({self.width} x {self.height} m)")
        for shelf, (x0, y0, x1, y1) in self.footprints.items():
            if x0 < p[0] < x1 and y0 < p[1] < y1:
                raise InputError(f"{name} at {list(p)} is inside the footprint of {shelf}")

    def _blocked(self, x: float, y: float) -> bool:
        return any(x0 < x < x1 and y0 < y < y1 for (x0, y0, x1, y1) in self.obstacles)

    def _visible(self, a: Point, b: Point) -> bool:
        return not any(_rect_hits_segment(r, a, b) for r in self.obstacles)

    def _grid(self):
        """The 8-connected free-space grid (built lazily: a warm cache never needs it)."""
        if self._graph is not None:
            return self._graph
        import networkx as nx

        r = self.resolution
        nx_, ny_ = int(math.floor(self.width / r + 1e-9)), int(math.floor(self.height / r + 1e-9))
        free = {(i, j) for i in range(nx_ + 1) for j in range(ny_ + 1) if not self._blocked(i * r, j * r)}
        g = nx.Graph()
        g.add_nodes_from(free)
        diag = r * math.sqrt(2)
        for (i, j) in free:
            for di, dj in ((1, 0), (0, 1), (1, 1), (1, -1)):
                n = (i + di, j + dj)
                if n not in free:
                    continue
                if di and dj:
                    # no corner cutting: both orthogonal neighbours free and the diagonal clear
                    if (i + di, j) not in free or (i, j + dj) not in free:
                        continue
                    if not self._visible((i * r, j * r), (n[0] * r, n[1] * r)):
                        continue
                    g.add_edge((i, j), n, weight=diag)
                else:
                    if not self._visible((i * r, j * r), (n[0] * r, n[1] * r)):
                        continue
                    g.add_edge((i, j), n, weight=r)
        self._graph = g
        return g

    def _snap(self, p: Point) -> tuple[int, int]:
        """The nearest free grid node that p can reach in a straight line."""
        g = self._grid()
        r = self.resolution
        ci, cj = round(p[0] / r), round(p[1] / r)
        best, best_d = None, math.inf
        for rad in range(0, 8):
            for i in range(ci - rad, ci + rad + 1):
                for j in range(cj - rad, cj + rad + 1):
                    if (i, j) not in g or max(abs(i - ci), abs(j - cj)) != rad:
                        continue
                    q = (i * r, j * r)
                    d = math.dist(p, q)
                    if d < best_d and self._visible(p, q):
                        best, best_d = (i, j), d
            if best is not None:
                return best
        raise InputError(f"point {list(p)} is not reachable: no free floor near it")

    def _finish(self, a: Point, b: Point, nodes: list | None) -> tuple[float, list[Point]]:
        """Turn a grid node path into a point path from a to b, smoothed if asked."""
        if a == b:
            return 0.0, [a, b]
        if nodes is None:
            raise InputError(f"no obstacle-free path from {list(a)} to {list(b)}")
        r = self.resolution
        pts = [a] + [(i * r, j * r) for (i, j) in nodes] + [b]
        # drop duplicates (a point exactly on a grid node)
        dedup = [pts[0]]
        for q in pts[1:]:
            if math.dist(q, dedup[-1]) > 1e-12:
                dedup.append(q)
        pts = dedup if len(dedup) > 1 else [a, b]
        if self.smooth:
            pts = self._string_pull(pts)
        return _length(pts), pts

    def _string_pull(self, pts: list[Point]) -> list[Point]:
        """Greedy line-of-sight shortcutting: from each kept point jump to the farthest visible
        one. Exact against the inflated rectangles, so the shortened path stays obstacle-free."""
        out = [pts[0]]
        k = 0
        while k < len(pts) - 1:
            nxt = k + 1
            for m in range(len(pts) - 1, k + 1, -1):
                if self._visible(pts[k], pts[m]):
                    nxt = m
                    break
            out.append(pts[nxt])
            k = nxt
        return out

    def _pair(self, a: Point, b: Point) -> tuple[float, list[Point]]:
        hit = self._pairs.get((a, b))
        if hit is not None:
            return hit
        import networkx as nx

        self._check_point(a, "point")
        self._check_point(b, "point")
        if a == b:
            res = (0.0, [a, b])
        elif self.smooth and self._visible(a, b):
            res = (math.dist(a, b), [a, b])
        else:
            g = self._grid()
            try:
                nodes = nx.shortest_path(g, self._snap(a), self._snap(b), weight="weight")
            except nx.NetworkXNoPath:
                nodes = None
            res = self._finish(a, b, nodes)
        self._pairs[(a, b)] = res
        self._pairs[(b, a)] = (res[0], res[1][::-1])
        return res

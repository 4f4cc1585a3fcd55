"""Travel on the floor: exact obstacle-free shortest paths between places and robot starts.

Why not straight lines: the paper's cost ``c_i`` is a robot's travel distance, and robots cannot
drive through shelves. A straight-line distance would make a robot behind a shelf look as cheap
as one in front of it, so allocation and TC-max/TC-avg would be wrong.

Shelf footprints, inflated by a small margin (robot radius), are rectangular obstacles. Among
convex polygonal obstacles a shortest path bends only at obstacle corners, so the **visibility
graph** (nodes: the free corners of the inflated rectangles plus the fixtures' access points;
edges: pairs that see each other) holds every shortest path between them, and Dijkstra on it
gives exact any-angle geodesics. ``distance`` is always the length of the path ``path`` returns,
so allocation costs and schedule legs agree.

Why it is built this way (scale): a run asks for the distances from a few hundred or thousand
robot starts to the access points of the shelves its subtasks visit, and between those access
points. So nothing is computed for all pairs up front:

* the graph has only corners and access points (a robot start is never a bend of a shortest path,
  so robots are not nodes: adding a thousand of them made a dense graph of a million edges);
  visibility is tested for all candidate segments at once with numpy, after a bounding-box
  filter, and the graph is a ``scipy.sparse`` matrix;
* one ``scipy.sparse.csgraph.dijkstra(indices=[target])`` per access point a run actually goes
  to, computed when first asked and kept (distances and predecessors: 2 x nodes numbers); a
  graph of at most :data:`SMALL_GRAPH` nodes is searched with networkx's Dijkstra instead, the
  same tree without importing ``scipy.sparse`` (about 0.2 s of CPU, a seventh of the main job,
  for a 20-node graph networkx searches in a millisecond);
* a robot start (or any point) is joined to the graph by the nodes it sees, once per point:
  ``d(p, t) = min over nodes v seen from p of |p - v| + d(v, t)``, with ``t`` itself among them
  when ``p`` sees it directly.

Memory is linear in what is asked: the graph (corners x their visible neighbours), one tree per
target asked, one visibility row per start asked. The geometry (graph and trees) is shared by all
``TravelMap`` objects of the same floor in a process (allocation, schedule and simulation each
make one), keyed by a hash of the floor, the footprints, the access points and the margin.
"""
from __future__ import annotations

import hashlib
import json
import math
import threading
from collections import OrderedDict
from typing import Any, Sequence, Union

import networkx as nx
import numpy as np

from pipflow.errors import InputError
from pipflow.taskdomains import task_domain

Point = tuple[float, float]
Place = Union[str, Sequence[float]]

_EPS = 1e-9
_GEOMETRIES: OrderedDict[str, "_Geometry"] = OrderedDict()  # floor key -> shared geometry
_GEOMETRIES_MAX = 8
#: most nodes (corners and access points: 16 shelves) searched with networkx rather than scipy
SMALL_GRAPH = 64
_GEOMETRIES_LOCK = threading.Lock()


def clip_segment(a: Point, b: Point, rect: tuple[float, float, float, float]) -> tuple[float, float] | None:
    """The shares (t0, t1) of segment a-b that lie in the open rectangle (x0, y0, x1, y1), by
    Liang-Barsky clipping; None when no piece of positive length does (a segment along an edge
    stays outside)."""
    x0, y0, x1, y1 = rect
    dx, dy = b[0] - a[0], b[1] - a[1]
    t0, t1 = 0.0, 1.0
    for p, q in ((-dx, a[0] - x0), (dx, x1 - a[0]), (-dy, a[1] - y0), (dy, y1 - a[1])):
        if abs(p) < 1e-12:
            if q <= _EPS:
                return None
        else:
            t = q / p
            if p < 0:
                t0 = max(t0, t)
            else:
                t1 = min(t1, t)
            if t0 >= t1 - _EPS:
                return None
    return t0, t1


def _rect_hits_segment(rect: tuple[float, float, float, float], a: Point, b: Point) -> bool:
    """True when segment a-b passes through the open rectangle (x0, y0, x1, y1).

    Touching the boundary does not count, so paths may graze the inflated footprint (the
    inflation already keeps robots off the real shelf): the clipped piece must have its midpoint
    strictly inside."""
    clipped = clip_segment(a, b, rect)
    if clipped is None:
        return False
    x0, y0, x1, y1 = rect
    t = (clipped[0] + clipped[1]) / 2
    mx, my = a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t
    return x0 + _EPS < mx < x1 - _EPS and y0 + _EPS < my < y1 - _EPS


def _blocked(ax: Any, ay: Any, bx: np.ndarray, by: np.ndarray, x0: np.ndarray,
             y0: np.ndarray, x1: np.ndarray, y1: np.ndarray) -> np.ndarray:
    """Element-wise: does segment (ax, ay)-(bx, by) pass through the open rectangle (x0, y0, x1, y1)?
    (:func:`_rect_hits_segment` for arrays of pairs.)

    Liang-Barsky clipping of the segment to the rectangle; the clipped piece must have positive
    length and its midpoint must lie strictly inside (so a segment along an edge or through a
    corner is not blocked)."""
    dx, dy = bx - ax, by - ay
    ax, ay = np.broadcast_to(ax, dx.shape), np.broadcast_to(ay, dx.shape)
    t0 = np.zeros_like(dx)
    t1 = np.ones_like(dx)
    miss = np.zeros(dx.shape, dtype=bool)
    with np.errstate(divide="ignore", invalid="ignore"):
        for p, q in ((-dx, ax - x0), (dx, x1 - ax), (-dy, ay - y0), (dy, y1 - ay)):
            parallel = np.abs(p) < 1e-12
            miss |= parallel & (q <= _EPS)
            t = q / p  # inf or nan where parallel: masked out below
            np.maximum(t0, t, out=t0, where=~parallel & (p < 0))
            np.minimum(t1, t, out=t1, where=~parallel & (p > 0))
    tm = (t0 + t1) / 2
    mx, my = ax + dx * tm, ay + dy * tm
    inside = (x0 + _EPS < mx) & (mx < x1 - _EPS) & (y0 + _EPS < my) & (my < y1 - _EPS)
    return ~miss & (t0 < t1 - _EPS) & inside


def _shown(p: Any) -> str:
    """A point as a message shows it: ``[9.6, 1.2]`` (never numpy's ``np.float64(9.6)``)."""
    return "[" + ", ".join(f"{float(v):g}" for v in p) + "]"


def _visible_from(a: Point, targets: np.ndarray, rects: np.ndarray, cores: np.ndarray) -> np.ndarray:
    """For each target (rows of an (n, 2) array), whether the segment from ``a`` keeps out of every
    inflated footprint (``rects``, (m, 4) arrays of x0, y0, x1, y1). An end point within a
    footprint's safety margin (a robot parked close to a shelf) may leave or reach it: for that
    footprint only the real one (``cores``) blocks.

    Only (target, rectangle) pairs whose bounding boxes overlap are clipped exactly, so the cost
    follows the rectangles near each segment rather than all of them."""
    n = len(targets)
    if not len(rects) or not n:
        return np.ones(n, dtype=bool)
    rx0, ry0, rx1, ry1 = np.ascontiguousarray(rects.T)
    ax, ay = float(a[0]), float(a[1])
    bx, by = targets[:, 0], targets[:, 1]
    lo_x, hi_x = np.minimum(ax, bx)[:, None], np.maximum(ax, bx)[:, None]
    lo_y, hi_y = np.minimum(ay, by)[:, None], np.maximum(ay, by)[:, None]
    near = rx0 < hi_x
    near &= lo_x < rx1
    near &= ry0 < hi_y
    near &= lo_y < ry1
    ti, ri = np.nonzero(near)
    if not len(ti):
        return np.ones(n, dtype=bool)
    x0, y0, x1, y1 = rx0[ri], ry0[ri], rx1[ri], ry1[ri]
    px, py = bx[ti], by[ti]
    in_a = ((rx0 < ax) & (ax < rx1) & (ry0 < ay) & (ay < ry1))[ri]
    special = in_a | ((x0 < px) & (px < x1) & (y0 < py) & (py < y1))
    if special.any():  # an end in a footprint's margin: only that footprint's core blocks
        k = ri[special]
        x0[special], y0[special], x1[special], y1[special] = cores[k, 0], cores[k, 1], cores[k, 2], cores[k, 3]
    hit = _blocked(ax, ay, px, py, x0, y0, x1, y1)
    seen = np.ones(n, dtype=bool)
    seen[ti[hit]] = False
    return seen


class _Geometry:
    """The visibility graph of one floor and the shortest-path trees asked of it so far.

    Shared between TravelMap objects of the same floor (see the module docstring); its lazily
    filled tables are guarded by a lock because steps may run in threads (``--jobs``)."""

    def __init__(self, width: float, height: float, rects: np.ndarray, cores: np.ndarray,
                 anchors: list[Point]):
        self.width, self.height = width, height
        self.rects, self.cores = rects, cores
        corners = self._corners()
        nodes = list(dict.fromkeys(list(corners) + list(anchors)))
        self.nodes = np.asarray(nodes, dtype=float).reshape(-1, 2)
        self.index = {p: i for i, p in enumerate(nodes)}
        # per node: its rectangle and the quadrant that rectangle occupies, for the tangency test
        # (-1: an access point, or a corner shared with or touching another footprint: never pruned)
        self._rect = np.full(len(nodes), -1)
        self._quad = np.zeros((len(nodes), 2))
        anchor_set = set(anchors)
        for p, (k, sx, sy) in corners.items():
            if k >= 0 and p not in anchor_set:
                i = self.index[p]
                self._rect[i], self._quad[i] = k, (sx, sy)
        self.anchors = list(anchors)
        self._graph = None
        self._edges: tuple[np.ndarray, np.ndarray, np.ndarray] | None = None
        self._small: nx.Graph | None = None
        self._trees: dict[int, tuple[np.ndarray, np.ndarray]] = {}  # target node -> (dist, pred)
        self._seen: dict[Point, tuple[np.ndarray, np.ndarray]] = {}  # point -> (nodes seen, lengths)
        self.lock = threading.RLock()

    def _corners(self) -> dict[Point, tuple[int, float, float]]:
        """Corners of the inflated footprints that a robot can stand on (on the floor and not
        strictly inside another inflated footprint), in sorted order, each with ``(rectangle,
        sx, sy)``: the rectangle lies towards ``(sx, sy)`` from the corner. A corner that touches
        another footprint (or is two rectangles' corner) gets rectangle -1."""
        if not len(self.rects):
            return {}
        r = self.rects
        n = len(r)
        c = np.concatenate([r[:, [0, 1]], r[:, [0, 3]], r[:, [2, 1]], r[:, [2, 3]]])
        own = np.tile(np.arange(n), 4)
        sign = np.repeat(np.array([[1, 1], [1, -1], [-1, 1], [-1, -1]], dtype=float), n, axis=0)
        on_floor = (c[:, 0] >= 0) & (c[:, 0] <= self.width) & (c[:, 1] >= 0) & (c[:, 1] <= self.height)
        inside = ((r[:, 0] < c[:, [0]]) & (c[:, [0]] < r[:, 2]) & (r[:, 1] < c[:, [1]])
                  & (c[:, [1]] < r[:, 3])).any(axis=1)
        touches = ((r[:, 0] <= c[:, [0]]) & (c[:, [0]] <= r[:, 2]) & (r[:, 1] <= c[:, [1]])
                   & (c[:, [1]] <= r[:, 3])).sum(axis=1) > 1  # on the closed boundary of another one too
        out: dict[Point, tuple[int, float, float]] = {}
        for i in np.nonzero(on_floor & ~inside)[0]:
            p = (float(c[i, 0]), float(c[i, 1]))
            k = -1 if touches[i] or p in out else int(own[i])
            out[p] = (k, float(sign[i, 0]), float(sign[i, 1]))
        return dict(sorted(out.items()))

    def _tangent(self, p: np.ndarray, v: np.ndarray) -> np.ndarray:
        """Element-wise over node indices ``v`` and points ``p`` ((n, 2) or one (2,)): can a
        shortest path from ``p`` bend at corner v? Why it holds: a geodesic bends only around the
        obstacle at v; when p lies in the quadrant of v's rectangle (beyond it: the segment is
        blocked) or in the opposite quadrant (the path p-v-w can be shortened near v), v is never
        the next bend. Access points and corners touching other footprints are always kept, and
        so is a corner whose rectangle holds p in its safety margin."""
        k = self._rect[v]
        d = (p - self.nodes[v]) * self._quad[v]
        r = self.rects[np.maximum(k, 0)]
        p = np.broadcast_to(p, d.shape)
        in_rect = (r[:, 0] < p[:, 0]) & (p[:, 0] < r[:, 2]) & (r[:, 1] < p[:, 1]) & (p[:, 1] < r[:, 3])
        return (k < 0) | in_rect | (d[:, 0] * d[:, 1] <= 0)

    def graph(self) -> Any:
        """The visibility graph as a symmetric sparse matrix of segment lengths (built once)."""
        with self.lock:
            if self._graph is None:
                self._graph = self._build_graph()
            return self._graph

    def _build_graph(self) -> Any:
        from scipy.sparse import csr_matrix  # heavy: only runs that search a large graph pay for it

        r, c, w = self.edges()
        k = len(self.nodes)
        return csr_matrix((np.concatenate([w, w]), (np.concatenate([r, c]), np.concatenate([c, r]))), shape=(k, k))

    def edges(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """The visibility graph's edges, each once: node indices ``r < c`` and lengths ``w``."""
        with self.lock:
            if self._edges is None:
                self._edges = self._build_edges()
            return self._edges

    def _build_edges(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        rows, cols = [], []
        k = len(self.nodes)
        for i in range(k - 1):
            a = (self.nodes[i, 0], self.nodes[i, 1])
            later = np.arange(i + 1, k)
            # an edge can be on a shortest path only if it is tangent at both of its ends
            later = later[self._tangent(self.nodes[i], later)
                          & self._tangent(self.nodes[later], np.full(len(later), i))]
            seen = later[_visible_from(a, self.nodes[later], self.rects, self.cores)]
            rows.append(np.full(len(seen), i))
            cols.append(seen)
        r = np.concatenate(rows) if rows else np.zeros(0, dtype=int)
        c = np.concatenate(cols) if cols else np.zeros(0, dtype=int)
        w = np.hypot(*(self.nodes[r] - self.nodes[c]).T)
        return r, c, w

    def _info(self, i: int) -> tuple:
        """What decides node ``i``'s edges besides visibility: its rectangle and quadrant (the
        tangency test), or none (an access point, a corner touching another footprint)."""
        k = int(self._rect[i])
        return (None,) if k < 0 else (tuple(self.rects[k].tolist()), tuple(self._quad[i].tolist()))

    def _rows(self, i: int, others: np.ndarray) -> np.ndarray:
        """Of the nodes ``others``, those node ``i`` has an edge with (tangent at both ends, in
        sight past every footprint): :meth:`_build_edges` for one node."""
        a = (self.nodes[i, 0], self.nodes[i, 1])
        others = others[self._tangent(self.nodes[i], others) & self._tangent(self.nodes[others], np.full(len(others), i))]
        return others[_visible_from(a, self.nodes[others], self.rects, self.cores)]

    @classmethod
    def grown(cls, base: "_Geometry", rects: np.ndarray, cores: np.ndarray, anchors: list[Point]) -> "_Geometry":
        """The geometry of ``base``'s floor with more footprints and access points (a closed
        passage's barrier, a stopped robot's drop place: :mod:`pipflow.execution`), built from
        ``base``'s edges rather than from nothing: an edge between two nodes whose tangency is
        unchanged stays exactly when no new footprint blocks it (visibility is tested footprint by
        footprint, so it only ever shrinks as footprints are added), and only the new nodes and
        those whose tangency changed (a corner a new footprint touches or covers) are joined
        anew. The same graph as a build from nothing (tests/test_travel.py checks it), for the
        cost of the nodes that changed: a recovery at 100 shelves does not rebuild 14,000 edges
        for one barrier."""
        geo = cls(base.width, base.height, rects, cores, anchors)
        have = set(map(tuple, base.rects.tolist()))
        fresh = [k for k, r in enumerate(geo.rects.tolist()) if tuple(r) not in have]
        inv = np.full(len(base.nodes), -1)
        same = np.zeros(len(geo.nodes), dtype=bool)
        for p, i in geo.index.items():
            j = base.index.get(p)
            if j is not None and geo._info(i) == base._info(j):
                inv[j], same[i] = i, True
        r, c, w = base.edges()
        r, c = inv[r], inv[c]
        keep = (r >= 0) & (c >= 0)
        r, c, w = r[keep], c[keep], w[keep]
        for k in fresh:  # an old edge a new footprint blocks goes (its margin rule as in _visible_from)
            if not len(r):
                break
            ax, ay, bx, by = geo.nodes[r, 0], geo.nodes[r, 1], geo.nodes[c, 0], geo.nodes[c, 1]
            x0, y0, x1, y1 = geo.rects[k]
            near = (x0 < ax) & (ax < x1) & (y0 < ay) & (ay < y1) | (x0 < bx) & (bx < x1) & (y0 < by) & (by < y1)
            box = np.where(near[:, None], geo.cores[k][None, :], geo.rects[k][None, :])
            hit = _blocked(ax, ay, bx, by, box[:, 0], box[:, 1], box[:, 2], box[:, 3])
            r, c, w = r[~hit], c[~hit], w[~hit]
        rows, cols = [r], [c]
        changed = np.nonzero(~same)[0]
        everyone = np.arange(len(geo.nodes))
        for i in changed:  # joined anew, each pair once (a pair of two changed nodes: by the lower)
            others = everyone[(everyone != i) & (same | (everyone > i))]
            seen = geo._rows(int(i), others)
            rows.append(np.minimum(seen, i))
            cols.append(np.maximum(seen, i))
        r, c = np.concatenate(rows).astype(int), np.concatenate(cols).astype(int)
        geo._edges = (r, c, np.hypot(*(geo.nodes[r] - geo.nodes[c]).T))
        return geo

    def tree(self, target: int) -> tuple[np.ndarray, np.ndarray]:
        """Distances to node ``target`` from every node, and each node's next node towards it
        (-9999 where there is none, scipy's mark)."""
        with self.lock:
            hit = self._trees.get(target)
            if hit is None:
                small = len(self.nodes) <= SMALL_GRAPH
                hit = self._trees[target] = self._small_tree(target) if small else self._scipy_tree(target)
            return hit

    def _scipy_tree(self, target: int) -> tuple[np.ndarray, np.ndarray]:
        from scipy.sparse.csgraph import dijkstra  # heavy: deferred with the graph

        dist, pred = dijkstra(self.graph(), directed=False, indices=[target], return_predecessors=True)
        return dist[0], pred[0]

    def _small_tree(self, target: int) -> tuple[np.ndarray, np.ndarray]:
        """:meth:`_scipy_tree`'s arrays from networkx's Dijkstra (see :data:`SMALL_GRAPH`)."""
        if self._small is None:
            r, c, w = self.edges()
            self._small = nx.Graph()
            self._small.add_nodes_from(range(len(self.nodes)))
            self._small.add_weighted_edges_from(zip(r.tolist(), c.tolist(), w.tolist()))
        preds, lengths = nx.dijkstra_predecessor_and_distance(self._small, target)
        dist = np.full(len(self.nodes), np.inf)
        pred = np.full(len(self.nodes), -9999, dtype=np.int32)
        for v, length in lengths.items():
            dist[v] = length
        for v, before in preds.items():
            if before:
                pred[v] = before[0]
        return dist, pred

    def seen(self, p: Point) -> tuple[np.ndarray, np.ndarray]:
        """The nodes point ``p`` sees and the straight lengths to them (a node sees itself at 0)."""
        with self.lock:
            hit = self._seen.get(p)
            if hit is None:
                cand = np.nonzero(self._tangent(np.asarray(p, dtype=float), np.arange(len(self.nodes))))[0]
                ok = cand[_visible_from(p, self.nodes[cand], self.rects, self.cores)]
                hit = self._seen[p] = (ok, np.hypot(self.nodes[ok, 0] - p[0], self.nodes[ok, 1] - p[1]))
            return hit

    def route_to_node(self, p: Point, target: int) -> tuple[float, list[Point]]:
        """Shortest path from point ``p`` to node ``target``: the best first node ``p`` sees, then
        the tree's predecessors."""
        dist, pred = self.tree(target)
        ok, lengths = self.seen(p)
        total = lengths + dist[ok]
        if not len(ok) or not np.isfinite(total).any():
            raise InputError(f"no obstacle-free path from {_shown(p)} to {_shown(self.nodes[target])}")
        best = int(np.argmin(total))
        v = int(ok[best])
        path = [p] if lengths[best] > 0 else []
        while v != target:
            path.append((float(self.nodes[v, 0]), float(self.nodes[v, 1])))
            v = int(pred[v])
        path.append((float(self.nodes[target, 0]), float(self.nodes[target, 1])))
        return float(total[best]), path

    def route_between_points(self, a: Point, b: Point) -> tuple[float, list[Point]]:
        """Shortest path between two points neither of which is a node: Dijkstra from ``a`` on
        the graph with ``a`` and ``b`` joined to the nodes they see (rare: tests, odd callers)."""
        from scipy.sparse import bmat, csr_matrix
        from scipy.sparse.csgraph import dijkstra

        k = len(self.nodes)
        extra = np.zeros((2, k))
        for row, p in enumerate((a, b)):
            ok, lengths = self.seen(p)
            extra[row, ok] = lengths
        ab = np.zeros((2, 2))
        if _visible_from(a, np.asarray([b]), self.rects, self.cores)[0]:
            ab[0, 1] = ab[1, 0] = math.dist(a, b)
        g = bmat([[self.graph(), csr_matrix(extra.T)], [csr_matrix(extra), csr_matrix(ab)]], format="csr")
        dist, pred = dijkstra(g, directed=False, indices=[k], return_predecessors=True)
        if not np.isfinite(dist[0, k + 1]):
            raise InputError(f"no obstacle-free path from {_shown(a)} to {_shown(b)}")
        path, v = [], k + 1
        while v != k:
            path.append(b if v == k + 1 else (float(self.nodes[v, 0]), float(self.nodes[v, 1])))
            v = int(pred[0, v])
        path.append(a)
        return float(dist[0, k + 1]), path[::-1]


class TravelMap:
    """Shortest obstacle-free travel between points or named places of one world.

    Places are the names of the world's fixtures (its task domain's
    :meth:`~pipflow.taskdomain.TaskDomain.places`: standing at the fixture's ``access`` point) and
    robot names (the robot's ``start``); points are ``[x, y]`` in metres.

    >>> tm = TravelMap(world)                       # doctest: +SKIP
    >>> tm.distance("robot0", "shelf3"), tm.path("shelf1", [20, 2])   # doctest: +SKIP
    """

    def __init__(self, world: dict, inflate: float = 0.3):
        self.world = world
        self.inflate = float(inflate)
        floor = world.get("floor") or {}
        try:
            self.width = float(floor["width"])
            self.height = float(floor["height"])
        except (KeyError, TypeError) as exc:
            raise InputError("world has no floor {width, height}") from exc
        fixtures = task_domain(world).places(world)  # footprints with access points, in any domain
        # barriers: footprints without an access point (a passage found closed during a run,
        # pipflow.execution): paths go around them like around any fixture
        blocked = {f"barrier {k + 1}": b for k, b in enumerate(world.get("barriers") or [])}
        self.footprints = {
            name: (float(s["x"]), float(s["y"]), float(s["x"]) + float(s["width"]),
                   float(s["y"]) + float(s["depth"]))
            for name, s in {**fixtures, **blocked}.items()
        }
        self.obstacles = [
            (x0 - self.inflate, y0 - self.inflate, x1 + self.inflate, y1 + self.inflate)
            for (x0, y0, x1, y1) in self.footprints.values()
        ]
        self._rects = np.asarray(self.obstacles, dtype=float).reshape(-1, 4)
        self._cores = np.asarray(list(self.footprints.values()), dtype=float).reshape(-1, 4)
        self.places: dict[str, Point] = {}
        for name, s in fixtures.items():
            self.places[name] = (float(s["access"][0]), float(s["access"][1]))
        for name, r in (world.get("robots") or {}).items():
            self.places[name] = (float(r["start"][0]), float(r["start"][1]))
        self._check_points(self.places)
        self._valid: set[Point] = set(self.places.values())  # points already checked
        self.key = self._key(self.places)
        self._anchors = [self.places[n] for n in fixtures]
        self._floor_key = self._key({n: self.places[n] for n in fixtures})
        self._geo: _Geometry | None = None
        self._pairs: dict[tuple[Point, Point], tuple[float, list[Point]]] = {}

    # ------------------------------------------------------------------ public API
    def point(self, a: Place) -> Point:
        """The floor point of a place name or an ``[x, y]`` point."""
        if isinstance(a, str):
            if a not in self.places:
                raise InputError(
                    f"unknown place {a!r}; places are the world's fixtures and robots: {', '.join(sorted(self.places))}")
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

    # ------------------------------------------------------------------ geometry
    def _key(self, places: dict[str, Point]) -> str:
        content = {
            "floor": [self.width, self.height],
            "footprints": sorted((n, list(r)) for n, r in self.footprints.items()),
            "places": sorted((n, list(p)) for n, p in places.items()),
            "inflate": self.inflate,
        }
        return hashlib.sha256(json.dumps(content, sort_keys=True).encode()).hexdigest()[:24]

    def geometry(self) -> _Geometry:
        """The floor's shared visibility graph (built on first use)."""
        if self._geo is None:
            with _GEOMETRIES_LOCK:
                geo = _GEOMETRIES.get(self._floor_key)
                if geo is None:
                    base = self._base()
                    geo = (_Geometry.grown(base, self._rects, self._cores, self._anchors) if base is not None
                           else _Geometry(self.width, self.height, self._rects, self._cores, self._anchors))
                    _GEOMETRIES[self._floor_key] = geo
                    while len(_GEOMETRIES) > _GEOMETRIES_MAX:
                        _GEOMETRIES.popitem(last=False)
                else:
                    _GEOMETRIES.move_to_end(self._floor_key)
            self._geo = geo
        return self._geo

    def _base(self) -> "_Geometry | None":
        """A built geometry of this floor with some of these footprints and access points and no
        others (the floor before a passage closed or a robot stopped), to grow rather than build
        from nothing; None when there is none. The caller holds the lock."""
        mine = set(map(tuple, self._rects.tolist()))
        anchors = set(self._anchors)
        for geo in reversed(_GEOMETRIES.values()):
            if (geo.width, geo.height) == (self.width, self.height) and geo._edges is not None \
                    and set(map(tuple, geo.rects.tolist())) <= mine and set(geo.anchors) <= anchors:
                return geo
        return None

    def _check_points(self, named: dict[str, Point]) -> None:
        """Every point on the floor and outside every footprint (all at once: a thousand robots)."""
        if not named:
            return
        pts = np.asarray(list(named.values()), dtype=float)
        off = (pts[:, 0] < 0) | (pts[:, 0] > self.width) | (pts[:, 1] < 0) | (pts[:, 1] > self.height)
        if off.any():
            name, p = list(named.items())[int(np.argmax(off))]
            raise InputError(f"{name} at {list(p)} is off the floor ({self.width} x {self.height} m)")
        c = self._cores
        inside = ((c[:, 0] < pts[:, [0]]) & (pts[:, [0]] < c[:, 2]) & (c[:, 1] < pts[:, [1]])
                  & (pts[:, [1]] < c[:, 3]))
        if inside.any():
            i, j = np.argwhere(inside)[0]
            name, p = list(named.items())[int(i)]
            raise InputError(f"{name} at {list(p)} is inside the footprint of {list(self.footprints)[int(j)]}")

    def _pair(self, a: Point, b: Point) -> tuple[float, list[Point]]:
        hit = self._pairs.get((a, b))
        if hit is not None:
            return hit
        for p in (a, b):
            if p not in self._valid:
                self._check_points({"point": p})
                self._valid.add(p)
        if a == b:
            res = (0.0, [a, b])
        else:
            geo = self.geometry()
            if b in geo.index:
                res = geo.route_to_node(a, geo.index[b])
            elif a in geo.index:
                d, path = geo.route_to_node(b, geo.index[a])
                res = (d, path[::-1])
            else:
                res = geo.route_between_points(a, b)
            if len(res[1]) == 1:  # a is the node itself: a path has both ends
                res = (res[0], [a, b])
        self._pairs[(a, b)] = res
        self._pairs[(b, a)] = (res[0], res[1][::-1])
        return res

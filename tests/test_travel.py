"""Travel distances: obstacle-free, symmetric, cached, and never shorter than a straight line."""
import math
from pathlib import Path

import pytest
import yaml

from pipflow.errors import InputError
from pipflow.team.travel import TravelMap, _rect_hits_segment

FIX = Path(__file__).parent / "fixtures" / "robot"
WAREHOUSE = Path(__file__).parents[1] / "benchmarks" / "warehouse" / "world.yaml"


@pytest.fixture(scope="module")
def world():
    return yaml.safe_load(WAREHOUSE.read_text())


def _crosses_shelf(tm: TravelMap, path) -> bool:
    return any(_rect_hits_segment(r, tuple(path[k]), tuple(path[k + 1]))
               for r in tm.footprints.values() for k in range(len(path) - 1))


def test_paths_avoid_shelves_and_are_at_least_straight(world):
    tm = TravelMap(world)
    names = list(world["shelves"]) + list(world["robots"])
    for a in names:
        for b in world["shelves"]:
            p = tm.path(a, b)
            d = tm.distance(a, b)
            assert p[0] == list(tm.point(a)) and p[-1] == list(tm.point(b))
            assert not _crosses_shelf(tm, p), (a, b, p)
            assert d >= math.dist(tm.point(a), tm.point(b)) - 1e-9
            assert d == pytest.approx(sum(math.dist(p[k], p[k + 1]) for k in range(len(p) - 1)))
            assert d == pytest.approx(tm.distance(b, a))


def test_detour_around_a_shelf(world):
    tm = TravelMap(world)
    # shelf1's access (7, 12) to shelf3's access (7, 4): shelf3 (y 5..7) is in the way
    straight = 8.0
    d = tm.distance("shelf1", "shelf3")
    # the exact geodesic bends at two corners of shelf3's footprint inflated by 0.3 m:
    # (7, 12) -> (2.7, 7.3) -> (2.7, 4.7) -> (7, 4)
    exact = math.dist((7, 12), (2.7, 7.3)) + 2.6 + math.dist((2.7, 4.7), (7, 4))
    assert d == pytest.approx(exact)
    assert tm.distance([1, 1], [1, 3]) == pytest.approx(2.0)  # open floor: straight
    assert d > straight


def test_a_robot_parked_within_the_safety_margin_still_goes_round_the_shelf(world):
    """A start 0.2 m below shelf3 (inside the 0.3 m margin, outside the footprint) can leave,
    but its path to shelf1 must not cut through shelf3."""
    near = dict(world, robots=dict(world["robots"], robot0={"start": [7, 4.8], "skills": {"carry": 1}}))
    tm = TravelMap(near)
    p = tm.path("robot0", "shelf1")
    assert not _crosses_shelf(tm, p), p
    assert tm.distance("robot0", "shelf1") > 12.0  # straight up would be 7.2 m, through the shelf


def test_geometry_is_shared_and_only_asked_targets_are_computed(world):
    """One visibility graph per floor in a process; one shortest-path tree per target asked."""
    from pipflow.team import travel

    travel._GEOMETRIES.clear()
    a = TravelMap(world)
    assert a._geo is None  # nothing computed until asked
    d = a.distance("robot3", "shelf2")
    geo = a.geometry()
    assert list(geo._trees) == [geo.index[tm_point(a, "shelf2")]]  # one tree: the target's
    assert list(geo._seen) == [tm_point(a, "robot3")]  # one visibility row: the start's
    b = TravelMap(world)
    assert b.geometry() is geo and b.distance("robot3", "shelf2") == d
    moved = dict(world, robots=dict(world["robots"], robot0={"start": [2, 2], "skills": {"carry": 1}}))
    c = TravelMap(moved)
    assert c.key != a.key and c.geometry() is geo  # robots moved, the floor did not


def tm_point(tm: TravelMap, name: str):
    return tm.point(name)


def _reference_distances(tm: TravelMap, pairs: list) -> list[float]:
    """An independent oracle: networkx Dijkstra on the visibility graph of every corner, place
    and asked point, visibility tested pair by pair with the scalar clipping test (as the old
    implementation did)."""
    import networkx as nx

    def inside(pt, r):
        return r[0] < pt[0] < r[2] and r[1] < pt[1] < r[3]

    def sees(p, q):
        return not any(_rect_hits_segment(c if inside(p, r) or inside(q, r) else r, p, q)
                       for r, c in zip(tm.obstacles, tm.footprints.values()))

    corners = [c for (x0, y0, x1, y1) in tm.obstacles for c in ((x0, y0), (x0, y1), (x1, y0), (x1, y1))
               if 0 <= c[0] <= tm.width and 0 <= c[1] <= tm.height
               and not any(inside(c, r) for r in tm.obstacles)]
    ends = [tuple(p) for pair in pairs for p in pair]
    nodes = list(dict.fromkeys(corners + list(tm.places.values()) + ends))
    g = nx.Graph()
    g.add_nodes_from(nodes)
    for i, p in enumerate(nodes):
        for q in nodes[i + 1:]:
            if sees(p, q):
                g.add_edge(p, q, weight=math.dist(p, q))
    return [nx.dijkstra_path_length(g, tuple(a), tuple(b)) for a, b in pairs]


def test_distances_equal_an_independent_visibility_graph_search():
    """Robots are not graph nodes, visibility is vectorized and corners that cannot be a bend
    (tangency) are skipped: the distances must still be the exact geodesics (a floor of 9
    shelves in a 3 x 3 grid plus three touching or overlapping others, 30 robots)."""
    import random

    rng = random.Random(7)
    shelves = {f"s{i}": {"x": 3 + 12 * (i % 3), "y": 4 + 7 * (i // 3), "width": 8, "depth": 2,
                         "capacity": 10, "access": [7 + 12 * (i % 3), 3 + 7 * (i // 3)]} for i in range(9)}
    # two more shelves whose safety margins overlap s0's and s4's (0.4 m gap, 0.3 m margins), and
    # one whose margin exactly meets s8's: corners that touch another footprint
    shelves["t0"] = {"x": 3, "y": 6.4, "width": 8, "depth": 1, "capacity": 5, "access": [7, 7.9]}
    shelves["t4"] = {"x": 23.4, "y": 11, "width": 2, "depth": 2, "capacity": 5, "access": [26, 12]}
    shelves["t8"] = {"x": 27, "y": 22.6, "width": 8, "depth": 1.4, "capacity": 5, "access": [31, 24.5]}
    tm0 = TravelMap({"floor": {"width": 40, "height": 26}, "shelves": shelves})
    robots = {}
    while len(robots) < 30:
        p = [round(rng.uniform(0, 40), 2), round(rng.uniform(0, 26), 2)]
        if not any(r[0] <= p[0] <= r[2] and r[1] <= p[1] <= r[3] for r in tm0.obstacles):
            robots[f"r{len(robots)}"] = {"start": p, "skills": {"carry": 1}}
    tm = TravelMap({"floor": {"width": 40, "height": 26}, "shelves": shelves, "robots": robots})
    asked = [(r, s) for r in list(robots)[:12] for s in ("s0", "s4", "s8", "t0", "t4")] + [("s0", "s8"), ("t0", "t8")]
    pairs = [(tm.point(a), tm.point(b)) for a, b in asked] + [((0.5, 0.5), (39.5, 25.5))]  # neither a node
    got = [tm.distance(a, b) for a, b in asked] + [tm.distance([0.5, 0.5], [39.5, 25.5])]
    assert got == pytest.approx(_reference_distances(tm, pairs), abs=1e-9)


def test_bad_places_are_input_errors():
    w = yaml.safe_load((FIX / "world.yaml").read_text())
    tm = TravelMap(w)
    with pytest.raises(InputError, match="unknown place"):
        tm.distance("nowhere", "shelfA")
    with pytest.raises(InputError, match="inside the footprint"):
        tm.distance([3, 8.5], "shelfA")
    bad = dict(w, robots={"r0": {"start": [50, 1], "skills": {"carry": 1}}})
    with pytest.raises(InputError, match="off the floor"):
        TravelMap(bad)


@pytest.mark.parametrize("size", ["paper", "generated"])
def test_a_floor_grown_by_a_barrier_and_a_drop_place_is_the_floor_built_anew(world, size):
    """A closed passage (a barrier) and a stopped robot's drop place (a small footprint with an
    access point) added to a floor whose graph is built: the grown graph has exactly the edges,
    lengths and distances of the graph built from nothing for the new floor, and it was grown
    (the old graph's edges reused), not built again."""
    import sys

    import numpy as np

    from pipflow.team import travel

    if size == "generated":
        sys.path.insert(0, str(Path(__file__).parents[1] / "benchmarks"))
        from pipeline import generate_world

        world = generate_world(60, 40, 4)
    shelves = list(world["shelves"].values())
    s = shelves[0]
    x, y = float(s["x"]) + float(s["width"]) + 0.2, float(s["y"]) - 0.4
    more = dict(world, shelves=dict(world["shelves"], **{"robot0-cargo": {
        "x": x, "y": y, "width": 0.6, "depth": 0.6, "capacity": 6, "access": [x + 0.3, y - 0.5], "drop": "robot0"}}),
        stock=dict(world.get("stock") or {}, **{"robot0-cargo": {}}),
        barriers=[{"x": float(s["x"]) - 1.5, "y": float(s["y"]) - 1.0, "width": 1.2, "depth": 0.3}])
    travel._GEOMETRIES.clear()
    before = TravelMap(world).geometry()
    before.edges()  # the floor before: built
    built = travel._Geometry.__init__
    grown_called = []
    original = travel._Geometry.grown.__func__

    def grown(cls, *args):
        grown_called.append(True)
        return original(cls, *args)

    travel._Geometry.grown = classmethod(grown)
    try:
        after = TravelMap(more)
        fresh = after.geometry()
    finally:
        travel._Geometry.grown = classmethod(original)
    assert grown_called and fresh._edges is not None
    travel._GEOMETRIES.clear()
    anew = TravelMap(more).geometry()
    assert anew is not fresh and travel._Geometry.__init__ is built

    def pairs(geo):
        r, c, w = geo.edges()
        return {frozenset([tuple(geo.nodes[i]), tuple(geo.nodes[j])]): round(float(d), 9) for i, j, d in zip(r, c, w)}

    assert pairs(fresh) == pairs(anew) and len(pairs(anew)) > 0
    gone, new = set(pairs(before)) - set(pairs(anew)), set(pairs(anew)) - set(pairs(before))
    assert gone and new  # the new footprints blocked some old edges and brought their own
    assert np.allclose(fresh.nodes, anew.nodes)
    places = list(more["shelves"])[:6] + ["robot0-cargo"]
    for a in places:
        for b in places:
            assert fresh.route_to_node(after.point(a), fresh.index[after.point(b)])[0] == pytest.approx(
                anew.route_to_node(after.point(a), anew.index[after.point(b)])[0])

"""Travel distances: obstacle-free, symmetric, cached, and never shorter than a straight line."""
import math
from pathlib import Path

import pytest
import yaml

from pipflow.errors import InputError
from pipflow.travel import TravelMap, _rect_hits_segment

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


def test_cached_in_memory_and_on_disk(world, tmp_path):
    from pipflow import travel

    travel._MEMORY_CACHE.clear()
    a = TravelMap(world, cache_dir=tmp_path)
    files = list(tmp_path.glob("travel-*.json"))
    assert len(files) == 1
    travel._MEMORY_CACHE.clear()
    b = TravelMap(world, cache_dir=tmp_path)
    assert b._graph is None  # served from disk without building the visibility graph
    assert b.distance("robot3", "shelf2") == pytest.approx(a.distance("robot3", "shelf2"))
    moved = dict(world, robots=dict(world["robots"], robot0={"start": [2, 2], "skills": {"carry": 1}}))
    assert TravelMap(moved).key != a.key


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

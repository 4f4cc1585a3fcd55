"""Worlds of any size fail fast or finish: the floor-plan checks go through a grid index (the
same findings as comparing every pair, at the cost of the footprints near each one), and a world
over a size limit is refused by its size, with the limit and how to change it, never as an
attack."""
from __future__ import annotations

import pytest
import yaml

from pipflow import floorplan
from pipflow.errors import WorldError
from pipflow.floorplan import FootprintGrid, layout_diagnostics
from pipflow.warehouse.world import load_world


def _grid_world(rows: int, cols: int, robots: int = 4) -> dict:
    shelves = {}
    for r in range(rows):
        for c in range(cols):
            x, y = 2 + c * 10, 2 + r * 5
            shelves[f"s{r}x{c}"] = {"x": x, "y": y, "width": 8, "depth": 2, "capacity": 10, "access": [x + 4, y - 1]}
    return {"name": "grid", "floor": {"width": 2 + cols * 10 + 2, "height": 2 + rows * 5 + 2},
            "shelves": shelves, "products": {"p": {"color": "red"}}, "stock": {},
            "robots": {f"r{i}": {"start": [1, 1 + i * 0.5], "skills": {"carry": 1}} for i in range(robots)}}


def _located(*path, key=False):
    return "/".join(map(str, path))


def test_a_large_grid_with_overlaps_names_exactly_those_and_asks_only_near_footprints(monkeypatch):
    world = _grid_world(60, 50)  # 3,000 shelves: 4.5 million pairs
    world["shelves"]["s10x10"]["x"] += 5  # onto s10x11
    world["shelves"]["s40x3"]["y"] += 3.5  # onto s41x3 and over s41x3's access point [36, 206]
    world["shelves"]["s7x7"]["access"] = [world["shelves"]["s7x8"]["x"] + 1, world["shelves"]["s7x8"]["y"] + 1]
    asked = {"n": 0}
    inside = floorplan.inside_footprint

    def counted(point, fixture):
        asked["n"] += 1
        return inside(point, fixture)

    monkeypatch.setattr(floorplan, "inside_footprint", counted)
    found = [d.message for d in layout_diagnostics(world["shelves"], world["floor"], _located, "shelves", "shelf")]
    assert found == [
        "access point [83, 38] of shelf 's7x7' lies inside the footprint of shelf 's7x8'; robots must be able to stand there",
        "access point [36, 206] of shelf 's41x3' lies inside the footprint of shelf 's40x3'; robots must be able to stand there",
        "shelf 's10x11' overlaps shelf 's10x10'",
        "shelf 's41x3' overlaps shelf 's40x3'",
    ]
    assert asked["n"] < 10 * len(world["shelves"])  # all pairs would be 9 million


def test_the_grid_finds_what_comparing_every_pair_finds_on_random_footprints():
    import random

    rng = random.Random(5)
    geo = {f"f{i}": {"x": rng.uniform(0, 60), "y": rng.uniform(0, 60), "width": rng.choice([0.5, 2, 8, 45]),
                     "depth": rng.choice([0.5, 2, 30]), "access": [rng.uniform(0, 70), rng.uniform(0, 70)]}
           for i in range(300)}
    grid = FootprintGrid(geo)
    names = list(geo)
    every = [(i, j) for i in range(len(names)) for j in range(i + 1, len(names))
             if floorplan.footprint(geo[names[i]])[0] < floorplan.footprint(geo[names[j]])[2]
             and floorplan.footprint(geo[names[j]])[0] < floorplan.footprint(geo[names[i]])[2]
             and floorplan.footprint(geo[names[i]])[1] < floorplan.footprint(geo[names[j]])[3]
             and floorplan.footprint(geo[names[j]])[1] < floorplan.footprint(geo[names[i]])[3]]
    assert grid.overlapping_pairs() == every
    for n, f in geo.items():
        assert grid.containing(f["access"], geo) == [m for m in names if floorplan.inside_footprint(f["access"], geo[m])]


def test_a_robot_inside_a_shelf_of_a_large_grid_is_found(tmp_path):
    world = _grid_world(40, 40)
    world["robots"]["r2"]["start"] = [world["shelves"]["s30x30"]["x"] + 1, world["shelves"]["s30x30"]["y"] + 1]
    path = tmp_path / "world.yaml"
    path.write_text(yaml.safe_dump(world, sort_keys=False))
    with pytest.raises(WorldError) as err:
        load_world(path)
    assert "robot 'r2' starts at [303, 153], inside the footprint of shelf 's30x30'" in str(err.value)


def test_a_world_over_the_robot_limit_is_refused_by_its_size_not_as_an_attack(tmp_path, monkeypatch):
    monkeypatch.setenv("PIPFLOW_WORLD_LIMITS", "robots=300")
    world = _grid_world(2, 2, robots=301)
    path = tmp_path / "world.yaml"
    path.write_text(yaml.safe_dump(world, sort_keys=False))
    with pytest.raises(WorldError) as err:
        load_world(path)
    text = str(err.value)
    assert "this world file has 301 robots; the limit is 300 (settable: PIPFLOW_WORLD_LIMITS=robots=N" in text
    assert "alias" not in text and "values" not in text

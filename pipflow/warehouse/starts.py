"""Seeded robot start positions.

The paper runs every warehouse task ten times "from varied initial robot locations". A seed
gives a reproducible variation: each robot starts at a random free point of the floor (on a
0.5 m grid, clear of every shelf footprint and access point, and apart from
the other robots). No seed keeps the world file's starts.
"""
from __future__ import annotations

import copy
import math
import random

from pipflow.errors import InputError

GRID = 0.5        # metres between candidate start points
CLEARANCE = 1.0   # metres kept from shelf footprints and from the floor's edge
SPACING = 1.0     # metres between two robots' starts


def _free(world: dict, x: float, y: float) -> bool:
    for shelf in world["shelves"].values():
        if (shelf["x"] - CLEARANCE <= x <= shelf["x"] + shelf["width"] + CLEARANCE
                and shelf["y"] - CLEARANCE <= y <= shelf["y"] + shelf["depth"] + CLEARANCE):
            return False
        ax, ay = shelf["access"]
        if math.hypot(ax - x, ay - y) < SPACING:
            return False
    return True


def vary_starts(world: dict, seed: int | None) -> dict:
    """A copy of the world whose robots start at seeded random free points (``seed=None``:
    the world unchanged)."""
    if seed is None:
        return world
    rng = random.Random(f"pipflow-starts-{seed}")
    width, height = world["floor"]["width"], world["floor"]["height"]
    candidates = [(i * GRID, j * GRID)
                  for i in range(int(CLEARANCE / GRID), int((width - CLEARANCE) / GRID) + 1)
                  for j in range(int(CLEARANCE / GRID), int((height - CLEARANCE) / GRID) + 1)]
    candidates = [p for p in candidates if _free(world, *p)]
    rng.shuffle(candidates)
    varied = copy.deepcopy(world)
    taken: list[tuple[float, float]] = []
    for name in sorted(varied["robots"]):
        for point in candidates:
            if all(math.hypot(point[0] - q[0], point[1] - q[1]) >= SPACING for q in taken):
                taken.append(point)
                varied["robots"][name]["start"] = [point[0], point[1]]
                break
        else:
            raise InputError(f"seed {seed}: no free start left on the floor for robot {name!r} "
                             f"({len(taken)} robots placed)")
    return varied

"""Seeded robot start positions in a warehouse.

The paper runs every warehouse task ten times "from varied initial robot locations". A seed
gives a reproducible variation (:func:`pipflow.floorplan.seeded_starts`, shared by every
domain): each robot starts at a random free point of a 0.5 m grid, 1 m clear of every shelf
footprint and of the floor's edge, 1 m from access points and from the other robots. No seed
keeps the world file's starts.
"""
from __future__ import annotations

from pipflow.floorplan import seeded_starts

CLEARANCE = 1.0   # metres kept from shelf footprints and from the floor's edge
SPACING = 1.0     # metres between two robots' starts, and from an access point


def vary_starts(world: dict, seed: int | None) -> dict:
    """A copy of the world whose robots start at seeded random free points (``seed=None``:
    the world unchanged)."""
    return seeded_starts(world, seed, world["shelves"].values(), label="pipflow-starts",
                         clearance=CLEARANCE, spacing=SPACING, margin=CLEARANCE)

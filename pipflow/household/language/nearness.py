"""Which things of the home are nearest a place, by the floor plan: "it's dark over by the sofa"
means the light nearest the sofa, not every light of the home. The home model has positions
(each place's rectangle; an object is where its place is), so nearness is read from them; two
things as near are both returned, for the reader to ask which (never a pick)."""
from __future__ import annotations

import math

#: distances closer than this are the same distance (metres): two lamps on one table are as near
SAME_DISTANCE = 0.05


def centre(world: dict, name: str) -> tuple[float, float]:
    """The middle of a place's rectangle; an object's is its place's (the home model has no
    position of its own for an object)."""
    if name in (world.get("objects") or {}):
        name = world["objects"][name]["in"]
    e = world["places"][name]
    return float(e["x"]) + float(e.get("width", 0)) / 2, float(e["y"]) + float(e.get("depth", 0)) / 2


def nearest(world: dict, names: list[str], place: str) -> list[str]:
    """The names nearest ``place`` (several when they are as near: :data:`SAME_DISTANCE`)."""
    if not names:
        return []
    px, py = centre(world, place)
    dist = {n: math.hypot(centre(world, n)[0] - px, centre(world, n)[1] - py) for n in names}
    best = min(dist.values())
    return [n for n in names if dist[n] - best < SAME_DISTANCE]

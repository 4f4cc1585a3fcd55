"""A ferry terminal of our own for reader tests: three places, two products, four robots (titan
the only strongest, moth and wasp tie as weakest)."""
from __future__ import annotations

import copy

TERMINAL = {
    "floor": {"width": 30, "height": 20},
    "shelves": {
        "quay": {"x": 3, "y": 13, "width": 8, "depth": 2, "capacity": 40, "access": [7, 12]},
        "shed": {"x": 17, "y": 13, "width": 8, "depth": 2, "capacity": 30, "access": [21, 12]},
        "ramp": {"x": 3, "y": 5, "width": 8, "depth": 2, "capacity": 12, "access": [7, 4]},
    },
    "products": {"crate": {"color": "brown"}, "barrel": {"color": "blue"}},
    "stock": {"quay": {"crate": 14, "barrel": 5}, "shed": {"crate": 2, "barrel": 6}, "ramp": {"barrel": 1}},
    "robots": {
        "titan": {"start": [1, 1], "skills": {"carry": 4}, "kind": "forklift", "tags": []},
        "ox": {"start": [1, 9], "skills": {"carry": 2}, "kind": "tugger", "tags": []},
        "moth": {"start": [28, 1], "skills": {"carry": 1}, "kind": "amr", "tags": []},
        "wasp": {"start": [28, 18], "skills": {"carry": 1}, "kind": "amr", "tags": []},
    },
}


def with_ramp_called(name: str) -> dict:
    """The terminal with its ramp renamed ``name`` (stock and all): for tests that a word the
    reader would otherwise drop or respell ("tae", "po") stays the name of a place."""
    world = copy.deepcopy(TERMINAL)
    world["shelves"][name] = world["shelves"].pop("ramp")
    world["stock"][name] = world["stock"].pop("ramp")
    return world

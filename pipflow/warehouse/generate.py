"""Synthetic warehouse instances for scale tests and benchmarks (never used to plan real tasks).

:func:`scale_instance` builds a world of ``shelves`` x ``products`` with random stock and a goal
that lists every count of a final state reached by moving exactly ``moved`` units (each random
transfer takes units from where they are to a shelf with room), so the goal is feasible and
every shelf is within capacity before and after.
"""
from __future__ import annotations

import random


def scale_instance(shelves: int = 50, products: int = 10, moved: int = 2000, capacity: int = 200,
                   fill: float = 0.6, seed: int = 0) -> tuple[dict, dict]:
    """``(world, goal)``: a world dict (docs/architecture.md) and a goal ``{shelf: {product: n}}``."""
    rng = random.Random(seed)
    S = [f"shelf{i + 1}" for i in range(shelves)]
    P = [f"product{j + 1}" for j in range(products)]
    stock = {s: {p: 0 for p in P} for s in S}
    for s in S:
        for _ in range(int(capacity * fill)):
            stock[s][rng.choice(P)] += 1
    final = {s: dict(c) for s, c in stock.items()}
    load = {s: sum(final[s].values()) for s in S}
    left = moved
    while left > 0:
        s, t, p = rng.choice(S), rng.choice(S), rng.choice(P)
        k = min(left, rng.randint(1, 15), final[s][p], capacity - load[t])
        if s == t or k <= 0:
            continue
        final[s][p] -= k
        final[t][p] += k
        load[s] -= k
        load[t] += k
        left -= k
    world = {
        "name": f"scale-{shelves}x{products}",
        "path": "<generated>",
        "floor": {"width": 10 * shelves, "height": 10},
        "shelves": {s: {"x": 10 * i + 1, "y": 4, "width": 8, "depth": 2, "capacity": capacity,
                        "access": [10 * i + 5, 3]} for i, s in enumerate(S)},
        "products": {p: {"color": "grey"} for p in P},
        "stock": {s: {p: n for p, n in c.items() if n} for s, c in stock.items()},
        "robots": {"robot0": {"start": [0, 0], "skills": {"carry": 6}}},
    }
    return world, final

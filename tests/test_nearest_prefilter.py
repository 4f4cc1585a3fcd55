"""The allocation's prefilter (pipflow.team.nearest) keeps the paper's optimum exactly: on random
worlds with shelves in the way, random subtask graphs and rules, the IP over the robots it keeps
gives the same coalitions and costs as the IP over every robot, and it asks far fewer path
lengths."""
from __future__ import annotations

import random

import pytest

from pipflow.team import nearest
from pipflow.team.allocation import allocate
from pipflow.team.scheduling import Timeline


def _world(rng: random.Random, robots: int, cols: int, rows: int) -> dict:
    """Shelves 6 x 2 m on a grid with 4 m aisles; robots on free aisle points, carry 1-3."""
    shelves = {}
    for r in range(rows):
        for c in range(cols):
            x, y = 4 + c * 10, 4 + r * 6
            shelves[f"s{r}_{c}"] = {"x": x, "y": y, "width": 6, "depth": 2, "capacity": 50,
                                    "access": [x + 3, y - 1]}
    width, height = 4 + cols * 10 + 4, 4 + rows * 6 + 4
    starts = set()
    while len(starts) < robots:
        p = (rng.randint(1, width - 1), rng.randint(1, height - 1))
        if not any(s["x"] - 0.5 <= p[0] <= s["x"] + 6.5 and s["y"] - 0.5 <= p[1] <= s["y"] + 2.5
                   for s in shelves.values()):
            starts.add(p)
    return {"name": "random", "floor": {"width": width, "height": height}, "shelves": shelves,
            "products": {"red": {"color": "red"}, "blue": {"color": "blue"}},
            "stock": {}, "robots": {f"r{i}": {"start": list(p), "skills": {"carry": 1 + i % 3}}
                                    for i, p in enumerate(sorted(starts))}}


def _graph(rng: random.Random, world: dict, n: int) -> dict:
    names = list(world["shelves"])
    nodes, edges = [], []
    for k in range(n):
        a, b = rng.sample(names, 2)
        product = rng.choice(["red", "blue"])
        nodes.append({"id": f"t{k}", "index": k, "action": "move-product", "args": [a, b, product, "m"],
                      "skills": {"carry": float(rng.randint(1, 6))}, "route": [a, b],
                      "fields": {"product": product, "from": a, "to": b}})
        if k and rng.random() < 0.5:
            edges.append([f"t{rng.randrange(k)}", f"t{k}"])
    return {"mode": "exact", "nodes": nodes, "edges": edges}


def _rules(rng: random.Random, world: dict) -> tuple[list, list]:
    robots = list(world["robots"])
    kind = rng.choice(["none", "never", "only", "linear"])
    if kind == "never":
        return [{"never": rng.sample(robots, 5), "product": "red"}], []
    if kind == "only":
        return [{"only": rng.sample(robots, 12), "product": "blue"}], []
    if kind == "linear":  # at most one of a few robots in any coalition
        return [], [{"robots": rng.sample(robots, 6), "coef": 1, "sense": "<=", "rhs": 1}]
    return [], []


def _without_prefilter(monkeypatch) -> None:
    monkeypatch.setattr(nearest, "FIRST_ROUND", 10 ** 9)  # the first round evaluates every robot


@pytest.mark.parametrize("cost", ["total", "subtask"])
@pytest.mark.parametrize("seed", range(8))
def test_the_prefiltered_ip_gives_the_same_optimum_as_the_ip_over_every_robot(seed, cost, monkeypatch):
    rng = random.Random(seed)
    world = _world(rng, robots=rng.randint(60, 140), cols=rng.randint(2, 5), rows=rng.randint(2, 4))
    graph = _graph(rng, world, rng.randint(4, 12))
    constraints, linear = _rules(rng, world)
    asked = {"n": 0}
    exact_cost = Timeline.cost

    def counted(self, robot, node):
        asked["n"] += 1
        return exact_cost(self, robot, node)

    monkeypatch.setattr(Timeline, "cost", counted)
    kept = allocate(graph, world, "scip", constraints, linear, cost=cost)
    with_filter = asked["n"]
    _without_prefilter(monkeypatch)
    asked["n"] = 0
    every = allocate(graph, world, "scip", constraints, linear, cost=cost)
    assert kept["assignments"] == every["assignments"]  # the same coalitions, in the same order, same costs
    assert kept["stats"]["predicted"] == every["stats"]["predicted"]
    assert with_filter < 0.6 * asked["n"]  # and most robots' paths were never asked for


def test_a_subtask_only_far_robots_can_do_is_still_allocated_to_them():
    """The prefilter widens until the coalition is proven: when the near robots lack the skill
    (only the farthest robot carries at all), the far robot is found, as without it."""
    rng = random.Random(3)
    world = _world(rng, robots=80, cols=4, rows=3)
    for r in world["robots"].values():
        r["skills"]["carry"] = 0
    far = max(world["robots"], key=lambda r: world["robots"][r]["start"][0])
    world["robots"][far]["skills"]["carry"] = 9
    graph = {"mode": "exact", "nodes": [{"id": "t0", "index": 0, "action": "move-product",
                                         "args": ["s0_0", "s0_1", "red", "m"], "skills": {"carry": 9.0},
                                         "route": ["s0_0", "s0_1"],
                                         "fields": {"product": "red", "from": "s0_0", "to": "s0_1"}}],
             "edges": []}
    assert allocate(graph, world, "scip")["assignments"][0]["robots"] == [far]

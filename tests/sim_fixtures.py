"""Hand-built schedules in the contract of docs/architecture.md, for tests that must not depend
on the travel or scheduling modules."""
from __future__ import annotations

import copy
import math
from pathlib import Path

import yaml

ROOT = Path(__file__).resolve().parents[1]
WORLD_FILE = ROOT / "benchmarks" / "warehouse" / "world.yaml"


def load_world() -> dict:
    """The warehouse world, normalized the way world.load promises (every shelf in stock)."""
    w = yaml.safe_load(WORLD_FILE.read_text())
    w["path"] = str(WORLD_FILE)
    w["stock"] = {s: dict(w.get("stock", {}).get(s, {})) for s in w["shelves"]}
    return copy.deepcopy(w)


def leg(subtask: str, pts: list, start: float, speed: float = 1.0) -> dict:
    d = sum(math.dist(p, q) for p, q in zip(pts, pts[1:]))
    return {"subtask": subtask, "from": list(pts[0]), "to": list(pts[-1]), "path": [list(p) for p in pts],
            "start": start, "end": start + d / speed, "distance": d}


def move_node(sid: str, index: int, src: str, dst: str, product: str, units: int) -> dict:
    return {"id": sid, "index": index, "action": "move-product",
            "args": [src, dst, product, f"magnitude{units}"], "skills": {"carry": units},
            "route": [src, dst], "fields": {"product": product, "from": src, "to": dst}}


def build(moves: list[dict]) -> tuple[dict, dict]:
    """``moves``: [{"id", "src", "dst", "product", "units", "robots": {robot: [to_src_pts, to_dst_pts]},
    "after": [ids]}] -> (graph, schedule). Each robot's legs start when it is free; the subtask
    starts when every robot is at the source and ends at the last arrival at the target."""
    nodes, edges, subtasks = [], [], []
    robots: dict[str, dict] = {}
    free: dict[str, float] = {}
    ends: dict[str, float] = {}
    for i, m in enumerate(moves):
        nodes.append(move_node(m["id"], i, m["src"], m["dst"], m["product"], m["units"]))
        edges += [[a, m["id"]] for a in m.get("after", [])]
        ready = max([ends[a] for a in m.get("after", [])] or [0.0])
        arrive = {}
        for r, (to_src, _) in m["robots"].items():
            l1 = leg(m["id"], to_src, free.get(r, 0.0))
            robots.setdefault(r, {"legs": []})["legs"].append(l1)
            arrive[r] = l1["end"]
        start = max([ready] + list(arrive.values()))
        end = start
        for r, (_, to_dst) in m["robots"].items():
            l2 = leg(m["id"], to_dst, start)
            robots[r]["legs"].append(l2)
            free[r] = l2["end"]
            end = max(end, l2["end"])
        ends[m["id"]] = end
        subtasks.append({"id": m["id"], "action": "move-product", "args": nodes[-1]["args"],
                         "robots": sorted(m["robots"]), "ready": ready, "start": start, "end": end})
    for info in robots.values():
        info["distance"] = sum(l["distance"] for l in info["legs"])
    dist = [info["distance"] for info in robots.values()]
    schedule = {"subtasks": subtasks, "robots": robots, "makespan": max(ends.values(), default=0.0),
                "tc_max": max(dist, default=0.0), "tc_avg": sum(dist) / len(dist) if dist else 0.0}
    graph = {"mode": "exact", "nodes": nodes, "edges": edges}
    return graph, schedule


# Paths that go around the shelves (x = 12 and x = 14 are free corridors; y = 4, 9, 12 free rows).
R5_TO_S1 = [(14, 9), (14, 12), (7, 12)]
S1_TO_S3 = [(7, 12), (12, 12), (12, 9), (12, 4), (7, 4)]


def wh01() -> tuple[dict, dict]:
    """Task wh-01: 2 product1 from shelf1 to shelf3 by robot5 (carry 2)."""
    return build([{"id": "s1", "src": "shelf1", "dst": "shelf3", "product": "product1", "units": 2,
                   "robots": {"robot5": [R5_TO_S1, S1_TO_S3]}}])


def route(p, q) -> list:
    """Obstacle-free in the warehouse world: along the row of p to the x = 14 corridor, along it
    to the row of q, then to q (every start and access row is clear of the shelves)."""
    pts = [tuple(p), (14.0, float(p[1])), (14.0, float(q[1])), tuple(q)]
    out = [pts[0]]
    for pt in pts[1:]:
        if math.dist(pt, out[-1]) > 1e-9:
            out.append(pt)
    return out


def chain(world: dict, spec: list[tuple]) -> tuple[dict, dict]:
    """``spec``: [(id, src, dst, product, units, [robots], [after ids])] -> (graph, schedule),
    robots routed with :func:`route` from wherever they last stopped."""
    where = {r: tuple(info["start"]) for r, info in world["robots"].items()}
    moves = []
    for sid, src, dst, prod, units, robots, after in spec:
        a, b = tuple(world["shelves"][src]["access"]), tuple(world["shelves"][dst]["access"])
        paths = {}
        for r in robots:
            paths[r] = [route(where[r], a), route(a, b)]
            where[r] = b
        moves.append({"id": sid, "src": src, "dst": dst, "product": prod, "units": units,
                      "robots": paths, "after": after})
    return build(moves)

"""Planned robot motion as data: a trajectory (piecewise-linear legs in time), the robots'
colours, and the arrival tolerance.

Why a module of its own: the simulator executes trajectories and the pictures draw them from a
run record without pybullet; both need the same motion model, and neither should import the
other for it.
"""
from __future__ import annotations

import math

Point = tuple[float, float]

#: Robot colours (tab10 without the product-like reds/greens first).
ROBOT_COLOURS = [
    (0.12, 0.47, 0.71, 1), (1.0, 0.5, 0.05, 1), (0.58, 0.4, 0.74, 1), (0.55, 0.34, 0.29, 1),
    (0.5, 0.5, 0.5, 1), (0.74, 0.74, 0.13, 1), (0.09, 0.75, 0.81, 1), (0.84, 0.15, 0.16, 1),
    (0.17, 0.63, 0.17, 1), (0.89, 0.47, 0.76, 1), (0.2, 0.2, 0.2, 1), (0.6, 0.8, 1.0, 1),
]
ARRIVAL_TOLERANCE = 0.75  # metres: a robot this close to an access point is "at the shelf"


class Trajectory:
    """A robot's planned motion: piecewise-linear in time along each leg's path, waiting in
    place between legs. Vertex times are exposed so the sampler never cuts a corner."""

    def __init__(self, start: Point, legs: list[dict]):
        self.start = (float(start[0]), float(start[1]))
        self.segments: list[tuple[float, float, list[Point], list[float]]] = []
        self.legs = sorted(legs, key=lambda l: float(l.get("start", 0.0)))
        for leg in self.legs:
            pts = [tuple(map(float, p)) for p in (leg.get("path") or [])]
            a = tuple(map(float, leg.get("from", pts[0] if pts else self.start)))
            b = tuple(map(float, leg.get("to", pts[-1] if pts else a)))
            if not pts or distance(pts[0], a) > 1e-9:
                pts.insert(0, a)
            if distance(pts[-1], b) > 1e-9:
                pts.append(b)
            cum = [0.0]
            for p, q in zip(pts, pts[1:]):
                cum.append(cum[-1] + distance(p, q))
            t0, t1 = float(leg.get("start", 0.0)), float(leg.get("end", leg.get("start", 0.0)))
            self.segments.append((t0, max(t1, t0), pts, cum))
        if self.segments:
            self.start = self.segments[0][2][0]
        # a leg that does not begin where the previous one ended would make the body jump
        self.jumps: list[dict] = []
        for (_, e0, p0, _), (s1, _, p1, _) in zip(self.segments, self.segments[1:]):
            gap = distance(p0[-1], p1[0])
            if gap > ARRIVAL_TOLERANCE:
                self.jumps.append({"time": round(s1, 3), "from": list(p0[-1]), "to": list(p1[0]),
                                   "metres": round(gap, 3)})

    def position(self, t: float) -> Point:
        """Where the plan puts the robot at time t."""
        here = self.start
        for t0, t1, pts, cum in self.segments:
            if t < t0:
                return here
            if t >= t1:
                here = pts[-1]
                continue
            frac = (t - t0) / (t1 - t0) if t1 > t0 else 1.0
            s = frac * cum[-1]
            for i in range(1, len(pts)):
                if cum[i] >= s:
                    span = cum[i] - cum[i - 1]
                    u = (s - cum[i - 1]) / span if span > 0 else 1.0
                    p, q = pts[i - 1], pts[i]
                    return (p[0] + u * (q[0] - p[0]), p[1] + u * (q[1] - p[1]))
            return pts[-1]
        return here

    def vertex_times(self) -> list[float]:
        times = []
        for t0, t1, pts, cum in self.segments:
            total = cum[-1]
            times += [t0 + (t1 - t0) * (c / total if total > 0 else 1.0) for c in cum]
        return times

    def max_speed(self) -> float:
        return max([(c[-1] / (t1 - t0)) for t0, t1, _, c in self.segments if t1 > t0] or [0.0])

    def arrival(self, subtask: str, place: Point, last: bool = False) -> float | None:
        """End time of the first (or last) leg of ``subtask`` that ends at ``place``."""
        hits = [t1 for (t0, t1, pts, _), leg in zip(self.segments, self.legs)
                if leg.get("subtask") == subtask and distance(pts[-1], place) <= ARRIVAL_TOLERANCE]
        if not hits:
            return None
        return hits[-1] if last else hits[0]


def distance(p: Point, q: Point) -> float:
    return math.hypot(p[0] - q[0], p[1] - q[1])


def planned_paths(world: dict, schedule: dict) -> dict[str, list[list[float]]]:
    """Each robot's planned motion as ``[[t, x, y], ...]`` (the form of a simulation's recorded
    trajectories, which the path map draws): its start, then every vertex of its legs at the time
    the schedule passes it; a robot without legs, its start alone. What a simulation that follows
    the schedule's legs (and keeps no trajectories of its own) drove."""
    robots = world.get("robots") or {}
    legs: dict[str, list[dict]] = {r: [] for r in robots}
    for r, info in (schedule.get("robots") or {}).items():
        legs.setdefault(r, []).extend(info.get("legs", []))
    out = {}
    for r, robot_legs in legs.items():
        tr = Trajectory(robots.get(r, {}).get("start", (0.0, 0.0)), robot_legs)
        points = [[0.0, *tr.start]]
        for t in tr.vertex_times():
            x, y = tr.position(t)
            if (x, y) != tuple(points[-1][1:]):
                points.append([round(t, 4), round(x, 4), round(y, 4)])
        out[r] = points
    return out

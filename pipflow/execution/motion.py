"""How robots really move when faults strike, from the legs a schedule plans: generic geometry
and timing, no task domain's words.

A schedule's legs say where each robot drives and when. Under faults the robot does something
else, and the simulation must play what it really does (:func:`actual_schedule`):

* a robot that **stops** for good at ``t`` stays where it is at ``t``: its leg is cut there and
  its later legs never happen;
* a robot that **slows down** from ``t`` drives at ``factor`` of its planned speed: each leg takes
  longer, the next one starts late (keeping the planned pause between the legs of one subtask);
  a leg planned at a known pace (``pace`` of the leg, :class:`pipflow.team.scheduling.Timeline`)
  is not slowed twice;
* a robot that reaches a **closed passage** (a barrier, from the time it closes) stops where its
  path meets the barrier (grown by the robot's radius) and waits there;
* legs marked ``done`` happened already (a recovery cut the run there) and are played as they are.

:func:`barrier_across` places a barrier across a passage, :func:`drop_site` the small place
where a stopped robot's cargo lies, and :func:`first_deviation` finds when a robot is farther
from where the plan has it than the arrival tolerance (how a monitor notices a slow robot).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any, Callable, Iterable, Sequence

from pipflow.metrics import travel_costs
from pipflow.taskdomains import task_domain
from pipflow.team.trajectory import ARRIVAL_TOLERANCE, Trajectory
from pipflow.team.travel import clip_segment

Point = tuple[float, float]
#: metres a barrier is grown by when robots meet it (the travel map's robot margin)
ROBOT_MARGIN = 0.3
#: thickness of a barrier (metres) and the most it reaches out on each side of the passage
BARRIER_THICKNESS = 0.2
BARRIER_REACH = 4.0
#: side of the square place where a stopped robot's cargo lies, and how far its centre is from
#: where the robot stopped (the place's access point, where another robot stands to take the cargo)
DROP_SIDE = 0.3
DROP_ACCESS = 0.4
#: seconds between the instants at which a plan and what happened are compared
MONITOR_STEP = 0.1


# ------------------------------------------------------------------------------------------
# polylines
# ------------------------------------------------------------------------------------------
def _points(leg: dict) -> list[Point]:
    pts = [(float(p[0]), float(p[1])) for p in (leg.get("path") or [])]
    a = tuple(map(float, leg.get("from") or (pts[0] if pts else (0.0, 0.0))))
    b = tuple(map(float, leg.get("to") or (pts[-1] if pts else a)))
    if not pts or math.dist(pts[0], a) > 1e-9:
        pts.insert(0, a)
    if math.dist(pts[-1], b) > 1e-9:
        pts.append(b)
    return pts


def _cumulative(pts: Sequence[Point]) -> list[float]:
    cum = [0.0]
    for p, q in zip(pts, pts[1:]):
        cum.append(cum[-1] + math.dist(p, q))
    return cum


def point_at(pts: Sequence[Point], cum: Sequence[float], s: float) -> Point:
    """The point ``s`` metres along a polyline (clamped to its ends)."""
    if s <= 0 or len(pts) == 1:
        return pts[0]
    for i in range(1, len(pts)):
        if cum[i] >= s:
            span = cum[i] - cum[i - 1]
            u = (s - cum[i - 1]) / span if span > 0 else 1.0
            return (pts[i - 1][0] + u * (pts[i][0] - pts[i - 1][0]), pts[i - 1][1] + u * (pts[i][1] - pts[i - 1][1]))
    return pts[-1]


def cut_polyline(pts: Sequence[Point], cum: Sequence[float], s: float) -> list[Point]:
    """The polyline's first ``s`` metres."""
    out = [pts[0]]
    for i in range(1, len(pts)):
        if cum[i] < s - 1e-12:
            out.append(pts[i])
        else:
            break
    end = point_at(pts, cum, s)
    if math.dist(out[-1], end) > 1e-9:
        out.append(end)
    return out if len(out) > 1 else [pts[0], pts[0]]


def share_point(path: Sequence[Sequence[float]], share: float) -> tuple[Point, Point]:
    """The point at ``share`` of a path's length, and the direction of the path there."""
    pts = [(float(p[0]), float(p[1])) for p in path]
    cum = _cumulative(pts)
    s = max(0.0, min(1.0, share)) * cum[-1]
    p = point_at(pts, cum, s)
    for i in range(1, len(pts)):
        if cum[i] >= s and cum[i] > cum[i - 1]:
            d = (pts[i][0] - pts[i - 1][0], pts[i][1] - pts[i - 1][1])
            n = math.hypot(*d)
            return p, (d[0] / n, d[1] / n)
    return p, (1.0, 0.0)


def _enter(a: Point, b: Point, rect: tuple[float, float, float, float]) -> float | None:
    """Share of segment a-b at which it enters the open rectangle (0 if a lies inside), or None."""
    clipped = clip_segment(a, b, rect)
    return None if clipped is None else clipped[0]


# ------------------------------------------------------------------------------------------
# what the robots really do
# ------------------------------------------------------------------------------------------
@dataclass
class MotionFaults:
    """The motion faults in force, by robot: when each stops, from when and how slow each drives,
    and the barriers (rectangle grown by the robot margin, closing time, fault id)."""

    stops: dict[str, float] = field(default_factory=dict)
    slow: dict[str, list[tuple[float, float]]] = field(default_factory=dict)
    barriers: list[tuple[tuple[float, float, float, float], float, str]] = field(default_factory=list)


@dataclass
class Motion:
    """The legs robots really drive, and what they met: ``stopped`` {robot: (time, point)},
    ``blocked`` [(time, robot, point, fault id)]."""

    legs: dict[str, list[dict]]
    stopped: dict[str, tuple[float, Point]] = field(default_factory=dict)
    blocked: list[tuple[float, str, Point, str]] = field(default_factory=list)


def grown(barrier: dict, margin: float = ROBOT_MARGIN) -> tuple[float, float, float, float]:
    x, y, w, d = (float(barrier[k]) for k in ("x", "y", "width", "depth"))
    return (x - margin, y - margin, x + w + margin, y + d + margin)


def _drive(leg: dict, start: float, slow: list[tuple[float, float]] | None):
    """Times along a leg driven from ``start``: a function from metres to time, and the end time.
    The leg's planned speed, over the pace it was planned at, is the robot's own; each slowdown
    ``(t, factor)`` sets the share of it the robot drives at from ``t`` on."""
    pts = _points(leg)
    cum = _cumulative(pts)
    length = cum[-1]
    planned = float(leg["end"]) - float(leg["start"])
    if length <= 1e-12 or planned <= 1e-12:
        return pts, cum, (lambda s: start), start + max(0.0, planned)
    own = length / planned / float(leg.get("pace") or 1.0)  # m/s at the robot's full pace
    changes = sorted(slow or [])
    now = next((f for t, f in reversed(changes) if t <= start), 1.0)
    speeds = [(start, own * now)] + [(t, own * f) for t, f in changes if t > start]

    def time_at(s: float) -> float:
        t, done = speeds[0][0], 0.0
        for k, (t0, v) in enumerate(speeds):
            t_next = speeds[k + 1][0] if k + 1 < len(speeds) else math.inf
            reach = done + (t_next - t0) * v
            if s <= reach + 1e-12:
                return t0 + (s - done) / v
            done, t = reach, t_next
        return t

    return pts, cum, time_at, time_at(length)


def _s_at(time_at, length: float, t: float) -> float:
    """Metres driven by time ``t`` (bisection on the monotone ``time_at``)."""
    lo, hi = 0.0, length
    for _ in range(60):
        mid = (lo + hi) / 2
        if time_at(mid) <= t:
            lo = mid
        else:
            hi = mid
    return lo


def robot_motion(start: Point, legs: list[dict], stop: float | None, slow: list[tuple[float, float]] | None,
                 barriers: list[tuple[tuple[float, float, float, float], float, str]]):
    """One robot's actual legs, where it stopped (time, point) or None, and where a barrier
    blocked it (time, point, fault id) or None."""
    out: list[dict] = []
    clock = -math.inf
    prev: dict | None = None
    here = (float(start[0]), float(start[1]))
    for leg in sorted(legs, key=lambda l: (float(l["start"]), float(l["end"]))):
        if leg.get("done"):
            out.append(leg)
            clock, prev = max(clock, float(leg["end"])), leg
            here = tuple(map(float, leg.get("to") or here))
            continue
        gap = 0.0
        if prev is not None and prev.get("subtask") == leg.get("subtask") and not prev.get("done"):
            gap = max(0.0, float(leg["start"]) - float(prev["end"]))
        begin = max(float(leg["start"]), clock + gap)
        if stop is not None and begin >= stop:
            return out, (stop, here), None
        pts, cum, time_at, end = _drive(leg, begin, slow)
        cut_s: float | None = None
        blocked = None
        if stop is not None and stop < end:
            cut_s = _s_at(time_at, cum[-1], stop)
        for rect, t_close, fid in barriers:
            for i in range(1, len(pts)):
                u = _enter(pts[i - 1], pts[i], rect)
                if u is None:
                    continue
                s_in = cum[i - 1] + u * (cum[i] - cum[i - 1])
                if s_in <= 1e-9:
                    continue  # it stands in the passage already: it may leave
                if time_at(s_in) >= t_close and (cut_s is None or s_in < cut_s):
                    cut_s, blocked = s_in, (time_at(s_in), point_at(pts, cum, s_in), fid)
                break
        if cut_s is None:
            actual = {**leg, "start": begin, "end": end}
            out.append(actual)
            clock, prev, here = end, leg, pts[-1]
            continue
        path = cut_polyline(pts, cum, cut_s)
        t_cut = time_at(cut_s)
        out.append({**leg, "start": begin, "end": t_cut, "path": [list(p) for p in path], "to": list(path[-1]),
                    "distance": cut_s, "cut": True})
        if blocked is not None:  # it waits at the barrier (and stops there, if it stops later)
            return out, ((stop, path[-1]) if stop is not None else None), blocked
        return out, (stop, path[-1]), None
    if stop is not None:
        return out, (stop, here), None
    return out, None, None


def actual_schedule(world: dict, schedule: dict, faults: MotionFaults) -> tuple[dict, Motion]:
    """The schedule with the legs robots really drive (module docstring), and what they met.
    Robots without a motion fault keep their legs unchanged (nothing is copied for them)."""
    starts = {r: info.get("start", (0.0, 0.0)) for r, info in (world.get("robots") or {}).items()}
    robots = {}
    motion = Motion(legs={})
    affected = set(faults.stops) | set(faults.slow)
    for r, info in (schedule.get("robots") or {}).items():
        legs = info.get("legs") or []
        if r not in affected and not faults.barriers:
            robots[r] = info
            continue
        actual, stopped, blocked = robot_motion(starts.get(r, (0.0, 0.0)), legs, faults.stops.get(r),
                                                faults.slow.get(r), faults.barriers)
        if stopped is not None:
            motion.stopped[r] = stopped
        if blocked is not None:
            motion.blocked.append((blocked[0], r, blocked[1], blocked[2]))
        robots[r] = {**info, "legs": actual, "distance": sum(float(l.get("distance", 0.0)) for l in actual)}
        motion.legs[r] = actual
    for r, t in faults.stops.items():  # a robot with no legs at all stops where it stands
        if r not in motion.stopped and r in starts and r not in (schedule.get("robots") or {}):
            motion.stopped[r] = (t, tuple(map(float, starts[r])))
    return with_legs(schedule, robots), motion


def with_legs(schedule: dict, robots: dict) -> dict:
    """A schedule with other legs: its makespan and travel figures recomputed from them."""
    ends = [float(s["end"]) for s in schedule.get("subtasks", [])]
    ends += [float(l["end"]) for info in robots.values() for l in info.get("legs", [])]
    return {**schedule, "robots": robots, "makespan": max(ends, default=0.0),
            **travel_costs({r: float(info.get("distance", 0.0)) for r, info in robots.items()})}


def trajectory(world: dict, schedule: dict, robot: str) -> Trajectory:
    start = (world.get("robots") or {}).get(robot, {}).get("start", (0.0, 0.0))
    return Trajectory(start, ((schedule.get("robots") or {}).get(robot) or {}).get("legs", []))


def first_deviation(planned: Trajectory, actual: Trajectory, after: float, until: float,
                    tolerance: float = ARRIVAL_TOLERANCE) -> float | None:
    """The first instant after ``after`` at which a robot is farther than ``tolerance`` from where
    the plan has it (sampled every :data:`MONITOR_STEP` and at every vertex), or None."""
    times = {t for t in planned.vertex_times() + actual.vertex_times() if after < t <= until}
    k = 1
    while after + k * MONITOR_STEP <= until:
        times.add(after + k * MONITOR_STEP)
        k += 1
    for t in sorted(times):
        if math.dist(planned.position(t), actual.position(t)) > tolerance:
            return t
    return None


def distance_until(legs: Iterable[dict], t: float) -> float:
    """Metres a robot's (actual) legs cover by time ``t``."""
    total = 0.0
    for leg in legs:
        start, end, d = float(leg["start"]), float(leg["end"]), float(leg.get("distance", 0.0))
        if end <= t:
            total += d
        elif start < t:
            total += d * (t - start) / (end - start) if end > start else d
    return total


def clip_legs(legs: Iterable[dict], t: float) -> list[dict]:
    """The part of the legs driven by ``t``, marked ``done`` (a leg under way is cut at ``t``)."""
    out = []
    for leg in legs:
        start, end = float(leg["start"]), float(leg["end"])
        if start >= t - 1e-9 and not (end <= t + 1e-9):
            continue
        if end <= t + 1e-9:
            out.append({**leg, "done": True})
            continue
        pts = _points(leg)
        cum = _cumulative(pts)
        s = cum[-1] * (t - start) / (end - start) if end > start else cum[-1]
        path = cut_polyline(pts, cum, s)
        out.append({**leg, "end": t, "path": [list(p) for p in path], "to": list(path[-1]), "distance": s,
                    "done": True, "cut": True})
    return out


# ------------------------------------------------------------------------------------------
# barriers and drop sites
# ------------------------------------------------------------------------------------------
def _footprints(world: dict) -> list[tuple[float, float, float, float]]:
    fixtures = task_domain(world).places(world)
    rects = [(float(s["x"]), float(s["y"]), float(s["x"]) + float(s["width"]), float(s["y"]) + float(s["depth"]))
             for s in fixtures.values()]
    rects += [(float(b["x"]), float(b["y"]), float(b["x"]) + float(b["width"]), float(b["y"]) + float(b["depth"]))
              for b in world.get("barriers") or []]
    return rects


def _points_to_keep_clear(world: dict) -> list[Point]:
    fixtures = task_domain(world).places(world)
    pts = [(float(s["access"][0]), float(s["access"][1])) for s in fixtures.values() if s.get("access")]
    pts += [(float(r["start"][0]), float(r["start"][1])) for r in (world.get("robots") or {}).values()]
    return pts


def barrier_across(world: dict, point: Point, direction: Point, reach: float = BARRIER_REACH,
                   clear: float = 0.5) -> dict | None:
    """A barrier across a passage at ``point`` on a path going ``direction``: a thin rectangle,
    axis-aligned (the travel map's obstacles are), perpendicular to the path's main axis, out on
    each side to the nearest footprint or wall, at most ``reach`` metres, and short of any access
    point or robot start (kept ``clear`` metres away, so no place is walled in and no robot is
    inside it). None when the point itself is too close to one of those."""
    px, py = float(point[0]), float(point[1])
    half = BARRIER_THICKNESS / 2
    width, height = float(world["floor"]["width"]), float(world["floor"]["height"])
    vertical = abs(direction[0]) >= abs(direction[1])  # a path along x is closed by a wall along y
    keep = _points_to_keep_clear(world)
    if any(math.dist((px, py), q) < clear + half for q in keep):
        return None
    rects = _footprints(world)
    # along the barrier: coordinate a (y for a vertical barrier), across it: b (its thickness)
    a0, b0 = (py, px) if vertical else (px, py)
    a_max = height if vertical else width
    lo, hi = max(0.0, a0 - reach), min(a_max, a0 + reach)
    for (x0, y0, x1, y1) in rects:
        r_b0, r_b1, r_a0, r_a1 = (x0, x1, y0, y1) if vertical else (y0, y1, x0, x1)
        if r_b1 <= b0 - half or r_b0 >= b0 + half:
            continue  # not in the barrier's strip
        if r_a0 <= a0 <= r_a1:
            return None  # the point lies in a footprint's strip: no passage here
        if r_a0 > a0:
            hi = min(hi, r_a0)
        else:
            lo = max(lo, r_a1)
    for q in keep:
        qa, qb = (q[1], q[0]) if vertical else (q[0], q[1])
        if abs(qb - b0) < clear + half:
            if qa > a0:
                hi = min(hi, qa - clear)
            else:
                lo = max(lo, qa + clear)
    if hi - lo < 0.5:
        return None
    if vertical:
        return {"x": round(px - half, 4), "y": round(lo, 4), "width": BARRIER_THICKNESS, "depth": round(hi - lo, 4)}
    return {"x": round(lo, 4), "y": round(py - half, 4), "width": round(hi - lo, 4), "depth": BARRIER_THICKNESS}


def inside(point: Point, rect: tuple[float, float, float, float]) -> bool:
    return rect[0] < point[0] < rect[2] and rect[1] < point[1] < rect[3]


def drop_site(world: dict, point: Point, toward: Point | None = None,
              reaches: Callable[[dict], bool] | None = None) -> dict:
    """The footprint and access point of the place where a robot that stopped at ``point`` keeps
    what it carried: its access point is ``point`` itself (another robot comes where it stands),
    its footprint a :data:`DROP_SIDE` square just beside it, on the side ``toward`` (where it came
    from) or the first side where the square covers no access point or robot start and overlaps
    no footprint (a robot may stop right at a shelf's access point). ``reaches(site)``: whether a
    robot can still get to the site's access point once its footprint is there; a side that walls
    the access point in (the square and the margins of the furniture around it closing a pocket)
    is passed over while another side keeps it reachable."""
    px, py = float(point[0]), float(point[1])
    half = DROP_SIDE / 2
    rects = _footprints(world)
    keep = _points_to_keep_clear(world)
    width, height = float(world["floor"]["width"]), float(world["floor"]["height"])
    sides = [(1.0, 0.0), (-1.0, 0.0), (0.0, 1.0), (0.0, -1.0)]
    if toward is not None:
        d = (toward[0] - px, toward[1] - py)
        sides.sort(key=lambda s: -(s[0] * d[0] + s[1] * d[1]))
    fits: list[dict] = []
    for size in (DROP_SIDE, DROP_SIDE / 3):
        half = size / 2
        for sx, sy in sides:
            cx, cy = px + sx * DROP_ACCESS, py + sy * DROP_ACCESS
            box = (cx - half, cy - half, cx + half, cy + half)
            on_floor = box[0] > 0 and box[1] > 0 and box[2] < width and box[3] < height
            overlaps = any(box[0] < r[2] and r[0] < box[2] and box[1] < r[3] and r[1] < box[3] for r in rects)
            covers = any(box[0] <= q[0] <= box[2] and box[1] <= q[1] <= box[3] for q in keep + [(px, py)])
            if on_floor and not overlaps and not covers:
                site = {"x": round(box[0], 4), "y": round(box[1], 4), "width": size, "depth": size,
                        "access": [round(px, 4), round(py, 4)]}
                if reaches is None or reaches(site):
                    return site
                fits.append(site)
    if fits:  # no side keeps it reachable: the first that fits (a re-plan will say what cannot be done)
        return fits[0]
    return {"x": round(px + 0.2, 4), "y": round(py + 0.2, 4), "width": 0.01, "depth": 0.01,
            "access": [round(px, 4), round(py, 4)]}


def clear_of(point: Point, rects: Iterable[tuple[float, float, float, float]], margin: float = 0.01) -> Point:
    """``point``, or the nearest point just outside the footprint it lies in (a robot standing
    where a barrier or a drop site now is): the travel map refuses points inside footprints."""
    x, y = float(point[0]), float(point[1])
    for x0, y0, x1, y1 in rects:
        if x0 < x < x1 and y0 < y < y1:
            moves = [(x0 - margin - x, 0.0), (x1 + margin - x, 0.0), (0.0, y0 - margin - y), (0.0, y1 + margin - y)]
            dx, dy = min(moves, key=lambda m: abs(m[0]) + abs(m[1]))
            x, y = x + dx, y + dy
    return (x, y)


def robot_starts(world: dict) -> dict[str, Any]:
    return {r: info.get("start") for r, info in (world.get("robots") or {}).items()}

"""Where a run stands at the moment a recovery begins: which subtasks are done, which are under
way (and run to their end), which have not begun; where every robot is, when it is free, how far
it has driven; and the legs driven so far, cut at that moment.

Why subtasks under way run to their end: their robots have taken something on (a load, an
object) and are the only ones who can put it down; stopping them would strand it. So the cut is
per robot: robots of a running subtask finish it (from where they are, at their real pace, round
any passage now known to be closed), every other robot stops where it is and waits for new work.
A running subtask whose coalition lost a member is **broken**: its surviving members still finish
their part (the domain's simulation decides what that delivers), and the plan must be made anew.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

from pipflow.execution.capability import Played
from pipflow.execution.motion import clear_of, clip_legs, distance_until
from pipflow.team.scheduling import Standing
from pipflow.team.trajectory import ARRIVAL_TOLERANCE, Trajectory

#: seconds within which two moments are one (the simulations report their events to the millisecond)
EPS = 1e-3


@dataclass
class Cut:
    """A run cut at ``time`` (module docstring). ``legs``: per robot, the legs driven by then
    (marked ``done``) and, for robots of running subtasks, the legs that finish them; ``records``:
    the schedule records of done and running subtasks (a running one with its new end)."""

    time: float
    done: list[str] = field(default_factory=list)
    running: list[str] = field(default_factory=list)
    broken: list[str] = field(default_factory=list)
    pending: list[str] = field(default_factory=list)
    legs: dict[str, list[dict]] = field(default_factory=dict)
    records: list[dict] = field(default_factory=list)
    standing: Standing = field(default_factory=Standing)


def split(records: list[dict], played: Played, t: float, stopped: set[str]) -> tuple[list, list, list, list]:
    """(done, running, broken, pending) subtask ids at ``t``: done when its effects landed by
    ``t`` as planned; running when its work began before ``t``; broken when it began and a member
    stopped (or it was interrupted) by ``t``, whether or not the others then ended their part (it
    counts as running: its surviving members finish it); pending otherwise (not begun, refused)."""
    done, running, broken, pending = [], [], [], []
    for rec in records:
        sid = rec["id"]
        began = played.began.get(sid, math.inf) < t - EPS
        cut_short = began and (played.interrupted.get(sid, math.inf) <= t + EPS
                               or (bool(set(rec.get("robots") or []) & stopped)
                                   and played.ended.get(sid, math.inf) > t + EPS))
        if cut_short:
            running.append(sid)
            broken.append(sid)
        elif played.ended.get(sid, math.inf) <= t + EPS:
            done.append(sid)
        elif began:
            running.append(sid)
        else:
            pending.append(sid)
    return done, running, broken, pending


@dataclass(frozen=True)
class Driving:
    """How robots drive from now on: the ``travel`` map of the world as now known (closed
    passages, drop places), the planned ``speed`` and ``handling`` time per route stop, and each
    robot's ``pace`` (the share of the planned speed a slowed robot drives at; 1 when absent)."""

    travel: Any
    speed: float
    handling: float
    pace: dict[str, float] = field(default_factory=dict)


@dataclass(frozen=True)
class Stops:
    """The robots ``stopped`` by the cut (their time and point) and, for a stopped robot that
    carried a load, its drop place (``drops``): where it now stands for the travel map."""

    stopped: dict[str, tuple[float, Any]]
    drops: dict[str, str] | None = None


def cut(world: dict, records: list[dict], nodes: dict[str, dict], actual: dict, played: Played, t: float,
        stops: Stops, driving: Driving) -> Cut:
    """The run cut at ``t`` (module docstring). ``actual``: the schedule with the legs robots
    really drove."""
    stopped, drops, pace, travel = stops.stopped, stops.drops, driving.pace, driving.travel
    lost = set(stopped)
    done, running, broken, pending = split(records, played, t, lost)
    out = Cut(t, done, running, broken, pending)
    by_id = {r["id"]: r for r in records}
    robots = world.get("robots") or {}
    legs_of = {r: list(((actual.get("robots") or {}).get(r) or {}).get("legs") or []) for r in robots}
    rects = [(x0, y0, x1, y1) for (x0, y0, x1, y1) in travel.footprints.values()]
    st = Standing(time=t)
    continuing: dict[str, tuple[list[dict], float, Any]] = {}
    for sid in running:
        members = [r for r in by_id[sid].get("robots") or [] if r not in lost and r in robots]
        if members:
            continuing.update(_finish(sid, nodes[sid], members, legs_of, world, t, driving, rects))
    ends: dict[str, float] = {}
    for r in robots:
        legs = legs_of[r]
        driven = distance_until(legs, t)
        out.legs[r] = clip_legs(legs, t)
        st.pace[r] = pace.get(r, 1.0)
        if r in continuing:
            new, free, place = continuing[r]
            out.legs[r] += new
            st.pos[r], st.free[r] = place, free
            st.driven[r] = driven + sum(float(l["distance"]) for l in new)
            for leg in new:
                ends[leg["subtask"]] = max(ends.get(leg["subtask"], 0.0), free)
            continue
        if r in lost and drops and r in drops:
            st.pos[r] = drops[r]  # it stands by its cargo: the drop place's access point
        else:
            st.pos[r] = _here(world, r, legs, t, rects)
        st.free[r], st.driven[r] = t, driven
    for sid in running:
        rec = dict(by_id[sid])
        if sid in ends:
            rec["end"] = ends[sid]
        out.records.append(rec)
        st.ended[sid] = float(rec["end"])
    for sid in done:
        out.records.append(by_id[sid])
        st.ended[sid] = played.ended[sid]
    out.records.sort(key=lambda r: (float(r["start"]), r["id"]))
    out.standing = st
    return out


def _reached(legs: list[dict], route_points: list[tuple[float, float]], t: float) -> int:
    """Index of the last route place a robot's legs of one subtask reached by ``t`` (0: the first,
    where the work began)."""
    j = 0
    for leg in legs:
        if float(leg["end"]) <= t + EPS and leg.get("to") is not None:
            for k, p in enumerate(route_points):
                if k > j and math.dist(tuple(map(float, leg["to"])), p) <= ARRIVAL_TOLERANCE:
                    j = k
    return j


def _finish(sid: str, node: dict, members: list[str], legs_of: dict[str, list[dict]], world: dict, t: float,
            driving: Driving, rects: list) -> dict[str, tuple[list, float, Any]]:
    """How the surviving members of a running subtask finish it from ``t``: per member its new
    legs, when it is free, and the place it ends at. Each drives from where it is to the next
    place of the route at its own pace; then the coalition drives on together at its slowest
    member's pace, handling at every stop (as :class:`~pipflow.team.scheduling.Timeline` plans)."""
    travel, speed, handling, pace = driving.travel, driving.speed, driving.handling, driving.pace
    route = list(node.get("route") or [])
    points = [travel.point(p) for p in route]
    mine = {m: [l for l in legs_of[m] if l.get("subtask") == sid] for m in members}
    reached = max(_reached(mine[m], points, t) for m in members)
    remaining = route[reached + 1:]
    if not remaining:  # at the last place: handling there, then done
        last = max([float(l["end"]) for m in members for l in mine[m]] + [t - handling])
        end = max(t, last + handling)
        return {m: ([], end, route[-1] if route else _here(world, m, legs_of[m], t, rects)) for m in members}
    new: dict[str, list[dict]] = {m: [] for m in members}
    arrive = {}
    for m in members:
        here = _here(world, m, legs_of[m], t, rects)
        ahead = [l for l in mine[m] if float(l["end"]) > t + EPS]
        depart = max([t] + [float(l["start"]) for l in ahead[:1] if float(l["start"]) > t])
        v = speed * pace.get(m, 1.0)
        d = travel.distance(here, remaining[0])
        if d > 1e-9:
            new[m].append(_leg(sid, travel, here, remaining[0], depart, depart + d / v, d, pace.get(m, 1.0)))
        arrive[m] = depart + d / v
    ready = max(arrive.values())
    v = speed * min(pace.get(m, 1.0) for m in members)
    for a, b in zip(remaining, remaining[1:]):
        depart = ready + handling
        d = travel.distance(a, b)
        for m in members:
            new[m].append(_leg(sid, travel, a, b, depart, depart + d / v, d, min(pace.get(x, 1.0) for x in members)))
        ready = depart + d / v
    end = ready + handling
    return {m: (new[m], end, remaining[-1]) for m in members}


def _here(world: dict, robot: str, legs: list[dict], t: float, rects: list) -> tuple[float, float]:
    """Where a robot is at ``t`` on its (actual) legs, moved just clear of a footprint it stands in."""
    start = (world.get("robots") or {}).get(robot, {}).get("start", (0.0, 0.0))
    return clear_of(Trajectory(start, legs).position(t), rects)


def _leg(sid: str, travel: Any, a: Any, b: Any, start: float, end: float, d: float, pace: float) -> dict:
    leg = {"subtask": sid, "from": list(travel.point(a)), "to": list(travel.point(b)), "path": travel.path(a, b),
           "start": start, "end": end, "distance": d}
    if pace != 1.0:
        leg["pace"] = pace
    return leg

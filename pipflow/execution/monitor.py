"""The monitor: what happened against what the schedule expects, and the first difference.

It watches what a real fleet manager can watch, each at the moment it can be known:

* **stopped**: a robot stops reporting (its heartbeat ends) at the moment it stops;
* **blocked**: a robot reports a closed passage when it reaches it;
* **surprise**: a robot that arrives at a place sees what it holds, and it is not what the
  records say (known at its arrival, before it takes anything);
* **behind**: a robot is farther from where the plan has it than the arrival tolerance (a slow
  robot is noticed as soon as it has fallen that far behind);
* **refused**: a subtask could not start when it was due (the simulation refused it: a
  precondition did not hold), and **unfinished**: a subtask began and never ended.

:func:`first_anomaly` returns the earliest one not handled yet; the executor stops the affected
part there and recovers.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

from pipflow.execution.capability import Played
from pipflow.execution.faults import SLOWDOWN, SURPRISE, Fault
from pipflow.execution.motion import Motion, first_deviation, trajectory
from pipflow.taskdomains import task_domain
from pipflow.team.trajectory import ARRIVAL_TOLERANCE

#: at equal times, which is seen first (a stop explains what follows it)
ORDER = ("stopped", "blocked", "surprise", "behind", "refused", "unfinished")


@dataclass(frozen=True)
class Anomaly:
    """One difference between the run and its schedule: when, what, who, which fault it reveals
    (None: none declared explains it), where, and in words."""

    time: float
    kind: str
    robot: str | None = None
    fault: str | None = None
    place: str | None = None
    subtask: str | None = None
    words: str = ""

    @property
    def key(self) -> tuple:
        """What makes two anomalies the same (the same one is handled once)."""
        return (self.kind, self.fault, self.robot, self.subtask)

    def to_json(self) -> dict:
        return {k: v for k, v in {"time": round(self.time, 3), "kind": self.kind, "robot": self.robot,
                                  "fault": self.fault, "place": self.place, "subtask": self.subtask,
                                  "words": self.words}.items() if v is not None}


def arrivals(schedule: dict, point: tuple[float, float]) -> list[tuple[float, str]]:
    """(time, robot) of every leg that ends at ``point`` (within the arrival tolerance)."""
    out = []
    for r, info in (schedule.get("robots") or {}).items():
        for leg in info.get("legs") or []:
            to = leg.get("to")
            if to is not None and math.dist((float(to[0]), float(to[1])), point) <= ARRIVAL_TOLERANCE:
                out.append((float(leg["end"]), r))
    return sorted(out)


@dataclass(frozen=True)
class Known:
    """What the executor knows already: the keys of the anomalies it ``handled``, the time of the
    last one (none is looked for before it: ``after``) and the surprises ``discovered`` (fault ids)."""

    handled: frozenset[tuple] = frozenset()
    after: float = 0.0
    discovered: frozenset[str] = frozenset()


def access_points(world: dict) -> dict[str, tuple[float, float]]:
    """A place's access point by name: where a robot arriving at it stands (its task domain's fixtures)."""
    return {n: (float(p["access"][0]), float(p["access"][1]))
            for n, p in task_domain(world).places(world).items() if p.get("access")}


def first_anomaly(world: dict, faults: list[Fault], planned: dict, actual: dict, motion: Motion, played: Played,
                  known: Known = Known()) -> Anomaly | None:
    """The earliest anomaly at or after ``known.after`` not handled yet (module doc).

    ``planned``: the schedule the robots were given; ``actual``: the one they drove."""
    after, place_points = known.after, access_points(world)
    found: list[Anomaly] = []
    by_id = {f.id: f for f in faults}
    stop_fault = {f.robot: f.id for f in faults if f.kind == "robot-loss"}
    for r, (t, _) in motion.stopped.items():
        found.append(Anomaly(t, "stopped", robot=r, fault=stop_fault.get(r), words=f"{r} stopped reporting"))
    for t, r, _, fid in motion.blocked:
        found.append(Anomaly(t, "blocked", robot=r, fault=fid, words=f"{r} found the passage closed "
                                                                    f"({by_id[fid].describe() if fid in by_id else fid})"))
    for f in faults:
        if f.kind != SURPRISE or f.id in known.discovered:
            continue
        seen = []
        for place in (f.surprise or {}).get("places") or []:
            if place in place_points:
                seen += [(t, r, place) for t, r in arrivals(actual, place_points[place])]
        if seen:
            t, r, place = min(seen)
            found.append(Anomaly(max(t, after), "surprise", robot=r, fault=f.id, place=place,
                                 words=f"{r} arrived at {place}: {f.describe()}"))
    slow = {f.robot: f for f in faults if f.kind == SLOWDOWN}
    blocked = {r for _, r, _, _ in motion.blocked}
    horizon = float(actual.get("makespan", 0.0)) + 1.0
    for r in motion.legs:
        if r in motion.stopped or r in blocked:
            continue
        planned_legs = ((planned.get("robots") or {}).get(r) or {}).get("legs") or []
        if planned_legs == motion.legs[r]:
            continue
        t = first_deviation(trajectory(world, planned, r), trajectory(world, actual, r), after, horizon)
        if t is not None:
            f = slow.get(r)
            found.append(Anomaly(t, "behind", robot=r, fault=f.id if f else None,
                                 words=f"{r} is {ARRIVAL_TOLERANCE:g} m behind where the plan has it"))
    for fail in played.failures:
        found.append(Anomaly(float(fail["time"]), "refused", subtask=fail["subtask"],
                             words=f"{fail['subtask']} could not start: {'; '.join(fail.get('reasons') or [])}"))
    stopped_robots = set(motion.stopped)
    for rec in planned.get("subtasks", []):
        sid = rec["id"]
        if sid in played.began and sid not in played.ended and not (set(rec.get("robots") or []) & stopped_robots):
            found.append(Anomaly(float(rec["end"]), "unfinished", subtask=sid,
                                 words=f"{sid} began at t={played.began[sid]:.1f} s and never ended"))
    fresh = [a for a in found if a.time >= after - 1e-9 and a.key not in known.handled]
    if not fresh:
        return None
    # times within a millisecond are one instant (the simulation reports its events to the ms)
    return min(fresh, key=lambda a: (round(a.time, 3), ORDER.index(a.kind)))

"""Alg. 1 timing: when each subtask starts and ends, and where every robot drives.

A subtask can start when (a) every predecessor in the dependency graph has ended and (b) every
robot of its coalition has reached the first place of its route. The coalition then handles
the load at each stop (``handling`` seconds per stop) and drives the route together at
``speed``. Afterwards each robot stands at the route's last place and is free at the
subtask's end. Allocation (which needs where robots are, and in frontier mode when they are
free) and the ``schedule`` step share this one :class:`Timeline`, so the costs the allocator
optimised are exactly the distances the schedule reports.

The allocation cost c_i of a robot for a subtask has two definitions (:data:`COSTS`):

* ``total`` (the paper, Sec. IV-C: "the total travel distance of robot i"): the metres the robot
  has driven so far in this schedule, plus its approach to the subtask and the subtask's route.
  Minimising the largest c_i then balances the team's work: a robot that has driven far is
  expensive, one that idled is cheap. The costs of a robot's last subtask are its distance in
  the schedule, so the allocator's max is the schedule's TC-max.
* ``subtask``: the approach plus the route of this subtask only. It picks the nearest robots
  for each subtask whatever they did before: less driving in total (TC-sum), but one robot may
  do most of the work (a larger TC-max and makespan).

A timeline may start from a :class:`Standing` instead of the world's starts: where each robot
stands (a place or a point), when it is free, how far it has driven, which subtasks have already
ended (or will, as they run) and when, and the pace of robots found slower than planned. That is
how a run re-allocates what is left after something went wrong (:mod:`pipflow.execution`): the
same costs, the same IP, from where everyone stands now.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any, Iterable

from pipflow.errors import InputError
from pipflow.metrics import travel_costs

#: the allocation costs c_i a :class:`Timeline` can give (the first is the paper's and the default)
COSTS = ("total", "subtask")
DEFAULT_COST = COSTS[0]


def check_cost(cost: str) -> str:
    """``cost`` if it names a definition of :data:`COSTS`, else an InputError listing them."""
    if cost not in COSTS:
        raise InputError(f"unknown allocation cost {cost!r}; use total (each robot's travel so far plus "
                         f"this subtask, the paper's) or subtask (this subtask's approach and route only)")
    return cost


@dataclass
class Standing:
    """Where a team stands at ``time``, for a timeline that continues from there (module doc).

    ``pos``: a robot's place name or ``[x, y]`` point (robots not given stand at their start);
    ``free``: when it can start something new; ``driven``: metres it has driven (or will, to
    finish what it is doing); ``ended``: end times of subtasks done or running (their successors
    wait for them); ``pace``: the share of the planned speed a robot really drives at (1: as
    planned), which its new legs then assume and record."""

    time: float = 0.0
    pos: dict[str, Any] = field(default_factory=dict)
    free: dict[str, float] = field(default_factory=dict)
    driven: dict[str, float] = field(default_factory=dict)
    ended: dict[str, float] = field(default_factory=dict)
    pace: dict[str, float] = field(default_factory=dict)


class Timeline:
    """Robots' positions and free times, and subtasks' end times, as subtasks are committed."""

    def __init__(self, world: dict, travel=None, speed: float = 1.0, handling: float = 2.0,
                 cost: str = DEFAULT_COST, standing: Standing | None = None):
        # deferred: pulls networkx and numpy (~350 ms; a schedule without travel times needs neither)
        from pipflow.team.travel import TravelMap

        if not 0 < speed < math.inf:  # NaN fails too: it would make every time NaN
            raise InputError(f"speed must be a positive finite number (m/s), got {speed}")
        if not 0 <= handling < math.inf:
            raise InputError(f"handling time must be a finite number >= 0 s, got {handling}")
        self.world = world
        self.travel = travel if travel is not None else TravelMap(world)
        self.speed = float(speed)
        self.handling = float(handling)
        self.cost_kind = check_cost(cost)
        self.robots = list((world.get("robots") or {}).keys())
        self.pos: dict[str, Any] = {r: r for r in self.robots}  # a robot name means its start
        self.free: dict[str, float] = {r: 0.0 for r in self.robots}
        self.end: dict[str, float] = {}
        self.legs: dict[str, list[dict]] = {r: [] for r in self.robots}
        self.driven: dict[str, float] = {r: 0.0 for r in self.robots}  # metres of the legs so far
        self.pace: dict[str, float] = {}  # robots slower than planned (absent: 1)
        self.records: list[dict] = []
        if standing is not None:
            self._continue_from(standing)

    def _continue_from(self, standing: Standing) -> None:
        """Start where ``standing`` says the team is (names it does not know are refused)."""
        named = set(standing.pos) | set(standing.free) | set(standing.driven) | set(standing.pace)
        unknown = sorted(named - set(self.robots))
        if unknown:
            raise InputError(f"the standing names robots the world does not have: {', '.join(unknown)}")
        for r, p in standing.pos.items():
            self.pos[r] = p if isinstance(p, str) else (float(p[0]), float(p[1]))
        self.free.update({r: float(t) for r, t in standing.free.items()})
        self.driven.update({r: float(m) for r, m in standing.driven.items()})
        self.end.update({s: float(t) for s, t in standing.ended.items()})
        for r, f in standing.pace.items():
            if not 0 < f < math.inf:
                raise InputError(f"pace of {r} must be a positive finite share of its speed, got {f}")
            if f != 1.0:
                self.pace[r] = float(f)

    def speed_of(self, robot: str) -> float:
        """Metres per second the robot really drives (its pace times the planned speed)."""
        return self.speed * self.pace.get(robot, 1.0)

    # -- costs ------------------------------------------------------------------------------
    def check_route(self, node: dict) -> list[str]:
        route = list(node.get("route") or [])
        if not route:
            raise InputError(f"subtask {node['id']} has an empty route; action metadata must give `route`")
        for p in route:
            self.travel.point(p)  # raises InputError naming unknown places
        return route

    def route_length(self, node: dict) -> float:
        return self.travel.route_length(self.check_route(node))

    def approach(self, robot: str, node: dict) -> float:
        """Metres robot drives from where it is to the route's first place."""
        return self.travel.distance(self.pos[robot], self.check_route(node)[0])

    def subtask_cost(self, robot: str, node: dict) -> float:
        """Metres this subtask alone makes the robot drive: approach plus the route itself."""
        return self.approach(robot, node) + self.route_length(node)

    def cost(self, robot: str, node: dict) -> float:
        """c_i of the allocation IP, as this timeline's ``cost_kind`` defines it (module doc):
        ``total``, the robot's distance in the schedule once it has done ``node``; ``subtask``,
        what ``node`` alone adds to it."""
        if self.cost_kind == "subtask":
            return self.subtask_cost(robot, node)
        return self.driven[robot] + self.subtask_cost(robot, node)

    def duration(self, node: dict) -> float:
        """Seconds from the coalition's gathering to the end: handling at each stop + driving."""
        return self.handling * len(self.check_route(node)) + self.route_length(node) / self.speed

    def ready(self, node: dict, preds: Iterable[str]) -> float:
        """Earliest start allowed by the dependency graph."""
        return max((self.end[p] for p in preds), default=0.0)

    def arrival(self, robot: str, node: dict) -> float:
        return self.free[robot] + self.approach(robot, node) / self.speed_of(robot)

    # -- commit -----------------------------------------------------------------------------
    def commit(self, node: dict, robots: list[str], preds: Iterable[str]) -> dict:
        """Fix the subtask's timing, append the robots' legs, move the robots."""
        preds = list(preds)
        missing = [p for p in preds if p not in self.end]
        if missing:
            raise InputError(f"subtask {node['id']} is committed before its predecessors {missing}")
        if not robots:
            raise InputError(f"subtask {node['id']} has no robots")
        route = self.check_route(node)
        ready = self.ready(node, preds)
        start = max([ready] + [self.arrival(r, node) for r in robots])
        for r in robots:
            d = self.approach(r, node)
            if d > 1e-12:
                a = self.travel.point(self.pos[r])
                b = self.travel.point(route[0])
                self.legs[r].append(self._paced(r, {
                    "subtask": node["id"], "from": list(a), "to": list(b),
                    "path": self.travel.path(self.pos[r], route[0]),
                    "start": self.free[r], "end": self.free[r] + d / self.speed_of(r), "distance": d,
                }))
                self.driven[r] += d
        speed = min(self.speed_of(r) for r in robots)  # a coalition drives at its slowest member's pace
        t = start + self.handling
        for k in range(1, len(route)):
            d = self.travel.distance(route[k - 1], route[k])
            a, b = self.travel.point(route[k - 1]), self.travel.point(route[k])
            path = self.travel.path(route[k - 1], route[k])
            for r in robots:
                self.legs[r].append(self._paced(r, {"subtask": node["id"], "from": list(a), "to": list(b),
                                                    "path": path, "start": t, "end": t + d / speed, "distance": d}))
                self.driven[r] += d
            t += d / speed + self.handling
        end = t
        for r in robots:
            self.pos[r] = route[-1]
            self.free[r] = end
        self.end[node["id"]] = end
        rec = {"id": node["id"], "action": node.get("action"), "args": node.get("args", []),
               "robots": list(robots), "ready": ready, "start": start, "end": end}
        self.records.append(rec)
        return rec

    def refuse(self, node: dict, robots: list[str], preds: Iterable[str]) -> dict:
        """Record a subtask that cannot be placed in this world (its node says why under
        ``unexecutable``: an action on a place or object the world lacks, robots that do not
        exist): it is in the schedule, at the moment its predecessors have ended, under
        ``refused``, and takes no time; nobody drives. A simulation counts it as planned and not
        executed (Exe < 1), as the paper's baselines count an action their executor cannot run."""
        preds = list(preds)
        missing = [p for p in preds if p not in self.end]
        if missing:
            raise InputError(f"subtask {node['id']} is committed before its predecessors {missing}")
        ready = self.ready(node, preds)
        self.end[node["id"]] = ready
        rec = {"id": node["id"], "action": node.get("action"), "args": node.get("args", []),
               "robots": list(robots), "ready": ready, "start": ready, "end": ready,
               "refused": [str(r) for r in node["unexecutable"]]}
        self.records.append(rec)
        return rec

    def _paced(self, robot: str, leg: dict) -> dict:
        """A leg of a robot slower than planned says at which share of the speed it was planned
        (``pace``), so that execution does not slow it a second time; other legs are unchanged."""
        if robot in self.pace:
            leg["pace"] = self.pace[robot]
        return leg

    def result(self) -> dict:
        """The schedule contract of docs/architecture.md."""
        robots = {}
        for r in self.robots:
            robots[r] = {"legs": self.legs[r], "distance": self.driven[r]}
        return {
            "subtasks": self.records,
            "robots": robots,
            "makespan": max((rec["end"] for rec in self.records), default=0.0),
            # tc_max, tc_avg (over the robots that moved: the paper's TC-avg), tc_avg_team (every robot)
            **travel_costs({r: v["distance"] for r, v in robots.items()}),
        }


def predecessors(graph: dict) -> dict[str, list[str]]:
    preds: dict[str, list[str]] = {n["id"]: [] for n in graph["nodes"]}
    for u, v in graph["edges"]:
        if u not in preds or v not in preds:
            raise InputError(f"graph edge {u} -> {v} names an unknown subtask")
        preds[v].append(u)
    return preds


def build_schedule(graph: dict, allocation: dict, world: dict, speed: float = 1.0,
                   handling: float = 2.0, travel=None) -> dict:
    """Replay an allocation in its order (Alg. 1) and time it.

    Every subtask must be allocated exactly once, after its predecessors. A node marked
    ``unexecutable`` (a plan's action that names what this world lacks) is recorded as refused
    (:meth:`Timeline.refuse`) instead of timed."""
    nodes = {n["id"]: n for n in graph["nodes"]}
    preds = predecessors(graph)
    tl = Timeline(world, travel=travel, speed=speed, handling=handling)
    seen = set()
    for a in allocation.get("assignments", []):
        sid = a.get("subtask")
        if sid not in nodes:
            raise InputError(f"allocation names unknown subtask {sid!r}")
        if sid in seen:
            raise InputError(f"allocation assigns subtask {sid} twice")
        if nodes[sid].get("unexecutable"):  # not placeable in this world: recorded, refused, no time
            seen.add(sid)
            tl.refuse(nodes[sid], list(a.get("robots", [])), preds[sid])
            continue
        unknown = [r for r in a.get("robots", []) if r not in tl.free]
        if unknown:
            raise InputError(f"allocation of {sid} names unknown robots {unknown}")
        seen.add(sid)
        tl.commit(nodes[sid], list(a["robots"]), preds[sid])
    missing = [s for s in nodes if s not in seen]
    if missing:
        raise InputError(f"allocation leaves subtasks unallocated: {', '.join(missing)}")
    return tl.result()

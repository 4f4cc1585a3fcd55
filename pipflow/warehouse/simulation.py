"""Execute a schedule in a headless pybullet world and read back what really happened.

Why a simulator at all, when the schedule already says where everything goes? Because the
benchmark judges what the *world* looks like afterwards, not what the plan claims: an action
whose preconditions do not hold when it starts (units missing on the source, no room on the
target, a coalition too weak or not at the shelf) is refused here and counted, and the final
stock is counted from the unit bodies lying on each shelf's footprint. Travel is measured from
the robots' simulated motion, so a schedule whose legs do not connect shows up as extra metres.

Everything is kinematic: bodies have no mass and are placed with ``resetBasePositionAndOrientation``
at sample times (every ``step`` metres of the fastest robot, plus every path vertex so corners are
not cut). No physics is stepped, which keeps a whole warehouse run well under a second.

Event model for a subtask ``s`` with coalition ``R`` and route ``[source, target]``:

* load time  = max(s.start, each robot's arrival at the source access point on its legs for s);
  at that time the preconditions are checked in the simulated state, and on success the units
  are lifted from the source shelf onto the robots (split by carry skill);
* unload time = the last arrival of a coalition robot at the target access point (else s.end);
  the carried units are put on the target shelf's free slots (stacked if the shelf is full, so an
  over-capacity plan is visible as a peak above capacity rather than hidden).

Unloads are applied before loads at the same instant, so a chain through one shelf works.
"""
from __future__ import annotations

import heapq
import math
import re
from dataclasses import dataclass, field
from pathlib import Path
from typing import Iterable

from pipflow import pictures as pics
from pipflow.bullet import colour_rgba, connect_direct, render_floor
from pipflow.goalcounts import values_met
from pipflow.metrics import goal_condition_recall, travel_costs
from pipflow.team.trajectory import ARRIVAL_TOLERANCE, ROBOT_COLOURS, Point, Trajectory
from pipflow.team.trajectory import distance as _dist


SHELF_HEIGHT = 1.0
ROBOT_RADIUS = 0.35
ROBOT_HEIGHT = 0.4


# --------------------------------------------------------------------------------------------
# Plan-side view of a subtask: what it moves and where the coalition goes
# --------------------------------------------------------------------------------------------


@dataclass
class Move:
    """A scheduled subtask as the simulator needs it (merged from schedule and graph)."""

    id: str
    action: str
    args: list
    robots: list[str]
    start: float
    end: float
    product: str | None = None
    source: str | None = None
    target: str | None = None
    units: int = 0
    skills: dict[str, float] = field(default_factory=dict)
    route: list[str] = field(default_factory=list)


def _units_from_args(args: list) -> int:
    """Trailing integer of the last argument (``magnitude6`` -> 6): the warehouse domain names
    its amounts that way; used only when the graph gives no carry requirement."""
    for a in reversed(args or []):
        m = re.search(r"(\d+)$", str(a))
        if m:
            return int(m.group(1))
    return 0


def moves_from(schedule: dict, graph: dict | None) -> list[Move]:
    """Merge schedule subtasks with graph nodes. Units moved = the node's ``carry`` requirement
    (the domain's ``amount`` of the magnitude: carry is units per trip), else the magnitude's
    trailing number. Fields come from the node, else from move-product's argument order."""
    nodes = {n["id"]: n for n in (graph or {}).get("nodes", [])}
    moves = []
    for s in schedule.get("subtasks", []):
        node = nodes.get(s["id"], {})
        args = list(s.get("args") or node.get("args") or [])
        fields = dict(node.get("fields") or {})
        if not fields and s.get("action", node.get("action")) == "move-product" and len(args) >= 3:
            fields = {"from": args[0], "to": args[1], "product": args[2]}
        skills = {k: float(v) for k, v in (node.get("skills") or {}).items()}
        if "units" in node:
            units = int(node["units"])
        elif "carry" in skills:
            units = int(round(skills["carry"]))
        else:
            units = _units_from_args(args)
        if "carry" not in skills and units:
            skills["carry"] = float(units)
        route = list(node.get("route") or [p for p in (fields.get("from"), fields.get("to")) if p])
        moves.append(Move(
            id=s["id"], action=s.get("action", node.get("action", "")), args=args,
            robots=list(s.get("robots") or []), start=float(s.get("start", 0.0)),
            end=float(s.get("end", s.get("start", 0.0))), product=fields.get("product"),
            source=fields.get("from"), target=fields.get("to"), units=units, skills=skills,
            route=route,
        ))
    return moves


# --------------------------------------------------------------------------------------------
# Robot trajectories from schedule legs
# --------------------------------------------------------------------------------------------


# --------------------------------------------------------------------------------------------
# The pybullet scene
# --------------------------------------------------------------------------------------------


class SlotGrid:
    """The slots on a shelf's top face: a cols x rows grid with at least as many cells as the
    shelf can hold (cells as square as the footprint allows), but never more than the units that
    exist in the world (no more can ever lie on it). A slot's position is computed from its index,
    never stored, and the free slots are a heap of freed indices below a high-water mark: placing
    a unit is O(log n), and memory follows the units placed, not the capacity (a capacity of
    10**8 once made a list of 10**8 points and ended in MemoryError).

    When every cell is taken, further units are stacked in layers above (an over-capacity plan
    stays visible as a peak above capacity instead of vanishing); their indices run on past the
    grid, each used once."""

    def __init__(self, shelf: dict, units: int):
        self.x, self.y = float(shelf["x"]), float(shelf["y"])
        self.width, self.depth = float(shelf["width"]), float(shelf["depth"])
        cap = max(1, min(int(shelf.get("capacity", 1)), max(1, units)))
        self.cols = max(1, round(math.sqrt(cap * self.width / self.depth))) if self.depth > 0 else cap
        self.rows = max(1, math.ceil(cap / self.cols))
        self.cells = self.cols * self.rows
        self._freed: list[int] = []   # heap of grid cells freed below the high-water mark
        self._next = 0                # the first grid cell never used
        self._stacked = 0             # units stacked above a full grid so far

    def take(self) -> int:
        """The index of the first free cell (the lowest), else the next place above the grid."""
        if self._freed:
            return heapq.heappop(self._freed)
        if self._next < self.cells:
            self._next += 1
            return self._next - 1
        self._stacked += 1
        return self.cells + self._stacked - 1

    def free(self, index: int) -> None:
        if index < self.cells:
            heapq.heappush(self._freed, index)

    def position(self, index: int) -> Point:
        cell = index % self.cells
        j, i = divmod(cell, self.cols)
        return (self.x + self.width * (i + 0.5) / self.cols, self.y + self.depth * (j + 0.5) / self.rows)

    def layer(self, index: int) -> int:
        return index // self.cells


class Scene:
    """Floor, shelves, unit bodies and robots in one DIRECT pybullet client.

    Shelf slots are a grid on the shelf's top face sized for its capacity; the slot map mirrors
    the bodies' positions, while counts are always read back from the bodies themselves. A grid
    is never built as a list: a slot's place is computed from its index (:class:`SlotGrid`), and
    only as many slots as there are units in the world can ever be used, so a shelf of capacity
    100,000,000 costs what a shelf of capacity 30 costs."""

    def __init__(self, world: dict, robots: Iterable[str] | None = None):
        """``robots``: the robots that get a body (None: all). A robot the schedule never names
        stands still and carries nothing, so a run without pictures builds none for it: 5,000
        robots of which a dozen move cost a dozen bodies, not 5,000."""
        self.p, self.cid = connect_direct()
        self.world = world
        self.embodied = None if robots is None else set(robots)
        self.unit_product: dict[int, str] = {}
        self.slots: dict[str, SlotGrid] = {}
        self.occupant: dict[str, dict[int, int]] = {}  # shelf -> slot index -> body
        self.robot_body: dict[str, int] = {}
        self.carried: dict[str, list[int]] = {}
        self.unit_size = 0.3
        self._build()

    # building ------------------------------------------------------------------------------
    def _box(self, half: tuple[float, float, float], rgba, pos) -> int:
        p, c = self.p, self.cid
        vis = p.createVisualShape(p.GEOM_BOX, halfExtents=half, rgbaColor=rgba, physicsClientId=c)
        col = p.createCollisionShape(p.GEOM_BOX, halfExtents=half, physicsClientId=c)
        return p.createMultiBody(0, col, vis, basePosition=pos, physicsClientId=c)

    def _build(self) -> None:
        p, c, w = self.p, self.cid, self.world
        fw, fh = float(w["floor"]["width"]), float(w["floor"]["height"])
        self._box((fw / 2, fh / 2, 0.01), (0.85, 0.85, 0.82, 1), (fw / 2, fh / 2, -0.01))
        shelves = w.get("shelves", {})
        units = sum(int(n) for items in w.get("stock", {}).values() for n in items.values())
        for name, sh in shelves.items():
            x, y, sw, sd = (float(sh[k]) for k in ("x", "y", "width", "depth"))
            self._box((sw / 2, sd / 2, SHELF_HEIGHT / 2), (0.55, 0.42, 0.3, 1),
                      (x + sw / 2, y + sd / 2, SHELF_HEIGHT / 2))
            self.slots[name] = SlotGrid(sh, units)
            self.occupant[name] = {}
        sizes = [min(float(sh["width"]) / self.slots[name].cols, float(sh["depth"]) / self.slots[name].rows)
                 for name, sh in shelves.items()
                 if not sh.get("drop")]  # a stopped robot's cargo place (pipflow.execution): not a shelf to size units by
        self.unit_size = max(0.05, min([0.3] + [0.6 * s for s in sizes]))
        half = self.unit_size / 2
        col = p.createCollisionShape(p.GEOM_BOX, halfExtents=[half] * 3, physicsClientId=c)
        visuals = {prod: p.createVisualShape(p.GEOM_BOX, halfExtents=[half] * 3,
                                             rgbaColor=colour_rgba(info.get("color", "grey")),
                                             physicsClientId=c)
                   for prod, info in w.get("products", {}).items()}
        for shelf, items in w.get("stock", {}).items():
            for prod, n in items.items():
                if prod not in visuals:
                    visuals[prod] = p.createVisualShape(p.GEOM_BOX, halfExtents=[half] * 3,
                                                        rgbaColor=(0.5, 0.5, 0.5, 1), physicsClientId=c)
                for _ in range(int(n)):
                    body = p.createMultiBody(0, col, visuals[prod], basePosition=(0, 0, -5),
                                             physicsClientId=c)
                    self.unit_product[body] = prod
                    self.place_on_shelf(body, shelf)
        rcol = p.createCollisionShape(p.GEOM_CYLINDER, radius=ROBOT_RADIUS, height=ROBOT_HEIGHT,
                                      physicsClientId=c)
        robot_visuals: dict[int, int] = {}  # one visual shape per colour, not per robot
        for i, (name, info) in enumerate(w.get("robots", {}).items()):
            if self.embodied is not None and name not in self.embodied:
                continue
            k = i % len(ROBOT_COLOURS)
            if k not in robot_visuals:
                robot_visuals[k] = p.createVisualShape(p.GEOM_CYLINDER, radius=ROBOT_RADIUS, length=ROBOT_HEIGHT,
                                                       rgbaColor=ROBOT_COLOURS[k], physicsClientId=c)
            vis = robot_visuals[k]
            sx, sy = info["start"]
            self.robot_body[name] = p.createMultiBody(
                0, rcol, vis, basePosition=(float(sx), float(sy), ROBOT_HEIGHT / 2), physicsClientId=c)
            self.carried[name] = []

    # state ----------------------------------------------------------------------------------
    def place_on_shelf(self, body: int, shelf: str) -> None:
        """Put a unit on the first free slot; when none is free, stack it on the top layer so the
        overflow stays on the shelf (and is counted) instead of vanishing."""
        k = self.slots[shelf].take()
        self.occupant[shelf][k] = body
        sx, sy = self.slots[shelf].position(k)
        z = SHELF_HEIGHT + self.unit_size * (0.5 + self.slots[shelf].layer(k))
        self.p.resetBasePositionAndOrientation(body, (sx, sy, z), (0, 0, 0, 1), physicsClientId=self.cid)

    def take_from_shelf(self, shelf: str, product: str, n: int) -> list[int]:
        occ = self.occupant[shelf]
        picked = [i for i in sorted(occ, reverse=True) if self.unit_product[occ[i]] == product][:n]
        for i in picked:
            self.slots[shelf].free(i)
        return [occ.pop(i) for i in picked]

    def body_xyz(self, body: int) -> tuple[float, float, float]:
        pos, _ = self.p.getBasePositionAndOrientation(body, physicsClientId=self.cid)
        return pos

    def count_stock(self, only: str | None = None) -> tuple[dict[str, dict[str, int]], int]:
        """Units per shelf and product read from the bodies' positions (footprint, above the
        floor); second value: units lying on no shelf (carried or lost). ``only``: count that
        shelf alone (what an unload can change), without the stray count (returned as 0)."""
        import numpy as np

        shelves = self.world.get("shelves", {})
        names = [only] if only else list(shelves)
        stock: dict[str, dict[str, int]] = {s: {} for s in names}
        bodies = list(self.unit_product)
        if not bodies:
            return stock, 0
        xyz = np.asarray([self.body_xyz(b) for b in bodies], dtype=float)
        box = np.asarray([[float(shelves[n]["x"]), float(shelves[n]["y"]),
                           float(shelves[n]["x"]) + float(shelves[n]["width"]),
                           float(shelves[n]["y"]) + float(shelves[n]["depth"])] for n in names]).reshape(-1, 4)
        on = ((box[:, 0] - 1e-6 <= xyz[:, [0]]) & (xyz[:, [0]] <= box[:, 2] + 1e-6)
              & (box[:, 1] - 1e-6 <= xyz[:, [1]]) & (xyz[:, [1]] <= box[:, 3] + 1e-6)
              & (xyz[:, [2]] >= SHELF_HEIGHT))
        first = np.where(on.any(axis=1), on.argmax(axis=1), -1)  # the first shelf listed, as before
        for body, k in zip(bodies, first.tolist()):
            if k >= 0:
                prod = self.unit_product[body]
                stock[names[k]][prod] = stock[names[k]].get(prod, 0) + 1
        return stock, 0 if only else int((first < 0).sum())

    def move_robot(self, robot: str, xy: Point) -> None:
        p, c = self.p, self.cid
        p.resetBasePositionAndOrientation(self.robot_body[robot], (xy[0], xy[1], ROBOT_HEIGHT / 2),
                                          (0, 0, 0, 1), physicsClientId=c)
        for k, body in enumerate(self.carried[robot]):
            p.resetBasePositionAndOrientation(
                body, (xy[0], xy[1], ROBOT_HEIGHT + self.unit_size * (0.5 + k)), (0, 0, 0, 1),
                physicsClientId=c)

    def robot_xy(self, robot: str) -> Point:
        x, y, _ = self.body_xyz(self.robot_body[robot])
        return (x, y)

    def snapshot(self, path: Path, width: int = 800, height: int = 500, caption: str = "") -> Path:
        """An oblique view of the whole floor with the tiny renderer (no display needed), each
        shelf and robot labelled with its name and ``caption`` (the time) in a corner."""
        labels = [(name, (float(sh["x"]) + float(sh["width"]) / 2, float(sh["y"]), SHELF_HEIGHT + 0.2), "place")
                  for name, sh in self.world.get("shelves", {}).items()]
        names = list(self.world.get("robots", {}))
        labels += [(r, (*self.robot_xy(r), ROBOT_HEIGHT + 0.35), "robot", ROBOT_COLOURS[names.index(r) % len(ROBOT_COLOURS)])
                   for r in names]
        return render_floor(self.p, self.cid, self.world["floor"], path, width, height, labels, caption)

    def close(self) -> None:
        try:
            self.p.disconnect(physicsClientId=self.cid)
        except Exception:
            pass


# --------------------------------------------------------------------------------------------
# Running a schedule
# --------------------------------------------------------------------------------------------


def _access(world: dict, place: str | None) -> Point | None:
    sh = world.get("shelves", {}).get(place or "")
    return (float(sh["access"][0]), float(sh["access"][1])) if sh else None


def simulate(world: dict, schedule: dict, graph: dict | None = None, goal: dict | None = None, *,
             snapshots: bool = False, animation: bool = False, out_dir: str | Path | None = None,
             step: float = 0.25, log=None, trace: bool = False) -> dict:
    """Run ``schedule`` in pybullet and return what the world looks like afterwards.

    Returns ``{final_stock, executed, failed, failures, exe, travel, tc_max, tc_avg, tc_avg_team, goal_met,
    gcr, peak_load, stray_units, jumps, makespan, trajectories, events, pictures}``; ``jumps``
    lists legs that start away from where the robot stood (a broken schedule: the body jumps); pictures (file
    names in ``out_dir``) only when ``out_dir`` is given. ``trace``: also ``interrupted`` (subtasks
    whose coalition lost a member between load and unload, with when), for the executor.

    A robot with ``stopped: {time, drop}`` in the world (:mod:`pipflow.execution`) is out of
    service from ``time``: a load that needs it is refused, it unloads nothing, and what it carries
    is put on the ``drop`` place at ``time`` (or stays on it, when there is none).

    Three phases: set up (the moves, each robot's trajectory, the load/unload instants and the
    sample times), run the schedule in a scene (:class:`Playback`), measure (the result) and,
    with ``out_dir``, draw."""
    log = log or (lambda m: None)
    moves = moves_from(schedule, graph)
    traj = _trajectories(world, schedule)
    events = _event_times(world, moves, traj)
    makespan, sample_times = _sample_times(schedule, traj, events, step)
    stops = _stops(world)
    if stops:
        sample_times = sorted(set(sample_times) | {t for t, _ in stops.values() if 0 <= t <= makespan})
    out = Path(out_dir) if out_dir else None
    snap_plan = _snapshot_times(events, makespan) if (snapshots and out) else {}
    # pictures show every robot; without them only the robots the schedule names need a body
    scene = Scene(world, None if (snapshots and out) else _named_robots(schedule, moves))
    try:
        run = Playback(scene, world, moves, traj, events, log)
        run.play(sample_times, snap_plan, out)
        final_stock, stray = scene.count_stock()
    finally:
        scene.close()
    result = _measure(run, traj, final_stock, stray, goal, makespan, planned=len(moves))
    if trace:
        result["interrupted"] = dict(run.interrupted)
    if out is not None:
        _draw(world, result, run.travel, out, makespan, animation, log)
    return result


# ---------------------------------------------------------------------------- set up
def _stops(world: dict) -> dict[str, tuple[float, str | None]]:
    """Robots out of service: ``{robot: (from when, drop place or None)}``."""
    out = {}
    for r, info in (world.get("robots") or {}).items():
        stop = info.get("stopped")
        if stop:
            out[r] = (float(stop["time"]), stop.get("drop"))
    return out


def _named_robots(schedule: dict, moves: list[Move]) -> set[str]:
    """The robots that drive a leg or belong to a move's coalition: the only ones that can
    move, carry or be checked at a place."""
    named = {r for r, info in (schedule.get("robots") or {}).items() if info.get("legs")}
    return named | {r for m in moves for r in m.robots}


def _trajectories(world: dict, schedule: dict) -> dict[str, Trajectory]:
    """Each robot's motion as the schedule's legs fix it (a robot without legs stands still)."""
    robots = world.get("robots", {})
    legs_by_robot: dict[str, list[dict]] = {r: [] for r in robots}
    for r, info in (schedule.get("robots") or {}).items():
        legs_by_robot.setdefault(r, []).extend(info.get("legs", []))
    return {r: Trajectory(robots.get(r, {}).get("start", (0, 0)), legs) for r, legs in legs_by_robot.items()}


def _event_times(world: dict, moves: list[Move], traj: dict[str, Trajectory]) -> list[tuple[float, int, int, str]]:
    """``(time, 0=unload/1=load, order, move id)`` for every move, sorted: a load when the
    coalition is at the source (not before the subtask's start), an unload at the last arrival at
    the target (else the subtask's end). Unloads sort before loads at the same instant."""
    events: list[tuple[float, int, int, str]] = []
    for order, m in enumerate(moves):
        src, tgt = _access(world, m.route[0] if m.route else m.source), _access(world, m.route[-1] if m.route else m.target)
        arr_src = [traj[r].arrival(m.id, src) for r in m.robots if r in traj and src] if src else []
        t_load = max([m.start] + [a for a in arr_src if a is not None])
        arr_tgt = [traj[r].arrival(m.id, tgt, last=True) for r in m.robots if r in traj] if tgt else []
        arr_tgt = [a for a in arr_tgt if a is not None]
        t_unload = max([t_load] + (arr_tgt if arr_tgt else [m.end]))
        events.append((t_load, 1, order, m.id))
        events.append((t_unload, 0, order, m.id))
    events.sort()
    return events


def _sample_times(schedule: dict, traj: dict[str, Trajectory], events: list, step: float) -> tuple[float, list[float]]:
    """The makespan, and the instants at which the scene is updated: every ``step`` metres of
    the fastest robot (at most 20 000 of them), every event and every path vertex (so corners
    are not cut and travel is measured exactly)."""
    makespan = max([float(schedule.get("makespan", 0.0))] + [e[0] for e in events]
                   + [s[1] for t in traj.values() for s in t.segments])
    vmax = max([t.max_speed() for t in traj.values()] + [1e-9])
    dt = step / vmax if vmax > 1e-6 else max(makespan, 1.0)
    n_grid = int(makespan / dt) + 1 if makespan > 0 else 1
    if n_grid > 20000:  # guard against absurd schedules: never more than 20k grid samples
        n_grid, dt = 20000, makespan / 20000
    sample_times = {i * dt for i in range(n_grid + 1)} | {e[0] for e in events} | {makespan}
    for t in traj.values():
        sample_times |= set(t.vertex_times())
    return makespan, sorted(x for x in sample_times if 0 <= x <= makespan + 1e-9)


# ---------------------------------------------------------------------------- run the schedule
class Playback:
    """The schedule being played in a scene: where each robot is and how far it has driven (from
    the bodies, not the plan), which loads happened, what failed, the peak load of each shelf,
    the snapshots taken. One object so that the phases of a sample (move the robots, apply the
    events that are due, take the snapshots that are due) share this state openly."""

    def __init__(self, scene: Scene, world: dict, moves: list[Move], traj: dict[str, Trajectory],
                 events: list[tuple[float, int, int, str]], log) -> None:
        self.scene, self.world, self.traj, self.events, self.log = scene, world, traj, events, log
        self.by_id = {m.id: m for m in moves}
        self.travel = {r: 0.0 for r in traj}
        # a robot without a body stands where it started (the start as the body would report it)
        starts = world.get("robots", {})
        self.last_xy = {r: scene.robot_xy(r) if r in scene.robot_body else
                        (float(starts[r]["start"][0]), float(starts[r]["start"][1]))
                        for r in traj if r in scene.robot_body or r in starts}
        self.paths = {r: [[0.0, *self.last_xy[r]]] for r in self.last_xy}
        stock0, _ = scene.count_stock()
        self.peak: dict[str, int] = {shelf: sum(items.values()) for shelf, items in stock0.items()}
        self.executed = 0
        self.failures: list[dict] = []
        self.log_events: list[dict] = []
        self.pictures: list[str] = []
        self._loaded: dict[str, bool] = {}
        self._unloaded: set[str] = set()
        self._next_event = 0
        # only robots with legs move, and each only from its first leg's start to its last leg's
        # end: pybullet work follows the robots a run uses, not the size of the fleet
        self._window = {r: (tr.segments[0][0], tr.segments[-1][1]) for r, tr in traj.items()
                        if tr.segments and r in scene.robot_body}
        self._movers = sorted(self._window, key=lambda r: self._window[r][0])
        self._settled: set[str] = set()
        self.stops = _stops(world)
        self.out: set[str] = set()  # robots out of service by now
        self.interrupted: dict[str, float] = {}

    def play(self, sample_times: list[float], snap_plan: dict[str, float], out: Path | None) -> None:
        for t in sample_times:
            self.move_robots(t)
            self.apply_stops(t)
            self.apply_events(t)
            self.take_snapshots(t, snap_plan, out)

    def apply_stops(self, t: float) -> None:
        """Robots whose stop is due: out of service from now; what they carry goes on their drop
        place (if they have one); a loaded move they belong to is interrupted."""
        for r, (when, drop) in self.stops.items():
            if r in self.out or when > t + 1e-9:
                continue
            self.out.add(r)
            for mid, loaded in self._loaded.items():
                m = self.by_id[mid]
                if loaded and r in m.robots and mid not in self._unloaded:
                    self.interrupted.setdefault(mid, round(when, 3))
            held = self.scene.carried.get(r) or []
            if held and drop in self.scene.occupant:
                for body in held:
                    self.scene.place_on_shelf(body, drop)
                self.scene.carried[r] = []
            self.log(f"{r} is out of service from t={when:.1f}"
                     + (f"; {len(held)} unit(s) it carried are on {drop}" if held and drop in self.scene.occupant else ""))

    def move_robots(self, t: float) -> None:
        """Put every moving robot where its trajectory says at ``t``; add the metres its body went."""
        for r in self._movers:
            first, last = self._window[r]
            if t < first - 1e-9:
                break  # sorted by start: nobody further on has started either
            if r in self._settled:
                continue
            if t >= last:
                self._settled.add(r)  # this sample puts it at its final place
            self.scene.move_robot(r, self.traj[r].position(t))
            now = self.scene.robot_xy(r)  # measured from the body, not from the plan
            d = _dist(now, self.last_xy[r])
            if d > 1e-9:
                self.travel[r] += d
                self.paths[r].append([t, now[0], now[1]])
                self.last_xy[r] = now

    def apply_events(self, t: float) -> None:
        """Every load and unload due by ``t``: a load's preconditions are checked in the scene
        (a failed one is recorded with its reasons); an unload follows only a load that happened."""
        scene, events = self.scene, self.events
        while self._next_event < len(events) and events[self._next_event][0] <= t + 1e-9:
            et, kind, _, mid = events[self._next_event]
            self._next_event += 1
            m = self.by_id[mid]
            if kind == 1:
                reasons = _check(scene, self.world, m)
                reasons += [f"{r} is out of service (stopped at t={self.stops[r][0]:.1f})" for r in m.robots if r in self.out]
                if reasons:
                    self.failures.append({"subtask": m.id, "action": m.action, "args": m.args,
                                          "time": round(et, 3), "reasons": reasons})
                    self.log(f"{m.id} not executed at t={et:.1f}: {'; '.join(reasons)}")
                    self._loaded[m.id] = False
                else:
                    _load(scene, self.world, m)
                    self._loaded[m.id] = True
                    self.log_events.append({"time": round(et, 3), "subtask": m.id, "event": "load"})
            elif self._loaded.get(m.id):
                # a robot that is not at the target (held up on the way) delivers nothing
                tgt = _access(self.world, m.target)
                away = [r for r in m.robots if r not in self.out and r in scene.robot_body and tgt is not None
                        and _dist(scene.robot_xy(r), tgt) > ARRIVAL_TOLERANCE]
                if away:
                    self.failures.append({"subtask": m.id, "action": m.action, "args": m.args, "time": round(et, 3),
                                          "reasons": [f"{', '.join(away)} not at {m.target}: what they carry was not "
                                                      "delivered"]})
                    self.log(f"{m.id} not delivered at t={et:.1f}: {', '.join(away)} not at {m.target}")
                _unload(scene, m, self.out | set(away))
                self._unloaded.add(m.id)
                if m.id not in self.interrupted and not away:  # else not all it carried arrived
                    self.executed += 1
                self.log_events.append({"time": round(et, 3), "subtask": m.id, "event": "unload"})
                if m.target in scene.occupant:  # an unload changes its target's load only
                    stock, _ = scene.count_stock(only=m.target)
                    self.peak[m.target] = max(self.peak.get(m.target, 0), sum(stock[m.target].values()))

    def take_snapshots(self, t: float, snap_plan: dict[str, float], out: Path | None) -> None:
        """The snapshots due by ``t`` (each taken once; ``snap_plan`` loses it)."""
        for name, ts in list(snap_plan.items()):
            if t + 1e-9 >= ts:
                fname = f"snapshot_{len(self.pictures) + 1}_{name}.png"
                self.scene.snapshot(out / fname, caption=f"t = {t:.1f} s: {name.replace('-', ' ')}")
                self.pictures.append(fname)
                del snap_plan[name]


# ---------------------------------------------------------------------------- measure
def _measure(run: Playback, traj: dict[str, Trajectory], final_stock: dict, stray: int, goal: dict | None,
             makespan: float, planned: int) -> dict:
    """The simulation's outputs from what the playback saw and the final count of the shelves."""
    final_stock = {s: {p: n for p, n in items.items() if n} for s, items in final_stock.items()}
    gm, gcr = goal_check(final_stock, goal or {}, run.world.get("stock") or {})
    travel = {r: round(v, 4) for r, v in run.travel.items()}
    return {
        "final_stock": final_stock, "executed": run.executed, "failed": len(run.failures),
        "failures": run.failures, "exe": run.executed / planned if planned else 1.0,
        "travel": travel,
        **travel_costs(travel),  # tc_max, tc_avg (robots that moved), tc_avg_team
        "goal_met": gm, "gcr": gcr, "peak_load": run.peak, "stray_units": stray,
        "jumps": {r: t.jumps for r, t in traj.items() if t.jumps},
        "makespan": round(makespan, 4), "events": run.log_events,
        "trajectories": {r: [[round(v, 4) for v in row] for row in pts] for r, pts in run.paths.items()},
        "pictures": run.pictures,
    }


def _draw(world: dict, result: dict, travel: dict[str, float], out: Path, makespan: float, animation: bool,
          log) -> None:
    """The path map and, if asked, the animation; their names join ``result["pictures"]``."""
    pictures = result["pictures"]
    pictures.append(pics.path_map(world, result["trajectories"], out / "paths.png", travel=travel).name)
    if animation:
        gif = pics.animation_gif(world, result["trajectories"], out / "animation.gif", makespan)
        if gif is None:
            log("animation skipped: Pillow is not installed (pip install pillow)")
            result["animation_skipped"] = "Pillow is not installed"
        else:
            pictures.append(gif.name)


def _snapshot_times(events: list, makespan: float) -> dict[str, float]:
    """Key moments like the paper's Fig. 4 a-d: the start, the first pick-up, halfway, the end."""
    first_load = next((e[0] for e in events if e[1] == 1), makespan / 3)
    return {"start": 0.0, "first-load": first_load, "halfway": max(first_load, makespan / 2),
            "end": makespan}


def _check(scene: Scene, world: dict, m: Move) -> list[str]:
    """Preconditions of a move in the simulated state at its start; every failed one is named."""
    reasons = []
    robots = world.get("robots", {})
    unknown = [r for r in m.robots if r not in robots]
    if unknown:
        reasons.append(f"unknown robots {unknown}")
    if not m.robots:
        reasons.append("no robot assigned")
    for skill, need in m.skills.items():
        have = sum(float(robots.get(r, {}).get("skills", {}).get(skill, 0)) for r in m.robots)
        if have + 1e-9 < need:
            reasons.append(f"coalition {skill} {have:g} < {need:g} needed")
    src = _access(world, m.route[0] if m.route else m.source)
    if src:
        away = [r for r in m.robots if r in scene.robot_body and _dist(scene.robot_xy(r), src) > ARRIVAL_TOLERANCE]
        if away:
            reasons.append(f"{', '.join(away)} not at {m.route[0] if m.route else m.source}")
    if m.product and m.source:
        if m.source not in scene.occupant:
            reasons.append(f"unknown shelf {m.source}")
        else:
            have = sum(1 for b in scene.occupant[m.source].values() if scene.unit_product[b] == m.product)
            if have < m.units:
                reasons.append(f"{m.source} has {have} {m.product}, {m.units} needed")
    if m.product and m.target:
        if m.target not in scene.occupant:
            reasons.append(f"unknown shelf {m.target}")
        else:
            cap = int(world["shelves"][m.target].get("capacity", 10 ** 9))
            load = len(scene.occupant[m.target])
            if load + m.units > cap:
                reasons.append(f"{m.target} holds {load}/{cap}, no room for {m.units}")
    return reasons


def _load(scene: Scene, world: dict, m: Move) -> None:
    """Lift the units onto the coalition, each robot up to its carry level, the strongest first."""
    if not (m.product and m.source and m.units):
        return
    bodies = scene.take_from_shelf(m.source, m.product, m.units)
    robots = world.get("robots", {})
    order = sorted(m.robots, key=lambda r: -float(robots.get(r, {}).get("skills", {}).get("carry", 0)))
    for r in order:
        cap = int(math.floor(float(robots.get(r, {}).get("skills", {}).get("carry", 0))))
        take, bodies = bodies[:cap], bodies[cap:]
        scene.carried[r].extend(take)
        scene.move_robot(r, scene.robot_xy(r))
    if bodies:  # fractional skills: whoever is first carries the rest
        scene.carried[order[0]].extend(bodies)
        scene.move_robot(order[0], scene.robot_xy(order[0]))


def _unload(scene: Scene, m: Move, out: set[str] = frozenset()) -> None:
    """The coalition puts what it carries on the target (a robot out of service puts nothing)."""
    for r in m.robots:
        if r in out:
            continue
        for body in scene.carried.get(r, []):
            scene.place_on_shelf(body, m.target)
        if r in scene.carried:
            scene.carried[r] = []


def goal_check(stock: dict, goal: dict, initial_stock: dict) -> tuple[bool, float]:
    """(goal met, GCR) of the final ``stock``: every listed goal value must hold, an exact count
    exactly, a bound ``{at_least, at_most}`` when the final count lies within it
    (:func:`pipflow.goalcounts.holds`). GCR is :func:`pipflow.metrics.goal_condition_recall`:
    the share that holds, where counts that already held in ``initial_stock`` count only once
    the run achieved a count it had to change (1.0 for no goal)."""
    end = values_met(stock, goal)
    return all(end), goal_condition_recall(values_met(initial_stock, goal), end)

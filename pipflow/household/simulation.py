"""Execute a household schedule and read back what the home looks like afterwards.

Why a simulation of its own, when the plan was validated? Because the benchmark judges the
*world*, not the plan's claims, and the robot level can break what the team level got right: a
coalition without the skill (no pickup for a 2-unit melon, nobody able to open the fridge), a
robot that is not at the place when the subtask starts, or a schedule that starts a subtask
before the one it depends on ends. Each subtask is checked when it starts, against the state at
that moment:

* the coalition's summed skills cover the subtask's requirement vector Y;
* every robot of the coalition stands at the route's first place (its legs end there);
* the action's preconditions hold (the same as domains/household.pddl, written out in Python).

Effects land when the subtask ends (a carried object is in nobody's place in between), ends
before starts at equal times. A refused subtask changes nothing and counts against Exe. Travel
is measured along the robots' legs (:class:`pipflow.team.trajectory.Trajectory`, which also reports
legs that do not connect). Pictures of the scene at the start and the end come from a headless
pybullet client (furniture boxes, objects on their places, robots), only when asked.
"""
from __future__ import annotations

import math
from pathlib import Path
from typing import Any, Callable

from pipflow.bullet import colour_rgba, connect_direct, render_floor
from pipflow.household.scoring import check_conditions, recall
from pipflow.metrics import travel_costs
from pipflow.household.world import initial_state
from pipflow.team.trajectory import ROBOT_COLOURS, Trajectory

TOLERANCE = 0.75  # metres: a robot this close to an access point is "there"
STATE_KEYS = ("open", "on", "dirty", "sliced", "hot")


class Home:
    """The mutable household state: where each object is and which flags hold."""

    def __init__(self, world: dict):
        self.world = world
        s = initial_state(world)
        self.at: dict[str, str | None] = dict(s["at"])
        self.flags: dict[str, set[str]] = {k: set(s[k]) for k in STATE_KEYS}

    def props(self, name: str) -> list[str]:
        e = self.world["places"].get(name) or self.world["objects"].get(name)
        return e["properties"] if e else []

    def where(self, name: str) -> str | None:
        return name if name in self.world["places"] else self.at.get(name)

    def accessible(self, place: str) -> bool:
        return "openable" not in self.props(place) or place in self.flags["open"]

    def problems(self, action: str, args: list[str]) -> list[str]:
        """Unmet preconditions of ``action(args)`` now (domains/household.pddl, in words)."""
        f, p = self.flags, self.props
        out: list[str] = []

        def need(cond: bool, text: str) -> None:
            if not cond:
                out.append(text)

        if action in ("store", "trash") and len(args) == 3:
            i, src, dst = args
            need(src != dst, f"{i}: source and target are the same place")
            need(self.at.get(i) == src, f"{i} is not in {src} (it is in {self.at.get(i)})")
            need("pickupable" in p(i), f"{i} cannot be picked up")
            need(self.accessible(src), f"{src} is closed")
            if action == "store":
                need("receptacle" in p(dst), f"{dst} is not a receptacle")
                need(self.accessible(dst), f"{dst} is closed")
            else:
                need("garbage" in p(dst), f"{dst} is not a garbage place")
        elif action in ("open", "close") and len(args) == 1:
            need("openable" in p(args[0]), f"{args[0]} cannot be opened or closed")
            need((args[0] in f["open"]) == (action == "close"), f"{args[0]} is already {'closed' if action == 'close' else 'open'}")
        elif action in ("switch-on", "switch-off") and len(args) == 2:
            e, place = args
            need("toggleable" in p(e), f"{e} has no switch")
            need((e in f["on"]) == (action == "switch-off"), f"{e} is already {'off' if action == 'switch-off' else 'on'}")
            need(self.where(e) == place, f"{e} is not at {place}")
        elif action in ("slice", "wash", "heat") and len(args) == 2:
            i, place = args
            need(self.at.get(i) == place, f"{i} is not in {place}")
            if action == "slice":
                need("sliceable" in p(i), f"{i} cannot be sliced")
                need(i not in f["sliced"], f"{i} is already sliced")
                need(self.accessible(place), f"{place} is closed")
            elif action == "wash":
                need("washable" in p(i), f"{i} cannot be washed")
                need(i in f["dirty"], f"{i} is not dirty")
                need("sink" in p(place), f"{place} is not a sink")
            else:
                need("heatable" in p(i), f"{i} cannot be heated")
                need(i not in f["hot"], f"{i} is already hot")
                need("heater" in p(place), f"{place} does not heat")
                need(place not in f["open"], f"{place} must be closed to heat")
        else:
            out.append(f"unknown action {action}({', '.join(args)})")
        return out

    def begin(self, action: str, args: list[str]) -> None:
        if action in ("store", "trash"):
            self.at[args[0]] = None  # carried by the coalition

    def finish(self, action: str, args: list[str]) -> None:
        f = self.flags
        if action in ("store", "trash"):
            self.at[args[0]] = args[2]
        elif action == "open":
            f["open"].add(args[0])
        elif action == "close":
            f["open"].discard(args[0])
        elif action == "switch-on":
            f["on"].add(args[0])
        elif action == "switch-off":
            f["on"].discard(args[0])
        elif action == "slice":
            f["sliced"].add(args[0])
        elif action == "wash":
            f["dirty"].discard(args[0])
        elif action == "heat":
            f["hot"].add(args[0])

    def data(self) -> dict:
        """The final state as JSON data: ``{"at": {obj: place}, "open": [...], "on": [...], ...}``."""
        return {"at": dict(self.at), **{k: sorted(v) for k, v in self.flags.items()}}


def _coalition_short(world: dict, robots: list[str], need: dict[str, float]) -> list[str]:
    have = {s: sum(float(world["robots"].get(r, {}).get("skills", {}).get(s, 0.0)) for r in robots) for s in need}
    return [f"{s}: needs {v:g}, the coalition has {have[s]:g}" for s, v in need.items() if have[s] < v - 1e-9]


def simulate(world: dict, schedule: dict, graph: dict | None, goal: dict | None = None, *,
             snapshots: bool = False, out_dir: str | Path | None = None,
             log: Callable[[str], None] | None = None, trace: bool = False) -> dict:
    """Run ``schedule`` on the household ``world``; see the module docstring.

    Returns ``{final_state, executed, failed, failures, exe, travel, tc_max, tc_avg, tc_avg_team, goal_met,
    gcr, conditions, jumps, makespan, pictures}``; ``trace``: also ``began``, ``ended`` (when each
    subtask began and ended) and ``interrupted`` (when a member of a running subtask stopped), for
    the executor.

    A robot with ``stopped: {time, drop}`` in the world (:mod:`pipflow.execution`) is out of
    service from ``time``: a subtask that needs it is refused; one it works on when it stops is
    interrupted (its effects do not land) and an object it carries is put in the ``drop`` place
    (or stays with it, when there is none)."""
    log = log or (lambda m: None)
    nodes = {n["id"]: n for n in (graph or {}).get("nodes", [])}
    places = {n: tuple(p["access"]) for n, p in world["places"].items()}
    traj = _trajectories(world, schedule)

    home = Home(world)
    scene = _Scene(world) if snapshots and out_dir else None
    pictures: list[str] = []
    if scene:  # named as every domain's snapshots are (snapshot_<n>_<moment>.png), labelled
        pictures.append(scene.snapshot(Path(out_dir) / "snapshot_1_start.png", home,
                                       {r: tuple(tr.position(0.0)) for r, tr in traj.items()}, "t = 0.0 s: start").name)

    stops = {r: info["stopped"] for r, info in world["robots"].items() if info.get("stopped")}
    events = _events(schedule, stops)
    executed, failures, running = 0, [], set()
    began: dict[str, float] = {}
    ended: dict[str, float] = {}
    interrupted: dict[str, float] = {}
    out: set[str] = set()
    by_id = {s["id"]: s for s in schedule.get("subtasks", [])}
    for t, kind, _, s in events:
        if kind == -1:
            _stop(home, s, t, running, by_id, interrupted, out, log)
            continue
        action, args, robots = s["action"], list(s.get("args") or []), list(s.get("robots") or [])
        if kind == 0:
            if s["id"] in running and s["id"] not in interrupted:
                home.finish(action, args)
                executed += 1
                ended[s["id"]] = t
            continue
        node = nodes.get(s["id"], {})
        why = home.problems(action, args)
        why += _coalition_short(world, robots, dict(node.get("skills") or {}))
        why += [f"{r} is out of service (stopped at t={float(stops[r]['time']):.1f})" for r in robots if r in out]
        why += _not_there(robots, list(node.get("route") or []), places, traj, t)
        if why:
            failures.append({"subtask": s["id"], "action": action, "args": args, "time": round(t, 3), "reasons": why})
            log(f"execute: {s['id']} {action} {' '.join(args)} refused: {'; '.join(why)}")
            continue
        home.begin(action, args)
        running.add(s["id"])
        began[s["id"]] = t

    final = home.data()
    if scene:
        end = float(schedule.get("makespan", 0.0))
        pictures.append(scene.snapshot(Path(out_dir) / "snapshot_2_end.png", home,
                                       {r: tuple(tr.position(end)) for r, tr in traj.items()},
                                       f"t = {end:.1f} s: end").name)
        scene.close()
    planned = len(schedule.get("subtasks", []))
    travel = {r: _metres(tr) for r, tr in traj.items() if r in world["robots"]}
    met, total, unmet = check_conditions(world, final, goal or {})
    traced = {"began": began, "ended": ended, "interrupted": interrupted} if trace else {}
    return {**traced,
        "final_state": final, "executed": executed, "failed": len(failures), "failures": failures,
        "exe": executed / planned if planned else 1.0, "travel": travel,
        **travel_costs(travel),  # tc_max, tc_avg (robots that moved), tc_avg_team
        "goal_met": met == total, "gcr": recall(world, final, goal or {}),
        "conditions": {"met": met, "total": total, "unmet": unmet},
        "jumps": {r: tr.jumps for r, tr in traj.items() if tr.jumps},
        "makespan": float(schedule.get("makespan", 0.0)), "pictures": pictures,
    }


def _trajectories(world: dict, schedule: dict) -> dict[str, Trajectory]:
    """Each robot's motion: its start and the legs the schedule gives it (none: it stays)."""
    legs: dict[str, list[dict]] = {r: [] for r in world["robots"]}
    for r, info in (schedule.get("robots") or {}).items():
        legs.setdefault(r, []).extend(info.get("legs", []))
    return {r: Trajectory(world["robots"].get(r, {}).get("start", (0, 0)), ls) for r, ls in legs.items()}


def _events(schedule: dict, stops: dict[str, dict]) -> list[tuple[float, int, int, dict]]:
    """The run's events in time order: at one instant subtasks end (0) before others start (1),
    and a robot's stop (-1) comes first."""
    events: list[tuple[float, int, int, dict]] = []
    for k, s in enumerate(schedule.get("subtasks", [])):
        events.append((float(s["start"]), 1, k, s))
        events.append((float(s["end"]), 0, k, s))
    for k, (r, stop) in enumerate(sorted(stops.items())):
        events.append((float(stop["time"]), -1, k, {"robot": r, **stop}))
    return sorted(events, key=lambda e: (e[0], e[1], e[2]))


def _not_there(robots: list[str], route: list[str], places: dict[str, tuple], traj: dict[str, Trajectory],
               t: float) -> list[str]:
    """Why a subtask cannot start at ``t``: members not standing at its route's first place."""
    if not route or route[0] not in places:
        return []
    return [f"{r} is not at {route[0]} at t={t:.1f}" for r in robots
            if r not in traj or math.dist(traj[r].position(t), places[route[0]]) > TOLERANCE]


def _metres(tr: Trajectory) -> float:
    """What a robot drove: its legs and its jumps (moves the plan did not route)."""
    return round(sum(seg[3][-1] for seg in tr.segments) + sum(j["metres"] for j in tr.jumps), 6)


def _stop(home: Home, stop: dict, t: float, running: set[str], by_id: dict[str, dict],
          interrupted: dict[str, float], out: set[str], log: Callable[[str], None]) -> None:
    """Robot ``stop["robot"]`` goes out of service at ``t``: the subtasks it works on are
    interrupted, and an object its coalition carries lands in its drop place, if it has one."""
    robot, drop = stop["robot"], stop.get("drop")
    out.add(robot)
    for sid in sorted(running):
        s = by_id[sid]
        if robot not in (s.get("robots") or []) or sid in interrupted or float(s["end"]) <= t:
            continue
        interrupted[sid] = t
        args = list(s.get("args") or [])
        if s["action"] in ("store", "trash") and args and home.at.get(args[0]) is None:
            home.at[args[0]] = drop if drop in home.world["places"] else None
            log(f"{robot} stopped at t={t:.1f} during {sid}: {args[0]} is "
                + (f"in {drop}" if drop in home.world["places"] else "stuck with it"))


class _Scene:
    """Headless pybullet pictures: furniture boxes, objects on their places, robots at their starts."""

    def __init__(self, world: dict):
        self.p, self.cid = connect_direct()
        p, self.world = self.p, world
        self.bodies: dict[str, int] = {}
        self.robots: dict[str, int] = {}
        fw, fh = float(world["floor"]["width"]), float(world["floor"]["height"])
        self._box((fw / 2, fh / 2, 0.01), "beige", (fw / 2, fh / 2, -0.01))
        for name, pl in world["places"].items():
            h = 0.45 if "receptacle" in pl["properties"] else 1.0
            self._box((pl["width"] / 2, pl["depth"] / 2, h / 2), pl.get("color", "grey"),
                      (pl["x"] + pl["width"] / 2, pl["y"] + pl["depth"] / 2, h / 2))
        for name in world["objects"]:
            self.bodies[name] = self._sphere(0.09, world["objects"][name].get("color", "grey"))
        for i, (name, r) in enumerate(world["robots"].items()):
            vis = p.createVisualShape(p.GEOM_CYLINDER, radius=0.25, length=0.5,
                                      rgbaColor=ROBOT_COLOURS[i % len(ROBOT_COLOURS)], physicsClientId=self.cid)
            self.robots[name] = p.createMultiBody(0, -1, vis, basePosition=(r["start"][0], r["start"][1], 0.25),
                                                  physicsClientId=self.cid)

    def _box(self, half, colour: str, pos) -> int:
        vis = self.p.createVisualShape(self.p.GEOM_BOX, halfExtents=half, rgbaColor=colour_rgba(colour), physicsClientId=self.cid)
        return self.p.createMultiBody(0, -1, vis, basePosition=pos, physicsClientId=self.cid)

    def _sphere(self, radius: float, colour: str) -> int:
        vis = self.p.createVisualShape(self.p.GEOM_SPHERE, radius=radius, rgbaColor=colour_rgba(colour), physicsClientId=self.cid)
        return self.p.createMultiBody(0, -1, vis, basePosition=(0, 0, -5), physicsClientId=self.cid)

    def snapshot(self, path: Path, home: Home, robots_at: dict | None = None, caption: str = "",
                 width: int = 800, height: int = 560) -> Path:
        """The home with each object where ``home`` has it and each robot at ``robots_at``; every
        place and robot labelled with its name, ``caption`` (the time) in a corner."""
        p, c = self.p, self.cid
        names = list(self.world["robots"])
        for r, xy in (robots_at or {}).items():
            if r in self.robots:
                p.resetBasePositionAndOrientation(self.robots[r], (float(xy[0]), float(xy[1]), 0.25), (0, 0, 0, 1),
                                                  physicsClientId=c)
        labels = [(name, (pl["x"] + pl["width"] / 2, pl["y"], (0.45 if "receptacle" in pl["properties"] else 1.0) + 0.15),
                   "place") for name, pl in self.world["places"].items()]
        for r, body in self.robots.items():
            (x, y, _), _ = p.getBasePositionAndOrientation(body, physicsClientId=c)
            labels.append((r, (x, y, 0.8), "robot", ROBOT_COLOURS[names.index(r) % len(ROBOT_COLOURS)]))
        slots: dict[str, int] = {}
        for name, body in self.bodies.items():
            place = home.at.get(name)
            if place is None:
                continue
            pl = self.world["places"][place]
            k = slots[place] = slots.get(place, -1) + 1
            cols = max(1, int(pl["width"] / 0.22))
            x = pl["x"] + 0.12 + 0.22 * (k % cols)
            y = pl["y"] + 0.12 + 0.22 * (k // cols) % max(pl["depth"], 0.22)
            h = 0.45 if "receptacle" in pl["properties"] else 1.0
            p.resetBasePositionAndOrientation(body, (x, y, h + 0.1), (0, 0, 0, 1), physicsClientId=c)
        return render_floor(p, c, self.world["floor"], path, width, height, labels, caption)

    def close(self) -> None:
        try:
            self.p.disconnect(physicsClientId=self.cid)
        except Exception:
            pass


__all__: list[Any] = ["simulate", "Home"]

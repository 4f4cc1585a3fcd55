"""The executor: a schedule played in the task domain's simulation under faults, watched by the
monitor, and recovered until it ends or the goal is out of reach.

Why it plays the whole run again after each recovery rather than resuming it: the simulation is
deterministic, and the new schedule keeps everything driven before the recovery as it was (the
legs are marked ``done``), so a replay reaches the same moment in the same state; a simulation
needs no way to be paused and resumed, and what happened before and after a recovery is measured
by the same code. Each pass:

1. the schedule's legs become the legs robots really drive (:func:`pipflow.execution.motion.actual_schedule`);
2. the domain plays them in the world as it really is (:meth:`~pipflow.execution.capability.ExecutionCapability.play`:
   every surprise in it, stopped robots out of service);
3. the monitor finds the first difference not handled yet (:func:`pipflow.execution.monitor.first_anomaly`);
4. the executor learns what it reveals (a robot lost, slow, a passage closed, a place's real
   contents), cuts the run there (:func:`pipflow.execution.standing.cut`) and recovers, cheapest first:

   * **continue**: nothing the run still has to do is affected (a robot lost after its last
     subtask; a surprise the remaining plan still reaches the goal through, checked by UP's plan
     validator on the observed state);
   * **re-allocate**: the plan still fits the observed state; only who does what, from where, changes;
   * **re-plan**: the plan no longer fits (a subtask broke off midway, the state differs, no
     coalition can be formed): a new team plan from the observed state to the same goal;
   * **refuse**: the goal is out of reach; the run stops with what cannot be done and what was
     done, and the robots finish only what they hold.

Every recovery is a round of the outcome: its cause, what it learned, what it did (which subtasks
were re-allocated, aborted, re-planned), the feasibility of the goal from the observed state
(checked by the domain, independently of the planner), and the seconds it took.
"""
from __future__ import annotations

import copy
import math
import time
from dataclasses import dataclass, field
from typing import Any, Callable

from pipflow.errors import AllocationError, InputError
from pipflow.execution import faults as fk
from pipflow.execution.capability import ExecutionCapability, Played
from pipflow.execution.faults import Fault
from pipflow.execution.monitor import Anomaly, Known, first_anomaly
from pipflow.execution.motion import MotionFaults, actual_schedule, clip_legs, drop_site, grown, with_legs
from pipflow.execution.recovery import Planning, Refused, cut_off, reallocate, renamed, replan, waits
from pipflow.execution.standing import Cut, Driving, Stops, cut
from pipflow.liberrors import UNIFIED_PLANNING, library_errors
from pipflow.errors import PlanningError
from pipflow.pddl.common import parse
from pipflow.pddl.convert import data_to_plan

EPS = 1e-6
#: recoveries allowed per fault (and a few for anomalies no fault explains) before the executor
#: stops recovering and lets the run end as it stands (a loop that never settles is a bug: it is
#: reported, never hidden)
ROUNDS_PER_FAULT = 3


@dataclass
class Outcome:
    """What the executor hands on (the ``execute`` step's outputs): the world as it really was
    (the records with every surprise, drop places, robots that stopped, closed passages), the
    schedule the robots carried out (legs as driven), its graph, the faults with what became of
    them, the recovery rounds, and the refusal if the goal went out of reach."""

    world: dict
    schedule: dict
    graph: dict
    faults: list[dict]
    rounds: list[dict]
    refusal: str | None = None
    feasible: bool | None = None
    feasibility: str = ""
    notes: list[str] = field(default_factory=list)


def cast(world: dict, schedule: dict) -> tuple[dict, dict]:
    """The world and the schedule with only the robots the schedule moves or names: the others
    stand still and change nothing, and a simulation of a thousand idle robots would build (and
    follow) a thousand bodies."""
    named = {r for r, info in (schedule.get("robots") or {}).items() if info.get("legs")}
    named |= {r for s in schedule.get("subtasks", []) for r in s.get("robots") or []}
    robots = world.get("robots") or {}
    if len(named) == len(robots):
        return world, schedule
    return ({**world, "robots": {r: info for r, info in robots.items() if r in named}},
            {**schedule, "robots": {r: info for r, info in (schedule.get("robots") or {}).items() if r in named}})


class _Observed:
    """What one recovery round learns of the observed state, each part computed once and only if
    asked: the world after the running subtasks end (played on what is known), the goal from it
    as a problem, and whether the pending subtasks still reach the goal from it. The
    stay-or-re-plan check, the re-plan and the feasibility check all read the same state."""

    def __init__(self, executor: "Executor", known: dict, now: Cut, lost: list[str], k: int):
        self.ex, self.known, self.now, self.lost, self.k = executor, known, now, lost, k
        self._world: dict | None = None
        self._problem: tuple[Any, str] | None = None
        self._fits: bool | None = None

    def world(self) -> dict:
        if self._world is None:
            ex, now = self.ex, self.now
            belief = ex.domain.play(*cast(self.known, ex._schedule(now.records, now.legs)), ex.graph)
            state_world = ex.domain.with_state(self.known, belief.final_state)
            self._world = {**state_world, "robots": {r: v for r, v in state_world["robots"].items() if r not in self.lost}}
        return self._world

    def problem(self) -> tuple[Any, str]:
        if self._problem is None:
            ex = self.ex
            with library_errors(UNIFIED_PLANNING, PlanningError, "building the problem from the observed state"):
                self._problem = ex.domain.observed_problem(ex._accepted(), self.world(), ex.goal,
                                                           ex.planning.domain_text, f"recovery{self.k}")
        return self._problem

    def fits(self) -> bool:
        if self._fits is None:
            self._fits = self.ex._still_fits(self.now, self.problem()[0], {n["id"]: n for n in self.ex.graph["nodes"]})
        return self._fits


class Executor:
    """One execution under faults (module docstring)."""

    def __init__(self, domain: ExecutionCapability, world: dict, schedule: dict, graph: dict, faults: list[Fault],
                 planning: Planning, log: Callable[[str], None] | None = None,
                 save: Callable[[str, Any], Any] | None = None):
        self.domain = domain
        self.records = world
        self.schedule = schedule
        self.graph = graph
        self.faults = faults
        self.planning = planning
        self.log = log or (lambda message: None)
        self.save = save
        self.by_id = {f.id: f for f in faults}
        self.handled: set = set()
        self.last = 0.0
        self.stopped: dict[str, tuple[float, Any]] = {}
        self.pace: dict[str, float] = {}
        self.known_barriers: list[str] = []
        self.discovered: list[str] = []
        self.drop_sites: dict[str, dict] = {}
        self.drops: dict[str, str] = {}
        self.rounds: list[dict] = []
        self.refusal: str | None = None
        self.feasible: tuple[bool | None, str] = (None, "no fault needed a recovery")
        self.status: dict[str, dict] = {f.id: {} for f in faults}
        self.notes: list[str] = []
        with library_errors(UNIFIED_PLANNING, PlanningError, "reading the accepted problem"):
            self.goal = domain.plan_goal(parse(planning.domain_text, planning.problem), world)

    # ------------------------------------------------------------------ worlds
    def _world(self, surprises: list[str], barriers: list[str], stops: dict[str, float]) -> dict:
        """The records with these surprises, drop places, barriers and stops. Copied where it
        changes only (the domain's ``apply_surprise`` and ``drop_place`` return copies; a stopped
        robot's entry is replaced, not written into): a deep copy of a thousand robots costs a
        tenth of a second per world, and a recovery makes several. Nothing downstream writes
        into a world (the records stay as loaded: tests/test_faults.py checks it)."""
        w = {**self.records, "robots": dict(self.records.get("robots") or {})}
        for fid in surprises:
            w = self.domain.apply_surprise(w, self.by_id[fid].surprise)
        for r, site in self.drop_sites.items():
            w, _ = self.domain.drop_place(w, r, site)
        if barriers:
            w["barriers"] = list(w.get("barriers") or []) + [self.by_id[fid].barrier for fid in barriers]
        for r, t in stops.items():
            w["robots"][r] = {**w["robots"][r], "stopped": {"time": t, "drop": self.drops.get(r)}}
        return w

    def truth(self) -> dict:
        """The world as it really is: every surprise, every stop that will happen."""
        return self._world([f.id for f in self.faults if f.kind == fk.SURPRISE], [], self.stop_times())

    def known(self) -> dict:
        """The world as the executor knows it: surprises found, passages found closed, robots lost."""
        return self._world(self.discovered, self.known_barriers, {r: t for r, (t, _) in self.stopped.items()})

    def stop_times(self) -> dict[str, float]:
        """When each robot-loss strikes: its time, or the end of the robot's k-th subtask as now scheduled."""
        out = {}
        for f in self.faults:
            if f.kind != fk.ROBOT_LOSS:
                continue
            if f.robot in self.stopped:
                out[f.robot] = self.stopped[f.robot][0]
            elif f.time is not None:
                out[f.robot] = f.time
            else:
                ends = sorted(float(s["end"]) for s in self.schedule.get("subtasks", []) if f.robot in s.get("robots", []))
                if len(ends) >= int(f.after):
                    out[f.robot] = ends[int(f.after) - 1]
        return out

    def motion_faults(self) -> MotionFaults:
        mf = MotionFaults(stops=self.stop_times())
        for f in sorted(self.faults, key=lambda f: f.time or 0.0):
            if f.kind == fk.SLOWDOWN:
                mf.slow.setdefault(f.robot, []).append((float(f.time), float(f.factor)))
            elif f.kind == fk.PASSAGE:
                mf.barriers.append((grown(f.barrier), float(f.time), f.id))
        return mf

    # ------------------------------------------------------------------ the loop
    def run(self) -> Outcome:
        most = ROUNDS_PER_FAULT * len(self.faults) + 3
        while True:
            truth = self.truth()
            actual, motion = actual_schedule(truth, self.schedule, self.motion_faults())
            played = self.domain.play(*cast(truth, actual), self.graph)
            if self.refusal is not None:
                break
            anomaly = first_anomaly(truth, self.faults, self.schedule, actual, motion, played,
                                    Known(frozenset(self.handled), self.last, frozenset(self.discovered)))
            if anomaly is None:
                break
            if len(self.rounds) >= most:
                self.notes.append(f"stopped recovering after {len(self.rounds)} rounds; the next difference was at "
                                  f"t={anomaly.time:.1f} s: {anomaly.words}")
                self.log(self.notes[-1])
                break
            self.recover(anomaly, actual, motion, played)
        return self.outcome(truth, actual, motion)

    # ------------------------------------------------------------------ one recovery
    def learn(self, anomaly: Anomaly, motion: Any) -> str:
        """What the anomaly reveals, added to what the executor knows; in words."""
        self.handled.add(anomaly.key)
        self.last = anomaly.time
        fault = self.by_id.get(anomaly.fault) if anomaly.fault else None
        if fault is not None:
            self.status[fault.id].setdefault("detected", round(anomaly.time, 3))
            self.status[fault.id].setdefault("round", len(self.rounds) + 1)
        if anomaly.kind == "stopped":
            self.stopped[anomaly.robot] = motion.stopped[anomaly.robot]
            return f"{anomaly.robot} is out of service from t={anomaly.time:.1f} s"
        if anomaly.kind == "blocked" and fault is not None:
            if fault.id not in self.known_barriers:
                self.known_barriers.append(fault.id)
            return f"the passage is closed: {fault.describe()}"
        if anomaly.kind == "behind" and fault is not None:
            self.pace[anomaly.robot] = float(fault.factor)
            return f"{anomaly.robot} drives at {100 * fault.factor:.0f}% of its planned speed"
        if anomaly.kind == "surprise" and fault is not None:
            self.discovered.append(fault.id)
            return f"{anomaly.place}: {fault.describe()}"
        return anomaly.words

    def recover(self, anomaly: Anomaly, actual: dict, motion: Any, played: Played) -> None:
        started = (time.perf_counter(), time.process_time())  # wall and this process's CPU
        k = len(self.rounds) + 1
        t = anomaly.time
        learned = self.learn(anomaly, motion)
        entry: dict[str, Any] = {"round": k, "time": round(t, 3), "cause": anomaly.to_json(), "learned": learned}
        self.log(f"recovery {k} at t={t:.1f} s: {anomaly.words}; {learned}")
        if anomaly.kind == "stopped":
            self._drop(anomaly.robot, played, motion)
        lost = sorted(r for r, (ts, _) in self.stopped.items() if ts <= t + EPS)
        known = self.known()
        from pipflow.team.travel import TravelMap  # deferred: numpy/networkx (only runs with faults get here)

        travel = TravelMap(known)
        nodes = {n["id"]: n for n in self.graph["nodes"]}
        access = {r: self.drop_sites[r]["access"] for r in self.drops}
        try:
            now = cut(known, self.schedule.get("subtasks", []), nodes, actual, played, t,
                      Stops({r: self.stopped[r] for r in lost}, access),
                      Driving(travel, self.planning.speed, self.planning.handling, self.pace))
        except InputError as err:  # no path any more from where a robot stands (a passage walled it in)
            self._refuse(entry, f"{err}", None, started)
            self._close(entry, started, None)
            return
        entry.update({"done": now.done, "running": now.running, "broken": now.broken, "pending": now.pending,
                      "lost": lost})
        seen = _Observed(self, known, now, lost, k)
        observed, problem, fits = seen.world, seen.problem, seen.fits
        affected = [s for s in now.pending + now.running if anomaly.robot in self._robots_of(s)] if anomaly.robot else []
        needs_plan = bool(now.broken) or anomaly.kind in ("surprise", "refused", "unfinished")
        try:
            if not now.pending and not now.broken and (not needs_plan or fits()):
                # they finish from where their robots are, at their pace (after what was learnt of
                # the state, only when the goal then holds: units found where the plan brings more)
                self.schedule = self._schedule(now.records, now.legs)
                self._continue(entry, "nothing is left to do but the subtasks under way; their robots finish them "
                                      "from where they are")
            elif anomaly.kind == "stopped" and not affected and not now.broken:
                self._continue(entry, f"{anomaly.robot} had no work left")
            elif needs_plan and not now.broken and fits():
                if anomaly.kind == "surprise":
                    self._continue(entry, "the remaining plan still reaches the goal from the observed state")
                else:
                    self._reallocate(entry, now, known, travel, lost)
            elif not needs_plan:
                try:
                    self._reallocate(entry, now, known, travel, lost)
                except AllocationError as err:
                    entry["reallocation_failed"] = str(err)
                    self._replan(entry, now, known, travel, lost, observed(), problem(), k)
            else:
                self._replan(entry, now, known, travel, lost, observed(), problem(), k)
        except Refused as err:
            self._refuse(entry, str(err), now, started)
        except InputError as err:  # no path any more from a robot or between places (a passage walled it off)
            self._refuse(entry, f"the floor is cut in two: {err}", now, started)
        self._close(entry, started, observed)

    def _close(self, entry: dict, started: tuple[float, float], observed: Callable[[], dict] | None) -> None:
        """Time the round, check the goal's feasibility from the observed state (not timed as
        recovery: a check, independent of the planner), keep the round."""
        k = entry["round"]
        entry["seconds"] = round(time.perf_counter() - started[0], 4)
        entry["cpu_seconds"] = round(time.process_time() - started[1], 4)
        checked = time.perf_counter()
        self.feasible = (self.domain.feasibility(observed(), self.goal, self.planning.constraints) if observed
                         else (None, "the state could not be observed"))
        entry["feasible"], entry["feasibility"] = self.feasible
        entry["check_seconds"] = round(time.perf_counter() - checked, 4)
        self.rounds.append(entry)
        if self.save is not None:
            self.save(f"recovery-{k}/round.json", entry)
        self.log(f"recovery {k}: {entry['action']} in {entry['seconds']:.3f} s"
                 + (f" ({entry.get('refusal')})" if entry.get("refusal") else ""))

    def _robots_of(self, sid: str) -> list[str]:
        rec = next((s for s in self.schedule.get("subtasks", []) if s["id"] == sid), None)
        return list((rec or {}).get("robots") or [])

    def _drop(self, robot: str, played: Played, motion: Any) -> None:
        """A robot that stopped during a subtask keeps what it carried where it stands: a place."""
        t, point = motion.stopped[robot]
        busy = [s["id"] for s in self.schedule.get("subtasks", []) if robot in s.get("robots", [])
                and played.began.get(s["id"], math.inf) < t - EPS and played.ended.get(s["id"], math.inf) > t - EPS]
        if not busy or robot in self.drops:
            return
        legs = ((self.schedule.get("robots") or {}).get(robot) or {}).get("legs") or []
        came = next((l.get("from") for l in reversed(legs) if float(l["start"]) < t), None)
        known = self.known()

        def reaches(site: dict) -> bool:
            """Whether a robot coming the way this one came can still get to the site."""
            if not came:
                return True
            from pipflow.team.travel import TravelMap  # deferred: numpy/networkx (only runs with faults get here)

            world, _ = self.domain.drop_place(known, robot, site)
            try:
                TravelMap(world).distance(tuple(came), tuple(site["access"]))
            except InputError:
                return False
            return True

        site = drop_site(known, point, tuple(came) if came else None, reaches)
        _, name = self.domain.drop_place(self.records, robot, site)
        self.drop_sites[robot], self.drops[robot] = site, name

    def _accepted(self) -> Any:
        """The accepted problem, parsed (the parse memo's shared copy: read-only)."""
        with library_errors(UNIFIED_PLANNING, PlanningError, "reading the accepted problem"):
            return parse(self.planning.domain_text, self.planning.problem)

    def _still_fits(self, now: Cut, problem: Any, nodes: dict) -> bool:
        """Whether the pending subtasks, in plan order, still reach the goal from the observed state
        (UP's sequential plan validator on the observed state's problem). Only the verdict is
        needed: the verifier's goal check and its explanation of a failed step are not asked for."""
        # deferred: pulls unified_planning (only recoveries from a surprise get here)
        from unified_planning.engines import ValidationResultStatus
        from unified_planning.shortcuts import PlanValidator

        rest = [{"action": nodes[s]["action"], "args": list(nodes[s]["args"])}
                for s in sorted(now.pending, key=lambda s: nodes[s]["index"])]
        with library_errors(UNIFIED_PLANNING, PlanningError, "checking the remaining plan"):
            try:
                plan = data_to_plan(problem, rest)
            except ValueError:  # a step names what the observed problem does not have
                return False
            with PlanValidator(name="sequential_plan_validator") as validator:
                return validator.validate(problem, plan).status == ValidationResultStatus.VALID

    def _schedule(self, records: list[dict], legs: dict[str, list[dict]]) -> dict:
        robots = {r: {"legs": ls, "distance": sum(float(l.get("distance", 0.0)) for l in ls)} for r, ls in legs.items()}
        return with_legs({"subtasks": records}, robots)

    def _continue(self, entry: dict, why: str) -> None:
        entry.update({"action": "continue", "why": why})

    def _walled_off(self, graph: dict, now: Cut, lost: list[str], travel: Any) -> list[dict]:
        """With a passage known closed: rules keeping robots off the subtasks they cannot reach."""
        if not self.known_barriers:
            return []
        alive = [r for r in self.records.get("robots", {}) if r not in lost]
        return cut_off(graph, now.standing, alive, travel)

    def _reallocate(self, entry: dict, now: Cut, known: dict, travel: Any, lost: list[str]) -> None:
        allocation, timeline = reallocate(self.graph, known, now.standing, self.planning, lost, travel,
                                          self._walled_off(self.graph, now, lost, travel))
        self._merge(now, timeline)
        entry.update({"action": "re-allocate", "reallocated": [a["subtask"] for a in allocation["assignments"]],
                      "allocation": allocation["assignments"]})

    def _replan(self, entry: dict, now: Cut, known: dict, travel: Any, lost: list[str], observed: dict,
                problem: tuple[Any, str], k: int) -> None:
        nodes = {n["id"]: n for n in self.graph["nodes"]}
        rest = [{"action": nodes[s]["action"], "args": list(nodes[s]["args"]), "subtask": s}
                for s in sorted(now.pending, key=lambda s: nodes[s]["index"])]
        found = replan(self.domain, observed, self.goal, self.planning, problem, rest)
        offset = 1 + max((int(n["index"]) for n in self.graph["nodes"]), default=-1)
        new = renamed(found.graph, f"r{k}-", offset)
        nodes = {n["id"]: n for n in self.graph["nodes"]}
        running = [nodes[s] for s in now.running]
        wait = waits(running, new["nodes"])
        walk = {"mode": new.get("mode"), "nodes": running + new["nodes"], "edges": new["edges"] + wait}
        try:
            allocation, timeline = reallocate(walk, known, now.standing, self.planning, lost, travel,
                                              self._walled_off(walk, now, lost, travel))
        except AllocationError as err:
            raise Refused(f"the new plan needs a coalition the robots still working cannot form: {err}") from None
        kept = set(now.done) | set(now.running)
        self.graph = {**self.graph, "nodes": [n for n in self.graph["nodes"] if n["id"] in kept] + new["nodes"],
                      "edges": [e for e in self.graph["edges"] if e[0] in kept and e[1] in kept] + new["edges"] + wait}
        self._merge(now, timeline)
        if found.kept is not None:
            entry["repaired"] = {"kept": found.kept, "dropped": [x["subtask"] for x in found.dropped]}
        entry.update({"action": "re-plan", "aborted": list(now.pending), "plan": found.plan,
                      "replanned": [n["id"] for n in new["nodes"]], "planner": found.message,
                      "allocation": allocation["assignments"]})
        if self.save is not None:
            self.save(f"recovery-{k}/problem.pddl", found.problem)

    def _merge(self, now: Cut, timeline: Any) -> None:
        legs = {r: list(now.legs.get(r, [])) + list(timeline.legs.get(r, [])) for r in set(now.legs) | set(timeline.legs)}
        self.schedule = self._schedule(now.records + list(timeline.records), legs)

    def _refuse(self, entry: dict, reason: str, now: Cut | None, started: tuple[float, float]) -> None:
        cause = entry["cause"].get("words") or entry["cause"]["kind"]
        if now is not None:
            did = now.done + now.running
            text = (f"after {cause} at t={entry['time']:.1f} s the goal cannot be reached any more: {reason}. "
                    f"Carried out: {len(did)} subtask(s){' (' + ', '.join(did) + ')' if did else ''}; not done: "
                    f"{', '.join(now.pending) or 'none'}")
            self.schedule = self._schedule(now.records, now.legs)
        else:  # the run stops where it stands: what ended stays, nobody drives on
            t = float(entry["time"])
            records = [r for r in self.schedule.get("subtasks", []) if float(r["end"]) <= t + EPS]
            legs = {r: clip_legs(info.get("legs") or [], t) for r, info in (self.schedule.get("robots") or {}).items()}
            self.schedule = self._schedule(records, legs)
            text = (f"after {cause} at t={entry['time']:.1f} s the run cannot go on: {reason}. Carried out: "
                    f"{len(records)} subtask(s) before t={t:.1f} s")
        self.refusal = text
        entry.update({"action": "refuse", "refusal": text})

    # ------------------------------------------------------------------ what is handed on
    def outcome(self, truth: dict, actual: dict, motion: Any) -> Outcome:
        end = float(actual.get("makespan", 0.0))
        stops = self.stop_times()
        faults = []
        for f in self.faults:
            info = {**f.to_json(), **self.status[f.id]}
            if f.kind == fk.ROBOT_LOSS:
                t = stops.get(f.robot)
                info["occurred"] = t is not None and t <= end + EPS
                if t is not None:
                    info["time"] = round(t, 3)
                    info["point"] = [round(v, 3) for v in motion.stopped[f.robot][1]] if f.robot in motion.stopped else None
                if f.robot in self.drops:
                    info["drop"] = self.drops[f.robot]
            elif f.kind == fk.SURPRISE:
                info["occurred"] = True
            else:
                info["occurred"] = float(f.time) <= end + EPS
            info["detected"] = info.get("detected")
            faults.append(info)
        world = copy.deepcopy(truth)
        barriers = [f.barrier for f in self.faults if f.kind == fk.PASSAGE and float(f.time) <= end + EPS]
        if barriers:
            world["barriers"] = barriers
        feasible, why = self.feasible
        return Outcome(world, actual, self.graph, faults, self.rounds, self.refusal, feasible, why, self.notes)

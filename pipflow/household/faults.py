"""The household's side of execution under faults (:mod:`pipflow.execution`): what only the home
knows about its world changing.

* **object surprise**: an object is not where the world file says; it lies in another place. A
  robot notices when it arrives at either place (it comes for the object and finds it gone, or
  finds it where it should not be); the home's inventory then knows where it is. Drawn among the
  objects the schedule moves, so it always matters.
* **play**: the home simulator; a subtask's work begins when it starts and ends when its
  effects land.
* **with_state**: the world whose initial state is a state the simulator reached, so that the
  household's own problem writer writes it as a new problem.
* **drop place**: what a stopped robot's coalition carried lies where it stopped: a small
  receptacle there, from which a new plan may fetch it.
* **feasibility**: whether the robots still working can reach the goal from a state, checked
  without the planner: every condition that does not hold yet needs a skill (lifting the
  object's mass together, opening a closed container on the way, switching, slicing, washing at
  a sink, heating in a heater that can be closed) that the robots the rules allow still have.
"""
from __future__ import annotations

import copy
import random
from typing import Any

from pipflow.errors import FaultNotApplicable, InputError
from pipflow.execution.capability import Played
from pipflow.household.problem import CONDITIONS, goal_from_problem, goal_refusal
from pipflow.household.scoring import holds
from pipflow.household.world import RESERVED, initial_state
from pipflow.suggest import did_you_mean

#: the household's name for a state surprise
SURPRISE_NAMES = ("object-surprise",)
#: the state flags a world records per entity, as the simulator's final state lists them
FLAGS = ("open", "on", "dirty", "sliced", "hot")
#: the skill of the action that makes a condition hold, by (predicate, positive)
#: (domains/household.pddl and .actions.yaml); none makes a thing dirty, whole or cold again
ACHIEVERS = {("is-open", True): "open", ("is-open", False): "open", ("is-on", True): "toggle",
             ("is-on", False): "toggle", ("sliced", True): "slice", ("dirty", False): "wash", ("hot", True): "heat"}


# ------------------------------------------------------------------------------------------
# surprises
# ------------------------------------------------------------------------------------------
def _words(obj: str, place: str, records: str) -> str:
    return f"{obj} is in {place}, not in {records} as the records say"


def draw_surprise(world: dict, schedule: dict, graph: dict | None, rng: random.Random) -> dict | None:
    """An object the schedule carries away from a place, lying in another receptacle;
    :class:`FaultNotApplicable` when the plan carries no object away (it only slices, switches,
    heats...) or the home has no other receptacle for it."""
    moved = sorted({(s.get("args") or [None])[0] for s in schedule.get("subtasks", [])
                    if s.get("action") in ("store", "trash")} - {None})
    moved = [o for o in moved if o in world["objects"]]
    if not moved:
        raise FaultNotApplicable("the plan carries no object from one place to another (it stores or trashes none), "
                                 "so no object lying elsewhere can matter to it")
    obj = rng.choice(moved)
    records = world["objects"][obj]["in"]
    elsewhere = sorted(p for p, e in world["places"].items()
                       if p != records and "receptacle" in e["properties"] and not e.get("drop"))
    if not elsewhere:
        raise FaultNotApplicable(f"no receptacle other than {records} for {obj} to lie in")
    place = rng.choice(elsewhere)
    return {"object": obj, "in": place, "records": records, "places": [records, place],
            "words": _words(obj, place, records)}


def check_surprise(world: dict, given: dict, where: str) -> dict:
    """``{object: OBJECT, in: PLACE}``: where the object really lies."""
    unknown = sorted(k for k in given if k not in ("object", "in"))
    if unknown:
        raise InputError(f"{where}: an object-surprise has no field {', '.join(map(repr, unknown))}; its fields: "
                         "object, in (the place where it really lies)")
    obj, place = given.get("object"), given.get("in")
    if obj not in world["objects"]:
        raise InputError(f"{where}: unknown object {obj!r}{did_you_mean(str(obj), world['objects'])}")
    if place not in world["places"] or "receptacle" not in world["places"][place]["properties"]:
        names = [p for p, e in world["places"].items() if "receptacle" in e["properties"]]
        raise InputError(f"{where}: {place!r} is not a receptacle of this home{did_you_mean(str(place), names)}")
    records = world["objects"][obj]["in"]
    if place == records:
        raise InputError(f"{where}: {obj} lying in {place} is what the records say: no surprise")
    return {"object": obj, "in": place, "records": records, "places": [records, place],
            "words": _words(obj, place, records)}


def apply_surprise(world: dict, surprise: dict) -> dict:
    out = copy.deepcopy(world)
    out["objects"][surprise["object"]]["in"] = surprise["in"]
    return out


# ------------------------------------------------------------------------------------------
# the world's state, drop places
# ------------------------------------------------------------------------------------------
def with_state(world: dict, state: dict) -> dict:
    """The world whose objects lie where ``state`` says and whose flags are ``state``'s."""
    out = copy.deepcopy(world)
    at = state.get("at") or {}
    for name, obj in out["objects"].items():
        if at.get(name) is not None:
            obj["in"] = at[name]
    for name, e in {**out["places"], **out["objects"]}.items():
        e["state"] = {k: name in set(state.get(k) or []) for k in FLAGS if name in set(state.get(k) or [])
                      or k in e.get("state", {})}
    return out


def drop_place(world: dict, robot: str, site: dict) -> tuple[dict, str]:
    """The world with a small receptacle ``<robot>-cargo`` where the stopped robot stands."""
    out = copy.deepcopy(world)
    name, k = f"{robot}-cargo", 1
    while name in out["places"] or name in out["objects"] or name in out["robots"] or name in RESERVED:
        k += 1
        name = f"{robot}-cargo{k}"
    out["places"][name] = {**{k2: site[k2] for k2 in ("x", "y", "width", "depth")}, "access": list(site["access"]),
                           "properties": ["receptacle"], "categories": [], "words": [], "state": {}, "drop": robot}
    return out, name


# ------------------------------------------------------------------------------------------
# playing and planning
# ------------------------------------------------------------------------------------------
def play(world: dict, schedule: dict, graph: dict | None) -> Played:
    # deferred: the simulator module pulls the scoring helpers (only runs with faults play here)
    from pipflow.household.simulation import simulate

    result = simulate(world, schedule, graph, None, trace=True)
    return Played(result["final_state"], dict(result["began"]), dict(result["ended"]), list(result["failures"]),
                  dict(result["interrupted"]), result)


def plan_goal(parsed: Any, world: dict) -> dict:
    """The accepted problem's goal conditions (objects named: counts were resolved when it was written)."""
    return goal_from_problem(parsed)


def feasibility(world: dict, goal: dict, constraints: list[dict]) -> tuple[bool | None, str]:
    """Module docstring: each condition still to reach needs skills the allowed working robots have."""
    refusal = goal_refusal(world, goal)
    if refusal:
        return False, refusal
    s = initial_state(world)
    state = {"at": s["at"], **{k: sorted(v) for k, v in s.items() if k != "at"}}
    problems: list[str] = []
    places, objects = world["places"], world["objects"]

    def team(skill: str, **fields: str) -> float:
        allowed = set(world["robots"])
        for rule in constraints or []:
            if all(rule[k] == v for k, v in fields.items() if k in rule) and all(k in fields for k in rule
                                                                                if k in ("object", "from", "to", "at")):
                allowed -= set(rule.get("never") or ())
                if "only" in rule:
                    allowed &= set(rule["only"])
        return sum(float(world["robots"][r].get("skills", {}).get(skill, 0)) for r in allowed)

    def reach(place: str | None) -> list[str]:
        p = places.get(place or "")
        if p and "openable" in p["properties"] and place not in state.get("open", []) and team("open", object=place) < 1:
            return [f"{place} is closed and no robot still working can open it"]
        return []

    def carry(obj: str, src: str | None, dst: str | None = None) -> list[str]:
        mass = float(objects[obj]["mass"])
        if src is None:
            return [f"{obj} is with a robot that stopped"]
        fields = {"object": obj, "from": src, **({"to": dst} if dst else {})}
        lift = team("pickup", **fields)
        out = [] if lift >= mass else [f"{obj} weighs {mass:g} and the robots still working lift {lift:g} together"]
        return out + reach(src) + reach(dst)

    for place, items in (goal.get("in") or {}).items():
        for obj in items:
            if state["at"].get(obj) != place:
                problems += carry(obj, state["at"].get(obj), place)
    for name, conds in (goal.get("state") or {}).items():
        for cond in conds:
            if holds(state, name, cond):
                continue
            pred, positive, _ = CONDITIONS[cond]
            skill = ACHIEVERS.get((pred, positive))
            if skill is None:
                problems.append(f"no action makes {name} {cond}")
                continue
            where = name if name in places else state["at"].get(name)
            fields = {"object": name, **({"at": where} if where and name not in places else {})}
            if team(skill, **fields) < 1:
                problems.append(f"no robot still working can {skill} {name}")
            if name in places:
                continue
            if skill == "slice":
                problems += reach(where)
            elif skill == "wash" and "sink" not in places.get(where or "", {}).get("properties", []):
                problems += carry(name, where)
            elif skill == "heat" and "heater" not in places.get(where or "", {}).get("properties", []):
                problems += carry(name, where)
                if not any("heater" in q["properties"] and ("openable" not in q["properties"] or team("open", object=n) >= 1)
                           for n, q in places.items()):
                    problems.append(f"no heater {name} could be put in and closed by the robots still working")
    if problems:
        return False, "; ".join(dict.fromkeys(problems))
    return True, "every condition still to reach has robots still working with the skills it needs"



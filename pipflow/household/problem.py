"""World + goal conditions -> PDDL problem for domains/household.pddl, and the world check of
``pddl.debug`` for household problems.

Goal conditions (task ground truth and translator output share this shape)::

    {"in": {PLACE: [OBJECT, ...]},                 # the object lies in/on the place at the end
     "state": {ENTITY: [CONDITION, ...]},           # open closed on off sliced clean dirty hot cold whole
     "count": [{"category": C, "in": PLACE, "at_least": N}]}   # vague: any N members of C

``count`` conditions cannot be written as PDDL as they stand (which members?); the translator
resolves them to concrete ``in`` conditions first (:func:`pipflow.household.language.translator.resolve_counts`).
The initial state is exactly the world's, so the debugger can demand it of any generated problem.
"""
from __future__ import annotations

from typing import Any

from pipflow.household.world import entity
from pipflow.pddl.common import goal_conditions
from pipflow.pddl.convert import initial_numbers
from pipflow.pddl.textpos import find_word
from pipflow.suggest import did_you_mean_clause

PLACE_FLAGS = {"receptacle": "is-receptacle", "garbage": "is-garbage", "sink": "is-sink", "heater": "is-heater",
               "openable": "openable", "toggleable": "toggleable"}
OBJECT_FLAGS = {"pickupable": "pickupable", "sliceable": "sliceable", "washable": "washable",
                "heatable": "heatable", "toggleable": "toggleable"}
STATE_FLUENT = {"open": "is-open", "on": "is-on", "dirty": "dirty", "sliced": "sliced", "hot": "hot"}
#: goal condition word -> (predicate, positive?, property the entity needs)
CONDITIONS: dict[str, tuple[str, bool, str]] = {
    "open": ("is-open", True, "openable"), "closed": ("is-open", False, "openable"),
    "on": ("is-on", True, "toggleable"), "off": ("is-on", False, "toggleable"),
    "sliced": ("sliced", True, "sliceable"), "clean": ("dirty", False, "washable"),
    "dirty": ("dirty", True, "washable"), "hot": ("hot", True, "heatable"),
    # no action of the domain reaches these two; a goal may keep them where they hold already
    "cold": ("hot", False, "heatable"), "whole": ("sliced", False, "sliceable"),
}


def initial_facts(world: dict) -> set[tuple[str, ...]]:
    """Every true atom of the world's initial state, as ``(predicate, arg, ...)``."""
    facts: set[tuple[str, ...]] = set()
    for name, p in world["places"].items():
        facts.add(("at", name, name))
        facts |= {(PLACE_FLAGS[k], name) for k in p["properties"] if k in PLACE_FLAGS}
        if "openable" not in p["properties"] or p["state"].get("open"):
            facts.add(("accessible", name))
        facts |= {(STATE_FLUENT[k], name) for k, v in p["state"].items() if v}
    for name, o in world["objects"].items():
        facts.add(("at", name, o["in"]))
        facts |= {(OBJECT_FLAGS[k], name) for k in o["properties"] if k in OBJECT_FLAGS}
        facts |= {(STATE_FLUENT[k], name) for k, v in o["state"].items() if v}
    return facts


def _num(v: float) -> str:
    return str(int(v)) if float(v).is_integer() else str(v)


def goal_literals(world: dict, goal: dict) -> list[str]:
    """PDDL literals of concrete goal conditions (``in`` and ``state``)."""
    out = []
    for place, items in (goal.get("in") or {}).items():
        out += [f"(at {o} {place})" for o in items]
    for name, conds in (goal.get("state") or {}).items():
        for c in conds:
            pred, positive, _ = CONDITIONS[c]
            out.append(f"({pred} {name})" if positive else f"(not ({pred} {name}))")
    return out


def write_problem(world: dict, goal: dict, name: str = "task", domain: str = "household") -> str:
    """PDDL problem text: the world's objects and initial state, the goal's conditions."""
    if goal.get("count"):
        raise ValueError("count conditions must be resolved to objects before writing the problem")
    lines = [f"(define (problem {name})", f"  (:domain {domain})", "  (:objects"]
    lines.append(f"    {' '.join(world['places'])} - place")
    if world["objects"]:
        lines.append(f"    {' '.join(world['objects'])} - item")
    lines[-1] += ")"
    lines.append("  (:init")
    for fact in sorted(initial_facts(world)):
        lines.append(f"    ({' '.join(fact)})")
    for o, obj in world["objects"].items():
        lines.append(f"    (= (mass {o}) {_num(obj['mass'])})")
    lines[-1] += ")"
    lits = goal_literals(world, goal)
    lines.append("  (:goal (and")
    lines += [f"    {c}" for c in lits]
    lines.append("  )))")
    return "\n".join(lines) + "\n"


# ---------------------------------------------------------------------------------------------
# the debugger's world check (called by pipflow.pddl.debugger for worlds with domain: household)
# ---------------------------------------------------------------------------------------------
def world_mismatches(problem: Any, text: str, world: dict) -> list[str]:
    """Every way a parsed household problem's objects and initial state differ from the world's:
    a problem that invents an object or a state would be solved in a world that is not ours."""
    out: list[str] = []
    have: dict[str, list[str]] = {}
    for o in problem.all_objects:
        have.setdefault(o.type.name, []).append(o.name)
    expect = {"place": list(world["places"]), "item": list(world["objects"])}
    for typ, names in expect.items():
        for n in have.get(typ, []):
            if n not in names:
                out.append(f"{find_word(text, n)}object {n!r} ({typ}) is not in the world{did_you_mean_clause(n, names)}")
        for n in names:
            if n not in have.get(typ, []):
                out.append(f"the problem lacks {typ} {n!r} of the world; declare it in :objects as '{n} - {typ}'")
    for typ in have:
        if typ not in expect:
            out.append(f"objects of type {typ!r} are not part of household worlds (types: place, item)")
    declared = {o.name for o in problem.all_objects}
    facts = set()
    for fexp, value in problem.explicit_initial_values.items():
        if fexp.is_fluent_exp() and value.is_bool_constant() and value.bool_constant_value():
            facts.add((fexp.fluent().name,) + tuple(str(a) for a in fexp.args))
    want = {f for f in initial_facts(world) if all(a in declared for a in f[1:])}
    for f in sorted(want - facts):
        out.append(f"the initial state lacks ({' '.join(f)}), which holds in the world: add it to :init")
    for f in sorted(facts - want):
        if all(a in declared for a in f[1:]):
            out.append(f"{find_word(text, f[0])}({' '.join(f)}) is in :init but does not hold in the world")
    nums = initial_numbers(problem)
    for o, obj in world["objects"].items():
        if o in declared and nums.get(("mass", o)) != obj["mass"]:
            out.append(f"(mass {o}) must be {_num(obj['mass'])} as in the world, not {nums.get(('mass', o))}")
    return out


def goal_from_problem(problem: Any) -> dict:
    """Concrete goal conditions read back from a parsed problem's goal (for judging LLM output)."""
    inv = {(pred, pos): word for word, (pred, pos, _) in CONDITIONS.items()}

    goal: dict = {"in": {}, "state": {}}
    for g in goal_conditions(problem):
        positive = not g.is_not()
        atom = g if positive else g.arg(0)
        if not atom.is_fluent_exp():
            continue
        name, args = atom.fluent().name, [str(a) for a in atom.args]
        if name == "at" and positive and len(args) == 2:
            goal["in"].setdefault(args[1], []).append(args[0])
        elif (name, positive) in inv and args:
            goal["state"].setdefault(args[0], []).append(inv[(name, positive)])
    return goal


def condition_allowed(world: dict, name: str, cond: str) -> bool:
    """Whether ``cond`` can apply to the entity at all (``sliced`` needs ``sliceable``...)."""
    return CONDITIONS[cond][2] in entity(world, name)["properties"]


def goal_refusal(world: dict, goal: dict) -> str | None:
    """Why no plan can ever reach ``goal`` in this world (a state the thing cannot take, e.g.
    slicing a mug), or None."""
    reasons = [f"{name} cannot be {cond}: it is not {CONDITIONS[cond][2]}"
               for name, conds in (goal.get("state") or {}).items() for cond in conds
               if cond in CONDITIONS and not condition_allowed(world, name, cond)]
    return "; ".join(reasons) or None

"""World and task files: load, validate with located errors, and expose the facts later steps use.

A world file (format: ``benchmarks/README.md``, schema: ``schemas/world.schema.json``) is checked
in two passes and every problem is reported at once, each with its line and column, because a
user fixing a file wants the whole list, not one error per run:

1. JSON Schema (structure, types, unknown keys with the closest known key);
2. meaning: stock names a shelf and a product that exist, counts are not negative, no shelf holds
   more than its capacity, footprints lie on the floor, robots start and access points lie on
   the floor and outside every footprint, a robot's ``kind`` and ``tags`` are not also the name
   of a shelf, product, robot or skill (commands select robots by them).

:func:`load_world` returns the normalized world dict of ``docs/architecture.md``;
:func:`load_tasks` loads a task file, resolves its ``world`` relative to the task file, and
reports goal and constraint names that the world does not have, bounds that contradict
themselves, and gold goals of feasible tasks that the world cannot meet.
"""
from __future__ import annotations

import re
from pathlib import Path
from typing import Any

from pipflow.errors import Diagnostic, Location, TaskFileError
from pipflow.floorplan import FootprintGrid, layout_diagnostics, on_floor
from pipflow.goalcounts import is_bound, value_problems
from pipflow.language.spelling import normalize
from pipflow.suggest import did_you_mean
from pipflow.taskdomain import Facts
from pipflow.worldfile import (LIMITS_VARIABLE, Locate, checked_yaml, duplicate_diagnostics, is_point, load_schema,
                               parse_mapping, read_world_file, schema_diagnostics, size_limits)


#: entries a warehouse world may hold per section (over :data:`pipflow.worldfile.SECTION_LIMIT`'s
#: default for the others), and ``units``: the units in stock, all shelves together (the
#: simulation plays each unit as a body, and a plan moves them a few at a time); settable with
#: PIPFLOW_WORLD_LIMITS, e.g. ``shelves=30000,units=500000``
SIZE_LIMITS = {"robots": 20_000, "shelves": 10_000, "products": 10_000, "units": 200_000}


# ---------------------------------------------------------------------------------------------
# meaning pass
# ---------------------------------------------------------------------------------------------
def case_clash_diagnostics(data: dict, locate: Locate) -> list[Diagnostic]:
    """PDDL reads names in lower case, so two names that differ only in case would be one
    object in every problem: name them apart."""
    out: list[Diagnostic] = []
    seen: dict[str, tuple[str, str]] = {}
    for section in ("shelves", "products", "robots"):
        for name in data.get(section) or {} if isinstance(data.get(section), dict) else {}:
            key = str(name).lower()
            if key in seen and seen[key] != (section, name):
                out.append(Diagnostic(locate((section, name), key=True),
                                      f"{name!r} differs from {seen[key][1]!r} ({seen[key][0]}) only in case; "
                                      "PDDL does not tell them apart: rename one"))
            seen.setdefault(key, (section, name))
    return out


def robot_label_diagnostics(data: dict, locate: Locate) -> list[Diagnostic]:
    """A robot's ``kind`` and ``tags`` select robots in commands ("only the forklifts", "a
    day_shift robot"), so each must not also be the name of a shelf, product, robot or skill: a
    command naming it could not say which one it means (compared in lower case, as the names are)."""
    out: list[Diagnostic] = []
    names: dict[str, tuple[str, str]] = {}
    for section, kind in (("shelves", "shelf"), ("products", "product"), ("robots", "robot")):
        block = data.get(section)
        for name in block if isinstance(block, dict) else {}:
            names.setdefault(str(name).lower(), (kind, str(name)))
    robots = data.get("robots") if isinstance(data.get("robots"), dict) else {}
    for robot in robots.values():
        skills = robot.get("skills") if isinstance(robot, dict) else None
        for skill in skills if isinstance(skills, dict) else {}:
            names.setdefault(str(skill).lower(), ("skill", str(skill)))
    for rname, robot in robots.items():
        if not isinstance(robot, dict):
            continue
        labels = [(("kind",), robot.get("kind"), "kind")]
        tags = robot.get("tags") if isinstance(robot.get("tags"), list) else []
        labels += [(("tags", i), t, "tag") for i, t in enumerate(tags)]
        for where, label, what in labels:
            if isinstance(label, str) and label.lower() in names:
                kind, name = names[label.lower()]
                out.append(Diagnostic(locate(("robots", rname) + where),
                                      f"{what} {label!r} of robot {rname!r} is also the name of {kind} {name!r}; "
                                      f"a command naming it could not tell them apart: rename one"))
    return out


def semantic_diagnostics(data: dict, locate: Locate) -> list[Diagnostic]:
    """Checks the schema cannot express. Runs on partially valid data: every check guards the
    types it needs, so one bad field does not hide the problems of the others."""
    out: list[Diagnostic] = []
    floor = data.get("floor") if isinstance(data.get("floor"), dict) else None
    if floor and not all(isinstance(floor.get(k), (int, float)) for k in ("width", "height")):
        floor = None
    shelves = data.get("shelves") if isinstance(data.get("shelves"), dict) else {}
    shelves = {k: v for k, v in shelves.items() if isinstance(v, dict)}
    products = data.get("products") if isinstance(data.get("products"), dict) else {}
    geo = {k: v for k, v in shelves.items()
           if all(isinstance(v.get(f), (int, float)) for f in ("x", "y", "width", "depth"))}
    out += case_clash_diagnostics(data, locate)

    out += layout_diagnostics(geo, floor, locate, "shelves", "shelf")

    stock = data.get("stock") if isinstance(data.get("stock"), dict) else {}
    units = sum(n for items in stock.values() if isinstance(items, dict)
                for n in items.values() if isinstance(n, int) and not isinstance(n, bool) and n > 0)
    limit = size_limits(SIZE_LIMITS)["units"]
    if units > limit:
        out.append(Diagnostic(locate(("stock",), key=True),
                              f"this world file has {units:,} units in stock; the limit is {limit:,} (each unit is a "
                              f"body in the simulation; settable: {LIMITS_VARIABLE}=units=N in the environment)"))
    for sname, items in stock.items():
        if sname not in shelves:
            out.append(Diagnostic(locate(("stock", sname), key=True),
                                  f"stock names unknown shelf {sname!r}{did_you_mean(sname, shelves)}"))
        if not isinstance(items, dict):
            continue
        total = 0
        for pname, units in items.items():
            if pname not in products:
                out.append(Diagnostic(locate(("stock", sname, pname), key=True),
                                      f"stock of shelf {sname!r} names unknown product {pname!r}"
                                      f"{did_you_mean(pname, products)}"))
            if isinstance(units, int) and not isinstance(units, bool):
                if units < 0:
                    out.append(Diagnostic(locate(("stock", sname, pname)),
                                          f"negative count {units} of {pname!r} on shelf {sname!r}"))
                else:
                    total += units
        cap = shelves.get(sname, {}).get("capacity")
        if isinstance(cap, int) and total > cap:
            out.append(Diagnostic(locate(("stock", sname), key=True),
                                  f"shelf {sname!r} holds {total} units but its capacity is {cap}"))

    robots = data.get("robots") if isinstance(data.get("robots"), dict) else {}
    out += robot_label_diagnostics(data, locate)
    out += declared_word_diagnostics(data, locate)
    grid = FootprintGrid(geo)  # a robot's start against the shelves near it, not every shelf
    for rname, robot in robots.items():
        start = robot.get("start") if isinstance(robot, dict) else None
        if not is_point(start):
            continue
        if floor and not on_floor(start, floor):
            out.append(Diagnostic(locate(("robots", rname, "start")),
                                  f"robot {rname!r} starts at {start}, off the floor "
                                  f"(0, 0)-({floor['width']}, {floor['height']})"))
        for sname in grid.containing(start, geo):
            out.append(Diagnostic(locate(("robots", rname, "start")),
                                  f"robot {rname!r} starts at {start}, inside the footprint of shelf {sname!r}"))
    return out


def declared_word_diagnostics(data: dict, locate: Locate) -> list[Diagnostic]:
    """A word the file declares for a thing (``words``) that another thing is named or declared by:
    the reader could never tell which is meant, so the file is refused where it says so."""
    owner: dict[str, str] = {}
    for key in ("shelves", "products", "robots"):
        for name in (data.get(key) or {}) if isinstance(data.get(key), dict) else ():
            owner.setdefault(normalize(str(name)), str(name))
    out: list[Diagnostic] = []
    for key in ("shelves", "products", "robots"):
        table = data.get(key) if isinstance(data.get(key), dict) else {}
        for name, entry in table.items():
            words = entry.get("words") if isinstance(entry, dict) else None
            for k, word in enumerate(words if isinstance(words, list) else []):
                form = normalize(str(word))
                other = owner.setdefault(form, str(name)) if form else str(name)
                if other != str(name):
                    out.append(Diagnostic(locate((key, name, "words", k)),
                                          f"{word!r} is said of {name!r} and of {other!r}: a word of one thing only"))
    return out


def normalize_robot(robot: dict) -> dict:
    """A robot as later steps see it: ``{start, skills, kind, tags}``; ``kind`` None and ``tags``
    [] when the file gives none, so that consumers never test for the keys."""
    return {"start": list(robot["start"]), "skills": dict(robot["skills"]),
            "kind": robot.get("kind"), "tags": list(robot.get("tags") or []), **_words(robot)}


def _words(entry: dict) -> dict:
    """``{"words": [...]}`` where the file says what people call the thing (the offline reader's
    vocabulary), else nothing: a world without them is the same dict as before they existed."""
    return {"words": [str(w) for w in entry["words"]]} if entry.get("words") else {}


def normalize_world(data: dict, path: Path) -> dict:
    """The world dict of docs/architecture.md: every shelf in ``stock``, zero counts omitted."""
    shelves = {
        name: {"x": s["x"], "y": s["y"], "width": s["width"], "depth": s["depth"],
               "capacity": s["capacity"], "access": list(s["access"]), **_words(s)}
        for name, s in data["shelves"].items()
    }
    stock = {name: {} for name in shelves}
    for sname, items in (data.get("stock") or {}).items():
        for pname, units in (items or {}).items():
            if units:
                stock[sname][pname] = units
    return {
        "name": data.get("name") or path.stem,
        "path": str(path),
        "floor": {"width": data["floor"]["width"], "height": data["floor"]["height"]},
        "shelves": shelves,
        "products": {name: dict(p or {}) for name, p in data["products"].items()},
        "stock": stock,
        "robots": {name: normalize_robot(r) for name, r in (data.get("robots") or {}).items()},
    }


def world_from_text(text: str, file: str) -> dict:
    """Validate and normalize world YAML ``text`` (``file`` names it in messages)."""
    data = checked_yaml(text, file, "world", "world.schema.json", semantic_diagnostics, limits=SIZE_LIMITS)
    return normalize_world(data, Path(file))


def load_world(path: str | Path) -> dict:
    """Load a world file; raise :class:`WorldError` listing every problem with its location."""
    p, text = read_world_file(path)
    return world_from_text(text, str(p))


# ---------------------------------------------------------------------------------------------
# task files
# ---------------------------------------------------------------------------------------------
def task_diagnostics(data: dict, world: dict, locate: Locate) -> list[Diagnostic]:
    """Names in goals and constraints that the world does not have; duplicate task ids; goal
    bounds whose at_least exceeds their at_most; gold goals of feasible tasks that no final state
    of the world meets."""
    out: list[Diagnostic] = []
    shelves, products, robots = world["shelves"], world["products"], world["robots"]
    seen: dict[str, int] = {}
    for i, task in enumerate(data.get("tasks") or []):
        if not isinstance(task, dict):
            continue
        tid = task.get("id")
        if isinstance(tid, str):
            if tid in seen:
                out.append(Diagnostic(locate(("tasks", i, "id")), f"duplicate task id {tid!r} (first at task {seen[tid] + 1})"))
            seen.setdefault(tid, i)
        goal = task.get("goal") if isinstance(task.get("goal"), dict) else {}
        for sname, items in goal.items():
            if sname not in shelves:
                out.append(Diagnostic(locate(("tasks", i, "goal", sname), key=True),
                                      f"task {tid}: goal names unknown shelf {sname!r}{did_you_mean(sname, shelves)}"))
            for pname in (items or {}) if isinstance(items, dict) else ():
                if pname not in products:
                    out.append(Diagnostic(locate(("tasks", i, "goal", sname, pname), key=True),
                                          f"task {tid}: goal names unknown product {pname!r}{did_you_mean(pname, products)}"))
                for why in value_problems(items[pname]):
                    out.append(Diagnostic(locate(("tasks", i, "goal", sname, pname)),
                                          f"task {tid}: goal for {pname!r} on {sname!r}: {why}"))
        out += _gold_feasibility(task, tid, goal, world, locate(("tasks", i, "goal")))
        for j, rule in enumerate(task.get("constraints") or []):
            if not isinstance(rule, dict):
                continue
            for key in ("only", "never"):
                for k, r in enumerate(rule.get(key) or []):
                    if r not in robots:
                        out.append(Diagnostic(locate(("tasks", i, "constraints", j, key, k)),
                                              f"task {tid}: constraint names unknown robot {r!r}{did_you_mean(r, robots)}"))
            for key, names in (("product", products), ("from", shelves), ("to", shelves)):
                if key in rule and rule[key] not in names:
                    kind = "product" if key == "product" else "shelf"
                    out.append(Diagnostic(locate(("tasks", i, "constraints", j, key)),
                                          f"task {tid}: constraint {key!r} names unknown {kind} "
                                          f"{rule[key]!r}{did_you_mean(rule[key], names)}"))
    return out


def _gold_feasibility(task: dict, tid: Any, goal: dict, world: dict, where: Location) -> list[Diagnostic]:
    """A task marked feasible must have a gold goal that some final state of the world meets
    (counts and lower bounds within capacity and within the units that exist, upper bounds leaving
    room for every unit): otherwise a correct refusal would be scored as a failure. Checked only
    once the goal's names and values are valid (their own diagnostics say what is wrong)."""
    # deferred: pulls networkx (~150 ms; only a task file's gold goals are checked with it)
    from pipflow.warehouse.feasibility import infeasibility_reasons

    if task.get("feasible", True) is False or task.get("expect") == "refuse":
        return []
    valid = all(isinstance(items, dict) and s in world["shelves"]
                and all(p in world["products"] and not value_problems(v) for p, v in items.items())
                for s, items in goal.items())
    if not valid:
        return []
    reasons = infeasibility_reasons(world, goal)
    if not reasons:
        return []
    return [Diagnostic(where, f"task {tid}: no final state of the world meets the gold goal "
                              f"({'; '.join(reasons)}); fix the goal or mark the task `feasible: false`")]


def _goal_copy(goal: dict) -> dict:
    """A task's goal with every value copied (bound mappings are mutable)."""
    return {s: {p: dict(v) if is_bound(v) else v for p, v in (items or {}).items()} for s, items in goal.items()}


def load_tasks(path: str | Path) -> dict:
    """Load a task file and its world.

    Returns ``{"path", "world_path", "world": <world dict>, "tasks": [{"id", "command", "goal",
    "constraints", "feasible", "expect", "construction"}]}`` (goal values: counts or bounds,
    :mod:`pipflow.goalcounts`; ``expect`` and ``construction`` None when absent); raises
    :class:`TaskFileError` with every problem located (a bad world file reports its own locations)."""
    p, text = read_world_file(path)
    file = str(p)
    data, locate = parse_mapping(text, file, "task")
    diags = duplicate_diagnostics(locate) + schema_diagnostics(data, load_schema("tasks.schema.json"), locate)
    if diags:
        raise TaskFileError(diags, f"invalid task file {file} ({len(diags)} problem(s))")
    world_path = (p.parent / data["world"]).resolve()
    if not world_path.exists():
        raise TaskFileError([Diagnostic(locate(("world",)), f"world file {data['world']!r} not found (looked at {world_path})")],
                         f"invalid task file {file}")
    world = load_world(world_path)
    diags = task_diagnostics(data, world, locate)
    if diags:
        raise TaskFileError(diags, f"invalid task file {file} ({len(diags)} problem(s))")
    tasks = [{"id": t["id"], "command": t["command"], "goal": _goal_copy(t["goal"]),
              "constraints": [dict(c) for c in t.get("constraints") or []],
              "feasible": t.get("feasible", True), "expect": t.get("expect"),
              "construction": t.get("construction")} for t in data["tasks"]]
    return {"path": file, "world_path": str(world_path), "world": world, "tasks": tasks}


# ---------------------------------------------------------------------------------------------
# facts
# ---------------------------------------------------------------------------------------------
def feedback_facts(messages: list[str], world: dict) -> Facts:
    """What the refinement loop tells a model about the shelves and products the round's
    messages name, when its next prompt would repeat the last one: the (shelf, product) pairs one
    message names together (answer lines naming both are marked), each named shelf's counts and
    capacity, and each named product's units in all and where."""
    shelves, products = list(world.get("shelves") or {}), list(world.get("products") or {})
    together: set[tuple[str, str]] = set()
    for m in messages:
        words = set(re.findall(r"[\w-]+", m.lower()))
        together |= {(s, p) for s in shelves for p in products if s.lower() in words and p.lower() in words}
    stock = world.get("stock") or {}
    named = [s for s in shelves if any(re.search(rf"\b{re.escape(s)}\b", m) for m in messages)]
    lines = []
    for s in named:
        held = ", ".join(f"{n} {p}" for p, n in (stock.get(s) or {}).items() if n) or "nothing"
        load = sum((stock.get(s) or {}).values())
        lines.append(f"- {s} holds {held} now ({load} units; capacity {world['shelves'][s].get('capacity')})")
    for p in products:
        if not any(re.search(rf"\b{re.escape(p)}\b", m) for m in messages):
            continue
        where = {s: (items or {}).get(p, 0) for s, items in stock.items() if (items or {}).get(p)}
        total = sum(where.values())
        lines.append(f"- there are {total} {p} in all" + (f" ({', '.join(f'{s} {n}' for s, n in where.items())})" if where else ""))
    return Facts(sorted(together), lines)

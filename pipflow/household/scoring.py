"""Household scoring's facts: final-state conditions, RU's reference, task files and the bench
table. The score itself is the protocol's, the same for every domain
(:func:`pipflow.scoring.score_run`).

A run succeeds when, judged on the simulation's final state (never on what the plan claims),
every ground-truth condition holds (objects in receptacles, object states, category counts),
no subtask was refused, and no robot's legs jump. Metrics as in the paper's AI2-THOR table:

* GCR: fraction of ground-truth conditions that hold at the end, conditions true from the start
  counting only once the run achieved one it had to change (:func:`pipflow.metrics.goal_condition_recall`);
* Exe: executed / planned subtasks;
* RU: ``min(1, reference / planned)``, the reference being the length of an optimal team-level
  plan of the task's goal (:mod:`pipflow.household.reference`; a relaxed count where no plan was
  proved optimal, :func:`relaxed_actions`), so an optimal plan scores 1;
* TC-max / TC-avg / TC-avg over the team: :func:`pipflow.metrics.travel_costs` of the simulated
  travel (the bench averages them over successful runs that executed, not over right refusals).

What ``pipflow bench`` uses for task files with ``domain: household``, through the domain object
(:class:`pipflow.household.domain.HouseholdDomain`): :func:`load_tasks`, :func:`condition_values`,
:func:`reference_actions`, :func:`bench_table`.
"""
from __future__ import annotations

from pathlib import Path
from typing import Any

from pipflow.errors import Diagnostic, TaskFileError
from pipflow.household.problem import CONDITIONS
from pipflow.household.reference import optimal_length
from pipflow.household.world import initial_state, load_world, members, team_members
from pipflow.meaning import misread_cell
from pipflow.metrics import goal_condition_recall
from pipflow.suggest import did_you_mean
from pipflow.worldfile import parse_mapping, read_world_file

CATEGORIES = ("compound", "complex", "vague")


# ------------------------------------------------------------------------------------------
# conditions
# ------------------------------------------------------------------------------------------
def holds(state: dict, name: str, cond: str) -> bool:
    """One state condition in a state dict (``{"at": .., "open": [..], "on": [..], ...}``)."""
    pred, positive, _ = CONDITIONS[cond]
    key = {"is-open": "open", "is-on": "on", "dirty": "dirty", "sliced": "sliced", "hot": "hot"}[pred]
    return (name in set(state.get(key) or [])) == positive


def condition_values(world: dict, state: dict, goal: dict) -> list[tuple[bool, str]]:
    """Each goal condition in ``state``, in the goal's order: ``(holds, description)``, the
    description saying what is there instead when it does not hold."""
    out = []
    at = state.get("at") or {}
    for place, items in (goal.get("in") or {}).items():
        for o in items:
            out.append((at.get(o) == place, f"{o} in {place} (it is in {at.get(o)})"))
    for name, conds in (goal.get("state") or {}).items():
        for c in conds:
            out.append((holds(state, name, c), f"{name} {c}"))
    for c in goal.get("count") or []:
        n = sum(1 for o in members(world, c["category"]) if at.get(o) == c["in"])
        out.append((n >= int(c["at_least"]), f"{c['at_least']} {c['category']} in {c['in']} (there are {n})"))
    return out


def check_conditions(world: dict, state: dict, goal: dict) -> tuple[int, int, list[str]]:
    """``(met, total, unmet descriptions)`` of the goal conditions in ``state``."""
    values = condition_values(world, state, goal)
    return sum(ok for ok, _ in values), len(values), [why for ok, why in values if not ok]


def recall(world: dict, state: dict, goal: dict) -> float:
    """GCR of ``state`` (:func:`pipflow.metrics.goal_condition_recall`), the conditions at the
    world's initial state for the start."""
    return goal_condition_recall([ok for ok, _ in condition_values(world, initial(world), goal)],
                                 [ok for ok, _ in condition_values(world, state, goal)])


def initial(world: dict) -> dict:
    """The world's state before anything moved, in the form of the simulation's final state."""
    s = initial_state(world)
    return {"at": s["at"], **{k: sorted(v) for k, v in s.items() if k != "at"}}


def reference_actions(world: dict, goal: dict) -> tuple[int, str]:
    """``(actions, how)``: RU's reference for ``goal``, the length of an optimal team-level plan
    (:mod:`pipflow.household.reference`), or, when none was proved optimal, the relaxed count of
    :func:`relaxed_actions` (which no plan beats; ``how`` says which and why)."""
    n, how = optimal_length(world, goal)
    if n is not None:
        return n, how
    return relaxed_actions(world, goal), f"a relaxed count of the actions any plan needs ({how})"


def relaxed_actions(world: dict, goal: dict) -> int:
    """A count of actions that no plan beats: one per condition that does not already hold, one
    more per count shortfall unit, an open (and a close when the goal wants it closed) per
    closed container that must be entered, a carry to a sink or heater for a wash or heat of an
    object that is elsewhere. It leaves out what a plan does around these (opening the container
    an object is taken from, carrying it back), so it is only RU's fallback reference."""
    s = initial(world)
    props = {n: e["properties"] for n, e in {**world["places"], **world["objects"]}.items()}
    n, entered = 0, set()
    for place, items in (goal.get("in") or {}).items():
        for o in items:
            if s["at"].get(o) != place:
                n += 1
                entered |= {place, s["at"].get(o)}
    for c in goal.get("count") or []:
        have = sum(1 for o in members(world, c["category"]) if s["at"].get(o) == c["in"])
        if have < int(c["at_least"]):
            n += int(c["at_least"]) - have
            entered.add(c["in"])
    for name, conds in (goal.get("state") or {}).items():
        for c in conds:
            if holds(s, name, c):
                continue
            n += 1
            where = s["at"].get(name)
            if c == "clean" and where is not None and "sink" not in props.get(where, []):
                n += 1
            if c == "hot" and where is not None and "heater" not in props.get(where, []):
                n += 1
    for p in entered:
        if p in world["places"] and "openable" in props[p] and p not in s["open"]:
            n += 1 + (1 if "closed" in (goal.get("state") or {}).get(p, []) else 0)
    return n


# ------------------------------------------------------------------------------------------
# task files and bench hooks
# ------------------------------------------------------------------------------------------
def load_tasks(path: str | Path) -> dict:
    """Load a household task file and its world; :class:`TaskFileError` lists every problem located.

    Returns ``{"path", "world_path", "world", "domain": "household", "workflow", "tasks": [{"id",
    "command", "category", "team", "goal", "feasible", "construction"?, "expect"?, "domain", "inputs": {"team": ...}}]}``;
    a task marked ``feasible: false`` (its right answer is a refusal) needs no goal."""
    p, text = read_world_file(path)
    data, locate = parse_mapping(text, str(p), "household task")
    diags: list[Diagnostic] = []
    world_path = (p.parent / str(data.get("world", ""))).resolve()
    if not data.get("world") or not world_path.is_file():
        raise TaskFileError([Diagnostic(locate(("world",)), f"world file {data.get('world')!r} not found (looked at {world_path})")],
                         f"invalid task file {p}")
    world = load_world(world_path)
    names = {**world["places"], **world["objects"]}
    tasks, seen = [], set()
    for i, t in enumerate(data.get("tasks") or []):
        if not isinstance(t, dict):
            diags.append(Diagnostic(locate(("tasks", i)), "a task must be a mapping"))
            continue
        tid = str(t.get("id"))
        for key in ("id", "command", "category") + (("goal",) if t.get("feasible", True) is not False else ()):
            if key not in t:
                diags.append(Diagnostic(locate(("tasks", i)), f"task {tid}: missing {key!r}"))
        if tid in seen:
            diags.append(Diagnostic(locate(("tasks", i, "id")), f"duplicate task id {tid!r}"))
        seen.add(tid)
        if t.get("category") not in CATEGORIES:
            diags.append(Diagnostic(locate(("tasks", i, "category")), f"task {tid}: category must be one of {', '.join(CATEGORIES)}"))
        try:
            team_members(world, t.get("team"))
        except Exception as exc:
            diags.append(Diagnostic(locate(("tasks", i, "team")), f"task {tid}: {exc}"))
        goal = t.get("goal") if isinstance(t.get("goal"), dict) else {}
        for name, conds in list((goal.get("state") or {}).items()):
            # YAML 1.1 reads the words on/off as booleans: [off] arrives as [False]
            goal["state"][name] = [{True: "on", False: "off"}.get(c, c) if isinstance(c, bool) else c for c in conds or []]
        for place, items in (goal.get("in") or {}).items():
            if place not in world["places"]:
                diags.append(Diagnostic(locate(("tasks", i, "goal", "in", place), key=True),
                                        f"task {tid}: unknown place {place!r}{did_you_mean(place, world['places'])}"))
            for k, o in enumerate(items or []):
                if o not in world["objects"]:
                    diags.append(Diagnostic(locate(("tasks", i, "goal", "in", place, k)),
                                            f"task {tid}: unknown object {o!r}{did_you_mean(o, world['objects'])}"))
        for name, conds in (goal.get("state") or {}).items():
            if name not in names:
                diags.append(Diagnostic(locate(("tasks", i, "goal", "state", name), key=True),
                                        f"task {tid}: unknown object or place {name!r}{did_you_mean(name, names)}"))
                continue
            for k, c in enumerate(conds or []):
                if c not in CONDITIONS:
                    diags.append(Diagnostic(locate(("tasks", i, "goal", "state", name, k)),
                                            f"task {tid}: unknown condition {c!r}; conditions: {', '.join(CONDITIONS)}"))
                elif CONDITIONS[c][2] not in names[name]["properties"]:
                    diags.append(Diagnostic(locate(("tasks", i, "goal", "state", name, k)),
                                            f"task {tid}: {name} cannot be {c} (it is not {CONDITIONS[c][2]})"))
        for k, c in enumerate(goal.get("count") or []):
            if c.get("category") not in world["categories"] or c.get("in") not in world["places"]:
                diags.append(Diagnostic(locate(("tasks", i, "goal", "count", k)),
                                        f"task {tid}: count needs a known category and place, got {c}"))
        team = t.get("team")
        tasks.append({"id": tid, "command": t.get("command"), "category": t.get("category"), "team": team,
                      "goal": {"in": dict(goal.get("in") or {}), "state": dict(goal.get("state") or {}),
                               **({"count": list(goal["count"])} if goal.get("count") else {})},
                      "feasible": t.get("feasible", True), "domain": "household",
                      **({"construction": str(t["construction"])} if t.get("construction") else {}),
                      **({"expect": str(t["expect"])} if t.get("expect") else {}),
                      "inputs": {"team": ",".join(team) if isinstance(team, list) else team}})
    if diags:
        raise TaskFileError(diags, f"invalid household task file {p} ({len(diags)} problem(s))")
    return {"path": str(p), "world_path": str(world_path), "world": world, "domain": "household",
            "workflow": data.get("workflow", "household"), "tasks": tasks}


def _fmt(v: Any) -> str:
    return "--" if v is None else f"{v:.1f}"


def bench_table(results: dict, tasks_file: str | Path) -> str:
    """The paper-shaped table (per category SR, TC-max/TC-avg, GCR, RU, Exe) for household
    bench results; a category's TC is the mean over its tasks that had a successful run that
    executed (a right refusal is no 0 m run)."""
    category = {t["id"]: t["category"] for t in load_tasks(tasks_file)["tasks"]}
    lines = []
    for variant in results["variants"]:
        if len(results["variants"]) > 1:
            lines.append(f"### {variant['name']}\n")
        lines += ["| Category | tasks | runs | SR (%) | understood (%) | misread (executed) | TC max/avg (m) | GCR | RU | Exe |",
                  "|---|---|---|---|---|---|---|---|---|---|"]
        groups = [(c, [t for t in variant["tasks"] if category.get(t["id"]) == c]) for c in CATEGORIES]
        groups.append(("**all**", list(variant["tasks"])))
        for name, rows in groups:
            if not rows:
                continue
            runs = sum(r["runs"] for r in rows)

            def w(key: str) -> float:
                return sum(r[key] * r["runs"] for r in rows) / runs if runs else 0.0

            ok = [r for r in rows if r.get("tc_max") is not None]
            tmax = sum(r["tc_max"] for r in ok) / len(ok) if ok else None
            tavg = sum(r["tc_avg"] for r in ok) / len(ok) if ok else None
            measured = [r for r in rows if r.get("understood") is not None]
            understood = (sum(r["understood"] * r["runs"] for r in measured) / sum(r["runs"] for r in measured)
                          if measured else None)
            misread = {k: sum(int(r.get(k) or 0) for r in rows) for k in ("misread", "misread_executed")}
            lines.append(f"| {name} | {len(rows)} | {runs} | {100 * w('sr'):.0f} | "
                         f"{'--' if understood is None else f'{100 * understood:.0f}'} | {misread_cell(misread)} | "
                         f"{_fmt(tmax)}/{_fmt(tavg)} | {w('gcr'):.2f} | {w('ru'):.2f} | {w('exe'):.2f} |")
        if variant.get("constructions"):
            lines += ["", "| Construction | runs | understood (%) | misread (executed) |", "|---|---|---|---|"]
            for name, c in sorted(variant["constructions"].items()):
                und = "--" if c.get("understood") is None else f"{100 * c['understood']:.0f}"
                lines.append(f"| {name} | {c['runs']} | {und} | {misread_cell(c)} |")
        lines += ["", "| Task | category | SR (%) | TC max/avg (m) | GCR | RU | Exe | error |", "|---|---|---|---|---|---|---|---|"]
        for t in variant["tasks"]:
            err = (t.get("error") or "").replace("|", "/").replace("\n", " ")[:90]
            lines.append(f"| {t['id']} | {category.get(t['id'])} | {100 * t['sr']:.0f} | {_fmt(t['tc_max'])}/{_fmt(t['tc_avg'])} | "
                         f"{t['gcr']:.2f} | {t['ru']:.2f} | {t['exe']:.2f} | {err} |")
        lines.append("")
    lines.append(f"wall time: {results['wall_seconds']:.1f} s")
    return "\n".join(lines)

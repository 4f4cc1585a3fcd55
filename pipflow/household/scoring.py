"""Household scoring: final-state conditions, one run's score, and the bench hooks.

A run succeeds when, judged on the simulation's final state (never on what the plan claims),
every ground-truth condition holds (objects in receptacles, object states, category counts),
no subtask was refused, and no robot's legs jump. Metrics as in the paper's AI2-THOR table:

* GCR: fraction of ground-truth conditions that hold at the end;
* Exe: executed / planned subtasks;
* RU: ``min(1, reference / planned)``, the reference being a relaxed count of the actions any
  plan needs (one per condition that does not already hold, one more per count shortfall unit,
  an open (and a close when the goal wants it closed) per closed container that must be
  entered, a carry to a sink or heater for a wash or heat of an object that is elsewhere);
* TC-max / TC-avg: the most and the mean metres a team robot travels, over successful runs.

What ``pipflow bench`` uses for task files with ``domain: household``, through the domain object
(:class:`pipflow.household.domain.HouseholdDomain`): :func:`load_tasks`, :func:`score_bench_run`,
:func:`understanding`, :func:`bench_table`.
"""
from __future__ import annotations

from pathlib import Path
from typing import Any

from pipflow.errors import Diagnostic, TaskFileError
from pipflow.household.problem import CONDITIONS
from pipflow.household.world import initial_state, load_world, members, select_team, team_members
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


def check_conditions(world: dict, state: dict, goal: dict) -> tuple[int, int, list[str]]:
    """``(met, total, unmet descriptions)`` of the goal conditions in ``state``."""
    met, total, unmet = 0, 0, []
    at = state.get("at") or {}
    for place, items in (goal.get("in") or {}).items():
        for o in items:
            total += 1
            if at.get(o) == place:
                met += 1
            else:
                unmet.append(f"{o} in {place} (it is in {at.get(o)})")
    for name, conds in (goal.get("state") or {}).items():
        for c in conds:
            total += 1
            if holds(state, name, c):
                met += 1
            else:
                unmet.append(f"{name} {c}")
    for c in goal.get("count") or []:
        total += 1
        n = sum(1 for o in members(world, c["category"]) if at.get(o) == c["in"])
        if n >= int(c["at_least"]):
            met += 1
        else:
            unmet.append(f"{c['at_least']} {c['category']} in {c['in']} (there are {n})")
    return met, total, unmet


def _initial(world: dict) -> dict:
    s = initial_state(world)
    return {"at": s["at"], **{k: sorted(v) for k, v in s.items() if k != "at"}}


def reference_actions(world: dict, goal: dict) -> int:
    """The relaxed count of actions any plan needs (module docstring)."""
    s = _initial(world)
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


def _mean_moved(sim: dict) -> float:
    """TC-avg over the robots that moved (the paper's meaning), from the simulation's travel: the
    same key as the warehouse's score, so the bench reads one shape in every domain."""
    moved = [float(v) for v in (sim.get("travel") or {}).values() if float(v) > 1e-9]
    return round(sum(moved) / len(moved), 4) if moved else 0.0


def score_run(world: dict, goal: dict, *, feasible: bool = True, graph: dict | None = None,
              schedule: dict | None = None, simulation: dict | None = None, refusal: str | None = None,
              error: str | None = None) -> dict:
    """Score one household run (``world``: the team's world). Keys as the outputs of step ``metrics.score``.

    A task marked ``feasible: false`` succeeds exactly when the run was refused with a reason and
    nothing was planned or executed (a refusal is the right answer: robots must not move)."""
    sim = simulation or {}
    planned = len((schedule or {}).get("subtasks", []))
    executed = int(sim.get("executed", 0))
    if not feasible:
        ok = bool(refusal and str(refusal).strip()) and executed == 0 and planned == 0
        violations = [] if ok else (["infeasible command was not refused"] if not refusal else
                                    ["refusal has no reason"] if not str(refusal).strip() else ["actions were executed"])
        return {"planned": planned, "executed": executed, "refused": bool(refusal), "error": refusal or error or None,
                "makespan": float(sim.get("makespan", 0.0) or 0.0), "lower_bound": None, "success": ok,
                "goal_met": ok, "gcr": 1.0 if ok else 0.0, "exe": 1.0 if ok else float(sim.get("exe", 0.0) or 0.0),
                "ru": 1.0 if ok else 0.0, "tc_max": float(sim.get("tc_max", 0.0)), "tc_avg": float(sim.get("tc_avg", 0.0)),
                "tc_avg_moved": _mean_moved(sim), "violations": violations}
    base = {"planned": planned, "executed": executed, "refused": bool(refusal),
            "error": refusal or error or None, "makespan": float(sim.get("makespan", 0.0) or 0.0),
            "lower_bound": reference_actions(world, goal)}
    if simulation is None:
        met, total, _ = check_conditions(world, _initial(world), goal)
        why = "refused a feasible command" if refusal else f"run failed: {error}" if error else "no simulation"
        return {**base, "success": False, "goal_met": False, "gcr": met / total if total else 1.0, "exe": 0.0,
                "ru": 0.0, "tc_max": 0.0, "tc_avg": 0.0, "tc_avg_moved": 0.0, "violations": [why]}
    met, total, unmet = check_conditions(world, sim.get("final_state") or {}, goal)
    violations = [f"goal: {u}" for u in unmet]
    violations += [f"{f['subtask']} {f['action']} refused: {'; '.join(f['reasons'])}" for f in sim.get("failures") or []]
    violations += [f"{r} jumps {j['metres']:g} m" for r, js in (sim.get("jumps") or {}).items() for j in js]
    ru = min(1.0, base["lower_bound"] / planned) if planned else (1.0 if base["lower_bound"] == 0 else 0.0)
    return {**base, "success": not violations, "goal_met": met == total, "gcr": met / total if total else 1.0,
            "exe": float(sim.get("exe", 0.0)), "ru": ru, "tc_max": float(sim.get("tc_max", 0.0)),
            "tc_avg": float(sim.get("tc_avg", 0.0)), "tc_avg_moved": _mean_moved(sim), "violations": violations}


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


def score_bench_run(world_path: str, task: dict, outputs: dict, refusal: str | None, error: str | None) -> dict:
    """Score one bench run of a household task (the team's world, the task's ground truth)."""
    world = select_team(load_world(world_path), task.get("team"))
    feasible = task.get("feasible", True) is not False and task.get("expect") != "refuse"  # refusing is right
    return score_run(world, task.get("goal") or {}, feasible=feasible,
                     graph=outputs.get("graph"), schedule=outputs.get("schedule"),
                     simulation=outputs.get("simulation"), refusal=refusal, error=error)


def _canonical_goal(goal: Any) -> str | None:
    """A household goal as sorted JSON (lists are sets; empty entries dropped), None if malformed."""
    import json

    if not isinstance(goal, dict):
        return None
    out = {"in": {p: sorted(v) for p, v in (goal.get("in") or {}).items() if v},
           "state": {n: sorted(v) for n, v in (goal.get("state") or {}).items() if v},
           "count": sorted(json.dumps(c, sort_keys=True) for c in goal.get("count") or [])}
    return json.dumps(out, sort_keys=True)


def understanding(task: dict, outputs: dict, status: str, error_kind: str | None) -> dict:
    """Whether a bench run read the household command as its gold (issue 12, item 9): a task whose
    right answer is a refusal is understood when the run was refused; any other when the run's
    goal (as the command states it, counts kept) equals the gold. ``misread``: the run executed
    with another goal (robots moved wrongly)."""
    refused = status == "refused" or error_kind in ("Refusal", "TranslationError")
    executed = status == "succeeded"
    if task.get("feasible") is False or task.get("expect") == "refuse":
        return {"understood": refused, "misread": executed,
                "understanding": "refused, as it should be" if refused else
                ("executed a command whose right answer is a refusal" if executed else "not refused")}
    run = _canonical_goal(outputs.get("goal"))
    if run is None:
        return {"understood": False, "misread": False,
                "understanding": "refused" if refused else "no goal among the run's outputs (it did not finish)"}
    same = run == _canonical_goal(task.get("goal") or {})
    return {"understood": same, "misread": not same and executed,
            "understanding": "goal as the gold" if same else f"goal {run}, gold {_canonical_goal(task.get('goal'))}"}


def _fmt(v: Any) -> str:
    return "--" if v is None else f"{v:.1f}"


def bench_table(results: dict, tasks_file: str | Path) -> str:
    """The paper-shaped table (per category SR, TC-max/TC-avg, GCR, RU, Exe) for household
    bench results."""
    category = {t["id"]: t["category"] for t in load_tasks(tasks_file)["tasks"]}
    lines = []
    for variant in results["variants"]:
        if len(results["variants"]) > 1:
            lines.append(f"### {variant['name']}\n")
        lines += ["| Category | tasks | runs | SR | understood | misread | TC max/avg (m) | GCR | RU | Exe |",
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
            misread = sum(int(r.get("misread") or 0) for r in rows)
            lines.append(f"| {name} | {len(rows)} | {runs} | {w('sr'):.2f} | "
                         f"{'--' if understood is None else f'{understood:.2f}'} | {misread} | {_fmt(tmax)}/{_fmt(tavg)} | "
                         f"{w('gcr'):.2f} | {w('ru'):.2f} | {w('exe'):.2f} |")
        if variant.get("constructions"):
            lines += ["", "| Construction | runs | understood | misread |", "|---|---|---|---|"]
            for name, c in sorted(variant["constructions"].items()):
                und = "--" if c.get("understood") is None else f"{c['understood']:.2f}"
                lines.append(f"| {name} | {c['runs']} | {und} | {c['misread']} |")
        lines += ["", "| Task | category | SR | TC max/avg (m) | GCR | RU | Exe | error |", "|---|---|---|---|---|---|---|---|"]
        for t in variant["tasks"]:
            err = (t.get("error") or "").replace("|", "/").replace("\n", " ")[:90]
            lines.append(f"| {t['id']} | {category.get(t['id'])} | {t['sr']:.2f} | {_fmt(t['tc_max'])}/{_fmt(t['tc_avg'])} | "
                         f"{t['gcr']:.2f} | {t['ru']:.2f} | {t['exe']:.2f} | {err} |")
        lines.append("")
    lines.append(f"wall time: {results['wall_seconds']:.1f} s")
    return "\n".join(lines)

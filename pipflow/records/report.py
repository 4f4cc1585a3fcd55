"""Static HTML report for a run directory or a bench directory (``pipflow report DIR``).

Why static files with relative ``<img>`` links: a run record must stay inspectable anywhere
(copied, zipped, attached to an issue) without a server, and the pictures the simulation already
wrote are linked in place rather than copied. Pictures the report draws itself (dependency
graph, Gantt chart, bench plots) go to ``DIR/report/``; the page is ``DIR/report.html``. With
``-o PAGE`` elsewhere, nothing is written into the record (it may be read-only): the pictures go
to ``PAGE_files/`` beside the page. Every write goes through :mod:`pipflow.engine.writes`: inside
the record no link is followed (a ``report.html`` or ``report/`` that is a link is refused), and a
full or read-only disk is a user error naming it.

A small inline script marks ``<body data-images-ok="true">`` once every image has loaded with a
non-zero size, so a headless browser can check the page really renders its pictures.

Run directory (engine/store.py): ``run.json``, ``inputs.json``, ``outputs.json``,
``events.jsonl``, ``steps/<id>/outputs.json`` and ``steps/<id>/artifacts/*``. Steps are found by
the family of outputs they declare (the ``shape`` of :mod:`pipflow.values` their start event
records: world, plan, graph, schedule, simulation, score...), never by id nor by the keys of what
they returned, so any workflow's record of any task domain is reported with the same sections;
a record made before shapes were recorded is read through the registry's declaration of the
step it used. Where the report reads a domain's values (the floor plan, the goal's conditions
in the final state) it asks the world's task domain.

The page of a bench directory is :mod:`pipflow.records.benchpage`; the sections of a run under
faults are :mod:`pipflow.records.faultview`, those of the refinement loop
:mod:`pipflow.records.loopview`.
"""
from __future__ import annotations

import html
import os
import re
from pathlib import Path
from typing import Any

from pipflow import pictures, values
from pipflow.engine.runner import install_report_writer
from pipflow.engine.status import RunStatus
from pipflow.engine.store import shown_status
from pipflow.engine.writes import make_dirs, write_file
from pipflow.errors import InputError, PipflowError, UserError
from pipflow.metrics import upgrade_travel_keys
from pipflow.records.benchpage import bench_body
from pipflow.records.benchread import Bench, read_bench
from pipflow.records.faultview import (executed_plan_section, executed_step, faults_section, incidents,
                                       not_applicable_section)
from pipflow.records.htmlparts import CHECK_SCRIPT, PIC, STYLE, Pictures, Raw, esc, img, read_json, table
from pipflow.records.loopview import failure_cause, loop_rounds, loop_section, understood_section
from pipflow.records.replay import replay_section
from pipflow.records.runrecord import find_step, step_outputs, step_shapes
from pipflow.taskdomains import task_domain
from pipflow.team.trajectory import planned_paths


def write_report(directory: str | Path, output: str | Path | None = None) -> Path:
    """Write ``report.html`` (or ``output``: a file, or a folder to write ``report.html`` in) for a
    run or bench directory and return its path. Links stay relative: to the directory, or rebased
    when the page lies elsewhere; a page written elsewhere writes nothing into the record."""
    d = Path(directory)
    is_bench = (d / "results.json").is_file()
    if not is_bench and not ((d / "steps").is_dir() or (d / "run.json").is_file()):
        raise InputError(f"{d}: neither a run directory (steps/, run.json) nor a bench directory (results.json)")
    out, root = _page_path(d, output)
    pics = Pictures(root / "report" if root is not None and out.parent == root else out.parent / f"{out.stem}_files",
                     root)
    if is_bench:
        bench = read_bench(d)
        if root is not None:  # a page elsewhere writes nothing into the record
            _write_run_reports(bench)  # so that every seed link opens a report
        body = bench_body(bench, d, pics)
        title = f"pipflow bench: {d.name}"
    else:
        body = _run_body(d, pics)
        title = f"pipflow run: {d.name}"
    page = (f"<!DOCTYPE html>\n<html lang='en'><head><meta charset='utf-8'><title>{esc(title)}</title>"
            f"{STYLE}</head>\n<body>\n<h1>{esc(title)}</h1>\n{body}\n{CHECK_SCRIPT}\n</body></html>\n")
    record = root if root is not None else d.resolve()
    if out.parent != record:
        base = os.path.relpath(record, out.parent)

        def rebase(m: "re.Match") -> str:
            url = m.group(2)
            if re.match(r"^([a-z]+:|/|#)", url):
                return m.group(0)
            return f"{m.group(1)}='{esc(Path(base, html.unescape(url)).as_posix())}'"

        page = re.sub(r"(src|href)='([^']*)'", rebase, page)
    page = page.replace(PIC, esc(Path(os.path.relpath(pics.folder, out.parent)).as_posix() + "/"))
    write_file(out, page.encode("utf-8"), root=root)
    return out


def _page_path(d: Path, output: str | Path | None) -> tuple[Path, Path | None]:
    """Where the page goes, and the record's folder when the page goes inside the record (then no
    link is followed on the way: the record's own links are not the user's). A page elsewhere
    is where the user named it (their links are theirs to follow)."""
    record = Path(os.path.abspath(d))
    if output is None:
        return record / "report.html", record
    out = Path(os.path.abspath(Path(output).expanduser()))
    if str(output).endswith(("/", os.sep)) or (out.is_dir() and not out.is_symlink()):
        out = out / "report.html"  # a folder: the page goes in it, under the usual name
    if out.parent == record or record in out.parent.parents:
        make_dirs(out.parent, root=record)
        return out, record
    make_dirs(out.parent)
    return Path(os.path.realpath(out.parent)) / out.name, None


def _run_body(d: Path, drawn: Pictures) -> str:
    info = read_json(d / "run.json", {}) or {}
    info = info if isinstance(info, dict) else {}
    inputs = read_json(d / "inputs.json", {}) or {}
    outputs = read_json(d / "outputs.json", {}) or {}
    steps = step_outputs(d)
    shapes = step_shapes(d)
    parts = []

    status = shown_status(d, info) if (d / "run.json").is_file() else "?"  # only a steps/ folder left
    succeeded = RunStatus.of(status) is RunStatus.SUCCEEDED
    cls = "ok" if succeeded else "bad"
    command = inputs.get("command")
    parts.append(table(["", ""], [["status", Raw(f"<span class='{cls}'>{esc(status)}</span>")],
                                   ["workflow", info.get("workflow", "")], ["error", info.get("error")]]))
    parts.append("<h2>Command</h2>" + (f"<p><q>{esc(command)}</q></p>" if command else "<p>(no command input)</p>"))
    rounds = loop_rounds(d, shapes)
    if not succeeded and rounds:
        parts.insert(1, failure_cause(info, rounds[-1]))
    parts.append(understood_section(steps, shapes))
    if rounds:
        parts.append(loop_section(rounds))

    world = (find_step(steps, shapes, values.WORLD) or (None, None, {}))[2].get("world")
    world = world if isinstance(world, dict) else None
    plan_s = find_step(steps, shapes, values.PLAN)
    graph_s = find_step(steps, shapes, values.GRAPH)
    sched_s = find_step(steps, shapes, values.SCHEDULE)
    sim_s = find_step(steps, shapes, values.SIMULATION)
    met_s = find_step(steps, shapes, values.SCORE)
    schedule = sched_s[2]["schedule"] if sched_s and isinstance(sched_s[2].get("schedule"), dict) else None
    graph_s = graph_s if graph_s and isinstance(graph_s[2].get("graph"), dict) else None
    planned = (graph_s, schedule)
    records = world  # the world as loaded (the records)
    executed = executed_step(steps, shapes)
    if executed is not None:  # under faults: what was carried out, in the world as it really was
        name, sd, out = executed
        world = out["world"] if isinstance(out.get("world"), dict) else world
        schedule = out["schedule"] if isinstance(out.get("schedule"), dict) else schedule
        graph_s = (name, sd, {"graph": out["graph"]}) if isinstance(out.get("graph"), dict) else graph_s

    plan = plan_s[2].get("plan") if plan_s else None
    if executed is None:
        parts.append(_plan_section(plan, graph_s, schedule))
    else:
        parts.append(executed_plan_section(executed[2], graph_s, schedule)
                     + "<details><summary>the plan as first made, before any fault</summary>"
                     + _plan_section(plan, *planned).replace("<h2 id='plan'>Team plan</h2>", "") + "</details>")

    mode = inputs.get("pictures") if inputs.get("pictures") in pictures.MODES else "auto"
    parts.append("<span id='pictures'></span>")  # where a bench's matrix links a run's pictures
    if graph_s and not pictures.wanted(mode, "graph", pictures.size_of("graph", graph_s[2]["graph"])):
        parts.append(f"<h2>Dependency graph</h2><p>not drawn (pictures: {esc(mode)}; "
                     f"{len(graph_s[2]['graph'].get('nodes', []))} subtasks)</p>")
    elif graph_s:
        try:
            pictures.dependency_graph(graph_s[2]["graph"], drawn.path("graph.png"))
            parts.append("<h2>Dependency graph</h2>" + img(drawn.src("graph.png"), "dependency graph"))
        except Exception as exc:  # a picture must never hide the rest of the report
            parts.append(f"<h2>Dependency graph</h2><p class='bad'>could not draw: {esc(exc)}</p>")
    parts.append(_schedule_section(schedule, executed[2] if executed is not None else None, mode, drawn))
    parts.append(_replay(d, steps, world, schedule, graph_s[2]["graph"] if graph_s else None,
                         incidents(world, executed[2]) if executed is not None else None))

    if sim_s:
        parts += _simulation_sections(sim_s, world, schedule, outputs.get("goal", inputs.get("goal")), mode, drawn)

    parts.append(faults_section(executed, world, drawn, records, sim_s)  # runs under faults only ("" otherwise)
                 + not_applicable_section(find_step(steps, shapes, values.EXECUTION)))

    parts.append(_metrics_section(met_s))

    parts.append("<h2>Steps</h2>" + table(["step", "outputs"], [[n, ", ".join(sorted(o))] for n, _, o in steps]))
    return "\n".join(parts)


def _metrics_section(met_s: tuple[str, Path, dict] | None) -> str:
    """The score step's metrics and the violations it found ("" for a skipped score step)."""
    if not met_s or not isinstance(met_s[2].get("violations"), list):  # a skipped score step: all null
        return ""
    m = upgrade_travel_keys(met_s[2])
    out = "<h2>Metrics</h2>" + table(
        ["success", "GCR", "Exe", "RU", "TC-max (m)", "TC-avg, robots that moved (m)", "TC-avg over the team (m)",
         "planned", "lower bound"],
        [[m.get("success"), m.get("gcr"), m.get("exe"), m.get("ru"), m.get("tc_max"), m.get("tc_avg"),
          m.get("tc_avg_team"), m.get("planned"), m.get("lower_bound")]])
    if m.get("violations"):
        out += "<ul>" + "".join(f"<li class='bad'>{esc(v)}</li>" for v in m["violations"]) + "</ul>"
    return out


def _schedule_section(schedule: dict | None, executed: dict | None, mode: str, drawn: Pictures) -> str:
    """The Gantt chart: of the schedule as carried out, with the faults and recoveries, under
    faults (``executed``: the execution step's outputs); of the schedule otherwise."""
    if not schedule:
        return ""
    if not pictures.wanted(mode, "gantt", pictures.size_of("gantt", schedule)):
        return (f"<h2>Schedule</h2><p>Gantt chart not drawn (pictures: {esc(mode)}; "
                f"{pictures.size_of('gantt', schedule)} working robots)</p>")
    if executed is None:
        pictures.gantt(schedule, drawn.path("gantt.png"))
        return "<h2>Schedule</h2>" + img(drawn.src("gantt.png"), "Gantt chart per robot")
    try:
        pictures.fault_gantt(schedule, executed["faults"], executed.get("recoveries") or [], drawn.path("faults-gantt.png"))
        return ("<h2>Schedule as carried out</h2>"
                + img(drawn.src("faults-gantt.png"), "the schedule carried out, with the faults and recoveries"))
    except Exception as exc:  # a picture must never hide the rest of the report
        return f"<h2>Schedule as carried out</h2><p class='bad'>could not draw: {esc(exc)}</p>"


def _plan_section(plan: Any, graph_s: tuple[str, Path, dict] | None, schedule: dict | None) -> str:
    """The team plan, with the robots the schedule gave each subtask (ids as the graph and the
    Gantt chart name them: s1, s2, ..., not list positions)."""
    if plan is None:
        return "<h2 id='plan'>Team plan</h2><p>(no plan in this run)</p>"
    nodes = graph_s[2]["graph"].get("nodes", []) if graph_s else []
    ids = {n.get("index"): n.get("id") for n in nodes if isinstance(n, dict)}
    by_id = {s.get("id"): s for s in (schedule or {}).get("subtasks", []) if isinstance(s, dict)}
    rows = []
    for i, a in enumerate(plan):
        text = " ".join(map(str, [a.get("action")] + list(a.get("args", []))))
        sid = ids.get(i, f"s{i + 1}")
        s = by_id.get(sid)
        rows.append([sid, f"({text})", ", ".join(s["robots"]) if s else "",
                     f"{s['start']:.1f}" if s else "", f"{s['end']:.1f}" if s else ""])
    return "<h2 id='plan'>Team plan</h2>" + (
        table(["subtask", "action", "robots", "start (s)", "end (s)"], rows) if rows else "<p>empty plan</p>")


def _replay(d: Path, steps, world: Any, schedule: Any, graph: Any, events: list[dict] | None = None) -> str:
    """The replay section (:mod:`pipflow.records.replay`): the recorded trajectories of whichever
    step kept them (``trajectories.json``), else the schedule's legs; the floor plan from the
    world's task domain; under faults, the faults and recoveries as they happen (``events``)."""
    if not isinstance(world, dict) or not isinstance(schedule, dict):
        return ""
    recorded = None
    for name, sd, _ in steps:
        data = read_json(sd / "artifacts" / "trajectories.json")
        if isinstance(data, dict) and isinstance(data.get("trajectories"), dict):
            recorded = data
    try:
        plan = list(task_domain(world).floor_plan(world))
    except UserError:  # the world's domain is no longer installed: the floor alone
        plan = []
    return replay_section(world, schedule, graph, recorded, plan, events)


def _simulation_sections(sim_s: tuple[str, Path, dict], world: dict | None, schedule: dict | None, goal: Any,
                         mode: str, drawn: Pictures) -> list[str]:
    """Robot paths, snapshots, animation and the Simulation table of any domain's simulation step
    (the family :data:`pipflow.values.SIMULATION`: the core, flat or with ``details``). The path
    map is the one the simulation drew, else drawn from the trajectories it kept, else from the
    schedule's legs (what a simulation that follows them drove); the goal's conditions in the
    final state are the world's task domain's."""
    name, sd, raw = sim_s
    sim = upgrade_travel_keys(values.flat_simulation(raw) or {})  # a record of before TC-avg had one definition
    if sim.get("executed") is None:  # skipped (the run was refused before it): all null
        return []
    parts = []
    art = sd / "artifacts"
    pics = [p for p in sim.get("pictures") or [] if isinstance(p, str) and (art / p).is_file()]
    src = f"steps/{name}/artifacts/paths.png" if "paths.png" in pics else None
    if src is None and world:
        kept = read_json(art / "trajectories.json", {}) or {}
        traj = kept.get("trajectories") if isinstance(kept, dict) else None
        traj = traj or (planned_paths(world, schedule) if schedule else None)
        if traj and not pictures.wanted(mode, "paths", pictures.size_of("paths", traj)):
            parts.append(f"<h2>Robot paths</h2><p>not drawn (pictures: {esc(mode)}; {len(traj)} robots)</p>")
        elif traj:
            try:
                pictures.path_map(world, traj, drawn.path("paths.png"), travel=sim.get("travel"))
                src = drawn.src("paths.png")
            except Exception as exc:  # a picture must never hide the rest of the report
                parts.append(f"<h2>Robot paths</h2><p class='bad'>could not draw: {esc(exc)}</p>")
    if src:
        parts.append("<h2>Robot paths</h2>" + img(src, "robot paths"))
    snaps = [p for p in pics if p != "paths.png" and p.endswith(".png")]
    if snaps:
        parts.append("<h2>Snapshots</h2><div class='snaps'>" + "".join(
            f"<figure>{img(f'steps/{name}/artifacts/{p}', p)}<figcaption>{esc(_snapshot_caption(p))}"
            f"</figcaption></figure>" for p in snaps) + "</div>")
    anim = [p for p in pics if p.endswith(".gif")]
    if anim:
        parts.append("<h2>Animation</h2>" + img(f"steps/{name}/artifacts/{anim[0]}", "animation"))
    parts.append("<h2>Simulation</h2>" + table(
        ["executed", "failed", "Exe", "TC-max (m)", "TC-avg, robots that moved (m)", "TC-avg over the team (m)",
         "makespan (s)", "goal met", "GCR"],
        [[sim.get("executed"), sim.get("failed"), sim.get("exe"), sim.get("tc_max"), sim.get("tc_avg"),
          sim.get("tc_avg_team"), sim.get("makespan"), sim.get("goal_met"), sim.get("gcr")]]))
    failures = [f for f in sim.get("failures") or [] if isinstance(f, dict)]
    if failures:
        parts.append("<p>Actions not executed:</p><ul>" + "".join(
            f"<li>{esc(f.get('subtask'))}" + (f" at t={esc(f['time'])}" if f.get("time") is not None else "")
            + f": {esc('; '.join(map(str, f.get('reasons') or [])))}</li>" for f in failures) + "</ul>")
    if isinstance(sim.get("travel"), dict) and sim["travel"]:
        parts.append(table(["robot", "travel (m)"], [[r, float(v)] for r, v in sorted(
            sim["travel"].items(), key=lambda kv: pictures.natural_key(kv[0]))]))
    conditions = _goal_conditions(world, sim, goal)
    if conditions:
        parts.append("<h3>Goal</h3>" + table(["goal condition (as the run read the command)", "holds at the end"],
                                              [[c.words, c.holds] for c in conditions]))
    return parts


def _goal_conditions(world: dict | None, sim: dict, goal: Any) -> list:
    """The goal's conditions in the simulation's final state, as the world's task domain reads
    them; none when the record lacks a world, a goal or a final state, or the domain cannot read
    this goal (a damaged record loses only this table)."""
    if not world or goal is None:
        return []
    try:
        domain = task_domain(world)
        final = domain.final_state(sim)
        return [] if final is None else list(domain.goal_conditions(world, final, goal))
    except (PipflowError, LookupError, TypeError, ValueError, AttributeError):
        return []


def _snapshot_caption(file_name: str) -> str:
    """``snapshot_2_first-load.png`` -> ``2. first load``."""
    stem = Path(file_name).stem.removeprefix("snapshot_")
    number, _, moment = stem.partition("_")
    return f"{number}. {moment.replace('-', ' ')}" if moment else stem


def _write_run_reports(bench: Bench) -> None:
    """The report of each run of the bench whose report is missing or older than its record."""
    for run in bench.runs:
        folder = bench.run_folder(run)
        if folder is None:
            continue
        page = folder / "report.html"
        try:
            if page.is_file() and not page.is_symlink() and page.stat().st_mtime >= (folder / "run.json").stat().st_mtime:
                continue
            write_report(folder)
        except (UserError, OSError):  # a run whose report cannot be written keeps a link to its folder
            continue


install_report_writer(write_report)  # Run.report() of the engine writes this report

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

Bench directory: ``results.json`` with ``{"summary": {...}, "tasks": [{"id", "runs", "sr", "gcr",
"exe", "ru", "tc_max", "tc_avg", "error"}], "variants"?: [{"name", "summary", "tasks"}], ...}`` and,
when ``pipflow bench`` wrote it, ``runs.json`` (one row per run: variant, task, seed, success,
tc_max, tc_avg, run_dir). Per-task plots come from those rows (or a task's own ``details``); run
directories inside the bench dir are linked to their own reports.
"""
from __future__ import annotations

import html
import json
import os
import re
from pathlib import Path
from typing import Any

from pipflow import pictures, values
from pipflow.engine.registry import default_registry
from pipflow.engine.runner import install_report_writer
from pipflow.engine.status import RunStatus
from pipflow.engine.store import shown_status
from pipflow.engine.writes import make_dirs, write_file
from pipflow.errors import InputError, PipflowError, UserError
from pipflow.meaning import misread_cell
from pipflow.metrics import upgrade_travel_keys
from pipflow.records.benchread import BY_KEY, ROW_KEY, Bench, fmt_interval, fmt_value, read_bench, task_commands, task_fields
from pipflow.records.intervals import LEVEL, STUDENT, WILSON, wilson
from pipflow.records.matrix import matrix_html, relative_link
from pipflow.records.replay import replay_section
from pipflow.taskdomain import plain_words
from pipflow.taskdomains import domain_named, task_domain
from pipflow.team.trajectory import planned_paths

_CHECK_SCRIPT = """<script>
window.addEventListener('load', function () {
  var imgs = Array.prototype.slice.call(document.images);
  var bad = imgs.filter(function (i) { return !(i.complete && i.naturalWidth > 0); });
  document.body.dataset.images = String(imgs.length);
  document.body.dataset.imagesOk = (bad.length === 0 && imgs.length > 0) ? 'true' : 'false';
  document.body.dataset.imagesBad = bad.map(function (i) { return i.getAttribute('src'); }).join(' ');
});
</script>"""

_STYLE = """<style>
body { font-family: sans-serif; margin: 2em; max-width: 1350px; color: #222; }
h1 { font-size: 1.5em; } h2 { border-bottom: 1px solid #ccc; padding-bottom: .2em; margin-top: 1.6em; }
table { border-collapse: collapse; margin: .5em 0; } td, th { border: 1px solid #bbb; padding: .25em .6em; }
th { background: #eef2f7; } td.num { text-align: right; font-variant-numeric: tabular-nums; }
.ok { color: #1a7f37; font-weight: bold; } .bad { color: #c62828; font-weight: bold; }
img { max-width: 100%; border: 1px solid #ddd; margin: .3em 0; }
.wide { overflow-x: auto; max-width: 100%; } .chart { overflow-x: auto; max-width: 100%; border: 1px solid #eee; } .chart img { max-width: none; border: 0; }
.snaps figure { display: inline-block; width: 48%; margin: .3em .5%; } .snaps img { width: 100%; } figcaption { text-align: center; color: #444; } pre { background: #f6f8fa; padding: .6em; overflow-x: auto; white-space: pre-wrap; }
.round { border: 1px solid #ccd; border-radius: 6px; padding: .2em 1em .6em; margin: .8em 0; }
.cause { border: 2px solid #c62828; border-radius: 6px; padding: .2em 1em; background: #fff5f5; }
pre.answer { max-height: 24em; overflow-y: auto; } .small { font-size: .85em; color: #555; } td.cmd, th.cmd { min-width: 18em; max-width: 28em; }
</style>"""


#: how a picture the report draws is linked until the page's place is known (a scheme, so the
#: rebasing of record links leaves it alone)
_PIC = "pipflowpic:"


class _Pictures:
    """The folder where the report draws its own pictures (created on first use; below the record
    ``root`` without following a link) and how the page links them."""

    def __init__(self, folder: Path, root: Path | None):
        self.folder, self.root, self._made = folder, root, False

    def path(self, name: str) -> Path:
        if not self._made:
            make_dirs(self.folder, root=self.root)
            self._made = True
        return self.folder / name

    @staticmethod
    def src(name: str) -> str:
        return _PIC + name


def write_report(directory: str | Path, output: str | Path | None = None) -> Path:
    """Write ``report.html`` (or ``output``: a file, or a folder to write ``report.html`` in) for a
    run or bench directory and return its path. Links stay relative: to the directory, or rebased
    when the page lies elsewhere; a page written elsewhere writes nothing into the record."""
    d = Path(directory)
    is_bench = (d / "results.json").is_file()
    if not is_bench and not ((d / "steps").is_dir() or (d / "run.json").is_file()):
        raise InputError(f"{d}: neither a run directory (steps/, run.json) nor a bench directory (results.json)")
    out, root = _page_path(d, output)
    pics = _Pictures(root / "report" if root is not None and out.parent == root else out.parent / f"{out.stem}_files",
                     root)
    if is_bench:
        body = _bench_body(d, pics, write_runs=root is not None)  # a page elsewhere writes nothing into the record
        title = f"pipflow bench: {d.name}"
    else:
        body = _run_body(d, pics)
        title = f"pipflow run: {d.name}"
    page = (f"<!DOCTYPE html>\n<html lang='en'><head><meta charset='utf-8'><title>{_e(title)}</title>"
            f"{_STYLE}</head>\n<body>\n<h1>{_e(title)}</h1>\n{body}\n{_CHECK_SCRIPT}\n</body></html>\n")
    record = root if root is not None else d.resolve()
    if out.parent != record:
        base = os.path.relpath(record, out.parent)

        def rebase(m: "re.Match") -> str:
            url = m.group(2)
            if re.match(r"^([a-z]+:|/|#)", url):
                return m.group(0)
            return f"{m.group(1)}='{_e(Path(base, html.unescape(url)).as_posix())}'"

        page = re.sub(r"(src|href)='([^']*)'", rebase, page)
    page = page.replace(_PIC, _e(Path(os.path.relpath(pics.folder, out.parent)).as_posix() + "/"))
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


# ------------------------------------------------------------------------------------------
# helpers
# ------------------------------------------------------------------------------------------


def _e(x: Any) -> str:
    return html.escape(str(x), quote=True)


def _read(path: Path, default: Any = None) -> Any:
    try:
        return json.loads(path.read_text(encoding="utf-8"))
    except (FileNotFoundError, json.JSONDecodeError):
        return default


def _img(src: str, alt: str) -> str:
    return f"<img src='{_e(src)}' alt='{_e(alt)}'>"


class Raw(str):
    """Trusted HTML for a table cell (links, coloured status), written without escaping."""


def _num(x: Any, digits: int = 2) -> str:
    if isinstance(x, Raw):
        return str(x)
    if x is None:
        return "&ndash;"
    if isinstance(x, bool):
        return "<span class='ok'>yes</span>" if x else "<span class='bad'>no</span>"
    if isinstance(x, (int, float)):
        return f"{x:.{digits}f}" if isinstance(x, float) else str(x)
    return _e(x)


def _table(headers: list[str], rows: list[list[Any]]) -> str:
    """An HTML table; a key-value table (every header empty) has no header row, not an empty one."""
    head = "".join(f"<th>{_e(h)}</th>" for h in headers) if any(headers) else ""
    body = "".join("<tr>" + "".join(
        f"<td class='num'>{_num(c)}</td>" if isinstance(c, (int, float)) or c is None else f"<td>{_num(c)}</td>"
        for c in row) + "</tr>" for row in rows)
    return f"<table>{f'<tr>{head}</tr>' if head else ''}{body}</table>"


# ------------------------------------------------------------------------------------------
# run directory
# ------------------------------------------------------------------------------------------


def _steps(d: Path) -> list[tuple[str, Path, dict]]:
    out = []
    for sd in sorted((d / "steps").glob("*")) if (d / "steps").is_dir() else []:
        outputs = _read(sd / "outputs.json")
        if isinstance(outputs, dict):
            out.append((sd.name, sd, outputs))
    return out


def _events(d: Path) -> list[dict]:
    """The readable events of a run's log (a torn or damaged line is skipped)."""
    try:
        lines = (d / "events.jsonl").read_text(encoding="utf-8", errors="replace").splitlines()
    except OSError:
        return []
    out = []
    for line in lines:
        try:
            event = json.loads(line)
        except json.JSONDecodeError:
            continue
        if isinstance(event, dict):
            out.append(event)
    return out


def _shapes(d: Path) -> dict[str, str]:
    """The family of outputs each step of the record declared (its start event's ``shape``); for a
    step whose event has none (a record made before they were recorded), the declaration of the
    step it used (``uses``), as the registry holds it."""
    shapes: dict[str, str] = {}
    uses: dict[str, str] = {}
    for e in _events(d):
        step = e.get("step")
        if e.get("event") in ("start", "skip") and isinstance(step, str):
            if isinstance(e.get("shape"), str):
                shapes[step] = e["shape"]
            elif isinstance(e.get("uses"), str):
                uses[step] = e["uses"]
    unknown = {s: u for s, u in uses.items() if s not in shapes}
    if unknown:
        registry = default_registry()
        for step, name in unknown.items():
            declared = registry.get(name)
            if declared is not None and declared.shape:
                shapes[step] = declared.shape
    return shapes


def _find(steps, shapes: dict[str, str], family: str) -> tuple[str, Path, dict] | None:
    """The last step (in the record's order) whose outputs are of ``family``."""
    hits = [s for s in steps if shapes.get(s[0]) == family]
    return hits[-1] if hits else None


def _run_body(d: Path, drawn: _Pictures) -> str:
    info = _read(d / "run.json", {}) or {}
    info = info if isinstance(info, dict) else {}
    inputs = _read(d / "inputs.json", {}) or {}
    outputs = _read(d / "outputs.json", {}) or {}
    steps = _steps(d)
    shapes = _shapes(d)
    parts = []

    status = shown_status(d, info) if (d / "run.json").is_file() else "?"  # only a steps/ folder left
    succeeded = RunStatus.of(status) is RunStatus.SUCCEEDED
    cls = "ok" if succeeded else "bad"
    command = inputs.get("command")
    parts.append(_table(["", ""], [["status", Raw(f"<span class='{cls}'>{_e(status)}</span>")],
                                   ["workflow", info.get("workflow", "")], ["error", info.get("error")]]))
    parts.append("<h2>Command</h2>" + (f"<p><q>{_e(command)}</q></p>" if command else "<p>(no command input)</p>"))
    rounds = _loop_rounds(d, shapes)
    if not succeeded and rounds:
        parts.insert(1, _failure_cause(info, rounds[-1]))
    parts.append(_understood(steps, shapes))
    if rounds:
        parts.append(_loop_section(rounds))

    world = (_find(steps, shapes, values.WORLD) or (None, None, {}))[2].get("world")
    world = world if isinstance(world, dict) else None
    plan_s = _find(steps, shapes, values.PLAN)
    graph_s = _find(steps, shapes, values.GRAPH)
    sched_s = _find(steps, shapes, values.SCHEDULE)
    sim_s = _find(steps, shapes, values.SIMULATION)
    met_s = _find(steps, shapes, values.SCORE)
    schedule = sched_s[2]["schedule"] if sched_s and isinstance(sched_s[2].get("schedule"), dict) else None
    graph_s = graph_s if graph_s and isinstance(graph_s[2].get("graph"), dict) else None
    planned = (graph_s, schedule)
    records = world  # the world as loaded (the records)
    executed = _executed(steps, shapes)
    if executed is not None:  # under faults: what was carried out, in the world as it really was
        name, sd, out = executed
        world = out["world"] if isinstance(out.get("world"), dict) else world
        schedule = out["schedule"] if isinstance(out.get("schedule"), dict) else schedule
        graph_s = (name, sd, {"graph": out["graph"]}) if isinstance(out.get("graph"), dict) else graph_s

    plan = plan_s[2].get("plan") if plan_s else None
    if executed is None:
        parts.append(_plan_section(plan, graph_s, schedule))
    else:
        parts.append(_executed_plan_section(executed[2], graph_s, schedule)
                     + "<details><summary>the plan as first made, before any fault</summary>"
                     + _plan_section(plan, *planned).replace("<h2 id='plan'>Team plan</h2>", "") + "</details>")

    mode = inputs.get("pictures") if inputs.get("pictures") in pictures.MODES else "auto"
    parts.append("<span id='pictures'></span>")  # where a bench's matrix links a run's pictures
    if graph_s and not pictures.wanted(mode, "graph", pictures.size_of("graph", graph_s[2]["graph"])):
        parts.append(f"<h2>Dependency graph</h2><p>not drawn (pictures: {_e(mode)}; "
                     f"{len(graph_s[2]['graph'].get('nodes', []))} subtasks)</p>")
    elif graph_s:
        try:
            pictures.dependency_graph(graph_s[2]["graph"], drawn.path("graph.png"))
            parts.append("<h2>Dependency graph</h2>" + _img(drawn.src("graph.png"), "dependency graph"))
        except Exception as exc:  # a picture must never hide the rest of the report
            parts.append(f"<h2>Dependency graph</h2><p class='bad'>could not draw: {_e(exc)}</p>")
    parts.append(_schedule_section(schedule, executed[2] if executed is not None else None, mode, drawn))
    parts.append(_replay(d, steps, world, schedule, graph_s[2]["graph"] if graph_s else None,
                         _incidents(world, executed[2]) if executed is not None else None))

    if sim_s:
        parts += _simulation_sections(sim_s, world, schedule, outputs.get("goal", inputs.get("goal")), mode, drawn)

    parts.append(_faults_section(executed, world, drawn, records, sim_s)  # runs under faults only ("" otherwise)
                 + _not_applicable_section(_find(steps, shapes, values.EXECUTION)))

    parts.append(_metrics_section(met_s))

    parts.append("<h2>Steps</h2>" + _table(["step", "outputs"], [[n, ", ".join(sorted(o))] for n, _, o in steps]))
    return "\n".join(parts)


def _metrics_section(met_s: tuple[str, Path, dict] | None) -> str:
    """The score step's metrics and the violations it found ("" for a skipped score step)."""
    if not met_s or not isinstance(met_s[2].get("violations"), list):  # a skipped score step: all null
        return ""
    m = upgrade_travel_keys(met_s[2])
    out = "<h2>Metrics</h2>" + _table(
        ["success", "GCR", "Exe", "RU", "TC-max (m)", "TC-avg, robots that moved (m)", "TC-avg over the team (m)",
         "planned", "lower bound"],
        [[m.get("success"), m.get("gcr"), m.get("exe"), m.get("ru"), m.get("tc_max"), m.get("tc_avg"),
          m.get("tc_avg_team"), m.get("planned"), m.get("lower_bound")]])
    if m.get("violations"):
        out += "<ul>" + "".join(f"<li class='bad'>{_e(v)}</li>" for v in m["violations"]) + "</ul>"
    return out


def _schedule_section(schedule: dict | None, executed: dict | None, mode: str, drawn: _Pictures) -> str:
    """The Gantt chart: of the schedule as carried out, with the faults and recoveries, under
    faults (``executed``: the execution step's outputs); of the schedule otherwise."""
    if not schedule:
        return ""
    if not pictures.wanted(mode, "gantt", pictures.size_of("gantt", schedule)):
        return (f"<h2>Schedule</h2><p>Gantt chart not drawn (pictures: {_e(mode)}; "
                f"{pictures.size_of('gantt', schedule)} working robots)</p>")
    if executed is None:
        pictures.gantt(schedule, drawn.path("gantt.png"))
        return "<h2>Schedule</h2>" + _img(drawn.src("gantt.png"), "Gantt chart per robot")
    try:
        pictures.fault_gantt(schedule, executed["faults"], executed.get("recoveries") or [], drawn.path("faults-gantt.png"))
        return ("<h2>Schedule as carried out</h2>"
                + _img(drawn.src("faults-gantt.png"), "the schedule carried out, with the faults and recoveries"))
    except Exception as exc:  # a picture must never hide the rest of the report
        return f"<h2>Schedule as carried out</h2><p class='bad'>could not draw: {_e(exc)}</p>"


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
        _table(["subtask", "action", "robots", "start (s)", "end (s)"], rows) if rows else "<p>empty plan</p>")


def _replay(d: Path, steps, world: Any, schedule: Any, graph: Any, events: list[dict] | None = None) -> str:
    """The replay section (:mod:`pipflow.records.replay`): the recorded trajectories of whichever
    step kept them (``trajectories.json``), else the schedule's legs; the floor plan from the
    world's task domain; under faults, the faults and recoveries as they happen (``events``)."""
    if not isinstance(world, dict) or not isinstance(schedule, dict):
        return ""
    recorded = None
    for name, sd, _ in steps:
        data = _read(sd / "artifacts" / "trajectories.json")
        if isinstance(data, dict) and isinstance(data.get("trajectories"), dict):
            recorded = data
    try:
        plan = list(task_domain(world).floor_plan(world))
    except UserError:  # the world's domain is no longer installed: the floor alone
        plan = []
    return replay_section(world, schedule, graph, recorded, plan, events)


# ------------------------------------------------------------------------------------------
# faults and recovery (pipflow.execution)
# ------------------------------------------------------------------------------------------


def _executed(steps, shapes: dict[str, str]) -> tuple[str, Path, dict] | None:
    """The execution step of a run under faults (its outputs: the world as it really was, the
    schedule carried out, its graph, faults, rounds); None for a run without faults."""
    found = _find(steps, shapes, values.EXECUTION)
    if not found or not isinstance(found[2].get("faults"), list) or not found[2]["faults"]:
        return None
    return found


def _executed_plan_section(out: dict, graph_s: tuple[str, Path, dict] | None, schedule: dict | None) -> str:
    """The team plan as carried out under faults: every subtask the robots did (the first plan's,
    then each re-plan's ``rK-...``), who did it and when, where it came from; and the subtasks of
    a plan a recovery set aside, with the round that did."""
    nodes = sorted((n for n in (graph_s[2]["graph"].get("nodes", []) if graph_s else []) if isinstance(n, dict)),
                   key=lambda n: n.get("index", 0))
    by_id = {s.get("id"): s for s in (schedule or {}).get("subtasks", []) if isinstance(s, dict)}
    rounds = [r for r in out.get("recoveries") or [] if isinstance(r, dict)]
    made_by = {sid: r for r in rounds for sid in r.get("replanned") or []}
    moved_by = {sid: r for r in rounds for sid in r.get("reallocated") or []}
    rows = []
    for n in nodes:
        sid = n.get("id")
        s = by_id.get(sid)
        text = " ".join(map(str, [n.get("action")] + list(n.get("args", []))))
        if sid in made_by:
            origin = f"re-planned in round {made_by[sid].get('round')}"
        elif sid in moved_by:
            origin = f"first plan, re-allocated in round {moved_by[sid].get('round')}"
        else:
            origin = "first plan"
        rows.append([sid, f"({text})", ", ".join(s["robots"]) if s else "(not carried out)",
                     f"{s['start']:.1f}" if s else "", f"{s['end']:.1f}" if s else "", origin])
    set_aside = [f"{', '.join(r['aborted'])} (round {r.get('round')}: {r.get('action')})"
                 for r in rounds if r.get("aborted")]
    carried = sum(1 for n in nodes if n.get("id") in by_id)
    head = (f"<h2 id='plan'>Team plan as carried out</h2><p class='small'>{carried} subtask(s) carried out, in the "
            f"world as it really was; {len(rounds)} recovery round(s) (see <a href='#faults'>Faults and recovery</a>)."
            + (f" Set aside by a re-plan, never carried out: {_e('; '.join(set_aside))}." if set_aside else "") + "</p>")
    return head + (_table(["subtask", "action", "robots", "start (s)", "end (s)", "from"], rows) if rows
                   else "<p>nothing was carried out</p>")


def _incidents(world: dict | None, out: dict) -> list[dict]:
    """The faults and recovery rounds of a run as moments of its replay: ``{time, kind, words}``
    and, where the fault is at a point, ``x``/``y`` (a robot's stop, a closed passage's middle,
    a surprising place's access point) or the ``robot`` it struck (the replay puts the mark
    where that robot is at that moment)."""
    places = {}
    try:
        places = task_domain(world).places(world) if isinstance(world, dict) else {}
    except UserError:
        places = {}
    events: list[dict] = []
    for f in out.get("faults") or []:
        if not isinstance(f, dict) or f.get("occurred") is False:
            continue
        words = f"{f.get('id')}: {_fault_words(f)}"
        kind = f.get("kind")
        t = f.get("time") if f.get("time") is not None else f.get("detected")
        event = {"time": float(t or 0.0), "kind": kind, "words": words}
        if kind == "robot-loss" and f.get("point"):
            event.update(x=float(f["point"][0]), y=float(f["point"][1]), stops=f.get("robot"))
            event["words"] = f"{words} (stops at t={event['time']:.1f} s)"
        elif kind == "passage-closed" and f.get("barrier"):
            b = f["barrier"]
            event.update(x=float(b["x"]) + float(b["width"]) / 2, y=float(b["y"]) + float(b["depth"]) / 2,
                         barrier=[float(b["x"]), float(b["y"]), float(b["width"]), float(b["depth"])])
        elif kind == "surprise":
            where = ((f.get("surprise") or {}).get("places") or [None])[0]
            access = (places.get(where) or {}).get("access") if where else None
            if access:
                event.update(x=float(access[0]), y=float(access[1]))
            event["time"] = float(f.get("detected") if f.get("detected") is not None else 0.0)
            event["words"] = f"{words} (found at t={event['time']:.1f} s)"
        elif f.get("robot"):
            event["robot"] = f["robot"]
        events.append(event)
    for r in out.get("recoveries") or []:
        if not isinstance(r, dict):
            continue
        secs = f", {r['seconds']:.2f} s" if isinstance(r.get("seconds"), (int, float)) else ""
        events.append({"time": float(r.get("time") or 0.0), "kind": "recovery",
                       "words": f"recovery {r.get('round')}: {r.get('action')}{secs}: {_remainder(r) or r.get('learned', '')}"})
    return sorted(events, key=lambda e: (e["time"], e["kind"] == "recovery"))


def _remainder(r: dict) -> str:
    """What a recovery round did with the rest of the run, in words: who took which subtask, the
    new plan's steps (and what a repair kept), the refusal."""
    if r.get("action") == "re-allocate":
        return "; ".join(f"{a.get('subtask')} to {', '.join(a.get('robots') or [])}"
                         for a in r.get("allocation") or [] if isinstance(a, dict)) or "nothing left to allocate"
    if r.get("action") == "re-plan":
        who = {a.get("subtask"): ", ".join(a.get("robots") or []) for a in r.get("allocation") or [] if isinstance(a, dict)}
        steps = [f"{sid} ({' '.join(map(str, [p.get('action')] + list(p.get('args') or [])))})"
                 + (f" to {who[sid]}" if who.get(sid) else "")
                 for sid, p in zip(r.get("replanned") or [], r.get("plan") or [])]
        rep = r.get("repaired")
        kept = (f"repaired: kept {rep.get('kept')} step(s) of the old plan, dropped "
                f"{', '.join(rep.get('dropped') or []) or 'none'}; " if isinstance(rep, dict) else "plan made anew; ")
        return (f"set aside {', '.join(r.get('aborted') or []) or 'nothing'}; {kept}new: " + ("; ".join(steps) or "none"))
    if r.get("action") == "refuse":
        return str(r.get("refusal") or "")
    return str(r.get("why") or "")


def _faults_section(executed: tuple[str, Path, dict] | None, world: dict | None, drawn: _Pictures,
                   records: dict | None = None, sim_s: tuple[str, Path, dict] | None = None) -> str:
    """What went wrong and how the run recovered: the faults (what, to whom, when, when noticed),
    each recovery round (cause, what it learned, what it did with the rest of the run, its
    seconds, whether the goal was still reachable), the refusal if the goal went out of reach,
    the world as it really was against the records, and where on the map. Empty for a run
    without faults (or whose execution step was skipped)."""
    if executed is None:
        return ""
    out = executed[2]
    faults, rounds = out["faults"], out.get("recoveries") or []
    parts = ["<h2 id='faults'>Faults and recovery</h2>"]
    if out.get("refusal"):
        parts.append(f"<div class='cause'><p><b>Refused after a fault:</b> {_e(out['refusal'])}</p></div>")
    parts.append(_table(["fault", "kind", "what", "struck at (s)", "noticed at (s)", "round"],
                        [[f.get("id"), f.get("name"), _fault_words(f), f.get("time"), f.get("detected"),
                          f.get("round")] for f in faults]))
    rows = [[r.get("round"), r.get("time"), (r.get("cause") or {}).get("words"), r.get("learned"),
             r.get("action"), _remainder(r), r.get("seconds"), r.get("feasible")] for r in rounds]
    parts.append("<h3>Recovery rounds</h3>" + _table(
        ["round", "t (s)", "cause", "learned", "action", "the rest of the run", "seconds", "goal reachable"], rows))
    parts.append(_as_it_was(out, world))
    parts.append(_state_table(records, world, sim_s))
    schedule, graph_world = out.get("schedule"), out.get("world") or world
    if isinstance(schedule, dict) and isinstance(graph_world, dict):
        try:
            pictures.fault_map(graph_world, schedule, faults, rounds, drawn.path("faults-map.png"))
            parts.append(_img(drawn.src("faults-map.png"), "where the faults struck"))
        except Exception as exc:  # a picture must never hide the rest of the report
            parts.append(f"<p class='bad'>could not draw the faults: {_e(exc)}</p>")
    return "\n".join(parts)


def _not_applicable_section(found: tuple[str, Path, dict] | None) -> str:
    """The faults asked for that had nothing in this run to strike (the run went on without
    them): which, their kind, and why. Empty when every fault asked for applied."""
    skipped = [f for f in ((found[2] if found else {}).get("not_applicable") or []) if isinstance(f, dict)]
    if not skipped:
        return ""
    return ("<h3 id='faults-not-applicable'>Faults not applicable (the run was carried out without them)</h3>"
            + _table(["fault", "kind", "asked for in", "why"],
                     [[f.get("id"), f.get("name"), f.get("where"), f.get("why")] for f in skipped]))


def _flat(state: Any, prefix: tuple = ()) -> dict[tuple, Any]:
    """A nested mapping's leaves by their path (``{("shelf4", "product3"): 12}``)."""
    if isinstance(state, dict):
        out: dict[tuple, Any] = {}
        for k, v in state.items():
            out.update(_flat(v, prefix + (str(k),)))
        return out
    return {prefix: state} if prefix else {}


def _count(state: dict, key: tuple) -> Any:
    """``state[key]``; a count the state leaves out under a place it does list is 0 (a state
    lists what is there: "shelf2 product3" gone from a listed shelf2 is none left, not unknown),
    while a place the state does not list at all stays unknown (None, drawn as a dash)."""
    if key in state:
        return state[key]
    siblings = [v for k, v in state.items() if k[:-1] == key[:-1] and len(k) == len(key)]
    counts = siblings and all(isinstance(v, int) and not isinstance(v, bool) for v in siblings)
    return 0 if len(key) > 1 and counts else None


#: the most rows the state table shows (a thousand shelves' worth would bury the report)
STATE_ROWS = 60


def _state_table(records: dict | None, world: dict | None, sim_s: tuple[str, Path, dict] | None) -> str:
    """The state where the records, the world as the run found it, and the end of the run differ
    (the task domain's ``initial_state`` of the loaded and of the real world, and its
    ``final_state`` of the simulation): what was really there and what the run left."""
    if not isinstance(records, dict) or not isinstance(world, dict) or sim_s is None:
        return ""
    try:
        domain = task_domain(world)
        before = _flat(domain.initial_state(records))
        found = _flat(domain.initial_state(world))
        end = _flat(domain.final_state(values.flat_simulation(sim_s[2]) or {}))
    except Exception:  # a state this table cannot read must never hide the rest of the report
        return ""
    if not end:
        return ""
    keys = sorted({k for k in (*before, *found, *end)
                   if not (before.get(k) == found.get(k) == end.get(k))}, key=lambda k: [pictures.natural_key(p) for p in k])
    if not keys:
        return ""
    rows = [[" ".join(k), *(_count(state, k) for state in (before, found, end))] for k in keys[:STATE_ROWS]]
    more = f"<p class='small'>and {len(keys) - STATE_ROWS} more</p>" if len(keys) > STATE_ROWS else ""
    return ("<h3>The state: records, as found, at the end</h3><p class='small'>Every entry that is not the same in "
            "all three: the world file's records, the world as the run really found it, and the final observed state "
            "(the simulation's).</p>" + _table(["where, what", "records", "as found", "at the end"], rows) + more)


def _as_it_was(out: dict, world: dict | None) -> str:
    """The world as the run found it, where it differs from the records: what a surprise showed,
    the passages that closed, the robots that stopped and where what they carried lies."""
    rows = []
    for f in out.get("faults") or []:
        if not isinstance(f, dict) or f.get("occurred") is False:
            continue
        if f.get("kind") == "surprise":
            rows.append(["contents", _fault_words(f), f.get("detected")])
        elif f.get("kind") == "passage-closed":
            rows.append(["passage", _fault_words(f), f.get("time")])
        elif f.get("kind") == "robot-loss":
            where = f" at ({f['point'][0]:.1f}, {f['point'][1]:.1f})" if f.get("point") else ""
            drop = f"; what it carried lies on {f['drop']}" if f.get("drop") else ""
            rows.append(["robot", f"{f.get('robot')} out of service{where}{drop}", f.get("time")])
        elif f.get("kind") == "slowdown":
            rows.append(["robot", _fault_words(f), f.get("time")])
    if not rows:
        return ""
    return ("<h3>The world as it really was</h3><p class='small'>Where it differed from the records; the "
            "sections above (plan, schedule, replay, paths, goal) show the run in this world.</p>"
            + _table(["what", "as it really was", "from t (s)"], rows))


def _fault_words(f: dict) -> str:
    if f.get("kind") == "surprise":
        return str((f.get("surprise") or {}).get("words") or "")
    who = f.get("robot") or " - ".join(f.get("between") or []) or ""
    extra = f" at {100 * f['factor']:.0f}% speed" if f.get("factor") else ""
    return f"{who}{extra}" + ("" if f.get("occurred", True) else " (did not happen before the run ended)")


def _simulation_sections(sim_s: tuple[str, Path, dict], world: dict | None, schedule: dict | None, goal: Any,
                         mode: str, drawn: _Pictures) -> list[str]:
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
        kept = _read(art / "trajectories.json", {}) or {}
        traj = kept.get("trajectories") if isinstance(kept, dict) else None
        traj = traj or (planned_paths(world, schedule) if schedule else None)
        if traj and not pictures.wanted(mode, "paths", pictures.size_of("paths", traj)):
            parts.append(f"<h2>Robot paths</h2><p>not drawn (pictures: {_e(mode)}; {len(traj)} robots)</p>")
        elif traj:
            try:
                pictures.path_map(world, traj, drawn.path("paths.png"), travel=sim.get("travel"))
                src = drawn.src("paths.png")
            except Exception as exc:  # a picture must never hide the rest of the report
                parts.append(f"<h2>Robot paths</h2><p class='bad'>could not draw: {_e(exc)}</p>")
    if src:
        parts.append("<h2>Robot paths</h2>" + _img(src, "robot paths"))
    snaps = [p for p in pics if p != "paths.png" and p.endswith(".png")]
    if snaps:
        parts.append("<h2>Snapshots</h2><div class='snaps'>" + "".join(
            f"<figure>{_img(f'steps/{name}/artifacts/{p}', p)}<figcaption>{_e(_snapshot_caption(p))}"
            f"</figcaption></figure>" for p in snaps) + "</div>")
    anim = [p for p in pics if p.endswith(".gif")]
    if anim:
        parts.append("<h2>Animation</h2>" + _img(f"steps/{name}/artifacts/{anim[0]}", "animation"))
    parts.append("<h2>Simulation</h2>" + _table(
        ["executed", "failed", "Exe", "TC-max (m)", "TC-avg, robots that moved (m)", "TC-avg over the team (m)",
         "makespan (s)", "goal met", "GCR"],
        [[sim.get("executed"), sim.get("failed"), sim.get("exe"), sim.get("tc_max"), sim.get("tc_avg"),
          sim.get("tc_avg_team"), sim.get("makespan"), sim.get("goal_met"), sim.get("gcr")]]))
    failures = [f for f in sim.get("failures") or [] if isinstance(f, dict)]
    if failures:
        parts.append("<p>Actions not executed:</p><ul>" + "".join(
            f"<li>{_e(f.get('subtask'))}" + (f" at t={_e(f['time'])}" if f.get("time") is not None else "")
            + f": {_e('; '.join(map(str, f.get('reasons') or [])))}</li>" for f in failures) + "</ul>")
    if isinstance(sim.get("travel"), dict) and sim["travel"]:
        parts.append(_table(["robot", "travel (m)"], [[r, float(v)] for r, v in sorted(
            sim["travel"].items(), key=lambda kv: pictures.natural_key(kv[0]))]))
    conditions = _goal_conditions(world, sim, goal)
    if conditions:
        parts.append("<h3>Goal</h3>" + _table(["goal condition (as the run read the command)", "holds at the end"],
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


# ------------------------------------------------------------------------------------------
# the refinement loop and what was understood
# ------------------------------------------------------------------------------------------


def _snapshot_caption(file_name: str) -> str:
    """``snapshot_2_first-load.png`` -> ``2. first load``."""
    stem = Path(file_name).stem.removeprefix("snapshot_")
    number, _, moment = stem.partition("_")
    return f"{number}. {moment.replace('-', ' ')}" if moment else stem


#: the part each family of step outputs plays in a round of the refinement loop
_ROLES = {values.READING: "generate", values.DEBUG: "debug", values.PLAN: "solve", values.VERIFY: "verify",
          values.CHECK: "check"}


def _loop_rounds(d: Path, shapes: dict[str, str]) -> list[dict]:
    """Every round of every loop in the record: ``{"loop", "n", "generate", "debug", "verify",
    "solve", "check"}``, each the outputs of the inner step that plays that part (found by the
    family its outputs declare, so any workflow's loop is shown) plus the step's artifact folder
    under ``_dir``."""
    rounds = []
    for it_dir in sorted((d / "steps").glob("*/iterations/*"), key=lambda p: (p.parent.parent.name, _int(p.name))):
        r: dict[str, Any] = {"loop": it_dir.parent.parent.name, "n": _int(it_dir.name)}
        for sd in sorted(p for p in it_dir.iterdir() if p.is_dir()):
            out = _read(sd / "outputs.json")
            if not isinstance(out, dict):
                out = {}
            role = _ROLES.get(shapes.get(sd.name, ""))
            if role is not None:
                r[role] = {**out, "_dir": sd, "_id": sd.name}
        gen = r.get("generate")
        if gen is not None and not gen.get("messages"):  # a failed generate keeps its prompt as an artifact
            gen["messages"] = _read(gen["_dir"] / "artifacts" / "messages.json", []) or []
        if gen is not None and not gen.get("response") and (gen["_dir"] / "artifacts" / "response.txt").is_file():
            gen["response"] = (gen["_dir"] / "artifacts" / "response.txt").read_text(encoding="utf-8", errors="replace")
        rounds.append(r)
    return rounds


def _int(text: str) -> int:
    return int(text) if text.isdigit() else 0


def _messages_of(r: dict, part: str) -> list[str]:
    out = r.get(part) or {}
    return [str(m) for m in (out.get("messages") or [])] if part != "generate" else \
        [str(m) for m in (out.get("errors") or [])]


def _failure_cause(info: dict, last: dict) -> str:
    """The top of a failed run's report: what the last round's checks said, not only that the
    loop ran out of rounds."""
    lines = (_messages_of(last, "generate") + _messages_of(last, "debug") + _messages_of(last, "verify")
             + _messages_of(last, "check"))
    items = "".join(f"<li>{_e(m)}</li>" for m in lines) or "<li>(the round left no messages)</li>"
    return (f"<div class='cause'><h2>Why it failed</h2><p>{_e(info.get('error') or '')}</p>"
            f"<p>Round {last['n']} of loop <code>{_e(last['loop'])}</code> ended with:</p><ul>{items}</ul></div>")


def _understood(steps, shapes: dict[str, str]) -> str:
    """The order as the run understood it, in plain words, before anything moved."""
    gen = _find(steps, shapes, values.READING)
    ver = _find(steps, shapes, values.VERIFY)
    explanation = (gen[2].get("explanation") if gen else None) or []
    lines = explanation.splitlines() if isinstance(explanation, str) else list(explanation)
    goal = (ver[2].get("goal") if ver else None) or (gen[2].get("goal") if gen else None)
    if not lines and isinstance(goal, dict):
        lines = _goal_lines(steps, shapes, goal)
    for rule in (gen[2].get("constraints") or []) if gen else []:
        if isinstance(rule, dict):
            lines.append(_rule_words(rule))
    if not lines:
        return ""
    return "<h2>Understood</h2><ul class='understood'>" + "".join(f"<li>{_e(x)}</li>" for x in lines) + "</ul>"


def _goal_lines(steps, shapes: dict[str, str], goal: dict) -> list[str]:
    """The goal in its task domain's words (``fridge holds pumpkin``, ``shelf4 product3: exactly
    12``), never a Python list; a domain no longer installed: the goal spelt out generically."""
    world = (_find(steps, shapes, values.WORLD) or (None, None, {}))[2].get("world")
    try:
        domain = task_domain(world) if isinstance(world, dict) else domain_named(None)
    except UserError:
        return plain_words(goal)
    return list(domain.goal_words(goal))


def _rule_words(rule: dict) -> str:
    who = ", ".join(rule.get("only") or rule.get("never") or [])
    scope = " ".join(f"{k} {v}" for k, v in rule.items() if k not in ("only", "never", "words") and v)
    verb = "only" if "only" in rule else "never"
    text = f"rule: {verb} {who} in moves" + (f" of {scope}" if scope else "")
    return text + (f" (from '{rule['words']}')" if rule.get("words") else "")


def _loop_section(rounds: list[dict]) -> str:
    """One card per round: the prompt as sent, the raw answer, the checks' messages, the cost."""
    cards = []
    for r in rounds:
        gen, ver = r.get("generate") or {}, r.get("verify") or {}
        usage = gen.get("usage") or {}
        ok = bool(ver.get("ok")) or bool(ver.get("refusal"))
        if r.get("check"):  # the second opinion decides whether a goal or a refusal stands
            ok = bool(ver.get("ok")) and bool(r["check"].get("ok")) or bool(r["check"].get("refusal"))
        head = (f"<h3>{_e(r['loop'])} round {r['n']} "
                f"<span class='{'ok' if ok else 'bad'}'>{'passed' if ok else 'rejected'}</span></h3>")
        facts = _table(["tokens in", "tokens out", "latency (s)", "cost (USD)", "cached"],
                       [[usage.get("prompt_tokens"), usage.get("completion_tokens"), usage.get("latency_s"),
                         usage.get("cost_usd"), usage.get("cached")]]) if usage.get("calls") or gen.get("response") else ""
        msgs = "".join(f"<details><summary>{_e(m.get('role', '?'))} message ({len(str(m.get('content', '')))} chars)"
                       f"</summary><pre>{_e(m.get('content', ''))}</pre></details>"
                       for m in gen.get("messages") or [] if isinstance(m, dict))
        answer = gen.get("response")
        answer_html = (f"<h4>Answer</h4><pre class='answer'>{_e(answer)}</pre>" if answer else
                       "<p>(offline: no model answer; the parser wrote the problem)</p>" if gen else "")
        checks = []
        for label, part in (("generator", "generate"), ("debugger", "debug"), ("verifier", "verify"),
                            ("second opinion", "check")):
            m = _messages_of(r, part)
            if m:
                checks.append(f"<h4>{label}</h4><ul>" + "".join(f"<li>{_e(x)}</li>" for x in m) + "</ul>")
        if ver.get("refusal"):
            checks.append(f"<h4>verifier: refusal</h4><p>{_e(ver['refusal'])}</p>")
        cards.append(f"<div class='round'>{head}{facts}"
                     + (f"<h4>Prompt</h4>{msgs}" if msgs else "") + answer_html + "".join(checks) + "</div>")
    return "<h2 id='loop'>Refinement loop</h2>" + "".join(cards)


# ------------------------------------------------------------------------------------------
# bench directory
# ------------------------------------------------------------------------------------------


def _bench_body(d: Path, drawn: _Pictures, write_runs: bool = True) -> str:
    """A bench: its configuration, a summary row per variant (SR and the other shares as
    percents, each figure with its 95% interval over seeds), the matrix of variants x tasks (one
    click to each run), a table per group of tasks when the task domain groups them (household:
    per category), the tasks' table with each seed's run, the right refusals apart from the
    errors, and the per-task charts. ``write_runs``: write the report of every run of the bench
    that has none yet (or an older one), so that every seed link opens a report."""
    bench = read_bench(d)
    if write_runs:
        _write_run_reports(bench)
    names = bench.variants
    parts = [_bench_config(bench.results, bench.config)]
    parts.append("<h2 id='summary'>Summary</h2>" + _summary_table(bench) + f"<p class='small'>{_e(_ci_note(bench))}</p>")
    for group, labels in _task_groups(bench).items():
        parts.append(f"<h2 id='per-{_e(group)}'>Per {_e(group)}</h2>" + _group_table(bench, group, labels))
    parts.append(matrix_html([bench], relative_link(d)))
    constructions = [(n, (v.get("constructions") or {})) for n, v in zip(names, bench.results.get("variants") or [])]
    if any(c for _, c in constructions):
        rows = [[k, *[Raw(f"{_e(c.get(k, {}).get('runs', ''))} runs, {_e(_pct(c.get(k, {}).get('understood')) or '-')} "
                          f"understood, misread {_e(misread_cell(c.get(k, {})))}") if k in c else None
                      for _, c in constructions]]
                for k in sorted({k for _, c in constructions for k in c})]
        parts.append("<h2 id='constructions'>Understanding per construction</h2>"
                     + _table(["construction", *names], rows))
    parts.append("<h2 id='tasks'>Tasks</h2>" + _tasks_table(bench))
    refusals, errors = _refusals_and_errors(bench)
    if refusals:
        parts.append("<h3 id='refusals'>Refused, as the task asks</h3><p class='small'>Commands the task file marks "
                     "impossible (or to refuse): a refusal with a reason is the right answer.</p><ul>" + "".join(
                         f"<li><b>{_e(tid)}</b>" + (f" [{_e(n)}]" if len(names) > 1 else "") + f": {_e(text)}</li>"
                         for n, tid, text in refusals) + "</ul>")
    if errors:
        parts.append("<h3 id='errors'>Errors</h3><p class='small'>Runs that did not succeed, with why.</p><ul>" + "".join(
            f"<li><b>{_e(tid)}</b>" + (f" [{_e(n)}]" if len(names) > 1 else "") + f": {_e(text)}</li>"
            for n, tid, text in errors) + "</ul>")
    if bench.task_ids:
        groups = _task_groups(bench)
        chart_groups = next(iter(groups.items()), None)
        parts.append("<h2 id='charts'>Per task</h2><p class='small'>At full size; scroll sideways in a wide "
                     "chart.</p>")
        sets = ([(label, [t for t in bench.task_ids if chart_groups[1].get(t) == label])
                 for label in dict.fromkeys(chart_groups[1].values())] if chart_groups else [("", bench.task_ids)])
        for k, (label, ids) in enumerate(sets):
            if not ids:
                continue
            name = f"overview{'-' + re.sub(r'[^A-Za-z0-9_-]', '_', str(label)) if label else ''}.png"
            _bench_overview(bench, ids, drawn.path(name), title=str(label))
            parts.append((f"<h3>{_e(label)}</h3>" if label else "")
                         + f"<div class='chart'>{_img(drawn.src(name), f'SR and TC-max per task and variant {label}'.strip())}</div>")
    return "\n".join(parts)


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


def _ci_note(bench: Bench) -> str:
    seeds = int(bench.config.get("seeds") or 1)
    if seeds < 2:
        return "One seed per task: no intervals (run the bench with --seeds 2 or more for them)."
    return (f"[lo, hi]: the {int(LEVEL * 100)}% interval over the {seeds} seeds: {WILSON} for SR and understood, "
            f"{STUDENT} for the others; the all-tasks figures over each seed's figure of all tasks.")


def _figure_cell(bench: Bench, variant: str, task: str | None, key: str) -> Any:
    metric = BY_KEY[key]
    f = bench.figure(variant, task, metric)
    if f.value is None:
        return None
    interval = fmt_interval(f.interval, metric)
    return Raw(_e(fmt_value(f.value, metric)) + (f" <span class='small'>{_e(interval)}</span>" if interval else ""))


def _summary_table(bench: Bench) -> str:
    rows = []
    for v in bench.variants:
        s = bench.summaries.get(v, {})
        fallbacks = [r for r in bench.runs_of(v) if r.get("fallback")]
        rows.append([v, s.get("runs"), _figure_cell(bench, v, None, "sr"), _figure_cell(bench, v, None, "understood"),
                     misread_cell(s), _figure_cell(bench, v, None, "gcr"), _figure_cell(bench, v, None, "exe"),
                     _figure_cell(bench, v, None, "ru"), _figure_cell(bench, v, None, "tc_max"),
                     _figure_cell(bench, v, None, "tc_avg"), _figure_cell(bench, v, None, "makespan"),
                     _figure_cell(bench, v, None, "seconds"), _engines(bench.runs_of(v)),
                     Raw(f"<span class='bad'>{len(fallbacks)}</span>") if fallbacks else 0])
    return _table(["variant", "runs", "SR", "understood", "misread (executed)", "GCR", "Exe", "RU", "TC-max (m)",
                   "TC-avg (m)", "makespan (s)", "time per run (s)", "planner", "planner fell back"], rows)


def _engines(runs: list[dict]) -> str:
    """Which planner answered, over the runs (``engine`` of each row; older rows have none)."""
    counts: dict[str, int] = {}
    for r in runs:
        if r.get("engine"):
            counts[str(r["engine"])] = counts.get(str(r["engine"]), 0) + 1
    return ", ".join(f"{k} ({n})" if len(counts) > 1 else k for k, n in counts.items()) or ""


def _task_groups(bench: Bench) -> dict[str, dict[str, str]]:
    """``{field: {task id: label}}`` for each field the bench's task domain groups its tasks by
    (:attr:`pipflow.taskdomain.TaskDomain.task_groups`), read from the task rows (or, for an
    older bench, from its task file)."""
    try:
        fields = tuple(domain_named(bench.config.get("domain")).task_groups)
    except UserError:  # a bench of a domain no longer installed: no groups
        return {}
    out: dict[str, dict[str, str]] = {}
    for field in fields:
        labels = {tid: str(row[field]) for v in bench.variants for tid, row in bench.tasks[v].items()
                  if row.get(field) is not None}
        if not labels:
            labels = {tid: str(t[field]) for tid, t in task_fields(bench.config, bench.path).items()
                      if t.get(field) is not None and tid in bench.task_ids}
        if labels:
            out[field] = labels
    return out


def _group_table(bench: Bench, field: str, labels: dict[str, str]) -> str:
    """One row per group (and all tasks) and variant: tasks, runs, SR, understood, misread, TC,
    GCR, RU, Exe; the rates over the group's runs, TC over its tasks that have a travel figure
    (as the bench's summary is made)."""
    rows = []
    for label in list(dict.fromkeys(labels.values())) + [None]:
        ids = [t for t in bench.task_ids if label is None or labels.get(t) == label]
        for v in bench.variants:
            runs = [r for r in bench.runs_of(v) if str(r.get("task")) in ids]
            tasks = [bench.tasks[v][t] for t in ids if t in bench.tasks[v]]
            n = sum(int(t.get("runs") or 0) for t in tasks)

            def share(key: str) -> Any:
                if runs:
                    vals = [bool(r.get(ROW_KEY.get(key, key))) for r in runs if r.get(ROW_KEY.get(key, key)) is not None]
                    if not vals:
                        return None
                    interval = fmt_interval(wilson(sum(vals), len(vals)), BY_KEY[key])
                    return Raw(f"{100 * sum(vals) / len(vals):.0f}%" + (f" <span class='small'>{interval}</span>" if interval else ""))
                vals = [(t.get(key), t.get("runs") or 0) for t in tasks if t.get(key) is not None]
                total = sum(w for _, w in vals)
                return _pct(sum(x * w for x, w in vals) / total) if total else None

            def mean(key: str, weighted: bool = True) -> Any:
                vals = [(float(t[key]), (t.get("runs") or 0) if weighted else 1) for t in tasks
                        if isinstance(t.get(key), (int, float))]
                total = sum(w for _, w in vals)
                return round(sum(x * w for x, w in vals) / total, 2) if total else None

            misread = {k: sum(int(t.get(k) or 0) for t in tasks) for k in ("misread", "misread_executed")}
            rows.append([Raw(f"<b>all</b>") if label is None else label] + ([v] if len(bench.variants) > 1 else [])
                        + [len(tasks), n, share("sr"), share("understood"), misread_cell(misread),
                           mean("tc_max", False), mean("tc_avg", False), mean("gcr"), mean("ru"), mean("exe")])
    head = [field] + (["variant"] if len(bench.variants) > 1 else []) + [
        "tasks", "runs", "SR", "understood", "misread (executed)", "TC-max (m)", "TC-avg (m)", "GCR", "RU", "Exe"]
    return _table(head, rows)


def _tasks_table(bench: Bench) -> str:
    """Per task, each variant's SR (with each seed's run linked), TC-max and makespan (mean and
    interval over seeds), RU and Exe; then each further variant's TC-max difference to the
    first."""
    names = bench.variants
    commands = task_commands(bench.config, bench.path)
    link = relative_link(bench.path)
    rows = []
    for tid in bench.task_ids:
        row: list[Any] = [tid, commands.get(tid, "")]
        for n in names:
            vr = sorted(bench.runs_of(n, tid), key=lambda r: r.get("seed") or 0)
            links = " ".join(f"<a href='{_e(url)}'>seed {_e(r.get('seed'))}</a>" for r in vr for url in [link(bench, r)] if url)
            sr = _figure_cell(bench, n, tid, "sr")
            row += [Raw(f"{sr if sr is not None else '&ndash;'}<br><span class='small'>{links}</span>"),
                    _figure_cell(bench, n, tid, "tc_max"), _figure_cell(bench, n, tid, "makespan"),
                    _figure_cell(bench, n, tid, "ru"), _figure_cell(bench, n, tid, "exe")]
        base = bench.figure(names[0], tid, BY_KEY["tc_max"]).value
        for n in names[1:]:
            other = bench.figure(n, tid, BY_KEY["tc_max"]).value
            row.append(other - base if other is not None and base is not None else None)
        rows.append(row)
    return _grouped_table(names, rows)


def _refusals_and_errors(bench: Bench) -> tuple[list, list]:
    """Per variant and task, the refusals that were the right answer (the run succeeded by
    refusing) and the errors of runs that did not succeed, each text once."""
    refusals, errors = [], []
    for v in bench.variants:
        for tid in bench.task_ids:
            runs = bench.runs_of(v, tid)
            right = {str(r.get("error")) for r in runs if r.get("success") and r.get("error")}
            wrong = {str(r.get("error")) for r in runs if not r.get("success") and r.get("error")}
            t = bench.tasks[v].get(tid) or {}
            if not right and not wrong and t.get("error"):  # rows without errors (older): the task row's, by its SR
                (right if t.get("sr") == 1 else wrong).add(str(t["error"]))
            refusals += [(v, tid, text) for text in sorted(right)]
            errors += [(v, tid, text) for text in sorted(wrong)]
    return refusals, errors


def _grouped_table(names: list[str], rows: list[list[Any]]) -> str:
    """Per-task rows under a two-level header: one column group per variant (SR, TC-max,
    makespan, RU, Exe), then the difference in TC-max of each further variant to the first."""
    per = ("SR", "TC-max (m)", "makespan (s)", "RU", "Exe")
    top = "<th rowspan='2'>task</th><th rowspan='2' class='cmd'>command</th>" + "".join(
        f"<th colspan='{len(per)}'>{_e(n)}</th>" for n in names)
    if len(names) > 1:
        top += f"<th colspan='{len(names) - 1}'>\u0394 TC-max (m) vs {_e(names[0])}</th>"
    sub = "".join(f"<th>{h}</th>" for _ in names for h in per) + "".join(f"<th>{_e(n)}</th>" for n in names[1:])
    body = "".join("<tr>" + "".join(
        f"<td class='num'>{_num(c)}</td>" if isinstance(c, (int, float)) or c is None else
        f"<td class='cmd'>{_num(c)}</td>" if i == 1 else f"<td>{_num(c)}</td>"
        for i, c in enumerate(row)) + "</tr>" for row in rows)
    return f"<div class='wide'><table class='tasks'><tr>{top}</tr><tr>{sub}</tr>{body}</table></div>"


def _bench_config(results: dict, config: dict) -> str:
    rows = [[k, v] for k, v in config.items() if not isinstance(v, (dict, list))]
    for key in ("matrix", "inputs"):
        for k, v in (config.get(key) or {}).items():
            rows.append([f"{key}: {k}", ", ".join(map(str, v)) if isinstance(v, list) else v])
    rows += [[k, v] for k, v in results.items() if not isinstance(v, (dict, list))]
    return "<h2>Configuration</h2>" + _table(["", ""], rows)


def _pct(x: Any) -> Any:
    return None if x is None else f"{100 * float(x):.0f}%"


def _bench_overview(bench: Bench, ids: list[str], path: Path, title: str = "") -> None:
    """SR and TC-max of tasks ``ids``, one bar per variant; TC-max bars carry the 95% interval
    over seeds (none with one seed). Drawn at a readable size (about 0.35 inch a bar), never
    squeezed: the page scrolls it; the legend sits above the axes, never on the bars."""
    plt = pictures._plt()  # matplotlib loads here, on first drawing
    x = list(range(len(ids)))
    k_vars = max(1, len(bench.variants))
    width = 0.8 / k_vars
    fig, (a1, a2) = plt.subplots(2, 1, figsize=(max(8.0, 0.35 * len(ids) * k_vars + 2.5), 7.5))
    for k, name in enumerate(bench.variants):
        xs = [i - 0.4 + width * (k + 0.5) for i in x]
        srs = [bench.figure(name, t, BY_KEY["sr"]).value for t in ids]
        a1.bar(xs, [100 * (v or 0.0) for v in srs], width, label=name)
        mid, lo, hi = [], [], []
        for t in ids:
            f = bench.figure(name, t, BY_KEY["tc_max"])
            m = f.value or 0.0
            mid.append(m)
            lo.append(m - f.interval[0] if f.interval else 0.0)
            hi.append(f.interval[1] - m if f.interval else 0.0)
        spread = any(lo) or any(hi)  # one seed: no interval, no whiskers
        a2.bar(xs, mid, width, yerr=[lo, hi] if spread else None, capsize=2 if spread else 0, label=name)
    a1.set_ylim(0, 105)
    a1.set_ylabel("SR (%)")
    a1.set_title("Success rate per task" + (f": {title}" if title else ""))
    a2.set_ylabel("TC-max (m), successful runs")
    a2.set_title("Longest robot travel per task (bars: 95% interval over seeds)")
    for a in (a1, a2):
        a.set_xticks(x)
        a.set_xticklabels(ids, rotation=60, ha="right", fontsize=9)
        a.set_xlim(-0.6, len(ids) - 0.4)
    if k_vars > 1:  # one legend for both charts, above them, a line per variant: it never covers a bar
        handles, labels = a1.get_legend_handles_labels()
        top = 0.22 * k_vars + 0.2  # inches
        fig.set_figheight(fig.get_figheight() + top)
        fig.legend(handles, labels, loc="upper left", ncol=1, fontsize=9, frameon=False, bbox_to_anchor=(0.01, 1.0))
        fig.tight_layout(rect=(0, 0, 1, 1 - top / fig.get_figheight()))
    else:
        fig.tight_layout()
    pictures.save_figure(fig, path, dpi=90)
    plt.close(fig)


install_report_writer(write_report)  # Run.report() of the engine writes this report

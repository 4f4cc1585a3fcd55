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
from pipflow.errors import InputError, PipflowError
from pipflow.meaning import misread_cell
from pipflow.metrics import counts_for_travel, upgrade_results, upgrade_travel_keys
from pipflow.taskdomains import task_domain
from pipflow.team.trajectory import planned_paths
from pipflow.yamlsource import read_source, safe_load

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
        body = _bench_body(d, pics)
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
    head = "".join(f"<th>{_e(h)}</th>" for h in headers)
    body = "".join("<tr>" + "".join(
        f"<td class='num'>{_num(c)}</td>" if isinstance(c, (int, float)) or c is None else f"<td>{_num(c)}</td>"
        for c in row) + "</tr>" for row in rows)
    return f"<table><tr>{head}</tr>{body}</table>"


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

    # team plan, with the robots the schedule gave each subtask
    parts.append("<h2>Team plan</h2>")
    plan = plan_s[2].get("plan") if plan_s else None
    if plan is not None:
        # subtask ids as the graph and the Gantt chart name them (s1, s2, ...), not list positions
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
        parts.append(_table(["subtask", "action", "robots", "start (s)", "end (s)"], rows) if rows else "<p>empty plan</p>")
    else:
        parts.append("<p>(no plan in this run)</p>")

    mode = inputs.get("pictures") if inputs.get("pictures") in pictures.MODES else "auto"
    if graph_s and not pictures.wanted(mode, "graph", pictures.size_of("graph", graph_s[2]["graph"])):
        parts.append(f"<h2>Dependency graph</h2><p>not drawn (pictures: {_e(mode)}; "
                     f"{len(graph_s[2]['graph'].get('nodes', []))} subtasks)</p>")
    elif graph_s:
        try:
            pictures.dependency_graph(graph_s[2]["graph"], drawn.path("graph.png"))
            parts.append("<h2>Dependency graph</h2>" + _img(drawn.src("graph.png"), "dependency graph"))
        except Exception as exc:  # a picture must never hide the rest of the report
            parts.append(f"<h2>Dependency graph</h2><p class='bad'>could not draw: {_e(exc)}</p>")
    if schedule and not pictures.wanted(mode, "gantt", pictures.size_of("gantt", schedule)):
        parts.append(f"<h2>Schedule</h2><p>Gantt chart not drawn (pictures: {_e(mode)}; "
                     f"{pictures.size_of('gantt', schedule)} working robots)</p>")
    elif schedule:
        pictures.gantt(schedule, drawn.path("gantt.png"))
        parts.append("<h2>Schedule</h2>" + _img(drawn.src("gantt.png"), "Gantt chart per robot"))

    if sim_s:
        parts += _simulation_sections(sim_s, world, schedule, outputs.get("goal", inputs.get("goal")), mode, drawn)

    if met_s and isinstance(met_s[2].get("violations"), list):  # a skipped score step: all null
        m = upgrade_travel_keys(met_s[2])
        parts.append("<h2>Metrics</h2>" + _table(
            ["success", "GCR", "Exe", "RU", "TC-max (m)", "TC-avg, robots that moved (m)", "TC-avg over the team (m)",
             "planned", "lower bound"],
            [[m.get("success"), m.get("gcr"), m.get("exe"), m.get("ru"), m.get("tc_max"), m.get("tc_avg"),
              m.get("tc_avg_team"),
              m.get("planned"), m.get("lower_bound")]]))
        if m.get("violations"):
            parts.append("<ul>" + "".join(f"<li class='bad'>{_e(v)}</li>" for v in m["violations"]) + "</ul>")

    parts.append("<h2>Steps</h2>" + _table(["step", "outputs"], [[n, ", ".join(sorted(o))] for n, _, o in steps]))
    return "\n".join(parts)


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
        for place, items in goal.items():
            for item, value in (items.items() if isinstance(items, dict) else []):
                lines.append(f"{place} {item}: {_goal_words(value)}")
    for rule in (gen[2].get("constraints") or []) if gen else []:
        if isinstance(rule, dict):
            lines.append(_rule_words(rule))
    if not lines:
        return ""
    return "<h2>Understood</h2><ul class='understood'>" + "".join(f"<li>{_e(x)}</li>" for x in lines) + "</ul>"


def _goal_words(value: Any) -> str:
    if isinstance(value, dict):
        lo, hi = value.get("at_least"), value.get("at_most")
        if lo is not None and hi is not None:
            return f"between {lo} and {hi}"
        return f"at least {lo}" if lo is not None else f"at most {hi}"
    return f"exactly {value}"


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
    return "<h2>Refinement loop</h2>" + "".join(cards)


# ------------------------------------------------------------------------------------------
# bench directory
# ------------------------------------------------------------------------------------------


def _bench_body(d: Path, drawn: _Pictures) -> str:
    """Variants side by side: a summary row per variant, then per task each variant's SR,
    understanding, travel and makespan (mean and spread over seeds), with the difference to the
    first variant; the configuration shows the matrix that made the variants."""
    results = _read(d / "results.json")
    if not isinstance(results, dict) or "tasks" not in results:
        raise InputError(f"{d / 'results.json'}: not a results file (needs 'summary' and 'tasks')")
    runs = [upgrade_travel_keys(r) for r in (_read(d / "runs.json", []) or []) if isinstance(r, dict)]
    results = upgrade_results(results)
    config = results.get("config") or {}
    variants = results.get("variants") or [{"name": "default", "summary": results.get("summary", {}),
                                            "tasks": results.get("tasks", [])}]
    names = [v.get("name", "default") for v in variants]
    parts = [_bench_config(results, config)]

    parts.append("<h2>Summary</h2>" + _table(
        ["variant", "runs", "SR", "understood", "misread (executed)", "GCR", "TC-max (m)", "TC-avg (m)", "makespan (s)",
         "time per run (s)", "tokens"],
        [[v.get("name", "default"), (v.get("summary") or {}).get("runs"), _pct((v.get("summary") or {}).get("sr")),
          _pct((v.get("summary") or {}).get("understood")), misread_cell(v.get("summary") or {}),
          (v.get("summary") or {}).get("gcr"), (v.get("summary") or {}).get("tc_max"),
          (v.get("summary") or {}).get("tc_avg"), _mean_of(runs, v.get("name", "default"), "makespan"),
          _mean_of(runs, v.get("name", "default"), "seconds"), _mean_of(runs, v.get("name", "default"), "tokens")]
         for v in variants]))

    commands = _task_commands(config)
    by_task = {name: {t.get("id"): t for t in v.get("tasks", []) if isinstance(t, dict)}
               for name, v in zip(names, variants)}
    task_ids = [t.get("id") for t in variants[0].get("tasks", []) if isinstance(t, dict)]
    rows = []
    for tid in task_ids:
        row: list[Any] = [tid, commands.get(tid, "")]
        base_tc = None
        for k, n in enumerate(names):
            t = by_task[n].get(tid) or {}
            vr = [r for r in runs if r.get("variant", "default") == n and r.get("task") == tid]
            tc = [float(r["tc_max"]) for r in vr if counts_for_travel(r) and isinstance(r.get("tc_max"), (int, float))]
            links = " ".join(f"<a href='{_e(link)}'>seed {_e(r.get('seed'))}</a>" for r in vr
                             for link in [_rel(d, r.get("run_dir"))] if link)
            row += [Raw(f"{_pct(t.get('sr'))}<br><span class='small'>{links}</span>"), _spread(tc),
                    _num(t.get("makespan"))]
            if k == 0:
                base_tc = t.get("tc_max")
        for n in names[1:]:
            t = by_task[n].get(tid) or {}
            row.append(t.get("tc_max") - base_tc if isinstance(t.get("tc_max"), (int, float))
                       and isinstance(base_tc, (int, float)) else None)
        rows.append(row)
    parts.append("<h2>Tasks</h2>" + _grouped_table(names, rows))
    errors = [(n, t.get("id"), t.get("error")) for n, v in zip(names, variants) for t in v.get("tasks", [])
              if isinstance(t, dict) and t.get("error")]
    if errors:
        parts.append("<h3>Errors</h3><ul>" + "".join(
            f"<li><b>{_e(tid)}</b>" + (f" [{_e(n)}]" if len(names) > 1 else "") + f": {_e(err)}</li>"
            for n, tid, err in errors) + "</ul>")
    if task_ids:
        _bench_overview(variants, runs, drawn.path("overview.png"))
        parts.append("<h2>Per task</h2>" + _img(drawn.src("overview.png"), "SR and TC-max per task and variant"))
    return "\n".join(parts)


def _grouped_table(names: list[str], rows: list[list[Any]]) -> str:
    """Per-task rows under a two-level header: one column group per variant (SR, TC-max,
    makespan), then the difference in TC-max of each further variant to the first."""
    per = ("SR", "TC-max (m)", "makespan (s)")
    top = "<th rowspan='2'>task</th><th rowspan='2' class='cmd'>command</th>" + "".join(
        f"<th colspan='{len(per)}'>{_e(n)}</th>" for n in names)
    if len(names) > 1:
        top += f"<th colspan='{len(names) - 1}'>\u0394 TC-max (m) vs {_e(names[0])}</th>"
    sub = "".join(f"<th>{h}</th>" for _ in names for h in per) + "".join(f"<th>{_e(n)}</th>" for n in names[1:])
    body = "".join("<tr>" + "".join(
        f"<td class='num'>{_num(c)}</td>" if isinstance(c, (int, float)) or c is None else
        f"<td class='cmd'>{_num(c)}</td>" if i == 1 else f"<td>{_num(c)}</td>"
        for i, c in enumerate(row)) + "</tr>" for row in rows)
    return f"<table class='tasks'><tr>{top}</tr><tr>{sub}</tr>{body}</table>"


def _bench_config(results: dict, config: dict) -> str:
    rows = [[k, v] for k, v in config.items() if not isinstance(v, (dict, list))]
    for key in ("matrix", "inputs"):
        for k, v in (config.get(key) or {}).items():
            rows.append([f"{key}: {k}", ", ".join(map(str, v)) if isinstance(v, list) else v])
    rows += [[k, v] for k, v in results.items() if not isinstance(v, (dict, list))]
    return "<h2>Configuration</h2>" + _table(["", ""], rows)


def _task_commands(config: dict) -> dict[str, str]:
    """Each task's command, read back from the bench's task file (empty when it is gone)."""
    try:
        doc = safe_load(read_source(config.get("tasks") or "", "task file"))
    except Exception:  # a moved or damaged task file only loses the command column
        return {}
    return {str(t.get("id")): str(t.get("command", "")) for t in (doc or {}).get("tasks", []) if isinstance(t, dict)}


def _pct(x: Any) -> Any:
    return None if x is None else f"{100 * float(x):.0f}%"


def _spread(values: list[float]) -> Any:
    """Mean over seeds, with the spread (min-max) when there is more than one."""
    if not values:
        return None
    mean = sum(values) / len(values)
    if len(values) == 1:
        return round(mean, 2)
    return f"{mean:.2f} ({min(values):.2f}\u2013{max(values):.2f})"


def _mean_of(runs: list[dict], variant: str, key: str) -> Any:
    vals = [float(r[key]) for r in runs if r.get("variant", "default") == variant
            and isinstance(r.get(key), (int, float)) and not isinstance(r.get(key), bool)]
    return round(sum(vals) / len(vals), 2) if vals else None


def _rel(d: Path, run_dir: str | None) -> str | None:
    """Link to a run inside the bench dir: its report.html when written, else the directory."""
    if not run_dir:
        return None
    p = Path(run_dir)
    p = p if p.is_absolute() else (d / p)
    try:
        rel = p.resolve().relative_to(d.resolve())
    except ValueError:
        return None
    if (p / "report.html").is_file():
        return f"{rel.as_posix()}/report.html"
    return rel.as_posix() if p.is_dir() else None


def _bench_overview(variants: list[dict], runs: list[dict], path: Path) -> None:
    """SR and TC-max per task, one bar per variant; TC-max bars carry the spread over seeds."""
    plt = pictures._plt()  # matplotlib loads here, on first drawing
    ids = [str(t.get("id")) for t in variants[0].get("tasks", [])]
    x = list(range(len(ids)))
    width = 0.8 / max(1, len(variants))
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(max(12, 0.6 * len(ids) * len(variants) + 4), 4.5))
    for k, v in enumerate(variants):
        name = v.get("name", "default")
        tasks = {str(t.get("id")): t for t in v.get("tasks", [])}
        xs = [i - 0.4 + width * (k + 0.5) for i in x]
        a1.bar(xs, [100 * float((tasks.get(i) or {}).get("sr") or 0) for i in ids], width, label=name)
        lo, mid, hi = [], [], []
        for i in ids:
            tc = [float(r["tc_max"]) for r in runs if r.get("variant", "default") == name and str(r.get("task")) == i
                  and counts_for_travel(r) and isinstance(r.get("tc_max"), (int, float))]
            m = sum(tc) / len(tc) if tc else 0.0
            mid.append(m)
            lo.append(m - min(tc) if tc else 0.0)
            hi.append(max(tc) - m if tc else 0.0)
        a2.bar(xs, mid, width, yerr=[lo, hi], capsize=2, label=name)
    a1.set_ylim(0, 105)
    a1.set_ylabel("SR (%)")
    a1.set_title("Success rate per task")
    a2.set_ylabel("TC-max (m), successful runs")
    a2.set_title("Longest robot travel per task (bars: spread over seeds)")
    for a in (a1, a2):
        a.set_xticks(x)
        a.set_xticklabels(ids, rotation=45, ha="right", fontsize=9)
        if len(variants) > 1:
            a.legend(fontsize=8)
    fig.tight_layout()
    pictures.save_figure(fig, path, dpi=90)
    plt.close(fig)


install_report_writer(write_report)  # Run.report() of the engine writes this report

"""The replay: a run's schedule as an animation over time in its report (robots moving on the
floor plan, what each is doing and carrying, a time slider, play and pause).

Drawn from the record alone: the simulation's recorded trajectories (``trajectories.json``: each
robot's sampled ``[t, x, y]`` and the load/unload instants of each subtask) when the domain's
simulation keeps them, else the schedule's legs (the planned motion, said so under the picture).
The floor plan is the task domain's (:meth:`pipflow.taskdomain.TaskDomain.floor_plan`: shelves,
furniture). Plain HTML: an inline SVG and a few lines of inline script, no network, no library;
the data rides in the page as JSON. Positions between samples are interpolated linearly, as the
simulation moved the bodies.

For tests and links, ``#t=12.5`` in the page's address opens the replay at that time, and each
robot's ``<circle data-robot=NAME>`` carries its position in floor metres (``data-x``, ``data-y``).
"""
from __future__ import annotations

import html
import json
from typing import Any

from pipflow.placelabels import place_labels
from pipflow.team.trajectory import ROBOT_COLOURS, Trajectory

#: the most samples a robot's track keeps in the page (longer tracks are thinned evenly; the
#: corners of a planned path are always kept)
MAX_SAMPLES = 4000


def _hex(rgba: tuple) -> str:
    return "#" + "".join(f"{int(round(255 * c)):02x}" for c in rgba[:3])


def _thin(points: list[list[float]]) -> list[list[float]]:
    if len(points) <= MAX_SAMPLES:
        return points
    step = len(points) / MAX_SAMPLES
    kept = [points[int(i * step)] for i in range(MAX_SAMPLES)]
    return kept + [points[-1]]


def _number(v: Any) -> str:
    return str(int(v)) if isinstance(v, float) and v.is_integer() else str(v)


def _planned_tracks(world: dict, schedule: dict) -> dict[str, list[list[float]]]:
    """Tracks from the schedule's legs: each robot's start, then every corner of its legs' paths
    at the time the plan passes it."""
    tracks = {}
    for r, info in (world.get("robots") or {}).items():
        legs = ((schedule.get("robots") or {}).get(r) or {}).get("legs", [])
        tr = Trajectory(info.get("start", (0, 0)), legs)
        times = sorted({0.0, *tr.vertex_times(), *(float(l.get("end", 0)) for l in legs),
                        *(float(l.get("start", 0)) for l in legs)})
        tracks[r] = [[round(t, 3), *map(lambda v: round(v, 3), tr.position(t))] for t in times]
    return tracks


def replay_data(world: dict, schedule: dict | None, graph: dict | None, recorded: dict | None,
                floor_plan: list[dict], incidents: list[dict] | None = None) -> dict | None:
    """What the page's script animates: floor, footprints, robots (colour, track), subtasks
    (robots, start, end, what they move, when the load is on), the end time, and the moments a
    run under faults went off plan (``incidents``, the page's ``events``: ``{time, kind, words}`` with ``x``/``y`` or the
    ``robot`` it struck, a closed passage's ``barrier`` [x, y, width, depth], the robot that ``stops`` there
    for good (its row then says so): a mark that appears
    at its time, and a line in the log under the floor); None without a world or anything to move."""
    if not isinstance(world, dict) or not isinstance(world.get("floor"), dict):
        return None
    schedule = schedule or {}
    tracks = (recorded or {}).get("trajectories") if isinstance(recorded, dict) else None
    source = "recorded" if isinstance(tracks, dict) and tracks else "planned"
    if source == "planned":
        if not schedule.get("robots"):
            return None
        tracks = _planned_tracks(world, schedule)
    names = list(world.get("robots") or tracks)
    nodes = {n.get("id"): n for n in (graph or {}).get("nodes", []) if isinstance(n, dict)}
    events = [e for e in ((recorded or {}).get("events") or []) if isinstance(e, dict)]
    subtasks = []
    for s in schedule.get("subtasks", []):
        node = nodes.get(s.get("id"), {})
        route = set(map(str, node.get("route") or []))
        items = [str(v) for k, v in (node.get("fields") or {}).items() if str(v) not in route]
        need = ", ".join(f"{k} {_number(v)}" for k, v in (node.get("skills") or {}).items())
        load = [e["time"] for e in events if e.get("subtask") == s.get("id") and e.get("event") == "load"]
        unload = [e["time"] for e in events if e.get("subtask") == s.get("id") and e.get("event") == "unload"]
        subtasks.append({"id": s.get("id"), "robots": list(s.get("robots") or []), "start": float(s.get("start", 0)),
                         "end": float(s.get("end", 0)),
                         "what": " ".join([str(s.get("action", ""))] + list(map(str, s.get("args") or []))),
                         "carries": (", ".join(items) + (f" ({need})" if need else "")) if items else "",
                         "load": float(load[0]) if load else None, "unload": float(unload[-1]) if unload else None})
    end = max([float(schedule.get("makespan") or 0)] + [float(p[-1][0]) for p in tracks.values() if p])
    robots = {r: {"colour": _hex(ROBOT_COLOURS[(names.index(r) if r in names else k) % len(ROBOT_COLOURS)]),
                  "track": _thin([[float(x) for x in p[:3]] for p in pts])}
              for k, (r, pts) in enumerate(sorted(tracks.items(), key=lambda kv: names.index(kv[0])
                                                  if kv[0] in names else len(names)))}
    return {"floor": {"width": float(world["floor"]["width"]), "height": float(world["floor"]["height"])},
            "places": floor_plan, "robots": robots, "subtasks": subtasks, "end": end, "source": source,
            "events": [e for e in incidents or [] if isinstance(e, dict) and isinstance(e.get("time"), (int, float))]}


_SCRIPT = """<script>
(function () {
  var data = JSON.parse(document.getElementById('replay-data').textContent);
  var svg = document.getElementById('replay-svg'), slider = document.getElementById('replay-time');
  var label = document.getElementById('replay-clock'), button = document.getElementById('replay-play');
  var speed = document.getElementById('replay-speed'), rows = document.getElementById('replay-robots');
  var H = data.floor.height;
  function at(track, t) {
    if (!track.length) { return [0, 0]; }
    if (t <= track[0][0]) { return [track[0][1], track[0][2]]; }
    var lo = 0, hi = track.length - 1;
    if (t >= track[hi][0]) { return [track[hi][1], track[hi][2]]; }
    while (hi - lo > 1) { var mid = (lo + hi) >> 1; if (track[mid][0] <= t) { lo = mid; } else { hi = mid; } }
    var a = track[lo], b = track[hi], u = b[0] > a[0] ? (t - a[0]) / (b[0] - a[0]) : 1;
    return [a[1] + u * (b[1] - a[1]), a[2] + u * (b[2] - a[2])];
  }
  function doing(robot, t) {
    var out = {doing: '', carries: ''}, next = null;
    var stop = data.events.filter(function (e) { return e.stops === robot && t >= e.time; })[0];
    if (stop) { return {doing: 'out of service since t = ' + stop.time.toFixed(1) + ' s', carries: ''}; }
    data.subtasks.forEach(function (s) {
      if (s.robots.indexOf(robot) < 0) { return; }
      if (t < s.start) { if (next === null || s.start < next.start) { next = s; } return; }
      if (t > s.end) { return; }
      out.doing = s.id + ': ' + s.what;
      var on = (s.load === null ? s.start : s.load), off = (s.unload === null ? s.end : s.unload);
      if (t >= on && t <= off) { out.carries = s.carries; }
    });
    if (!out.doing && next !== null) {
      var a = at(data.robots[robot].track, t), b = at(data.robots[robot].track, t + 0.25);
      var moving = Math.abs(a[0] - b[0]) + Math.abs(a[1] - b[1]) > 1e-6;
      out.doing = (moving ? 'on the way to ' : 'waiting for ') + next.id + ' (starts at ' + next.start.toFixed(1) + ' s)';
    }
    return out;
  }
  function show(t) {
    t = Math.max(0, Math.min(data.end, t));
    slider.value = t;
    label.textContent = 't = ' + t.toFixed(1) + ' s of ' + data.end.toFixed(1) + ' s';
    Object.keys(data.robots).forEach(function (r) {
      var p = at(data.robots[r].track, t), c = svg.querySelector('circle[data-robot="' + r + '"]');
      var name = svg.querySelector('text[data-robot="' + r + '"]'), load = svg.querySelector('text[data-load="' + r + '"]');
      var d = doing(r, t);
      c.setAttribute('cx', p[0]); c.setAttribute('cy', H - p[1]);
      c.setAttribute('data-x', p[0].toFixed(3)); c.setAttribute('data-y', p[1].toFixed(3));
      c.setAttribute('stroke-width', d.carries ? 0.12 : 0.03);
      name.setAttribute('x', p[0]); name.setAttribute('y', H - p[1] - 0.45);
      load.setAttribute('x', p[0]); load.setAttribute('y', H - p[1] + 0.75); load.textContent = d.carries;
      var row = rows.querySelector('tr[data-robot="' + r + '"]');
      row.cells[1].textContent = p[0].toFixed(1) + ', ' + p[1].toFixed(1);
      row.cells[2].textContent = d.doing || 'idle';
      row.cells[3].textContent = d.carries || '';
    });
    var shown = [];
    data.events.forEach(function (e, k) {
      var on = t >= e.time - 1e-9, mark = svg.querySelector('[data-event="' + k + '"]');
      if (on) { shown.push('t = ' + e.time.toFixed(1) + ' s  ' + e.words); }
      if (!mark) { return; }
      mark.setAttribute('visibility', on ? 'visible' : 'hidden');
      if (e.robot !== undefined && data.robots[e.robot]) {
        var q = at(data.robots[e.robot].track, e.time);
        mark.setAttribute('transform', 'translate(' + q[0] + ',' + (H - q[1]) + ')');
      }
    });
    var log = document.getElementById('replay-events');
    if (log) { log.textContent = shown.length ? shown.join('\\n') : 'nothing has gone off plan yet'; }
    document.body.dataset.replayEvents = String(shown.length);
    document.body.dataset.replayTime = t.toFixed(3);
  }
  var timer = null, last = null;
  function frame(now) {
    if (timer === null) { return; }
    if (last !== null) { show(parseFloat(slider.value) + (now - last) / 1000 * parseFloat(speed.value)); }
    last = now;
    if (parseFloat(slider.value) >= data.end) { pause(); return; }
    timer = requestAnimationFrame(frame);
  }
  function play() {
    if (parseFloat(slider.value) >= data.end) { show(0); }
    last = null; timer = requestAnimationFrame(frame); button.textContent = 'pause';
  }
  function pause() { if (timer !== null) { cancelAnimationFrame(timer); } timer = null; button.textContent = 'play'; }
  button.addEventListener('click', function () { if (timer === null) { play(); } else { pause(); } });
  slider.addEventListener('input', function () { pause(); show(parseFloat(slider.value)); });
  window.pipflowReplay = {show: show, play: play, pause: pause, data: data};
  var m = /[#&]t=([0-9.]+)/.exec(location.hash);
  show(m ? parseFloat(m[1]) : 0);
})();
</script>"""


def replay_html(data: dict) -> str:
    """The replay section: the SVG floor with robots, the controls, the robots' table."""
    fw, fh = data["floor"]["width"], data["floor"]["height"]
    parts = [f"<rect x='0' y='0' width='{fw}' height='{fh}' fill='#f4f4ef' stroke='#222' stroke-width='0.06'/>"]
    labels = place_labels([(str(pl["name"]), (pl["x"], pl["y"], pl["width"], pl["depth"])) for pl in data["places"]],
                          (fw, fh))
    for pl, label in zip(data["places"], labels):
        x, y, w, d = pl["x"], pl["y"], pl["width"], pl["depth"]
        name = html.escape(str(pl["name"]))
        cx, cy = f"{label.x:.3f}", f"{fh - label.y:.3f}"
        turn = f" transform='rotate(-90 {cx} {cy})'" if label.upright else ""
        parts.append(f"<rect x='{x}' y='{fh - y - d}' width='{w}' height='{d}' fill='#b08a66' stroke='#5a4030' "
                     f"stroke-width='0.04'><title>{name}</title></rect>"
                     f"<text x='{cx}' y='{cy}' class='{'place' if label.inside else 'place-beside'}' "
                     f"style='font-size:{label.size:.3f}px'{turn}>{name}</text>")
    for r, info in data["robots"].items():
        pts = " ".join(f"{p[1]:.2f},{fh - p[2]:.2f}" for p in info["track"])
        parts.append(f"<polyline points='{pts}' fill='none' stroke='{info['colour']}' stroke-width='0.05' "
                     "stroke-opacity='0.35'/>")
    for r, info in data["robots"].items():
        q = html.escape(r)
        parts.append(f"<circle data-robot='{q}' r='0.3' fill='{info['colour']}' stroke='#111' stroke-width='0.03'>"
                     f"<title>{q}</title></circle><text data-robot='{q}' class='robot'>{q}</text>"
                     f"<text data-load='{q}' class='load'></text>")
    colours = {"robot-loss": "#c62828", "passage-closed": "#111111", "surprise": "#7b1fa2", "slowdown": "#ef6c00"}
    for k, e in enumerate(data.get("events") or []):
        c = colours.get(e.get("kind"), "#c62828")
        title = f"<title>{html.escape(str(e.get('words', '')))}</title>"
        if e.get("barrier"):
            x, y, w, d = e["barrier"]
            parts.append(f"<g data-event='{k}' visibility='hidden'>{title}<rect x='{x}' y='{fh - y - d}' width='{w}' "
                         f"height='{d}' fill='{c}' stroke='{c}' stroke-width='0.05'/></g>")
        elif e.get("kind") == "recovery":
            continue
        elif "x" in e and "y" in e:
            parts.append(f"<g data-event='{k}' visibility='hidden' transform='translate({e['x']},{fh - e['y']})'>{title}"
                         f"<path d='M-0.5,-0.5L0.5,0.5M-0.5,0.5L0.5,-0.5' stroke='{c}' stroke-width='0.16'/>"
                         "<circle r='0.75' fill='none' stroke-width='0.08' "
                         f"stroke='{c}'/></g>")
        elif e.get("robot"):
            parts.append(f"<g data-event='{k}' visibility='hidden'>{title}<circle r='0.7' fill='none' "
                         f"stroke='{c}' stroke-width='0.12' stroke-dasharray='0.2,0.12'/></g>")
    table = "".join(f"<tr data-robot='{html.escape(r)}'><td><span style='color:{info['colour']}'>&#9679;</span> "
                    f"{html.escape(r)}</td><td></td><td></td><td></td></tr>" for r, info in data["robots"].items())
    source = ("the simulation's recorded trajectories" if data["source"] == "recorded" else
              "the schedule's planned legs (this domain's simulation records no trajectories)")
    payload = json.dumps(data, separators=(",", ":")).replace("</", "<\\/")
    return ("<h2 id='replay'>Replay</h2>"
            f"<p class='small'>The schedule over time, from {source}; a thick ring: the robot carries the "
            "subtask's load. Drag the slider, or play.</p>"
            "<style>#replay-svg text.place{font-size:.42px;fill:#fff;text-anchor:middle;dominant-baseline:middle}"
            "#replay-svg text.place-beside{fill:#3b2a1c;text-anchor:middle;dominant-baseline:middle}"
            "#replay-svg text.robot{font-size:.42px;fill:#111;text-anchor:middle;font-weight:bold}"
            "#replay-svg text.load{font-size:.36px;fill:#7a2e00;text-anchor:middle}"
            ".replay-wrap{display:flex;gap:1.5em;align-items:flex-start;flex-wrap:wrap}"
            "#replay-svg{flex:0 1 600px;width:600px;max-width:100%;border:1px solid #ccc;background:white}"
            ".replay-controls{margin:.4em 0} .replay-controls input[type=range]{width:460px;vertical-align:middle}</style>"
            f"<div class='replay-controls'><button id='replay-play' type='button'>play</button> "
            f"<input id='replay-time' type='range' min='0' max='{data['end']:.3f}' step='0.1' value='0'> "
            "<span id='replay-clock'></span> speed <select id='replay-speed'><option value='1'>1x</option>"
            "<option value='2'>2x</option><option value='5' selected>5x</option><option value='10'>10x</option></select></div>"
            f"<div class='replay-wrap'><svg id='replay-svg' viewBox='-0.5 -0.5 {fw + 1} {fh + 1}' "
            f"xmlns='http://www.w3.org/2000/svg'>{''.join(parts)}</svg>"
            "<table id='replay-robots'><tr><th>robot</th><th>at (m)</th><th>doing</th><th>carrying</th></tr>"
            f"{table}</table></div>"
            + ("<p class='small'>Faults and recoveries so far (a cross where a fault struck, a black bar: a closed "
               "passage, a dashed ring: a robot slowed):</p><pre id='replay-events'></pre>" if data.get("events") else "")
            + 
            f"<script type='application/json' id='replay-data'>{payload}</script>" + _SCRIPT)


def replay_section(world: Any, schedule: Any, graph: Any, recorded: Any, floor_plan: list[dict],
                   incidents: list[dict] | None = None) -> str:
    """The report's replay section, or ``""`` when the record has nothing to replay."""
    data = replay_data(world, schedule if isinstance(schedule, dict) else None,
                       graph if isinstance(graph, dict) else None, recorded, floor_plan, incidents)
    return replay_html(data) if data else ""

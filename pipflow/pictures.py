"""Matplotlib pictures shared by the simulation and the report: the floor map with the robots'
paths, an animation of it, the Gantt chart of a schedule and the dependency graph.

They live apart from the simulator because the report redraws them from a run record (JSON)
without pybullet. matplotlib is imported inside each function with the Agg backend, so
importing this module is cheap and never needs a display."""
from __future__ import annotations

import io
import tempfile
from pathlib import Path
from typing import Any

from pipflow.engine.writes import write_file
from pipflow.placelabels import place_labels
from pipflow.taskdomains import task_domain
from pipflow.team.trajectory import ROBOT_COLOURS, Trajectory

#: ``pictures`` workflow input: ``always`` draws them during the run; ``never`` draws none (the
#: report neither); ``auto`` leaves them to ``pipflow report``, which draws those below
#: :data:`AUTO_LIMITS`. Why not in the run by default: matplotlib's import and drawing were 0.65 s
#: of a 1.4 s main job, and a Gantt chart of 1000 robots took 32 s that nobody looked at.
MODES = ("auto", "always", "never")
#: the largest picture ``auto`` draws: rows of the Gantt chart (robots that work), subtasks of the
#: graph, robots that moved on the path map; beyond that a picture is unreadable and slow.
AUTO_LIMITS = {"gantt": 60, "graph": 80, "paths": 60}


def wanted(mode: str | None, kind: str, size: int) -> bool:
    """Whether to draw picture ``kind`` (a key of :data:`AUTO_LIMITS`) of ``size`` under ``mode``
    (``None`` means ``auto``)."""
    mode = mode or "auto"
    if mode not in MODES:
        raise ValueError(f"pictures must be one of {', '.join(MODES)}, not {mode!r}")
    return mode == "always" or (mode == "auto" and size <= AUTO_LIMITS[kind])


def size_of(kind: str, data: dict) -> int:
    """The size :func:`wanted` judges: Gantt rows (robots with work), graph nodes, moving robots."""
    if kind == "gantt":
        return len(_working_robots(data))
    if kind == "graph":
        return len(data.get("nodes", []))
    return sum(1 for pts in data.values() if len(pts) > 1)  # paths: {robot: [[t, x, y], ...]}


def _working_robots(schedule: dict) -> list[str]:
    """Robots with a leg or a subtask: the rows of a Gantt chart (idle robots have none)."""
    robots = [r for r, info in (schedule.get("robots") or {}).items() if info.get("legs")]
    for s in schedule.get("subtasks", []):
        robots += [r for r in s.get("robots", []) if r not in robots]
    return sorted(set(robots), key=natural_key)


def save_figure(fig: Any, path: Path, **options: Any) -> Path:
    """Write a matplotlib figure to ``path`` through pipflow's one writer: drawn into memory, then
    written atomically, so a link at ``path`` (in a record someone else could write) is replaced,
    never written through, and a full disk is a :class:`~pipflow.engine.writes.DiskError`."""
    buffer = io.BytesIO()
    fig.savefig(buffer, format=Path(path).suffix.lstrip(".") or "png", **options)
    return write_file(path, buffer.getvalue())


def _plt():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def robot_colour(i: int) -> tuple:

    return ROBOT_COLOURS[i % len(ROBOT_COLOURS)]


def draw_floor(ax, world: dict) -> None:
    """Floor outline, the world's fixtures (its task domain's places: footprint, name and access
    point)."""
    from matplotlib.patches import Rectangle

    fw, fh = float(world["floor"]["width"]), float(world["floor"]["height"])
    ax.add_patch(Rectangle((0, 0), fw, fh, fill=False, lw=1.5, ec="black"))
    for name, fixture in task_domain(world).places(world).items():
        ax.add_patch(Rectangle((fixture["x"], fixture["y"]), fixture["width"], fixture["depth"], fc="#b08a66",
                               ec="#5a4030"))
        ax.plot(*fixture["access"], marker="x", color="#5a4030", ms=6)
    ax.set_xlim(-0.5, fw + 0.5)
    ax.set_ylim(-0.5, fh + 0.5)
    ax.set_aspect("equal")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")


def name_places(ax, world: dict) -> None:
    """Write each place's name where it can be read (:func:`pipflow.placelabels.place_labels`),
    sized to the axes as laid out: call it after ``tight_layout``, which sets how many points a
    metre takes. A drop place's name is red; a name beside its place is in dark ink."""
    ax.apply_aspect()
    fig, box = ax.figure, ax.get_position()
    (x0, x1), (y0, y1) = ax.get_xlim(), ax.get_ylim()
    per_metre = 72 * min(box.width * fig.get_figwidth() / (x1 - x0), box.height * fig.get_figheight() / (y1 - y0))
    places = task_domain(world).places(world)
    labels = place_labels([(n, (f["x"], f["y"], f["width"], f["depth"])) for n, f in places.items()],
                          (float(world["floor"]["width"]), float(world["floor"]["height"])),
                          largest=8 / per_metre, smallest=5.5 / per_metre, beside=7 / per_metre)
    for (name, f), label in zip(places.items(), labels):
        ink = "#c62828" if f.get("drop") else "white" if label.inside else "#3b2a1c"
        ax.text(label.x, label.y, name, ha="center", va="center", fontsize=label.size * per_metre,
                rotation=90 if label.upright else 0, color=ink)


def path_map(world: dict, trajectories: dict[str, list], path: Path, travel: dict | None = None) -> Path:
    """Top-down map: each robot's simulated path (``[[t, x, y], ...]``) in its colour, start dot,
    travelled metres in the legend."""
    plt = _plt()
    fig, ax = plt.subplots(figsize=(9, 6.5))
    draw_floor(ax, world)
    index = {r: i for i, r in enumerate(world.get("robots", {}))}
    idle = [pts[0] for pts in trajectories.values() if len(pts) == 1]
    for r, pts in sorted(trajectories.items(), key=lambda kv: natural_key(kv[0])):  # robot2 before robot10
        if len(pts) < 2:
            continue  # idle robots: one grey dot each below, no legend row (a thousand would hide the map)
        c = robot_colour(index.get(r, len(index)))
        xs, ys = [p[1] for p in pts], [p[2] for p in pts]
        label = f"{r} ({travel[r]:.1f} m)" if travel and r in travel else r
        ax.plot(xs, ys, "-", color=c, lw=1.6, alpha=0.85, label=label)
        ax.plot(xs[0], ys[0], "o", color=c, ms=6)
        ax.plot(xs[-1], ys[-1], "s", color=c, ms=5)
    if idle:
        ax.plot([p[1] for p in idle], [p[2] for p in idle], "o", color="#999999", ms=3,
                label=f"{len(idle)} idle robot{'s' if len(idle) != 1 else ''}")
    ax.legend(fontsize=9, loc="upper left", bbox_to_anchor=(1.01, 1.0), title="robot (travel)", title_fontsize=9)
    ax.set_title("Robot paths (o start, \u25a0 end)")
    fig.tight_layout()
    name_places(ax, world)
    save_figure(fig, path, dpi=90)
    plt.close(fig)
    return Path(path)


def animation_gif(world: dict, trajectories: dict[str, list], path: Path, makespan: float,
                  frames: int = 40) -> Path | None:
    """Top-down animation of the robots; None when Pillow (needed by PillowWriter) is missing."""
    try:
        import PIL  # noqa: F401
    except ImportError:
        return None
    from matplotlib.animation import FuncAnimation, PillowWriter


    plt = _plt()
    fig, ax = plt.subplots(figsize=(5, 3.5), dpi=72)
    draw_floor(ax, world)
    name_places(ax, world)
    names = list(world.get("robots", {}))
    # replay the recorded samples as a trajectory (one leg through all recorded points)
    replay = {}
    for r, pts in trajectories.items():
        if len(pts) > 1:
            legs = [{"from": p[1:], "to": q[1:], "path": [p[1:], q[1:]], "start": p[0], "end": q[0]}
                    for p, q in zip(pts, pts[1:])]
            replay[r] = Trajectory(pts[0][1:], legs)
        elif pts:
            replay[r] = Trajectory(pts[0][1:], [])
    dots = {r: ax.plot([], [], "o", ms=7, color=robot_colour(names.index(r) if r in names else 0))[0]
            for r in replay}
    title = ax.set_title("")

    def draw(k: int):
        t = makespan * k / max(frames - 1, 1)
        for r, tr in replay.items():
            x, y = tr.position(t)
            dots[r].set_data([x], [y])
        title.set_text(f"t = {t:.1f} s")
        return list(dots.values()) + [title]

    anim = FuncAnimation(fig, draw, frames=frames, blit=False)
    with tempfile.TemporaryDirectory(prefix="pipflow-gif-") as scratch:  # Pillow writes a named file only
        drawn = Path(scratch) / "animation.gif"
        anim.save(drawn, writer=PillowWriter(fps=10))
        write_file(path, drawn.read_bytes())
    plt.close(fig)
    return Path(path)


#: the tallest Gantt chart drawn, whatever the number of robots (inches; 5,400 pixels at 90 dpi)
GANTT_MAX_INCHES = 60.0
#: subtask colours of the Gantt chart: distinct, and none grey (grey is travel without a load)
SUBTASK_COLOURS = ["#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b", "#e377c2", "#bcbd22",
                   "#17becf", "#393b79", "#e6550d", "#31a354", "#756bb1", "#843c39", "#d6616b", "#637939"]
#: travel to a subtask, empty (the approach): the only grey of the chart
TRAVEL_GREY = "#cccccc"


def subtask_colour(k: int) -> str:
    return SUBTASK_COLOURS[k % len(SUBTASK_COLOURS)]


def gantt(schedule: dict, path: Path) -> Path:
    """One row per robot that works. Grey bars: travel to a subtask, empty (the approach). A
    coloured box: a subtask, from its start to its end, its id at the left; the darker box inside
    it: the part of the subtask spent travelling with the load between its places (the route),
    the rest of the box being loading and unloading. The legend says so. Subtask colours are
    never grey. Idle robots get no row (the title counts them): with a thousand robots the chart
    stays readable and cheap."""
    from matplotlib.patches import Patch

    plt = _plt()
    robots = _working_robots(schedule)
    idle = len(set(schedule.get("robots") or {}) - set(robots))
    # rows thin out past 130 robots rather than the canvas growing with them (a chart of 20,000
    # working robots would be a 9,000-inch image: gigabytes of pixels)
    fig, ax = plt.subplots(figsize=(10, min(GANTT_MAX_INCHES, max(2.5, 0.45 * len(robots) + 1.6))))
    row = {r: i for i, r in enumerate(robots)}
    colour = {s.get("id"): subtask_colour(k) for k, s in enumerate(schedule.get("subtasks", []))}
    spans = {s.get("id"): (float(s["start"]), float(s["end"])) for s in schedule.get("subtasks", [])}
    for k, s in enumerate(schedule.get("subtasks", [])):
        for r in s.get("robots", []):
            ax.barh(row[r], max(float(s["end"]) - float(s["start"]), 1e-3), left=float(s["start"]),
                    height=0.62, color=colour[s.get("id")], alpha=0.45, edgecolor="black", lw=0.6)
            ax.text(float(s["start"]), row[r], f" {s['id']}", va="center", fontsize=7)
    for r, info in (schedule.get("robots") or {}).items():
        for leg in info.get("legs", []) if r in row else []:
            start, end = float(leg["start"]), float(leg["end"])
            span = spans.get(leg.get("subtask"))
            carrying = span is not None and start >= span[0] - 1e-6 and end <= span[1] + 1e-6
            ax.barh(row[r], end - start, left=start, height=0.3,
                    color=colour[leg.get("subtask")] if carrying else TRAVEL_GREY,
                    edgecolor="#333333" if carrying else "#999999", lw=0.5, alpha=0.9 if carrying else 1.0)
    ax.set_yticks(range(len(robots)))
    ax.set_yticklabels(robots, fontsize=8)
    ax.invert_yaxis()
    ax.set_xlabel("time (s)")
    ax.set_title(f"Schedule (makespan {float(schedule.get('makespan', 0)):.1f} s"
                 + (f"; {idle} idle robot{'s' if idle != 1 else ''} not shown)" if idle else ")"))
    first = subtask_colour(0)
    ax.legend(handles=[Patch(facecolor=TRAVEL_GREY, edgecolor="#999999", label="travel to a subtask, empty"),
                       Patch(facecolor=first, alpha=0.45, edgecolor="black", label="subtask (id at left): start to end"),
                       Patch(facecolor=first, alpha=0.9, edgecolor="#333333",
                             label="inside it: travel with the load; the rest: loading, unloading")],
              loc="upper center", bbox_to_anchor=(0.5, -0.16 if len(robots) > 3 else -0.3), ncol=3, fontsize=8,
              frameon=False)
    fig.tight_layout()
    save_figure(fig, path, dpi=90)
    plt.close(fig)
    return Path(path)


def dependency_graph(graph: dict, path: Path) -> Path:
    """The subtask DAG top to bottom by longest path from the roots: each subtask a box sized to
    its label (its id, action and arguments, the same ids as the plan table and the Gantt chart),
    each layer centred, arrows from a subtask to those that wait for it."""
    import networkx as nx
    from matplotlib.patches import FancyBboxPatch

    plt = _plt()
    g = nx.DiGraph()
    labels = {}
    for n in graph.get("nodes", []):
        g.add_node(n["id"])
        args = list(map(str, n.get("args", [])))
        labels[n["id"]] = f"{n['id']}: {n.get('action', '')}\n" + " ".join(args)
    g.add_edges_from(tuple(e) for e in graph.get("edges", []))
    layers = [sorted(layer, key=natural_key) for layer in nx.topological_generations(g)]
    char_w, box_h, gap_x, gap_y = 0.075, 0.55, 0.35, 0.55
    width = {v: max(1.2, char_w * max(len(line) for line in labels.get(v, v).split("\n")) + 0.3) for v in g}
    pos = {}
    for depth, layer in enumerate(layers):
        x = -(sum(width[v] for v in layer) + gap_x * (len(layer) - 1)) / 2
        for v in layer:
            pos[v] = (x + width[v] / 2, -depth * (box_h + gap_y))
            x += width[v] + gap_x
    xs = [pos[v][0] + s * width[v] / 2 for v in g for s in (-1, 1)] or [0.0, 1.0]
    ys = [y for _, y in pos.values()] or [0.0]
    fig, ax = plt.subplots(figsize=(min(30.0, max(5.0, max(xs) - min(xs) + 1.0)),
                                    min(40.0, max(2.5, max(ys) - min(ys) + 1.6))))
    for u, v in g.edges:
        (xu, yu), (xv, yv) = pos[u], pos[v]
        ax.annotate("", xy=(xv, yv + box_h / 2), xytext=(xu, yu - box_h / 2),
                    arrowprops={"arrowstyle": "-|>", "color": "#555", "lw": 0.9, "shrinkA": 0, "shrinkB": 0})
    for v, (x, y) in pos.items():
        ax.add_patch(FancyBboxPatch((x - width[v] / 2, y - box_h / 2), width[v], box_h, boxstyle="round,pad=0.02",
                                    facecolor="#cfe3f7", edgecolor="#336699"))
        ax.text(x, y, labels[v], ha="center", va="center", fontsize=8)
    ax.set_xlim(min(xs) - 0.3, max(xs) + 0.3)
    ax.set_ylim(min(ys) - box_h - 0.3, max(ys) + box_h + 0.3)
    ax.set_aspect("equal")
    ax.axis("off")
    ax.set_title(f"Dependency graph ({graph.get('mode', '?')} mode, {g.number_of_nodes()} subtasks, "
                 f"{len(layers)} levels)", fontsize=9)
    save_figure(fig, path, dpi=100, bbox_inches="tight")
    plt.close(fig)
    return Path(path)


def natural_key(name: str) -> Any:
    """Sort key that puts robot2 before robot10."""
    import re

    return [int(t) if t.isdigit() else t for t in re.split(r"(\d+)", name)]


# ------------------------------------------------------------------------------------------
# faults and recovery (pipflow.execution): where and when things went wrong
# ------------------------------------------------------------------------------------------
#: how each fault kind is marked on the map and the Gantt chart
FAULT_MARKS = {"robot-loss": ("X", "#c62828"), "slowdown": ("v", "#ef6c00"), "passage-closed": ("s", "#000000"),
               "surprise": ("*", "#8e24aa")}


def _fixtures(ax, world: dict) -> None:
    """Every footprint of the floor (shelves, household places, drop places; their names are
    written by :func:`name_places` once the figure is laid out)."""
    from matplotlib.patches import Rectangle

    for name, f in task_domain(world).places(world).items():
        drop = bool(f.get("drop"))
        ax.add_patch(Rectangle((f["x"], f["y"]), f["width"], f["depth"], fc="#e0b0b0" if drop else "#b08a66",
                               ec="#c62828" if drop else "#5a4030"))


def fault_map(world: dict, schedule: dict, faults: list[dict], rounds: list[dict], path: Path) -> Path:
    """Top-down map of a run under faults: each robot's path as driven (the schedule's legs), and
    where each fault struck: a red X where a robot stopped, a black bar where a passage closed, a
    purple star at a place whose contents surprised, an orange triangle where a slow robot was
    noticed; each labelled with its time and the recovery round that answered it."""
    from matplotlib.patches import Rectangle

    plt = _plt()
    fig, ax = plt.subplots(figsize=(9, 6.5))
    fw, fh = float(world["floor"]["width"]), float(world["floor"]["height"])
    ax.add_patch(Rectangle((0, 0), fw, fh, fill=False, lw=1.5, ec="black"))
    _fixtures(ax, world)
    index = {r: i for i, r in enumerate(world.get("robots", {}))}
    for r, info in sorted((schedule.get("robots") or {}).items(), key=lambda kv: natural_key(kv[0])):
        legs = info.get("legs") or []
        if not legs:
            continue
        c = robot_colour(index.get(r, 0))
        for leg in legs:
            pts = leg.get("path") or [leg["from"], leg["to"]]
            ax.plot([p[0] for p in pts], [p[1] for p in pts], "-", color=c, lw=1.4, alpha=0.8)
        ax.plot(*legs[0]["from"], "o", color=c, ms=5)
        ax.plot([], [], "-", color=c, label=r)
    fixtures = task_domain(world).places(world)
    answered = {r.get("cause", {}).get("fault"): r.get("round") for r in rounds}
    for f in faults:
        marker, colour = FAULT_MARKS.get(f.get("kind"), ("o", "grey"))
        when = f"t={f['time']:.0f}s" if f.get("time") is not None else ""
        label = f"{f.get('id')} {f.get('name')} {when}" + (f" (R{answered[f.get('id')]})" if f.get("id") in answered else "")
        if f.get("kind") == "passage-closed" and f.get("barrier"):
            b = f["barrier"]
            ax.add_patch(Rectangle((b["x"], b["y"]), b["width"], b["depth"], fc="black", ec="black", hatch="//"))
            ax.annotate(label, (b["x"] + b["width"] / 2, b["y"] + b["depth"]), fontsize=7, ha="center", va="bottom")
        elif f.get("kind") == "surprise":
            for place in (f.get("surprise") or {}).get("places") or []:
                if place in fixtures:
                    x, y = fixtures[place]["access"]
                    ax.plot(x, y, marker, color=colour, ms=14, mec="black")
                    ax.annotate(label, (x, y), textcoords="offset points", xytext=(6, 6), fontsize=7, color=colour)
        elif f.get("point"):
            x, y = f["point"]
            ax.plot(x, y, marker, color=colour, ms=13, mew=3)
            ax.annotate(f"{f.get('robot')}: {label}", (x, y), textcoords="offset points", xytext=(6, -10),
                        fontsize=7, color=colour)
        elif f.get("robot") and f.get("detected") is not None:
            legs = ((schedule.get("robots") or {}).get(f["robot"]) or {}).get("legs") or []
            if legs:
                x, y = Trajectory(legs[0]["from"], legs).position(float(f["detected"]))
                ax.plot(x, y, marker, color=colour, ms=11)
                ax.annotate(f"{f['robot']}: {label}", (x, y), textcoords="offset points", xytext=(6, 6),
                            fontsize=7, color=colour)
    ax.set_xlim(-0.5, fw + 0.5)
    ax.set_ylim(-0.5, fh + 0.5)
    ax.set_aspect("equal")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0), title="robot", title_fontsize=8)
    ax.set_title("Faults and the paths as driven (X robot stopped, bar passage closed, * surprise, v slow)")
    fig.tight_layout()
    name_places(ax, world)
    save_figure(fig, path, dpi=90)
    plt.close(fig)
    return Path(path)


def fault_gantt(schedule: dict, faults: list[dict], rounds: list[dict], path: Path) -> Path:
    """The Gantt chart of the schedule carried out, with a dashed line at each recovery (its round
    and action) and, on a robot's row, the mark of the fault that struck it."""
    plt = _plt()
    robots = _working_robots(schedule)
    row = {r: i for i, r in enumerate(robots)}
    fig, ax = plt.subplots(figsize=(10, max(2.5, 0.45 * len(robots) + 1.6)))
    for r, info in (schedule.get("robots") or {}).items():
        for leg in info.get("legs", []) if r in row else []:
            ax.barh(row[r], float(leg["end"]) - float(leg["start"]), left=float(leg["start"]), height=0.35,
                    color="#cccccc", edgecolor="#999999")
    for k, s in enumerate(schedule.get("subtasks", [])):
        for r in s.get("robots", []):
            if r in row:
                ax.barh(row[r], max(float(s["end"]) - float(s["start"]), 1e-3), left=float(s["start"]), height=0.6,
                        color=robot_colour(k), alpha=0.75, edgecolor="black", lw=0.5)
                ax.text(float(s["start"]), row[r], f" {s['id']}", va="center", fontsize=7)
    for rd in rounds:
        t = float(rd.get("time", 0.0))
        ax.axvline(t, color="#c62828", ls="--", lw=1)
        ax.text(t, -0.9, f"R{rd.get('round')} {rd.get('action')}", color="#c62828", fontsize=7, rotation=0)
    for f in faults:
        marker, colour = FAULT_MARKS.get(f.get("kind"), ("o", "grey"))
        if f.get("robot") in row and f.get("time") is not None:
            ax.plot(float(f["time"]), row[f["robot"]], marker, color=colour, ms=11, mew=3)
    ax.set_yticks(range(len(robots)))
    ax.set_yticklabels(robots, fontsize=8)
    ax.set_ylim(len(robots) - 0.5, -1.3)
    ax.set_xlabel("time (s)")
    ax.set_title(f"Schedule carried out (makespan {float(schedule.get('makespan', 0)):.1f} s); "
                 "dashed: recoveries; marks: faults")
    fig.tight_layout()
    save_figure(fig, path, dpi=90)
    plt.close(fig)
    return Path(path)

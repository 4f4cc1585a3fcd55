"""Pictures that say what they show (issue 25), read back from the PNGs pipflow writes: the Gantt
chart's subtasks are never drawn in the travel grey and its legend (below the axes) explains the
grey bars and the box inside a subtask; pybullet snapshots carry their time and names; the bench
chart's legend sits above the axes, never on the bars."""
from __future__ import annotations

import json
from pathlib import Path

import numpy as np
from PIL import Image

import pipflow
from pipflow import pictures


def _rgb(path: Path) -> np.ndarray:
    return np.asarray(Image.open(path).convert("RGB")).astype(int)


def _axes_box(img: np.ndarray) -> tuple[int, int, int, int]:
    """(top, bottom, left, right) of the black frame of a chart with one axes: the rows and
    columns that are dark over most of their length."""
    dark = img.sum(axis=2) < 200
    rows = np.where(dark.mean(axis=1) > 0.5)[0]
    cols = np.where(dark.mean(axis=0) > 0.3)[0]
    return rows.min(), rows.max(), cols.min(), cols.max()


def test_gantt_subtasks_are_never_grey_and_the_legend_explains_the_boxes(tmp_path):
    n = 16  # more subtasks than the colours before issue 25 held without a grey
    schedule = {"makespan": float(n), "robots": {"robot1": {"legs": [], "distance": 0.0}},
                "subtasks": [{"id": f"s{k + 1}", "action": "move", "args": [], "robots": ["robot1"],
                              "start": float(k), "end": float(k + 1)} for k in range(n)]}
    path = pictures.gantt(schedule, tmp_path / "gantt.png")
    img = _rgb(path)
    top, bottom, left, right = _axes_box(img)
    y = (top + bottom) // 2 + 6  # inside the one row, below its labels
    lo, hi = -0.05 * n, n * 1.05  # matplotlib's 5% margins around the bars
    for k in range(n):
        x = int(left + (k + 0.7 - lo) / (hi - lo) * (right - left))
        r, g, b = img[y, x]
        assert max(r, g, b) - min(r, g, b) > 20, (f"s{k + 1}", (r, g, b))  # a colour, not a grey
    below = img[bottom + 30:]
    travel = (np.abs(below - np.array([204, 204, 204])).sum(axis=2) < 6).sum()
    assert travel > 20, "the legend below the chart shows the grey travel bar"


def test_snapshots_are_labelled_with_time_and_names(tmp_path):
    run = pipflow.run("warehouse", runs_dir=tmp_path / "runs", snapshots=True,
                      command="shelf2 holds 9 product1")
    assert run.status == "succeeded", run.error
    art = run.record / "steps" / "simulate" / "artifacts"
    shots = sorted(art.glob("snapshot_*.png"))
    assert len(shots) >= 3
    for shot in shots:
        img = _rgb(shot)
        corner = img[4:30, 4:150]
        assert (corner.sum(axis=2) < 150).mean() > 0.03, shot.name  # the time, dark on the caption box
    # the robots' name tags: boxes in each robot's colour (darkened) in the picture
    world = json.loads((run.record / "steps" / "world" / "outputs.json").read_text())["world"]
    from pipflow.team.trajectory import ROBOT_COLOURS

    img = _rgb(shots[0])
    found = 0
    for i, _ in enumerate(world["robots"]):
        tag = np.array([int(255 * c * 0.8) for c in ROBOT_COLOURS[i % len(ROBOT_COLOURS)][:3]])
        found += int((np.abs(img - tag).sum(axis=2) <= 3).sum() > 40)
    assert found >= len(world["robots"]) // 2


def test_bench_chart_legend_sits_above_the_bars(tmp_path, monkeypatch):
    import yaml

    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("PIPFLOW_CACHE_DIR", str(tmp_path / "cache"))
    repo = Path(__file__).resolve().parents[1]
    doc = yaml.safe_load((repo / "benchmarks/warehouse/tasks.yaml").read_text())
    doc["tasks"] = doc["tasks"][:1]
    doc["world"] = str(repo / "benchmarks/warehouse/world.yaml")
    (tmp_path / "t.yaml").write_text(yaml.safe_dump(doc))
    out = Path(pipflow.bench(tmp_path / "t.yaml", matrix={"graph_mode": ["exact", "paper"]})["out"])
    from pipflow.records.report import write_report

    write_report(out)
    img = _rgb(out / "report" / "overview.png")
    dark = img.sum(axis=2) < 200
    frame_rows = np.where(dark.mean(axis=1) > 0.3)[0]
    first_frame = frame_rows.min()  # the top edge of the upper chart's axes
    above = img[:first_frame]
    colours = [np.array([31, 119, 180]), np.array([255, 127, 14])]  # the two variants' bars (tab10)
    for c in colours:
        assert (np.abs(above - c).sum(axis=2) < 30).sum() > 30, "each variant's legend patch is above the axes"

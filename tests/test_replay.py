"""The replay of a run's schedule in its report, driven in a real headless Chromium: the test sets
the slider to two times, screenshots each, and checks each robot's drawn position against the
recorded trajectories (linear between samples, as the simulation moved the bodies)."""
from __future__ import annotations

import json
from pathlib import Path

import pytest

import pipflow
from cdp import Browser, looks_drawn
from pipflow.records.report import write_report


def _at(track: list, t: float) -> tuple[float, float]:
    """Where a recorded track puts the robot at ``t`` (linear between samples)."""
    if t <= track[0][0]:
        return track[0][1], track[0][2]
    for a, b in zip(track, track[1:]):
        if a[0] <= t <= b[0]:
            u = (t - a[0]) / (b[0] - a[0]) if b[0] > a[0] else 1.0
            return a[1] + u * (b[1] - a[1]), a[2] + u * (b[2] - a[2])
    return track[-1][1], track[-1][2]


@pytest.fixture(scope="module")
def warehouse_run(tmp_path_factory) -> Path:
    runs = tmp_path_factory.mktemp("replay") / "runs"
    run = pipflow.run("warehouse", runs_dir=runs, seed=3,
                      command="shelf4 stores a dozen product3 and a quintet of product1.")
    assert run.status == "succeeded", run.error
    return run.record


def _drawn(browser: Browser) -> dict[str, tuple[float, float]]:
    got = browser.eval("Array.from(document.querySelectorAll('#replay-svg circle[data-robot]')).map("
                       "c => [c.dataset.robot, parseFloat(c.dataset.x), parseFloat(c.dataset.y),"
                       " parseFloat(c.getAttribute('cx')), parseFloat(c.getAttribute('cy'))])")
    return {r: (x, y, cx, cy) for r, x, y, cx, cy in got}


def _set_time(browser: Browser, t: float) -> None:
    browser.eval(f"(() => {{ const s = document.getElementById('replay-time'); s.value = '{t}';"
                 " s.dispatchEvent(new Event('input')); return s.value; })()")


def test_the_replay_moves_the_robots_as_recorded(warehouse_run, tmp_path):
    page = write_report(warehouse_run)
    recorded = json.loads((warehouse_run / "steps" / "simulate" / "artifacts" / "trajectories.json").read_text())
    tracks = recorded["trajectories"]
    world = json.loads((warehouse_run / "steps" / "world" / "outputs.json").read_text())["world"]
    height = float(world["floor"]["height"])
    makespan = json.loads((warehouse_run / "outputs.json").read_text())["makespan"]
    t1, t2 = 4.0, round(0.6 * makespan, 1)
    with Browser(1400, 1100) as browser:
        browser.goto(page.resolve().as_uri() + "#replay")
        assert browser.eval("document.getElementById('replay-time').max") == f"{recorded_end(tracks, makespan):.3f}"
        seen = {}
        for n, t in enumerate((t1, t2), 1):
            _set_time(browser, t)
            assert abs(float(browser.eval("document.body.dataset.replayTime")) - t) < 1e-6
            assert browser.eval("document.getElementById('replay-clock').textContent").startswith(f"t = {t:.1f} s")
            browser.eval("document.getElementById('replay').scrollIntoView()")
            looks_drawn(browser.screenshot(tmp_path / f"replay_t{n}.png"))
            seen[t] = _drawn(browser)
            doing = browser.eval("Array.from(document.querySelectorAll('#replay-robots tr[data-robot]'))"
                                 ".map(r => [r.dataset.robot, r.cells[2].textContent, r.cells[3].textContent])")
            seen[(t, "doing")] = {r: (d, c) for r, d, c in doing}
        assert not [c for c in browser.console if c.startswith("Uncaught")], browser.console
    for t in (t1, t2):
        for robot, track in tracks.items():
            x, y, cx, cy = seen[t][robot]
            ex, ey = _at(track, t)
            assert abs(x - ex) < 0.01 and abs(y - ey) < 0.01, (robot, t, (x, y), (ex, ey))
            assert abs(cx - ex) < 0.01 and abs(cy - (height - ey)) < 0.01  # drawn where it is (y up on the floor)
    moved = [r for r in tracks if abs(seen[t1][r][0] - seen[t2][r][0]) + abs(seen[t1][r][1] - seen[t2][r][1]) > 0.5]
    assert moved, "no robot moved between the two times"
    # at t2 someone is carrying, as the schedule's subtasks and the load events say
    schedule = json.loads((warehouse_run / "outputs.json").read_text())["schedule"]
    busy = {r for s in schedule["subtasks"] if s["start"] <= t2 <= s["end"] for r in s["robots"]}
    assert busy and all(seen[(t2, "doing")][r][0].startswith(tuple(s["id"] + ":" for s in schedule["subtasks"]))
                        for r in busy)


def recorded_end(tracks: dict, makespan: float) -> float:
    return max([float(makespan)] + [float(p[-1][0]) for p in tracks.values() if p])


def test_play_advances_and_a_link_opens_at_a_time(warehouse_run):
    page = write_report(warehouse_run)
    with Browser(1200, 900) as browser:
        browser.goto(page.resolve().as_uri() + "#t=12.5")
        assert browser.eval("document.body.dataset.replayTime") == "12.500"
        browser.eval("document.getElementById('replay-play').click()")
        later = browser.eval("new Promise(done => setTimeout(() => done(document.body.dataset.replayTime), 1500))")
        assert float(later) > 12.5  # playing moves the clock on
        assert browser.eval("document.getElementById('replay-play').textContent") == "pause"
        browser.eval("document.getElementById('replay-play').click()")
        assert browser.eval("document.getElementById('replay-play').textContent") == "play"


def test_a_domain_without_recorded_trajectories_replays_its_planned_legs(tmp_path):
    run = pipflow.run("household", runs_dir=tmp_path / "runs",
                      command="Put the apple in the fridge and switch off the floor lamp.")
    assert run.status == "succeeded", run.error
    html = write_report(run.record).read_text()
    assert "<h2 id='replay'>Replay</h2>" in html and "the schedule's planned legs" in html
    data = json.loads(html.split("<script type='application/json' id='replay-data'>")[1].split("</script>")[0])
    assert data["source"] == "planned" and {"fridge", "floorlamp"} <= {p["name"] for p in data["places"]}
    assert any(len(v["track"]) > 2 for v in data["robots"].values())  # someone walks

"""The report of a run under faults shows what was carried out, not what was planned (issue 27):
the plan as carried out (the first plan's subtasks that were done, a re-plan's new ones, who did
them), the schedule as carried out, a replay of the world as it really was (a robot's cargo on
its drop place, the fault marked where and when it struck, each recovery in the log as the
clock passes it), the recovery rounds with what they did with the rest of the run, and the world
as it really was. Through the real pipeline and a real headless Chromium."""
from __future__ import annotations

import json
from pathlib import Path

import pytest

import pipflow
from cdp import Browser, looks_drawn
from pipflow.records.report import write_report

WH10 = "shelf4 stores a dozen product3 and a quintet of product1."


def _replay_data(html: str) -> dict:
    return json.loads(html.split("<script type='application/json' id='replay-data'>")[1].split("</script>")[0])


@pytest.fixture(scope="module")
def lost_while_carrying(tmp_path_factory):
    """WH10, seed 3: a robot stops half way along a move it carries units on (a re-plan)."""
    runs = tmp_path_factory.mktemp("fault-report") / "runs"
    base = pipflow.run("warehouse", command=WH10, seed=3, runs_dir=runs, cache=False)
    records = {s["id"]: s for s in base.outputs["schedule"]["subtasks"]}
    for robot, info in sorted(base.outputs["schedule"]["robots"].items()):
        for leg in info.get("legs") or []:
            rec = records.get(leg.get("subtask"))
            if rec and float(leg["start"]) > float(rec["start"]) and float(leg["end"]) - float(leg["start"]) > 2.0:
                t = round((float(leg["start"]) + float(leg["end"])) / 2, 3)
                run = pipflow.run("warehouse", command=WH10, seed=3, runs_dir=runs, cache=False,
                                  faults=[{"kind": "robot-loss", "robot": robot, "time": t}])
                assert run.status == "succeeded", run.error
                return base, run, robot, t
    raise AssertionError("no carrying leg in WH10's schedule")


def test_the_report_shows_the_run_as_carried_out(lost_while_carrying):
    base, run, robot, t = lost_while_carrying
    html = write_report(run.record).read_text()
    rounds = run.outputs["recoveries"]
    assert [r["action"] for r in rounds] == ["re-plan"]
    new = rounds[0]["replanned"]
    carried = {s["id"]: s for s in run.outputs["schedule"]["subtasks"]}
    # the plan as carried out: the re-plan's subtasks with the robots that did them, where they came from
    plan = html.split("<h2 id='plan'>Team plan as carried out</h2>")[1].split("<details>")[0]
    for sid in new:
        row = plan.split(f"<td>{sid}</td>")[1].split("</tr>")[0]
        assert ", ".join(carried[sid]["robots"]) in row and "re-planned in round 1" in row
    assert f"{carried[new[0]]['start']:.1f}" in plan
    # what the first plan had that a re-plan set aside is said, and the first plan is still there, folded
    assert "Set aside by a re-plan" in plan and "the plan as first made" in html
    assert "<h2>Schedule as carried out</h2>" in html and "<h2>Schedule</h2>" not in html
    # the recovery round says what it did with the rest of the run, and how long it took
    section = html.split("<h2 id='faults'>Faults and recovery</h2>")[1]
    assert "the rest of the run" in section and f"{new[0]} (" in section and "set aside" in section
    # the world as it really was: the robot out of service, where its cargo lies
    drop = next(f for f in run.outputs["faults"] if f["kind"] == "robot-loss")["drop"]
    assert "The world as it really was" in section and f"{robot} out of service" in section and drop in section
    # the final observed state: what lies on the drop place at the end, which the records never had
    final = run.outputs["simulation"]["final_stock"]
    state = section.split("The state: records, as found, at the end")[1]
    for product, n in final[drop].items():
        assert f"<td>{drop} {product}</td><td class='num'>&ndash;</td><td class='num'>&ndash;</td><td class='num'>{n}</td>" in state
    # a count gone from a shelf the final state lists is none left (0), never drawn as unknown
    table = state.split("</table>")[0]
    records = json.loads((Path(run.record) / "steps" / "world" / "outputs.json").read_text())["world"]["stock"]
    emptied = [f"{shelf} {product}" for shelf, held in records.items() for product, n in held.items()
               if n and shelf in final and product not in final[shelf]]
    assert emptied, "WH10 empties some shelf of a product"
    for name in emptied:
        assert table.split(f"<td>{name}</td>")[1].split("</tr>")[0].endswith("<td class='num'>0</td>")


def test_the_replay_plays_the_executed_schedule_in_the_real_world(lost_while_carrying, tmp_path):
    base, run, robot, t = lost_while_carrying
    page = write_report(run.record)
    data = _replay_data(page.read_text())
    # the executed schedule (the re-plan's subtasks), not the planned one; the drop place is on the floor
    replanned = set(run.outputs["recoveries"][0]["replanned"])
    assert replanned <= {s["id"] for s in data["subtasks"]}
    assert not replanned & {s["id"] for s in base.outputs["schedule"]["subtasks"]}
    drop = next(f for f in run.outputs["faults"] if f["kind"] == "robot-loss")["drop"]
    assert drop in {p["name"] for p in data["places"]}
    assert [e["kind"] for e in data["events"]] == ["robot-loss", "recovery"]
    assert data["events"][0]["time"] == pytest.approx(t, abs=1e-3)
    with Browser(1400, 1100) as browser:
        browser.goto(page.resolve().as_uri() + "#replay")
        for when, shown in ((max(0.0, t - 2.0), 0), (t + 3.0, 2)):
            browser.eval(f"(() => {{ const s = document.getElementById('replay-time'); s.value = '{when}';"
                         " s.dispatchEvent(new Event('input')); return s.value; })()")
            assert browser.eval("document.body.dataset.replayEvents") == str(shown)
            mark = browser.eval("document.querySelector('#replay-svg [data-event=\"0\"]').getAttribute('visibility')")
            assert mark == ("visible" if shown else "hidden")
            row = browser.eval(f"document.querySelector('#replay-robots tr[data-robot=\"{robot}\"]').cells[2].textContent")
            assert row.startswith("out of service since t = ") == bool(shown), row
            log = browser.eval("document.getElementById('replay-events').textContent")
            if shown:
                assert robot in log and "recovery 1: re-plan" in log
            else:
                assert log == "nothing has gone off plan yet"
            browser.eval("document.getElementById('replay').scrollIntoView()")
            looks_drawn(browser.screenshot(tmp_path / f"fault-replay-{shown}.png"))
        # the robot that stopped stays where the fault put it
        stopped = browser.eval(f"document.querySelector('#replay-svg circle[data-robot=\"{robot}\"]').dataset.x")
        point = next(f for f in run.outputs["faults"] if f["kind"] == "robot-loss")["point"]
        assert abs(float(stopped) - point[0]) < 0.05
        browser.eval("document.getElementById('faults').scrollIntoView()")
        looks_drawn(browser.screenshot(tmp_path / "fault-section.png"))
        assert not [c for c in browser.console if c.startswith("Uncaught")], browser.console

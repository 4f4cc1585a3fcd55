"""What a household run and a household bench look like (issue 25), rendered in a real headless
Chromium: the run report's Simulation section with labelled snapshots and the goal in plain
words; the bench report's per-category table (SR, understood, RU, Exe; SR a percent everywhere),
right refusals apart from the errors, and charts shown at their own size (scrolled, never
squeezed); the CLI's household table with SR in percent like the other table."""
from __future__ import annotations

import os
import re
import subprocess
from pathlib import Path

import numpy as np
import pytest
import yaml

import pipflow
from cdp import Browser, looks_drawn
from pipflow.records.report import write_report
from cli_entry import PIPFLOW

REPO = Path(__file__).resolve().parents[1]
#: two tasks of each of the paper's categories; hx-23 ("heat the mug") is impossible: refusing is right
TASKS = ("hc-01", "hc-03", "hx-01", "hx-23", "hv-01", "hv-24")


@pytest.fixture(scope="module")
def household_bench(tmp_path_factory) -> tuple[Path, str]:
    root = tmp_path_factory.mktemp("hbench")
    doc = yaml.safe_load((REPO / "benchmarks/household/tasks.yaml").read_text())
    doc["tasks"] = [t for t in doc["tasks"] if t["id"] in TASKS]
    doc["world"] = str(REPO / "benchmarks/household/world.yaml")
    (root / "tasks.yaml").write_text(yaml.safe_dump(doc))
    env = {**os.environ, "PIPFLOW_CACHE_DIR": str(root / "cache")}
    out = subprocess.run([PIPFLOW, "bench", "tasks.yaml", "--out", "hb", "--jobs", "2"], cwd=root, env=env,
                         capture_output=True, text=True, timeout=3000)
    assert out.returncode == 0, out.stderr[-3000:]
    return root / "hb", out.stdout


def test_household_cli_table_gives_sr_in_percent(household_bench):
    _, table = household_bench
    head = next(line for line in table.splitlines() if line.startswith("| Category |"))
    assert "| SR (%) | understood (%) |" in head
    every = next(line for line in table.splitlines() if line.startswith("| **all** |"))
    sr = every.split("|")[4].strip()
    assert re.fullmatch(r"\d{1,3}", sr), every  # a percent, as in the warehouse table, not 0.83
    hx23 = next(line for line in table.splitlines() if line.startswith("| hx-23 |"))
    assert hx23.split("|")[3].strip() == "100"


def test_household_bench_report(household_bench, tmp_path):
    bench, _ = household_bench
    page = write_report(bench)
    html = page.read_text()
    per = html.split("<h2 id='per-category'>Per category</h2>")[1].split("</table>")[0]
    heads = re.findall(r"<th>([^<]*)</th>", per)
    assert heads[:3] == ["category", "tasks", "runs"] and {"SR", "understood", "RU", "Exe"} <= set(heads)
    rows = re.findall(r"<tr>(.*?)</tr>", per)[1:]
    assert [re.sub(r"<[^>]+>", "", r.split("</td>")[0]) for r in rows] == ["compound", "complex", "vague", "all"]
    for r in rows:
        sr = re.sub(r"<[^>]+>", "", r.split("</td>")[3])
        assert re.match(r"\d{1,3}%", sr), r  # SR a percent in every table
    summary = html.split("<h2 id='summary'>Summary</h2>")[1].split("</table>")[0]
    assert "<th>RU</th>" in summary and "<th>Exe</th>" in summary and re.search(r">\d{1,3}%", summary)
    # the right refusal of the impossible task is not an error
    refusals = html.split("<h3 id='refusals'>")[1].split("</ul>")[0]
    assert "hx-23" in refusals and "mug cannot be hot" in refusals
    errors = html.split("<h3 id='errors'>")[1].split("</ul>")[0] if "<h3 id='errors'>" in html else ""
    assert "hx-23" not in errors
    with Browser(1400, 1000) as b:
        b.goto(page.as_uri())
        charts = b.eval("Array.from(document.querySelectorAll('.chart img')).map(i => [i.naturalWidth, i.width,"
                        " i.parentElement.clientWidth, i.parentElement.scrollWidth])")
        assert len(charts) == 3  # one chart per category, at its own size
        for natural, shown, box, scroll in charts:
            assert natural == shown, charts  # never squeezed to the page
            assert scroll >= min(natural, scroll) and box <= 1400
        b.eval("document.getElementById('per-category').scrollIntoView()")
        looks_drawn(b.screenshot(tmp_path / "household_bench_report.png"), min_colour=0.001)
        looks_drawn(b.screenshot(tmp_path / "household_bench_report_full.png", full_page=True))
        assert not [c for c in b.console if c.startswith("Uncaught")], b.console


def test_household_run_report_shows_the_simulation(tmp_path):
    run = pipflow.run("household", runs_dir=tmp_path / "runs", snapshots=True,
                      command="Put the apple in the fridge and switch off the floor lamp.")
    assert run.status == "succeeded", run.error
    page = run.report()
    html = page.read_text()
    understood = html.split("<h2>Understood</h2>")[1].split("</ul>")[0]
    assert "fridge holds apple" in understood and "floorlamp: off" in understood
    assert "[" not in understood and "&#x27;" not in understood  # words, not Python lists
    with Browser(1400, 1000) as b:
        b.goto(page.as_uri())
        looks_drawn(b.screenshot(tmp_path / "household_run_report.png", full_page=True))
    assert "snapshot_1_start.png" in html and "snapshot_2_end.png" in html
    assert "<h2>Simulation</h2>" in html  # the household's simulation, shown as the warehouse's is
    # each snapshot is labelled: the time in the top left corner, names on places and robots
    from PIL import Image

    img = np.asarray(Image.open(run.record / "steps" / "simulate" / "artifacts" / "snapshot_2_end.png").convert("RGB"))
    corner = img[4:30, 4:140].astype(int)
    assert (corner.sum(axis=2) < 150).mean() > 0.03  # dark text on the caption's white box

"""Comparisons a researcher can trust, and records found the way every command names them
(issue 25): compare of matrix benches per variant with intervals over seeds and shares as
percents (CLI and the view's page), the matrix view of a 4-variant bench driven in Chromium (a
metric menu, a cell's panel, a seed's link to its run report), one resolver for show, report,
compare, resume and view (``latest``, ``-N``, a bare run id, a bench's name), ``pipflow runs``
and the view's index with the command and the headline, ``show`` short by default, and the
view listing ``bench-out/``."""
from __future__ import annotations

import json
import os
import re
import subprocess
import urllib.request
from pathlib import Path

import pytest
import yaml

from cdp import Browser, looks_drawn
from cli_entry import PIPFLOW

REPO = Path(__file__).resolve().parents[1]
TASKS = ("wh-04", "wh-06", "wh-10")  # several moves each: the variants differ


def pipflow_cli(*args: str, cwd: Path, check: bool = True, **kw) -> subprocess.CompletedProcess:
    out = subprocess.run([PIPFLOW, *args], cwd=cwd, capture_output=True, text=True, timeout=1800, **kw)
    if check:
        assert out.returncode == 0, out.stderr[-3000:]
    return out


@pytest.fixture(scope="module")
def place(tmp_path_factory) -> Path:
    """A working folder as a researcher's: two runs in runs/, and in bench-out/ (where `pipflow
    bench` writes by default) a 4-variant matrix bench with 2 seeds and a 1-variant bench."""
    root = tmp_path_factory.mktemp("place")
    doc = yaml.safe_load((REPO / "benchmarks/warehouse/tasks.yaml").read_text())
    doc["tasks"] = [t for t in doc["tasks"] if t["id"] in TASKS]
    doc["world"] = str(REPO / "benchmarks/warehouse/world.yaml")
    (root / "tasks.yaml").write_text(yaml.safe_dump(doc))
    env = {**os.environ, "PIPFLOW_CACHE_DIR": str(root / "cache")}
    pipflow_cli("run", "warehouse", "-q", "-i", "command=shelf2 holds 9 product1", cwd=root, env=env)
    pipflow_cli("run", "warehouse", "-q", "-i", "command=shelf4 stores a dozen product3 and a quintet of product1.",
                cwd=root, env=env)
    pipflow_cli("bench", "tasks.yaml", "--seeds", "2", "--jobs", "2", "--matrix",
                "workflow=warehouse,warehouse-greedy", "--matrix", "graph_mode=deorder,paper", cwd=root, env=env)
    pipflow_cli("bench", "tasks.yaml", "--jobs", "2", "-i", "graph_mode=paper", cwd=root, env=env)
    return root


def _benches(place: Path) -> tuple[Path, Path]:
    found = sorted((place / "bench-out").iterdir())
    four = next(b for b in found if len(json.loads((b / "results.json").read_text())["variants"]) == 4)
    one = next(b for b in found if b != four)
    return four, one


def test_compare_of_matrix_benches_is_per_variant_with_intervals(place):
    four, one = _benches(place)
    out = pipflow_cli("compare", str(four), str(one), cwd=place).stdout
    # a column per variant of each bench: A1..A4 for the matrix bench, B for the other
    for key, variant in (("A1", "workflow=warehouse,graph_mode=deorder"), ("A2", "workflow=warehouse,graph_mode=paper"),
                         ("A3", "workflow=warehouse-greedy,graph_mode=deorder"),
                         ("A4", "workflow=warehouse-greedy,graph_mode=paper")):
        assert re.search(rf"^  {key} = .*{re.escape(variant)}$", out, re.M), out[:800]
    assert re.search(r"^  B = ", out, re.M)
    # shares are percents with their Wilson interval, never fractions
    sr = next(line for line in out.splitlines() if line.startswith("wh-04 SR (%)"))
    assert "100% [34, 100]" in sr and "1.0" not in sr  # 2 of 2 seeds: Wilson 95% is 34% to 100%
    # the variants differ, and the differences are shown (the greedy allocator travels otherwise)
    every = next(line for line in out.splitlines() if line.startswith("all tasks TC-max (m)"))
    diffs = re.findall(r"\(([+-]\d+\.\d\d)\)", every)
    assert len(diffs) == 4 and any(abs(float(d)) > 0.05 for d in diffs), every
    assert "Wilson score interval" in out and "Student t-interval" in out


def test_records_are_named_the_same_way_by_every_command(place):
    four, _ = _benches(place)
    runs = sorted((place / "runs").iterdir())
    newest = max(runs, key=lambda r: json.loads((r / "run.json").read_text())["started"])
    rid = newest.name.rsplit("-", 1)[1]  # the run's id: the end of its folder name
    report = pipflow_cli("report", "latest", cwd=place).stdout.strip()
    assert report == str((newest / "report.html").resolve())
    assert pipflow_cli("report", rid, cwd=place).stdout.strip() == report
    assert pipflow_cli("report", four.name, cwd=place).stdout.strip() == str((four / "report.html").resolve())
    both = pipflow_cli("compare", "latest", "-2", cwd=place).stdout
    assert "A = runs/" in both and "B = runs/" in both and "tc_max (m)" in both
    assert pipflow_cli("compare", rid, "-2", cwd=place).stdout.splitlines()[1:3] == both.splitlines()[1:3]
    assert pipflow_cli("show", rid, cwd=place).stdout.startswith(f"run       runs/{newest.name}")
    resumed = pipflow_cli("resume", rid, cwd=place, check=False)  # found by its id; finished, so nothing to do
    assert resumed.returncode == 2 and f"{newest.name}: this run already succeeded" in resumed.stderr
    nothing = pipflow_cli("report", "nosuchrun", cwd=place, check=False)
    assert nothing.returncode == 2 and "no run or bench 'nosuchrun'" in nothing.stderr and "Traceback" not in nothing.stderr


def test_runs_and_show_say_what_was_asked_and_how_it_went(place):
    listing = pipflow_cli("runs", cwd=place).stdout.splitlines()
    assert len(listing) == 2
    line = next(x for x in listing if "shelf2 holds 9 product1" in x)
    assert "succeeded" in line and "goal met" in line and re.search(r"makespan \d+\.\d s", line)
    short = pipflow_cli("show", "latest", cwd=place).stdout
    assert len(short.splitlines()) < 40 and "command   shelf4 stores a dozen" in short
    assert "result    goal met" in short and "pipflow show latest --full" in short
    assert '"subtasks"' not in short  # the schedule is summarised, not printed whole
    full = pipflow_cli("show", "latest", "--full", cwd=place).stdout
    assert '"subtasks"' in full and len(full.splitlines()) > 200


def test_view_lists_runs_and_benches_with_command_and_result(place):
    proc = subprocess.Popen([PIPFLOW, "view", "--no-browser"], cwd=place, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True)
    try:
        first = proc.stdout.readline()
        url = re.search(r"(http://127\.0\.0\.1:\d+/)", first).group(1)
        assert "bench-out" in first  # both folders are viewed
        index = urllib.request.urlopen(url, timeout=60).read().decode()
        four, one = _benches(place)
        assert f"/report/bench-out/{four.name}" in index and f"/report/bench-out/{one.name}" in index
        assert index.count("<td>run</td>") == 2  # the benches' own runs are reached through their bench
        assert "shelf2 holds 9 product1" in index and "goal met, makespan" in index
        assert "matrix workflow=warehouse,warehouse-greedy; graph_mode=deorder,paper" in index
        picked = f"compare?r=bench-out/{four.name}&r=bench-out/{one.name}"
        page = urllib.request.urlopen(url + picked, timeout=300).read().decode()
        assert "Compare 2 benches" in page and page.count("<th class='variant'>") == 5
        assert "wh-04 SR (%)" in page and "100% [34, 100]" in page
    finally:
        proc.terminate()
        proc.wait(timeout=30)


def test_matrix_view_of_a_four_variant_bench(place, tmp_path):
    four, _ = _benches(place)
    page = Path(pipflow_cli("report", str(four), cwd=place).stdout.strip())
    html = page.read_text()
    assert html.count("<th class='variant'>") == 4 and "id='matrix'" in html
    with Browser(1400, 1000) as b:
        b.goto(page.as_uri())
        assert b.eval("document.querySelectorAll('table.matrix td.cell').length") == 4 * (len(TASKS) + 1)
        b.eval("document.getElementById('matrix').scrollIntoView()")
        looks_drawn(b.screenshot(tmp_path / "matrix_view_4_variants.png"))
        first = "document.querySelector('table.matrix td.cell .metric').textContent"
        tc = b.eval(first)
        assert re.fullmatch(r"\d+\.\d\d \[\d+\.\d\d, \d+\.\d\d\]", tc), tc  # TC-max with its interval
        b.eval("(() => { const m = document.getElementById('matrix-metric'); m.value = 'makespan';"
               " m.dispatchEvent(new Event('change')); })()")
        assert b.eval(first) != tc and b.eval("document.querySelector('.metric-name').textContent") == "makespan (s)"
        b.eval("document.querySelector('table.matrix td.cell').click()")
        panel = b.eval("document.getElementById('matrix-panel').innerHTML")
        assert not b.eval("document.getElementById('matrix-panel').hidden")
        for anchor in ("#loop", "#plan", "#pictures"):
            assert f"report.html{anchor}" in panel
        b.screenshot(tmp_path / "matrix_view_panel.png")
        seed = b.eval("document.querySelector('table.matrix td.cell .seeds a').href")
        b.goto(seed)  # a seed opens its run's report, not a folder listing
        assert b.eval("document.title").startswith("pipflow run:")
        assert b.eval("!!document.getElementById('plan') && !!document.getElementById('loop')")
        assert not [c for c in b.console if c.startswith("Uncaught")], b.console


def test_seed_links_of_the_bench_report_open_run_reports(place):
    four, _ = _benches(place)
    html = (four / "report.html").read_text() if (four / "report.html").is_file() else \
        Path(pipflow_cli("report", str(four), cwd=place).stdout.strip()).read_text()
    links = re.findall(r"href='([^']*)'>seed \d+</a>", html)
    assert len(links) == 4 * len(TASKS) * 2
    assert all(link.endswith("/report.html") and (four / link).is_file() for link in links)

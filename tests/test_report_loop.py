"""What a researcher sees of a run through a model: the Python API, and the report's refinement
loop (each round's prompt, answer and check messages), driven through a scripted
OpenAI-compatible server on loopback, i.e. litellm's real HTTP path.

The report is rendered by headless Chromium; set PIPFLOW_SCREENSHOTS=DIR to keep the
screenshots for a look."""
from __future__ import annotations

import os
import re
import shutil
from pathlib import Path

import pytest

import pipflow
from fake_openai import FakeOpenAI
from test_report import render

REPO = Path(__file__).resolve().parents[1]
WAREHOUSE = REPO / "workflows" / "warehouse.yaml"
COMMAND = "shelf4 stores a dozen product3 and a quintet of product1."
CUT_OFF = "Sure! (define (problem p) (:domain warehouse) (:objects shelf1 - shelf"
GOOD = """(define (problem task) (:domain warehouse)
  (:objects shelf1 shelf2 shelf3 shelf4 - shelf product1 product2 product3 product4 - product
            magnitude1 magnitude2 magnitude3 magnitude4 magnitude5 magnitude6 - magnitude)
  (:init
    (= (stock shelf1 product1) 10) (= (stock shelf1 product2) 2) (= (stock shelf1 product3) 3) (= (stock shelf1 product4) 0)
    (= (load shelf1) 15) (= (capacity shelf1) 30)
    (= (stock shelf2 product1) 8) (= (stock shelf2 product2) 5) (= (stock shelf2 product3) 6) (= (stock shelf2 product4) 2)
    (= (load shelf2) 21) (= (capacity shelf2) 30)
    (= (stock shelf3 product1) 5) (= (stock shelf3 product2) 3) (= (stock shelf3 product3) 4) (= (stock shelf3 product4) 4)
    (= (load shelf3) 16) (= (capacity shelf3) 30)
    (= (stock shelf4 product1) 15) (= (stock shelf4 product2) 0) (= (stock shelf4 product3) 2) (= (stock shelf4 product4) 6)
    (= (load shelf4) 23) (= (capacity shelf4) 30)
    (= (amount magnitude1) 1) (= (amount magnitude2) 2) (= (amount magnitude3) 3) (= (amount magnitude4) 4)
    (= (amount magnitude5) 5) (= (amount magnitude6) 6))
  (:goal (and (= (stock shelf4 product3) 12) (= (stock shelf4 product1) 5))))"""


@pytest.fixture(autouse=True)
def _key(monkeypatch):
    monkeypatch.setenv("OPENAI_API_KEY", "sk-test-not-a-real-key")


def _keep(shot: Path, name: str) -> None:
    keep = os.environ.get("PIPFLOW_SCREENSHOTS")
    if keep:
        Path(keep).mkdir(parents=True, exist_ok=True)
        shutil.copy(shot, Path(keep) / name)


def test_python_api_runs_the_offline_main_job(tmp_path):
    run = pipflow.run("warehouse", runs_dir=tmp_path, command="There should be 7 product1 in shelf3.")
    assert run.ok and run.status == "succeeded" and run.error is None
    assert run.outputs["goal"] == {"shelf3": {"product1": 7}}
    assert run.outputs["goal_met"] is True
    assert run.record.parent == tmp_path and (run.record / "run.json").is_file()


def test_python_api_reports_a_refusal_as_a_status(tmp_path):
    run = pipflow.run(WAREHOUSE, runs_dir=tmp_path, command="shelf1 holds 500 product1")
    assert run.status == "refused" and not run.ok
    assert "500" in run.error


def test_report_shows_every_round_of_a_model_loop(tmp_path):
    with FakeOpenAI([CUT_OFF, f"```pddl\n{GOOD}\n```"]) as server:
        run = pipflow.run(WAREHOUSE, runs_dir=tmp_path, model="openai/fake", api_base=server.api_base,
                          command=COMMAND, cache=False)
        prompts = server.prompts()
    assert run.status == "succeeded", run.error
    assert len(prompts) == 2 and COMMAND in prompts[0]
    page = run.report().read_text(encoding="utf-8")
    assert "Refinement loop" in page
    assert page.count("class='round'") == 2
    assert "round 1 <span class='bad'>rejected</span>" in page and "round 2 <span class='ok'>passed</span>" in page
    # round 1: the prompt as sent, the raw answer and the messages the model was told
    assert "user message" in page and COMMAND.replace(".", "") in page
    assert "Sure! (define (problem p)" in page
    assert "never closed" in page  # the generator's note on the cut-off answer
    # round 2's prompt carried that feedback: the report shows what the model was told
    assert "never closed" in prompts[1]
    assert "(= (stock shelf4 product3) 12)" in page
    # the model's goal read back into an order, explained with the words it came from
    assert "<h2>Understood</h2>" in page and "shelf4 product3: 2 now, set 12 -&gt; 12" in page
    shot = tmp_path / "report.png"
    dom = render(run.record / "report.html", shot)
    assert "Refinement loop" in dom
    _keep(shot, "run_report_llm_loop.png")


def test_a_failed_loop_puts_its_cause_at_the_top(tmp_path):
    with FakeOpenAI([CUT_OFF]) as server:
        run = pipflow.run(WAREHOUSE, runs_dir=tmp_path, model="openai/fake", api_base=server.api_base,
                          command=COMMAND, rounds=2, cache=False)
        assert len(server.requests) == 2
    assert run.status == "failed" and run.error_step == "refine"
    # the message itself quotes the last round's checks, not only "reached its maximum"
    assert "round 2 ended with: generate: the PDDL problem" in run.error and "never closed" in run.error
    events = (run.record / "events.jsonl").read_text()
    assert '"step": "refine", "status": "succeeded"' not in events.replace("'", '"')
    page = run.report().read_text(encoding="utf-8")
    cause = page.index("Why it failed")
    assert cause < page.index("<h2>Command</h2>")
    assert re.search(r"Round 2 of loop <code>refine</code> ended with:</p><ul><li>[^<]*never closed", page)


def test_progress_tells_ok_from_rejected_from_not_run():
    import io

    from pipflow.engine.progress import LiveProgress, PlainProgress

    out = io.StringIO()
    plain = PlainProgress(stream=out)
    plain({"event": "end", "step": "debug", "iteration": 1, "duration": 0.1, "verdict": "rejected"})
    plain({"event": "end", "step": "solve", "iteration": 1, "duration": 0.1})
    lines = out.getvalue().splitlines()
    assert " no    debug #1" in lines[0] and " ok    solve #1" in lines[1]
    live = LiveProgress(["debug", "refine", "graph"], stream=io.StringIO())
    try:
        live({"event": "end", "step": "debug", "duration": 0.1, "verdict": "rejected"})
        live({"event": "error", "step": "refine", "status": "failed"})
        assert [r[0] for r in live.rows.values()] == ["rejected", "failed", "not run"]
    finally:
        live.close()

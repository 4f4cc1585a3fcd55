"""Running workflows: loops, conditions, inputs, concurrency, time-outs, retries, failure
records, resume, the cache and exit codes. Steps from the demo plugin (tests/fixtures/plugin_pkg)
count their calls in files, so the tests see what really ran."""
from __future__ import annotations

import json
import textwrap
from pathlib import Path

import pytest

from pipflow.engine import RunOptions, resume_run, run_workflow
from pipflow.engine.cli import main

WORKFLOWS = Path(__file__).resolve().parent / "fixtures" / "workflows"
LOOP_DEMO = WORKFLOWS / "loop_demo.yaml"


def write(path: Path, text: str) -> Path:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(textwrap.dedent(text).lstrip())
    return path


def events(run_dir: Path) -> list[dict]:
    return [json.loads(line) for line in (run_dir / "events.jsonl").read_text().splitlines() if line.strip()]


def of(evs: list[dict], kind: str, step: str) -> list[dict]:
    return [e for e in evs if e["event"] == kind and e.get("step") == step]


def run_info(run_dir: Path) -> dict:
    return json.loads((run_dir / "run.json").read_text())


def only_run(runs: Path) -> Path:
    dirs = [p for p in runs.iterdir() if p.is_dir()]
    assert len(dirs) == 1, dirs
    return dirs[0]


def cli_run(runs: Path, *args: str) -> tuple[int, Path | None]:
    code = main(["run", "-q", "--runs-dir", str(runs), *args])
    dirs = sorted(p for p in runs.iterdir()) if runs.exists() else []
    return code, (dirs[-1] if dirs else None)


def counter(path: Path) -> int:
    return int(path.read_text()) if path.exists() else 0


# --- loops and conditions -------------------------------------------------------------------

def test_loop_runs_until_its_condition_seeing_the_previous_iteration(engine_env):
    result = run_workflow(LOOP_DEMO, runs_dir=engine_env / "runs")
    assert result.ok, result.error
    assert result.outputs == {"final": 3, "rounds": 3, "message": "hello: reached 3 in 3 rounds"}
    # every iteration is recorded and each one added 1 to the previous one's output
    iters = result.run_dir / "steps" / "count" / "iterations"
    seen = [json.loads((iters / str(n) / "bump" / "outputs.json").read_text())["value"] for n in (1, 2, 3)]
    assert seen == [1, 2, 3]
    assert not (iters / "4").exists()
    loop_end = of(events(result.run_dir), "end", "count")
    assert loop_end and loop_end[0]["iterations"] == 3
    assert [e["done"] for e in events(result.run_dir) if e["event"] == "iteration"] == [False, False, True]
    assert json.loads((result.run_dir / "outputs.json").read_text()) == result.outputs


def test_previous_is_none_in_the_first_iteration(engine_env):
    wf = write(engine_env / "prev.yaml", """
        pipflow: 1
        name: prev
        steps:
          - id: l
            loop:
              max: 3
              until: ${iteration >= 3}
              steps:
                - id: x
                  uses: core.value
                  with: {value: "${[iteration, previous.x.value]}"}
        outputs: {last: "${x.value}"}
    """)
    result = run_workflow(wf, runs_dir=engine_env / "runs")
    assert result.ok, result.error
    assert result.outputs["last"] == [3, [2, [1, None]]]


def test_loop_reaching_max_fails_with_on_max_fail(engine_env):
    result = run_workflow(LOOP_DEMO, {"target": 10}, runs_dir=engine_env / "runs")
    assert result.status == "failed"
    assert result.error_step == "count"
    assert "maximum of 5" in result.error
    # everything done before the failure is kept: five iterations and the loop's own record
    assert (result.run_dir / "steps" / "count" / "iterations" / "5" / "bump" / "outputs.json").exists()
    assert json.loads((result.run_dir / "steps" / "count" / "outputs.json").read_text()) == {"iterations": 5, "done": False}
    assert not of(events(result.run_dir), "start", "big")


def test_loop_reaching_max_continues_with_the_last_result(engine_env):
    wf = write(engine_env / "cont.yaml", LOOP_DEMO.read_text().replace("on_max: fail", "on_max: continue"))
    result = run_workflow(wf, {"target": 10}, runs_dir=engine_env / "runs")
    assert result.ok, result.error
    assert result.outputs["final"] == 5 and result.outputs["rounds"] == 5
    assert "reached 5 in 5 rounds" in result.outputs["message"]


def test_when_false_skips_the_step(engine_env):
    result = run_workflow(LOOP_DEMO, {"target": 2}, runs_dir=engine_env / "runs")
    assert result.ok, result.error
    assert result.outputs["message"] is None
    evs = events(result.run_dir)
    assert of(evs, "skip", "big") and not of(evs, "start", "big")
    assert json.loads((result.run_dir / "steps" / "big" / "outputs.json").read_text()) == {"message": None}


# --- inputs -------------------------------------------------------------------------------

def test_cli_input_is_coerced_to_the_declared_type(engine_env):
    code, run = cli_run(engine_env / "runs", str(LOOP_DEMO), "-i", "target=4")
    assert code == 0
    assert json.loads((run / "inputs.json").read_text())["target"] == 4  # an int, not "4"
    assert json.loads((run / "outputs.json").read_text())["final"] == 4


def test_cli_input_of_the_wrong_type_is_a_user_error(engine_env, capsys):
    code, run = cli_run(engine_env / "runs", str(LOOP_DEMO), "-i", "target=four")
    assert code == 2 and run is None
    assert "target" in capsys.readouterr().err


def test_inputs_file(engine_env):
    f = write(engine_env / "in.yaml", "target: 2\ngreeting: hi\n")
    code, run = cli_run(engine_env / "runs", str(LOOP_DEMO), "--inputs", str(f))
    assert code == 0
    assert json.loads((run / "outputs.json").read_text()) == {"final": 2, "rounds": 2, "message": None}
    assert json.loads((run / "inputs.json").read_text()) == {"target": 2, "greeting": "hi"}


def test_inputs_file_and_cli_values_mix(engine_env):
    f = write(engine_env / "in.yaml", "target: 2\ngreeting: hi\n")
    code, run = cli_run(engine_env / "runs", str(LOOP_DEMO), "--inputs", str(f), "-i", "target=3")
    assert code == 0
    assert json.loads((run / "outputs.json").read_text())["message"] == "hi: reached 3 in 3 rounds"


def test_unknown_input_exits_2_with_a_hint(engine_env, capsys):
    code, run = cli_run(engine_env / "runs", str(LOOP_DEMO), "-i", "targt=4")
    err = capsys.readouterr().err
    assert code == 2 and run is None
    assert "unknown input 'targt'" in err and "did you mean 'target'" in err


def test_env_reference_with_default(engine_env, monkeypatch):
    monkeypatch.delenv("DEMO_GREETING", raising=False)
    assert run_workflow(LOOP_DEMO, runs_dir=engine_env / "r1").outputs["message"].startswith("hello:")
    monkeypatch.setenv("DEMO_GREETING", "ahoy")
    assert run_workflow(LOOP_DEMO, runs_dir=engine_env / "r2").outputs["message"].startswith("ahoy:")


def test_path_inputs_are_relative_to_the_workflow_file(engine_env, monkeypatch):
    wf = write(engine_env / "sub" / "paths.yaml", """
        pipflow: 1
        name: paths
        inputs:
          data: {type: path, default: data/file.txt}
        steps:
          - id: p
            uses: core.value
            with: {value: "${inputs.data}"}
        outputs: {data: "${p.value}"}
    """)
    (engine_env / "sub" / "data").mkdir()
    (engine_env / "sub" / "data" / "file.txt").write_text("x")  # a default path must name a file that exists
    elsewhere = engine_env / "elsewhere"
    elsewhere.mkdir()
    monkeypatch.chdir(elsewhere)
    result = run_workflow(wf, runs_dir=engine_env / "runs")
    assert result.outputs["data"] == str(engine_env / "sub" / "data" / "file.txt")
    # a relative path given on the command line is relative to where the command runs
    code, run = cli_run(engine_env / "runs2", str(wf), "-i", "data=mine.txt")
    assert code == 0
    assert json.loads((run / "outputs.json").read_text())["data"] == str(elsewhere / "mine.txt")


def test_path_arguments_of_steps_are_relative_to_the_workflow_file(engine_env, demo_registry, monkeypatch):
    wf = write(engine_env / "sub" / "count.yaml", """
        pipflow: 1
        name: count-path
        steps:
          - id: c
            uses: demo.flaky
            with: {counter: calls.txt, failures: 0}
    """)
    monkeypatch.chdir(engine_env)
    assert run_workflow(wf, runs_dir=engine_env / "runs", registry=demo_registry).ok
    assert counter(engine_env / "sub" / "calls.txt") == 1
    assert not (engine_env / "calls.txt").exists()


# --- concurrency, time-outs, retries ----------------------------------------------------------

PAIR = """
    pipflow: 1
    name: pair
    steps:
      - id: a
        uses: demo.sleep
        with: {seconds: 0.3, tag: a}
      - id: b
        uses: demo.sleep
        with: {seconds: 0.3, tag: b}
      - id: c
        uses: core.value
        with: {value: ["${a.tag}", "${b.tag}"]}
    outputs: {tags: "${c.value}"}
"""


@pytest.mark.parametrize("jobs", [1, 2])
def test_jobs_runs_independent_steps_concurrently(engine_env, demo_registry, jobs):
    wf = write(engine_env / "pair.yaml", PAIR)
    result = run_workflow(wf, runs_dir=engine_env / "runs", options=RunOptions(jobs=jobs), registry=demo_registry)
    assert result.ok and result.outputs["tags"] == ["a", "b"]
    evs = events(result.run_dir)
    start = {s: of(evs, "start", s)[0]["t"] for s in "abc"}
    end = {s: of(evs, "end", s)[0]["t"] for s in "abc"}
    first, second = sorted("ab", key=start.get)
    if jobs == 2:
        assert start[second] < end[first], "with --jobs 2, b must start before a ends"
    else:
        assert start[second] >= end[first], "with --jobs 1, steps run one after the other"
    assert start["c"] >= max(end["a"], end["b"]), "a dependent step waits for both"


def test_step_timeout_gives_a_clear_error(engine_env, demo_registry):
    wf = write(engine_env / "slow.yaml", """
        pipflow: 1
        name: slow
        steps:
          - id: slow
            uses: demo.sleep
            timeout: 0.2
            with: {seconds: 1.0}
    """)
    result = run_workflow(wf, runs_dir=engine_env / "runs", registry=demo_registry)
    assert result.status == "failed" and result.error_step == "slow"
    assert "timed out after 0.2 s" in result.error
    assert result.seconds < 0.9
    info = run_info(result.run_dir)
    assert info["status"] == "failed" and "timed out" in info["error"]


FLAKY = """
    pipflow: 1
    name: flaky
    inputs:
      counter: {type: path}
    steps:
      - id: call
        uses: demo.flaky
        retry: {attempts: ATTEMPTS, backoff: 0.01}
        with: {counter: "${inputs.counter}", failures: 2}
    outputs: {calls: "${call.calls}"}
"""


def test_retry_with_backoff_retries_a_flaky_step(engine_env, demo_registry):
    wf = write(engine_env / "flaky.yaml", FLAKY.replace("ATTEMPTS", "3"))
    calls = engine_env / "calls.txt"
    result = run_workflow(wf, {"counter": str(calls)}, runs_dir=engine_env / "runs", registry=demo_registry)
    assert result.ok, result.error
    assert result.outputs == {"calls": 3} and counter(calls) == 3
    retries = of(events(result.run_dir), "retry", "call")
    assert [r["attempt"] for r in retries] == [1, 2]
    assert [r["delay"] for r in retries] == [0.01, 0.02]  # exponential backoff
    assert "ConnectionError" in retries[0]["error"]


def test_retries_exhausted_fail_the_run(engine_env, demo_registry):
    wf = write(engine_env / "flaky.yaml", FLAKY.replace("ATTEMPTS", "2"))
    calls = engine_env / "calls.txt"
    result = run_workflow(wf, {"counter": str(calls)}, runs_dir=engine_env / "runs", registry=demo_registry)
    assert result.status == "failed" and result.error_step == "call"
    assert "ConnectionError" in result.error and counter(calls) == 2


# --- failure records and resume -----------------------------------------------------------------

def test_failing_step_leaves_a_complete_run_record(engine_env, capsys):
    wf = write(engine_env / "fails.yaml", """
        pipflow: 1
        name: fails
        steps:
          - id: a
            uses: core.value
            with: {value: 41}
          - id: b
            uses: core.fail
            with: {message: "b broke at ${a.value}"}
          - id: c
            uses: core.value
            with: {value: "${b.failed}"}
    """)
    code, run = cli_run(engine_env / "runs", str(wf))
    assert code == 1
    assert "b broke at 41" in capsys.readouterr().err
    info = run_info(run)
    assert info["status"] == "failed" and info["error_step"] == "b" and "b broke at 41" in info["error"]
    assert info["finished"] and info["inputs"] == {}
    evs = events(run)
    assert of(evs, "start", "a") and of(evs, "end", "a") and of(evs, "start", "b")
    assert not of(evs, "end", "b") and not of(evs, "start", "c")
    errors = [e for e in evs if e["event"] == "error"]
    assert len(errors) == 1 and errors[0]["step"] == "b" and "b broke" in errors[0]["error"]
    assert json.loads((run / "steps" / "a" / "outputs.json").read_text()) == {"value": 41}
    assert (run / "workflow.yaml").exists() and (run / "metrics.json").exists()
    assert not (run / "outputs.json").exists()


def test_resume_reruns_only_what_did_not_finish(engine_env, demo_registry):
    wf = write(engine_env / "resume.yaml", """
        pipflow: 1
        name: resume
        inputs:
          dir: {type: path}
        steps:
          - id: a
            uses: demo.count
            cache: false
            with: {counter: "${inputs.dir}/a.txt", value: 1}
          - id: b
            uses: demo.flaky
            with: {counter: "${inputs.dir}/b.txt", failures: 1}
          - id: c
            uses: demo.count
            cache: false
            with: {counter: "${inputs.dir}/c.txt", value: "${a.value + b.calls}"}
        outputs: {c: "${c.value}"}
    """)
    d = engine_env
    first = run_workflow(wf, {"dir": str(d)}, runs_dir=d / "runs", registry=demo_registry)
    assert first.status == "failed" and first.error_step == "b"
    assert (counter(d / "a.txt"), counter(d / "b.txt"), counter(d / "c.txt")) == (1, 1, 0)

    code = main(["resume", "-q", "--runs-dir", str(d / "runs"), first.run_dir.name])
    assert code == 0
    assert (counter(d / "a.txt"), counter(d / "b.txt"), counter(d / "c.txt")) == (1, 2, 1)
    evs = events(first.run_dir)
    resume_at = next(i for i, e in enumerate(evs) if e["event"] == "resume")
    assert evs[resume_at]["reused"] == ["a"]
    after = evs[resume_at:]
    assert not of(after, "start", "a") and of(after, "start", "b") and of(after, "start", "c")
    info = run_info(first.run_dir)
    assert info["status"] == "succeeded" and info["error"] is None
    assert json.loads((first.run_dir / "outputs.json").read_text()) == {"c": 3}
    # a finished run cannot be resumed
    with pytest.raises(Exception, match="already succeeded"):
        resume_run(first.run_dir, registry=demo_registry)


# --- cache --------------------------------------------------------------------------------

def test_cache_hit_no_cache_and_clear(engine_env, demo_registry, capsys):
    calls = engine_env / "calls.txt"
    wf = write(engine_env / "cached.yaml", f"""
        pipflow: 1
        name: cached
        inputs:
          v: {{type: integer, default: 1}}
        steps:
          - id: c
            uses: demo.count
            with: {{counter: "{calls.name}", value: "${{inputs.v}}"}}
        outputs: {{v: "${{c.value}}", calls: "${{c.calls}}"}}
    """)
    runs = engine_env / "runs"

    def run(*extra):
        before = set(runs.iterdir()) if runs.exists() else set()
        assert main(["run", "-q", "--runs-dir", str(runs), str(wf), *extra]) == 0
        (new,) = set(runs.iterdir()) - before
        return new, of(events(new), "end", "c")[0]["cached"]

    r1, cached1 = run()
    assert (cached1, counter(calls)) == (False, 1)
    r2, cached2 = run()
    assert (cached2, counter(calls)) == (True, 1), "second run must be a cache hit without calling the step"
    assert json.loads((r2 / "outputs.json").read_text()) == {"v": 1, "calls": 1}
    assert (r2 / "steps" / "c" / "artifacts" / "note.txt").read_text() == "call 1"  # artifacts restored
    _, cached3 = run("-i", "v=2")  # a different input is a different key
    assert (cached3, counter(calls)) == (False, 2)
    _, cached4 = run("--no-cache")
    assert (cached4, counter(calls)) == (False, 3)
    assert (engine_env / "cache").is_dir()
    capsys.readouterr()
    assert main(["cache", "clear"]) == 0
    assert "removed 2 cache entries" in capsys.readouterr().out
    assert not (engine_env / "cache").exists()
    _, cached5 = run()
    assert (cached5, counter(calls)) == (False, 4)


# --- exit codes -----------------------------------------------------------------------------

@pytest.mark.parametrize("uses, args, code, status", [
    ("core.value", "{value: 1}", 0, "succeeded"),
    ("core.fail", "{message: boom}", 1, "failed"),
    ("core.refuse", "{reason: 'no such shelf'}", 3, "refused"),
])
def test_exit_codes(engine_env, capsys, uses, args, code, status):
    wf = write(engine_env / "x.yaml", f"pipflow: 1\nname: x\nsteps:\n  - id: s\n    uses: {uses}\n    with: {args}\n")
    got, run = cli_run(engine_env / "runs", str(wf))
    assert got == code
    assert run_info(run)["status"] == status
    if status == "refused":
        assert "no such shelf" in capsys.readouterr().err


def test_missing_workflow_file_exits_2(engine_env, capsys):
    assert main(["run", str(engine_env / "nope.yaml")]) == 2
    assert "nope.yaml" in capsys.readouterr().err

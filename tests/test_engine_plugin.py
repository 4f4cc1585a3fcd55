"""An external step plugin, installed from its own pyproject.toml into a private folder, is
found through the `pipflow.steps` entry point by the `pipflow` command in a fresh process; a
demo workflow with a loop, a condition and the plugin's step runs and leaves a complete record."""
from __future__ import annotations

import json
import os
import subprocess
from pathlib import Path

WORKFLOWS = Path(__file__).resolve().parent / "fixtures" / "workflows"
DEMO = WORKFLOWS / "demo_plugin.yaml"


def pipflow(site: Path, cwd: Path, *args: str) -> subprocess.CompletedProcess:
    cmd = [PIPFLOW]
    env = {**os.environ, "PYTHONPATH": os.pathsep.join([str(site), os.environ.get("PYTHONPATH", "")]).rstrip(os.pathsep),
           "PIPFLOW_CACHE_DIR": str(cwd / "cache")}
    return subprocess.run([*cmd, *args], cwd=cwd, env=env, capture_output=True, text=True, timeout=120)


def test_plugin_package_declares_no_pipflow_dependency():
    text = (Path(__file__).resolve().parent / "fixtures" / "plugin_pkg" / "pyproject.toml").read_text()
    deps = text.split("dependencies =", 1)[1].split("]", 1)[0]
    assert "pipflow" not in deps, "pip must never fetch the unrelated `pipflow` from PyPI"


def test_demo_workflow_with_plugin_step_in_a_fresh_process(demo_plugin_site, tmp_path):
    proc = pipflow(demo_plugin_site, tmp_path, "run", str(DEMO), "--runs-dir", "runs")
    assert proc.returncode == 0, proc.stderr
    assert "HELLO!!!! after 3 rounds" in proc.stdout  # the outputs are printed
    outputs = {"text": "HELLO!!!!", "rounds": 3, "quiet": None, "announced": "HELLO!!!! after 3 rounds"}

    (run,) = (tmp_path / "runs").iterdir()
    info = json.loads((run / "run.json").read_text())
    assert info["status"] == "succeeded" and info["error"] is None and info["finished"]
    assert info["inputs"] == {"text": "hello", "rounds": 3, "loud": True}
    for name in ("workflow.yaml", "inputs.json", "events.jsonl", "outputs.json", "metrics.json"):
        assert (run / name).is_file(), name
    assert json.loads((run / "outputs.json").read_text()) == outputs
    # per-step outputs and the plugin step's artifacts, per loop iteration too
    assert json.loads((run / "steps" / "first" / "outputs.json").read_text()) == {"text": "HELLO!"}
    assert (run / "steps" / "first" / "artifacts" / "shout.txt").read_text() == "HELLO"
    for n, text in ((1, "HELLO!!"), (2, "HELLO!!!"), (3, "HELLO!!!!")):
        step_dir = run / "steps" / "refine" / "iterations" / str(n) / "louder"
        assert json.loads((step_dir / "outputs.json").read_text()) == {"text": text}
        assert (step_dir / "artifacts" / "shout.txt").is_file()
    events = [json.loads(line) for line in (run / "events.jsonl").read_text().splitlines()]
    kinds = {(e["event"], e.get("step")) for e in events}
    assert ("skip", "quiet") in kinds and ("end", "announce") in kinds
    assert sum(1 for e in events if e["event"] == "end" and e.get("step") == "louder") == 3
    assert all("duration" in e and e["status"] for e in events if e["event"] == "end")
    metrics = json.loads((run / "metrics.json").read_text())
    assert set(metrics["step_seconds"]) >= {"first", "refine", "louder", "announce"}


def test_plugin_steps_are_listed_and_validated(demo_plugin_site, tmp_path):
    proc = pipflow(demo_plugin_site, tmp_path, "steps", "demo.shout")
    assert proc.returncode == 0, proc.stderr
    assert "pipflow-demo-plugin:demo" in proc.stdout and "text" in proc.stdout
    proc = pipflow(demo_plugin_site, tmp_path, "validate", str(DEMO))
    assert proc.returncode == 0, proc.stderr


def test_without_the_plugin_its_steps_are_unknown(tmp_path):
    proc = pipflow(Path(tmp_path / "empty"), tmp_path, "run", str(DEMO), "--runs-dir", "runs")
    assert proc.returncode == 2
    assert "demo_plugin.yaml:10:11: step 'first': unknown step 'demo.shout'" in proc.stderr
    assert not (tmp_path / "runs").exists()


def test_condition_flips_with_an_input(demo_plugin_site, tmp_path):
    proc = pipflow(demo_plugin_site, tmp_path, "run", "-q", str(DEMO), "-i", "loud=false", "-i", "rounds=1",
                   "--runs-dir", "runs")
    assert proc.returncode == 0, proc.stderr
    (run,) = (tmp_path / "runs").iterdir()
    outputs = json.loads((run / "outputs.json").read_text())
    assert outputs == {"text": "HELLO!!", "rounds": 1, "quiet": "HELLO!!", "announced": None}


# ---------------------------------------------------------------- the step contract: one source
from typing import Annotated, Any  # noqa: E402

import pytest  # noqa: E402

from pipflow import Check, Choices, Doc, Input, PathStr, StepContext, step  # noqa: E402
from pipflow.engine import run_workflow  # noqa: E402
from pipflow.engine.registry import Registry, default_registry  # noqa: E402
from pipflow.errors import StepDefinitionError  # noqa: E402


def _no_shouting(value, base_dir):
    return "no capitals, please" if isinstance(value, str) and value.isupper() else None


def test_inputs_are_read_from_the_signature():
    @step("t.sig", outputs={"n": "integer"})
    def sig(ctx: StepContext, text: Annotated[str, Doc("the text")], n: int, ratio: float = 0.5,
            flag: bool = False, table: dict | None = None, items: list[str] | None = None,
            where: Annotated[PathStr, Doc("a file")] = "a.txt", anything: Any = None,
            mode: Annotated[str, Choices("a", "b"), Check(_no_shouting)] = "a") -> dict:
        return {"n": n}

    got = {k: (v.type, v.required, None if v.required else v.default) for k, v in sig.inputs.items()}
    assert got == {"text": ("string", True, None), "n": ("integer", True, None), "ratio": ("number", False, 0.5),
                   "flag": ("boolean", False, False), "table": ("object", False, None),
                   "items": ("array", False, None), "where": ("path", False, "a.txt"),
                   "anything": ("any", False, None), "mode": ("string", False, "a")}
    assert sig.inputs["text"].doc == "the text" and sig.inputs["where"].doc == "a file"
    assert sig.inputs["mode"].choices == ("a", "b")
    assert sig.inputs["mode"].check("LOUD", None) == "no capitals, please"
    assert sig.defaults() == {"ratio": 0.5, "flag": False, "table": None, "items": None, "where": "a.txt",
                              "anything": None, "mode": "a"}


@pytest.mark.parametrize("define, words", [
    (lambda: step("t.bad")(lambda ctx, text: {}), "parameter 'text' has no type hint"),
    (lambda: step("t.bad")(_with_hint(set)), "maps to no input type"),
    (lambda: step("t.bad")(_with_hint(int, "three")), "default 'three' is not integer"),
    (lambda: step("t.bad")(_with_hint(list, ())), "default () is not array"),
    (lambda: step("t.bad")(_with_hint(str, None)), "does not admit None"),
    (lambda: step("t.bad")(_with_hint(str | int)), "maps to no input type"),
    (lambda: step("t.bad", outputs={"x": "text"})(_with_hint(str)), "output 'x' has unknown type 'text'"),
])
def test_a_step_that_contradicts_its_contract_is_refused_at_registration(define, words):
    with pytest.raises(StepDefinitionError) as err:
        define()
    assert words in str(err.value) and "step 't.bad'" in str(err.value)


_MISSING = object()


def _with_hint(hint, default=_MISSING):
    """A step function whose one parameter has ``hint`` (and ``default``), named in messages."""
    if default is _MISSING:
        def func(ctx: StepContext, value: hint) -> dict:
            return {}
    else:
        def func(ctx: StepContext, value: hint = default) -> dict:
            return {}
    func.__annotations__["value"] = hint  # a real object, not a string: the hint is built here
    return func


def test_the_first_style_is_checked_against_the_signature():
    def legacy(ctx: StepContext, text: str, times: int = 1) -> dict:
        return {}

    same = step("t.old", inputs={"text": Input("string", doc="the text"), "times": Input("integer", default=1)})(legacy)
    assert same.inputs["text"].doc == "the text" and same.inputs["times"].default == 1
    drifts = [
        ({"text": Input("string"), "times": Input("integer", default=2)}, "'times': inputs= says default 2, the signature says 1"),
        ({"text": Input("integer"), "times": Input("integer", default=1)}, "'text': inputs= says type integer, the signature says string"),
        ({"text": Input("string")}, None),  # a parameter inputs= leaves out is read from the signature
        ({"text": Input("string"), "times": Input("integer", default=1), "extra": Input("any")}, "declares 'extra'"),
        ({"text": Input("string", default="x"), "times": Input("integer", default=1)},
         "'text': inputs= says default 'x', the signature says (required)"),
    ]
    for declared, words in drifts:
        if words is None:
            assert step("t.old", inputs=declared)(legacy).inputs["times"].default == 1
            continue
        with pytest.raises(StepDefinitionError) as err:
            step("t.old", inputs=declared)(legacy)
        assert words in str(err.value) and ".legacy)" in str(err.value), str(err.value)


def test_every_builtin_step_registers_and_documents_its_inputs():
    """Each built-in step passes the registration checks (none is broken) and says what each of
    its inputs means (``pipflow steps NAME`` shows it)."""
    steps = [s for s in default_registry() if default_registry().origin(s.name) == "pipflow:builtin"]
    assert {"simulate", "score", "simulate.pybullet", "household.load"} <= {s.name for s in steps}
    assert len(steps) >= 20 and not default_registry().broken
    undocumented = [f"{s.name}.{name}" for s in steps for name, spec in s.inputs.items() if not spec.doc]
    assert not undocumented


@step("t.chatty", outputs={"text": "string"})
def _chatty(ctx: StepContext, text: str) -> dict:
    return {"text": text, "secret": 1}


def test_a_step_returning_an_undeclared_output_fails_naming_it(tmp_path):
    registry = Registry()
    registry.add(_chatty, "test")
    wf = tmp_path / "wf.yaml"
    wf.write_text("pipflow: 1\nname: chatty\nsteps:\n  - id: talk\n    uses: t.chatty\n    with: {text: hi}\n")
    result = run_workflow(wf, runs_dir=tmp_path / "runs", registry=registry)
    assert result.status == "failed" and result.error_step == "talk"
    assert "returned 'secret', which it does not declare" in result.error
    assert "step 'talk' (t.chatty)" in result.error


def test_pipflow_steps_shows_the_signature_contract(capsys):
    from pipflow.engine.cli import main

    assert main(["steps", "graph.dependencies"]) == 0
    out = capsys.readouterr().out
    assert "(one of: deorder, exact, paper)" in out
    assert "picture        boolean  default True" in out and "also draw graph.png" in out


# ------------------------------------------------------------------ outputs declared by the return type
from typing import TypedDict  # noqa: E402

from pipflow.engine.step import shape  # noqa: E402
from cli_entry import PIPFLOW


class _Inner(TypedDict):
    x: float


@shape("greeting")
class _Greeting(TypedDict):
    text: str
    length: int
    ratio: float | None
    parts: list[str]
    table: dict[str, int]
    inner: _Inner
    anything: Any


def test_a_typeddict_return_declares_the_outputs_and_their_family():
    @step("t.greet", doc="Greet.")
    def greet(ctx: StepContext, name: str) -> _Greeting:
        return {"text": f"hello {name}"}

    assert greet.outputs == {"text": "string", "length": "integer", "ratio": "number", "parts": "array",
                             "table": "object", "inner": "object", "anything": "any"}
    assert greet.shape == "greeting"
    # outputs= beside the TypedDict must say the same; a difference names the outputs
    same = step("t.greet", outputs=dict(greet.outputs))(greet.func)
    assert same.outputs == greet.outputs
    with pytest.raises(StepDefinitionError) as err:
        step("t.greet", outputs={**greet.outputs, "length": "number", "extra": "string"})(greet.func)
    assert "outputs= and the return TypedDict disagree on 'extra', 'length'" in str(err.value)
    # -> dict and outputs=: the first style, no family
    def counted(ctx: StepContext, n: int) -> dict:
        return {"n": n}

    plain = step("t.plain", outputs={"n": "integer"})(counted)
    assert plain.outputs == {"n": "integer"} and plain.shape is None


class _Odd(TypedDict):
    values: set


def test_an_output_hint_that_maps_to_no_type_is_refused():
    def odd(ctx: StepContext) -> _Odd:
        return {}

    with pytest.raises(StepDefinitionError) as err:
        step("t.odd")(odd)
    assert "output 'values' of _Odd" in str(err.value) and "maps to no output type" in str(err.value)
    with pytest.raises(TypeError):
        shape("x")(dict)  # a family names TypedDicts only


def test_the_record_keeps_each_steps_family_and_the_status_words(tmp_path):
    """The start event says which family of outputs a step declared (what the report looks steps
    up by); run.json keeps the status as the word it always was, and pipflow.run returns the
    engine's one Run."""
    import json

    import pipflow
    from pipflow.engine.runner import Run
    from pipflow.engine.status import RunStatus

    @step("t.greeted", doc="Greet.")
    def greeted(ctx: StepContext, name: str) -> _Greeting:
        return {"text": f"hello {name}", "length": 6 + len(name)}

    registry = Registry()
    registry.add(greeted, "test")
    wf = tmp_path / "wf.yaml"
    wf.write_text("pipflow: 1\nname: greet\nsteps:\n  - id: hi\n    uses: t.greeted\n    with: {name: ada}\n")
    result = run_workflow(wf, runs_dir=tmp_path / "runs", registry=registry)
    assert isinstance(result, Run) and result.status is RunStatus.SUCCEEDED and result.ok
    starts = [json.loads(line) for line in (result.run_dir / "events.jsonl").read_text().splitlines()]
    assert {"event": "start", "step": "hi", "uses": "t.greeted", "shape": "greeting"}.items() <= \
        next(e for e in starts if e["event"] == "start").items()
    assert json.loads((result.run_dir / "run.json").read_text())["status"] == "succeeded"
    assert pipflow.Run is Run and RunStatus.of("refused") is RunStatus.REFUSED and RunStatus.of("ok") is None

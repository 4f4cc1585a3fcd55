"""Ctrl-C during a run: the record keeps what finished, says it was interrupted, and `resume`
finishes only the rest."""
from __future__ import annotations

import json

import pytest

from pipflow import Input, step
from pipflow.engine import resume_run, run_workflow
from pipflow.engine.registry import Registry, default_registry

CALLS: list[str] = []
INTERRUPT = {"on": True}


@step("test.mark", inputs={"tag": Input("string")}, outputs={"tag": "string"})
def mark(ctx, tag):
    CALLS.append(tag)
    if tag == "b" and INTERRUPT["on"]:
        raise KeyboardInterrupt
    return {"tag": tag}


WORKFLOW = """\
pipflow: 1
name: interrupted
steps:
  - id: a
    uses: test.mark
    with: {tag: a}
  - id: b
    uses: test.mark
    when: ${a.tag == 'a'}
    with: {tag: b}
outputs:
  last: ${b.tag}
"""


def test_an_interrupted_run_keeps_its_record_and_resumes(tmp_path):
    registry = Registry()
    for s in default_registry():
        registry.add(s, "pipflow")
    registry.add(mark, "test")
    wf = tmp_path / "wf.yaml"
    wf.write_text(WORKFLOW)
    CALLS.clear()
    INTERRUPT["on"] = True
    with pytest.raises(KeyboardInterrupt):
        run_workflow(wf, runs_dir=tmp_path / "runs", registry=registry)
    run_dir = next((tmp_path / "runs").iterdir())
    info = json.loads((run_dir / "run.json").read_text())
    assert info["status"] == "interrupted"
    assert json.loads((run_dir / "steps/a/outputs.json").read_text()) == {"tag": "a"}
    INTERRUPT["on"] = False
    CALLS.clear()
    result = resume_run(run_dir, registry=registry)
    assert result.ok and result.outputs == {"last": "b"}
    assert CALLS == ["b"]  # a finished before the interruption and was not run again

"""`extends`, and the inspection commands: graph, steps, runs, show."""
from __future__ import annotations

import json
from pathlib import Path

import pytest

from pipflow.engine import check_workflow, run_workflow
from pipflow.engine.cli import main

WORKFLOWS = Path(__file__).resolve().parent / "fixtures" / "workflows"
LOOP_DEMO = WORKFLOWS / "loop_demo.yaml"


# --- extends --------------------------------------------------------------------------------

def test_extends_overrides_input_argument_step_and_removes(engine_env):
    base = run_workflow(WORKFLOWS / "extends_base.yaml", runs_dir=engine_env / "runs")
    assert base.outputs == {"final": "*hello, world*", "greeting": "hello"}
    child = run_workflow(WORKFLOWS / "extends_child.yaml", runs_dir=engine_env / "runs")
    assert child.ok, child.error
    # input default overridden (its type kept from the base), `greet` argument overridden,
    # `decorate` replaced by another step, `final`'s argument rewired, `extra` removed
    assert child.outputs == {"final": "[bonjour, dear world]", "greeting": "bonjour"}
    steps_run = sorted(p.name for p in (child.run_dir / "steps").iterdir())
    assert steps_run == ["decorate", "final", "greet"]
    snapshot = (child.run_dir / "workflow.yaml").read_text()
    assert "extends:" not in snapshot and "extra" not in snapshot and "core.log" in snapshot
    wf, diags = check_workflow(WORKFLOWS / "extends_child.yaml")
    assert not diags
    assert wf.inputs["greeting"].type == "string" and wf.inputs["name"].default == "world"
    assert len(wf.files) == 2


def test_extends_input_override_keeps_cli_coercion(engine_env):
    result = run_workflow(WORKFLOWS / "extends_child.yaml", {"name": "Ada"}, runs_dir=engine_env / "runs")
    assert result.outputs["final"] == "[bonjour, dear Ada]"


def test_errors_in_a_child_are_located_in_the_child_file():
    _, diags = check_workflow(WORKFLOWS / "extends_child_bad.yaml")
    where = {(Path(d.location.file).name, d.location.line): d.message for d in diags}
    assert "no output 'valu'" in where[("extends_child_bad.yaml", 7)]
    assert "'nosuch' overrides nothing" in where[("extends_child_bad.yaml", 8)]
    assert "no inherited step 'ghost'" in where[("extends_child_bad.yaml", 10)]
    # the base's `final` reads decorate.value, which the child's replacement does not have
    assert "no output 'value'" in where[("extends_base.yaml", 19)]
    assert len(diags) == 4


def test_extends_adds_a_step_inside_an_inherited_loop(engine_env):
    """``inside: LOOP`` adds a step to the steps of an inherited loop (the loop's condition may
    then read it), without copying the loop; the snapshot keeps the merged loop and no
    ``inside``."""
    child = engine_env / "child.yaml"
    child.write_text(f"""pipflow: 1
name: loop-child
extends: {LOOP_DEMO}
steps:
  - id: double
    inside: count
    uses: core.value
    with: {{value: "${{bump.value * 2}}"}}
  - id: count
    until: ${{double.value >= 6}}
outputs:
  doubled: ${{double.value}}
""")
    result = run_workflow(child, runs_dir=engine_env / "runs")
    assert result.ok, result.error
    assert result.outputs["doubled"] == 6 and result.outputs["rounds"] == 3 and result.outputs["final"] == 3
    assert sorted(p.name for p in (result.run_dir / "steps" / "count" / "iterations" / "3").iterdir()) == \
        ["bump", "double"]
    snapshot = (result.run_dir / "workflow.yaml").read_text()
    assert "inside" not in snapshot and "double" in snapshot


def test_inside_names_a_loop_of_the_base_and_needs_extends(tmp_path):
    """A step placed inside a loop the base does not have, or inside a loop of a workflow that
    extends nothing, is a located problem, not a step silently added elsewhere."""
    child = tmp_path / "child.yaml"
    child.write_text(f"pipflow: 1\nname: c\nextends: {LOOP_DEMO}\nsteps:\n  - id: extra\n    inside: counting\n"
                     "    uses: core.value\n    with: {value: 1}\n")
    _, diags = check_workflow(child)
    assert [(d.location.line, d.message) for d in diags] == [
        (6, "step 'extra': inside 'counting': no inherited loop has that id (loops: count)")]
    alone = tmp_path / "alone.yaml"
    alone.write_text("pipflow: 1\nname: a\nsteps:\n  - id: extra\n    inside: count\n    uses: core.value\n"
                     "    with: {value: 1}\n")
    _, diags = check_workflow(alone)
    assert len(diags) == 1 and diags[0].location.line == 5 and "needs 'extends'" in diags[0].message


def test_extends_missing_base_is_located(tmp_path):
    child = tmp_path / "child.yaml"
    child.write_text("pipflow: 1\nname: c\nextends: nothere.yaml\nsteps:\n  - id: a\n    with: {value: 1}\n")
    _, diags = check_workflow(child)
    assert len(diags) == 1
    assert (diags[0].location.line, diags[0].location.column) == (3, 10)
    assert "nothere.yaml" in diags[0].message and "no such file" in diags[0].message


def test_extends_cycle_is_reported(tmp_path):
    (tmp_path / "a.yaml").write_text("pipflow: 1\nname: a\nextends: b.yaml\nsteps: []\n")
    (tmp_path / "b.yaml").write_text("pipflow: 1\nname: b\nextends: a.yaml\nsteps: []\n")
    _, diags = check_workflow(tmp_path / "a.yaml")
    assert any("cycle" in d.message for d in diags)


# --- graph ----------------------------------------------------------------------------------

def test_graph_text(capsys):
    assert main(["graph", str(LOOP_DEMO)]) == 0
    lines = capsys.readouterr().out.splitlines()
    by_node = {line.split()[0]: line for line in lines}
    assert set(by_node) == {"start", "count", "bump", "big"}
    assert "loop, max 5" in by_node["count"] and "(core.value)" in by_node["bump"]
    assert by_node["bump"].endswith("<- start")
    assert by_node["big"].endswith("<- bump, count")
    assert "<-" not in by_node["start"]
    assert lines.index(by_node["start"]) < lines.index(by_node["bump"]) < lines.index(by_node["big"])


def test_graph_dot(capsys, tmp_path):
    assert main(["graph", str(LOOP_DEMO), "--format", "dot"]) == 0
    dot = capsys.readouterr().out
    assert dot.startswith('digraph "loop-demo"')
    assert 'subgraph "cluster_count"' in dot
    assert '"start" -> "bump";' in dot and '"bump" -> "big";' in dot
    out = tmp_path / "g.dot"
    assert main(["graph", str(LOOP_DEMO), "--format", "dot", "-o", str(out)]) == 0
    assert out.read_text().strip() == dot.strip()


def test_graph_png(tmp_path, capsys):
    out = tmp_path / "g.png"
    assert main(["graph", str(LOOP_DEMO), "--format", "png", "-o", str(out)]) == 0
    assert out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert main(["graph", str(LOOP_DEMO), "--format", "png"]) == 2
    assert "-o" in capsys.readouterr().err


def test_graph_of_a_bad_file_exits_2(capsys):
    assert main(["graph", str(WORKFLOWS / "bad" / "cycle.yaml")]) == 2
    assert "cycle" in capsys.readouterr().err


# --- steps ----------------------------------------------------------------------------------

def test_steps_lists_every_step_with_its_doc(capsys):
    assert main(["steps"]) == 0
    out = capsys.readouterr().out
    rows = {line.split()[0]: line for line in out.splitlines() if line.strip()}
    for name in ("core.value", "core.log", "core.refuse", "core.fail"):
        assert name in rows
    assert "Pass a value through unchanged" in rows["core.value"]


def test_steps_name_shows_inputs_outputs_and_origin(capsys):
    assert main(["steps", "core.refuse"]) == 0
    out = capsys.readouterr().out
    assert out.startswith("core.refuse") and "version 1" in out and "pipflow:builtin" in out
    inputs = out.split("inputs:")[1].split("outputs:")[0]
    assert "reason" in inputs and "default None" in inputs
    assert "refused" in out.split("outputs:")[1] and "boolean" in out.split("outputs:")[1]


def test_steps_name_of_a_plugin_step(demo_registry, capsys):
    assert main(["steps", "demo.count"]) == 0
    out = capsys.readouterr().out
    assert "cacheable" in out and "pipflow-demo-plugin:demo" in out
    assert "counter" in out and "path" in out


def test_steps_unknown_name_suggests(capsys):
    assert main(["steps", "core.valu"]) == 2
    assert "did you mean core.value" in capsys.readouterr().err


# --- runs and show ----------------------------------------------------------------------------

def test_runs_and_show(engine_env, capsys):
    runs = engine_env / "runs"
    assert main(["runs", "--runs-dir", str(runs)]) == 0
    assert "no runs" in capsys.readouterr().out
    ok = run_workflow(LOOP_DEMO, runs_dir=runs)
    bad = run_workflow(LOOP_DEMO, {"target": 9}, runs_dir=runs)
    capsys.readouterr()
    assert main(["runs", "--runs-dir", str(runs)]) == 0
    listing = capsys.readouterr().out
    assert ok.run_dir.name in listing and bad.run_dir.name in listing
    bad_line = next(line for line in listing.splitlines() if bad.run_dir.name in line)
    assert "failed" in bad_line and "maximum of 5" in bad_line

    assert main(["show", "--runs-dir", str(runs), ok.run_dir.name[-6:]]) == 0  # unique suffix
    shown = capsys.readouterr().out
    assert "succeeded" in shown and "final: 3" in shown and "--full" in shown  # a summary, saying where more is
    assert main(["show", "--full", "--runs-dir", str(runs), ok.run_dir.name[-6:]]) == 0
    shown = capsys.readouterr().out
    assert "succeeded" in shown and "target = 3" in shown
    assert '"final": 3' in shown and "bump #3" in shown

    assert main(["show", str(bad.run_dir)]) == 0
    shown = capsys.readouterr().out
    assert "failed" in shown and "error_step count" in shown


def test_show_unknown_run_exits_2(engine_env, capsys):
    assert main(["show", "--runs-dir", str(engine_env / "runs"), "nosuchrun"]) == 2
    assert "no run 'nosuchrun'" in capsys.readouterr().err


def test_options_before_the_command_are_honoured(engine_env, capsys):
    runs = engine_env / "elsewhere"
    assert main(["--runs-dir", str(runs), "-q", "run", str(LOOP_DEMO)]) == 0
    assert runs.is_dir() and not (engine_env / "runs").exists()
    assert capsys.readouterr().out == ""  # -q: no outputs printed
    assert main(["--runs-dir", str(runs), "runs"]) == 0
    assert "loop-demo" in capsys.readouterr().out


def test_graph_png_layout_frames_each_loop_around_its_own_steps_only(tmp_path):
    """A loop of two steps next to a branch that runs beside it: the frame holds the loop's steps
    and nothing else, no two boxes overlap, and arrows implied by others are left out."""
    from pipflow.engine.graphview import _labels, layout
    from pipflow.engine.validate import dependency_graph, load_workflow

    wf_file = tmp_path / "branch.yaml"
    wf_file.write_text("""pipflow: 1
name: branch
steps:
  - {id: start, uses: core.value, with: {value: 1}}
  - {id: side, uses: core.value, with: {value: "${start.value}"}}
  - id: refine
    loop:
      max: 2
      until: ${second.value > 0}
      steps:
        - {id: first, uses: core.value, with: {value: "${start.value}"}}
        - {id: second, uses: core.value, with: {value: "${first.value}"}}
  - {id: after, uses: core.value, with: {value: "${second.value + side.value + start.value}"}}
""")
    wf = load_workflow(wf_file)
    graph = dependency_graph(wf)
    pos, width, frames = layout(wf, graph, _labels(wf))
    x0, y0, x1, y1 = frames["refine"]
    inside = {n for n, (x, y) in pos.items() if x0 <= x <= x1 and y0 <= y <= y1}
    assert inside == {"first", "second"}
    boxes = [(x - width[n] / 2, x + width[n] / 2, y) for n, (x, y) in pos.items()]
    for i, (a0, a1, ay) in enumerate(boxes):
        for b0, b1, by in boxes[i + 1:]:
            assert ay != by or a1 <= b0 or b1 <= a0  # same row: side by side, never overlapping
    out = tmp_path / "g.png"
    assert main(["graph", str(wf_file), "--format", "png", "-o", str(out)]) == 0
    assert out.stat().st_size > 5000

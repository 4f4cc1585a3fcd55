"""Validation: every bad fixture yields its kind of error at the right place, all at once, and
nothing runs when a workflow is invalid."""
from __future__ import annotations

from pathlib import Path

import pytest

from pipflow.engine import check_workflow, run_workflow
from pipflow.engine.cli import main
from pipflow.errors import WorkflowError

BAD = Path(__file__).resolve().parent / "fixtures" / "workflows" / "bad"


def problems(name: str) -> list[tuple[int, int, str]]:
    wf, diags = check_workflow(BAD / name)
    assert diags, f"{name} should not validate"
    for d in diags:
        assert d.location is not None and Path(d.location.file).name == name
    return [(d.location.line, d.location.column, d.message) for d in diags]


def only(name: str) -> tuple[int, int, str]:
    found = problems(name)
    assert len(found) == 1, found
    return found[0]


def test_syntax_error_is_located_at_the_bad_token():
    line, col, msg = only("syntax.yaml")
    assert (line, col) == (6, 24)
    assert "YAML syntax" in msg


def test_schema_errors_name_the_key_and_suggest_the_right_one():
    found = problems("schema.yaml")
    assert len(found) == 2
    unknown = [p for p in found if "unknown key 'stepz'" in p[2]]
    assert unknown and "did you mean 'steps'" in unknown[0][2]
    timeout = [p for p in found if "timeout" in p[2]]
    assert timeout and timeout[0][:2] == (7, 14)


def test_unknown_step_suggests_close_names():
    line, col, msg = only("unknown_step.yaml")
    assert (line, col) == (5, 11)  # the value of `uses:`
    assert "unknown step 'core.valeu'" in msg and "'core.value'" in msg


def test_unknown_references_each_located_at_their_argument():
    found = sorted(problems("unknown_reference.yaml"))
    assert [p[:2] for p in found] == [(8, 19), (11, 19), (14, 19)]
    assert "unknown input 'inputs.m'" in found[0][2]
    assert "unknown reference 'c'" in found[1][2]
    assert "no output 'valu'" in found[2][2] and "did you mean 'value'" in found[2][2]


def test_missing_and_misspelled_arguments():
    found = sorted(problems("missing_argument.yaml"))
    assert len(found) == 2
    missing, unknown = found  # line 4 (the step) before line 6 (the argument)
    assert missing[:2] == (4, 5) and "missing required argument 'message'" in missing[2]
    assert unknown[:2] == (6, 20) and "unknown argument 'mesage'" in unknown[2] and "'message'" in unknown[2]


def test_type_mismatches_of_literals_defaults_and_references():
    found = sorted(problems("type_mismatch.yaml"))
    assert [p[:2] for p in found] == [(5, 10), (9, 21), (12, 21)]
    assert "default 'three' is not of type integer" in found[0][2]
    assert "must be string, got 42" in found[1][2]
    assert "${inputs.flag} is boolean" in found[2][2]


def test_duplicate_id_points_at_the_second_and_names_the_first():
    line, col, msg = only("duplicate_id.yaml")
    assert (line, col) == (7, 5)
    assert "duplicate step id 'a'" in msg and "duplicate_id.yaml:4:5" in msg


def test_cycle_names_every_step_on_it():
    line, col, msg = only("cycle.yaml")
    assert (line, col) == (4, 5)  # at the first step of the cycle in the file, whatever the hash seed
    assert msg == "cycle between steps: a -> b -> c -> a"


def test_loop_without_max_is_rejected():
    line, _, msg = only("loop_without_max.yaml")
    assert line in (5, 6)
    assert "max" in msg and "loop" in msg


def test_many_problems_are_all_reported_at_once():
    found = problems("many.yaml")
    kinds = {
        "unknown step": (5, 11),
        "unknown reference 'nothere'": (9, 19),
        "duplicate step id 'b'": (10, 5),
        "missing required argument 'message'": (10, 5),
    }
    for text, where in kinds.items():
        hits = [p for p in found if text in p[2]]
        assert hits, f"{text!r} not reported: {found}"
        assert hits[0][:2] == where, (text, hits)


def test_cli_validate_prints_file_line_col_and_exits_2(capsys):
    code = main(["validate", str(BAD / "unknown_step.yaml"), str(BAD / "cycle.yaml")])
    err = capsys.readouterr().err
    assert code == 2
    assert f"{BAD / 'unknown_step.yaml'}:5:11: step 'a': unknown step" in err
    assert "cycle.yaml:" in err


def test_cli_validate_ok_file_exits_0(capsys):
    code = main(["validate", str(BAD.parent / "loop_demo.yaml")])
    assert code == 0
    assert "ok" in capsys.readouterr().out


@pytest.mark.parametrize("name", sorted(p.name for p in BAD.glob("*.yaml")))
def test_cli_run_of_a_bad_file_runs_nothing(name, engine_env, capsys):
    runs = engine_env / "runs"
    code = main(["run", str(BAD / name), "--runs-dir", str(runs)])
    assert code == 2
    assert not runs.exists(), "no run directory may be created for an invalid workflow"
    assert f"{name}:" in capsys.readouterr().err


def test_run_workflow_raises_with_all_diagnostics(engine_env):
    with pytest.raises(WorkflowError) as info:
        run_workflow(BAD / "many.yaml", runs_dir=engine_env / "runs")
    assert len(info.value.diagnostics) == 4
    assert "nothing was run" in str(info.value)
    assert not (engine_env / "runs").exists()


def test_step_without_uses_in_a_plain_workflow_is_an_error(tmp_path):
    wf = tmp_path / "nouses.yaml"
    wf.write_text("pipflow: 1\nname: nouses\nsteps:\n  - id: a\n    with: {value: 1}\n")
    _, diags = check_workflow(wf)
    assert diags, "a step with neither `uses` nor `loop` (and nothing to extend) must not be dropped silently"
    assert diags[0].location.line == 4

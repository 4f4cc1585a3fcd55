"""Prompt template names are checked by validation whatever the model: a misspelt variant fails
before anything runs, with the offline model too (which never renders a prompt)."""
from __future__ import annotations

import subprocess
from pathlib import Path
from cli_entry import PIPFLOW

REPO = Path(__file__).resolve().parents[1]


def _pipflow(*args: str, cwd: Path) -> subprocess.CompletedProcess:
    return subprocess.run([PIPFLOW, *args], capture_output=True, text=True, cwd=cwd, timeout=120)


def test_misspelt_prompt_input_is_a_user_error_before_any_step(tmp_path):
    out = _pipflow("run", str(REPO / "workflows/warehouse.yaml"), "-i", "prompt=warehouse_problem_cto",
                   "--runs-dir", str(tmp_path / "runs"), cwd=tmp_path)
    assert out.returncode == 2
    assert "input 'prompt' (used by step 'generate')" in out.stderr and "warehouse_problem_cot" in out.stderr
    assert "Traceback" not in out.stderr
    assert not (tmp_path / "runs").exists() or not any((tmp_path / "runs").iterdir())


def test_misspelt_literal_prompt_is_located_by_validate(tmp_path):
    wf = tmp_path / "variant.yaml"
    wf.write_text(f"extends: {REPO / 'workflows/warehouse.yaml'}\ninputs:\n  prompt: {{default: warehouse_problme}}\n")
    out = _pipflow("validate", str(wf), cwd=tmp_path)
    assert out.returncode == 2, out.stdout + out.stderr
    text = out.stdout + out.stderr
    assert "prompt template 'warehouse_problme' not found" in text and "warehouse.yaml:" in text


def test_a_prompt_file_next_to_the_workflow_is_accepted(tmp_path):
    (tmp_path / "mine.j2").write_text("{% block user %}Command: {{ command }}{% endblock %}")
    wf = tmp_path / "variant.yaml"
    wf.write_text(f"extends: {REPO / 'workflows/warehouse.yaml'}\ninputs:\n  prompt: {{default: mine.j2}}\n")
    out = _pipflow("validate", str(wf), cwd=tmp_path)
    assert out.returncode == 0, out.stdout + out.stderr

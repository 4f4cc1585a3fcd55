"""A non-editable install (``pip install .``) must carry everything pipflow reads at run time:
the engine and steps under the ``pipflow`` package (nothing named ``engine`` or ``steps`` at the
top of site-packages), and the schemas, prompts, domains, built-in workflows and the benchmark
world, found from the installed copy with no clone in sight."""
from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from conftest import _can_build_without_isolation

REPO = Path(__file__).resolve().parents[1]


@pytest.fixture(scope="module")
def installed_copy(tmp_path_factory) -> Path:
    root = tmp_path_factory.mktemp("installed")
    src, site = root / "src", root / "site"
    shutil.copytree(REPO, src, ignore=shutil.ignore_patterns(
        ".git", "runs", "bench-out", "__pycache__", "*.egg-info", "build", ".pipflow-cache", ".pytest_cache"))
    cmd = [sys.executable, "-m", "pip", "install", "--no-deps", "--disable-pip-version-check", "-q",
           "--target", str(site), str(src)]
    if _can_build_without_isolation():
        cmd[4:4] = ["--no-build-isolation", "--no-index"]
    proc = subprocess.run(cmd, capture_output=True, text=True)
    assert proc.returncode == 0, proc.stderr
    return site


def _run(site: Path, cwd: Path, *args: str) -> subprocess.CompletedProcess:
    env = {**os.environ, "PYTHONPATH": str(site)}
    return subprocess.run([sys.executable, *args], cwd=cwd, env=env, capture_output=True, text=True, timeout=300)


def test_install_puts_everything_under_the_pipflow_package(installed_copy):
    top = {p.name for p in installed_copy.iterdir()}
    assert "pipflow" in top
    assert not {"engine", "steps", "workflows", "schemas", "prompts", "domains", "benchmarks"} & top
    pkg = installed_copy / "pipflow"
    for needed in ("engine/cli.py", "steps/pddl.py", "schemas/workflow.schema.json", "schemas/world.schema.json",
                   "prompts/warehouse_problem.j2", "domains/warehouse.pddl", "domains/warehouse.actions.yaml",
                   "workflows/warehouse.yaml", "benchmarks/warehouse/world.yaml", "benchmarks/warehouse/tasks.yaml",
                   "household/world.py", "workflows/household.yaml", "domains/household.pddl",
                   "domains/household.actions.yaml", "schemas/household.schema.json",
                   "prompts/household_problem.j2", "benchmarks/household/world.yaml"):
        assert (pkg / needed).is_file(), needed


def test_install_misses_no_module_and_no_data_file(installed_copy):
    """Every module of the library, engine and steps, and every data file, lands in the
    installed package (the package list in pyproject.toml is explicit: this keeps it complete)."""
    pkg = installed_copy / "pipflow"
    expected = [(f, pkg / f.relative_to(REPO / "pipflow")) for f in (REPO / "pipflow").rglob("*.py")]
    for folder in ("engine", "steps"):
        expected += [(f, pkg / folder / f.relative_to(REPO / folder)) for f in (REPO / folder).rglob("*.py")]
    for folder, pattern in (("workflows", "*.yaml"), ("prompts", "*.j2"), ("schemas", "*.json"),
                            ("domains", "*.*"), ("benchmarks", "*/*.yaml")):
        expected += [(f, pkg / folder / f.relative_to(REPO / folder)) for f in (REPO / folder).glob(pattern)]
    missing = [str(src.relative_to(REPO)) for src, dst in expected
               if "__pycache__" not in src.parts and not dst.is_file()]
    assert not missing, f"not installed: {missing}"


def test_installed_copy_runs_the_builtin_workflow_from_any_folder(installed_copy, tmp_path):
    probe = _run(installed_copy, tmp_path, "-c", "import pipflow; print(pipflow.__file__)")
    assert str(installed_copy) in probe.stdout, probe.stdout + probe.stderr
    proc = _run(installed_copy, tmp_path, "-m", "pipflow.engine.cli", "run", "warehouse", "-q",
                "--runs-dir", str(tmp_path / "runs"), "-i", "command=shelf4 has ten plus seven product1")
    assert proc.returncode == 0, proc.stderr
    outputs = next((tmp_path / "runs").iterdir()) / "outputs.json"
    assert '"product1": 17' in outputs.read_text()
    household = _run(installed_copy, tmp_path, "-m", "pipflow.engine.cli", "run", "household", "-q",
                     "--runs-dir", str(tmp_path / "household-runs"))
    assert household.returncode == 0, household.stderr

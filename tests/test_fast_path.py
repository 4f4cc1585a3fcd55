"""The fast main path: no ConfigSpace/scipy.stats unless used, one shared read-only parse per
problem text, and pictures only when asked (real UP, real planner, real validator)."""
from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest
import yaml

from pipflow.dependency import build_graph
from pipflow.pddl.common import parse
from pipflow.pddl.debugger import debug_problem
from pipflow.pddl.solver import solve_problem
from pipflow.pddl.verifier import verify_plan
from pipflow.pddl.writer import write_problem

ROOT = Path(__file__).resolve().parents[1]
DOMAIN = ROOT / "domains" / "warehouse.pddl"
WORLD = yaml.safe_load((ROOT / "benchmarks" / "warehouse" / "world.yaml").read_text())
META = yaml.safe_load((ROOT / "domains" / "warehouse.actions.yaml").read_text())
GOAL = {"shelf4": {"product3": 12, "product1": 5}}


def _snapshot(problem) -> str:
    """Everything a consumer could change: objects, fluents, actions, initial values, goals."""
    return "\n".join([str(problem), repr(sorted(map(str, problem.explicit_initial_values.items())))])


def test_consumers_share_one_parse_and_leave_it_unchanged():
    text = write_problem(WORLD, GOAL)
    report = debug_problem(text, str(DOMAIN), WORLD)
    assert report.ok, report.messages
    shared = parse(DOMAIN, text)
    assert shared is report.problem  # the debugger's parse is the one everybody gets
    assert parse(str(DOMAIN), text) is shared and parse(DOMAIN.read_text(), text) is shared
    before = _snapshot(shared)
    robots = {n: r["skills"]["carry"] for n, r in WORLD["robots"].items()}
    result = solve_problem(shared, "pipflow-transport", {"robots": robots, "rules": []})
    assert result.status == "solved" and result.plan
    assert verify_plan(shared, result.plan, WORLD).ok
    graph = build_graph(DOMAIN.read_text(), text, result.plan, META)
    assert len(graph["nodes"]) == len(result.plan)
    assert _snapshot(shared) == before  # nobody mutated the memoised problem
    other = write_problem(WORLD, {"shelf4": {"product3": 11}})
    assert parse(DOMAIN, other) is not shared  # content, not the path, is the key


def test_a_failed_parse_is_not_memoised():
    bad = write_problem(WORLD, GOAL).replace("(:goal", "(:goal (", 1)
    for _ in range(2):
        report = debug_problem(bad, str(DOMAIN), WORLD)
        assert not report.ok and "line" in report.messages[0]


def test_planning_does_not_import_scipy_stats_until_asked():
    """UP's engine base class imports ConfigSpace (and so scipy.stats, ~1 s) at import time;
    pipflow defers it. A whole debug/solve/verify pass must not load it, and asking an engine
    for its configuration space must still give the real object."""
    code = f"""
import sys
import yaml
from pipflow.pddl.debugger import debug_problem
from pipflow.pddl.solver import solve_problem
from pipflow.pddl.verifier import verify_plan
from pipflow.pddl.writer import write_problem
world = yaml.safe_load(open({str(ROOT / 'benchmarks' / 'warehouse' / 'world.yaml')!r}))
report = debug_problem(write_problem(world, {GOAL!r}), {str(DOMAIN)!r}, world)
robots = {{n: r["skills"]["carry"] for n, r in world["robots"].items()}}
res = solve_problem(report.problem, "pipflow-transport", {{"robots": robots, "rules": []}})
assert verify_plan(report.problem, res.plan, world).ok
assert "scipy.stats" not in sys.modules, "scipy.stats was imported"
from unified_planning.engines import Engine
space = Engine.get_configuration_space()
import ConfigSpace
assert type(space).__name__ == "ConfigurationSpace" and isinstance(space, ConfigSpace.ConfigurationSpace)
print("ok")
"""
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=300)
    assert out.returncode == 0 and out.stdout.strip().endswith("ok"), out.stderr[-2000:]


def test_main_job_imports_neither_matplotlib_nor_scipy_stats(tmp_path):
    """The main job with the default pictures=auto draws nothing, so it must not pay for
    matplotlib (unit colours come from a table) nor for scipy.stats (ConfigSpace deferred)."""
    code = f"""
import sys
from pipflow.engine.cli import main
code = main(["run", {str(ROOT / 'workflows' / 'warehouse.yaml')!r}, "--runs-dir", {str(tmp_path)!r}, "--no-cache", "-q"])
assert code == 0, code
heavy = [m for m in ("matplotlib", "scipy.stats", "ConfigSpace.hyperparameters") if m in sys.modules]
assert not heavy, heavy
print("ok")
"""
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=300)
    assert out.returncode == 0 and out.stdout.strip().endswith("ok"), out.stdout[-1000:] + out.stderr[-2000:]


def test_common_colours_match_matplotlib():
    from matplotlib.colors import to_rgba

    from pipflow.warehouse.simulation import colour_rgba

    for name in ("red", "Green", "blue", "magenta", "yellow", "cyan", "black", "white", "orange",
                 "purple", "grey", "gray", "brown", "teal", "#ff8800"):
        assert colour_rgba(name) == pytest.approx(to_rgba(name)), name
    assert colour_rgba("no-such-colour") == (0.5, 0.5, 0.5, 1.0)


def test_workflow_pictures_input(tmp_path):
    """auto (the default) draws nothing in the run; always draws the graph, Gantt and path map."""
    from pipflow.engine.cli import main

    for mode, drawn in (("auto", False), ("always", True)):
        runs = tmp_path / mode
        code = main(["run", str(ROOT / "workflows" / "warehouse.yaml"), "--runs-dir", str(runs), "--no-cache",
                     "-q", "-i", f"pictures={mode}"])
        assert code == 0
        run = next(runs.iterdir())
        pngs = sorted(p.name for p in run.rglob("*.png"))
        assert pngs == (["gantt.png", "graph.png", "paths.png"] if drawn else []), pngs


def test_picture_policy_by_mode_and_size():
    from pipflow import pictures

    schedule = {"robots": {f"r{i}": {"legs": [{"subtask": "s1"}] if i < 3 else []} for i in range(500)},
                "subtasks": [{"id": "s1", "robots": ["r0", "r1", "r2"]}]}
    assert pictures.size_of("gantt", schedule) == 3  # rows are the robots that work, not the fleet
    assert pictures.wanted("auto", "gantt", 3) and pictures.wanted(None, "graph", 80)
    assert not pictures.wanted("auto", "graph", 81) and pictures.wanted("always", "graph", 10_000)
    assert not pictures.wanted("never", "paths", 1)
    with pytest.raises(ValueError, match="pictures must be one of"):
        pictures.wanted("sometimes", "gantt", 1)

"""The step cache is content-addressed: a cached step whose input names a file is re-run when
that file's content changes, even though the path is the same."""
from __future__ import annotations

import json
import shutil
from pathlib import Path

from pipflow.engine import RunOptions, run_workflow

REPO = Path(__file__).resolve().parents[1]

WORKFLOW = """\
pipflow: 1
name: load-world
inputs:
  world: {type: path, default: world.yaml}
steps:
  - id: world
    uses: world.load
    with: {path: "${inputs.world}"}
outputs:
  stock: ${world.world.stock}
"""


def _run(folder: Path) -> tuple[dict, list[dict]]:
    result = run_workflow(folder / "wf.yaml", runs_dir=folder / "runs", options=RunOptions(use_cache=True))
    assert result.ok, result.error
    events = [json.loads(line) for line in (result.run_dir / "events.jsonl").read_text().splitlines()]
    return result.outputs, [e for e in events if e["event"] == "end" and e.get("step") == "world"]


def test_editing_a_file_named_by_a_cached_steps_input_is_a_cache_miss(engine_env):
    (engine_env / "wf.yaml").write_text(WORKFLOW)
    world = engine_env / "world.yaml"
    shutil.copy(REPO / "benchmarks/warehouse/world.yaml", world)

    first, ends = _run(engine_env)
    assert ends[0]["cached"] is False
    again, ends = _run(engine_env)
    assert ends[0]["cached"] is True and again == first

    world.write_text(world.read_text().replace("shelf4: {product1: 15,", "shelf4: {product1: 14,"))
    edited, ends = _run(engine_env)
    assert ends[0]["cached"] is False
    assert edited["stock"]["shelf4"]["product1"] == 14 and first["stock"]["shelf4"]["product1"] == 15


def test_a_cached_output_keeps_the_order_of_its_mappings(engine_env):
    """Robots in file order are data (the allocation breaks ties by it): a cache hit and a
    resumed run read back the same order as a fresh run, not keys sorted (robot10 before robot2)."""
    (engine_env / "wf.yaml").write_text(WORKFLOW.replace("stock: ${world.world.stock}",
                                                         "robots: ${world.world.robots}"))
    shutil.copy(REPO / "benchmarks/warehouse/world.yaml", engine_env / "world.yaml")
    fresh, _ = _run(engine_env)
    cached, ends = _run(engine_env)
    assert ends[0]["cached"] is True
    assert list(fresh["robots"]) == [f"robot{i}" for i in range(12)]
    assert list(cached["robots"]) == list(fresh["robots"])


def test_changed_step_code_is_a_cache_miss(tmp_path, monkeypatch):
    """A step whose code (or the code of its package) changed must not be served an old result,
    even when nobody bumped its version."""
    from pipflow.engine.cache import cache_key, code_fingerprint

    pkg = tmp_path / "fingerprint_demo"
    pkg.mkdir()
    (pkg / "__init__.py").write_text("")
    (pkg / "work.py").write_text("def f():\n    return 1\n")
    monkeypatch.syspath_prepend(str(tmp_path))
    code_fingerprint.cache_clear()
    before = cache_key("demo.step", "1", {"x": 1}, "fingerprint_demo.steps")
    (pkg / "work.py").write_text("def f():\n    return 2\n")  # the library the step calls changed
    code_fingerprint.cache_clear()
    after = cache_key("demo.step", "1", {"x": 1}, "fingerprint_demo.steps")
    assert before != after
    code_fingerprint.cache_clear()
    assert cache_key("demo.step", "1", {"x": 1}, "fingerprint_demo.steps") == after

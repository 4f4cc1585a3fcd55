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

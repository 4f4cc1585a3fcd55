"""The whole warehouse workflow with a language model (litellm's mock_response stands in for the
provider): a first answer that invents a product gets precise feedback, the second answer is
right, and its robot-use rule reaches the allocation."""
from __future__ import annotations

import json
from pathlib import Path

from pipflow.engine import RunOptions, run_workflow
from pipflow.language import asking, generator, llm
from pipflow.warehouse.problem import write_problem
from pipflow.warehouse.world import load_world

REPO = Path(__file__).resolve().parents[1]
GOAL = {"shelf2": {"product1": 20}, "shelf4": {"product1": 16}, "shelf3": {"product1": 2}}
RULE = {"never": ["robot0"], "product": "product1"}


def test_a_model_corrected_by_the_debugger_drives_the_whole_pipeline(tmp_path, monkeypatch, engine_env):
    good = write_problem(load_world(REPO / "benchmarks/warehouse/world.yaml"), GOAL)
    bad = good.replace("product1", "prodcut1")  # the paper's failure: a misspelling taken as a new product
    answers = [f"```pddl\n{bad}\n```", f"```pddl\n{good}\n```\n```json\n{json.dumps({'constraints': [RULE]})}\n```"]
    prompts: list[str] = []

    def provider(messages, **kw):
        prompts.append(messages[-1]["content"])
        return llm.complete(messages, **{**kw, "extra": {**(kw.get("extra") or {}), "mock_response": answers.pop(0)}})

    monkeypatch.setattr(asking, "complete", provider)
    command = ("There should be 20 product1 in shelf2, 16 product1 in shelf4, 2 product1 in shelf3. "
               "But robot 0 should not be used to move product1 from one shelf to another.")
    result = run_workflow("warehouse", {"command": command, "model": "openai/gpt-4o-mini"},
                          runs_dir=tmp_path / "runs", options=RunOptions(use_cache=False))
    assert result.ok, result.error
    assert result.outputs["rounds"] == 2 and len(prompts) == 2
    assert "prodcut1" in prompts[1] and "product1" in prompts[1]  # round 1's debugger feedback reached round 2
    assert result.outputs["goal"] == GOAL and result.outputs["constraints"] == [RULE]
    used = {r for s in result.outputs["schedule"]["subtasks"] for r in s["robots"]}
    assert "robot0" not in used and result.outputs["goal_met"] is True
    usage = json.loads((result.run_dir / "metrics.json").read_text())["totals"]
    assert usage["llm.total_tokens"] > 0  # summed over both rounds

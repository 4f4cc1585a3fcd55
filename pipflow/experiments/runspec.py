"""One bench run: what defines it (:class:`RunSpec`) and how it is run and scored in the calling
process (:func:`run_one`).

Below both the bench (which builds the specs and tables) and the backends (which ship specs to
processes or dask workers and call :func:`run_one` there), so neither imports the other for it.
"""
from __future__ import annotations

import time
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import yaml

from pipflow.engine.executor import RunOptions
from pipflow.engine.expr import resolve
from pipflow.engine.runner import run_workflow
from pipflow.engine.status import RunStatus
from pipflow.engine.store import read_json
from pipflow.errors import Refusal, TranslationError, UserError
from pipflow.experiments.benchdomains import domain_named
from pipflow.experiments.faultstats import fault_columns
from pipflow.meaning import misread_executed
from pipflow.values import NOT_UNDERSTOOD, ambiguous


#: the outputs a run under faults leaves even when it stops early (what it did, what went wrong)
FAULT_OUTPUTS = ("graph", "schedule", "simulation", "faults", "recoveries", "feasible_after_faults",
                 "faults_not_applicable")


@dataclass(frozen=True)
class RunSpec:
    variant: str
    task: dict
    seed: int
    workflow: str
    inputs: dict
    world_path: str
    runs_dir: str
    use_cache: bool = True
    fingerprint: dict | None = None  # what defines the run (see fingerprint()); None: not computed



def run_one(spec: RunSpec) -> dict:
    """Run and score one (variant, task, seed) in this process; never raises. A run that ends in
    a user error is marked ``user_error`` (the bench stops on it: see :func:`_execute`)."""
    task = spec.task
    row: dict[str, Any] = {"variant": spec.variant, "task": task["id"], "seed": spec.seed}
    started = time.perf_counter()
    inputs = {"command": task["command"], "world": spec.world_path, "seed": spec.seed,
              **(task.get("inputs") or {}), **spec.inputs}  # per-task inputs (a robot team, say)
    refusal = error = None
    kind: str | None = None   # the error's kind as the verdict reads it (judged_kind)
    outputs: dict = {}
    offered: list = []
    try:
        result = run_workflow(spec.workflow, inputs, runs_dir=spec.runs_dir, inputs_from_text=True,
                              options=RunOptions(use_cache=spec.use_cache))
        row["status"], row["run_dir"] = RunStatus(result.status).value, str(result.run_dir)
        row["error_kind"] = type(result.exception).__name__ if result.exception is not None else None
        row["user_error"] = isinstance(result.exception, UserError)
        kind = judged_kind(result.exception)
        outputs = result.outputs or {}
        offered = result.candidates
        if result.status is RunStatus.REFUSED:
            refusal = result.error
        elif result.status is not RunStatus.SUCCEEDED:
            error = result.error
        metrics = read_json(result.run_dir / "metrics.json", {})
        row["stage_seconds"] = metrics.get("step_seconds", {})
    except Exception as err:  # an invalid workflow or input: the run never started
        row["status"], error = "error", f"{type(err).__name__}: {err}"
        row["error_kind"], row["user_error"] = type(err).__name__, isinstance(err, UserError)
        kind = judged_kind(err)
    if ambiguous(task) and error is not None and kind == NOT_UNDERSTOOD:
        refusal, error = error, None  # the right answer to an ambiguous command: refuse, quoting the words
    domain = domain_named(task.get("domain"))
    if row["status"] != RunStatus.SUCCEEDED and row.get("run_dir") and spec.inputs.get("faults"):
        # a run a fault stopped (refused, failed) is scored on what it carried out before it stopped
        outputs = {**recorded_outputs(Path(row["run_dir"]), FAULT_OUTPUTS), **outputs}
    row.update(domain.score_bench_run(spec.world_path, task, outputs, refusal, error))
    row.update(fault_columns(outputs, row["status"]))
    read = outputs if row["status"] == RunStatus.SUCCEEDED or not row.get("run_dir") else \
        recorded_outputs(Path(row["run_dir"]), ("goal", "constraints", "loop", "reader", "planner", "engine",
                                                "planner_fallback"))
    # which refinement loop ran (pip-llm, checked) and whose reading the goal was (offline, model)
    row["loop"], row["reader"] = read.get("loop"), read.get("reader")
    row["model"] = _recorded_model(row.get("run_dir"))  # what the paper's tables label a variant with
    # which planner was asked for and which answered; a fallback the bench's own values asked to
    # avoid (a planner named by --matrix or -i) is not that planner's result: the run is an error
    row["planner"], row["engine"], row["fallback"] = read.get("planner"), read.get("engine"), read.get("planner_fallback")
    if row["fallback"] and row["planner"] and str(row["planner"]) in {str(v) for v in spec.inputs.values()}:
        error = (f"the planner {row['planner']} that this bench asks for could not run the problem: "
                 f"{row['fallback']}; {row['engine']}'s plan is not {row['planner']}'s result, so the run counts as "
                 f"failed (a fallback is accepted only where the bench does not name the planner)")
        row.update(domain.score_bench_run(spec.world_path, task, {}, None, error))
        row["status"], row["error_kind"] = "failed", "PlannerFallback"
        kind = "PlannerFallback"
    if row.get("run_dir") and not writes_goal(Path(row["run_dir"])):  # a baseline: it plans without a goal
        judged = {"understood": None, "misread": None, "understanding": "not measured: the workflow writes no goal"}
    elif row["status"] == RunStatus.SUCCEEDED and "goal" in read and read["goal"] is None:
        # a workflow whose model states no goal but writes the plan itself (the w/o D ablation):
        # there is no reading to compare with the gold, only the outcome (SR)
        judged = {"understood": None, "misread": None, "understanding": "not measured: the run states no goal"}
    else:
        judged = domain.understand(task, read, row["status"], kind, world_path=spec.world_path)
    row.update(judged if judged is not None else
               {"understood": None, "misread": None, "understanding": "not measured for this domain"})
    row["misread_executed"] = misread_executed(row.get("misread"), row.get("executed"))
    row["candidate_hit"] = _candidate_hit(domain, task, spec.world_path, row, kind, offered)
    row["seconds"] = round(time.perf_counter() - started, 3)
    return row


def judged_kind(exc: BaseException | None) -> str | None:
    """An error's kind as a run's verdict reads it: every :class:`TranslationError` is
    :data:`NOT_UNDERSTOOD`, whatever its class (a reading asked as a ``Choice``, a command said
    without stops that reads two ways): the reader refused to guess. Other errors by their class
    name (``Refusal``: refused as impossible)."""
    if exc is None:
        return None
    if isinstance(exc, TranslationError) and not isinstance(exc, Refusal):
        return NOT_UNDERSTOOD
    return type(exc).__name__


def _candidate_hit(domain: Any, task: dict, world_path: str, row: dict, kind: str | None,
                   offered: list) -> bool | None:
    """For a clear, feasible command the reader refused as not understood: whether the task's
    gold reading is among the candidate readings the refusal offered (issue 23's
    ``candidate_recall``); None for every other run."""
    if (row.get("status") == "succeeded" or kind != NOT_UNDERSTOOD
            or task.get("expect") == "refuse" or task.get("feasible") is False):
        return None
    for c in offered:
        read = {"goal": c.get("goal"), "constraints": c.get("constraints") or []}
        judged = domain.understand(task, read, "succeeded", None, world_path=world_path)
        if judged and judged.get("understood"):
            return True
    return False


def _recorded_model(run_dir: str | None) -> str | None:
    """The model a run was given (its input ``model`` as resolved), or None (no such input, no
    record)."""
    if not run_dir:
        return None
    try:
        inputs = read_json(Path(run_dir) / "inputs.json", None)
    except (UserError, OSError):  # a damaged record: the row stays, without the model
        return None
    model = inputs.get("model") if isinstance(inputs, dict) else None
    return str(model) if model is not None else None


def writes_goal(run_dir: Path) -> bool:
    """Whether the run's workflow has an output ``goal`` (its own snapshot says): a method that
    plans without stating a goal (the paper's baselines) reads no command into one, so whether
    it read the command right is not measured. True when the snapshot cannot be read."""
    try:
        snapshot = yaml.safe_load((run_dir / "workflow.yaml").read_text(encoding="utf-8")) or {}
    except (OSError, ValueError, yaml.YAMLError):
        return True
    outputs = snapshot.get("outputs") if isinstance(snapshot, dict) else None
    return not isinstance(outputs, dict) or "goal" in outputs


def recorded_outputs(run_dir: Path, names: tuple[str, ...]) -> dict:
    """The workflow outputs ``names`` of a run that did not finish, evaluated over the step outputs
    its record holds: a run that failed after resolving its goal (in allocation, say) still shows
    what it understood. An output whose steps did not finish is left out."""
    try:
        snapshot = yaml.safe_load((run_dir / "workflow.yaml").read_text(encoding="utf-8")) or {}
        steps = [d for d in (run_dir / "steps").iterdir() if d.is_dir()]
    except (OSError, ValueError, yaml.YAMLError):
        return {}
    namespace: dict[str, Any] = {}
    for folder in steps:
        data = read_json(folder / "outputs.json", None)
        if isinstance(data, dict):
            namespace[folder.name] = data["outputs"] if isinstance(data.get("outputs"), dict) else data
    out: dict[str, Any] = {}
    expressions = snapshot.get("outputs") if isinstance(snapshot, dict) else None
    for name in names:
        if isinstance(expressions, dict) and name in expressions:
            try:
                out[name] = resolve(expressions[name], namespace)
            except Exception:  # a step it needs did not finish: nothing to read
                continue
    return out

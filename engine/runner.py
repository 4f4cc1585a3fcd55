"""Run a workflow file end to end: validate, resolve inputs, create the run record, execute,
and leave the record complete whatever happens (success, step failure, refusal, Ctrl-C).
"""
from __future__ import annotations

import difflib
import math
import os
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from pipflow.errors import InputError, PipflowError, Refusal, UserError
from pipflow.resources import data_dir

from .executor import Executor, RunOptions, write_metrics
from .expr import ExpressionError, has_expression, resolve
from .interrupts import Interrupted, interrupt_signals
from .model import Workflow
from .provenance import Provenance, outside
from .registry import Registry, default_registry
from .store import DamagedRecord, RunStore, looks_secret, read_json, utc_now
from .types import coerce_text, type_matches
from .validate import check_given_values, load_workflow
from .writes import DiskError


@dataclass
class RunResult:
    run_dir: Path
    status: str  # succeeded | failed | refused | interrupted
    outputs: dict = field(default_factory=dict)
    error: str | None = None
    error_step: str | None = None
    exception: BaseException | None = None
    seconds: float = 0.0

    @property
    def ok(self) -> bool:
        return self.status == "succeeded"

    @property
    def candidates(self) -> list:
        """The readings a refusal offered instead (the error's ``candidates``; the input
        ``reading`` of a workflow that declares it runs one): empty when none were offered."""
        return list(getattr(self.exception, "candidates", None) or [])


def find_workflow(ref: str | Path) -> Path:
    """A workflow by path, or by the name of a built-in workflow (``warehouse``)."""
    p = Path(ref)
    if p.exists():
        return p
    builtin = data_dir("workflows")
    name = p.name if p.suffix in (".yaml", ".yml") else f"{p.name}.yaml"
    if (builtin / name).is_file():
        return builtin / name
    known = sorted(x.name for x in builtin.glob("*.yaml"))
    close = difflib.get_close_matches(name, known, n=1)
    raise UserError(f"{ref}: no such workflow file" + (f"; did you mean the built-in {close[0]!r}?" if close else
                                                       f"; built-in workflows: {', '.join(known)}"))


def declared_env(wf: Workflow) -> dict[str, str]:
    """The environment variables the workflow declares under ``env:`` (those set), less those
    whose names say they hold a key: all that ``${env.X}`` can see. A key is never a value in a
    workflow (validation refuses ``${env.OPENAI_API_KEY}``; this is the second line)."""
    return {name: os.environ[name] for name in wf.env if name in os.environ and not looks_secret(name)}


def resolve_inputs(wf: Workflow, given: dict[str, Any], from_text: bool = False, cwd: Path | None = None) -> dict:
    """Declared defaults, overridden by the given values (coerced from text for ``-i``)."""
    unknown = [k for k in given if k not in wf.inputs]
    if unknown:
        hints = []
        for k in unknown:
            close = difflib.get_close_matches(str(k), list(wf.inputs), n=1)  # an inputs file may have number keys
            hints.append(f"{k!r}" + (f" (did you mean {close[0]!r}?)" if close else ""))
        raise InputError(f"{wf.file}: unknown input {', '.join(hints)}; declared: {', '.join(wf.inputs) or 'none'}")
    env_ns = {"env": declared_env(wf), "inputs": {}}
    values: dict[str, Any] = {}
    for name, spec in wf.inputs.items():
        if name in given:
            value = given[name]
            if from_text and isinstance(value, str):
                try:
                    value = coerce_text(value, spec.type)
                except ValueError as err:
                    raise InputError(f"input {name!r}: {err}") from None
            base = cwd or Path.cwd()
        elif spec.required:
            raise InputError(f"{wf.file}: input {name!r} is required" + (f" ({spec.doc})" if spec.doc else "")
                             + f"; set it with -i {name}=...")
        else:
            value = spec.default
            if has_expression(value):
                try:
                    value = resolve(value, env_ns)
                except ExpressionError as err:
                    raise InputError(f"{spec.loc}: default of input {name!r}: {err}") from None
            base = Path(spec.loc.file).resolve().parent if spec.loc else wf.file.parent
        if spec.type == "path" and isinstance(value, str) and value and not Path(value).expanduser().is_absolute():
            value = str((base / Path(value).expanduser()).resolve())
        if spec.type == "path" and name not in given and isinstance(value, str) and value:
            problem = outside(value, [base])  # a default reads only where its workflow lives
            if problem:
                raise InputError(f"{spec.loc or wf.file}: default of input {name!r}: {problem}")
        if not type_matches(value, spec.type):
            raise InputError(f"input {name!r} must be {spec.type}, got {value!r}")
        if isinstance(value, float) and not math.isfinite(value):  # .nan / .inf in an inputs file
            raise InputError(f"input {name!r} must be a finite number, got {value!r}")
        if spec.choices and value not in spec.choices:
            raise InputError(f"input {name!r} must be one of {', '.join(map(str, spec.choices))}, got {value!r}")
        values[name] = value
    return values


def run_workflow(workflow: str | Path, inputs: dict[str, Any] | None = None, *, runs_dir: str | Path = "runs",
                 options: RunOptions | None = None, registry: Registry | None = None,
                 inputs_from_text: bool = False) -> RunResult:
    """Validate and run a workflow; never raises for a failed run (see ``RunResult``), only for
    problems found before a run directory exists (invalid workflow, bad inputs)."""
    registry = registry or default_registry()
    wf = load_workflow(find_workflow(workflow), registry)
    values = resolve_inputs(wf, inputs or {}, from_text=inputs_from_text)
    check_given_values(wf, registry, {k: values[k] for k in (inputs or {}) if k in values})
    provenance = _provenance(wf, values, inputs or {})
    store = RunStore.create(Path(runs_dir), wf.name)
    try:  # run.json first: a record is never without it (runs, show and resume look for it)
        store.update_run(workflow=str(wf.file), name=wf.name, status="running", started=utc_now(),
                         inputs=values, pid=os.getpid(), path_bases=wf.path_bases(), given=provenance.to_json(),
                         workflow_files=[str(f) for f in (wf.files or [wf.file])])
        store.reserve()
        store.write_snapshot(wf.snapshot(), values)
    except DiskError as err:  # full from the start: no record that could be resumed is left behind
        store.abandon()
        raise DiskError(f"{err}; nothing was run and no run record was kept", err.path, err.errno) from None
    except BaseException:
        store.close()
        raise
    return _execute(wf, store, values, options or RunOptions(), registry, completed=None, provenance=provenance)


def _provenance(wf: Workflow, values: dict, given: Any) -> Provenance:
    """Which values the user gave (names of ``given``), for the rules of :mod:`.provenance`."""
    return Provenance.of_run(values, list(given), [n for n, s in wf.inputs.items() if s.type == "path"])


SNAPSHOT = "workflow.yaml"


def resume_run(run_dir: str | Path, options: RunOptions | None = None, registry: Registry | None = None) -> RunResult:
    """Rerun only what did not finish in an earlier run, in the same run directory.

    The steps come from the run's own snapshot (``workflow.yaml``), never from the workflow
    file, which may have been edited or removed since: old outputs continue only under the step
    definitions that made them. The run directory is locked first, so a run that is still
    running cannot be resumed a second time."""
    registry = registry or default_registry()
    store = RunStore.open(Path(run_dir))
    store.lock()
    try:
        info = store.run_info()
        if info.get("status") == "succeeded":
            raise UserError(f"{run_dir}: this run already succeeded; nothing to resume")
        wf = _snapshot_workflow(store, info, registry)
        values = _recorded_inputs(wf, store)
        given = info.get("given") if isinstance(info.get("given"), list) else []
        provenance = _provenance(wf, values, [g for g in given if isinstance(g, str)])
        completed = _completed_nodes(wf, store)
        store.reserve()
        store.update_run(status="running", resumed=utc_now(), error=None, error_step=None, pid=os.getpid())
    except DiskError as err:
        store.close()
        raise DiskError(f"{err}; the run was not resumed (free some space and resume it again)",
                        err.path, err.errno) from None
    except BaseException:
        store.close()
        raise
    try:
        store.event("resume", reused=sorted(completed), damaged_events=store.damaged_events or None)
    except UserError as err:  # the event log cannot be written (a link, a full disk): the record says so
        result = RunResult(run_dir=store.root, status="failed", error=str(err), exception=err)
        store.release_reserve()
        try:
            store.update_run(status="failed", finished=utc_now(), error=str(err))
        finally:
            store.close()
        return result
    files = info.get("workflow_files")
    files = [f for f in files if isinstance(f, str)] if isinstance(files, list) else None
    return _execute(wf, store, values, options or RunOptions(), registry, completed, provenance=provenance,
                    files=files)


def _snapshot_workflow(store: RunStore, info: dict, registry: Registry) -> Workflow:
    """The workflow as the run recorded it, with relative paths starting where they did."""
    snapshot = store.root / SNAPSHOT
    if not snapshot.is_file():
        raise UserError(f"{store.root}: the run has no {SNAPSHOT} snapshot of its workflow; it cannot be resumed")
    wf = load_workflow(snapshot, registry)
    bases = info.get("path_bases")
    if isinstance(bases, dict):
        wf.apply_path_bases(bases)
    else:  # a record from before path_bases: paths start where the workflow file was
        origin = str(Path(str(info.get("workflow") or snapshot)).parent)
        wf.apply_path_bases({s.id: {"": origin} for s in wf.all_steps()})
    return wf


def _recorded_inputs(wf: Workflow, store: RunStore) -> dict:
    """The run's inputs. A value the record redacted (it held a secret) is read again from the
    environment when it came from a default; otherwise the run cannot go on with it."""
    values = read_json(store.root / "inputs.json", {})
    if not isinstance(values, dict):
        raise UserError(f"{store.root / 'inputs.json'}: damaged record (not a mapping of inputs)")
    hidden = [k for k, v in values.items() if isinstance(v, str) and "[redacted " in v]
    if hidden:
        fresh = resolve_inputs(wf, {k: v for k, v in values.items() if k not in hidden})
        for name in hidden:
            spec = wf.inputs.get(name)
            if spec is None or not has_expression(spec.default):
                raise UserError(f"input {name!r} of {store.root} held a secret, which run records never keep; "
                                "start a new run")
            values[name] = fresh[name]
    return values


def _completed_nodes(wf: Workflow, store: RunStore) -> dict[str, dict]:
    """Outputs of nodes that finished (a loop counts only if the loop itself finished)."""
    finished = {e.get("step") for e in store.events() if e.get("event") in ("end", "skip") and "iteration" not in e}
    completed: dict[str, dict] = {}
    for node in wf.nodes:
        if node.id not in finished:
            continue
        try:
            outputs = store.read_step_outputs(node.id)
            inner = {s.id: store.read_step_outputs(s.id) for s in getattr(node, "steps", [])}
        except DamagedRecord as err:  # run the node again rather than trust a damaged record
            store.event("warning", node.id, message=f"{err}; the step runs again")
            continue
        if not isinstance(outputs, dict):
            continue
        completed[node.id] = outputs
        completed.update({sid: out for sid, out in inner.items() if isinstance(out, dict)})
    return completed


def _execute(wf: Workflow, store: RunStore, values: dict, options: RunOptions, registry: Registry,
             completed: dict | None, provenance: Provenance, files: list | None = None) -> RunResult:
    executor = Executor(wf, registry, store, values, options, completed, provenance=provenance, files=files)
    started = time.perf_counter()
    result = RunResult(run_dir=store.root, status="running")
    store.listener = options.on_event
    try:
        with interrupt_signals():  # SIGTERM and SIGHUP end the run as interrupted, as Ctrl-C does
            result.outputs = executor.run()
            store.write_json(store.root / "outputs.json", result.outputs)
        result.status = "succeeded"
    except KeyboardInterrupt as err:
        why = f"interrupted by {err.name}" if isinstance(err, Interrupted) else "interrupted by the user"
        result.status, result.error, result.exception = "interrupted", why, err
    except ExpressionError as err:
        result.status, result.error, result.exception = "failed", str(err), err
    except PipflowError as err:
        result.status = "refused" if isinstance(err, Refusal) else "failed"
        result.error, result.exception = str(err), err
        result.error_step = getattr(err, "step_id", None)
    except Exception as err:  # a bug: keep the record, then let the traceback show
        result.status, result.error, result.exception = "failed", f"internal error: {type(err).__name__}: {err}", err
        result.error_step = getattr(err, "step_id", None)
        raise
    finally:
        result.seconds = time.perf_counter() - started
        _finish(store, executor, result)
    if isinstance(result.exception, KeyboardInterrupt):
        raise result.exception
    return result


def _finish(store: RunStore, executor: Executor, result: RunResult) -> None:
    """The record's last words: metrics, the error event, run.json's final status. The space
    reserved for them is given back first, so a run that filled the disk still says so; a write
    that fails even then turns a success into a failure naming the disk, and the rest are still
    tried (run.json last: a record whose run.json could not be written is shown as stale)."""
    store.release_reserve()
    try:
        for write in (lambda: write_metrics(store, executor.state, result.seconds), lambda: _error_event(store, result)):
            try:
                write()
            except DiskError as err:
                _fail(result, err)
        try:
            store.update_run(status=result.status, finished=utc_now(), error=result.error,
                             error_step=result.error_step, seconds=round(result.seconds, 6),
                             **({"candidates": result.candidates} if result.candidates else {}))
        except DiskError as err:
            _fail(result, err)
    finally:
        store.close()


def _error_event(store: RunStore, result: RunResult) -> None:
    if result.status != "succeeded":
        store.event("error", result.error_step, status=result.status, error=result.error,
                    kind=type(result.exception).__name__ if result.exception else None)


def _fail(result: RunResult, err: DiskError) -> None:
    if result.status == "succeeded":
        result.status, result.error, result.exception = "failed", str(err), err

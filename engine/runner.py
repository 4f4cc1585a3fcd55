"""Run a workflow file end to end: validate, resolve inputs, create the run record, execute,
and leave the record complete whatever happens (success, step failure, refusal, Ctrl-C).

What comes back is one :class:`Run`, the same object ``pipflow.run`` returns to a notebook and
the bench scores: its ``status`` is a :class:`~pipflow.engine.status.RunStatus`.
"""
from __future__ import annotations

import math
import os
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Callable

from pipflow.errors import InputError, PipflowError, Refusal, UserError
from pipflow.resources import data_dir
from pipflow.suggest import closest

from .executor import Executor, RunOptions, write_metrics
from .expr import ExpressionError, has_expression, resolve
from .interrupts import Interrupted, interrupt_signals
from .model import Workflow
from .provenance import Provenance, outside
from .status import RunStatus
from .registry import Registry, default_registry
from .store import DamagedRecord, RunStore, looks_secret, read_json, utc_now
from .types import coerce_text, type_matches
from .validate import check_given_values, load_workflow
from .writes import DiskError


#: writes a run's static HTML report and returns its path; installed by the records layer
#: (:mod:`pipflow.records.report`) when it is imported, since the engine imports nothing above it
_report_writer: Callable[[Path], Path] | None = None


def install_report_writer(writer: Callable[[Path], Path]) -> None:
    """Let :meth:`Run.report` write reports with ``writer`` (the records layer's hook)."""
    global _report_writer
    _report_writer = writer


@dataclass
class Run:
    """One run, finished or not: where its record is, how it stands, its outputs and why it
    stopped. Returned by :func:`run_workflow` and :func:`resume_run`, and by ``pipflow.run``."""

    run_dir: Path
    status: RunStatus
    outputs: dict = field(default_factory=dict)
    error: str | None = None
    error_step: str | None = None
    exception: BaseException | None = None
    seconds: float = 0.0

    @property
    def ok(self) -> bool:
        return RunStatus(self.status).ok

    @property
    def record(self) -> Path:
        """The run directory (what ``pipflow show``, ``report`` and ``view`` read)."""
        return Path(self.run_dir)

    @property
    def candidates(self) -> list:
        """The readings a refusal offered instead (the error's ``candidates``; the input
        ``reading`` of a workflow that declares it runs one): empty when none were offered."""
        return list(getattr(self.exception, "candidates", None) or [])

    def report(self) -> Path:
        """Write the run's static HTML report and return its path."""
        if _report_writer is None:
            raise UserError("no report writer is loaded: import pipflow.records.report (pipflow.run does)")
        return _report_writer(self.record)


#: the name this class had before it was one with the API's (kept for code that imports it)
RunResult = Run


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
    close = closest(name, known, n=1)
    raise UserError(f"{ref}: no such workflow file" + (f"; did you mean the built-in {close[0]!r}?" if close else
                                                       f"; built-in workflows: {', '.join(known)}"))


def declared_env(wf: Workflow) -> dict[str, str]:
    """The environment variables the workflow declares under ``env:`` (those set), less those
    whose names say they hold a key: all that ``${env.X}`` can see. A key is never a value in a
    workflow (validation refuses ``${env.OPENAI_API_KEY}``; this is the second line)."""
    return {name: os.environ[name] for name in wf.env if name in os.environ and not looks_secret(name)}


def default_path_problem(wf: Workflow, name: str, written: Any, resolved: str, base: Path) -> str | None:
    """Why the default of path input ``name`` (``written`` in the workflow, ``resolved`` against
    ``base``, the folder of the file that declares it) cannot be read, in words that say what to
    do; None when it can. A default must exist and reads only where its workflow lives
    (:func:`outside`: a file elsewhere only when the user names it). A copied built-in workflow is
    the usual case: its ``../benchmarks/...`` defaults were relative to pipflow's own folder; the
    message names pipflow's file and ``extends``."""
    spec = wf.inputs[name]
    where = f"{spec.loc or wf.file}: default of input {name!r}"
    if not Path(resolved).exists():
        problem = (f"{written!r} names {resolved}, which does not exist (a workflow's relative paths are read from "
                   f"the folder of the file that writes them, {base})")
    else:
        problem = outside(resolved, [base])  # a default reads only where its workflow lives
        if problem is None:
            return None
    builtins = data_dir("workflows").resolve()
    builtin = (builtins / str(written)).resolve() if isinstance(written, str) else None
    if builtin is None or not builtin.exists() or Path(wf.file).resolve().parent == builtins:
        return f"{where}: {problem}; name the file yourself: -i {name}=PATH (or --inputs, or a keyword of pipflow.run)"
    stem = Path(wf.file).stem
    base_name = stem if (builtins / f"{stem}.yaml").is_file() else "NAME"
    return (f"{where}: {problem}. This looks like a copy of a built-in workflow, whose defaults are relative to "
            f"pipflow's folder, where this file is {builtin}. Either name it: -i {name}={builtin} (or --inputs, or a "
            f"keyword of pipflow.run), or write `extends: {base_name}` instead of a copy, which keeps the built-in's "
            "defaults (a workflow's default may name a file outside its own folder and pipflow's only when you give "
            "it yourself)")


def resolve_inputs(wf: Workflow, given: dict[str, Any], from_text: bool = False, cwd: Path | None = None) -> dict:
    """Declared defaults, overridden by the given values (coerced from text for ``-i``)."""
    unknown = [k for k in given if k not in wf.inputs]
    if unknown:
        hints = []
        for k in unknown:
            close = closest(str(k), list(wf.inputs), n=1)  # an inputs file may have number keys
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
            problem = default_path_problem(wf, name, spec.default, value, base)
            if problem:
                raise InputError(problem)
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
                 inputs_from_text: bool = False) -> Run:
    """Validate and run a workflow; never raises for a failed run (see :class:`Run`), only for
    problems found before a run directory exists (invalid workflow, bad inputs)."""
    registry = registry or default_registry()
    wf = load_workflow(find_workflow(workflow), registry)
    values = resolve_inputs(wf, inputs or {}, from_text=inputs_from_text)
    check_given_values(wf, registry, {k: values[k] for k in (inputs or {}) if k in values})
    provenance = _provenance(wf, values, inputs or {})
    store = RunStore.create(Path(runs_dir), wf.name)
    try:  # run.json first: a record is never without it (runs, show and resume look for it)
        store.update_run(workflow=str(wf.file), name=wf.name, status=RunStatus.RUNNING, started=utc_now(),
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


def resume_run(run_dir: str | Path, options: RunOptions | None = None, registry: Registry | None = None) -> Run:
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
        if RunStatus.of(info.get("status")) is RunStatus.SUCCEEDED:
            raise UserError(f"{run_dir}: this run already succeeded; nothing to resume")
        wf = _snapshot_workflow(store, info, registry)
        values = _recorded_inputs(wf, store)
        given = info.get("given") if isinstance(info.get("given"), list) else []
        provenance = _provenance(wf, values, [g for g in given if isinstance(g, str)])
        completed = _completed_nodes(wf, store)
        store.reserve()
        store.update_run(status=RunStatus.RUNNING, resumed=utc_now(), error=None, error_step=None, pid=os.getpid())
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
        result = Run(run_dir=store.root, status=RunStatus.FAILED, error=str(err), exception=err)
        store.release_reserve()
        try:
            store.update_run(status=RunStatus.FAILED, finished=utc_now(), error=str(err))
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
             completed: dict | None, provenance: Provenance, files: list | None = None) -> Run:
    executor = Executor(wf, registry, store, values, options, completed, provenance=provenance, files=files)
    started = time.perf_counter()
    result = Run(run_dir=store.root, status=RunStatus.RUNNING)
    store.listener = options.on_event
    try:
        with interrupt_signals():  # SIGTERM and SIGHUP end the run as interrupted, as Ctrl-C does
            result.outputs = executor.run()
            store.write_json(store.root / "outputs.json", result.outputs)
        result.status = RunStatus.SUCCEEDED
    except KeyboardInterrupt as err:
        why = f"interrupted by {err.name}" if isinstance(err, Interrupted) else "interrupted by the user"
        result.status, result.error, result.exception = RunStatus.INTERRUPTED, why, err
    except ExpressionError as err:
        result.status, result.error, result.exception = RunStatus.FAILED, str(err), err
    except PipflowError as err:
        result.status = RunStatus.REFUSED if isinstance(err, Refusal) else RunStatus.FAILED
        result.error, result.exception = str(err), err
        result.error_step = getattr(err, "step_id", None)
    except Exception as err:  # a bug: keep the record, then let the traceback show
        result.status, result.error, result.exception = RunStatus.FAILED, f"internal error: {type(err).__name__}: {err}", err
        result.error_step = getattr(err, "step_id", None)
        raise
    finally:
        result.seconds = time.perf_counter() - started
        _finish(store, executor, result)
    if isinstance(result.exception, KeyboardInterrupt):
        raise result.exception
    return result


def _finish(store: RunStore, executor: Executor, result: Run) -> None:
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


def _error_event(store: RunStore, result: Run) -> None:
    if result.status is not RunStatus.SUCCEEDED:
        store.event("error", result.error_step, status=result.status, error=result.error,
                    kind=type(result.exception).__name__ if result.exception else None)


def _fail(result: Run, err: DiskError) -> None:
    if result.status is RunStatus.SUCCEEDED:
        result.status, result.error, result.exception = RunStatus.FAILED, str(err), err

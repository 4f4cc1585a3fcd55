"""Run a validated workflow: topological order, independent steps concurrently (``jobs``),
``when:`` conditions, bounded loops, per-step time-out and retries, the cache, and a run record
that is complete up to the moment anything fails.
"""
from __future__ import annotations

import concurrent.futures as cf
import heapq
import json
import os
import stat
import threading
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Callable

import networkx as nx

from pipflow.errors import InputError, PipflowError, Refusal, StepError, UserError

from .cache import CacheRefused, StepCache, cache_key
from .expr import ExpressionError, resolve, truthy
from .model import LoopSpec, StepSpec, Workflow
from .registry import Registry
from .step import Step, StepContext, check_outputs
from .provenance import Provenance
from .store import RunStore, looks_secret
from .types import type_matches
from .validate import dependency_graph


@dataclass
class RunOptions:
    jobs: int = 1
    use_cache: bool = True
    cache_dir: Path | None = None
    on_event: Callable[[dict], None] | None = None


@dataclass
class ExecutionState:
    """Outputs known so far, by step id (a loop's own outputs under the loop's id)."""

    outputs: dict[str, dict] = field(default_factory=dict)
    durations: dict[str, float] = field(default_factory=dict)
    metrics: dict[str, list[dict]] = field(default_factory=dict)  # per step, one dict per call


def _none_outputs(step: Step | None) -> dict:
    return {name: None for name in (step.outputs if step else {})}


def _declared(step: Step) -> dict:
    """What the record keeps of a step's declaration beside its name: the family of its outputs
    (readers of the record find steps by it, :func:`pipflow.engine.step.shape`)."""
    return {"shape": step.shape} if step.shape else {}


class Executor:
    def __init__(self, workflow: Workflow, registry: Registry, store: RunStore, inputs: dict,
                 options: RunOptions, completed: dict[str, dict] | None = None,
                 provenance: Provenance | None = None, files: list | None = None):
        self.wf = workflow
        self.registry = registry
        self.store = store
        self.inputs = inputs
        self.options = options
        self.cache = StepCache(options.cache_dir) if options.use_cache else None  # --no-cache: no reads, no writes
        self._cache_writable = True
        self.state = ExecutionState()
        self.state.outputs.update(completed or {})
        # declared only, and never a key: keys go to their providers from the environment, not
        # through a workflow's values (validation refuses ${env.SOME_KEY}; this is the second line)
        self._env = {name: os.environ[name] for name in workflow.env if name in os.environ and not looks_secret(name)}
        self.provenance = provenance if provenance is not None else Provenance(open=True)
        # the folders of the workflow file and of those it extends (``files``: as the run recorded
        # them, for a resume from the snapshot): files there are the workflow's own
        self._folders = tuple(dict.fromkeys(Path(f).resolve().parent for f in (files or workflow.files or [workflow.file])))
        self._lock = threading.Lock()

    # -- public --------------------------------------------------------------------------
    def run(self) -> dict:
        """Run every node not yet completed; return the workflow's outputs."""
        graph = self._node_graph()
        pending = [n for n in nx.topological_sort(graph) if n not in self.state.outputs]
        nodes = {n.id: n for n in self.wf.nodes}
        if self.options.jobs <= 1:
            for node_id in pending:
                self._run_node(nodes[node_id])
        else:
            self._run_parallel(graph, pending, nodes)
        return resolve(self.wf.outputs, self._namespace())

    # -- scheduling ----------------------------------------------------------------------
    def _node_graph(self) -> nx.DiGraph:
        owners = self.wf.node_of()
        graph = nx.DiGraph()
        graph.add_nodes_from(n.id for n in self.wf.nodes)
        for a, b in dependency_graph(self.wf).edges:
            if owners[a] != owners[b]:
                graph.add_edge(owners[a], owners[b])
        return graph

    def _run_parallel(self, graph: nx.DiGraph, pending: list[str], nodes: dict) -> None:
        """Run nodes on ``jobs`` threads, each as soon as its predecessors have finished, in the
        order of ``pending`` among those ready. Each node's count of unfinished predecessors is
        kept, so a finished node costs its out-degree, not a scan of everything still waiting
        (a scan per finished node is quadratic on a long chain)."""
        position = {node_id: i for i, node_id in enumerate(pending)}
        unfinished = {node_id: sum(1 for p in graph.predecessors(node_id) if p not in self.state.outputs)
                      for node_id in pending}
        ready = [position[node_id] for node_id in pending if unfinished[node_id] == 0]
        heapq.heapify(ready)
        running: dict[cf.Future, str] = {}
        failure: BaseException | None = None
        with cf.ThreadPoolExecutor(max_workers=self.options.jobs) as pool:
            while ready or running:
                if failure is None:
                    while ready and len(running) < self.options.jobs:
                        node_id = pending[heapq.heappop(ready)]
                        running[pool.submit(self._run_node, nodes[node_id])] = node_id
                if not running:
                    break
                done, _ = cf.wait(running, return_when=cf.FIRST_COMPLETED)
                for fut in done:
                    node_id = running.pop(fut)
                    if fut.exception() is not None:
                        failure = failure or fut.exception()
                        continue
                    for successor in graph.successors(node_id):
                        if successor in unfinished:
                            unfinished[successor] -= 1
                            if unfinished[successor] == 0:
                                heapq.heappush(ready, position[successor])
                if failure is not None and not running:
                    break
        if failure is not None:
            raise failure

    # -- namespace -----------------------------------------------------------------------
    def _namespace(self, extra: dict | None = None) -> dict:
        with self._lock:
            ns = dict(self.state.outputs)
        ns["inputs"] = self.inputs
        ns["env"] = self._env
        if extra:
            ns.update(extra)
        return ns

    def _publish(self, step_id: str, outputs: dict) -> None:
        with self._lock:
            self.state.outputs[step_id] = outputs

    # -- nodes ---------------------------------------------------------------------------
    def _run_node(self, node: StepSpec | LoopSpec) -> None:
        if isinstance(node, LoopSpec):
            self._run_loop(node)
        else:
            outputs = self._run_step(node, self._namespace())
            self._publish(node.id, outputs)

    def _run_loop(self, loop: LoopSpec) -> None:
        ns = self._namespace()
        steps = {s.id: self.registry.get(s.uses) for s in loop.steps}
        if loop.when is not None and not self._condition(loop.when, ns, loop.id):
            for s in loop.steps:
                self._publish(s.id, _none_outputs(steps[s.id]))
            self._finish_loop(loop, {"iterations": 0, "done": False, "skipped": True})
            self.store.event("skip", loop.id, reason="when")
            return
        try:
            maximum = resolve(loop.max, ns)
        except ExpressionError as err:
            raise self._located(InputError(f"loop {loop.id!r}: max: {err}"), loop.id)
        if not isinstance(maximum, int) or isinstance(maximum, bool) or maximum < 1:
            raise self._located(InputError(f"loop {loop.id!r}: max must be a whole number >= 1, got {maximum!r}"), loop.id)
        order = list(nx.topological_sort(dependency_graph(self.wf).subgraph([s.id for s in loop.steps])))
        by_id = {s.id: s for s in loop.steps}
        previous = {sid: _none_outputs(steps[sid]) for sid in by_id}
        self.store.event("start", loop.id, kind="loop", max=maximum)
        started = time.perf_counter()
        done, iteration = False, 0
        for iteration in range(1, maximum + 1):
            current: dict[str, dict] = {}
            for sid in order:
                iter_ns = self._namespace({**current, "previous": previous, "iteration": iteration})
                current[sid] = self._run_step(by_id[sid], iter_ns, (loop.id, iteration))
            for sid, out in current.items():
                self._publish(sid, out)
            done = self._condition(loop.until, self._namespace({**current, "iteration": iteration}), loop.id)
            self.store.event("iteration", loop.id, iteration=iteration, done=done)
            previous = current
            if done:
                break
        for sid in by_id:
            self.store.write_step_outputs(sid, self.state.outputs[sid])
        if not done and loop.on_max == "fail":
            # the loop's record says failed (not succeeded, then failed), and the message quotes
            # what the last round's steps said, so the cause is not left in the files
            self.store.write_step_outputs(loop.id, {"iterations": iteration, "done": False})
            said = _last_round_messages(previous, [sid for sid in order])
            raise self._located(StepError(
                f"loop {loop.id!r} reached its maximum of {maximum} iteration(s) and `until: {loop.until}` "
                f"still does not hold" + (f"; round {iteration} ended with: " + " | ".join(said) if said else "")),
                loop.id)
        self._finish_loop(loop, {"iterations": iteration, "done": done}, time.perf_counter() - started)

    def _finish_loop(self, loop: LoopSpec, outputs: dict, duration: float = 0.0) -> None:
        self.store.write_step_outputs(loop.id, outputs)
        self._publish(loop.id, outputs)
        self.state.durations[loop.id] = duration
        self.store.event("end", loop.id, status="skipped" if outputs.get("skipped") else "succeeded",
                         duration=round(duration, 6), iterations=outputs["iterations"])

    def _condition(self, value: Any, ns: dict, step_id: str) -> bool:
        try:
            return truthy(value, ns)
        except ExpressionError as err:
            raise self._located(InputError(f"condition of {step_id!r}: {err}"), step_id)

    # -- one step ------------------------------------------------------------------------
    def _run_step(self, spec: StepSpec, ns: dict, iteration: tuple[str, int] | None = None) -> dict:
        try:
            return self._step_and_record(spec, ns, iteration)
        except UserError as err:  # a record write of this step (a full disk, a link) names the step too
            raise self._located(err, spec.id)

    def _step_and_record(self, spec: StepSpec, ns: dict, iteration: tuple[str, int] | None) -> dict:
        step = self.registry.get(spec.uses)
        assert step is not None, spec.uses  # validation guarantees it
        label = {"iteration": iteration[1]} if iteration else {}
        if spec.when is not None and not self._condition(spec.when, ns, spec.id):
            outputs = _none_outputs(step)
            self.store.write_step_outputs(spec.id, outputs, iteration)
            self.store.event("skip", spec.id, reason="when", **_declared(step), **label)
            return outputs
        args = self._arguments(spec, step, ns)
        step_dir = self.store.step_dir(spec.id, iteration)
        artifact_dir = step_dir / "artifacts"
        self.store.event("start", spec.id, uses=spec.uses, **_declared(step), **label)
        started = time.perf_counter()
        use_cache = self.cache is not None and (spec.cache if spec.cache is not None else step.cacheable)
        key = cache_key(step.name, step.version, args, step.module) if use_cache else None
        problems: list[str] = []
        outputs = self.cache.get(key, artifact_dir, step.outputs, problems, root=self.store.root) if key else None
        for problem in problems:
            self.store.event("warning", spec.id, message=problem)
        cached = outputs is not None
        if not cached:
            outputs = self._call_with_retries(spec, step, args, artifact_dir, iteration)
            if key:
                self._cache_put(spec.id, key, outputs, artifact_dir)
        duration = time.perf_counter() - started
        self.store.write_step_outputs(spec.id, outputs, iteration)
        with self._lock:
            self.state.durations[spec.id] = self.state.durations.get(spec.id, 0.0) + duration
        verdict = {"verdict": "rejected"} if outputs.get("ok") is False else {}
        self.store.event("end", spec.id, status="succeeded", duration=round(duration, 6), cached=cached,
                         **verdict, **label)
        return outputs

    def _cache_put(self, step_id: str, key: str, outputs: dict, artifact_dir: Path) -> None:
        """Store a result; a cache that cannot be written is a warning (once), never a failure:
        the result is in the run record either way."""
        if not self._cache_writable:
            return
        try:
            self.cache.put(key, outputs, artifact_dir)
        except (OSError, CacheRefused) as err:
            message = str(err) if isinstance(err, CacheRefused) else \
                f"cannot write the step cache in {self.cache.root} ({err.strerror or err}); results are not cached"
            self.store.event("warning", step_id, message=message)
            self._cache_writable = False  # no more attempts in this run

    def _arguments(self, spec: StepSpec, step: Step, ns: dict) -> dict:
        args = step.defaults()
        for name, raw in spec.args.items():
            try:
                value = resolve(raw, ns)
            except ExpressionError as err:
                raise self._located(InputError(f"step {spec.id!r}: argument {name!r}: {err}"), spec.id)
            declared = step.inputs.get(name)
            if declared is not None and declared.type == "path" and isinstance(value, str) and value:
                base = spec.arg_base(name)
                value = str((base / Path(value).expanduser()).resolve()) if not Path(value).is_absolute() else value
                special = _special_file(value)
                if special:
                    raise self._located(InputError(
                        f"step {spec.id!r} ({spec.uses}): argument {name!r}: {value} is {special}, not an "
                        "ordinary file (a step would read it without end or block on it)"), spec.id)
                try:  # a path the workflow names lies where the workflow lives, or the user named it
                    self.provenance.check(value, [base, spec.base_dir, *self._folders],
                                          f"step {spec.id!r} ({spec.uses}): argument {name!r}")
                except InputError as err:
                    raise self._located(err, spec.id)
            args[name] = value
        for name, declared in step.inputs.items():
            value = args.get(name)
            if not type_matches(value, declared.type):
                raise self._located(InputError(
                    f"step {spec.id!r} ({spec.uses}): argument {name!r} must be {declared.type}, "
                    f"got {type(value).__name__} {_short(value)}"), spec.id)
            if declared.choices and value is not None and value not in declared.choices:
                raise self._located(InputError(
                    f"step {spec.id!r} ({spec.uses}): argument {name!r} must be one of "
                    f"{', '.join(map(str, declared.choices))}, got {value!r}"), spec.id)
        return args

    def _call_with_retries(self, spec: StepSpec, step: Step, args: dict, artifact_dir: Path,
                           iteration: tuple[str, int] | None) -> dict:
        attempts = int(spec.retry.get("attempts", 1))
        backoff = float(spec.retry.get("backoff", 1.0))
        for attempt in range(1, attempts + 1):
            ctx = StepContext(spec.id, artifact_dir, spec.base_dir,
                              log=lambda m: self.store.event("log", spec.id, message=m),
                              iteration=iteration[1] if iteration else None,
                              use_cache=self.options.use_cache,
                              warn=lambda m: self.store.event("warning", spec.id, message=m),
                              record_root=self.store.root, provenance=self.provenance,
                              own_folders=(spec.base_dir, *(spec.arg_base(a) for a in spec.args), *self._folders))
            try:
                outputs = self._call(spec, step, ctx, args)
                if ctx.metrics:
                    with self._lock:
                        self.state.metrics.setdefault(spec.id, []).append(dict(ctx.metrics))
                return outputs
            except (UserError, Refusal) as err:
                raise self._located(err, spec.id)
            except Exception as err:
                if attempt >= attempts:
                    if isinstance(err, PipflowError):
                        raise self._located(err, spec.id)
                    wrapped = StepError(f"step {spec.id!r} ({spec.uses}) failed: {type(err).__name__}: {err}")
                    wrapped.__cause__ = err
                    raise self._located(wrapped, spec.id)
                delay = backoff * 2 ** (attempt - 1)
                self.store.event("retry", spec.id, attempt=attempt, error=f"{type(err).__name__}: {err}", delay=delay)
                time.sleep(delay)
        raise AssertionError("unreachable")

    def _call(self, spec: StepSpec, step: Step, ctx: StepContext, args: dict) -> dict:
        if spec.timeout:
            outputs = _call_with_timeout(spec, step, ctx, args)
        else:
            outputs = step.func(ctx, **args)
        if not isinstance(outputs, dict):
            raise StepError(f"step {spec.id!r} ({spec.uses}) returned {type(outputs).__name__}, not a dict of outputs")
        try:
            outputs = json.loads(json.dumps(outputs))
        except (TypeError, ValueError) as err:
            raise StepError(f"step {spec.id!r} ({spec.uses}) returned outputs that are not JSON data: {err}") from None
        check_outputs(step, outputs, spec.id)
        for name in step.outputs:
            outputs.setdefault(name, None)
        return outputs

    def _located(self, err: BaseException, step_id: str) -> BaseException:
        if getattr(err, "step_id", None) is None:
            err.step_id = step_id  # type: ignore[attr-defined]
        return err


def _call_with_timeout(spec: StepSpec, step: Step, ctx: StepContext, args: dict) -> dict:
    """Run a step in a daemon thread and stop waiting after ``spec.timeout`` seconds.

    Python cannot kill a thread: a step that overruns keeps running in the background, but as a
    daemon it no longer holds the process open once the run has ended."""
    box: dict[str, Any] = {}

    def target() -> None:
        try:
            box["outputs"] = step.func(ctx, **args)
        except BaseException as err:  # handed to the caller's thread below
            box["error"] = err

    thread = threading.Thread(target=target, name=f"pipflow-step-{spec.id}", daemon=True)
    thread.start()
    thread.join(spec.timeout)
    if thread.is_alive():
        raise StepError(f"step {spec.id!r} ({spec.uses}) timed out after {spec.timeout:g} s")
    if "error" in box:
        raise box["error"]
    return box["outputs"]


def _special_file(path: str) -> str | None:
    """What a path-typed argument names when it is neither an ordinary file nor a folder nor
    missing (``/dev/zero``, a FIFO, a socket): steps read such paths as files."""
    try:
        mode = os.stat(path).st_mode
    except (OSError, ValueError):
        return None  # missing or unreadable: the step says so itself
    if stat.S_ISREG(mode) or stat.S_ISDIR(mode):
        return None
    if stat.S_ISFIFO(mode):
        return "a pipe"
    if stat.S_ISSOCK(mode):
        return "a socket"
    return "a device"


def _short(value: Any, limit: int = 60) -> str:
    text = repr(value)
    return text if len(text) <= limit else text[: limit - 3] + "..."


def _numeric_totals(records: list[dict]) -> dict[str, float]:
    """Sum every numeric leaf over all calls, by dotted key (e.g. ``llm.total_tokens``): a run's
    token usage and cost over every round of a loop, without the engine knowing about LLMs."""
    totals: dict[str, float] = {}

    def walk(value: Any, key: str) -> None:
        if isinstance(value, dict):
            for k, v in value.items():
                walk(v, f"{key}.{k}" if key else str(k))
        elif isinstance(value, (int, float)) and not isinstance(value, bool):
            totals[key] = totals.get(key, 0) + value

    for record in records:
        walk(record, "")
    return {k: round(v, 6) for k, v in sorted(totals.items())}


def write_metrics(store: RunStore, state: ExecutionState, total: float) -> dict:
    metrics = {
        "total_seconds": round(total, 6),
        "step_seconds": {k: round(v, 6) for k, v in state.durations.items()},
        "steps": state.metrics,
        "totals": _numeric_totals([m for calls in state.metrics.values() for m in calls]),
    }
    store.write_json(store.root / "metrics.json", metrics)
    return metrics


def _last_round_messages(outputs: dict[str, dict], order: list[str], limit: int = 6) -> list[str]:
    """What the steps of a loop's last round said: their ``errors`` and ``messages`` outputs
    (lists of text, by the convention of checking steps), at most ``limit``, each cut short."""
    said: list[str] = []
    for sid in order:
        out = outputs.get(sid) or {}
        for key in ("errors", "messages"):
            value = out.get(key)
            if isinstance(value, list) and all(isinstance(m, str) for m in value):
                said += [f"{sid}: {m[:300]}" for m in value]
    return said[:limit]

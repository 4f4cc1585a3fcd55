"""Where the runs of a bench execute: this machine's process pool (``local``) or a Dask cluster
(``dask``: a LocalCluster here, or ``dask=tcp://host:port`` for a running scheduler).

The unit of work is one run: one (variant, task, seed). A worker of a cluster may be another
machine, so it receives what a run needs **by content**: a *bundle* ``{relative path: text}`` of the
workflow file and every file it extends, the files its ``path`` inputs name (world, domain,
action metadata) and the folder of its prompt template. The worker writes the bundle once into a
temporary folder keyed by its hash, points the run's inputs there, runs and scores the run, and
sends back the result row with the run record zipped; the client unpacks the record into
``OUT/records/`` so a bench directory looks the same whichever backend made it.

These are the bench's *backends* (``pipflow bench --backend local|dask[=ADDRESS]``); the word
"executor" names only the engine's :mod:`pipflow.engine.executor`, which runs the steps of one
workflow inside each run.

Results stream back as runs finish (``as_completed``): each row is handed to ``on_row`` at once
(the bench writes it to ``OUT/runs/<variant>/<task>/<seed>.json`` and moves the progress bar).
Rows are keyed by (variant, task, seed) and deduplicated, so a run that Dask retried after a worker
died counts once.

LLM concurrency across a cluster is bounded per provider by :func:`llm_slot`, which
:func:`configure_llm_limits` installs as the hook of :mod:`pipflow.llmslot` that
:func:`pipflow.language.llm.complete` enters around each provider call: on a Dask worker it holds
a lease of a ``distributed.Semaphore`` named ``pipflow-llm-<provider>``; elsewhere it is a no-op.
"""
from __future__ import annotations

import contextlib
import ctypes
import hashlib
import io
import os
import shutil
import signal
import stat
import sys
import tempfile
import threading
import time
import uuid
import zipfile
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Callable

from pipflow import llmslot
from pipflow.engine.interrupts import SIGNALS
from pipflow.engine.registry import default_registry
from pipflow.engine.runner import find_workflow, resolve_inputs
from pipflow.engine.validate import load_workflow
from pipflow.errors import UserError
from pipflow.experiments.runspec import RunSpec, run_one
from pipflow.language.prompting import find_template

#: how long the client waits for a scheduler / workers before giving up (seconds)
CONNECT_TIMEOUT = 60


# ------------------------------------------------------------------------------------------
# LLM concurrency: a cluster-wide semaphore per provider
# ------------------------------------------------------------------------------------------

_LIMITS: dict[str, int] = {}
_BACKEND: str | None = None  # None (no limit) | "dask"
_SEMAPHORES: dict[str, Any] = {}
_LOCK = threading.Lock()


def parse_limits(text: str | None) -> dict[str, int]:
    """``"4"`` (every provider) or ``"openai=4,anthropic=2,default=8"`` -> {provider: n}."""
    out: dict[str, int] = {}
    for part in (text or "").split(","):
        part = part.strip()
        if not part:
            continue
        key, _, value = part.rpartition("=")
        try:
            n = int(value)
        except ValueError:
            raise UserError(f"LLM concurrency {text!r}: expected N or provider=N,...") from None
        if n < 1:
            raise UserError(f"LLM concurrency {text!r}: limits must be >= 1")
        out[key.strip() or "default"] = n
    return out


def configure_llm_limits(limits: dict[str, int] | None, backend: str | None) -> None:
    """Set this process's limiter (the dask backend calls it on the worker before each run)."""
    global _LIMITS, _BACKEND
    with _LOCK:
        if dict(limits or {}) != _LIMITS or backend != _BACKEND:
            _SEMAPHORES.clear()
        _LIMITS, _BACKEND = dict(limits or {}), backend
    llmslot.install(llm_slot if backend == "dask" else None)  # the hook language.llm.complete enters


def provider_of(model: str) -> str:
    """``openai/gpt-4o`` -> ``openai``; a bare model name is its own provider."""
    model = (model or "").strip()
    return model.split("/", 1)[0] if "/" in model else model or "default"


def _semaphore(provider: str):
    n = _LIMITS.get(provider, _LIMITS.get("default"))
    if n is None or _BACKEND != "dask":
        return None
    with _LOCK:
        sem = _SEMAPHORES.get(provider)
        if sem is None:
            from distributed import Semaphore

            sem = _SEMAPHORES[provider] = Semaphore(max_leases=n, name=f"pipflow-llm-{provider}")
        return sem


@contextlib.contextmanager
def llm_slot(model: str, timeout: float | None = None):
    """Hold one of the provider's cluster-wide LLM slots for the duration of the block."""
    sem = _semaphore(provider_of(model))
    if sem is None:
        yield
        return
    if not sem.acquire(timeout=timeout):
        raise TimeoutError(f"no free LLM slot for {provider_of(model)} within {timeout} s")
    try:
        yield
    finally:
        sem.release()


# ------------------------------------------------------------------------------------------
# bundles: what a run needs, by content
# ------------------------------------------------------------------------------------------


@dataclass(frozen=True)
class Bundle:
    """Files by path relative to a common root, and how the run's inputs point into them."""

    files: dict[str, str]          # relative posix path -> text
    workflow: str                   # relative path of the workflow file
    path_inputs: dict[str, str]     # input name -> relative path (path inputs, the prompt)
    digest: str


def _text_files(folder: Path, pattern: str) -> list[Path]:
    return [p for p in sorted(folder.glob(pattern)) if p.is_file()]


def build_bundle(workflow_ref: str, inputs: dict[str, Any]) -> Bundle:
    """The bundle of one variant: ``inputs`` are the bench's given inputs (text, like ``-i``)
    plus the task file's ``world``. Raises :class:`UserError` for an invalid workflow or input."""
    registry = default_registry()
    wf = load_workflow(find_workflow(workflow_ref), registry)
    values = resolve_inputs(wf, dict(inputs), from_text=True)
    files: set[Path] = {Path(f).resolve() for f in (wf.files or [wf.file])}
    targets: dict[str, Path] = {}
    for name, spec in wf.inputs.items():
        value = values.get(name)
        if spec.type == "path" and isinstance(value, str) and value and Path(value).is_file():
            targets[name] = Path(value).resolve()
        elif name == "prompt" or name.endswith("_prompt"):
            if isinstance(value, str) and value:
                try:
                    template = find_template(value, Path(wf.file).parent)
                except Exception:
                    continue
                targets[name] = template
                files.update(p.resolve() for p in _text_files(template.parent, "*.j2"))
    files.update(targets.values())
    root = Path(os.path.commonpath([str(p.parent) for p in files]))
    content = {p.relative_to(root).as_posix(): p.read_text(encoding="utf-8") for p in sorted(files)}
    digest = hashlib.sha256(repr(sorted(content.items())).encode("utf-8")).hexdigest()[:16]
    return Bundle(files=content, workflow=Path(wf.file).resolve().relative_to(root).as_posix(),
                  path_inputs={k: v.relative_to(root).as_posix() for k, v in targets.items()}, digest=digest)


def _bundles_folder() -> Path:
    """This user's folder of bundles in the temp folder, private (0700): a bundle found there is
    run as it is, so a folder another account could write into (``/tmp`` is shared) is never
    used; without a private one, a fresh folder of this process's serves."""
    uid = os.getuid() if hasattr(os, "getuid") else 0
    base = Path(tempfile.gettempdir()) / f"pipflow-bundles-{uid}"
    try:
        base.mkdir(mode=0o700, exist_ok=True)
        info = os.lstat(base)
        if stat.S_ISDIR(info.st_mode) and info.st_uid == uid and not info.st_mode & 0o077:
            return base
    except OSError:
        pass
    global _PRIVATE_BUNDLES
    if _PRIVATE_BUNDLES is None:
        _PRIVATE_BUNDLES = Path(tempfile.mkdtemp(prefix="pipflow-bundles-"))
    return _PRIVATE_BUNDLES


_PRIVATE_BUNDLES: Path | None = None


def materialize(bundle_files: dict[str, str], digest: str) -> Path:
    """Write a bundle under this user's private bundle folder once (keyed by its hash); return
    the root."""
    base = _bundles_folder()
    root = base / digest
    if (root / ".complete").exists():
        return root
    staging = Path(tempfile.mkdtemp(dir=base, prefix=f".{digest}."))
    for rel, text in bundle_files.items():
        target = staging / rel
        if ".." in Path(rel).parts or Path(rel).is_absolute():
            raise ValueError(f"bundle path {rel!r} leaves the bundle")
        target.parent.mkdir(parents=True, exist_ok=True)
        target.write_text(text, encoding="utf-8")
    (staging / ".complete").write_text("ok")
    try:
        os.rename(staging, root)
    except OSError:  # another run on this machine got there first
        shutil.rmtree(staging, ignore_errors=True)
    return root


def _zip_dir(folder: Path) -> bytes:
    buf = io.BytesIO()
    with zipfile.ZipFile(buf, "w", zipfile.ZIP_DEFLATED) as zf:
        for p in sorted(folder.rglob("*")):
            if p.is_file():
                zf.write(p, p.relative_to(folder).as_posix())
    return buf.getvalue()


def unpack_record(data: bytes, target: Path) -> Path:
    """Unpack a zipped run record into ``target`` (a fresh folder)."""
    target.mkdir(parents=True, exist_ok=True)
    with zipfile.ZipFile(io.BytesIO(data)) as zf:
        for name in zf.namelist():
            if ".." in Path(name).parts or Path(name).is_absolute():
                raise ValueError(f"record path {name!r} leaves the record")
        zf.extractall(target)
    return target


def run_remote(payload: dict) -> dict:
    """Run one (variant, task, seed) on a worker from its payload (bundle + run fields); never
    raises for a failed run. Returns the scored row plus ``record_zip`` (the run record)."""
    configure_llm_limits(payload.get("llm_limits"), "dask" if payload.get("llm_limits") else None)
    root = materialize(payload["bundle"], payload["digest"])
    inputs = dict(payload["inputs"])
    for name, rel in payload["path_inputs"].items():
        if name != "world":
            inputs[name] = str(root / rel)
    world_path = str(root / payload["path_inputs"]["world"])
    runs_dir = Path(tempfile.mkdtemp(prefix="pipflow-run-"))
    try:
        spec = RunSpec(payload["variant"], payload["task"], payload["seed"], str(root / payload["workflow"]),
                       inputs, world_path, str(runs_dir), payload.get("use_cache", True))
        row = run_one(spec)
        record = Path(row["run_dir"]) if row.get("run_dir") else None
        if record is not None and record.is_dir():
            row["record_name"] = record.name
            row["record_zip"] = _zip_dir(record)
        row["worker"] = _worker_address()
        return row
    finally:
        shutil.rmtree(runs_dir, ignore_errors=True)


def _worker_address() -> str | None:
    try:
        from distributed import get_worker

        return get_worker().address
    except Exception:
        return None


# ------------------------------------------------------------------------------------------
# backends: where the runs execute
# ------------------------------------------------------------------------------------------


def run_key(row_or_spec: Any) -> tuple[str, str, int]:
    """The identity of a run: (variant, task id, seed)."""
    if isinstance(row_or_spec, dict):
        return (row_or_spec["variant"], row_or_spec["task"], int(row_or_spec["seed"]))
    return (row_or_spec.variant, row_or_spec.task["id"], int(row_or_spec.seed))


def lost_row(spec, error: str) -> dict:
    """A row for a run the backend could not finish (not written to disk: ``--resume`` reruns it)."""
    return {"variant": spec.variant, "task": spec.task["id"], "seed": spec.seed, "status": "lost",
            "success": False, "goal_met": False, "gcr": 0.0, "exe": 0.0, "ru": 0.0, "tc_max": 0.0,
            "tc_avg": 0.0, "tc_avg_team": 0.0, "makespan": 0.0, "planned": 0, "executed": 0, "refused": False,
            "error": error, "violations": [error], "seconds": 0.0}


def parse_backend(text: str | None) -> tuple[str, str | None]:
    """``local`` | ``dask`` | ``dask=tcp://host:port`` -> (kind, address)."""
    text = (text or "local").strip()
    kind, _, address = text.partition("=")
    kind = kind.strip().lower()
    if kind not in ("local", "dask"):
        raise UserError(f"--backend {text!r}: expected local, dask or dask=ADDRESS")
    if kind == "local" and address:
        raise UserError(f"--backend {text!r}: the local backend takes no address")
    return kind, (address.strip() or None)


def die_with_parent(parent: int) -> None:
    """Start-up of a pool worker: end when the bench process ends, however it ends. A worker
    left behind (parent 1) blocks on its pipe for ever and keeps the caller's stdout open, so a
    script waiting for the bench's output hangs. On Linux the kernel sends the worker SIGKILL
    when its parent dies (``PR_SET_PDEATHSIG``); everywhere a watcher thread checks the parent
    every second. SIGTERM and SIGHUP get their default action back (the bench's own handler was
    inherited with the fork): an idle worker ends quietly, a running one records its run as
    interrupted (the engine turns them into an interrupt while a run runs)."""
    for signum in SIGNALS:
        signal.signal(signum, signal.SIG_DFL)
    if sys.platform.startswith("linux"):
        with contextlib.suppress(OSError, AttributeError):
            ctypes.CDLL(None, use_errno=True).prctl(1, int(signal.SIGKILL))  # 1: PR_SET_PDEATHSIG
    if os.getppid() != parent:  # the parent died before the line above took effect
        os._exit(1)
    threading.Thread(target=_watch_parent, args=(parent,), name="pipflow-parent-watch", daemon=True).start()


def _watch_parent(parent: int) -> None:
    while os.getppid() == parent:
        time.sleep(1.0)
    os._exit(1)


class LocalBackend:
    """Today's process pool (``jobs`` processes; 1 runs in this process)."""

    name = "local"

    def __init__(self, jobs: int):
        self.jobs = max(1, jobs)

    def run(self, specs: list, on_row: Callable[[dict], None]) -> None:
        import concurrent.futures as cf


        if self.jobs <= 1:
            for spec in specs:
                on_row(run_one(spec))
            return
        pool = cf.ProcessPoolExecutor(max_workers=self.jobs, initializer=die_with_parent, initargs=(os.getpid(),))
        try:
            futures = {pool.submit(run_one, spec): spec for spec in specs}
            for fut in cf.as_completed(futures):
                try:
                    row = fut.result()
                except Exception as err:  # a worker process died (BrokenProcessPool) or similar
                    row = lost_row(futures[fut], f"{type(err).__name__}: {err}")
                on_row(row)
        except BaseException:
            # stopped (Ctrl-C, SIGTERM, a user error in a row): the runs still going are told to
            # stop (their records say interrupted) instead of being waited for to the end
            for worker in list((getattr(pool, "_processes", None) or {}).values()):
                with contextlib.suppress(OSError, ValueError):
                    worker.terminate()
            raise
        finally:
            pool.shutdown(wait=True, cancel_futures=True)


class DaskBackend:
    """Runs on a Dask cluster: a LocalCluster of ``jobs`` single-threaded worker processes, or the
    scheduler at ``address``. Each run is submitted with ``retries`` (a worker that dies mid-run
    has its run rerun elsewhere)."""

    name = "dask"

    def __init__(self, jobs: int, address: str | None = None, retries: int = 2,
                 llm_limits: dict[str, int] | None = None, records_dir: Path | None = None):
        self.jobs, self.address, self.retries = max(1, jobs), address, retries
        self.llm_limits = dict(llm_limits or {})
        self.records_dir = records_dir
        self._bundles: dict[tuple, Bundle] = {}

    @contextlib.contextmanager
    def client(self):
        from distributed import Client, LocalCluster

        if self.address:
            client = Client(self.address, timeout=CONNECT_TIMEOUT)
            try:
                yield client
            finally:
                client.close(timeout=10)
            return
        cluster = LocalCluster(n_workers=self.jobs, threads_per_worker=1, processes=True,
                               dashboard_address=":0", silence_logs=40)
        client = Client(cluster, timeout=CONNECT_TIMEOUT)
        try:
            client.wait_for_workers(self.jobs, timeout=CONNECT_TIMEOUT)
            yield client
        finally:
            client.close(timeout=10)
            cluster.close(timeout=20)

    def bundle_for(self, spec) -> Bundle:
        given = {k: (str(v) if v is not None else v) for k, v in spec.inputs.items()}
        given["world"] = spec.world_path
        key = (spec.workflow, tuple(sorted(given.items())))
        if key not in self._bundles:
            self._bundles[key] = build_bundle(spec.workflow, given)
        return self._bundles[key]

    def payload(self, spec) -> dict:
        bundle = self.bundle_for(spec)
        inputs = {"command": spec.task["command"], "seed": spec.seed, **spec.inputs}
        return {"variant": spec.variant, "task": spec.task, "seed": spec.seed, "inputs": inputs,
                "bundle": bundle.files, "digest": bundle.digest, "workflow": bundle.workflow,
                "path_inputs": bundle.path_inputs, "use_cache": spec.use_cache, "llm_limits": self.llm_limits}

    def run(self, specs: list, on_row: Callable[[dict], None]) -> None:
        from distributed import as_completed

        payloads = [(spec, self.payload(spec)) for spec in specs]  # bundle errors before any cluster
        nonce = uuid.uuid4().hex[:8]
        with self.client() as client:
            futures = {}
            for spec, payload in payloads:
                v, t, s = run_key(spec)
                fut = client.submit(run_remote, payload, key=f"pipflow-run-{nonce}-{v}-{t}-{s}",
                                    retries=self.retries, pure=False)
                futures[fut] = spec
            try:
                for fut in as_completed(list(futures)):
                    spec = futures[fut]
                    try:
                        row = fut.result(timeout=CONNECT_TIMEOUT)
                    except Exception as err:  # KilledWorker after the retries, a lost scheduler...
                        row = lost_row(spec, f"{type(err).__name__}: {err}")
                    fut.release()
                    on_row(self._receive(row))
            finally:
                for fut in futures:
                    if not fut.done():
                        fut.cancel()

    def _receive(self, row: dict) -> dict:
        data = row.pop("record_zip", None)
        name = row.pop("record_name", None)
        if data is not None and name and self.records_dir is not None:
            row["run_dir"] = str(unpack_record(data, Path(self.records_dir) / name))
        elif row.get("run_dir"):
            row["run_dir"] = f"{row.get('worker') or 'worker'}:{row['run_dir']}"
        return row


def make_backend(backend: str, jobs: int, llm_limits: dict[str, int] | None = None,
                 records_dir: Path | None = None, retries: int = 2) -> LocalBackend | DaskBackend:
    """The backend that ``--backend`` names (see :func:`parse_backend`), ready to ``run`` specs."""
    kind, address = parse_backend(backend)
    if kind == "local":
        return LocalBackend(jobs)
    try:
        import distributed  # noqa: F401
    except ImportError:
        raise UserError("--backend dask needs the `distributed` package (pip install distributed)") from None
    return DaskBackend(jobs, address, retries=retries, llm_limits=llm_limits, records_dir=records_dir)


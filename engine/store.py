"""Run records: one directory per run, written atomically so that a failed or interrupted run
keeps everything done before the failure.

    runs/<UTC time>-<workflow>-<short id>/
      run.json            workflow file, inputs, status, error, times (updated as the run goes)
      workflow.yaml       snapshot of the resolved workflow (after `extends`)
      inputs.json         the inputs the run used
      events.jsonl        one JSON line per event: start, end, skip, retry, cached, error
      steps/<id>/outputs.json, steps/<id>/artifacts/...
      steps/<loop>/iterations/<n>/<id>/...   every iteration of a loop
      outputs.json, metrics.json

Guarantees: every record file has one mode (what ``open`` gives under the user's umask, also for
files written atomically); values of environment variables whose names look like keys, tokens or
passwords never reach a record or a log line (:func:`redact`); one process at a time writes a
run directory (an ``fcntl`` lock: :mod:`.locks`; a second writer is refused, and a record that
says "running" while nobody holds its lock is shown as stale); no write follows a link inside the
run's folder and a full or read-only disk is a user error (:mod:`.writes`); ``run.json`` is
written first and space is kept in reserve, so a run that fills the disk still records how it
ended; a damaged ``run.json`` or a torn line of ``events.jsonl`` is reported and skipped by the
readers, never a traceback.
"""
from __future__ import annotations

import datetime as _dt
import json
import os
import re
import shutil
import threading
import time
import uuid
from pathlib import Path
from typing import Any, Callable

import yaml

from pipflow.errors import UserError

from .locks import FolderLock, writer_alive
from .status import RunStatus
from .writes import FILE_MODE, AppendLog, DiskError, disk_error, write_file  # noqa: F401  (FILE_MODE, DiskError: re-exported)


# -- secrets ---------------------------------------------------------------------------------
# KEY, TOKEN, SECRET, PASSWORD/PASSWD, CREDENTIAL(S), PRIVATE: OPENAI_API_KEY, HF_TOKEN, DB_PASSWORD...
# (not PWD: that is the working folder, and redacting it would hide every path)
SECRET_NAME = re.compile(r"KEY|TOKEN|SECRET|PASSW|CREDENTIAL|PRIVATE", re.IGNORECASE)
_MIN_SECRET = 6  # shorter values ("1", "true") would redact ordinary text
_secrets: dict[str, str] = {}  # value -> variable name
_secrets_lock = threading.Lock()


def looks_secret(name: str) -> bool:
    """Whether an environment variable's name says that its value is a key, token or password."""
    return bool(SECRET_NAME.search(name))


def register_secrets(environ: Any = None) -> None:
    """Remember the values of secret-looking environment variables, so that :func:`redact`
    removes them from whatever pipflow writes (records, events, error messages)."""
    environ = os.environ if environ is None else environ
    with _secrets_lock:
        for name, value in environ.items():
            if looks_secret(name) and isinstance(value, str) and len(value) >= _MIN_SECRET \
                    and not (value.startswith(("/", "~")) and os.path.exists(os.path.expanduser(value))):
                _secrets[value] = name  # (the path of a key file is not the key: paths stay readable)


def redact(text: str) -> str:
    """``text`` with every registered secret value (also as it appears inside JSON strings)
    replaced by ``[redacted NAME]``."""
    if not _secrets:
        return text
    pattern, names = _redaction()
    return pattern.sub(lambda m: f"[redacted {names[m.group(0)]}]", text)


def secrets_in(text: str, min_length: int = 12) -> list[str]:
    """The names of the variables whose secret values occur in ``text`` (values of at least
    ``min_length`` characters: a refusal must not fire on ordinary words that happen to be short
    values). For checks of what leaves the machine (pipflow.language.llm)."""
    with _secrets_lock:
        found = {name for value, name in _secrets.items() if len(value) >= min_length and value in text}
    return sorted(found)


def _redact_bytes(data: bytes) -> bytes:
    if not _secrets:
        return data
    pattern, names = _redaction(raw=True)
    return pattern.sub(lambda m: f"[redacted {names[m.group(0)]}]".encode(), data)


_compiled_redaction: dict[tuple, tuple[re.Pattern, dict]] = {}


def _redaction(raw: bool = False) -> tuple[re.Pattern, dict]:
    """One pattern for all registered secrets (each value, and for text also its JSON-escaped
    form), compiled once per set of secrets: a record write is one scan, not one per secret and
    form. Longer forms are tried first, so a secret that contains another is removed whole."""
    with _secrets_lock:
        key = (raw, tuple(_secrets.items()))
        found = _compiled_redaction.get(key)
        if found is None:
            names: dict = {}
            for value, name in _secrets.items():
                forms = [value.encode("utf-8")] if raw else [value, json.dumps(value)[1:-1]]
                for form in forms:
                    names.setdefault(form, name)
            escaped = [re.escape(f) for f in sorted(names, key=len, reverse=True)]
            found = (re.compile(b"|".join(escaped) if raw else "|".join(escaped)), names)
            _compiled_redaction.clear()  # only the current set of secrets is ever asked for
            _compiled_redaction[key] = found
        return found


# -- files -----------------------------------------------------------------------------------
def atomic_write(path: Path, content: str | bytes, redacted: bool = True, root: Path | None = None) -> None:
    """Write a file so that readers see the old or the new content, never a torn one, with
    :data:`FILE_MODE`. Secrets are redacted unless ``redacted=False`` (caches, whose content
    hashes must match what the step returned). Below ``root`` (a record's folder) no link is
    followed (:mod:`pipflow.engine.writes`); a full or read-only disk raises
    :class:`~pipflow.engine.writes.DiskError`."""
    if isinstance(content, str):
        data = (redact(content) if redacted else content).encode("utf-8")
    else:
        data = _redact_bytes(content) if redacted else content
    write_file(path, data, root=root)


def write_json(path: Path, value: Any, root: Path | None = None) -> None:
    """Mappings keep their order (outputs read back by ``resume`` must equal the originals)."""
    atomic_write(path, json.dumps(value, indent=2, default=str) + "\n", root=root)


def read_json(path: Path, default: Any = None) -> Any:
    """A JSON file's value; ``default`` if it does not exist. A damaged file raises
    :class:`DamagedRecord` (a UserError naming the file and the cause)."""
    try:
        return json.loads(path.read_text(encoding="utf-8"))
    except FileNotFoundError:
        return default
    except (UnicodeDecodeError, json.JSONDecodeError) as err:
        where = f":{err.lineno}:{err.colno}" if isinstance(err, json.JSONDecodeError) else ""
        raise DamagedRecord(f"{path}{where}: damaged record ({_short_cause(err)})") from None
    except IsADirectoryError:
        raise DamagedRecord(f"{path}: damaged record (a folder where a file should be)") from None


def _short_cause(err: Exception) -> str:
    if isinstance(err, json.JSONDecodeError):
        return f"not valid JSON: {err.msg}"
    return "not UTF-8 text"


class DamagedRecord(UserError, ValueError):
    """A record file cannot be read (edited by hand, truncated, not JSON). Also a ValueError, as
    ``json.loads`` raised before: callers that treat a damaged file as missing keep doing so."""


def utc_now() -> str:
    return _dt.datetime.now(_dt.timezone.utc).strftime("%Y-%m-%dT%H:%M:%S.%fZ")


#: bytes a running record keeps in reserve (at least; more for a big run.json): when a write fails
#: for want of space, the reserve is given back so that the record can still say how the run ended
RESERVE_MIN = 64 * 1024
RESERVE_FILE = ".pipflow-reserve"


class RunStore:
    """The directory of one run and the writes into it (all through :mod:`pipflow.engine.writes`:
    below the run's folder no link is followed, and a full disk is a :class:`DiskError`)."""

    def __init__(self, root: Path):
        self.root = Path(root)
        self._lock = threading.Lock()
        self._events: AppendLog | None = None
        self._folder_lock = FolderLock(self.root, "run")
        self._reserved = False
        self.damaged_events: list[int] = []  # line numbers of events.jsonl that could not be read
        self.listener: Callable[[dict], None] | None = None  # e.g. a progress display
        register_secrets()

    @classmethod
    def create(cls, runs_dir: Path, workflow_name: str) -> "RunStore":
        """A new, locked run folder under ``runs_dir`` (nothing written in it yet)."""
        stamp = _dt.datetime.now(_dt.timezone.utc).strftime("%Y%m%dT%H%M%SZ")
        root = Path(runs_dir) / f"{stamp}-{workflow_name}-{uuid.uuid4().hex[:6]}"
        try:
            root.mkdir(parents=True, exist_ok=False)
            probe = root / ".pipflow-probe"  # /proc and friends accept mkdir but not files
            probe.write_bytes(b"")
            probe.unlink()
        except OSError as err:
            full = disk_error(err, root)
            if full is not None and full.full:
                raise full from None
            cause = err.strerror or type(err).__name__
            if Path(runs_dir).exists() and not Path(runs_dir).is_dir():
                cause = "it is a file, not a folder"
            raise UserError(f"--runs-dir {runs_dir}: cannot write a run record there ({cause})") from None
        store = cls(root)
        store.lock()
        return store

    @classmethod
    def open(cls, root: Path) -> "RunStore":
        root = Path(root)
        if not (root / "run.json").exists():  # a damaged run.json is reported by the readers
            raise UserError(f"{root}: not a pipflow run directory (no run.json)")
        return cls(root)

    def lock(self) -> None:
        """Become the one process that writes this run (released by :meth:`close`, or when the
        process ends, however it ends); a second writer (``resume`` of a run that is still
        running) is refused."""
        self._folder_lock.acquire()

    # -- space -------------------------------------------------------------------------
    def reserve(self) -> None:
        """Set space aside for the record's last words (see :data:`RESERVE_MIN`); raises
        :class:`DiskError` when even that does not fit."""
        try:
            size = (self.root / "run.json").stat().st_size
        except OSError:
            size = 0
        write_file(self.root / RESERVE_FILE, bytes(RESERVE_MIN + 2 * size), root=self.root)
        self._reserved = True

    def release_reserve(self) -> None:
        """Give the reserved space back (before the last writes of a run, and at once when a
        write failed for want of space)."""
        if self._reserved:
            try:
                os.unlink(self.root / RESERVE_FILE)
            except OSError:
                pass
            self._reserved = False

    def abandon(self) -> None:
        """Remove a record that never got as far as its snapshot (the disk was full from the
        start): it holds only what this process just wrote, and a record without a workflow
        snapshot could be neither listed usefully nor resumed."""
        self.close()
        shutil.rmtree(self.root, ignore_errors=True)

    # -- files ---------------------------------------------------------------------------
    def step_dir(self, step_id: str, iteration: tuple[str, int] | None = None) -> Path:
        if iteration:
            loop, n = iteration
            return self.root / "steps" / loop / "iterations" / str(n) / step_id
        return self.root / "steps" / step_id

    def write(self, path: Path, content: str | bytes) -> None:
        """Write a file of this record (atomically, no link followed, secrets redacted)."""
        atomic_write(path, content, root=self.root)

    def write_json(self, path: Path, value: Any) -> None:
        write_json(path, value, root=self.root)

    def write_step_outputs(self, step_id: str, outputs: dict, iteration: tuple[str, int] | None = None) -> None:
        self.write_json(self.step_dir(step_id, iteration) / "outputs.json", outputs)

    def read_step_outputs(self, step_id: str) -> dict | None:
        return read_json(self.step_dir(step_id) / "outputs.json")

    def write_snapshot(self, workflow_data: dict, inputs: dict) -> None:
        dumper = getattr(yaml, "CSafeDumper", yaml.SafeDumper)  # libyaml: ~10x faster on big workflows
        self.write(self.root / "workflow.yaml", yaml.dump(workflow_data, Dumper=dumper, sort_keys=False))
        self.write_json(self.root / "inputs.json", inputs)

    def update_run(self, **fields: Any) -> dict:
        with self._lock:
            info = read_json(self.root / "run.json", {})
            info.update(fields)
            self.write_json(self.root / "run.json", info)
            return info

    def run_info(self) -> dict:
        info = read_json(self.root / "run.json", {})
        if not isinstance(info, dict):
            raise DamagedRecord(f"{self.root / 'run.json'}: damaged record (not a JSON object)")
        return info

    # -- events --------------------------------------------------------------------------
    def event(self, event: str, step: str | None = None, /, **fields: Any) -> None:
        record = {"time": utc_now(), "t": time.time(), "event": event}
        if step is not None:
            record["step"] = step
        record.update(fields)
        text = json.dumps(record, default=str)
        line = redact(text)
        if line is not text and line != text:  # the listener sees what the record keeps
            record = json.loads(line)
        with self._lock:
            if self._events is None:
                self._events = AppendLog(self.root / "events.jsonl", root=self.root)
            self._events.write((line + "\n").encode("utf-8"))
        if self.listener is not None:
            try:
                self.listener(record)
            except Exception:  # a display that cannot write (closed pipe) must not fail the run
                self.listener = None

    def events(self) -> list[dict]:
        """The readable events; the numbers of lines that are not (a torn last line, a hand
        edit) are kept in :attr:`damaged_events`."""
        try:
            raw = (self.root / "events.jsonl").read_bytes()
        except FileNotFoundError:
            return []
        except OSError:  # a folder or an unreadable file where the log should be
            self.damaged_events = [0]
            return []
        out, self.damaged_events = [], []
        for number, line in enumerate(raw.split(b"\n"), start=1):
            if not line.strip():
                continue
            try:
                event = json.loads(line.decode("utf-8"))
            except (UnicodeDecodeError, json.JSONDecodeError):
                self.damaged_events.append(number)
                continue
            if isinstance(event, dict):
                out.append(event)
            else:
                self.damaged_events.append(number)
        return out

    def close(self) -> None:
        with self._lock:
            if self._events is not None:
                self._events.close()
                self._events = None
            self.release_reserve()
            self._folder_lock.release()


#: the status shown for a record whose writer died (the name readers used before the enum)
STALE = RunStatus.STALE


def shown_status(run_dir: Path, info: dict) -> RunStatus | str:
    """The status readers show: a record that says "running" while no process holds its lock
    was left by a process that died without saying how the run ended (kill -9, a power cut):
    it is shown as ``stale`` (``pipflow resume`` continues it). A word that names no status (a
    damaged or foreign record) is shown as it is."""
    status = RunStatus.of(info.get("status", "?"))
    if status is None:
        return str(info.get("status", "?"))
    if status is RunStatus.RUNNING and writer_alive(run_dir) is False:
        return RunStatus.STALE
    return status


def stale_note(run_dir: Path, info: dict) -> str:
    """Why a stale record is stale, in words, for ``show`` and the listings."""
    pid = info.get("pid")
    # short enough for the listing's column (70 characters), hint included
    return f"process{f' {pid}' if pid else ''} gone (killed?); `pipflow resume` continues it"


def list_runs(runs_dir: Path) -> list[Path]:
    """Run directories under ``runs_dir``, newest first."""
    if not Path(runs_dir).is_dir():
        return []
    try:
        runs = [p for p in Path(runs_dir).iterdir() if (p / "run.json").exists()]
    except OSError as err:
        raise UserError(f"{runs_dir}: cannot list runs ({err.strerror or err})") from None
    return sorted(runs, key=lambda p: p.name, reverse=True)


def find_run(ref: str, runs_dir: Path) -> Path:
    """A run by path, by directory name, or by a unique prefix/suffix of its name."""
    p = Path(ref)
    if (p / "run.json").exists():
        return p
    matches = [r for r in list_runs(runs_dir) if r.name == ref or r.name.startswith(ref) or r.name.endswith(ref)]
    if len(matches) == 1:
        return matches[0]
    if not matches:
        raise UserError(f"no run {ref!r} in {runs_dir} (see `pipflow runs`)")
    raise UserError(f"{ref!r} matches {len(matches)} runs: " + ", ".join(m.name for m in matches[:5]))

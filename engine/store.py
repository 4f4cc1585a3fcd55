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
"""
from __future__ import annotations

import datetime as _dt
import json
import os
import tempfile
import threading
import time
import uuid
from pathlib import Path
from typing import Any, Callable

import yaml

from pipflow.errors import UserError


def atomic_write(path: Path, content: str | bytes) -> None:
    """Write a file so that readers see the old or the new content, never a torn one."""
    path.parent.mkdir(parents=True, exist_ok=True)
    data = content.encode("utf-8") if isinstance(content, str) else content
    fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.")
    try:
        with os.fdopen(fd, "wb") as fh:
            fh.write(data)
        os.replace(tmp, path)
    except BaseException:
        try:
            os.unlink(tmp)
        except OSError:
            pass
        raise


def write_json(path: Path, value: Any) -> None:
    atomic_write(path, json.dumps(value, indent=2, sort_keys=True, default=str) + "\n")


def read_json(path: Path, default: Any = None) -> Any:
    try:
        return json.loads(path.read_text(encoding="utf-8"))
    except FileNotFoundError:
        return default


def utc_now() -> str:
    return _dt.datetime.now(_dt.timezone.utc).strftime("%Y-%m-%dT%H:%M:%S.%fZ")


class RunStore:
    """The directory of one run and the writes into it."""

    def __init__(self, root: Path):
        self.root = root
        self._lock = threading.Lock()
        self._events = None
        self.listener: Callable[[dict], None] | None = None  # e.g. a progress display

    @classmethod
    def create(cls, runs_dir: Path, workflow_name: str) -> "RunStore":
        stamp = _dt.datetime.now(_dt.timezone.utc).strftime("%Y%m%dT%H%M%SZ")
        root = Path(runs_dir) / f"{stamp}-{workflow_name}-{uuid.uuid4().hex[:6]}"
        root.mkdir(parents=True, exist_ok=False)
        return cls(root)

    @classmethod
    def open(cls, root: Path) -> "RunStore":
        root = Path(root)
        if not (root / "run.json").exists():
            raise UserError(f"{root}: not a pipflow run directory (no run.json)")
        return cls(root)

    # -- files ---------------------------------------------------------------------------
    def step_dir(self, step_id: str, iteration: tuple[str, int] | None = None) -> Path:
        if iteration:
            loop, n = iteration
            return self.root / "steps" / loop / "iterations" / str(n) / step_id
        return self.root / "steps" / step_id

    def write_step_outputs(self, step_id: str, outputs: dict, iteration: tuple[str, int] | None = None) -> None:
        write_json(self.step_dir(step_id, iteration) / "outputs.json", outputs)

    def read_step_outputs(self, step_id: str) -> dict | None:
        return read_json(self.step_dir(step_id) / "outputs.json")

    def write_snapshot(self, workflow_data: dict, inputs: dict) -> None:
        dumper = getattr(yaml, "CSafeDumper", yaml.SafeDumper)  # libyaml: ~10x faster on big workflows
        atomic_write(self.root / "workflow.yaml", yaml.dump(workflow_data, Dumper=dumper, sort_keys=False))
        write_json(self.root / "inputs.json", inputs)

    def update_run(self, **fields: Any) -> dict:
        with self._lock:
            info = read_json(self.root / "run.json", {})
            info.update(fields)
            write_json(self.root / "run.json", info)
            return info

    def run_info(self) -> dict:
        return read_json(self.root / "run.json", {})

    # -- events --------------------------------------------------------------------------
    def event(self, event: str, step: str | None = None, /, **fields: Any) -> None:
        record = {"time": utc_now(), "t": time.time(), "event": event}
        if step is not None:
            record["step"] = step
        record.update(fields)
        line = json.dumps(record, default=str) + "\n"
        with self._lock:
            if self._events is None:
                self._events = open(self.root / "events.jsonl", "a", encoding="utf-8")
            self._events.write(line)
            self._events.flush()
        if self.listener is not None:
            try:
                self.listener(record)
            except Exception:  # a display that cannot write (closed pipe) must not fail the run
                self.listener = None

    def events(self) -> list[dict]:
        try:
            lines = (self.root / "events.jsonl").read_text(encoding="utf-8").splitlines()
        except FileNotFoundError:
            return []
        return [json.loads(line) for line in lines if line.strip()]

    def close(self) -> None:
        with self._lock:
            if self._events is not None:
                self._events.close()
                self._events = None


def list_runs(runs_dir: Path) -> list[Path]:
    """Run directories under ``runs_dir``, newest first."""
    if not Path(runs_dir).is_dir():
        return []
    runs = [p for p in Path(runs_dir).iterdir() if (p / "run.json").exists()]
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

"""Content-addressed step cache: the key is the step's name and version, a hash of its code, its
resolved inputs and the content of every file they name, so a changed argument, changed code or an
edited world, domain or prompt file is a miss. On by default
for steps that declare themselves cacheable (LLM calls); ``--no-cache`` turns it off.
An entry holds the outputs and a copy of the artifacts, so a hit leaves the same run record."""
from __future__ import annotations

import functools
import hashlib
import json
import os
import shutil
from pathlib import Path
from typing import Any

from .store import atomic_write


def default_cache_dir() -> Path:
    env = os.environ.get("PIPFLOW_CACHE_DIR")
    if env:
        return Path(env)
    base = os.environ.get("XDG_CACHE_HOME") or str(Path.home() / ".cache")
    return Path(base) / "pipflow" / "steps"


_HASH_LIMIT = 64 * 1024 * 1024  # bytes; larger files are keyed by size and modification time


def _file_digests(value: Any, out: dict[str, str]) -> None:
    """Digest every existing file an input names by absolute path, so that editing a world,
    domain or prompt file is a cache miss even though the path is the same."""
    if isinstance(value, str):
        if os.path.isabs(value) and os.path.isfile(value):
            stat = os.stat(value)
            if stat.st_size > _HASH_LIMIT:
                out[value] = f"size={stat.st_size},mtime={stat.st_mtime_ns}"
            else:
                with open(value, "rb") as fh:
                    out[value] = hashlib.sha256(fh.read()).hexdigest()
    elif isinstance(value, dict):
        for v in value.values():
            _file_digests(v, out)
    elif isinstance(value, list):
        for v in value:
            _file_digests(v, out)


@functools.lru_cache(maxsize=None)
def code_fingerprint(module: str) -> str:
    """A hash of the source code a step runs, so that changed code is a miss even where nobody
    bumped the step's version: a step's work lives in the library it calls, so this covers the
    whole top-level package of the step's module (for pipflow: the library, engine and steps)."""
    import importlib

    top = module.split(".")[0]
    roots: set[Path] = set()
    for name in ([top, f"{top}.engine", f"{top}.steps"] if top == "pipflow" else [top]):
        try:
            mod = importlib.import_module(name)
        except ImportError:
            continue
        roots |= {Path(p) for p in getattr(mod, "__path__", [])} or {Path(mod.__file__).parent}
    digest = hashlib.sha256()
    for root in sorted(roots):
        for file in sorted(root.rglob("*.py")):
            digest.update(str(file.relative_to(root)).encode())
            digest.update(file.read_bytes())
    return digest.hexdigest()


def cache_key(step_name: str, version: str, inputs: dict[str, Any], module: str = "") -> str:
    """Step name, step version, the step's code, resolved inputs, and the content of the files
    the inputs name."""
    files: dict[str, str] = {}
    _file_digests(inputs, files)
    code = code_fingerprint(module) if module else ""
    canonical = json.dumps({"step": step_name, "version": version, "code": code, "inputs": inputs, "files": files},
                           sort_keys=True, separators=(",", ":"), default=str)
    return hashlib.sha256(canonical.encode("utf-8")).hexdigest()


class StepCache:
    def __init__(self, root: Path | None = None):
        self.root = Path(root) if root else default_cache_dir()

    def _entry(self, key: str) -> Path:
        return self.root / key[:2] / key

    def get(self, key: str, artifact_dir: Path) -> dict | None:
        entry = self._entry(key)
        try:
            outputs = json.loads((entry / "outputs.json").read_text(encoding="utf-8"))
        except (FileNotFoundError, json.JSONDecodeError):
            return None
        if (entry / "artifacts").is_dir():
            shutil.copytree(entry / "artifacts", artifact_dir, dirs_exist_ok=True)
        return outputs

    def put(self, key: str, outputs: dict, artifact_dir: Path) -> None:
        entry = self._entry(key)
        if artifact_dir.is_dir():
            shutil.copytree(artifact_dir, entry / "artifacts", dirs_exist_ok=True)
        atomic_write(entry / "outputs.json", json.dumps(outputs, sort_keys=True, default=str))

    def clear(self) -> int:
        """Remove every entry; returns how many there were."""
        if not self.root.is_dir():
            return 0
        count = sum(1 for p in self.root.glob("*/*") if p.is_dir())
        shutil.rmtree(self.root)
        return count

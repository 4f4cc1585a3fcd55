"""Content-addressed step cache: the key is the step's name and version, a hash of its code, its
resolved inputs and the content of every file they name, so a changed argument, changed code or an
edited world, domain or prompt file is a miss. On by default
for steps that declare themselves cacheable (LLM calls); ``--no-cache`` turns it off.
An entry holds the outputs and a copy of the artifacts, so a hit leaves the same run record.

Nothing in the cache is trusted: each entry carries a manifest with the SHA-256 of its outputs
and of every artifact, written last; an entry that does not verify (damaged, truncated, edited,
``[]``/``{}`` in place of the step's outputs, half written) is a miss and is removed, never a
failure. The cache folder is marked with a ``CACHEDIR.TAG`` naming pipflow; pipflow writes into
no folder that holds anything else, and ``pipflow cache clear`` removes only the entries it
wrote, refusing a folder without the mark. A cache that cannot be written is a warning."""
from __future__ import annotations

import functools
import hashlib
import json
import os
import re
import shutil
import uuid
from pathlib import Path
from typing import Any, Iterable

from pipflow.errors import UserError

from .store import atomic_write
from .writes import write_file


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
            if stat.st_size > _HASH_LIMIT or stat.st_size == 0:  # size 0: also /proc files that never end
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


#: the layout of stored outputs; entries of another format are never hit (2: mappings keep their order)
FORMAT = 2


def cache_key(step_name: str, version: str, inputs: dict[str, Any], module: str = "") -> str:
    """Step name, step version, the step's code, resolved inputs, and the content of the files
    the inputs name."""
    files: dict[str, str] = {}
    _file_digests(inputs, files)
    code = code_fingerprint(module) if module else ""
    canonical = json.dumps({"format": FORMAT, "step": step_name, "version": version, "code": code, "inputs": inputs, "files": files},
                           sort_keys=True, separators=(",", ":"), default=str)
    return hashlib.sha256(canonical.encode("utf-8")).hexdigest()


MARKER = "CACHEDIR.TAG"
_MARKER_TEXT = ("Signature: 8a477f597d28d172789f06886806bc55\n"
                "# This folder is a pipflow step cache (pipflow cache clear removes its entries).\n"
                "# For information about cache directory tags, see https://bford.info/cachedir/\n")
_CREATED = "# pipflow created this folder\n"
_SHARD = re.compile(r"^[0-9a-f]{2}$")
_KEY = re.compile(r"^[0-9a-f]{64}$")
_TEMP = re.compile(r"^\.tmp-[0-9a-f]{64}-[0-9a-f]{8}$")
_MAX_OUTPUTS = 256 * 1024 * 1024  # bytes of one entry's outputs.json


class CacheRefused(UserError):
    """The cache folder holds things pipflow did not write; nothing is written or removed there."""


def _sha256(path: Path) -> str:
    digest = hashlib.sha256()
    with open(path, "rb") as fh:
        for block in iter(lambda: fh.read(1 << 20), b""):
            digest.update(block)
    return digest.hexdigest()


def _artifact_files(folder: Path) -> dict[str, Path]:
    """Relative name -> path of every file under ``folder``; a link or a special file makes the
    whole entry untrustworthy (ValueError)."""
    files: dict[str, Path] = {}
    if not folder.is_dir():
        return files
    for path in sorted(folder.rglob("*")):
        if path.is_symlink() or not (path.is_file() or path.is_dir()):
            raise ValueError(f"{path.name}: not a plain file")
        if path.is_file():
            files[path.relative_to(folder).as_posix()] = path
    return files


class StepCache:
    def __init__(self, root: Path | None = None):
        self.root = Path(root) if root else default_cache_dir()

    def _entry(self, key: str) -> Path:
        return self.root / key[:2] / key

    # -- read ----------------------------------------------------------------------------
    def get(self, key: str, artifact_dir: Path, expected: Iterable[str] = (),
            problems: list[str] | None = None, root: Path | None = None) -> dict | None:
        """The outputs stored under ``key`` (and its artifacts copied into ``artifact_dir``, below
        the record ``root`` without following a link), or ``None``. An entry that does not verify
        is removed, and why is added to ``problems``; a link at an entry's place (or its shard's)
        is no entry: the link itself is removed, never what it points to."""
        entry = self._entry(key)
        link = next((p for p in (entry.parent, entry) if p.is_symlink()), None)
        if link is not None:
            self._drop_link(link, problems)
            return None
        if not entry.is_dir():
            return None
        try:
            outputs = self._verified(entry, key, set(expected))
        except (OSError, ValueError, KeyError, TypeError) as err:
            removed = self._is_marked()  # remove only from a folder that is pipflow's
            if removed:
                shutil.rmtree(entry, ignore_errors=True)
                removed = not entry.exists()
            if problems is not None:
                problems.append(f"cache entry {entry} did not verify and was {'removed' if removed else 'left in place'} ({err})")
            return None
        for name, path in _artifact_files(entry / "artifacts").items():
            write_file(artifact_dir / name, path.read_bytes(), root=root)
        return outputs

    def _drop_link(self, link: Path, problems: list[str] | None) -> None:
        """A symbolic link where pipflow keeps an entry (or a shard of entries): not pipflow's
        entry, and never followed. In pipflow's marked folder the link itself is removed (what it
        points to stays); elsewhere it is left, and said so once per run by the caller."""
        removed = False
        if self._is_marked():
            try:
                os.unlink(link)
                removed = True
            except OSError:
                removed = False
        if problems is not None:
            problems.append(f"cache entry {link} is a symbolic link, not an entry pipflow wrote; it was "
                            + ("removed (what it points to is untouched)" if removed else "not used, and left in place"))

    def _verified(self, entry: Path, key: str, expected: set[str]) -> dict:
        manifest = json.loads((entry / "manifest.json").read_text(encoding="utf-8"))
        if not isinstance(manifest, dict) or manifest.get("key") != key:
            raise ValueError("manifest does not name this entry")
        raw = (entry / "outputs.json").read_bytes()
        if len(raw) > _MAX_OUTPUTS or hashlib.sha256(raw).hexdigest() != manifest["outputs"]:
            raise ValueError("outputs do not match their hash")
        outputs = json.loads(raw.decode("utf-8"))
        if not isinstance(outputs, dict):
            raise ValueError(f"outputs are a {type(outputs).__name__}, not a mapping")
        missing = expected - set(outputs)
        if missing:
            raise ValueError(f"outputs lack {', '.join(sorted(missing))}")
        files = _artifact_files(entry / "artifacts")
        recorded = manifest["artifacts"]
        if not isinstance(recorded, dict) or set(files) != set(recorded):
            raise ValueError("artifacts differ from the manifest")
        for name, path in files.items():
            if _sha256(path) != recorded[name]:
                raise ValueError(f"artifact {name} does not match its hash")
        return outputs

    # -- write ---------------------------------------------------------------------------
    def put(self, key: str, outputs: dict, artifact_dir: Path) -> None:
        """Store an entry: written in a temporary folder, manifest last, then moved into place.
        Raises OSError (cannot write) or :class:`CacheRefused`; callers turn both into a warning."""
        self._claim_root()
        entry = self._entry(key)
        if entry.parent.is_symlink() or entry.is_symlink():
            raise CacheRefused(f"{entry if entry.is_symlink() else entry.parent} is a symbolic link in the cache "
                               "folder; pipflow writes no cache entry through it")
        tmp = self.root / key[:2] / f".tmp-{key}-{uuid.uuid4().hex[:8]}"
        try:
            tmp.mkdir(parents=True)
            if artifact_dir.is_dir():
                shutil.copytree(artifact_dir, tmp / "artifacts", symlinks=True)
            # mappings keep their order: a world's robots in file order is data (ties are broken by
            # it), and a cached run must equal a fresh one
            raw = json.dumps(outputs, default=str).encode("utf-8")
            atomic_write(tmp / "outputs.json", raw, redacted=False)
            manifest = {"pipflow_cache": 1, "key": key, "outputs": hashlib.sha256(raw).hexdigest(),
                        "artifacts": {name: _sha256(path) for name, path in _artifact_files(tmp / "artifacts").items()}}
            atomic_write(tmp / "manifest.json", json.dumps(manifest, sort_keys=True), redacted=False)
            if entry.exists():
                shutil.rmtree(entry)
            os.replace(tmp, entry)
        except (OSError, ValueError):
            shutil.rmtree(tmp, ignore_errors=True)
            raise

    def _claim_root(self) -> None:
        """Make sure the cache folder is pipflow's: new or empty (then marked), or marked."""
        if self._is_marked():
            return
        if self.root.exists():
            if not self.root.is_dir():
                raise CacheRefused(f"{self.root}: the cache folder is a file; no step results are cached")
            if any(self.root.iterdir()) and not self._only_entries():
                raise CacheRefused(f"{self.root}: this folder holds files pipflow did not write; no step results "
                                   f"are cached there (point PIPFLOW_CACHE_DIR at a new or empty folder)")
        created = not self.root.exists()
        self.root.mkdir(parents=True, exist_ok=True)
        # whether pipflow made the folder: `cache clear` removes only a folder it made
        atomic_write(self.root / MARKER, _MARKER_TEXT + (_CREATED if created else ""), redacted=False)

    def _only_entries(self) -> bool:
        """Whether the folder holds nothing but entries in pipflow's layout (a cache written
        before caches were marked): such a folder is pipflow's and gets the mark."""
        for shard in self.root.iterdir():
            if not (_SHARD.match(shard.name) and shard.is_dir() and not shard.is_symlink()):
                return False
            for entry in shard.iterdir():
                if not ((_KEY.match(entry.name) and entry.name.startswith(shard.name)) or _TEMP.match(entry.name)) \
                        or not entry.is_dir() or entry.is_symlink():
                    return False
        return True

    def _is_marked(self) -> bool:
        try:
            text = (self.root / MARKER).read_text(encoding="utf-8", errors="replace")
        except OSError:
            return False
        return text.startswith("Signature: 8a477f597d28d172789f06886806bc55") and "pipflow" in text

    # -- clear ---------------------------------------------------------------------------
    def clear(self) -> int:
        """Remove every entry pipflow wrote; returns how many there were. A folder without
        pipflow's mark is refused (nothing removed); files that are not entries stay."""
        if not self.root.exists():
            return 0
        marker = self.root / MARKER
        created = self._is_marked() and _CREATED in marker.read_text(encoding="utf-8", errors="replace")
        if not self.root.is_dir() or not (self._is_marked() or self._only_entries()):
            raise CacheRefused(f"{self.root}: not a pipflow step cache (no {MARKER} written by pipflow); "
                               "nothing was removed")
        count = 0
        for shard in list(self.root.iterdir()):
            if not (_SHARD.match(shard.name) and shard.is_dir() and not shard.is_symlink()):
                continue
            for entry in list(shard.iterdir()):
                ours = (_KEY.match(entry.name) and entry.name.startswith(shard.name)) or _TEMP.match(entry.name)
                if ours and entry.is_dir() and not entry.is_symlink():
                    shutil.rmtree(entry)
                    count += 0 if _TEMP.match(entry.name) else 1
            try:
                shard.rmdir()  # only if nothing else is in it
            except OSError:
                pass
        if created and not self.leftovers():  # a folder pipflow made, now holding nothing but the mark
            marker.unlink(missing_ok=True)
            try:
                self.root.rmdir()
            except OSError:
                pass
        return count

    def leftovers(self) -> list[Path]:
        """What is in the cache folder besides pipflow's mark and entries (after :meth:`clear`)."""
        if not self.root.is_dir():
            return []
        return sorted(p for p in self.root.iterdir() if p.name != MARKER)

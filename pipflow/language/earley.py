"""Built lark Earley parsers, cached in memory and on disk, so that a run does not pay the build.

Why: building lark's Earley parser for the command grammar (about 1850 rules once optional
parts are expanded) takes about 0.4 s on an idle machine, the largest single cost of the main
job. lark caches only LALR parsers (``Lark(cache=...)`` and ``Lark.save`` refuse Earley in lark
1.3), so this module pickles the whole built ``Lark`` object itself. Loading it back takes about
a tenth of the build (0.04-0.07 s against 0.4-0.8 s).

The key is a hash of everything that shapes the parser: the grammar text, the options (the lexer
class by its qualified name), lark's version, Python's version and this module's format. An
entry that is missing, stale, damaged or written by anything else is rebuilt, never an error: a
file is trusted only when it belongs to the user, nobody else may write it, its header names this
format and key, and the SHA-256 of its body matches (that catches damage and other accounts, not a
forger with the user's own rights, who could just as well edit pipflow itself).

Where: ``$PIPFLOW_GRAMMAR_CACHE_DIR`` if set (set to the empty string to keep parsers in memory
only), else ``$XDG_CACHE_HOME/pipflow/grammar`` (``~/.cache/pipflow/grammar``), beside the step
cache of :mod:`pipflow.engine.cache`. Like that cache, the folder is marked with a
``CACHEDIR.TAG`` naming pipflow, and nothing is written into an existing folder that holds other
files without the mark. Writers write a temporary file in the folder and rename it into place,
so concurrent runs never see half a file. A folder that cannot be written costs only the cache.
"""
from __future__ import annotations

import copy
import gc
import hashlib
import importlib
import io
import os
import pickle
import re
import sys
import tempfile
import threading
import time
import types
from pathlib import Path
from typing import Any

import lark
from lark import Lark
from lark.lexer import Lexer

#: bump when the file layout or what is pickled changes (old files then never match a key)
FORMAT = 1
ENV_DIR = "PIPFLOW_GRAMMAR_CACHE_DIR"
MARKER = "CACHEDIR.TAG"
_MARKER_TEXT = ("Signature: 8a477f597d28d172789f06886806bc55\n"
                "# This folder is pipflow's cache of built command-grammar parsers (safe to delete).\n"
                "# For information about cache directory tags, see https://bford.info/cachedir/\n")
_MAGIC = b"pipflow-earley"
_SUFFIX = ".earley"
_NAME = re.compile(r"^[0-9a-f]{64}\.earley$")
_TEMP = re.compile(r"^\.tmp-\w+\.earley$")
KEEP = 8  # parsers kept on disk (grammars in use, and a few recent edits of them)

_MEMORY: dict[str, Lark] = {}  # key -> parser built or loaded by this process
_LOCK = threading.Lock()  # one build per key, even when steps run in threads


class ListLexer(Lexer):
    """Hands lark the terminals the lexicon made (the parser never sees raw text).

    At module level, and written to lark's current lexer interface (``__future_interface__ =
    2``), so that lark uses the class as it is instead of wrapping it in a local class that
    cannot be pickled."""

    __future_interface__ = 2

    def __init__(self, lexer_conf: Any):
        pass

    def lex(self, lexer_state: Any, parser_state: Any):  # type: ignore[override]
        yield from lexer_state.text


def cache_dir() -> Path | None:
    """The folder of built parsers, or ``None`` when the disk cache is turned off."""
    env = os.environ.get(ENV_DIR)
    if env is not None:
        return Path(env) if env.strip() else None
    base = os.environ.get("XDG_CACHE_HOME")
    if not base:
        try:
            base = str(Path.home() / ".cache")
        except (RuntimeError, KeyError):  # no home folder (a service account): memory only
            return None
    return Path(base) / "pipflow" / "grammar"


def parser_key(grammar: str, options: dict[str, Any]) -> str:
    """SHA-256 over the grammar text, the options, lark's and Python's versions and the format."""
    shown = {name: (f"{value.__module__}.{value.__qualname__}" if isinstance(value, type) else repr(value))
             for name, value in sorted(options.items())}
    material = repr((FORMAT, lark.__version__, sys.version_info[:2], shown, grammar))
    return hashlib.sha256(material.encode("utf-8")).hexdigest()


def earley_parser(grammar: str, **options: Any) -> Lark:
    """``Lark(grammar, parser="earley", **options)``, built once per key: from this process's
    memory, else from the disk cache, else built (and then stored on disk)."""
    options = {"parser": "earley", **options}
    key = parser_key(grammar, options)
    with _LOCK:
        parser = _MEMORY.get(key)
        if parser is None:
            folder = cache_dir()
            parser = _load(folder, key) if folder else None
            if parser is None:
                parser = _build(grammar, options)
                if folder:
                    _store(folder, key, parser)
            _MEMORY[key] = parser
        return parser


def _build(grammar: str, options: dict[str, Any]) -> Lark:
    return Lark(grammar, **options)


def _entry(folder: Path, key: str) -> Path:
    return folder / f"{key}{_SUFFIX}"


def _header(key: str, digest: str) -> bytes:
    return b"%s %d %s %s\n" % (_MAGIC, FORMAT, key.encode(), digest.encode())


def _load(folder: Path, key: str) -> Lark | None:
    """The parser stored under ``key``, or ``None`` for anything that does not verify."""
    try:
        with open(_entry(folder, key), "rb") as fh:
            if not _own(os.fstat(fh.fileno())):
                return None
            raw = fh.read()
    except OSError:
        return None
    head, sep, body = raw.partition(b"\n")
    if not sep or head + b"\n" != _header(key, hashlib.sha256(body).hexdigest()):
        return None
    paused = gc.isenabled()
    gc.disable()  # the body is ~10^5 small objects: collections while loading cost 4x the load
    try:
        parser = pickle.loads(body)
    except Exception:  # noqa: BLE001 - any failure to load (a renamed class, another lark) is a miss
        return None
    finally:
        if paused:
            gc.enable()
    return parser if isinstance(parser, Lark) else None


def _own(stat: os.stat_result) -> bool:
    """Whether a file is this user's and writable by nobody else: unpickling runs code, so a file
    another account could have written (a shared or mistyped cache folder) is never loaded."""
    if not hasattr(os, "getuid"):
        return True
    return stat.st_uid == os.getuid() and not stat.st_mode & 0o022


class _Pickler(pickle.Pickler):
    """Pickles module references (lark keeps the ``re`` module in its lexer configuration) by
    name; everything else as usual."""

    def reducer_override(self, obj: Any) -> Any:
        if isinstance(obj, types.ModuleType):
            return importlib.import_module, (obj.__name__,)
        return NotImplemented


def _store(folder: Path, key: str, parser: Lark) -> None:
    """Write the parser under ``key`` (temporary file, then rename); any failure leaves the
    cache as it was."""
    buffer = io.BytesIO()
    stored = copy.copy(parser)
    stored.grammar = None  # the unanalysed grammar: lark reads it only while building (a third of the bytes)
    try:
        _Pickler(buffer, protocol=pickle.HIGHEST_PROTOCOL).dump(stored)
    except Exception:  # noqa: BLE001 - a parser that cannot be pickled is simply not cached
        return
    body = buffer.getvalue()
    try:
        if not _claim(folder):
            return
        _write_atomically(folder, _entry(folder, key), _header(key, hashlib.sha256(body).hexdigest()), body)
        _prune(folder)
    except OSError:
        return


def _prune(folder: Path) -> None:
    """Keep the :data:`KEEP` newest parsers (each grammar edit makes a new key, ~0.8 MB) and
    remove temporary files a crashed writer left more than an hour ago; only this cache's names."""
    entries = sorted((p for p in folder.iterdir() if _NAME.match(p.name)), key=_mtime, reverse=True)
    stale = [p for p in folder.iterdir() if _TEMP.match(p.name) and time.time() - _mtime(p) > 3600]
    for path in entries[KEEP:] + stale:
        path.unlink(missing_ok=True)


def _mtime(path: Path) -> float:
    try:
        return path.stat().st_mtime
    except OSError:
        return 0.0


def _claim(folder: Path) -> bool:
    """Whether pipflow may write in ``folder``: it is marked as this cache, or new or empty
    (then marked now). A folder holding anything else is left alone."""
    marker = folder / MARKER
    try:
        if marker.read_text(encoding="utf-8", errors="replace") == _MARKER_TEXT:
            return True
    except OSError:
        pass
    if folder.exists() and (not folder.is_dir() or any(folder.iterdir())):
        return False
    folder.mkdir(parents=True, exist_ok=True)
    _write_atomically(folder, marker, _MARKER_TEXT.encode("utf-8"))
    return True


def _write_atomically(folder: Path, target: Path, *parts: bytes) -> None:
    """A temporary file in ``folder``, renamed onto ``target``: readers see all of it or none."""
    fd, tmp = tempfile.mkstemp(dir=folder, prefix=".tmp-", suffix=_SUFFIX)
    try:
        with os.fdopen(fd, "wb") as fh:
            for part in parts:
                fh.write(part)
        os.replace(tmp, target)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise

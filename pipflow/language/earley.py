"""Built lark Earley parsers, cached in memory and on disk, so that a run does not pay the build.

Why: building lark's Earley parser for the command grammar (about 1850 rules once optional
parts are expanded) takes about 0.4 s on an idle machine, the largest single cost of the main
job. lark caches only LALR parsers (``Lark(cache=...)`` and ``Lark.save`` refuse Earley in lark
1.3), so this module pickles the whole built ``Lark`` object itself. Loading it back takes about
a tenth of the build (0.04-0.07 s against 0.4-0.8 s).

The key is a hash of everything that shapes the parser: the grammar text, the options (the lexer
class by its qualified name), lark's version, Python's version and this module's format. An
entry that is missing, stale, damaged or written by anything else is rebuilt, never an error.

A pickle is code, and lark offers no other form for an Earley parser (``Lark.save`` is LALR-only:
lark issues #788 and #1348), so an entry is loaded only when all of this holds (issue 21: another
user's link in a shared cache folder, pointing at a root-owned file of pickle bytes, ran code as
root): the folder is this user's and writable by nobody else (opened once and checked on its
descriptor; a new one is made with mode 0700); the entry is opened through that descriptor with
``O_NOFOLLOW`` (a link is never followed, whoever placed it) and is a regular file of this user
that nobody else may write (checked on the open file); its header names this format and key and
the SHA-256 of its body; and the body is decoded by an unpickler that builds only lark's own
classes (a forged entry cannot name ``os.system`` or import a module of its choosing).

Where: ``$PIPFLOW_GRAMMAR_CACHE_DIR`` if set (set to the empty string to keep parsers in memory
only), else ``$XDG_CACHE_HOME/pipflow/grammar`` (``~/.cache/pipflow/grammar``), beside the step
cache of :mod:`pipflow.engine.cache`. Like that cache, the folder is marked with a
``CACHEDIR.TAG`` naming pipflow, and nothing is written into an existing folder that holds other
files without the mark, nor into a folder others may write. Writers write a temporary file in the folder and rename it into place,
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
import stat
import sys
import threading
import time
import types
import uuid
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
_DIRECTORY = getattr(os, "O_DIRECTORY", 0)
_NOFOLLOW = getattr(os, "O_NOFOLLOW", 0)
_CLOEXEC = getattr(os, "O_CLOEXEC", 0)
_NONBLOCK = getattr(os, "O_NONBLOCK", 0)
KEEP = 32  # parsers kept on disk (the warehouse's, one per household world's dual classes, recent edits)

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
            # the parser is ~10^5 objects that live as long as the process: out of the garbage
            # collector's sweeps, which otherwise walk all of them again and again while commands
            # are read (about a tenth of the reading time of the household sets). It freezes all
            # that lives now: cyclic garbage made before it is never collected (once per parser)
            gc.freeze()
        return parser


def _build(grammar: str, options: dict[str, Any]) -> Lark:
    return Lark(grammar, **options)


def _entry(folder: Path, key: str) -> Path:
    return folder / f"{key}{_SUFFIX}"


def _header(key: str, digest: str) -> bytes:
    return b"%s %d %s %s\n" % (_MAGIC, FORMAT, key.encode(), digest.encode())


def _load(folder: Path, key: str) -> Lark | None:
    """The parser stored under ``key``, or ``None`` for anything that does not verify.

    A pickle is code, so the file must be one this user wrote into a folder nobody else can
    write: the folder is opened once and checked on its descriptor (:func:`_private`), the entry
    is opened through that descriptor with ``O_NOFOLLOW`` (a link, whoever placed it, is never
    followed) and checked on the open file (a regular file of this user, writable by nobody
    else); its header must name this format and key and its body's SHA-256; and the body is
    decoded by :class:`_LarkUnpickler`, which builds only lark's own classes."""
    try:
        dir_fd = os.open(folder, os.O_RDONLY | _DIRECTORY | _CLOEXEC)
    except OSError:
        return None
    try:
        if not _private(os.fstat(dir_fd)):
            return None
        fd = os.open(_entry(folder, key).name, os.O_RDONLY | _NOFOLLOW | _CLOEXEC | _NONBLOCK, dir_fd=dir_fd)
        with os.fdopen(fd, "rb") as fh:
            info = os.fstat(fh.fileno())
            if not (stat.S_ISREG(info.st_mode) and _own(info)):
                return None
            raw = fh.read()
            if os.utime in os.supports_fd:
                os.utime(fh.fileno())   # in use: the newest are kept (:func:`_prune`)
    except OSError:
        return None
    finally:
        os.close(dir_fd)
    head, sep, body = raw.partition(b"\n")
    if not sep or head + b"\n" != _header(key, hashlib.sha256(body).hexdigest()):
        return None
    paused = gc.isenabled()
    gc.disable()  # the body is ~10^5 small objects: collections while loading cost 4x the load
    try:
        parser = _LarkUnpickler(io.BytesIO(body)).load()
    except Exception:  # noqa: BLE001 - any failure to load (a renamed class, another lark, a refused name) is a miss
        return None
    finally:
        if paused:
            gc.enable()
    return parser if isinstance(parser, Lark) else None


def _own(info: os.stat_result) -> bool:
    """Whether a file (or folder) is this user's and writable by nobody else."""
    if not hasattr(os, "getuid"):
        return True
    return info.st_uid == os.getuid() and not info.st_mode & 0o022


def _private(info: os.stat_result) -> bool:
    """Whether a folder may hold parsers this process loads: a folder (not a link: it was opened
    as one), this user's, and writable by nobody else. A shared folder (``/tmp``-like, mode 1777,
    or group-writable) is never used: someone else could place an entry there."""
    return stat.S_ISDIR(info.st_mode) and _own(info)


#: what a stored parser may be built from: lark's own classes (and the two helpers it pickles)
_LARK_MODULE = re.compile(r"^lark(\.[A-Za-z_][A-Za-z0-9_]*)*$")
_ALLOWED_FUNCTIONS = {("functools", "partial"), ("lark.parser_frontends", "_match_earley_basic"),
                      ("lark.parser_frontends", "_match_earley_dynamic")}
_MODULES_BY_NAME = {"re", "regex"}  # what the ``import_module`` entries may name (lark's regex module)


def _import_regex_module(name: str) -> types.ModuleType:
    if name not in _MODULES_BY_NAME:
        raise pickle.UnpicklingError(f"a stored parser may not import {name!r}")
    return importlib.import_module(name)


class _LarkUnpickler(pickle.Unpickler):
    """Decodes a stored parser from lark's own classes only. A forged entry (one that passed
    every file check: written by this very user) still cannot name ``os.system`` or import a
    module of its choosing: a name outside lark is refused before any import happens."""

    def find_class(self, module: str, name: str) -> Any:
        if "." in name:  # no attribute paths (protocol 4 allows "A.b"): only top-level names
            raise pickle.UnpicklingError(f"a stored parser may not name {module}.{name}")
        if (module, name) == ("importlib", "import_module"):
            return _import_regex_module
        if (module, name) in _ALLOWED_FUNCTIONS:
            return super().find_class(module, name)
        if _LARK_MODULE.match(module):
            found = super().find_class(module, name)
            if isinstance(found, type):
                return found
        elif module in sys.modules:  # a lexer class of the caller's (already imported: nothing is imported here)
            found = getattr(sys.modules[module], name, None)
            if isinstance(found, type) and issubclass(found, Lexer):
                return found
        raise pickle.UnpicklingError(f"a stored parser may not name {module}.{name}")


class _Pickler(pickle.Pickler):
    """Pickles module references (lark keeps the ``re`` module in its lexer configuration) by
    name; everything else as usual."""

    def reducer_override(self, obj: Any) -> Any:
        if isinstance(obj, types.ModuleType):
            return importlib.import_module, (obj.__name__,)
        return NotImplemented


def _store(folder: Path, key: str, parser: Lark) -> None:
    """Write the parser under ``key`` (temporary file, then rename, through the folder's
    descriptor); any failure leaves the cache as it was. Only a private folder is written
    (:func:`_private`); a new one is made with mode 0700."""
    buffer = io.BytesIO()
    stored = copy.copy(parser)
    stored.grammar = None  # the unanalysed grammar: lark reads it only while building (a third of the bytes)
    try:
        _Pickler(buffer, protocol=pickle.HIGHEST_PROTOCOL).dump(stored)
    except Exception:  # noqa: BLE001 - a parser that cannot be pickled is simply not cached
        return
    body = buffer.getvalue()
    try:
        dir_fd = _claim(folder)
    except OSError:
        return
    if dir_fd is None:
        return
    try:
        _write_atomically(dir_fd, _entry(folder, key).name, _header(key, hashlib.sha256(body).hexdigest()), body)
        _prune(dir_fd)
    except OSError:
        return
    finally:
        os.close(dir_fd)


def _prune(dir_fd: int) -> None:
    """Keep the :data:`KEEP` parsers written or loaded last (each grammar edit makes a new key;
    0.3-0.8 MB each) and
    remove temporary files a crashed writer left more than an hour ago; only this cache's names
    (links among them are removed as links)."""
    names = os.listdir(dir_fd)
    entries = sorted((n for n in names if _NAME.match(n)), key=lambda n: _mtime(dir_fd, n), reverse=True)
    stale = [n for n in names if _TEMP.match(n) and time.time() - _mtime(dir_fd, n) > 3600]
    for name in entries[KEEP:] + stale:
        try:
            os.unlink(name, dir_fd=dir_fd)
        except OSError:
            pass


def _mtime(dir_fd: int, name: str) -> float:
    try:
        return os.stat(name, dir_fd=dir_fd, follow_symlinks=False).st_mtime
    except OSError:
        return 0.0


def _claim(folder: Path) -> int | None:
    """A descriptor of ``folder`` when pipflow may write there: a private folder
    (:func:`_private`) that is marked as this cache, or new (made with mode 0700) or empty (then
    marked now). ``None`` for anything else, which is left alone."""
    if not folder.exists():
        folder.mkdir(mode=0o700, parents=True, exist_ok=True)
    dir_fd = os.open(folder, os.O_RDONLY | _DIRECTORY | _CLOEXEC)
    try:
        if not _private(os.fstat(dir_fd)):
            os.close(dir_fd)
            return None
        try:
            fd = os.open(MARKER, os.O_RDONLY | _NOFOLLOW | _CLOEXEC | _NONBLOCK, dir_fd=dir_fd)
            with os.fdopen(fd, "rb") as fh:
                if fh.read(len(_MARKER_TEXT) + 1).decode("utf-8", "replace") == _MARKER_TEXT:
                    return dir_fd
        except OSError:
            pass
        if os.listdir(dir_fd):
            os.close(dir_fd)
            return None
        _write_atomically(dir_fd, MARKER, _MARKER_TEXT.encode("utf-8"))
        return dir_fd
    except BaseException:
        try:
            os.close(dir_fd)
        except OSError:
            pass
        raise


def _write_atomically(dir_fd: int, name: str, *parts: bytes) -> None:
    """A temporary file in the folder (created exclusively, mode 0600), renamed onto ``name``:
    readers see all of it or none, and a link at ``name`` is replaced, never written through."""
    tmp = f".tmp-{uuid.uuid4().hex}{_SUFFIX}"
    fd = os.open(tmp, os.O_WRONLY | os.O_CREAT | os.O_EXCL | _NOFOLLOW | _CLOEXEC, 0o600, dir_fd=dir_fd)
    try:
        with os.fdopen(fd, "wb") as fh:
            for part in parts:
                fh.write(part)
        os.replace(tmp, name, src_dir_fd=dir_fd, dst_dir_fd=dir_fd)
    except BaseException:
        try:
            os.unlink(tmp, dir_fd=dir_fd)
        except OSError:
            pass
        raise

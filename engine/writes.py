"""The one place pipflow opens files for writing: run records, bench folders, reports, caches.

Why one place: two things must hold for every write, and each is easy to forget at a call site.

- **No write goes through a link inside a record.** A record folder may hold links that someone
  else placed (a shared runs folder, a record copied from elsewhere, a tarball); a write that
  follows ``RUN/report.html -> ~/.bashrc`` overwrites the link's target. Below a record's root
  (``root=``), folders are opened one component at a time with ``O_NOFOLLOW`` and a link is
  refused, naming it; files are written as a new temporary file (``O_EXCL``) renamed into place,
  so even a link planted after the check is replaced, never written through; the event log is
  appended through ``O_NOFOLLOW``. The root itself is the user's to name (it may be a link).
- **A disk that cannot take the write is a user error naming the device and the path**: no
  space (``ENOSPC``), over quota (``EDQUOT``), over the process's file size limit (``EFBIG``), a
  read-only file system (``EROFS``) or no permission (``EACCES``/``EPERM``) raise
  :class:`DiskError` (exit 2), not an ``OSError`` traceback. :class:`DiskError` is also an
  ``OSError``, so callers that treat an unwritable cache as a warning keep doing so.
"""
from __future__ import annotations

import contextlib
import errno
import itertools
import os
import stat
import uuid
from pathlib import Path
from typing import Iterator

from pipflow.errors import UserError


def _umask() -> int:
    mask = os.umask(0o022)
    os.umask(mask)
    return mask


FILE_MODE = 0o666 & ~_umask()  # the mode `open()` gives a new file: every record file has it

_CLOEXEC = getattr(os, "O_CLOEXEC", 0)
_NOFOLLOW = getattr(os, "O_NOFOLLOW", 0)
_DIRECTORY = getattr(os, "O_DIRECTORY", 0)

#: what each errno means for a write, in the words of the message
_CAUSES = {
    errno.ENOSPC: "no space left on {device}",
    errno.EDQUOT: "no space left on {device} (your disk quota is used up)",
    errno.EFBIG: "no space left on {device} (the file size limit of this process, `ulimit -f`, was reached)",
    errno.EROFS: "{device} is read-only",
    errno.EACCES: "no permission to write on {device}",
    errno.EPERM: "no permission to write on {device}",
}
#: the errnos that mean the disk is full (the run can go on once space is freed)
FULL = frozenset({errno.ENOSPC, errno.EDQUOT, errno.EFBIG})


class DiskError(UserError, OSError):
    """A write failed because of the disk, not because of pipflow: full, over quota, over the
    file size limit, read-only, or not writable by this user. The message names the device (its
    mount point and file system) and the path; ``errno`` says which."""

    def __init__(self, message: str, path: str | os.PathLike, code: int | None):
        UserError.__init__(self, message)
        self.path = str(path)
        self.errno = code

    def __str__(self) -> str:
        return str(self.args[0]) if self.args else ""

    def __reduce__(self):  # crosses process boundaries (a bench's workers) whole
        return (type(self), (str(self), self.path, self.errno))

    @property
    def full(self) -> bool:
        """Whether space ran out (freeing space and resuming continues the run)."""
        return self.errno in FULL


class LinkInRecord(UserError):
    """A symbolic link where pipflow would write inside a record: refused, never followed."""


def disk_error(err: OSError, path: str | os.PathLike, doing: str = "writing") -> DiskError | None:
    """``err`` as a :class:`DiskError` naming the device and ``path``; None when the error is not
    about the disk (a bug, a missing folder: those keep their own meaning)."""
    if isinstance(err, DiskError):
        return err
    cause = _CAUSES.get(err.errno or 0)
    if cause is None:
        return None
    return DiskError(f"{cause.format(device=device_of(path))} {doing} {path}", path, err.errno)


@contextlib.contextmanager
def writing(path: str | os.PathLike, doing: str = "writing") -> Iterator[None]:
    """Turn a disk's refusal inside the block into a :class:`DiskError` naming ``path``."""
    try:
        yield
    except DiskError:
        raise
    except OSError as err:
        translated = disk_error(err, path, doing)
        if translated is None:
            raise
        raise translated from None


def device_of(path: str | os.PathLike) -> str:
    """The file system ``path`` lives on, as a user recognises it: ``tmpfs mounted at /mnt/x``
    (from /proc/self/mountinfo: the longest mount point above the path), else ``the device of
    PATH``."""
    where = Path(os.path.abspath(path))
    while not where.exists() and where != where.parent:
        where = where.parent
    real = os.path.realpath(where)
    best: tuple[str, str, str] | None = None
    try:
        with open("/proc/self/mountinfo", encoding="utf-8", errors="replace") as fh:
            for line in fh:
                left, _, right = line.partition(" - ")
                fields, more = left.split(), right.split()
                if len(fields) < 5 or len(more) < 2:
                    continue
                mount = fields[4].replace("\\040", " ")
                inside = real == mount or real.startswith(mount.rstrip("/") + "/")
                if inside and (best is None or len(mount) >= len(best[0])):
                    best = (mount, more[0], more[1])
    except OSError:
        best = None
    if best is None:
        return f"the device of {where}"
    mount, fstype, source = best
    name = fstype if source in (fstype, "none", "") or not source.startswith("/") else f"{source} ({fstype})"
    return f"{name} mounted at {mount}"


# -- walking a record without following links ----------------------------------------------------

def _parts_below(root: Path, path: Path) -> tuple[str, ...]:
    try:
        rel = path.relative_to(root)
    except ValueError:
        raise ValueError(f"{path} is not inside the record {root}") from None
    parts = rel.parts
    if any(p in ("..", "") for p in parts):
        raise ValueError(f"{path}: '..' inside a record path")
    return parts


def _link_error(shown: Path, dir_fd: int, name: str) -> LinkInRecord:
    try:
        target = os.readlink(name, dir_fd=dir_fd)
    except OSError:
        target = "?"
    return LinkInRecord(f"{shown} is a symbolic link (to {target}) inside a pipflow record; pipflow never "
                        "writes through links in a record: remove the link, or write the record elsewhere")


def _open_dir(root: Path, parts: tuple[str, ...], create: bool) -> int:
    """A descriptor of ``root/parts...``, each component opened with ``O_NOFOLLOW`` (created when
    missing and ``create``); a link or a file on the way is refused."""
    fd = os.open(root, os.O_RDONLY | _DIRECTORY | _CLOEXEC)
    shown = root
    try:
        for part in parts:
            shown = shown / part
            try:
                child = os.open(part, os.O_RDONLY | _DIRECTORY | _NOFOLLOW | _CLOEXEC, dir_fd=fd)
            except FileNotFoundError:
                if not create:
                    raise
                try:
                    os.mkdir(part, 0o777, dir_fd=fd)
                except FileExistsError:
                    pass
                child = os.open(part, os.O_RDONLY | _DIRECTORY | _NOFOLLOW | _CLOEXEC, dir_fd=fd)
            except (NotADirectoryError, OSError) as err:
                if err.errno not in (errno.ENOTDIR, errno.ELOOP):
                    raise
                if stat.S_ISLNK(os.lstat(part, dir_fd=fd).st_mode):
                    raise _link_error(shown, fd, part) from None
                raise UserError(f"{shown} is a file where pipflow needs a folder") from None
            # the parent's descriptor is dropped only once the child's is held: an interrupt
            # (SIGTERM/SIGHUP raise in here, engine/interrupts.py) that lands in this close
            # leaves ``fd`` naming the child, never a descriptor closed already
            parent, fd = fd, child
            os.close(parent)
        return fd
    except BaseException:
        with contextlib.suppress(OSError):  # the cause is what propagates, not a failed clean-up
            os.close(fd)
        raise


@contextlib.contextmanager
def _parent(path: Path, root: Path | None, create: bool = True) -> Iterator[int]:
    """A descriptor of ``path``'s folder: walked from ``root`` without links, or (no root) the
    folder as named, created with its parents."""
    if root is None:
        if create:
            path.parent.mkdir(parents=True, exist_ok=True)
        fd = os.open(path.parent, os.O_RDONLY | _DIRECTORY | _CLOEXEC)
    else:
        fd = _open_dir(Path(root), _parts_below(Path(root), path)[:-1], create)
    try:
        yield fd
    finally:
        os.close(fd)


def _refuse_link_or_folder(path: Path, dir_fd: int, name: str, root: Path | None) -> None:
    try:
        mode = os.lstat(name, dir_fd=dir_fd).st_mode
    except FileNotFoundError:
        return
    if stat.S_ISLNK(mode) and root is not None:
        raise _link_error(path, dir_fd, name)
    if stat.S_ISDIR(mode):
        raise UserError(f"{path} is a folder; pipflow writes a file there (name a file, or remove the folder)")


def make_dirs(path: str | os.PathLike, root: str | os.PathLike | None = None) -> Path:
    """Create the folder ``path`` (and its parents); below ``root`` no link is followed."""
    path = Path(path)
    with writing(path):
        if root is None:
            path.mkdir(parents=True, exist_ok=True)
        else:
            os.close(_open_dir(Path(root), _parts_below(Path(root), path), True))
    return path


_temporaries = itertools.count()


def write_file(path: str | os.PathLike, data: bytes, root: str | os.PathLike | None = None,
               mode: int = FILE_MODE) -> Path:
    """Write ``data`` to ``path`` atomically: readers see the old or the new content, never a torn
    one. Below ``root`` no link is followed and a link at ``path`` itself is refused; without a
    root the folder is taken as named (a cache's, a file the user named) and a link at ``path``
    is replaced, never written through. Raises :class:`DiskError` for a disk that refuses."""
    path = Path(path)
    root = Path(root) if root is not None else None
    with writing(path), _parent(path, root) as dir_fd:
        _refuse_link_or_folder(path, dir_fd, path.name, root)
        tmp, fd = _create_temporary(dir_fd, path.name, mode)
        try:
            try:
                view = memoryview(data)
                while view:
                    view = view[os.write(fd, view):]
            finally:
                os.close(fd)
            os.replace(tmp, path.name, src_dir_fd=dir_fd, dst_dir_fd=dir_fd)
        except BaseException:
            with contextlib.suppress(OSError):
                os.unlink(tmp, dir_fd=dir_fd)
            raise
    return path


_PID = os.getpid()


def _create_temporary(dir_fd: int, name: str, mode: int) -> tuple[str, int]:
    """A new, empty file ``.NAME.PID.N`` in the folder, open for writing, created exclusively
    (``O_EXCL`` never follows a link) with ``mode`` by ``open`` itself: one system call, where
    ``mkstemp`` + ``fchmod`` take more (a record is written per step, and each call counts)."""
    flags = os.O_WRONLY | os.O_CREAT | os.O_EXCL | _NOFOLLOW | _CLOEXEC
    for _ in range(100):
        tmp = f".{name}.{_PID}.{next(_temporaries)}"
        try:
            return tmp, os.open(tmp, flags, mode, dir_fd=dir_fd)
        except FileExistsError:  # left by a killed process, or a forked child with the same counter
            continue
    tmp = f".{name}.{uuid.uuid4().hex}"
    return tmp, os.open(tmp, flags, mode, dir_fd=dir_fd)


class AppendLog:
    """A file appended to line by line (the event log), opened without following a link and
    written with unbuffered ``write`` calls, so a failed write leaves nothing half in a buffer."""

    def __init__(self, path: str | os.PathLike, root: str | os.PathLike | None = None):
        self.path = Path(path)
        root = Path(root) if root is not None else None
        with writing(self.path), _parent(self.path, root) as dir_fd:
            flags = os.O_RDWR | os.O_APPEND | os.O_CREAT | _NOFOLLOW | _CLOEXEC | getattr(os, "O_NONBLOCK", 0)
            try:
                self._fd = os.open(self.path.name, flags, FILE_MODE, dir_fd=dir_fd)
            except OSError as err:
                if err.errno == errno.ELOOP:
                    raise _link_error(self.path, dir_fd, self.path.name) from None
                raise
        info = os.fstat(self._fd)
        if not stat.S_ISREG(info.st_mode):  # a pipe or a device planted under the log's name
            os.close(self._fd)
            raise UserError(f"{self.path} is not an ordinary file; pipflow appends its event log only to a file")
        if hasattr(os, "O_NONBLOCK"):
            os.set_blocking(self._fd, True)
        if info.st_size > 0 and os.pread(self._fd, 1, info.st_size - 1) != b"\n":
            self.write(b"\n")  # a torn last line (a killed process) must not swallow the next event

    def write(self, data: bytes) -> None:
        with writing(self.path):
            view = memoryview(data)
            while view:
                view = view[os.write(self._fd, view):]

    def close(self) -> None:
        if self._fd >= 0:
            os.close(self._fd)
            self._fd = -1

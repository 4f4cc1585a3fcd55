"""One writer per folder: the lock that runs and benches take on the folder they write.

Why a lock and not a pid in a file: a pid outlives its process (kill -9 leaves it behind, and the
number is reused), while an ``fcntl.flock`` on the folder's descriptor is released by the kernel
the moment its process ends, however it ends. So the same lock answers two questions: may I write
here (a second ``resume`` of a running run, a second bench into one ``--out`` are refused), and is
the writer of a record that says "running" still alive (readers show a dead run as stale).
Which process holds a lock is read from ``/proc/locks`` where there is one.

File systems without locks (some network mounts) make :meth:`FolderLock.acquire` a no-op: the
folder is written as before, without the guarantee.
"""
from __future__ import annotations

import errno
import fcntl
import os
from pathlib import Path

from pipflow.errors import UserError

_DIRECTORY = getattr(os, "O_DIRECTORY", 0)
_CLOEXEC = getattr(os, "O_CLOEXEC", 0)


class FolderBusy(UserError):
    """Another process holds the folder's lock (it is writing the run or the bench there)."""


class FolderLock:
    """An exclusive lock on ``folder``, held from :meth:`acquire` until :meth:`release` (or the
    process's end). ``what`` names the folder in the refusal ("run", "bench folder")."""

    def __init__(self, folder: str | os.PathLike, what: str = "folder"):
        self.folder = Path(folder)
        self.what = what
        self._fd: int | None = None

    @property
    def held(self) -> bool:
        return self._fd is not None

    def acquire(self) -> None:
        """Take the lock, or raise :class:`FolderBusy` naming the process that holds it."""
        if self._fd is not None:
            return
        try:
            fd = os.open(self.folder, os.O_RDONLY | _DIRECTORY | _CLOEXEC)
        except OSError:
            return  # a folder that cannot be opened: its writes will say what is wrong
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except OSError as err:
            os.close(fd)
            if err.errno not in (errno.EWOULDBLOCK, errno.EAGAIN):  # no locks on this file system
                return
            pid = lock_holder(self.folder)
            raise FolderBusy(f"{self.folder}: another pipflow process{f' (pid {pid})' if pid else ''} is "
                             f"writing this {self.what}; wait until it ends (or stop it) and try again") from None
        self._fd = fd

    def release(self) -> None:
        if self._fd is not None:
            os.close(self._fd)  # closing the descriptor releases the flock
            self._fd = None

    def __enter__(self) -> "FolderLock":
        self.acquire()
        return self

    def __exit__(self, *exc: object) -> None:
        self.release()


def writer_alive(folder: str | os.PathLike) -> bool | None:
    """Whether a process holds ``folder``'s lock now: True, False, or None when the folder cannot
    be opened or its file system has no locks. A shared lock is tried, so two readers never get in
    each other's way; a writer's exclusive lock makes the try fail."""
    try:
        fd = os.open(folder, os.O_RDONLY | _DIRECTORY | _CLOEXEC)
    except OSError:
        return None
    try:
        fcntl.flock(fd, fcntl.LOCK_SH | fcntl.LOCK_NB)
    except OSError as err:
        return True if err.errno in (errno.EWOULDBLOCK, errno.EAGAIN) else None
    finally:
        os.close(fd)  # releases the shared lock, if it was taken
    return False


def lock_holder(folder: str | os.PathLike) -> int | None:
    """The pid holding an flock on ``folder``, from /proc/locks (Linux); None elsewhere."""
    try:
        info = os.stat(folder)
        with open("/proc/locks", encoding="ascii", errors="replace") as fh:
            lines = fh.read().splitlines()
    except OSError:
        return None
    want = (os.major(info.st_dev), os.minor(info.st_dev), info.st_ino)
    for line in lines:
        fields = line.split()
        if "->" in fields or "FLOCK" not in fields:  # a waiter, or another kind of lock
            continue
        for i, field in enumerate(fields):
            parts = field.split(":")
            if len(parts) == 3 and i > 0:
                try:
                    key = (int(parts[0], 16), int(parts[1], 16), int(parts[2]))
                    pid = int(fields[i - 1])
                except ValueError:
                    continue
                if key == want:
                    return pid
    return None

"""SIGTERM and SIGHUP end a run the way Ctrl-C does: the record says "interrupted".

Why: by default both signals end Python at once, so ``run.json`` kept saying "running" and the
steps that were done were not marked. While a run or a bench runs in the main thread, both are
turned into :class:`Interrupted` (a ``KeyboardInterrupt``, so everything that handles Ctrl-C
handles them), and the command exits with ``128 + signal`` as a shell reports a death by that
signal. A handler the program installed itself, or a signal it ignores (``nohup``), is left alone.
"""
from __future__ import annotations

import contextlib
import signal
import threading
from typing import Iterator

#: the signals that end a run as interrupted (SIGINT is Python's own KeyboardInterrupt)
SIGNALS = tuple(s for s in (getattr(signal, "SIGTERM", None), getattr(signal, "SIGHUP", None)) if s is not None)


class Interrupted(KeyboardInterrupt):
    """A run stopped by a signal; ``signum`` says which."""

    def __init__(self, signum: int):
        super().__init__(signum)
        self.signum = signum

    @property
    def name(self) -> str:
        try:
            return signal.Signals(self.signum).name
        except ValueError:
            return f"signal {self.signum}"


def _raise(signum: int, frame: object) -> None:
    raise Interrupted(signum)


@contextlib.contextmanager
def interrupt_signals() -> Iterator[None]:
    """Within the block, SIGTERM and SIGHUP raise :class:`Interrupted` in the main thread (where
    they still have Python's default action; elsewhere nothing changes)."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    installed = {}
    for signum in SIGNALS:
        if signal.getsignal(signum) is signal.SIG_DFL:
            installed[signum] = signal.signal(signum, _raise)
    try:
        yield
    finally:
        for signum, previous in installed.items():
            signal.signal(signum, previous)


@contextlib.contextmanager
def held() -> Iterator[None]:
    """Within the block, Ctrl-C, SIGTERM and SIGHUP wait: one that arrives is raised as the block
    ends, as it would have been raised inside it.

    Why: some work must be done whole or not at all. A bench moves a finished run's record into
    ``records/`` and then writes the row that refers to it; an interrupt between the two left a
    record no row named, and ``--resume`` ran that task again beside it. Only signals that raise
    (a Python handler) are held; an ignored one, or one with its default action, is left alone."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    arrived: list[int] = []
    previous = {}
    for signum in (signal.SIGINT, *SIGNALS):
        handler = signal.getsignal(signum)
        if callable(handler):
            previous[signum] = signal.signal(signum, lambda n, _frame: arrived.append(n))
    try:
        yield
    finally:
        for signum, handler in previous.items():
            signal.signal(signum, handler)
    if arrived:
        previous[arrived[0]](arrived[0], None)


def exit_code(err: KeyboardInterrupt) -> int:
    """130 for Ctrl-C, 128 + N for signal N."""
    return 128 + (err.signum if isinstance(err, Interrupted) else int(signal.SIGINT))

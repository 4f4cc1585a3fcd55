"""The hook through which whoever runs a step bounds concurrent language-model calls.

:func:`pipflow.language.llm.complete` enters :func:`llm_slot` around each provider call. By
itself that is a no-op; a bench backend that shares providers between many runs (the Dask backend
of :mod:`pipflow.experiments.backends`) installs its limiter with :func:`install`. The language layer
thus never imports the backend above it.

The hook is process-wide rather than a ``contextvars.ContextVar``: the engine runs steps in worker
threads (``--jobs``, step time-outs), which would not see a context variable set by the thread
that started the run, and a limit that silently stops applying is worse than none.
"""
from __future__ import annotations

import contextlib
import threading
from typing import Callable, ContextManager, Iterator

#: ``slot(model, timeout=None)`` -> a context manager held for one provider call
Slot = Callable[..., ContextManager]

_hook: Slot | None = None
_lock = threading.Lock()


def install(slot: Slot | None) -> None:
    """Make ``slot`` the limiter of this process (None: no limit)."""
    global _hook
    with _lock:
        _hook = slot


@contextlib.contextmanager
def llm_slot(model: str, timeout: float | None = None) -> Iterator[None]:
    """Hold the installed limiter's slot for ``model`` for the block; nothing when none is installed."""
    hook = _hook
    if hook is None:
        yield
        return
    with hook(model, timeout=timeout):
        yield

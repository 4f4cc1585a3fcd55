"""The workflow engine: load and validate YAML workflows, run them as DAGs of steps, record runs.

Public entry points (imported lazily, so that ``from pipflow import step`` stays cheap):
:func:`run_workflow`, :func:`resume_run`, :func:`load_workflow`, :func:`check_workflow`,
:func:`find_workflow`, :class:`RunOptions`, :class:`Run` (a run and how it stands, :class:`RunStatus`;
``RunResult`` is its former name)."""
from __future__ import annotations

import importlib
from typing import Any

_EXPORTS = {
    "run_workflow": "runner", "resume_run": "runner", "find_workflow": "runner", "Run": "runner", "RunResult": "runner",
    "RunStatus": "status",
    "load_workflow": "validate", "check_workflow": "validate", "RunOptions": "executor",
}

__all__ = sorted(_EXPORTS)


def __getattr__(name: str) -> Any:
    if name in _EXPORTS:
        return getattr(importlib.import_module(f"{__name__}.{_EXPORTS[name]}"), name)
    raise AttributeError(name)

"""pipflow: the PIP-LLM pipeline as a declarative YAML workflow engine.

Public surface: for notebooks and scripts, :func:`run` and :func:`bench` (:mod:`pipflow.api`);
for step authors, :func:`step`, :class:`StepContext` and the signature markers :class:`Doc`,
:class:`Choices`, :class:`Check`, :data:`PathStr` (:class:`Input` for the first style); and the exception hierarchy
in :mod:`pipflow.errors`.
"""
from pipflow.engine.step import Check, Choices, Doc, Input, PathStr, Step, StepContext, step
from pipflow.errors import (
    AllocationError,
    Diagnostic,
    InputError,
    LLMError,
    Location,
    PipflowError,
    PlanningError,
    Refusal,
    StepError,
    TaskFileError,
    TranslationError,
    UserError,
    WorkflowError,
    WorldError,
)
from pipflow.version import __version__


def __getattr__(name: str):
    """``run``, ``bench`` and ``Run`` load the engine's executor (networkx and the rest) on first
    use, so that a step plugin's ``from pipflow import step`` stays a light import."""
    if name in ("run", "bench", "Run"):
        # deferred: pulls networkx and jsonschema (the executor); `from pipflow import step` stays light
        from pipflow import api

        return getattr(api, name)
    raise AttributeError(f"module 'pipflow' has no attribute {name!r}")


__all__ = [
    "run", "bench", "Run",
    "step", "Input", "Step", "StepContext", "Doc", "Choices", "Check", "PathStr",
    "PipflowError", "UserError", "WorkflowError", "WorldError", "TaskFileError", "InputError", "StepError",
    "PlanningError", "AllocationError", "LLMError", "TranslationError", "Refusal",
    "Diagnostic", "Location",
]

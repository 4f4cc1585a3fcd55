"""pipflow: the PIP-LLM pipeline as a declarative YAML workflow engine.

Public surface for step authors: :func:`step`, :class:`Input`, :class:`StepContext`, and the
exception hierarchy in :mod:`pipflow.errors`.
"""
from pipflow.engine.step import Input, Step, StepContext, step
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
    TranslationError,
    UserError,
    WorkflowError,
    WorldError,
)

__version__ = "0.1.0"

__all__ = [
    "step", "Input", "Step", "StepContext",
    "PipflowError", "UserError", "WorkflowError", "WorldError", "InputError", "StepError",
    "PlanningError", "AllocationError", "LLMError", "TranslationError", "Refusal",
    "Diagnostic", "Location",
]

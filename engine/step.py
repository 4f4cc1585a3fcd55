"""The contract of a step: a declared name, typed inputs and outputs, and a function.

Built-in and third-party steps are written the same way::

    from pipflow import step, Input, StepContext

    @step("text.upper", doc="Upper-case a text.",
          inputs={"text": Input("string", doc="the text")},
          outputs={"text": "string"})
    def upper(ctx: StepContext, text: str) -> dict:
        return {"text": text.upper()}

and are registered through the entry-point group ``pipflow.steps``. Step functions receive
resolved, JSON-like arguments and return a dict of JSON-like outputs: that is what makes run
records, the cache, ``resume`` and remote execution possible without pickling anything.
"""
from __future__ import annotations

import json
import os
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Callable

TYPES = ("string", "integer", "number", "boolean", "object", "array", "path", "any")
_REQUIRED = object()


@dataclass(frozen=True)
class Input:
    """A declared step input. ``default`` omitted means the argument is required."""

    type: str = "any"
    default: Any = _REQUIRED
    doc: str = ""
    choices: tuple | None = None
    # check(value, base_dir) -> a problem in words, or None: run by `validate` on literal values
    # and on the workflow inputs that flow into this argument, before any step runs (a misspelt
    # prompt name must fail at once, not only when a real model is called)
    check: Callable[[Any, Path | None], str | None] | None = field(default=None, compare=False)

    def __post_init__(self) -> None:
        if self.type not in TYPES:
            raise ValueError(f"unknown input type {self.type!r}; use one of {', '.join(TYPES)}")

    @property
    def required(self) -> bool:
        return self.default is _REQUIRED


@dataclass
class Step:
    """A registered step: metadata plus the function that runs it."""

    name: str
    func: Callable[..., dict]
    doc: str = ""
    inputs: dict[str, Input] = field(default_factory=dict)
    outputs: dict[str, str] = field(default_factory=dict)
    version: str = "1"
    cacheable: bool = False
    module: str = ""

    def defaults(self) -> dict[str, Any]:
        return {k: v.default for k, v in self.inputs.items() if not v.required}


def step(
    name: str,
    *,
    doc: str = "",
    inputs: dict[str, Input] | None = None,
    outputs: dict[str, str] | None = None,
    version: str = "1",
    cacheable: bool = False,
) -> Callable[[Callable[..., dict]], Step]:
    """Declare a step. The decorated function becomes a :class:`Step` object."""

    def wrap(func: Callable[..., dict]) -> Step:
        return Step(
            name=name,
            func=func,
            doc=doc or (func.__doc__ or "").strip().split("\n\n")[0],
            inputs=dict(inputs or {}),
            outputs=dict(outputs or {}),
            version=version,
            cacheable=cacheable,
            module=func.__module__,
        )

    return wrap


class StepContext:
    """What a running step may use besides its arguments: where to put artifacts, how to log,
    how to resolve relative paths, and the id of the step in its workflow."""

    def __init__(
        self,
        step_id: str,
        artifact_dir: Path,
        base_dir: Path,
        log: Callable[[str], None] | None = None,
        iteration: int | None = None,
        use_cache: bool = True,
        warn: Callable[[str], None] | None = None,
    ):
        self.step_id = step_id
        self.artifact_dir = artifact_dir
        self.base_dir = base_dir
        self.iteration = iteration
        self.use_cache = use_cache  # False under --no-cache: steps with caches of their own obey it too
        self._log = log or (lambda message: None)
        self._warn = warn or self._log
        self.metrics: dict[str, Any] = {}

    def warn(self, message: str) -> None:
        """Record a warning: something the user should know although the step goes on (shown
        without ``-v``), e.g. a cache of the step's own that cannot be written."""
        self._warn(message)

    def log(self, message: str) -> None:
        """Record a line in the run's event log (and show it with ``-v``)."""
        self._log(message)

    def resolve_path(self, path: str | os.PathLike) -> Path:
        """A path relative to the workflow file's folder (absolute paths stay as they are)."""
        p = Path(path).expanduser()
        return p if p.is_absolute() else (self.base_dir / p).resolve()

    def write_artifact(self, name: str, content: str | bytes | Any) -> Path:
        """Write an artifact atomically into this step's folder of the run record.

        Text and bytes are written as they are; anything else is written as JSON."""
        from .store import atomic_write

        path = self.artifact_dir / name
        if isinstance(content, (str, bytes)):
            atomic_write(path, content)
        else:
            atomic_write(path, json.dumps(content, indent=2, sort_keys=True, default=str))
        return path

    def artifact_path(self, name: str) -> Path:
        """A path inside this step's artifact folder, for libraries that write files themselves
        (matplotlib, pybullet). The folder exists when this returns."""
        self.artifact_dir.mkdir(parents=True, exist_ok=True)
        return self.artifact_dir / name

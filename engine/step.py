"""The contract of a step: a declared name, typed inputs and outputs, and a function.

The function's signature is the one source of its inputs: type hints give the types, defaults
the defaults, and ``Annotated`` markers the docs, choices and value checks::

    from typing import Annotated
    from pipflow import Doc, StepContext, step

    @step("text.upper", doc="Upper-case a text.", outputs={"text": "string"})
    def upper(ctx: StepContext, text: Annotated[str, Doc("the text")]) -> dict:
        return {"text": text.upper()}

Hints map to declared types: ``str`` string, ``int`` integer, ``float`` number, ``bool``
boolean, ``dict`` object, ``list`` array, ``pathlib.Path`` or :data:`PathStr` path (the step
receives the resolved path as a string), ``Any`` any. ``X | None`` says the value may be null (a
skipped step's output is); a parameter is required exactly when it has no default. Everything is
checked when the step is declared: a parameter without a hint, a hint that maps to no type, or a
default of another type is a :class:`~pipflow.errors.StepDefinitionError` naming the function.

``inputs={name: Input(...)}`` (the first style) is still accepted for one release, for
third-party plugins: it is checked against the signature, and a difference (a name, a type, a
default) is an error naming the parameter and both values.

Outputs are declared by the return annotation: a ``TypedDict`` names each output and its type
(mapped like the inputs' hints; a nested TypedDict is an object), and the family it belongs to
when it carries a :func:`shape` (recorded with the step's start in the run's events, so a reader
such as the report finds "the simulation" by what the step declared, never by the keys of what
it returned)::

    @shape("greeting")
    class Greeting(TypedDict):
        text: str
        length: int

    @step("text.greet", doc="Greet.")
    def greet(ctx: StepContext, name: Annotated[str, Doc("who")]) -> Greeting:
        return {"text": f"hello {name}", "length": len(name) + 6}

``outputs={...}`` (with ``-> dict``) still declares them by hand; given beside a TypedDict it
must agree with it. A step that returns a key it does not declare fails when it runs.

Steps are registered through the entry-point group ``pipflow.steps``. Step functions receive
resolved, JSON-like arguments and return a dict of JSON-like outputs: that is what makes run
records, the cache, ``resume`` and remote execution possible without pickling anything.
"""
from __future__ import annotations

import collections.abc as abc
import inspect
import json
import os
import pathlib
import types
import typing
from dataclasses import dataclass, field
from pathlib import Path
from typing import Annotated, Any, Callable, NewType, Union

import yaml

from pipflow.errors import InputError, StepDefinitionError
from pipflow.yamlsource import read_source, safe_load, yaml_error_diagnostic

from .provenance import Provenance
from .store import atomic_write
from .writes import make_dirs
from .types import type_matches

TYPES = ("string", "integer", "number", "boolean", "object", "array", "path", "any")
_REQUIRED = object()

#: A path argument: the step receives the path, resolved against the workflow's folder, as a str.
PathStr = NewType("PathStr", str)

#: the attribute a :func:`shape` sets on a TypedDict
SHAPE_ATTRIBUTE = "__pipflow_shape__"


def shape(name: str) -> Callable[[type], type]:
    """Class decorator: the TypedDict declares outputs of the family ``name`` (``"simulation"``,
    ``"score"``, ...). Steps whose outputs differ in detail (a domain's own simulation step with
    keys of its own) belong to one family by carrying the same name; readers of run records look
    steps up by it (:func:`pipflow.engine.store.RunStore` keeps it in the step's ``start`` event)."""
    def tag(cls: type) -> type:
        if not typing.is_typeddict(cls):
            raise TypeError(f"@shape({name!r}) marks a TypedDict, not {cls!r}")
        setattr(cls, SHAPE_ATTRIBUTE, name)
        return cls
    return tag


@dataclass(frozen=True)
class Doc:
    """``Annotated[str, Doc("the text")]``: what an input means, shown by ``pipflow steps``."""

    text: str


@dataclass(frozen=True)
class Choices:
    """``Annotated[str, Choices("a", "b")]``: the only values an input accepts."""

    values: tuple

    def __init__(self, *values: Any) -> None:
        object.__setattr__(self, "values", tuple(values))


@dataclass(frozen=True)
class Check:
    """``Annotated[str, Check(fn)]``: ``fn(value, base_dir)`` returns a problem in words or None;
    ``validate`` runs it on literal values before any step runs."""

    fn: Callable[[Any, Path | None], str | None]


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
    #: the family of its outputs (a :func:`shape` of its return TypedDict), or None
    shape: str | None = None

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
    """Declare a step. The decorated function becomes a :class:`Step` object whose inputs are
    read from its signature (``inputs=`` is the deprecated first style, checked against it)."""

    def wrap(func: Callable[..., dict]) -> Step:
        for key, type_name in (outputs or {}).items():
            if type_name not in TYPES:
                raise StepDefinitionError(f"step {name!r} ({_where(func)}): output {key!r} has unknown type "
                                          f"{type_name!r}; use one of {', '.join(TYPES)}")
        typed, family = signature_outputs(func, name)
        if typed is not None and outputs is not None and dict(outputs) != typed:
            differ = sorted(k for k in set(typed) | set(outputs) if typed.get(k) != outputs.get(k))
            raise StepDefinitionError(f"step {name!r} ({_where(func)}): outputs= and the return TypedDict disagree "
                                      f"on {', '.join(map(repr, differ))}; declare the outputs in one place")
        return Step(
            name=name,
            func=func,
            doc=doc or (func.__doc__ or "").strip().split("\n\n")[0],
            inputs=signature_inputs(func, name, inputs),
            outputs=dict(typed if typed is not None else outputs or {}),
            version=version,
            cacheable=cacheable,
            module=func.__module__,
            shape=family,
        )

    return wrap


# ---------------------------------------------------------------------- signature -> inputs
_SIMPLE = {str: "string", int: "integer", float: "number", bool: "boolean", dict: "object", list: "array",
           pathlib.Path: "path", PathStr: "path", Any: "any"}
_ORIGINS = {dict: "object", list: "array", abc.Mapping: "object", abc.Sequence: "array"}


def _where(func: Callable) -> str:
    return f"{func.__module__}.{func.__qualname__}"


def _type_of(hint: Any) -> tuple[str | None, bool]:
    """The declared type a hint maps to (None: no type) and whether it admits None."""
    origin = typing.get_origin(hint)
    if origin is Annotated:  # Annotated[...] | None: the type of what is annotated
        return _type_of(typing.get_args(hint)[0])
    if origin in (Union, types.UnionType):
        members = [a for a in typing.get_args(hint) if a is not type(None)]
        nullable = len(members) < len(typing.get_args(hint))
        found = {_type_of(m)[0] for m in members}
        if found == {"integer", "number"}:
            return "number", nullable
        return (found.pop() if len(found) == 1 else None), nullable
    if hint in _SIMPLE:
        return _SIMPLE[hint], False
    if origin is not None:
        return _ORIGINS.get(origin), False
    return None, False


def signature_inputs(func: Callable, name: str, declared: dict[str, Input] | None = None) -> dict[str, Input]:
    """The inputs of step ``name`` read from ``func``'s signature; ``declared`` (the first style)
    must agree with it. Raises :class:`StepDefinitionError` naming the function and parameter."""
    where = f"step {name!r} ({_where(func)})"
    try:
        hints = typing.get_type_hints(func, include_extras=True)
    except Exception as err:  # a hint naming something the module does not import
        raise StepDefinitionError(f"{where}: its type hints cannot be read: {type(err).__name__}: {err}") from None
    params = list(inspect.signature(func).parameters.values())
    if not params or params[0].kind not in (params[0].POSITIONAL_ONLY, params[0].POSITIONAL_OR_KEYWORD):
        raise StepDefinitionError(f"{where}: the first parameter must take the StepContext")
    declared = dict(declared or {})
    found: dict[str, Input] = {}
    for p in params[1:]:
        if p.kind in (p.VAR_POSITIONAL, p.VAR_KEYWORD):
            raise StepDefinitionError(f"{where}: parameter {p.name!r}: *args and **kwargs cannot be declared inputs")
        legacy = declared.pop(p.name, None)
        found[p.name] = _one_input(where, p, hints.get(p.name, inspect.Parameter.empty), legacy)
    if declared:
        raise StepDefinitionError(f"{where}: inputs= declares {', '.join(map(repr, declared))}, "
                                  f"which the function does not take")
    return found


def signature_outputs(func: Callable, name: str) -> tuple[dict[str, str] | None, str | None]:
    """The outputs a step's return annotation declares (a TypedDict: each key's type) and their
    family (its :func:`shape`); ``(None, None)`` for any other annotation (``-> dict``)."""
    where = f"step {name!r} ({_where(func)})"
    try:
        hint = typing.get_type_hints(func, include_extras=True).get("return")
    except Exception as err:
        raise StepDefinitionError(f"{where}: its type hints cannot be read: {type(err).__name__}: {err}") from None
    if typing.get_origin(hint) is Annotated:
        hint = typing.get_args(hint)[0]
    if not typing.is_typeddict(hint):
        return None, None
    found = {}
    for key, field_hint in typing.get_type_hints(hint, include_extras=True).items():
        type_name = output_type(field_hint)
        if type_name is None:
            raise StepDefinitionError(f"{where}: output {key!r} of {hint.__name__}: the hint {_show_hint(field_hint)} "
                                      f"maps to no output type; use str, int, float, bool, dict, list, a TypedDict or Any")
        found[key] = type_name
    return found, getattr(hint, SHAPE_ATTRIBUTE, None)


def output_type(hint: Any) -> str | None:
    """The declared type of one output from its hint (a TypedDict is an object; whether it may be
    null does not matter: a skipped step's outputs are all null)."""
    if typing.get_origin(hint) is Annotated:
        hint = typing.get_args(hint)[0]
    if typing.get_origin(hint) in (Union, types.UnionType):
        members = [m for m in typing.get_args(hint) if m is not type(None)]
        found = {output_type(m) for m in members}
        if found == {"integer", "number"}:
            return "number"
        return found.pop() if len(found) == 1 else "any"
    if typing.is_typeddict(hint):
        return "object"
    return _type_of(hint)[0]


def _one_input(where: str, p: inspect.Parameter, hint: Any, legacy: Input | None) -> Input:
    doc, choices, check = "", None, None
    if typing.get_origin(hint) is Annotated:
        base, *extras = typing.get_args(hint)
        for extra in extras:
            if isinstance(extra, Doc):
                doc = extra.text
            elif isinstance(extra, Choices):
                choices = extra.values
            elif isinstance(extra, Check):
                check = extra.fn
        hint = base
    default = _REQUIRED if p.default is inspect.Parameter.empty else p.default
    if hint is inspect.Parameter.empty:
        if legacy is None:
            raise StepDefinitionError(f"{where}: parameter {p.name!r} has no type hint; write one "
                                      f"(str, int, float, bool, dict, list, PathStr, Any; X | None if it may be null)")
        type_name, nullable = legacy.type, True  # the first style's declaration is all there is
    else:
        type_name, nullable = _type_of(hint)
        if type_name is None:
            raise StepDefinitionError(f"{where}: parameter {p.name!r}: the hint {_show_hint(hint)} maps to no "
                                      f"input type; use str, int, float, bool, dict, list, PathStr or Any")
    if default is not _REQUIRED:
        if default is None and not nullable and type_name != "any":
            raise StepDefinitionError(f"{where}: parameter {p.name!r}: default None, but the hint "
                                      f"{_show_hint(hint)} does not admit None (write {_show_hint(hint)} | None)")
        if default is not None and not type_matches(default, type_name):
            raise StepDefinitionError(f"{where}: parameter {p.name!r}: default {default!r} is not "
                                      f"{type_name} (the hint is {_show_hint(hint)})")
        if choices and default is not None and default not in choices:
            raise StepDefinitionError(f"{where}: parameter {p.name!r}: default {default!r} is not one of its choices")
    if legacy is not None:
        # a hint may be wider than the declaration it predates (str for a path, Any): the declared
        # type is then the narrower one; any other difference is drift
        if legacy.type != type_name and not (type_name == "any" or (type_name, legacy.type) == ("string", "path")):
            raise StepDefinitionError(f"{where}: parameter {p.name!r}: inputs= says type {legacy.type}, "
                                      f"the signature says {type_name} (hint {_show_hint(hint)})")
        if _shown_default(legacy.default) != _shown_default(default):
            raise StepDefinitionError(f"{where}: parameter {p.name!r}: inputs= says default "
                                      f"{_shown_default(legacy.default)}, the signature says {_shown_default(default)}")
        type_name = legacy.type
        for what, theirs, ours in (("doc", legacy.doc, doc), ("choices", legacy.choices, choices)):
            if theirs and ours and theirs != ours:
                raise StepDefinitionError(f"{where}: parameter {p.name!r}: inputs= says {what} {theirs!r}, "
                                          f"the signature says {ours!r}")
        doc, choices, check = doc or legacy.doc, choices or legacy.choices, check or legacy.check
    return Input(type_name, default, doc, choices, check)


def _shown_default(default: Any) -> str:
    return "(required)" if default is _REQUIRED else repr(default)


def _show_hint(hint: Any) -> str:
    return getattr(hint, "__name__", None) or str(hint).replace("typing.", "")


def check_outputs(step: Step, outputs: dict, step_id: str) -> None:
    """A step may return only what it declares: an undeclared key would reach no consumer that
    ``validate`` checked, and usually means the declaration is out of date."""
    extra = [key for key in outputs if key not in step.outputs]
    if extra:
        raise StepDefinitionError(
            f"step {step_id!r} ({step.name}) returned {', '.join(map(repr, extra))}, which it does not declare "
            f"(declared outputs: {', '.join(step.outputs) or 'none'}); declare it in outputs= or stop returning it")


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
        record_root: Path | None = None,
        provenance: Provenance | None = None,
        own_folders: tuple = (),
    ):
        self.step_id = step_id
        self.artifact_dir = artifact_dir
        self.base_dir = base_dir
        self.record_root = record_root  # the run's folder: below it no write follows a link
        # what the user named, and the folders of the workflow files that set this step's arguments:
        # a path the workflow alone names is read only there (engine/provenance.py); a context made
        # by hand (a test, a notebook calling a step) reads anything
        self.provenance = provenance if provenance is not None else Provenance(open=True)
        self.own_folders = tuple(own_folders) or (base_dir,)
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
        """A path relative to the workflow file's folder (absolute paths stay as they are), which
        the step may read: one the user named, or one inside the workflow's folder or pipflow's
        data (:mod:`pipflow.engine.provenance`; an :class:`~pipflow.errors.InputError` otherwise)."""
        p = Path(path).expanduser()
        resolved = p if p.is_absolute() else (self.base_dir / p).resolve()
        self.check_readable(resolved, f"step {self.step_id!r}: {path}", named_as=str(path))
        return resolved

    def read_yaml(self, value: Any, what: str) -> dict:
        """A step input that is "a path or its content": a mapping given inline is returned as it
        is; anything else names a YAML file (resolved as :meth:`resolve_path`), read by the shared
        bounded reader and loader (regular files, a size cap, no alias bombs). Bad YAML is an
        :class:`~pipflow.errors.InputError` naming ``what``, the file and the line."""
        if isinstance(value, dict):
            return value
        path = self.resolve_path(value)
        try:
            return safe_load(read_source(path, what)) or {}
        except yaml.YAMLError as exc:
            raise InputError(f"{what}: {yaml_error_diagnostic(exc, str(path))}") from None

    def check_readable(self, path: str | os.PathLike, what: str, named_as: Any = None) -> None:
        """Raise :class:`~pipflow.errors.InputError` unless the step may read ``path`` (named by
        the user as ``named_as``, or where the workflow lives: see :meth:`resolve_path`)."""
        self.provenance.check(path, self.own_folders, what, named_as=named_as)

    def named_by_user(self, value: Any) -> bool:
        """Whether the user gave this exact value (a server address, a template name), rather
        than the workflow file: such values may go where the workflow's own may not."""
        return self.provenance.named(value)

    def write_artifact(self, name: str, content: str | bytes | Any) -> Path:
        """Write an artifact atomically into this step's folder of the run record (no link in
        the record is followed; a full disk is a :class:`~pipflow.engine.writes.DiskError`).

        Text and bytes are written as they are; anything else is written as JSON."""
        path = self.artifact_dir / name
        if isinstance(content, (str, bytes)):
            atomic_write(path, content, root=self.record_root)
        else:
            atomic_write(path, json.dumps(content, indent=2, sort_keys=True, default=str), root=self.record_root)
        return path

    def artifact_path(self, name: str) -> Path:
        """A path inside this step's artifact folder, for libraries that write files themselves
        (matplotlib, pybullet; they should write through :func:`pipflow.engine.writes.write_file`
        so that a link is never followed). The folder exists when this returns."""
        make_dirs(self.artifact_dir, root=self.record_root)
        return self.artifact_dir / name

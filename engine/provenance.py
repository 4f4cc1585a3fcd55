"""What a workflow may read on its own, and which values the user named.

A workflow file may come from anyone: a colleague, a repository, a download. The values a user
gives (``-i``, ``--inputs``, keyword arguments of ``pipflow.run``, a bench's ``-i``, ``--matrix`` and
task file) are the user's own choices. So a file that only the workflow file names (an input's
default, a step argument) is read only from where that workflow lives:

- inside the folder of the workflow file that names it, or of a file of its ``extends`` chain
  (not in a hidden sub-folder: a workflow saved into a home folder must not read ``~/.ssh``);
  a workflow inside a Python package (``pkg/workflows/x.yaml`` with ``pkg/__init__.py``) owns the
  whole package, as its ``../data/world.yaml`` shows (a download cannot make the folder it is
  unpacked into a package: that takes an ``__init__.py`` above it),
- inside pipflow's built-in data (workflows, prompts, domains, benchmarks, schemas), or
- inside the package folder of an installed pipflow plugin (its workflows name its own data);

anything else only when the user names it (a path they gave, or a file inside a folder they
gave). The path is checked after links are resolved, so a link unpacked with a shared workflow
cannot point elsewhere. Why: a shared workflow whose ``prompt`` defaulted to ``/etc/passwd`` and
whose ``api_base`` named its own server sent the file's text as the prompt.
"""
from __future__ import annotations

import functools
import importlib.util
import json
import os
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Iterable

from pipflow.errors import InputError
from pipflow.resources import data_dir

#: pipflow's data folders: files in them may be named by any workflow
DATA_FOLDERS = ("workflows", "prompts", "domains", "benchmarks", "schemas")
#: the entry-point groups of pipflow plugins: their package folders count as built-in data
PLUGIN_GROUPS = ("pipflow.steps", "pipflow.task_domains", "pipflow.commands")


@functools.lru_cache(maxsize=1)
def data_roots() -> tuple[str, ...]:
    """pipflow's data folders (real paths)."""
    roots: set[str] = set()
    for name in DATA_FOLDERS:
        try:
            roots.add(os.path.realpath(data_dir(name)))
        except FileNotFoundError:
            continue
    return tuple(sorted(roots))


@functools.lru_cache(maxsize=1)
def plugin_roots() -> tuple[str, ...]:
    """The package folders of installed pipflow plugins (real paths; asked only when a path is
    not inside anything cheaper to check: reading the entry points costs a few ms)."""
    from importlib.metadata import entry_points  # deferred: scans every installed distribution

    roots: set[str] = set()
    for group in PLUGIN_GROUPS:
        for ep in entry_points(group=group):
            top = ep.value.split(":")[0].split(".")[0].strip()
            try:  # the package's folder, found without importing it
                spec = importlib.util.find_spec(top)
            except (ImportError, ValueError):
                continue
            for folder in (spec.submodule_search_locations or []) if spec else []:
                roots.add(os.path.realpath(folder))
    return tuple(sorted(roots))


def package_root(folder: str) -> str:
    """``folder``, or the outermost Python package above it when its parent is one (a folder
    with ``__init__.py``): the folder a workflow shipped in a package owns."""
    root = folder
    while os.path.isfile(os.path.join(os.path.dirname(root), "__init__.py")) and os.path.dirname(root) != root:
        root = os.path.dirname(root)
    return root


def _inside(path: str, root: str) -> bool:
    return path == root or path.startswith(root.rstrip(os.sep) + os.sep)


def _hidden_below(path: str, root: str) -> bool:
    rel = os.path.relpath(path, root)
    return any(part.startswith(".") and part not in (".", "..") for part in Path(rel).parts)


@dataclass(frozen=True)
class Provenance:
    """The values the user gave a run, and the folders they and the workflow may read from.

    ``given``: the text of every value the user gave (paths as they resolve too); ``roots``: real
    paths the user named (files or folders) and the values of path-typed inputs (a default was
    checked when it was resolved). A ``Provenance()`` with ``open=True`` (a step called by hand,
    outside a run) allows everything."""

    given: frozenset[str] = frozenset()
    roots: tuple[str, ...] = ()
    open: bool = False
    names: tuple[str, ...] = field(default=())  # the inputs the user gave, by name (recorded for resume)

    @classmethod
    def of_run(cls, values: dict[str, Any], given_names: Iterable[str], path_inputs: Iterable[str]) -> "Provenance":
        """From a run's resolved inputs: ``given_names`` are those the user gave; the values of
        ``path_inputs`` (path-typed inputs) are readable whoever named them."""
        given_names = tuple(sorted(n for n in given_names if n in values))
        texts: set[str] = set()
        roots: set[str] = set()
        for name in given_names:
            for text in _texts(values[name]):
                texts.add(text)
                if os.path.isabs(os.path.expanduser(text)):
                    roots.add(os.path.realpath(os.path.expanduser(text)))
        for name in path_inputs:
            value = values.get(name)
            if isinstance(value, str) and value and os.path.isabs(value):
                roots.add(os.path.realpath(value))
        return cls(frozenset(texts), tuple(sorted(roots)), names=given_names)

    def named(self, value: Any) -> bool:
        """Whether the user gave this exact value (a server address, a template name)."""
        return self.open or (isinstance(value, str) and value.strip() in self.given)

    def check(self, path: str | os.PathLike, own: Iterable[str | os.PathLike], what: str,
              named_as: Any = None) -> None:
        """Raise :class:`InputError` unless ``path`` may be read (see the module's rules);
        ``own`` are the folders of the workflow files that name it, ``named_as`` the value as
        written (a value the user gave is always allowed)."""
        if self.open or (named_as is not None and self.named(named_as)):
            return
        problem = outside(path, own, self.roots)
        if problem:
            raise InputError(f"{what}: {problem}")

    def to_json(self) -> list[str]:
        return list(self.names)


def _texts(value: Any) -> list[str]:
    if isinstance(value, str):
        return [value.strip()]
    if isinstance(value, (list, tuple)):
        return [t for v in value for t in _texts(v)]
    if isinstance(value, dict):
        return [t for v in value.values() for t in _texts(v)]
    return [json.dumps(value)] if isinstance(value, (int, float)) and not isinstance(value, bool) else []


def outside(path: str | os.PathLike, own: Iterable[str | os.PathLike], roots: Iterable[str] = ()) -> str | None:
    """Why a workflow may not read ``path`` on its own (None when it may)."""
    real = os.path.realpath(os.path.expanduser(str(path)))
    if any(_inside(real, r) for r in (*data_roots(), *roots)):
        return None
    folders = list(dict.fromkeys(package_root(os.path.realpath(f)) for f in own))
    for folder in folders:
        if _inside(real, folder):
            if _hidden_below(real, folder):
                return (f"{real} is in a hidden folder or file inside the workflow's folder {folder}; a workflow reads "
                        "hidden files only when you name them (give the path yourself, e.g. with -i)")
            return None
    if any(_inside(real, r) for r in plugin_roots()):
        return None
    shown = folders[0] if folders else "?"
    via = f" ({path} leads there through a link)" if os.path.abspath(os.path.expanduser(str(path))) != real else ""
    return (f"{real}{via} is outside the workflow's folder {shown} and pipflow's built-in data; a workflow file reads "
            "such files only when you name them yourself (-i NAME=PATH, --inputs, or a keyword of pipflow.run)")

"""Find task domains: pipflow's own and third-party ones register the same way, through the
entry-point group ``pipflow.task_domains`` (as steps do through ``pipflow.steps``).

An entry point names a :class:`pipflow.taskdomain.TaskDomain` subclass (instantiated once) or an
instance. The table is built once per process; the domains themselves are imported only when
first asked for, so a run in one domain does not load the others' code.
"""
from __future__ import annotations

import re
from functools import lru_cache
from importlib.metadata import entry_points
from importlib.util import find_spec
from pathlib import Path
from typing import Any

from pipflow.errors import InputError, UserError
from pipflow.taskdomain import DEFAULT_DOMAIN, TaskDomain
from pipflow.yamlsource import read_source, top_level_scalar

GROUP = "pipflow.task_domains"


@lru_cache(maxsize=1)
def _entry_points() -> dict[str, Any]:
    return {ep.name: ep for ep in entry_points(group=GROUP)}


def known_domains() -> list[str]:
    """The names of the installed task domains."""
    return sorted(_entry_points())


def own_domain_step_modules() -> list[str]:
    """The ``steps`` modules of the task domains pipflow itself ships (its own entry points in
    :data:`GROUP`, e.g. ``pipflow.<domain>.domain`` -> ``pipflow.<domain>.steps``), for those
    that have one: the steps a built-in domain keeps for older workflows count as pipflow's own
    (entry point ``builtin``) while steps/ names no domain. Found without importing the domains."""
    modules = []
    for ep in _entry_points().values():
        if ep.dist is not None and ep.dist.name == "pipflow":
            candidate = ep.module.rsplit(".", 1)[0] + ".steps"
            if find_spec(candidate) is not None:
                modules.append(candidate)
    return sorted(modules)


@lru_cache(maxsize=None)
def domain_named(name: str | None) -> TaskDomain:
    """The installed domain ``name`` (None: the default domain). An unknown name is the user's
    error, naming the known domains; a plugin that fails to load says which and why."""
    name = name or DEFAULT_DOMAIN
    ep = _entry_points().get(name)
    if ep is None:
        raise InputError(f"unknown task domain {name!r}; known: {', '.join(known_domains()) or '(none installed)'}")
    try:
        target = ep.load()
    except Exception as err:  # a broken plugin: say which, never a traceback
        raise UserError(f"task domain {name!r} ({ep.value}) failed to load: {type(err).__name__}: {err}") from None
    domain = target() if isinstance(target, type) else target
    if not isinstance(domain, TaskDomain):
        raise UserError(f"entry point {name!r} of group {GROUP} ({ep.value}) is not a pipflow.taskdomain.TaskDomain")
    return domain


def task_domain(world: Any) -> TaskDomain:
    """The domain of a world dict (``world["domain"]``; absent or not a dict: the default)."""
    name = world.get("domain") if isinstance(world, dict) else None
    return domain_named(name if isinstance(name, str) else None)


def declared_domain(path: str | Path, what: str = "world file") -> TaskDomain:
    """The domain a YAML file (world or task file) declares with a top-level ``domain:`` key,
    read cheaply; the domain's own loader validates the file and locates its problems."""
    text = ""
    try:  # the shared bounded reader: no /dev/zero, no alias bomb, no deep nesting
        text = read_source(path, what)
    except UserError:
        pass  # the loader reports the problem with its location
    # only the one key is read (libyaml's events up to it): loading a 5 MB world here took 40 s
    # before its own loader could refuse it as too large
    name = top_level_scalar(text, "domain")
    try:
        return domain_named(name)
    except InputError as exc:  # say where the file names it
        line = next((n for n, row in enumerate(text.splitlines(), 1) if re.match(r"domain\s*:", row)), 1)
        raise InputError(f"{path}:{line}: {exc}") from None

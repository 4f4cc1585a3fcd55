"""Find steps: built-in and third-party steps register the same way, through the entry-point
group ``pipflow.steps``.

An entry point may name a :class:`Step` object, a module (every Step in it is registered), or a
package with a ``STEP_MODULES`` list of module names (how pipflow registers its own steps).

A plugin that fails to load (an import error, a step name registered twice) does not take the
others down: it is listed in :attr:`Registry.broken`, the CLI warns about it and lists it in
``pipflow steps``, and only a workflow that uses a step pipflow cannot find fails, with a
message that names the broken plugin.
"""
from __future__ import annotations

import importlib
from importlib.metadata import entry_points
from types import ModuleType
from typing import Iterable

from pipflow.errors import UserError
from pipflow.suggest import closest

from .step import Step

GROUP = "pipflow.steps"


class Registry:
    """Step names to :class:`Step` objects, with where each came from."""

    def __init__(self) -> None:
        self._steps: dict[str, Step] = {}
        self._origin: dict[str, str] = {}
        self.broken: dict[str, str] = {}  # plugin (origin) -> why it could not be loaded

    def add(self, step: Step, origin: str) -> None:
        known = self._origin.get(step.name)
        if known is not None and self._steps[step.name] is not step:
            raise UserError(f"step {step.name!r} is registered twice: by {known} and by {origin}")
        self._steps[step.name] = step
        self._origin[step.name] = origin

    def add_module(self, module: ModuleType, origin: str) -> None:
        for value in vars(module).values():
            if isinstance(value, Step):
                self.add(value, origin)

    def get(self, name: str) -> Step | None:
        return self._steps.get(name)

    def origin(self, name: str) -> str:
        return self._origin.get(name, "")

    def names(self) -> list[str]:
        return sorted(self._steps)

    def closest(self, name: str, n: int = 3) -> list[str]:
        return closest(name, self._steps, n=n, cutoff=0.5)  # the module's function: pipflow.suggest

    def __contains__(self, name: str) -> bool:
        return name in self._steps

    def __iter__(self) -> Iterable[Step]:
        return iter(self._steps[n] for n in self.names())

    def broken_hint(self) -> str:
        """For an unknown step: the plugins that failed to load, one of which may provide it."""
        if not self.broken:
            return ""
        shown = [f"{o} ({why})" for o, why in list(self.broken.items())[:2]]
        more = len(self.broken) - len(shown)
        return ("; step plugin(s) that failed to load: " + "; ".join(shown)
                + (f"; and {more} more (see `pipflow steps`)" if more > 0 else ""))


def _register_target(registry: Registry, target: object, origin: str) -> None:
    if isinstance(target, Step):
        registry.add(target, origin)
    elif isinstance(target, ModuleType):
        for name in getattr(target, "STEP_MODULES", ()):
            try:  # one broken module of a package leaves its siblings' steps usable
                registry.add_module(importlib.import_module(name), origin)
            except Exception as err:
                registry.broken[f"{origin} ({name})"] = f"{type(err).__name__}: {err}"
        registry.add_module(target, origin)
    else:
        raise UserError(f"entry point {origin} of group {GROUP} names neither a step nor a module")


_default: Registry | None = None


def default_registry() -> Registry:
    """All installed steps (built once per process)."""
    global _default
    if _default is None:
        registry = Registry()
        for ep in entry_points(group=GROUP):
            origin = f"{ep.dist.name if ep.dist else '?'}:{ep.name}"
            try:  # a broken plugin must not hide the others' steps, nor stop workflows without it
                _register_target(registry, ep.load(), origin)
            except Exception as err:
                registry.broken[f"{origin} ({ep.value})"] = f"{type(err).__name__}: {err}"
        _default = registry
    return _default

"""Defer the ConfigSpace import that unified-planning's engine base class makes at import time.

Why: ``unified_planning/engines/engine.py`` does ``from ConfigSpace import ConfigurationSpace`` at
its top, only to build an (empty) configuration space in ``Engine.get_configuration_space`` (used
by hyper-parameter tuners, never by pipflow). ConfigSpace imports scipy.stats, and on the 2-core
reference machine that one import took 1.0-1.4 s of a 3-4 s main job. Importing a narrower UP
module does not help: any ``unified_planning.engines.*`` import runs ``engines/__init__`` and
hence ``engine.py`` (measured with ``python -X importtime``).

:func:`defer` puts a stand-in module under the name ``ConfigSpace`` whose ``ConfigurationSpace``
builds the real object on first call, and whose every other attribute imports the real package
and hands the attribute over (after that the real package is in ``sys.modules``, so any later
``import ConfigSpace`` gets it). Nothing changes for code that uses ConfigSpace; code that does
not, never pays for it. When the real package is already imported, nothing is done.
"""
from __future__ import annotations

import importlib
import importlib.util
import sys
import threading
import types
from typing import Any

_NAME = "ConfigSpace"
_LOCK = threading.Lock()


class _Deferred(types.ModuleType):
    """Stand-in for ConfigSpace until something other than the class name is asked for."""

    def __getattr__(self, name: str) -> Any:
        if name.startswith("__"):  # import machinery probes (__path__, __spec__...): not a use
            raise AttributeError(name)
        return getattr(real(), name)


def real() -> types.ModuleType:
    """The real ConfigSpace package (imported now if only the stand-in was there)."""
    with _LOCK:
        mod = sys.modules.get(_NAME)
        if mod is None or isinstance(mod, _Deferred):
            sys.modules.pop(_NAME, None)
            try:
                mod = importlib.import_module(_NAME)
            except BaseException:
                if isinstance(mod, _Deferred):
                    sys.modules[_NAME] = mod
                raise
        return mod


def _configuration_space(*args: Any, **kwargs: Any) -> Any:
    return real().ConfigurationSpace(*args, **kwargs)


def defer() -> None:
    """Install the stand-in unless ConfigSpace (or the stand-in) is already imported."""
    with _LOCK:
        if _NAME in sys.modules or "unified_planning.engines.engine" in sys.modules:
            return
        if importlib.util.find_spec(_NAME) is None:  # not installed: UP will say so itself
            return
        stand_in = _Deferred(_NAME, "deferred by pipflow.pddl.deferred_configspace")
        stand_in.ConfigurationSpace = _configuration_space
        sys.modules[_NAME] = stand_in

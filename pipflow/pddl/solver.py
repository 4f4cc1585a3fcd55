"""Solve a parsed problem with a UP OneshotPlanner named by the workflow.

Engines: ``pipflow-transport`` (the warehouse's own, registered through the entry-point group
``pipflow.planners``; see
:mod:`pipflow.warehouse.planner`: near-fewest moves on the paper's tasks, large instances in
seconds), ``enhsp`` (ENHSP gbfs + hadd, any numeric domain; about 1 s on the paper's tasks but it
grows fast), ``enhsp-opt`` / ``enhsp-any``, and any other engine installed in UP (``fast-downward``
for classical domains). Params go to the engine's constructor (``{"params": "-h hadd -s gbfs"}``
for ENHSP). Each outcome gets its own status and message:

    solved        a plan
    unsolvable    the engine proved no plan exists (the reason, when known)
    timeout       no answer within the time limit
    error         the engine failed, is unknown, or does not support the problem
"""
from __future__ import annotations

import hashlib
import json
import time
import warnings
from collections import OrderedDict
from dataclasses import dataclass, field
from enum import Enum
from importlib.metadata import entry_points
from typing import Any

from pipflow.errors import InputError, PlanningError
from pipflow.liberrors import SCIP, UNIFIED_PLANNING, library_errors
from pipflow.pddl.common import PLANNERS, environment
from pipflow.pddl.convert import plan_to_data
from pipflow.pddl.java import ensure_java
from pipflow.suggest import closest

DEFAULT_ENGINE = "pipflow-transport"
JAVA_ENGINES = ("enhsp",)
#: how many unsolved outcomes a process remembers (see :func:`remembered`)
MEMORY = 64
_unsolved: "OrderedDict[str, SolveResult]" = OrderedDict()


class Status(str, Enum):
    """The outcome of one planner call. A ``str`` so that run records, JSON outputs and
    comparisons with the plain words (``status == "solved"``) keep working."""

    SOLVED = "solved"
    UNSOLVABLE = "unsolvable"
    TIMEOUT = "timeout"
    ERROR = "error"

    def __str__(self) -> str:  # the word itself in messages and f-strings, not "Status.SOLVED"
        return self.value


#: outcomes that carry a plan
POSITIVE_OUTCOMES = frozenset({Status.SOLVED})


@dataclass
class SolveResult:
    status: Status
    plan: list[dict] | None
    message: str
    time: float
    engine: str = ""
    details: dict = field(default_factory=dict)

    def __post_init__(self) -> None:
        self.status = Status(self.status)  # a plain word is accepted and checked
        if (self.status in POSITIVE_OUTCOMES) != (self.plan is not None):
            raise ValueError(f"a {self.status} result must {'' if self.status in POSITIVE_OUTCOMES else 'not '}carry a plan")


def planner_names() -> list[str]:
    """The one-shot planners installed in UP (``enhsp``, ``pipflow-transport``, ...), without
    UP's meta-engines (``oversubscription[...]``) and non-planners (validators, compilers)."""
    factory = environment().factory
    names = []
    for name in factory.engines:
        if "[" in name:
            continue
        try:
            if factory.engine(name).is_oneshot_planner():
                names.append(name)
        except Exception as exc:
            if not UNIFIED_PLANNING.owns(exc):
                raise  # a bug in an engine of pipflow's own is shown, not hidden
            continue  # an installed engine that UP cannot even load or describe is not offered
    return names


def check_engine(engine: str) -> None:
    """Raise :class:`InputError` (exit 2) for a planner that is not installed, naming those that
    are: a misspelt planner must never be replaced silently by another one."""
    known = planner_names()
    if engine not in known:
        close = closest(str(engine), known, n=1)
        stale = "" if any(True for _ in entry_points(group=PLANNERS)) else (
            f" (none registered in the entry-point group {PLANNERS}: an install older than its pyproject.toml; "
            "reinstall pipflow, e.g. pip install -e .)")
        raise InputError(f"unknown planner {engine!r}" + (f" (did you mean {close[0]!r}?)" if close else "")
                         + f"; installed planners: {', '.join(known)}{stale}")


def problem_digest(domain_text: str, problem_text: str, engine: str, params: Any, timeout: Any) -> str:
    """The identity of one solver call: what it solves, with what, for how long."""
    material = json.dumps([domain_text, problem_text, engine, params, timeout], sort_keys=True, default=str)
    return hashlib.sha256(material.encode("utf-8")).hexdigest()


def remembered(digest: str) -> "SolveResult | None":
    """The outcome of an identical call that found no plan earlier in this process (time-out,
    error, unsolvable), or None. A refinement loop whose problem did not change does not pay the
    planner's time limit again: the answer would be the same."""
    return _unsolved.get(digest)


def remember(digest: str, result: "SolveResult") -> None:
    """Keep an unsolved outcome (solved ones are not kept: their time is measured every run)."""
    if result.status in POSITIVE_OUTCOMES:
        return
    _unsolved[digest] = result
    _unsolved.move_to_end(digest)
    while len(_unsolved) > MEMORY:
        _unsolved.popitem(last=False)


def _logs(result: Any, limit: int = 600) -> str:
    """The engine's log messages on one line, cut to ``limit`` characters (a planner may print
    pages; the message must stay readable)."""
    text = " ".join("; ".join(m.message.strip() for m in (result.log_messages or [])
                              if m.message and m.message.strip()).split())
    return text if len(text) <= limit else text[:limit] + " ..."


def solve_problem(problem: Any, engine: str = DEFAULT_ENGINE, params: dict | None = None,
                  timeout: float | None = 60.0) -> SolveResult:
    """Solve UP ``problem`` with ``engine``; never raises for an engine-side failure, i.e. an
    error of UP or of the engine it runs (an engine that is not installed is the user's:
    :class:`InputError`)."""
    from unified_planning.engines import PlanGenerationResultStatus as S
    from unified_planning.shortcuts import OneshotPlanner

    env = environment()
    started = time.monotonic()
    if engine not in env.factory.engines:
        check_engine(engine)
    if engine.startswith(JAVA_ENGINES):
        try:
            ensure_java()
        except PlanningError as exc:
            return SolveResult(Status.ERROR, None, str(exc), 0.0, engine)
    try:
        # an error of UP, of the engine it runs or of SCIP (which pipflow-transport uses) becomes
        # an "error" outcome; any other error in pipflow's own engine is a bug and keeps its traceback
        doing = f"running the planner {engine}"
        with library_errors(UNIFIED_PLANNING, PlanningError, doing), library_errors(SCIP, PlanningError, doing):
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")  # "we cannot establish whether X can solve this problem"
                with OneshotPlanner(name=engine, params=dict(params or {})) as planner:
                    result = planner.solve(problem, timeout=timeout)
    except PlanningError as exc:
        return SolveResult(Status.ERROR, None, str(exc), time.monotonic() - started, engine)
    elapsed = time.monotonic() - started
    logs = _logs(result)
    st = result.status
    if st in (S.SOLVED_SATISFICING, S.SOLVED_OPTIMALLY) and result.plan is not None:
        plan = plan_to_data(result.plan)
        return SolveResult(Status.SOLVED, plan, f"{engine} found a plan of {len(plan)} action(s) in {elapsed:.2f} s"
                           + (" (optimal)" if st == S.SOLVED_OPTIMALLY else ""), elapsed, engine)
    if st == S.UNSOLVABLE_PROVEN:
        return SolveResult(Status.UNSOLVABLE, None, f"{engine} proved that no plan reaches the goal"
                           + (f": {logs}" if logs else ""), elapsed, engine)
    if st == S.TIMEOUT:
        return SolveResult(Status.TIMEOUT, None, f"the planner {engine} timed out after {timeout:g} s without a plan",
                           elapsed, engine)
    if st == S.UNSOLVABLE_INCOMPLETELY:
        return SolveResult(Status.ERROR, None, f"{engine} gave up without a plan (it is incomplete, so a plan may "
                           f"still exist; try engine 'enhsp')" + (f": {logs}" if logs else ""), elapsed, engine)
    if st == S.UNSUPPORTED_PROBLEM:
        return SolveResult(Status.ERROR, None, f"{engine} does not support this problem" + (f": {logs}" if logs else ""),
                           elapsed, engine)
    return SolveResult(Status.ERROR, None, f"{engine} failed ({st.name})" + (f": {logs}" if logs else ""), elapsed, engine)

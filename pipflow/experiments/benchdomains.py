"""What ``pipflow bench`` needs to know about the domain of a task file, read from the task-domain
registry (:mod:`pipflow.taskdomains`).

A task file may name its domain (``domain: household``); without one it is of the default domain
(the format of benchmarks/README.md). The domain says how its task files load, which workflow runs
them by default, how one run is scored against its task, how the goal and rules a run resolved
are compared with the task's gold (understanding, issue 12) and, where its table is grouped
differently, how the markdown table looks (:class:`pipflow.taskdomain.TaskDomain`, "the bench").
The bench itself knows no domain.
"""
from __future__ import annotations

from pathlib import Path

from pipflow.taskdomain import TaskDomain
from pipflow.taskdomains import declared_domain
from pipflow.taskdomains import domain_named as _domain_named

__all__ = ["domain_named", "domain_of"]


def domain_named(name: str | None) -> TaskDomain:
    """The installed task domain ``name`` (None: the default); unknown names are the user's error,
    naming the known domains."""
    return _domain_named(name)


def domain_of(tasks_file: str | Path) -> TaskDomain:
    """The domain a task file declares (read cheaply; validation comes with loading)."""
    return declared_domain(tasks_file, "task file")

"""The offline reading of a command: the world's task domain reads it with no model (its parser
and resolver, or its translator) and writes the problem.

Why a module of its own: the generator runs it for model ``offline``, and the LLM loop's
agreement check compares a model's goal with it; both import it from here, so neither imports
the other.
"""
from __future__ import annotations

from typing import Any, Callable

from pipflow.taskdomain import TaskDomain
from pipflow.taskdomains import task_domain


def offline(command: str, world: dict, domain_text: str = "",
            save: Callable[[str, Any], Any] | None = None, domain: TaskDomain | None = None) -> dict[str, Any]:
    """Model ``offline``: the command read by the world's task domain (``domain``, when the caller
    has it already; :meth:`pipflow.taskdomain.TaskDomain.read_offline`), its goal written as PDDL.
    ``order`` is the typed meaning where the domain has one, ``explanation`` the resolver's
    arithmetic in plain words, for the run summary to echo before robots move."""
    return (domain or task_domain(world)).read_offline(command, world, domain_text, save)

"""The offline reading of a command: the world's task domain reads it with no model (its parser
and resolver, or its translator) and writes the problem.

Why a module of its own: the generator runs it for model ``offline``, and the LLM loop's
agreement check compares a model's goal with it; both import it from here, so neither imports
the other.
"""
from __future__ import annotations

from typing import Any, Callable

from pipflow.errors import InputError, TranslationError
from pipflow.taskdomain import TaskDomain
from pipflow.taskdomains import task_domain


def offline(command: str, world: dict, domain_text: str = "",
            save: Callable[[str, Any], Any] | None = None, reading: int | None = None,
            domain: TaskDomain | None = None) -> dict[str, Any]:
    """Model ``offline``: the command read by the world's task domain (``domain``, when the caller
    has it already; :meth:`pipflow.taskdomain.TaskDomain.read_offline`), its goal written as PDDL.
    ``order`` is the typed meaning where the domain has one, ``explanation`` the resolver's
    arithmetic in plain words, for the run summary to echo before robots move.

    ``reading`` (1-based): where the reader refuses the command but offers candidate readings
    (``TranslationError.candidates``, issue 23), the one the user chose
    (:meth:`pipflow.taskdomain.TaskDomain.read_candidate`). A command the reader understands
    needs no choice and ignores it; a choice that is not one of the offered readings is a user
    error naming them."""
    domain = domain or task_domain(world)
    try:
        return domain.read_offline(command, world, domain_text, save)
    except TranslationError as exc:
        if reading is None:
            raise
        offered = list(exc.candidates)
        if not 1 <= reading <= len(offered):
            listed = "; ".join(f"({k}) {c.get('reading')}" for k, c in enumerate(offered, 1)) or "none"
            raise InputError(f"reading {reading}: the command offers {len(offered)} candidate reading(s): "
                             f"{listed}") from None
        out = domain.read_candidate(offered[reading - 1], world, domain_text, save)
        out["explanation"] = [f"reading {reading} of {len(offered)}, chosen by the user (the command "
                              f"was not understood as said: {exc})"] + list(out.get("explanation") or [])
        return out

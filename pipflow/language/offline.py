"""The offline reading of a command: parser and resolver (or the household translator), and the
problem writer, with no model.

Why a module of its own: the generator runs it for model ``offline``, and the LLM loop's
agreement check compares a model's goal with it; both import it from here, so neither imports
the other.
"""
from __future__ import annotations

from typing import Any, Callable

NO_USAGE: dict[str, Any] = {"calls": 0, "cached": False, "prompt_tokens": 0, "completion_tokens": 0,
                            "total_tokens": 0, "latency_s": 0.0, "cost_usd": 0.0}
def domain_of(world: Any) -> str:
    """``household`` for a household world (``domain: household``), else ``warehouse``."""
    return "household" if isinstance(world, dict) and world.get("domain") == "household" else "warehouse"


def domain_name(domain_text: str, default: str) -> str:
    """The name in ``(define (domain NAME)`` of a PDDL domain text, or ``default``."""
    import re

    m = re.search(r"\(\s*domain\s+([^\s()]+)", domain_text or "", flags=re.IGNORECASE)
    return m.group(1) if m else default


def write_problem(world: dict, goal: dict) -> str:
    """The problem writer of :mod:`pipflow.pddl.writer` (imported late, like every pddl helper)."""
    from pipflow.pddl.writer import write_problem as writer

    return writer(world, goal)


def write_household_problem(world: dict, goal: dict, domain: str = "household") -> str:
    """The household problem writer (:mod:`pipflow.household.problem`): the world's objects and
    initial state, the goal's ``in``/``state`` conditions."""
    from pipflow.household.problem import write_problem as writer

    return writer(world, goal, domain=domain)


def offline(command: str, world: dict, domain_text: str = "",
            save: Callable[[str, Any], Any] | None = None) -> dict[str, Any]:
    """Model ``offline``: the command parsed into an order and resolved against the world
    (:mod:`pipflow.language.understand`), its goal written as PDDL (the household translator and
    writer for a household world). ``order`` is the typed meaning, ``explanation`` the resolver's
    arithmetic in plain words, for the run summary to echo before robots move."""
    if domain_of(world) == "household":
        return household_offline(command, world, domain_text, save)
    from pipflow.language.understand import understand

    result = understand(command, world)
    if save is not None:
        save("order.json", result["order"])
    return {"problem": write_problem(world, result["goal"]), "goal": result["goal"],
            "constraints": list(result["constraints"]), "order": result["order"],
            "explanation": list(result["explanation"]), "messages": [], "response": "",
            "usage": dict(NO_USAGE), "errors": []}


def household_offline(command: str, world: dict, domain_text: str = "",
                      save: Callable[[str, Any], Any] | None = None) -> dict[str, Any]:
    """The household translator (:mod:`pipflow.household.translator`) and writer: ``goal`` keeps
    the command's conditions (counts included) for judging, ``concrete`` resolves counts to
    objects, which is what the problem asks for. Untranslatable commands raise TranslationError,
    impossible ones Refusal (the same as step ``household.problem``)."""
    from pipflow.household.translator import translate

    result = translate(command, world)
    problem = write_household_problem(world, result["concrete"], domain_name(domain_text, "household"))
    if save is not None:
        save("goal.json", result)
        save("problem.pddl", problem)
    return {"problem": problem, "goal": result["goal"], "concrete": result["concrete"], "constraints": [],
            "messages": [], "response": "", "usage": dict(NO_USAGE), "errors": []}

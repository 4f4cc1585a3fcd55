"""Understanding a command offline: parse it into an order, resolve the order against the world.

The one entry point of the offline path (model ``offline``); the LLM's grounded mode reaches the
same resolver with an order of its own.
"""
from __future__ import annotations

from typing import Any

from pipflow.warehouse.language.order import validate_order
from pipflow.warehouse.language.parser import parse
from pipflow.warehouse.language.resolver import resolve


def understand(command: str, world: dict, check: bool = True) -> dict[str, Any]:
    """``{"order", "goal", "constraints", "explanation"}`` of a command in a world.

    Raises TranslationError (words it cannot place), Refusal (impossible requests, with why) and
    InputError (a command too long to be one).
    """
    order = parse(command, world)
    validate_order(order)
    resolved = resolve(order, world, check)
    return {"order": order, "goal": resolved.goal, "constraints": resolved.constraints,
            "explanation": resolved.explanation}


def translate(command: str, world: dict, check: bool = True) -> dict[str, Any]:
    """The goal and robot rules of a command (the shape task files use for their gold)."""
    got = understand(command, world, check)
    return {"goal": got["goal"], "constraints": got["constraints"]}

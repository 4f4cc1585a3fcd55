"""Understanding a command offline: parse it into an order, resolve the order against the world.

The one entry point of the offline path (model ``offline``); the LLM's grounded mode reaches the
same resolver with an order of its own.
"""
from __future__ import annotations

from typing import Any

from pipflow.language.asides import said
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
    explanation = (([f"said without stops, read as: {' / '.join(repr(p) for p in order['read_as'])}"]
                    if order.get("read_as") else []) + list(order.get("corrected") or []) + resolved.explanation
                   + ([said(order["set_aside"])] if order.get("set_aside") else []))
    return {"order": order, "goal": resolved.goal, "constraints": resolved.constraints,
            "explanation": explanation}


def translate(command: str, world: dict, check: bool = True) -> dict[str, Any]:
    """The goal and robot rules of a command (the shape task files use for their gold)."""
    got = understand(command, world, check)
    return {"goal": got["goal"], "constraints": got["constraints"]}

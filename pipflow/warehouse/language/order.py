"""Orders: the typed meaning of a command, independent of PDDL (``schemas/order.schema.json``).

An order is plain JSON data: ``{"command", "statements": [...], "rules": [...]}``. A statement
says what should happen to counts (``set``, ``change``, ``bound``, ``transfer``, ``swap``,
``empty``, ``fill``, ``keep``, ``distribute``, ``nothing_else``) with selectors for places and
items (``{"names": [...]}`` or ``{"all": true, "except": [...]}``) and an amount; a rule says
which robots may (``only``) or may not (``never``) do which moves, with a robot selector (names,
kind, tag, skill bound or the strongest/weakest). Each keeps the words it came from. Parser and
LLM produce orders; :mod:`pipflow.warehouse.language.resolver` turns them into goals.
"""
from __future__ import annotations

import functools
import json
from typing import Any

import jsonschema

from pipflow.errors import TranslationError
from pipflow.resources import data_file


@functools.lru_cache(maxsize=1)
def order_schema() -> dict[str, Any]:
    return json.loads(data_file("schemas/order.schema.json").read_text(encoding="utf-8"))


def validate_order(order: Any) -> None:
    """Raise TranslationError naming the first place where ``order`` breaks the schema."""
    validator = jsonschema.Draft202012Validator(order_schema())
    errors = sorted(validator.iter_errors(order), key=lambda e: list(e.absolute_path))
    if errors:
        e = errors[0]
        where = "/".join(str(p) for p in e.absolute_path) or "(top)"
        raise TranslationError(f"the order is not valid at {where}: {e.message}")

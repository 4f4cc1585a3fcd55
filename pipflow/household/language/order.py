"""Household orders as data: the JSON Schema check (``schemas/household_order.schema.json``).

An order is what the parser (or, later, a language model) says a command means; the resolver
trusts only orders that pass this check, so a malformed order is an error that names the place
in the order and the rule it breaks, never a half-read goal.
"""
from __future__ import annotations

import functools
import json

from jsonschema import Draft202012Validator

from pipflow.errors import TranslationError
from pipflow.resources import data_file

SCHEMA = "schemas/household_order.schema.json"


@functools.lru_cache(maxsize=1)
def _validator() -> Draft202012Validator:
    return Draft202012Validator(json.loads(data_file(SCHEMA).read_text(encoding="utf-8")))


def order_problems(order: object) -> list[str]:
    """Every way ``order`` breaks the schema, as ``path: message`` lines (empty: valid)."""
    out = []
    for err in sorted(_validator().iter_errors(order), key=lambda e: list(map(str, e.absolute_path))):
        where = "/".join(str(p) for p in err.absolute_path) or "(the order)"
        out.append(f"{where}: {err.message}")
    return out


def check_order(order: object) -> dict:
    """The order if it is valid, else TranslationError listing the problems."""
    problems = order_problems(order)
    if problems:
        raise TranslationError("invalid household order: " + "; ".join(problems[:5]))
    assert isinstance(order, dict)
    return order

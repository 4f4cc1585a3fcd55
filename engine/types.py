"""Declared value types of inputs and outputs, and how values are checked and coerced."""
from __future__ import annotations

import math
from typing import Any

import yaml

from pipflow.yamlsource import safe_load

from .expr import has_expression

_CHECKS = {
    "string": lambda v: isinstance(v, str),
    "path": lambda v: isinstance(v, str),
    "integer": lambda v: isinstance(v, int) and not isinstance(v, bool),
    "number": lambda v: isinstance(v, (int, float)) and not isinstance(v, bool),
    "boolean": lambda v: isinstance(v, bool),
    "object": lambda v: isinstance(v, dict),
    "array": lambda v: isinstance(v, list),
    "any": lambda v: True,
}


def type_matches(value: Any, type_name: str, allow_expr: bool = False) -> bool:
    """Whether a value fits a declared type. ``None`` fits every type (a skipped step's
    outputs are ``None``); with ``allow_expr`` a string holding ``${...}`` fits too, since
    its type is known only when it is resolved."""
    if value is None or (allow_expr and has_expression(value)):
        return True
    return _CHECKS.get(type_name, _CHECKS["any"])(value)


def coerce_text(text: str, type_name: str) -> Any:
    """Turn a command-line value (``-i key=value``) into the declared type.

    Strings and paths stay as written; other types are read as YAML (``3``, ``true``,
    ``[a, b]``, ``{x: 1}``) and then checked."""
    if type_name in ("string", "path"):
        return text
    try:
        value = safe_load(text) if text.strip() else None
    except yaml.YAMLError as err:
        raise ValueError(f"{text[:80]!r} is not a YAML value ({getattr(err, 'problem', None) or err})") from None
    if type_name == "number" and isinstance(value, int) and not isinstance(value, bool):
        try:
            return float(value)
        except OverflowError:
            raise ValueError(f"{text[:80]!r} is too large a number") from None
    if type_name == "number" and isinstance(value, float) and not math.isfinite(value):
        raise ValueError(f"{text!r} is not a finite number")
    if not type_matches(value, type_name):
        raise ValueError(f"{text!r} is not {'an' if type_name[0] in 'aeiou' else 'a'} {type_name}")
    return value

"""``${...}`` references and conditions, evaluated by jinja2's sandbox (never Python eval).

A string that is exactly one ``${expr}`` evaluates to the expression's value with its type
(a list stays a list); a string with text around one or more ``${...}`` is interpolated.
Inside the braces is a jinja2 expression over the run's namespace::

    ${inputs.command}              an input
    ${solve.plan}                  an output of step `solve`
    ${verify.ok and not debug.ok}  a condition
    ${env.PIPFLOW_MODEL | default('offline')}   an environment variable with a default
    ${previous.verify.messages}    in a loop: the previous iteration's output (None at first)

The dependencies of a step are the step ids its expressions name, read off jinja2's AST.
"""
from __future__ import annotations

import functools
import json
import re
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

from jinja2 import StrictUndefined, Undefined, nodes
from jinja2.exceptions import TemplateError, TemplateSyntaxError
from jinja2.sandbox import SandboxedEnvironment

_OPEN = "${"
_WHOLE = re.compile(r"^\s*\$\{(.*)\}\s*$", re.S)


class ExpressionError(Exception):
    """An expression cannot be parsed or evaluated; the message says why."""


class _Env(SandboxedEnvironment):
    """Sandbox in which ``a.b`` on a mapping looks up the key first, so an output named
    ``items`` or ``keys`` is the output and not the dict method."""

    def getattr(self, obj: Any, attribute: str) -> Any:
        if isinstance(obj, Mapping):
            if attribute in obj:
                return obj[attribute]
            return self.undefined(obj=obj, name=attribute)
        return super().getattr(obj, attribute)


_ENV = _Env(undefined=StrictUndefined)


@dataclass(frozen=True)
class Reference:
    """A name an expression reads, with the first attribute after it (``step.output``)."""

    name: str
    attr: str | None


def split_template(text: str) -> list[tuple[bool, str]]:
    """Split a string into literal parts (False, text) and expressions (True, source).

    Braces inside an expression may nest (dict literals) and may appear in quotes."""
    parts: list[tuple[bool, str]] = []
    pos = 0
    while True:
        start = text.find(_OPEN, pos)
        if start < 0:
            if pos < len(text):
                parts.append((False, text[pos:]))
            return parts
        if start > pos:
            parts.append((False, text[pos:start]))
        end = _matching_brace(text, start + 2)
        if end < 0:
            raise ExpressionError(f"unclosed '${{' in {text!r}")
        parts.append((True, text[start + 2:end].strip()))
        pos = end + 1


def _matching_brace(text: str, i: int) -> int:
    depth, quote = 1, ""
    while i < len(text):
        ch = text[i]
        if quote:
            if ch == quote:
                quote = ""
        elif ch in "'\"":
            quote = ch
        elif ch == "{":
            depth += 1
        elif ch == "}":
            depth -= 1
            if depth == 0:
                return i
        i += 1
    return -1


def has_expression(value: Any) -> bool:
    return isinstance(value, str) and _OPEN in value


@functools.lru_cache(maxsize=4096)
def _compiled(source: str):
    try:
        return _ENV.compile_expression(source, undefined_to_none=False)
    except TemplateSyntaxError as err:
        raise ExpressionError(f"invalid expression ${{{source}}}: {err.message}") from None


@functools.lru_cache(maxsize=4096)
def references(source: str) -> tuple[Reference, ...]:
    """The names an expression reads (with their first attribute), from jinja2's AST."""
    try:
        tree = _ENV.parse("{{ (" + source + ") }}")
    except TemplateSyntaxError as err:
        raise ExpressionError(f"invalid expression ${{{source}}}: {err.message}") from None
    found: list[Reference] = []
    seen_names: set[int] = set()
    for node in tree.find_all((nodes.Getattr, nodes.Getitem)):
        if isinstance(node.node, nodes.Name):
            if isinstance(node, nodes.Getattr):
                attr = node.attr
            elif isinstance(node.arg, nodes.Const) and isinstance(node.arg.value, str):
                attr = node.arg.value
            else:
                attr = None
            found.append(Reference(node.node.name, attr))
            seen_names.add(id(node.node))
    for node in tree.find_all(nodes.Name):
        if id(node) not in seen_names and node.ctx == "load":
            found.append(Reference(node.name, None))
    return tuple(dict.fromkeys(found))


def template_references(value: Any) -> list[Reference]:
    """Every reference in a value: strings, and strings nested in lists and dicts."""
    out: list[Reference] = []
    if isinstance(value, str):
        if _OPEN in value:
            for is_expr, part in split_template(value):
                if is_expr:
                    out.extend(references(part))
    elif isinstance(value, dict):
        for v in value.values():
            out.extend(template_references(v))
    elif isinstance(value, list):
        for v in value:
            out.extend(template_references(v))
    return out


_PLAIN = re.compile(r"^[A-Za-z_][A-Za-z0-9_]*(?:\.[A-Za-z_][A-Za-z0-9_]*)*$")
_MISSING = object()
_CONSTANTS = {"true", "false", "none", "True", "False", "None"}  # jinja2 literals, not names


def _plain_lookup(source: str, namespace: Mapping[str, Any]) -> Any:
    """``a.b.c`` through mappings only (the common case), without compiling the expression;
    ``_MISSING`` when jinja2 must decide (a missing key, a non-mapping), so errors stay the same."""
    if not _PLAIN.match(source):
        return _MISSING
    name, *attrs = source.split(".")
    if name in _CONSTANTS:
        return _MISSING
    value = namespace.get(name, _MISSING)
    for attr in attrs:
        if value is _MISSING or not isinstance(value, Mapping):
            return _MISSING
        value = value.get(attr, _MISSING)
    return value


def evaluate_expression(source: str, namespace: Mapping[str, Any]) -> Any:
    """Evaluate one expression; an undefined result names what was missing."""
    value = _plain_lookup(source, namespace)
    if value is not _MISSING:
        return value
    compiled = _compiled(source)
    try:
        result = compiled(**namespace)
    except TemplateError as err:
        raise ExpressionError(f"${{{source}}}: {err.message or err}") from None
    except Exception as err:  # a filter or operator failed on the values given
        raise ExpressionError(f"${{{source}}}: {type(err).__name__}: {err}") from None
    if isinstance(result, Undefined):
        try:
            str(result)
        except TemplateError as err:
            raise ExpressionError(f"${{{source}}}: {err.message}") from None
        raise ExpressionError(f"${{{source}}} is undefined")
    return result


def resolve(value: Any, namespace: Mapping[str, Any]) -> Any:
    """Resolve every ``${...}`` in a value (recursively through lists and dicts)."""
    if isinstance(value, str):
        if _OPEN not in value:
            return value
        whole = _WHOLE.match(value)
        if whole:
            parts = split_template(value)
            if len(parts) == 1 and parts[0][0]:
                return evaluate_expression(parts[0][1], namespace)
        pieces = []
        for is_expr, part in split_template(value):
            if not is_expr:
                pieces.append(part)
                continue
            result = evaluate_expression(part, namespace)
            pieces.append(result if isinstance(result, str) else json.dumps(result, default=str))
        return "".join(pieces)
    if isinstance(value, dict):
        return {k: resolve(v, namespace) for k, v in value.items()}
    if isinstance(value, list):
        return [resolve(v, namespace) for v in value]
    return value


def truthy(value: Any, namespace: Mapping[str, Any]) -> bool:
    """A condition (``when:``/``until:``): a bool, or a string with ``${...}``."""
    result = resolve(value, namespace)
    if isinstance(result, str):
        return result.strip().lower() not in ("", "false", "0", "no", "none", "null")
    return bool(result)

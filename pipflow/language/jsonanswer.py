"""A model's JSON answer read as data: the one object it holds, or a located reason why not.

Why one reader: the ablations' model steps (a team plan without a PDDL domain, an allocation by
a model) ask for a JSON object and must tell a model, and a user reading the record, exactly
where an answer went wrong. Nothing in the answer is evaluated: ``json`` reads it (Python code,
``__import__(...)`` or anything else that is not JSON is a parse error, quoted back).
"""
from __future__ import annotations

import json
import re
from typing import Any

from pipflow.language.parsing import ParseIssue

_FENCE = re.compile(r"```[ \t]*([A-Za-z0-9_-]*)[^\n]*\n(.*?)(?:```|\Z)", re.DOTALL)
#: an answer's JSON may nest no deeper than this (a real answer nests 4 or 5 levels)
MAX_DEPTH = 32


def json_object(text: str, what: str = "answer") -> dict[str, Any]:
    """The JSON object of ``text``: a fenced ```json block first, else an untagged fenced block
    that starts like JSON, else the text from its first ``{``. Raises :class:`ParseIssue` with
    the line and column (counted in the block) when it is not valid JSON, or not an object."""
    fences = [(lang.lower(), body) for lang, body in _FENCE.findall(text or "")]
    blocks = [("the ```json block", b) for lang, b in fences if lang == "json"]
    blocks += [("the code block", b) for lang, b in fences if lang == "" and b.lstrip()[:1] in "[{"]
    start = (text or "").find("{")
    if not blocks and start >= 0:
        blocks.append((f"the {what}", text[start:]))
    if not blocks:
        shown = (text or "").strip().replace("\n", " ")[:80]
        raise ParseIssue(f"the {what} holds no JSON object (it begins {shown!r}); answer with one JSON object "
                         "in a ```json block")
    where, body = blocks[0]
    body = body.strip()
    if _depth(body) > MAX_DEPTH:
        raise ParseIssue(f"{where} nests deeper than {MAX_DEPTH} levels; no answer needs that")
    try:
        data, end = json.JSONDecoder().raw_decode(body)
    except json.JSONDecodeError as exc:
        raise ParseIssue(f"{where} is not valid JSON: {exc.msg} at line {exc.lineno}, column {exc.colno} "
                         f"(near {body[max(0, exc.pos - 20):exc.pos + 20]!r})") from None
    if not isinstance(data, dict):
        raise ParseIssue(f"{where} must be one JSON object {{...}}, not {type(data).__name__}")
    return data


def _depth(text: str) -> int:
    """The deepest bracket nesting of ``text`` outside strings (a cheap bound before parsing)."""
    depth = deepest = 0
    in_string = escaped = False
    for ch in text:
        if in_string:
            if escaped:
                escaped = False
            elif ch == "\\":
                escaped = True
            elif ch == '"':
                in_string = False
        elif ch == '"':
            in_string = True
        elif ch in "[{":
            depth += 1
            deepest = max(deepest, depth)
        elif ch in "]}":
            depth -= 1
    return deepest

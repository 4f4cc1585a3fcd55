"""Read a model's answer as data: the PDDL problem and the robot-use constraints.

Nothing here evaluates model output. The problem is cut out of the text by counting parentheses
from ``(define (problem``, so code fences and prose around it do not matter; the constraints are
JSON (``json.loads``, never ``eval``) checked against the task-file format. Every failure is a
:class:`ParseIssue` message precise enough to send back to the model in the next round.
"""
from __future__ import annotations

import json
import math
import re
from typing import Any

from pipflow.taskdomain import TaskDomain
from pipflow.taskdomains import task_domain

_PROBLEM_START = re.compile(r"\(\s*define\s*\(\s*problem\b", re.IGNORECASE)
_FENCE = re.compile(r"```[ \t]*([A-Za-z0-9_-]*)[^\n]*\n(.*?)(?:```|\Z)", re.DOTALL)
RULE_KEYS = ("only", "never")


class ParseIssue(ValueError):
    """The answer has no usable problem or constraints; the message says what and where."""


#: the largest number a model's JSON may state (counts, shares, skill levels), as for world files
MAX_JSON_NUMBER = 10**9
#: PDDL problems tried, last first, when an answer has several ``(define (problem``: each try
#: reads to the end of the text, so an answer of 20,000 of them would cost 20,000 readings
MAX_PROBLEM_DRAFTS = 8


def _number_issue(text: str) -> ParseIssue:
    shown = text if len(text) <= 24 else text[:20] + "..."
    return ParseIssue(f"the JSON states the number {shown}; no count, share or skill level here is larger "
                      f"than {MAX_JSON_NUMBER:,}: write the number the command says")


def _json_int(text: str) -> int:
    if len(text.lstrip("-")) > 10:  # before int(): a 100,000-digit literal is refused, not converted
        raise _number_issue(text)
    value = int(text)
    if abs(value) > MAX_JSON_NUMBER:
        raise _number_issue(text)
    return value


def _json_float(text: str) -> float:
    value = float(text)
    if not math.isfinite(value) or abs(value) > MAX_JSON_NUMBER:
        raise _number_issue(text)
    return value


def _json_constant(name: str) -> Any:
    raise ParseIssue(f"the JSON states {name}, which is no number JSON allows: write the number itself")


#: what reads every JSON a model writes: bounded numbers, no NaN or Infinity
ANSWER_DECODER = json.JSONDecoder(parse_int=_json_int, parse_float=_json_float, parse_constant=_json_constant)


def decode_answer_json(text: str, start: int = 0) -> tuple[Any, int]:
    """``(value, end)`` of the JSON value at ``text[start:]`` as a model wrote it (as
    ``JSONDecoder.raw_decode``): a :class:`ParseIssue` for numbers beyond
    :data:`MAX_JSON_NUMBER`, ``NaN``/``Infinity``, nesting deeper than Python's decoder goes, and
    strings with lone surrogates (``"\\ud800"``: no valid text, and no file or terminal can
    show it); ``json.JSONDecodeError`` for JSON that is not JSON."""
    try:
        value, end = ANSWER_DECODER.raw_decode(text, start)
    except RecursionError:
        raise ParseIssue("the JSON is nested deeper than any order or rule needs: write it flat, "
                         "one statement and one rule per item") from None
    bad = _lone_surrogate(value)
    if bad is not None:
        raise ParseIssue(f"the JSON has a string with an invalid character (a lone surrogate, "
                         f"{bad!r} as escaped): write names as plain text, as the world spells them")
    return value, end


def _lone_surrogate(value: Any) -> str | None:
    """A string of ``value`` (keys too) holding a lone surrogate, escaped for showing; else None."""
    stack = [value]
    while stack:
        v = stack.pop()
        if isinstance(v, str):
            if any("\ud800" <= ch <= "\udfff" for ch in v):
                return v.encode("utf-8", "backslashreplace").decode("ascii", "backslashreplace")
        elif isinstance(v, dict):
            stack.extend(v.keys())
            stack.extend(v.values())
        elif isinstance(v, list):
            stack.extend(v)
    return None


def plain_text(text: str) -> tuple[str, int]:
    """``text`` with every lone surrogate (no valid character: a model's ``"\\ud800"`` decoded by
    its client) replaced by U+FFFD, and how many there were. Such a character cannot be written
    to a UTF-8 file or terminal: kept, it ended the step with a UnicodeEncodeError."""
    bad = sum(1 for ch in text if "\ud800" <= ch <= "\udfff")
    if not bad:
        return text, 0
    return "".join("\ufffd" if "\ud800" <= ch <= "\udfff" else ch for ch in text), bad


def _line_of(text: str, index: int) -> int:
    return text.count("\n", 0, index) + 1


def _balanced_end(text: str, start: int) -> int | None:
    """Index just past the parenthesis that closes the one at ``start`` (``;`` comments skipped),
    or None if the text ends first."""
    depth = 0
    i = start
    while i < len(text):
        c = text[i]
        if c == ";":
            nl = text.find("\n", i)
            i = len(text) if nl < 0 else nl
            continue
        if c == "(":
            depth += 1
        elif c == ")":
            depth -= 1
            if depth == 0:
                return i + 1
        elif c == "`" and text.startswith("```", i):
            return None  # a fence closed before the problem did
        i += 1
    return None


def extract_problem(text: str) -> str:
    """The last complete ``(define (problem ...))`` in ``text``.

    The last one, because a model that drafts and then corrects itself puts the answer last."""
    starts = [m.start() for m in _PROBLEM_START.finditer(text)]
    if not starts:
        if re.search(r"\(\s*define\b", text, re.IGNORECASE):
            raise ParseIssue("the answer has a `(define ...` but no `(define (problem NAME) ...)`: "
                             "write a PDDL problem, not a domain")
        raise ParseIssue("the answer contains no PDDL problem: expected `(define (problem NAME) "
                         "(:domain ...) (:objects ...) (:init ...) (:goal ...))`")
    for start in list(reversed(starts))[:MAX_PROBLEM_DRAFTS]:
        end = _balanced_end(text, start)
        if end is not None:
            return text[start:end].strip()
    start = starts[-1]
    depth = _depth_at_end(text, start)
    raise ParseIssue(f"the PDDL problem starting on line {_line_of(text, start)} of the answer is "
                     f"cut off: {depth} parenthes{'is' if depth == 1 else 'es'} never closed "
                     "(answer too long for max_tokens, or a missing `)`)")


def _depth_at_end(text: str, start: int) -> int:
    depth = 0
    for line in text[start:].split("```")[0].splitlines():
        code = line.split(";", 1)[0]
        depth += code.count("(") - code.count(")")
    return max(depth, 1)


def _json_candidates(text: str) -> list[str]:
    """Fenced ``json`` blocks first (the format the prompts ask for), then any untagged fenced
    block that looks like JSON, then a bare ``{"constraints": ...}`` object in prose."""
    fences = [(lang.lower(), body.strip()) for lang, body in _FENCE.findall(text)]
    found = [b for lang, b in fences if lang == "json"]
    found += [b for lang, b in fences if lang == "" and b[:1] in "[{"]
    m = re.search(r"\{\s*\"constraints\"\s*:", text)
    if m:
        found.append(text[m.start():])
    return found


def extract_constraints(text: str, fields: tuple[str, ...] | None = None) -> list[dict[str, Any]]:
    """The robot-use rules stated in the answer, as ``[{"only"|"never": [...], ...}]``.

    No JSON at all means the model stated no rule: an empty list. JSON that is there but wrong is
    a :class:`ParseIssue`, because silently dropping a rule would let a forbidden robot work."""
    errors = []
    for candidate in _json_candidates(text):
        try:
            data, _ = decode_answer_json(candidate)
        except json.JSONDecodeError as exc:
            errors.append(f"the JSON block is not valid JSON ({exc.msg} at line {exc.lineno}, "
                          f"column {exc.colno})")
            continue
        if isinstance(data, dict) and "constraints" in data:
            data = data["constraints"]
        elif isinstance(data, dict) and any(k in data for k in RULE_KEYS):
            data = [data]
        if isinstance(data, list):
            return validate_constraints(data, fields=fields)
        errors.append('the JSON block must be {"constraints": [...]} or a list of rules')
    if errors:
        raise ParseIssue(errors[0])
    return []


def validate_constraints(rules: list[Any], world: dict | None = None,
                         fields: tuple[str, ...] | None = None, domain: TaskDomain | None = None) -> list[dict[str, Any]]:
    """Check each rule's shape (and, given a world, its names); return them normalized.
    ``fields``: the keys a rule may narrow by (None: the world's task domain's
    :attr:`~pipflow.taskdomain.TaskDomain.rule_fields`; without a world, the default domain's);
    ``domain``: the world's task domain, when the caller has it already."""
    if domain is None:
        domain = task_domain(world)
    if fields is None:
        fields = domain.rule_fields
    out = []
    for n, rule in enumerate(rules, 1):
        where = f"constraint {n}"
        if not isinstance(rule, dict):
            raise ParseIssue(f"{where} must be an object, got {json.dumps(rule)}")
        kinds = [k for k in RULE_KEYS if k in rule]
        if len(kinds) != 1:
            raise ParseIssue(f"{where} must have exactly one of \"only\" or \"never\": {json.dumps(rule)}")
        unknown = sorted(set(rule) - set(RULE_KEYS) - set(fields))
        if unknown:
            raise ParseIssue(f"{where} has unknown keys {unknown}; allowed: only, never, "
                             f"{', '.join(fields)}")
        robots = rule[kinds[0]]
        robots = [robots] if isinstance(robots, str) else robots
        if not isinstance(robots, list) or not robots or not all(isinstance(r, str) for r in robots):
            raise ParseIssue(f"{where}: \"{kinds[0]}\" must be a non-empty list of robot names")
        clean: dict[str, Any] = {kinds[0]: list(robots)}
        for key in fields:
            if rule.get(key) is not None:
                if not isinstance(rule[key], str):
                    raise ParseIssue(f"{where}: \"{key}\" must be a name, got {json.dumps(rule[key])}")
                clean[key] = rule[key]
        if world is not None:
            _check_names(where, clean, world, domain)
        out.append(clean)
    return out


def _check_names(where: str, rule: dict[str, Any], world: dict, domain: TaskDomain) -> None:
    kind = "only" if "only" in rule else "never"
    names = domain.rule_names(world)  # field -> (its names in this world, what they are)
    pools = {kind: world.get("robots", {}), **{key: pool for key, (pool, _) in names.items()}}
    what = {kind: "robot", **{key: label for key, (_, label) in names.items()}}
    for key, pool in pools.items():
        values = rule.get(key)
        for v in ([values] if isinstance(values, str) else values or []):
            if v not in pool:
                raise ParseIssue(f"{where}: {v!r} is not a {what[key]} "
                                 f"of this world; known: {', '.join(sorted(pool))}")

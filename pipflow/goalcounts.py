"""Goal count values: an exact count or a bound on the final count of one item at one place.

A goal is ``{PLACE: {ITEM: value}}`` where ``value`` is an int (the final count, exactly) or a
bound mapping ``{at_least: n}``, ``{at_most: m}`` or ``{at_least: n, at_most: m}`` ("take shelf3
up to ten product1" leaves the planner free below ten). Every consumer of goals (problem writer,
goal reader, verifier, simulation, scoring, task loader) reads values through this module so that
the meaning of a bound is decided in one place: a bound holds when the final count lies within it,
both ends included; exact ints stay ints everywhere (a compatible extension of the task format).
"""
from __future__ import annotations

from typing import Any

BOUND_KEYS = ("at_least", "at_most")


def is_bound(value: Any) -> bool:
    """True for a bound mapping (whatever its content; :func:`value_problems` checks that)."""
    return isinstance(value, dict)


def _whole(v: Any) -> bool:
    return isinstance(v, int) and not isinstance(v, bool)


def value_problems(value: Any) -> list[str]:
    """What is wrong with one goal value, in words (empty when it is a valid count or bound).

    Checked here rather than only by the JSON Schema because goals also come from PDDL problems
    and from the language steps, which no schema sees."""
    if _whole(value):
        return [] if value >= 0 else [f"count {value} is negative; counts are whole numbers >= 0"]
    if not is_bound(value):
        return [f"{value!r} is neither a whole number nor a bound {{at_least: n, at_most: m}}"]
    out = []
    unknown = [k for k in value if k not in BOUND_KEYS]
    if unknown:
        out.append(f"unknown bound key(s) {', '.join(map(repr, unknown))}; a bound has at_least and/or at_most")
    if not any(k in value for k in BOUND_KEYS):
        out.append("a bound needs at_least, at_most or both")
    for k in BOUND_KEYS:
        if k in value:
            v = value[k]
            if not _whole(v):
                out.append(f"{k} {v!r} is not a whole number")
            elif v < 0:
                out.append(f"{k} {v} is negative; counts are whole numbers >= 0")
    lo, hi = value.get("at_least"), value.get("at_most")
    if _whole(lo) and _whole(hi) and lo > hi:
        out.append(f"at_least {lo} is more than at_most {hi}: no count lies between them")
    return out


def limits(value: Any) -> tuple[int, int | None]:
    """``(lowest, highest)`` final count a valid value allows; ``None`` for no upper limit."""
    if is_bound(value):
        return int(value.get("at_least", 0)), (int(value["at_most"]) if "at_most" in value else None)
    return int(value), int(value)


def holds(count: int, value: Any) -> bool:
    """Whether a final ``count`` meets ``value`` (exact: equal; bound: within, ends included)."""
    lo, hi = limits(value)
    return lo <= count and (hi is None or count <= hi)


def values_met(counts: dict | None, goal: dict | None) -> list[bool]:
    """Whether each value of ``goal`` holds in ``counts`` (``{place: {item: count}}``, a missing
    count is 0), in the goal's order: what goal checks and GCR are computed from."""
    return [holds(int((counts or {}).get(place, {}).get(item, 0)), v)
            for place, items in (goal or {}).items() for item, v in items.items()]


def describe(value: Any) -> str:
    """The value in words: ``7``, ``at least 3``, ``at most 9``, ``between 3 and 9``."""
    if not is_bound(value):
        return str(value)
    lo, hi = value.get("at_least"), value.get("at_most")
    if lo is not None and hi is not None:
        return f"exactly {lo}" if lo == hi else f"between {lo} and {hi}"
    return f"at least {lo}" if lo is not None else f"at most {hi}"


def from_limits(lo: int | None, hi: int | None, exact: bool = False) -> Any:
    """The goal value for conditions read back from a problem: an int when an exact count was
    stated and the limits agree; otherwise a bound mapping with the limits that were stated
    (kept even when ``lo > hi``, so the verifier can say the goal contradicts itself)."""
    if exact and lo is not None and lo == hi:
        return lo
    out = {}
    if lo is not None:
        out["at_least"] = lo
    if hi is not None:
        out["at_most"] = hi
    return out

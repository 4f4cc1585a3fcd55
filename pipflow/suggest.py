"""Name suggestions for error messages ("did you mean ...?"), the one place they are computed.

A base module (it imports nothing of pipflow): the engine's workflow checks (unknown steps,
inputs, outputs, references, workflows), the world and task checkers of every domain, the
planner names, the PDDL debugger and the verifier all suggest names through :func:`closest`,
and none of them imports another to borrow its helper."""
from __future__ import annotations

import difflib
from typing import Iterable


def closest(name: str, choices: Iterable[str], n: int = 3, cutoff: float = 0.6) -> list[str]:
    """Closest existing names to ``name`` (difflib), best first."""
    return difflib.get_close_matches(str(name), [str(c) for c in choices], n=n, cutoff=cutoff)


def did_you_mean(name: str, choices: Iterable[str]) -> str:
    """``" (did you mean 'a', 'b'?)"``, or "" when nothing is close: for located file problems."""
    near = closest(name, choices)
    return f" (did you mean {', '.join(repr(c) for c in near)}?)" if near else ""


def did_you_mean_clause(name: str, choices: Iterable[str]) -> str:
    """``"; did you mean 'a' or 'b'?"``, or "": for the debugger's messages, which a language model
    reads back (a looser cutoff: a model's misspellings stray further than a user's)."""
    near = closest(name, choices, cutoff=0.5)
    return f"; did you mean {' or '.join(repr(n) for n in near)}?" if near else ""

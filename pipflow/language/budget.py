"""How long a model may talk: a token budget from the expected answer's size, and stop sequences.

A small model on a CPU rarely stops by itself: it runs to ``max_tokens`` and a call of 1024
tokens takes about a minute (issue 17). The answer's size is known before the call, though: a
free answer is one problem for this world (about the size of the example problem the prompt
shows) and a JSON block of rules; a grounded answer is one JSON item per goal count. The budget
is that size in tokens with a margin, so a runaway answer is cut where no real answer could
still be going; the answer readers then say it was cut off, which is feedback like any other.
"""
from __future__ import annotations

import math
from typing import Any

from pipflow.taskdomain import GroundedDecoding

#: characters per token of PDDL and JSON for small models' tokenizers (names split into word and
#: digits, every parenthesis a token): measured 2.88 (PDDL) and 2.61 (grounded JSON) on SmolLM2-135M
#: for the paper's world; 2.6 leaves room for other tokenizers
CHARS_PER_TOKEN = 2.6
#: tokens for what surrounds the problem: code fences, the rules' JSON block, a sentence of prose
FREE_MARGIN = 128
GROUNDED_MARGIN = 48
#: the fewest tokens ever asked for (a command may ask for many counts the estimate missed)
FLOOR = 128
GROUNDED_FLOOR = 256
#: tokens of one grounded statement (an order's ``set`` with its source words) and one rule as
#: small models lay them out (newlines, indents)
ITEM_TOKENS, RULE_TOKENS = 55, 60
#: where a free answer has certainly ended: the model starts writing the prompt's parts again
FREE_STOPS = ["\nCommand:", "Your previous answer", "\n\n\n\n"]


def tokens_for(text: str) -> int:
    return math.ceil(len(text) / CHARS_PER_TOKEN)


def free_budget(expected_problem: str) -> int:
    """Tokens for a free answer whose problem is about ``expected_problem``'s size (plus a
    quarter for a longer goal)."""
    return max(FLOOR, math.ceil(tokens_for(expected_problem) * 1.25) + FREE_MARGIN)


def grounded_budget(goal_items: int, rules: int) -> int:
    """Tokens for a grounded answer of ``goal_items`` counts and ``rules`` rules, twice over and
    at least two of each (a model may restate counts that stay, and the grammar lets it lay an
    item out over several lines: about 55 tokens a statement, 60 a rule, for SmolLM2)."""
    return max(GROUNDED_FLOOR, 2 * (max(goal_items, 2) * ITEM_TOKENS + max(rules, 2) * RULE_TOKENS) + GROUNDED_MARGIN)


def answer_budget(world: dict, grounding: GroundedDecoding | None, example: str | None, reading: Any = None) -> int:
    """The ``max_tokens`` of one call: a grounded answer's (``grounding``: the world's task
    domain, when the answer is grounded) from the size its domain expects
    (:meth:`~pipflow.taskdomain.GroundedDecoding.answer_size`: from the offline reading when the
    parser read the command, else from the world), a free answer's from the example problem."""
    if grounding is not None:
        return grounded_budget(*grounding.answer_size(world, reading if isinstance(reading, dict) else None))
    return free_budget(example or "")

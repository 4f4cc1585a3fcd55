"""Feedback for the next round, in the form the model was asked to answer in, and never the
same prompt twice.

Two things go wrong in a refinement loop driven by a real model (issue 17):

* **Messages in the wrong form.** A grounded model answers with JSON; telling it to "write a
  (define (problem ...) ...) form" asks for something its decoder cannot even produce. The
  messages of the checked loop's second opinion name what disagrees in plain words, in no form
  at all (and never as an entry to paste: :mod:`pipflow.language.agreement`); the answer
  reader's own messages are phrased for the mode it read.
* **Wasted rounds.** When the checks say the same thing twice, the next prompt is byte-identical
  to the last one and, at temperature 0, so is the answer. :func:`vary` then changes the prompt,
  one step further each time the base prompt repeats: quote the previous answer with the lines
  the messages point at marked; add the world facts the messages are about; raise the
  temperature. The step records which (``varied``).
"""
from __future__ import annotations

import json
import re

from pipflow.language.parsing import decode_answer_json

#: the variations, in the order they are tried (each level adds one to the ones before)
QUOTE, FACTS, TEMPERATURE = "quoted previous answer", "added world facts", "raised temperature"
LEVELS = (QUOTE, FACTS, TEMPERATURE)
#: the most lines of a previous answer quoted back (a runaway answer is cut, the marks kept)
QUOTE_LINES = 60
MARK = ">> "


# ---------------------------------------------------------------------------------------------
# varying a prompt that would repeat
# ---------------------------------------------------------------------------------------------
def _cited_lines(messages: list[str]) -> set[int]:
    """Line numbers the messages point at ("line 12, column 3")."""
    return {int(n) for m in messages for n in re.findall(r"\bline (\d+)", m)}


def _pairs(messages: list[str], world: dict) -> set[tuple[str, str]]:
    """(shelf, product) pairs that one message names together."""
    shelves, products = list(world.get("shelves") or {}), list(world.get("products") or {})
    out = set()
    for m in messages:
        words = set(re.findall(r"[\w-]+", m.lower()))
        for s in shelves:
            for p in products:
                if s.lower() in words and p.lower() in words:
                    out.add((s, p))
    return out


def quote(answer: str, messages: list[str], world: dict, grounded: bool) -> str:
    """The previous answer, lines the messages point at marked with ``>>``: lines they cite by
    number (the debugger's positions) and lines that name a shelf and a product that one message
    names together. A grounded answer is laid out one statement (or goal item) and rule per line first."""
    text = answer.strip()
    if grounded:
        try:
            data, _ = decode_answer_json(text)
            items = [json.dumps(x) for x in data.get("statements", []) + data.get("goal", [])] + \
                    [json.dumps(x) for x in data.get("rules", []) + data.get("constraints", [])]
            text = "\n".join(items) or text
        except (ValueError, AttributeError, TypeError):
            pass
    else:
        m = re.search(r"\(\s*define\s*\(\s*problem\b", text, re.IGNORECASE)
        text = text[m.start():] if m else text  # the debugger counts lines from the problem's start
    cited, pairs = _cited_lines(messages), _pairs(messages, world)
    lines = text.splitlines() or [""]
    out = []
    for n, line in enumerate(lines[:QUOTE_LINES], 1):
        low = set(re.findall(r"[\w-]+", line.lower()))
        marked = n in cited or any(s.lower() in low and p.lower() in low for s, p in pairs)
        out.append((MARK if marked else "   ") + line)
    if len(lines) > QUOTE_LINES:
        out.append(f"   ... ({len(lines) - QUOTE_LINES} more lines)")
    return ("Your previous answer, with the lines the messages above point at marked '>>':\n```\n"
            + "\n".join(out) + "\n```")


def world_facts(messages: list[str], world: dict) -> str:
    """The world's facts about the shelves and products the messages name: current counts,
    capacity, how many units of a product exist in all and where."""
    stock = world.get("stock") or {}
    shelves = [s for s in world.get("shelves") or {} if any(re.search(rf"\b{re.escape(s)}\b", m) for m in messages)]
    products = [p for p in world.get("products") or {} if any(re.search(rf"\b{re.escape(p)}\b", m) for m in messages)]
    lines = []
    for s in shelves:
        held = ", ".join(f"{n} {p}" for p, n in (stock.get(s) or {}).items() if n) or "nothing"
        load = sum((stock.get(s) or {}).values())
        lines.append(f"- {s} holds {held} now ({load} units; capacity {world['shelves'][s].get('capacity')})")
    for p in products:
        where = {s: (items or {}).get(p, 0) for s, items in stock.items() if (items or {}).get(p)}
        total = sum(where.values())
        lines.append(f"- there are {total} {p} in all" + (f" ({', '.join(f'{s} {n}' for s, n in where.items())})" if where else ""))
    return ("Facts of the world that the messages are about:\n" + "\n".join(lines)) if lines else ""


def vary(level: int, answer: str, messages: list[str], world: dict, grounded: bool,
         temperature: float) -> tuple[list[str], float, list[str]]:
    """``(extra feedback lines, temperature, what was varied)`` at ``level`` (1 = quote the
    answer, 2 = also the world's facts, 3 and more = also a higher temperature, 0.3 per level
    above 2, at most 1.0). A level whose addition is empty (no facts to add) still counts, so
    a higher level always adds something new: the attempt line names the level."""
    extra, done = [], []
    if level >= 1 and answer.strip():
        extra.append(quote(answer, messages, world, grounded))
        done.append(QUOTE)
    if level >= 2:
        facts = world_facts(messages, world)
        if facts:
            extra.append(facts)
            done.append(FACTS)
    if level >= 3:
        temperature = min(1.0, max(temperature, 0.3 * (level - 2)))
        done.append(f"{TEMPERATURE} to {temperature:g}")
    if level >= 1:
        extra.append(f"The checks said the same as before (attempt {level + 1} at this answer): "
                     "write a different answer that fixes the marked lines.")
    return extra, temperature, done

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
from pipflow.taskdomain import Facts
from pipflow.taskdomains import task_domain

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


def quote(answer: str, messages: list[str], together: list[tuple[str, ...]], grounded: bool) -> str:
    """The previous answer, lines the messages point at marked with ``>>``: lines they cite by
    number (the debugger's positions) and lines that name every name of a group that one message
    names together (``together``: the world's task domain finds them,
    :meth:`pipflow.taskdomain.TaskDomain.feedback_facts`). A grounded answer is laid out one
    statement (or goal item) and rule per line first."""
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
    cited = _cited_lines(messages)
    lines = text.splitlines() or [""]
    out = []
    for n, line in enumerate(lines[:QUOTE_LINES], 1):
        low = set(re.findall(r"[\w-]+", line.lower()))
        marked = n in cited or any(all(name.lower() in low for name in group) for group in together)
        out.append((MARK if marked else "   ") + line)
    if len(lines) > QUOTE_LINES:
        out.append(f"   ... ({len(lines) - QUOTE_LINES} more lines)")
    return ("Your previous answer, with the lines the messages above point at marked '>>':\n```\n"
            + "\n".join(out) + "\n```")


def vary(level: int, answer: str, messages: list[str], world: dict, grounded: bool,
         temperature: float) -> tuple[list[str], float, list[str]]:
    """``(extra feedback lines, temperature, what was varied)`` at ``level`` (1 = quote the
    answer, 2 = also the world's facts, 3 and more = also a higher temperature, 0.3 per level
    above 2, at most 1.0). A level whose addition is empty (no facts to add) still counts, so
    a higher level always adds something new: the attempt line names the level."""
    extra, done = [], []
    facts = task_domain(world).feedback_facts(messages, world) if level >= 1 else Facts()
    if level >= 1 and answer.strip():
        extra.append(quote(answer, messages, facts.together, grounded))
        done.append(QUOTE)
    if level >= 2 and facts.lines:
        extra.append("Facts of the world that the messages are about:\n" + "\n".join(facts.lines))
        done.append(FACTS)
    if level >= 3:
        temperature = min(1.0, max(temperature, 0.3 * (level - 2)))
        done.append(f"{TEMPERATURE} to {temperature:g}")
    if level >= 1:
        extra.append(f"The checks said the same as before (attempt {level + 1} at this answer): "
                     "write a different answer that fixes the marked lines.")
    return extra, temperature, done

"""Located reader issues: what a baseline's reader says about an answer it cannot read.

Every reader (the CoT plan, SMART-LLM's code, LaMMA-P's summary) reports each problem with the
line and column of the model's answer where it is, the text found there and what the format
expects, as precisely as the debugger does for PDDL: the same words serve the run record, the
user reading it, and (where a baseline's paper gives it a round of feedback) the model.
"""
from __future__ import annotations

from dataclasses import dataclass

from pipflow.errors import AnswerFormatError

#: the most issues one message lists (the rest are counted): a garbled answer has one per line
MAX_LISTED = 12


@dataclass(frozen=True)
class Issue:
    """One problem of an answer: 1-based ``line`` and ``column`` in the whole answer."""

    line: int
    column: int
    message: str

    def __str__(self) -> str:
        return f"line {self.line}, column {self.column}: {self.message}"


class Unreadable(ValueError):
    """The answer is not in the reader's format; ``issues`` says where and why."""

    def __init__(self, issues: list[Issue]):
        self.issues = sorted(issues, key=lambda i: (i.line, i.column))
        super().__init__("; ".join(str(i) for i in self.issues))

    def lines(self) -> list[str]:
        """Each issue as a line, at most :data:`MAX_LISTED` and a count of the rest."""
        shown = [str(i) for i in self.issues[:MAX_LISTED]]
        if len(self.issues) > MAX_LISTED:
            shown.append(f"... and {len(self.issues) - MAX_LISTED} more problems")
        return shown

    def refusal(self, method: str, what: str, cut_off: int | None = None) -> AnswerFormatError:
        """The run's error when the method gives no further round: the answer is not read.
        ``cut_off``: the answer stopped at this many tokens (its ``max_tokens``), which is said."""
        n = len(self.issues)
        cut = (f" The answer was cut off at the {cut_off} tokens it may take (raise -i max_tokens)."
               if cut_off else "")
        return AnswerFormatError(f"the {method} answer is not {what} ({n} problem{'s' if n != 1 else ''}; "
                                 f"{method} gives the model no further round, so nothing is executed):{cut}\n  "
                                 + "\n  ".join(self.lines()))


def line_col(text: str, offset: int) -> tuple[int, int]:
    """1-based line and column of character ``offset`` of ``text``."""
    line = text.count("\n", 0, offset) + 1
    return line, offset - (text.rfind("\n", 0, offset) + 1) + 1


def snippet(text: str, limit: int = 60) -> str:
    """``text`` quoted for a message, cut to ``limit`` characters on one line."""
    one = " ".join(str(text).split())
    return repr(one if len(one) <= limit else one[: limit - 3] + "...")

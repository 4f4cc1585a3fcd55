"""Positions in PDDL text: line and column of an offset, of a whole word, with ``;`` comments
blanked. No parsing here: the debugger and every domain's world check point at the words they
complain about with these, without importing one another."""
from __future__ import annotations

import re


def line_col(text: str, offset: int) -> tuple[int, int]:
    """1-based line and column of character ``offset``."""
    before = text[:offset]
    return before.count("\n") + 1, offset - (before.rfind("\n") + 1) + 1


def strip_comments(text: str) -> str:
    """The text with ``;`` comments blanked out (same length, so offsets stay valid)."""
    return re.sub(r";[^\n]*", lambda m: " " * len(m.group(0)), text)


def find_word(text: str, word: str, nth: int = 0) -> str:
    """``"line L, column C: "`` of the ``nth`` occurrence of ``word`` as a whole token, or ``""``."""
    hits = list(re.finditer(r"(?<![\w-])" + re.escape(word) + r"(?![\w-])", strip_comments(text)))
    if len(hits) <= nth:
        return ""
    line, col = line_col(text, hits[nth].start())
    return f"line {line}, column {col}: "

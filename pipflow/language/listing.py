"""Lists numbered inline: "Today's plan: 1) bay 1 should have 10 batteries 2) take 2 tyres off
bay 3 3) don't use bhavani", or with a slash as Vietnamese and French lists write it ("1/ 4 box
pin rack 1 to iqc 2/ shipping sac total 12 box").

People who write to a team from a desk number the jobs in one line, as in an email. The numbers
are no counts and the brackets close nothing; each number opens a job of its own, as a line of a
list would. Read so only where the numbers run 1, 2, 3 ... in order (at least two of them), each
number is followed by ")" or "/" and a space (never "1/2", a fraction) and stands at the head of
the text, after a colon, or after a space, and
no "(" is open before it (then the ")" closes an aside: "(it has 2)"). Anything else is left as
written, and the count a number may be is read as ever."""
from __future__ import annotations

import re

#: a list number: digits and ")" at the head, after a colon or after white space
_NUMBERED = re.compile(r"(?:(?<=\s)|(?<=:)|^)(\d{1,2})[)/](?=\s)")


def inline_numbering(text: str) -> str:
    """The text with an inline numbered list's numbers read as stops (module docstring)."""
    found = [m for m in _NUMBERED.finditer(text) if text[:m.start()].count("(") <= text[:m.start()].count(")")]
    if len(found) < 2 or [int(m.group(1)) for m in found] != list(range(1, len(found) + 1)):
        return text
    out, at = [], 0
    for m in found:
        out += [text[at:m.start()].rstrip(), ". "]
        at = m.end()
    return "".join(out) + text[at:]

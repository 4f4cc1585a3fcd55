"""Corrections sent as "*word": a texting convention. A message with a slip ("move 3 cowboys ...",
"shift 5 carboys ...") is followed by one that opens with an asterisk and the word meant ("*carboys",
"*6"). The asterisk word replaces the one word before it that it corrects, and is said in the echo.

Which word it corrects must be clear, or nothing is guessed: a number corrects the one number said
before it (two or more numbers: refused); a word corrects the word before it that is nearest in
spelling, within two edits (or a third of its length), and only when no other is as near. The rest
of the line after the asterisk word stays for the reader, as talk or not (", bloody autocorrect"),
unless it only says the correction again ("*6 sorry, 6 carboys": the word, words of the command
before it, and words that take a slip back): then it goes with the asterisk word.
"""
from __future__ import annotations

import re
from pipflow.errors import TranslationError
from pipflow.language.numbers import is_number
from pipflow.language.spelling import distance

#: an asterisk opening a word, at the start of the command, of a line or of a sentence, or after a space
_STAR = re.compile(r"(?:^|(?<=[\s.!?]))\*([A-Za-z0-9][\w'-]*)")
_WORD = re.compile(r"[A-Za-z0-9][\w'-]*")
#: words that take a slip back, said with a correction said again ("sorry, 6 carboys")
TAKE_BACK = frozenset({"sorry", "oops", "i", "mean", "meant", "my", "bad", "that", "is", "should", "be", "it", "s"})


def star_corrections(text: str) -> tuple[str, list[str]]:
    """``text`` with each "*word" correction made (the word it corrects replaced, the asterisk
    word removed) and what was read so, one note each. Raises :class:`TranslationError` when it
    is not clear which word a correction corrects."""
    notes: list[str] = []
    while (m := _STAR.search(text)) is not None:
        right = m.group(1)
        before = text[:m.start()]
        words = list(_WORD.finditer(before))
        if is_number(right.lower()):
            targets = [w for w in words if is_number(w.group(0).lower())]
        else:
            near = [(distance(w.group(0).lower(), right.lower()), w) for w in words
                    if w.group(0).lower() != right.lower() and not is_number(w.group(0).lower())]
            limit = max(2, len(right) // 3)
            best = min((d for d, _ in near), default=limit + 1)
            targets = [w for d, w in near if d == best <= limit]
        if len(targets) != 1:
            raise TranslationError(
                f"cannot tell which word '*{right}' corrects"
                + (f" ({', '.join(repr(w.group(0)) for w in targets)} are as near)" if targets else
                   " (no word before it is near it)") + ": say the command again with the word put right")
        wrong = targets[0]
        notes.append(f"'*{right}': read '{wrong.group(0)}' as '{right}'")
        after = text[m.end():]
        line = re.match(r"[^\n]*", after).group(0)
        said = {w.lower() for w in _WORD.findall(before)} | {right.lower()}
        again = [w.lower() for w in _WORD.findall(line)]
        if right.lower() in again and all(w in said or w in TAKE_BACK for w in again):
            after = after[len(line):]   # the correction said again: nothing more
        text = before[:wrong.start()] + right + before[wrong.end():] + after
    return text, notes

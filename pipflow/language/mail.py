"""Orders sent as an e-mail: the parts of a mail that are its form, not its content.

A work e-mail heads the order with a subject line ("Subject: RE: Pickline gloves") and may set
its orders out as a list ("- Move 5 ...", "1. Move 4 ...", "2) ..."). The subject names the
topic, often with names of the world, so it is no talk by the reader's test; yet it asks for
nothing the body does not. Here the subject line is set aside (said in the echo) unless it holds
a number or an operative word (:data:`pipflow.language.asides.OPERATIVE`: "Subject: NOT the
forklift" bears on what the robots do, so it is read, and refused if it does not read). List
markers at the start of a line are left out; each item stays a line, so a sentence of its own. A
greeting line that names only who is asked ("Team,", "Hi all,") and the sender's name signing the
mail off (after a blank line, a closing line such as "Thx," or a dash: "Deb", "-D", "Thx - Deb")
are set aside too; a name that is a word of the world's names (a robot called so), or that holds
an operative word ("Not Bob"), never is.
"""
from __future__ import annotations

import re

from pipflow.language.asides import OPERATIVE
from pipflow.language.numbers import is_number

#: the subject line heading a mail, with any "RE:" / "FW:" before or after "Subject:"
_SUBJECT = re.compile(r"\A\s*(?:(?:re|fw|fwd)\s*:\s*)*subject\s*:[ \t]*(?P<topic>[^\n]*)(?:\n|\Z)", re.IGNORECASE)
#: a list marker opening a line: a dash, a bullet or an asterisk with a space, or a number with
#: "." or ")" and a space ("1. Move 4 ...", "2) ..."): "1 box" has no mark after its number
_MARKER = re.compile(r"^([ \t]*)(?:[-*\u2022]|\d{1,2}[.)])[ \t]+(?=\S)", re.MULTILINE)
#: a line that greets the ones asked and says nothing else
_GREETING = re.compile(r"\A\s*(?P<line>(?:(?:hi|hello|hey|dear|good\s+morning|morning|afternoon)[ \t]+)?"
                       r"(?:team|all|everyone|everybody|folks|guys|y'all|crew|gang|robots|bots)[ \t]*[,!:]?)[ \t]*\n", re.IGNORECASE)
#: words that close a mail on a line of their own, before the sender's name
CLOSINGS = r"(?i:thanks|thx|thank\s+you|cheers|regards|best|ta|many\s+thanks|best\s+regards|kind\s+regards)"
#: the sender's name closing the mail: after a blank line, a closing line or a dash
_SIGNATURE = re.compile(
    r"(?:\n[ \t]*\n|\n[ \t]*" + CLOSINGS + r"[ \t]*[,!.]*[ \t]*\n|[ \t,!.]*\n?[ \t]*[-\u2013\u2014]+)[ \t]*"
    r"(?P<name>[A-Z][a-z]{0,15}(?:[ \t]+[A-Z][a-z]{0,15})?)[ \t]*\.?\s*\Z")


def without_mail_form(text: str, names: frozenset[str] = frozenset()) -> tuple[str, list[str]]:
    """``text`` without its subject line (when it asks for nothing), its greeting line, the
    sender's name and its list markers, and what was set aside ("subject line: ...", "signed:
    Deb"). ``names``: the words of the world's names, in lower case (never a signature)."""
    aside: list[str] = []
    m = _SUBJECT.match(text)
    if m is not None:
        topic = m.group("topic").strip()
        words = [w.lower() for w in re.findall(r"[A-Za-z0-9']+", topic)]
        if not any(is_number(w) or w.strip("'") in OPERATIVE for w in words):
            aside.append(f"subject line: {topic}" if topic else "subject line")
            text = text[m.end():]
        else:
            text = topic + "\n" + text[m.end():]   # read as a line of its own, "Subject:" left out
    m = _GREETING.match(text)
    if m is not None:
        aside.append(m.group("line"))
        text = text[m.end():]
    m = _SIGNATURE.search(text)
    signed = {w.lower() for w in m.group("name").split()} if m is not None else set()
    # "Not Bob", "Only Ox": an operative word or a name of the world is no sender's name
    if m is not None and not signed & (names | OPERATIVE) and text[:m.start()].strip():
        aside.append(f"signed: {m.group('name')}")
        text = text[:m.start()]
    return _MARKER.sub(r"\1", text), aside

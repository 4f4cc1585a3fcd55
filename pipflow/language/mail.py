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

A ticket or a note is headed the same way by a title without "Subject:": its first line, closed
by no mark, naming the topic ("Bulbs dock 2" over "Pls bring dock 2 to 12 bulbs"). Such a line is
set aside only when it is a summary of what follows: every word of it a name of the world (a
place's name said "dock 2", a plural, a name's stem: "docks") or a word that only links names
(:data:`TITLE_LINKS`: "from", "to", an arrow), at least one name, each said again below it, and no
number but a name's, no operative word. Anything else in it, a count ("5 gouda dock 2"), a word of
an order ("Dock 3 empty") or a word no name has, keeps it a line to be read.
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
    r"(?:\n[ \t]*\n|\n[ \t]*" + CLOSINGS + r"[ \t]*[,!.]*[ \t]*\n|[ \t,!.]*\n?[ \t]*(?<![A-Za-z0-9])[-\u2013\u2014]+)[ \t]*"
    r"(?P<name>[A-Z][a-z]{0,15}(?:[ \t]+[A-Z][a-z]{0,15})?)[ \t]*\.?\s*\Z")


#: words a title may hold besides names: they only link the names ("Gouda from buffer to the
#: docks", "Frames dock3 -> dock1") or say how urgent the ticket is
TITLE_LINKS = frozenset({"from", "to", "for", "of", "out", "the", "and", "at", "on", "in", "into", "onto", "off",
                         "over", "prio", "asap", "urgent", "->", "=>", "\u2192", "<->", "<>"})
#: the first line of several, closed by no mark, with more after it
_TITLE = re.compile(r"\A[ \t]*(?P<title>[^\n.!?;:,]*[^\n.!?;:,\s])[ \t]*\n(?=\s*\S)")


def _named(text: str, names: frozenset[str]) -> list[str] | None:
    """The names ``text`` says, each as the world has it or as a stem ("dock 2" and "Dock2" are
    dock2, "docks" and "dock" the stem dock), or None when it holds a word that is no name and no
    :data:`TITLE_LINKS` word, or a number that is no part of a name."""
    stems = {re.sub(r"\d+$", "", n) for n in names}
    words = re.findall(r"[a-z]+|\d+|[-=<>\u2192]+", text.lower())
    out: list[str] = []
    k = 0
    while k < len(words):
        w, nxt = words[k], words[k + 1] if k + 1 < len(words) else ""
        if nxt.isdigit() and w + nxt in names:
            out.append(w + nxt)
            k += 2
            continue
        single = next((x for x in _singulars(w) if x in names or x in stems), None)
        if single is not None:
            out.append(single)
        elif w not in TITLE_LINKS:
            return None
        k += 1
    return out


def _singulars(word: str) -> list[str]:
    """The word and the forms it may be the plural of ("docks", "boxes", "shelves")."""
    out = [word]
    if word.endswith("s"):
        out.append(word[:-1])
    if word.endswith("es"):
        out.append(word[:-2])
    if word.endswith("ves"):
        out += [word[:-3] + "f", word[:-3] + "fe"]
    return out


def _title_aside(text: str, names: frozenset[str]) -> tuple[str, str] | None:
    """``text`` without its title and the title, when the title sums up what follows (module doc)."""
    m = _TITLE.match(text)
    if m is None:
        return None
    title, body = m.group("title").strip(), text[m.end():]
    named = _named(title, names)
    words = set(re.findall(r"[a-z]+", title.lower()))
    if not named or words & OPERATIVE:
        return None
    said_below = set()
    for w in re.findall(r"[a-z]+\d*|\d+", body.lower()):
        said_below |= {re.sub(r"\d+$", "", w), *_singulars(w)}
    joined = re.sub(r"([a-z]+)\s+(\d+)", r"\1\2", body.lower())
    said_below |= set(re.findall(r"[a-z]+\d+", joined))
    if not all(n in said_below for n in named):
        return None
    return body, title


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
    elif (titled := _title_aside(text, names)) is not None:
        text, title = titled
        aside.append(f"title line: {title}")
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

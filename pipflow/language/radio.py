"""Orders given over a two-way radio, as its speech-to-text writes them down: "Yard control to
all units. Cement on counter, bring it up to 7. Over."

A transmission is framed by voice procedure, words that carry no order:

- **the call**, who is called and who calls: "Yard control to all units", "All units, yard
  control", "Sierra, Sierra, this is yard control", "Yard control. All units.". The calling
  station names nothing of the world and ends in a word for a station (:data:`STATION_WORDS`:
  "yard control", "base", "ops"). "All units" calls everyone: no robot rule. A robot called by
  name is kept as "<robot>," in front of the message, which is how a robot addressed at the head
  of a sentence is read (a rule that it does the work); any other name called is kept the same
  way, and is refused as a robot this world lacks.
- **prowords said as whole clauses** (:data:`PROWORDS`): "over", "out" closing a transmission,
  "copy?", "roger", "wilco", "break" between two messages (each may open with a call of its own).
- **"I say again"** and the words it repeats, when they repeat the clause before word for word
  ("No fewer than five sleepers at counter, I say again, no fewer than five"). A repeat that says
  anything else stays, and must read.
- **numbers said digit by digit**, joined by hyphens ("one-two" is 12, "one-zero" 10), and
  "niner" for nine.
- **"unit" for a robot** ("the weakest unit", "units that carry three or more"); after a number
  ("5 units") it stays a count's word.

A command is read so only when it is a transmission: it closes with "over" or "out" said as a
clause, or opens with a call that names its station. Anywhere else these words mean what they
always mean ("send 3 crates over", "one-two boxes"). Everything set aside is said in the echo.
"""
from __future__ import annotations

import re
from typing import Callable, NamedTuple

#: words that end the call sign of a station, not a robot ("yard control", "base", "ops")
STATION_WORDS = ("control", "base", "ops", "operations", "tower", "hq", "command", "office", "desk", "central")
#: prowords said as whole clauses, which carry no order
PROWORDS = ("over and out", "over out", "over", "out", "copy that", "copy", "do you copy", "how copy",
            "roger that", "roger", "wilco", "break break", "break", "standby", "stand by", "acknowledge")
#: prowords that close a transmission: a command ending with one is read as radio procedure
CLOSING = ("over and out", "over out", "over", "out")
#: digits as said over the radio, for numbers said digit by digit
DIGITS = {"zero": "0", "oh": "0", "one": "1", "two": "2", "three": "3", "four": "4", "five": "5", "six": "6",
          "seven": "7", "eight": "8", "nine": "9", "niner": "9"}

_EVERYONE = r"all\s+(?:units|stations|call\s*signs|robots|bots|mobiles)"
_STATION = r"(?:[a-z][a-z0-9'-]*\s+){0,2}(?:" + "|".join(STATION_WORDS) + r")"
_CALLEE = rf"(?:{_EVERYONE}|[a-z][a-z0-9_-]*)"
_MARK = r"\s*[.,:;!]+\s*"
#: the forms of a call at the head of a message, each with the station, the called, or both
CALLS = [re.compile(p, re.IGNORECASE) for p in (
    # the called (said once or twice), then the station: "Sierra, Sierra, yard control."
    rf"^(?P<callee>{_CALLEE})(?:[\s,]+(?P=callee))?\s*,\s*(?:this\s+is\s+)?(?P<station>{_STATION}){_MARK}",
    # the station to the called: "Yard control to all units.", "Yard control, all units."
    rf"^(?P<station>{_STATION})\s*(?:,|\s+to|\s+calling)\s*(?P<callee>{_CALLEE})(?:[\s,]+(?P=callee))?{_MARK}",
    # each as a sentence: "Yard control. All units."
    rf"^(?P<station>{_STATION})\s*[.!]\s*(?P<callee>{_EVERYONE})(?:[\s,]+(?P=callee))?{_MARK}",
    # everyone called, the station left out: "All units.", "All units all units,"
    rf"^(?P<callee>{_EVERYONE})(?:[\s,]+(?P=callee))?{_MARK}",
    # the station alone: "Yard control."
    rf"^(?P<station>{_STATION})\s*[.:;!]+\s*",
)]
_PROWORD = r"(?:" + "|".join(p.replace(" ", r"\s+") for p in PROWORDS) + r")"
#: a proword as a whole clause: after the start or a clause mark, before a mark or the end
_PROWORD_CLAUSE = re.compile(rf"(^|[.,;:!?])\s*{_PROWORD}\s*\??\s*(?=[.,;:!?]|$)", re.IGNORECASE)
_CLOSING = "|".join(c.replace(" ", r"\s+") for c in CLOSING)
_CLOSES = re.compile(rf"(?:^|[.,;:!?])\s*(?:{_CLOSING})\s*[.!]?\s*$", re.IGNORECASE)
#: "break" said as a sentence or clause of its own, between two messages
_BREAK = re.compile(r"(?:^|(?<=[.,;:!?]))\s*break(?:\s+break)?\s*[.,;:!]+\s*", re.IGNORECASE)
_SAY_AGAIN = re.compile(r",\s*i\s+(?:say\s+again|repeat)\s*,\s*(?P<rep>[^.;!?,]+)", re.IGNORECASE)
_DIGITS = "|".join(DIGITS)
_DIGIT_RUN = re.compile(rf"\b(?:{_DIGITS})(?:-(?:{_DIGITS}))+\b", re.IGNORECASE)
_NINER = re.compile(r"\bniner\b", re.IGNORECASE)
_UNIT = re.compile(r"(?P<before>\b[\w-]+\s+)?\bunit(?P<s>s?)\b", re.IGNORECASE)


class Transmission(NamedTuple):
    """A command read as a radio transmission: its message(s) without the procedure, and the
    procedure set aside, as said."""

    text: str
    aside: list[str]


def transmission(command: str, names: Callable[[str], bool], robot: Callable[[str], bool],
                 counts: Callable[[str], bool]) -> Transmission | None:
    """The command without its voice procedure (module docstring), or None when it is no radio
    transmission. ``names(word)``: whether a word names something of the world (a station's call
    sign never does); ``robot(word)``: whether it names a robot; ``counts(word)``: whether a word
    is a number (before "units")."""
    messages = _BREAK.split(command.strip())
    called = [_call(m, names, robot) for m in messages]
    if not _CLOSES.search(command) and not any(call and call[2] for call in called):
        return None
    aside: list[str] = []
    out: list[str] = []
    for message, call in zip(messages, called):
        if call is not None:
            said, rest, _ = call
            aside.append(said)
            message = rest
        out.append(message)
    text = " ".join(m.strip() for m in out if m.strip())
    if len(messages) > 1:
        aside.append("break")
    text, prowords = _without_prowords(text)
    aside += prowords
    text, repeats = _without_repeats(text)
    aside += repeats
    text = _DIGIT_RUN.sub(lambda m: "".join(DIGITS[d.lower()] for d in m.group(0).split("-")), text)
    text = _NINER.sub("9", text)
    text = _UNIT.sub(lambda m: m.group(0) if m.group("before") and counts(m.group("before").strip().lower())
                     else (m.group("before") or "") + "robot" + m.group("s"), text)
    return Transmission(text.strip(), aside)


def _call(message: str, names: Callable[[str], bool], robot: Callable[[str], bool]) -> tuple[str, str, bool] | None:
    """(the call as said, the message after it, whether it names its station) of a message that
    opens with a call (:data:`CALLS`); the message keeps "<name>," where one robot is called."""
    for form in CALLS:
        m = form.match(message.strip())
        if m is None:
            continue
        station = m.groupdict().get("station")
        if station and any(names(w) for w in re.findall(r"[a-z0-9'-]+", station.lower())):
            continue   # a place or thing of the world ("dispatch office") is no station's call sign
        callee = m.groupdict().get("callee")
        rest = message.strip()[m.end():]
        said = m.group(0).strip(" ,.:;!")
        if callee and not re.fullmatch(_EVERYONE, callee, re.IGNORECASE):
            if names(callee.lower()) and not robot(callee.lower()):
                continue   # "Counter, base ...": a place is not called
            rest, said = f"{callee}, {rest}", station.strip()   # the one called is read as addressed
        return said, rest, bool(station)
    return None


def _without_prowords(text: str) -> tuple[str, list[str]]:
    """The text without the prowords said as whole clauses, and those prowords."""
    found: list[str] = []

    def drop(m: re.Match) -> str:
        found.append(m.group(0).strip(" .,;:!"))
        return m.group(1)
    out = _PROWORD_CLAUSE.sub(drop, text)
    while out != text:   # "Copy? Over.": a proword after one just dropped
        text, out = out, _PROWORD_CLAUSE.sub(drop, out)
    # the marks left side by side keep the one that ends a sentence ("..., over. Gantry ...")
    out = re.sub(r"\s*[.,;:!?](?:\s*[.,;:!?])+", lambda m: next((c for c in m.group(0) if c in ".!?"),
                                                                   m.group(0).strip()[0]), out).strip(" ,;:")
    return out, found


def _without_repeats(text: str) -> tuple[str, list[str]]:
    """The text without "I say again, <words>" where the words repeat the clause before word for
    word (a contiguous run of its words), and those repeats."""
    found: list[str] = []

    def drop(m: re.Match) -> str:
        before = re.split(r"[.,;:!?]", text[:m.start()])[-1]
        said, again = _words(before), _words(m.group("rep"))
        if again and any(said[k:k + len(again)] == again for k in range(len(said) - len(again) + 1)):
            found.append(m.group(0).strip(" ,"))
            return ""
        return m.group(0)
    return _SAY_AGAIN.sub(drop, text), found


def _words(text: str) -> list[str]:
    return re.findall(r"[a-z0-9]+", text.lower())

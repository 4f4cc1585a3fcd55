""""him" said of a thing: "the veranda light is on since last night, off him", "open the gwada, take
the shinkurt out, then close him back", "the shiro pot, put him in the frij".

Speakers whose first language gives every noun a gender (Amharic, Arabic, the Romance and Slavic
languages) carry it into English: a lamp or a pot is "he". The reader takes "him" for a person
(:mod:`.people`), and a person's place is asked for or the command refused. Here "him" is read as
"it" only where it cannot be a person:

* after a verb whose object is only ever a thing (opening, closing, cooking, cutting:
  :data:`THING_VERBS`), after "on" / "off" said as a verb opening a clause ("..., off him please"),
  or before "on" / "off" after "switch", "turn" or "put" ("switch him off");
* after a verb of handling (:data:`HANDLING`: put, take, leave, lift ...), which a child may be the
  object of, only in a command that names no person at all (no name, no kinship word, no owner of
  a thing of the home, no "he" or "she").

"it" then needs a thing said before it, as any "it" does; where there is none the command is
refused as before. "he" and "she" as a subject, and "her" (also a possessive), are left as said.
"""
from __future__ import annotations

import re

from pipflow.household.language.people import person_named

#: verbs whose object is only ever a thing: "close him", "heat him" ("warm him up" and "lock him in"
#: may be said of a child, and are not here)
THING_VERBS = frozenset({"open", "close", "shut", "heat", "reheat", "microwave", "boil", "fry", "cook", "slice",
                         "cut", "chop", "dice", "peel", "grate", "toast", "defrost", "chill", "freeze", "plug",
                         "unplug", "dim", "empty", "fill", "refill", "rinse"})
#: "on" and "off" said as verbs ("off him please"): only opening a clause ("put the blanket on him"
#: is a where, and may be a person)
SWITCH_WORDS = frozenset({"on", "off"})
#: what may stand before a clause's first word
_CLAUSE_OPENS = re.compile(r"(?:^|[,.;:!?]|(?:and|then|please|pls|now|also|so))\s*$", re.IGNORECASE)
#: verbs that take "him" and a particle of switching ("switch him off", "turn him on", "put him on")
SWITCHING = frozenset({"switch", "turn", "put"})
#: verbs of handling, which may have a person as their object ("lift him", "put him to bed")
HANDLING = frozenset({"put", "take", "bring", "leave", "lift", "move", "carry", "throw", "keep", "place", "return",
                      "hang", "store"})


def things_called_him(command: str, world: dict, notes: list[str]) -> str:
    """The command with "him" read as "it" where it can only be a thing (module docstring), each
    change said in the notes."""
    if not re.search(r"\bhim\b", command, re.IGNORECASE):
        return command
    nobody = not person_named(command, world, but={"him"})
    said: list[str] = []

    def thing(m: re.Match) -> str:
        verb, particle = m.group(1).lower(), (m.group(2) or "").strip().lower()
        opens = bool(_CLAUSE_OPENS.search(command[:m.start()]))
        if verb in THING_VERBS or (verb in SWITCH_WORDS and opens) or (verb in SWITCHING and particle) \
                or (verb in HANDLING and nobody):
            said.append(f"{m.group(1)} him")
            return f"{m.group(1)} it"
        return m.group(0)

    out = re.sub(r"\b([A-Za-z]+)\s+him\b(?=(\s+(?:on|off)\b)?)", thing, command, flags=re.IGNORECASE)
    if said:
        notes.append("'him' read as 'it' (a thing, as a language that gives things a gender says it): "
                     + "; ".join(f"'{s}'" for s in said))
    return out

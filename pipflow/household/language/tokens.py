"""The household tagger's tokens: one per word or phrase of a command, of a token class of the
grammar (:mod:`pipflow.household.language.grammar`), and the marks that end a sentence or a clause."""
from __future__ import annotations

from dataclasses import dataclass, field


@dataclass
class Tag:
    """One token for the grammar: its class, its meaning, and the words it stands for."""

    cls: str
    value: object
    words: str
    nouns: list[dict] = field(default_factory=list)   # world readings: {"kind", "name", "plural"}


#: marks and the token class each is
PUNCT = {".": "END", ";": "END", "!": "END", "?": "END", ":": "END", ",": "COMMA"}

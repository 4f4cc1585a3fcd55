"""Québec French words said in English, as typed in Montréal ("move 4 X to P pis empty Q", "wash
the pan pis put it away"): each read as the English word the grammars have, only where the word is
no word of the world's names. The words any domain reads; a domain adds its own verbs (the
household reader: "ferme" close, "réchauffe" heat)."""
from __future__ import annotations

#: Québec French word (accents off: the reader folds them from words of talk) -> the English word
QUEBEC = {"pis": "then", "puis": "then"}

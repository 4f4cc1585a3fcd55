"""Jamaican Creole (patois) function words, as typed in Jamaica and its diaspora ("put di sorrel
pon di table", "tek it outa di freezer", "di plate dem", "mi need fi pack it"): each read as the
English word the grammars have. Read only in a command that uses at least two of them
(:data:`MARKERS`) or one that is no English word (:data:`STRONG_MARKERS`), so a single "den" or
"dat" in English stays as typed, and only where the word is no name of the world's things alone."""
from __future__ import annotations

#: patois word -> the English word(s); "mi", "dem", "fi", "him" depend on what follows (the reader)
PATOIS = {"di": "the", "de": "the", "pon": "on", "inna": "in", "ina": "in", "eena": "in", "outa": "out of",
          "offa": "off", "den": "then", "dat": "that", "dis": "this", "tek": "take", "yuh": "you", "unu": "you",
          "nuh": "do not", "nah": "not", "cyaan": "can not", "caan": "can not", "ting": "thing", "tings": "things",
          "everyting": "everything", "anyting": "anything", "nutten": "nothing", "likkle": "little", "seh": "say",
          "wid": "with", "bout": "about", "cause": "because", "fimi": "for me",
          # verbs and words of chores ("tun off di TV", "lef it pon di counter", "mek sure", "outta di
          # fridge", "gi mi", "mi haffi go", "soh", "waan", "smaddy"; "dutty", dirty, is the household's)
          "tun": "turn", "lef": "leave", "mek": "make", "outta": "out of", "gi": "give",
          "haffi": "have to", "soh": "so", "waan": "want", "smaddy": "somebody", "wi": "we"}
#: words that show a command is in patois: two different ones and the map applies
MARKERS = frozenset({"di", "pon", "inna", "dem", "fi", "mi", "nuh", "tek", "weh", "deh", "cyaan", "yuh", "dat",
                     "den", "outa", "tings", "ting", "unu", "tun", "lef", "mek", "outta", "dutty", "gi", "haffi",
                     "soh", "waan", "smaddy", "an"})
#: markers that are no English word: one of them alone is enough ("put it back pon him study desk",
#: "tun off di TV")
STRONG_MARKERS = frozenset({"di", "pon", "inna", "cyaan", "outa", "tek", "yuh", "nuh", "fi", "unu", "weh", "lef", "mek",
                            "outta", "dutty", "haffi", "soh", "waan", "smaddy"})
#: words after "fi" that make it "for" (who or what for: "fi mi", "fi di children"); before
#: anything else "fi" is "to" ("mi need fi pack it")
FOR_WHOM = frozenset({"mi", "di", "de", "dem", "him", "yuh", "unu", "we", "she", "he", "dat", "dis", "me", "the",
                      "my", "her", "his", "them", "you"})

"""Scots, northern and Midlands English spellings of everyday English words, as typed or said in
Scotland, the north of England and the Black Country ("take 2 aff the rack", "bring it ben",
"switch aff aw the lights", "fae the bedside table", "divvent touch it", "dow bother"): each read
as the English word, by both readers, only where the word is no word of the world's names (a place
called "the Ben" stays that place) and, in the household reader, no English word itself."""
from __future__ import annotations

#: Scots word -> the English word the grammars have
SCOTS = {"fae": "from", "frae": "from", "tae": "to", "aff": "off", "oot": "out", "doon": "down", "wi": "with",
         "ower": "over", "ontae": "onto", "intae": "into", "oantae": "onto", "nae": "no", "mair": "more",
         "dinnae": "dont", "dinna": "dont", "cannae": "cant", "canna": "cant", "wullnae": "wont", "willnae": "wont",
         "shouldnae": "shouldnt", "disnae": "doesnt", "mustnae": "mustnt", "hae": "have", "nane": "none",
         "roon": "round", "whit": "what", "fower": "four", "twa": "two", "awa": "away", "efter": "after",
         "gonnae": "will", "ye": "you", "ma": "my", "bar": "except",
         # "bring my specs ben (the room)": through (to the other room); "that yin": that one
         "ben": "through", "yin": "one", "yins": "ones", "naebody": "nobody", "naw": "no", "wid": "would",
         "dae": "do", "masel": "myself", "auld": "old", "windae": "window", "hing": "hang", "hoose": "house",
         "anaw": "too", "aye": "yes",
         # Geordie and other northern English ("divvent touch it", "gan and put the light on", "hoy
         # it in the bin", "wor lass": our (my) wife, "yem": home, "nowt": nothing; "aal" (all) is
         # read before what it quantifies only: pipflow.household.language.dialect.scots_as_english)
         "divvent": "dont", "divvnt": "dont", "dinnet": "dont", "cannet": "cant", "gan": "go",
         "gannin": "going", "hoy": "throw", "yem": "home", "wor": "our", "neebody": "nobody",
         "nowt": "nothing", "owt": "anything", "summat": "something", "deein": "doing", "knaa": "know",
         "roond": "round",
         # Scouse ("the arl fella": the old man, her partner; "giz": give us; "youse": you, to more
         # than one; "bevvies": drinks)
         "arl": "old", "giz": "give", "youse": "you", "yous": "you",
         # Yorkshire ("put t'kettle on will tha", "shut it after thee": you; "it's nobbut adverts":
         # only; "nay": no; "reyt": right)
         "tha": "you", "thee": "you", "thy": "your", "nobbut": "only", "nay": "no", "reyt": "right",
         # Brummie and Black Country ("can yow get it out", "dow bother with butter": don't)
         "yow": "you", "dow": "dont"}

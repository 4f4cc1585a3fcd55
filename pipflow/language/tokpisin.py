"""Tok Pisin words said in Papua New Guinea English ("tekim 10 rais from the boat side", "put
wanpela more on the counter", "4 more rais plis", "goroka load counted pinis"): each read as the
English word the grammars have, by both readers, only where the word is no word of the world's names
or of the reader. Only words that are no English word are here, so an English command never reads
one of them; words whose reading depends on the words around them ("stap": is, or stay; "i", the
predicate marker; "em nau": that's it, or right now; "olsem": like so) are not, and stay unread.

Verbs take "-im" when they have an object (tekim, putim): the English verb. Numbers are counted
with "-pela" (wanpela, tupela): the English number, so "wanpela more" is one more."""
from __future__ import annotations

#: Tok Pisin word -> the English word
TOK_PISIN = {
    # courtesy and talk: "plis" (please), "tenkyu" (thank you), "orait" (all right), "hariap"
    # (hurry), "moning" (morning)
    "plis": "please", "tenkyu": "thanks", "orait": "alright", "hariap": "quickly", "moning": "morning",
    "apinun": "afternoon",
    # verbs with the object suffix "-im"
    "tekim": "take", "kisim": "take", "putim": "put", "karim": "carry", "bringim": "bring", "muvim": "move",
    "rausim": "remove", "givim": "give", "pulimapim": "fill",
    # numbers counted with "-pela"
    "wanpela": "one", "tupela": "two", "tripela": "three", "fopela": "four", "faivpela": "five",
    "sikispela": "six", "sevenpela": "seven", "etpela": "eight", "nainpela": "nine", "tenpela": "ten",
    # "pinis" after a verb says it is done ("counted pinis": counted already); "nogat" (no, none);
    # "maski" (never mind: takes back what was said, as "no" does);
    # "tumora" (tomorrow); "yumi" (we, the speaker with the one asked)
    "pinis": "already", "nogat": "no", "maski": "no",
    "tumora": "tomorrow", "yumi": "we",
    # "emi" (he, she or it is: "dont use binatang emi too slow"), written as one word of "em i"
    "emi": "its",
}

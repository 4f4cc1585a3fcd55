"""Content-free parts of a command: what may be set aside unread, and what never may.

People wrap an order in talk: a greeting ("Morning all"), thanks ("cheers"), a reason or an aside
("it's broken", "I'm off out"). A reader that must place every word refuses the whole command on
such a part, though it carries nothing the order needs. This module decides, for any domain,
whether a clause (a sentence, or a part of one set off by commas) is *content-free*: it names
nothing of the world, has no number and no **operative word**. Such a part is set aside, not
parsed, and the reader says so aloud (the echo lists it), so a user sees what was not read.

Operative words are the ones whose loss would change what is asked, even in a clause that names
nothing: negation ("not", "never", "nothing", "don't"), exclusivity ("only", "except", "but",
"unless", "instead"), bounds and comparison ("at least", "no more than", "above", "max"),
quantities and quantifiers ("all", "every", "both", "half", "rest", "another", "some"), and
repetition ("too", "also", "same", "again"); a word one edit or one swap away from one of them
("nto", "olny", "exept") is operative too. The domain adds its own: its world's names (and words
close to them: a misspelt name is never an aside), and its lexicon's content words (verbs such as
"move" or "empty"), which the domain reader passes in as ``operative``.

A greeting with its addressee ("Morning all", "Hi everyone") is the one place where a quantifier
is no quantifier: a clause that opens with a greeting word and has nothing but addressee words
after it is content-free. A clause that opens with a word that attaches it to the one before (a
preposition, "and", an article: "..., on the left", "..., the big ones") or that picks out which
things are meant ("those", "which") is never set aside: it would narrow the order, and dropping it
would widen what the robots do.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Callable, Iterable

from pipflow.language.english import common_word, dropped_g
from pipflow.language.numbers import NUMBER_WORDS
from pipflow.language.spelling import Slips

NEGATION = {"no", "not", "never", "nothing", "none", "nobody", "noone", "neither", "nor", "without", "dont",
            "doesnt", "didnt", "cant", "cannot", "wont", "shouldnt", "mustnt", "isnt", "arent", "nowhere",
            "n't", "nope",
            # northern English and Scots "nowt" (nothing): "gaffer does nowt tonight"
            "nowt", "naught"}
EXCLUSIVITY = {"only", "except", "excepting", "but", "besides", "apart", "unless", "instead", "alone", "solely",
               "exclusively", "else", "just", "other", "otherwise", "rather",
               # Yorkshire "nobbut" (only: "it's nobbut adverts")
               "nobbut"}
BOUNDS = {"least", "most", "max", "maximum", "min", "minimum", "more", "fewer", "less", "above", "below",
          "under", "over", "exceed", "exceeds", "between", "beyond", "within", "limit", "cap", "capped",
          "upto", "tops", "than", "enough", "full", "empty", "capacity", "exactly", "precisely"}
QUANTITIES = {"all", "every", "each", "both", "any", "some", "several", "few", "many", "much", "half",
              "halves", "double", "twice", "triple", "thrice", "dozen", "rest", "remaining", "remainder",
              "everything", "anything", "everyone", "everybody", "anyone", "anybody", "whole", "entire",
              "another", "either", "respectively", "apiece", "once", "single", "pair", "couple", "lot",
              "lots", "zero", "number", "amount", "count", "quarter", "third", "bit"}
REPETITION = {"too", "also", "same", "again", "likewise", "aswell", "back", "first", "then", "after",
              "before", "while", "until", "till", "or"}
#: words that pick out which things are meant ("those on the left", ", which ...", "the ones"):
#: a clause with one restricts the order it belongs to, even when it names nothing
SELECTION = {"those", "these", "ones", "one", "which", "whichever", "whose", "where", "wherever"}
#: the words that can never be set aside, whatever the domain
OPERATIVE = frozenset(NEGATION | EXCLUSIVITY | BOUNDS | QUANTITIES | REPETITION | SELECTION)
#: words that attach a clause to the one before ("..., from the top", "..., on the left"): such a
#: clause modifies what was said, so it is never talk to set aside
ATTACHING = frozenset({"from", "on", "in", "at", "to", "into", "onto", "off", "of", "with", "for", "by",
                       "under", "over", "near", "behind", "above", "below", "inside", "towards", "toward",
                       "via", "through", "and", "plus", "that", "the", "a", "an", "its", "their"})
#: English function words: pronouns, auxiliaries, articles, prepositions and conjunctions, and
#: the verbs of talk ("think", "know", "got"). A domain lexicon that has them as grammar words
#: does not make them content: alone, they say nothing an order needs ("it's broken", "I'm off out")
FUNCTION_WORDS = frozenset({
    "i", "im", "me", "my", "mine", "we", "us", "our", "you", "your", "yours", "it", "its", "they", "them",
    "their", "he", "him", "his", "she", "her", "this", "that", "these", "those", "there", "here", "what",
    "which", "who", "whom", "whose", "is", "am", "are", "was", "were", "be", "been", "being", "has", "have",
    "had", "having", "will", "would", "shall", "should", "can", "could", "may", "might", "must", "ought",
    "a", "an", "the", "of", "to", "from", "in", "on", "at", "for", "with", "by", "about", "off", "out", "up",
    "down", "into", "onto", "and", "so", "as", "if", "because", "since", "cause", "cuz", "coz", "well", "oh",
    "ah", "now", "today", "please", "yes", "yeah", "yep", "got", "get", "getting", "go", "going", "gone",
    "let", "lets", "think", "know", "see", "sure", "right", "really", "bother", "very", "still", "already", "yet",
    "when", "where", "how", "why", "like", "s", "ll", "ve", "d", "re", "m", "t"})
#: a word followed by one of these is a verb acting on a thing ("recount them"): an instruction
OBJECT_PRONOUNS = frozenset({"it", "them", "this", "that", "these", "those", "him", "her", "everything"})
#: words that open a greeting or a thanks; with nothing after them but addressees, the clause is talk
GREETINGS = frozenset({"hi", "hello", "hey", "hiya", "heya", "howdy", "morning", "afternoon", "evening", "good", "dear",
                       "greetings", "yo", "cheers", "thanks", "thank", "ta", "thx", "ok", "okay", "alright",
                       # South African greetings ("Howzit team", "Sawubona team", "Molo all")
                       "howzit", "sawubona", "molo", "dumela", "heita",
                       # French, said in English chat ("Bonjour l'équipe", "Salut tout le monde": with its addressee)
                       "bonjour", "salut", "merci",
                       # Swahili and Sheng, said in Kenyan English ("Sasa team", "Sawa team": OK, "Asante")
                       "sasa", "sawa", "poa", "jambo", "habari", "mambo", "niaje", "asante", "asanteni",
                       # Polish, said in English chat ("OK, dzięki": thanks; "cześć": hi)
                       "dzieki", "dziekuje", "czesc",
                       # Brazilian Portuguese ("bom dia pessoal": good morning, folks; "oi", "olá": hi)
                       "oi", "ola", "bom", "boa",
                       # Brummie goodbyes ("Tara bab", "ta-ra-a-bit": bye for now)
                       "tara", "tarra", "tarrar",
                       # Bemba and Nyanja, said in Zambian English ("Mwaiseni!": welcome; "shani": how
                       # are you; "natotela", "twatotela", "zikomo": thank you)
                       "mwaiseni", "shani", "natotela", "twatotela", "zikomo",
                       # Swedish ("hej", "hejsan", "tjena", "hallå": hi)
                       "hej", "hejsan", "tjena", "halla",
                       # Greek ("Re paidia": hey, kids; "kalimera")
                       "re", "kalimera", "kalispera",
                       # Indonesian ("pagi pak": morning; "selamat pagi")
                       "pagi", "selamat",
                       # Japanese ("Ohayo gozaimasu": good morning; "otsukaresama": thanks for the work)
                       "ohayo", "ohayou", "gozaimasu", "otsukaresama", "otsukare", "konnichiwa", "arigato",
                       "arigatou",
                       # Vietnamese ("anh em": brothers, the team, said to it; "chao": hello)
                       "anh", "chao",
                       # Urdu and Punjabi, said in Pakistani English ("AoA team": assalam-o-alaikum; "Jumma
                       # Mubarak everyone": a blessed Friday; "Eid Mubarak")
                       "aoa", "salam", "salaam", "assalam", "assalamualaikum", "asalamualaikum", "walaikum",
                       "jumma", "eid", "mubarak",
                       # Jamaican ("Wah gwaan unu": what's going on, you all)
                       "wah", "wha", "gwaan",
                       # Romanian ("Buna seara, ...": good evening; "salut baieti": hi, lads)
                       "buna", "seara", "ziua", "dimineata", "noapte",
                       # Australian ("G'day team", "Gday all")
                       "gday", "gidday",
                       # Maltese ("Bongu", "Bonġu": good morning; "bonswa": good evening; "grazzi": thanks)
                       "bongu", "bonswa", "grazzi",
                       # Shona, said in Zimbabwean English ("Mangwanani guys": good morning; "masikati":
                       # good afternoon; "manheru": good evening; "mhoro": hi; "ndatenda": thanks)
                       "mangwanani", "masikati", "manheru", "mhoro", "mhoroi", "makadini", "ndatenda",
                       # Yorkshire "ey up" (hello: :func:`is_greeting` reads its "up" with it), "eyup"
                       "ey", "eyup",
                       # Fijian, said in Fiji English ("Bula bro": hello; "ni sa bula"; "vinaka": thanks)
                       "bula", "vinaka"})
#: words that open an apology or a thanks for something ("sorry for the late ask", "thanks for
#: earlier"): what follows "for" / "about" is what one is sorry or thankful for, not an order
PLEASANTRIES = frozenset({"sorry", "apologies", "apologise", "apologize", "pardon", "thanks", "thank", "thx",
                          "ta", "cheers", "ty", "grateful", "appreciate", "appreciated", "dankie", "diolch", "merci",
                          "asante", "asanteni"})
#: words that open a statement about someone or something ("she's been dropping them", "it's broken"):
#: a verb acting on a pronoun after them reports what happened, it asks for nothing
SUBJECTS = frozenset({"i", "im", "ive", "we", "were", "weve", "he", "hes", "she", "shes", "it", "its", "they",
                      "theyre", "theyve", "there", "theres"})
#: who a greeting is said to ("Morning all", "Hi team")
ADDRESSEES = frozenset({"all", "everyone", "everybody", "team", "folks", "guys", "gang", "lads", "people",
                        "there", "you", "mate", "mates", "yall", "crew", "robots", "bots", "y", "again", "so",
                        "much", "very", "a", "lot", "in", "advance", "love", "loves", "dear", "dears", "darling",
                        "pet", "hun", "honey", "sweetie", "chaps", "pal", "pals", "buddy", "boys", "girls", "ladies",
                        # Tok Pisin "boi", "bois" (lads: "morning boi")
                        "boi", "bois",
                        "gents", "gentlemen", "kids", "sir", "madam", "friends", "colleagues", "staff", "squad",
                        # Welsh English ("Morning bud", "Alright butt")
                        "bud", "butt", "butty", "bach", "cariad",
                        # Scots and northern English ("Morning son", "ta hen"), and the young's "bro"
                        "son", "hen", "sunshine", "bro", "bruv", "dude",
                        # Nigerian English and Pidgin ("Good morning una": you all; "oga": boss), Guyanese
                        # and Trinidadian "allyuh" (you all: "Big day today allyuh!")
                        "una", "oga", "ogas", "allyuh",
                        # Kenyan English and Sheng ("Sawa wasee": OK guys; "mzee": elder, sir)
                        "boss", "wasee", "mzee",
                        # Mexican Spanish ("oye jefe", "gracias muchachos")
                        "jefe", "compa", "compas", "muchachos",
                        # Brazilian Portuguese ("bom dia pessoal", "boa noite galera": the day, the night, folks)
                        "dia", "tarde", "noite", "pessoal", "galera", "gente",
                        # Gulf Arabic, said in English on a floor in the Gulf ("habibi": my dear)
                        "habibi", "habibti",
                        # Greek ("re paidia": kids)
                        "paidia",
                        # Vietnamese ("anh em", "cac ban": you all)
                        "em", "cac", "ban",
                        # Urdu ("AoA bhai": brother; "ji": the polite particle; "sahab", "janab": sir; "yaar": mate)
                        "bhai", "bhaiya", "ji", "sahab", "sahib", "janab", "yaar",
                        # Jamaican ("Morning unu": you all; "bredda": brother; "mi bredren": friends)
                        "unu", "bredda", "breddah", "bredren", "sistren", "yute",
                        # Romanian ("frate": bro; "baieti", "baietii": lads; "bre": hey you; "colegi": colleagues)
                        "frate", "fratilor", "baieti", "baietii", "bre", "colegi",
                        # European Portuguese ("Bom dia pá": mate; "malta": folks)
                        "pa", "malta",
                        # Malay ("Abang, ...": brother; "bang", "kak": sister; "encik", "tuan": sir; "adik")
                        "abang", "bang", "encik", "tuan", "adik",
                        # Sinhala ("machan": mate; "malli": younger brother; "akka": older sister)
                        "machan", "machang", "malli", "akka",
                        # Trinidadian ("Evening allyuh": you all; "padna": partner; "Boy move ...": man) and
                        # Scouse ("youse": you all)
                        "allyuh", "alyuh", "padna", "pardna", "boy", "youse", "yous",
                        # Brummie and Midlands English ("Put the kettle on bab", "ta duck"), and
                        # Ugandan English's Luganda "sebo" (sir) and "nnyabo" (madam)
                        "bab", "babs", "duck", "sebo", "ssebo", "nnyabo"})


#: a thanks that can close an order without a comma before it ("... to bay 2 ta")
THANKS = frozenset({"thanks", "ta", "cheers", "xiexie", "thx", "ty", "tyvm", "thankyou", "dankie", "diolch", "merci", "asante",
                    "asanteni", "gracias", "dzieki", "dziekuje", "obrigada", "obrigado", "brigada", "brigado", "valeu",
                    "vlw",
                    # Urdu ("..., shukriya": thank you; "jazakallah": God reward you); Jamaican "tanks"
                    "shukriya", "shukria", "jazakallah", "tanks",
                    # Romanian ("mersi": thanks; "multumesc": thank you)
                    "mersi", "multumesc", "multam",
                    # Egyptian Arabic ("shokran": thanks)
                    "shokran", "shukran",
                    # Swedish ("tack", "tack så mycket": thanks)
                    "tack", "tackar",
                    # Maltese ("grazzi": thanks)
                    "grazzi",
                    # Fijian ("vinaka", "vinaka vakalevu": thank you very much)
                    "vinaka", "vakalevu"})
#: words that soften an order they close, and are a "no" anywhere else: Trinidadian "nah" ("add 4
#: more X to P nah": do it, nah; "nah wait, make it 6" takes back)
SOFTENERS = frozenset({"nah"})
#: who an order is said to, or a tag that closes it, without a comma before it ("... on dispatch
#: please mate", "... forklifts only mind", "... thanks lads"): never a word that is operative
CLOSERS = frozenset({"mate", "mates", "pal", "lads", "guys", "folks", "chaps", "boss", "love", "pet", "hun",
                     "son", "hen", "sunshine", "buddy", "bro", "bruv", "dude",
                     "mind", "yeah", "eh", "though", "cheers", "ta", "thanks", "thx", "ty", "tyvm", "thankyou",
                     "dankie",
                     "man", "bru", "boet", "chale", "bud", "butt", "butty", "bach", "cariad", "mun", "diolch", "merci",
                     "svp", "stp",
                     "asante", "asanteni", "bana", "mzee", "gracias", "jefe",
                     # Brummie and Midlands English ("..., bab", "... ta duck"); Ugandan English's
                     # Luganda "sebo" (sir), "nnyabo" (madam) and "bambi" (please)
                     "bab", "babs", "duck", "sebo", "ssebo", "nnyabo", "bambi",
                     # Zambian English's Bemba and Nyanja thanks ("..., natotela")
                     "natotela", "twatotela", "zikomo",
                     # Sri Lankan English ("..., machan"; "... to P already": at once, no report)
                     "machan", "machang", "already",
                     # Irish English ("..., deadly": great; "..., grma": thanks)
                     "deadly", "grma", "slainte",
                     # Cajun English ("..., cher", "chère", "sha": dear; "podna": partner)
                     "cher", "chere", "sha", "podna",
                     # Bahamian English ("..., bey": boy, man; "ya hear")
                     "bey",
                     # Trinidadian English ("..., padna", "allyuh")
                     "padna", "allyuh",
                     # Scouse ("..., la": lad; "..., ta la")
                     "la", "lad",
                     # Maltese ("..., grazzi": thanks; "ċaw", "saħħa": bye; "ħabib": friend; "insomma": anyway)
                     "grazzi", "caw", "sahha", "habib", "habiba", "insomma",
                     # Brazilian Portuguese: thanks, "OK?" ("..., beleza?"), laughter
                     "obrigada", "obrigado", "valeu", "vlw", "beleza", "blz", "rsrs", "kkk", "kkkk", "kkkkk",
                     "valew", "galera", "pessoal", "rapidinho", "agora", "pfv", "pf",
                     # Gulf Arabic ("..., yalla habibi", "..., inshallah", "khalas": done)
                     "habibi", "habibti", "yalla", "inshallah", "khalas", "shukran",
                     # Vietnamese particles closing a request ("..., nha", "... nhé": OK?, please), and
                     # "giúp anh" (help me: said by an older brother), "giúp tôi", "giúp mình"
                     "nha", "nhe", "nhen", "giup", "anh", "toi", "minh",
                     # Turkish ("..., hadi": come on; "acil": urgent; "abi", "hocam": said to the reader)
                     "hadi", "acil", "abi", "abla", "hocam", "tamam", "bakalim", "insallah",
                     # Russian in Latin letters ("..., davai": come on; "bratan": bro; "spasibo": thanks)
                     "davai", "bratan", "spasibo", "srochno",
                     # Japanese ("..., hai": yes; "arigato": thanks; "sumimasen": excuse me)
                     "hai", "arigato", "arigatou", "sumimasen",
                     # Greek ("..., efharisto": thanks; "endaxi?": OK?; "parakalo": please)
                     "efharisto", "efcharisto", "endaxi", "entaxi", "parakalo",
                     # Flemish ("..., seffens": right away; "dank u", "merci": thanks; "amai", "voilà")
                     "seffens", "amai", "voila", "allez",
                     # Italian ("..., grazie": thanks; "subito": at once; "dai": come on; "mannaggia": dismay)
                     "grazie", "subito", "dai", "mannaggia", "allora",
                     # Indonesian ("..., makasih": thanks; "wkwk": laughter; "pak", "kak", "bu": to the reader)
                     "makasih", "wkwk", "wkwkwk", "pak", "kak", "bu", "siap",
                     # Colombian Spanish ("..., parce": mate; "..., listo?": OK?)
                     "parce", "parcero", "listo",
                     # Québec French ("..., câline": darn; "..., tsé": you know; "..., genre": like)
                     "caline", "tse", "genre",
                     # Mandarin in pinyin ("..., xie xie": thanks; "hao de": OK; "mei wenti": no problem;
                     # "kuai dian": hurry)
                     "xie", "xiexie", "hao", "de", "mei", "wenti", "kuai", "dian",
                     # Thai ("..., kob khun ka": thank you; "jing jing": really; "na", "ka", "krub": polite
                     # particles)
                     "kob", "khun", "jing", "na", "ka", "kha", "krub", "khrub", "krap", "khrap", "jaa",
                     # German ("..., bitte": please; "danke": thanks; "genau": exactly; "los": go)
                     "bitte", "danke", "genau", "jawohl", "los", "schnell",
                     # Spain's Spanish ("..., vale?": OK?; "venga": come on; "tío": mate)
                     "vale", "venga", "tio", "tia", "hombre", "ostras",
                     # Urdu ("..., yaar": mate; "ji": the polite particle; "shukriya": thanks; "inshallah")
                     "yaar", "ji", "shukriya", "shukria", "jazakallah", "inshallah", "inshaallah",
                     # Jamaican ("..., bless": take care; "respect"; "seen?": understood?; "eeh": OK?;
                     # "tanks": thanks)
                     "bless", "respect", "seen", "eeh", "tanks",
                     # Romanian ("..., gata": done, that's it; "mersi": thanks; "frate", "bre": mate; "pa": bye)
                     "gata", "mersi", "multumesc", "frate", "bre", "pa",
                     # Swedish ("..., tack": thanks; "hej då", "hejdå": bye)
                     "tack", "hejda"})


#: words only ever said to the one asked ("..., love", "bab, ...", "Sebo, ..."): who is greeted and
#: who an order closes on, never a word that may be operative ("all", "so", "again" are greeted too)
VOCATIVES = frozenset(w for w in ADDRESSEES & CLOSERS if w.isalpha() and w not in OPERATIVE)

#: a request tag after an order ("... over to the shed would ya", "... could you"): it asks
#: nothing more than the order does
REQUEST_TAGS = frozenset((modal, you) for modal in ("would", "could", "will", "can", "wont")
                         for you in ("you", "ya", "u", "yous")) | {("isnt", "it")} \
    | {(you, "hear") for you in ("you", "ya", "yuh", "yu")}   # Welsh English's tag on anything; Jamaican "yuh hear?"
#: the words of a thanks or a request tag, which are no operative words there
_TAG_WORDS = frozenset(w for tag in REQUEST_TAGS for w in tag) | {"thank", "you"}


def trailing_thanks(words: list[str], content: Callable[[str], bool]) -> int:
    """How many words at the end of a clause are a thanks, a closing word or a request tag said
    without a comma ("... to bay 2 ta", "... thank you", "... please mate", "... only mind", "...
    would ya"): they are set aside like a thanks set off by one. 0 when there is none, when it is
    the whole clause (then the clause itself is talk), or when a word of it carries content in
    this domain (a name that happens to be "ta") or is operative."""
    rest, k = list(words), 0
    while rest and (rest[-2:] == ["thank", "you"] or tuple(rest[-2:]) in REQUEST_TAGS or rest[-1] in CLOSERS
                    or rest[-1] in SOFTENERS):
        n = 2 if rest[-2:] == ["thank", "you"] or tuple(rest[-2:]) in REQUEST_TAGS else 1
        rest, k = rest[:-n], k + n
    said = words[-k:] if k else []
    if k == 0 or k >= len(words) or any(content(w) or (w not in THANKS | SOFTENERS and w not in _TAG_WORDS and near_operative(w)
                                                       and not _inside_talk(said, n)) for n, w in enumerate(said)):
        return 0
    return k


def trailing_vocatives(words: list[str], names: Callable[[str], bool]) -> int:
    """How many words closing a clause are said to the one asked (:data:`VOCATIVES`: "put the gas
    fire on bab, and ...", "..., pass me the mail love, then ..."), where a thanks or tag may close
    only the last clause (:func:`trailing_thanks`): a word said to someone asks nothing wherever it
    stands. 0 when there is none, when it is the whole clause or a word names the world."""
    k = 0
    while k < len(words) - 1 and words[-1 - k] in VOCATIVES and not names(words[-1 - k]):
        k += 1
    return k


def _inside_talk(run: list[str], n: int) -> bool:
    """Whether the closing word at ``n`` of ``run`` has after it a closing word that is no slip of
    an operative word ("giúp anh nhé": "anh" looks like "and", but "nhé" after it makes the run talk)."""
    return any(w in CLOSERS and not near_operative(w) for w in run[n + 1:])


#: words that open an adjunct of purpose, time or reason at the end of a clause ("... for afternoon
#: pickup", "... before the coach turns up", "... by opening time", "... because we're short"): the
#: adjunct is set aside when nothing after its opening word carries content (:func:`trailing_adjunct`).
#: "before", "after", "until", "till" and "while" are operative elsewhere (they order things); here
#: only as the opening word, and never before a pronoun or "then" ("before that" orders the
#: command's own parts). Not "but", "except", "so", "and", "or", "then": they join or restrict.
ADJUNCTS = frozenset({"for", "before", "after", "by", "until", "till", "once", "when", "while", "because",
                      "since", "as", "cause", "cos", "coz", "cuz", "ahead", "b4"})
#: adjunct openings of time: what follows says when ("before the van comes", "ahead of the count"),
#: its verb describes
TEMPORAL = frozenset({"before", "after", "until", "till", "when", "once", "while", "by", "ahead", "b4"})   # "b4": texted
#: adjunct openings of purpose and reason: what follows says what for ("for the Hadleys order"), and
#: a word of the grammar in it ("order", "delivery") orders nothing
PURPOSIVE = frozenset({"for", "because", "cause", "cos", "coz", "cuz"})
#: the robots, addressed: a clause of time said to them orders the work ("before you move them")
_YOU = frozenset({"you", "your", "u", "ya", "ye", "yous", "youse"})
#: words after an adjunct's opening word that point back at the order itself ("for this", "before that")
_BACK = OBJECT_PRONOUNS | {"then", "now", "which"}
#: of those, the ones that pick out what follows them when something does ("for that pickup")
_DEMONSTRATIVES = frozenset({"that", "this", "those", "these"})


def trailing_adjunct(words: list[str], content: Callable[[str], bool],
                     names: Callable[[str], bool] | None = None) -> int:
    """How many words at the end of a clause that carries content are an adjunct of purpose, time
    or reason that carries none ("... on the ramp for afternoon pickup"): it opens with a word of
    :data:`ADJUNCTS`, and no word after it is operative (:func:`near_operative`, opening words of
    further adjuncts aside), a number, a name of the world or a content word of the domain
    (``content``); 0 when there is none. The earliest such opening word is taken (the adjunct may
    hold several: "for pickup before lunch"); the words before it must still carry content.

    A clause of time or purpose ("before the van comes", "until we open", "for the Hadleys order"):
    with ``names`` (only names of the world and numbers) its words may be words of the grammar
    ("comes", "order"), since they say when or what for,
    unless it is said to the robots or about the order's things ("before you ...", "after it
    ..."). A time of day is a number ("before 2pm", "at nine"): never set aside."""
    for j in range(1, len(words) - 1):
        # "before that": the order itself; "before that truck gets here": "that" picks the truck
        picks = words[j + 1] in _DEMONSTRATIVES and j + 2 < len(words)
        if words[j] not in ADJUNCTS or (words[j + 1] in _BACK and not picks):
            continue
        rest = words[j + 2:] if picks else words[j + 1:]
        carries = content
        if words[j] in TEMPORAL | PURPOSIVE and names is not None and not (set(rest) & (OBJECT_PRONOUNS | _YOU)):
            carries = names
        if any(carries(w) or any(ch.isdigit() for ch in w) or (near_operative(w) and w not in ADJUNCTS)
               for w in rest):   # "for 2pm collection": a time is a number, never talk
            continue
        if any(w in ADJUNCTS and nxt in _BACK for w, nxt in zip(rest, rest[1:] + [""])):
            continue
        if words[j] in TEMPORAL and words[j - 1] == "for":   # "for when she wakes up": what for, a time
            j -= 1
        if not any(content(w) or near_operative(w) for w in words[:j]):
            return 0   # the clause is talk as a whole, or nothing: judged as a clause
        return len(words) - j
    return 0


#: the speaker, whose wish may follow a fronted purpose ("for the Lidl order I need ...")
_SPEAKER = frozenset({"i", "we", "im", "id", "ill", "ive"})


def leading_adjunct(words: list[str], content: Callable[[str], bool], names: Callable[[str], bool]) -> int:
    """How many words open a clause as a purpose that carries nothing: "for the order of Pingo Doce
    I need ...", "For the Auchan the dock takes ...", "For the inventory: ..." (a client or an
    occasion said first, as Portuguese and Spanish front "para"). It is "for", then words none of
    which is operative, a number, a name of the world (``names``: the words of the grammar may say
    what for: "order", "count") or a pronoun that points at the order's things or the robots, up to
    the first name of the world (with the determiner before it) or the speaker ("I", "we"); the
    words after it must carry content (``content``). The whole clause when no such word comes: a
    heading set off by its mark. 0 when the clause opens otherwise."""
    if len(words) < 2 or words[0] != "for":
        return 0
    j = 1
    while j < len(words) and not names(words[j]) and words[j] not in _SPEAKER:
        j += 1
    while 1 < j < len(words) and words[j - 1] in DETERMINERS:
        j -= 1
    said = words[1:j]
    if not said or said[0] in _BACK or any(
            names(w) or any(ch.isdigit() for ch in w) or w in _YOU or w in OBJECT_PRONOUNS or near_operative(w)
            for w in said):
        return 0
    if j < len(words) and not any(content(w) or near_operative(w) for w in words[j:]):
        return 0
    return j


@dataclass(frozen=True)
class Clause:
    """A stretch of a command between clause marks: its words and where they are."""

    start: int
    end: int            # one past the last word
    words: tuple[str, ...]


#: the operative words of three letters or more, for finding a slip of one by lookup
_OPERATIVE_SLIPS = Slips(o for o in OPERATIVE if len(o) >= 3)


def near_operative(word: str) -> bool:
    """An operative word, or one slip from one (:func:`pipflow.language.spelling.slip`: "nto",
    "olny", "exept", "onlu"): a misspelt "not" or "only" must never be read as talk."""
    if word in OPERATIVE:
        return True
    if word in FUNCTION_WORDS or word in INTERJECTIONS:   # a word in its own right: "the" is no slip of
        return False                                      # "then", "on" none of "no", "shame" none of "same"
    slips = _OPERATIVE_SLIPS.of(word) if len(word) >= 3 else set()
    # a common word written as itself ("big") is no slip of a quantity ("bit"); a slip that would
    # say no, only or except is always taken as one ("nit", "nor" for "not")
    if slips and common_word(word) and not slips & (NEGATION | EXCLUSIVITY):
        return False
    return bool(slips)


def is_greeting(words: Iterable[str]) -> bool:
    """ "Morning all", "hi team", "thanks so much", "hej again": a greeting word, then only
    addressees (and "again" last: greeted a second time, nothing done again). Yorkshire "ey up" is
    one greeting of two words ("Ey up lads")."""
    ws = [w for w in words if w]
    if ws[:2] == ["ey", "up"]:
        ws = ws[:1] + ws[2:]
    rest = ws[1:-1] if len(ws) > 1 and ws[-1] == "again" else ws[1:]
    return bool(ws) and (ws[0] in GREETINGS or dropped_g(ws[0]) in GREETINGS) \
        and all(w in ADDRESSEES or w in GREETINGS for w in rest)   # "mornin all"


#: how warmly thanks are said ("thank you ever so much", "thanks very much"): no quantity of anything
_WARMLY = (("ever", "so", "much"), ("so", "much"), ("very", "much"))


def is_pleasantry(words: Iterable[str], names: Callable[[str], bool]) -> bool:
    """ "sorry for the late ask", "thanks for earlier", "thank you ever so much", "many thanks in
    advance": an apology or thanks,
    then only what it is for. Words of the grammar may follow ("ask", "earlier"): they say what
    one is sorry for, not what to do; a name of the world, a number (``names``) or an operative
    word may not ("thanks, and not on bay 2" is no pleasantry)."""
    ws = [w for w in words if w]
    ws = ws[1:] if ws[:1] == ["and"] or ws[:2] == ["many", "thanks"] else ws   # "and sorry for ...", "many thanks"
    if not ws or ws[0] not in PLEASANTRIES:
        return False
    rest = ws[2:] if ws[:2] == ["thank", "you"] else ws[1:]
    warmly = next((w for w in _WARMLY if rest[:len(w)] == list(w)), ())
    rest = rest[len(warmly):]
    if rest and rest[0] not in ("for", "about", "again", "so", "very", "a", "lot", "all", "everyone", "team", "in",
                                "to"):   # "sorry to bother you"
        return False
    return not any(near_operative(w) and w not in ADDRESSEES for w in rest) and not any(names(w) for w in rest)


#: forms of "be" after a subject ("it is", "they're" split as "they re")
_BE = frozenset({"is", "are", "am", "was", "were", "s", "re", "m", "be", "been", "being"})
#: subjects with "be" already in them ("it's" read as "its", "he's", "they're")
_SUBJECT_BE = frozenset({"its", "hes", "shes", "theyre", "im", "youre", "thats", "theres"})


#: verbs of wanting, modals and "please": a clause with one asks for something ("we want it
#: cleared", "they must go in the cooler", "I'd like it emptied"), so it is never a report
ASKING = frozenset({"want", "wants", "wanted", "need", "needs", "needed", "like", "wish", "would", "should",
                    "must", "shall", "will", "can", "could", "ought", "gotta", "let", "lets", "d", "ll", "please",
                    "sure", "mind", "have", "has", "got", "wanna", "needa", "hafta"})
#: words of time that may come before a report's subject ("tomorrow we wash it with vinegar")
WHEN = frozenset({"today", "tomorrow", "tonight", "yesterday", "later", "earlier", "lately", "recently"})


#: words that open a noun phrase subject ("the auditors are in", "her wheel's squeaking")
DETERMINERS = frozenset({"the", "a", "an", "her", "his", "their", "my", "our", "your"})
#: finite verbs a noun phrase subject is followed by in a statement ("... are in", "... keep drumming")
FINITE = frozenset({"is", "are", "was", "were", "s", "re", "keep", "keeps", "has", "have", "had"})
#: words for robots in general: a statement about them ("the strongest robot is busy") may be a
#: rule said as a fact, so it is never set aside
ROBOT_WORDS = frozenset({"robot", "robots", "bot", "bots", "agent", "agents", "strongest", "weakest", "fastest",
                         "slowest", "biggest", "smallest", "heaviest", "lightest"})


def is_statement(words: Iterable[str], names: Callable[[str], bool]) -> bool:
    """ "..., he make a strange noise", "..., tomorrow we wash it with vinegar", "..., the auditors
    are in", "..., her wheel's squeaking", "..., is broken": a clause whose subject is a pronoun
    other than "you", a noun phrase followed by "is / are / keep / has" within three words (after a
    word of time, if any), a noun with a verb that lacks its -s (:data:`_BARE_VERBS`), or no
    subject at all before "is / are / was / were", says what is or will be so; it asks for nothing
    (an order to the robots is an imperative, or is said to "you"). The words of the grammar in it
    describe ("make", "wash", "keep"). Kept in,
    and read, when it names anything of the world or a number (``names``), holds an operative word,
    a word of wanting or a modal (:data:`ASKING`: "we want it cleared", "they must go in salt", "it
    has to go"; "has" and "got" alone say what someone has) or a
    word for robots (:data:`ROBOT_WORDS`: "the strongest robot is busy" is a rule)."""
    ws = [w for w in words if w]
    while ws and ws[0] in WHEN:
        ws = ws[1:]
    if len(ws) < 2:
        return False
    pronoun = ws[0] in (SUBJECTS | _SUBJECT_BE) - {"there", "theres", "youre"}
    noun = ws[0] not in FINITE and ws[0] not in FUNCTION_WORDS - DETERMINERS and any(
        w in FINITE or (w.endswith("ing") and len(w) > 4 and ws[0] in DETERMINERS) for w in ws[1:5])
    # "..., is broken": its subject left out, as Polish, Spanish and Italian speakers leave it
    dropped = ws[0] in ("is", "are", "was", "were") and ws[1] not in ("there", "it", "this", "that")
    # "..., service come Monday", "..., auditor from customer come": a noun and a verb without its -s
    bare = any(w in _BARE_VERBS for w in ws[1:4]) and ws[0] not in FUNCTION_WORDS | _BARE_VERBS | _BEFORE_ORDERS
    if not (pronoun or noun or dropped or bare or _past_of_a_noun(ws) or _bare_progressive(ws)):
        return False
    return _asks_nothing(ws, names)


#: verbs a noun subject may have without the -s of the third person, as learners of English say
#: them ("the driver come at 6", "the customer want it so"): a statement, never an order
_BARE_VERBS = frozenset({"come", "go", "arrive", "say", "send", "wait", "call", "ask", "complain", "order",
                         "check", "count", "know", "think", "want", "like", "leave"})


#: verbs in the past tense that do not end in "-ed" ("the labels got mixed up", "the truck came")
PAST_FORMS = frozenset({"got", "came", "went", "broke", "fell", "ran", "said", "left", "took", "made", "did",
                        "forgot", "told", "gave", "saw", "knew", "thought", "brought", "bought", "wore", "tore"})


#: verbs that take an "-ing" word after them as their object ("stop sending", "keep moving"): an
#: order, never a noun said with what it is doing
_ING_TAKERS = frozenset({"stop", "quit", "avoid", "keep", "start", "finish", "try", "begin", "continue", "resume",
                         "consider", "mind", "go", "get", "need", "needs", "want", "wants", "like", "love", "hate",
                         "prevent", "risk", "delay", "postpone", "practise", "practice", "imagine", "enjoy"})


def _bare_progressive(ws: list[str]) -> bool:
    """ "truck coming at 4 pm", "Shoprite collecting just now", "Friday fish fry orders coming in":
    a noun (of several words, the last a plural) and a verb in -ing with no "is" between (as South
    African, Indian and Jamaican English drop it), reporting what is going on. Never
    with a pronoun object in the clause ("stop sending them") or after a verb that takes an -ing
    object (:data:`_ING_TAKERS`)."""
    if set(ws) & OBJECT_PRONOUNS:
        return False
    for j in range(1, min(len(ws), 5)):
        if not (ws[j - 1].isalpha() and ws[j - 1] not in FUNCTION_WORDS and ws[j - 1] not in _ING_TAKERS):
            return False
        if ws[j].endswith("ing") and len(ws[j]) > 4:
            # a noun of several words only where its last is a plural ("fish fry orders coming in"):
            # an order opens with its verb, never with a plural
            return j == 1 or (ws[j - 1].endswith("s") and not ws[j - 1].endswith("ss") and len(ws[j - 1]) > 3)
    return False


def _past_of_a_noun(ws: list[str]) -> bool:
    """ "spinners cleaned us out", "the labels got mixed up", "the truck came early": a noun said
    as a subject (after a determiner, or a plural: an order opens with its verb, never a plural)
    and then a verb in the past tense, which reports what happened."""
    k = 1 if ws[0] in DETERMINERS else 0
    if len(ws) < k + 2:
        return False
    noun, verb = ws[k], ws[k + 1]
    if len(ws) >= k + 3 and noun.isalpha() and noun not in FUNCTION_WORDS and verb.isalpha() \
            and verb not in FUNCTION_WORDS and _past(ws[k + 2]):
        return True   # a noun of two words: "Ceat vehicle reached early", "the Lakeba order changed again"
    subject = noun.isalpha() and noun not in FUNCTION_WORDS and (k == 1 or (noun.endswith("s") and len(noun) > 3
                                                                         and not noun.endswith("ss")))
    return (subject and _past(verb)) or _placed_noun_past(ws, k)


#: prepositions that say where a noun is or comes from, after the noun ("customer in Laredo")
_NOUN_PLACES = frozenset({"in", "from", "at", "of", "near"})


def _placed_noun_past(ws: list[str], k: int) -> bool:
    """ "customer in Laredo rejected them", "the truck from Saltillo arrived early": a noun, where
    it is or comes from (a preposition and one or two words, an article allowed), then a verb in
    the past tense: a report of what happened, as people writing English as a second language say
    it without an article. An order opens with its verb, never with a noun and where it is."""
    noun = ws[k]
    if not (noun.isalpha() and noun not in FUNCTION_WORDS and len(ws) > k + 3 and ws[k + 1] in _NOUN_PLACES):
        return False
    words = [w for w in ws[k + 2:k + 5] if w not in DETERMINERS]
    return any(_past(words[j]) and all(w.isalpha() and w not in FUNCTION_WORDS for w in words[:j])
               for j in (1, 2) if j < len(words))


def _past(word: str) -> bool:
    """A verb in the past tense: of :data:`PAST_FORMS`, or in "-ed" (five letters or more)."""
    return word in PAST_FORMS or (word.endswith("ed") and len(word) > 4)


def _asks_nothing(ws: list[str], names: Callable[[str], bool]) -> bool:
    """No operative word (:func:`_operative_at`), name, number, word of wanting or word for robots
    in a statement: it says what is so, and asks for nothing. An "again" closing it says that what
    it reports happened once more ("the truck is late again"), no repeat of an order."""
    while len(ws) > 2 and ws[-1] in INTERJECTIONS:   # "... late again eish"
        ws = ws[:-1]
    ws = ws[:-1] if len(ws) > 2 and ws[-1] == "again" else ws
    return not any(_operative_at(ws, k) or names(w) or _asks(ws, k) or w in ROBOT_WORDS for k, w in enumerate(ws))


#: words that say where, not how many, before "there" / "here" ("the lads are relaying concrete
#: under there", "it's over here"): no bound in a statement
_WHERE_BEFORE_THERE = frozenset({"under", "over", "above", "below", "beyond"})


#: times of day and days, after which "before" / "after" / "until" say when, ordering nothing of
#: the order ("the truck is coming before lunch")
TIMES_SAID = frozenset({"lunch", "lunchtime", "noon", "midday", "midnight", "tonight", "tomorrow", "morning",
                        "afternoon", "evening", "dinner", "breakfast", "teatime", "closing", "monday", "tuesday",
                        "wednesday", "thursday", "friday", "saturday", "sunday", "weekend",
                        # breaks of a shift: Australian "smoko", Swedish "fika"
                        "smoko", "fika", "break", "lunchbreak", "brekkie"})


#: spans of time after "all" ("it's been on all night", "all the time"): how long, no quantity
DURATIONS = frozenset({"day", "night", "week", "weekend", "month", "year", "morning", "afternoon", "evening",
                       "summer", "winter", "time"})


#: words an order may open with before its verb ("please send ...", "just go ..."): never a subject
_BEFORE_ORDERS = frozenset({"please", "pls", "plz", "kindly", "just", "also", "then", "now", "so", "and", "quickly",
                            "u", "you", "ya", "yall", "guys", "team", "everyone", "somebody", "someone"})


#: units of time after a number ("waiting 40 min", "in 20 minutes"): how long, never a count of things
TIME_UNITS = frozenset({"min", "mins", "minute", "minutes", "sec", "secs", "second", "seconds", "h", "hr", "hrs",
                        "hour", "hours", "day", "days", "week", "weeks"})


def duration_at(ws: list[str], k: int) -> bool:
    """Whether the word at ``k`` is the number or the unit of a span of time ("40 min")."""
    if ws[k] in TIME_UNITS:
        return k > 0 and _count_word(ws[k - 1])
    return k + 1 < len(ws) and ws[k + 1] in TIME_UNITS and _count_word(ws[k])


def _count_word(w: str) -> bool:
    """A number in digits or words, or a reader's stand-in for one (the warehouse reader's marks)."""
    return w.isdigit() or w in NUMBER_WORDS or w in ("\1", "\2")


def _just_now(ws: list[str], k: int) -> bool:
    """Whether the word at ``k`` is the "just" of "just now", a time (South African: later; British:
    a moment ago), neither "only" nor a word of a domain's grammar."""
    return ws[k] == "just" and k + 1 < len(ws) and ws[k + 1] == "now"


def _operative_at(ws: list[str], k: int) -> bool:
    """:func:`near_operative` of the word at ``k``, except a word of :data:`_WHERE_BEFORE_THERE`
    before "there" or "here", a word of :data:`TEMPORAL` before a time (:data:`TIMES_SAID`),
    "all" before a span of time (:data:`DURATIONS`: "all night", "all the time") or "over" ("all
    over the floor": everywhere), and "last" or
    "next" before one (:data:`_SPANS`: "last week", "last time")."""
    nxt = ws[k + 1] if k + 1 < len(ws) else None
    if ws[k] in _WHERE_BEFORE_THERE and nxt in ("there", "here"):
        return False
    if ws[k] in TEMPORAL and nxt in TIMES_SAID:
        return False
    if _just_now(ws, k):
        return False
    if ws[k] == "all" and (nxt in DURATIONS or (nxt == "the" and k + 2 < len(ws) and ws[k + 2] in DURATIONS)):
        return False
    if _all_over(ws, k):
        return False
    if ws[k] in ("last", "next") and nxt in _SPANS:   # "last week it hit the fence": when, no selection
        return False
    if _the_same_as_subject(ws, k):
        return False
    if _degree_at(ws, k):
        return False
    if k == 0 and ws[0] in ("those", "these") and nxt in ("are", "were", "re", "is") and len(ws) > 2:
        return False   # "..., those are booked for the other party": the subject of a report, no selection
    if k == 0 and ws[0] == "that" and nxt in ("is", "s", "was") and len(ws) > 2:
        return False   # "..., that's for the sandwich place": the subject of a report, no slip of "than"
    if k < 2 and k < _demonstrative_subject(ws):   # the subject is at most "that one"
        return False   # "..., that one bruk", "..., those dent up": said of the things just named
    if ws[k] in SOFTENERS and nxt in ("wait", "scratch", "sorry", "hold"):
        return True    # "nah wait", "nah scratch that": a taking back, as "no wait" is
    return near_operative(ws[k])


def _all_over(ws: list[str], k: int) -> bool:
    """Whether the word at ``k`` is of "all over" ("grease all over my phone": everywhere on it),
    neither a quantity nor a bound."""
    return (ws[k] == "all" and k + 1 < len(ws) and ws[k + 1] == "over") or \
        (ws[k] == "over" and k > 0 and ws[k - 1] == "all")


#: what a demonstrative opening a report may be said with ("that one", "those ones")
_ONES = frozenset({"one", "ones"})
#: words that make a clause after a demonstrative an order's tail, never a report of its state
#: ("..., those as well", "..., that one too", "..., those please")
_TAIL_WORDS = frozenset({"well", "too", "also", "aswell", "please", "pls", "plz", "again", "instead", "first", "then",
                         "now", "later"})


def _demonstrative_subject(ws: list[str]) -> int:
    """How many words open ``ws`` as the subject of what is said of the things just named ("...,
    that one bruk", "..., those dent up", "..., this one is cracked": a demonstrative, with "one" or
    "ones"; "that" before "is": "..., that's reserved for the pickup"), with a word of their state
    after it and no word of an order's tail (:data:`_TAIL_WORDS`); 0 where none does. The words
    after it are judged as any clause's."""
    n = 2 if len(ws) > 1 and ws[0] in ("that", "this", "those", "these") and ws[1] in _ONES else \
        1 if ws and ws[0] in ("those", "these") else \
        1 if len(ws) > 2 and ws[0] == "that" and ws[1] in ("is", "s", "was") else 0   # "..., that's for P"
    rest = [w for w in ws[n:] if w not in _BE]
    said = bool(rest) and any(w.isalpha() and w not in FUNCTION_WORDS for w in rest) and not set(rest) & _TAIL_WORDS
    return n if said else 0


#: words "too" says the degree of, that are operative alone ("too much", "too full")
_DEGREED = frozenset({"much", "many", "few", "little", "full", "empty"})


def _degree_at(ws: list[str], k: int) -> bool:
    """Whether the word at ``k`` is the "too" of a degree ("is too full there", "too heavy for
    them", "too much there": a reason, no "also") or the word it grades ("much" of "too much").
    "too" closing a clause, or before "please" or a thanks ("this too please"), is "also"."""
    if k and ws[k - 1] == "too" and ws[k] in _DEGREED:
        return True
    nxt = ws[k + 1] if k + 1 < len(ws) else ""
    return ws[k] == "too" and (nxt in _DEGREED or (
        nxt.isalpha() and common_word(nxt) and nxt not in FUNCTION_WORDS | CLOSERS | THANKS | PLEASANTRIES
        and nxt not in INTERJECTIONS and nxt not in ("please", "pls", "plz")))


def _the_same_as_subject(ws: list[str], k: int) -> bool:
    """ "..., the same is blocking the roller door", "..., the same has a battery issue": "the
    same" opening a report is the thing just named (Kenyan and Indian English), no repetition. Only
    before "is/are/was/were" and a verb in -ing, or "has/had" not followed by "to": "the same goes
    for bay 2" or "the same is needed on shelf 2" repeat an order, and stay operative."""
    if ws[k] != "same" or k != 1 or ws[0] != "the" or len(ws) < 4:
        return False
    verb, after = ws[2], ws[3]
    return (verb in ("is", "are", "was", "were") and after.endswith("ing") and len(after) > 4) or \
        (verb in ("has", "had") and after != "to")


#: words of :data:`ASKING` that ask only before "to" ("has to go", "got to have"); elsewhere they
#: say what someone has ("he's still got a dodgy wheel")
_HAVING = frozenset({"have", "has", "got"})


def _asks(ws: list[str], k: int) -> bool:
    """Whether the word at ``k`` is a word of wanting or a modal (:data:`ASKING`)."""
    if ws[k] in _HAVING:
        return k + 1 < len(ws) and ws[k + 1] == "to"
    return ws[k] in ASKING


def is_report(words: Iterable[str], names: Callable[[str], bool]) -> bool:
    """ "it is getting serviced", "its wheel is playing up", "we're re-laying the floor": a subject,
    a form of "be" and a verb in -ing (within three words), reporting what is going on: the words of
    the grammar in it describe, they ask for nothing ("serviced", "wheel"). A name of the world, a
    number (``names``) or an operative word ("it's not coming", "they're only ...") keeps it in.
    Any other statement of a pronoun subject: :func:`is_statement`."""
    ws = [w for w in words if w]
    if is_statement(ws, names):
        return True
    if len(ws) >= 3 and ws[0] in ("that", "this") and ws[2] in _BE | {"got", "has", "had"} \
            and not near_operative(ws[1]) and not names(ws[1]):
        # "..., that order got cut", "..., this lot's ... ": a remark about a thing (a demonstrative,
        # a noun, then "be" or "got"); "..., that came in today" (a verb after "that") is no remark
        return not any(near_operative(w) or names(w) for w in ws)
    if len(ws) < 2 or not (ws[0] in SUBJECTS or ws[0] in _SUBJECT_BE):
        return False
    head = ws[:5]
    has_be = ws[0] in _SUBJECT_BE or any(w in _BE | {"keep", "keeps"} for w in head[1:4])
    if not has_be or not any(w.endswith("ing") and len(w) > 4 for w in head[1:5]):
        return False
    return not any(_operative_at(ws, k) or names(w) for k, w in enumerate(ws))


#: verbs an "-ing" after them may complete ("start loading", "keep going"): an order, no subject
_ASPECT_VERBS = frozenset({"start", "stop", "keep", "begin", "finish", "continue", "quit", "try", "go", "get",
                           "avoid", "resume"})


def is_bare_report(words: Iterable[str], content: Callable[[str], bool], names: Callable[[str], bool]) -> bool:
    """ "Saturday rush coming", "customs officer coming to check it", "dem painting the shop floor
    tomorrow": what is going on, said without "be" as Caribbean, Fiji and Singapore English (and
    people typing fast) say it. The subject is a pronoun, or one to three words (after an article or
    demonstrative) that are no content, no name, no function word and nothing operative, then a
    verb in -ing; no word of the clause names the world or a number, or is operative. The grammar
    words after the verb describe, as in :func:`is_report`."""
    ws = [w for w in words if w]
    k = 1 if ws and ws[0] in DETERMINERS else 0
    j = next((i for i in range(k, min(len(ws), k + 4)) if ws[i].endswith("ing") and len(ws[i]) > 4), None)
    if j is None or j == k:
        return False
    subject = ws[k:j]
    pronoun = subject[0] in SUBJECTS and len(subject) == 1 and not k
    if not pronoun and (subject[0] in _ASPECT_VERBS or any(
            not w.isalpha() or w in FUNCTION_WORDS or content(w) or near_operative(w) for w in subject)):
        return False
    return not any(_operative_at(ws, i) or names(w) for i, w in enumerate(ws))


#: words that open a statement said after an order without a comma between them ("... its
#: starting to bow", "... hes got a flat tyre", "... his forks are playing up", "... theres
#: customers about"): a subject pronoun (not "it", which is an object as often) or a possessive
STATEMENT_OPENERS = frozenset((SUBJECTS | _SUBJECT_BE | {"his", "her", "their", "our", "my"}) - {"it", "there"})


def unmarked_statement(words: list[str], names: Callable[[str], bool]) -> int:
    """How many words at the end of a clause are a statement run on without a comma, as people
    dictating or typing fast do ("take 2 slabs off the a frame theyre sticking out into the
    aisle"): the longest tail that opens with a :data:`STATEMENT_OPENERS` word after at least two
    words of the order and is a report or a statement (:func:`is_report`: no name, number,
    operative word or word of wanting in it). 0 when there is none."""
    for k in range(2, len(words) - 1):
        joined = words[k - 1] in _JOINED or words[k - 1] in ADJUNCTS
        if words[k - 1] in _JOINING:
            continue   # "... so that the lads are ...": a part of the sentence before
        if _opens_statement(words, k) and (is_report(words[k:], names) or _existential(words[k:], names)):
            return len(words) - k + joined   # "... and his forks are playing up": the "and" too
    return 0


#: words after which a clause is a part of the sentence before, never a statement run on
_JOINING = frozenset({"that", "so", "if", "than", "where", "which", "who", "whether", "or"})
#: words that join a statement to the order and go with it ("... because the delivery is due",
#: "... and his forks are playing up"), as an adjunct's first word does ("... while we sort it")
_JOINED = frozenset({"and", "but", "because", "cos", "coz", "cause", "as", "since"})


def _opens_statement(words: list[str], k: int) -> bool:
    """Whether a statement may open at ``k``: a :data:`STATEMENT_OPENERS` word, or a noun said as
    its subject ("... out lads are relaying concrete", "... would ya doreen had a fit"): a word of
    no function, followed by a form of "be" or a verb in the past tense, after a word that opens no
    noun phrase; or a determiner before such a noun ("the lads are ...")."""
    def subject(j: int) -> bool:   # a noun of no function, then a form of "be"
        return j + 1 < len(words) and words[j + 1] in ("are", "is", "were", "was") and words[j].isalpha() \
            and words[j] not in FUNCTION_WORDS and not near_operative(words[j])

    def reporting(j: int) -> bool:   # a noun or a name of no function, then a verb in the past tense
        return j + 1 < len(words) and words[j].isalpha() and words[j] not in FUNCTION_WORDS \
            and not near_operative(words[j]) and (_past(words[j + 1]) or words[j + 1] in ("had", "has"))

    if words[k] in STATEMENT_OPENERS:
        return True
    if subject(k) or reporting(k):   # "... would ya doreen had a fit", "... the truck came late"
        return words[k - 1] not in DETERMINERS
    return words[k] in ("the", "my", "our", "his", "her", "their") and subject(k + 1)


def _existential(ws: list[str], names: Callable[[str], bool]) -> bool:
    """ "theres customers about", "there are lads working": what there is, with no name, number,
    operative word or word of wanting in it."""
    return (ws[0] == "theres" or ws[:2] in (["there", "is"], ["there", "are"], ["there", "s"])) \
        and _asks_nothing(ws, names)


#: clauses that open a request and say nothing else ("Quick one: ...", "Right then, ...", "Whatever
#: you do, ..."): whole clauses only, though "one" and "then" are operative elsewhere
OPENERS = frozenset({("quick", "one"), ("right", "then"), ("ok", "then"), ("okay", "then"), ("right", "so"),
                     ("whatever", "you", "do"), ("now", "then"), ("so", "then"), ("right", "folks"),
                     ("quick", "favour"), ("quick", "favor"), ("quick", "job"),
                     # a heading before a list ("Today's plan: 1) ... 2) ...")
                     ("today", "s", "plan"), ("todays", "plan"), ("the", "plan"), ("plan", "for", "today"),
                     ("today", "s", "tasks"), ("todays", "tasks"), ("tasks", "for", "today"), ("to", "do"),
                     ("todo",), ("to", "do", "list"),
                     # what the order follows from ("As discussed on call: ...", "As per our discussion, ...")
                     ("as", "discussed"), ("as", "discussed", "on", "call"), ("as", "discussed", "earlier"),
                     ("as", "agreed"), ("as", "per", "discussion"), ("as", "per", "our", "discussion"),
                     ("as", "per", "the", "plan"), ("as", "per", "plan")}) | frozenset(
    # a count of what is to come ("Two things:", "3 jobs plz:", "a couple of tasks for you:",
    # Jamaican "two ting:"): it announces the list, it is no count of anything
    (*many, what, *courtesy)
    for many in (("two",), ("three",), ("four",), ("five",), ("2",), ("3",), ("4",), ("5",), ("couple", "of"),
                 ("a", "couple", "of"), ("few",), ("a", "few",), ("couple",))
    for what in ("things", "jobs", "tasks", "requests", "points", "ting", "tings", "thing")
    for courtesy in ((), ("plz",), ("pls",), ("please",), ("for", "you"), ("today",)))


#: whole clauses that close a message and say nothing else ("that's all for now", "that's it"):
#: their "all" and "it" point at what was said, no quantity or thing
CLOSINGS = frozenset({(*that, *rest, *later) for that in (("thats",), ("that", "is"), ("that", "s"))
                      for rest in (("all",), ("it",), ("everything",))
                      for later in ((), ("for", "now"), ("for", "today"), ("for", "tonight"), ("then",))}) | {
    # how things are, said in passing ("on the bus now, all grand", "... . sound"): "all" is everything
    # being fine, no quantity; Irish and British "grand" and "sound" are fine and thanks
    ("all", "good"), ("all", "grand"), ("all", "fine"), ("its", "all", "good"), ("all", "good", "here"),
    ("grand",), ("sound",), ("grand", "job"), ("sound", "job"), ("nice", "one"), ("legend",),
    # Australian: it is no trouble, it will be fine ("..., too easy", "no worries", "she'll be right")
    ("too", "easy"), ("no", "worries"), ("no", "wucking", "furries"), ("she", "ll", "be", "right"),
    ("shell", "be", "right"), ("sweet", "as"), ("good", "on", "ya"), ("all", "sweet"),
    # that is enough, said after the order ("..., reckon that'll do", "..., that should do it")
    *((*r, *t, *d) for r in ((), ("reckon",), ("i", "reckon"), ("think",), ("i", "think"))
      for t in (("thatll",), ("that", "ll"), ("that", "will"), ("that", "should"))
      for d in (("do",), ("do", "it"), ("do", "the", "trick"))),
    # a letter's closing ("With kind regards, Ingrid"; the name after it is the signature)
    *((*w, *r, "regards") for w in ((), ("with",)) for r in ((), ("kind",), ("best",), ("warm",), ("many",)))}


#: whole clauses that only urge the order said before them ("..., sort it out", "get it done"):
#: their "it" is that order, no thing
URGINGS = frozenset({("sort", "it", "out"), ("sort", "it"), ("sort", "that", "out"), ("sort", "it", "out", "now"),
                     ("get", "it", "sorted"), ("get", "it", "done"), ("get", "that", "done"), ("make", "it", "happen"),
                     ("see", "to", "it"), ("chop", "chop"), ("do", "the", "needful"), ("do", "needful"),
                     ("do", "it"), ("just", "do", "it"), ("do", "it", "now"),
                     # asking to be told when it is done: a reply, nothing to do to the stock
                     ("revert", "back"), ("revert",), ("let", "me", "know"), ("update", "me"), ("keep", "me", "posted"),
                     ("report", "back"), ("confirm", "back"),
                     # asking whether it can be done (Fiji, Singapore and Malaysian English: "Can or
                     # not?", "can anot?"), which the order already asks
                     ("can", "or", "not"), ("can", "or", "cannot"), ("can", "anot"), ("can", "not", "can")})
#: words that may open or close an urging without changing it ("pls do the needful", "revert back
#: once done")
_URGING_COURTESY = frozenset({"pls", "please", "kindly", "plz", "asap"})
_URGING_ENDS = (("once", "done"), ("when", "done"), ("once", "completed"), ("after", "completion"), ("asap",))


def is_urging(words: Iterable[str]) -> bool:
    """A whole clause that only urges the order on or asks to hear back (:data:`URGINGS`), with
    "please" or "kindly" before it and "once done" after it, if any."""
    ws = [w for w in words if w]
    while ws and ws[0] in _URGING_COURTESY:
        ws = ws[1:]
    for end in _URGING_ENDS:
        if len(ws) > len(end) and tuple(ws[-len(end):]) == end:
            ws = ws[:-len(end)]
            break
    return tuple(ws) in URGINGS


#: words that may lead an opener ("OK, few things", "right, two jobs")
_OPENER_LEADS = frozenset({"ok", "okay", "alright", "right", "so", "now", "well"})


def is_opener(words: Iterable[str]) -> bool:
    """A whole clause that only opens a request ("Quick one", "Right then": :data:`OPENERS`),
    also with words that lead it and words it is said to ("Ok bro few things": :data:`CLOSERS`)."""
    ws = tuple(w for w in words if w)
    if ws in OPENERS:
        return True
    while ws and ws[0] in _OPENER_LEADS:
        ws = ws[1:]
    return tuple(w for w in ws if w not in CLOSERS) in OPENERS


#: what opens a command that replaces an earlier one ("Change of plan: ...", "orait change of plan.
#: ..."): said first, it asks nothing; said after an order it takes that order back, so it is an
#: opener only where nothing was asked before it (:func:`opens_changed_plan`)
PLAN_CHANGES = frozenset({("change", "of", "plan"), ("change", "of", "plans"), ("change", "in", "plan"),
                          ("change", "in", "plans"), ("plan", "change"), ("new", "plan"), ("plans", "changed"),
                          ("plan", "changed"), ("slight", "change", "of", "plan"), ("slight", "change", "of", "plans")})


def opens_changed_plan(words: Iterable[str]) -> bool:
    """Whether a whole clause, said first in a command, only says the plan has changed ("Change of
    plan", "alright, new plan", "ok change of plans guys"): with words that lead it and words it is
    said to (:data:`CLOSERS`). Only a command's first clause may be read so."""
    ws = tuple(w for w in words if w)
    while ws and ws[0] in _OPENER_LEADS:
        ws = ws[1:]
    return tuple(w for w in ws if w not in CLOSERS) in PLAN_CHANGES


def said_talk(words: Iterable[str], names: Callable[[str], bool]) -> bool:
    """Whether words are talk by what they are, not only by lacking content: a greeting, a closing
    ("that's all for now"), thanks or an apology, or a statement with its subject ("hes getting his
    forks looked at"). A part of a command said without stops may be set aside only so: "pronto"
    or "and the blorp" lack content too, yet could be words of the order no rule reads."""
    ws = [w for w in words if w]
    return bool(ws) and (is_greeting(ws) or tuple(ws) in CLOSINGS or is_pleasantry(ws, names)
                         or is_statement(ws, names) or is_report(ws, names))


#: words said alone as a clause that address no one: interjections, exclamations, words of urgency
#: and of signposting ("Right, ...", "Brr, ...", "Urgent: ...", "..., cheers"). Any other word said
#: alone is taken for someone addressed by name (:func:`addressee`)
INTERJECTIONS = frozenset({
    # Welsh English ("Duw, the middle room is like a tip", "duw duw"; "..., mun": man, a tag; "..., lush")
    "duw", "mun", "lush",
    "right", "righto", "rightio", "ok", "okay", "alright", "aright", "oh", "ah", "ahh", "aha", "um", "umm", "uh",
    "er", "erm", "hmm", "hm", "ugh", "urgh", "argh", "brr", "brrr", "shh", "ach", "och", "oi", "oy", "phew",
    "whoops", "oops", "gosh", "golly", "jeez", "geez", "blimey", "crikey", "strewth", "cor", "wow", "meh", "lol",
    "haha", "sigh", "look", "listen", "well", "so", "now", "anyway", "anyways", "honestly", "seriously",
    "basically", "sure", "yes", "yeah", "yep", "yup", "please", "pls", "plz", "kindly", "urgent", "urgently",
    "quick", "quickly", "asap", "pronto", "reminder", "update", "important", "note", "fyi", "btw", "ps", "nb",
    "sorry", "cheers", "thanks", "ta", "thx", "ty", "hello", "hi", "hey", "hiya", "heya", "howdy", "yo", "gday",
    "morning", "mornin", "afternoon", "arvo", "evening", "night", "goodnight", "bye", "ciao", "later",
    # adverbs that signpost the message ("Separately, ...", "Ideally, ...")
    "separately", "additionally", "meanwhile", "finally", "lastly", "firstly", "secondly", "thirdly", "however",
    "incidentally", "ideally", "hopefully", "obviously", "frankly", "personally", "apparently", "unfortunately",
    "fortunately", "luckily", "sadly", "importantly", "actually", "regardless", "sincerely", "regards",
    # how to do it, said alone ("and - careful - the rocking horse"): a manner, no one addressed
    "careful", "carefully", "gently", "slowly", "quietly", "steady", "easy", "gingerly", "safely",
    # South African and West African English ("eish", "ag", "ja", "yebo", "hayibo", "shame" for
    # sympathy, "lekker"; Ghanaian "chale", "ei", "abi")
    "eish", "ag", "ja", "yebo", "hayibo", "haibo", "jislaaik", "lekker", "shame", "sho", "chale", "ei", "eii",
    "abi", "ehe",
    # Bajan sympathy ("Cuhdear, ...", "..., cuhdear": poor dear)
    "cuhdear",
    # Mexican Spanish opening an English order ("Oye, ...", "Bueno, ...": hey, well; "porfa": please;
    # "ahorita": right now; "ya": already; "órale", "ándale": come on)
    "oye", "oiga", "bueno", "pues", "porfa", "porfavor", "ahorita", "ya", "orale", "andale", "mira",
    # Indian English: Hindi and Tamil assent and urging ("Achha, take 3 ...", "Seri, ten tyres ...")
    "achha", "acha", "accha", "seri", "haan", "ji", "jaldi", "arre", "arey",
    # Brazilian Portuguese: "OK", "right?", laughter typed ("kkkk", "rsrs"), "quickly" ("rapidinho")
    "beleza", "blz", "rsrs", "kkk", "kkkk", "kkkkk", "rapidinho", "atencao",
    # and "galera", "pessoal" (folks) opening a message with no comma ("galera I want ..."); "agora": now
    "galera", "pessoal", "agora",
    # European Portuguese ("Olha, ...": look; "Então, ...": so; "pronto": right, done; "vá": go on; "pá":
    # mate; "já está": done; "ai ai"; "obrigado": thanks)
    "olha", "olhe", "entao", "pronto", "va", "ja", "esta", "ai", "obrigado", "obrigada",
    # Swedish ("Hej, ...", "Okej, ...", "Nja, ...": well, not quite; "Jaha, ...": I see; "precis":
    # exactly; "alltså": so, I mean; "tack": thanks)
    "hej", "hejsan", "tjena", "halla", "okej", "nja", "jaha", "precis", "alltsa", "tack",
    # Gulf Arabic ("Yalla, ...": come on; "inshallah", "mashallah", "wallah"; "khalas": done)
    "yalla", "inshallah", "mashallah", "wallah", "khalas", "shukran",
    # Vietnamese particles ("nha", "nhé": OK?, please)
    "nha", "nhe", "nhen",
    # Turkish ("hocam", "abi": to whoever reads; "hadi": come on; "acil": urgent; "tamam": OK;
    # "bakalım": let's see; "kolay gelsin": may it go easy; "günaydın": good morning)
    "hocam", "abi", "abla", "hadi", "acil", "tamam", "bakalim", "kolay", "gelsin", "gunaydin", "insallah",
    # Russian typed in Latin letters ("davai": come on; "srochno": urgent; "koroche": in short; "nu":
    # well; "bratan": bro; "normalno": fine; "ladno": OK; "spasibo": thanks; "privet": hi; "poka": bye)
    "davai", "srochno", "koroche", "nu", "bratan", "normalno", "ladno", "spasibo", "privet", "poka",
    # Japanese ("Sumimasen, ...": excuse me; "hai": yes; "ano": um; "ohayo": good morning)
    "sumimasen", "hai", "ano", "ohayo", "ohayou", "otsukaresama", "otsukare", "arigato", "arigatou",
    # Greek in Latin letters ("Ela, ...": come on; "kalimera": good morning; "endaxi": OK; "efharisto":
    # thanks; "parakalo": please)
    "ela", "kalimera", "kalispera", "endaxi", "entaxi", "efharisto", "efcharisto", "parakalo", "oriste",
    # Flemish ("Allez, ...": come on; "amai": wow; "voilà"; "seffens": right away; "ff": just a moment;
    # "goeiemorgen": good morning; "dank u": thank you)
    "allez", "amai", "voila", "seffens", "ff", "goeiemorgen", "goedemorgen", "dank", "merci",
    # Italian and Neapolitan ("Allora, ...": so; "dai": come on; "uè": hey; "subito": at once; "mannaggia",
    # "madonna": dismay; "jamme": let's go; "ecco": there)
    "allora", "dai", "ue", "subito", "mannaggia", "jamme", "ecco", "grazie", "prego", "basta", "va", "bene",
    # Indonesian ("Pak, ...", "kak", "bu": to whoever reads; "siap": ready; "wkwk": laughter; "oke", "sip": OK)
    "pak", "bu", "kak", "mas", "mbak", "siap", "wkwk", "wkwkwk", "oke", "sip", "makasih",
    # Shona and Zimbabwean English ("Manje, ...": now, so; "Nhai, ...": hey, is it so; "zvakanaka": it's
    # fine; "iwe": you there); Yorkshire "sithee" (look here)
    "manje", "nhai", "zvakanaka", "iwe", "sithee",
    # Fijian, said in Fiji English ("Isa, ...": alas, dear; "Ia, ...": well, so; "io": yes; "maleka":
    # delicious, great; "vinaka": thanks; "bula": hello)
    "isa", "ia", "io", "maleka", "vinaka", "bula",
    # Colombian Spanish ("Ay, ...", "parce": mate; "listo": ready, OK; "dale": go on; "uy")
    "ay", "uy", "parce", "parcero", "listo", "dale",
    # Québec French ("Bon, ...": well; "genre": like; "tsé": you know; "câline": darn; "voyons": come on)
    "bon", "genre", "tse", "caline", "voyons", "coudonc",
    # Korean chat: a cheer ("Fighting!", "hwaiting"), dismay ("aigoo"), "really" ("jinjja"), laughter ("kk")
    "fighting", "hwaiting", "aigoo", "aigo", "jinjja", "omo", "kk",
    # Mandarin in pinyin ("Kuai dian, ...": hurry; "aiya": dismay; "hao de": OK; "xie xie": thanks)
    "kuai", "dian", "aiya", "aiyo", "aiyah", "hao", "xie", "xiexie", "mei", "wenti",
    # Malaysian English ("Alamak, ...", "aiyoh": dismay; "walao": wow; "paiseh": sorry; "wah")
    "alamak", "aiyoh", "aiseh", "walao", "wah", "paiseh", "adoi", "aduh",
    # Sinhala in Latin letters ("Aney, ...": oh, please; "apoi": dismay; "hari": OK; "isthuthi": thanks;
    # "ayubowan": hello)
    "aney", "anee", "apoi", "hari", "harida", "isthuthi", "istuti", "ayubowan",
    # Irish ("Dia duit": hello; "a chara": friend; "GRMA": thanks; "sláinte": cheers; "slán": bye)
    "dia", "duit", "chara", "grma", "slainte", "slan",
    # Maltese ("Bongu": good morning; "bonswa": good evening; "mela", "allura": so; "insomma": anyway; "iva":
    # yes; "ħabib": friend; "għaġġla": hurry; "ejja": come on; "grazzi": thanks; "ċaw", "saħħa": bye;
    # "prosit": well done), spelt without their letters' dots and strokes (:mod:`.characters`)
    "bongu", "bonswa", "mela", "allura", "insomma", "iva", "habib", "habiba", "ghaggla", "ejja", "grazzi", "caw",
    "sahha", "prosit",
    # Cajun English ("cher", "chère", "sha": dear; "podna": partner; "ayee": surprise)
    "cher", "chere", "sha", "podna", "ayee", "ayyee",
    # Thai ("Sawasdee ka, ...": hello; "kob khun": thank you; "jing jing": really; "mai pen rai": never
    # mind; "reo reo": quickly; "na ka", "krub": polite particles)
    "sawasdee", "sawatdee", "kob", "khun", "jing", "reo", "ka", "kha", "krub", "khrub", "krap", "khrap", "jaa",
    # German ("Genau.", "Jawohl.", "Los!", "Danke.", "Bitte, ...", "Moin", "Servus")
    "genau", "jawohl", "los", "danke", "bitte", "moin", "servus", "schnell",
    # Spain's Spanish ("Hola, ...", "Venga, ...": come on; "vale": OK; "tío": mate; "ostras": wow)
    "hola", "venga", "vale", "tio", "tia", "hombre", "ostras",
    # Urdu and Punjabi ("Yaar, ...": mate; "theek hai": fine; "acha": OK; "chalo": come on; "inshallah",
    # "mashallah", "alhamdulillah"; "shukriya": thanks)
    "yaar", "theek", "thik", "acha", "achha", "accha", "chalo", "inshallah", "inshaallah", "mashallah",
    "alhamdulillah", "shukriya", "shukria", "jazakallah",
    # Jamaican ("Lawd, ...", "cho": annoyance; "eeh": OK?; "irie": all is well; "bless", "respect", "seen")
    "lawd", "cho", "choh", "eeh", "irie", "bless", "respect", "seen", "gwaan", "tanks",
    # Romanian ("Hai, ...": come on; "gata": done; "bine": fine; "deci": so; "adica": that is; "doamne":
    # God; "mersi": thanks; "frate", "bre": mate)
    "hai", "haide", "gata", "bine", "deci", "adica", "doamne", "mersi", "multumesc", "frate", "bre", "pa",
    # Trinidadian ("Boy, ...": man; "wam": what's happening; "steups": the sucked teeth of annoyance;
    # "eh eh": surprise) and Scouse ("ey", "ar eh": aw, come on)
    "boy", "wam", "steups", "steupes", "ey", "ar",
    # a signpost of urgency ("Attention! swap ...")
    "attention"})


def addressee(words: list[str]) -> str | None:
    """Who a clause addresses by name ("Hornet, move ...", "..., Hornet", "Hi Hornet, ..."): its
    one word, or the word after a greeting or thanks, when that word is no interjection, addressee
    or function word; None when the clause is no such address."""
    if len(words) == 2 and words[0] in GREETINGS | PLEASANTRIES:
        words = words[1:]
    if len(words) != 1:
        return None
    word = words[0]
    if word.isalpha() and word not in INTERJECTIONS | GREETINGS | ADDRESSEES | CLOSERS | PLEASANTRIES \
            and word not in FUNCTION_WORDS and word not in OPERATIVE:
        return word
    return None


#: words that close a letter before its writer's name ("Regards, Ramesh", "Yours sincerely, Tom"):
#: only letters close so; "thanks" and "cheers" may be said to a robot by name, and are not here
SIGN_OFFS = frozenset({"regards", "rgds", "sincerely", "faithfully", "truly", "yours", "best", "warmly", "wishes"})


def signature(before: Iterable[str], words: Iterable[str]) -> bool:
    """Whether a clause that addresses a name (:func:`addressee`) is a letter's signature: the last
    clause, after one that ends with a sign-off word ("Regards, Ramesh", "With kind regards,
    Ingrid Thode": a first name and a family name). The writer signs; no one is asked to do
    anything."""
    said = [w for w in before if w]
    ws = [w for w in words if w]
    return bool(said) and said[-1] in SIGN_OFFS and len(ws) in (1, 2) and all(addressee([w]) is not None for w in ws)


#: what goods are like, that no order reads and no rule says ("the tins are heavy", "fragile",
#: "the floor's wet"): said as the reason for an order or a rule. Sizes are left out: "the small
#: ones" and "the big lads" are robots as often, and a robot's size may be a rule
CONDITIONS = frozenset({"heavy", "hefty", "fragile", "delicate", "breakable", "awkward", "bulky", "slippery", "wet",
                        "damp", "soaked", "icy", "frozen", "perishable", "flammable", "hazardous", "toxic",
                        "dangerous", "expensive", "pricey", "valuable", "precious", "dusty", "sticky", "leaky",
                        "leaking", "greasy", "oily", "wobbly", "unstable", "mucky", "muddy", "dry", "dried"})
#: words that grade a condition ("too heavy", "proper heavy", "a bit wet", "heavy as")
_GRADING = frozenset({"too", "very", "so", "quite", "really", "bit", "a", "proper", "real", "super", "pretty",
                      "extra", "dead", "bloody", "damn", "plumb", "kinda", "rather", "way", "little", "well", "still",
                      "that", "awful", "awfully", "mighty", "right", "wicked", "bone"})   # "bone dry"


def is_condition(words: Iterable[str], content: Callable[[str], bool], names: Callable[[str], bool],
                 thing: Callable[[str], bool]) -> bool:
    """ "..., the tins are heavy", "..., minyak is heavy", "..., heavy", "..., formula is heavy":
    what goods are like (:data:`CONDITIONS`), said as the reason for an order or a rule; it orders
    nothing, so it is set aside even where it names a thing of the world. Only its subject may name
    one, and only what ``thing`` lets a condition be said of (the warehouse: goods; never a robot,
    "the forklift is dirty" may be a rule, nor a place, "bay 1 is wet, move the rice" may say where
    from), in words of no grammar ("keep them dry" is an order) with "be" and words grading the
    condition; after the condition at most three words of talk ("heavy buggers") or where it is so
    ("it too heavy up there"). An operative word, a number, a word of wanting or a word for robots
    keeps it in."""
    ws = [w for w in words if w]
    if len(ws) > 2 and ws[-1] in ("there", "here") and ws[-2] in _WHERE_BEFORE_THERE | {"up", "down", "in", "out"}:
        ws = ws[:-2]   # "up there": where, no order
    k = next((i for i, w in enumerate(ws) if w in CONDITIONS and not names(w)), None)
    if k is None or len(ws) - k > 4:
        return False
    if any(_operative_at(ws, i) or _asks(ws, i) or w in ROBOT_WORDS or _count_word(w) for i, w in enumerate(ws)):
        return False
    subject = [w for w in ws[:k] if w not in _BE and w not in _GRADING and w not in DETERMINERS
               and w not in _DEMONSTRATIVES and w not in SUBJECTS and w not in _SUBJECT_BE]
    return all(thing(w) or not (names(w) or content(w)) for w in subject) and \
        not any(content(w) or names(w) for w in ws[k + 1:])


def content_free(words: Iterable[str], content: Callable[[str], bool],
                 names: Callable[[str], bool] | None = None, reports: bool = False,
                 robot: Callable[[str], bool] = lambda w: False,
                 thing: Callable[[str], bool] | None = None) -> bool:
    """Whether a clause carries nothing an order needs (module doc). ``content(word)`` is the
    domain's test: a name of its world (or close to one), a number, a content word of its lexicon.
    ``names(word)`` (optional; without it apologies and thanks are judged by ``content``): only a
    name of the world or a number, for a pleasantry (:func:`is_pleasantry`), whose grammar words
    are what it is for. ``robot(word)``: whether a word names a robot (or team) of the world. A
    clause that addresses one by name (:func:`addressee`) is talk in a domain whose orders are for
    the team; addressed to a name the world lacks, it is never talk: a robot that is not there is
    asked to do it, and the command must be refused, not given to the robots there are.
    ``thing(word)`` (optional): whether a word names what a condition may be said of and still be
    set aside (:func:`is_condition`)."""
    ws = [w for w in words if w]
    ws = [w for k, w in enumerate(ws) if not duration_at(ws, k)]   # "in 20 minutes": how long, no count
    if not ws:
        return True
    if tuple(ws) in CLOSINGS and not any(content(w) for w in ws):
        return True   # "..., all grand", "... . sound": said in passing, no one addressed
    if names is not None and thing is not None and is_condition(ws, content, names, thing):
        return True   # "..., heavy": what the goods are like, no name said to
    if all(w in VOCATIVES for w in ws) and not any((names or content)(w) for w in ws):
        return True   # "..., love", "Sebo, ...": said to the one asked, who is no name of the world
    name = addressee(ws)
    if name is not None:
        return robot(name)   # "Hornet, ...": set aside only when it names a robot of the world
    if is_greeting(ws) or tuple(ws) in CLOSINGS or is_urging(ws):
        return True   # its "all" or "team" is who is greeted, no quantifier or robot group
    if names is not None and is_pleasantry(ws, names):
        return True
    if reports and names is not None and (is_report(ws, names) or is_bare_report(ws, content, names)) \
            and not _order_opening(ws, content, names):
        return True   # "it is getting serviced": a report, whatever grammar words it uses
    subject = _demonstrative_subject(ws)
    if ws[0] in ATTACHING and not _it_is(ws) and not subject:
        return False  # it modifies the clause before ("..., on the left", "..., and the rest")
    opener = next((w for w in ws if w not in _CLAUSE_JOINERS), "")   # "..., then we lock it": "we" opens it
    if opener not in SUBJECTS and any(w not in FUNCTION_WORDS and w not in _SPANS and nxt in OBJECT_PRONOUNS
                                     and not _this_time(ws, k + 1) for k, (w, nxt) in enumerate(zip(ws, ws[1:]))):
        return False  # "..., recount them": an instruction about a thing, in a verb not read
    # "then" before a subject joins what the speaker says of someone, and orders nothing
    joined = next((k for k, w in enumerate(ws) if w not in _CLAUSE_JOINERS), 0) if opener in SUBJECTS else 0
    return not any(_operative_at(ws, k) or (content(w) and not _just_now(ws, k) and not _all_over(ws, k)
                                            and k >= subject and not _possessed(ws, k, names))
                   for k, w in enumerate(ws) if k >= joined)


#: words that say whose a thing is ("its wheel", "that one's wheel": the "s" of the apostrophe)
_POSSESSIVES = frozenset({"his", "her", "its", "their", "my", "our", "your", "s"})


def _possessed(ws: list[str], k: int, names: Callable[[str], bool] | None) -> bool:
    """Whether the word at ``k`` is a noun someone or something has ("..., that one's wheel still
    squeaking", "..., her wheel is loose"): after a possessive, a grammar word ("wheel": a verb)
    is a noun, no order. A name of the world stays content, and without ``names`` nothing is judged so."""
    return names is not None and k > 0 and ws[k - 1] in _POSSESSIVES and not names(ws[k])


#: words that join a clause to the one before and say nothing of who does what ("then we lock it")
_CLAUSE_JOINERS = frozenset({"then", "and", "but"})


#: words after "its" that make it "it's" typed without its apostrophe ("its friday", "its a mess",
#: "its not urgent"), not the possessive that attaches a clause ("..., its top shelf")
_AFTER_IT_IS = frozenset({"a", "an", "the", "not", "so", "too", "very", "just", "all", "still", "been", "ok", "okay",
                          "fine", "only", "already", "getting", "gonna", "going", "always", "never", "probably"})


#: spans of time a demonstrative may point at ("this week", "that arvo"): when, no thing
_SPANS = frozenset(TIMES_SAID | {"week", "month", "year", "time", "shift", "arvo", "season", "summer", "winter",
                                 "spring", "autumn", "fall", "quarter", "day", "night", "once"})


def _this_time(ws: list[str], k: int) -> bool:
    """Whether the word at ``k`` is a demonstrative before a span of time ("orders this week"):
    it says when, no object of a verb."""
    return ws[k] in _DEMONSTRATIVES and k + 1 < len(ws) and ws[k + 1] in _SPANS


#: words that open what a verb of an order acts on ("leave what is in there as it is", "keep the rest")
_OBJECT_OPENERS = frozenset(DETERMINERS | OBJECT_PRONOUNS | {"what", "whatever", "all", "every", "everything", "any",
                                                             "anything", "some", "each"})


def _order_opening(ws: list[str], content: Callable[[str], bool], names: Callable[[str], bool]) -> bool:
    """Whether a clause opens as an order does: a word of the domain's grammar that names nothing of
    the world, then what it acts on ("leave what is already in there as it is"). Its "is" is no
    report's: the clause asks for something, and is never set aside as a report."""
    return len(ws) > 1 and content(ws[0]) and not names(ws[0]) and ws[1] in _OBJECT_OPENERS


def _it_is(ws: list[str]) -> bool:
    """Whether a clause opening with "its" is "it's" said without its apostrophe: a word of
    :data:`_AFTER_IT_IS` or a time (:data:`TIMES_SAID`) after it, or a verb of "be" or a modal
    later in the clause ("its friday and the pub will be chockers")."""
    return ws[0] == "its" and len(ws) > 1 and (ws[1] in _AFTER_IT_IS or ws[1] in TIMES_SAID
                                               or any(w in _BE or w in _MODALS for w in ws[2:]))


#: modal verbs: a clause with one says what will or may be, no noun phrase alone
_MODALS = frozenset({"will", "would", "can", "could", "should", "shall", "might", "may", "must", "wont", "cant"})


def clauses(words: list[str], marks: set[str]) -> list[Clause]:
    """The clauses of a word list, split at the clause marks (which belong to no clause)."""
    out: list[Clause] = []
    start = 0
    for k, w in enumerate(words + [next(iter(marks))]):
        if w in marks:
            if k > start:
                out.append(Clause(start, k, tuple(words[start:k])))
            start = k + 1
    return out


def said(parts: list[str]) -> str:
    """The echo line of what was set aside."""
    return ("set aside, not read (it asks for nothing: no number, no operative word): "
            + "; ".join(f"'{p}'" for p in parts))


#: words that point back at something said before them: a reason that names what they point at
#: ("We're closing aisle 2, so clear it out") is no reason to set aside
BACK_REFERENCES = frozenset({"it", "its", "them", "their", "there", "those", "these", "that", "this", "em"})


#: words that leave things out of an order ("except the pigment", "but not the dog food")
_LEAVING_OUT = frozenset({"except", "excepting", "excluding", "but", "apart", "besides", "not", "leave", "leaving"})
#: verbs of staying, said of what was left out ("..., that stays", "..., that one stays put")
_STAYING = frozenset({"stays", "stay", "remains", "remain"})
#: what may follow them: where, or what for ("that stays for picking")
_STAYING_TAIL = frozenset({"put", "there", "here", "where", "it", "is", "they", "are", "as", "for", "behind", "too"})


def restates_what_stays(before: Iterable[str], words: Iterable[str], names: Callable[[str], bool]) -> bool:
    """ "Empty the kaai except the pigment, that stays", "... except the one in pickface, that one
    stay for picking": a demonstrative and a verb of staying right after a clause that leaves
    something out (:data:`_LEAVING_OUT`) says again that it stays, which the clause before says;
    set aside. After any other clause "that stays" says what stays, and is read or refused as ever.
    "Let them stay", "leave those there" (Guyanese "leh dem stay") and "don't touch those ones" say
    it so too. Nothing of the world, no number and no operative word but its demonstrative may be in
    it."""
    ws, prev = [w for w in words if w], set(before)
    if not ws or not prev & _LEAVING_OUT:
        return False
    touched = 3 if ws[:3] == ["do", "not", "touch"] else 2 if ws[:2] == ["dont", "touch"] else 0
    if touched:   # "..., don't touch those ones": what is left out is left alone
        said = ws[touched:]
        ones = said[1:] in ([], ["ones"], ["one"])
        return len(said) in (1, 2) and said[0] in _DEMONSTRATIVES | {"them", "it"} and ones
    told = len(ws) > 1 and ws[0] in ("let", "leave") and ws[1] in _DEMONSTRATIVES | {"them", "it"}
    if ws[0] == "leave" and told:   # "leave them (there)": no verb of staying
        ws = [ws[1], "stay"] + ws[2:]
    elif told:
        ws = ws[1:]
    n = 2 if ws[1:2] and ws[1] in _ONES else 1
    if not (ws[0] in _DEMONSTRATIVES or told) or len(ws) <= n or ws[n] not in _STAYING:
        return False
    rest = ws[n + 1:]
    return not any(near_operative(w) or names(w) for w in rest) and (not rest or rest[0] in _STAYING_TAIL)


def leading_reason(parts: list[Clause], free: list[Clause], counts: Callable[[str], bool],
                   content: Callable[[str], bool] | None = None) -> list[Clause]:
    """The reason that opens a sentence and is followed by "so" ("We're doing a sale on bay 9 this
    afternoon, so get 3 paperbacks ..."): a report of what is going on (a subject, "be", a
    verb in -ing: :func:`is_report`) that may name places and products, or what a party did or
    wants (:func:`said_of_a_party`, with ``content``: "The Taveuni resort cut back their order, ia,
    so cut ..."), with "so" after it (talk set aside between them); both are set aside. Never with
    a count (``counts``: the domain's test, which lets the world's names pass) or an operative word
    in it, nor where the order after it points back with a pronoun or "there" (whatever it names is
    what "it" means)."""
    after = [c for c in parts[1:] if c not in free]
    if len(parts) < 2 or parts[0] in free or not after or after[0].words[:1] != ("so",):
        return []
    if not (is_report(parts[0].words, counts) or (content is not None and said_of_a_party(parts[0].words, counts,
                                                                                           content))):
        return []
    if any(w in BACK_REFERENCES for c in parts[1:] for w in c.words):
        return []
    so = after[0]
    return [parts[0], Clause(so.start, so.start + 1, ("so",))]


#: verbs a party's report is said with besides those in -s and -ed ("customs want samples", "the
#: resort cut back their order")
_PARTY_VERBS = frozenset(_BARE_VERBS | ASKING | FINITE | _MODALS | PAST_FORMS | {"cut"})


def said_of_a_party(words: Iterable[str], counts: Callable[[str], bool], content: Callable[[str], bool]) -> bool:
    """ "The Taveuni resort cut back their order", "customs want samples", "QA says whole Tuesday":
    what a party did, does or wants, said before "so" and the order it leads to
    (:func:`leading_reason`). Its subject is one or two words of no grammar, no name of the world
    (``content``) and nobody spoken of or to ("we", "you", "they": those may be the robots or the
    speaker, whose wish is an order), its verb one in -s or -ed or of :data:`_PARTY_VERBS`; no count
    and no operative word anywhere in it."""
    ws = [w for w in words if w]
    k = 1 if ws[:1] and ws[0] in DETERMINERS else 0
    n = next((j for j in (1, 2) if len(ws) > k + j and _finite(ws[k + j])), None)
    if n is None or any(content(w) or w in ROBOT_WORDS or w in SUBJECTS or w in _YOU or not w.isalpha()
                        for w in ws[k:k + n]):
        return False
    return not any(_operative_at(ws, i) or counts(w) for i, w in enumerate(ws))


def _finite(word: str) -> bool:
    """A verb as a subject has it: in -s (not -ss), in -ed, or of :data:`_PARTY_VERBS`."""
    return word in _PARTY_VERBS or _past(word) or (word.endswith("s") and len(word) > 3 and not word.endswith("ss"))


#: words the reader knows as talk (greetings, thanks, closers, apologies, interjections): said as
#: written, never a misspelt name of the world ("cheers" is no cider)
TALK = frozenset(GREETINGS | THANKS | CLOSERS | PLEASANTRIES | INTERJECTIONS)

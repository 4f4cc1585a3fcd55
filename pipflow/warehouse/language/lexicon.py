"""The command's words as the grammar's terminals, with the world as the lexicon.

Names come from :mod:`pipflow.warehouse.language.names` (typo-tolerant, refusing near-ties), counts from
:mod:`pipflow.language.numbers`; this module adds what the grammar needs on top: robot kinds,
tags and skills of the world, superlatives, fractions, the possessive "'s", misspelt number
words ("thre", "sixe"), and the checks on the raw text that must happen before any of that (a
size cap, negative counts, symbols that are not English). A word that is neither a keyword of
the grammar nor a filler stays an unknown terminal, so the parser refuses it by name.
"""
from __future__ import annotations

import copy
import re
from dataclasses import dataclass, replace
from typing import Any, Callable, Collection

from lark import Token

from pipflow.errors import InputError, Refusal, TranslationError
from pipflow.language.asides import (ADDRESSEES, BACK_REFERENCES, CLOSERS, FUNCTION_WORDS, GREETINGS, INTERJECTIONS,
                                     OPERATIVE, SUBJECTS, TALK, VOCATIVES, Clause, clauses, content_free, is_opener,
                                     leading_adjunct, leading_reason, opens_changed_plan, restates_what_stays,
                                     said_talk, signature, trailing_adjunct, trailing_thanks, unmarked_statement)
from pipflow.language.asterisk import star_corrections
from pipflow.language.characters import (accents_folded, declared_spellings, non_ascii_words, refuse_unread, turkish_i,
                                         without_expressions)
from pipflow.language.english import common_word, dropped_g
from pipflow.language.numbers import NUMBER_WORDS, TENS, UNITS, is_number
from pipflow.language.patois import CREOLE_WORDS, LEFT_OUT, PLURAL, english_of
from pipflow.language.radio import transmission
from pipflow.language.quebec import QUEBEC
from pipflow.language.scots import SCOTS
from pipflow.language.tokpisin import TOK_PISIN
from pipflow.language.spelling import distance, normalize, plural_forms, slip, tolerance
from pipflow.warehouse.language.grammar import ASIDE_ONLY, ORDER_VERBS
from pipflow.warehouse.language.names import (CONTAINERS, KIND_WORDS, PACKAGING_WORDS, POSS_MARK, STOPWORDS,
                                              NameIndex, Tok, read_counts, recognize)
from pipflow.warehouse.language.restatedscope import item_scope_restated
from pipflow.warehouse.language.roles import read_by_roles
from pipflow.warehouse.language.reordered import (base_verb, by_as_among, count_after_item, destination_first,
                                                fronted_source, item_as_subject, needs_doing, object_before_verb,
                                                of_as_from, on_as_to, only_after_a_move, place_as_it, place_first,
                                                place_must_be, place_set_off, places_then_each, said_at,
                                                source_after_verb, to_be_done, topic_first, verb_last)
from pipflow.warehouse.language.transcripts import HESITATIONS, orders_taken_back, places_taken_back, them_as_determiner
from pipflow.warehouse.language.wordorder import (WHERE_WORDS, left_dislocated, noun_adjuncts, numbered_siblings,
                                                  places_listed_after_sharing, unit_of_its_product, unmarked_lists,
                                                  where_words_placed)

#: no user writes a longer command; past this the parser would only be asked to burn time
MAX_COMMAND_CHARS = 4000
#: digits in one count; a shelf never holds a trillion units, and huge numbers are a typo or an attack
MAX_DIGITS = 9
#: words that carry no meaning of their own in a command
#: determiners that make a robot kind or tag said in the singular one robot ("the AGV", "our forklift")
DEFINITE = frozenset({"the", "this", "that", "our", "your", "my", "their"})
FILLERS = {"the", "please", "kindly", "units", "unit", "pieces", "piece", "boxes", "box", "crates", "oi", "oy",
           "qty", "fyi", "aye", "ken", "och", "prio", "graag", "toch",
           "crate", "cases", "case", "pcs", "pallets", "pallet", "x", "exactly", "precisely",
           "actually", "really", "hey", "um", "uh", "ok,", "just", "right", "away", "quickly",
           "now", "today", "currently", "sku", "skus", "of", "moment", "pls", "plz", "asap", "thx",
           "completely", "entirely", "fully", "totally", "immediately", "soon", "tonight", "thanks", "overnight",
           "sharpish", "pronto", "promptly", "swiftly",
           # a sentence adverb that only turns to the next thing ("Anyway send 6 ...")
           "anyway", "anyways",
           # South African interjections, said anywhere in a sentence ("ag the cage is packed", "ja so swap")
           "eish", "ag", "ja", "yebo", "hayibo", "haibo", "jislaaik",
           # Indian English: "6 nos" (numbers: units), "at 3 pm itself" (emphasis), "Meanwhile move ...",
           # and Hindi and Tamil assent said anywhere ("Achha take 3 ...")
           "nos", "itself", "meanwhile", "additionally", "achha", "acha", "accha", "seri", "haan", "jaldi",
           # Welsh English: "tidy" (good, proper) closing an order
           "tidy",
           # French politeness said in English chat ("move 3 ... svp", "merci")
           "svp", "stp", "merci",
           # Nigerian English and Pidgin "please" ("Abeg add 5 ...", "biko"), said anywhere
           "abeg", "biko",
           # Swahili and Sheng said in Kenyan English ("Clear packing kabisa": completely, "haraka":
           # quickly, "tafadhali": please, "bana": man, "sasa": now)
           "kabisa", "haraka", "tafadhali", "bana", "sasa",
           # Sinhala said in Sri Lankan English orders ("ikmanata": quickly)
           "ikmanata", "ikmanin",
           # Mexican Spanish said in English orders ("porfa move ...", "ahorita put ...", "oye, ..."):
           # please, right now, hey, then, well, come on ("ya" is "you" in "can ya": SPELLINGS)
           "porfa", "porfavor", "ahorita", "oye", "luego", "pues", "bueno", "orale", "andale",
           # Thai said in English orders ("Kor add 5 ...": may I have, please; "reo reo": quickly)
           "kor", "reo",
           # German said in English orders ("bitte": please; "schnell": quickly; "danke": thanks)
           "bitte", "schnell", "danke"}
#: words of talk of our lists: never a slip of a name ("hai" is no "hat")
_TALK_WORDS = INTERJECTIONS | CLOSERS
FILLERS |= PACKAGING_WORDS
#: fillers that make the count after them a final count
EXACT_WORDS = {"exactly", "precisely"}
#: chat spellings of keywords
SPELLINGS = {"shud": "should", "shld": "should", "u": "you", "r": "are", "wont": "wont", "gonna": "will",
             "wanna": "want", "lemme": "let", "cuz": "because", "thru": "through", "frm": "from",
             "em": "them", "yous": "you", "youse": "you", "ya": "you", "yer": "your", "atm": "now", "dun": "dont", "hv": "have",
             "b4": "before", "rn": "now", "tmrw": "tomorrow",
             # Irish English "ye" (you, to several), "giz" (give us: get us)
             "ye": "you", "giz": "get", "tmr": "tomorrow", "2moro": "tomorrow",
             # "k" typed alone for OK ("k shift 7 X to P")
             "k": "ok",
             # "whatever's on P" typed or transcribed without its apostrophe: its "'s" is "is"
             "whatevers": "whatever",
             # "leave P as is tho": though
             "tho": "though", "altho": "although",
             # Malay and Indonesian "jangan": don't ("Jangan touch anything at mezz")
             "jangan": "dont",
             # "th" said as "d" (Cajun, Caribbean, West African English): "dat", "dis", "dem", "dey", "dese"
             "dat": "that", "dis": "this", "dem": "them", "dey": "they", "dese": "these",
             # and Caribbean English (Bahamian, Jamaican, Trinidadian): "wit" (with), "nuttin"
             # (nothing), "dere" (there), "ting" (thing), "da" (the), "fa" (for), "gat" (got),
             # "wha" (what), "jes" (just), "bout" (about)
             "wit": "with", "nuttin": "nothing", "nutten": "nothing", "notting": "nothing", "ting": "thing",
             "tings": "things", "everyting": "everything", "anyting": "anything", "someting": "something",
             "dere": "there", "da": "the", "fa": "for", "gat": "got", "wha": "what", "jes": "just",
             "bout": "about",
             # Trinidadian English "doh" (don't: "doh touch the chiller"), "jus" (just)
             "doh": "dont", "jus": "just",
             # Shona "aiwa" (no: "10, aiwa sorry, 8"), said in Zimbabwean English
             "aiwa": "no",
             # Fijian "sega" (no: "5 more, sega, make it 7"), said in Fiji English
             "sega": "no"}
#: Scots spellings of the grammar's own words (shared with the household reader: "shift 5 corks fae
#: pend tae steading", "take 2 aff vault", "dinnae touch it"), read only where the word is no word
#: of the world's names
SPELLINGS |= SCOTS
#: and Québec French words said in English ("move 4 X to P pis empty Q": then), as at home
SPELLINGS |= QUEBEC
#: and Tok Pisin words said in Papua New Guinea English ("tekim 10 X from P", "wanpela more", "plis")
SPELLINGS |= TOK_PISIN
#: words for people that name robots after a robot group ("the night shift boys", "the backup bois",
#: "the strongest boi": :meth:`Lexicon._people_as_robots`)
PEOPLE_AS_ROBOTS = frozenset({"boys", "bois", "lads", "guys", "fellas", "fellows", "blokes", "girls", "crew", "gang",
                              "boy", "boi", "lad", "guy", "fella", "fellow", "bloke", "girl"})
#: texting's one-letter words, as typed in lower case ("mezz n dock", "end up w a dozen"); a capital
#: "N" or "W" is more often north or west ("N cage"), and is left alone
LETTER_WORDS = {"n": "and", "w": "with"}
#: spellings of two words run together as said ("outta the shed", "offa the rack"): read as the
#: two words (the first keeps the text as written, the second has none of its own)
RUN_TOGETHER = {"outta": ("out", "of"), "outa": ("out", "of"), "offa": ("off", "of"), "hafta": ("have", "to")}
#: a count said in digits or words
_NUMBER = r"(?:\d+|" + "|".join(sorted(NUMBER_WORDS, key=len, reverse=True)) + r")\b"
#: a word of a robot's name or group ("the night shift ones"): no word that joins or ends a clause
_ROBOT_WORD = r"(?!(?:and|then|so|but|or|to|from|on|in|into|at|of|while|because|cos|with)\b)[a-z][a-z0-9_]*"
#: "3 X for each of the 4 trucks": a count for each of several (:meth:`Lexicon._times_for_each`)
_FOR_EACH_OF = re.compile(rf"\b({_NUMBER})\s+((?:[a-z][a-z0-9_-]*\s+){{1,3}}?)for\s+each\s+of\s+(?:the\s+|those\s+|these\s+)?"
                          rf"({_NUMBER})\s+([a-z]+)\b", re.IGNORECASE)
#: the grammar words a spelling may stand for in a remark's words as said: a subject, an article,
#: a preposition ("dey", "da", "fa", "wit"); never a pronoun of things or a demonstrative ("dem
#: order big" is "their order", "dat" may point at a thing), nor a modal ("gonna")
_SAID_AS = frozenset({"they", "the", "for", "with"})


def _as_said_in_full(word: str, tok: Tok | None = None) -> str:
    """A word as written, or the grammar word of :data:`_SAID_AS` it spells ("dey": they), which
    is never a slip of a name, or the word said with "in" for "ing" ("chargin"): a remark "dey
    chargin" is talk as "they charging" is. A Creole word the patois read gave an English word of
    its own (``tok``: "leh dem stay", let them stay) is that word ("nah" read as "not" is never the
    interjection "nah": the negation would be lost), as a Tok Pisin word is its English word. A
    repair of a slip is not: "Big day today" is no "bit day"."""
    read = str(tok.value) if tok is not None else word
    if read != word and " " not in read and word in CREOLE_WORDS:
        return read
    if word in TOK_PISIN:   # a word of another language, no slip: "emi too slow" is "its too slow"
        return TOK_PISIN[word]
    said = SPELLINGS.get(word)
    if said in _SAID_AS:
        return said
    return dropped_g(word) or word


#: a time of day said after a verb of arriving or leaving, with no count after it (:meth:`Lexicon.sentences`)
_ARRIVING_AT = re.compile(r"\b((?:com(?:ing|in)|arriv(?:ing|in|es?)|leav(?:ing|in|es?)|land(?:ing|in|s)?|due|here|"
                          r"reach(?:es)?|pick(?:ing|in)\s+up|comes?|clos(?:ing|in|es)|open(?:ing|in|s)?)"
                          r"(?:\s+(?:fa|for)\s+(?:his|her|their|the|a|an)\s+[a-z]+)?\s+"
                          r"(?:at|by|around|about|bout|before|after|until|till))\s+([01]?\d|2[0-4])"
                          r"(?=\s*(?:[.,;:!?]|$|and\b|so\b|but\b))", re.IGNORECASE)
#: what a second negative after a negated verb repeats (negative concord)
_CONCORD = {"nothing": "anything", "none": "any", "nobody": "anybody", "no": "any",
            # Caribbean English "nuttin" (nothing)
            "nuttin": "anything", "nutten": "anything"}
#: verbs "out" completes ("clear out the dock"): there "out the" is no "out of the"
_OUT_VERBS = frozenset({"clean", "clear", "empty", "take", "get", "sort", "lay", "put", "pull", "carry", "bring", "move",
                        "send", "ship", "throw", "chuck", "pick", "check", "hand", "roll", "wheel", "cart", "haul",
                        "find", "figure", "work", "set", "sweep", "muck", "tidy", "even", "spread", "share", "split",
                        "dish", "parcel", "give", "pass", "kick", "toss", "turf", "bin", "load", "unload", "fill",
                        "tip", "dump", "hang", "cut", "cross", "run", "max", "thin", "weed", "shift", "lift", "fish",
                        "dig", "hook", "drag", "tow", "ferry", "shove", "push", "slide", "wipe"})
#: words that may stand before the subject that opens a sentence: talk, or a word that joins it
#: ("Manje the boss wants ...", "and the customer wants ...")
_OPENING_WORDS = "|".join(sorted(w for w in INTERJECTIONS | {"and", "so", "also", "but"} if w.isalpha()))
#: idioms read as the plain words the grammar has: "leave it as she is" ("she" for a place or a
#: load, as trades say), "all told" (in total), "keep it well away from P" (away from)
IDIOMS = (  # "15 pal. water", "min. 2": a trade abbreviation's full stop before a word in lower case or a
          # digit ends no sentence (before a capital it may: "must be 10 pal. Only day shift robots")
          (re.compile(r"\b(pal|pall|pals|plt|plts|pcs|pc|ctn|ctns|min|max|approx|qty|st)\.(?=\s+(?-i:[a-z0-9])|,)",
                      re.IGNORECASE), r"\1"),
          # German "5 Stk. Kugellager" (Stück: pieces): the unit's full stop before what it counts, which
          # German writes with a capital, ends no sentence
          (re.compile(rf"\b({_NUMBER})\s+(stk|stck)\.(?=\s+[A-Za-z])", re.IGNORECASE), r"\1 \2"),
          # "must have at the end 16", "... each 7 crates at the end." (German "am Ende"): finally, the
          # count wanted; never before "of" ("at the end of the aisle" is a where this reader lacks)
          (re.compile(rf"\s*\bat\s+the\s+end\b(?=\s+(?:{_NUMBER})\b|\s*[.,;!?]|\s*$)", re.IGNORECASE), ""),
          # "bring me 4 crates of valves" (German "bring mir"): to whom, said before the count
          (re.compile(rf"\b(bring|send|get)\s+me\s+(?=(?:{_NUMBER})\b)", re.IGNORECASE), r"\1 "),
          # "Please be so kind and exchange ..." (German "sei so gut und"): please
          (re.compile(r"\b(?:please\s+)?be\s+so\s+kind\s+(?:and|to)\s+", re.IGNORECASE), "please "),
          # Dutch "a.u.b." / "aub" (alstublieft: please) and "dank u" (thank you), said in English orders
          (re.compile(r"(?<![\w.])a\.?u\.?b\.?(?![\w])", re.IGNORECASE), "please"),
          (re.compile(r"\bdank\s+u\b", re.IGNORECASE), "thanks"),
          # Romanian "please" ("te rog", "va rog"), said in English orders
          (re.compile(r"\b(?:te|va)\s+rog\b", re.IGNORECASE), "please"),
          # Spanish and Portuguese "please" ("por favor", "por favour", "(se) faz favor"), said in English orders
          (re.compile(r"\b(?:por|(?:se\s+)?faz)\s+(?:favor|favour)\b", re.IGNORECASE), "please"),
          # "kl 06", "kl. 14:30" (Swedish and Norwegian "klockan": at o'clock): a time of day, no count
          (re.compile(r"\bkl\.?\s*(\d{1,2})(?:[:.]\d{2})?\b", re.IGNORECASE), r"\1 oclock"),
          # "until is full": the subject left out, as Portuguese, Spanish and Romanian leave it ("até estar cheia")
          (re.compile(r"\b(until|till)\s+is\s+full\b", re.IGNORECASE), r"\1 full"),
          # Portuguese dozens ("uma dúzia de", "meia dúzia de": a dozen, half a dozen), accents left out
          (re.compile(r"\b(?:(uma)|(meia))\s+duzias?(?:\s+de)?\b", re.IGNORECASE),
           lambda m: "12" if m.group(1) else "6"),
          # "EUR pal.", "6 pal water": pallets (a unit word; "pal" alone elsewhere may be a friend)
          (re.compile(r"\b(?:eur|euro)\.?\s+(?=pal)", re.IGNORECASE), ""),
          (re.compile(rf"\b({_NUMBER}|more|less|dozen)\s+pal(?:l|s|ls)?\b", re.IGNORECASE), r"\1 pallets"),
          # chat's slashed abbreviations: "w/o" without, "w/" with, "b/c" because, "p/" (Portuguese and
          # Spanish "para") for; any other slash is still refused as a symbol
          (re.compile(r"(?<![\w/])w/o(?![\w/])", re.IGNORECASE), "without"),
          (re.compile(r"(?<![\w/])w/(?=\s*[a-z0-9])", re.IGNORECASE), "with "),
          (re.compile(r"(?<![\w/])b/c(?![\w/])", re.IGNORECASE), "because"),
          (re.compile(r"(?<![\w/])p/(?=\s*[a-z0-9])", re.IGNORECASE), "for "),
          # "robots that carry 5 and up / and above": or more (never before where to: "5 and up to P")
          (re.compile(r"\b(\d+)\s+and\s+(?:up|upwards|above|over)\b(?!\s+(?:to|the|into|onto|on|in)\b)",
                      re.IGNORECASE), r"\1 or more"),
          # "please to move 5 X" (a learner's "please" with the infinitive): please move
          (re.compile(r"\b(please|pls|plz|kindly)\s+to\s+(?=[a-z])", re.IGNORECASE), r"\1 "),
          # "P is need 4 more X": needs
          (re.compile(rf"\b(?:is|are)\s+need(?:ed)?\s+(?=(?:{_NUMBER}|more|at\s+least|minimum)\b)", re.IGNORECASE),
           "needs "),
          # "returns make completely empty", "X on P make double" (the thing first, then "make" and what
          # it becomes, as Polish and Russian say it): make P empty, double X on P
          (re.compile(r"(^|[.;!?,:]\s+|\s-\s)([a-z][^.;!?,:]*?)\s+make\s+(?:[a-z]+ly\s+)?(empty|full)\b", re.IGNORECASE),
           r"\1make \2 \3"),
          (re.compile(r"(^|[.;!?,:]\s+|\s-\s)([a-z][^.;!?,:]*?)\s+make\s+(double|triple|half)\b", re.IGNORECASE),
           r"\1\3 \2"),
          # "minimum 6, not less", "maximum 5, not more": the bound said again
          (re.compile(r"\b((?:minimum|at\s+least)\s+\d+[^.;!?\n]*?)\s*,?\s*not\s+less\b", re.IGNORECASE), r"\1"),
          (re.compile(r"\b((?:maximum|at\s+most)\s+\d+[^.;!?\n]*?)\s*,?\s*not\s+more\b", re.IGNORECASE), r"\1"),
          # "between 10 and 14 bags on staging, not less not more", "12 exactly, no more no less": the
          # count or bounds said before, said again (after a number in the same sentence only)
          (re.compile(r"\b(\d+[^.;!?\n]*?)\s*,?\s*(?:not|no)\s+(?:less|fewer|more)\s*,?\s*(?:and\s+|or\s+|,\s*)?"
                      r"(?:not|no)\s+(?:less|fewer|more)\b", re.IGNORECASE), r"\1"),
          # "Robots that carry less than 4 should not do any of this", "Dont use Sher for any of it": no
          # part of the command's work, a rule for all of it
          (re.compile(r"\b(should|must|may|can|shall)(?:\s*not|n'?t|'?t)\s+do\s+any\s+of\s+(?:this|it|that|these|them)\b",
                      re.IGNORECASE), r"\1 not be used"),
          (re.compile(r"\b(use|using)\s+([^.,;:!?]{1,40}?)\s+for\s+any\s+of\s+(?:this|it|that|these|them)\b",
                      re.IGNORECASE), r"\1 \2"),
          # "mezz should hold 15 X, rack 2 also same" (Pakistani and Indian English): the same, too
          (re.compile(r"\b(?:the\s+)?(?:also\s+(?:the\s+)?same|same\s+also)(?=\s*(?:[.,;!?]|$))", re.IGNORECASE),
           "the same"),
          # "from 2 till 3 X there": between 2 and 3 (a number after "from" is no place)
          (re.compile(r"\bfrom\s+(\d+)\s+(?:till|until|til|to)\s+(\d+)\b", re.IGNORECASE), r"between \1 and \2"),
          # "ramp 1 and ramp 2 - swap everything between them": the places said first
          (re.compile(r"(^|[.;!?]\s*)([a-z][a-z0-9 ]*?\s+and\s+[a-z][a-z0-9 ]*?)\s*[-:]\s+(swap|switch|exchange)\s+"
                      r"(everything|all)\s+between\s+them\b", re.IGNORECASE), r"\1\3 \4 between \2"),
          # "divide 8 X equal between P and Q": evenly ("equal for P and Q" puts a preposition for another:
          # offered, never read, by the candidates' repairs)
          (re.compile(r"\b(divide|split|distribute|share)\b([^.;!?\n]*?)\s+equal\s+(?=(?:among|between)\b)",
                      re.IGNORECASE), r"\1\2 evenly "),
          # "from rack B take a third of the X away": take it away from rack B
          (re.compile(r"(^|[.;!?]\s*)from\s+([a-z][a-z0-9 ]*?)\s*,?\s+(take|remove|clear)\s+([^.;!?,\n]+?)\s+(away|off|out)\b",
                      re.IGNORECASE), r"\1\3 \4 \5 from \2"),
          # "3 more X on P, on Q also": the same for Q
          (re.compile(r",\s*(?:and\s+)?(?:on|at|in|for)\s+([a-z][^.;!?,\n]*?)\s+(?:also|too|as\s+well)\b(?=\s*(?:[.;!?,]|$))",
                      re.IGNORECASE), r", same for \1"),
          # "X on P and Q - 4 on each (one)": 4 X on each of P and Q
          (re.compile(r"(^|[.;!?]\s*)([a-z][a-z0-9_-]*)\s+(?:on|in|at)\s+([a-z][a-z0-9 ]*?\s+and\s+[a-z][a-z0-9 ]*?)\s*[-:]\s*"
                      r"(\d+)\s+(?:pallets\s+|pcs\s+)?(?:on|in|at)\s+each(?:\s+one)?\b", re.IGNORECASE), r"\1\4 \2 on each of \3"),
          # "robots what can carry 4": that (a relative "what", as learners and some dialects say it)
          (re.compile(r"\b([a-z]+s)\s+what\s+(?=(?:can|could|are|is|have|has|will)\b)", re.IGNORECASE), r"\1 that "),
          # "fill P full with X": fill P with X
          (re.compile(r"\b(fill\s+[^.;!?,\n]+?)\s+full\s+(?=with\b)", re.IGNORECASE), r"\1 "),
          # "min. 2", "max 5": at least, at most (never "40 min", which is minutes)
          (re.compile(r"\bmin\.?\s+(?=\d)", re.IGNORECASE), "minimum "),
          (re.compile(r"\bmax\.?\s+(?=\d)", re.IGNORECASE), "maximum "),
          (re.compile(r"\b(as|what)\s+she(?=\s+(?:is|was|stands|has)\b|['\u2019]s\b)", re.IGNORECASE), r"\1 it"),
          (re.compile(r"\ball\s+told\b", re.IGNORECASE), "in total"),
          (re.compile(r"\bwell\s+(?=away\s+from\b|clear\s+of\b)", re.IGNORECASE), ""),
          # "can one of yous shift ...": anyone of the team, as "can someone" is
          (re.compile(r"\bone\s+of\s+(?:you|yous|youse|ya|you\s+guys|you\s+lot)\b", re.IGNORECASE), "someone"),
          # "..., no worries", "no rush": a pleasantry; what follows it is read as ever
          (re.compile(r"\bno\s+(?:worries|worry|wukkas|rush|hurry|stress|probs|problem|problemo)\b", re.IGNORECASE), "thanks"),
          # office shorthand: "w/" is with; "by EOD" (end of day, of business) is when, which a goal
          # does not fix
          (re.compile(r"(?<![\w/])w/(?=\s|[a-z])", re.IGNORECASE), "with "),
          (re.compile(r"\s*\b(?:by|before|until|till)\s+(?:EOD|COB|EOB)\b", re.IGNORECASE), ""),
          # Scots "the now" closing a clause ("I'm busy the now"): now ("the now empty bay" is untouched)
          (re.compile(r"\bthe\s+now\b(?=\s*(?:[.,;:!?]|$))", re.IGNORECASE), "now"),
          # Dutch English "for the rest (all) to P" (voor de rest): the rest; "all the rest", "the
          # rest all": the rest, which is all of it already
          (re.compile(r"\b(?:for\s+)?the\s+rest\s+all\b|\ball\s+(?:the\s+)?rest\b|\bfor\s+the\s+rest\b", re.IGNORECASE), "the rest"),
          # "(on top of what's there)" after "more" / "extra" in its sentence: in addition, which
          # those words say already
          (re.compile(r"\b((?:more|extra|additional)\b[^.;!?\n]*?),?\s*on\s+top\s+of\s+what(?:['\u2019]s|\s+is)\s+"
                      r"(?:already\s+)?(?:there|on\s+it)\b", re.IGNORECASE), r"\1"),
          # "one of each on P, on top of what's (already) there": one more of each (convention 7)
          (re.compile(r"\bone\s+of\s+each\b([^.;!?\n]*?),?\s*on\s+top\s+of\s+what(?:['\u2019]s|\s+is)\s+"
                      r"(?:already\s+)?(?:there|on\s+it)\b", re.IGNORECASE), r"one more of each\1"),
          # "except those on P": the ones on P
          (re.compile(r"\b(except|bar|but|apart\s+from|other\s+than)\s+(?:those|this|that)\s+(?=(?:on|in|at|from)\b)", re.IGNORECASE),
           r"\1 the ones "),
          # Southern and spoken American English, as a headset's transcript writes it: "y'all" or
          # "you all" said to the team before the order ("listen up y'all", "y'all might could
          # swap ..."), "might could" a double modal (could), "real quick" (soon), "lemme see" a
          # pause to think, "let me get" / "can I get" asking for it, "don't nobody but R" (nobody but)
          (re.compile(r"\blisten\s+up\b\s*,?", re.IGNORECASE), ""),
          (re.compile(r"(^|[.;!?,:]\s*|\b(?:okay|ok|alright|so|and|then|now)\s+)(?:y['\u2019]?all|you\s+all)\b\s*,?\s*"
                      r"(?:(?:might\s+)?(?:could|can)\s+|need\s+to\s+|gotta\s+)?", re.IGNORECASE), r"\1"),
          (re.compile(r"\bmight\s+(?=(?:could|can|should|would)\b)", re.IGNORECASE), ""),
          (re.compile(r"\s*\b(?:real|right)\s+(?:quick|fast)\b(?=\s*(?:[.,;:!?]|$|(?:and|then|so|please|pls)\b))",
                      re.IGNORECASE), ""),
          (re.compile(r",?\s*\b(?:lemme|let\s+me|let['\u2019]?s)\s+(?:see|think)\b\s*,?", re.IGNORECASE), " "),
          (re.compile(r"\b(?:lemme|let\s+me|can\s+i|could\s+i)\s+get\b", re.IGNORECASE), "get"),
          (re.compile(r"\b(?:do\s*n['\u2019]?t|do\s+not|ai\s*n['\u2019]?t)\s+(?=nobody\s+but\b)", re.IGNORECASE), ""),
          # negative concord: "I don't want no more than 3 X on P" is at most 3 ("no fewer than": at least)
          (re.compile(r"\b(?:i|we)\s+(?:do\s*n['\u2019]?t|do\s+not)\s+want\s+(?:no\s+)?(more|fewer|less)\s+than\b",
                      re.IGNORECASE), lambda m: "i want at " + ("most" if m.group(1).lower() == "more" else "least")),
          # "the night shift robots ain't touchin nothing today" (a rule said as what they are not
          # doing): don't touch
          (re.compile(r"\b(?:are\s*n['\u2019]?t|ai\s*n['\u2019]?t|is\s*n['\u2019]?t|are\s+not|is\s+not)\s+touch(?:ing|in)\b",
                      re.IGNORECASE), "dont touch"),
          # negative concord after a verb that places or takes ("don't touch nothing in P", "don't put
          # none on P", "don't move nothing off P"): the second negative repeats the first. Never
          # after "leave", "keep", "let" or "want", where "don't leave P with no X" may mean the opposite
          (re.compile(r"\b((?:do\s*n['\u2019]?t|do\s+not|never|ca\s*n['\u2019]?t|cannot|wo\s*n['\u2019]?t)\s+"
                      r"(?:touch|put|move|send|take|bring|use|load|ship|stack|store|carry|shift|drop|pull|place|"
                      r"park|stage|give)\s+)(nothing|none|nobody|no|nuttin|nutten)\b", re.IGNORECASE),
           lambda m: m.group(1) + _CONCORD[m.group(2).lower()]),
          # "bring all the paint to the hardware side where it belongs": where it belongs is the place
          # just named, so the clause adds nothing (without a place before it, nothing is dropped)
          (re.compile(r"(\bto\s+(?:the\s+)?[\w-]+(?:\s+[\w-]+){0,2}?)\s*,?\s*where\s+(?:it|they|dey|dem)\s+"
                      r"belongs?\b", re.IGNORECASE), r"\1"),
          # "Ramp same thing.": the order before, for this place ("same for the ramp")
          (re.compile(r"(^|[.!?;]\s*)(?!(?:do|then|and|just|exactly|it|that|dat|same|the\s+same)\b)"
                      r"((?:the\s+)?[\w-]+(?:\s+[\w-]+)?)\s*,?\s+(?:the\s+)?same\s+(?:thing|ting)"
                      r"(?=\s*(?:[.!?;]|$))", re.IGNORECASE), r"\1same for \2"),
          # "one more of each thing we carry": of each product
          (re.compile(r"\beach\s+(?:thing|ting)(?:\s+(?:we|you)\s+(?:carry|stock|have|got|gat|sell|keep))?\b",
                      re.IGNORECASE), "each product"),
          # Cajun English: "mais" (well) opening a sentence ("Mais, bring twelve ..."; never before a
          # count, where a Portuguese speaker's "mais 4" is "4 more": WORD_ORDER), "ah non" (oh no)
          (re.compile(rf"(^|[.;!?:]\s*)mais\b(?!\s+(?:de\s+)?{_NUMBER})\s*,?\s*", re.IGNORECASE), r"\1"),
          # "Ah non, ...", "Oh no!" opening a sentence: dismay, not a negation of anything (after a count,
          # "oh no, 12" still takes the count back)
          (re.compile(r"(^|[.;!?]\s*)(?:ah|oh|aw)\s+(?:non|no)\s*[,!.]+\s*", re.IGNORECASE), r"\1"),
          # "Okay, last thing: ...", "one more thing, ...": a signpost opening a sentence
          (re.compile(r"(^|[.;!?]\s*)(?:(?:ok|okay|and|so|oh)\s*,?\s*)?(?:one\s+)?(?:last|final|more|other)\s+thing\s*[,:.!-]+\s*",
                      re.IGNORECASE), r"\1"),
          # "out the back shed", "keep R out the cold room": out of, except after a verb it completes
          # ("clear out the dock", "lay out the pallets")
          (re.compile(r"\b([a-z][a-z0-9_'-]*)\s+out\s+(?=the\b)", re.IGNORECASE),
           lambda m: m.group(0) if m.group(1).lower() in _OUT_VERBS else m.group(1) + " out of "),
          # "pass by P and grab 3 X", "swing by P and pick up ...": what is taken, taken from P
          (re.compile(r"\b(?:pass|stop|swing|drop|come|go)\s+(?:by|past)\s+((?:the\s+)?[a-z][a-z0-9 _-]*?)\s+and\s+"
                      r"(grab|get|pick\s+up|take|collect|fetch)\s+([^.,;!?]+?)(?=\s*(?:[.,;!?]|$))", re.IGNORECASE),
           r"\2 \3 from \1"),
          # "... out of P. Put it wherever(, but ...)": where to is left open, as it is unsaid
          (re.compile(r"[.;!]?\s*(?:and\s+)?(?:put|stick|take|send)\s+(?:it|them|em|those)\s+(?:wherever|anywhere)"
                      r"(?:\s+you\s+(?:want|like))?(?=\s*(?:[,.;!]|$))", re.IGNORECASE), ""),
          # "put as many X on P as Q has (now)": as many X as Q has, on P (the grammar's order)
          (re.compile(r"\bas\s+(many|much)\s+([a-z][a-z0-9 _-]*?)\s+((?:on|onto|to|into|in|at)\s+[a-z][a-z0-9 _-]*?)\s+as\s+"
                      r"([a-z][a-z0-9 _-]*?)\s+(has\s+got|has|holds|got|have)((?:\s+(?:right\s+)?now)?)(?=\s*(?:[.,;!?]|$))",
                      re.IGNORECASE), r"as \1 \2 as \4 \5\6 \3"),
          # "split 8 X from P evenly to Q and R" ("equally into", "evenly over"): evenly between them
          (re.compile(r"\b((?:split|divide|distribute|share|spread)\b[^.;!?]*?)\s+(?:evenly|equally)\s+"
                      r"(?:to|into|over|across|among|amongst)\s+", re.IGNORECASE), r"\1 evenly between "),
          # "the MCU only ESD robots can touch", "coils only the strongest robot may carry": the
          # thing said first, the rule about it after: "only <robots> can touch <thing>"
          (re.compile(r"(^|[.;!?,:]\s*)((?:the\s+)?[a-z][a-z0-9_-]*(?:\s+[a-z][a-z0-9_-]*){0,2})\s+only\s+"
                      r"((?:the\s+)?[a-z][a-z0-9_-]*(?:\s+[a-z][a-z0-9_-]*){0,2})\s+(can|may|should|must|will)\s+"
                      r"(touch|carry|move|handle|take|lift)(?=\s*(?:[.,;!?]|$))", re.IGNORECASE), r"\1only \3 \4 \5 \2"),
          # "get 6 X slotted on P", "get em put away in P": the order is the move ("get" a causative)
          (re.compile(r"\b(get\b(?:(?!\b(?:and|then)\b)[^.;!?\n,])*?)\s+(?:slotted|staged|moved|stocked|put\s+away|sent|brought|taken|shifted|"
                      r"carried|dropped|parked|put)\s+(?=(?:on|onto|to|into|in|at|over|up|down)\b)", re.IGNORECASE), r"\1 "),
          # "3 X sitting on P", "the fans stacked in P": where they are, said of the things
          # (never after "is" / "be": "P is sitting at 3 X" reports the stock, "should be sitting at" asks it)
          (re.compile(r"(?<!\bis\s)(?<!\bare\s)(?<!\bbe\s)(?<!\bwas\s)(?<!\bbeen\s)"
                      r"\b(?:sitting|sat|lying|laying|stacked|stored)\s+(?=(?:on|in|at)\b)", re.IGNORECASE), ""),
          # "take 6 X from P on over to Q": over to Q
          (re.compile(r"\bon\s+over\s+(?=to\b)", re.IGNORECASE), "over "),
          # "put em away on aisle 14", "put away 5 X on P": put them there (a warehouse keeps no homes)
          (re.compile(r"\bput\s+(them|em|it|those)\s+away\s+(?=(?:on|onto|in|into|at|over)\b)", re.IGNORECASE), r"put \1 "),
          (re.compile(r"\bput\s+away\b(?=(?:(?!\b(?:and|then)\b)[^.;!?\n,])*?\b(?:on|onto|in|into|at)\b)", re.IGNORECASE),
           "put"),
          # "I'd like to see 12 X on P", "I want to see ...": what the speaker wants there
          (re.compile(r"\b(want|like|need)\s+to\s+see\b", re.IGNORECASE), r"\1"),
          # "none of the night shift robots are to be used": do not use them (the negation kept, said
          # as the grammar has it; "the AMRs are not to be used" it reads as said)
          (re.compile(r"\bnone\s+of\s+((?:the\s+)?[a-z_ ]+?)\s+(?:are|is)\s+to\s+be\s+used\b", re.IGNORECASE),
           r"dont use \1"),
          # "all the popok to bulk, except the one in pickface": "the one" left out of a move is what
          # lies there (a pallet, a pile), as "the ones in P" is; "except one in P" counts one
          (re.compile(r"\b(except(?:\s+for)?|but\s+not|apart\s+from|other\s+than|excluding)\s+the\s+one\s+"
                      r"(?=(?:in|on|at|from)\b)", re.IGNORECASE), r"\1 the ones "),
          # "All the kava up to the mezz, every bag": "every" and a unit said again after "all" in the
          # same sentence restates it (after a count it would contradict it, and is left as said)
          (re.compile(r"(\b(?:all|everything)\b[^.;!?\n\d]*?),\s*every\s+(?:single\s+|last\s+)?(?:one|unit|piece|"
                      + "|".join(sorted(PACKAGING_WORDS | CONTAINERS, key=len, reverse=True))
                      + r")\b(?=\s*(?:[.,;!?]|$))", re.IGNORECASE), r"\1"),
          # "fill P with X, as far as it goes": to the limit, which "fill" says
          (re.compile(r",?\s*\bas\s+far\s+as\s+(?:it|they)\s+(?:goes|go|will\s+go|can\s+go)\b", re.IGNORECASE), ""),
          # "fill P up with X, as many as it'll take": the limit again, said after a fill only (elsewhere
          # "as many as" is a count, read as said)
          (re.compile(r"\b(fill\b[^.;!?\n]*?),?\s*as\s+(?:many|much)\s+as\s+(?:it|they)\s*(?:['\u2019]?ll|will|can|ll)?\s+"
                      r"(?:take|hold|fit|go)\b", re.IGNORECASE), r"\1"),
          (re.compile(r"\b(fill\b[^.;!?\n]*?),?\s*as\s+(?:many|much)\s+as\s+itll\s+(?:take|hold|fit|go)\b", re.IGNORECASE), r"\1"),
          # a sentence "All the X into P" says no verb: a move, as the same words after "move" are (never
          # before a count: "every shelf to 4 X" is a final count)
          (re.compile(rf"(^|[.;!?]\s+)((?:all|every)\s+(?:of\s+)?(?:the\s+)?[a-z][a-z0-9_-]*\s+(?:to|into|onto|over\s+to)\s+)"
                      rf"(?!(?:{_NUMBER}|\d))", re.IGNORECASE), r"\1move \2"),
          # "P has at least 5 X on." closing its sentence: on it
          (re.compile(r"\b(has|have|got|holds?)\b([^.;!?\n]*?\d[^.;!?\n]*?)\s+on(?=\s*(?:[.;!?]|$))", re.IGNORECASE), r"\1\2 on it"),
          # "at (the) end of (the) day / shift": by the end, an aside the grammar has (its words
          # "day", "night" stay fillers and words of tags: "night shift robots")
          (re.compile(r"\b(?:at|by|before|for)\s+(?:the\s+)?end\s+of\s+(?:the\s+)?(?:day|shift|night|week)\b",
                      re.IGNORECASE), "by end"),
          # South African "sharp sharp" (all right, goodbye, quickly): no content
          (re.compile(r"[,;]?\s*\bsharp\s+sharp\b", re.IGNORECASE), ""),
          # "between 4 to 6" (Indian English): between 4 and 6; "b/w": between; "&": and
          (re.compile(rf"\bbetween\s+({_NUMBER})\s+to\s+(?={_NUMBER})", re.IGNORECASE), r"between \1 and "),
          (re.compile(r"(?<![\w/])b/w(?=\s)", re.IGNORECASE), "between"),
          (re.compile(r"\s*&\s*"), " and "),
          # "3 to dispatch and remaining to bay 2": the rest
          (re.compile(r"\b(and|,)\s+(?:the\s+)?remaining\s+(?=(?:to|into|onto|in|on|at)\b)", re.IGNORECASE), r"\1 the rest "),
          # "just now", "now now" closing a clause (South African: later, soon): a time, as "now" is
          (re.compile(r"\b(?:just|now)\s+now\b(?=\s*(?:[.,;:!?]|$))", re.IGNORECASE), "now"),
          # "one time" closing a clause, or before the one it is said to (Fiji, Nigerian and Ghanaian
          # English: at once, "empty the wharf door one time bro"): a time, as "now" is
          (re.compile(r"\bone\s+time\b(?=(?:\s+(?:" + "|".join(sorted(CLOSERS)) + r"))?\s*(?:[.,;:!?]|$))",
                      re.IGNORECASE), "now"),
          # "at the minute", "at the mo" (British): now
          (re.compile(r"\bat\s+(?:the\s+)?(?:minute|mo)\b", re.IGNORECASE), "now"),
          # "at the very least 3": at least ("at the very most": at most)
          (re.compile(r"\bat\s+(?:the\s+)?very\s+(least|most)\b", re.IGNORECASE), r"at \1"),
          # "..., not fussed where", "I'm not bothered which": the speaker leaves open what the
          # command leaves open; it fixes nothing, and is left out ("don't mind which" likewise)
          (re.compile(r"[,;]?\s*\b(?:(?:i\s*['\u2019]?m|im|i\s+am)\s+)?not\s+(?:fussed|bothered|mithered|picky|particular)"
                      r"\s+(?:where|which|what|how|who|about\s+which)\b", re.IGNORECASE), ""),
          (re.compile(r"[,;]?\s*\b(?:i\s+)?(?:don['\u2019]?t|do\s+not)\s+mind\s+(?:where|which|how|who)(?:\s+(?:from|to))?\b",
                      re.IGNORECASE), ""),
          # "get 3 X onto the dock from wherever": where from is left open, as it is unsaid
          (re.compile(r"[,;]?\s*\bfrom\s+wherever\b(?!\s+(?:is|it|they|there|you|we))", re.IGNORECASE), ""),
          # "..., don't ask me why": no content (an idiom: no negation of anything said)
          (re.compile(r"[,;]?\s*\b(?:do\s*n['\u2019]?t|do\s+not|doh)\s+ask\s+(?:me\s+)?(?:why|how\s+come)\b", re.IGNORECASE), ""),
          # "Don't ask." closing its clause: the same
          (re.compile(r"[,;]?\s*\b(?:do\s*n['\u2019]?t|do\s+not|doh)\s+ask(?:\s+me)?(?=\s*(?:[.,;:!?]|$))", re.IGNORECASE), ""),
          # "..., no excuses": insisting, no content
          (re.compile(r"[,;]?\s*\bno\s+(?:excuses|messing(?:\s+about|\s+around)?|arguments)\b", re.IGNORECASE), ""),
          # "forklifts only on this lot (job, run)" and bare "on this": "on this one", the job
          (re.compile(r"\bonly\s+on\s+this(?:\s+(?:lot|job|run|batch))?(?!\s+one\b)\b", re.IGNORECASE), "only on this one"),
          # "Only robots that carry 5 or more on this" ("on that", "on dat"): a rule opened by "only",
          # closed by "on this"
          (re.compile(r"(\bonly\b[^.;:!?,]*?\bon\s+)(?:this|that|dis|dat)(?=\s*(?:[.,;:!?]|$))", re.IGNORECASE),
           r"\1this one"),
          (re.compile(r"(\bonly\b[^.;:!?,]*?\bon\s+)(?:that|dis|dat)(?=\s+one\b)", re.IGNORECASE), r"\1this"),
          # "the boss wants P to have N", "the customer wants ...": a wish passed on is the order
          (re.compile(r"(^|[.;!?]\s*)(?:the\s+)?(?:boss|manager|gaffer|supervisor|office|customer|client|he|she|they)\s+"
                      r"wants?\s+(?=(?:the\s+)?[a-z][a-z0-9 _-]*?\s+to\s+(?:have|hold|be|get|end\s+up|stay|keep)\b)",
                      re.IGNORECASE), r"\1i want "),
          # "Boss say switch round P and Q", "the manager says to bring ...": an order passed on is the
          # order (only before a verb of the orders: "the boss says P is full" is a report, left as said)
          (re.compile(r"(^|[.;!?]\s*)(?:the\s+)?(?:boss|manager|gaffer|supervisor|office)\s+(?:say|says|said)\s*,?\s*"
                      r"(?:that\s+|to\s+)?(?=(?:switch|swap|move|bring|send|take|put|clear|empty|fill|double|halve|"
                      r"give|get|keep|leave|shift|load|stack|split|spread)\b)", re.IGNORECASE), r"\1"),
          # "switch round P and Q", "swap around P and Q": the particle said before the places, as
          # "switch P and Q round" is read
          (re.compile(r"\b(switch|swap)\s+(?:a?round|over)\s+(?=(?:the\s+)?[a-z])", re.IGNORECASE), r"\1 "),
          # "only robots dat could carry 4 or more": a skill said with "could" is what they can carry
          (re.compile(r"\b(that|dat|which|who)\s+could\s+(carry|lift|take|handle)\b", re.IGNORECASE), r"\1 can \2"),
          # Irish "go raibh (míle) maith agat / agaibh" (thank you), "mo bhuachaill" (my lad), "grand job":
          # no content anywhere; "so it is" (said for stress) and "good girl" (lad, man: praise of who is
          # addressed) only closing a clause
          (re.compile(r"[,;]?\s*\b(?:go\s+raibh\s+(?:mile\s+)?maith\s+(?:agat|agaibh)|mo\s+bhuachaill|grand\s+job)\b",
                      re.IGNORECASE), ""),
          (re.compile(r"[,;]?\s*\b(?:so\s+it\s+is|good\s+(?:girl|boy|lad|lass|man|woman))\b(?=\s*(?:[.,;:!?]|$))",
                      re.IGNORECASE), ""),
          # Maltese "jekk jogħġbok" (please, spelt without its dots and strokes, and as often typed)
          # and the tag "mhux hekk?" (isn't it?) closing a clause: no content
          (re.compile(r"\bjekk\s+j(?:o|u)?g?h?g?h?bok\b", re.IGNORECASE), "please"),
          (re.compile(r"[,;]?\s*\bmhux\s+hekk\b(?=\s*(?:[.,;:!?]|$))", re.IGNORECASE), ""),
          # "max 10 X from now on", "going forward": the goal holds when the work is done, which adds nothing
          (re.compile(r"[,;]?\s*\b(?:from\s+now\s+on|going\s+forward|from\s+here\s+on(?:\s+in)?)\b(?=\s*(?:[.,;:!?]|$))",
                      re.IGNORECASE), ""),
          # "one more of each in P, on top of what's in there (already)": "more" says it already
          (re.compile(r"(\bmore\b[^.;!?]*?)[,;]?\s*\bon\s+top\s+of\s+what(?:\s+is|['\u2019]?s)\s+(?:already\s+)?"
                      r"(?:(?:in|on)\s+)?(?:there|it)(?:\s+already)?\b", re.IGNORECASE), r"\1"),
          # "bring all the X to P, every single tin", "clear out P, every last thing", "swap everything on
          # P with Q, all of it": "all", "every" or emptying says it already
          (re.compile(r"(\b(?:all|every|everything|empty|clear|clean)\b[^.;!?]*?)[,;]?\s*\b(?:every\s+(?:single|last)"
                      r"(?:\s+(?:one|[a-z]+))?|all\s+of\s+(?:it|them|dem))(?=\s*(?:[.,;:!?]|$))", re.IGNORECASE), r"\1"),
          # "move every last X to P": every X; "each and every place": every place
          (re.compile(r"\bevery\s+last\b(?=\s+[a-z])", re.IGNORECASE), "every"),
          (re.compile(r"\beach\s+and\s+every\b", re.IGNORECASE), "every"),
          # "at least 10 X on P, more is fine": "at least" says it already
          (re.compile(r"(\b(?:at\s+least|minimum|or\s+more)\b[^.;!?]*?)[,;]?\s*\b(?:any(?:thing)?\s+)?more\s+(?:is|['\u2019]?s)\s+"
                      r"(?:fine|ok|okay|good|alright|no\s+problem)\b", re.IGNORECASE), r"\1"),
          # "don't touch P at all": "at all" stresses the "not" before it
          (re.compile(r"(\b(?:do\s*n['\u2019]?t|doh|do\s+not|never|not)\b[^.;!?,]*?)\s+at\s+all\b(?=\s*(?:[.,;:!?]|$))",
                      re.IGNORECASE), r"\1"),
          # Trinidadian "leave it just so": as it is; "now for now": right now
          (re.compile(r"\b(leave|keep)\s+(it|them|dem)\s+just\s+so\b", re.IGNORECASE), r"\1 \2 as it is"),
          (re.compile(r"\bnow\s+for\s+now\b", re.IGNORECASE), "now"),
          # "... by the time the truck reach(es)": when, which a goal does not fix
          (re.compile(r"[,;]?\s*\bby\s+the\s+time\s+[^.,;:!?\d]*", re.IGNORECASE), ""),
          # Trinidadian ", is so dem want it" (that's how they want it), opening its clause: why, no order
          (re.compile(r"[,.;]\s*is\s+so\s+(?:dem|they|dey|he|she|we|i|the\s+[a-z]+)\b[^.;:!?,\d]*", re.IGNORECASE), ""),
          # "The cement in the big shed is too much, ... Halve it": there is too much X in P (a topic
          # that "it" takes up), as "there's too much X in P" is read
          (re.compile(r"(^|[.;:!?]\s*)the\s+([a-z][a-z0-9 -]*?)\s+(in|on|at)\s+(the\s+)?([a-z][a-z0-9 -]*?)\s+(?:is|are)\s+"
                      r"too\s+(much|many)\b", re.IGNORECASE), r"\1there is too \6 \2 \3 \4\5"),
          # "the boss wants the mezz and the counter swapped", "customer wants 5 X on P": a wish the
          # speaker passes on is the order, as "I want" is
          (re.compile(rf"(^|[.;:!?]\s*|,\s*|\b(?:{_OPENING_WORDS})\s+)(?:the\s+|our\s+|my\s+)?(?:boss|manager|supervisor|"
                      r"gaffer|foreman|client|customer|owner|director)\s+wants\b(?!\s+to\b)", re.IGNORECASE), r"\1i want"),
          # "P, which has 11 X right now, needs to come down to 6": P should have 6 X (the count it has
          # now is what the world says anyway)
          (re.compile(rf"\b([a-z][a-z0-9-]*(?:\s+[a-z0-9]+)?)\s*,\s*which\s+(?:has|have|got|holds?)\s+(?:{_NUMBER}|\d+)\s+"
                      r"([a-z][a-z0-9_-]*(?:\s+(?!right\b|now\b|at\b)[a-z][a-z0-9_-]*)?)(?:\s+(?:right\s+now|now|at\s+the\s+moment))?\s*,\s*"
                      r"(?:needs?\s+to|has\s+to|have\s+to|should|must)\s+(?:come|go|get|be\s+brought)\s+(?:down|up)\s+to\s+"
                      rf"({_NUMBER}|\d+)\b", re.IGNORECASE), r"\1 should have \3 \2"),
          # "move 10 X off P, wherever there's space": where to is left open, as it is unsaid
          (re.compile(r"[,;]?\s*\bwherever\s+there(?:\s+is|['\u2019]?s)\s+(?:space|room)\b", re.IGNORECASE), ""),
          # "the night shift ones stay on charge": those robots are not used
          (re.compile(rf"\b((?:the\s+)?{_ROBOT_WORD}(?:\s+{_ROBOT_WORD}){{0,2}})\s+(?:stays?|remains?)\s+on\s+(?:the\s+)?"
                      r"(?:charge|charger|charging)\b", re.IGNORECASE), r"dont use \1"),
          # Maltese "le" (no) said twice before a count, taking one back ("10 X to P, le le, 8"), as "no no"
          (re.compile(rf",\s*le(?:\s*,?\s*le)+\s*(?=,?\s*(?:{_NUMBER}|\d))", re.IGNORECASE), ", no no "),
          # "P should come to N X", "must come to": a count P ends with, as "should be" says
          (re.compile(rf"\b(should|must|has\s+to|have\s+to|needs?\s+to)\s+come\s+to\b(?=\s+(?:(?:a|an)\s+)?(?:{_NUMBER}|\d))",
                      re.IGNORECASE), r"\1 be"),
          # "... goods out (driver took the wrong lane), the cage ...": a closing bracket before a comma
          # is that comma (two marks in a row would stand where an aside was set aside)
          (re.compile(r"\)\s*(?=[,;])"), " "),
          # "... to the dock instead": the order replaces another, closing "instead" adds nothing
          (re.compile(r"\s+\binstead\b(?=\s*(?:[.,;:!?]|$))", re.IGNORECASE), ""),
          # northern "an' all" closing a clause: as well
          (re.compile(r"\ban['\u2019]?\s+all\b(?=\s*(?:[.,;:!?]|$))", re.IGNORECASE), "as well"),
          # "every shelf in the place": every shelf (the place, the building: the whole store)
          (re.compile(r"\b(every|each|all(?:\s+the)?)\s+([a-z]+)\s+(?:in\s+the\s+(?:place|building|warehouse|shed|site)|"
                      r"on\s+the\s+floor)\b", re.IGNORECASE), r"\1 \2"),
          # "all the vacs we got", "every X we have": all of them
          (re.compile(r"\b((?:every|each|all(?:\s+the)?)\s+[a-z]+)\s+(?:we|you)\s+(?:got|have|['\u2019]?ve\s+got)\b",
                      re.IGNORECASE), r"\1"),
          # a count taken back as dictated, with no comma ("five fans no scratch that make it seven"):
          # the comma the taking back is heard with
          (re.compile(r"(?<=[a-z0-9])(?<!\bno)\s+((?:no\s+)?(?:wait|scratch\s+that|sorry|hold\s+on)\b[\s,]*(?:no\s+)?"
                      r"(?:make\s+(?:it|that)|i\s+mean|i\s+meant)\b)", re.IGNORECASE), r", \1"),
          # "all them flatpacks", "both those racks": the demonstrative after "all" / "both" is "the"
          # (never before a preposition or a link word: "all those on P" is left as said)
          (re.compile(r"\b(all|both)\s+(?:them|those|these)\s+(?!(?:on|in|at|from|to|of|off|over|out|up|down|that|which|there|"
                      r"here|and|or|but|with|for|are|is|were|was|will|should|must|can|go|going)\b)(?=[a-z])", re.IGNORECASE), r"\1 the "),
          # "share X out (even) between P and Q": the particle of "share out" says what "share" says;
          # "even" before "between" is "evenly"
          (re.compile(r"\b((?:share|split|divide|spread|dish|parcel)\b[^.;!?\n]*?)\s+out\s+(?=(?:even|evenly|equally|between|"
                      r"among|amongst|across|over)\b)", re.IGNORECASE), r"\1 "),
          (re.compile(r"\beven\s+(?=(?:between|among|amongst|across)\b)", re.IGNORECASE), "evenly "),
          # "and despatch (the) same", "same for despatch": the elided statement again, as "too" says
          (re.compile(r"\band\s+([a-z][a-z0-9_-]*)\s+(?:the\s+)?same\b(?=\s*(?:[.,;:!?]|$))", re.IGNORECASE), r"and \1 too"),
          (re.compile(r"[.,;]\s*(?:and\s+)?(?:the\s+)?same\s+(?:for|with|goes\s+for)\s+([a-z][a-z0-9_-]*)\b(?=\s*(?:[.,;:!?]|$))",
                      re.IGNORECASE), r", and \1 too"),
          # "as many X as it has Y": the place said already; "as many X as Y" on it ("as many X as it
          # has now" is twice its own count, read as said)
          (re.compile(r"\b(as\s+(?:many|much)\s+[a-z][a-z0-9_-]*\s+as)\s+(?:it|she)\s+(?:has|holds|got|has\s+got)\b"
                      r"(?=\s+(?!(?:now|today|currently|right|at|already|there|here|on|in|of|to)\b)[a-z])", re.IGNORECASE),
           r"\1"),
          # "check P, it needs ...": look at P; "it" is P, the sentence says what P needs
          (re.compile(r"(^|[.;!?]\s*)check\s+(?:on\s+)?((?:the\s+)?[a-z][a-z0-9_ -]{0,24}?)(?:\s*,?\s*(?:pls|please|plz))?\s*,\s*"
                      r"(?:it|she)\b(?=\s*(?:is|has|needs|should|must|shld)\b)", re.IGNORECASE), r"\1\2"),
          # "swap P and Q, the whole lot, everything (on them)", "swap P and Q, everything, the trucks
          # changed doors": a whole swap, which "swap P and Q" is
          (re.compile(r"\b(swap\s[^.,;!?\n]*?\band?\s[^.,;!?\n]*?)\s*[,.:]\s*(?:(?:the\s+)?whole\s+lot|every(?:thing|ting)|all"
                      r"(?:\s+of\s+it)?)(?:\s*,\s*(?:(?:the\s+)?whole\s+lot|every(?:thing|ting)|all\s+of\s+it"
                      r"|all\s+(?:the|de|di)\s+stock))*"
                      r"(?:\s+on\s+(?:them|both|there))?(?=\s*(?:[.,;!?]|$))", re.IGNORECASE), r"\1"))
#: the order of words of a speaker whose first language puts them so (Portuguese and Spanish
#: "mais 4", "mais de 4", "o dobro de", "longe de"), read as English puts them: "add more 4 tubes"
#: is "add 4 more tubes", "no more of 4" is "no more than 4", "the double of the saddles" is
#: "double the saddles", "stay away of P" is "stay away from P". Each reads a number or a place
#: word after it as before: nothing here adds a count or a name.
#: verbs a modal may stand before with a stray "to" ("must to have"), for :data:`WORD_ORDER`
_BARE_VERBS = "|".join(("be", "have", "hold", "keep", "stay", "remain", "contain", "store", "get", "go", "end", "take",
                        "move", "put", "bring", "carry", "touch", "enter", "use", "handle", "leave", "send", "fill",
                        "empty", "swap"))
WORD_ORDER = ((re.compile(rf"\bmore\s+({_NUMBER})(?!\s*(?:than|%|percent))", re.IGNORECASE), r"\1 more"),
              (re.compile(rf"\b(more|less|fewer)\s+of\s+(?={_NUMBER})", re.IGNORECASE), r"\1 than "),
              (re.compile(r"\b(?:the\s+)?(double|triple)\s+of\b", re.IGNORECASE), r"\1"),
              (re.compile(r"\baway\s+of\b", re.IGNORECASE), "away from"),
              # "except ones of rack 3" (Spanish "los de"): the ones on it
              (re.compile(r"\bones\s+of\b", re.IGNORECASE), "ones on"),
              # "5 alternators each one" (Spanish "cada uno") closing a clause: each
              (re.compile(r"\beach\s+one\b(?=\s*(?:[.,;:!?]|$))", re.IGNORECASE), "each"),
              # "rack 3 stays like it is": as it is
              (re.compile(r"\blike\s+(it|they)\s+(is|are|was|were)\b", re.IGNORECASE), r"as \1 \2"),
              # "a dozen less two": minus, between two amounts only ("2 less than" is read as said)
              (re.compile(rf"\b({_NUMBER})\s+less\s+(?={_NUMBER})", re.IGNORECASE), r"\1 minus "),
              # "give us / give me 4 more X on P": the more wanted there ("give" alone names no place)
              (re.compile(rf"\bgive\s+(?:us|me)\s+(?=(?:{_NUMBER})\s+(?:more|extra)\b)", re.IGNORECASE), ""),
              # "P has 4 X too much" (Dutch "te veel", German "zu viel"): too many
              (re.compile(rf"\b({_NUMBER}\s+[a-z]+\s+)too\s+much\b", re.IGNORECASE), r"\1too many"),
              # "fill P up to the top": the article of "the top" / "the brim" says nothing
              (re.compile(r"\b(to|until|till)\s+the\s+(top|brim)\b", re.IGNORECASE), r"\1 \2"),
              # "P must to have 12 X" (Spanish "debe de tener", Portuguese "deve de"): a modal takes the
              # bare verb, so the "to" between them says nothing
              (re.compile(rf"\b(must|should|shall|can|could|would)\s+to\s+(?=(?:not\s+)?(?:{_BARE_VERBS})\b)",
                          re.IGNORECASE), r"\1 "),
              # "P must stay with 6 X" (Portuguese "ficar com", Spanish "quedarse con"): must have; "P cannot
              # stay with less than 8 X": must have at least 8
              (re.compile(rf"\b(?:can\s*not|cannot|cant|can't|must\s+not|mustnt)\s+(?:stay|remain|be|end)\s+with\s+"
                          rf"(?:less|fewer)\s+than\s+(?={_NUMBER}\b)", re.IGNORECASE), "must have at least "),
              (re.compile(rf"\b(must|should|has\s+to|have\s+to)\s+(?:stay|remain)\s+with\s+(?={_NUMBER}\b)",
                          re.IGNORECASE), r"\1 have "),
              # "divide 8 X between P and Q, half half" (Portuguese "meio a meio"): evenly
              (re.compile(r"\b((?:divide|split|share)\b[^.;!?\n]*?\s+between\s+[^.;!?\n]+?)"
                          r"\s*,?\s*half\s+(?:and\s+)?half\b", re.IGNORECASE), r"\1 evenly"),
              # "(the) robots must (to) take 6 X ...": an order said of the robots is an order to them (a
              # text rule: "robots" is read as the robots' group before request frames are)
              (re.compile(r"(^|[.;!?]\s*)(?:the\s+)?(?:robots|bots)\s+(?:must|should|have\s+to|need\s+to)\s+(?:to\s+)?"
                          r"(?=(?:take|move|bring|carry|send|put)\b)", re.IGNORECASE), r"\1"))

#: discourse particles of Singapore, Malaysian and Hong Kong English, closing a clause ("add 4
#: more lah", "botak off today ah,", "kitting make it 8 la", "dun touch rack B ar"): they colour
#: the clause, they say nothing of the order
PARTICLES = ("lah", "leh", "lor", "hor", "meh", "liao", "sia", "ah", "ha", "la", "ar", "wor", "lo", "ga", "mah",
             # Japanese's closing "ne" and "yo" ("yoroshiku ne": OK?)
             "ne", "yo",
             # Thai's polite and softening particles ("... to pickface na", "... ka", "na ka", "krub",
             # "jaa"): the speaker's manners, nothing of the order
             "na", "ka", "kha", "krub", "khrub", "krap", "khrap", "jaa", "ja", "naka")
_PARTICLE = re.compile(r"(?:\s+(?:" + "|".join(PARTICLES) + r")\b)+(?=\s*(?:[.,;:!?()]|$))", re.IGNORECASE)
#: Tagalog's honorific and softening particles in Taglish ("move po 3 X", "add naman 2 X"), said
#: anywhere in a clause: politeness, nothing of the order
TAGALOG_PARTICLES = ("po", "naman")
_TAGALOG_PARTICLE = re.compile(r"\s*\b(?:" + "|".join(TAGALOG_PARTICLES) + r")\b", re.IGNORECASE)
#: Japanese politeness said in English orders ("... please move, onegaishimasu", "yoroshiku ne",
#: "OK desu", "..., hai"): please, thank you in advance, the copula, yes; nothing of the order
_JAPANESE_POLITE = re.compile(r"\s*\b(?:onegai\s*shimasu|onegai|yoroshiku|kudasai|desu|hai)\b", re.IGNORECASE)
#: Indonesian's closing "ya" ("... to promo ya", "... ya pak", "ya kak": OK?, said to the reader),
#: never after a request tag's modal ("... would ya": you)
_INDONESIAN_YA = re.compile(r"(?<!would)(?<!could)(?<!will)(?<!can)(?<!wont)(?<!thank)\s+ya"
                            r"(?:\s+(?:pak|bu|kak|mas|mbak|bos|gan))?\b(?=\s*(?:[.,;:!?()]|$))", re.IGNORECASE)
#: Indonesian "tolong", "mohon" (please) before an order
_INDONESIAN_PLEASE = re.compile(r"\b(?:tolong|mohon)\b", re.IGNORECASE)
#: "minimal 10", "maksimal 8" (Indonesian, Dutch "minimaal"): at least, at most, before a count
_MINIMAL = re.compile(r"\b(minimal|maksimal|maximal)(?=\s+\d)", re.IGNORECASE)
#: Japanese honorifics on a name ("Gonta-kun", "Tanaka-san"): the one named
_HONORIFIC = re.compile(r"\b([a-z][a-z0-9]*)-(?:san|kun|chan|sama)\b", re.IGNORECASE)
#: Tagalog's object marker before a count ("transfer ng 3 X": transfer 3 X)
_TAGALOG_MARKER = re.compile(rf"\bng\s+(?={_NUMBER})", re.IGNORECASE)
#: Tagalog's request prefixes on an English verb ("paki-move", "pakiempty", "pa-add", "i-transfer",
#: and "pa move" opening a clause): please <verb>; read so only when the verb is a word the grammar
#: knows (:meth:`Lexicon._chat_said_plainly`)
_TAGALOG_REQUEST = re.compile(r"\b(?:paki-?\s*|pa-\s*|i-\s*|(?:^|(?<=[.,;:!?]))\s*pa\s+)(?=([a-z]+))", re.IGNORECASE)
#: a tag that asks whether the order can be done, closing it ("take 5 off can", "... can or not?",
#: "... ok?"): it asks nothing more than the order does
_CAN_TAG = re.compile(r"\s*,?\s+(?:can\s+or\s+not|can(?:\s+help)?|ok|okay)\s*(?:\?+|(?=[.,;:!]|$))", re.IGNORECASE)
#: "go and shift 6 router ...", "the weakest one go and bring ...", "go ahead and move ...": "go
#: (ahead) and" before a verb adds nothing
_GO_AND = re.compile(r"\bgo\s+(?:ahead\s+)?and\s+(?=[a-z])", re.IGNORECASE)
FRACTIONS = {"third": 3, "thirds": 3, "quarter": 4, "quarters": 4, "fourth": 4, "fourths": 4,
             "fifth": 5, "fifths": 5, "sixth": 6, "sixths": 6, "eighth": 8, "eighths": 8,
             "tenth": 10, "tenths": 10}
SUPERLATIVES = {"strongest": "max", "biggest": "max", "largest": "max", "heaviest": "max",
                "weakest": "min", "smallest": "min", "lightest": "min"}
#: contractions whose "'s" is "is" ("it's"), not a possessive
IS_CONTRACTIONS = {"it", "that", "there", "what", "whatever", "here", "who", "he", "she"}
#: words a name of the talk may follow ("the Lau guy", "for the Kadavu boat", "in Koro")
_BEFORE_A_NAME = frozenset({"the", "a", "an", "for", "to", "in", "from", "at", "of", "on", "with", "by"})
#: what a name, kind word ("\0") or count ("\1") stands as in the words a clause is judged on
_HELD = ("\0", "\1", "\3", "\4")


def _one_of_these(toks: list[Tok], k: int) -> bool:
    """Whether the count at ``k`` is the "one" of "that one", "this one" (a thing pointed at, no count:
    "..., that one bruk")."""
    return toks[k].text.lower() == "one" and k > 0 and toks[k - 1].kind == "word" \
        and str(toks[k - 1].value) in ("that", "this")
_BAD_SYMBOLS = re.compile(r"[\^*=+%$<>~|\\{}@/&`\u00d7]")
#: the marks this reader reads besides ASCII letters, digits and white space (see
#: :mod:`pipflow.language.characters`), each with its reading: sentence and clause punctuation;
#: brackets (an aside, like commas: round ones; square ones carry nothing); quotes and
#: apostrophes (nothing; "'s" is a possessive or "is"); "#" before a number ("shelf #2"); the
#: hyphen, underscore and dashes (set apart by spaces: a pause, like a colon; inside a word: a
#: hyphen, "8\u201311" a range, but an em dash a space); the minus sign (refused before a count); arrows "->", "=>",
#: "\u2192" (to); "\u00d7" after a count ("5\u00d7", as "5x"); the ellipsis (full stops). The other
#: ASCII symbols are in the alphabet only to be refused by name below (:data:`_BAD_SYMBOLS`).
MARKS = frozenset(".,;:!?()[]'\"#-_+^*=%$<>~|\\{}@/&`"
                  "\u2018\u2019\u201c\u201d\u2010\u2011\u2012\u2013\u2014\u2015\u2212\u2192\u00d7\u2026")


@dataclass(frozen=True)
class Lexed:
    """A sentence's terminals and, for each, the index of the recognised token it came from."""

    tokens: list[Token]
    source: list[Tok]
    #: positions of counts said with "exactly" / "precisely" (the word itself is a filler): a
    #: final count, never a delivery ("Give each shelf exactly 3")
    exact: frozenset[int] = frozenset()
    #: the sentence without its content-free clauses (:mod:`pipflow.language.asides`), read when
    #: the whole does not parse; None when no clause is content-free
    trimmed: "Lexed | None" = None
    #: the words of those clauses, for the echo
    aside: tuple[str, ...] = ()
    #: the sentence with a fronted topic put where its pronoun stands (:func:`wordorder.left_dislocated`),
    #: read when the sentence as said does not parse; None when it has no such topic
    dislocated: "Lexed | None" = None


def check_text(command: str) -> str:
    """Refuse what cannot be a command before reading it; returns the text to read."""
    if not isinstance(command, str) or not command.strip():
        raise InputError("command must be a non-empty string")
    if len(command) > MAX_COMMAND_CHARS:
        raise InputError(f"the command is {len(command)} characters long; commands are limited to "
                         f"{MAX_COMMAND_CHARS} characters (split it into several runs)")
    refuse_unread(command, MARKS)
    command = command.replace("\u2026", "...")
    # a minus sign binds only when attached to its number ("-5"); a dash set apart by spaces is
    # punctuation ("Cross dock - 2 sku-220", "bin 4 \u2013 3 bolts"), read like a colon
    # (the minus sign U+2212 is never punctuation)
    # before "and" / "then" / "but" it joins two orders, as a comma does ("... to returns - and tug2 ...")
    command = re.sub(r"(?<=\S)\s+[-\u2013\u2012\u2010\u2011\u2014\u2015]+\s+(?=(?:and|then|but)\b)", " , ", command,
                     flags=re.IGNORECASE)
    command = re.sub(r"(?<=\S)\s+[-\u2013\u2012\u2010\u2011\u2014\u2015]+\s+(?=\S)", " : ", command)
    command = re.sub(r"[\u2014\u2015]+", " ", command)  # an em dash between two words: a space (as always)
    m = re.search(r"(?:^|(?<=[\s(:,;]))[-\u2212\u2013\u2012\u2010]\s*(\d[\d,.]*)", command)
    if m:
        raise Refusal(f"'{m.group(0).strip()}': a count cannot be negative (a shelf holds 0 units "
                      f"or more); say what should happen instead, e.g. remove {m.group(1)} units")
    m = re.search(r"\S*\^\S*|\d+(?:\.\d+)?e[+-]?\d+\b", command, flags=re.IGNORECASE)
    if m:
        raise Refusal(f"'{m.group(0)}': powers are not read as counts; write the number of units")
    m = re.search(r"\d{%d,}" % (MAX_DIGITS + 1), command)
    if m:
        raise Refusal(f"'{m.group(0)}' units: no shelf holds that many; write the count the "
                      f"shelves can hold")
    text = re.sub(r"[\u2010\u2011\u2012\u2013\u2212]", "-", command)  # other dashes inside a word: a hyphen
    text = re.sub(r"\b([0-9]+)\s*\u00d7", r"\1 x", text)  # "5\u00d7 product1"; any other "\u00d7" is refused below
    text = re.sub(r"-+>|\u2192|=>", " to ", text)
    text = re.sub(r"(?<=\w)\s*\+\s*(?=\w)", " plus ", text)  # "3 + 4"
    m = _BAD_SYMBOLS.search(text)
    if m:
        word = re.search(r"\S*" + re.escape(m.group(0)) + r"\S*", text)
        raise TranslationError(f"'{word.group(0) if word else m.group(0)}': the symbol "
                               f"'{m.group(0)}' is not read in commands; write it in words")
    text = re.sub(r"\bwhats\b", "what is", text, flags=re.IGNORECASE)  # "what's" typed without its apostrophe
    text = re.sub(r"\b([A-Za-z0-9_-]+)['\u2019](" + "|".join(_CASE_SUFFIXES) + r")\b",
                  lambda m: f"{m.group(1)} {_CASE_MARKS[_CASE_SUFFIXES[m.group(2).lower()]]}", text, flags=re.IGNORECASE)
    # "the dock 's got": the mark typed apart from its word is the same mark
    return re.sub(r"\b([A-Za-z0-9_-]+)[ \t]?['\u2019]s\b", _possessive, text)


#: Turkish case endings set off from a name by an apostrophe, as Turkish writes them after proper
#: nouns ("Rack A'dan": from rack A, "Rack B'ye": to rack B, "sevkiyat'ta": at sevkiyat), with the
#: preposition each says; read by :func:`case_endings` where the name is a place of the world
_CASE_SUFFIXES = {**dict.fromkeys(("dan", "den", "tan", "ten"), "from"), **dict.fromkeys(("ya", "ye", "a", "e"), "to"),
                  **dict.fromkeys(("da", "de", "ta", "te"), "at")}
_CASE_MARKS = {"from": "zzcasefrom", "to": "zzcaseto", "at": "zzcaseat"}
#: Urdu and Hindi postpositions said after a place in English orders ("rack 1 se 9 bags to
#: staging": from rack 1; "dock tak": up to the dock; "rack 2 pe": on rack 2), read as the
#: preposition before it by :func:`case_endings`; after anything else they stay as written
_POSTPOSITIONS = {"se": "from", "ko": "to", "tak": "to", "pe": "at", "par": "at", "mein": "at"}


def this_job_announced(toks: list[Tok]) -> list[Tok]:
    """The tokens with "for this" before a colon read as "for this job" ("Use only tuggers for this:
    the 6 tubes go to picking"): the colon announces the job the rule is for, as "for this one:"
    does; "in this (one)" before a colon is "for this (one)" (Portuguese "nisso", "nessa"); "for
    this" elsewhere keeps its reading (the move just said, or asked)."""
    out: list[Tok] = []
    for k, t in enumerate(toks):
        out.append(t)
        colon = k + 1 < len(toks) and toks[k + 1].kind == "punct" and toks[k + 1].value == ":"
        if t.kind == "word" and t.value == "this" and colon and k and toks[k - 1].kind == "word" \
                and toks[k - 1].value in ("for", "in"):
            out[-2:] = [Tok("word", toks[k - 1].text, "for"), t, Tok("word", "", "job")]
        elif t.kind == "word" and t.value == "one" and colon and k > 1 and said_at(toks, k - 2, ("in", "this")):
            out[-3] = Tok("word", toks[k - 2].text, "for")   # "in this one:" (Portuguese "nessa"): for this one
    return out


def topic_marked(toks: list[Tok]) -> list[Tok]:
    """The tokens without Japanese's topic particle "wa" after a name of the world ("kenpin area wa
    bearing maximum 1 case", "Motor wa every place all collect to B rack"): it marks what the
    sentence is about, which the name already is. Elsewhere "wa" is kept, and refused unread."""
    return [t for k, t in enumerate(toks) if not (
        t.kind == "word" and t.value == "wa" and k and toks[k - 1].kind in ("name", "kind")
        and k + 1 < len(toks) and toks[k + 1].kind != "punct")]


def case_endings(toks: list[Tok]) -> list[Tok]:
    """The tokens with a Turkish case ending after a place ("Rack A'dan 4 silecek take out", "Rack
    B'ye nobody goes") or an Urdu postposition ("rack 1 se 9 bags ...", :data:`_POSTPOSITIONS`)
    read as the preposition it is, before the place: "from rack A", "to rack B", "at P". After
    anything else the ending is kept as written, and refused where it is unread."""
    marks = {mark: prep for prep, mark in _CASE_MARKS.items()}
    out: list[Tok] = []
    for k, t in enumerate(toks):
        place = bool(out) and out[-1].kind == "name" and out[-1].of == "shelf"
        prep = marks.get(str(t.value)) if t.kind == "word" else None
        if prep is None and place and t.kind == "word" and str(t.value) in _POSTPOSITIONS:
            # "rack 1 se 9 bags ...": the count after the place is set off as a fronted source's is
            # ("from rack 1, 9 bags ..."), never read as the place's number
            counted = k + 1 < len(toks) and is_number(str(toks[k + 1].value))
            out[-1:] = [Tok("word", _POSTPOSITIONS[str(t.value)], _POSTPOSITIONS[str(t.value)]), out[-1]] \
                + ([Tok("punct", ",", ",")] if counted else [])
        elif prep is None:
            out.append(t)
        elif place:
            out[-1:] = [Tok("word", prep, prep), out[-1]]
        else:
            out.append(Tok("word", "'" + prep, "'" + prep))
    return out


def _name_words(world: dict) -> set[str]:
    """The words of the world's place and product names, and their plurals ("tray", "trays" of
    seed_tray), but for a product named by what its container holds and the container
    (dog_food_sack: "4 sacks of dog food", :func:`pipflow.warehouse.language.names._contents`)."""
    out: set[str] = set()
    for key in ("shelves", "products"):
        for name in world.get(key) or {}:
            words = [w for w in re.split(r"[-_\s]+", str(name).lower()) if w.isalpha()]
            if len(words) >= 3 and words[-1] in CONTAINERS:
                continue   # "sacks of dog food" of dog_food_sack: its container is still a unit
            for w in words:
                out |= {w, *plural_forms(w)}
    return out


def _possessive(m: re.Match) -> str:
    word = m.group(1)
    if word.lower() in IS_CONTRACTIONS:
        return f"{word} is"
    if word.lower() == "let":
        return "let us"
    return f"{word} {POSS_MARK}"


def _number_typo(word: str) -> str | None:
    """The number word a misspelt word means ("thre" -> three), when exactly one is 1 edit away
    and the word is no common word written as itself ("fire" is no "five", "footy" no "forty":
    :func:`pipflow.language.english.common_word`, consulted only for a near miss)."""
    if len(word) < 3 or not word.isalpha():
        return None
    cands = [w for w in list(UNITS) + list(TENS) + ["dozen", "hundred", "thousand"]
             if len(w) >= 3 and w[0] == word[0] and distance(word, w) <= 1]
    return cands[0] if len(cands) == 1 and not common_word(word) else None


#: words that take back the count before them: "5, no, 6", "3, sorry, 4", "2, I mean 3"
CORRECTIONS = (("no",), ("sorry",), ("wait",), ("i", "mean"), ("make", "that"), ("make", "it"), ("or", "rather"), ("rather",))
#: a taking back said without a comma after the count must hold one of these ("5 no sorry 6"),
#: never only "no" ("5 no 6" says nothing clear)
UNMARKED_TAKE_BACK = frozenset({"sorry", "wait", "oops"})


#: The verb lexicon (issue 23, point 2; docs/language.md "Verbs"): each verb or phrasal verb of
#: placing, moving, removing, keeping and gathering that staff use, with the order operation it
#: means and the grammar verb that carries that operation. The grammar's own verbs are read as
#: they are (its rules decide what each does in its clause); the phrases below are read as the
#: grammar verb they name, their words kept for the echo. A verb in neither is never guessed: it
#: stays an unknown word, and the sentence is refused on it. Words that are nouns as often as verbs
#: ("hand", "truck", "group", "pool") and idioms that mean something else ("take over", "run over")
#: are left out on purpose.
#:   place  - a count put on a place ("put", "stow"): a final count where the place holds none
#:   move   - units taken from a place to another ("shift", "bring over"): adds at the target
#:   remove - units taken off a place ("pull off", "offload"): removes at the source
#:   keep   - a place or count left as it is ("hang on to")
#:   gather - every unit of an item brought to one place ("round up", "consolidate")
#:   empty  - a place cleared of everything ("clear out", "clean out")
#:   fill   - a place filled up with an item ("complete P with X")
VERB_LEXICON: dict[str, tuple[str, str]] = {
    # placing
    "stow": ("place", "put"), "stash": ("place", "put"), "slot": ("place", "put"), "set down": ("place", "put"),
    "lay": ("place", "put"), "plonk": ("place", "put"), "shelve": ("place", "put"), "bung": ("place", "put"),
    "whack": ("place", "put"), "slap": ("place", "put"),
    # moving (and the grammar's own: move, bring, send, ship, transfer, carry, haul, shift, cart,
    # ferry, tow, lug, shuttle, wheel, relocate, deliver, stage, restage, fetch, dispatch, pass, bring over,
    # move over)
    "shove": ("move", "move"), "chuck": ("move", "toss"), "sling": ("move", "toss"), "lob": ("move", "toss"), "drag": ("move", "move"), "move across": ("move", "move"),
    "send across": ("move", "send"), "carry over": ("move", "carry"), "bring across": ("move", "bring"),
    # "push 5 X from P to Q" (a pallet pushed or pulled along; Portuguese "puxar": pull)
    "push": ("move", "move"), "pull": ("move", "move"),
    # removing (and the grammar's own: remove, unload, withdraw, take away, get rid of, dispose of, throw out)
    "offload": ("remove", "unload"), "off-load": ("remove", "unload"), "off load": ("remove", "unload"), "pull off": ("remove", "take"),
    "pull out": ("remove", "take"), "take off": ("remove", "take"), "take out": ("remove", "take"),
    "clear away": ("remove", "remove"),
    # keeping (and the grammar's own: keep, leave, retain, hold)
    "hang on to": ("keep", "keep"), "hold on to": ("keep", "keep"), "hang onto": ("keep", "keep"),
    "maintain": ("keep", "keep"),
    # gathering (and the grammar's own: gather, consolidate, collect)
    "round up": ("gather", "gather"), "bring together": ("gather", "gather"),
    "centralise": ("gather", "consolidate"), "centralize": ("gather", "consolidate"),
    # emptying (and the grammar's own: empty, clear, clear out, clean out)
    "clear off": ("empty", "clear"), "strip": ("empty", "empty"), "vacate": ("empty", "empty"),
    # filling (and the grammar's own: fill, fill up, top up): "complete P with X" (Portuguese and
    # Spanish "completar": make up to full)
    "complete": ("fill", "fill"),
}


#: phrases of quantity people say for the grammar's own words (issue 23, r6w): "the whole lot" is
#: everything; "the whole of P" is everything of P; what follows "everything" to say it is the
#: stock ("everything we stock", "everything there is") says nothing more
QUANTITY_PHRASES: dict[str, tuple[str, ...]] = {
    "whole lot": ("everything",), "whole of": ("everything", "of"),
    "everything we stock": ("everything",), "everything we have": ("everything",),
    "everything we carry": ("everything",), "everything we hold": ("everything",),
    "everything we ve got": ("everything",), "everything we got": ("everything",),
    "everything there is": ("everything",), "everything in stock": ("everything",),
    # "they can go wherever there's room": anywhere ("room" is no word of the grammar: it is a
    # word of place names)
    "wherever there is room": ("wherever",), "wherever there s room": ("wherever",),
    "wherever theres room": ("wherever",), "wherever there is space": ("wherever",),
    "anywhere there is room": ("anywhere",), "anywhere there s room": ("anywhere",),
    # "with the exception of those at the pick face": except
    "with the exception of": ("except",), "with exception of": ("except",),
    # "swap P and Q in their entirety": all of it, which the grammar's reading already is
    "in their entirety": (), "in its entirety": (),
    # "no more than 3 at any given time": a bound holds at the end too, which is what a goal fixes
    "at any given time": (), "at any one time": (), "at all times": (),
    # "P must always have at least 10 X" (Guyanese "must always got"): the same, said before the verb
    "always have": ("have",), "always hold": ("hold",), "always got": ("got",), "always has": ("has",),
    # "P shouldn't drop below 20 X all night": so too ("all" is no quantity of a span of time)
    "all night": (), "all day": (), "all shift": (), "all week": (), "all the time": (),
    "all night long": (), "all day long": (),
    # "first thing in the morning": early, a time ("first" orders nothing there)
    "first thing in the morning": (), "first thing in morning": (), "first thing tomorrow": (),
}


#: ways of asking that say nothing the order needs, at the start of a sentence: left out, as
#: "please" is ("Would it be possible to have R bring ...", "Is it possible to move ...")
REQUEST_FRAMES = (("would", "it", "be", "possible", "to"), ("is", "it", "possible", "to"),
                  ("would", "you", "mind"), ("do", "you", "mind"), ("any", "chance", "you", "could"),
                  ("i", "was", "wondering", "if", "you", "could"), ("would", "it", "be", "ok", "to"),
                  # "while you're at it, ...": the order goes on, nothing more is said
                  ("while", "youre", "at", "it"), ("while", "you", "are", "at", "it"), ("while", "ur", "at", "it"),
                  ("whilst", "youre", "at", "it"), ("whilst", "you", "are", "at", "it"),
                  # "sort it so dock 1 has 6 X": the clause after "so" is the order
                  ("sort", "it", "out", "so", "that"), ("sort", "it", "out", "so"), ("sort", "it", "so", "that"),
                  ("sort", "it", "so"), ("arrange", "it", "so", "that"), ("arrange", "it", "so"),
                  ("see", "to", "it", "that"),
                  # Hong Kong and Singapore English "can help (to) move ...", "pls help move ...",
                  # "help to move ...": asking for the verb that follows
                  ("can", "help", "to"), ("can", "help"), ("help", "to"), ("help",),
                  # "please help me move ...", "can you help me (to) ...": the same, with who is helped
                  *((*ask, "help", who, *to) for ask in ((), ("can",), ("can", "you"), ("could", "you"))
                    for who in ("me", "us") for to in (("to",), ())),
                  # "pls arrange for OB to have 10 X", "arrange OB to have 10 X": the order follows
                  ("arrange", "for"), ("arrange",),
                  # a request passed on ("I've been asked to get returns up to 20", "I've been told
                  # only tuggers are to be used"): what follows is the order
                  *((*who, "been", said, *rest) for who in (("ive",), ("i", "have"), ("weve",), ("we", "have"))
                    for said in ("asked", "told") for rest in (("to",), ("that",), ())),
                  *((*who, said, *rest) for who in (("i", "was"), ("we", "were")) for said in ("asked", "told")
                    for rest in (("to",), ("that",))),
                  # the hedged and over-polite ways of asking ("Could I trouble you to ...", "Would you
                  # be so kind as to ...", "Could you possibly ...")
                  ("would", "it", "be", "possible", "for", "you", "to"), ("is", "it", "possible", "for", "you", "to"),
                  ("i", "was", "wondering", "whether", "you", "could"), ("i", "was", "wondering", "whether", "you", "might"),
                  ("i", "was", "wondering", "if", "you", "might"), ("i", "was", "hoping", "you", "could"),
                  ("could", "i", "trouble", "you", "to"), ("could", "i", "ask", "you", "to"), ("might", "i", "ask", "you", "to"),
                  ("would", "you", "be", "able", "to"), ("could", "you", "be", "so", "kind", "as", "to"),
                  ("would", "you", "be", "so", "kind", "as", "to"), ("could", "you", "possibly"),
                  ("would", "you", "possibly"), ("can", "you", "possibly"), ("would", "you", "mind", "terribly"))
#: a want of the speaker's that the robots do it ("I want you to ...", "we need you to ...", "Need you
#: all to ...", or with the team as the speaker's "we": "we need to move ..."), and its calque from French, Spanish or
#: Italian ("I want that you ..."): request frames of words the grammar has anyway ("u" is "you" by
#: then), so none of them is reserved as a frame word
WANT_FRAMES = tuple((*who, want) + rest for who in (("i",), ("we",), ()) for want in ("want", "need")
                    for rest in (("you", "to"), ("you", "all", "to"), ("that", "you"))) + \
    (("i", "would", "like", "you", "to"), ("we", "would", "like", "you", "to"), ("id", "like", "you", "to")) + \
    tuple((who,) + want + ("to",) for who in ("i", "we") for want in (("want",), ("need",), ("would", "like"))) + \
    (("id", "like", "to"),)
REQUEST_FRAMES = tuple(sorted(REQUEST_FRAMES + WANT_FRAMES, key=len, reverse=True))   # the longest said is the frame
#: frames after which the verb comes as "-ing" ("would you mind moving ..."): read as the verb
GERUND_FRAMES = {("would", "you", "mind"), ("do", "you", "mind"), ("would", "you", "mind", "terribly")}
#: frames that ask for a place to end up so ("Would it be possible for receiving to end up with 12
#: X", "I was wondering whether loadout might hold ..."), with the word that links the place to what
#: it should do: read as "<place> should ..."
SUBJECT_FRAMES = {("would", "it", "be", "possible", "for"): ("to",), ("is", "it", "possible", "for"): ("to",),
                  ("i", "was", "wondering", "whether"): ("might", "could"), ("i", "was", "wondering", "if"): ("might", "could")}


#: when the robots may do it, said as a courtesy ("at your earliest convenience", "when you have a
#: moment", "as soon as possible"): no time the plan can keep, set aside wherever it stands (one
#: list: the grammar has no aside of its own for these; "asap" is a filler)
COURTESY_TIMES = tuple(sorted(
    {("at", "your", "earliest", "convenience"), ("at", "your", "convenience"), ("as", "soon", "as", "possible"),
     ("as", "soon", "as", "you", "can"), ("when", "convenient"), ("when", "possible"), ("when", "you", "can"),
     ("when", "you", "have", "time"), ("when", "you", "get", "time"), ("at", "the", "earliest"),
     # "when ur free", "whenever you're free": when the robot has no other job, no condition of the world
     *((when, *you, "free") for when in ("when", "whenever") for you in (("you", "are"), ("youre",), ("ur",))),
     ("at", "earliest"), ("on", "priority"), ("on", "a", "priority", "basis"), ("on", "priority", "basis"),
     ("on", "an", "urgent", "basis"), ("on", "urgent", "basis"), ("urgent", "basis"),
     # "if it isn't too much trouble", "if at all possible": asked politely, no condition of the world
     ("if", "at", "all", "possible"), ("if", "possible"), ("if", "it", "is", "no", "bother"),
     ("if", "it", "is", "no", "trouble"), ("if", "its", "no", "bother"), ("if", "its", "no", "trouble")}
    | {("if", *it, *neg, "too", "much", trouble) for it in (("it",), ("its",)) for neg in (("is", "not"), ("isnt",), ("not",))
       for trouble in ("trouble", "bother")}
    | {(when,) + have + ("a", moment) for when in ("when", "whenever")
       for have in (("you", "have"), ("you", "get"), ("youve", "got"), ("you", "have", "got"), ("you", "ve", "got"))
       for moment in ("moment", "minute", "min", "sec", "second", "chance")}
    | {(when, "you", "have", "a", "spare", moment) for when in ("when", "whenever") for moment in ("moment", "minute")},
    key=len, reverse=True))
#: "Per our discussion this morning, ...": a clause that says what the order follows opens with
#: "per" and one of these (never "per trip", a rate)
_PER_WHOSE = {"our", "your", "the", "my", "his", "her", "their", "this", "that", "yesterdays", "todays"}
#: "As discussed in the meeting, ...", "As agreed, ...": a clause that says what the order follows
#: opens with "as" and one of these, or with "as per"
_AS_SAID = {"per", "discussed", "agreed", "mentioned", "requested", "arranged", "planned", "promised", "usual",
            "always", "instructed", "advised", "informed"}

#: the words of the frames, spelt right ("sort" is no slip of "short")
FRAME_WORDS = frozenset(w for f in REQUEST_FRAMES + COURTESY_TIMES if f not in WANT_FRAMES for w in f)


def _subject_framed(toks: list[Tok], k: int) -> list[Tok] | None:
    """The tokens of a sentence opened at ``k`` by a frame of :data:`SUBJECT_FRAMES`, read as
    "<place> should ...", or None: the words between the frame and its link word must name a
    place and hold no mark."""
    for frame, links in SUBJECT_FRAMES.items():
        if not said_at(toks, k, frame):
            continue
        j = k + len(frame)
        at = next((i for i in range(j + 1, min(j + 7, len(toks))) if toks[i].kind == "word" and toks[i].value in links), None)
        subject = toks[j:at] if at is not None else []
        if subject and all(t.kind != "punct" for t in subject) and any(t.kind == "name" for t in subject):
            return [*subject, Tok("word", toks[at].text, "should")]
    return None


#: words of asking that may stand before a request frame ("pls help move ...")
_COURTESIES = {"pls", "plz", "please", "kindly"}


def _opens_clause(toks: list[Tok], k: int) -> bool:
    """Whether the token at ``k`` opens a sentence or a clause (a request frame is said there)."""
    return k == 0 or (toks[k - 1].kind == "punct" and toks[k - 1].value in (".", ";", "!", "?", ",", ":"))


def without_request_frames(toks: list[Tok], verbs: Collection[str] = ()) -> tuple[list[Tok], list[str]]:
    """The tokens without a frame of :data:`REQUEST_FRAMES` that opens a sentence or a clause
    ("Hi, while you're at it, ..."), a courtesy of time or a "Per ...," clause; with the words of
    the courtesies and "Per" clauses, as said, for the echo (they read like a time or a reason, so
    the user is told they were not kept; a request frame only asks). After a frame of
    :data:`GERUND_FRAMES` a verb of ``verbs`` said with "-ing" is the verb; a frame of
    :data:`SUBJECT_FRAMES` is read as "<place> should"."""
    out: list[Tok] = []
    aside: list[str] = []
    k = 0
    while k < len(toks):
        start = _opens_clause(toks, k) or (toks[k - 1].kind == "word" and toks[k - 1].value in _COURTESIES
                                           and _opens_clause(toks, k - 1))   # "pls help move ..."
        hit = next((f for f in REQUEST_FRAMES if start and said_at(toks, k, f)), None)
        if hit in GERUND_FRAMES and k + len(hit) < len(toks) and toks[k + len(hit)].kind == "word":
            verb = base_verb(str(toks[k + len(hit)].value), verbs)
            if verb is not None:
                out.append(Tok("word", toks[k + len(hit)].text, verb))
                k += len(hit) + 1
                continue
        subject = _subject_framed(toks, k) if start and hit is None else None
        if subject is not None:
            out += subject
            k += len(subject) + next(len(f) for f in SUBJECT_FRAMES if said_at(toks, k, f))
            continue
        courtesy = next((f for f in COURTESY_TIMES if len(toks) >= k + len(f) and all(
            x.kind == "word" and x.value == w for x, w in zip(toks[k:k + len(f)], f))), None)
        size = len(hit or courtesy or ()) or (_per_clause(toks, k) if start else 0)
        if size:
            if not hit:
                aside.append(" ".join(t.text for t in toks[k:k + size] if t.kind == "word"))
            k += size
            if not courtesy and not hit:
                continue   # a "Per" clause took its comma
            if k < len(toks) and toks[k].kind == "punct" and toks[k].value == ",":
                k += 1   # the comma that set the frame off goes with it
            continue
        out.append(toks[k])
        k += 1
    return out, aside


def _per_clause(toks: list[Tok], k: int) -> int:
    """How many tokens at ``k`` are a clause that says what the order follows ("Per our discussion
    this morning," "per the revised plan,", "As per fire NOC,", "..., as per safety SOP.", "As
    discussed in the meeting,"): "per" and a word of :data:`_PER_WHOSE`, or "as" and a word of
    :data:`_AS_SAID` ("as per" is never a rate), then words only (no name, count, robot word or
    operative word) up to a comma, which goes with it, or, after "as ...", up to the end of the
    sentence; 0 otherwise."""
    def word(j: int, *values: str) -> bool:
        return j < len(toks) and toks[j].kind == "word" and (not values or toks[j].value in values)

    as_per = word(k, "as") and word(k + 1, *_AS_SAID)
    if not as_per and not (word(k, "per") and word(k + 1, *_PER_WHOSE)):
        return 0
    # the words said after "per our" / "as per", or after "as discussed" (which may end there)
    body = k + 1 if as_per and toks[k + 1].value != "per" else k + 2
    for j in range(body, len(toks)):
        if toks[j].kind == "punct":
            if toks[j].value == "," and j > body:
                return j + 1 - k
            return j - k if as_per and j > body and toks[j].value in (".", ";", "!", "?") else 0
        if toks[j].kind != "word" or toks[j].value in OPERATIVE:
            return 0
    return len(toks) - k if as_per and len(toks) > body else 0


def _replace_phrases(toks: list[Tok], phrases: list[tuple[tuple[str, ...], Any]],
                     said_as: Callable[[list[Tok], tuple[str, ...], Any], list[Tok] | None]) -> list[Tok]:
    """The tokens with each phrase (longest first) that ``said_as`` accepts at a position replaced
    by the tokens it returns (None: the phrase does not stand there)."""
    out: list[Tok] = []
    k = 0
    while k < len(toks):
        for words, value in phrases:
            got = toks[k:k + len(words)]
            new = said_as(got, words, value) if len(got) == len(words) else None
            if new is not None:
                out += new
                k += len(words)
                break
        else:
            out.append(toks[k])
            k += 1
    return out


def quantity_phrases(toks: list[Tok], keywords: dict[str, str]) -> list[Tok]:
    """The tokens with each phrase of :data:`QUANTITY_PHRASES` read as its grammar words (longest
    first; the words as written stay the first token's text)."""
    phrases = sorted(((tuple(k.split()), v) for k, v in QUANTITY_PHRASES.items() if all(w in keywords for w in v)),
                     key=lambda x: -len(x[0]))

    def said_as(got: list[Tok], words: tuple[str, ...], said: Any) -> list[Tok] | None:
        # a word of the phrase may have been read as a word of a name ("room" of cold_room in
        # "wherever there's room"): the phrase, said as a whole, is the idiom
        # and a word the typo repair read as another ("given" as "give"): the phrase as written
        if not all((x.kind == "word" and w in (x.value, x.text.lower()))
                   or (j > 0 and x.kind == "name" and x.text.lower() == w)
                   for j, (x, w) in enumerate(zip(got, words))):
            return None
        text = " ".join(x.text for x in got)
        return [Tok("word", text if j == 0 else "", w) for j, w in enumerate(said)]

    return _replace_phrases(toks, phrases, said_as)


def whole_places(toks: list[Tok]) -> list[Tok]:
    """The tokens with "whole" or "entire" before a place's name read as the place ("clear the
    whole damages bay out", "swap entire P with Q"): a place is named whole already; the words as
    written stay the name's text."""
    out: list[Tok] = []
    for k, t in enumerate(toks):
        if out and out[-1].kind == "word" and out[-1].value in ("whole", "entire") and t.kind == "name" \
                and t.of == "shelf":
            t = Tok("name", f"{out.pop().text} {t.text}", t.value, t.of)
        out.append(t)
    return out


#: whom a request is put to, after "can / could / would / will": "can somebody shift ..." is "can you
#: shift ..." (a request to whoever does it, never a robot's name)
ANYONE = {"somebody", "someone", "anybody", "anyone"}
_ASKING = {"can", "could", "would", "will"}


def addressed_anyone(toks: list[Tok]) -> list[Tok]:
    """The tokens with "somebody" (:data:`ANYONE`) after a modal of asking read as "you", and
    left out where it opens a clause before a verb of an order (:data:`_ORDER_VERBS`: "And someone
    bring 6 X to P": whoever is asked, which the allocation decides)."""
    verbs = _ORDER_VERBS
    out: list[Tok] = []
    for k, t in enumerate(toks):
        if t.kind == "word" and t.value in ANYONE and k + 1 < len(toks) and toks[k + 1].kind == "word" \
                and toks[k + 1].value in verbs and (_opens_clause(toks, k) or (
                    toks[k - 1].kind == "word" and toks[k - 1].value in _JOINING)):
            continue
        asked = t.kind == "word" and t.value in ANYONE and k > 0 and toks[k - 1].kind == "word" \
            and toks[k - 1].value in _ASKING
        out.append(Tok("word", t.text, "you") if asked else t)
    return out


#: the verbs that open an order: the grammar's and the verb lexicon's (never a pronoun or another
#: grammar word: "can you ...", "someone moved ..." open none)
_ORDER_VERBS = ORDER_VERBS | frozenset(VERB_LEXICON)
#: verbs of a change by a factor or an amount ("cut it by a third"), which may replace an order taken back
_CHANGE_VERBS = frozenset({"cut", "reduce", "increase", "raise", "lower", "triple", "quadruple", "trim"})
#: words of address that may open an order without a comma ("Boss send 15 X to P", "abang move ..."):
#: who is asked, never a word that counts or selects
_ADDRESSED = frozenset(w for w in ADDRESSEES | CLOSERS if w.isalpha() and w not in OPERATIVE
                       and w not in FUNCTION_WORDS and len(w) > 2)


def asked_plainly(toks: list[Tok]) -> list[Tok]:
    """The tokens without the words that only ask, where an order follows: a word of address
    opening a sentence before a verb of an order (grammar ``ORDER_VERBS``, the verb lexicon: "Boss
    send 15 X to P"), "can" opening a clause before one ("can add 6 more X to P or not": Malaysian
    and Singapore English), and the "or not" closing such a question."""
    verbs = _ORDER_VERBS
    out: list[Tok] = []
    asking = False
    k = 0
    while k < len(toks):
        t, nxt = toks[k], toks[k + 1] if k + 1 < len(toks) else None
        before_verb = nxt is not None and nxt.kind == "word" and nxt.value in verbs
        opens_sentence = k == 0 or toks[k - 1].value in (".", "!", "?")
        if t.kind == "word" and before_verb and _opens_clause(toks, k) and (
                (t.value in _ADDRESSED and opens_sentence) or t.value == "can"):
            asking = asking or t.value == "can"
            k += 1
            continue
        if asking and t.kind == "word" and t.value == "or" and nxt is not None and nxt.kind == "word" \
                and nxt.value == "not" and (k + 2 == len(toks) or toks[k + 2].kind == "punct"):
            asking = False
            k += 2   # "or not": a question's tag
            continue
        out.append(t)
        k += 1
    return out


#: words that join a clause on before its subject ("and someone bring ...")
_JOINING = {"and", "so", "then", "but", "also", "plus"}


def lexicon_verbs(toks: list[Tok], keywords: dict[str, str]) -> list[Tok]:
    """The tokens with each phrase of :data:`VERB_LEXICON` read as its grammar verb (longest
    phrase first; a phrase whose words are already the grammar's, or whose verb the grammar does
    not have, is left alone). The verb's words as written stay its text."""
    phrases = sorted(((tuple(k.split()), v[1]) for k, v in VERB_LEXICON.items() if v[1] in keywords),
                     key=lambda x: -len(x[0]))

    def said_as(got: list[Tok], words: tuple[str, ...], verb: Any) -> list[Tok] | None:
        if not all(x.kind == "word" and x.value == w for x, w in zip(got, words)) or (
                len(words) == 1 and words[0] in keywords):
            return None
        return [Tok("word", " ".join(x.text for x in got), verb)]

    return _replace_phrases(toks, phrases, said_as)


#: words that take back what was just said ("no wait, make that 3", "sorry, I meant 4", "yeah nah, make
#: it 9": Australian "no")
TAKE_BACK = {"no", "wait", "sorry", "oops", "actually", "hmm", "erm", "nope", "correction", "scratch", "that", "nah",
             "yeah"}
#: the words that then say the new count
RESTATE = (("make", "that"), ("make", "it"), ("i", "mean"), ("i", "meant"), ("i", "meant", "to", "say"),
           ("or", "rather"), ("rather",))
#: a particle of direction before a preposition and a place ("bring them down from the mezzanine",
#: "up to the mezzanine"): it says nothing the place does not ("up to 5" is a bound: no place follows)
DIRECTION_PARTICLES = {"up", "down", "across", "along"}
_PLACE_PREPOSITIONS = {"to", "into", "onto", "from", "off", "in", "on", "at"}


def without_particles(toks: list[Tok]) -> list[Tok]:
    """The tokens without a particle of direction that stands between a verb's object and
    a preposition followed by a place (:data:`DIRECTION_PARTICLES`), or a word of where there
    ("the ones upstairs in the loft": the place says where)."""
    out: list[Tok] = []
    for k, t in enumerate(toks):
        if t.kind == "word" and (t.value in DIRECTION_PARTICLES or t.value in WHERE_WORDS) and k + 2 < len(toks):
            prep, nxt = toks[k + 1], toks[k + 2]
            if nxt.kind == "word" and nxt.value == "the" and k + 3 < len(toks):
                nxt = toks[k + 3]
            if (prep.kind == "word" and prep.value in _PLACE_PREPOSITIONS and nxt.kind == "name"
                    and nxt.of == "shelf"):
                continue
        out.append(t)
    return out


def put_back_after_its_object(toks: list[Tok]) -> list[Tok]:
    """ "6 ctn connector from OB put back rack B", "all resistor put back to rack A": the things
    said first, then "put back" and the place (with or without "to"), as "... go to rack B" says
    it. Only after something said before it (never "put back 3 X ..."), and before a place."""
    out: list[Tok] = []
    k = 0
    while k < len(toks):
        t = toks[k]
        at = k + 2 + (k + 2 < len(toks) and toks[k + 2].kind == "word" and toks[k + 2].value in ("to", "into", "in"))
        if (t.kind == "word" and t.value == "put" and out and out[-1].kind in ("name", "num")
                and k + 1 < len(toks) and toks[k + 1].kind == "word" and toks[k + 1].value == "back"
                and at < len(toks) and toks[at].kind == "name" and toks[at].of == "shelf"):
            out += [Tok("word", "put", "go"), Tok("word", "back", "to")]
            k = at
            continue
        out.append(t)
        k += 1
    return out


def counts_sent_from_a_topic(toks: list[Tok]) -> list[Tok]:
    """ "bunker carboys: 2 to counter and rest to mezz", "rack B resistor 5 to kitting, rest go
    OB": a place and an item said first, then counts sent on from there; read as "move 2 carboys
    from bunker to counter and rest to mezz". Only at a sentence's start, with a count and "to"
    right after the item; so too "out of P, 4 X to Q ..." (or "from P ..."), said without a verb."""
    k = 0
    out: list[Tok] = []
    while k < len(toks):
        opens = not out or (out[-1].kind == "punct" and out[-1].value in (".", ";", "!", "?"))
        led = (out and out[-1].kind == "word" and out[-1].value in ("okay", "ok", "so", "alright", "now", "then")
               and (len(out) == 1 or out[-2].kind == "punct" and out[-2].value in (".", ";", "!", "?")))
        sent = _sent_out_of(toks, k) if opens or led else None
        if sent is not None:   # "out of high bay, 4 fryers to aisle 12 and the rest to ..."
            place, n = sent
            out += [Tok("word", "", "move"), toks[n], toks[n + 1], Tok("word", "", "from"), toks[place]]
            k = n + 2
            continue
        topic = _topic_sent_on(toks, k) if opens else None
        if topic is not None:
            place, item, n = topic
            out += [Tok("word", "", "move"), toks[n], toks[item], Tok("word", "", "from"), toks[place]]
            k = n + 1
            continue
        out.append(toks[k])
        k += 1
    return out


def _topic_sent_on(toks: list[Tok], k: int) -> tuple[int, int, int] | None:
    """(where the place is, where the item is, where the count is) of a place and an item said
    first and a count sent on "to" somewhere, at ``toks[k]``: "[from] P's X [:|,] N to", "[the] X
    (from | on | in | at) [the] P [:|,] N to"; None where the sentence does not open so."""
    def at(j: int, kind: str, of: str | None = None, *values: str) -> bool:
        return j < len(toks) and toks[j].kind == kind and (of is None or toks[j].of == of) \
            and (not values or toks[j].value in values)
    j = k + at(k, "word", None, "from")
    if at(j, "name", "shelf") and at(j + 1, "word", None, POSS_MARK) and at(j + 2, "name", "product"):
        place, item, j = j, j + 2, j + 3
    else:
        j = k + at(k, "word", None, "the")
        if not (at(j, "name", "product") and at(j + 1, "word", None, "from", "on", "in", "at")):
            return None
        item, j = j, j + 2
        j += at(j, "word", None, "the")
        if not at(j, "name", "shelf"):
            return None
        place, j = j, j + 1
    j += at(j, "punct", None, ":", ",")
    return (place, item, j) if at(j, "num") and at(j + 1, "word", None, "to") else None


def _sent_out_of(toks: list[Tok], k: int) -> tuple[int, int] | None:
    """(where the place is, where the count is) of "out of [the] P [,] N X to" at ``toks[k]``."""
    words = [str(t.value) if t.kind == "word" else None for t in toks[k:k + 3]]
    j = k + 2 if words[:2] == ["out", "of"] else k + 1 if words[:1] == ["from"] else None
    if j is None:
        return None
    j += j < len(toks) and toks[j].kind == "word" and toks[j].value == "the"
    n = j + 1 + (j + 1 < len(toks) and toks[j + 1].kind == "punct" and toks[j + 1].value == ",")
    if (n + 2 < len(toks) and toks[j].kind == "name" and toks[j].of == "shelf" and toks[n].kind == "num"
            and toks[n + 1].kind == "name" and toks[n + 1].of == "product"
            and toks[n + 2].kind == "word" and toks[n + 2].value == "to"):
        return j, n
    return None


#: grammar verbs that put what was taken somewhere (the verb lexicon's words are read as these)
_PUTTING = frozenset({"put", "drop", "stick", "pop", "leave", "stack", "dump", "load", "toss", "bring", "take",
                      "move", "send", "shift", "carry", "throw", "stock", "store", "park"})


def dropped_object(toks: list[Tok]) -> list[Tok]:
    """ "take 4 chains from P and put in Q": a putting verb that opens a clause joined by "and" /
    "then" and has a place right after its preposition, but no object, after a clause that
    counted something. Its object is what was taken, as if said "put them"; "them" then finds
    what it stands for as it always does (and is refused where it finds nothing). Also "dont
    touch" alone after a clause that keeps a place (:func:`_touch_alone`): "dont touch it"."""
    out: list[Tok] = []
    for k, t in enumerate(toks):
        out.append(t)
        if _touch_alone(toks, k):
            out.append(Tok("word", "", "it"))
        if not (t.kind == "word" and t.value in _PUTTING and k > 1 and k + 2 < len(toks)):
            continue
        joined = toks[k - 1].value in ("and", "then")
        prep = toks[k + 1]
        place = toks[k + 3] if toks[k + 2].value == "the" and k + 3 < len(toks) else toks[k + 2]
        if (joined and prep.kind == "word" and prep.value in _PLACE_PREPOSITIONS - {"from", "off"}
                and place.kind == "name" and place.of == "shelf" and any(x.kind == "num" for x in toks[:k])):
            out.append(Tok("word", "", "them"))
    return out


def _touch_alone(toks: list[Tok], k: int) -> bool:
    """Whether ``toks[k]`` is the "touch" of a clause that is only "dont touch", said right after a
    clause that keeps a place as it is ("shipping keep as it is, dont touch": don't touch it, the
    place kept); "it" then finds what it stands for as it always does."""
    def word(j: int, *values: str) -> bool:
        return 0 <= j < len(toks) and toks[j].kind == "word" and toks[j].value in values
    if not (word(k, "touch") and word(k - 1, "dont") and k >= 3 and toks[k - 2].kind == "punct"
            and (k + 1 == len(toks) or toks[k + 1].kind == "punct")):
        return False
    start = max((j for j in range(k - 2) if toks[j].kind == "punct"), default=-1) + 1
    return word(start, "keep", "leave")


#: words of a bound that a count taken back may be said with again ("at least 6, no wait, at least 8")
_BOUND_SAID_AGAIN = frozenset({"at", "least", "most", "no", "not", "more", "less", "fewer", "than", "max", "maximum",
                               "min", "minimum", "up", "to"})


def _bound_before(toks: list[Tok], k: int) -> list[str]:
    """The words of a bound said right before the count at ``k`` ("no fewer than"), all of them."""
    m = k
    while m > 0 and toks[m - 1].kind == "word" and toks[m - 1].value in _BOUND_SAID_AGAIN:
        m -= 1
    return [str(x.value) for x in toks[m:k]]


def _clause_follows(toks: list[Tok], k: int) -> bool:
    """Whether at least two words follow ``k`` before the next mark: after a comma an interjection
    is set off only before a clause ("..., ah no wait, 8"); "..., pls fix" stays one clause of talk."""
    n = 0
    while k < len(toks) and toks[k].kind != "punct":
        n, k = n + 1, k + 1
    return n >= 2


def corrected_later(toks: list[Tok]) -> list[Tok]:
    """A count taken back at the end of its sentence or of a clause ("Move 2 X from P to Q, no wait,
    make that 3"; "..., sorry, I meant 3"; "at least 6 X, no wait, at least 8, ..."), or in a
    sentence of its own that says nothing else ("8 lager to
    dispatch.. yeah nah make it 9"): the one count of the sentence taken back becomes the new one,
    and the taking back is no part of the order. Where that sentence has several counts, which one
    is taken back is not said: the words stay, and the command is refused on them."""
    ends = {".", ";", "!", "?"}
    out = list(toks)
    k = 0
    while k < len(out):
        t = out[k]
        if not (t.kind == "punct" and t.value in {",", ":"} | ends) or (t.value in ends and k + 1 < len(out)
                                                                      and out[k + 1].kind == "punct"):
            k += 1
            continue
        after_end = t.value in ends   # a sentence of its own: only with words that take back or restate
        j = k + 1
        took_back = False
        while j < len(out) and out[j].kind == "word" and out[j].value in TAKE_BACK:
            took_back, j = True, j + 1
        if j < len(out) and out[j].kind == "punct" and out[j].value == ",":
            j += 1
        restated = False
        for words in sorted(RESTATE, key=len, reverse=True):
            got = [str(x.value) for x in out[j:j + len(words)] if x.kind == "word"]
            if got == list(words):
                restated, j = True, j + len(words)
                break
        # "at least 6 X, no wait, at least 8": the bound said again with the new count; it must be
        # the old count's, word for word (checked below), and the bound stays the old one's
        bound = j
        while j < len(out) and out[j].kind == "word" and out[j].value in _BOUND_SAID_AGAIN:
            j += 1
        bound_words = [str(x.value) for x in out[bound:j]]
        if not (took_back or restated) or j >= len(out) or out[j].kind != "num":
            k += 1
            continue
        new = out[j]
        end = j + 1
        if end < len(out) and out[end].kind == "name" and out[end].of == "product":
            end += 1
        # the sentence ends there, or a clause of its own follows ("..., at least 8, the Gau order got
        # bigger"), judged as any clause is
        if end < len(out) and not (out[end].kind == "punct" and out[end].value in ends | {","}):
            k += 1
            continue
        start = k
        while after_end and start > 0 and out[start - 1].kind == "punct" and out[start - 1].value in ends:
            start -= 1   # "..": the sentence before both marks
        while start > 0 and not (out[start - 1].kind == "punct" and out[start - 1].value in ends):
            start -= 1
        counts = [m for m in range(start, k) if out[m].kind == "num"]
        named = out[j + 1] if j + 1 < end else None
        other_bound = bool(bound_words) and _bound_before(out, counts[0]) != bound_words if counts else False
        if len(counts) != 1 or other_bound or (named is not None and not (
                counts[0] + 1 < k and out[counts[0] + 1].kind == "name" and out[counts[0] + 1].value == named.value)):
            k += 1
            continue
        old = out[counts[0]]
        spoken = " ".join(x.text for x in out[k + 1:end])
        out[counts[0]] = Tok("num", f"{old.text} (taken back: {spoken})", new.value)
        del out[k:end]
    return out


def _split_hyphens(toks: list[Tok], keywords: dict[str, str]) -> list[Tok]:
    """A hyphenated word that is no name, keyword or count reads as its words ("night-shift"
    robots are the night shift robots, "re-stock" is restock's words)."""
    out: list[Tok] = []
    for t in toks:
        word = str(t.value)
        parts = [p for p in word.split("-") if p]
        if (t.kind != "word" or len(parts) < 2 or word in keywords
                or any(p in NUMBER_WORDS or p.isdigit() for p in parts)):
            out.append(t)
            continue
        out += [Tok("word", p, p) for p in parts]
    return out


#: "is having", "are having", "be having": the progressive of "have" said of what a place holds, as
#: in Indian and some other Englishes ("Showroom is having 6 jars"): it means "has" / "have"
_HAVING = {"is": "has", "s": "has", "are": "have", "be": "have"}


def stative_having(toks: list[Tok]) -> list[Tok]:
    """"P is having N X" as "P has N X", "should both be having" as "should both have" (one
    token, its text the words said); "having" after anything else is left to the grammar ("with
    P having 3 X")."""
    out: list[Tok] = []
    for t in toks:
        if t.kind == "word" and t.value == "having" and out and out[-1].kind == "word" and out[-1].value in _HAVING:
            be = out.pop()
            out.append(Tok("word", f"{be.text} {t.text}", _HAVING[str(be.value)]))
            continue
        out.append(t)
    return out


#: words after which "'s" is "is", never a possessive ("the weakest bot's not to go near P",
#: "bazza's off tonight", "the dock's out of X")
_IS_BEFORE = frozenset({"not", "to", "never", "allowed", "gonna", "going", "off", "down", "broken", "busy", "out"})


def is_contracted(toks: list[Tok]) -> list[Tok]:
    """The tokens with "'s" read as "is" before a word of :data:`_IS_BEFORE` (its text kept)."""
    return [Tok("word", t.text, "is") if t.kind == "word" and t.value == POSS_MARK and k + 1 < len(toks)
            and toks[k + 1].kind == "word" and toks[k + 1].value in _IS_BEFORE else t for k, t in enumerate(toks)]


def _spoken_no(toks: list[Tok], k: int) -> bool:
    """Whether a bare "no" at ``k``, after a count, takes it back as said aloud: before a
    restatement ("four no make that five") or a count said in words ("six no seven", as dictated).
    "5 no 3" stays unread: written "no" before digits may abbreviate "number" ("No. 3")."""
    if toks[k].value != "no" or k + 1 >= len(toks):
        return False
    after = toks[k + 1]
    if after.kind == "num":
        return not any(c.isdigit() for c in after.text)
    return any([str(x.value) for x in toks[k + 1:k + 1 + len(w)] if x.kind == "word"] == list(w) for w in RESTATE)


def corrected(toks: list[Tok]) -> list[Tok]:
    """A count taken back and replaced ("5, no, 6 bolts", "Send 5 logs, no wait, 4 logs from P")
    is the second count, its source words all of the span; the first is never read. Only a count
    right after correction words set off by a comma counts ("2, no bolts" is left to the grammar);
    a product said with the first count stays the product of the second, and one said with the
    second must be the same."""
    out: list[Tok] = []
    i = 0
    while i < len(toks):
        t = toks[i]
        k = i + 1
        named = toks[k] if t.kind == "num" and k < len(toks) and toks[k].kind == "name" and toks[k].of == "product" else None
        k += named is not None
        # set off by commas, or by dashes (read as ":"): "Take two - sorry, three - foam swords";
        # or said straight on, as dictated, with an apology in it: "move 5 no sorry 6 of sand"
        unmarked = (t.kind == "num" and named is None and k + 1 < len(toks) and toks[k].kind == "word"
                    and (any(x.kind == "word" and x.value in UNMARKED_TAKE_BACK for x in toks[k:k + 2])
                         or _spoken_no(toks, k)))
        if t.kind == "num" and k < len(toks) and (unmarked or (toks[k].kind == "punct" and toks[k].value in (",", ":"))):
            opened = toks[k].value if toks[k].kind == "punct" else None
            j = k + 1 - unmarked
            took_back = False
            while True:   # "no", "no wait", "no sorry, make that"
                comma = took_back and j < len(toks) and toks[j].kind == "punct" and toks[j].value == ","
                at = j + comma
                while at < len(toks) and toks[at].kind == "word" and toks[at].value in HESITATIONS:
                    at += 1   # "12, eh sorry 15"
                words = next((w for w in CORRECTIONS
                              if [str(x.value) for x in toks[at:at + len(w)] if x.kind == "word"] == list(w)), None)
                if words is None:
                    break
                took_back, j = True, at + len(words)
            if took_back and j < len(toks) and toks[j].kind == "punct" and toks[j].value in (",", opened):
                j += 1
            said = toks[j + 1] if j + 1 < len(toks) and toks[j + 1].kind == "name" and toks[j + 1].of == "product" else None
            if took_back and j < len(toks) and toks[j].kind == "num" and not (
                    named is not None and said is not None and said.value != named.value):
                closing = j + 1 < len(toks) and toks[j + 1].kind == "punct" and toks[j + 1].value == opened
                # the closing dash goes too, and a closing comma before the product ("Send 5, no
                # sorry 4, seed trays from ...": the correction set off on both sides)
                end = j + 1 if closing and (opened == ":" or (
                    named is None and j + 2 < len(toks) and toks[j + 2].kind == "name" and toks[j + 2].of == "product")) else j
                text = " ".join(x.text for x in toks[i:end + 1])
                out.append(Tok("num", text, toks[j].value))
                if named is not None and said is None:
                    out.append(Tok("name", "", named.value, named.of))   # its words are the count's
                i = end + 1
                continue
        out.append(t)
        i += 1
    return out


#: words of time the grammar reads only in its asides ("by tonight", "before lunch"): inside an
#: adjunct ("... for afternoon pickup", "... by opening time") they say when, nothing the order needs
TIMES_OF_DAY = frozenset({"morning", "afternoon", "evening", "tonight", "tomorrow", "noon", "lunch", "time",
                          "later", "today", "oclock", "pm", "am", "end", "day", "week", "weekend", "night"})


def _clock(toks: list[Tok], k: int) -> bool:
    """Whether the count at ``k`` is a time of day ("the 2 o'clock wagon", "by 3pm"): a time, no count."""
    after = [re.sub(r"[^a-z]", "", t.text.lower()) for t in toks[k + 1:k + 3] if t.kind == "word"]
    return bool(after) and (after[0] in ("oclock", "pm", "am") or after[:2] == ["o", "clock"])


def by_as_at(toks: list[Tok]) -> list[Tok]:
    """The tokens with "by" before a place read as "at" (Welsh English: "the plasterboard by the
    counter", "what's by the van bay"): where the place is, as "at" says. Only right before a
    place's name (or "the" and one); "by 5pm", "by a third" and "by hand" are left as said."""
    out = list(toks)
    for k, t in enumerate(toks):
        j = k + 2 if k + 1 < len(toks) and toks[k + 1].kind == "word" and toks[k + 1].value == "the" else k + 1
        if t.kind == "word" and t.value == "by" and j < len(toks) and toks[j].kind == "name" and toks[j].of == "shelf":
            out[k] = Tok("word", t.text, "at")
    return out


def _set_off(cur: list[Tok], free: list[Clause], inner: set[int]) -> tuple[list[Tok], list[str]]:
    """The tokens without the parts ``free`` sets aside, each with the clause mark that set it off
    (none for a part that starts at one of ``inner``: a part of a clause has no mark of its own),
    and the words of those parts."""
    if not free:
        return cur, []
    drop = {k for c in free for k in range(c.start, c.end)}
    aside: list[str] = []
    for c in sorted(free, key=lambda c: c.start):
        aside.append(" ".join(t.text for t in cur[c.start:c.end]))
        if c.start in inner:
            continue
        if c.end < len(cur) and cur[c.end].kind == "punct":
            drop.add(c.end)
        elif c.start > 0 and cur[c.start - 1].kind == "punct":
            drop.add(c.start - 1)
    return [t for k, t in enumerate(cur) if k not in drop], aside


#: interjections that are sounds, no word of English grammar ("Ah please add 4 ...", "Oh move ..."):
#: set off as "Ah, ..." though English has them
SOUNDS = frozenset({"ah", "ahh", "oh", "uh", "um", "umm", "er", "erm", "ugh", "aha", "phew", "eh"})


class Lexicon:
    """The world's vocabulary for the grammar: names, robot kinds, tags and skills."""

    def __init__(self, world: dict, keywords: dict[str, str]):
        self.world = world
        #: robot kinds, tags and name stems said after "the" / "our" / ... in the command read last
        #: (:meth:`_definite_groups`), normalized: "the forklift" is one robot, "forklift" the kind
        self.definite_said: set[str] = set()
        self.keywords = keywords  # keyword text -> terminal name
        # the grammar's own words are English, never a misspelt name ("haul" is no hauler1)
        # superlatives are words of robot rules, never a misspelt name ("strongest" is no string_set)
        # another spelling of a grammar word said alone is that word, never a misspelt name ("tae",
        # to, is no slip of a robot "tam"; a name spelt so exactly is still that name)
        # a packaging word that is a word of one of the world's names ("trays" of seed_tray) is that
        # name's word there, not a unit
        self.index = NameIndex(world, reserved={k for k in keywords if k.isalpha()} | set(SUPERLATIVES)
                               | (FILLERS - PACKAGING_WORDS) | (PACKAGING_WORDS - _name_words(world)) | FRAME_WORDS,
                               respelt=set(SPELLINGS))
        robots = world.get("robots") or {}
        self.kinds = {str(r.get("kind")).lower() for r in robots.values()
                      if isinstance(r, dict) and r.get("kind")}
        self.tags = {str(t).lower() for r in robots.values() if isinstance(r, dict)
                     for t in (r.get("tags") or [])}
        self.skills = {str(s).lower() for r in robots.values() if isinstance(r, dict)
                       for s in (r.get("skills") or {})}
        # the words of the world's names, for telling a misspelt name from talk
        self._name_words = {w for n in self.index.names
                            for w in [n.alpha + n.digits, n.alpha] + re.split(r"[-_\s]+", n.name.lower())
                            if len(w) >= 3} | {w for ws in KIND_WORDS.values() for w in ws}
        self._name_words |= {w for ws in self.index.stems.values() for w in ws}
        #: the names as written, short ones too ("po", "ok"), which no particle or tag may swallow
        self._whole_names = {n.name.lower() for n in self.index.names}
        #: the same without the English kind words ("bay", "bot"), which are never misspelt
        self._own_name_words = self._name_words - {w for ws in KIND_WORDS.values() for w in ws}
        self.aside: list[str] = []
        self.corrected: list[str] = []   # "*word" corrections made (asterisk.star_corrections)
        self._robots = {str(r).lower() for r in robots}
        #: the world's own spellings with accents ("açaí" for acai), read as the names they are
        self._declared = non_ascii_words(world, ("shelves", "products", "robots"))
        #: the places, as a pattern, for the chat forms that name one (:meth:`_chat_said_plainly`)
        #: with the words the world gives them ("the cold aisle got 8": the cold aisle has 8)
        shelves = sorted({str(w) for name, shelf in (world.get("shelves") or {}).items()
                          for w in [name, *((shelf or {}).get("words") or [])]}, key=len, reverse=True)
        self._places = "|".join(re.escape(w).replace(r"\ ", r"\s+") for w in shelves) or None
        #: numbered places by letters + digits ("dock2" -> dock2, "bay9" of "bay_9" -> bay_9)
        self._numbered_places = {n.alpha + str(int(n.digits)): n.name for n in self.index.names
                                 if n.kind == "shelf" and n.digits}
        #: name stems two or more robots share ("tug" of tug1..tug4): groups of the world
        self.robot_stems = {stem for stem in self.index.robot_groups if stem not in KIND_WORDS["robot"]}

    def _patois_read(self, toks: list[Tok]) -> list[Tok]:
        """The tokens with Jamaican Creole words read as English (:func:`pipflow.language.patois.english_of`:
        "mi want 40 X in P", "yuh fi take 4 X", "shift 6 of dem", "him battery weak"), each keeping
        the text it was said in; a name of the world is never read so, and "dem" after one (its
        plural) is left out. A word of no grammar, verb or function is taken for a thing ("mi
        phone": my)."""
        said = [str(t.value) if t.kind == "word" else "\0" if t.kind in ("name", "shelf", "kind") else t.text
                for t in toks]
        english = english_of(said, lambda w: w == "\0",
                             lambda w: w == "\0" or (w.isalpha() and w not in self.keywords and w not in VERB_LEXICON
                                                     and w not in FUNCTION_WORDS and w not in FILLERS))
        out: list[Tok] = []
        for t, read in zip(toks, english):
            if read is None:
                out.append(t)
            elif read not in (PLURAL, LEFT_OUT):
                first, *rest = read.split()
                out += [Tok("word", t.text, first)] + [Tok("word", "", x) for x in rest]
        return out

    def _known(self, word: str) -> bool:
        return (word in self.keywords or word in FILLERS or word in STOPWORDS or word in FRAME_WORDS
                or word in NUMBER_WORDS or word in FRACTIONS or word in SUPERLATIVES)

    def _reads(self, word: str) -> bool:
        """Whether a word is one this reader reads as its own: a grammar word, a filler, a number, a
        name of the world or a robot, or a slip of one (what an accented word may never be read as:
        :func:`pipflow.language.characters.accents_folded`)."""
        return self._known(word) or word in self._robots or self.content(word) or self.names_world(word)

    def _keyword_typo(self, word: str) -> str | None:
        """The keyword a misspelt word means ("shuld" -> should, "mvoe" -> move, "form" -> from):
        one edit with the same first letter for words of five letters or more, or one slip of the
        fingers (:func:`pipflow.language.spelling.slip`) for any of three or more; one candidate
        only: two repairs that compete ("fro": for, or from?) leave the word unknown, refused."""
        if len(word) < 3 or not word.isalpha():
            return None
        cands = set()
        if len(word) >= 5:
            cands |= {k for k in self.keywords if k[:1] == word[:1] and k.isalpha() and len(k) >= 4
                      and abs(len(k) - len(word)) <= 1 and distance(word, k) <= 1}
        # a slip of the fingers on any grammar word of 3 letters or more ("mvoe", "form" for
        # "from", "teh"): neighbours swapped, a letter dropped or doubled, a key next to it
        cands |= {k for k in self.keywords if k.isalpha() and len(k) >= 3 and slip(word, k)}
        # and towards the verb lexicon's one-word verbs ("sotw" -> stow, read as "put")
        cands |= {verb for k, (_, verb) in VERB_LEXICON.items()
                  if " " not in k and k.isalpha() and verb in self.keywords and slip(word, k)}
        return next(iter(cands)) if len(cands) == 1 else None

    def robot_stem(self, word: str) -> str | None:
        """The name stem a robot word means as a group ("tugs", "tug" -> "tug" where robots are
        tug1..tug4), when it is no English word for robots ("robots", "bots" mean every robot)
        and no declared kind or tag (those come first: :meth:`_group`)."""
        low = normalize(word)
        for v in dict.fromkeys([low, low[:-1] if low.endswith("s") else low, low[:-2] if low.endswith("es") else low]):
            if v in KIND_WORDS["robot"]:
                return None
            if v in self.robot_stems:
                return v
        return None

    def group_names(self) -> str:
        """The robot groups of this world, for a refusal of a group word that matches none."""
        parts = [f"kind {k}" for k in sorted(self.kinds)] + [f"tag {t}" for t in sorted(self.tags)]
        parts += [f"{stem}s ({', '.join(self.index.robot_groups[stem])})" for stem in sorted(self.robot_stems)]
        return ", ".join(parts) or "none but all robots"

    def _joined(self, text: str) -> str:
        """Multi-word robot kinds and tags ("night shift") as one word, so they read as one."""
        for label in sorted(self.kinds | self.tags, key=len, reverse=True):
            parts = [p for p in re.split(r"[\s_-]+", label) if p]
            if len(parts) > 1:
                text = re.sub(r"\b" + r"[\s_-]+".join(map(re.escape, parts)) + r"(e?s)?\b",
                              lambda m: label.replace(" ", "_") + (m.group(1) or ""), text, flags=re.IGNORECASE)
        return text

    def _definite_groups(self, toks: list[Tok]) -> list[Tok]:
        """The tokens as they are, noting in :attr:`definite_said` each robot kind, tag or name stem
        said after "the", "this", "our", ...: the determiner is a filler the grammar drops, but it
        says one robot is meant where the kind said bare ("forklift only") is the kind
        (:meth:`~.robots.RobotSelector._check_one`). A word said both ways counts as said with it."""
        self.definite_said = {normalize(nxt.text) for t, nxt in zip(toks, toks[1:])
                              if t.kind == "word" and str(t.value) in DEFINITE and nxt.kind in ("word", "kind") and nxt.text
                              and (self._group(nxt.text) is not None or self.robot_stem(nxt.text) is not None)}
        return toks

    def _interjection_set_off(self, toks: list[Tok]) -> list[Tok]:
        """The tokens with a comma after an interjection that opens a sentence or a clause of two
        words or more without one ("davai komplektovka 4 more smes", "yalla move 3 X ...", "..., ah no
        wait, 8", "..., isa that one's wheel still squeaking"): as "Davai, ..." it is talk, set aside
        as ever. Only a word of no other language's talk that is no English word, or a sound
        (:data:`SOUNDS`: "Ah please add ..."; "night robots", "no wait" keep their readings), no
        greeting (said with its addressee: "morning team"), no word of the grammar, no verb and no
        operative word."""
        out: list[Tok] = []
        for k, t in enumerate(toks):
            out.append(t)
            opens = k == 0 or (toks[k - 1].kind == "punct" and toks[k - 1].value in (".", ";", "!", "?", ":")) \
                or (toks[k - 1].kind == "punct" and toks[k - 1].value == "," and _clause_follows(toks, k + 1))
            word = str(t.value)
            if (opens and t.kind == "word" and word in INTERJECTIONS and word not in GREETINGS
                    and (not common_word(word) or word in SOUNDS)
                    and word not in self.keywords and word not in VERB_LEXICON and word not in OPERATIVE
                    and k + 1 < len(toks) and toks[k + 1].kind != "punct"
                    and not (toks[k + 1].kind == "word" and toks[k + 1].value in ADDRESSEES)):
                out.append(Tok("punct", ",", ","))
        return out

    def _vocative_set_off(self, toks: list[Tok]) -> list[Tok]:
        """The tokens with a comma after a word said only to the one asked that opens a sentence
        before its order ("boss the counter shouldn't drop below 10", "mate move 3 X to P"): as
        "Boss, ..." it is set aside as ever. Only before an article or a verb of the reader, and
        never a word of the grammar or a name of the world (those are tokens of their own kind)."""
        out: list[Tok] = []
        for k, t in enumerate(toks):
            out.append(t)
            opens = k == 0 or (toks[k - 1].kind == "punct" and toks[k - 1].value in (".", ";", "!", "?", ":"))
            nxt = toks[k + 1] if k + 1 < len(toks) else None
            if (opens and t.kind == "word" and str(t.value) in VOCATIVES and str(t.value) not in self.keywords
                    and nxt is not None and nxt.kind == "word"
                    and (str(nxt.value) in DEFINITE | {"a", "an"} or str(nxt.value) in VERB_LEXICON)):
                out.append(Tok("punct", ",", ","))
        return out

    def _people_as_robots(self, toks: list[Tok]) -> list[Tok]:
        """The tokens with a word for people read as robots where a robot group says whose they are
        ("the night shift boys keep out of P", "the backup bois", "the strongest boi", "only boys
        that carry 4 or more"): after a robot kind, tag, name stem or superlative
        (:meth:`_says_robots`), or before "that", "which" or "who" and a skill of the world's robots;
        never before a word for robots ("the night crew robots": the crew is the tag's). Said alone
        ("the boys counted it", "lads, ...") such a word is read as before."""
        out: list[Tok] = []
        for k, t in enumerate(toks):
            # as written: "lads" is no slip of "loads" here
            if t.kind == "word" and t.text.lower() in PEOPLE_AS_ROBOTS and self._group(t.text) is None \
                    and not self._robots_at(toks, k + 1) \
                    and ((k and self._says_robots(toks[k - 1])) or self._skill_follows(toks, k + 1)):
                t = Tok("kind", t.text, "robot", "robot")   # as the lexer reads "robots" and "robot"
            out.append(t)
        return out

    def _robots_at(self, toks: list[Tok], k: int) -> bool:
        """Whether the token at ``k`` names robots: a word for robots, a kind or a tag."""
        return k < len(toks) and (toks[k].of == "robot" or self._group(toks[k].text) is not None)

    def _says_robots(self, tok: Tok) -> bool:
        """Whether a token names robots as a word before a noun does: a robot kind, tag or name stem
        as declared, not its plural ("the forklift guys"; in "use the forklifts lads" the lads are
        the ones asked), or a superlative ("the strongest boi")."""
        low = normalize(tok.text)
        groups = self.kinds | self.tags | self.robot_stems
        return tok.kind in ("word", "kind") and bool(low) and (
            any(low == normalize(g) for g in groups) or str(tok.value) in SUPERLATIVES)

    def _skill_follows(self, toks: list[Tok], k: int) -> bool:
        """Whether "that", "which" or "who" and a skill of the world's robots (its verb) open at ``k``
        ("... boys that carry 4 or more", "... that can carry 5")."""
        said = [str(t.value) for t in toks[k:k + 3] if t.kind == "word"]
        if said[:1] not in (["that"], ["which"], ["who"]):
            return False
        verb = said[2] if said[1:2] in (["can"], ["could"]) and len(said) > 2 else said[1] if len(said) > 1 else ""
        return any(verb == s or verb in plural_forms(s) for s in self.skills)

    def _group(self, text: str) -> tuple[str, str] | None:
        """("RKIND", kind) or ("RTAG", tag) when the word names robots by kind or tag."""
        low = normalize(text)
        for kind in self.kinds:   # the word itself, or a plural of it ("gantries" of gantry)
            if low == normalize(kind) or low in plural_forms(normalize(kind)):
                return "RKIND", kind
        for tag in self.tags:
            if low == normalize(tag) or low in plural_forms(normalize(tag)):
                return "RTAG", tag
        return None

    def content(self, word: str) -> bool:
        """Whether a word of a clause carries content here (:func:`pipflow.language.asides.content_free`):
        a grammar word that is no function word, a number or fraction word, a robot kind, tag,
        skill or superlative, or a word within a typo's reach of a name of the world (a misspelt
        name is never talk)."""
        if word in self.keywords and word not in FUNCTION_WORDS and word not in ASIDE_ONLY:
            return True   # "morning", "tonight": a grammar word of asides only is no content
        if word in NUMBER_WORDS or word in FRACTIONS or word in SUPERLATIVES or word in self.skills:
            return True
        if self._group(word) is not None:
            return True
        if word in FUNCTION_WORDS or word in FILLERS:
            return False  # "for" is no misspelt "four", "to" none of "two" (as in names_world)
        if _number_typo(word) is not None:
            return True
        if SPELLINGS.get(word) in _SAID_AS:   # "dey" (they) is no slip of a name ("dry")
            return False
        full = dropped_g(word)
        if full is not None:   # "runnin": as "running" is
            return self.content(full)
        # a common word written as itself is no slip of a grammar word ("driver" no "drive"), as it
        # is none of a number (_number_typo) or of a name (_near_name)
        repaired = SPELLINGS.get(word) or (None if common_word(word) else self._keyword_typo(word))
        if repaired is not None and repaired not in FUNCTION_WORDS:
            return repaired not in ASIDE_ONLY   # "tmr": tomorrow
        return self._near_name(word)

    def _free_clauses(self, parts: list[Clause], content: Callable[[str], bool]) -> list[Clause]:
        """The clauses of a sentence that carry nothing an order needs (:meth:`_clauses`)."""
        def names(w: str) -> bool:
            return w in _HELD or self.names_world(w)
        free = [c for c in parts if content_free(c.words, content, names, reports=True, thing=self._names_goods)]
        # what goods are like ("Tea chests are heavy, use only ... for them") is kept where a later
        # clause points back: what it names is what "them" means (asides.is_condition)
        free = [c for c in free if "\0" not in c.words or not any(
            w in BACK_REFERENCES for later in parts[parts.index(c) + 1:] for w in later.words)]
        free += [c for k, c in enumerate(parts) if k and c not in free
                 and restates_what_stays(parts[k - 1].words, c.words, names)]
        free += leading_reason(parts, free, lambda w: w == "\1" or w in NUMBER_WORDS, content)
        if len(parts) > 1 and parts[-1] not in free and signature(parts[-2].words, parts[-1].words):
            free.append(parts[-1])   # "Regards, Ramesh": the writer's name
        return free

    def _proper_name(self, toks: list[Tok], k: int) -> bool:
        """Whether the word at ``k`` is a name of the talk ("the Lau guy", "for the Kadavu boat", "in
        Koro"): written with a capital after an article or a preposition, no word of English, of this
        reader or of talk, and no name of the world (those are names). In a clause judged for
        content it is no content: never a slip of a grammar word ("Lau" is no "lay"), a name of the
        world or a count. A name said alone ("..., Hornet") is someone addressed, and is judged so."""
        t, before = toks[k], toks[k - 1] if k else None
        word = t.text.lower()   # as written: a repair may have made it a grammar word ("Lau" as "lay")
        return before is not None and before.kind == "word" and before.text.lower() in _BEFORE_A_NAME \
            and t.text[:1].isupper() and t.text[1:].islower() and word.isalpha() and not common_word(word) \
            and word not in self.keywords and word not in TALK and not self.names_world(word)

    @staticmethod
    def _names_goods(word: str) -> bool:
        """Whether a word of a clause (:meth:`_clauses`) names goods: a name held as "\0" (a robot's
        is "\3", a place's "\4": "bay 1 is wet, move the rice to bay 2" may mean from bay 1)."""
        return word == "\0"

    def _near_name(self, word: str) -> bool:
        """Whether a word is within a typo's reach of a word of the world's names and may be a slip
        of it: a common English word written as itself ("big" near "bin", "left" near "loft"), or a
        word of talk of our lists, is none (:func:`pipflow.language.english.common_word`)."""
        if word in self._name_words:
            return True
        if word in _TALK_WORDS:   # "hai" (Japanese: yes) is no slip of a name
            return False
        return any(distance(word, w) <= max(1, tolerance(len(w))) for w in self._name_words) \
            and not common_word(word)

    def names_world(self, word: str, closely: bool = False) -> bool:
        """Whether a word of a clause names something of this world or a count: a world name, a
        robot kind or tag, a number word, or a word within a typo's reach of a name's word (the
        test a pleasantry's words must pass: :func:`pipflow.language.asides.is_pleasantry`).

        ``closely``: only a slip of one edit from a word of the world's own names (same first
        letter, five letters or more), for a statement run on without a comma
        (:func:`pipflow.language.asides.unmarked_statement`): its ordinary words ("flat", "forks",
        "bow") are two edits from a name or one from a kind word, and it is judged word by word."""
        if word in NUMBER_WORDS or word in FRACTIONS or self._group(word) is not None:
            return True
        if word in FUNCTION_WORDS or word in FILLERS or word in self.keywords:
            return False  # "for" is no misspelt "four", "there" none of "three"
        if _number_typo(word):
            return True
        if closely:
            return word in self._name_words or any(
                len(w) >= 5 and w[:1] == word[:1] and distance(word, w) <= 1 for w in self._own_name_words)
        return self._near_name(word)

    def _label(self, toks: list[Tok], k: int) -> bool:
        """Whether the number at ``k`` is part of a label, no count: "door 3", "truck 14", "PO
        4471", "TN 09 BQ 4471". It is written in digits ("Quick one before ..." counts); it follows
        a noun that is no word of this reader (a grammar word, filler, number or name of the world,
        or a slip of one: "bay 12" where places are bay1..bay4 stays a count), never a verb form
        ("expecting 3" counts); and no item or unit follows it ("3 pallets" counts)."""
        before = toks[k - 1] if k else None
        if not toks[k].text.isdigit() or before is None or before.kind != "word":
            return False
        word = str(before.value)
        if not word.isalpha() or word.endswith(("ing", "ed")) or self._reads(word):
            return False
        after = toks[k + 1] if k + 1 < len(toks) else None
        return after is None or after.kind == "punct" or (after.kind == "word" and str(after.value) not in FILLERS)

    def _clauses(self, cur: list[Tok]) -> tuple[list[Tok], list[str]]:
        """The sentence's tokens without its content-free clauses (split at commas and colons),
        and the words of those. A name, count or kind word is content by itself."""
        marks = {",", ":", "(", ")"}
        # the words as written (a greeting's "lads" is no misspelt "loads"); a word that a repair
        # would make a grammar word is content (:meth:`content`)
        # a name, kind word or count stands as "\0" (a robot's name as "\3", a place's as "\4",
        # which what goods are like may not name: asides.is_condition; a count as "\1": a reason
        # may name places, never hold a count: asides.leading_reason); all are content by themselves; a number that
        # labels something of the talk ("truck 14": :meth:`_label`) stands as "\2", no content
        # (a kind word keeps its text: "good" of goods opens "Good morning team"; it is content by
        # the names test all the same)
        words = [str(t.value) if t.kind == "punct" and t.value in marks else
                 "s" if t.kind == "word" and t.value == POSS_MARK else   # "Today's plan": the 's is no content
                 (_as_said_in_full(re.sub(r"[^a-z0-9]", "", t.text.lower()), t) or str(t.value)
                  if t.kind in ("word", "kind") else
                  "oclock" if t.kind == "num" and _clock(cur, k) else "\2" if t.kind == "num" and self._label(cur, k)
                  else "one" if t.kind == "num" and _one_of_these(cur, k)
                  else "\1" if t.kind == "num" else "\3" if t.kind == "name" and t.of == "robot"
                  else "\4" if t.kind == "name" and t.of == "shelf" else "\0")
                 for k, t in enumerate(cur)]
        parts = clauses(words, marks)
        # names of the talk ("the Lau guy") are never content, whatever a repair made of them
        talk_names = {words[k] for k in range(len(cur)) if cur[k].kind == "word" and self._proper_name(cur, k)}

        def content(w: str) -> bool:
            return w in _HELD or (w not in talk_names and self.content(w))
        free = self._free_clauses(parts, content)
        # "... to the dray bay ta", "... over to the shed would ya, pissing down", "take 3 X out of
        # P pá, they ...": a thanks, a closing word or a request tag closing a clause that is no
        # talk, without a comma
        inner: set[int] = set()   # the starts of parts of a clause: no clause mark of their own
        closing: dict[Clause, int] = {}
        for c in [c for c in parts if c not in free]:
            closing[c] = trailing_thanks(list(c.words), lambda w: w in _HELD or self.names_world(w))
            if closing[c]:
                free.append(Clause(c.end - closing[c], c.end, c.words[-closing[c]:]))
                if c is not parts[-1]:
                    inner.add(c.end - closing[c])
        for c in parts:
            # "... on the ramp for afternoon pickup": an adjunct of purpose, time or reason that
            # carries nothing, at the end of a clause that does (asides.trailing_adjunct)
            if c in free:
                continue
            clause = list(c.words[:len(c.words) - closing.get(c, 0)])
            # "For the Auchan the cais takes ...", "For the inventory: ...": a purpose said first
            # (asides.leading_adjunct), the whole clause where it is a heading
            lead = leading_adjunct(clause, content, lambda w: w in _HELD or self.names_world(w))
            if lead == len(clause):
                free.append(c)
                continue
            if lead:
                free.append(Clause(c.start, c.start + lead, tuple(clause[:lead])))
                inner.add(c.start)
            # "... dont use flint hes got a flat tyre": a statement run on without a comma
            n = unmarked_statement(clause, lambda w: w in _HELD or self.names_world(w, closely=True))
            if n:
                end = c.start + len(clause)
                free.append(Clause(end - n, end, tuple(clause[-n:])))
                inner.add(end - n)
                clause = clause[:-n]
            # an adjunct of time or purpose may hold words of the grammar, never a word of a name
            # ("for the dispatch" of dispatch-dock, though "dispatch" is a verb of the grammar too)
            n = trailing_adjunct(clause, lambda w: w not in TIMES_OF_DAY and content(w),
                                 lambda w: w in _HELD or (w not in TIMES_OF_DAY and (
                                     self.names_world(w) or (w in self._name_words and w not in FUNCTION_WORDS))))
            if n:
                end = c.start + len(clause)
                free.append(Clause(end - n, end, tuple(clause[-n:])))
                inner.add(end - n)
            # "Quick one: ...", "Quick one before the brewers get in: ...": an opener (with its
            # adjunct), judged on the words as written (its "one" is read as a count)
            said = [re.sub(r"[^a-z0-9]", "", x.text.lower()) for x in cur[c.start:c.start + len(clause) - n]]
            # "Change of plan: ...", "orait change of plan. ...": only as the command's first clause
            first = c.start == 0 and self.position(cur[0]) == 0 and opens_changed_plan(
                [str(x.value) if x.kind == "word" else x.text.lower() for x in cur[:len(clause) - n]])
            if is_opener(said) or first:
                free[:] = [f for f in free if not (c.start <= f.start < c.end)] + [c]
                inner.discard(c.start + len(clause) - n)
        return _set_off(cur, free, inner)

    def sentences(self, command: str, stops: frozenset[int] = frozenset()) -> list[Lexed]:
        """The command's sentences as terminals (split at . ; ! ?, and before the recognised
        tokens at ``stops``: a command said without stops read with them, :mod:`runon`). A
        sentence with no content (:meth:`content`) is set aside: not returned, its words kept in
        :attr:`aside`; a sentence with some content-free clauses carries its reading without them
        as ``trimmed``. :attr:`tokens` keeps the recognised tokens, :meth:`position` finds one."""
        # "the truck from Québec is late": an accented word that can only be talk, spelled without accents
        command, declared = declared_spellings(command, self._declared)
        command, keyboard = turkish_i(command)
        declared += keyboard
        command, accented = accents_folded(command, self._reads)
        radio = transmission(command, self._names_exactly, lambda w: w in self._robots, is_number)
        if radio is not None:   # "Yard control to all units. ... Over.": the voice procedure set aside
            command = radio.text
        # "... short again 🙄 send 4 more": a face or a gesture ends a sentence, and is said as set aside
        command, feelings = without_expressions(command)
        for idiom, plain in IDIOMS + WORD_ORDER:
            command = idiom.sub(plain, command)
        # "... 3 cowboys ... *carboys": a texted correction made, and said
        command, starred = star_corrections(command)
        command = self._chat_said_plainly(command)
        # a time written as one word ("3pm", "10am", "2oclock") is the count and its word, as "3 pm" is;
        # the 24-hour clock written the French way ("at 15h", "3h30") is one too
        text = re.sub(r"\b(\d{1,2})(am|pm|oclock)\b", r"\1 \2", self._joined(check_text(command)), flags=re.IGNORECASE)
        text = re.sub(r"\b([01]?\d|2[0-4])h(?:[0-5]\d)?\b", r"\1 oclock", text, flags=re.IGNORECASE)
        # and "14:00", "2:30 PM": a time of day (its minutes and half of the day are no count)
        text = re.sub(r"\b([01]?\d|2[0-4]):[0-5]\d(?:\s*(?:am|pm|a\.m\.|p\.m\.)(?![a-z]))?", r"\1 oclock", text,
                      flags=re.IGNORECASE)
        # "by 7ish": about a time of day, after a word that says when; read as "by 7 o'clock", never as
        # a count ("cut the cider by 7ish" is no cut by 7)
        text = re.sub(r"\b(by|at|around|before|after|until|till)\s+(\d{1,2})ish\b", r"\1 \2 oclock", text,
                      flags=re.IGNORECASE)
        # "the truck is comin at 10", "contractor pickin up at 11", "comin for his order bout 9":
        # after a verb of arriving or leaving, a bare number after "at", "by", "about" is the time
        # of day (no count follows it)
        text = _ARRIVING_AT.sub(r"\1 \2 oclock", text)
        toks = noun_adjuncts(unmarked_lists(places_listed_after_sharing(unit_of_its_product(where_words_placed(
            numbered_siblings(recognize(text, self.index), self._numbered_places))))))
        fixed = []
        for t in self._patois_read(toks):
            if t.kind == "word" and not self._known(str(t.value)) and self._group(t.text) is None:
                word = str(t.value)
                typo = (SPELLINGS.get(word) or LETTER_WORDS.get(t.text) or _number_typo(word)
                        or dropped_g(word) or self._keyword_typo(word))
                if typo is not None:
                    t = Tok("word", t.text, typo)
            if t.kind == "word" and str(t.value) in RUN_TOGETHER and not self._known(str(t.value)):
                first, second = RUN_TOGETHER[str(t.value)]
                fixed += [Tok("word", t.text, first), Tok("word", "", second)]
                continue
            fixed.append(t)
        verbs = {w for w in self.keywords if " " not in w} | set(VERB_LEXICON)
        toks = self._definite_groups(them_as_determiner(read_counts(_split_hyphens(
            this_job_announced(case_endings(topic_marked(self._vocative_set_off(self._interjection_set_off(
                self._people_as_robots(fixed)))))),
            self.keywords))))
        toks, restated = item_scope_restated(toks)   # "..., just the cement" where only cement was named
        toks, framed = without_request_frames(orders_taken_back(places_taken_back(toks), _ORDER_VERBS | _CHANGE_VERBS), verbs)
        toks = places_then_each(by_as_among(toks))   # before "by" is read as "at"
        toks = only_after_a_move(source_after_verb(of_as_from(place_as_it(by_as_at(toks)))))
        toks = item_as_subject(fronted_source(to_be_done(needs_doing(toks, verbs), verbs), verbs))
        toks = on_as_to(object_before_verb(topic_first(place_first(place_set_off(count_after_item(destination_first(
            place_must_be(verb_last(read_by_roles(toks))))))))))
        toks = addressed_anyone(stative_having(is_contracted(asked_plainly(toks))))
        toks = lexicon_verbs(whole_places(quantity_phrases(toks, self.keywords)), self.keywords)
        toks = put_back_after_its_object(counts_sent_from_a_topic(corrected(toks)))
        toks = dropped_object(corrected_later(without_particles(toks)))
        self._framed = (radio.aside if radio is not None else []) + feelings + framed + restated
        self.corrected = declared + accented + starred
        return self._split(toks, stops)

    def _chat_said_plainly(self, command: str) -> str:
        """Chat forms read as the plain words the grammar has (Singapore English and chat
        generally): clause-closing particles (:data:`PARTICLES`) and "can" / "ok" / "can or
        not" tags left out (a tag asked with "?" ends the sentence), Taglish's particles
        (:data:`TAGALOG_PARTICLES`) and request prefixes on a verb the grammar knows ("paki-move":
        move) left out, "go and <verb>" as the verb,
        "<item> go <place>" as "to <place>", "<place> got" as "has". A word of the world's names
        is never taken for a particle or a tag ("can" of soup_can, a place called "ok")."""
        def left_out(m: re.Match) -> str:
            if any(self._names_exactly(w) for w in re.findall(r"[a-z]+", m.group(0).lower())):
                return m.group(0)
            return "." if "?" in m.group(0) else ""
        def unprefixed(m: re.Match) -> str:
            verb = m.group(1).lower()
            return "" if verb in self.keywords or verb in VERB_LEXICON else m.group(0)
        command = _PARTICLE.sub(left_out, _CAN_TAG.sub(left_out, command))
        command = _TAGALOG_PARTICLE.sub(left_out, _TAGALOG_REQUEST.sub(unprefixed, command))
        command = _TAGALOG_MARKER.sub(left_out, command)
        command = _JAPANESE_POLITE.sub(left_out, _INDONESIAN_YA.sub(left_out, command))
        command = _INDONESIAN_PLEASE.sub(lambda m: m.group(0) if self._names_exactly(m.group(0).lower()) else "please",
                                         command)
        command = _MINIMAL.sub(lambda m: "minimum" if m.group(1).lower() == "minimal" else "maximum", command)
        command = re.sub(r"(^|[.!?;:\n])(\s*),", r"\1\2", command)   # "Hai, move ...": no comma opens a sentence
        command = _HONORIFIC.sub(lambda m: m.group(0) if self._names_exactly(m.group(0).lower()) else m.group(1), command)
        command = _GO_AND.sub("", command)
        command = _FOR_EACH_OF.sub(self._times_for_each, command)
        if self._places is not None:
            command = re.sub(rf"\bgo\s+(?=(?:the\s+)?(?:{self._places})\b)", "to ", command, flags=re.IGNORECASE)
            # "bunker got", and "bunkers got" typed for "bunker's got"
            command = re.sub(rf"\b({self._places})s?\s+got\b", r"\1 has", command, flags=re.IGNORECASE)
        return command

    def _times_for_each(self, m: re.Match) -> str:
        """ "three fryers for each of the four trucks": three times four fryers, where what there
        are four of is no name or kind word of the world (then it says where they go: left as said)."""
        said = m.group(4).lower()
        try:
            kind = self.index.kind_of_word(normalize(said))
        except TranslationError:   # it could name several kinds: a word of the world either way
            kind = "several"
        if self._names_exactly(said) or kind is not None or self.index.group(said) is not None:
            return m.group(0)
        return f"{m.group(1)} times {m.group(3)} {m.group(2)}"

    def _names_exactly(self, word: str) -> bool:
        """Whether a word is a word of the world's names, a robot kind or tag, as written."""
        return word in self._name_words or word in self._whole_names or self._group(word) is not None

    def stopped(self, stops: frozenset[int]) -> tuple["Lexicon", list[Lexed]]:
        """A copy of this lexicon with the command it lexed last split again with ``stops``
        (:meth:`sentences` with them, without recognising its words again)."""
        other = copy.copy(self)
        return other, other._split(self.tokens, stops)

    def _split(self, toks: list[Tok], stops: frozenset[int]) -> list[Lexed]:
        """The recognised tokens split into sentences (:meth:`sentences`)."""
        out: list[Lexed] = []
        cur: list[Tok] = []
        self.aside: list[str] = list(self._framed)
        self.tokens = toks
        self._positions = {id(t): k for k, t in enumerate(toks)}
        stopped = False   # whether the sentence being read was opened by a stop put in (runon)
        for k, t in enumerate(toks + [Tok("punct", ".", ".")]):
            if k in stops or (t.kind == "punct" and t.value in (".", ";", "!", "?")):
                if cur:
                    said = self._sentence(cur)
                    if said is None and (stopped or k in stops) and not (self.talk(cur) or self._remark(cur)):
                        said = self._terminals(cur)   # neither talk nor a remark: it must read
                    if said is None:
                        self.aside.append(" ".join(x.text for x in cur))
                    else:
                        out.append(self._with_topic_moved(said, cur))
                cur = []
                stopped = k in stops
            if not (t.kind == "punct" and t.value in (".", ";", "!", "?")):
                cur.append(t)
        return out

    def _remark(self, toks: list[Tok]) -> bool:
        """Whether a part of a command said without stops that asks for nothing (:meth:`_sentence`
        is None for it) is a remark of its own, as a stop put before it may make it: it opens
        with a subject ("they been breaking") or with a word no rule knows and goes on for two
        words more ("fire marshal been on us about that"). A part that opens with a word of the
        grammar ("up there ...", "does ...") is the end of the sentence before it: never set aside."""
        words = [t for t in toks if t.kind == "word"]
        said = [t for t in words if self.terminal(t) is not None]   # "the fire marshal ...": from "fire"
        if not said or len(words) < len(toks):
            return False
        first = re.sub(r"[^a-z]", "", said[0].text.lower())
        return first in SUBJECTS or (self.terminal(said[0]) or ("",))[0] == "UNKNOWN" and len(said) >= 3

    def position(self, tok: Tok) -> int | None:
        """Where a token of the last command lexed stands among its recognised tokens."""
        return self._positions.get(id(tok))

    def talk(self, toks: list[Tok]) -> bool:
        """Whether recognised tokens are talk by what they are, as a part of a command said without
        stops must be to be set aside (:func:`pipflow.language.asides.said_talk`, judged on the
        words as written; a name, count or kind word is content), and ask for nothing."""
        if any(t.kind in ("name", "num", "kind") for t in toks):
            return False
        words = [re.sub(r"[^a-z0-9]", "", t.text.lower()) for t in toks if t.kind == "word"]
        return said_talk(words, self.names_world) and self._sentence(toks) is None

    def _sentence(self, cur: list[Tok]) -> Lexed | None:
        """A sentence's terminals, with its reading without content-free clauses (``trimmed``);
        None when it is nothing but such clauses (it is set aside whole)."""
        keep, aside = self._clauses(cur)
        if not [x for x in keep if x.kind != "punct"]:
            return None
        if aside:
            return replace(self._terminals(cur), trimmed=self._with_topic_moved(self._terminals(keep), keep),
                           aside=tuple(aside))
        return self._terminals(cur)

    def _with_topic_moved(self, said: Lexed, toks: list[Tok]) -> Lexed:
        """The sentence with its reading where a fronted topic stands where its pronoun does
        (``dislocated``: :func:`wordorder.left_dislocated`), when it has one; its reading without
        talk (``trimmed``) gets its own."""
        moved = left_dislocated(toks)
        return said if moved == toks else replace(said, dislocated=self._sentence(moved))

    def _terminals(self, toks: list[Tok]) -> Lexed:
        tokens: list[Token] = []
        source: list[Tok] = []
        exact: set[int] = set()
        said_exactly = False
        for k, t in enumerate(toks):
            term = self.terminal(t)
            if term is None:
                said_exactly = t.kind == "word" and str(t.value) in EXACT_WORDS
                continue
            if said_exactly and term[0] == "NUM":
                exact.add(len(tokens))
            said_exactly = False
            if term[0] == "ROBOTWORD" and not (k + 1 < len(toks) and toks[k + 1].kind == "num"):
                # "tugs" where the robots are tug1..tug4: a group of the world, never every robot
                stem = self.robot_stem(t.text)
                if stem is not None:
                    term = ("RKIND", stem)
            if term[0] == "POSS" and tokens and tokens[-1].type == "ROBOT" and "is" in self.keywords:
                term = (self.keywords["is"], "is")  # "Jumbo's the only one ...": a robot's "'s" is "is"
            elif (term[0] == "POSS" and tokens and tokens[-1].type == "PLACE" and k + 1 < len(toks)
                  and toks[k + 1].kind == "word" and toks[k + 1].value in ("got", "getting", "looking")):
                # "Cellar B's got ...": a place's "'s got" is "has got"; "P's getting crowded": "is"
                said = "has" if toks[k + 1].value == "got" else "is"
                if said in self.keywords:
                    term = (self.keywords[said], said)
            tokens.append(Token(term[0], term[1], start_pos=len(tokens)))
            source.append(t)
        return Lexed(tokens, source, frozenset(exact))

    def terminal(self, t: Tok) -> tuple[str, object] | None:
        """The grammar terminal a recognised token reads as (None: a filler, or a mark that
        carries nothing)."""
        if t.kind == "num":
            return "NUM", t.value
        if t.kind == "name":
            return {"shelf": "PLACE", "product": "ITEM", "robot": "ROBOT"}[t.of], t.value
        if t.kind == "punct":
            # a bracketed aside reads like one set off by commas ("lane 7 (it has 3 now) should...")
            name = self.keywords.get("," if str(t.value) in "()" else str(t.value))
            return (name, t.value) if name else None  # brackets and quotes carry nothing
        group = self._group(t.text)
        if group is not None and (t.kind == "kind" or str(t.value) not in self.keywords):
            return group
        if t.kind == "kind":
            return {"shelf": "PLACEWORD", "product": "ITEMWORD", "robot": "ROBOTWORD"}[t.of], t.value
        word = str(t.value)
        if word == POSS_MARK:
            return "POSS", "'s"
        if word in self.keywords:
            return self.keywords[word], word
        if word in FRACTIONS:
            return "FRAC", FRACTIONS[word]
        if word in SUPERLATIVES:
            return "SUPER", SUPERLATIVES[word]
        if word in self.skills:
            return "SKILL", word
        if word in FILLERS:
            return None
        return "UNKNOWN", word

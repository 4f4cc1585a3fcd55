"""The grammar of warehouse command English, for lark's Earley parser.

Why a grammar and not word lists: what a clause means comes from its structure (who holds what,
which way things move, what a negation or an "except" scopes over), and only a parse can tell
"Restock shelf3 so that it holds ten product1" (a count) from "restock shelf3 with ten product1"
(ten more). A sentence that the grammar cannot derive is refused at the first word that fits
nowhere, so a phrasing nobody wrote a rule for is never half-read.

The terminals are categories that :mod:`pipflow.warehouse.language.lexicon` assigns from the world: PLACE,
ITEM and ROBOT (a world name), PLACEWORD/ITEMWORD/ROBOTWORD (a kind word alone: "shelf",
"products", "robots"), RKIND and RTAG (a robot kind or tag of this world: "forklifts"), NUM (a
count already read from digits, words, collectives or arithmetic), FRAC ("third", "quarters").
Every other terminal is an English keyword written in quotes below. Filler words ("the",
"please", "units") are dropped by the lexicon before parsing; nothing else is.
"""
from __future__ import annotations

import re

GRAMMAR = r"""
start: sentence
sentence: lead? part aside? (sep part aside?)* (sep | bare_only)? aside?
        | places                                   -> topic_sentence
// "And can you bring ...": a word that joins the sentence on, then a way of asking
lead: ("but" | "and" | "then" | "also" | "so" | "however" | "now" | "tonight" | "oh" | "well" | "next" | "right" | "ok" | "okay" | "alright"
      | "finally" | "first" | "afterwards" | "after" "that" | "additionally" | "plus"
      | ("team" | "guys" | "folks" | "people" | "crew") ",") ("," | ":")? (("can" | "could" | "would") ("you" | "we") | "you" ("should" | "must" | "can") | "just" | "let" "us")?
    | (("can" | "could" | "would") ("you" | "we") | "you" ("should" | "must" | "can") | "just" | "let" "us") ("," | ":")?

// a separator costs: of two readings, the one with fewer, longer parts wins
// ("only alpha and charlie may carry bolts" is one rule, not "only alpha" and a second clause)
sep.-1: "," | "and" | "," "and" | "but" | "," "but" | "while" | "," "while" | "whereas"
   | "," "whereas" | "then" | "," "then" | "and" "then" | "," "and" "then" | "also" | "," "also"
   | "and" "also" | "," "and" "also" | ":" | "so" | "," "so" | "though" | "," "though"
   | "," "plus" | "plus" | "," "however" ","? | "," "just" | "but" "just" | "," "but" "just" | "and" "just"

?part: goal | rule | aside | tail | addressed | scoped_goal
     // "make sure the tuggers stay away from the cage": a rule asked to hold, as said without it
     | ("make" "sure" | "ensure") that? rule                     -> ensured_rule

aside: "instead" "of" NUM | "rather" "than" NUM
     | "now" | "right" "now" | "right" "away" | "tonight" | "at" "once" | "for" "now"
     | "no" "more" | "no" "less" | "no" "more" ","? "no" "less" | "not" "more" | "not" "one" "more"
     | "not" "more" ","? "not" "less"
     | "by" ("end" | "tonight" | "tomorrow" | "noon" | "morning" | "evening" | "shift" "end")
     | ("at" | "in") "end" | "eventually" | "afterwards" | "later"
     | "i" ("think" | "guess" | "suppose" | "believe") | "i" "have" "a" "plan" | "ok" | "okay"
     | "thanks" | "thank" "you" | "if" "possible" | "as" "well" | "too"
     | "urgently" | "if" "you" "can"
     | ("this" | "before") ("morning" | "afternoon" | "evening" | "shift" "ends"?) | "before" ("lunch" | "noon")
     | "tomorrow" | "first" "thing" | "before" "end" "of" "shift"
     | "by" NUM ("pm" | "am" | "oclock" | "o" "clock")?

// ---------------------------------------------------------------- amounts and items
rlsep: "," | "and" | "," "and" | "or" | "nor" | "," "or"
lsep: "," | "and" | "," "and" | "plus" | "&" | "as" "well" "as"
items: np (lsep np)*

np: NUM of? ihead                          -> np_count
  | NUM ITEMWORD "of" ITEM                 -> np_count
  | "just" NUM of? ihead                   -> np_count
  | NUM more of? ihead                     -> np_more
  | ("another" | "an" "extra") NUM of? ihead -> np_more
  | "another" ihead                        -> np_one_more
  | NUM of? ihead more                     -> np_more
  | NUM more of? ihead "than" ("it" | "they") ("does" | "do" | "has" | "have" | "holds" | "hold") now? -> np_more
  | NUM fewer of? ihead "than" ("it" | "they") ("does" | "do" | "has" | "have" | "holds" | "hold") now? -> np_fewer
  | NUM (more | fewer) of? ihead "than" PLACE (("has" | "holds" | "have" | "does" | "contains") now?)? -> np_more_than_place
  | NUM more                               -> np_more_bare
  | NUM fewer of? ihead                    -> np_fewer
  | NUM of? ihead fewer                    -> np_fewer
  | ("a" | "an") ihead                     -> np_one
  | ("a" | "an") more ihead               -> np_one_more
  | ("all" | "every") of? ihead within?   -> np_all
  | "all" of? its ihead                    -> np_all
  | ("no" | "none" "of" | "zero") ihead    -> np_none
  | frac of? its? ihead                    -> np_frac
  | lower NUM of? ihead                    -> np_atleast
  | NUM of? ihead "or" "more"              -> np_atleast
  | NUM "or" "more" of? ihead              -> np_atleast
  | upper NUM of? ihead                    -> np_atmost
  | NUM of? ihead ("max" | "maximum" | "tops" | "at" "most" | "or" "under") -> np_atmost
  | NUM of? ihead ("min" | "minimum" | "at" "least" | "or" "over") -> np_atleast
  | NUM of? ihead "or" ("fewer" | "less")  -> np_atmost
  | NUM "or" ("fewer" | "less") of? ihead  -> np_atmost
  | "more" "than" NUM of? ihead            -> np_above
  | ("fewer" | "less") "than" NUM of? ihead -> np_below
  | ("somewhere" | "anywhere")? "between" NUM "and" NUM of? ihead -> np_between
  | lower NUM ","? ("but" | "and") upper NUM of? ihead    -> np_between
  | lower NUM of? ihead ","? ("but" | "and") upper NUM    -> np_between
  | ("somewhere" | "anywhere")? "from" NUM "to" NUM of? ihead -> np_between
  | NUM more "of" ("each" | "every") ITEMWORD? -> np_each_more
  | ("one" more | NUM more) "of" "everything" -> np_each_more
  | NUM "to" NUM of? ihead                 -> np_between
  | vague NUM of? ihead                    -> np_vague
  | vagueq of? ihead                       -> np_vague
  | "too" ("many" | "much") of? ihead       -> np_too_many
  | "just"? NUM "of" ("each" | "every") ITEMWORD? -> np_each
  | NUM "of" "everything"                  -> np_each
  | "everything"                           -> np_everything
  | ("everything" | "all" ITEMWORD | "every" ITEMWORD | "all" "goods") except_items -> np_everything
  | "as" "many" of? ihead "as" PLACE ("has" "got"? | "got" | "holds" | "have" | "contains") now? -> np_as_many
  | "as" "many" of? ihead "as" PLACE                    -> np_as_many
  | "as" "many" ihead "as" ihead (("it" | "they") ("has" | "have" | "holds" | "hold" | "does" | "do"))? now? -> np_as_many_item
  | "same" ("number" | "amount" | "count" | "quantity") "of" ihead "as" ihead -> np_as_many_item
  | "as" "many" ihead? "as" PLACE (lsep PLACE)+ ("has" "got"? | "got" | "have" | "hold" | "holds" | "contain")? now? together -> np_as_many_total
  | "same" ("number" | "amount" | "count" | "quantity") "of" ihead "as" PLACE (("has" "got"? | "got" | "holds" | "have" | "contains" | "does") now?)? -> np_as_many
  | ("another" | "one" "more")                      -> np_another
  | "as" "many" "as" PLACE ("has" "got"? | "got" | "holds" | "have" | "contains") now? -> np_as_many_elided
  | ("rest" | "others" | "extras" | "extra" | "excess" | "surplus" | "remainder") rest_of? -> np_rest
  | "twice" "as" "many" ihead              -> np_twice
  | "twice" "as" "many" ihead "as" ("it" | "they") ("has" | "have" | "holds" | "hold") now? -> np_twice
  | NUM "times" "as" "many" ihead ("as" ("it" | "they") ("has" | "have" | "holds" | "hold") now?)? -> np_ntimes
  | ("twice" | NUM "times") "as" "many" ihead "as" PLACE ("has" "got"? | "got" | "holds" | "have" | "contains") now? -> np_times_as_many
  | lower NUM more of? ihead               -> np_atleast_more
  | "all" NUM of? ihead                    -> np_all_n
  | ("double" | "triple" | "quadruple") ihead -> np_times
  | "half" of? its? ihead                  -> np_half
  | NUM                                    -> np_bare
  | upper NUM                              -> np_atmost_bare
  | lower NUM                              -> np_atleast_bare
  | NUM "of" ("them" | "those" | "these")  -> np_bare

rest_of: "of" (ihead | "them" | "it" | its ihead | posplace ihead | ihead "there")
bare: ihead (lsep ihead)*
// "there shouldn't be any X left on P": after a negation "any X" is none of it
any_items: "any" any_none ((lsep | "or") "any"? any_none)*  -> items
any_none: ihead                                -> np_none
inum: ihead ":"? "just"? NUM left?
except_items: ("except" "for"? | "but" | "besides" | "other" "than" | "apart" "from" | "excluding") ihead (lsep ihead)*

ihead: ITEM | ITEMWORD
of: "of"
its: "its" | "their" | "it" POSS
now: "now" | "right" "now" | "at" "moment" | "currently"
more: "more" | "extra" | "additional"
fewer: "fewer" | "less"
frac: NUM FRAC | ("a" | "an") FRAC
lower: "at" "least" | "no" ("fewer" | "less") "than" | "not" ("fewer" | "less") "than" | "a" "minimum" "of"
     | "minimum" "of"? | "min"
upper: "at" "most" | "no" "more" "than" | "not" "more" "than" | "up" "to" | "a" "maximum" "of"
     | "maximum" "of"? | "max"
vague: "about" | "around" | "roughly" | "approximately" | "nearly" | "almost" | "some" | "like"
vagueq: "some" | "several" | "a" "few" | "few" | "many" | "lots" "of" | "plenty" "of" | "a" "lot" "of"

// ---------------------------------------------------------------- places
places: place (lsep place)*
place: PLACE                                -> place_name
     | PLACEWORD                            -> place_word
     | ("it" | "there")                     -> place_it
     | PLACE PLACEWORD                      -> place_name
     | ("every" | "each" | "all") (PLACEWORD | PLACE_VERB | "places") within?  -> place_all
     | ("every" | "each" | "all") (PLACEWORD | PLACE_VERB | "places") except_pl -> place_all
     | "all" "of" "them"                    -> place_all
     | "all" NUM (PLACEWORD | "places")     -> place_all_n
     | "each" "of" place (lsep place)*       -> place_each
except_pl: ("except" | "but" | "besides" | "other" "than" | "apart" "from" | "excluding") place (lsep place)*
posplace: PLACE POSS
prep: "in" | "on" | "at" | "into" | "onto" | "inside" | "within" | "to" | "in" "to" | "on" "to"
each: "each" | "apiece" | "both" | "every" NUM
// "every fish tank in the building", "every location in here": the whole world, said again
within: ("in" | "across" | "throughout") ("building" | "here" | "warehouse" | "shed" | "site" | "store" | "yard" | "depot") | "on" "site"
loc: prep places                            -> loc
   | prep ("each" "of" | "both" | "both" "of" | "all" "of" | "every" NUM "of") places -> loc_each
   | prep places each                       -> loc_each
   | prep places "respectively"             -> loc_resp

// ---------------------------------------------------------------- verbs
_keeps: "keep" | "keeps" | "retain" | "retains"
modal: "should" | "must" | "shall" | "will" | "would" | "ought" "to" | "oughta" | "gotta"
     // "P's gotta hold 65 X", "P has got to have 6 X": has to
     | POSS? "gotta" | (POSS | "has" | "have") "got" "to"
     | ("needs" | "need" | "wants" | "want" | "has" | "have" | "got") "to" | ("is" | "are" | "be") "supposed" "to"
     | "supposed" "to" | ("is" | "are") "to" | "to" | "can" | "could" | "may" | "might"
be: "be" | "is" | "are" | "become" | "becomes" | "end" "up" "with" | "get"
setv: "has" "got" | "have" "got" | "has" | "have" | "hold" | "holds" | "store" | "stores" | "stock" | "stocks" | "contain"
    | "contains" | "get" | "gets" | "keep" | "keeps" | "carry" | "carries" | "house" | "houses"
    | "need" | "needs" | "receive" | "receives" | "end" "up" "with" | "be" "stocked" "with"
    | "ends" "up" "with" | "ends" "with" | "end" "up" "holding" | "ends" "up" "holding"
    | ("end" | "ends" | "finish" | "finishes") "shift" "with" | "finish" "with" | "finishes" "with"
    | "be" "filled" "with" | "be" "loaded" "with" | "hold" "onto" | "be" "holding" | "is" "holding"
    | "end" "with" | "want" | "wants" | "be" "left" "with" | "be" ("sitting" | "standing")? "at" | "is" "at" | "are" "at"
putv: "put" | PLACE_VERB | "store" | "stock" | "set" | "leave" | "get" | "keep" | "park"
    | "make" "sure" "there" ("is" | "are") | "ensure" "there" ("is" | "are")
addv: "add" | "bring" | "deliver" | "send" | "ship" | "move" | "transfer" | "carry" | "shift" | "throw" | "toss"
    | "load" | "drop" | "stick" | "pop" | "stack"
    | "relocate" | "take" | "haul" | "bring" "over" | "move" "over" | "send" "over"
    | "supply" | "drop" "off" | "get" | "push" | "cart" | "ferry" | "tow" | "lug" | "shuttle" | "wheel"
    | "grab" | "run" | "pull" | "return" | "dump" | "fetch" | "dispatch"
    | "stage" | "gather" | "consolidate" | "collect" | "restage" | "pass"
removev: "remove" | "take" | "unload" | "pull" | "push" | "withdraw" | "clear" | "get" | "move"
       | "get" "rid" "of" | "dispose" "of" | "throw" "out" | "take" "away" | "knock" | "grab" | "send" | "ship"
splitv: "split" | "divide" | "distribute" | "share" | "spread" | "spread" "out" | "share" "out"
among: "between" | "among" | "amongst" | "across" | "over"
even: "evenly" | "equally" | "equal" | "fairly" | "in" "equal" ("parts" | "shares") | ","? "same" "amount" "each"
    | ","? "same" "number" "each" | ","? "equal" ("amounts" | "shares" | "parts")
want: ("i" | "we") ("want" | "would" "like" | "like" | "need" | "wish") | "id" "like" | "wed" "like"
    | "give" | "make"
    | "make" "it" "so" that? | "make" "sure" that? | "ensure" that? | "let" | "have" | "get"
    | "i" "want" "it" "so" that?
that: "that"
there_be: ("there" | "theyre" | "their" | "theres") (modal? "be" | "is" | "are") | "make" "it"
        | "theres" | ("we" | "i") modal? ("need" | "want" | "require" | "needs") | "need"
// "9 bags should come to staging": where they go, seen from there
go: "go" | "goes" | "come" | "comes" | "move" | "moves" | "be" "moved" | "be" "sent" | "be" "taken" | "be" "brought"
  | "be" "transferred" | "be" "shipped" | "be" "relocated" | "be" "carried" | "be" "delivered"
  | "end" "up" | "travel" | "be" "put" | "moved" | "sent" | "taken" | "brought" | "delivered" | "shifted"
// "take 4 wallets out the cage": "out" alone says from, as "out of" does
from: "from" | "out" "of" | "out" | "off" | "off" "of"
moving: "moving" | "moved" | "shifting" | "shifted" | "taking" | "taken" | "bringing" | "brought" | "sending" | "sent"
to: "to" | "into" | "onto" | "over" "to"

// ---------------------------------------------------------------- goal statements
goal: there_be items loc                                  -> g_set
    | there_be items loc "and"? "nothing" "else"          -> g_set_only
    | ("there" | "theres") ("shouldnt" | "mustnt" | "cant" | "wont" | modal ("not" | "never")) "be" any_items left? loc -> g_set
    | "leave" places "with" items                          -> g_place_set
    | there_be items left loc                             -> g_set
    | items modal? stay? loc                              -> g_set
    | items left loc                                      -> g_set
    | loc ","? there_be? items                            -> g_loc_set
    | both? places modal? each? setv each? items left? resumptive? -> g_place_set
    | both? places modal? setv items ("each" | "apiece") left? -> g_place_set
    | both? places modal? "each" be? items                  -> g_place_set
    | places ("both" | "each") modal? setv items              -> g_place_set
    | places (":" | ",") items resumptive                  -> g_place_set
    | places (":" | ",") items                             -> g_place_set
    | places crowded ("on" ihead)?                         -> g_complaint
    | places (":" | ",") items ("each" | "apiece") final?  -> g_place_set
    | places (":" | ",") items final                       -> g_place_set
    | places ":" ("add" | "plus") items                     -> g_add_place
    | places ("needs" | "need" | "wants") ("emptying" | "clearing" "out"? | "emptying" "out") ("into" | "onto" | "to") places -> g_empty_into
    | places ("needs" | "need" | "wants") ("emptying" | "clearing" "out"? | "emptying" "out") -> g_empty
    | ("no" | "zero") ihead (lsep ihead)* ("anywhere" | "elsewhere") except_pl -> g_none_except
    | "nothing" "but" ihead (lsep ihead)* loc                -> g_nothing_but
    | places (":" | ",") inum (lsep inum)*                 -> g_place_inum
    | places modal? setv items "respectively"               -> g_place_set_resp
    | places "to" setv items                                -> g_place_set
    // "canopy to 8 trays, dock 1 to 4": a place brought to a count, said without a verb
    | places "to" items                                     -> g_place_set
    | putv items loc                                       -> g_set
    | putv items "each" loc                                -> g_set
    | want places "to"? setv items resumptive?              -> g_place_set
    | "set" places "to" items                               -> g_place_set
    | "set" ihead loc "to" NUM                              -> g_item_first
    | ihead loc? ":" NUM loc?                               -> g_item_first
    | ihead loc? modal? be equal? NUM loc?                  -> g_item_first
    | ("make" | "have") ihead loc? ("equal" "to" | "be" | "equal" | "total") NUM loc? -> g_item_first
    | refill places ("so" that? | "until") ("it" | "they") setv items -> g_place_set
    | refill places "to" items                                -> g_place_set
    | ("bring" | "take" | "top" "up" | "top" | "raise" | "fill" | "get" | "lower" | "cut" | "bump" | "drop" | "knock"
       | "push" | "boost" | "pull" | "run") places ("up" | "down")? "to" items -> g_place_set
    // "picking needs topping up to 10 chains", "the cage wants bringing down to 4 packs"
    | places ("needs" | "need" | "wants" | "want") ("topping" | "bringing" | "filling" | "taking" | "getting"
       | "bumping") ("up" | "down")? "to" items -> g_place_set
    | ("can" | "could") places setv items                   -> g_place_set
    | emptyv pitems ("into" | "onto" | "to") places          -> g_transfer_src
    | want items go from places to places                   -> g_transfer
    | want items go to places from places                   -> g_transfer
    | places modal? each? ("get" | "come" | "go" | "drop" | "fall" | "rise" | "climb") ("up" | "down")? "to" items -> g_place_set
    | places modal? "be" "down" "to" items                   -> g_place_set
    | places modal? "only" setv items resumptive?          -> g_place_set
    | places modal? setv "only" items resumptive?          -> g_place_set
    | pitems modal? go to places appos?                    -> g_transfer_src
    | want items loc                                       -> g_set
    | (places ":")? ("increase" | "raise" | "up" | "bump" "up" | "boost") ihead loc? "by" NUM -> g_raise
    | (places ":")? ("decrease" | "lower" | "reduce" | "cut" | "drop") ihead loc? "by" NUM -> g_lower
    | want places ("to" "be")? "at" items                     -> g_place_set
    | "give" places items                                     -> g_place_set
    | "give" places items "each"                              -> g_place_set
    | places place_appos modal? setv items                    -> g_place_set
    | addv bare src appos? adv? to places                   -> g_transfer_src
    | removev bare src                                     -> g_remove_src
    | splitv bare src even? among places even?              -> g_split_src
    | addv items to places each?                             -> g_add
    // "Dock needs 6 ackee added": the count added to it
    | places modal? ("needs" | "need" | "wants" | "want" | "gets" | "get") items ("added" | "adding") -> g_add
    | addv items loc                                      -> g_add
    | refill places "with" items from places               -> g_refill_from
    | refill places "with" items                           -> g_add_place
    | addv items adv? from places adv? to places           -> g_transfer
    | addv items from places ("and" | "," "and"?) to places -> g_transfer
    | to places from places ","? items                      -> g_transfer
    | from? places to places (":" | ",") items             -> g_transfer
    | addv items places adv? to places                     -> g_transfer
    | addv items "each" to places                          -> g_add
    | addv items ("with" | "using") robots adv? from places adv? to places -> g_transfer_with
    | addv items src adv? to places                       -> g_transfer_src
    | addv pitems adv? to places                          -> g_transfer_src
    | putv pitems loc                                     -> g_transfer_src
    | putv items from places loc                           -> g_transfer_src
    | items ("to" | "into" | "onto") places from places     -> g_transfer
    | emptyv places ("into" | "onto" | "to") places         -> g_empty_into
    | places bneg above NUM of? ihead                        -> g_ceiling
    | ("make" "sure" | "ensure") that? places bneg above NUM of? ihead -> g_ceiling
    | ("dont" | "do" "not" | "never") "let" places above NUM of? ihead -> g_ceiling
    | ("dont" | "do" "not" | "never") ("leave" | "keep" | "store" | "have") ("more" "than" | "over" | "above") NUM of? ihead loc -> g_ceiling
    | items src modal? go to places                       -> g_transfer_src
    | places ("gets" | "receives" | "takes" | "should" "get" | "should" "receive") items from places -> g_receive
    | places modal? setv items from places                  -> g_receive
    | emptyv places except_items                            -> g_empty_except
    | addv "everything" from places to places except_items  -> g_transfer_except_items
    | removev items src                                   -> g_remove_src
    | removev items ("away" | "out" | "off") src           -> g_remove_src
    | ("get" | "have") items go from places to places       -> g_transfer
    | want places "to"? "be"? emptied                      -> g_empty
    | want places ("holding" | "having" | "with") items       -> g_place_set
    | "nothing" modal? ("leaves" | "leave" | go "out" "of" | "be" "taken" "from" | "be" "removed" "from" | "comes" "off" | "come" "off") places -> g_keep
    // "nobody touches rack 3", "rack 3 nobody touches tonight": it stays as it is
    | ("nobody" | "noone" | "no" "one") modal? ("touches" | "touch") places -> g_keep
    | places ","? ("nobody" | "noone" | "no" "one") modal? ("touches" | "touch") -> g_keep
    | ("reduce" | "lower" | "cut" | "drop" | "increase" | "raise" | "bring" | "take" | "get") ihead loc ("down" | "up")? "to" NUM -> g_item_first
    | ("bring" | "take" | "get" | "knock") ihead loc ("down" | "up") "by" NUM -> g_updown
    | ("bring" | "take" | "get" | "cut" | "lower") ihead "there" ("up" | "down")? "to" NUM -> g_item_there
    | posplace ihead (":" | ",")? ("make" | "set") ("it" | "them" | "that") ("to" | "at")? NUM -> g_poss_make
    | removev pitems ("out" | "away" | "off")?             -> g_remove_src
    | places modal? setv items "too" "many"                  -> g_too_many
    // "bunker has 4 malt too many, pull them off": the removal said again
    | places modal? setv items "too" "many" ","? ("so" | "and")? removev ("them" | "those" | "it") ("off" | "out" | "away")? -> g_too_many
    | places place_appos? modal? "lose" items                -> g_lose
    | places ("is" | "are") ("short" ("by" | "of")? items | items "short" | "missing" items)  -> g_short
    | places ("is" | "are") ("over" "by" items | items "over")            -> g_too_many
    | ("cut" | "reduce") (ihead loc | pitem_plain) "down"? ("by" (frac | "half" | NUM) | "in" "half")  -> g_cut
    | ("cut" | "reduce") ("them" | "it" | "those") "down"? ("by" (frac | "half" | NUM) | "in" "half")  -> g_cut_pronoun
    | refill places "with" ihead ("until" ("it" | "they") ("is" | "are") "full" | "to" ("capacity" | "top")) -> g_fill
    | ("keep" | "hold") places ("to" | "at")? items           -> g_place_set
    | places bneg below NUM of? ihead                        -> g_floor
    // the place and the item said first, what to do with them after ("OB connector max 4 only",
    // "kitting resistor cannot lower than 5", "dock 2 bolts take away 3", "bay 1 nuts add 2")
    | posplace ihead ":"? (upper NUM | NUM ("max" | "maximum" | "tops")) "only"? -> g_poss_ceiling
    | posplace ihead ":"? (lower NUM | NUM ("min" | "minimum"))              -> g_poss_floor
    | posplace ihead bneg (below | ("be" | "go" | "get" | "drop" | "fall")? (("lower" | "less" | "fewer") "than" | "below" | "under")) NUM -> g_poss_floor
    | posplace ihead bneg (above | ("be" | "go" | "get")? (("higher" | "more") "than" | "above" | "over")) NUM -> g_poss_ceiling
    | posplace ihead ":"? ("remove" | "take" "away" | "take" "out" | "take" "off" | "minus" | "less") NUM -> g_poss_fewer
    | posplace ihead ":"? ("add" | "plus" | "add" "another") NUM more?        -> g_poss_more
    | places "never" never_has? ("under" | "below" | ("fewer" | "less") "than") NUM of? ihead -> g_floor
    | places "never" never_has? ("over" | "above" | "more" "than") NUM of? ihead -> g_ceiling
    | ("make" "sure" | "ensure") that? places bneg below NUM of? ihead -> g_floor
    | ("dont" | "do" "not" | "never") "let" places below NUM of? ihead -> g_floor
    | places modal? setv items ","? on_top                  -> g_add_place
    | "give" places items ","? on_top                        -> g_add_place
    | ("can" | "could") places setv items ","? on_top        -> g_add_place
    | addv items to places ","? on_top                       -> g_add
    | ("dont" | "do" "not" | "never") ("touch" | "move" | "take") ("any" | "anything")? ihead loc? -> g_keep_item
    | ("dont" | "do" "not") emptyv places                    -> g_noop
    | ("dont" | "do" "not" | "never") (putv | addv | "send" | "bring") ("any" | "anything" | "them" | "it" | ihead | "any" "of" ("it" | "them" | "that" | "those"))? loc -> g_no_inflow
    | ("none" "of" ("them" | "it") | "none") modal? go loc  -> g_no_inflow
    | swapv ("what" | "contents" "of" | "loads" "of" | "stock" "of" | "everything" ("on" | "in" | "between" | "of") | "between")? places ("hold" | "have" | "contain" | "holds" | "has")? -> g_swap
    | swapv ("round" | "around" | "over")? ("what" "is"? ("on" | "in" | "at") | "everything" ("on" | "in" | "between" | "of")) places -> g_swap
    | swapv ihead (lsep ihead)* ("between" | "of" | "on" | "in" | "at") places -> g_swap_items
    | swapv ("over" | "round" | "around")? ihead (lsep ihead)* ("round" | "around" | "over")? ("between" | "of" | "on" | "in" | "at") places ("round" | "around" | "over")? -> g_swap_items
    | swapv ihead loc "with" (ihead | "ones" | "those")? loc -> g_swap_two
    | places modal? ("swap" | "trade" | "exchange") (("their" | "its") | "what" "they" ("hold" | "have"))? swapwhat -> g_swap_subj
    | swapv ("what" | "contents" "of" | "loads" "of" | "stock" "of")? places ("around" | "round" | "over") -> g_swap
    // "I want the mezz and the counter swapped (round)"
    | want places ("to"? "be")? ("swapped" | "switched" | "exchanged") ("around" | "round" | "over")? ("," ("everything" | "all"))? -> g_swap
    // "Swap aisle 5 and aisle 6 round, everything on them": the whole contents, said again
    | swapv ("whole" | "whole" "contents" "of")? places ("around" | "round" | "over")? ","? ("everything" | "all") ("on" | "in" | "of") ("them" | "both") -> g_swap
    // "swap P with Q (, everything on them)": the two places' contents
    | swapv ("what" | "contents" "of" | "stock" "of")? places "with" places (","? ("everything" | "all") ("on" | "in" | "of") ("them" | "both"))? -> g_swap
    | splitv items src even? among places even?              -> g_split_src
    | splitv pitems even? among places even?                 -> g_split_src
    | addv items adv? to places from places                -> g_transfer
    | addv items to places ","? except_places              -> g_transfer_except
    | addv items to places ","? except_count               -> g_transfer_except_count
    | addv items except_count to places                    -> g_transfer_except_count
    | putv items loc ","? except_count                     -> g_transfer_except_count
    | items modal? go? to places ","? except_places        -> g_transfer_except
    | items modal? go to places                            -> g_add
    | items to places                                      -> g_add
    | ("can" | "could" | "would") items go to places       -> g_add
    | addv items except_places to places                   -> g_transfer_except
    | items ("on" | "in" | "at" | "from") places modal? go to places -> g_transfer
    | items from places modal? go? adv? to places           -> g_transfer
    // said without "from": "3 satchels top rack to despatch"
    | items places to places                                -> g_transfer
    | items "," "from"? places to places                    -> g_transfer
    | items modal? go from places to places                 -> g_transfer
    // "Need 2 lawn feed moving from dock 1 to dock 2", "we want 3 X taking to P from Q"
    | (("i" | "we")? ("need" | "want") | "needs" | "wants") items moving from places to places -> g_transfer
    | (("i" | "we")? ("need" | "want") | "needs" | "wants") items moving to places from places -> g_transfer
    | bare src modal? go to places                          -> g_transfer_src
    | removev items from places                            -> g_remove
    | removev items ("off" | "out")                        -> g_remove_complained
    | removev "everything" from places                      -> g_empty
    | mult "up"? ihead loc                                 -> g_mult
    | (putv | addv) ("them" | "it" | "those" | "these" | "all" "of" "them") adv? loc -> g_pronoun_dest
    | ("clear" | "empty" | "clean") places "right"? ("out" | "off")  -> g_empty
    | places ("shouldnt" | "mustnt" | "cant" | "cannot" | "wont" | modal ("not" | "never")) setv ("more" "than" | "over" | "above") NUM of? ihead resumptive? -> g_ceiling
    | places ("shouldnt" | "mustnt" | "cant" | "cannot" | "wont" | modal ("not" | "never")) setv ("fewer" "than" | "less" "than" | "under" | "below") NUM of? ihead resumptive? -> g_floor
    | places modal? "keep" "only"? items                     -> g_keep_part
    // "P keeps its X as it is": said of the place, in the third person too
    | places modal? _keeps its NUM? ihead (lsep its? NUM? ihead)* as_is? -> g_keep_its
    | emptyv places                                        -> g_empty
    | places modal? be? emptied                            -> g_empty
    | places modal? "hold" "nothing"                        -> g_empty
    // "nothing should remain on P", "nothing (is) to be left in P": P holds nothing at the end
    | "nothing" (modal | "is" "to" | "to")? ("remain" | "remains" | "be" "left" | "stay" | "stays") ("on" | "in" | "at") places -> g_empty
    | places (modal ("not" | "never") | "shouldnt" | "mustnt" | "cant" | "cannot") ("have" | "hold" | "contain" | "keep") ("any" | "anything")? ihead (lsep ihead)* left? -> g_none_of
    | emptyv ihead from places                              -> g_empty_item
    | emptyv pitem_plain                                     -> g_empty_item
    | emptyv places "of" its? ihead                          -> g_empty_item
    | ("i" | "we") ("dont" | "do" "not") ("want" | "need") ("any" | "anything")? ihead (lsep ihead)* left? loc -> g_none_in
    | places modal? be "full" "of" only? ihead only?         -> g_fill
    | places modal? "be" "filled" "up"? "with" only? ihead only? -> g_fill
    | "fill" places "up"? "with" only? ihead only? as_far?   -> g_fill
    | ("fill" "up"? | "top" "up" | "pack") "rest" "of" places "up"? "with" only? ihead only? -> g_fill
    | "fill" places ("up" | "to" ("top" | "capacity" | "brim")) "with" only? ihead only? -> g_fill
    | "fill" places "up"? "with" "nothing" "but" ihead       -> g_fill
    | modal? be "full" "of" only? ihead                      -> g_fill_elided
    | "nothing" "else"                                     -> g_nothing_else
    | "nothing" "else" loc                                  -> g_nothing_else
    | "nothing" modal? go loc                               -> g_no_inflow
    | "nothing" ("goes" | "comes" | "is" "added" | "gets" "added" | "should" "be" "added" | "may" "go" | "can" "go") loc -> g_no_inflow
    | ("add" | "put" | "bring" | "move") "nothing" loc      -> g_no_inflow
    | ("leave" | "keep") posplace ihead as_is               -> g_keep
    | "leave" ihead loc as_is                               -> g_keep
    | ("leave" | "keep") places as_is                       -> g_keep
    | ("dont" | "do" "not") "touch" places                  -> g_keep
    // "dont touch anything at P": P kept as it is
    | ("dont" | "do" "not" | "never") ("touch" | "move") "anything" ("at" | "on" | "in" | "from") places -> g_keep
    | ("dont" | "do" "not" | "never") ("take" | "remove" | "move" | "pull") ("anything" | "any" ihead) ("off" | "from" | "out" "of") places -> g_keep
    | places modal? ("stay" | "stays" | "remain" | "remains" | "be" "left") as_is  -> g_keep
    | places modal? ("stay" | "stays" | "remain" | "remains") "put" -> g_keep
    | ihead loc modal? ("stay" | "stays" | "remain" | "remains") ("put" | as_is) -> g_keep
    | posplace ihead modal? ("stay" | "stays" | "remain" | "remains") ("put" | as_is) -> g_keep
    | ihead (lsep ihead)* modal? ("stay" | "stays" | "remain" | "remains") ("put" | as_is) -> g_keep_its_elided
    | places modal? ("use" | "do" "with") items ","? on_top   -> g_add_place
    // "the fuse room could take another 2 packs": room for more, said of the place
    | places ("could" | "can" | "will") "take" ("another" | "an" "extra") items -> g_add_place
    | places modal? ("use" | "do" "with") items              -> g_could_use
    | ("top" ("up" | "off") | "fill" "up") places "with" only? ihead only? -> g_fill
    | (putv | addv) items loc on_top                         -> g_add
    | mult "up"? posplace ihead                              -> g_mult
    | mult ("them" | "it" | "those")                        -> g_mult_pronoun
    | ("lose" | "remove" | "take" "away" | "take" "off" | "get" "rid" "of") (frac | "half" | NUM) "of" ("them" | "those" | "it") -> g_cut_pronoun
    | places ("is" | "are") ("light" | "low" | "short" | "running" "low") "on" ihead ","? ("add" | "bring" | "send") NUM more? -> g_light_add
    | ("pack" | "load" | "stock" | "fill") places "up"? "full" "of" only? ihead only? -> g_fill
    | ("cap" | "limit") places ("at" | "to") NUM of? ihead    -> g_ceiling
    | ("keep" | "hold") pitem_plain ("somewhere" | "anywhere")? "between" NUM ("and" | "to") NUM -> g_poss_bound
    | ("keep" | "hold") pitem_plain (lower | upper) NUM       -> g_poss_bound
    | pitem_plain ":"? lower NUM ","? ("and" | "but")? upper NUM -> g_poss_bound
    | places modal? "match" posplace ihead ("count" | "number" | "level" | "total")? -> g_match
    | places place_appos? modal? ("give" | "pass" | "hand" "over" | "hand") items ("to" | "over" "to") places -> g_give
    | ("bring" | "take" | "get" | "cut" | "reduce" | "lower" | "raise" | "increase" | "drop") pitem_plain ("down" | "up")? "to" NUM -> g_item_first
    // "east bench's pots should come down to 1", "the pots on east bench should go up to 5"
    | pitem_plain modal? ("come" | "go" | "get") ("down" | "up") "to" NUM -> g_item_first
    | ihead loc modal? ("come" | "go" | "get") ("down" | "up") "to" NUM -> g_item_first
    // said without a verb: "belts on despatch down to 1" ("up to N" alone is a bound, so not here)
    | (pitem_plain | ihead loc) "down" "to" NUM              -> g_item_first
    // "cider on pick face to 6", "pick face cider to 6": the count it should come to, without a verb
    | (pitem_plain | ihead loc) "to" NUM                     -> g_item_first
    | ("leave" | "keep") its ihead (lsep ihead)* as_is?        -> g_keep_its_elided
    | ("make" | "set" | "bring" | "get" | "have") posplace ihead ("count" | "number" | "level" | "stock" | "total")? ("equal" "to" | "to" | "same" "as" | "match" | "equal") posplace ihead? -> g_equal_poss
    | putv "as" "many" ihead loc "as" ("there" ("are" | "is") | "sit" | "are") ("on" | "in" | "at") PLACE ((lsep) PLACE)* together? -> g_as_many_there
    | ("have" | "let" | "make") places ("swap" | "trade" | "exchange") (("their" | "its") | "what" "they" ("hold" | "have"))? swapwhat -> g_swap_subj
    | swapv ("what" | "contents" "of")? places ("hold" | "have" | "contain" | "holds" | "has")? -> g_swap
    | swapv ihead (lsep ihead)* ("between" | "of" | "on") places -> g_swap_items
    | swapv posplace ihead "with" (posplace | places)       -> g_swap_poss
    | swapv ("everything" | "what" "is" | "contents" | "stock" | "what" "sits") ("on" | "in" | "at" | "of") places "with" ("everything" | "what" "is" | "whatever" "is"? | "contents" | "stock" | "what" "sits" | "that" | "those")? ("on" | "in" | "at" | "of")? places -> g_swap
    | swapv posplace "and" posplace ihead                  -> g_swap_poss
    | splitv items? even? among places even?                -> g_split
    | splitv bare even? among places even?                  -> g_split
    | splitv ("them" | "those" | "these" | "it" | "all" "of" "them") even? among places even? -> g_split_pronoun
    | "put" items even? among places even?                  -> g_split

// "must not go above 3", "never drops under 2", "doesn't exceed 5": a ceiling or a floor
// "dock never has less than 15 X": what a place holds, said in the present
never_has: "has" | "holds" | "gets" | "contains" | "keeps"
bneg: modal? ("not" | "never") | "shouldnt" | "mustnt" | "cant" | "cannot" | "doesnt" | "does" "not"
    | "wont" | "will" "not" | "never"
above: ("go" | "goes" | "get" | "gets" | "rise" | "rises" | "climb" | "climbs") ("above" | "over" | "past" | "beyond")
     | "exceed" | "exceeds"
below: ("go" | "goes" | "get" | "gets" | "drop" | "drops" | "fall" | "falls" | "dip" | "dips" | "sink" | "sinks") ("below" | "under" | "beneath")
on_top: ("on" "top" "of" | "in" "addition" "to" | "besides" | "over" "and" "above") "what" (("it" | "they") ("has" | "have" | "holds" | "hold" | "is" "got" | "has" "got" | "have" "got" | "s" "got") now? | ("is" | "s") "already"? "there")
adv: "over" | "back" | "across" | "along" | "out"
src: ("in" | "on" | "at" | "from" | "off" | "out" "of" | "out" | "of") places
pitems: frac of? posplace ihead appos?                     -> pi_frac
      | "half" of? posplace ihead appos?                   -> pi_frac
      | NUM of? posplace ihead appos?                      -> pi_count
      | posplace NUM ihead appos?                          -> pi_count
      | ("all" of?)? posplace ihead appos?                 -> pi_all
      | ("all" of?)? "its" ihead                           -> pi_all
pitem_plain: posplace ihead
place_appos: "," ("which" | "that" | "it" | "they") ("has" | "have" | "holds" | "hold" | "already" "has") items now? ","
           | "," ("with" | "holding" | "having") its? items now? ","
appos: ","? ("all" | "both") (NUM ("of" ("them" | "it"))? | "of" ("them" | "it")) ","?
     | "," "both" ","                                   // "P's X, both, to Q": the two there
swapwhat: ihead (lsep ihead)* | "everything" ("they" ("hold" | "have"))? | "contents" | "loads" | "stock" | "places" | "goods" | "items"
stay: be | "be" "left" | "remain" | "be" "kept" | "sit" | "stay" | "lie" | "go" | "be" "placed" | "be" "stored" | "belong" | "end" "up"
both: "both"
together: "together" | "combined" | "put" "together" | "between" "them" | "in" "total" | "altogether"
left: "left" | "remaining" | "left" "over" | "in" "total" | "total" | "in" "all"
only: "only"
equal: "equal" "to" | "at"
refill: "restock" | "refill" | "replenish" | "top" "up" | "top" "off" | "supply" | "load" "up" | "stock" "up"
mult: "double" | "triple" | "quadruple" | "halve"
swapv: "swap" | "trade" | "exchange" | "switch" | "interchange"
emptyv: "empty" | "clear" | "clean" "out" | "clear" "out" | "empty" "out"
emptied: "empty" | "emptied" | "cleared" | "clear" | "vacant" | "cleaned" "out" | "emptied" "out" | "cleared" "out"
// "fill P up with X (as) far as it'll go / as much as it takes / as much as will fit": to capacity
as_far: ","? ("as"? "far" "as" (("it" | "they") ("will" | "can")? | "itll" | "theyll") ("go" | "goes")
        | "as" "much" "as" ("it" "takes" | "will" "fit" | "fits" | "it" ("will" | "can") "take" | "it" "holds")
        // "fill P with X up to the top", "... until top", "... to the brim", "... till full"
        | "up"? ("to" | "until" | "till") ("top" | "brim" | "capacity" | "full" | "it" ("is" | "s") "full"))
as_is: "where" ("it" | "they") ("is" | "are") | ("as" | "how") ("it" | "they") ("is" | "are") | "alone" | "as" "is" | "be"
     | "unchanged" | "untouched"
     | "untouched" | "unchanged" | "as" "is" | "way" ("it" | "they") ("is" | "are" | "was" | "were") | "as" ("it" | "they") ("was" | "were")

except_places: ("except" | "but" "not" | "apart" "from" | "other" "than" | "excluding" | "not") except_what? ("up" | "down" | "over" | "out")? ("on" | "in" | "at" | "from") places
             | ("except" | "but" "not" | "excluding" | "not") from places
// "P is overstocked on X", "P's getting a bit crowded", "P is looking bare": a complaint, no count
crowded: crowdbe crowdhow? crowdstate "already"?
       // "bay one getting too full", "bay one too full already": "is" left out, as said in Fiji,
       // Singapore and Nigerian English
       | "getting"? crowdhow crowdstate "already"?
crowdbe: "is" | "s" | "looks" | "is" "looking" | "s" "looking" | "is" "getting" | "s" "getting"
crowdhow: "too" | "a" "bit" | "very" | "rather" | "quite" | "really" | "way"
crowdstate: "overstocked" | "full" | "crowded" | "cramped" | "packed" | "rammed" | "overloaded" | "bare"
          | "understocked" | "overflowing"
anywhere: ("wherever" | "anywhere") ("you" "like" | "it" "fits" | "they" "fit")?
// ", final count": the count is what the place ends with (no addition)
final: ","? "final" ("count" | "total" | "figure" | "number")
// "P should have 3 X on it": the pronoun is P itself
resumptive: ("on" | "in" | "at" | "inside") ("it" | "them" | "there") left?
except_count: ("except" "for"? | "but" | "apart" "from" | "other" "than" | "excluding" | "leaving") ("one" | NUM) ("of" "them")? ("on" | "in" | "at") places
except_what: "ones" | "those" | "them" | ("what" | "whatever") "is" | "any" | "what" "sits" | "what" "lies" | "ones" "that" ("are" | "sit" | "lie")
           | ("what" | "whatever") ("is" | "s") ("sitting" | "lying" | "left" | "stored" | "kept")

// ---------------------------------------------------------------- ellipsis tails
tail: places ("too" | "as" "well" | "also" | "same" "same"?) -> t_too
    | ("not" | "instead" "of" | "rather" "than") NUM       -> t_noop
    | "not" ("to" | "into" | "onto") places                 -> t_not_to
    | ("not" | "nothing" | "none" ("of" ("them" | "it" | "those" | "these"))?) (modal? ("come" | "comes"))? ("from" | "out" "of" | "off") places -> t_not_from
    | items from places                                  -> t_from
    | "so" ("does" | "do" | "should" | "must" | "will") places -> t_too
    | places "with"? items                               -> t_gap
    | ("rest" | "others" | "extras" | "extra" | "excess" | "surplus" | "remainder") rest_of? to places -> t_rest
    | "same" ("off" | "from" | "out" "of" | "to" | "on" | "in" | "at" | "for" | "into" | "onto") places -> t_same
    | ("they" | "it" | "those" | "these") ("can" | "may" | "could")? ("go" | "goes") anywhere -> t_anywhere
    | "not" ihead (lsep ihead)*                           -> t_not_items
    | ("also" | "same" "for" | "same" "thing" "for") places   -> t_too
    | NUM fewer loc                                      -> t_elided_fewer
    | items ("other" "way" ("round" | "around")? | "in" "other" "direction" | "in" "reverse" | "back") -> t_reverse
    | ("taking" | "take" | "taken" | "brought" | "coming") ("them" | "it" | "those" | "these" | "all" | "everything")? from places -> t_source
    | ("all" | "both" | "each")? from places               -> t_source

// ---------------------------------------------------------------- robots and rules
robots: robot (rlsep (robot | rnum))*
      | rgroup
robot: ROBOTWORD? ROBOT                                   -> r_name
     | ROBOTWORD? ROBOT ("to" | "through" | "thru" | "till") NUM -> r_range
     | ROBOTWORD? ROBOT ("to" | "through" | "thru" | "till") ROBOTWORD? ROBOT -> r_name_range
     | ROBOTWORD NUM                                      -> r_number
rnum: NUM                                                 -> r_number
rgroup: (all | "a" | "an" | "any")? (RKIND | RTAG)        -> r_kind
      | all? ROBOTWORD ("tagged" | "labelled" | "labeled" | "marked") (RTAG | RKIND) -> r_kind
      // "robots of night_shift" (Spanish and Portuguese "robôs do turno"): the tag's robots
      | all? ROBOTWORD ("of" | "from") (RTAG | RKIND)      -> r_kind
      // "robots with a cage pass", "robots that have a cold rating": a tag they carry
      | all? ROBOTWORD ("with" | ("that" | "who") ("have" | "hold" | "carry")) ("a" | "an")? RTAG -> r_kind
      | all? (RTAG | RKIND) (ROBOTWORD | "ones")           -> r_kind
      | all? (RTAG | RKIND) ("shift" | "crew" | "team" | "squad") ROBOTWORD? -> r_kind
      | all? ROBOTWORD ("that" | "who")? able? skillv NUM ("or" "more" | "or" "above" | "plus") -> r_skill_min
      | all? ROBOTWORD ("that" | "who") able? skillv ("at" "least" | "no" "less" "than" | "no" "fewer" "than") NUM -> r_skill_min
      | all? ROBOTWORD ("that" | "who") able? skillv NUM "or" ("less" | "fewer" | "below") -> r_skill_max
      | all? ROBOTWORD ("that" | "who") able? skillv ("at" "most" | "no" "more" "than") NUM -> r_skill_max
      | all? ROBOTWORD ("with" | "whose") skillv ("is" | "of")? ("at" "least" NUM | NUM ("or" "more" | "or" "above" | "plus")) -> r_skill_min
      | all? ROBOTWORD ("with" | "whose") skillv ("is" | "of")? ("at" "most" NUM | NUM "or" ("less" | "fewer" | "below")) -> r_skill_max
      | all? ROBOTWORD ("carrying" | "lifting" | "with" skillv | ("that" | "who") able? skillv | "whose" skillv "is") cmp per_trip? -> r_skill_cmp
      // "the weakest one": "one" is lexed as NUM; the reader takes it only when the word is "one"
      | SUPER (ROBOTWORD | NUM)?                           -> r_super
      | NUM "of" SUPER ROBOTWORD                           -> r_super
all: "all" | "any" | "every"
cmp: ("at" "least" | "no" "less" "than" | "no" "fewer" "than" | "not" "less" "than") NUM -> cmp_min
   | NUM ("or" "more" | "or" "above" | "plus" | "or" "higher")  -> cmp_min
   | ("more" | "greater" | "higher") "than" NUM                  -> cmp_above
   | ("less" | "fewer" | "lower") "than" NUM                      -> cmp_below
   | ("at" "most" | "no" "more" "than" | "not" "more" "than") NUM -> cmp_max
   | NUM "or" ("less" | "fewer" | "below" | "lower")             -> cmp_max
able: "can" | "may" | "could"   // "robots that could carry 4 or more": their skill, as "can" says it
per_trip: "at" "a" "time" | "per" "trip" | "a" "trip" | "in" "one" "go"
skillv: SKILL | "carry" | "carries" | "lift" | "lifts" | "move" | "moves" | "handle" | "handles"

rneg: "not" | "never" | "dont" | "doesnt" | "shouldnt" | "mustnt" | "cant" | "cannot" | "wont"
    | "isnt" | "arent" | "no" "longer"
rmodal: "should" | "must" | "shall" | "will" | "may" | "can" | "is" "to" | "are" "to" | "would"
      | "do" | "does" | "is" "allowed" "to" | "are" "allowed" "to" | "ought" "to"
      | ("allowed" | "permitted") "to"
oblig: "should" | "must" | "shall" | "will" | "is" "to" | "are" "to" | "has" "to" | "have" "to"
state: "broken" | "faulty" | "unavailable" | "offline" | "disabled" | "damaged" | "down"
     | "idle" | "unused" | "busy" | "charging" | "malfunctioning" | "out" "of" ("order" | "service")
     | "out-of-service" | "under" "maintenance" | "in" "maintenance" | "off" "limits" | "spare"
     | "not" "working" | "not" "available" | "excluded" | "off" | "parked" | "benched" | "resting"
     | "off" "duty" | "on" "break" | "not" "allowed" | "banned" | "forbidden" | "off" "this"? ("job" | "task")
     | "off" "this" NUM | "out" "of" "this" NUM | "out" "of" "this"? ("job" | "task" | "work") | "out" "of" "it"
     | ("down" | "out" | "off" | "in") "for" ("maintenance" | "repairs" | "repair" | "service" | "charging" | "inspection")
use: "use" | "used" | "using" | "employ" | "employed" | "assign" | "assigned" | "involve" | "involved"
   | "moving" | "carrying" | "handling" | "shifting"
   | "work" | "help" | "be" "used" | "be" "involved" | "be" "employed" | "be" "assigned" | "participate"
act: "move" | "moves" | "carry" | "carries" | "touch" | "touches" | "take" | "takes" | "deliver" | "send" | "sends"
   | "delivers" | "handle" | "handles" | "bring" | "brings" | "transport" | "transports" | "ship"
   | "put" | PLACE_VERB | "load" | "unload" | "work" "on" | "pick" "up" | "fetch" | "help" "with"
   | "be" "used" "to" act | "be" "used" "for" | use "to" act | "go" | "drive" | "serve" | "supply"
   | "stock" | "restock" | "remove"
useact: use | act

robj: ITEM ((lsep | "or" | "nor" | "," "or") ITEM)*       -> ro_items
    | ("anything" | "everything" | "any" ITEMWORD | ITEMWORD | "goods" | "stuff" | "things" | "stock" | "all" ITEMWORD) -> ro_any
    | ("it" | "them" | "that" | "those" | "these" | "this")  -> ro_pronoun
    | ("for" | "on") ITEM (lsep ITEM)*                      -> ro_items
    | "all" ITEM (lsep ITEM)*                               -> ro_items
    | "any" ITEM ((lsep | "or" | "nor" | "," "or") ITEM)*   -> ro_items
rwhere: from places                                    -> rw_from
      | from places to places                          -> rw_route
      | ("to" | "into" | "onto" | "towards" | "toward") places -> rw_to
      | ("to" | "into" | "onto") place ("or" place)+          -> rw_to
      | from place ("or" place)+                           -> rw_from
      | ("at" | "on" | "in" | "near") place ("or" place)+     -> rw_at
      | "to" (PLACEWORD | "location") "of" places        -> rw_to
      | ("at" | "on" | "in" | "near" | "around" | "by") places -> rw_at
      | "away" "from" places                               -> rw_at
      | ("anywhere" | "somewhere")? ("close" "to" | "next" "to") places -> rw_at
      | ("anywhere" | "somewhere") ("near" | "around" | "by") places -> rw_at
      | ("going" | "headed" | "heading" | "moving" | "bound") ("to" | "into" | "for") places -> rw_to
      | ("coming" | "leaving") from places                 -> rw_from
      | from NUM PLACEWORD "to" "another"                  -> rw_none
      | ("between" | "among") PLACEWORD                      -> rw_none
      | "for" ("that" | "this" | "it" | "them" | "those" | "job" | "task")  -> rw_pronoun
      | "for" ("that" | "this") ("move" | "transfer" | "trip" | "run")       -> rw_pronoun
      | "at" "all"                                         -> rw_all
      | "whatsoever"                                       -> rw_all
      | "ever"                                             -> rw_all
      | "for" ("anything" | "everything" | "any" ("job" | "task" | "work") | "this" ("job" | "task")) -> rw_all
      | "for" "whole" ("job" | "task" | "command" | "order" | "lot" | "thing") -> rw_all
      | "on" ("this" | "whole")? ("job" | "task")                          -> rw_all
      | ("on" | "for") "this" NUM                                           -> rw_all
rscope: robj? rwhere*

rule: robots rmodal? rneg rmodal? useact? rscope          -> rule_never
    | robots rmodal? rneg "be" use ("to" act?)? rscope       -> rule_never
    | robots ("is" | "are") rneg? state                      -> rule_state
    | robots rmodal? rneg ("enter" | "visit" | "approach" | "access" | "go" "near" | "go" "into" | "go" "to" | "come" "near") places -> rule_away
    | robots ("is" | "are") "only" ("ones" | NUM | ROBOTWORD | RKIND | RTAG) ("allowed" | "permitted") rwhere+ -> rule_only
    | robots modal? ("stay" | "stays" | "remain" | "remains") state -> rule_state
    // "robots that carry less than 3, stay off this job": the robots addressed sit the job out
    | robots ","? modal? ("stay" | "keep") ("off" | "out" "of" | "away" "from" | "clear" "of") "this" ("job" | "task" | "order" | NUM) -> rule_state
    | robots modal? ("sit" | "sits") ("this" (NUM | "job" | "task" | "round") | "it") "out" -> rule_state
    | ("dont" | "do" "not" | "never") act robots rscope       -> rule_never
    | ("use" | "employ") robots "only" rscope                 -> rule_only
    | "no" robots ("on" "this" (NUM | "job" | "task"))? rscope -> rule_never
    | "nothing" ("leaves" | "goes" "out" "of" | "comes" "off" | "comes" "out" "of" | "may" "leave" | "should" "leave") places ("on" | "by" | "with" | "using") robots -> rule_never_from
    | ("let" | "have") ("only" | "just")? robots act rscope -> rule_only
    | ("keep" | "leave") robots ("away" | "clear") from ITEM (lsep ITEM)* -> rule_away_items
    | ("keep" | "leave") robots "off" ITEM (lsep ITEM)*       -> rule_away_items
    | robots modal? ("stay" | "keep" | "stays" | "keeps") ("off" | "away" "from" | "clear" "of") ITEM (lsep ITEM)* -> rule_away_items
    // "the weakest robot must not go near rum (at all)": keeps off the product
    | robots (rmodal? rneg | ("arent" | "isnt" | ("are" | "is") "not") "to") ("go" "near" | "come" "near" | "approach") ITEM (lsep ITEM)* ("at" "all")? -> rule_away_items
    | robots ("is" | "are") state ","? ("so" | "and")? ("dont" | "do" "not") "use" ("it" | "them") -> rule_state
    | robots (("is" | "are") "not" | "isnt" | "arent") "to" "be" ("used" | "involved" | "employed" | "assigned") rscope -> rule_never
    // a notice, its "is" left out: "Queenie not to be used", "Only tuggers to be used"
    | robots "not" "to" "be" ("used" | "involved" | "employed" | "assigned") rscope -> rule_never
    // the robot said first, then "don't use" (Hong Kong and Singapore English: "fork 2 dun use")
    | robots ("dont" | "do" "not" | "no" | "cannot" | "cant") ("use" | "used" | "to" "use") rscope -> rule_never
    | ("only" | "just") robots "to" "be" ("used" | "involved" | "employed" | "assigned") rscope -> rule_only
    | robots (("is" | "are") "not" | "isnt" | "arent") "to" act rscope -> rule_never
    | robots modal? ("stay" | "keep" | "stays" | "keeps") ("away" | "clear") from places -> rule_away
    | robots modal? ("stay" | "keep" | "keeps" | "stays") ("off" | "out" "of") places -> rule_away
    | ("keep" | "leave") robots ("away" | "clear") from places -> rule_away
    | ("keep" | "leave") robots ("out" "of" | "off") places  -> rule_away
    | ("keep" | "leave") robots state                        -> rule_state
    | ("keep" | "leave") robots "out" "of" "this" "task"?     -> rule_state
    | ("dont" | "do" "not" | "never" | "avoid") ("use" | "using" | "involve" | "employ" | "assign") robots rscope -> rule_never
    | ("dont" | "do" "not" | "never") "let" robots act? rscope -> rule_never
    | ("exclude" | "skip" | "leave" "out" | "disable" | "ignore" | "bench" | "rest") robots rscope -> rule_never
    | ("keep" | "leave") robots "out" rscope                  -> rule_never
    | "without" ("using" | "help" "of" | "help" "from")? robots rscope -> rule_never
    | "not" ("with" | "by" | "using") robots rscope          -> rule_never
    | ("only" | "just") robots rmodal? useact? rscope        -> rule_only
    | "only" robots rmodal? "be" use ("to" act?)? rscope      -> rule_only
    | robots "only" rmodal? useact? rscope                   -> rule_only
    | robots rmodal? "only" useact rscope                    -> rule_only
    | ("we" | "you")? rmodal? "only" ("use" | "employ") robots ("to" act? | "for")? rscope -> rule_only
    | ("we" | "you")? rmodal? ("use" | "employ") "only" robots ("to" act? | "for")? rscope -> rule_only
    | ("using" | "with" | "by") ("only" | "just" | "exclusively") robots rscope -> rule_only
    | ("only" | "just") ("using" | "with" | "by") robots rscope -> rule_only
    | "use" ("any" | "every" | "all")? ROBOTWORD? ("except" | "but" | "other" "than" | "besides" | "apart" "from") robots rscope -> rule_never
    | (("any" | "all" | "every") ROBOTWORD? | "everyone" | "everybody" | "anyone" | "anybody") ("except" | "but" | "other" "than" | "besides" | "apart" "from") robots rmodal? useact? rscope -> rule_never
    | ("dont" | "do" "not") "use" ("any" | "a")? ROBOTWORD ("other" "than" | "except" | "besides" | "apart" "from" | "but") robots rscope -> rule_only
    | ("no" | "none" "of") ROBOTWORD ("except" | "but" | "other" "than" | "besides" | "apart" "from") robots rmodal? useact? rscope -> rule_only
    | "no" (RKIND | RTAG | ROBOTWORD) rmodal? useact? rscope   -> rule_never_group
    | ("nobody" | "no" NUM | "none") ("except" | "but" | "other" "than" | "besides") robots rmodal? useact? rscope -> rule_only
    | ("use" | "using" | "with" | "by" | "employ") robots ("to" act? | "for")? rscope -> rule_use
    | robots oblig act rscope                               -> rule_use
    | robots ("moves" | "carries" | "handles" | "takes" | "delivers" | "brings" | "does") rscope -> rule_use
    | ("all" | "every" | "any")? ROBOTWORD ("other" "than" | "except" | "besides" | "but" | "apart" "from") robots rmodal? rneg useact? rscope -> rule_only
    | ("all" | "every" | "any")? ROBOTWORD ("other" "than" | "except" | "besides" | "but" | "apart" "from") robots ("is" | "are" | modal? ("stay" | "be" | "remain")) state -> rule_only
    | ("except" | "apart" "from" | "other" "than" | "besides") robots ","? ("all" | "every")? ROBOTWORD? ("is" | "are" | modal? ("stay" | "be" | "remain")) state -> rule_only
    | ("except" | "apart" "from" | "other" "than" | "besides") robots ","? ("all" | "every" | "no")? ROBOTWORD? rmodal? rneg useact? rscope -> rule_only
    | robots oblig? "do" ("it" | "that" | "this" | "job" | "task" | "work") -> rule_do_it
    | ("let" | "have" | "get")? robots oblig? "do" ("all" "of" ("it" | "that" | "this" | "them") | "everything" | "whole" ("job" | "lot" | "thing")) -> rule_only
    | "only" robots (rmodal | oblig)? "do" ("it" | "that" | "this" | "job" | "task" | "work") -> rule_do_it
    // "Get the strongest robot on it: ...": on the job, the whole command (as "on this one");
    // "get R to do it" is "have R do it"
    | ("get" | "put") robots "on" ("it" | "this" (NUM | "job" | "task")?) -> rule_only
    | "get" robots "to" "do" ("it" | "this" | "that")         -> rule_do_it
    | robots ("is" | "are") "only" ("ones" | NUM | ROBOTWORD) ("allowed" "to" | "permitted" "to" | "that" ("may" | "can") | "who" ("may" | "can")) useact? rscope -> rule_only
    | robots ("can" | "may" | "could" | "might") act rscope  -> rule_permission

// "... to the counter forklifts only": a rule closing the sentence without a comma, for the whole
// command as "..., forklifts only" is
bare_only: robots ("only" | "alone")                        -> rule_only

// "Titan should put 5 kegs on outbound", "Titan, bring two kegs to outbound"
// "Ziggy, you should take 4 X ...": the robot addressed, then "you" (and what it is to do)
addressed: robots ("," | ":")? ("you" oblig? | oblig)? goal
         | ("can" | "could" | "would" | "will") robots goal
         // "Ruru, can you take 6 lamb ...": the robot addressed, then asked
         | robots ("," | ":") ("can" | "could" | "would" | "will") "you" goal
         | robots "," ("our" | "a" | "an" | "my")? (RKIND | RTAG) "," oblig? goal  -> addressed_appos
         | ("let" | "have" | "get" | "ask" | "tell") robots "to"? goal
scoped_goal: ("using" | "with" | "by") ("only" | "just")? robots ","? goal    -> scoped_only
           | ("use" | "employ") ("only" | "just")? robots ("to" | "for") goal    -> scoped_only
           | "use" ("any" | "all" | "every")? ROBOTWORD? ("except" | "but" | "other" "than" | "besides") robots "to" goal -> scoped_never_before
           | goal ("using" | "with" | "by") ("only" | "just")? robots           -> scoped_only_after
           | goal ("using" | "with" | "by") robots ("only" | "alone")             -> scoped_only_after
           | goal ("without" ("using" | "help" "of")? | "but" "not" "with" | "not" "using") robots -> scoped_never_after
           // "move 3 saddles to P, but not jacu", "..., not jacu though": the move without that robot
           | goal ","? "but"? "not" robots "though"?                 -> scoped_never_after

// the word "place" has a terminal of its own: written as a string it would be named PLACE by lark,
// the terminal of a world's place, and any place's name would then read as the verb ("rack A 4
// bolts to rack B" as "place 4 bolts to rack B", the first place dropped)
PLACE_VERB: "place"
%declare NUM ITEM ITEMWORD PLACE PLACEWORD ROBOT ROBOTWORD RKIND RTAG SKILL SUPER FRAC POSS UNKNOWN
"""


def _aside_only_words(grammar: str) -> frozenset[str]:
    """Words the grammar reads only as an aside or a sentence's lead ("morning", "tonight",
    "thanks", "guys"): said in a remark, they are no content of an order. Words that order what is
    said around them ("if", "before", "first", "once") are left out: they may open a condition."""
    rules: dict[str, set[str]] = {}
    rule = ""
    for line in grammar.splitlines():
        head = re.match(r"^\??([a-z_]+)(?:\.-?\d+)?\s*:", line)
        if head:
            rule = head.group(1)
        if rule and not line.strip().startswith("//"):
            for word in re.findall(r'"([a-z]+)"', line.split("->")[0]):
                rules.setdefault(word, set()).add(rule)
    return frozenset(w for w, used in rules.items() if used <= {"aside", "lead"}) - _ORDERING


#: aside words that may order what is said around them ("if possible", "before noon", "first")
_ORDERING = frozenset({"if", "before", "after", "first", "once", "finally", "additionally", "afterwards", "possible",
                       "plan", "us", "o", "clock"})
#: words the grammar reads only as an aside or a lead (:func:`_aside_only_words`)
ASIDE_ONLY = _aside_only_words(GRAMMAR)
#: the grammar's verbs of an order: the words of its verb rules, and the verbs that open an order
#: of their own ("fill", "double", "halve", "keep")
ORDER_VERBS = frozenset(w for line in GRAMMAR.splitlines()
                        if re.match(r"^(put|add|remove|split|swap|empty)v\s*:", line)
                        for w in re.findall(r'"([a-z]+)"', line) if w != "out") | {
    "fill", "double", "triple", "halve", "keep", "leave", "top", "give", "make", "get", "restock", "replenish"}

"""The words of household command English: what the parser's grammar is written over.

Two halves. The *world's* words (object, place and category names and their ``words``, with
plurals) come from the world file, so a new home needs no code. The *command* words below are
a small, closed lexicon: verbs that ask for a state, adjectives that name one, the function words
of the grammar, and the **state cues** of vague commands ("nobody is watching the TV" means the
TV may go off). Each word maps to a token class of the grammar (:mod:`pipflow.household.language.grammar`)
and, where it carries meaning, a value (a goal condition, a polarity). docs/household.md lists
them for users. A word in neither half is never skipped: the parser refuses and quotes it.
"""
from __future__ import annotations

import functools
import re

from pipflow.language.english import spoken_forms

#: verbs asking for a state (value: the goal condition); "open", "shut", "clean", "warm" have
#: classes of their own because they are adjectives too, or start a phrasal verb ("clean up")
STATE_VERBS = {
    "slice": "sliced", "cut": "sliced", "chop": "sliced", "dice": "sliced", "halve": "sliced",
    "wash": "clean", "rinse": "clean", "scrub": "clean", "wipe": "clean", "clean": "clean",
    "heat": "hot", "cook": "hot", "reheat": "hot", "microwave": "hot", "toast": "hot", "boil": "hot",
    "bake": "hot", "fry": "hot", "warm": "hot",
    "open": "open", "close": "closed", "shut": "closed",
}
#: adjectives and participles naming a state (value: the condition)
ADJECTIVES = {
    "sliced": "sliced", "chopped": "sliced", "diced": "sliced",
    "clean": "clean", "washed": "clean", "cleaned": "clean", "rinsed": "clean", "dirty": "dirty",
    "filthy": "dirty", "used": "dirty", "mucky": "dirty", "grubby": "dirty", "grimy": "dirty", "greasy": "dirty",
    "unwashed": "dirty", "grotty": "dirty",
    "hot": "hot", "warm": "hot", "heated": "hot", "warmed": "hot", "cooked": "hot", "cold": "cold",
    "cool": "cold", "unheated": "cold", "whole": "whole", "unsliced": "whole",
    "open": "open", "opened": "open", "closed": "closed", "shut": "closed",
}
#: the home's states said in the family's other language ("the sufuria is chafu": Swahili; "kasif":
#: Persian; "the comal is sucio": Spanish). Read only as written: no slip of another word is read as
#: one of them ("câline", folded, is no "caliente"). "frío" is left out: its accent folded, it would be a
#: word of the reader's own, and an accented word of the reader's is refused (characters.py)
STATES_SAID_OTHERWISE = {
    "chafu": "dirty", "kasif": "dirty", "baridi": "cold", "sard": "cold",
    "sucio": "dirty", "sucia": "dirty", "sucios": "dirty", "sucias": "dirty", "limpio": "clean", "limpia": "clean",
    "caliente": "hot",
    # Punjabi and Hindi ("the cup is so ganda", "the basement is too garam")
    "garam": "hot", "thanda": "cold", "thandi": "cold", "ganda": "dirty", "gandi": "dirty", "saaf": "clean",
}
ADJECTIVES.update(STATES_SAID_OTHERWISE)
#: participles of the verbs above that are no adjective of their own: "once the mug is washed"
#: says the washing is done first (as "once you have washed it"), while "once the mug is clean"
#: or "once the fridge is closed" is a condition on the home (refused)
ACTION_PARTICIPLES = {"washed", "cleaned", "rinsed", "scrubbed", "wiped", "sliced", "chopped", "diced", "halved",
                      "heated", "warmed", "cooked", "reheated", "baked", "boiled", "fried", "toasted", "opened"}
#: conditions a plan can reach from the other polarity (the domain's actions); the others
#: (``dirty``, ``cold``, ``whole``) only select, or are kept where they already hold
REACHABLE = {"open", "closed", "on", "off", "sliced", "clean", "hot"}
#: the place property an action needs when the command names where it happens ("heat the egg
#: in the microwave": the microwave must be a heater)
VIA_PROPERTY = {"hot": "heater", "clean": "sink", "sliced": "receptacle"}

#: the last words of names of two words whose first word is what people call the thing ("my
#: crossword" of crossword_book, "the jigsaw" of jigsaw_puzzle, "the photos" of photo_album): the
#: thing is a form or a carrier of what its first word names. Other names are not read by their
#: first word: "the wine" is no wine_glass, "dinner" no dinner_plate, "the phone" no phone_charger;
#: "set", "pad", "board" are not forms ("dinner set", "heating pad", "ironing board")
FORM_HEADS = {"book", "books", "puzzle", "puzzles", "album", "magazine"}
#: words that name a kind of thing as well as a thing's name: "stove" of a "camping stove" is as
#: much the range or the oven of the same kitchen. Such a word read alone (as the head of one
#: thing's name) names that thing only where no other thing of the home is of the kind (its
#: name or words have one of the kind's words); else it names none of them (asked, never a guess)
KIND_WORDS = {
    "stove": {"stove", "oven", "range", "cooker", "hob", "burner", "primus", "aga", "grill"},
    "cooker": {"stove", "oven", "range", "cooker", "hob", "burner", "primus", "aga", "grill"},
}
#: state cues: activities whose absence means "off"; ``None``: only what the sentence names,
#: a category word: that category of the world when the sentence names nothing
ACTIVITIES = {"watching": None, "reading": "light", "using": None, "listening": None, "playing": None,
              "working": None, "looking": None, "studying": "light", "cooking": None}
#: "it is (too) bright" -> off, "it is dark" -> on; both speak of the world's category "light"
LIGHT_CUES = {"bright": "off", "sunny": "off", "dark": "on", "gloomy": "on", "dim": "on", "pitch black": "on",
              "pitch dark": "on", "murky": "on", "like a cave": "on"}
LIGHT_CATEGORY_WORD = "light"
#: "it's freezing in here", "I'm cold": the home's room heaters on; "it's roasting in here": the
#: room heaters that are on, off. Words that say how warm the *room* is ("cold" and "hot" also
#: describe things, so they are cues only said of the room or of a person: "it's cold in here",
#: "I'm cold"; "freezing", "chilly" alone are cues)
TEMPERATURE_CUES = {"freezing": "on", "chilly": "on", "nippy": "on", "perishing": "on", "baltic": "on",
                    "frozen": "on", "roasting": "off", "boiling": "off", "sweltering": "off", "stifling": "off",
                    "baking": "off", "perished": "on", "frozen stiff": "on", "icy": "on", "arctic": "on",
                    "parky": "on", "cold as ice": "on", "like an oven": "off", "like a sauna": "off",
                    "sweating": "off", "shivering": "on", "like a fridge": "on", "like an icebox": "on",
                    "like a freezer": "on", "like the arctic": "on", "like a furnace": "off",
                    # Yorkshire "I'm nithered" (chilled through), "nesh" (feeling the cold)
                    "nithered": "on", "nesh": "on"}
#: the adjectives that are temperature cues when said of the room or of a person
TEMPERATURE_ADJECTIVES = {"cold": "on", "hot": "off", "warm": "off"}
#: what warms a room (not food): a thing that switches and is named, or worded, by one of these
#: ("log burner", "radiator"), or a member of a category of the world so named. "stove" and
#: "burner" alone are not here: a kitchen stove warms food, and no two people agree it is the heating
ROOM_HEATERS = ("heater", "heaters", "radiator", "radiators", "fire", "fireplace", "log burner", "wood burner",
                "woodburner", "wood stove", "log stove", "stove heater", "space heater", "heating",
                "central heating", "electric fire", "gas fire")

#: one-or-more-word phrases of command English -> (token class, value)
PHRASES: dict[tuple[str, ...], tuple[str, object]] = {}


def _add(cls: str, words: str, value: object = None) -> None:
    for w in words.split(","):
        PHRASES[tuple(w.split())] = (cls, value)


for _w, _c in STATE_VERBS.items():
    _add({"open": "V_OPEN", "shut": "V_SHUT", "clean": "V_CLEAN", "warm": "V_WARM"}.get(_w, "V_STATE"),
         _w, _c)
for _w, _c in ADJECTIVES.items():
    if tuple(_w.split()) not in PHRASES:
        _add("ADJ", _w, _c)
_add("V_TOGGLE", "turn,switch,power,flip,flick")
#: "wash off the boots", "wipe down the counter": the thing washed (the particle says no place)
_add("V_STATE", ",".join(p for p in ("wash off", "rinse off", "scrub off", "wipe off", "wipe down", "scrub down")
                         if tuple(p.split()) not in PHRASES), "clean")
#: "light the stove", "light the fire": a thing that burns or shines is switched on
_add("V_LIGHT", "light,light up", "on")
#: "start the coffee maker", "fire up the laptop": a device started is switched on (read as "light" is)
_add("V_LIGHT", "start,start up,fire up,boot up", "on")
#: "chill the juice": into the home's cold place (the category named, or with a word, "cold")
COLD = "cold"
#: "put the clothes in the wash": the home's one laundry place (lexicon ``LAUNDRY_PLACES``)
LAUNDRY = "laundry"
_add("V_CHILL", "chill,cool,refrigerate,cool down,chill down")
_add("TOGGLED", "turned,switched,powered")
#: verbs that mean "off" by themselves ("shut down the tablet"); "turn down" is a volume, not here
_add("V_SHUTDOWN", "shut down,power down", "off")
#: "close over the bread bin" (Irish and Scots English): closed, as "close" is
_add("V_STATE", "close over,shut over", "closed")
#: "give the pot a scrub": the noun of an action that cleans (value: the condition)
_add("V_GIVE", "give")
_add("ACT", "a scrub,a wash,a rinse,a wipe,a clean,a good scrub,a good wash,a good clean,a quick rinse,"
     "a quick wash,a quick wipe,a wipe down,a proper clean", "clean")
#: "a piece of fruit": a kind counted in pieces (only a category may be; "a piece of bread" is no
#: thing of the home model and is refused)
_add("UNIT", "pieces of,bits of,items of,cans of,tins of,bottles of,packets of,jars of,cartons of")
#: "a piece of fruit" is a determiner of one (a unit word in the determiner keeps the grammar small)
UNIT_DETERMINERS = {"a piece of", "a bit of", "an item of"}
_add("V_PUT", "put,place,move,bring,take,carry,set,transfer,gather,collect,stash,drop,store,stick,pop,lay,"
     "hang,deliver,fetch,get,pick,relocate,stack,grab,shift,clear,pack,lift,haul,lug,hand,drag,plonk,bung,"
     "shove,tuck,hoist,ferry,send,peg,"
     # Appalachian and Southern US "tote" (carry: "tote that poke of taters down to the cellar");
     # British "sling" (put, carelessly: "sling them almonds in the washing basket")
     "tote,sling")
#: "empty the fridge onto the counter": everything in a place taken, to where the command says
_add("V_EMPTY", "empty,clear out,unload,unpack")
#: "put the espresso cup down on the bar": a particle of the move before where it goes
_add("DOWN", "down")
#: "leave the hoodie where it is": the thing stays in the place it is in now
_add("STAY", "where it is,where they are,as it is,as they are,alone,in place,where it was,where they were,"
     "where you found it,where you found them")
#: "someone's left the lemon out": disorder said of things, like ``MESS`` (a later clause that
#: acts on them makes it the reason)
#: "my coat has been lying on the sofa": a thing said to lie about somewhere, disorder like ``MESS``
#: (British "sat", "stood": "the butter's been sat out on the table"; "out" before where it is)
_add("LYING", "lying,left lying,lying there,sitting there,sitting,sat,sat there,stood,stood there,standing there,"
     "lying out,sitting out,sat out,stood out,standing out,left sitting,left sat,left standing,left stood,standing")
#: "the fridge has been left open": a state complained of (a class the tagger gives "has been
#: left" before a state word: :func:`pipflow.household.language.retag.left_lying`)
_add("LEFTAS", "left as is")
#: "the crockery needs doing": what the things need, as "deal with" (lexicon ``V_TEND``)
_add("DOING", "doing,seeing to,sorting,sorting out,dealing with,attention,some attention")
#: "the scarf is cluttering up the armchair": a thing said to be in the way somewhere, disorder
_add("CLUTTER", "cluttering up,cluttering,clogging up,taking up room on,taking up space on,in the way on,"
     "hogging")
#: "the table has still got the dirty dishes on it": what a place holds, said as disorder
_add("HASGOT", "has still got,have still got,still has,still have,still has got,still have got,"
     "still got")
_add("LEFT", "left,has left,have left,someone has left,somebody has left,someone left,somebody left,"
     "i have left,i left,we have left,we left,i think i have left,i think i left,i think we have left")
_add("V_THROW", "throw,toss,chuck")
_add("V_TRASH", "trash,discard,bin,dump,junk,get rid of,dispose of,throw away,throw out")
_add("V_TIDY", "tidy,return,clear away")
_add("V_LEAVE", "leave,keep")
#: "don't touch my cooler": the thing stays as and where it is, as "leave it alone" says
_add("V_TOUCH", "touch,disturb,mess with,fiddle with")
_add("V_MAKE", "make")
#: "heat the pie, not in the oven, use the hob": the place an action happens, said after it
_add("V_USE", "use,do it in,do it on")
#: verbs that prepare a meal ("fix us some breakfast"); "make" is V_MAKE (also "make sure")
_add("V_PREPARE", "prepare,fix,fix up,whip up,rustle up")
_add("SURE", "sure,certain")
_add("ACTIVITY", ",".join(ACTIVITIES))
_add("LIGHTCUE", ",".join(LIGHT_CUES))
for _w, _v in TEMPERATURE_CUES.items():
    _add("TEMPCUE", _w, _v)
#: "deal with the dishes", "sort the bedding out": what the things need, read from their states
#: and the home (docs/household.md, "what things need"); never a guess when two things would do
_add("V_TEND", "deal with,see to,take care of,sort,sort out,handle,attend to,do something about")
#: "the bedding's all over the place", "the dishes are piling up": disorder said of things, a cue
#: that they need what "deal with" reads
_add("MESS", "all over the place,piling up,piled up,lying around,lying about,left out,scattered about,"
     "scattered around,strewn about,strewn around,a mess,in a mess,messy,a tip")
#: "an absolute tip", "a right state", "a bit of a pigsty": a word for disorder, as strong as said
_add("MESS", ",".join(f"{article} {strength}{noun}" for noun in ("tip", "mess", "pigsty", "bombsite", "state", "shambles")
                      for article, strength in (("a", ""), ("a", "complete "), ("a", "total "), ("a", "right "),
                                                ("a", "proper "), ("a", "real "), ("an", "absolute "),
                                                ("a", "bit of a "), ("in", "a "), ("like", "a "),
                                                ("like", "an absolute "), ("like", "a complete "))))
for _w in LIGHT_CUES:
    PHRASES[tuple(_w.split())] = ("LIGHTCUE", LIGHT_CUES[_w])
_add("SEE", "see,read,see anything,read anything")
#: "I'm trying to sleep", "going to sleep": the lights off (a cue like "it is too bright")
_add("SLEEPCUE", "trying to sleep,trying to nap,trying to get some sleep,trying to get to sleep,going to sleep,"
     "want to sleep,need to sleep,off to sleep,having a nap,taking a nap,going to have a nap,sleeping,napping,"
     "trying to have a nap,want a nap,need a nap")
#: "I want to watch something", "I'd like to read", "it's too dark to study": an activity wished for
#: (value: what it needs on: a kind of lexicon ``DEVICES``, or the light category)
DO_ACTIVITIES = {"watch": "screen", "listen": "sound", "study": "light", "work": "light", "read": "light"}
for _w, _v in DO_ACTIVITIES.items():
    if (_w,) not in PHRASES:
        _add("DOACT", _w, _v)
_add("DOACT", "watch something,watch telly,watch tv,listen to something,listen to music,do some reading,do some work,"
     "get some work done,hear something", None)
for _p in ("watch something", "watch telly", "watch tv"):
    PHRASES[tuple(_p.split())] = ("DOACT", "screen")
for _p in ("listen to something", "listen to music", "hear something"):
    PHRASES[tuple(_p.split())] = ("DOACT", "sound")
for _p in ("do some reading", "do some work", "get some work done"):
    PHRASES[tuple(_p.split())] = ("DOACT", "light")
#: "there are dishes everywhere": an existential opening
_add("THERE", "there")
#: "the sink is full of dishes", "the floor is covered in clothes": disorder said of what a place holds
_add("FULLOF", "full of,covered in,covered with,piled with,piled high with,littered with,stacked with,cluttered with")
#: "it's too quiet in here" -> the home's sound makers on; "it's too loud" -> the ones on, off
SOUND_CUES = {"quiet": "on", "silent": "on", "loud": "off", "noisy": "off", "deafening": "off"}
for _w, _v in SOUND_CUES.items():
    _add("SOUNDCUE", _w, _v)
#: what plays sound: a thing that switches and is named or worded so (or a member of a category
#: so named); "put some music on", "it's too quiet in here"
SOUND_MAKERS = ("radio", "radios", "speaker", "speakers", "stereo", "record player", "turntable", "music",
                "hifi", "hi fi", "sound system", "music player", "jukebox", "gramophone", "music system")
#: "it's stuffy in here", "it's muggy": the air wants moving: a fan that is off, on, or a window that
#: is closed, open (resolver ``air_cue``; several such things: asked, each offered)
AIR_CUES = ("stuffy", "muggy", "airless", "humid", "fuggy", "close and stuffy", "like a greenhouse")
for _w in AIR_CUES:
    _add("AIRCUE", _w, "air")
#: what moves the air when switched on (a thing that switches, named or worded so)
FANS = ("fan", "fans", "ceiling fan", "desk fan", "pedestal fan", "tower fan", "air conditioner", "air con", "aircon",
        "air conditioning", "extractor", "extractor fan", "ventilator")
#: what lets air in when opened (a thing that opens, named or worded so)
WINDOWS = ("window", "windows", "skylight", "fanlight", "casement", "sash window", "french window", "french windows",
           "vent", "air vent", "patio door", "back door")
#: "I can't hear myself think (with that radio blaring)": the noise wants stopping: what is said to
#: make it, else the home's sound makers that are on, off (a cue like "it's too loud")
_add("HEARCUE", "hear myself think,hear myself speak,hear myself,hear a thing,hear anything,hear the telly,"
     "hear the tv,hear the radio,get any peace,think straight,concentrate", "off")
#: "make it warmer in here", "can it be a bit brighter": a change wished for (value: the kind of
#: thing it speaks of and the state it asks of it); only after "make it" / "can it be", never a
#: description ("it's warmer now" asks nothing)
COMPARATIVES = {"warmer": ("heating", "on"), "less cold": ("heating", "on"), "cooler": ("heating", "off"),
                "less hot": ("heating", "off"), "brighter": ("light", "on"), "lighter": ("light", "on"),
                "darker": ("light", "off"), "quieter": ("sound", "off"), "louder": ("sound", "on"),
                "less stuffy": ("air", "on"), "fresher": ("air", "on")}
for _w, _v in COMPARATIVES.items():
    _add("MORE", _w, _v)
#: "can we get some air in here?": the air wants moving (as "it's stuffy")
_add("FRESHAIR", "some air,some fresh air,fresh air,a bit of air,a breeze,a bit of a breeze,some air in here")
_add("MUSIC", "music,some music,a tune,some tunes,tunes,a song,some songs")
_add("V_PLAY", "play")
#: a hot drink wished for ("could murder a cuppa", "I'd love a cup of tea", "make a brew"): the
#: home's drink makers on (a kettle, a coffee machine); the drink itself is no thing of the home
HOT_DRINKS = ("cuppa", "cup of tea", "tea", "brew", "coffee", "cup of coffee", "hot drink", "cocoa", "hot chocolate",
              "mug of tea", "pot of tea", "espresso", "latte", "cappuccino")
_add("HOTDRINK", ",".join(HOT_DRINKS))
#: what makes a hot drink: a thing that switches and is named or worded so
DRINK_MAKERS = ("kettle", "kettles", "coffee machine", "coffee maker", "espresso machine", "teasmade", "urn",
                "percolator", "coffee pot", "bean to cup", "samovar")
#: the kinds of thing a cue of the room may speak of (cue ``device``): what warms the room, what
#: plays sound, what makes a hot drink; each read from the world's names and words
#: what shows something to watch
SCREENS = ("tv", "television", "telly", "projector", "screen", "monitor", "tv set")
#: what lights a room, where the world has no category of lights: a light cue ("the salon is too
#: dark") is of the things that switch and are named or worded so ("salon light", "lustre")
LIGHTS = ("light", "lights", "lamp", "lamps", "chandelier", "lustre", "bulb", "lantern", "sconce", "spotlight",
          "spotlights", "downlight", "downlights", "floor lamp", "desk lamp", "ceiling light", "tube light",
          "tubelight")
DEVICES = {"heating": ROOM_HEATERS, "sound": SOUND_MAKERS, "hot drink": DRINK_MAKERS, "screen": SCREENS, "air": FANS}
DEVICE_NOUNS = {"heating": "room heater", "sound": "sound maker", "hot drink": "drink maker", "screen": "screen",
                "air": "fan or window"}
#: "the mug is minging", "the pizza box is starting to smell": foulness said of a thing. A thing
#: that washes is washed; food and rubbish (a category named or worded so) go in the bin; any
#: other thing is asked (docs/household.md, cues)
FOUL_WORDS = {"minging", "smelly", "stinky", "rank", "gross", "disgusting", "rotten", "mouldy", "moldy", "manky",
              "grotty", "rancid", "putrid", "revolting", "whiffy", "pongy", "skanky", "nasty", "foul", "stale",
              "sour", "off"}
#: what food turns when it is past eating, said only after a verb of becoming ("the orange has
#: gone soft", "it's gone all mushy"): alone they are no state ("a soft cushion"), so no adjective
GONE_OFF = {"soft", "mushy", "squishy", "wrinkly", "slimy", "furry", "soggy", "limp", "brown", "black",
            # the colours of mould ("the bread's gone green", "the cheese has gone blue")
            "green", "blue", "fuzzy"}
for _w in FOUL_WORDS - {"off"}:
    _add("ADJ", _w, "dirty")
#: a foul predicate said whole: "the fish smells off", "the scone has gone stale", "it's gone mouldy"
_add("FOULS", ",".join(
    [f"{v}{' ' + how if how else ''}" for v in ("smells", "stinks", "reeks", "smell", "stink", "reek", "is smelling",
                                              "is stinking", "is starting to smell", "is beginning to smell",
                                              "started to smell", "is starting to stink")
     for how in ("", "off", "bad", "awful", "funny", "horrible", "terrible")]
    + [f"{v} {how}" for v in ("has gone", "have gone", "is gone", "are gone", "has turned", "have turned",
                              "is going", "are going", "went", "gone", "turned")
       for how in sorted(FOUL_WORDS - {"rank", "gross", "disgusting", "revolting", "nasty", "foul", "grim"}) + ["bad"]
       + sorted(GONE_OFF)]),
     "dirty")
#: the words that say a rubbish or food thing is for the bin when it is foul
BIN_KINDS = ("rubbish", "trash", "garbage", "litter", "waste", "junk", "recycling", "food", "leftovers")
#: the kinds of BIN_KINDS that are never kept: lying about, they go in the bin (food is put away)
RUBBISH_KINDS = ("rubbish", "trash", "garbage", "litter", "waste", "junk")
_add("THE", "the,a,an,my,our,your,its,their,his,her,these,those,this,some")
_add("THE", "a piece of,a bit of,an item of")
_add("THAT", "that,which,who")
_add("ALL", "all")
_add("EVERY", "every,each,any")
_add("BOTH", "both")
_add("EVERYTHING", "everything,all things,all the things,anything")
_add("THING", "thing,things,stuff,items,objects")
_add("AND", "and,as well as,plus,along with,n")
_add("THEN", "then,after that,afterwards,next,finally,and then,also")
_add("BUT", "but,bas")   # Levantine Arabic "bas": but
_add("IN", "in,into,inside,inside of,within")
_add("ON", "on,onto,upon")
_add("TO", "to,over to,back to")
_add("AT", "at")
#: spatial relations the home model has no place for ("next to the fridge" is not in it): a
#: class the grammar never uses, so a command with one is refused, quoting it
_add("NEAR", "next to,beside,near,by,behind,under,underneath,below,above,in front of,on top of,over,between,around")
#: the words of NEAR that say a light cue is felt close to a place ("dark over by the sofa"); the
#: others ("under", "behind", "between") say where, not near what, and are refused in a cue
NEARNESS = {"by", "near", "next to", "beside", "over", "around"}
_add("WITH", "with")
_add("FROM", "from,out of,off of")
_add("OUT", "out")
_add("OFF", "off")
_add("UP", "up")
_add("AWAY", "away,where it belongs,where they belong,where it goes,where they go,where it lives,where they live,"
     "away where it belongs,away where they belong,away where it goes,away where they go,in its place,in their place,in their places,back in its place,"
     "back in their place,back where it belongs,back where they belong,back where it lives,back where they live,"
     "back where it goes,back where they go,"
     # Southern and Appalachian "put it up where it goes" (put it away); "put the radio up on the
     # shelf" keeps "up" as a particle of the move
     "up where it belongs,up where they belong,up where it goes,up where they go")
_add("BACK", "back")
_add("OF", "of")
_add("IT", "it,them,they")
#: "slice the cucumber and leave the slices on the table": what an action made of the things
#: before is those things
_add("IT", "the slices,the pieces,the bits,the chunks,the halves,the lot")
_add("EXCEPT", "except,except for,apart from,other than,besides,excluding,but not")
_add("NOT", "not")
#: "is", and the perfect of a state said of a thing ("the console has been on all night", "the
#: drink has gone warm", "the curry has gone off"): a description, like "is"
_add("IS", "is,are,am,is still,are still,has been,have been,has gone,have gone,has got,have got,has become,"
     "has been left,have been left,was left,were left,is left,are left")
_add("BE", "be,stay,remain,stays,remains,go")
_add("SHOULD", "should,must,has to,have to,needs to,need to,ought to,got to,can")
_add("SUBJ", "i,we,you")
#: wishes: "I want X", and what people say for it of food and drink ("I fancy a warm bagel",
#: "could murder a cuppa", "I'd love a tea", "I'm dying for a coffee")
_add("WANT", "want,would like,like,wish,d like,prefer,fancy,would love,love,could murder,could kill for,"
     "am dying for,am craving,crave,would kill for,could do with,could use,could go for,would go for,could eat,am gasping for,"
     # British "I'm gagging for a brew", "I'm desperate for a cuppa"
     "am gagging for,am desperate for,can i get,can i have,"
     "could i get,could i have,may i have,can we get,can we have,could we have,could we get")
#: a wish graded by a hedge inside it ("I could really go for", "I would just love"): the same wish
for _k, (_c, _v) in list(PHRASES.items()):
    if _c == "WANT" and len(_k) >= 2 and _k[0] in ("could", "would", "am"):
        for _h in ("really", "just", "so", "honestly"):
            PHRASES.setdefault((_k[0], _h) + _k[1:], (_c, _v))
_add("NEED", "need,needs,wants")
#: a wish said of the time to come ("I'll want my hottie in with me", "we'll need the lamp lit"):
#: the same wish; "will" before any other verb is no wish, and is not read
_add("WANT", "will want,shall want,will be wanting")
_add("NEED", "will need,shall need,will be needing")
_add("NEEDED", "needed,necessary,required,in use")
#: "we are done with the laptop": the thing is not needed (a state cue, like "we do not need")
_add("DONE", "done with,finished with,through with")
#: "we have finished reading": an activity that ended (a state cue, like "nobody is reading")
_add("FINISHED", "finished,stopped,done")
_add("HAVE", "have,has")
#: "once you have washed the pan, put it ...": a clause done first
_add("ONCE", "once,after,when")
#: "X goes in P", "X belongs on P": where X should end
_add("GOES", "goes,belongs,belong,lives,live,is meant to live,is meant to go,is meant to be,are meant to live,"
     "are meant to go,are meant to be,is supposed to live,is supposed to go,is supposed to be,are supposed to go,"
     "are supposed to be,are supposed to live,should live,should go,should be kept,is kept,are kept,usually goes,"
     "usually lives")
#: reasons that ask for nothing by themselves ("it is late, turn off the TV"): dropped before a
#: request, refused alone
#: reasons of leaving the home or going to bed: alone they ask for nothing two people agree on
#: (the lights off? everything off?), so they are asked, offering both (docs/household.md, cues)
LEAVING_REASONS = {"bedtime", "time for bed", "off to bed", "going to bed", "heading to bed", "off out", "going out",
                   "heading out", "off to work", "going to work", "late", "night time",
                   # the working day over: "we're done for the day", "logging off"
                   "done for the day", "finished for the day", "off for the day", "done with work",
                   "finished work", "logging off", "clocking off", "signing off",
                   # northern English "we're off up" (up to bed)
                   "off up"}
#: "off to my bed", "away to my bed" (Scots and northern English: "away" is "off"), "off up to bed"
LEAVING_REASONS |= {f"{go} to {whose}bed" for go in ("off", "away", "going", "heading", "off up", "away up")
                    for whose in ("", "my ", "our ")}
_add("REASON", ",".join(sorted(LEAVING_REASONS)))
#: how a person is (tired, thirsty, hungry): alone it asks for nothing two people agree on, so it is
#: asked, offering what answers it in the home (a refusal's candidates: ``NEEDS_OFFERED``); before
#: a request it is the request's reason ("I'm shattered, turn the telly off")
TIRED = ("tired", "shattered", "knackered", "exhausted", "worn out", "sleepy", "whacked", "pooped", "done in",
         "dead on my feet", "dead on me feet", "ready for bed", "beat")
THIRSTY = ("thirsty", "parched", "gasping", "dry", "spitting feathers")
HUNGRY = ("hungry", "starving", "famished", "peckish", "ravenous", "starved")
_add("REASON", ",".join(TIRED + THIRSTY + HUNGRY))
#: the candidate readings a need said alone offers (a wording each, read by the translator like any
#: command, so only what this home can do is offered); "hungry": each food that heats (candidates)
NEEDS_OFFERED = {**{w: ("it is too bright", "switch off everything that is on") for w in TIRED},
                 **{w: ("make a cup of tea",) for w in THIRSTY}, **{w: () for w in HUNGRY}}
#: how a thing is to be handled, said of it ("the wok is too heavy for one of you", "the can is
#: leaking"): a reason for how the robots work, not an end state of the home; alone it asks nothing
_add("HANDLING", "heavy,bulky,awkward,fragile,delicate,breakable,slippery,leaking,dripping,broken,cracked,chipped,"
     "wet,sticky,too big,too heavy,too awkward,quite heavy")
#: "it takes two to lift", "the trunk needs two of you": the same, said as how many it takes
#: (only words of lifting: a word such as "people" here would make "we've got people coming
#: round" content, and no longer talk to set aside)
_add("TAKESTWO", ",".join(f"{v} two{how}" for v in ("takes", "needs", "take", "need")
                          for how in (" to lift", " to carry", " to move", " of you", "")))
#: "it's a heavy one", "it's an awkward one": the same, said of the thing as "a ... one"
_add("HANDLING", ",".join(f"{'an' if w[0] in 'aeiou' else 'a'} {w} one" for w in
                          ("heavy", "bulky", "awkward", "fragile", "delicate", "slippery")))
_add("FORONE", "for one of you,for one robot,for one person,for one,to carry alone,to lift alone,on your own,"
     "for one of them,to lift on your own,to carry on your own")
#: exclamations that ask for nothing by themselves ("What a tip.", "Ugh, ..."): reasons
_add("REASON", "what a mess,what a tip,what a state,what a pigsty,what a dump,what a racket,what a din,what a noise")
#: "it's like a tip in here", "it's a pigsty in here": the same, said of the room
_add("REASON", ",".join(f"it is {like}a {mess} in {where}" for like in ("", "like ")
                        for mess in ("tip", "pigsty", "mess", "bomb site", "dump") for where in ("here", "there")))
#: interjections: they open or close a sentence and say nothing ("Blimey it's cold", "Ugh, ..."): read
#: as a pause, like a comma (a sentence of nothing else asks for nothing, and is refused)
_add("EXCL", "ugh,urgh,ew,eww,yuck,blimey,brr,brrr,phew,oof,ooh,oh dear,oh,gosh,cor,crikey,jeez,sheesh,eek,bah")
_add("DONOT", "do not,does not,did not,no longer,dont")
_add("ANYMORE", "anymore,any more,any longer,for now,for the night,tonight,right now")
_add("NOBODY", "nobody,no one,noone,none of us")
_add("INTENS", "very,so,really,quite,rather,extremely,pretty,a bit,a little,way too,much too,far too,getting,bit,"
     "bit of a,a bit of a")
#: intensifiers and hedges that grade the word after them and say nothing of what is wanted ("it's
#: ever so dark", "absolutely freezing", "proper cold", "dead noisy", "I could really go for"): read
#: as nothing before a word they may grade (a state, a cue, a wish, "too"); anywhere else they are
#: unplaced and refused ("dead" of "the plant is dead" is never dropped: nothing follows it there)
HEDGES = ("ever so", "ever such a", "absolutely", "proper", "properly", "dead", "awfully", "awful", "terribly", "bloody",
          "utterly", "totally", "a tad", "a touch", "somewhat", "fairly", "a little bit", "a wee bit", "a tiny bit",
          "incredibly", "so very", "that", "really quite", "just so", "too too", "well", "right",
          "all", "super", "kinda", "kind of", "sorta", "sort of", "hella",
          # Appalachian "plumb" (completely: "plumb dark", "plumb covered in mud")
          "plumb")
HEDGE_WORDS = tuple(h for h in HEDGES if tuple(h.split()) not in PHRASES)
_add("HEDGE", ",".join(HEDGE_WORDS))
#: the token classes a hedge may grade: the hedge before one of them is read as nothing
GRADED = {"ADJ", "LIGHTCUE", "TEMPCUE", "SOUNDCUE", "AIRCUE", "HANDLING", "WANT", "NEED", "MESS", "ALLOVER", "TOO",
          "INTENS", "HEDGE", "FOULS", "GOING", "V_CLEAN", "V_WARM", "V_OPEN", "V_SHUT", "HEARCUE", "REASON", "MORE",
          "V_STATE"}
_add("TOO", "too,as well")
#: "it's freezing with that fan going": a thing said to be running
_add("GOING", "going,running,blasting,blaring,whirring,humming,lit,burning,on the go,blaring away,blasting away,going full blast,"
     "humming away,whirring away,droning on,droning away,on full blast,at full blast", "on")
_add("CANNOT", "can not,could not,cannot,can barely,can hardly,could barely,could hardly,can scarcely")
_add("SOMEWHERE", "somewhere,some place,someplace")
#: words for the home itself or a room of it, which no world lists as a place: "in here", "all
#: over the flat", "over here" (where a cue is felt, or a mess lies). A world that has a thing so
#: named ("kitchen" of a kitchen place) keeps it: the tagger reads its name, not these phrases
HOME_WORDS = ("house", "home", "flat", "apartment", "cabin", "boat", "cottage", "studio", "loft")
#: rooms of a home, which no world lists as places: "nobody is in the kitchen" is a cue (what was
#: observed there off); "turn off the lights in the kitchen" names no part of the home model and is
#: refused (reading it as "here" would widen the order)
ROOM_WORDS = ("room", "lounge", "living room", "sitting room", "bedroom", "kitchen", "hall", "hallway", "study",
              "office", "dining room", "bathroom", "floor", "conservatory", "sunroom", "sun room", "utility room",
              "utility", "porch", "landing", "attic", "cellar", "basement", "garage", "nursery", "playroom", "den",
              "snug", "parlour", "front room", "back room", "spare room", "box room", "games room", "kitchenette",
              "lobby", "cloakroom", "laundry room", "scullery", "pantry",
              # French and Levantine "salon" (the living room), and rooms said in other Englishes
              "salon", "toilet", "washroom", "lounge room", "family room", "tv room", "guest room", "kids room")
_add("HERE", "here,in here,over here,over there," + ",".join(f"in the {h},around the {h}" for h in HOME_WORDS)
     + "," + ",".join(f"{at} {whose} {h}" for h in HOME_WORDS + ("place",) for at in ("in", "around")
                      for whose in ("this", "my", "our")))
_add("ROOMSAID", ",".join(f"the {r},my {r},our {r}" for r in ROOM_WORDS))
#: the whole home said so ("this place is a tip", "the house is a pigsty"): its disorder, as a room's
_add("ROOMSAID", ",".join(f"{whose} {h}" for h in HOME_WORDS + ("place",) for whose in ("this", "the", "my", "our")))
_add("INROOM", ",".join(f"in the {r},in {r}" for r in ROOM_WORDS) + ",at home,home")
#: "freezing in my room": whose room it is (resolver ``_called_after``: the home's "my heater")
_add("INROOM", ",".join(f"in {whose} {r}" for r in ("room", "bedroom") for whose in ("my", "our")))
#: a room said with a particle of where ("out in the conservatory", "over in the study", "up in the
#: attic"): where a cue is felt, as "in the ..." (a room the home model lacks: resolver ``_room``)
_add("INROOM", ",".join(f"{p} in the {r}" for p in ("out", "over", "up", "down", "back") for r in ROOM_WORDS))
#: "put the clothes in the wash": the home's one laundry place (a place named or worded so)
_add("THEWASH", "the wash")
LAUNDRY_PLACES = ("laundry basket", "washing basket", "laundry", "hamper", "washing machine", "washer",
                  "laundry bin", "linen basket", "dirty clothes basket", "clothes basket")
#: "everywhere", "all over (the flat)": where a cue is felt ("lights on everywhere"), or, said of
#: things, disorder like ``MESS`` ("clothes everywhere", "the cat's toys are all over the flat")
_add("ALLOVER", "everywhere,all over,everywhere in here,all over the shop,all over the show,all over the gaff,"
     "all over the joint,here there and everywhere," + ",".join(f"all over the {h},everywhere in the {h}"
                                                                    for h in HOME_WORDS + ROOM_WORDS))
_add("PIECES", "in half,in two,into pieces,into slices,into cubes,in pieces,in slices,into halves")
_add("DOOR", "door,doors,lid,lids")
#: the part of a switching thing that switches it: "turn on the lamp switch" is the lamp
_add("SWITCHPART", "button,power button,on button,off button")
_add("ONES", "ones")
#: the first words of the lexicon's verbs of an order ("put", "switch", "wash", ...), with "turn":
#: a clause that holds one says what to do
ORDER_VERB_WORDS = frozenset(k[0] for k, (cls, _) in PHRASES.items() if cls.startswith("V_")) | {"turn", "switch"}

#: the negation of a wanted state is the other polarity of the same predicate ("don't leave the
#: fridge open": closed); every condition has exactly one opposite, so nothing is guessed
OPPOSITE = {"open": "closed", "closed": "open", "on": "off", "off": "on", "clean": "dirty", "dirty": "clean",
            "hot": "cold", "cold": "hot", "sliced": "whole", "whole": "sliced"}

#: meals: an activity cue names a state of the foods of a meal ("make a salad": the salad
#: vegetables sliced; "prepare breakfast": the breakfast foods hot). Which foods make a meal is
#: kitchen knowledge that no world file holds, so it is written here, small and closed; a world
#: may override it with a category of its own named (or worded) like the meal. ``foods``: the
#: last word of an object's name or words, singular; ``base``: at least one of these must be in
#: the home, else the meal is refused (a salad of tomatoes alone is not what was asked).
MEALS: dict[str, dict] = {
    "salad": {"state": "sliced",
              "foods": ["lettuce", "tomato", "cucumber", "cabbage", "spinach", "rocket", "arugula", "kale",
                        "radish", "celery", "pepper", "avocado", "carrot", "onion", "olive", "leaf", "leaves"],
              "base": ["lettuce", "cabbage", "spinach", "rocket", "arugula", "kale", "leaf", "leaves"]},
    "fruit salad": {"state": "sliced",
                    "foods": ["apple", "banana", "orange", "pear", "melon", "watermelon", "grape", "strawberry",
                              "kiwi", "mango", "pineapple", "peach", "plum", "apricot", "berry", "cherry"]},
    "breakfast": {"state": "hot",
                  "foods": ["egg", "bread", "toast", "bacon", "sausage", "pancake", "waffle", "porridge", "oatmeal",
                            "bagel", "croissant", "muffin", "bun", "roll"]},
}
#: toast is bread sliced and heated: "make (some) toast" (a meal whose word is also a verb, "toast
#: the bread": the verb keeps its class, and the grammar reads "make" + it as the meal)
MEALS["toast"] = {"state": "hot", "also": ["sliced"], "foods": ["bread", "loaf", "toast", "bloomer", "baguette"],
                  "base": ["bread", "loaf", "toast", "bloomer", "baguette"]}
for _m in MEALS:
    if tuple(_m.split()) not in PHRASES:
        PHRASES[tuple(_m.split())] = ("MEAL", _m)

#: category words that name a mass, not one thing: "put away the fruit" means all of it, while
#: "turn off the lamp" names one lamp (and is asked back when the home has several)
#: (the last word of the phrase decides: "reading material")
MASS_NOUNS = {"fruit", "food", "bedding", "cutlery", "stationery", "lighting", "tableware", "cookware",
              "laundry", "rubbish", "equipment", "furniture", "produce", "veg", "electronics", "clothing",
              "silverware", "crockery", "groceries", "trash", "garbage", "stuff", "material", "gear", "kit",
              "junk", "mail", "post", "paperwork", "luggage", "baggage", "washing", "shopping"}
#: determiners that ask for one thing of a kind
INDEFINITE = {"a", "an", "a piece of", "a bit of", "an item of"}

#: politeness and framing words that carry no content; dropped before parsing (listed in docs)
FILLER = {("um",), ("umm",), ("uh",), ("uhh",), ("uhm",), ("er",), ("erm",),   # hesitations, said aloud
          # New Zealand and Australian thanks and approval ("Thanks heaps", "Sweet as", "ka pai")
          ("thanks", "heaps"), ("cheers", "heaps"), ("sweet", "as"), ("ka", "pai"),
          # Nigerian Pidgin and Yoruba: "oya" (come on), "sha" (anyway), "jare" (do), "ehn", "ehen",
          # "na wa" (wow), "shey" / "shebi" opening a yes-no question ("Shey the gen is on?": is it?)
          ("oya",), ("sha",), ("jare",), ("ehn",), ("ehen",), ("na", "wa"), ("shey",), ("shebi",),
          # Vietnamese ("troi oi": oh my; "da": yes; "nha", "nhe": OK?, please)
          ("troi", "oi"), ("da",), ("nha",), ("nhe",),
          # Japanese ("onegai (shimasu)": please; "arigatou": thanks; "mou": ugh; "haa": a sigh)
          ("onegai",), ("onegaishimasu",), ("onegai", "shimasu"), ("arigatou",), ("arigato",), ("mou",), ("haa",),
          # Jamaican ("Lawd", "cho": dismay; "eeh", "seen?": OK?, understood?; "irie", "bless", "respect",
          # "tanks" closing; "beg yuh": please; "yuh hear (mi)?": you hear?; said after the patois is read
          # as English, so no patois word is made a word of the reader here)
          ("lawd",), ("cho",), ("eeh",), ("seen",), ("irie",), ("bless",), ("respect",), ("tanks",), ("gwaan",),
          ("beg", "you"), ("you", "hear"), ("you", "hear", "me"),
          # Egyptian Arabic, typed in Latin letters ("yaani": I mean; "maalesh": never mind; "khalas": done,
          # enough; "yalla": come on; "mashi": OK; "ya rab": o Lord; "habibi": dear), spelt without digits
          # (pipflow.language.arabizi)
          ("yaani",), ("maalesh",), ("khalas",), ("yalla",), ("mashi",), ("ya", "rab"), ("ya", "habibi"),
          ("habibi",), ("habibti",), ("inshallah",), ("shokran",), ("merci",), ("ya", "salam"), ("ya", "nhar", "abyad"), ("awi",), ("awy",),
          # Lebanese Arabic and French, typed in Latin letters ("yaane": I mean; "tayyeb": OK; "hala2": now;
          # "ba2a": then, come on; "ktir": very; "shway": a bit; "bref": anyway; "s'il te plait": please;
          # "ca va": all right?), the digits spelt as letters (pipflow.language.arabizi)
          ("yaane",), ("yaaneh",), ("tayyeb",), ("tayeb",), ("hala",), ("halla",), ("baa",), ("ktir",), ("kteer",),
          ("shway",), ("shwayy",), ("bref",), ("s", "il", "te", "plait"), ("s", "il", "vous", "plait"), ("stp",),
          ("ca", "va"), ("bonjour",), ("habibte",), ("yislamo",), ("yeslamo",), ("allah", "yekhalik"),
          # Persian, typed in Latin letters ("lotfan": please; "mamnoon", "merci": thanks; "kheyli": very;
          # "khob": well; "zood": quick; "azizam", "joon": dear; "ghorbanet beram": a loving please;
          # "bebakhshid": sorry; "akhey", "vay": oh; "khasteh nabashid": well done)
          ("lotfan",), ("mamnoon",), ("mamnun",), ("kheyli",), ("khob",), ("zood",), ("azizam",), ("joon",),
          ("ghorbanet", "beram"), ("ghorboonet", "beram"), ("bebakhshid",), ("akhey",), ("vay",), ("hatman",),
          ("khasteh", "nabashid"), ("dastet", "dard", "nakone"), ("yani",),
          # Amharic, typed in Latin letters ("ishi": OK; "bejih", "ebakih": please; "amesegnalehu": thank
          # you; "selam", "tena yistilign": hello; "ere", "wey", "inji": oh, well; "yene konjo": my dear;
          # "egziabher yimesgen": thank God; "chigir yelem": no problem; "betam": very)
          ("ishi",), ("eshi",), ("bejih",), ("bejh",), ("ebakih",), ("ebakish",), ("ebakachu",), ("amesegnalehu",),
          ("amesegnalew",), ("selam",), ("tena", "yistilign"), ("tenayistilign",), ("ere",), ("wey",), ("inji",),
          ("yene", "konjo"), ("egziabher", "yimesgen"), ("chigir", "yelem"), ("betam",),
          # and as others type them ("tenastelign": hello; "ameseginalehu": thank you; "ebakachihu":
          # please, to several; "wey gud": oh my; "gobez": well done; "yikirta": sorry; "tolo": quick)
          # Swahili ("tafadhali": please; "asante": thanks; "haraka": quick; "sawa": OK; "pole": sorry;
          # "jamani": come on, oh dear; "kweli": truly; "kabisa": completely; "sana": very)
          ("tafadhali",), ("asante",), ("asanteni",), ("asante", "sana"), ("haraka",), ("sawa",), ("pole",),
          ("pole", "sana"), ("jamani",), ("kweli",), ("kabisa",), ("sana",), ("mambo",), ("habari",), ("karibu",),
          # Spanish as Tejano and Mexican families type it in English ("porfa": please; "gracias":
          # thanks; "ahorita": right now; "ándale": come on; "oye": hey; "bueno": well; "ay": oh;
          # "pobrecita": poor thing; "mija", "mijo": dear)
          ("porfa",), ("porfavor",), ("por", "favor"), ("gracias",), ("muchas", "gracias"), ("ahorita",),
          ("andale",), ("orale",), ("oye",), ("bueno",), ("ay",), ("ay", "ay", "ay"), ("pobrecita",), ("pobrecito",),
          ("mija",), ("mijo",), ("buenos", "dias"), ("buenas", "tardes"), ("buenas", "noches"), ("gracias", "mija"),
          # Punjabi and Hindi as Punjabi-Canadian families type them ("sat sri akal": hello; "ji": the
          # polite particle; "acha": OK; "haye": oh; "chalo": come on; "theek hai": all right; "beta": child)
          ("sat", "sri", "akal"), ("ji",), ("acha",), ("achha",), ("haye",), ("hai", "hai"), ("chalo",), ("theek", "hai"),
          ("thik", "hai"), ("haanji",), ("haan", "ji"), ("beta",), ("yaar",), ("jaldi",), ("jaldi", "jaldi"),
          # Hawaiian and Hawai'i Pidgin talk ("mahalo (nui)": thank you (very much); "aloha"; "shoots": OK;
          # "brah", "bruddah": mate; "k" for OK); its words of the grammar: :mod:`pipflow.language.pidgin`
          ("mahalo",), ("mahalo", "nui"), ("mahalo", "nui", "loa"), ("aloha",), ("shoots",), ("brah",), ("bruddah",),
          ("k",),
          # Newfoundland English talk ("luh": look; "b'y": boy, said to anyone; "yes b'y"; "where ye to?":
          # how are you, where are you)
          ("luh",), ("b", "y"), ("yes", "b", "y"), ("where", "you", "to"),
          # the speaker too tired to do it themselves ("I haven't got it in me (today)", "I can't be
          # bothered"): why the robots are asked, nothing asked of them; and Scouse talk ("ta la":
          # thanks, lad; "ey": hey; "ar eh": aw, come on; "giz a hand": help me; "while youse are at it")
          ("i", "have", "not", "got", "it", "in", "me"), ("i", "have", "not", "got", "it", "in", "me", "today"),
          ("i", "can", "not", "be", "bothered"), ("i", "can", "not", "be", "arsed"),
          ("ta", "la"), ("la",), ("ey",), ("ar", "eh"), ("give", "a", "hand"), ("give", "us", "a", "hand"),
          ("while", "you", "are", "at", "it"), ("while", "you", "re", "at", "it"),
          ("can", "one", "of", "you"), ("could", "one", "of", "you"), ("will", "one", "of", "you"),
          ("while", "you", "are", "out", "there"), ("while", "you", "are", "there"), ("while", "you", "are", "up", "there"),
          ("while", "you", "are", "in", "there"), ("but", "tough"), ("tough", "luck"),
          # Yorkshire "while tha's up" (while you're on your feet), "tha knows" (you know)
          ("while", "you", "are", "up"), ("you", "knows"), ("ey", "up"),
          ("tenastelign",), ("tenastilign",), ("ameseginalehu",), ("ameseginalew",), ("ebakachihu",), ("ebakachuh",),
          ("wey", "gud"), ("gobez",), ("gobeze",), ("yikirta",), ("yiqirta",), ("tolo",), ("tolo", "tolo"),
          ("please",), ("kindly",), ("abeg",), ("biko",), ("just",), ("quickly",), ("now",), ("for", "me"), ("for", "us"), ("could", "you"),
          ("can", "you"), ("would", "you"), ("will", "you"), ("i", "need", "you", "to"), ("i", "want", "you", "to"),
          ("we", "need", "you", "to"), ("go", "ahead", "and"), ("go", "and"), ("hey",), ("robots",), ("team",),
          ("thanks",), ("thank", "you"), ("right", "away"), ("let", "us"), ("lets",), ("let", "s"),
          ("for", "me", "please"), ("me",), ("ok",), ("okay",), ("already",), ("again",),
          ("can", "someone"), ("could", "someone"), ("someone",), ("somebody",), ("can", "somebody"),
          ("us",), ("would", "you", "mind"), ("do", "you", "mind"), ("would", "you", "please"),
          # Hiberno-English "would you ever ...": a request, as "would you" is
          ("would", "you", "ever"),
          # Indian English: "do one thing, ..." opens a request, "..., na?" closes one, "what to
          # do" sighs; "on the dining table itself" stresses the place it follows
          ("do", "one", "thing"), ("na",), ("what", "to", "do"), ("itself",),
          # how a step is done, not how the home should end ("wash it nicely", "close it properly")
          ("nicely",), ("properly",), ("carefully",), ("gently",), ("thoroughly",), ("neatly",), ("tight",), ("tightly",),
          # Singapore English "anyhow" (carelessly: "don't anyhow touch"), a manner as "carefully" is
          ("anyhow",),
          ("could", "you", "please"), ("if", "you", "would"), ("if", "you", "could"),
          ("do", "not", "forget", "to"), ("remember", "to"), ("make", "sure", "to"), ("you", "can"),
          ("pls",), ("plz",), ("plse",), ("thx",), ("ta",), ("cheers",),
          ("while", "you", "are", "at", "it"), ("when", "you", "get", "a", "chance"), ("when", "you", "can"),
          *(("when", "you", verb, "a", time) for verb in ("get", "have") for time in ("minute", "moment", "sec", "second")),
          ("when", "you", "have", "a", "chance"), ("if", "you", "get", "a", "chance"),
          *((*whether, "no", "bother") for whether in (("if", "it", "is"), ("if", "its"))),
          *((*whether, "not", "too", "much", "bother") for whether in (("if", "it", "is"), ("if", "its"))),
          ("be", "a", "dear", "and"), ("be", "a", "love", "and"), ("be", "an", "angel", "and"), ("be", "a", "star", "and"),
          # formal requests ("would you be so kind as to ...", German "so nett sein und": "be so kind and")
          ("be", "so", "kind", "as", "to"), ("be", "so", "kind", "and"), ("be", "so", "good", "as", "to"),
          ("be", "so", "good", "and"), ("kindly", "be", "so", "kind", "as", "to"),
          ("while", "you", "are", "about", "it"), ("while", "you", "are", "there"), ("while", "you", "are", "over", "there"),
          ("while", "you", "are", "in", "there"), ("while", "you", "are", "up"), ("while", "you", "are", "passing"),
          ("while", "you", "are", "on", "your", "feet"), ("while", "you", "are", "over", "here"), ("if", "you", "get", "a", "chance"),
          ("honestly",), ("seriously",), ("even",), ("actually",),
          ("the", "two", "of", "you"), ("both", "of", "you"), ("you", "two"), ("you", "both"), ("all", "of", "you"),
          ("the", "pair", "of", "you"), ("you", "guys"), ("guys",), ("hang", "on"), ("hold", "on"),
          # texting: laughter, "right now", "real quick", and words of emphasis that grade nothing
          ("lol",), ("lmao",), ("haha",), ("hahaha",), ("rn",), ("right", "now"), ("real", "quick"),
          ("literally",), ("tbh",), ("btw",), ("fyi",), ("omg",), ("ugh",), ("ngl",),
          ("tho",), ("ty",), ("tysm",), ("lowkey",),
          # Ghanaian and South African English exclamations and Twi "please" ("Ei the sink!", "Chale
          # ...", "..., abi?", "mepa wo kyew", "yoo": all right), said beside the request
          ("ei",), ("eii",), ("chale",), ("abi",), ("yoo",), ("mepa", "wo", "kyew"), ("eish",), ("hayibo",),
          # South African English and Afrikaans beside the request ("ag, put the ...", "ja, and wash
          # ...", "nee man", "shame" for sympathy, "jislaaik"): no content
          ("ag",), ("ag", "man"), ("ag", "no"), ("ja",), ("ja", "nee"), ("nee", "man"), ("shame",), ("jislaaik",),
          ("yebo",), ("lekker",),
          # the team told or asked, by the one who talks to the assistant ("tell the robots to put
          # ..."): the request itself
          *((verb, who, "to") for verb in ("tell", "ask", "get") for who in ("them", "everyone")),
          *((verb, "the", who, "to") for verb in ("tell", "ask", "get") for who in ("robots", "robot", "team", "bots")),
          # Malaysian and Singapore English particles and exclamations ("wash them lah", "aiyo so
          # messy", "alamak"), "tq" (thank you), and "later" / "still", which say when, not what
          ("lah",), ("leh",), ("lor",), ("meh",), ("hor",), ("aiyo",), ("aiyoh",), ("aiya",), ("alamak",), ("wah",),
          ("eh",), ("tq",), ("later",), ("still",),
          # and their ways of asking: "can help (me) wash ...", "... or not", "... can already", "can or
          # not": the request itself
          ("can", "help", "me"), ("can", "help"), ("help", "me", "to"), ("or", "not"), ("can", "already"),
          ("can", "or", "not"),
          # Geordie: "howay" / "haway" (come on), "hinny" and "lads" said to the ones asked, "mind"
          # closing a remark ("it's heavy, mind"), "ye knaa" (you know)
          ("howay",), ("haway",), ("howay", "the", "lads"), ("hinny",), ("lads",), ("mind",), ("never", "mind"),
          ("you", "know"),
          # going to where the step is ("gan up and put the light on"), and "out of the way" after
          # where a thing goes ("in the wardrobe oot the road"): said, nothing of how the home ends
          ("go", "up", "and"), ("go", "down", "and"), ("go", "through", "and"), ("go", "upstairs", "and"),
          ("go", "downstairs", "and"), ("out", "the", "road"), ("out", "of", "the", "road"), ("out", "of", "the", "way"),
          # "don't you dare touch my leek": don't touch it
          ("you", "dare")}
#: endearments and praise that close or open a request ("..., there's a love", "..., there's a good
#: girl", "good lad, ..."): said to the one asked, they carry nothing; "mind you" / "mind and"
#: before a verb is "make sure you" (northern and Scots English: "and mind you shut the door after")
ENDEARMENTS = ("love", "dear", "pet", "duck", "darling", "sweetheart", "treasure", "angel", "star", "gem")
PRAISED = ("girl", "boy", "lad", "lass", "lassie", "laddie")
FILLER |= {("there", "is", "a", w) for w in ENDEARMENTS} | {("there", "is", "my", w) for w in ENDEARMENTS} \
    | {("there", "is", "a", "good", w) for w in PRAISED} | {("good", w) for w in PRAISED} \
    | {("mind", "you"), ("mind", "and"), ("make", "sure", "you")}
#: thanks said to the ones asked ("Thanks loves", "cheers pets", "ta darling") and the kisses that
#: sign a message off ("... in my bed x", "xx"): said to the robots, they carry nothing
FILLER |= {(thanks, w) for thanks in ("thanks", "cheers", "ta") for e in ENDEARMENTS for w in (e, e + "s")} \
    | {("thank", "you", w) for e in ENDEARMENTS for w in (e, e + "s")} | {("x",), ("xx",), ("xxx",)}
#: the one asked, named after a word said to them ("please son", "ta hen", "morning pal"): nothing
#: asked; alone, such a word may be someone's ("my son's bike"), so only after one of these
ADDRESSED = ENDEARMENTS + ("son", "hen", "mate", "pal", "sunshine", "bro", "dude", "buddy")
#: Cockney "me old china" (china plate: mate), "me old son", "me old mucker": the one asked
FILLER |= {(my, "old", who) for my in ("me", "my") for who in ("china", "son", "mucker", "mate", "cocker", "pal")}
FILLER |= {(said, who) for said in ("please", "pls", "plz", "thanks", "cheers", "ta", "morning", "hiya", "hello", "hi")
           for who in ADDRESSED}
#: who of the team is asked ("can one of you open the larder, and someone else light the fire",
#: "two of you lift the sack"): who does a step is the plan's choice, so the words are framing,
#: like "someone" above; a thing lifted by two is the team's way of working, not an end state
FILLER |= {tuple(f"{ask} {who}".split()) for ask in ("", "can", "could", "will", "would")
           for who in ("one of you", "two of you", "someone else", "somebody else", "one of the robots")}
#: when something happened or for how long, which says nothing of how the home should end
#: ("the console has been on all night", "last night's dishes"): dropped like politeness
TIME_WORDS = {("all", "night"), ("all", "day"), ("all", "evening"), ("all", "morning"), ("all", "afternoon"),
              ("all", "week"), ("for", "hours"), ("for", "ages"), ("for", "days"), ("last", "night"),
              ("yesterday",), ("this", "morning"), ("earlier",), ("since", "yesterday"), ("since", "breakfast"),
              ("since", "lunch"), ("since", "dinner"), ("overnight",), ("later", "on"),
              ("from", "last", "night"), ("since", "last", "night"), ("from", "yesterday"), ("this", "evening"), ("this", "afternoon"),
              ("today",),
              # what happened before, said as the reason ("don't leave it open like last time")
              ("like", "last", "time"), ("like", "the", "last", "time"), ("as", "last", "time"), ("last", "time"),
              # where the speaker is ("don't leave anything running down here"): the whole home
              ("down", "here"), ("up", "here")}
#: "since" or "from" a time of day, a meal or a day ("it's been sitting in the sink since the
#: morning", "there's grease on it since Sunday", "still dirty from lunch"): when it began, which
#: says nothing of how the home should end ("from the tea" may be where a teabag comes from)
SINCE_TIMES = ("morning", "afternoon", "evening", "breakfast", "lunch", "dinner", "tea", "supper", "weekend",
               "monday", "tuesday", "wednesday", "thursday", "friday", "saturday", "sunday")
TIME_WORDS |= {(since, *the, w) for since in ("since", "from") for the in ((), ("the",)) for w in SINCE_TIMES
               if since == "since" or w != "tea"} \
    | {(since, "last", w) for since in ("since", "from") for w in SINCE_TIMES + ("week", "night")}
FILLER |= TIME_WORDS
#: how the steps are to be run, not what the home should end like: a goal is the end state, and
#: the planner and the allocator decide the order and what runs in parallel. A clause made only of
#: "do" + what it does it to + one of these, or of one of these alone, is read as no condition
#: (a note says so); "first" / "firstly" opening a clause likewise
MANNERS = {("in", "parallel"), ("at", "the", "same", "time"), ("at", "once"), ("simultaneously",),
           ("in", "any", "order"), ("one", "after", "the", "other"), ("one", "by", "one"), ("in", "turn"),
           ("in", "that", "order"), ("in", "this", "order"), ("in", "order"), ("in", "sequence"),
           ("together",), ("either", "way"),
           # a thing lifted by two: how the robots work (the team decides who), not what the home ends like
           ("between", "you"), ("between", "you", "both"), ("between", "the", "two", "of", "you"),
           ("between", "them"), ("between", "the", "pair", "of", "you"), ("as", "a", "team"),
           # how fast ("do it quick quick", West African English doubles a word to stress it)
           ("quick",), ("quick", "quick"), ("fast",), ("fast", "fast"), ("sharp", "sharp"), ("quickly",),
           ("real", "quick"), ("real", "fast"), ("really", "quick"), ("really", "fast")}
MANNER_OBJECTS = {("both",), ("them",), ("it",), ("these",), ("those",), ("all",), ("everything",),
                  ("both", "of", "them"), ("all", "of", "them"), ("the", "two"), ("the", "lot"), ()}
ORDER_OPENERS = {"first", "firstly", "start", "to", "with"}
#: words that put a step first or last ("wash the mug first"): the order of the steps, which the
#: plan decides; an ordinal after a determiner ("the first banana") is no such word (refused)
ORDER_WORDS = {"first", "firstly", "last", "lastly", "second", "secondly"}
#: determiners after which "first" is an ordinal ("the first mug")
ORDINAL_DETERMINERS = {"the", "a", "an", "my", "your", "our", "this", "that", "its", "their", "his", "her"}
#: how long an action takes ("heat the curry for two minutes"): how, not what the home ends like;
#: "for" + (about / like / around / a few / a couple of)? + a number + one of these is dropped
DURATION_UNITS = {"second", "seconds", "sec", "secs", "minute", "minutes", "min", "mins", "hour", "hours", "hr", "hrs"}
DURATION_HEDGES = {"like", "about", "around", "roughly", "maybe", "a", "few", "couple", "of", "an", "another"}
#: containers people name an amount by ("a bowl of cherries", "a bag of flour"): no thing of the
#: home model holds another, so "a bowl of X" is some X; when the home has a thing named by the
#: container word itself (a bowl), it is refused: the bowl may be meant too
MEASURES = {"bowl", "bowlful", "plate", "plateful", "cup", "glass", "mug", "bag", "box", "basket", "tin", "can", "jar",
            "bottle", "handful", "pile", "stack", "bunch", "punnet", "packet", "pack", "tray", "dish", "carton",
            "crate", "sack", "pot", "jug", "tub", "heap", "load"}
#: "the quilt goes on the table for airing": what for, not what the home should end like: "for" +
#: a word of no verb of the lexicon in -ing, or one of these, at the end of a clause
PURPOSES = {("later",), ("tomorrow",), ("the", "morning"), ("the", "weekend"), ("now",), ("safekeeping",),
            ("safe", "keeping"), ("tea",), ("dinner",), ("lunch",), ("supper",), ("breakfast",), ("brunch",),
            ("guests",), ("the", "guests"), ("visitors",), ("the", "visitors"), ("tonight",), ("the", "party")}
#: words a purpose or its beneficiary is made of, in any order ("for tea tonight", "for my
#: breakfast", "for the little one", "for the kids"): meals, times and people who are no robot
PURPOSE_WORDS = {"later", "tomorrow", "morning", "weekend", "tonight", "today", "tea", "dinner", "lunch", "supper",
                 "breakfast", "brunch", "guests", "visitors", "party", "kids", "children", "baby", "little", "wee",
                 "one", "ones", "sandwich", "sandwiches",
                 # a packed lunch, said in the north of England ("for me snap", "for his bait")
                 "snap", "bait"}

#: "put it on the worktop to dry": what a thing is left somewhere for, which no robot does
PURPOSE_INFINITIVES = {"dry", "cool", "air", "soak", "defrost", "thaw", "drain", "rest", "settle", "soften", "drip",
                       "steep", "marinate", "breathe", "prove"}

#: filler words a misspelling may be read as ("plese"): only these, long and close to no
#: content word, so that a misspelt content word is never dropped as politeness
FILLER_TYPO_TARGETS = {"please", "thanks"}


def gerund(verb: str) -> str:
    """The -ing form of a one-word verb: slice -> slicing, put -> putting, open -> opening, fry ->
    frying ("would you mind putting", "the plate needs washing")."""
    if verb.endswith("ie"):
        return verb[:-2] + "ying"
    if verb.endswith("e") and not verb.endswith(("ee", "ye", "oe")):
        return verb[:-1] + "ing"
    vowels = "aeiou"
    groups = len(re.findall(r"[aeiou]+", verb))
    if groups == 1 and len(verb) >= 3 and verb[-1] not in vowels + "wxy" and verb[-2] in vowels \
            and verb[-3] not in vowels:
        return verb + verb[-1] + "ing"
    return verb + "ing"


#: verb classes whose -ing forms are the same word of the grammar
_VERB_CLASSES = {"V_STATE", "V_OPEN", "V_SHUT", "V_CLEAN", "V_WARM", "V_TOGGLE", "V_PUT", "V_THROW", "V_TRASH",
                 "V_CHILL", "V_TIDY", "V_PREPARE"}
for (_k, (_c, _v)) in list(PHRASES.items()):
    if _c in _VERB_CLASSES:
        _g = (gerund(_k[0]),) + _k[1:]
        if _g not in PHRASES:
            PHRASES[_g] = (_c, _v)


#: the words that name a state, after which "'s" is "is" (normalize)
_STATE_WORDS = sorted({w for w in ADJECTIVES} | {"on", "off"}, key=len, reverse=True)


#: an arrow typed or drawn ("->", "=>", "-->", "\u2192"): "to" between a thing and a place, "then"
#: after a clause ("tv on? -> turn it off"); an arrow that reads neither way is refused as a symbol
ARROW = re.compile(r"\s*(?:-+>|=+>|[\u2192\u27f6\u2794\u279c\u21d2])\s*")


def arrows_said_as(command: str, word: str) -> str:
    """The command with each arrow said as ``word``."""
    return ARROW.sub(f" {word} ", command)


#: the marks this reader reads besides ASCII letters, digits and white space (every other
#: character is refused before reading: :mod:`pipflow.language.characters`), each with its
#: reading: sentence and clause punctuation (. ; ! ? end a sentence, the ellipsis too); the
#: apostrophes of contractions and possessives; "-" and "_" inside names (a space), "-" before a
#: number (a minus sign: no count); quotes, brackets and dashes (nothing)
MARKS = frozenset("+&.,;:!?'\"()[]-_\u2018\u2019\u201c\u201d\u2010\u2011\u2012\u2013\u2014\u2015\u2026")


#: Appalachian English (eastern Kentucky, West Virginia) and the American South, written out:
#: "hit" for it ("set hit on the table", "hit's got a ring in it"), never before what a verb hits
#: ("hit the lights", "hit that switch"); "warsh" (wash), "'fore" (before), "acrost", "agin",
#: "ever'" (every), "het up" (heated up), "hisself", "might could" (could), "a-plenty"; "a-" before a
#: verb in -ing ("hit's a-wiltin'", "you're a-going by"); "yonder" (over there, in the other room);
#: "that pone of cornbread" (a loaf of it), "a mess of beans" (a helping): the thing; "fixing to"
#: (about to); "the television set" (the television)
_APPALACHIAN = ((r"(?<![\w'])hit(?=['\s.,;!?]|$)(?!\s+(?:the|a|an|that|this|those|these|them|my|our|your|his|her|"
                 r"their|it|me|him|us|some|every|all\s+the)\b)", "it"),
                (r"\bwarsh(?=(?:es|ed|ing)?\b)", "wash"),
                (r"(?<![\w'])'?fore(?=\s+(?:they|it|he|she|i|we|you|the|supper|dinner|lunch|breakfast|church|dark|"
                 r"bed|night|morning|noon)\b)", "before"),
                (r"\bacrost\b", "across"), (r"\bagin\b", "again"), (r"\bever'(?=\s)", "every"),
                (r"\bhet\s+up\b", "heated up"), (r"\bhisself\b", "himself"),
                (r"\bmight\s+(could|would|should)\b", r"\1"), (r"\ba-plenty\b", "plenty"),
                (r"\ba-(?=[a-z]{2,}ing\b)", ""), (r"\byonder\b", "there"),
                (r"\b(?:a|that|this|the)\s+(?:pone|mess)\s+of\s+(?=[a-z])", "the "),
                (r"\bfixing\s+to\b", "about to"), (r"\b(television|tv|telly)\s+set\b", r"\1"))


#: Yorkshire, then Appalachian, as written out: "reyt" (right: "Reyt, we're off up"); "put wood in
#: t'ole" (in the hole: shut the door); "switch the lights off, and don't forget the fire" (the fire
#: too, as a list goes on); "tha's" (you are: "while tha's up"; you have, before "got" or "been")
_DIALECTS = ((r"\breyt\b", "right"),
             (r"\bput\s+(?:the\s+)?wood\s+in\s+(?:the\s+)?h?ole\b", "shut the door"),
             (r"\b(?:do\s+not|don'?t)\s+forget\s+(?:about\s+)?(?=(?:the|my|our|your|that|this|those|these|me)\b)", ""),
             *_APPALACHIAN,
             (r"\btha['\u2019]?s\b(?=\s+(?:got|been)\b)", "you have"), (r"\btha['\u2019]s\b", "you are"))


#: texting and typing without apostrophes ("can u", "theyre", "itll", "isnt", "gonna"), written out
_TYPED = ((r"(?<!['\u2019])\bu\b", "you"),   # never the "u" of "pa'u" (Hawaiian: a glottal stop written in the word)
          # "ur" before where or how one is ("while ur there", "when ur done") is "you are", else "your"
          (r"\bur\s+(?=(?:there|here|up|done|passing|over|in|out|back|home|at|finished)\b)", "you are "),
          # "your" for "you're" after a word that opens a clause of time ("while your out there")
          (r"\b(while|whilst|when|once|if|as|since)\s+your\b(?=\s+(?:out|there|here|up|done|passing|over|at|in|back|"
           r"home|finished|going|on)\b)", r"\1 you are"),
          (r"\bur\b", "your"), (r"\br\b", "are"), (r"\bw\b(?=\s+(?:the|a|an|my|your|her|his|it|them)\b)", "with"),
          (r"\b(?:tmrw|tmr|tmrrw|2moro|2morrow)\b", "tomorrow"), (r"\b(they|you)re\b", r"\1 are"),
          # "were" typed for "we're" where it opens a clause ("were out of milk"), never after a subject
          # ("it were stood open": Yorkshire, was; "the lights were on")
          (r"(^|[.,;:!?]\s*|\b(?:and|so|then|but|because|cos|coz|if|when|while|as)\s+)were\b(?!\s+(?:you|we|they|the)\b)",
           r"\1we are"),
          (r"\b(it|that|there|what)ll\b", r"\1 will"), (r"\b(that|there|what)s\b", r"\1 is"), (r"\bim\b", "i am"),
          (r"\bive\b", "i have"), (r"\b(is|are|was|were|does|did|has|have|could|would|should)nt\b", r"\1 not"),
          (r"\bcant\b", "can not"), (r"\bgonna\b", "going to"), (r"\bwanna\b", "want to"), (r"\bgotta\b", "have to"),
          # speech: "em" for them ("stick em in the oven"), and "like" hedging after a preposition
          # ("at like four", "in like ten minutes")
          (r"\bem\b", "them"), (r"\b(at|in|for|about|around|by)\s+like\b", r"\1"),
          # "would ya", "can ya" (you, after a verb that asks); "outa", "outta" (out of)
          (r"\b(would|could|will|can|wont|do|did)\s+ya\b", r"\1 you"), (r"\bout(?:t?a)\b", "out of"),
          # texting "b4" (before); Irish and Scots "ye" (you, said to more than one: "can ye wash it")
          (r"\bb4\b", "before"), (r"\bye\b", "you"))


#: "wash my bowl its in the sink", typed without a mark: "it is" / "they are" (or "its" typed for
#: "it's") before where a thing lies opens a clause of its own, said apart with a comma; never after
#: a word that joins it to what comes before ("leave it where it is on ...", "and it's on ...")
_LOCATED_RUN_ON = re.compile(r"\b([a-z]+)\s+(it\s+is|it's|its|they\s+are|they're|theyre)\s+(?=(?:still\s+|just\s+|"
                             r"already\s+|now\s+)?(?:in|on|at|under|inside|by|beside|sitting|lying)\b)")
_JOINING = frozenset({"where", "wherever", "what", "whatever", "that", "if", "when", "whether", "because", "as", "so",
                      "and", "but", "or", "since", "while", "once", "until", "till", "cos", "think", "see", "know",
                      "sure", "say", "said", "unless", "though", "although"})


def _located_said_apart(m: re.Match) -> str:
    """:data:`_LOCATED_RUN_ON`'s clause, with a comma before it unless a joining word leads to it."""
    before, said = m.group(1), m.group(2)
    if before in _JOINING:
        return m.group(0)
    return f"{before} , {'it is' if said.startswith('it') else 'they are'} "


#: words that say how the room feels ("its freezing", "its gloomy"): cues of warmth, light, sound and air
_FEEL_WORDS = sorted({w for k, (cls, _) in PHRASES.items() if cls in ("TEMPCUE", "LIGHTCUE", "SOUNDCUE", "AIRCUE")
                      and len(k) == 1 for w in k}, key=len, reverse=True)


def normalize(text: str) -> str:
    """Lower case, contractions spelt out ("don't" -> "do not"), hyphens and underscores as
    spaces, so that "desk-lamp", "desk_lamp" and "desk lamp" read alike."""
    t = spoken_forms(text.replace("’", "'")).lower().replace("\u2026", "...")   # "burnin'", "'em"
    # a letter typed three times or more is stretched for feeling ("sooo hot", "pleaseee"): no
    # English word has one, so it is read once
    t = re.sub(r"([a-z])\1{2,}", r"\1", t)
    t = re.sub(r"\s*[+&]\s*", " and ", t)   # "noodles + curry", "salt & pepper"
    for said, written in _DIALECTS:
        t = re.sub(said, written, t)
    # northern English "an" for and ("wash t'pan an the mug", "an put it away"): "an" is the article
    # only before a vowel (or an "h" word: "an hour"), so before any other letter it joins
    t = re.sub(r"\ban(?=\s+(?:h(?:e|is|er|im|ers)\b|[bcdfgjklmnpqrstvwz]|(?:into|in|on|onto|out|up|off|over|under|it|its|if|"
               r"i|at|as|a|an|us|em|each|every|everything|any|anything|our|owt|after|again)\b))", "and", t)
    # a dash set off by spaces, or an en or em dash, is a pause, like a comma ("throw it away -
    # it smells off - and ..."); a hyphen inside a word joins it ("desk-lamp")
    t = re.sub(r"\s[-\u2010-\u2015]+\s|[\u2013\u2014\u2015]", " , ", t)
    t = re.sub(r"\b(don't|dont)\b", "do not", t)
    t = re.sub(r"\bdoesn't\b", "does not", t)
    t = re.sub(r"\bcan't\b|\bcannot\b", "can not", t)
    t = re.sub(r"\bwon't\b", "will not", t)
    # "it's" is "it is", except before a participle: "it's been on all night" is "it has been"
    t = re.sub(r"\b(it|that|there|what|who)'s\b(?!\s+(?:been|gone|got|become)\b)", r"\1 is", t)
    t = re.sub(r"\blet's\b", "let us", t)
    t = re.sub(r"(?<![\w'])'?t(is|was)\b", r"it \1", t)   # Irish and archaic "'tis", "'twas": it is, it was
    t = re.sub(r"'ve\b", " have", t)
    t = re.sub(r"'ll\b", " will", t)
    # "the oven's open", "the TV's still on": 's before a state word is "is", not a possessive
    # (not after a time: "last night's dirty dishes", "yesterday's cold tea" are possessives)
    t = re.sub(r"(?<!night)(?<!day)(?<!week)(?<!morning)(?<!evening)(?<!weekend)"
               r"'s(?=\s+(?:still\s+|not\s+|too\s+|very\s+|so\s+)?(?:" + "|".join(_STATE_WORDS) + r")\b)", " is", t)
    # "the melon's too heavy", "the room's ever so stuffy": a possessive is never followed by a degree
    t = re.sub(r"'s(?=\s+(?:too|very|so|really|quite|rather|ever so|absolutely|dead|proper|plumb|awfully|far too|way too|full|"
               r"covered|like)\s)", " is", t)
    # "its dead gloomy in there", typed without its apostrophe: "its" before a degree or a cue of
    # how the room feels is "it is" (a possessive is followed by a thing)
    t = re.sub(r"\bits(?=\s+(?:too|very|so|really|quite|rather|ever so|absolutely|dead|proper|awfully|far too|way too|"
               r"a bit|bit|" + "|".join(_FEEL_WORDS) + r")\b)", "it is", t)
    # "it's dead gloomy in there": after how the room feels, "in there" is the room spoken of, as "in
    # here" ("put the butter in there" stays where a thing goes)
    t = re.sub(r"\b(" + "|".join(_FEEL_WORDS) + r")\s+in\s+there\b", r"\1 in here", t)
    # a tag question closing a sentence asks nothing: "bit dark in here, isn't it?"
    t = re.sub(r",?\s*\b(?:is|isn't|isnt|are|aren't|arent|was|wasn't)\s*(?:n't\s+)?(?:it|they|not it)\s*(?=\?)", " ", t)
    t = re.sub(r",?\s*\binnit\b", " ", t)
    t = re.sub(r",?\s*\beh\b(?=\s*(?:[?.!]|$))", " ", t)   # "sort it out, eh?": a tag that asks nothing
    t = re.sub(r"\bye\b", "you", t)   # "could ye ...": the older and dialect "you"
    # Scots negatives: "I cannae see", "it wasnae me", "I'm no' sleeping" ("no" with its apostrophe)
    t = re.sub(r"\b(can|do|does|did|is|was|are|were|could|would|should|will|have|has|had|must)nae\b", r"\1 not", t)
    t = re.sub(r"\bdinnae\b", "do not", t)
    t = re.sub(r"\bdisnae\b", "does not", t)
    t = re.sub(r"\bno'(?=\s|$)", "not", t)
    t = re.sub(r"\bthon\b", "that", t)   # "thon frying pan": Scots "that"
    for typed, written in _TYPED:
        t = re.sub(typed, written, t)
    t = _LOCATED_RUN_ON.sub(_located_said_apart, t)
    # "its freezing in here", "its a tip": "it's" typed without its apostrophe, where a clause opens
    # and a word that never follows the possessive comes next ("its lid" stays a possessive)
    t = re.sub(r"(^|[.,;!?]\s*|\b(?:and|but|so|cos|because)\s+)its(?=\s+(?:so|too|very|really|quite|a|an|getting|"
               r"gone|been|still|not|[a-z]+ing|[a-z]+ed|" + "|".join(_STATE_WORDS) + r")\b)", r"\1it is", t)
    t = re.sub(r"'s(?=\s+(?:been|gone|got|become|left)\b)", " has", t)   # "the console's been on"
    # "the pan's still sat on the stove", "the mug's in the sink": where a thing is, "is"
    t = re.sub(r"'s(?=\s+(?:still\s+|just\s+|already\s+)?(?:sat|sitting|lying|stood|standing|in|on|inside)\s)", " is", t)
    t = re.sub(r"'s(?=\s+still\s+(?:been|gone|got)\b)", " has", t)   # "the table's still got ..."
    t = re.sub(r"'s(?=\s+[a-z]{3,}ing\b)", " is", t)   # "the watering can's leaking"
    t = re.sub(r"'s(?=\s+(?:still|already)\s+[a-z]{3,}ing\b)", " is", t)   # "the porch light's still burning"
    t = re.sub(r"\b(i|we|you)'d\b", r"\1 would", t)
    t = re.sub(r"\b(we|you|they)'re\b", r"\1 are", t)
    t = re.sub(r"\bi'm\b", "i am", t)
    t = re.sub(r"n't\b", " not", t)
    t = re.sub(r"'s\b", "", t)
    t = re.sub(r"(?<![\w-])-(?=\d)", "\0", t)   # a minus sign before a number is kept, not a hyphen
    t = t.replace("-", " ").replace("_", " ")
    return t.replace("\0", "-")


def words_of(text: str) -> list[str]:
    """Tokens: words, numbers and the punctuation that separates clauses. A signed or decimal
    number ("-2", "3.5") stays one token, which no count reads: it is refused, never read as 2."""
    return list(_tokens(text))


@functools.lru_cache(maxsize=8192)
def _tokens(text: str) -> tuple[str, ...]:
    """:func:`words_of`, kept: the names of a home's things are split into words again and again
    (every name index and every candidate reading), and :func:`normalize` is some forty regular
    expressions."""
    return tuple(re.findall(r"-?\d+(?:[.,]\d+)?|[a-z]+|[.,;!?:]", normalize(text)))


def plurals(phrase: str) -> list[str]:
    """English plural forms of a phrase's last word (enough for the names of things)."""
    if phrase.endswith("y") and not phrase.endswith(("ay", "ey", "oy", "uy")):
        return [phrase[:-1] + "ies"]
    if phrase.endswith(("s", "x", "ch", "sh", "z")):
        return [phrase + "es"]
    if phrase.endswith("o"):
        return [phrase + "es", phrase + "s"]
    if phrase.endswith("fe"):
        return [phrase[:-2] + "ves", phrase + "s"]
    return [phrase + "s"]

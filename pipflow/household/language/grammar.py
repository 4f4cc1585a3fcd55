"""The grammar of household command English, for lark's Earley parser.

Written over token classes, not words: the tagger (:mod:`pipflow.household.language.parser`) turns the
command into a sequence of classes from the lexicon (:mod:`pipflow.household.language.lexicon`) and the
world's names (``NOUN``), so the grammar is the same for every home. ``@CLASS`` below stands for
a class *or* that class doubling as a world name: a word such as "trash" or "microwave" is a verb
in "trash the mug" and a place in "put the mug in the trash"; the tagger emits ``V_TRASH__NOUN``
and the parse decides. Earley keeps every reading of an ambiguous sentence; the translator
resolves each, and refuses when they mean different things (never a silent pick).

The sentence shapes: clauses joined by "and", "then", commas; a clause is a change of state
("slice the bread", "heat the egg in the microwave"), a switch ("turn off the TV"), a move ("put
the pen on the desk", with gapping: "and the pillow on the bed"), a put-away, a trash, a wanted
state ("leave the fridge open", "the TV should be off"), an observation ("the desk lamp is on")
or a state cue ("nobody is reading", "we do not need the TV anymore", "it is too bright"), a
negated wish ("don't leave the fridge open": the other polarity) or a meal ("make me a salad",
whose foods the resolver finds through the lexicon's ``MEALS`` and the world's affordances).
"""
from __future__ import annotations

from pipflow.household.language.lexicon import PHRASES

_RULES = r"""
start: _sep* (_when _sep*)? item (_sep+ item | _sep* thengap | _sep+ _when _sep* item | _sep* _when)* _sep*
_when: once | onceat
_sep: COMMA | END | @AND | @THEN | @BUT | @EXCL

?item: change | toggle | put | gap | away | trash | chill | request | unwant | ensure | observe | cue | meal | after | reason
      | tend | notvia | usevia
      | keep
      | empty
      | desire
      | handling

change: _vstate (@UP | @OUT)? things @PIECES? via? exception? _here?
      | _vstate things @UP via? exception?
      | @V_CLEAN things via? exception?
      | @V_GIVE things @ACT
_vstate: @V_STATE | @V_OPEN | @V_SHUT | @V_WARM
via: (@IN | @ON | @WITH | @AT) (place | placeref)

toggle: @V_TOGGLE onoff tthings _here?
      | @V_TOGGLE tthings onoff _here?
      | @V_SHUT off tthings
      | @V_SHUT tthings off
      | @V_TOGGLE typo_off tthings
      | @V_SHUTDOWN tthings
      | _vput tthings on
      | @V_TOGGLE tthings onoff (@AND | COMMA @AND) tthings _here?
      | _vput tthings on (@AND | COMMA @AND) tthings
      | @V_LIGHT tthings _here?
      | _vput tthings @GOING
      | @V_SHUT tthings @DOWN @ANYMORE?
typo_off: @OF
tthings: tnp ((COMMA | @AND | COMMA @AND) tnp)*
tnp: sel (@SWITCHPART | @V_TOGGLE)? where? exception?
onoff: on | off
on: @ON
off: @OFF | @OUT

put: _vput @UP? things source? target? exception?
   | _vput @UP? things _particle target source?
   | _vput @UP? things _particle source target?
   | _wish things target
   | _vput @UP? things target source
   | _vput @OUT things | _vput things @OUT
   | _vput @UP? things source @AND target
   | _vput @UP? things @AWAY? target (@AND | COMMA @AND) things
   | _vput things @AWAY target
   | sthings @SHOULD? (@GOES | @BE) target
   | @SHOULD sthings (@GOES | @BE) target
   | _vput @AWAY things target
   | sthings (@NEED | @WANT) @V_PUT source? target source?
   | @V_LEAVE things target
   | @V_LEAVE things _particle target
   | @V_TIDY @UP? things target
   | _vput @UP? things _particle? target wherewas
   // "take the bag off the bed and the book off the table": each thing with where it is taken off
   | _vput @UP? offthings target?
_vput: @V_PUT | @V_THROW
_particle: @OUT | @DOWN | @IN | @UP
source: @FROM place | @OUT @OF? place | @OFF @OF? place
target: _prep place | @SOMEWHERE? bare | _prep placeref
      | _prep @THEWASH
placeref: @IT
_prep: @IN | @ON | @TO | @AT | @BACK @IN | @BACK @ON | @BACK @TO
place: @THE? noun
bare: noun

gap: things target
   | things _particle target
   | things onoff
   | things @TOO
thengap: @THEN things -> gap

away: @V_PUT @AWAY things | @V_PUT things @AWAY | @V_PUT things @BACK | @V_PUT @BACK things
    | @V_TIDY @UP? things | @V_TIDY things @UP? | @V_CLEAN @UP things | @V_CLEAN things @UP
    | @V_TIDY things @AWAY | @V_TIDY @AWAY things

chill: @V_CHILL things
trash: @V_TRASH sthings | @V_THROW @AWAY sthings | @V_THROW things @AWAY | @V_THROW things @OUT

request: @V_LEAVE things state
       | @V_MAKE things state
       | @SUBJ? (@WANT | @NEED) things (@TO @BE)? state @UP?
       | sthings @SHOULD @BE? state @TOO?
       | sthings @NEED state @UP?
       | sthings @WANT state @UP?
       | sthings @NEED @ACT
unwant: @DONOT @V_LEAVE things state
      | sthings @SHOULD @NOT @BE? state
      | @LEFT things state
      | sthings @LEFTAS state
ensure: @V_MAKE @SURE @THAT? wish ((COMMA | @AND | COMMA @AND) wish)*
wish: sthings (@IS | @SHOULD @BE) not? state
not: @NOT
state: @ADJ | @V_OPEN | @V_SHUT | @V_CLEAN | @V_WARM | @V_STATE | on | off | @TOGGLED onoff | @V_TOGGLE onoff
     | @GOING

after: @ONCE @SUBJ @HAVE? state things
once: @ONCE sthings @IS state
onceat: @ONCE sthings @IS (@THERE | (@IN | @ON) place)
wherewas: @STAY
reason: @IT @IS (@INTENS | @TOO)* @REASON | @SUBJ @IS @REASON | @REASON
meal: (@V_MAKE | @V_PREPARE | _vstate) @THE? @MEAL _here?
    | (@V_MAKE | @V_PREPARE) @THE? @V_STATE _here?
    | @SUBJ? (@WANT | @NEED) @THE? @MEAL

observe: sthings @IS @INTENS* state _here?
       | sthings _here @IS state
       | sthings @FOULS

cue: @NOBODY @IS? activity (@TO | @ON | @AT)? things? @ANYMORE?
   | @NOBODY @IS? (@INROOM | _here) @ANYMORE?
   | @SUBJ? @DONOT @NEED things (on | @ANYMORE)?
   | @NOBODY @NEED things @ANYMORE?
   | @SUBJ? @IS? @DONE things @ANYMORE?
   | @SUBJ @HAVE? @FINISHED activity things?
   | sthings @IS @NOT @NEEDED @ANYMORE?
   | @IT @IS (@INTENS | @TOO)* tempcue _here? (@WITH @THAT? things (@GOING | on))?
   | @IT @IS (@INTENS | @TOO)* tempadj _here (@WITH @THAT? things (@GOING | on))?
   | @SUBJ @IS (@INTENS | @TOO)* (tempcue | tempadj) _here?
   | @IT @IS (@INTENS | @TOO)* lightcue _here?
   | @IT @IS (@INTENS | @TOO)* lightcue near
   | @IT @IS (@INTENS | @TOO)* lightcue _here? _doact
   | _wish _doact things? _here?
   | @SUBJ @IS? @SLEEPCUE
   | @SUBJ @CANNOT @SEE things? _here?
   | @IT @IS (@INTENS | @TOO)* soundcue _here?
   | @IT @IS (@INTENS | @TOO)* soundcue _here? @WITH @THAT? things (@GOING | on)?
   | @SUBJ @CANNOT @HEARCUE _here? (@WITH @THAT? things (@GOING | on)?)?
   | @IT @IS (@INTENS | @TOO)* aircue (_here | room)?
   | sthings @IS (@INTENS | @TOO)* soundcue
   | (_wish | _vput) @FRESHAIR _here?
   | @HAVE _music
   | @IT @IS (@INTENS | @TOO)* closecue (_here | room)
   | @ROOMSAID @IS (@INTENS | @TOO)* (tempcue | tempadj | lightcue | soundcue | aircue | closecue)
   | (@V_MAKE @IT | @SUBJ? @WANT @IT (@TO @BE)? | @SHOULD @IT @BE) (@INTENS | @TOO)* @MORE (_here | room)?
   | @IT @IS (@INTENS | @TOO)* (tempcue | tempadj | lightcue | soundcue) room
   | @IT @IS (@INTENS | @TOO)* (tempcue | tempadj | lightcue | aircue) inplace
   | @SUBJ @IS (@INTENS | @TOO)* (tempcue | tempadj) room
   | _vput _music on
   | @V_TOGGLE on _music
   | @V_PLAY _music
   | _wish _music
   | _wish @THE? @HOTDRINK @ANYMORE?
   | (@V_MAKE | @V_PREPARE) @THE? @HOTDRINK
activity: @ACTIVITY
lightcue: @LIGHTCUE
near: @NEAR+ place
soundcue: @SOUNDCUE
aircue: @AIRCUE
closecue: @V_STATE
hearcue: @HEARCUE
room: @INROOM
inplace: (@IN | @AT | @ON) @THE? place
_wish: @SUBJ? (@WANT | @NEED)
_doact: @TO (@DOACT | @SEE)
_music: @THE? @MUSIC
_here: @HERE
     | @ALLOVER
     | @THERE
tempcue: @TEMPCUE
tempadj: @ADJ

notvia: @NOT via
usevia: @V_USE @THE? place

tend: @V_TEND @OUT? things | @V_TEND things @OUT
    | sthings @IS? @MESS -> mess
    | sthings @IS? @ALLOVER -> mess
    | @LEFT things (@OUT | @ALLOVER) -> mess
    | @LEFT things @OUT? (@ON | @IN) place -> mess
    | sthings @IS? @LYING (@ON | @IN) place -> mess
    | sthings @IS @CLUTTER place -> mess
    | sthings @NEED @DOING
    | place @HASGOT things (@ON | @IN) @IT -> mess
    | @THERE @IS sthings (@MESS | @ALLOVER) -> mess
    | @THERE @IS sthings @ALLOVER place -> mess
    | sthings @IS? @ALLOVER place -> mess
    | (place | @ROOMSAID) @IS @FULLOF things -> mess
    | @ROOMSAID @IS? @MESS -> roommess

keep: @V_LEAVE things @STAY
    | @V_LEAVE things @THERE
    | @DONOT @V_TOUCH things
handling: sthings @IS (@INTENS | @TOO)* @HANDLING @FORONE?
        | sthings @TAKESTWO
empty: @V_EMPTY @OUT? place target?
desire: _wish @THE? adj+ noun

things: np ((COMMA | @AND | COMMA @AND) np)*
      | @BOTH np @AND np
np: sel exception?
offthings: offnp ((COMMA | @AND | COMMA @AND) offnp)+
offnp: sel @OFF @OF? place
sthings: snp ((COMMA | @AND | COMMA @AND) snp)*
snp: sel where? exception?
exception: COMMA? @EXCEPT things
sel: quant? @OF? @THE? count? adj* noun @DOOR? rel?
   | @EVERYTHING where?
   | @EVERYTHING rel
   | @THE @THING where?
   | @THE @THING rel
   | quant? @OF? @IT
   | @THE adj+ @ONES
   | @BOTH
   | @THE @DOOR
quant: @ALL | @EVERY | @BOTH
count: NUM @OF? | NUM @UNIT | NUM @OF @THE
adj: @ADJ | @V_CLEAN | @V_WARM | @V_OPEN | @V_SHUT
rel: @THAT @IS state | @THAT @IS where | @FROM place
where: (@IN | @ON) place
noun: NOUN__
"""

NOUN_DUAL = "__NOUN"


def base_class(cls: str) -> str:
    """The lexicon class of a token class: a dual class (a lexicon word that is also a name of the
    world, ``V_TRASH__NOUN``) without its twin mark."""
    return cls[:-len(NOUN_DUAL)] if cls.endswith(NOUN_DUAL) else cls


def classes() -> list[str]:
    """Every token class of the lexicon (plus the punctuation and number classes)."""
    return sorted({cls for cls, _ in PHRASES.values()})


def grammar_text(dual: frozenset[str] | None = None) -> str:
    """The lark grammar: ``@C`` expanded to ``(C | C__NOUN)``, ``NOUN__`` to ``NOUN`` and every
    dual class; the terminals are declared (a custom lexer supplies them). ``dual``: only these
    classes get a ``__NOUN`` twin (the classes whose words are also names of the world at hand):
    each twin is one more alternative wherever a noun may stand, which Earley pays for at every
    noun position of every command, so a grammar for one world carries only the twins it needs."""
    text = _RULES
    twins = classes() if dual is None else sorted(dual)
    duals = [c + NOUN_DUAL for c in twins]
    for c in sorted(classes(), key=len, reverse=True):
        text = text.replace("@" + c, f"({c} | {c}{NOUN_DUAL})" if c in twins else c)
    text = text.replace("NOUN__", " | ".join(["NOUN"] + duals))
    terminals = ["NOUN", "NUM", "COMMA", "END"] + classes() + duals
    return text + "\n%declare " + " ".join(terminals) + "\n"

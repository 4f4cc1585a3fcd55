"""The household resolver: a pure function of (order, world) -> goal conditions, with reasons.

An order (``schemas/household_order.schema.json``) says what the command means in words of the
world: *which* things (selectors: a name, a category, "all ... except ...", "the dirty mug", "it",
"everything on the sofa", "3 school supplies") and *what* about them (a state, a place, away,
trashed, a cue). This module decides which objects those are in this world and whether the
request can be met, and explains each goal condition with the words it came from, so a user can
see a misunderstanding before robots move.

Rules it applies (docs/household.md lists them for users):

* a named thing that cannot take a state is a :class:`Refusal` ("the mug cannot be sliced"); a
  category ("wash the dishes") means its members the action applies to;
* a selector by state or place that matches nothing is a Refusal that says what holds instead
  ("no dirty bowl: the bowl is clean"); a singular that matches several things is a
  :class:`TranslationError` asking which;
* "heat the egg in the microwave": the egg is hot *and* in the microwave (where it was heated),
  so no plan heats it on the stove; the place must afford the action (a heater, a sink);
* a state no action of the domain reaches (``dirty``, ``cold``, ``whole``) is kept where it holds
  and refused where it does not;
* state cues ("nobody is reading") set the state of what the sentence names, else of what the
  command observed ("the desk lamp is on"), else of the cue's category in the world ("light");
* a condition named for one thing overrides the same condition implied for its whole category
  ("switch off the lights but leave the desk lamp on"); two named conditions that clash are an
  error.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Callable

from pipflow.errors import PipflowError, Refusal, TranslationError
from pipflow.household.language.lexicon import (BIN_KINDS, COLD, DEVICE_NOUNS, DEVICES, INDEFINITE, LAUNDRY,
                                                LAUNDRY_PLACES, LIGHT_CATEGORY_WORD, LIGHTS, MASS_NOUNS, MEALS, OPPOSITE,
                                                REACHABLE, ROOM_WORDS, RUBBISH_KINDS, VIA_PROPERTY, WINDOWS, plurals,
                                                words_of)
from pipflow.household.language.nearness import nearest
from pipflow.household.language.order import check_order
from pipflow.household.problem import CONDITIONS
from pipflow.household.world import entity, initial_state, members

_FLAG = {"is-open": "open", "is-on": "on", "dirty": "dirty", "sliced": "sliced", "hot": "hot"}


#: the words that lead a room said as where a cue is felt ("out in the conservatory", "in our lounge")
_ROOM_LEADS = {"out", "over", "up", "down", "back", "in", "the", "my", "our"}


#: the rooms of a home in words (lexicon ``ROOM_WORDS``), longest first
_ROOMS = sorted((words_of(r) for r in ROOM_WORDS), key=len, reverse=True)


def _room_said(room: str) -> list[str]:
    """The words of a room said with a cue, without the words that lead to it; "in my room" is
    "my" (what the home calls mine: "my heater")."""
    said = words_of(room)
    while said and said[0] in _ROOM_LEADS - {"my", "our"}:
        said = said[1:]
    if len(said) == 2 and said[0] in ("my", "our") and said[1] in ("room", "bedroom"):
        return said[:1]
    while said and said[0] in _ROOM_LEADS:
        said = said[1:]
    return said


def _choice(error: TranslationError, words: str, names: list[str]) -> TranslationError:
    """The error with what it asks to choose among: ``choices`` = (the words that name several
    things, their names), from which the refusal's candidate readings are built
    (:mod:`pipflow.household.language.candidates`)."""
    error.choices = (words, list(names))  # type: ignore[attr-defined]
    return error


def _raise(error: Exception) -> None:
    raise error


def holds_now(world: dict, name: str, cond: str) -> bool:
    """Whether a state condition holds in the world as it is (before any plan)."""
    pred, positive, _ = CONDITIONS[cond]
    return (name in initial_state(world)[_FLAG[pred]]) == positive


def applies(world: dict, name: str, cond: str) -> bool:
    return CONDITIONS[cond][2] in entity(world, name)["properties"]


#: prepositions that say only where a thing goes, never where a change is made ("to the counter")
_DESTINATIONS = {"to", "into", "onto", "towards", "toward"}


def _moved_to(target: dict, cond: str) -> bool:
    """Whether an elided verb after a change of state to ``cond`` is a move to ``target``: no
    place makes a thing so ("open", "on"), or the place is said with a preposition of
    destination only ("wash the pot, the cup to the desk")."""
    return VIA_PROPERTY.get(cond) is None or (target.get("words", "").split() or [""])[0] in _DESTINATIONS


def _describe(world: dict, name: str) -> str:
    """The states an entity is in, in words ("dirty, off")."""
    words = [c for c in CONDITIONS if applies(world, name, c) and holds_now(world, name, c)]
    return ", ".join(words) or "in no particular state"


@dataclass
class _Condition:
    cond: str
    explicit: bool
    words: str


@dataclass
class _Goal:
    inside: dict[str, tuple[str, str]] = field(default_factory=dict)       # object -> (place, words)
    state: dict[str, dict[str, _Condition]] = field(default_factory=dict)  # name -> predicate -> condition
    count: list[dict] = field(default_factory=list)
    notes: list[str] = field(default_factory=list)


class Resolver:
    """One order in one world; see the module docstring."""

    def __init__(self, world: dict, choose: dict[str, str] | None = None):
        self.world = world
        #: words that name several things -> the one a user chose among them (a candidate reading)
        self.choose = dict(choose or {})
        self.goal = _Goal()
        self.last: list[str] = []
        self.picked: dict[str, str] = {}          # objects taken with no place yet -> words
        self.observed: list[tuple[list[str], str, str]] = []   # (names, state, words), unused so far
        self.previous: dict | None = None                      # the statement an elided verb repeats
        self.last_places: list[str] = []                       # the places of the statement before
        self.last_any: list[str] = []                          # everything the statement before named
        self.before: list[str] = []                            # what "in it" may mean in this statement
        self.history: list[list[str]] = []                     # what each statement before named, in order
        # (category, state, words, members, whether a room said where)
        self.cue_defaults: list[tuple[str, str, str, list[str], bool]] = []
        self.wanting_light: set[str] = set()                   # words of a cue for light, said of no place
        self.via_placed: dict[str, str] = {}                   # objects put where an action happens -> place
        self.said: list[list[str]] = []                        # the things each statement before was about
        # disorder said of things: (statement, words, what "it" / "they" stood for when it was said)
        self.mess: list[tuple[dict, str, list[str]]] = []
        self.foul: set[str] = set()                            # words of observations of foulness
        self.gone_cold: set[str] = set()                       # words of "X has gone cold"
        # a cue of warmth decided at the end: (state, words, what to do when no request answers it)
        self.unanswered: list[tuple[str, str, Callable[[], None]]] = []
        self.handled: list[tuple[list[str], str]] = []         # how things are to be handled: (names, words)
        self.excepted: list[tuple[list[str], str]] = []        # things left out of a selection: (names, words)

    # selectors -------------------------------------------------------------------------
    def _candidates(self, sel: dict, words: str, prop: str | None = None) -> tuple[list[str], bool]:
        """Names a selector's noun may mean, and whether they come from a category (implicit);
        ``prop``: what the statement will ask of them."""
        if sel.get("ones"):
            raise TranslationError(f"'{words}': '{sel['words']}' of what? (name the things)")
        if sel.get("door") and "noun" not in sel:
            # "put the milk in the fridge and close the door": the door of the place that opens
            # named last ("take the egg out of the fridge, put it on the counter and close the door")
            for said in reversed(self.history):
                doors = [n for n in dict.fromkeys(said) if "openable" in self.world["places"].get(n, {}).get("properties", [])]
                if doors:
                    break
            else:
                doors = []
            if len(doors) != 1:
                raise TranslationError(f"'{words}': which door? (say 'the fridge door')")
            return doors, False
        if sel.get("pronoun") and sel.get("both") and len(self.last) != 2:
            # "heat the tomato and slice the lettuce, then put both on the table": the two things of
            # the statements before, when they add up to exactly two
            two: list[str] = []
            for things in reversed(self.said):
                two = list(dict.fromkeys(things + two))
                if len(two) >= 2:
                    break
            if len(two) != 2:
                raise TranslationError(f"'{words}': which two things does '{sel['words']}' mean?")
            return two, False
        if sel.get("pronoun"):
            if not self.last and not self.last_places:
                raise TranslationError(f"'{words}': '{sel['words']}' refers to nothing said before it")
            return list(self.last or self.last_places), False
        if sel.get("everything"):
            if "from" in sel:
                return list(self.world["objects"]), True
            if sel.get("state"):   # "everything that is on": every thing of the home in that state
                return list(self.world["objects"]) + list(self.world["places"]), True
            raise TranslationError(f"'{words}': '{sel['words']}' needs a place or a state "
                                   "(e.g. 'everything on the sofa', 'everything that is on')")
        readings = sel["noun"]["readings"]
        named = [r for r in readings if r["kind"] in ("object", "place")]
        if named and ("from" in sel or prop == "pickupable") and all(r["kind"] == "place" for r in named) and \
                any(r["kind"] == "category" for r in readings):
            # "there's trash all over the coffee table" where "trash" is the trash can and the
            # rubbish: no place lies in another, and no place is carried, so the word is the category
            named = []
        if named:
            return list(dict.fromkeys(r["name"] for r in named)), False
        out: list[str] = []
        for r in readings:
            out += members(self.world, r["name"])
        return list(dict.fromkeys(out)), True

    def select(self, sel: dict, words: str, *, cond: str | None = None, prop: str | None = None) -> tuple[list[str], bool]:
        """The world names a selector means (module docstring); ``cond``/``prop``: what the
        statement will ask of them (a category keeps the members it applies to)."""
        if sel.get("everything") and "from" not in sel and not sel.get("state") and cond in ("on", "off"):
            # "turn everything off": every thing of the home that switches (only for on/off: "clean
            # everything" or "put everything in the fridge" without a place or state is asked)
            names, implicit = list(self.world["objects"]) + list(self.world["places"]), True
        else:
            names, implicit = self._candidates(sel, words, prop)
        what = sel["words"]
        if sel.get("unit") and not implicit:   # "a piece of bread": no piece is a thing of the home model
            raise TranslationError(f"'{words}': '{what}': pieces of one thing are not things of this home; "
                                   "name the thing")
        if implicit and sel.get("det") == "some" and "count" not in sel:
            raise TranslationError(f"'{words}': how many of '{sel['noun']['words'] if 'noun' in sel else what}'? "
                                   "('some' does not say; give a number, or 'all')")
        need = CONDITIONS[cond][2] if cond else prop
        if sel.get("pronoun") and need and self.last_places and \
                not any(need in entity(self.world, n)["properties"] for n in names):
            # "put the apple in the fridge, then close it": the apple cannot be closed, the
            # place of the sentence before can; the pronoun means what the action applies to
            places = [p for p in self.last_places if need in entity(self.world, p)["properties"]]
            if places:
                self.goal.notes.append(f"'{words}': '{sel['words']}' read as {', '.join(places)}")
                names = places
        if sel.get("pronoun") and need and names and not any(need in entity(self.world, n)["properties"] for n in names):
            # "open the sideboard, get the plate out onto the table, then shut it again": neither the
            # plate nor the table shuts; the nearest statement before that named exactly one thing
            # that does is what "it" means (two such things there: left as said, and refused)
            for said in reversed(self.history):
                fit = [n for n in dict.fromkeys(said) if need in entity(self.world, n)["properties"]]
                if len(fit) == 1:
                    self.goal.notes.append(f"'{words}': '{sel['words']}' read as {fit[0]} (the one thing said before "
                                           f"that can be {cond or need})")
                    names = fit
                if fit:
                    break
        if sel.get("door") and not all("openable" in entity(self.world, n)["properties"] for n in names):
            raise TranslationError(f"'{words}': '{what}' has no door in this world")
        names = self._narrow(sel, words, names, implicit)
        if not implicit and len(names) == 1 and "count" not in sel and self._plural_of_one(sel, names[0]):
            # "the pans are filthy" where one thing is called a pan: the plural says more than one
            # is meant, and which others is a guess (the casserole? the wok?)
            raise TranslationError(f"'{words}': '{what}' is plural, but only {names[0]} is called so in this "
                                   f"world; say which things")
        if implicit and need and "count" not in sel:
            fit = [n for n in names if need in entity(self.world, n)["properties"]]
            if not fit:
                raise Refusal(f"'{words}': nothing of '{what}' can be {cond or 'picked up'} "
                              f"({', '.join(names) or 'there is none'})")
            left = [n for n in names if n not in fit]
            if left:   # said, so that a user sees what "all the devices" came to
                self.goal.notes.append(f"'{words}': {', '.join(left)} of '{what}' cannot be "
                                       f"{cond or 'picked up'}; left as {'it is' if len(left) == 1 else 'they are'}")
            names = fit
        plural = sel.get("all") or sel.get("everything") or sel.get("pronoun") or \
            any(r.get("plural") for r in (sel.get("noun") or {}).get("readings", []))
        if implicit and not plural:
            # a category named in the singular: a mass ("the fruit", bare "light") means all of
            # it; otherwise it names one thing ("the lamp"), asked back when there are several
            plural = sel.get("det") is None or sel["noun"]["words"].split()[-1] in MASS_NOUNS
        if sel.get("count") == 0:
            raise TranslationError(f"'{words}': '{what}' is a count of 0, which asks for nothing; say what to do")
        if "count" in sel:
            if implicit:
                return names, True   # the caller turns a category count into a count condition
            n = sel["count"]
            if n != len(names):
                raise TranslationError(f"'{words}': '{what}' asks for {n} of {len(names)} things named so "
                                       f"({', '.join(names)}); say which")
        elif not plural and len(names) > 1 and self.choose.get(what) in names:
            names = [self.choose[what]]
        elif not plural and len(names) > 1:
            raise _choice(TranslationError(f"'{words}': '{what}' could be any of {', '.join(names)}; say which"),
                          what, names)
        if sel.get("both") and len(names) != 2:
            raise TranslationError(f"'{words}': 'both' but '{what}' are {len(names)} things")
        if not names:
            raise Refusal(f"'{words}': nothing in this world is '{what}'")
        return names, implicit

    def _plural_of_one(self, sel: dict, name: str) -> bool:
        """Whether a selector names one thing in the plural of a one-word kind word that is not
        its name ("the pans" for frying_pan, whose words list "pan": the casserole may be a pan
        too), and the thing is no food (named in the plural for one portion). The plural of a
        thing's name or of a longer word for it ("them horn mugs", "the jugs of water") means it."""
        noun = sel.get("noun") or {}
        readings = noun.get("readings") or []
        if not readings or not all(r.get("plural") for r in readings) or sel.get("all") or sel.get("everything"):
            return False
        e = entity(self.world, name)
        if {"sliceable", "heatable"} & set(e.get("properties") or ()):
            return False
        said, own = noun.get("words", ""), " ".join(words_of(name))
        listed = {" ".join(words_of(x)) for x in e.get("words") or []}
        kinds = [w for w in listed if " " not in w and w != own]
        return said not in listed | {own} and any(said in plurals(k) for k in kinds)

    def _narrow(self, sel: dict, words: str, names: list[str], implicit: bool) -> list[str]:
        """The names a selector keeps of ``names`` by where they are ("from"), their states and
        its exceptions; refused when nothing is left of a place or a state."""
        what = sel["words"]
        if "from" in sel:
            place = self.place_of(sel["from"], words)
            there = [n for n in names if n in self.world["objects"] and self.world["objects"][n]["in"] == place]
            if not there and not _holds_things(self.world, place):
                # "the lounge is full of toys" where "lounge" names only the lounge light: a thing
                # that holds nothing was read as where, a reading gone wrong, never an impossible order
                raise TranslationError(f"'{words}': {place} holds nothing, so '{what}' cannot be in it; "
                                       "say where they are")
            if not there:
                where = ", ".join(f"{n} is in {self.world['objects'][n]['in']}" for n in names if n in self.world["objects"])
                raise Refusal(f"'{words}': nothing of '{what}' is in {place}" + (f" ({where})" if where and not implicit else ""))
            names = there
        for st in sel.get("state") or []:
            if st == "whole" and not any(applies(self.world, n, st) for n in names):
                continue   # "the whole veranda", "the whole house": all of it, of things that are never sliced
            ok = [n for n in names if applies(self.world, n, st) and holds_now(self.world, n, st)]
            if not ok:
                now = "; ".join(f"{n} is {_describe(self.world, n)}" for n in names[:4])
                raise Refusal(f"'{words}': nothing matches '{what}' in this world" + (f" ({now})" if now else ""))
            names = ok
        for ex in sel.get("except") or []:
            if ex.get("ones"):   # "all the dishes except the clean ones"
                out = [n for n in names if all(applies(self.world, n, c) and holds_now(self.world, n, c)
                                               for c in ex.get("state") or [])]
            else:
                out, _ = self.select(ex, words)
            missing = [n for n in out if n not in names]
            if missing:
                raise TranslationError(f"'{words}': '{ex['words']}' is not one of '{what}'")
            names = [n for n in names if n not in out]
            if not ex.get("ones"):
                self.excepted.append((out, words))
        return names

    def place_of(self, place: dict, words: str) -> str:
        """The one place a place phrase names (a category of places with one member counts)."""
        if place.get("quality") == COLD:   # "chill the juice": the home's one cold place
            cats = [c for c, e in (self.world.get("categories") or {}).items()
                    if c == COLD or any(COLD in words_of(w) for w in ((e or {}).get("words") or []))]
            cold = [m for c in cats for m in members(self.world, c) if m in self.world["places"]]
            if len(set(cold)) != 1:
                raise TranslationError(f"'{words}': this home has {len(set(cold))} cold places; say where")
            return cold[0]
        if place.get("quality") == LAUNDRY:   # "put the clothes in the wash": the home's one laundry place
            wanted = {" ".join(words_of(w)) for w in LAUNDRY_PLACES}
            found = [p for p, e in self.world["places"].items()
                     if {" ".join(words_of(w)) for w in [p] + list(e.get("words") or [])} & wanted]
            if len(found) != 1:
                raise TranslationError(f"'{words}': this home has {len(found)} places for laundry "
                                       f"({', '.join(found) or 'no laundry basket or washing machine'}); say where")
            return found[0]
        if place.get("pronoun"):
            said = [n for n in dict.fromkeys(self.before) if n in self.world["places"]]
            if len(said) != 1:
                raise TranslationError(f"'{words}': which place does '{place['words']}' mean?")
            return said[0]
        names = []
        for r in place["readings"]:
            if r["kind"] == "place":
                names.append(r["name"])
            elif r["kind"] == "category":
                names += [m for m in members(self.world, r["name"]) if m in self.world["places"]]
        names = list(dict.fromkeys(names))
        if not names:
            raise TranslationError(f"'{words}': '{place['words']}' is not a place of this world")
        if len(names) > 1 and self.choose.get(place["words"]) in names:
            names = [self.choose[place["words"]]]
        if len(names) > 1:
            raise _choice(TranslationError(f"'{words}': '{place['words']}' could be {', '.join(names)}; say which"),
                          place["words"], names)
        return names[0]

    # goal building -----------------------------------------------------------------------
    def set_state(self, name: str, cond: str, explicit: bool, words: str) -> None:
        pred = CONDITIONS[cond][0]
        have = self.goal.state.setdefault(name, {})
        old = have.get(pred)
        if old is not None and old.cond != cond:
            if old.explicit and not explicit:
                self.goal.notes.append(f"{name} stays {old.cond} ('{old.words}' names it; '{words}' means its kind)")
                return
            if explicit and not old.explicit:
                self.goal.notes.append(f"{name}: {cond} ('{words}' names it; '{old.words}' meant its kind)")
            elif explicit and old.explicit and old.words != words:
                # a sequence: "open the fridge, take out the milk ... and close the fridge"
                self.goal.notes.append(f"{name} ends {cond}: '{words}' comes after '{old.words}'")
            else:
                raise TranslationError(f"the command asks for {name} to be both {old.cond} ('{old.words}') "
                                       f"and {cond} ('{words}')")
        if old is None or old.cond != cond or (explicit and not old.explicit):
            have[pred] = _Condition(cond, explicit, words)

    def keep_states(self, name: str, words: str) -> None:
        """The states the world file writes for a thing, held as they are now ("don't touch my
        cooler": it stays dirty); a state it leaves unwritten is no part of what was said."""
        written = (self.world["objects"][name].get("state") or {})
        for cond, (pred, _, _) in CONDITIONS.items():
            if _FLAG[pred] in written and applies(self.world, name, cond) and holds_now(self.world, name, cond):
                old = self.goal.state.get(name, {}).get(pred)
                if old is not None and old.cond != cond and old.explicit:
                    raise TranslationError(f"the command asks for {name} to be {old.cond} ('{old.words}') "
                                           f"and left as it is, {cond} ('{words}')")
                self.set_state(name, cond, True, words)

    def put(self, obj: str, place: str, words: str) -> None:
        if obj not in self.world["objects"]:
            # "something's gone off in the fridge, get rid of it": what "it" names there is the
            # fridge, a fixture of the home; what is meant is not said (it crashed: KeyError)
            raise TranslationError(f"'{words}': {obj} is part of the home, no thing to move; say which thing")
        old = self.goal.inside.get(obj)
        if old is not None and old[0] != place and self.via_placed.get(obj) == old[0]:
            # "heat the egg in the microwave, then bring it to the table": the microwave is where
            # it was heated, the table where it ends; the microwave is left as found
            via = self.via_placed.pop(obj)
            self.goal.notes.append(f"{obj} ends in {place} ('{words}'), after '{old[1]}' (the goal is the end "
                                   f"state: that it was first in {via}, where the change is done, is not part of it)")
            del self.goal.inside[obj]
            if "openable" in self.world["places"][via]["properties"] and not holds_now(self.world, via, "open"):
                self.set_state(via, "closed", False, old[1])
            old = None
        if old is not None and old[0] != place:
            raise TranslationError(f"the command puts {obj} both in {old[0]} ('{old[1]}') and in {place} ('{words}')")
        props = self.world["places"][place]["properties"]
        if "receptacle" not in props and "garbage" not in props:
            raise Refusal(f"'{words}': nothing can be put in {place}: it is not a receptacle")
        if "pickupable" not in self.world["objects"][obj]["properties"] and self.world["objects"][obj]["in"] != place:
            raise Refusal(f"'{words}': {obj} cannot be picked up")
        self.goal.inside[obj] = (place, words)
        self.picked.pop(obj, None)

    def want(self, name: str, cond: str, explicit: bool, words: str) -> None:
        if not applies(self.world, name, cond):
            if explicit:
                raise Refusal(f"'{words}': {name} cannot be {cond}: it is not {CONDITIONS[cond][2]} in this world")
            return
        if cond not in REACHABLE and not holds_now(self.world, name, cond):
            raise Refusal(f"'{words}': nothing in this home makes {name} {cond} (it is {_describe(self.world, name)})")
        self.set_state(name, cond, explicit, words)

    # statements --------------------------------------------------------------------------
    @staticmethod
    def counted(sel: dict) -> dict | None:
        """The selector with its count: "3 school supplies", or "a fruit" (one of a category)."""
        if "count" in sel:
            return sel
        readings = (sel.get("noun") or {}).get("readings", [])
        if sel.get("det") in INDEFINITE and readings and all(r["kind"] == "category" and not r["plural"] for r in readings):
            return {**sel, "count": 1}
        return None

    def _the_counted(self, sel: dict, names: list[str], words: str, need: str | None) -> list[str]:
        """ "wash the two plates": "the" with a count names every one of the things so called (that
        the clause can act on), as many as said; where there are more or fewer, which is asked."""
        if need:
            req = CONDITIONS[need][2] if need in CONDITIONS else need
            names = [n for n in names if req in entity(self.world, n)["properties"]]
        if len(names) != sel["count"]:
            raise TranslationError(f"'{words}': '{sel['words']}' asks for {sel['count']} of {len(names)} things "
                                   f"called so ({', '.join(names) or 'none'}); say which")
        return names

    def objects(self, things: list[dict], words: str, *, cond: str | None = None, prop: str | None = None,
                exceptions: list[dict] | None = None) -> list[tuple[str, bool]]:
        """(name, named explicitly?) of every thing the selectors mean, less the exceptions said
        after the whole clause ("... but not the watermelon")."""
        out: list[tuple[str, bool]] = []
        for sel in things:
            names, implicit = self.select(sel, words, cond=cond, prop=prop)
            if "count" in sel and implicit and sel.get("det") == "the":
                names, implicit = self._the_counted(sel, names, words, cond or prop), False
            if "count" in sel and implicit:
                raise TranslationError(f"'{words}': a count of '{sel['noun']['words']}' only makes sense with a "
                                       "place to gather them")
            out += [(n, not implicit) for n in names]
        for ex in exceptions or []:
            if ex.get("ones"):
                gone = [n for n, _ in out if all(applies(self.world, n, c) and holds_now(self.world, n, c)
                                                 for c in ex.get("state") or [])]
            else:
                gone, _ = self.select(ex, words)
                self.excepted.append((gone, words))
            if gone and not set(gone) & {n for n, _ in out}:
                # "wash the teacup and the glass, but not the saucer": a reminder of what not to do
                self.goal.notes.append(f"'{words}': '{ex['words']}' was not asked for; nothing is done to it")
            elif not set(gone) <= {n for n, _ in out}:
                raise TranslationError(f"'{words}': '{ex['words']}' is not among the things the clause names")
            out = [(n, e) for n, e in out if n not in gone]
        return list(dict.fromkeys(out))

    def repeat(self, st: dict) -> dict:
        """The statement an elided verb stands for: the one before, with these things (and the
        place or state the gap names): "put the pen on the desk and the pillow on the bed",
        "turn the lamp off and the stove on", "heat the egg and the bread too"."""
        prev, words = self.previous, st["words"]
        out = {"things": st["things"], "words": words}
        if "state" in st:
            return {**out, "op": "change", "to": st["state"]}
        if prev is None or prev["op"] in ("observe", "cue"):
            if "to" in st:
                return {**out, "op": "put", "to": st["to"]}
            raise TranslationError(f"'{words}': which action? (nothing before it to repeat)")
        if prev["op"] == "change" and "to" in st and (_moved_to(st["to"], prev["to"]) or (
                any(t.get("from") for t in st["things"]) and not self._makes(st["to"], prev["to"], words))):
            # "open the fridge, the pot to the counter": no place makes a thing open, and "to" says
            # where a thing goes; "warm the bread, the yoghurt from the fridge on the table": a thing
            # said with where it comes from, to a place that heats nothing; the elided verb is a move
            # ("wash the cup on my desk": the desk says which cup)
            return {**out, "op": "put", "to": st["to"]}
        place = self._only_a_destination(st, prev["to"], words) if prev["op"] == "change" and "to" in st else None
        if place and self._made_so_before(st, words):
            # "wash the teapot. Teapot in the cupboard": the things were made so by the clause
            # before, and this place makes nothing so: it says where they go
            return {**out, "op": "put", "to": st["to"]}
        if place and prev.get("via"):
            # "heat the tortillas on the comal, and the tortillero on the mesa": the change was made
            # at a place of its own, this place makes nothing so, and the things are not there:
            # heated there is impossible, moved there is likely; which is asked, never refused as
            # impossible nor guessed
            raise TranslationError(f"'{words}': made {prev['to']} too, or put in {place}? ({place} makes nothing "
                                   f"{prev['to']}); say which")
        if prev["op"] == "change":
            via = st.get("to") or prev.get("via")
            if "to" not in st and via and self._via_said_which(prev, st, words):
                raise TranslationError(f"'{words}': made {prev['to']} in {self.place_of(via, words)} too, or only "
                                       f"made {prev['to']}? ('{prev['words']}': the things already lie there, so the "
                                       "place may say which were meant); say which")
            return {**out, "op": "change", "to": prev["to"], **({"via": via} if via else {})}
        if prev["op"] == "put":
            to = st.get("to") or prev.get("to")
            if to is None:
                raise TranslationError(f"'{words}': where to? name a place (e.g. 'in the fridge')")
            return {**out, "op": "put", "to": to}
        if "to" in st and prev["op"] == "trash":
            return self._trash_gap(st, out)
        if "to" in st:
            return {**out, "op": "put", "to": st["to"]}
        return {**out, "op": prev["op"]}

    def _makes(self, target: dict, cond: str, words: str) -> bool:
        """Whether the place said makes a thing ``cond`` (a heater heats, a sink washes); True
        where it names no one place (then the change reading is left to refuse or ask)."""
        try:
            place = self.place_of(target, words)
        except TranslationError:
            return True
        return VIA_PROPERTY[cond] in self.world["places"].get(place, {}).get("properties", [])

    def _only_a_destination(self, st: dict, cond: str, words: str) -> str | None:
        """The place of an elided verb's things, after a change to ``cond``, where it can only say
        where they go: it makes nothing ``cond`` and none of the things named lies there (where one
        does, the place may say which things are meant: "wash the cup on my desk"); else None."""
        if self._makes(st["to"], cond, words):
            return None
        place = self.place_of(st["to"], words)
        try:
            named = [n for n, _ in self.objects(st["things"], words)]
        except TranslationError:
            return None
        return place if named and all(self.world["objects"].get(n, {}).get("in") != place for n in named) else None

    def _made_so_before(self, st: dict, words: str) -> bool:
        """Whether every thing of an elided verb's clause is one the clause before changed."""
        named = [n for n, _ in self.objects(st["things"], words)]
        return bool(named) and set(named) <= set(self.last)

    def _via_said_which(self, prev: dict, st: dict, words: str) -> bool:
        """ "wash the bowl in the sink and the mug too", the bowl in the sink already: "in the sink"
        may say where the washing is done, or which bowl is meant; the two readings differ for the
        gap's things where they lie elsewhere (put in the sink, or only washed)."""
        try:
            place = self.place_of(prev["via"], prev["words"])
            before = [n for n, _ in self.objects(prev["things"], prev["words"])]
            now = [n for n, _ in self.objects(st["things"], words)]
        except TranslationError:
            return False
        lies = self.world["objects"]
        return bool(before and now) and all(lies.get(n, {}).get("in") == place for n in before) and \
            any(lies.get(n, {}).get("in") != place for n in now)

    def _trash_gap(self, st: dict, out: dict) -> dict:
        """ "throw the chip paper away, and the stale bread in the larder": after a throwing away,
        the place of an elided verb's things says where they are (thrown away too) or where they
        go (put there). Where every thing is already in that place a move would do nothing, so the
        place says which things are meant; else the two readings differ and it is asked."""
        words = st["words"]
        place = self.place_of(st["to"], words)
        named = [n for n, _ in self.objects(st["things"], words)]
        if named and all(self.world["objects"].get(n, {}).get("in") == place for n in named):
            self.goal.notes.append(f"'{words}': already in {place}, so the place says which things are thrown away")
            return {**out, "op": "trash"}
        raise TranslationError(f"'{words}': thrown away too, or put in {place}? say which")

    def statement(self, st: dict) -> None:
        if st["op"] == "repeat":
            st = self.repeat(st)
        self.previous = st
        op, words = st["op"], st["words"]
        self.before = self.last_any + self.last_places   # what "in it" may mean in this statement
        if self.before:
            self.history.append(self.before)
        self.last_any = []
        self._statement(st, op, words)
        self.said.append(list(self.last))
        if op != "observe":   # "the oven is open, close it": the observation was the reason
            acted = set(self.last) | set(self.last_any)
            self.observed = [o for o in self.observed if not set(o[0]) <= acted]
        # a pronoun after this statement may mean its place ("... in the fridge, then close it")
        self.last_places = [self.place_of(st[k], words) for k in ("to", "via", "from") if isinstance(st.get(k), dict)]

    def _statement(self, st: dict, op: str, words: str) -> None:
        """One statement's goal conditions (the op's rules in the module docstring)."""
        if op == "change":
            self.change(st, words)
        elif op == "put":
            self.move(st, words)
        elif op == "put_away":
            named = self.objects(st["things"], words, prop="pickupable")
            for n, _ in named:
                homes = [self.world["categories"][c]["home"] for c in entity(self.world, n)["categories"]
                         if (self.world["categories"].get(c) or {}).get("home")]
                if not homes:
                    raise TranslationError(f"'{words}': {n} has no home in this world (no category of it names one)")
                self.put(n, homes[0], words)
            self.last = [n for n, _ in named]
        elif op == "trash":
            cans = self._garbage()
            if len(cans) != 1:
                raise TranslationError(f"'{words}': the world has {len(cans)} garbage places; say which")
            named = self.objects(st["things"], words, prop="pickupable")
            for n, _ in named:
                self.put(n, cans[0], words)
            self.last = [n for n, _ in named]
        elif op == "observe":
            names = [n for n, _ in self.objects(st["things"], words)]
            for n in names:
                if CONDITIONS.get(st["is"]) and applies(self.world, n, st["is"]) and not holds_now(self.world, n, st["is"]):
                    self.goal.notes.append(f"'{words}': the world file says {n} is {_describe(self.world, n)}")
            weather = st["is"] in ("hot", "cold") and all(sel.get("pronoun") for sel in st["things"])
            if names and set(names) <= set(self.goal.inside) | set(self.goal.state) and not weather:
                # ("..., it is cold" may be the room: not read as a reason)
                # "bin the scone, it's gone stale": said after what is done with it, it is the reason
                self.goal.notes.append(f"'{words}' is the reason for what is done with {', '.join(names)}")
                self.last = names
                return
            self.observed.append((names, st["is"], words))
            if st.get("foul"):
                self.foul.add(words)
            if st.get("gone"):
                self.gone_cold.add(words)
            self.last = names
        elif op == "cue":
            self.cue(st, words)
        elif op == "meal":
            self.meal(st, words)
        elif op == "tend" and st.get("said"):   # decided at the end: a later clause may answer it
            self.mess.append((st, words, self.last))
            self.last = [n for n, _ in self.objects(st["things"], words)]
        elif op == "tend":
            self.tend(st, words)
        elif op == "handling":   # "the wok is too heavy for one of you": the reason for how a later clause is done
            names = [n for n, _ in self.objects(st["things"], words)]
            self.handled.append((names, words))
            self.last = names
        elif op == "keep":   # "leave the hoodie where it is"
            named = self.objects(st["things"], words)
            for n, _ in named:
                if n not in self.world["objects"]:
                    raise TranslationError(f"'{words}': {n} is a place; it stays where it is whatever is done")
                if st.get("there") and n in self.goal.inside:
                    continue   # "put the fish in the freezer and leave it there": where the command puts it
                self.put(n, self.world["objects"][n]["in"], words)
                if st.get("as_is"):
                    self.keep_states(n, words)
            self.last = [n for n, _ in named]
        else:
            raise TranslationError(f"'{words}': unknown statement {op!r}")

    def change(self, st: dict, words: str) -> None:
        cond = st["to"]
        st, named = self._via_as_where_things_are(st, words)
        if named is None:
            named = self.objects(st["things"], words, cond=cond, exceptions=st.get("except"))
        else:   # the place said which things: a verb elided after this clause repeats no place
            self.previous = st
        if st.get("once"):
            self.once(named, cond, words)
            return
        self.last_any = [n for n, _ in named]
        for n, _ in named:
            if n in self.picked:   # "pick up the phone and switch it on": the taking was the means
                self.goal.notes.append(f"'{self.picked.pop(n)}' says no place for {n}: it ends where the plan leaves it")
        via = None
        if st.get("via"):
            via = self.place_of(st["via"], words)
            need = VIA_PROPERTY.get(cond)
            if need is None:
                raise TranslationError(f"'{words}': '{st['via']['words']}' does not say how something becomes {cond}")
            if need not in self.world["places"][via]["properties"]:
                raise Refusal(f"'{words}': {via} cannot make anything {cond}: it is not a {need}")
        need = VIA_PROPERTY.get(cond)
        for n, explicit in named:
            if st.get("phrasal") and not applies(self.world, n, cond):
                # "put the afghan on" is no switching: wearing it, or covering someone, is not read
                raise TranslationError(f"'{words}': {n} has no switch, and 'put on' is read only as switching on")
            self.want(n, cond, explicit, words)
            held = self.goal.inside.get(n)
            if via is None and held is not None and need and need in self.world["places"][held[0]]["properties"] \
                    and n not in self.via_placed:
                # "take the mug to the sink, wash it, then put it away": where it was taken is where
                # the change happens, so a later move may take it on from there
                self.via_placed[n] = held[0]
            if via is not None:
                if n not in self.world["objects"]:
                    raise Refusal(f"'{words}': {n} cannot be moved into {via}")
                self.put(n, via, words)
                self.via_placed[n] = via
        self.last = [n for n, _ in named] or self.last

    def _via_as_where_things_are(self, st: dict, words: str) -> tuple[dict, list[tuple[str, bool]] | None]:
        """ "wash the plate on the coffee table": a place that cannot make the things so (no sink)
        but holds them now says which ones, as "the plate that is on the coffee table" does: (the
        statement without its "via", the place moved to the things' words; the things it names).
        Anything else is (the statement, None), left for :meth:`change` to read and refuse (the
        place cannot make anything so)."""
        need = VIA_PROPERTY.get(st["to"])
        if not isinstance(st.get("via"), dict) or st["via"].get("pronoun") or need is None:
            return st, None
        via = self.place_of(st["via"], words)
        if need in self.world["places"][via]["properties"] or any(t.get("from") for t in st["things"]):
            return st, None
        things = [{**t, "from": st["via"]} for t in st["things"]]
        try:
            named = self.objects(things, words, cond=st["to"], exceptions=st.get("except"))
        except PipflowError:
            return st, None
        if not named:
            return st, None
        one = len(named) == 1
        self.goal.notes.append(f"'{st['via']['words']}' says which: where {', '.join(n for n, _ in named)} "
                               f"{'is' if one else 'are'} now, not where {'it becomes' if one else 'they become'} "
                               f"{st['to']}")
        return {k: v for k, v in st.items() if k != "via"} | {"things": things}, named

    def once(self, named: list[tuple[str, bool]], cond: str, words: str) -> None:
        """ "wash the bowl and the mug, and once they are clean put them away": a state that an
        earlier step of the command asks of the same things is when the next step may start (the
        plan's order), no condition of its own. A state nothing earlier asks is a condition on the
        home ("once the TV is off, ..."), which this reader does not make: refused."""
        pred = CONDITIONS[cond][0]
        unasked = [n for n, _ in named if (self.goal.state.get(n, {}).get(pred) is None
                                           or self.goal.state[n][pred].cond != cond)]
        if unasked or not named:
            raise TranslationError(f"'{words}': a condition on the home ({', '.join(unasked) or 'it'} {cond}) that "
                                   "no step before asks for; say what to do, not when")
        self.goal.notes.append(f"'{words}': what an earlier step does; the plan orders the steps")
        self.last = [n for n, _ in named]

    def once_there(self, st: dict, words: str) -> None:
        """ "clear the desk onto the settee, and switch the laptop off once it is there": where an
        earlier step of the command puts the things is when (the plan's order), no condition; a
        place no step before puts them in is a condition on the home: refused."""
        named = [n for n, _ in self.objects(st["things"], words)]
        place = self.place_of(st["to"], words) if st.get("to") else None
        unput = [n for n in named if n not in self.goal.inside or (place and self.goal.inside[n][0] != place)]
        if unput or not named:
            raise TranslationError(f"'{words}': a condition on the home ({', '.join(unput) or 'it'} "
                                   f"{'in ' + place if place else 'there'}) that no step before brings about; say "
                                   "what to do, not when")
        self.goal.notes.append(f"'{words}': what an earlier step does; the plan orders the steps")
        self.last = named

    def where_it_was(self, names: list[str], place: str, said: str, words: str) -> None:
        """ "put the teacake out on the bar where it was": "where it was" restates the place; "it"
        is what this statement moves or what the statement before was about. Read when one of them
        is in that place now (a restatement the world confirms), else refused: where it was is then
        not where the command puts it."""
        referents = list(dict.fromkeys(names + (self.said[-1] if self.said else [])))
        there = [n for n in referents if n in self.world["objects"] and self.world["objects"][n]["in"] == place]
        if not there:
            was = ", ".join(f"{n} is in {self.world['objects'][n]['in']}" for n in referents
                            if n in self.world["objects"])
            raise TranslationError(f"'{words}': '{said}' is not {place} ({was}); say where")
        self.goal.notes.append(f"'{said}': {place}, where {', '.join(there)} is now (a restatement of the place)")

    def move(self, st: dict, words: str) -> None:
        if st.get("once"):
            self.once_there(st, words)
            return
        counted = [c for c in (self.counted(s) for s in st["things"] if not s.get("pronoun")) if c is not None]
        plain = [s for s in st["things"] if self.counted(s) is None]
        if "from" in st:
            plain = [{**s, "from": st["from"]} if "from" not in s and not s.get("pronoun") else s for s in plain]
        named = self.objects(plain, words, prop="pickupable", exceptions=st.get("except"))
        if st.get("from") and any(s.get("pronoun") for s in plain):
            place = self.place_of(st["from"], words)
            for n, _ in named:
                if self.world["objects"].get(n, {}).get("in") != place:
                    raise Refusal(f"'{words}': {n} is not in {place}")
        if "to" not in st:
            if counted:
                raise TranslationError(f"'{words}': where to? name a place (e.g. 'in the fridge')")
            for n, _ in named:
                self.picked[n] = words
            self.last = [n for n, _ in named]
            return
        place = self.place_of(st["to"], words)
        if st["to"].get("prep") == "on" and "openable" in self.world["places"][place]["properties"]:
            raise TranslationError(f"'{words}': things go in {place}, not on it; the top of {place} is no place "
                                   "of this world")
        for sel in counted:
            names, implicit = self.select(sel, words, prop="pickupable")
            if not implicit:
                for n in names:
                    self.put(n, place, words)
                continue
            cats = [r["name"] for r in sel["noun"]["readings"] if r["kind"] == "category"]
            able = [n for n in names if n in self.world["objects"]
                    and "pickupable" in self.world["objects"][n]["properties"]]
            if len(able) < sel["count"]:
                raise Refusal(f"'{words}': the world has only {len(able)} {sel['noun']['words']} that can be "
                              f"picked up, not {sel['count']}")
            if len(cats) != 1 or sel.get("state") or sel.get("except") or sel.get("from"):
                raise TranslationError(f"'{words}': a count of '{sel['words']}' can only name a whole category")
            self.goal.count.append({"category": cats[0], "in": place, "at_least": sel["count"]})
        if st.get("as_was"):
            self.where_it_was([n for n, _ in named], place, st["as_was"], words)
        for n, _ in named:
            if n not in self.world["objects"]:
                raise Refusal(f"'{words}': {n} is not something that can be moved")
            self.put(n, place, words)
        self.last = [n for n, _ in named] or self.last

    def room_heaters(self) -> list[str]:
        """The things that warm the room (lexicon ``ROOM_HEATERS``)."""
        return self.devices("heating")

    def devices(self, kind: str, cond: str = "on") -> list[str]:
        """The things of a kind of lexicon ``DEVICES`` (room heaters, sound makers, drink makers):
        members of a category of the world named or worded so, else things whose name or words
        are so or end so ("salon fan", "kids' room aircon": what is said before the kind word says
        where, or which); only those that can be ``cond`` (switched on; "hot": a kettle that heats)."""
        wanted = {" ".join(words_of(w)) for w in DEVICES[kind]}
        cats = [c for c, e in (self.world.get("categories") or {}).items()
                if {" ".join(words_of(w)) for w in [c] + list((e or {}).get("words") or [])} & wanted]
        found = [n for c in cats for n in members(self.world, c)] or self.called(DEVICES[kind])
        return [n for n in dict.fromkeys(found) if applies(self.world, n, cond)]

    def called(self, kind_words: tuple[str, ...]) -> list[str]:
        """The things whose name or words are one of ``kind_words`` or end with one ("salon fan",
        "kids' room aircon": what is said before the kind word says where, or which)."""
        wanted = {" ".join(words_of(w)) for w in kind_words}
        return [n for n, e in {**self.world["places"], **self.world["objects"]}.items()
                if any(said in wanted or any(said.endswith(f" {w}") for w in wanted)
                       for said in {" ".join(words_of(w)) for w in [n] + list(e.get("words") or [])})]

    def device_cue(self, st: dict, words: str) -> None:
        """ "it's too quiet in here", "put some music on": the home's sound makers; "could murder a
        cuppa": its drink makers (lexicon ``DEVICES``). Switching off, every one that is on;
        switching on, the one that is off when there is one, and several are asked (each offered
        as a candidate reading), never all at once. None: asked."""
        kind, cond = st["device"], st["to"]
        if st["things"]:   # "I can't hear myself think with that radio blaring": what is named
            named = self.objects(st["things"], words, cond=cond)
            for n, explicit in named:
                self.want(n, cond, explicit, words)
            self.last = [n for n, _ in named]
            return
        if kind == "air":
            self.air_cue(st, words)
            return
        every = self.devices(kind)
        if kind == "hot drink" and cond == "on" and not every and self._stovetop_kettle(words):
            return
        able = [n for n in every if not holds_now(self.world, n, cond)]
        self._room(st, able, words)
        if st.get("room") and len(able) > 1:
            able = [self.choose[words]]
        if not able:
            raise TranslationError(f"'{words}': which thing? this home has no {DEVICE_NOUNS[kind]} "
                                   f"{'that is ' + ('on' if cond == 'off' else 'off') + ' ' if every else ''}"
                                   f"({', '.join(DEVICES[kind][:4])} that switches); say what to switch")
        if cond == "on" and len(able) > 1:
            if self.choose.get(words) in able:
                able = [self.choose[words]]
            else:
                raise _choice(TranslationError(f"'{words}': which one? it could be any of {', '.join(able)}; say "
                                               "which to switch on"), words, able)
        self.goal.notes.append(f"'{words}': read as {', '.join(able)} {cond} (the home's {kind} "
                               "things; docs/household.md, cues)")
        for n in able:
            self.want(n, cond, False, words)
        self.last = able

    def _stovetop_kettle(self, words: str) -> bool:
        """A hot drink wished for where no drink maker switches, but one heats (a kettle put on a
        stove): that one hot. True when read; several such are asked, none leaves the caller's
        refusal."""
        heated = self.devices("hot drink", cond="hot")
        if not heated:
            return False
        if len(heated) > 1:
            raise _choice(TranslationError(f"'{words}': which one? it could be any of {', '.join(heated)}; "
                                           "say which to heat"), words, heated)
        self.goal.notes.append(f"'{words}': read as {heated[0]} hot (a drink maker that heats, none that "
                               "switches; docs/household.md, cues)")
        self.want(heated[0], "hot", False, words)
        self.last = heated
        return True

    def air_cue(self, st: dict, words: str) -> None:
        """ "it's stuffy in here": the air wants moving: a fan (lexicon ``FANS``) that is off, on, or
        a window (``WINDOWS``) that is closed, open. One such thing: it; several: asked, each
        offered as a candidate reading (a fan and a window are two answers two people would not
        agree on); none: asked."""
        windows = self.windows("closed")
        options = {n: "on" for n in self.devices("air") if not holds_now(self.world, n, "on")}
        options.update({n: "open" for n in windows})
        # decided at the end: "open a window, it's stuffy" asks the window; the cue is its reason
        self.unanswered.append(("", words, lambda: self._air(st, options, words)))

    def _air(self, st: dict, options: dict[str, str], words: str) -> None:
        """:meth:`air_cue`, when no request of the command answers the cue."""
        asked = [n for n, c in options.items() if any(x.cond == c and x.explicit and x.words != words
                                                      for x in self.goal.state.get(n, {}).values())]
        if asked:
            self.goal.notes.append(f"'{words}' is the reason for {', '.join(asked)} {options[asked[0]]}")
            return
        if not options:
            raise TranslationError(f"'{words}': which thing? this home has no fan that is off or window that is "
                                   "closed; say what to do")
        names = list(options)
        self._room(st, names, words)
        if st.get("near") and len(names) > 1:   # "it's stuffy in the salon": what is nearest it
            names = nearest(self.world, names, self.place_of(st["near"], words))
        if len(names) > 1:
            if self.choose.get(words) in options:
                names = [self.choose[words]]
            else:
                raise _choice(TranslationError(f"'{words}': which? it could be {' or '.join(f'{n} {options[n]}' for n in names)}; "
                                               "say which"), words, names)
        n = names[0]
        self.goal.notes.append(f"'{words}': read as {n} {options[n]} (the air wants moving; docs/household.md, cues)")
        self.want(n, options[n], False, words)
        self.last = [n]

    def windows(self, now: str) -> list[str]:
        """The windows of the home (lexicon ``WINDOWS``: a thing that opens, named or worded so) that
        are ``now`` (open or closed) in the world as it is."""
        wanted = {" ".join(words_of(w)) for w in WINDOWS}
        return [n for n, e in {**self.world["places"], **self.world["objects"]}.items()
                if {" ".join(words_of(w)) for w in [n] + list(e.get("words") or [])} & wanted
                and applies(self.world, n, "open") and holds_now(self.world, n, now)]

    def _either(self, heaters: list[str], windows: dict[str, str], cond: str, words: str) -> None:
        """ "it's freezing" with a window open: the heating on, or the window closed; two answers two
        people would not agree on, so asked (each offered), unless the user chose one."""
        options = {**({"the heating": cond} if heaters else {}), **windows}
        asked = [n for n, c in windows.items() if any(x.cond == c and x.explicit and x.words != words
                                                      for x in self.goal.state.get(n, {}).values())]
        if asked:   # "it's freezing, shut the skylight": the cue is the reason
            self.goal.notes.append(f"'{words}' is the reason for {', '.join(asked)} {windows[asked[0]]}")
            return
        pick = self.choose.get(words) if len(options) > 1 else next(iter(options))
        if pick not in options:
            raise _choice(TranslationError(f"'{words}': which? {' or '.join(f'{n} {c}' for n, c in options.items())}; "
                                           "say which"), words, list(options))
        names = heaters if pick == "the heating" else [pick]
        self.goal.notes.append(f"'{words}': read as {', '.join(names)} {options[pick]}"
                               + (" (chosen)" if len(options) > 1 else ""))
        for n in names:
            self.want(n, options[pick], False, words)
        self.last = names

    def _room(self, st: dict, names: list[str], words: str) -> None:
        """A cue felt in a room the home model lacks ("out in the conservatory"): the home model has
        no rooms, so the room is read only when it cannot change which thing is meant (one thing
        fits), or when the home's words place one of ``names`` there (``names`` is narrowed to it,
        in place); several: asked, each offered, naming the room (never all of them, never one)."""
        room = st.get("room")
        if not room:
            return
        called = self._called_after(room, names)
        if len(called) == 1:   # "the fan in the living room" where the home calls one "living room fan"
            self.goal.notes.append(f"'{room}': the one of them the home's words place there ({called[0]})")
            names[:] = called
            return
        elsewhere = [n for n in names if self._called_in_another_room(n, room)]
        if names and len(elsewhere) == len(names):   # "the kitchen is too dark" where only the salon light is off
            raise TranslationError(f"'{words}': the home's words place {', '.join(names)} in another room than "
                                   f"'{room}', and nothing called '{' '.join(_room_said(room))} ...' fits; "
                                   "say what to switch")
        if _room_said(room)[:1] in (["my"], ["our"]):   # whose room: never some other room's thing
            raise TranslationError(f"'{words}': none of {', '.join(names) or 'the things that fit'} is called "
                                   f"'{_room_said(room)[0]} ...' in this home, so '{room}' does not say which; say which")
        if len(names) > 1 and self.choose.get(words) not in names:
            raise _choice(TranslationError(f"'{words}': this home model has no rooms, so '{room}' cannot say which "
                                           f"of {', '.join(names)} is meant; say which"), words, names)
        if names:
            self.goal.notes.append(f"'{room}': the home model has no rooms; the one thing that fits is meant")

    def _called_in_another_room(self, name: str, room: str) -> bool:
        """Whether the home's words for a thing open with a room other than ``room`` ("salon light"
        where the kitchen is said)."""
        said = _room_said(room)
        for w in [name] + list(entity(self.world, name).get("words") or []):
            opening = words_of(w)
            if any(opening[:len(r)] == r and r != said for r in _ROOMS):
                return True
        return False

    def _called_after(self, room: str, names: list[str]) -> list[str]:
        """Of ``names``, those whose name or words open with the room's words ("living room fan" for
        "in the living room", "kids' room aircon" for "out in the kids room", "my heater" for "in
        my room"): the home model has no rooms, but its words may say where a thing is."""
        said = _room_said(room)
        return [n for n in names if said and any(words_of(w)[:len(said)] == said
                                                 for w in [n] + list(entity(self.world, n).get("words") or []))]

    def _near(self, st: dict, names: list[str], cond: str, words: str) -> None:
        """A light cue felt by a place ("it's dark over by the sofa"): the one light nearest that
        place (:mod:`pipflow.household.language.nearness`); two as near: asked, each offered; the
        nearest already as the cue asks: refused (the cue asks for a change, and a light further
        away is not what was said)."""
        place = self.place_of(st["near"], words)
        close = nearest(self.world, names, place)
        if len(close) > 1 and self.choose.get(words) in close:
            close = [self.choose[words]]
        if len(close) > 1:
            raise _choice(TranslationError(f"'{words}': {', '.join(close)} are as near {place}; say which"),
                          words, close)
        if holds_now(self.world, close[0], cond):
            raise TranslationError(f"'{words}': {close[0]}, the light nearest {place}, is {cond} already; "
                                   "say what to do")
        self.goal.notes.append(f"'{words}': read as {close[0]} {cond} (the light nearest {place})")
        self.want(close[0], cond, False, words)
        self.last = close

    def warmth(self, st: dict, words: str) -> None:
        """ "it is freezing in here": the room heaters on; "it is roasting in here": the room
        heaters that are on, off. Things the sentence names are what it speaks of ("it is freezing
        with that fan going": the fan off). No heater, or none on when it is too warm: asked."""
        cond = st["to"]
        if st["things"]:   # the thing named is the cause: a heater on/off as asked, anything else the other way
            heaters = set(self.room_heaters())
            for n, explicit in self.objects(st["things"], words, cond="on"):
                self.want(n, cond if n in heaters else ("off" if cond == "on" else "on"), explicit, words)
            return
        every = self.room_heaters()
        # a cue asks for a change: a heater already as asked is no condition
        heaters = [n for n in every if not holds_now(self.world, n, cond)]
        # cold with a window open: the window closed is an answer too (warm with one closed: open)
        windows = self.windows("open" if cond == "on" else "closed")
        fans = [n for n in self.devices("air") if not holds_now(self.world, n, "on")]
        if cond == "off" and not heaters and not windows and fans:
            # too warm, no heater on and no window to open, in a home with fans or air
            # conditioners: one that is off, on, as "it's stuffy" asks
            self.air_cue(st, words)
            return
        if windows:   # decided at the end: a request of the heating's state makes the cue its reason
            answers = {w: "closed" if cond == "on" else "open" for w in windows}
            self.unanswered.append((cond, words, lambda: self._either(heaters, answers, cond, words)))
            return
        self._room(st, heaters, words)
        if st.get("near") and len(heaters) > 1:   # "it's freezing in the study": the heater nearest it
            heaters = nearest(self.world, heaters, self.place_of(st["near"], words))
        if st.get("room") and len(heaters) > 1:
            heaters = [self.choose[words]]
        if not heaters:   # decided at the end: "I'm roasting, switch the fire off" gives the reason
            why = (f"'{words}': which thing? this home has no room heater "
                   f"{'that is on ' if cond == 'off' else 'that is off ' if every else ''}(a heater, "
                   "radiator, fire or log burner that switches); say what to switch")
            self.unanswered.append((cond, words, lambda: self._reason_or_refused(words, why, bool(every))))
            return
        self.goal.notes.append(f"'{words}': read as the room's heating {cond} ({', '.join(heaters)}; "
                               "docs/household.md, cues)")
        for n in heaters:
            self.want(n, cond, False, words)
        self.last = heaters

    def _reason_or_refused(self, words: str, why: str, heated: bool) -> None:
        """A cue of warmth no heater answers: in a home with no room heater at all, said with other
        requests ("Me mam's freezing. Put the throw on her bed"), it is their reason (noted); alone,
        or where the home has heaters but none as asked, it is asked (``why``)."""
        done = list(dict.fromkeys([*self.goal.inside, *self.goal.state]))
        if heated or not done:
            raise TranslationError(why)
        self.goal.notes.append(f"'{words}': this home has no room heater; read as the reason for the rest "
                               f"({', '.join(done)})")

    def tend(self, st: dict, words: str) -> None:
        """What things need ("deal with the dishes", "the bedding is all over the place"), read
        from their states and the home: when any of them is dirty, the dirty ones washed (the
        clean ones are left); else the ones away from their category's home put there. Things
        that need neither, or a need the home cannot meet, are asked, never guessed."""
        named = self.objects(st["things"], words)
        names = [n for n, _ in named]
        # disorder said of a place ("my desk is a mess") is of the things it holds
        names = list(dict.fromkeys(o for n in names for o in ([n] if n in self.world["objects"] else
                                                              [o for o, e in self.world["objects"].items()
                                                               if e["in"] == n]))) or names
        dirty = [n for n in names if applies(self.world, n, "clean") and holds_now(self.world, n, "dirty")]
        if dirty:
            left = [n for n in names if n not in dirty]
            self.goal.notes.append(f"'{words}': read as {', '.join(dirty)} washed (dirty)"
                                   + (f"; {', '.join(left)} left as found" if left else ""))
            for n in dirty:
                self.want(n, "clean", True, words)
            self.last = dirty
            return
        homes = {}
        for n in names:
            e = entity(self.world, n)
            home = [self.world["categories"][c]["home"] for c in e["categories"]
                    if (self.world["categories"].get(c) or {}).get("home")]
            if n in self.world["objects"] and home and "pickupable" in e["properties"]:
                homes[n] = home[0]
        away = [n for n in names if n in homes and self.world["objects"][n]["in"] != homes[n]]
        # "the hob's still on, can you sort that": a thing left on or open may need switching off
        # or closing; that is asked (each offered as a candidate reading), never guessed
        undo = [OPPOSITE[c] for c in ("on", "open")
                if names and all(applies(self.world, n, c) and holds_now(self.world, n, c) for n in names)]
        if not away and self.choose.get(words) in undo:
            for n in names:
                self.want(n, self.choose[words], True, words)
            self.last = names
            return
        if not away and undo:
            raise _choice(TranslationError(f"'{words}': what should be done with {', '.join(names)}? (nothing of "
                                           f"it is dirty or away from its home; it could be {' or '.join(undo)})"),
                          words, undo)
        cans = self._garbage()
        if not away and names and len(cans) == 1 and all(
                n in self.world["objects"] and "pickupable" in entity(self.world, n)["properties"]
                and self._of_kinds(n, RUBBISH_KINDS) for n in names):
            # "there's rubbish all over the lounge": rubbish lying about (an object that picks up, of
            # a category of RUBBISH_KINDS: never food, which may be put away) goes in the one bin
            self.goal.notes.append(f"'{words}': rubbish lying about: read as {', '.join(names)} thrown away")
            for n in names:
                self.put(n, cans[0], words)
            self.last = names
            return
        if not away:
            raise TranslationError(f"'{words}': what should be done with {', '.join(names) or 'it'}? "
                                   "(nothing of it is dirty or away from its home); say what to do")
        self.goal.notes.append(f"'{words}': read as {', '.join(names)} put where {'they belong' if len(names) > 1 else 'it belongs'}")
        for n in names:
            if n in homes:
                self.put(n, homes[n], words)
        self.last = names

    def cue(self, st: dict, words: str) -> None:
        if st.get("heating"):
            self.warmth(st, words)
            return
        if st.get("device"):
            self.device_cue(st, words)
            return
        cond = st["to"]
        default = st.get("default")
        # the cue's category: named or worded by its word, in the singular or the plural ("lights")
        forms = {default, *plurals(default)} if default else set()
        cats = [c for c, e in (self.world.get("categories") or {}).items()
                if default and (c in forms or forms & set((e or {}).get("words") or []))]
        # an observation answers the cue when it is about what the cue speaks of ("the desk lamp
        # is on and nobody is reading": a light); "the TV is on and nobody is reading" is not
        fits = [o for o in self.observed
                if not cats or all(cats[0] in entity(self.world, n)["categories"] for n in o[0])]
        if st["things"]:
            named = self.objects(st["things"], words, cond=cond)
            said = {n for n, _ in named}   # "the TV is on but nobody is watching it": the cue answers it
            if said and said <= set(self.goal.inside) | set(self.goal.state) and \
                    not any(applies(self.world, n, cond) for n in said):
                # "put the veg away, I don't need it today": of things the command already acts on
                # and that cannot be switched so, the cue is the reason for what is done with them
                self.goal.notes.append(f"'{words}' is the reason for what is done with {', '.join(sorted(said))}")
                self.last = sorted(said)
                return
            self.observed = [o for o in self.observed if not set(o[0]) <= said]
        elif fits:
            named = [(n, True) for names, _, _ in fits for n in names]
            self.observed = [o for o in self.observed if o not in fits]
        else:
            # a home with no category of lights: its things named or worded as lights ("salon light")
            group = members(self.world, cats[0]) if cats else \
                self.called(LIGHTS) if default == LIGHT_CATEGORY_WORD else []
            if not group:   # decided at the end: the reason for a request the command makes, or asked
                self.cue_defaults.append(("", cond, words, [], False))
                return
            cat = cats[0] if cats else default
            named = [(n, False) for n in group if applies(self.world, n, cond)]
            if not named:
                raise Refusal(f"'{words}': nothing of the {cat} category can be switched {cond}")
            if st.get("near"):   # "it's dark over by the sofa": the one light nearest the sofa
                self._near(st, [n for n, _ in named], cond, words)
                return
            if st.get("room"):   # "it's gloomy in the study": which light, when the home has no rooms?
                fit = [n for n, _ in named if not holds_now(self.world, n, cond)]
                self._room(st, fit, words)
                named = [(n, False) for n in ([self.choose[words]] if len(fit) > 1 else fit)] or named
            if default == LIGHT_CATEGORY_WORD and cond == "on" and not st.get("room"):
                self.wanting_light.add(words)
            # decided at the end: "it is getting dark, turn on the floor lamp" gives the reason
            # for a request, it does not ask for every light
            self.cue_defaults.append((cat, cond, words, [n for n, _ in named], bool(st.get("room"))))
            self.last = [n for n, _ in named]
            return
        for n, explicit in named:
            self.want(n, cond, explicit, words)
        self.last = [n for n, _ in named]

    def meal(self, st: dict, words: str) -> None:
        """A meal (lexicon ``MEALS``): its foods in this home end in the meal's state. A category
        of the world named like the meal lists them; else the lexicon's foods, matched on the last
        word of an object's name or words. No food, or no base food, is a refusal: the offline
        reading does not invent a recipe from what happens to be in the home."""
        meal = st["meal"]
        spec = MEALS[meal]
        cond = spec["state"]
        need = CONDITIONS[cond][2]
        own = [c for c, e in (self.world.get("categories") or {}).items()
               if meal in [" ".join(words_of(w)) for w in [c] + list((e or {}).get("words") or [])]]
        if own:
            foods = [n for c in own for n in members(self.world, c) if n in self.world["objects"]]
            source = f"the home's category {own[0]}"
        else:
            def food_word(name: str) -> str | None:
                e = self.world["objects"][name]
                for phrase in [name] + list(e.get("words") or []):
                    last = (words_of(phrase) or [""])[-1]
                    for f in spec["foods"]:
                        if last == f or last in plurals(f):
                            return f
                return None
            matched = {n: food_word(n) for n in self.world["objects"]}
            foods = [n for n, f in matched.items() if f]
            base = spec.get("base")
            if base and not any(matched[n] in base for n in foods):
                raise Refusal(f"'{words}': this home has no {' or '.join(base[:3])} (or other base for a {meal}), "
                              f"so the offline reading will not guess one; say which things should be {cond}")
            source = f"the {meal} foods of the lexicon"
        also = list(spec.get("also") or [])   # toast: sliced too
        able = [n for n in foods if all(CONDITIONS[c][2] in self.world["objects"][n]["properties"] for c in [cond] + also)]
        if not able:
            raise Refusal(f"'{words}': this home has nothing for a {meal} that can be {cond}"
                          + (f" ({', '.join(foods)} cannot)" if foods else ""))
        self.goal.notes.append(f"'{words}': read as {', '.join(able)} {cond} ({source}; docs/household.md, meals)")
        for n in able:
            for c in [cond] + also:
                self.want(n, c, False, words)
        self.last = able

    def _answer_mess(self) -> None:
        """Disorder said of things ("the clothes are everywhere") is the reason for a clause that
        acts on them ("..., put them in the basket"); said alone, it asks for what they need
        (:meth:`tend`)."""
        acted = set(self.goal.inside) | set(self.goal.state) | {c["in"] for c in self.goal.count}
        for st, words, before in self.mess:
            self.last = before   # "they" said in it stands for what it stood for then, not what was said after
            if st.get("room"):   # "the front room's like a tip, get the rubbish in the bin": its reason
                if not acted:
                    raise TranslationError(f"'{words}': what should be done about it? say what to tidy or put away")
                self.goal.notes.append(f"'{words}' is the reason for the rest")
                continue
            names = [n for n, _ in self.objects(st["things"], words)]
            if names and set(names) <= acted:
                self.goal.notes.append(f"'{words}' is the reason for what is done with {', '.join(names)}")
                continue
            self.tend(st, words)

    def _garbage(self) -> list[str]:
        """The home's garbage places (the bin a thing thrown away goes in)."""
        return [p for p, e in self.world["places"].items() if "garbage" in e["properties"]]

    def _of_kinds(self, name: str, kinds: tuple[str, ...]) -> bool:
        """Whether a thing is of a category named or worded as one of ``kinds`` ("rubbish", "food")."""
        said = {" ".join(words_of(w)) for w in kinds}
        return any({" ".join(words_of(w)) for w in [c] + list((self.world["categories"].get(c) or {}).get("words") or [])}
                   & said for c in entity(self.world, name).get("categories") or [])

    def _foul(self, names: list[str], words: str) -> None:
        """Foulness said and nothing done about it: a thing that washes is washed; food or rubbish
        (a category named or worded like ``BIN_KINDS``) goes in the home's one bin; anything else
        is asked."""
        cans = self._garbage()
        for n in names:
            cats = entity(self.world, n).get("categories") or []
            binned = self._of_kinds(n, BIN_KINDS)
            if applies(self.world, n, "clean"):
                self.goal.notes.append(f"'{words}': foul, and it washes: read as {n} washed (docs/household.md, cues)")
                self.want(n, "clean", True, words)
            elif binned and len(cans) == 1 and n in self.world["objects"]:
                self.goal.notes.append(f"'{words}': foul {' or '.join(c for c in cats)}: read as {n} thrown away "
                                       "(docs/household.md, cues)")
                self.put(n, cans[0], words)
            else:
                raise TranslationError(f"'{words}': what should be done with {n}? (it does not wash, and it is no "
                                       "food or rubbish for the bin); say what to do")

    def _apply_cue_defaults(self) -> None:
        """A cue that names nothing means its whole category, unless the command itself asks the
        same state of one of its members (then the cue is only the reason)."""
        said = {}
        for cat, cond, words, *_ in self.cue_defaults:   # "it's too dark, I'm trying to sleep": which?
            if cat and said.get(cat, (cond, words))[0] != cond:
                raise TranslationError(f"'{said[cat][1]}' and '{words}' ask opposite things of the {cat}; say which")
            said.setdefault(cat, (cond, words))
        # "so dark in the hall, I can't see the paper": the cue said with a room says where; the other
        # is its reason, not a request for every member
        roomed = {(cat, cond): names for cat, cond, _, names, room in self.cue_defaults if room and cat}
        for cat, cond, words, names, room in self.cue_defaults:
            if not room and (cat, cond) in roomed:
                self.goal.notes.append(f"'{words}' is the reason for {', '.join(roomed[cat, cond])} {cond}")
                continue
            if not cat:   # "we have finished listening, switch off the radio": the reason for a request
                asked = [n for n, preds in self.goal.state.items()
                         if any(c.cond == cond and c.explicit and c.words != words for c in preds.values())]
                if not asked:
                    raise TranslationError(f"'{words}': which thing? (it names nothing to switch)")
                self.goal.notes.append(f"'{words}' is the reason for {', '.join(asked)} {cond}")
                continue
            asked = [n for n in names if any(c.cond == cond and c.explicit and c.words != words
                                             for c in self.goal.state.get(n, {}).values())]
            if asked:
                self.goal.notes.append(f"'{words}' is the reason for {', '.join(asked)} {cond}, not a request for "
                                       f"every {cat}")
                continue
            # a cue asks for a change: "it is getting dark" asks nothing of a light that is on already
            already = [n for n in names if holds_now(self.world, n, cond)]
            names = [n for n in names if n not in already]
            if not names:
                raise TranslationError(f"'{words}': every {cat} is {cond} already; say what to do")
            if words in self.wanting_light and len(names) > 1:
                if any(c.cond == cond and c.words != words for n in names for c in self.goal.state.get(n, {}).values()):
                    # "is getting dark already, put all lights on": the reason for what is asked
                    self.goal.notes.append(f"'{words}' is the reason for what is asked of the {cat}")
                    continue
                names = self._light_here(names, words)
            self.goal.notes.append(f"'{words}': read as every {cat} {cond} ({', '.join(names)})"
                                   + (f"; {', '.join(already)} {cond} already" if already else ""))
            for n in names:
                self.want(n, cond, False, words)

    def _light_here(self, names: list[str], words: str) -> list[str]:
        """ "it's so dark in here": light where the speaker is, which the command does not say and the
        home model cannot know; with one light off that one is meant, with several it is asked, each
        offered (never every light of the home: docs/household.md, cues)."""
        if self.choose.get(words) in names:
            return [self.choose[words]]
        raise _choice(TranslationError(f"'{words}': {', '.join(names)} are off, and '{words}' does not say where "
                                       "light is wanted; say which"), words, names)

    def _hold_excepted(self) -> None:
        """A thing left out of a selection ("all the toys except the footy", "all the lights except
        the porch one") is left alone: where it is and as its world entry writes, as "don't touch
        it" is (benchmarks/README.md); unless another part of the command asks something of it."""
        for names, words in self.excepted:
            for n in names:
                if n in self.goal.inside or self.goal.state.get(n):
                    continue
                if n in self.world["objects"]:
                    self.put(n, self.world["objects"][n]["in"], words)
                    self.keep_states(n, words)
                elif "toggleable" in (self.world["places"][n].get("properties") or []):
                    self.set_state(n, "on" if holds_now(self.world, n, "on") else "off", False, words)

    def resolve(self, order: dict) -> dict:
        for st in order["statements"]:
            self.statement(st)
        self._hold_excepted()
        self._apply_cue_defaults()
        for cond, words, otherwise in self.unanswered:   # the reason for a request of the same state, else
            asked = [n for n, preds in self.goal.state.items()
                     if any(c.cond == cond and c.explicit and c.words != words for c in preds.values())]
            if not asked:
                otherwise()
                continue
            self.goal.notes.append(f"'{words}' is the reason for {', '.join(asked)} {cond}")
        if self.picked:
            obj, words = next(iter(self.picked.items()))
            raise TranslationError(f"'{words}': where to? name a place for {obj} (e.g. 'in the fridge')")
        self._answer_mess()
        acted = set(self.goal.inside) | set(self.goal.state)
        for names, words in self.handled:
            if not set(names) & acted:
                raise TranslationError(f"'{words}' says how {', '.join(names)} is to be handled, but nothing is asked "
                                       "of it; say what to do")
        for names, state, words in list(self.observed):
            if words in self.foul and names:
                self._foul(names, words)
                self.observed.remove((names, state, words))
                continue
            if words in self.gone_cold and names and all(applies(self.world, n, "hot") for n in names):
                # "my tea has gone cold": cold is what went wrong with it, said and not answered: heated
                self.goal.notes.append(f"'{words}': gone cold and nothing done about it: read as heating "
                                       f"{', '.join(names)} (docs/household.md, cues)")
                for n in names:
                    self.want(n, "hot", True, words)
                self.observed.remove((names, state, words))
                continue
            if state == "dirty" and names and all(applies(self.world, n, "clean") for n in names):
                # "the dishes on the table are filthy": dirt that nothing else answers asks for washing;
                # of several things, the ones that are dirty ("last night's dishes are still dirty")
                dirty = [n for n in names if holds_now(self.world, n, "dirty")] or names
                self.goal.notes.append(f"'{words}': dirt said and nothing done about it: read as washing "
                                       f"{', '.join(dirty)} (docs/household.md, cues)")
                for n in dirty:
                    self.want(n, "clean", True, words)
                self.observed.remove((names, state, words))
        if self.observed:
            words = self.observed[0][2]
            raise TranslationError(f"'{words}' describes the home but asks for nothing (say what to do, "
                                   "or why: 'nobody is reading')")
        g = self.goal
        inside: dict[str, list[str]] = {}
        for obj, (place, _) in g.inside.items():
            inside.setdefault(place, []).append(obj)
        state = {n: [c.cond for c in preds.values()] for n, preds in g.state.items() if preds}
        explain = [f"{o} in {p}, from '{w}'" for o, (p, w) in g.inside.items()]
        explain += [f"{n} {c.cond}, from '{c.words}'" for n, preds in g.state.items() for c in preds.values()]
        explain += [f"at least {c['at_least']} {c['category']} in {c['in']}" for c in g.count]
        goal: dict = {"in": inside, "state": state}
        if g.count:
            goal["count"] = [dict(c) for c in g.count]
        words = {"in": {o: w for o, (_, w) in g.inside.items()},
                 "state": {n: {c.cond: c.words for c in preds.values()} for n, preds in g.state.items() if preds}}
        return {"goal": goal, "explain": explain, "notes": list(g.notes), "words": words}


def resolve(order: dict, world: dict, choose: dict[str, str] | None = None) -> dict:
    """``{"goal": {"in", "state", "count"?}, "explain": [one line per condition with its words],
    "notes": [...], "words": {"in": {object: words}, "state": {name: {condition: words}}}}`` for a
    household order in a world (checked against its schema first);
    Refusal or TranslationError otherwise. ``choose``: words that name several things -> the
    one meant (a candidate reading the refusal offers; never set by the reader itself)."""
    return Resolver(world, choose).resolve(check_order(order))


def _holds_things(world: dict, place: str) -> bool:
    """Whether things can lie in a place of the home (a receptacle, a sink or the garbage)."""
    props = set((world.get("places") or {}).get(place, {}).get("properties") or ())
    return bool(props & {"receptacle", "sink", "garbage"})

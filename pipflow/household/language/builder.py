"""Step 3 of :mod:`pipflow.household.language.parser`: one parse tree -> one order
(``schemas/household_order.schema.json``): a list of statements, each with the selectors of the
things it is about and the words it came from. Which objects a selector means, and whether the
request is possible, is the resolver's job, not the builder's."""
from __future__ import annotations

from lark import Token, Tree

from pipflow.errors import TranslationError
from pipflow.household.language.grammar import base_class
from pipflow.household.language.lexicon import (ACTION_PARTICIPLES, ACTIVITIES, COLD, FOUL_WORDS, LAUNDRY, LIGHT_CATEGORY_WORD, MEALS, NEARNESS, OPPOSITE,
                                                TEMPERATURE_ADJECTIVES, UNIT_DETERMINERS)
from pipflow.household.language.tokens import Tag


def words_under(tags: list[Tag], node: Tree | Token) -> str:
    """The words of the tags under a node of the parse tree, in order."""
    toks = [node] if isinstance(node, Token) else list(node.scan_values(lambda v: isinstance(v, Token)))
    idx = sorted({int(t) for t in toks})
    return " ".join(tags[k].words for k in idx)



#: what a thing left so keeps besides its place: its states ("leave the cooler alone": still dirty)
AS_IS = {"alone", "as it is", "as they are"}

class Builder:
    """One parse tree -> one order (``schemas/household_order.schema.json``)."""

    def __init__(self, tags: list[Tag], command: str):
        self.tags = tags
        self.command = command

    # tokens ------------------------------------------------------------------------------
    def tag_of(self, tok: Token) -> Tag:
        return self.tags[int(tok)]

    def _cls(self, tok: Token) -> str:
        return base_class(tok.type)

    def _tokens(self, node: Tree | Token) -> list[Token]:
        if isinstance(node, Token):
            return [node]
        return [c for c in node.children if isinstance(c, Token)]

    def _sub(self, node: Tree, name: str) -> Tree | None:
        return next((c for c in node.children if isinstance(c, Tree) and c.data == name), None)

    def _subs(self, node: Tree, name: str) -> list[Tree]:
        return [c for c in node.children if isinstance(c, Tree) and c.data == name]

    def _has(self, node: Tree, cls: str) -> bool:
        return any(self._cls(t) == cls for t in self._tokens(node))

    # pieces ------------------------------------------------------------------------------
    def noun(self, node: Tree) -> dict:
        tok = node.children[0]
        t = self.tag_of(tok)
        return {"words": t.words, "readings": [dict(r) for r in t.nouns]}

    def place(self, node: Tree) -> dict:
        return {**self.noun(self._sub(node, "noun")), "words": words_under(self.tags, node)}

    def state(self, node: Tree) -> str:
        onoff = self._sub(node, "onoff")
        if onoff is not None:
            node = onoff
        if self._sub(node, "on") is not None:
            return "on"
        if self._sub(node, "off") is not None or self._sub(node, "typo_off") is not None:   # "turn of the TV"
            return "off"
        tok = self._tokens(node)[-1]
        return str(self.tag_of(tok).value)

    def sel(self, node: Tree) -> dict:
        out: dict = {"words": words_under(self.tags, node)}
        toks = [self._cls(t) for t in self._tokens(node)]
        quant = self._sub(node, "quant")
        if quant is not None:
            out["all"] = True
            if self._has(quant, "BOTH"):
                out["both"] = True
        if "DOOR" in toks:
            out["door"] = True
        count_node = self._sub(node, "count")
        det_words = [self.tag_of(t).words for t in self._tokens(node) if self._cls(t) == "THE"]
        if (count_node is not None and self._has(count_node, "UNIT")) or \
                any(d in UNIT_DETERMINERS for d in det_words):
            out["unit"] = True   # "a piece of fruit", "two pieces of fruit": only a kind may be counted in pieces
        if "ONES" in toks:
            out["ones"] = True   # "except the clean ones": of the things just named
        if "EVERYTHING" in toks or "THING" in toks:
            out["everything"] = True
        if "IT" in toks or toks == ["BOTH"]:   # "them", "put both on the table"
            out["pronoun"] = True
        if toks == ["BOTH"]:
            out.update(all=True, both=True)
        count = self._sub(node, "count")
        if count is not None:
            out["count"] = int(self.tag_of(count.children[0]).value)
        adjs = [str(self.tag_of(self._tokens(a)[0]).value) for a in self._subs(node, "adj")]
        noun = self._sub(node, "noun")
        if noun is not None:
            out.update(noun=self.noun(noun))
        det = [self.tag_of(t).words for t in self._tokens(node) if self._cls(t) == "THE"]
        if det:
            out["det"] = det[0]
        rel = self._sub(node, "rel")
        where = self._sub(node, "where") or (self._sub(rel, "where") if rel is not None else None)
        if rel is not None and self._sub(rel, "state") is not None:
            adjs.append(self.state(self._sub(rel, "state")))
        if rel is not None and self._sub(rel, "place") is not None:
            out["from"] = self.place(self._sub(rel, "place"))
        if where is not None:
            out["from"] = self.place(self._sub(where, "place"))
        if adjs:
            out["state"] = adjs
        return out

    def np(self, node: Tree) -> dict:
        out = self.sel(self._sub(node, "sel"))
        if node.data == "offnp":   # "the book off the table": where it is taken from
            out["from"] = self.place(self._sub(node, "place"))
            out["words"] = words_under(self.tags, node)
        where = self._sub(node, "where")   # a switch's thing by where it is: "the lamp on the desk"
        if where is not None:
            out["from"] = self.place(self._sub(where, "place"))
            out["words"] = words_under(self.tags, node)
        exc = self._sub(node, "exception")
        if exc is not None:
            out["except"] = self.things(self._sub(exc, "things"))
            out["words"] = words_under(self.tags, node)
        return out

    def things(self, node: Tree) -> list[dict]:
        return [self.np(n) for n in self._subs(node, "np") + self._subs(node, "tnp") + self._subs(node, "snp")
                + self._subs(node, "offnp")]

    def target(self, node: Tree) -> dict:
        p = self._sub(node, "place") or self._sub(node, "bare")
        if p is None and self._has(node, "THEWASH"):   # "put the clothes in the wash"
            return {"words": words_under(self.tags, node), "quality": LAUNDRY}
        if p is None:   # "put the apple in it": the place said before
            return {"words": words_under(self.tags, node), "pronoun": True}
        out = {**self.noun(self._sub(p, "noun")), "words": words_under(self.tags, node)}
        if any(self._cls(t) == "ON" for t in self._tokens(node)):
            out["prep"] = "on"   # a surface: "on the fridge" is not "in the fridge"
        return out

    # statements --------------------------------------------------------------------------
    def statement(self, node: Tree) -> dict:
        kind = node.data
        words = words_under(self.tags, node)
        th = self._sub(node, "things") or self._sub(node, "tthings") or self._sub(node, "sthings")
        things = self.things(th) if th is not None else []
        exc = self._sub(node, "exception")
        if kind == "change":
            toks = self._tokens(node)
            # the state comes from the verb, or from the action noun of "give the pot a scrub"
            act = next((t for t in toks if self._cls(t) == "ACT"), None)
            verb = act if act is not None else next(t for t in toks if self._cls(t).startswith("V_"))
            st = {"op": "change", "things": things, "to": str(self.tag_of(verb).value)}
            via = self._sub(node, "via")
            if via is not None and self._sub(via, "place") is not None:
                st["via"] = self.place(self._sub(via, "place"))
            elif via is not None:   # "heat the pan on it"
                st["via"] = {"words": words_under(self.tags, via), "pronoun": True}
            elif act is None and self.verb_place(verb) is not None:   # "microwave the noodles"
                st["via"] = self.verb_place(verb)
        elif kind == "toggle" and self._has(node, "V_LIGHT"):   # "light the stove"
            st = {"op": "change", "things": things, "to": "on"}
        elif kind == "toggle":   # "turn the fire on and the kettle": the things after the particle too
            st = {"op": "change", "things": [t for sub in self._subs(node, "tthings") for t in self.things(sub)],
                  "to": "off" if self._has(node, "DOWN") else self.state(node)}   # "shut everything down"
            if self._has(node, "V_PUT"):
                st["phrasal"] = True   # "put the radio on": switched on only if it has a switch
        elif kind == "put":
            st = self.move(node)
        elif kind == "gap":   # the verb is elided: "... and the pillow on the bed", "... and the stove on", "... and the cup too"
            st = {"op": "repeat", "things": things}
            if self._sub(node, "target") is not None:
                st["to"] = self.target(self._sub(node, "target"))
            elif self._sub(node, "onoff") is not None:
                st["state"] = self.state(node)
        elif kind == "away":
            st = {"op": "put_away", "things": things}
        elif kind == "trash":
            st = {"op": "trash", "things": things}
        elif kind == "chill":
            verb = next(t for t in self._tokens(node) if self._cls(t) == "V_CHILL")
            st = {"op": "put", "things": things, "to": {"words": self.tag_of(verb).words, "quality": COLD}}
        elif kind == "request" and self._has(node, "ACT"):   # "the saucepan wants a good scrub"
            act = next(t for t in self._tokens(node) if self._cls(t) == "ACT")
            st = {"op": "change", "things": things, "to": str(self.tag_of(act).value)}
        elif kind == "onceat":   # "switch the laptop off once it is there": where an earlier step puts it
            st = {"op": "put", "things": things, "once": True}
            if self._sub(node, "place") is not None:
                st["to"] = {**self.place(self._sub(node, "place"))}
        elif kind == "once":   # "once they are clean, put them away": a state an earlier step asks
            state = self._sub(node, "state")
            st = {"op": "change", "things": things, "to": self.state(state)}
            if words_under(self.tags, state) not in ACTION_PARTICIPLES:   # "once the mug is washed": done first
                st["once"] = True
        elif kind in ("request", "after"):   # "after": "once you have washed the pan, ..." (done first)
            st = {"op": "change", "things": things, "to": self.state(self._sub(node, "state"))}
        elif kind == "unwant":   # "don't leave the fridge open", "the TV shouldn't be on": the other polarity
            st = {"op": "change", "things": things, "to": OPPOSITE[self.state(self._sub(node, "state"))]}
        elif kind == "meal":
            st = self.meal(node, words)
        elif kind == "cue":
            st = self.cue(node, things)
        elif kind in ("observe", "tend", "mess", "handling", "keep", "empty", "desire"):
            st = self.said_of_things(node, kind, things)
        elif kind == "roommess":   # "the front room's like a tip": a room's disorder, said for a later clause
            st = {"op": "tend", "things": [], "said": True, "room": True}
        else:  # a rule of the grammar without a statement: a bug, not a user error
            raise AssertionError(f"no statement for grammar rule {kind!r}")
        if exc is not None:   # "put all the fruit in the fridge but not the watermelon"
            st["except"] = self.things(self._sub(exc, "things"))
        st["words"] = words
        return st

    def move(self, node: Tree) -> dict:
        """A move ("put the mug in the sink"), or a throw said nowhere else (a trash)."""
        # "put it in the cabinet along with the bowl": the things after the place go there too
        subs = self._subs(node, "things") + self._subs(node, "sthings") + self._subs(node, "offthings")
        st = {"op": "put", "things": [s for sub in subs for s in self.things(sub)]}
        src, tgt = self._sub(node, "source"), self._sub(node, "target")
        if src is None and tgt is None and self._has(node, "V_THROW") and len(self._tokens(node)) == 1:
            # "chuck the crisp packet", "toss the orange": thrown, and said nowhere else, is away
            st = {"op": "trash", "things": st["things"]}
        if src is not None:
            st["from"] = self.place(self._sub(src, "place"))
        if tgt is not None:
            st["to"] = self.target(tgt)
        was = self._sub(node, "wherewas")
        if was is not None:   # "put the teacake on the bar where it was": checked against the world
            st["as_was"] = words_under(self.tags, was)
        return st

    def meal(self, node: Tree, words: str) -> dict:
        """A meal named ("make me a salad"), checked against the verb that asks for it."""
        named = next((t for t in self._tokens(node) if self._cls(t) == "MEAL"), None)
        if named is None:   # "make some toast": a meal whose word is a verb too
            said = self.tag_of(next(t for t in self._tokens(node)[1:] if self._cls(t) == "V_STATE")).words
            if said not in MEALS:
                raise TranslationError(f"'{words}': '{said}' is no meal the offline parser knows")
            meal = said
        else:
            meal = str(self.tag_of(named).value)
        verb = self.tag_of(self._tokens(node)[0])
        if verb.value is not None and verb.value != MEALS[meal]["state"]:   # "cook breakfast", never "heat a salad"
            raise TranslationError(f"'{words}': a {meal} is not made by '{verb.words}' "
                                   f"(its foods end {MEALS[meal]['state']}); say what to do with which things")
        st = {"op": "meal", "meal": meal}
        return st

    def verb_place(self, verb: Token) -> dict | None:
        """ "microwave the noodles": a verb that is a place of the home says where the action
        happens (a noun of the place's readings), else None."""
        places = [dict(r) for r in self.tag_of(verb).nouns if r["kind"] == "place"]
        return {"words": self.tag_of(verb).words, "readings": places} if places else None

    def said_of_things(self, node: Tree, kind: str, things: list[dict]) -> dict:
        """Statements that say something of things: an observation, what they need ("tend"),
        disorder said ("mess"), how a thing is handled, a thing to stay where it is, a place
        emptied, a thing wished for in a state."""
        if kind == "observe":
            state = self._sub(node, "state")
            st = {"op": "observe", "things": things, "is": self.state(state) if state is not None else "dirty"}
            said = words_under(self.tags, state).split()[-1] if state is not None else ""
            if state is None or said in FOUL_WORDS:   # "the pizza box is starting to smell", "the mug is minging"
                st["foul"] = True
            verb = next((self.tag_of(x).words for x in self._tokens(node) if self._cls(x) == "IS"), "")
            if st["is"] == "cold" and "gone" in verb.split():   # "my tea has gone cold": cold is what went wrong
                st["gone"] = True
        elif kind == "tend":   # "deal with the dishes"
            st = {"op": "tend", "things": things}
        elif kind == "mess":   # "the bedding is all over the place": said, so a later clause may answer it
            place = self._sub(node, "place")
            if place is not None:   # "the sink is full of dishes": the dishes in the sink
                where = self.place(place)
                things = [{**t, "from": t.get("from") or where} for t in things]
            st = {"op": "tend", "things": things, "said": True}
        elif kind == "handling":   # "the wok is too heavy for one of you": how, for a later clause
            st = {"op": "handling", "things": things}
        elif kind == "keep":   # "leave the hoodie where it is"; "leave it alone", "don't touch it": as it is too
            stay = next((self.tag_of(x).words for x in self._tokens(node) if self._cls(x) == "STAY"), "")
            st = {"op": "keep", "things": things, "as_is": self._has(node, "V_TOUCH") or stay in AS_IS,
                  **({"there": True} if self._has(node, "THERE") else {})}
        elif kind == "empty":   # "empty the fridge onto the counter": everything in it
            place = self.place(self._sub(node, "place"))
            st = {"op": "put", "things": [{"words": f"everything in {place['words']}", "everything": True,
                                           "from": place}]}
            if self._sub(node, "target") is not None:
                st["to"] = self.target(self._sub(node, "target"))
        else:   # "desire": "I fancy a warm bagel": the thing in the state its adjective names
            noun = self._sub(node, "noun")
            adjs = [str(self.tag_of(self._tokens(a)[0]).value) for a in self._subs(node, "adj")]
            det = [self.tag_of(t).words for t in self._tokens(node) if self._cls(t) == "THE"]
            sel = {"words": words_under(self.tags, noun), "noun": self.noun(noun), **({"det": det[0]} if det else {})}
            st = {"op": "change", "things": [sel], "to": adjs[-1]}
        return st

    def cue(self, node: Tree, things: list[dict]) -> dict:
        st: dict = {"op": "cue", "things": things}
        act, light = self._sub(node, "activity"), self._sub(node, "lightcue")
        warmth = self._sub(node, "tempcue") or self._sub(node, "tempadj")
        if warmth is not None:
            t = self.tag_of(self._tokens(warmth)[0])
            to = TEMPERATURE_ADJECTIVES.get(str(t.value)) if warmth.data == "tempadj" else str(t.value)
            if to is None:   # "it is dirty in here": no temperature, no cue
                raise TranslationError(f"'{t.words}' says nothing of how warm it is")
            st.update(to=to, cue=f"it is {t.words}", heating=True, device="heating")
        elif act is not None:
            word = self.tag_of(self._tokens(act)[0]).words
            st.update(to="off", cue=f"nobody is {word}")
            if ACTIVITIES.get(word):
                st["default"] = ACTIVITIES[word]
        elif light is not None:
            t = self.tag_of(self._tokens(light)[0])
            st.update(to=str(t.value), cue=f"it is {t.words}", default=LIGHT_CATEGORY_WORD)
            near = self._sub(node, "near")
            if near is not None:   # "it's dark over by the sofa": the light nearest the sofa
                said = [self.tag_of(x).words for x in self._tokens(near) if self._cls(x) == "NEAR"]
                if not set(said) <= NEARNESS:
                    raise TranslationError(f"'{' '.join(said)}': a light cue says where it is felt by 'by' or "
                                           "'near' a place; say which light")
                st["near"] = self.place(self._sub(near, "place"))
        elif self._has(node, "DOACT") or (self._has(node, "SEE") and self._has(node, "TO")):
            # "I want to watch something": what the activity needs, on; "too dark to study": the light
            t = next(self.tag_of(x) for x in self._tokens(node) if self._cls(x) in ("DOACT", "SEE"))
            kind = t.value if self._cls(next(x for x in self._tokens(node) if self.tag_of(x) is t)) == "DOACT" else "light"
            if kind == "light" or light is not None:
                st.update(things=[] if light is not None else things, to="on", cue=f"to {t.words}",
                          **({"default": LIGHT_CATEGORY_WORD} if not things or light is not None else {}))
            elif things:   # "I want to watch the telly": that thing on
                st.update(to="on", cue=f"to {t.words}")
            else:
                st.update(to="on", cue=f"to {t.words}", device=str(kind))
        elif self._has(node, "SLEEPCUE"):   # "I'm trying to sleep": the lights off
            st.update(things=[], to="off", cue="sleep", default=LIGHT_CATEGORY_WORD)
        elif self._has(node, "SEE"):   # "I can't read my notes": what cannot be read is the reason
            st.update(things=[], to="on", cue="cannot see", default=LIGHT_CATEGORY_WORD)
        elif self._sub(node, "soundcue") is not None:   # "it's too quiet in here"
            t = self.tag_of(self._tokens(self._sub(node, "soundcue"))[0])
            st.update(to=str(t.value), cue=f"it is {t.words}", device="sound")
        elif self._has(node, "HEARCUE"):   # "I can't hear myself think (with that radio blaring)"
            t = next(self.tag_of(x) for x in self._tokens(node) if self._cls(x) == "HEARCUE")
            st.update(to="off", cue=f"cannot {t.words}", device="sound")
        elif self._sub(node, "closecue") is not None:   # "it's close in here": stuffy; "it's sliced" is nothing
            t = self.tag_of(self._tokens(self._sub(node, "closecue"))[0])
            if t.words != "close":
                raise TranslationError(f"'{t.words}' says nothing of how the room feels")
            st.update(to="on", cue="it is close", device="air")
        elif self._has(node, "MORE"):   # "make it warmer in here": the change wished for
            t = next(self.tag_of(x) for x in self._tokens(node) if self._cls(x) == "MORE")
            kind, to = t.value
            st.update(to=to, cue=f"it {t.words}", **({"default": LIGHT_CATEGORY_WORD} if kind == "light" else
                                                     {"device": kind, **({"heating": True} if kind == "heating" else {})}))
        elif self._has(node, "FRESHAIR"):   # "can we get some air in here?"
            st.update(to="on", cue="air wanted", device="air")
        elif self._sub(node, "aircue") is not None:   # "it's stuffy in here": a fan on or a window open
            t = self.tag_of(self._tokens(self._sub(node, "aircue"))[0])
            st.update(to="on", cue=f"it is {t.words}", device="air")
        elif self._has(node, "MUSIC"):   # "put some music on"
            st.update(to="on", cue="music wanted", device="sound")
        elif self._has(node, "HOTDRINK"):   # "could murder a cuppa"
            st.update(to="on", cue="a hot drink wanted", device="hot drink")
        else:
            st.update(to="off", cue="not needed")
        room = self._sub(node, "room")
        said = next((self.tag_of(x).words for x in self._tokens(node) if self._cls(x) == "ROOMSAID"), None)
        if room is not None or said:   # "it's stuffy out in the conservatory": a room the home model lacks
            st["room"] = words_under(self.tags, room) if room is not None else said
        inplace = self._sub(node, "inplace")
        if inplace is not None:   # "it's so hot in the salon", the salon a place of the home: what is nearest it
            st["near"] = self.place(self._sub(inplace, "place"))
        return st

    def where_instead(self, item: Tree, statements: list[dict], refused: dict | None) -> dict | None:
        """ "heat up the pie? not in the oven, use the hob": the place the change before happens,
        said after it; the place said not to use must not be the one it had. Returns the refused
        place still waiting for its replacement (None once said)."""
        if item.data == "notvia":
            via = self._sub(item, "via")
            refused_now = {"words": words_under(self.tags, item), "place": self.place(self._sub(via, "place"))}
            last = statements[-1] if statements else None
            said = (last.get("via") or (last.get("to") if last.get("op") == "put" else None)) if last else None
            if refused is None and isinstance(said, dict) and said.get("readings"):
                # "heat the kugel in the microwave, not on the stove": a place already said, and
                # another said not to use; the goal keeps the one said, which rules out the other
                if {r["name"] for r in said["readings"]} & {r["name"] for r in refused_now["place"]["readings"]}:
                    raise TranslationError(f"'{last['words']}' and '{refused_now['words']}' name the same place")
                last["words"] += " , " + refused_now["words"]
                return None
            return refused_now
        last = statements[-1] if statements else None
        if last is None or last.get("op") != "change":
            raise TranslationError(f"'{words_under(self.tags, item)}': use it for what? (no action before it)")
        place = self.place(self._sub(item, "place"))
        if refused is not None and {r["name"] for r in refused["place"]["readings"]} & \
                {r["name"] for r in place["readings"]}:
            raise TranslationError(f"'{refused['words']}' and '{words_under(self.tags, item)}' name the same place")
        if "via" in last and refused is None:
            raise TranslationError(f"'{last['words']}' says where already; '{words_under(self.tags, item)}' says another place")
        last["via"] = place
        last["words"] += " ; " + (refused["words"] + " , " if refused else "") + words_under(self.tags, item)
        return None

    def ensure(self, node: Tree) -> list[dict]:
        """"make sure the oven is closed and the big light is off": one change per wish."""
        out = []
        for wish in self._subs(node, "wish"):
            to = self.state(self._sub(wish, "state"))
            if self._sub(wish, "not") is not None:   # "make sure the oven is not on"
                to = OPPOSITE[to]
            out.append({"op": "change", "things": self.things(self._sub(wish, "sthings")),
                        "to": to, "words": words_under(self.tags, wish)})
        return out

    def order(self, tree: Tree) -> dict:
        items = [c for c in tree.children if isinstance(c, Tree)]
        statements: list[dict] = []
        refused_place: dict | None = None
        for item in items:
            if item.data == "reason":   # "it is late, ...": why, not what
                continue
            if item.data in ("notvia", "usevia"):
                refused_place = self.where_instead(item, statements, refused_place)
                continue
            statements += self.ensure(item) if item.data == "ensure" else [self.statement(item)]
        if refused_place is not None:   # "heat the pie, not in the oven": where then?
            raise TranslationError(f"'{refused_place['words']}': not there, but where? say where (e.g. 'use the hob')")
        if not statements:
            error = TranslationError(f"{self.command.strip()!r} gives a reason but asks for nothing; say what to do")
            error.reasons = [words_under(self.tags, i) for i in items if i.data == "reason"]  # type: ignore[attr-defined]
            raise error
        return {"domain": "household", "command": self.command, "statements": statements}

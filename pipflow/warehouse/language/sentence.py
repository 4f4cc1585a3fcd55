"""The sentence reader: one parsed sentence (a tree of the grammar) in, statements and rules out.

It parses each sentence with lark's Earley parser over the grammar of
:mod:`pipflow.warehouse.language.grammar`, whose lexicon is the world's names (:mod:`lexicon`), and reads
the tree into statements and robot rules (a goal clause by the method of its rule:
:mod:`pipflow.warehouse.language.goals`). It does no arithmetic against the stock: relative
amounts, "except", "the rest", swaps and ellipsis stay symbolic for the resolver
(:mod:`pipflow.warehouse.language.resolver`). What it does resolve is the sentence's own structure:

* coordination with ellipsis: "four product1 to shelf2 and three to shelf3, taking them from
  shelf1" (the item and the source are shared), "shelf2 to hold 6 product3, and shelf4 too";
* a robot addressed by name ("Robot 5, bring two product1 to shelf2") or a rule that follows a
  goal in its sentence with no scope of its own: the rule governs that goal's one product and
  its one place or one move (several products or places leave the field open);
* several places: "each"/"both"/"apiece" repeat a count, "respectively" pairs counts and
  places in order; a count for a list of places with neither is refused (each, or a total?).

A word the grammar cannot place is a :class:`TranslationError` that quotes it.
The command as a whole (sentences, memory across them, line breaks, candidates) is
:mod:`pipflow.warehouse.language.parser`; this module reads one tree.
"""
from __future__ import annotations

from typing import Any, Callable

from lark import Token, Tree
from lark.visitors import Interpreter

from pipflow.errors import TranslationError
from pipflow.language.numbers import NUMBER_WORDS
from pipflow.language.spelling import normalize
from pipflow.warehouse.language.goals import Asked, Choice, GoalRules, quote
from pipflow.warehouse.language.lexicon import Lexed, Lexicon
from pipflow.warehouse.language.robots import RobotSelector
from pipflow.warehouse.language.rulescope import RuleScope
from pipflow.warehouse.language.tails import TailRules

SET_AMOUNTS = {"count", "all", "none", "as_many_as", "rest", "each"}
CHANGE_AMOUNTS = {"more", "fewer", "times", "fraction"}
BOUND_AMOUNTS = {"at_least", "at_most", "between", "at_least_more"}
#: noun phrases whose amount is read from their numbers alone (``nums``), by rule; the phrase's item
#: (if it names one) is the last item said, for ellipsis
AMOUNTS: dict[str, Callable[[list[int]], dict]] = {
    "np_count": lambda n: {"count": n[0]}, "np_more": lambda n: {"more": n[0]},
    "np_fewer": lambda n: {"fewer": n[0]}, "np_one": lambda n: {"count": 1}, "np_one_more": lambda n: {"more": 1},
    "np_all": lambda n: {"all": True}, "np_none": lambda n: {"none": True}, "np_half": lambda n: {"fraction": [1, 2]},
    "np_twice": lambda n: {"times": 2}, "np_ntimes": lambda n: {"times": n[0]},
    "np_atleast_more": lambda n: {"at_least_more": n[0]}, "np_all_n": lambda n: {"all": True, "expect": n[0]},
    "np_atleast": lambda n: {"at_least": n[0]}, "np_atmost": lambda n: {"at_most": n[0]},
    "np_above": lambda n: {"at_least": n[0] + 1}, "np_rest": lambda n: {"rest": True},
}
#: noun phrases that name no item ("another", "3 more", "two"): the item comes from the clause
ITEMLESS: dict[str, Callable[[list[int]], dict]] = {
    "np_another": lambda n: {"count": 1}, "np_more_bare": lambda n: {"more": n[0]},
    "np_bare": lambda n: {"count": n[0]},
    "np_atmost_bare": lambda n: {"at_most": n[0]}, "np_atleast_bare": lambda n: {"at_least": n[0]},
}
#: verbs whose object goes somewhere: a destination said later in the sentence is theirs too
MOVE_VERBS = {"move", "bring", "send", "ship", "transfer", "carry", "haul", "shift", "cart", "ferry", "tow",
              "lug", "shuttle", "wheel", "run", "relocate", "deliver", "pull", "grab", "stage", "gather",
              "consolidate", "collect"}
#: verbs whose object is the units themselves ("must not move them", "should handle it"); after
#: "P gets N X": a final count or a delivery; read only where both mean the same
RECEIVE_VERBS = {"get", "gets", "receive", "receives", "give"}


class SentenceReader(GoalRules, TailRules, RuleScope, Interpreter):
    """Reads one parsed sentence into statements and rules. A goal clause and a tail (a clause
    that continues the one before it) go to the method their rule names (lark's Interpreter
    dispatch; the methods are :class:`GoalRules` and :class:`TailRules`)."""

    def __init__(self, lexed: Lexed, lex: Lexicon, robots: RobotSelector, memory: dict | None = None,
                 picks: dict | None = None):
        self.lexed, self.lex, self.robots = lexed, lex, robots
        self.picks = picks or {}  # a reading the user chose where the sentence has several (Choice)
        memory = memory or {}
        # what earlier sentences said, for "them", "too", "do it" and an elided item or place
        self.prior: list[dict] = list(memory.get("statements") or [])
        self.prior_last: list[dict] = list(memory.get("last") or [])
        self.updates: dict[int, dict] = {}
        self.index = lex.index
        self.statements: list[dict] = []
        self.rules: list[dict] = []
        self.bind: list[dict] = []  # rules that take the sentence's goal as their scope
        self.own: dict[int, list[dict]] = {}  # of those, an addressed robot's: its own goal's statements
        # of those, the ones whose pronoun is what the robots handle ("must not move them"): the
        # items, or the items on this move? (finish refuses where the two differ)
        self.item_pronouns: list[dict] = []
        self.job_pronouns: list[dict] = []  # "for this / for that": the job, or the move just said?
        self.last_item: list[str] | None = memory.get("item")
        self.last_places: list[str] | None = memory.get("places")
        # the places named aloud in this sentence, in order, and those of the sentence before: what
        # "it" / "there" as a place can mean (see place_list)
        self.named_places: list[str] = []
        self.prior_named: list[str] = list(memory.get("named") or [])
        self.distributive = False  # "every bay", "each of A and B": a count applies to each
        self.before_places: list[str] = []  # the places named before the current part
        self.last_add = False  # whether the last counts came with an add verb (for gapping)
        self.pending_source: list[str] | None = None  # a source said before its moves
        # words of counts said with "gets / receives": repeated elsewhere ("and so does Q"), they
        # must again mean one thing there
        self.received: set[str] = set(memory.get("received") or ())
        # units taken off a place and then shared out ("Move 3 lids from dispatch: 2 to silo 2 and
        # 1 to rack east"): the removal and how many of it are not yet given a destination
        self.budget: dict | None = None
        # complaints with no count ("P has too many X"): they set the context, and alone ask nothing
        self.observed: list[tuple[str, list[str]]] = []   # (words, places)
        self.prior_observed: list[tuple[str, list[str]]] = list(memory.get("observed") or [])
        self.prior_item_first: bool = bool(memory.get("item_first"))  # the sentence before opened with an item

    # -- the rules' dispatch -----------------------------------------------------------------
    def __getattr__(self, name: str) -> Any:
        """lark's Interpreter answers every missing name with ``__default__``; here only a goal or
        a tail rule's name does (any other missing attribute is a bug, and says so)."""
        if name.startswith(("g_", "t_")):
            return self.__default__
        raise AttributeError(f"{type(self).__name__!r} object has no attribute {name!r}")

    def __default__(self, node: Tree) -> None:
        """A rule with no method: refused with its words, never half-read."""
        if node.data.startswith("t_"):
            raise TranslationError(f"{quote(self.words(node))}: cannot read this")
        raise TranslationError(f"{quote(self.clause_parts(node).words)}: cannot read this statement")

    # -- words ------------------------------------------------------------------------------
    def words(self, node: Tree | Token | list) -> str:
        toks = [node] if isinstance(node, Token) else (
            [t for n in node for t in (n.scan_values(lambda v: isinstance(v, Token)) if isinstance(n, Tree) else [n])]
            if isinstance(node, list) else list(node.scan_values(lambda v: isinstance(v, Token))))
        pos = [t.start_pos for t in toks if isinstance(t, Token) and t.start_pos is not None]
        if not pos:
            return ""
        return " ".join(s.text for s in self.lexed.source[min(pos):max(pos) + 1] if s.text).replace(" zzposs", "'s")

    def robots_said(self, node: Tree, addressed: bool = False) -> str:
        """The words of a group of robots, with "the" before them where a determiner was said ("the
        forklift": :attr:`~.lexicon.Lexicon.definite_said`), which the grammar drops: "the
        forklift" is one robot, "forklift" alone, as on a sign, the kind. Robots ``addressed``
        ("Tugger, take 4 X ...") are called as one calls a person: a kind said so in the singular
        is one robot, as with "the"."""
        said = self.words(node)
        definite = addressed or bool(said) and (normalize(said) in self.lex.definite_said
                                                or normalize(said.split()[0]) in self.lex.definite_said)
        return ("the " if definite else "") + said

    def toks(self, node: Tree, kind: str) -> list[Token]:
        return [t for t in node.scan_values(lambda v: isinstance(v, Token) and v.type == kind)]

    def first_word(self, node: Tree) -> str:
        got = self.toks_any(node)
        return str(got[0].value).lower() if got else ""

    def toks_any(self, node: Tree) -> list[Token]:
        return sorted(node.scan_values(lambda v: isinstance(v, Token)), key=lambda t: t.start_pos or 0)

    # -- items ------------------------------------------------------------------------------
    def ihead(self, node: Tree, words: str) -> str | None:
        tok = node.children[0]
        if tok.type == "ITEM":
            return str(tok.value)
        products = self.index.by_kind["product"]
        if len(products) == 1:
            return products[0]
        raise TranslationError(f"{quote(words)} does not say which product "
                               f"(candidates: {self.index.candidates('product')})")

    def nps(self, items: Tree) -> list[dict]:
        return [self.np(c) for c in items.children if isinstance(c, Tree) and c.data.startswith("np_")]

    def np(self, node: Tree) -> dict:
        """One noun phrase: ``{"items": selector|None, "amount": {...}, "words": str}``. The
        phrases whose amount is one of their numbers are :data:`AMOUNTS` (and :data:`ITEMLESS`,
        which name no item); the others are read here."""
        kind = node.data
        words = self.words(node)
        nums = [int(t.value) for t in node.scan_values(lambda v: isinstance(v, Token) and v.type == "NUM")]
        heads = [c for c in node.children if isinstance(c, Tree) and c.data == "ihead"]
        named = [str(c.value) for c in node.children if isinstance(c, Token) and c.type == "ITEM"]
        item = {"names": [self.ihead(heads[0], words)]} if heads else {"names": named[:1]} if named else None

        def places() -> list[str]:
            return [str(t.value) for t in node.scan_values(lambda v: isinstance(v, Token) and v.type == "PLACE")]

        def out(amount: dict, sel: dict | None = item) -> dict:
            if sel is not None and sel.get("names"):
                self.last_item = sel["names"]
            return {"items": sel, "amount": amount, "words": words}

        if kind in ITEMLESS:
            return {"items": None, "amount": ITEMLESS[kind](nums), "words": words}
        if kind == "np_rest":
            # "the rest of P's X": whose rest is checked against the statement before (_rest)
            named = [str(pp.children[0].value) for r in self.sub(node, "rest_of") for pp in self.sub(r, "posplace")]
            if any(str(tok.value) == "there" for r in self.sub(node, "rest_of") for tok in r.children
                   if isinstance(tok, Token)):
                named = list(self.last_places or ["(no place said)"])   # "the rest of the rice there"
            return {**out(AMOUNTS[kind](nums)), **({"rest_of": named} if named else {})}
        if kind in AMOUNTS:
            return out(AMOUNTS[kind](nums))
        if kind == "np_more_than_place":
            return out({"as_many_as": places()[0], "more" if self.sub(node, "more") else "fewer": nums[0]})
        if kind == "np_times_as_many":
            return out({"as_many_as": places()[0], "times": nums[0] if nums else 2})
        if kind == "np_frac":
            frac = next(c for c in node.children if isinstance(c, Tree) and c.data == "frac")
            den = next(int(t.value) for t in frac.scan_values(lambda v: isinstance(v, Token) and v.type == "FRAC"))
            num = next((int(t.value) for t in frac.scan_values(lambda v: isinstance(v, Token) and v.type == "NUM")), 1)
            return out({"fraction": [num, den]})
        if kind == "np_times":
            first = str(node.children[0].value) if isinstance(node.children[0], Token) else words.split()[0]
            return out({"times": {"double": 2, "triple": 3, "quadruple": 4}.get(first.lower(), 2)})
        if kind == "np_below":
            if nums[0] == 0:
                raise TranslationError(f"{quote(words)}: fewer than 0 units is impossible")
            return out({"at_most": nums[0] - 1})
        if kind == "np_between":
            lo, hi = nums[0], nums[1]
            if lo > hi:
                raise TranslationError(f"{quote(words)}: the lower bound {lo} is above the upper bound {hi}")
            return out({"at_least": lo, "at_most": hi})
        if kind == "np_vague":
            raise TranslationError(f"{quote(words)} is a bound, not a count: it is approximate, and "
                                   f"the goal needs an exact count or a firm bound ('at least 5', "
                                   f"'at most 5', 'between 3 and 5')")
        if kind == "np_too_many":
            # "P's got too many X": a complaint, no count; it says what "them" / "it" will mean
            # in the instruction after it ("Halve them", "take it down to 2"), nothing more
            return out({"observed": True})
        if kind in ("np_each_more", "np_each"):
            return out({"more": nums[0]} if kind == "np_each_more" else {"count": nums[0] if nums else 1}, {"all": True})
        if kind == "np_everything":
            excl = []
            for c in node.children:
                if isinstance(c, Tree) and c.data == "except_items":
                    excl = [self.ihead(h, words) for h in c.children if isinstance(h, Tree) and h.data == "ihead"]
            return out({"all_held": True}, {"all": True, "except": excl})
        if kind == "np_as_many":
            return out({"as_many_as": places()[0]})
        if kind == "np_as_many_item":
            # "as many gears as widgets": the other item's count on the statement's own place
            return out({"as_many_here": True, "of": self.ihead(heads[1], words)})
        if kind == "np_as_many_total":
            named_places = places()
            amount = {"as_many_as": named_places[0], "together_with": named_places[1:]}
            return out(amount) if heads else out(amount, None)
        if kind == "np_as_many_elided":
            return out({"as_many_as": places()[0]}, None)
        raise TranslationError(f"{quote(words)}: cannot read this amount")

    # -- places -----------------------------------------------------------------------------
    def place_list(self, node: Tree) -> list[str]:
        out: list[str] = []
        for c in node.children:
            if not isinstance(c, Tree):
                continue
            if c.data == "place_name":
                out.append(str(c.children[0].value))
            elif c.data == "place_word":
                shelves = self.class_places(c)
                if len(shelves) > 1 and self._plural_group(c):
                    # "the aisles" where aisle-1 and aisle-2 share the head: those places (a count
                    # for them still needs "each" or a total: see put)
                    out.extend(shelves)
                    continue
                if len(shelves) != 1:
                    raise TranslationError(f"{quote(self.words(c))} does not say which shelf "
                                           f"(candidates: {self.index.candidates('shelf')})")
                out.append(shelves[0])
            elif c.data == "place_it":
                if not self.last_places:
                    raise TranslationError(f"{quote(self.words(c))}: no place named before it "
                                           f"(candidates: {self.index.candidates('shelf')})")
                out.extend(self._referent(c))
            elif c.data == "place_all":
                excl: list[str] = []
                for e in self.sub(c, "except_pl"):
                    excl += [str(t.value) for t in self.toks(e, "PLACE")]
                out.extend(p for p in self.class_places(c) if p not in excl)
                self.distributive = True
            elif c.data == "place_all_n":  # "all four areas": the count must be the world's
                n = int(self.toks(c, "NUM")[0].value)
                every = self.class_places(c)
                if n != len(every):
                    raise TranslationError(f"{quote(self.words(c))}: this world has {len(every)} places, not {n}")
                out.extend(every)
                self.distributive = True
            elif c.data == "place_each":
                out.extend(str(t.value) for t in self.toks(c, "PLACE"))
                self.distributive = True
        out = list(dict.fromkeys(out))
        if not any(isinstance(c, Tree) and c.data == "place_it" for c in node.children):
            self.named_places += [p for p in out if p not in self.named_places]
        self.last_places = out
        return out

    def _referent(self, node: Tree) -> list[str]:
        """The place(s) "it" / "there" means: those just named, only where nothing else named in
        this sentence (or, when it names none, the one before) could be meant. After "out of the
        fish room and into aisle 6", "only wet-rated robots in there" is either: it was read as the
        last one named (a misreading); now each is offered (``picks["place_it"]``: the user's
        choice)."""
        last = list(self.last_places or [])
        heard = self.named_places or self.prior_named
        others = [p for p in heard if p not in last]
        if not others:
            return last
        options = ("+".join(last), *others)
        choice = self.picks.get("place_it")
        if choice is not None:
            return choice.split("+")
        raise Choice("place_it", options, f"{quote(self.words(node))}: which place is meant: "
                     f"{' or '.join(o.replace('+', ' and ') for o in options)}? say it")

    def _plural_group(self, node: Tree) -> bool:
        """Whether a place word is the plural of a head noun the world's place names share
        ("aisles", "docks"): a group of the world. A generic word ("shelves", "places") is not."""
        words = [t for t in node.children if isinstance(t, Token) and t.type == "PLACEWORD"]
        if not words or words[0].start_pos is None:
            return False
        text = normalize(self.lexed.source[words[0].start_pos].text)
        return text.endswith("s") and text not in self.index.groups and self.index.group(text) is not None

    def class_places(self, node: Tree) -> list[str]:
        """The places a class word selects: "cages" only the world's cages (a head noun their
        names share), "places" / "areas" / "shelves" of a world with no such name every place."""
        words = [t for t in node.children if isinstance(t, Token) and t.type == "PLACEWORD"]
        if words and words[0].start_pos is not None:
            group = self.index.group(self.lexed.source[words[0].start_pos].text)
            if group is not None:
                return group
        return list(self.index.by_kind["shelf"])

    def loc(self, node: Tree) -> tuple[list[str], str]:
        """Places of a location phrase and how a count applies: "one", "each" or "respectively"."""
        places = self.place_list(next(c for c in node.children if isinstance(c, Tree) and c.data == "places"))
        mode = {"loc": "one", "loc_each": "each", "loc_resp": "respectively"}[node.data]
        return places, mode

    def sub(self, node: Tree, name: str) -> list[Tree]:
        return [c for c in node.children if isinstance(c, Tree) and c.data == name]

    # -- statements -------------------------------------------------------------------------
    def statement(self, op: str, places: list[str], np: dict, **extra: Any) -> dict:
        st = {"op": op, "places": {"names": places}, "items": np["items"], "amount": np["amount"],
              "words": np["words"], **extra}
        return st

    def put(self, places: list[str], mode: str, nps: list[dict], words: str, add: bool = False) -> None:
        """Counts for places: one place, each of several, or respectively."""
        self.last_add = add
        if mode == "respectively" or (len(places) > 1 and mode == "resp"):
            self.respectively(places, nps, words, add)
            return
        if self.distributive:
            mode, self.distributive = "each", False
        if len(places) > 1 and mode != "each" and not all(
                "none" in np["amount"] for np in nps):
            if self.picks.get("several") == "each":
                mode = "each"   # chosen by the user among the candidates
            else:
                # each, or shared? The "each" reading is offered (a share would need the split said)
                raise Choice(
                    "several", ("each",),
                    f"{quote(words)}: the command does not say whether each of {', '.join(places)} "
                    f"gets these counts or they share them (say 'each', 'respectively' or 'evenly between')")
        if nps and all(np["amount"].get("observed") for np in nps):
            # "P has too many X": no goal; P and X are what the next clause's pronoun means
            self.last_places = places
            self.observed.append((words, list(places)))
            return
        for np in nps:
            if add and np["amount"].get("none"):
                # "bring / move / add no lids to P": nothing goes there, P keeps its lids (it was
                # read as "P holds no lids", emptying P: a misreading)
                items = np["items"] or ({"names": list(self.last_item)} if self.last_item else None)
                if items is None:
                    raise TranslationError(f"{quote(np['words'])}: cannot tell which product")
                self.statements.append({"op": "keep", "places": {"names": places}, "items": items,
                                        "inflow_only": False, "words": np["words"]})
                continue
            if np["amount"].get("as_many_here"):  # each place against its own count of the other item
                for p in places:
                    here = {**np, "amount": {"as_many_as": p, "of": np["amount"]["of"]}}
                    self.statements.append(self._goal_statement([p], here, add))
                continue
            self.statements.append(self._goal_statement(places, np, add))

    def _goal_statement(self, places: list[str], np: dict, add: bool) -> dict:
        a = np["amount"]
        key = next(iter(a))
        prev = self.statements[-1] if self.statements else None
        if np["items"] is None and key in ("count", "more", "rest"):
            taken = self.budget["st"] if self.budget else (
                prev if prev is not None and prev["op"] == "transfer" and prev.get("to") is None
                and "names" in (prev.get("from") or {}) else None)
            if taken is not None:
                return self._share(taken, places, np, key)
        if np["items"] is None and prev is not None and prev["op"] == "transfer" and key in ("count", "more") \
                and prev.get("to"):
            # "Move 2 totes from inbound to outbound and 1 (more) to quarantine": same item, same source
            return {**prev, "amount": {"count": a[key]}, "to": {"names": places}, "words": np["words"]}
        if key == "rest":
            return self._rest(places, np)
        if self.pending_source and add and key in ("count", "more", "all", "all_held"):
            if np["items"] is None and not self.last_item:
                raise TranslationError(f"{quote(np['words'])}: cannot tell which product")
            items = np["items"] or {"names": list(self.last_item or [])}
            n = {"count": a[key]} if key in ("count", "more") else a
            return {"op": "transfer", "items": items, "amount": n, "from": {"names": self.pending_source},
                    "to": {"names": places}, "words": np["words"]}
        if key == "all_held" and add and self.before_places and self.before_places != places:
            # "clear out staging and take everything to outbound": from the place just named
            return {"op": "transfer", "items": np["items"], "amount": a, "from": {"names": list(self.before_places)},
                    "to": {"names": places}, "words": np["words"]}
        if np["items"] is None:
            if not self.last_item:
                raise TranslationError(f"{quote(np['words'])}: cannot tell which product this count "
                                       f"is for (candidates: {self.index.candidates('product')})")
            np = {**np, "items": {"names": list(self.last_item)}}
        if add and key == "count":
            a, key = {"more": a["count"]}, "more"
        if add and set(a) == {"at_least"}:
            # "add / bring at least 2 X to P": at least 2 more than now (it was read as "P holds at
            # least 2", already met where P holds 3: a misreading)
            a, key = {"at_least_more": a["at_least"]}, "at_least_more"
        elif add and set(a) & {"at_most", "between"}:
            raise TranslationError(f"{quote(np['words'])}: a bound on how many to bring is not a count the "
                                   f"place ends with; say it so ('P should have at most N')")
        if key in CHANGE_AMOUNTS:
            op = "change"
        elif key in BOUND_AMOUNTS:
            op = "bound"
        elif key == "all_held":
            op = "set_all_held"
        else:
            op = "set"
        return {"op": op, "places": {"names": places}, "items": np["items"], "amount": a,
                "words": np["words"]}

    def respectively(self, places: list[str], nps: list[dict], words: str, add: bool) -> None:
        if len(nps) != len(places):
            shown = ", ".join(n["words"] for n in nps)
            raise TranslationError(f"'respectively': {len(nps)} count(s) with products ({shown}) for "
                                   f"{len(places)} shelves ({', '.join(places)}); give one count and "
                                   f"product per shelf")
        named = [n for n in nps if n["items"] is not None]
        if len(named) == 1 and nps[-1]["items"] is not None:
            nps = [{**n, "items": nps[-1]["items"]} for n in nps]
        for place, np in zip(places, nps):
            self.statements.append(self._goal_statement([place], np, add))


    def _items_and_source(self, node: Tree, nps: list, words: str) -> tuple[list, list]:
        """An item phrase that names its own place ("2 gears from rack B") gives the items and the
        source; otherwise the clause's items and its ``src`` places."""
        pit = [c for c in node.children if isinstance(c, Tree) and c.data.startswith("pi_")]
        if pit:
            np, source = self.pitem(pit[0], words)
            return [np], source
        return nps, self.place_list(self.sub(self.sub(node, "src")[0], "places")[0])

    def _receive_is_clear(self, node: Tree, places: list[str], nps: list[dict], words: str) -> None:
        """ "P gets / receives N X" is the count P ends with or the count delivered to it: the same
        when P holds no X now, else two goals; then nothing is guessed."""
        verbs = [self.first_word(v) for v in self.sub(node, "setv")] or (
            ["give"] if self.first_word(node) == "give" else [""])  # "give P N X"; "get P to N" is a count
        if verbs[0] not in RECEIVE_VERBS:
            return
        if any(t.start_pos in self.lexed.exact for t in self.toks(node, "NUM")):
            return  # "exactly 3": a final count
        for np in nps:
            if set(np["amount"]) == {"count"}:
                items = (np["items"] or {}).get("names") or list(self.last_item or [])
                self._received_check(places, items, np["words"], words)
                self.received.add(np["words"])

    def _received_check(self, places: list[str], items: list[str], count_words: str, words: str) -> None:
        stock = self.lex.world.get("stock") or {}
        for item in items:
            for p in places:
                have = int((stock.get(p) or {}).get(item, 0) or 0)
                if have:
                    raise TranslationError(
                        f"{quote(words)}: 'gets {count_words}' could be the count {p} ends with or "
                        f"the count it receives ({p} holds {have} {item} now); say 'should have' or 'more'")

    def bare_nps(self, node: Tree, words: str) -> list[dict]:
        """ "Take the drums out of bay 2": an item without a count is all of it (there)."""
        out = []
        for b in self.sub(node, "bare"):
            for h in self.sub(b, "ihead"):
                head = self.ihead(h, words)
                self.last_item = [head]
                amount: dict = {"all": True}
                appos = self.sub(node, "appos")
                expect = _expected(self, appos[0]) if appos else None
                if expect is not None:
                    amount["expect"] = expect
                out.append({"items": {"names": [head]}, "amount": amount, "words": words})
        return out

    def pitem(self, node: Tree, words: str) -> tuple[dict, list[str]]:
        """A possessive item phrase ("half of bay 1's crates"): its amount and its place."""
        pos = self.sub(node, "posplace")
        if pos:
            source = [str(self.toks(pos[0], "PLACE")[0].value)]
        elif self.last_places:
            source = list(self.last_places)  # "its valves": of the place just named
        else:
            raise TranslationError(f"{quote(words)}: 'its' of which place?")
        head = self.ihead(self.sub(node, "ihead")[0], words)
        self.last_item = [head]
        appos = self.sub(node, "appos")
        expect = _expected(self, appos[0]) if appos else None
        if node.data == "pi_frac":
            fr = self.sub(node, "frac")
            if not fr:
                amount: dict = {"fraction": [1, 2]}  # "half of bay 1's crates"
            else:
                den = int(self.toks(fr[0], "FRAC")[0].value)
                num = int(self.toks(fr[0], "NUM")[0].value) if self.toks(fr[0], "NUM") else 1
                amount = {"fraction": [num, den]}
        elif node.data == "pi_count":
            amount = {"count": int(self.toks(node, "NUM")[0].value)}
        else:
            amount = {"all": True}
        if expect is not None:
            amount["expect"] = expect
        return {"items": {"names": [head]}, "amount": amount, "words": words}, source

    def _gap_after_more(self, nps: list[dict], places: list[str]) -> None:
        """ "Put 2 more lids on A and 1 on B", "A gets 2 more lids, B 3": is B's count one more or
        one in all? The words do not say; where B holds some now the two differ and nothing is
        guessed (B's final count was read). The same after a stop: "... 2 more lids on A. 1 on B"."""
        prev = self.statements[-1] if self.statements else (self.prior_last[-1] if self.prior_last else None)
        if prev is None or prev["op"] != "change" or "more" not in (prev.get("amount") or {}):
            return
        stock = self.lex.world.get("stock") or {}
        for np in nps:
            items = (np["items"] or prev.get("items") or {}).get("names") or []
            if set(np["amount"]) == {"count"} and any(
                    int((stock.get(p) or {}).get(i, 0) or 0) for p in places for i in items):
                raise Asked(f"{quote(np['words'])} after {prev['words']!r}: cannot tell whether it is "
                                       f"{np['words']} more or {np['words']} in all (say 'more' or 'in all')")

    def _shared_destination(self) -> None:
        """ "Move 2 lids from dispatch and 1 from rack east to silo 2": the destination said once at
        the end is that of both moves (it was read as a removal of 2 to anywhere: a misreading).
        After a removal verb ("take 2 off A and 1 from B to C") it could be either: refused."""
        for k in range(len(self.statements) - 1):
            st, nxt = self.statements[k], self.statements[k + 1]
            if not (st["op"] == "transfer" and st.get("to") is None and nxt["op"] == "transfer" and nxt.get("to")
                    and "names" in (st.get("from") or {}) and nxt.get("items") == st.get("items")):
                continue
            first = (nxt.get("words") or "").split()[:1]
            if not first or not (first[0].isdigit() or first[0].lower() in NUMBER_WORDS | {"another", "all"}):
                continue  # the second move has its own verb: two statements
            if (st.get("words") or "").split()[0].lower() not in MOVE_VERBS:
                raise TranslationError(f"{quote(st['words'])} and {quote(nxt['words'])}: cannot tell whether "
                                       f"the first goes to {', '.join(nxt['to']['names'])} too")
            st["to"] = {"names": list(nxt["to"]["names"])}

    def _share(self, taken: dict, places: list[str], np: dict, key: str) -> dict:
        """A share of units just taken off a place ("take 3 off A and put 2 on B", "Move 3 lids from
        dispatch: 2 to silo 2 and the rest to rack east"): a move from that place, counted against
        what was taken; what is never given a place stays a removal (see :meth:`finish`). It was
        read as a final count for B before: a misreading."""
        if self.budget is None or self.budget["st"] is not taken:
            amount = self._taken_count(taken)
            if amount is None:
                raise TranslationError(f"{quote(np['words'])} after {taken['words']!r}: cannot tell how the "
                                       f"units taken are shared")
            at = next(k for k, st in enumerate(self.statements) if st is taken)
            del self.statements[at]
            self.budget = {"st": taken, "left": int(amount["count"])}
        left = self.budget["left"]
        n = left if key == "rest" else int(np["amount"][key])
        if n > left or (key == "rest" and n == 0):
            raise TranslationError(f"{quote(np['words'])}: only {left} of {taken['words']!r} are left to share")
        self.budget["left"] = left - n
        return {"op": "transfer", "items": taken["items"], "amount": {"count": n}, "from": taken["from"],
                "to": {"names": places}, "words": np["words"]}

    def _taken_count(self, taken: dict) -> dict | None:
        """How many units a removal took, as ``{"count": n}``: its count, or for "all" of one
        product off one place ("take the red cases out of the barrel hall: 2 to A, the rest to B")
        what the place holds now, where nothing said before touches that place (else the count
        would depend on the goal so far: None, refused)."""
        amount = taken["amount"]
        if set(amount) == {"count"}:
            return amount
        items = (taken.get("items") or {}).get("names") or []
        source = (taken.get("from") or {}).get("names") or []
        if not ({"all", "all_held"} & set(amount)) or len(items) != 1 or len(source) != 1 or amount.get("expect"):
            return None
        touched = [st for st in self.prior + self.statements if st is not taken and source[0] in (
            ((st.get("places") or {}).get("names") or []) + ((st.get("from") or {}).get("names") or [])
            + ((st.get("to") or {}).get("names") or []))]
        if touched:
            return None
        held = int(((self.lex.world.get("stock") or {}).get(source[0]) or {}).get(items[0], 0) or 0)
        return {"count": held} if held else None

    def _rest(self, places: list[str], np: dict) -> dict:
        """ "and the rest to P": what is left at the source of the statement before (in this
        sentence, or the last of the sentence before: "Take it down to 1. The extras go to P.")."""
        prev = self.statements[-1] if self.statements else (self.prior_last[-1] if self.prior_last else None)
        if not self.statements and prev is not None and self.prior_item_first:
            raise TranslationError(f"'{np['words']}': the rest of what the sentence before put there, or of "
                                   f"every one in the world? say where it comes from")
        if prev is None:
            raise TranslationError(f"'{np['words']}': the rest of what? (say where it comes from)")
        source = (prev.get("from") or {}).get("names") if prev["op"] == "transfer" else (
            prev.get("places") or {}).get("names")
        items = np["items"] or prev.get("items")
        if not source or not items or "names" not in items:
            raise TranslationError(f"'{np['words']}': the rest of what? (say where it comes from)")
        if np.get("rest_of") and np["rest_of"] != source:
            # "the rest of Q's X" after a move from P: nothing was taken from Q, so its rest is
            # not said (all of Q's? what P has left?)
            raise TranslationError(f"'{np['words']}': the rest of {', '.join(np['rest_of'])}'s, but the move "
                                   f"before takes from {', '.join(source)}; say how many")
        toks = self.lexed.tokens
        if prev["op"] == "set" and toks and (toks[0].type in ("ITEM", "ITEMWORD") or (
                toks[0].type == "NUM" and len(toks) > 1 and toks[1].type in ("ITEM", "ITEMWORD"))):
            # "tote bags: 1 on P, rest to Q", "1 tote bag on P, rest to Q": the sentence is about the
            # item, so "the rest" may be the rest of every tote bag, or of P's; neither is guessed
            raise TranslationError(f"'{np['words']}': the rest of {', '.join(source)}'s, or of every one in the "
                                   f"world? say where it comes from")
        return {"op": "transfer", "items": items, "amount": {"rest": True}, "from": {"names": source},
                "to": {"names": places}, "words": np["words"]}

    def apposition(self, places: list[str], nps: list[dict], words: str) -> None:
        """ "Shelf 2, which has 8 product1 now, ...": must agree with the world, else refused."""
        stock = self.lex.world.get("stock") or {}
        for np in nps:
            if "count" not in np["amount"] or not np["items"] or "names" not in np["items"]:
                raise TranslationError(f"{quote(words)}: cannot check this against the world")
            for p in places:
                for i in np["items"]["names"]:
                    have = int((stock.get(p) or {}).get(i, 0) or 0)
                    if have != np["amount"]["count"]:
                        raise TranslationError(f"{quote(words)}: {p} holds {have} {i}, not "
                                               f"{np['amount']['count']}; cannot tell which is meant")

    def _last_places(self, words: str) -> list[str]:
        if not self.last_places:
            raise TranslationError(f"{quote(words)}: the command does not say which shelf "
                                   f"(candidates: {self.index.candidates('shelf')})")
        return list(self.last_places)

    def _transfer_statement(self, np: dict, source: list[str] | None, target: list[str] | None,
                            words: str, exclude: list[str] | None = None) -> dict:
        a = np["amount"]
        if np["items"] is None:
            if not self.last_item:
                raise TranslationError(f"{quote(np['words'])}: cannot tell which product "
                                       f"(candidates: {self.index.candidates('product')})")
            np = {**np, "items": {"names": list(self.last_item)}}
        if set(a) & BOUND_AMOUNTS or set(a) & {"more", "fewer", "times", "as_many_as", "as_many_here"}:
            raise TranslationError(f"{quote(np['words'])}: cannot tell how many units this moves")
        if source and len(source) > 1 and "count" in a:
            self._count_from_each(source, a["count"], words)
        src: dict = {"names": source} if source else {"all": True, "except": list(exclude or [])}
        st = {"op": "transfer", "items": np["items"], "amount": a, "from": src,
              "to": {"names": target} if target else None, "words": words}
        return st

    def _count_from_each(self, source: list[str], count: Any, words: str) -> None:
        """A count taken from several places is taken from each where the words say so ("from
        each of A and B", "off every bay") or the user chose it; "take 2 X off A and B" may be 2 in
        all, so it is asked with the "each" reading offered (it was read as 2 from each: a guess).
        The user's "each" is ``picks["several_from"]``."""
        if self.distributive or self.picks.get("several_from") == "each":
            self.distributive = False
            return
        raise Choice("several_from", ("each",),
                     f"{quote(words)}: the command does not say whether {count} come from each of "
                     f"{', '.join(source)} or {count} in all (say 'from each', or how many from which)")

    def transfer(self, node: Tree, nps: list[dict], words: str) -> None:
        exc = self.sub(node, "except_places")
        # the order of "from" and "to" in the words: find which places list follows "from"
        kids = node.children
        src: list[str] | None = None
        dst: list[str] | None = None
        exclude: list[str] = []
        prev = None
        each = False   # "to each of P and Q": the count goes to each
        for c in kids:
            if isinstance(c, Tree) and c.data == "places":
                names = self.place_list(c)
                if prev == "to":
                    dst = names
                    each = any(isinstance(p, Tree) and p.data in ("place_each", "place_all", "place_all_n")
                               for p in c.children)
                else:
                    src = names
            elif isinstance(c, Tree) and c.data == "from":
                prev = "from"
            elif (isinstance(c, Tree) and c.data == "to") or (
                    isinstance(c, Token) and str(c.value).lower() in ("to", "into", "onto")):
                prev = "to"
            elif isinstance(c, Tree) and c.data == "except_places":
                exclude = self.place_list((self.sub(c, "places") or [c])[0])
        if exc:
            src = None
        if dst is None or (src is None and not exc):
            raise TranslationError(f"{quote(words)}: cannot tell where from and where to")
        for np in nps:
            if exc and not ({"all", "all_held", "fraction"} & set(np["amount"])):
                raise TranslationError(f"{quote(words)}: 'except' needs all of a product "
                                       f"('every keg ... except the ones on staging')")
            if each and len(dst) > 1 and "count" in np["amount"] and len(src or []) <= 1:
                # "send 3 X from S to each of P, Q and R": 3 to each, all from S
                self.distributive = False
                self.statements += [self._transfer_statement(np, src, [p], words, exclude) for p in dst]
                continue
            self.statements.append(self._transfer_statement(np, src, dst, words, exclude))

    def swap(self, node: Tree, words: str) -> None:
        places: list[str] = []
        heads: list[str] = []
        for c in node.children:
            if isinstance(c, Tree) and c.data == "posplace":
                places.append(str(c.children[0].value))
            elif isinstance(c, Tree) and c.data == "places":
                places.extend(self.place_list(c))
            elif isinstance(c, Tree) and c.data.startswith("loc"):
                places.extend(self.loc(c)[0])
            elif isinstance(c, Tree) and c.data == "ihead":
                heads.append(self.ihead(c, words))
            elif isinstance(c, Tree) and c.data == "swapwhat":
                heads += [self.ihead(h, words) for h in self.sub(c, "ihead")]
        places = list(dict.fromkeys(places))
        if len(places) != 2:
            raise TranslationError(f"{quote(words)}: a swap needs exactly two places "
                                   f"({len(places)} named)")
        if node.data == "g_swap_two" and len(heads) == 2 and heads[0] != heads[1]:
            # "Swap the product1 on shelf 1 with the product3 on shelf 2": those units change
            # places (all of X from A to B, all of Y from B to A), not each item's count between
            # the two places (a misreading of the earlier reader)
            for item, src, dst in ((heads[0], places[0], places[1]), (heads[1], places[1], places[0])):
                self.statements.append({"op": "transfer", "items": {"names": [item]}, "amount": {"all": True},
                                        "from": {"names": [src]}, "to": {"names": [dst]}, "words": words})
            return
        sel = {"names": list(dict.fromkeys(heads))} if heads else {"all": True}
        self.statements.append({"op": "swap", "places": {"names": places}, "items": sel, "words": words})

    # -- parts ------------------------------------------------------------------------------
    def part(self, node: Tree) -> None:
        d = node.data
        self.before_places = list(self.last_places or [])
        if d == "goal" or d.startswith("g_"):
            self.visit(node if d != "goal" else node.children[0])
        elif d.startswith("t_"):
            self.visit(node)
        elif d.startswith("rule_"):
            self.rule(node)
        elif d == "ensured_rule":   # "make sure the tuggers stay away from P": the rule itself
            self.part(next(c for c in node.children if isinstance(c, Tree) and c.data.startswith("rule_")))
        elif d == "aside":
            return
        elif d == "addressed_appos":
            robots_node = self.sub(node, "robots")[0]
            sel = self.robots.read(robots_node, self.robots_said(robots_node, addressed=True))
            said = [t for t in self.toks_any(node) if t.type in ("RKIND", "RTAG")][0]
            self.robots.check_apposition(sel, said.type, str(said.value), self.words(node))
            goal = next(c for c in node.children if isinstance(c, Tree) and c.data.startswith("g_"))
            self.visit(goal)
            self._rule_for(sel, "only", [], self.words(node))
        elif d == "addressed":
            robots_node = self.sub(node, "robots")[0]
            sel = self.robots.read(robots_node, self.robots_said(robots_node, addressed=True))
            before = len(self.statements)
            goal = next(c for c in node.children if isinstance(c, Tree) and c.data.startswith("g_"))
            self.visit(goal)
            self._rule_for(sel, "only", self.statements[before:], self.words(node))
        elif d in ("scoped_only", "scoped_only_after", "scoped_never_after", "scoped_never_before"):
            robots_node = self.sub(node, "robots")[0]
            sel = self.robots.read(robots_node, self.robots_said(robots_node))
            goal = next(c for c in node.children if isinstance(c, Tree) and c.data.startswith("g_"))
            self.visit(goal)
            mode = "never" if d in ("scoped_never_after", "scoped_never_before") else "only"
            base = {"mode": mode, "robots": sel, "words": self.words(node)}
            self.bind.append(base)
            self.rules.append(base)
        else:
            raise TranslationError(f"{quote(self.words(node))}: cannot read this")



def _expected(reader: SentenceReader, appos: Tree) -> int | None:
    """The count an apposition says the things come to ("all 5 of them": 5; "both": 2), or None
    where it says none ("all of them")."""
    if reader.toks(appos, "NUM"):
        return int(reader.toks(appos, "NUM")[0].value)
    return 2 if "both" in reader.words(appos).lower().split() else None

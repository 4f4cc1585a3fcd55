"""The offline parser: a command and a world in, an order (:mod:`pipflow.warehouse.language.order`) out.

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
"""
from __future__ import annotations

import functools
import json
from collections import OrderedDict
from typing import Any, Callable

from lark import Lark, Token, Tree
from lark.visitors import CollapseAmbiguities, Interpreter
from lark.exceptions import UnexpectedInput, UnexpectedToken

from pipflow.errors import PipflowError, Refusal, TranslationError
from pipflow.language.characters import line_readings
from pipflow.language.earley import ListLexer, earley_parser
from pipflow.language.lookahead import with_lookahead
from pipflow.warehouse.language.goals import Choice, GoalRules, quote
from pipflow.warehouse.language.grammar import GRAMMAR, nullable_optionals
from pipflow.warehouse.language.lexicon import Lexed, Lexicon
from pipflow.warehouse.language.repairs import near_words, with_word
from pipflow.language.numbers import NUMBER_WORDS
from pipflow.language.spelling import normalize
from pipflow.warehouse.language.resolver import resolve
from pipflow.warehouse.language.robots import RobotSelector
from pipflow.warehouse.language.tails import TailRules

#: the most terminals one sentence may have: Earley's time grows faster than the length on
#: ambiguous lists, so a bound per sentence keeps a whole command's parse linear in its length
MAX_SENTENCE_WORDS = 120
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
}
#: verbs whose object goes somewhere: a destination said later in the sentence is theirs too
MOVE_VERBS = {"move", "bring", "send", "ship", "transfer", "carry", "haul", "shift", "cart", "ferry", "tow",
              "lug", "shuttle", "wheel", "run", "relocate", "deliver", "pull", "grab", "stage", "gather",
              "consolidate", "collect"}
#: verbs whose object is the units themselves ("must not move them", "should handle it"); after
#: "do", "help with" or "work on" a pronoun is the task instead
ITEM_VERBS = {"move", "moves", "carry", "carries", "touch", "touches", "take", "takes", "deliver", "delivers",
              "send", "sends", "handle", "handles", "bring", "brings", "transport", "transports", "ship", "put",
              "place", "load", "unload", "fetch", "stock", "restock", "remove", "supply", "lift", "haul"}
PRONOUNS = {"it", "them", "that", "those", "these", "this"}
#: "P gets N X": a final count or a delivery; read only where both mean the same
RECEIVE_VERBS = {"get", "gets", "receive", "receives", "give"}


@functools.lru_cache(maxsize=1)
def _all_readings_parser() -> Lark:
    """Earley over the command grammar, keeping every reading (``_ambig`` nodes) so that they
    can be checked to agree. Built once per process (about a second: the one parser a run
    builds; cached on disk by :mod:`pipflow.language.earley`), predicting with one terminal of
    lookahead (:mod:`pipflow.language.lookahead`: the same forests, about a sixth of the time)."""
    return with_lookahead(earley_parser(nullable_optionals(GRAMMAR), lexer=ListLexer, keep_all_tokens=True,
                                        ambiguity="explicit"))


@functools.lru_cache(maxsize=1)
def keywords() -> dict[str, str]:
    """Keyword text -> terminal name, from the grammar's anonymous terminals."""
    out = {}
    for t in _all_readings_parser().terminals:
        if t.pattern.type == "str":
            out[t.pattern.value] = t.name
    return out


class _Sentence(GoalRules, TailRules, Interpreter):
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
        return " ".join(s.text for s in self.lexed.source[min(pos):max(pos) + 1]).replace(" zzposs", "'s")

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
                out.extend(self.last_places)
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
        self.last_places = out
        return out

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
            raise TranslationError(
                f"{quote(words)}: the command does not say whether each of {', '.join(places)} "
                f"gets these counts or they share them (say 'each', 'respectively' or 'evenly between')")
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
                if appos and self.toks(appos[0], "NUM"):
                    amount["expect"] = int(self.toks(appos[0], "NUM")[0].value)
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
        expect = None
        if appos and self.toks(appos[0], "NUM"):
            expect = int(self.toks(appos[0], "NUM")[0].value)
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
        guessed (B's final count was read)."""
        prev = self.statements[-1] if self.statements else None
        if prev is None or prev["op"] != "change" or "more" not in (prev.get("amount") or {}):
            return
        stock = self.lex.world.get("stock") or {}
        for np in nps:
            items = (np["items"] or prev.get("items") or {}).get("names") or []
            if set(np["amount"]) == {"count"} and any(
                    int((stock.get(p) or {}).get(i, 0) or 0) for p in places for i in items):
                raise TranslationError(f"{quote(np['words'])} after {prev['words']!r}: cannot tell whether it is "
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
        amount = taken["amount"]
        if set(amount) != {"count"}:
            raise TranslationError(f"{quote(np['words'])} after {taken['words']!r}: cannot tell how the units "
                                   f"taken are shared")
        if self.budget is None or self.budget["st"] is not taken:
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

    def _rest(self, places: list[str], np: dict) -> dict:
        """ "and the rest to P": what is left at the source of the statement before."""
        prev = self.statements[-1] if self.statements else None
        if prev is None:
            raise TranslationError(f"'{np['words']}': the rest of what? (say where it comes from)")
        source = (prev.get("from") or {}).get("names") if prev["op"] == "transfer" else (
            prev.get("places") or {}).get("names")
        items = np["items"] or prev.get("items")
        if not source or not items or "names" not in items:
            raise TranslationError(f"'{np['words']}': the rest of what? (say where it comes from)")
        if prev["op"] == "set" and self.lexed.tokens and self.lexed.tokens[0].type in ("ITEM", "ITEMWORD"):
            # "tote bags: 1 on P, rest to Q": the sentence is about the item, so "the rest" may be
            # the rest of every tote bag, or of P's; neither is guessed
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
        src: dict = {"names": source} if source else {"all": True, "except": list(exclude or [])}
        st = {"op": "transfer", "items": np["items"], "amount": a, "from": src,
              "to": {"names": target} if target else None, "words": words}
        return st

    def transfer(self, node: Tree, nps: list[dict], words: str) -> None:
        exc = self.sub(node, "except_places")
        # the order of "from" and "to" in the words: find which places list follows "from"
        kids = node.children
        src: list[str] | None = None
        dst: list[str] | None = None
        exclude: list[str] = []
        prev = None
        for c in kids:
            if isinstance(c, Tree) and c.data == "places":
                names = self.place_list(c)
                if prev == "to":
                    dst = names
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

    # -- ellipsis ---------------------------------------------------------------------------

    # -- rules ------------------------------------------------------------------------------
    def rule(self, node: Tree) -> None:
        kind = node.data
        words = self.words(node)
        if kind == "rule_never_group":  # "no forklift may carry widgets"
            said = [t for t in self.toks_any(node) if t.type in ("RKIND", "RTAG", "ROBOTWORD")][0]
            group = (self.robots.group(said.type, str(said.value)) if said.type in ("RKIND", "RTAG")
                     else {"names": list(self.index.by_kind["robot"])})
            scope = self.sub(node, "rscope")
            self.scoped({"mode": "never", "robots": group, "words": words}, scope[0] if scope else node)
            return
        robots_node = self.sub(node, "robots")
        if not robots_node:
            raise TranslationError(f"{quote(words)}: names no robot")
        sel = self.robots.read(robots_node[0], self.words(robots_node[0]))
        if kind == "rule_permission":
            raise TranslationError(f"cannot tell whether {quote(words)} requires or forbids the robots "
                                   f"(a permission restricts nothing: say 'only ...' or '... must not ...')")
        mode = {"rule_never": "never", "rule_state": "never", "rule_away": "never", "rule_only": "only",
                "rule_away_items": "never", "rule_never_from": "never", "rule_do_it": "only",
                "rule_use": "only"}[kind]
        base = {"mode": mode, "robots": sel, "words": words}
        if kind == "rule_state":
            self.rules.append(base)
            return
        if kind == "rule_do_it":
            self.bind.append(base)
            self.rules.append(base)
            return
        if kind == "rule_never_from":
            for p in self.place_list(self.sub(node, "places")[0]):
                self.rules.append({**base, "from": p})
            return
        if kind == "rule_away_items":
            for t in self.toks(node, "ITEM"):
                self.rules.append({**base, "product": str(t.value)})
            return
        if kind == "rule_away":
            for p in self.place_list(self.sub(node, "places")[0]):
                self.rules.append({**base, "from": p})
                self.rules.append({**base, "to": p})
            return
        scope = self.sub(node, "rscope")
        # "Using only robot 5, move ...", "... without robot 3": an instrument of the sentence's
        # goal, as a pronoun would be
        instrument = self.first_word(node) in ("using", "with", "by", "without")
        self.scoped(base, scope[0] if scope else node, instrument)  # scope words may sit on the rule itself

    def scoped(self, base: dict, scope: Tree | None, pronoun: bool = False) -> None:
        """One rule per product and place the scope names; none named: bound to the sentence."""
        products: list[str] = []
        places: list[dict] = []
        unscoped_all = False
        item_pronoun = False  # "must not move them": the pronoun is the object of the robots' work
        if scope is not None:
            for c in scope.children:
                if not isinstance(c, Tree):
                    continue
                if c.data == "ro_items":
                    products += [str(t.value) for t in c.children if isinstance(t, Token) and t.type == "ITEM"]
                    # "... may touch the steel sheets; move 3 of them": the item named last
                    # (one item only: after two, "move 2" would not say which)
                    self.last_item = products[:1] if len(set(products)) == 1 else None
                elif c.data == "ro_pronoun":
                    pronoun = True
                    said = (base.get("words") or "").lower().split()
                    at = max((k for k, w in enumerate(said) if w in PRONOUNS), default=0)
                    item_pronoun = at > 0 and said[at - 1] in ITEM_VERBS
                elif c.data == "ro_any":
                    unscoped_all = True
                elif c.data == "rw_from":
                    places += [{"from": p} for p in self.place_list((self.sub(c, "places") or [c])[0])]
                elif c.data == "rw_to":
                    places += [{"to": p} for p in self.place_list((self.sub(c, "places") or [c])[0])]
                elif c.data == "rw_at":
                    for p in self.place_list((self.sub(c, "places") or [c])[0]):
                        places += [{"from": p, "at": True}, {"to": p, "at": True}]
                elif c.data == "rw_route":
                    a, b = self.sub(c, "places")
                    for x in self.place_list(a):
                        for y in self.place_list(b):
                            places.append({"from": x, "to": y})
                elif c.data == "rw_pronoun":
                    pronoun = True
                elif c.data in ("rw_all",):
                    unscoped_all = True
        # "from shelf1 to shelf2" is one move, whether read as a route or as "from" then "to"
        merged: list[dict] = []
        for p in places:
            if merged and set(p) == {"to"} and set(merged[-1]) == {"from"}:
                merged[-1] = {**merged[-1], **p}
            else:
                merged.append(p)
        places = [{k: v for k, v in p.items() if k != "at"} for p in merged]  # "at P": to and from P
        if not products and not places:
            # no scope words: the rule holds for the whole command, unless a pronoun ("for
            # that", "move them") points at what the sentence asks for
            if pronoun and not unscoped_all:
                self.bind.append(base)
                if item_pronoun:
                    self.item_pronouns.append(base)
                if _for_this(base.get("words") or ""):
                    self.job_pronouns.append(base)
            self.rules.append(base)
            return
        for product in products or [None]:
            for place in places or [None]:
                r = dict(base)
                if product:
                    r["product"] = product
                if place:
                    r.update(place)
                self.rules.append(r)

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
        elif d == "aside":
            return
        elif d == "addressed_appos":
            robots_node = self.sub(node, "robots")[0]
            sel = self.robots.read(robots_node, self.words(robots_node))
            said = [t for t in self.toks_any(node) if t.type in ("RKIND", "RTAG")][0]
            self.robots.check_apposition(sel, said.type, str(said.value), self.words(node))
            goal = next(c for c in node.children if isinstance(c, Tree) and c.data.startswith("g_"))
            self.visit(goal)
            self._rule_for(sel, "only", [], self.words(node))
        elif d == "addressed":
            robots_node = self.sub(node, "robots")[0]
            sel = self.robots.read(robots_node, self.words(robots_node))
            before = len(self.statements)
            goal = next(c for c in node.children if isinstance(c, Tree) and c.data.startswith("g_"))
            self.visit(goal)
            self._rule_for(sel, "only", self.statements[before:], self.words(node))
        elif d in ("scoped_only", "scoped_only_after", "scoped_never_after", "scoped_never_before"):
            robots_node = self.sub(node, "robots")[0]
            sel = self.robots.read(robots_node, self.words(robots_node))
            goal = next(c for c in node.children if isinstance(c, Tree) and c.data.startswith("g_"))
            self.visit(goal)
            mode = "never" if d in ("scoped_never_after", "scoped_never_before") else "only"
            base = {"mode": mode, "robots": sel, "words": self.words(node)}
            self.bind.append(base)
            self.rules.append(base)
        else:
            raise TranslationError(f"{quote(self.words(node))}: cannot read this")

    def _rule_for(self, sel: dict, mode: str, statements: list[dict], words: str) -> None:
        """A rule of an addressed robot: bound to the sentence's goal (:meth:`finish`); where the
        sentence addresses several robots, each with its own goal ("the forklift take 2 X from P
        to Q, and the cobot 1 Y from R to Q"), each rule takes its own goal's scope."""
        base = {"mode": mode, "robots": sel, "words": words}
        self.bind.append(base)
        self.rules.append(base)
        if statements:
            self.own[id(base)] = list(statements)

    def finish(self) -> None:
        """Rules with no scope of their own take the sentence's goal (see the module doc)."""
        if self.budget and self.budget["left"]:  # units taken and not all shared out: still taken off
            self.statements.append({**self.budget["st"], "amount": {"count": self.budget["left"]}})
        self._shared_destination()
        if self.pending_source and not any(st["op"] == "transfer" for st in self.statements):
            raise TranslationError(f"'from {', '.join(self.pending_source)}': nothing in the sentence is taken from there")
        # "Empty rack D and put its valves on rack B": what leaves the place goes first, then
        # the rest of it is emptied (else the move would find the place already empty)
        for k, st in enumerate(list(self.statements)):
            if st["op"] != "empty":
                continue
            later = [t for t in self.statements[k + 1:] if t["op"] == "transfer"
                     and set((t.get("from") or {}).get("names") or []) & set(st["places"]["names"])]
            if later:
                self.statements.remove(st)
                at = self.statements.index(later[-1]) + 1
                self.statements.insert(at, st)
        statements = self.statements
        if self.bind and not statements and all(r in self.bind for r in self.rules):
            statements = self.prior_last  # "Empty shelf3. Robot 4 should do it."
        if not self.bind or not statements:
            for r in self.rules:
                r.pop("open", None)
            return
        own = [r for r in self.rules if id(r) in self.own]
        out: list[dict] = []
        for r in self.rules:
            if r in self.bind and not r.get("open"):
                scope = self.own[id(r)] if len(own) > 1 and id(r) in self.own else statements
                use_product, use_place = self._scope(scope)
                if (r in self.job_pronouns and not self.statements and (use_product or use_place)
                        and self.picks.get("scope") != "move"):   # a sentence of its own after the goal
                    if self.picks.get("scope") == "command":
                        out.append(dict(r))   # chosen: the whole job
                        continue
                    # "Move the hats to P. Don't use grip2 for this.": this job (no robot of it
                    # may be grip2), or this move (grip2 may still do any other)? Readers differ
                    # (both are in our held-out sets' golds); the rules allow different plans
                    raise Choice(
                        "scope", ("command", "move"),
                        f"{quote(r.get('words') or '')}: the rule may hold for the whole command or only for "
                        f"this move ({_scope_words(use_product, use_place)}); say which "
                        f"(e.g. 'for the whole job' or 'for that move')")
                new = dict(r)
                if use_product:
                    new["product"] = use_product
                if use_place:
                    if use_product and r in self.item_pronouns and self.picks.get("scope") == "item":
                        out.append(new)   # chosen: the product wherever it goes
                        continue
                    if use_product and r in self.item_pronouns and self.picks.get("scope") != "move":
                        # "only the forklift should handle it": it is the product (any move of
                        # it) or this move of it? Readers differ; the two rules allow different
                        # plans, so neither is guessed
                        raise Choice(
                            "scope", ("item", "move"),
                            f"{quote(r.get('words') or '')}: the rule may hold for {use_product} wherever it "
                            f"goes or only for this move of it ({', '.join(f'{k} {v}' for k, v in use_place.items())}); "
                            f"say which (e.g. 'for {use_product}' or 'for that move')")
                    new.update(use_place)
                out.append(new)
            else:
                r = dict(r)
                r.pop("open", None)
                out.append(r)
        self.rules = out

    @staticmethod
    def _scope(statements: list[dict]) -> tuple[str | None, dict | None]:
        """The one product and the one move (``{"from", "to"}``) of some statements, where each is
        one (None where several leave the field open)."""
        products: list[str] = []
        moves: list[dict] = []
        for s in statements:
            items = s.get("items") or {}
            products += items.get("names", []) if "names" in items else ["*"]
            if s["op"] == "transfer":
                src = (s.get("from") or {}).get("names") or ["*"]
                dst = (s.get("to") or {}).get("names") or [None]
                for a in src:
                    for b in dst:
                        moves.append({"from": a, **({"to": b} if b else {})})
            elif s["op"] == "empty":
                for p in (s.get("places") or {}).get("names", ["*"]):
                    moves.append({"from": p})
            elif s["op"] != "keep":
                for p in (s.get("places") or {}).get("names", ["*"]):
                    moves.append({"to": p})
        products = list(dict.fromkeys(products))
        uniq_moves = [dict(t) for t in dict.fromkeys(tuple(sorted(m.items())) for m in moves)]
        # "clear out staging and take everything to outbound": one move, staging -> outbound
        uniq_moves = [m for m in uniq_moves if not any(m != o and m.items() <= o.items() for o in uniq_moves)]
        places = {v for m in uniq_moves for v in m.values()}
        use_product = products[0] if len(products) == 1 and products[0] != "*" else None
        use_place = uniq_moves[0] if (len(uniq_moves) == 1 and "*" not in places) else None
        return use_product, use_place


def _clause_of(lexed: Lexed, k: int) -> list[int]:
    """The terminals of the clause (between commas or colons) that holds terminal ``k``."""
    marks = {",", ":"}
    start = k
    while start > 0 and str(lexed.tokens[start - 1].value) not in marks:
        start -= 1
    end = k
    while end + 1 < len(lexed.tokens) and str(lexed.tokens[end + 1].value) not in marks:
        end += 1
    if end + 1 < len(lexed.tokens):
        end += 1  # its comma goes with it
    elif start > 0:
        start -= 1
    return list(range(start, end + 1))


def _without(lexed: Lexed, drop: list[int]) -> Lexed:
    """The sentence with the terminals at ``drop`` left out (a candidate reading that does not
    read them; offered, never acted on unchosen)."""
    keep = [k for k in range(len(lexed.tokens)) if k not in set(drop)]
    tokens = [Token(lexed.tokens[k].type, lexed.tokens[k].value, start_pos=j) for j, k in enumerate(keep)]
    exact = frozenset(j for j, k in enumerate(keep) if k in lexed.exact)
    return Lexed(tokens, [lexed.source[k] for k in keep], exact)


def _fail(exc: UnexpectedInput, lexed: Lexed, lex: Lexicon) -> TranslationError:
    sentence = " ".join(t.text for t in lexed.source).replace(" zzposs", "'s")
    where = ""
    if isinstance(exc, UnexpectedToken) and exc.token.type != "$END":
        k = exc.token.start_pos
        word = lexed.source[k].text.replace("zzposs", "'s")
        prev = lexed.source[k - 1] if k > 0 else None
        if prev is not None and prev.kind == "num" and lexed.tokens[k].type == "UNKNOWN":
            error = TranslationError(f"'{prev.text} {word}': cannot tell which product this count is for "
                                     f"(candidates: {lex.index.candidates('product')})")
            error.unplaced, error.word = k, word  # type: ignore[attr-defined]
            error.clause = _clause_of(lexed, k)  # type: ignore[attr-defined]
            return error
        where = f"cannot place '{word}' in '{sentence}'"
        error = TranslationError(f"{where}: the command is not understood, so nothing is guessed "
                                 f"(shelves: {lex.index.candidates('shelf')}; products: "
                                 f"{lex.index.candidates('product')}; robots: {lex.index.candidates('robot')}; "
                                 f"robot groups: {lex.group_names()})")
        error.unplaced, error.word = k, word  # type: ignore[attr-defined]
        error.clause = _clause_of(lexed, k)  # type: ignore[attr-defined]
        return error
    else:
        kinds = [t.type for t in lexed.tokens]
        if "PLACE" not in kinds and "ITEM" in kinds and "ROBOT" not in kinds:
            first = kinds.index("ITEM")
            start = first - 1 if first > 0 and kinds[first - 1] == "NUM" else first
            shown = " ".join(t.text for t in lexed.source[start:first + 1])
            return TranslationError(f"'{shown}': the command does not say which shelf "
                                    f"(candidates: {lex.index.candidates('shelf')})")
        where = f"'{sentence}' ends before it says what to do"
    return TranslationError(f"{where}: the command is not understood, so nothing is guessed "
                            f"(shelves: {lex.index.candidates('shelf')}; products: "
                            f"{lex.index.candidates('product')}; robots: {lex.index.candidates('robot')}; "
                            f"robot groups: {lex.group_names()})")


def _for_this(words: str) -> bool:
    """"for this" / "for that" with no noun after it: the job, or the move just said? ("for that
    move" says which; "for this job" is read as the whole command by the grammar)."""
    said = words.lower().split()
    return any(w == "for" and said[k + 1:k + 2] in (["this"], ["that"])
               and said[k + 2:k + 3] not in (["move"], ["transfer"], ["trip"], ["run"]) for k, w in enumerate(said))


def _scope_words(product: str | None, place: dict | None) -> str:
    """A move's scope in words: "top_hat, from scene_dock, to green_room"."""
    return ", ".join(([product] if product else []) + [f"{k} {v}" for k, v in (place or {}).items()])


def _read(tree: Tree, lexed: Lexed, lex: Lexicon, selector: RobotSelector, memory: dict,
          picks: dict | None = None) -> _Sentence:
    reader = _Sentence(lexed, lex, selector, memory, picks)
    for part in tree.children[0].children:
        if isinstance(part, Tree) and part.data not in ("sep", "lead"):
            reader.part(part)
    reader.finish()
    return reader


#: readings of one sentence compared at most; beyond, the sentence is refused as too ambiguous
MAX_READINGS = 64
#: readings offered at most when a command is refused (issue 23: ask rather than refuse)
MAX_CANDIDATES = 3


def canonical(goal: dict, constraints: list[dict]) -> str:
    """A meaning in one form, so that two readings that ask for the same thing compare equal: the
    goal's places and items in sorted order; the rules as a set (a conjunction: order and
    repetition do not matter), robot lists as sets, a ``never`` rule one rule per robot (never
    [a, b] forbids what never [a] and never [b] forbid), and a rule's source words left out.
    Two readings that are the same rule said twice are one reading, never "two ways"."""
    rules: set[str] = set()
    for rule in constraints:
        scope = {k: v for k, v in rule.items() if k not in ("only", "never", "words")}
        if "never" in rule:
            rules |= {json.dumps({**scope, "never": r}, sort_keys=True, default=str) for r in rule["never"]}
        else:
            rules.add(json.dumps({**scope, "only": sorted(rule.get("only") or [])}, sort_keys=True, default=str))
    return json.dumps([goal, sorted(rules)], sort_keys=True, default=str)


def _meaning(reader: _Sentence, world: dict) -> str | None:
    """What a reading asks for, for comparison: its resolved goal and rules in one form
    (:func:`canonical`; None when the reading does not resolve on its own: it is then no
    meaning to compare)."""
    try:
        r = resolve({"statements": reader.statements, "rules": reader.rules}, world, check=False)
    except PipflowError:
        return None
    return canonical(r.goal, r.constraints)


def _parts(tree: Tree) -> int:
    return sum(1 for p in tree.children[0].children if isinstance(p, Tree) and p.data not in ("sep", "lead"))


#: parse forests of recent sentences, by their terminals (the grammar is the same in every world,
#: and a sentence's terminals are all the parse sees): a candidate reading re-reads the sentences
#: that did parse, and a command's two line readings share most sentences
_FORESTS: "OrderedDict[tuple, tuple[bool, Any]]" = OrderedDict()
_FORESTS_KEPT = 256
#: new sentence parses one refusal may spend on its candidate readings (a parse of a sentence read
#: before is remembered and free): the candidates of a refused command cost at most this many
#: parses more than the refusal itself. With the lookahead predictor a parse costs a sixth of what
#: it did, so a refusal may try four partial parses of up to three words each (9 parses) and still
#: read faster than a344570 (benchmarks/parse_speed.py)
CANDIDATE_PARSES = 9
_CANDIDATE_BUDGET: dict[str, int | None] = {"left": None}


def _tree(tokens: list[Token]) -> Tree:
    """The Earley forest of a sentence's terminals (every reading), or the parse error it raised,
    remembered for the last :data:`_FORESTS_KEPT` sentences. Readers only read the forest (lark's
    Interpreter and CollapseAmbiguities build new trees), so one forest serves every reading."""
    key = tuple((t.type, repr(t.value)) for t in tokens)
    hit = _FORESTS.get(key)
    if hit is None:
        if _CANDIDATE_BUDGET["left"] is not None:
            if _CANDIDATE_BUDGET["left"] <= 0:
                raise TranslationError("no parse left for candidate readings")
            _CANDIDATE_BUDGET["left"] -= 1
        try:
            hit = (True, _all_readings_parser().parse(tokens))
        except UnexpectedInput as exc:
            hit = (False, exc)
        _FORESTS[key] = hit
        if len(_FORESTS) > _FORESTS_KEPT:
            _FORESTS.popitem(last=False)
    else:
        _FORESTS.move_to_end(key)
    if not hit[0]:
        raise hit[1]
    return hit[1]


def _one_meaning(lexed: Lexed, lex: Lexicon, selector: RobotSelector, world: dict, memory: dict,
                 picks: dict | None = None) -> _Sentence:
    """Read a sentence in every way the grammar allows, and keep its meaning only if there is one.

    Readings that make no sense (an error, or nothing that resolves) are not meanings. Of the
    rest, all must ask for the same goal and rules, or the sentence is refused with two of
    them: the grammar's preferences never choose between meanings silently. The reading kept
    is the one with the fewest, longest parts.
    """
    picks = picks or {}
    tree = _tree(lexed.tokens)
    if not any(t.data == "_ambig" for t in tree.iter_subtrees()):
        return _read(tree, lexed, lex, selector, memory, picks)
    sentence = " ".join(t.text for t in lexed.source).replace(" zzposs", "'s")
    readings: list[tuple[int, _Sentence, str | None]] = []
    errors: list[tuple[int, PipflowError]] = []
    for k, alt in enumerate(CollapseAmbiguities().transform(tree)):
        if k >= MAX_READINGS:
            raise TranslationError(f"'{sentence}' can be read in too many ways to be sure of one; "
                                   f"say it in shorter sentences")
        try:
            reader = _read(alt, lexed, lex, selector, memory, picks)
        except PipflowError as exc:
            errors.append((_parts(alt), exc))
            continue
        readings.append((_parts(alt), reader, _meaning(reader, world)))
    if not readings:
        raise min(errors, key=lambda e: e[0])[1]
    meant = [(n, r, m) for n, r, m in readings if m is not None]
    distinct = list(dict.fromkeys(m for _, _, m in meant))
    if len(distinct) > 1:
        if picks.get("reading") is not None:   # chosen by the user among the candidates
            return min((x for x in meant if x[2] == distinct[picks["reading"]]), key=lambda x: x[0])[1]
        (_, a, _), (_, b, _) = meant[0], next(x for x in meant if x[2] != meant[0][2])
        wa = "; ".join(s["words"] for s in a.statements + a.rules)
        wb = "; ".join(s["words"] for s in b.statements + b.rules)
        raise Choice("reading", tuple(range(min(len(distinct), MAX_CANDIDATES))),
                      f"'{sentence}' can be read in two ways that ask for different things "
                      f"('{wa}' or '{wb}'); nothing is guessed: say it another way")
    return min(meant or readings, key=lambda x: x[0])[1]


def parse(command: str, world: dict) -> dict:
    """The order of a command: ``{"statements": [...], "rules": [...], "command": command}``.

    Raises :class:`TranslationError` quoting the words it cannot place (or a character it does
    not read: :mod:`pipflow.language.characters`), :class:`InputError` for a command too long to
    be one, and :class:`Refusal` for counts that cannot exist (negative).

    A line break ends a sentence; a command whose lines only make sense joined (a sentence
    wrapped onto the next line) is read joined, and one that makes sense both ways with two
    different meanings is refused, quoting both (:func:`pipflow.language.characters.line_readings`).
    """
    readings = line_readings(command)
    if len(readings) == 1:
        try:
            return {**_parse(readings[0], world), "command": command}
        except TranslationError as exc:
            exc.candidates = candidates(readings[0], world, exc)
            if exc.candidates:
                exc.args = (f"{exc.args[0]}. Did you mean: " + "; or ".join(
                    f"({k}) {c['reading']} [from '{c['words']}']" for k, c in enumerate(exc.candidates, 1))
                    + "? Say it so, or choose one",)
            raise
    broken, joined = readings
    try:
        first = _parse(broken, world)
    except (TranslationError, Refusal) as exc:
        try:
            return {**_parse(joined, world), "command": command}
        except (TranslationError, Refusal):
            raise exc from None
    try:
        second = _parse(joined, world)
    except (TranslationError, Refusal):
        return {**first, "command": command}
    a, b = _meaning_of(first, world), _meaning_of(second, world)
    if b is not None and a != b:
        if a is None:
            return {**second, "command": command}
        wa = "; ".join(s["words"] for s in first["statements"] + first["rules"])
        wb = "; ".join(s["words"] for s in second["statements"] + second["rules"])
        raise TranslationError(f"the line breaks of '{broken}' can end sentences ('{wa}') or continue them "
                               f"('{wb}'), and the two readings ask for different things; nothing is guessed: "
                               f"end each sentence with a full stop")
    return {**first, "command": command}


def candidates(command: str, world: dict, exc: TranslationError) -> list[dict]:
    """Up to :data:`MAX_CANDIDATES` readings to offer for a command refused as not understood or
    ambiguous (issue 23: ask rather than refuse), each ``{"reading", "words", "goal",
    "constraints", "order"}``: the competing readings of an ambiguous sentence, and for a word no
    rule places, the sentence without that word, without its clause, without the words that open
    its clause, and (in a command of several sentences) without the sentence. Each is the whole
    command read with that one choice and resolved against the world; readings that do not
    resolve, or repeat another's meaning, are not offered. Nothing here is acted on: a user (or
    the bench) chooses."""
    sentence = getattr(exc, "sentence", None)
    if sentence is None:
        picks: list[dict] = []
    elif isinstance(exc, Choice):
        picks = [{sentence: {exc.key: option}} for option in exc.options]
    else:
        picks = []  # a word no rule places: the partial parses below leave it (or its clause) out first
    if getattr(exc, "trimmed", False):
        picks = [{k: {**p, "trimmed": True} for k, p in pick.items()} for pick in picks]
    # partial parses: in every sentence, the words no rule places (or their clauses) left out one
    # after another, the clauses that do parse kept, the words left out named
    picks += [{"*": {"salvage": how}} for how in SALVAGE]
    out: list[dict] = []
    seen: set[str] = set()
    _CANDIDATE_BUDGET["left"] = CANDIDATE_PARSES
    word = getattr(exc, "word", None)
    # the readings to try, in order; the first three that resolve to different meanings are
    # offered, so the search stops there (what it would find later is never offered)
    tries: list[Callable[[], None]] = [
        *(functools.partial(_candidate, command, world, pick, out, seen) for pick in picks[:-len(SALVAGE)]),
        # a word no rule places may be a near miss of a word that has a place: the command read
        # with it respelt, once for each near word, the repair said in the echo
        *(functools.partial(_with_choices, repaired, world, {}, out, seen, note=f"read '{word}' as '{right}'")
          for right in (near_words(word, _lexed(command, world)[0]) if word else [])
          for repaired in [with_word(command, word, right)] if repaired is not None),
        *(functools.partial(_with_choices, command, world, pick, out, seen) for pick in picks[-len(SALVAGE):]),
    ]
    try:
        for attempt in tries:
            if len(out) >= MAX_CANDIDATES:
                break
            attempt()
    finally:
        _CANDIDATE_BUDGET["left"] = None
    return out[:MAX_CANDIDATES]


#: the partial parses a refusal offers, in this order (:func:`_dropped`; "sentence": a sentence
#: that does not read left out of a command of several)
SALVAGE = ("clause", "word", "lead", "sentence")


def _with_choices(command: str, world: dict, pick: dict, out: list[dict], seen: set[str], note: str = "") -> None:
    """:func:`_candidate`, and where that reading stops at a sentence with competing readings (a
    :class:`Choice`: "put 3" in all or more?), the reading once with each of them."""
    error = _candidate(command, world, pick, out, seen, note)
    sentence = getattr(error, "sentence", None)
    if isinstance(error, Choice) and sentence is not None and error.key not in (pick.get(sentence) or {}):
        for option in error.options:
            if len(out) >= MAX_CANDIDATES:
                return
            _candidate(command, world, {**pick, sentence: {**(pick.get(sentence) or {}), error.key: option}},
                       out, seen, note)


def _candidate(command: str, world: dict, pick: dict, out: list[dict], seen: set[str],
               note: str = "") -> PipflowError | None:
    """The command read with one pick, resolved, added to ``out`` unless it fails (the error is
    returned) or repeats a meaning already offered; ``note`` (a repair made to the command) is
    said in its echo."""
    try:
        order = _parse(command, world, pick)
        got = resolve(order, world)
    except PipflowError as exc:
        return exc
    meaning = canonical(got.goal, got.constraints)
    if meaning in seen:
        return
    seen.add(meaning)
    unread = order.get("unread") or []
    explanation = (([note] if note else []) + list(got.explanation)
                   + ([f"not read: {', '.join(repr(w) for w in unread)}"] if unread else []))
    out.append({"reading": "; ".join(explanation), "explanation": explanation,
                "goal": got.goal, "constraints": got.constraints, "unread": unread,
                "words": "; ".join(x["words"] for x in order["statements"] + order["rules"]), "order": order})


#: words (or clauses) a partial parse may leave out of one sentence, at most: each costs a parse of
#: the sentence (a third one added 1 of 86 refused gold readings to the candidates, 2026-12-02; it
#: is affordable since parses take a sixth of the time)
MAX_SALVAGED = 3


def _salvage(lexed: Lexed, lex: Lexicon, selector: RobotSelector, world: dict, memory: dict,
             pick: dict, how: str) -> tuple[_Sentence, list[str]]:
    """A candidate reading of a sentence that does not read: the word no rule places (``how`` =
    "word") or its clause ("clause") left out, again while another word cannot be placed, up to
    :data:`MAX_SALVAGED` times; returns the reading and the words left out (named in the
    candidate's echo). Only ever offered, never acted on unchosen."""
    unread: list[str] = []
    for _ in range(MAX_SALVAGED + 1):
        try:
            return _one_meaning(lexed, lex, selector, world, memory, pick), unread
        except UnexpectedInput as exc:
            error = _fail(exc, lexed, lex)
            if getattr(error, "unplaced", None) is None:
                # it ends before it says what to do: the last word is the one that does not fit
                error.unplaced, error.clause = len(lexed.tokens) - 1, [len(lexed.tokens) - 1]  # type: ignore[attr-defined]
        except TranslationError as exc:
            error = exc
        k = getattr(error, "unplaced", None)
        if k is None or len(unread) >= MAX_SALVAGED:
            raise error
        drop = _dropped(how, k, list(error.clause), lexed)  # type: ignore[attr-defined]
        unread.append(" ".join(lexed.source[j].text for j in drop if j < len(lexed.source)
                               and lexed.tokens[j].type != ",").replace(" zzposs", "'s"))
        lexed = _without(lexed, drop)
        if not lexed.tokens:
            raise error
    raise TranslationError("nothing left to read")


def _said(lexed: Lexed) -> str:
    """A sentence's words as the user wrote them (for an echo)."""
    return " ".join(t.text for t in lexed.source).replace(" zzposs", "'s")


def _dropped(how: str, k: int, clause: list[int], lexed: Lexed) -> list[int]:
    """The terminals a partial parse leaves out for the word at ``k`` that no rule places: the
    word ("word"), its clause ("clause"), or the word that opens its clause ("lead": what led the
    parser astray, as "could" in "could two more X go to P"; again while the next still does not
    read, up to :data:`MAX_SALVAGED`; the word itself when it opens its clause)."""
    if how == "word":
        return [k]
    if how == "lead":
        opening = [j for j in clause if j < k and str(lexed.tokens[j].value) not in (",", ":")]
        return opening[:1] or [k]
    return clause


def _meaning_of(order: dict, world: dict) -> str | None:
    """What an order asks for, for comparing two readings (None: it does not resolve)."""
    try:
        r = resolve(order, world, check=False)
    except PipflowError:
        return None
    return canonical(r.goal, r.constraints)


#: the lexicon and sentences of recent commands, by the command, the world object and the names
#: in it (what the lexicon reads of a world; counts are read live from the world): a refusal's
#: candidate readings re-read the same command up to a dozen times (each with another pick), and
#: tokenising it took a quarter of a refusal's time. Lexed sentences are never changed in place
#: (a partial parse builds new ones), so one serves every reading.
_LEXED: "OrderedDict[tuple, tuple[dict, Lexicon, RobotSelector, list[Lexed]]]" = OrderedDict()
_LEXED_KEPT = 8


def _names_of(world: dict) -> tuple:
    """What the lexicon reads of a world: its names, and the robots' kinds, tags and skills."""
    robots = world.get("robots") or {}
    return (tuple(world.get("shelves") or ()), tuple(world.get("products") or ()),
            tuple((str(r), repr(v.get("kind")), repr(v.get("tags")), tuple(v.get("skills") or ()))
                  if isinstance(v, dict) else (str(r),) for r, v in robots.items()))


def _lexed(command: str, world: dict) -> tuple[Lexicon, RobotSelector, list[Lexed]]:
    """(lexicon, robot selector, sentences) of ``command`` in ``world``, remembered for the last
    :data:`_LEXED_KEPT` commands (the same world object only: a changed world is a new object)."""
    key = (command, id(world), _names_of(world))
    hit = _LEXED.get(key)
    if hit is not None and hit[0] is world:
        _LEXED.move_to_end(key)
        return hit[1], hit[2], hit[3]
    lex = Lexicon(world, keywords())
    selector = RobotSelector(world, lex.index)
    sentences = lex.sentences(command)
    _LEXED[key] = (world, lex, selector, sentences)
    if len(_LEXED) > _LEXED_KEPT:
        _LEXED.popitem(last=False)
    return lex, selector, sentences


def _parse(command: str, world: dict, picks: dict | None = None) -> dict:
    """:func:`parse` of one reading of the line breaks. ``picks``: for a sentence (its index), the
    reading a user chose among candidates: ``{"reading": k}``, ``{"scope": ...}``, or ``{"drop":
    [token indexes]}`` (words left out of it); none in an ordinary run."""
    picks = picks or {}
    lex, selector, sentences = _lexed(command, world)
    statements: list[dict] = []
    rules: list[dict] = []
    memory: dict = {}
    set_aside: list[str] = []
    unread: list[str] = []  # words a candidate reading left out (salvage mode only)
    for index, lexed in enumerate(sentences):
        if not lexed.tokens:
            continue
        pick = picks.get(index) or {}
        if pick.get("trimmed") and lexed.trimmed is not None:
            set_aside += list(lexed.aside)
            lexed = lexed.trimmed
        if pick.get("drop"):
            lexed = _without(lexed, pick["drop"])
            if not lexed.tokens:
                continue
        if len(lexed.tokens) > MAX_SENTENCE_WORDS:
            shown = " ".join(t.text for t in lexed.source[:12])
            raise TranslationError(f"the sentence '{shown} ...' has {len(lexed.tokens)} words; sentences "
                                   f"are read up to {MAX_SENTENCE_WORDS} words (end it with a full stop "
                                   f"and go on in a new one)")
        salvage = (picks.get("*") or {}).get("salvage")
        try:
            if salvage and salvage != "sentence":
                reader, left_out = _salvage(lexed.trimmed or lexed, lex, selector, world, memory, pick, salvage)
                unread += left_out
                set_aside += list(lexed.aside) if lexed.trimmed is not None else []
            else:
                reader = _one_meaning(lexed, lex, selector, world, memory, pick)
        except (UnexpectedInput, TranslationError) as exc:
            # the sentence as said does not read; without its content-free clauses it may
            # (asides.py): they are set aside and said aloud, the rest still needs every word
            error = _fail(exc, lexed, lex) if isinstance(exc, UnexpectedInput) else exc
            error.sentence = index  # type: ignore[attr-defined]  # for the candidates (parse)
            if salvage and salvage != "sentence":
                raise error from None  # the partial parse read the sentence without its talk already
            if lexed.trimmed is None:
                if salvage == "sentence" and len(sentences) > 1 and not isinstance(error, Choice):
                    # a candidate reading without this sentence (one that reads, with competing
                    # meanings, is offered with each of them instead: never dropped)
                    unread.append(_said(lexed))
                    continue
                raise error from None
            try:
                reader = _one_meaning(lexed.trimmed, lex, selector, world, memory, pick)
            except (UnexpectedInput, TranslationError) as again:
                # what is left after the talk is set aside is what does not read: say that
                error = _fail(again, lexed.trimmed, lex) if isinstance(again, UnexpectedInput) else again
                error.sentence, error.trimmed = index, True  # type: ignore[attr-defined]
                error.args = (f"{error.args[0]} (set aside: {'; '.join(repr(a) for a in lexed.aside)})",)
                if salvage == "sentence" and len(sentences) > 1 and not isinstance(error, Choice):
                    unread.append(_said(lexed))
                    continue
                raise error from None
            set_aside += list(lexed.aside)
        for k, new in reader.updates.items():
            statements[k] = new
        statements += reader.statements
        rules += reader.rules
        memory = {"statements": list(statements), "last": list(reader.statements) or memory.get("last", []),
                  "item": reader.last_item, "places": reader.last_places,
                  "received": reader.received | set(memory.get("received") or ())}
    if not statements and not rules:
        raise TranslationError(f"found no goal and no robot rule in '{command}' "
                               f"(shelves: {lex.index.candidates('shelf')}; "
                               f"products: {lex.index.candidates('product')})")
    set_aside = lex.aside + set_aside
    return {"command": command, "statements": statements, "rules": rules,
            **({"set_aside": set_aside} if set_aside else {}), **({"unread": unread} if unread else {})}

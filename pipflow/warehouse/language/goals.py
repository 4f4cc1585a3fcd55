"""The goal rules of the warehouse's command grammar: one method per rule.

Each goal construction of the grammar (:mod:`pipflow.warehouse.language.grammar`) has an alias
``g_...``: ``g_set`` ("put 4 X on P"), ``g_transfer_src`` ("move 3 X from P to Q"), ``g_swap``,
``g_empty_except``, ... The sentence reader (:mod:`pipflow.warehouse.language.parser`) is a lark
:class:`~lark.visitors.Interpreter` that inherits :class:`GoalRules`: a goal clause's tree goes to
the method its rule names, as pyperplan's tree visitor does, and the method turns it into
statements of the order (:mod:`pipflow.warehouse.language.order`). Nothing here counts against
the stock: relative amounts, "the rest" and ellipsis stay symbolic for the resolver.

The methods share the reader's state: the statements and rules read so far, the item and places
an ellipsis refers to, a source said before its moves. Each starts from the clause's
parts (:class:`ClauseParts`), read in the same order for every rule, because reading an item
phrase may refuse the command or remember its item for the next clause. The rules that a bare
item may fill (``bare=True``: "take the drums out of bay 2" moves all of them) read it there too.
"""
from __future__ import annotations

from dataclasses import dataclass

from lark import Token, Tree

from pipflow.errors import TranslationError


def quote(words: str) -> str:
    """Words of the command, quoted in a message."""
    return f"'{words}'"


class Asked(TranslationError):
    """A sentence read with two meanings the words do not choose between, refused with the
    question ("1 more or 1 in all?"), with no option the reader can be told to pick. Like a
    :class:`Choice`, it makes a line break that may end the sentence or go on an ambiguity of the
    command (:func:`pipflow.warehouse.language.parser.parse`)."""


class Choice(TranslationError):
    """A sentence with several readings that ask for different things: which one is ``key``'s
    option; the parser offers each as a candidate reading (never picks one itself)."""

    def __init__(self, key: str, options: tuple, message: str):
        super().__init__(message)
        self.key, self.options = key, options


#: verbs of placing whose count is a final count or a delivery, as the place holds the item or not:
#: "put 2 X on P" where P holds none is 2 either way; where P holds some, 2 in all or 2 more?
PLACING_VERBS = {"put", "place", "stick", "pop", "park", "store", "stock"}
#: "P needs N X" says what P lacks as often as what it should end with: asked where P holds some X
NEEDING_VERBS = {"need", "needs"}
#: words that make such a count a final one ("in total", "in all", "altogether", "final count")
FINAL_WORDS = {"total", "all", "altogether", "final", "overall"}


def leaving_out_what_stays(empty: dict, moves: list[dict], statements: list[dict]) -> list[dict]:
    """The moves of everything on an emptied place ("Empty the kaai except the pigment, everything
    to the hoogbouw"), with what the emptying leaves out left out of them too, replaced in
    ``statements`` as well: the pigment stays (it was moved with the rest, a misreading). A move of
    named things keeps its names."""
    kept = (empty.get("items") or {}).get("except") or []
    out: list[dict] = []
    for move in moves:
        items = move.get("items") or {}
        if kept and items.get("all"):
            narrowed = {**move, "items": {**items, "except": list(dict.fromkeys([*(items.get("except") or []), *kept]))}}
            statements[statements.index(move)] = narrowed
            move = narrowed
        out.append(move)
    return out


@dataclass
class ClauseParts:
    """What a goal clause says, before its rule's method reads the rest: the rule (``kind``), the
    words it spans, its item phrases (``items``) read as counts of items (``nps``), its location
    phrases (``locs``), its place lists (``plist``), and whether it says "each" or "both"."""

    kind: str
    words: str
    items: list[Tree]
    nps: list[dict]
    locs: list[Tree]
    plist: list[Tree]
    each: bool


def _held(world: dict, place: str, item: str) -> int:
    """Units of an item on a place now (the world's stock; missing means zero)."""
    return int(((world.get("stock") or {}).get(place) or {}).get(item, 0) or 0)


class GoalRules:
    """The goal rules, one method each (several aliases of one construction share a method),
    mixed into the sentence reader, whose state they use."""

    def clause_parts(self, node: Tree, bare: bool = False) -> ClauseParts:
        """The clause's parts (see :class:`ClauseParts`); ``bare``: an item said without a count
        is all of it ("take the drums out of bay 2")."""
        words = self.words(node)
        items = self.sub(node, "items")
        nps = self.nps(items[0]) if items else []
        locs = [c for c in node.children if isinstance(c, Tree) and c.data in ("loc", "loc_each", "loc_resp")]
        plist = self.sub(node, "places")
        each = bool(self.sub(node, "each") or self.sub(node, "both")) or any(
            isinstance(c, Token) and c.value in ("each", "both") for c in node.children)
        if bare and self.sub(node, "bare"):
            nps = self.bare_nps(node, words)
        return ClauseParts(node.data, words, items, nps, locs, plist, each)

    def g_set(self, node: Tree) -> None:
        parts = self.clause_parts(node)
        kind, words, nps, locs = parts.kind, parts.words, parts.nps, parts.locs
        if not locs:
            shown = ", ".join(n["words"] for n in nps)
            raise TranslationError(f"{quote(shown)}: the command does not say which shelf "
                                   f"(candidates: {self.index.candidates('shelf')})")
        places, mode = self.loc(locs[0])
        if any(isinstance(c, Token) and str(c.value).lower() == "each" for c in node.children):
            mode = "each"  # "Put 2 springs each on rack B and rack E"
        # "Add 2 lids to A, 1 to B": a part with no verb of its own shares the add verb before it
        # (it was read as B's final count: a misreading)
        bare = len(node.children) == 2 and kind == "g_set"
        if bare and not self.last_add:
            self._gap_after_more(nps, places)
        add = bare and self.last_add
        verb = self.sub(node, "putv")
        several = len(places) > 1 and mode not in ("each", "respectively", "resp") and not self.distributive
        if verb and not several and self.first_word(verb[0]) in PLACING_VERBS and self._put_adds(places, nps, words, mode):
            add = True
        self.put(places, mode, nps, words, add=add)
        if kind == "g_set_only":
            self.statements.append({"op": "nothing_else", "places": {"names": places},
                                    "words": "nothing else"})

    def _put_adds(self, places: list[str], nps: list[dict], words: str, mode: str = "one", said: str = "put") -> bool:
        """Whether "put N X on P" is a delivery: where P holds none of X it does not matter (a final
        count, as read before); where P holds some, "put" says neither "in all" nor "more", so
        the sentence is refused with both readings offered (``picks["put"]``: the user's choice)."""
        if self.budget:
            return True  # "take 3 X off P and put 2 on Q": the units taken, delivered
        pairs = ([(p, np) for p, np in zip(places, nps)] if mode in ("respectively", "resp")
                 else [(p, np) for p in places for np in nps])
        held = [(p, np) for p, np in pairs if "count" in np["amount"] and np["items"]
                for i in (np["items"].get("names") or [])
                if _held(self.lex.world, p, i) > 0]
        if not held:
            return False
        choice = self.picks.get("put")
        if choice is None:
            p, np = held[0]
            n = np["amount"]["count"]
            raise Choice("put", ("set", "add"),
                         f"{quote(words)}: {p} already holds some; '{said} {n}' can mean {n} there in all or "
                         f"{n} more; nothing is guessed: say '{n} in all' or '{n} more'")
        return choice == "add"

    g_loc_set = g_set

    g_set_only = g_set

    def g_place_set(self, node: Tree) -> None:
        parts = self.clause_parts(node)
        words, nps, plist, each = parts.words, parts.nps, parts.plist, parts.each
        places = self.place_list(plist[0])
        for ap in self.sub(node, "place_appos"):
            self.apposition(places, self.nps(self.sub(ap, "items")[0]), self.words(ap))
        self._receive_is_clear(node, places, nps, words)
        # "P needs N X" where P holds some: N in all or N more, as "put N" (benchmarks/language README, 2)
        setv = self.sub(node, "setv")
        said = self.first_word(setv[0]) if setv else ""
        final = bool(FINAL_WORDS & set(words.lower().split()))   # "needs 10 in total": said in all
        add = (said in NEEDING_VERBS and not each and not final and len(places) == 1
               and self._put_adds(places, nps, words, said=said))
        start = len(self.statements)
        self.put(places, "each" if each else "one", nps, words, add=add)
        for st in self.statements[start:]:
            if st["op"] == "set":   # the place first, then its count: in all, whatever a source said after it
                st["final"] = True

    def g_place_set_resp(self, node: Tree) -> None:
        parts = self.clause_parts(node)
        words, nps, plist = parts.words, parts.nps, parts.plist
        self.respectively(self.place_list(plist[0]), nps, words, False)

    def g_place_set_one(self, node: Tree) -> None:
        parts = self.clause_parts(node)
        words, plist = parts.words, parts.plist
        places = self.place_list(plist[0])
        num = next(int(t.value) for t in node.scan_values(lambda v: isinstance(v, Token) and v.type == "NUM"))
        head = self.sub(node, "ihead")[0]
        self.put(places, "one", [{"items": {"names": [self.ihead(head, words)]}, "amount": {"count": num},
                                  "words": words}], words)

    def g_item_first(self, node: Tree) -> None:
        parts = self.clause_parts(node)
        words, locs = parts.words, parts.locs
        pp = self.sub(node, "pitem_plain")  # "bring the apron's seat belts down to 3"
        head = self.ihead(self.sub(pp[0] if pp else node, "ihead")[0], words)
        self.last_item = [head]
        num = next(int(t.value) for t in node.scan_values(lambda v: isinstance(v, Token) and v.type == "NUM"))
        if pp:
            place = [str(self.toks(pp[0], "PLACE")[0].value)]
            self.put(place, "one", [{"items": {"names": [head]}, "amount": {"count": num}, "words": words}], words)
            return
        if not locs:
            raise TranslationError(f"{quote(words)}: the command does not say which shelf "
                                   f"(candidates: {self.index.candidates('shelf')})")
        places, mode = self.loc(locs[0])
        self.put(places, mode, [{"items": {"names": [head]}, "amount": {"count": num}, "words": words}], words)

    def g_add(self, node: Tree) -> None:
        parts = self.clause_parts(node)
        words, nps, locs, plist, each = parts.words, parts.nps, parts.locs, parts.plist, parts.each
        if locs:
            places, mode = self.loc(locs[0])
        else:
            places, mode = self.place_list(plist[0]), "each" if each else "one"
        self.put(places, mode, nps, words, add=True)

    def g_equal_poss(self, node: Tree) -> None:
        parts = self.clause_parts(node)
        words = parts.words
        # "Make rack E's gear count equal to rack D's (valves)": D's count now, of its item
        poss = self.sub(node, "posplace")
        heads = [self.ihead(h, words) for h in self.sub(node, "ihead")]
        place, other = str(poss[0].children[0].value), str(poss[1].children[0].value)
        amount = {"as_many_as": other} if len(heads) == 1 or heads[1] == heads[0] else \
            {"as_many_as": other, "of": heads[1]}
        self.last_item = heads[:1]
        self.statements.append({"op": "set", "places": {"names": [place]}, "items": {"names": heads[:1]},
                                "amount": amount, "words": words})

    def g_as_many_there(self, node: Tree) -> None:
        parts = self.clause_parts(node)
        words, locs = parts.words, parts.locs
        # "Put as many valves on rack E as there are on rack A (and rack B together)"
        head = self.ihead(self.sub(node, "ihead")[0], words)
        places = self.loc(locs[0])[0]
        others = [str(t.value) for t in node.children if isinstance(t, Token) and t.type == "PLACE"]
        if len(others) > 1 and not self.sub(node, "together"):
            raise TranslationError(f"{quote(words)}: as many as each of {', '.join(others)} has, or as "
                                   f"all of them together? (say 'together')")
        amount = {"as_many_as": others[0], **({"together_with": others[1:]} if others[1:] else {})}
        self.put(places, "one", [{"items": {"names": [head]}, "amount": amount, "words": words}], words)

    def g_keep_its_elided(self, node: Tree) -> None:
        parts = self.clause_parts(node)
        words = parts.words
        # "Empty hangar B but leave its seat belts": the emptying of that place spares them
        places = self._last_places(words)
        heads = [self.ihead(h, words) for h in self.sub(node, "ihead")]
        for st in self.statements:
            if st["op"] == "empty" and st["places"]["names"] == places and st["items"].get("all"):
                st["items"] = {"all": True, "except": list(dict.fromkeys((st["items"].get("except") or []) + heads))}
        self.statements.append({"op": "keep", "places": {"names": places}, "items": {"names": heads},
                                "inflow_only": False, "words": words})

    def g_light_add(self, node: Tree) -> None:
        parts = self.clause_parts(node)
        words, plist = parts.words, parts.plist
        # "Rack east is light on flour bags, add three": the count is more of that item there
        head = self.ihead(self.sub(node, "ihead")[0], words)
        n = int(self.toks(node, "NUM")[0].value)
        self.last_item = [head]
        self.put(self.place_list(plist[0]), "one", [{"items": {"names": [head]}, "amount": {"more": n},
                                                      "words": words}], words)

    def g_poss_bound(self, node: Tree) -> None:
        parts = self.clause_parts(node)
        words = parts.words
        # "Keep rack east's lids between 2 and 6", "hold P's X at least 3"
        pp = self.sub(node, "pitem_plain")[0]
        place = [str(self.toks(pp, "PLACE")[0].value)]
        head = self.ihead(self.sub(pp, "ihead")[0], words)
        nums = [int(t.value) for t in node.children if isinstance(t, Token) and t.type == "NUM"]
        if len(nums) == 2:
            if nums[0] > nums[1]:
                raise TranslationError(f"{quote(words)}: the lower bound {nums[0]} is above the upper bound {nums[1]}")
            amount = {"at_least": nums[0], "at_most": nums[1]}
        else:
            amount = {"at_least": nums[0]} if self.sub(node, "lower") else {"at_most": nums[0]}
        self.put(place, "one", [{"items": {"names": [head]}, "amount": amount, "words": words}], words)

    def g_match(self, node: Tree) -> None:
        parts = self.clause_parts(node)
        words, plist = parts.words, parts.plist
        # "Rack east should match silo 2's flour bag count": that place's count now
        head = self.ihead(self.sub(node, "ihead")[0], words)
        other = str(self.sub(node, "posplace")[0].children[0].value)
        self.last_item = [head]
        self.put(self.place_list(plist[0]), "one", [{"items": {"names": [head]}, "amount": {"as_many_as": other},
                                                      "words": words}], words)

    def g_give(self, node: Tree) -> None:
        parts = self.clause_parts(node)
        words, items, nps, plist = parts.words, parts.items, parts.nps, parts.plist
        # "Dispatch, with its 8 lids, should give 3 of them to rack east": a move from the subject
        source = self.place_list(plist[0])
        for ap in self.sub(node, "place_appos"):
            self.apposition(source, self.nps(self.sub(ap, "items")[0]), self.words(ap))
        nps = self.nps(items[0])
        for np in nps:
            self.statements.append(self._transfer_statement(np, source, self.place_list(plist[1]), words))

    def g_could_use(self, node: Tree) -> None:
        parts = self.clause_parts(node)
        words, nps, plist, each = parts.words, parts.nps, parts.plist, parts.each
        # "P could use / could do with N more X" is a change; without "more" it could be the
        # count P should end with or the count to bring: refused with both readings offered
        # (``picks["could_use"]``: the user's choice), never guessed
        choice = self.picks.get("could_use")
        for np in nps:
            if set(np["amount"]) != {"more"} and choice is None:
                raise Choice("could_use", ("set", "add"),
                             f"{quote(words)}: 'could use' does not say whether {np['words']} is the "
                             f"count to end with or to add (say 'N more' or 'should have N')")
        if choice == "add":
            nps = [{**np, "amount": {"more": np["amount"]["count"]}} if set(np["amount"]) == {"count"} else np
                   for np in nps]
        self.put(self.place_list(plist[0]), "each" if each else "one", nps, words)

    def g_add_place(self, node: Tree) -> None:
        parts = self.clause_parts(node)
        words, nps, plist = parts.words, parts.nps, parts.plist
        places = self.place_list(plist[0])
        self.put(places, "one", nps, words, add=True)

    def g_transfer_with(self, node: Tree) -> None:
        parts = self.clause_parts(node)
        words, nps = parts.words, parts.nps
        robots_node = self.sub(node, "robots")[0]
        sel = self.robots.read(robots_node, self.robots_said(robots_node))
        self.transfer(node, nps, words)
        base = {"mode": "only", "robots": sel, "words": words}
        self.bind.append(base)
        self.rules.append(base)

    def g_transfer(self, node: Tree) -> None:
        parts = self.clause_parts(node)
        words, nps = parts.words, parts.nps
        self.transfer(node, nps, words)

    g_transfer_except = g_transfer

    def g_refill_from(self, node: Tree) -> None:
        """ "Restock P with 2 X from Q": the units come from Q to P, a move (as "bring 2 X from Q
        to P"): the place restocked is named first, the source after "from"."""
        parts = self.clause_parts(node)
        dst, src = (self.place_list(p) for p in self.sub(node, "places")[:2])
        for np in parts.nps:
            self.statements.append(self._transfer_statement(np, src, dst, parts.words))

    def g_transfer_except_count(self, node: Tree) -> None:
        """ "Bring all X to Q except one on P": every X goes to Q, but P keeps that many of its
        own (read as P set to N, then the rest of P's X to Q). Refused where P holds fewer than N
        now (it would be brought there: no "except"), for anything but all of one product, and
        where P is Q."""
        parts = self.clause_parts(node)
        words, nps = parts.words, parts.nps
        exc = self.sub(node, "except_count")[0]
        kept = self.place_list(self.sub(exc, "places")[0])
        nums = [int(t.value) for t in self.toks(exc, "NUM")]
        n = nums[0] if nums else 1
        lists = self.sub(node, "places") + [p for loc in parts.locs for p in self.sub(loc, "places")]
        dst = [self.place_list(p) for p in lists if p not in self.sub(exc, "places")][0]
        if len(nps) != 1 or "all" not in nps[0]["amount"] or not nps[0]["items"] \
                or len(nps[0]["items"].get("names") or []) != 1:
            raise TranslationError(f"{quote(words)}: 'except {n} on ...' needs all of one product "
                                   f"('every X to Q except one on P')")
        item = nps[0]["items"]["names"][0]
        for p in kept:
            if p in dst:
                raise TranslationError(f"{quote(words)}: {p} is where they go; nothing is kept there")
            if _held(self.lex.world, p, item) < n:
                raise TranslationError(f"{quote(words)}: {p} holds {_held(self.lex.world, p, item)} {item} now, "
                                       f"fewer than the {n} it should keep; say what to bring there")
        self.statements.append(self._transfer_statement(nps[0], None, dst, words, kept))
        for p in kept:
            self.statements.append({"op": "set", "places": {"names": [p]}, "items": {"names": [item]},
                                    "amount": {"count": n}, "words": words})
            self.statements.append({"op": "transfer", "items": {"names": [item]}, "amount": {"rest": True},
                                    "from": {"names": [p]}, "to": {"names": dst}, "words": words})

    def g_remove(self, node: Tree) -> None:
        parts = self.clause_parts(node)
        words, nps, plist = parts.words, parts.nps, parts.plist
        source = self.place_list(plist[0])
        for np in nps:
            self.statements.append(self._transfer_statement(np, source, None, words))

    def g_item_there(self, node: Tree) -> None:
        """ "Get the soup there down to 2": the place is the one just named (one place only)."""
        words = self.words(node)
        if not self.last_places or len(self.last_places) != 1:
            raise TranslationError(f"{quote(words)}: 'there' is which place? say it")
        head = self.ihead(self.sub(node, "ihead")[0], words)
        n = int(self.toks(node, "NUM")[-1].value)
        self.put(list(self.last_places), "one", [{"items": {"names": [head]}, "amount": {"count": n},
                                                 "words": words}], words)

    def g_poss_make(self, node: Tree) -> None:
        """ "Row A's brake pads - make it 2": that place's item, set to the count."""
        self._poss_amount(node, "count")

    def _poss_amount(self, node: Tree, amount: str) -> None:
        """ "OB connector max 4", "bay 1 nuts take away 3", "Row A's brake pads - make it 2": the
        place and the item said first (read as that place's item), then what to do with its count."""
        words = self.words(node)
        place = [str(self.sub(node, "posplace")[0].children[0].value)]
        head = self.ihead(self.sub(node, "ihead")[0], words)
        n = int(self.toks(node, "NUM")[-1].value)
        self.put(place, "one", [{"items": {"names": [head]}, "amount": {amount: n}, "words": words}], words)

    def g_poss_ceiling(self, node: Tree) -> None:
        self._poss_amount(node, "at_most")

    def g_poss_floor(self, node: Tree) -> None:
        self._poss_amount(node, "at_least")

    def g_poss_fewer(self, node: Tree) -> None:
        self._poss_amount(node, "fewer")

    def g_poss_more(self, node: Tree) -> None:
        self._poss_amount(node, "more")

    def g_remove_complained(self, node: Tree) -> None:
        """ "P is overstocked on X, take 2 off": off the place of the complaint just made (in this
        sentence or the one before); with no complaint, "off" what? refused."""
        said = (self.observed or self.prior_observed or [None])[-1]
        words = self.words(node)
        if said is None:
            raise TranslationError(f"{quote(words)}: off which place? say it")
        parts = self.clause_parts(node)
        for np in parts.nps:
            self.statements.append(self._transfer_statement(np, list(said[1]), None, words))

    def g_mult(self, node: Tree) -> None:
        parts = self.clause_parts(node)
        words, locs = parts.words, parts.locs
        verb = self.first_word(node)
        head = self.ihead(self.sub(node, "ihead")[0], words)
        poss = self.sub(node, "posplace")  # "halve the loading bay's bearings"
        places = [str(poss[0].children[0].value)] if poss else self.loc(locs[0])[0]
        amount = {"fraction": [1, 2]} if verb == "halve" else {"times": {"double": 2, "triple": 3, "quadruple": 4}[verb]}
        self.put(places, "each", [{"items": {"names": [head]}, "amount": amount, "words": words}], words)

    def g_topic(self, node: Tree) -> None:
        """ "Back shed. Pull 3 shackles off it.": a place said alone is what "it" and "there" in the
        next sentence mean; alone in a command it asks for nothing (refused as nothing asked)."""
        places = self.place_list(self.sub(node, "places")[0])
        if len(places) != 1:
            raise TranslationError(f"{quote(self.words(node))}: which place? (a topic is one place)")
        self.last_places = places
        self.observed.append((self.words(node), places))

    def g_complaint(self, node: Tree) -> None:
        """ "P is overstocked on X", "P's getting a bit crowded": no count, so no goal; P (and X)
        are what the instruction after it means ("take 2 off", "get the soup there down to 2"),
        as after "P has too many X" (:meth:`put`: the same checks follow)."""
        places = self.place_list(self.sub(node, "places")[0])
        heads = self.sub(node, "ihead")
        if heads:
            self.last_item = [self.ihead(heads[0], self.words(node))]
        self.last_places = places
        self.observed.append((self.words(node), places))

    def g_mult_pronoun(self, node: Tree) -> None:
        """ "P has too many X. Halve them.": "them" is the X of the complaint just made (the only
        place a bare pronoun may take its place from: after a move it could be either end)."""
        words = self.words(node)
        said = (self.observed or self.prior_observed or [None])[-1]
        if said is None or not self.last_item or len(self.last_item) != 1:
            raise TranslationError(f"{quote(words)}: which product on which place? say it "
                                   f"(e.g. 'halve P's X')")
        verb = self.first_word(node)
        amount = {"fraction": [1, 2]} if verb == "halve" else {"times": {"double": 2, "triple": 3, "quadruple": 4}[verb]}
        self.put(list(said[1]), "each", [{"items": {"names": list(self.last_item)}, "amount": amount,
                                          "words": words}], words)

    def g_keep_part(self, node: Tree) -> None:
        parts = self.clause_parts(node)
        nps, plist = parts.nps, parts.plist
        places = self.place_list(plist[0])
        for np in nps:
            if "fraction" in np["amount"]:
                self.statements.append(self._goal_statement(places, np, False))
            else:
                self.statements.append(self._goal_statement(places, np, False))

    def g_empty(self, node: Tree) -> None:
        parts = self.clause_parts(node)
        words, plist = parts.words, parts.plist
        places = self.place_list(plist[0])
        self.statements.append({"op": "empty", "places": {"names": places}, "items": {"all": True},
                                "words": words})

    def g_empty_item(self, node: Tree) -> None:
        parts = self.clause_parts(node)
        words, plist = parts.words, parts.plist
        pp = self.sub(node, "pitem_plain")  # "empty out the parts cage's fuses"
        places = [str(self.toks(pp[0], "PLACE")[0].value)] if pp else self.place_list(plist[0])
        head = self.ihead(self.sub(pp[0] if pp else node, "ihead")[0], words)
        self.statements.append({"op": "empty", "places": {"names": places}, "items": {"names": [head]},
                                "words": words})

    def g_fill(self, node: Tree) -> None:
        parts = self.clause_parts(node)
        kind, words, plist = parts.kind, parts.words, parts.plist
        if kind == "g_fill":
            places = self.place_list(plist[0])
        else:
            places = self._last_places(words)
        head = self.ihead(self.sub(node, "ihead")[0], words)
        only = "only" in words.lower().split() or "nothing but" in words.lower()
        for p in places:
            self.statements.append({"op": "fill", "places": {"names": [p]}, "items": {"names": [head]},
                                    "only": only, "words": words})

    g_fill_elided = g_fill

    def g_none_except(self, node: Tree) -> None:
        """ "No X anywhere except P": none of X on every place of the world but P (P is not
        listed: it is just not selected, as "every place except P" is)."""
        parts = self.clause_parts(node, bare=True)
        words = parts.words
        heads = [self.ihead(h, words) for h in self.sub(node, "ihead")]
        kept = [p for e in self.sub(node, "except_pl") for p in self.place_list(e)]
        places = [p for p in self.index.by_kind["shelf"] if p not in kept]
        if not kept or not places:
            raise TranslationError(f"{quote(words)}: cannot tell which places are excepted")
        self.put(places, "each", [{"items": {"names": [h]}, "amount": {"none": True}, "words": words}
                                  for h in heads], words)

    def g_nothing_but(self, node: Tree) -> None:
        """ "Nothing but X on P": none of every other product of the world on P (convention 3's
        "every product"); X itself is not fixed."""
        parts = self.clause_parts(node, bare=True)
        words = parts.words
        heads = [self.ihead(h, words) for h in self.sub(node, "ihead")]
        places = self.loc(parts.locs[0])[0]
        others = [i for i in self.index.by_kind["product"] if i not in heads]
        self.put(places, "each", [{"items": {"names": [i]}, "amount": {"none": True}, "words": words}
                                  for i in others], words)

    def g_nothing_else(self, node: Tree) -> None:
        """ "P should have X, nothing else": P holds nothing but what is named. After a swap or a
        move ("swap only the paint between A and B, nothing else") it says what the operation
        leaves alone, which it does already: nothing else at those places changes (read as
        emptying them, the robots moved out all else)."""
        parts = self.clause_parts(node)
        words, locs = parts.words, parts.locs
        if not locs and self.statements and self.statements[-1]["op"] in ("swap", "transfer"):
            return
        places = self.loc(locs[0])[0] if locs else self._last_places(words)
        self.statements.append({"op": "nothing_else", "places": {"names": places}, "words": words})

    def g_no_inflow(self, node: Tree) -> None:
        parts = self.clause_parts(node)
        words, locs = parts.words, parts.locs
        # "Clear shelf2, but nothing goes to shelf4": shelf4 keeps what it has of what moves
        places, _ = self.loc(locs[0])
        heads = [self.ihead(h, words) for h in self.sub(node, "ihead")]
        moved: list[str] = []
        everything = False
        for st in self.statements:
            sel = st.get("items") or {}
            if "names" in sel:
                moved += sel["names"]
            else:
                everything = True
        if heads:
            sel = {"names": heads}
        elif moved and not everything:
            sel = {"names": list(dict.fromkeys(moved))}
        else:
            sel = {"all": True}
        self.statements.append({"op": "keep", "places": {"names": places}, "items": sel,
                                "inflow_only": False, "words": words})

    def g_keep(self, node: Tree) -> None:
        parts = self.clause_parts(node)
        words, locs, plist = parts.words, parts.locs, parts.plist
        poss = self.sub(node, "posplace")
        heads = self.sub(node, "ihead")
        if poss:
            places = [str(poss[0].children[0].value)]
            self.last_places = places  # "P's X stays where it is, and it should get ...": "it" is P
        elif locs:
            places = self.loc(locs[0])[0]
        else:
            places = self.place_list(plist[0])
        sel = {"names": [self.ihead(heads[0], words)]} if heads else {"all": True}
        self.statements.append({"op": "keep", "places": {"names": places}, "items": sel,
                                "inflow_only": False, "words": words})

    def g_swap(self, node: Tree) -> None:
        parts = self.clause_parts(node)
        words = parts.words
        self.swap(node, words)

    g_swap_items = g_swap

    g_swap_poss = g_swap

    def g_split(self, node: Tree) -> None:
        parts = self.clause_parts(node)
        words, items, nps, plist = parts.words, parts.items, parts.nps, parts.plist
        places = self.place_list(plist[0])
        for b in self.sub(node, "bare"):
            nps = [{"items": {"names": [self.ihead(h, words)]}, "amount": {"all": True}, "words": words}
                   for h in self.sub(b, "ihead")]
        if not nps:
            raise TranslationError(f"{quote(words)}: the command does not say what to share")
        for np in nps:
            a = np["amount"]
            if not ({"count", "all"} & set(a)):
                raise TranslationError(f"{quote(np['words'])}: cannot share this amount")
            items = np["items"] if np["items"] is not None else {"names": list(self.last_item or [])}
            stock = self.lex.world.get("stock") or {}
            held = [p for p in places for i in items.get("names") or [] if int((stock.get(p) or {}).get(i, 0) or 0)]
            if "count" in a and held:
                # "Split 4 X between A and B" with no source: does each end with 2, or get 2 more?
                # The same only where none holds X now (each was set to 2: a misreading)
                raise TranslationError(f"{quote(words)}: cannot tell whether each place ends with its share "
                                       f"or gets it on top of what it holds ({', '.join(dict.fromkeys(held))} "
                                       f"hold some now); say where the units come from")
            self.statements.append({"op": "distribute", "places": {"names": places}, "items": items,
                                    "amount": a, "words": words})

    def g_split_pronoun(self, node: Tree) -> None:
        """ "Take 4 X off P and split them evenly between Q and R": the move still open (taken, not
        yet delivered) is shared out from where it was taken, as "Split 4 X from P between Q and
        R"; as "move them to Q" (:meth:`g_pronoun_dest`), only a move without a destination, in
        this sentence or the one before, gives "them" its meaning."""
        parts = self.clause_parts(node, bare=True)
        words, plist = parts.words, parts.plist
        places = self.place_list(plist[-1])

        def shared(st: dict) -> dict:
            return {"op": "distribute", "places": {"names": places}, "items": st["items"], "amount": st["amount"],
                    "from": st["from"], "words": f"{st['words']}, {words}"}

        open_moves = [k for k, st in enumerate(self.statements) if st["op"] == "transfer" and not st.get("to")]
        for k in open_moves:
            self.statements[k] = shared(self.statements[k])
        if not open_moves:
            for k, st in enumerate(self.prior):
                if st["op"] == "transfer" and not st.get("to"):
                    self.updates[k] = shared(st)
        if not open_moves and not self.updates:
            raise TranslationError(f"{quote(words)}: 'them' of what? nothing was taken before it")

    def g_each(self, node: Tree) -> None:
        parts = self.clause_parts(node)
        words, locs = parts.words, parts.locs
        places, mode = self.loc(locs[0])
        self.put(places, "each", [{"items": {"all": True}, "amount": {"count": 1}, "words": words}], words)

    def g_transfer_src(self, node: Tree) -> None:
        parts = self.clause_parts(node, bare=True)
        words, nps, locs, plist = parts.words, parts.nps, parts.locs, parts.plist
        srcs = self.sub(node, "src")
        pit = [c for c in node.children if isinstance(c, Tree) and c.data.startswith("pi_")]
        if pit:
            np, source = self.pitem(pit[0], words)
            nps = [np]
        elif srcs:
            source = self.place_list(self.sub(srcs[0], "places")[0])
        else:  # "put the 6 springs from rack C on rack E"
            source = self.place_list(plist[0])
        dst = self.loc(locs[0])[0] if locs else self.place_list(plist[-1]) if plist else []
        for np in nps:
            self.statements.append(self._transfer_statement(np, source, dst, words))

    def g_receive(self, node: Tree) -> None:
        parts = self.clause_parts(node, bare=True)
        words, nps, plist = parts.words, parts.nps, parts.plist
        dst, source = self.place_list(plist[0]), self.place_list(plist[1])
        for np in nps:
            if "more" in np["amount"]:  # "Overflow needs 4 more boxes from dock 1"
                np = {**np, "amount": {"count": np["amount"]["more"]}}
            self.statements.append(self._transfer_statement(np, source, dst, words))

    def g_remove_src(self, node: Tree) -> None:
        parts = self.clause_parts(node, bare=True)
        words, nps = parts.words, parts.nps
        nps, source = self._items_and_source(node, nps, words)
        for np in nps:
            st = self._transfer_statement(np, source, None, words)
            self.statements.append(st)

    def g_short(self, node: Tree) -> None:
        parts = self.clause_parts(node, bare=True)
        words, nps, plist = parts.words, parts.nps, parts.plist
        # "Bay 2 is 3 crates short": it needs 3 more; any other amount is not read
        for np in nps:
            if set(np["amount"]) != {"count"}:
                raise TranslationError(f"{quote(words)}: cannot tell how many are missing")
            np = {**np, "amount": {"more": np["amount"]["count"]}}
            self.statements.append(self._goal_statement(self.place_list(plist[0]), np, False))

    def g_too_many(self, node: Tree) -> None:
        parts = self.clause_parts(node, bare=True)
        words, items, nps, plist = parts.words, parts.items, parts.nps, parts.plist
        places = self.place_list(plist[0])
        for ap in self.sub(node, "place_appos"):  # "P, which holds 7 X, should lose 2 of them"
            self.apposition(places, self.nps(self.sub(ap, "items")[0]), self.words(ap))
        nps = self.nps(items[0])  # read after the apposition: "them" is what it named
        for np in nps:
            a = np["amount"]
            if "count" in a:
                np = {**np, "amount": {"fewer": a["count"]}}
            elif "fraction" in a:
                num, den = a["fraction"]
                np = {**np, "amount": {"fraction": [den - num, den]}}
            else:
                raise TranslationError(f"{quote(words)}: cannot tell how many to take away")
            self.statements.append(self._goal_statement(places, np, False))

    g_lose = g_too_many

    def g_cut(self, node: Tree) -> None:
        parts = self.clause_parts(node, bare=True)
        words, locs = parts.words, parts.locs
        pp = self.sub(node, "pitem_plain")
        if pp:
            places = [str(self.toks(pp[0], "PLACE")[0].value)]
            head = self.ihead(self.sub(pp[0], "ihead")[0], words)
        else:
            places = self.loc(locs[0])[0]
            head = self.ihead(self.sub(node, "ihead")[0], words)
        self.statements.append(self._goal_statement(places, {"items": {"names": [head]}, "amount": self._cut(node),
                                                              "words": words}, False))

    def _cut(self, node: Tree) -> dict:
        """What "cut by a third / by half / in half / by 2" leaves: a fraction of the count now, or
        fewer by a count."""
        fr = self.sub(node, "frac")
        if fr:
            den = int(self.toks(fr[0], "FRAC")[0].value)
            num = int(self.toks(fr[0], "NUM")[0].value) if self.toks(fr[0], "NUM") else 1
            return {"fraction": [den - num, den]}
        if any(isinstance(c, Token) and c.value == "half" for c in node.children):
            return {"fraction": [1, 2]}
        return {"fewer": int(self.toks(node, "NUM")[-1].value)}

    def g_cut_pronoun(self, node: Tree) -> None:
        """ "P's got too many X. Cut them by a fifth.": "them" is the X of the complaint just made,
        as in "halve them" (:meth:`g_mult_pronoun`); nothing else gives a bare pronoun its place."""
        words = self.words(node)
        said = (self.observed or self.prior_observed or [None])[-1]
        if said is None or not self.last_item or len(self.last_item) != 1:
            raise TranslationError(f"{quote(words)}: which product on which place? say it "
                                   f"(e.g. 'cut P's X by a third')")
        self.put(list(said[1]), "each", [{"items": {"names": list(self.last_item)}, "amount": self._cut(node),
                                          "words": words}], words)

    def g_keep_its(self, node: Tree) -> None:
        parts = self.clause_parts(node, bare=True)
        words, plist = parts.words, parts.plist
        places = self.place_list(plist[0])
        stock = self.lex.world.get("stock") or {}
        heads = [self.ihead(h, words) for h in self.sub(node, "ihead")]
        nums = [int(t.value) for t in self.toks(node, "NUM")]
        if nums and len(nums) != len(heads):
            raise TranslationError(f"{quote(words)}: cannot tell which count goes with which item")
        for k, h in enumerate(heads):
            for p in places:
                have = int((stock.get(p) or {}).get(h, 0) or 0)
                if nums and nums[k] != have:
                    raise TranslationError(f"{quote(words)}: {p} holds {have} {h}, not {nums[k]}; "
                                           f"cannot tell which is meant")
        self.statements.append({"op": "keep", "places": {"names": places}, "items": {"names": heads},
                                "inflow_only": False, "words": words})

    def g_place_inum(self, node: Tree) -> None:
        parts = self.clause_parts(node, bare=True)
        words, nps, plist = parts.words, parts.nps, parts.plist
        places = self.place_list(plist[0])
        nps = []
        for inum in self.sub(node, "inum"):
            head = self.ihead(self.sub(inum, "ihead")[0], words)
            nps.append({"items": {"names": [head]}, "amount": {"count": int(self.toks(inum, "NUM")[0].value)},
                        "words": self.words(inum)})
        self.put(places, "one", nps, words)

    def g_empty_except(self, node: Tree) -> None:
        parts = self.clause_parts(node, bare=True)
        words, plist = parts.words, parts.plist
        # "Clear out dock 1 except the pallets": the rest goes, the pallets stay as they are
        places = self.place_list(plist[0])
        excl = [self.ihead(h, words) for e in self.sub(node, "except_items") for h in self.sub(e, "ihead")]
        self.statements.append({"op": "empty", "places": {"names": places}, "items": {"all": True, "except": excl},
                                "words": words})
        self.statements.append({"op": "keep", "places": {"names": places}, "items": {"names": excl},
                                "inflow_only": False, "words": words})

    def g_transfer_except_items(self, node: Tree) -> None:
        parts = self.clause_parts(node, bare=True)
        words, plist = parts.words, parts.plist
        source, dst = self.place_list(plist[0]), self.place_list(plist[1])
        excl = [self.ihead(h, words) for e in self.sub(node, "except_items") for h in self.sub(e, "ihead")]
        self.statements.append(self._transfer_statement(
            {"items": {"all": True, "except": excl}, "amount": {"all_held": True}, "words": words}, source, dst, words))

    def g_none_of(self, node: Tree) -> None:
        parts = self.clause_parts(node, bare=True)
        kind, words, locs, plist = parts.kind, parts.words, parts.locs, parts.plist
        places = self.place_list(plist[0]) if kind == "g_none_of" else self.loc(locs[0])[0]
        heads = [self.ihead(h, words) for h in self.sub(node, "ihead")]
        self.put(places, "each", [{"items": {"names": [h]}, "amount": {"none": True}, "words": words} for h in heads],
                 words)

    g_none_in = g_none_of

    def g_updown(self, node: Tree) -> None:
        parts = self.clause_parts(node, bare=True)
        words, locs = parts.words, parts.locs
        head = self.ihead(self.sub(node, "ihead")[0], words)
        places = self.loc(locs[0])[0]
        n = int(self.toks(node, "NUM")[-1].value)
        down = any(isinstance(t, Token) and str(t.value).lower() == "down" for t in self.toks_any(node))
        self.statements.append(self._goal_statement(
            places, {"items": {"names": [head]}, "amount": {"fewer": n} if down else {"more": n}, "words": words},
            False))

    def g_raise(self, node: Tree) -> None:
        parts = self.clause_parts(node, bare=True)
        kind, words, locs, plist = parts.kind, parts.words, parts.locs, parts.plist
        head = self.ihead(self.sub(node, "ihead")[0], words)
        if locs:
            places = self.loc(locs[0])[0]
        elif plist:
            places = self.place_list(plist[0])
        else:
            places = self._last_places(words)
        n = int(self.toks(node, "NUM")[-1].value)
        amount = {"more": n} if kind == "g_raise" else {"fewer": n}
        self.statements.append(self._goal_statement(places, {"items": {"names": [head]}, "amount": amount,
                                                              "words": words}, False))

    g_lower = g_raise

    def g_pronoun_dest(self, node: Tree) -> None:
        parts = self.clause_parts(node, bare=True)
        words, locs = parts.words, parts.locs
        # "Take 2 bags out of overflow and drop them at dock 1": the move gets its destination
        places = self.loc(locs[0])[0]
        open_moves = [st for st in self.statements if st["op"] == "transfer" and not st.get("to")]
        for st in open_moves:
            st["to"] = {"names": places}
            st["words"] = f"{st['words']}, {words}"
        if not open_moves:  # "Take 3 product1 from shelf1. Put them on shelf2."
            for k, st in enumerate(self.prior):
                if st["op"] == "transfer" and not st.get("to"):
                    self.updates[k] = {**st, "to": {"names": places}, "words": f"{st['words']}, {words}"}
        if not open_moves and not self.updates:
            raise TranslationError(f"{quote(words)}: 'them' of what? nothing was taken before it")

    def g_ceiling(self, node: Tree) -> None:
        parts = self.clause_parts(node, bare=True)
        words, plist = parts.words, parts.plist
        # "don't leave more than 5 X in P": the place said after the things
        places = self.place_list(plist[0]) if plist else self.loc(parts.locs[0])[0]
        head = self.ihead(self.sub(node, "ihead")[0], words)
        n = int(self.toks(node, "NUM")[0].value)
        self.put(places, "each", [{"items": {"names": [head]}, "amount": {"at_most": n}, "words": words}], words)

    def g_empty_into(self, node: Tree) -> None:
        parts = self.clause_parts(node, bare=True)
        words, plist = parts.words, parts.plist
        source, dst = self.place_list(plist[0]), self.place_list(plist[1])
        self.statements.append(self._transfer_statement(
            {"items": {"all": True, "except": []}, "amount": {"all_held": True}, "words": words}, source, dst, words))
        # the source is emptied, like "empty P": none of any product is left or parked there
        self.statements.append({"op": "empty", "places": {"names": source}, "items": {"all": True}, "words": words})

    def g_floor(self, node: Tree) -> None:
        parts = self.clause_parts(node, bare=True)
        words, plist = parts.words, parts.plist
        places = self.place_list(plist[0])
        head = self.ihead(self.sub(node, "ihead")[0], words)
        n = int(self.toks(node, "NUM")[0].value)
        self.put(places, "each", [{"items": {"names": [head]}, "amount": {"at_least": n}, "words": words}], words)

    def g_keep_item(self, node: Tree) -> None:
        parts = self.clause_parts(node, bare=True)
        words, locs = parts.words, parts.locs
        head = self.ihead(self.sub(node, "ihead")[0], words)
        places = self.loc(locs[0])[0] if locs else list(self.index.by_kind["shelf"])
        self.statements.append({"op": "keep", "places": {"names": places}, "items": {"names": [head]},
                                "inflow_only": False, "words": words})

    def g_noop(self, node: Tree) -> None:
        parts = self.clause_parts(node, bare=True)
        plist = parts.plist
        self.place_list(plist[0])  # "Don't empty rack B, just take 2 gears off it": "it"

    def g_swap_two(self, node: Tree) -> None:
        parts = self.clause_parts(node, bare=True)
        words = parts.words
        self.swap(node, words)

    g_swap_subj = g_swap_two

    def g_split_src(self, node: Tree) -> None:
        parts = self.clause_parts(node, bare=True)
        words, items, nps, plist = parts.words, parts.items, parts.nps, parts.plist
        nps, source = self._items_and_source(node, nps, words)
        places = self.place_list(plist[-1])
        for np in nps:
            items = np["items"] if np["items"] is not None else {"names": list(self.last_item or [])}
            self.statements.append({"op": "distribute", "places": {"names": places}, "items": items,
                                    "amount": np["amount"], "from": {"names": source}, "words": words})

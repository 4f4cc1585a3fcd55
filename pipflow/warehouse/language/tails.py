"""The tail rules of the warehouse's command grammar: one method per rule.

A tail (an alias ``t_...`` of :mod:`pipflow.warehouse.language.grammar`) is a clause that only
makes sense after another: "..., and shelf4 too" (``t_too``), "..., three to shelf3" (``t_elided``),
"..., taking them from shelf1" (``t_source``), "... and 1 Y the other way" (``t_reverse``), "..., but
not the springs" (``t_not_items``). Each method reads its clause against the statements said
before it in the sentence (or the sentences before), and adds or changes statements of the
order; the sentence reader (:mod:`pipflow.warehouse.language.parser`) inherits these methods and
dispatches a tail to the one its rule names, as it does a goal clause
(:mod:`pipflow.warehouse.language.goals`).
"""
from __future__ import annotations

from lark import Tree

from pipflow.errors import TranslationError
from pipflow.warehouse.language.goals import quote


class TailRules:
    """The tail rules, one method each (mixed into the sentence reader, whose state they use)."""

    def t_too(self, node: Tree) -> None:
        words = self.words(node)
        places = self.place_list(self.sub(node, "places")[0])
        last = [s for s in self.statements if "places" in s] or [s for s in self.prior_last if "places" in s]
        if not last:
            raise TranslationError(f"{quote(words)}: cannot tell what to repeat there")
        prev = last[-1]
        if prev["op"] not in ("set", "change", "bound", "empty", "fill", "keep", "distribute"):
            raise TranslationError(f"{quote(words)}: cannot tell what to repeat there")
        group = [s for s in self.statements or self.prior_last if s.get("words") == prev.get("words")]
        for s in group:
            if s["words"] in self.received and set(s.get("amount") or {}) == {"count"}:
                self._received_check(places, (s.get("items") or {}).get("names") or [], s["words"], words)
            self.statements.append({**s, "places": {"names": places}, "words": f"{s['words']} ({words})"})

    def t_elided(self, node: Tree) -> None:
        kind, words = node.data, self.words(node)
        num = int(node.children[0].value)
        more = bool(self.sub(node, "more"))
        amount = {"fewer": num} if kind == "t_elided_fewer" else {"more": num} if more else {"count": num}
        places, mode = self.loc(self.sub(node, "loc")[0] if self.sub(node, "loc") else
                                next(c for c in node.children if isinstance(c, Tree) and c.data.startswith("loc")))
        prev = [s for s in self.statements if s["op"] in ("set", "change", "transfer")]
        add = bool(prev) and prev[-1]["op"] == "change" and "more" in prev[-1]["amount"] and "more" not in amount \
            and "count" in amount
        if prev and prev[-1]["op"] == "transfer" and "count" in amount:
            last = prev[-1]
            self.statements.append({**last, "amount": amount, "to": {"names": places}, "words": words})
            return
        self.put(places, mode, [{"items": None, "amount": amount, "words": words}], words, add=add)

    t_elided_fewer = t_elided

    def t_source(self, node: Tree) -> None:
        words = self.words(node)
        source = self.place_list(self.sub(node, "places")[0])
        changed = False
        out: list[dict] = []
        for s in self.statements:
            if s["op"] == "change" and "more" in s["amount"]:
                # a change adds to each of its places ("3 X to each of P and Q"): each gets them from there
                each = [{"names": [p]} for p in s["places"]["names"]] if s["places"].get("names") else [s["places"]]
                out += [{"op": "transfer", "items": s["items"], "amount": {"count": s["amount"]["more"]},
                         "from": {"names": source}, "to": to, "words": f"{s['words']}, {words}"} for to in each]
                changed = True
            elif s["op"] == "set" and "count" in s["amount"]:
                # "four product1 to shelf2, taking them from shelf1": the four come from there; "get
                # shelf2 to 4 product1, taking them from shelf1": 4 there in all, what is missing from there
                amount = {"up_to": s["amount"]["count"]} if s.get("final") else s["amount"]
                out.append({"op": "transfer", "items": s["items"], "amount": amount, "from": {"names": source},
                            "to": s["places"], "words": f"{s['words']}, {words}"})
                changed = True
            else:
                out.append(s)
        self.statements[:] = out
        if not changed and not self.statements:
            self.pending_source = source  # "From shelf 4, move 5 product4 to shelf 1"
            return
        if not changed:
            raise TranslationError(f"{quote(words)}: nothing before it to take from there")

    def t_gap(self, node: Tree) -> None:
        words = self.words(node)
        # "Rack A should have 9 widgets and rack B 6 gears", "..., staging 8": the verb is shared
        places = self.place_list(self.sub(node, "places")[0])
        prev = [st for st in self.statements if st["op"] in ("set", "change", "bound")]
        if not prev and not self.statements and not self.prior:
            # "Quay door 5 mooring lines, back shed 3": a list line that opens the command says
            # what the place should hold, as "P: 5 X" does (the clauses after it continue it)
            for np in self.nps(self.sub(node, "items")[0]):
                self.statements.append(self._goal_statement(places, np, False))
            return
        if not prev:
            raise TranslationError(f"{quote(words)}: nothing said before it that it continues")
        # the verb is what is shared: "add 3 to A, B 2" adds, "A should have ..., B 2" sets
        if not self.last_add:
            self._gap_after_more(self.nps(self.sub(node, "items")[0]), places)
        for np in self.nps(self.sub(node, "items")[0]):
            self.statements.append(self._goal_statement(places, np, self.last_add))

    def t_not_to(self, node: Tree) -> None:
        """ "Move trays out of freezer A, but not to pick face": pick face keeps what it has of them."""
        self._keeps_what_is_moved(node)

    def t_not_from(self, node: Tree) -> None:
        """ "Send 10 X to staging but nothing from the cooler": the cooler keeps what it has of them."""
        self._keeps_what_is_moved(node)

    def _keeps_what_is_moved(self, node: Tree) -> None:
        """The places of ``node`` keep what they have of the things moved before it."""
        words = self.words(node)
        places = self.place_list(self.sub(node, "places")[0])
        moved = [n for st in self.statements for n in (st.get("items") or {}).get("names", [])]
        if not moved:
            raise TranslationError(f"{quote(words)}: not what? nothing is moved before it")
        self.statements.append({"op": "keep", "places": {"names": places}, "items": {"names": list(dict.fromkeys(moved))},
                                "inflow_only": False, "words": words})

    def t_noop(self, node: Tree) -> None:
        """"4 valves, not 5": a correction that restates what was said (nothing to add)."""

    def t_reverse(self, node: Tree) -> None:
        words = self.words(node)
        # "Move 2 X from A to B, and 1 Y the other way": the move before, from B to A
        prev = self.statements[-1] if self.statements else None
        if prev is None or prev["op"] != "transfer" or not prev.get("to") or "names" not in prev["from"]:
            raise TranslationError(f"{quote(words)}: 'the other way' of what? no move from one place "
                                   f"to another comes before it")
        back_from, back_to = list(prev["to"]["names"]), list(prev["from"]["names"])
        for np in self.nps(self.sub(node, "items")[0]):
            self.statements.append(self._transfer_statement(np, back_from, back_to, words))

    def t_from(self, node: Tree) -> None:
        words = self.words(node)
        # "Rack B gets 3 widgets from rack C and 2 gears from rack A": the same destination
        prev = self.statements[-1] if self.statements else None
        if prev is None or prev["op"] != "transfer":
            raise TranslationError(f"{quote(words)}: cannot tell where these go")
        source = self.place_list(self.sub(node, "places")[0])
        for np in self.nps(self.sub(node, "items")[0]):
            if prev.get("to") is None and np["amount"] == {"count": 1} and np["words"].lower() == "another" \
                    and prev["amount"] != {"count": 1}:
                # "take 3 off A and another off B": one more, or another 3? not guessed
                raise TranslationError(f"{quote(words)}: 'another' after {prev['words']!r} does not "
                                       f"say how many (one, or as many again?)")
            # "Take 1 bolt off A and 2 off B" repeats the removal; after a move, its destination
            target = prev["to"]["names"] if prev.get("to") else None
            self.statements.append(self._transfer_statement(np, source, target, words))

    def t_rest(self, node: Tree) -> None:
        words = self.words(node)
        places = self.place_list(self.sub(node, "places")[0])
        rest_of = self.sub(node, "rest_of")
        heads = [self.ihead(h, words) for r in rest_of for h in self.sub(r, "ihead")]
        np = {"items": {"names": heads} if heads else None, "amount": {"rest": True}, "words": words}
        named = [str(pp.children[0].value) for r in rest_of for pp in self.sub(r, "posplace")]
        if any(str(tok.value) == "there" for r in rest_of for tok in r.children if hasattr(tok, "type")):
            named = list(self.last_places or ["(no place said)"])   # "the rest of the rice there"
        if self.budget and not heads and not named:
            # "Take the X off P: 2 to A, the rest to B": the rest of the units taken
            self.statements.append(self._share(self.budget["st"], places, np, "rest"))
            return
        self.statements.append(self._rest(places, {**np, "rest_of": named} if named else np))

    def t_same(self, node: Tree) -> None:
        """ "Knock a brake pad off row A, and the same off row B": the statement before again, at
        the other place: its source after "off" / "from", its target or its place otherwise
        (a statement with neither, or one that names several, is refused)."""
        words = self.words(node)
        prev = self.statements[-1] if self.statements else None
        places = self.place_list(self.sub(node, "places")[0])
        prep = next(str(c.value).lower() for c in node.children if hasattr(c, "type") and str(c.value).lower() != "same")
        if prev is None:
            raise TranslationError(f"{quote(words)}: the same as what? nothing said before it")
        new = dict(prev, words=words)
        if prev["op"] == "transfer":
            key = "from" if prep in ("off", "from", "out") else "to"
            if prev.get(key) is None or "names" not in prev[key]:
                raise TranslationError(f"{quote(words)}: the same as {prev['words']!r}, but it has no place to change")
            new[key] = {"names": places}
        elif "places" in prev and "names" in prev["places"] and prep not in ("off", "from", "out"):
            new["places"] = {"names": places}
        else:
            raise TranslationError(f"{quote(words)}: cannot tell what the same means here")
        self.statements.append(new)

    def t_anywhere(self, node: Tree) -> None:
        """ "take 2 X off P: they can go wherever there's room": what a removal means already
        (no destination); after anything else it is refused (where to, then?)."""
        words = self.words(node)
        prev = self.statements[-1] if self.statements else None
        if prev is None or prev["op"] != "transfer" or prev.get("to") is not None:
            raise TranslationError(f"{quote(words)}: after what? (only units taken off a place may go anywhere)")

    def t_not_items(self, node: Tree) -> None:
        words = self.words(node)
        # "Take the widgets off rack C, but not the springs": they stay where they are
        heads = [self.ihead(h, words) for h in self.sub(node, "ihead")]
        prev = self.statements[-1] if self.statements else None
        if prev is None:
            raise TranslationError(f"{quote(words)}: nothing said before it that it excepts")
        items = prev.get("items") or {}
        if items.get("all"):
            # "Move everything from P to Q but not the pears", "Empty P, not the pears": excepted
            prev["items"] = {**items, "except": list(dict.fromkeys((items.get("except") or []) + heads))}
        places = (prev.get("from") or prev.get("places") or {}).get("names")
        if not places:
            raise TranslationError(f"{quote(words)}: cannot tell where they stay")
        self.statements.append({"op": "keep", "places": {"names": places}, "items": {"names": heads},
                                "inflow_only": False, "words": words})

    def t_resp(self, node: Tree) -> None:
        words = self.words(node)
        raise TranslationError(f"{quote(words)}: 'respectively' must follow the places it pairs")

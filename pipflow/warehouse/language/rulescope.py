"""Robot rules of a sentence and their scope: the rule clauses ("robot 3 must not carry kegs",
"only the forklifts"), the products and places a rule's own words name, and, for a rule with
none, the sentence's goal it is bound to (:meth:`RuleScope.finish`): its one product and its one
place or move, or a :class:`Choice` where readers differ ("for this": the job or the move?).

A mixin of the sentence reader (:class:`pipflow.warehouse.language.sentence.SentenceReader`), as
:class:`GoalRules` and :class:`TailRules` are.
"""
from __future__ import annotations

from lark import Token, Tree

from pipflow.errors import TranslationError
from pipflow.warehouse.language.goals import Choice, leaving_out_what_stays, quote

#: "do", "help with" or "work on" a pronoun is the task instead
ITEM_VERBS = {"move", "moves", "carry", "carries", "touch", "touches", "take", "takes", "deliver", "delivers",
              "send", "sends", "handle", "handles", "bring", "brings", "transport", "transports", "ship", "put",
              "place", "load", "unload", "fetch", "stock", "restock", "remove", "supply", "lift", "haul"}
PRONOUNS = {"it", "them", "that", "those", "these", "this"}


class RuleScope:
    """The rule clauses of a sentence and the scope each rule takes."""

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
        sel = self.robots.read(robots_node[0], self.robots_said(robots_node[0]))
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
            if words.lower().split()[-3:] == ["out", "of", "it"]:
                # "keep beetle out of it": the idiom is the job, never a place "it" stands for
                self.rules.append(base)
                return
            for p in self.place_list(self.sub(node, "places")[0]):
                self.rules.append({**base, "from": p})
                self.rules.append({**base, "to": p})
            return
        scope = self.sub(node, "rscope")
        # "Using only robot 5, move ...", "... without robot 3": an instrument of the sentence's
        # goal, as a pronoun would be
        instrument = self.first_word(node) in ("using", "with", "by", "without")
        said = words.lower().split()
        # "cart1 can't go / drive to P": it cannot be at P, so takes nothing from it either (as
        # "keep cart1 away from P"; it was also read as "never delivers to P": asked, one echo)
        visit = kind == "rule_never" and any(w in ("go", "drive") and k + 1 < len(said) and said[k + 1] in (
            "to", "into") for k, w in enumerate(said))
        self.scoped(base, scope[0] if scope else node, instrument, visit)  # scope words may sit on the rule itself

    def scoped(self, base: dict, scope: Tree | None, pronoun: bool = False, visit: bool = False) -> None:
        """One rule per product and place the scope names; none named: bound to the sentence.
        ``visit``: a place the robots go to is one they are at (from and to)."""
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
                    for p in self.place_list((self.sub(c, "places") or [c])[0]):
                        places += [{"from": p, "at": True}, {"to": p, "at": True}] if visit else [{"to": p}]
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
                if for_this(base.get("words") or ""):
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
        if self.pending_source and not any(st["op"] == "transfer" and (st.get("from") or {}).get("names") == self.pending_source
                                           for st in self.statements):
            # "From P, move 2 X from Q to R": the moves say their own source; P would be dropped unread
            raise TranslationError(f"'from {', '.join(self.pending_source)}': nothing in the sentence is taken from there")
        # "Empty rack D and put its valves on rack B": what leaves the place goes first, then
        # the rest of it is emptied (else the move would find the place already empty)
        for k, st in enumerate(list(self.statements)):
            if st["op"] != "empty":
                continue
            later = [t for t in self.statements[k + 1:] if t["op"] == "transfer"
                     and set((t.get("from") or {}).get("names") or []) & set(st["places"]["names"])]
            later = leaving_out_what_stays(st, later, self.statements)
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
                        f"this move ({scope_words(use_product, use_place)}); say which "
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


def for_this(words: str) -> bool:
    """"for this" / "for that" with no noun after it: the job, or the move just said? ("for that
    move" says which; "for this job" is read as the whole command by the grammar)."""
    said = words.lower().split()
    return any(w == "for" and said[k + 1:k + 2] in (["this"], ["that"])
               and said[k + 2:k + 3] not in (["move"], ["transfer"], ["trip"], ["run"]) for k, w in enumerate(said))


def scope_words(product: str | None, place: dict | None) -> str:
    """A move's scope in words: "top_hat, from scene_dock, to green_room"."""
    return ", ".join(([product] if product else []) + [f"{k} {v}" for k, v in (place or {}).items()])

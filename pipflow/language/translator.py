"""The offline translator: a command and a world in, the goal and robot-use rules out.

It is the default generator (model ``offline``), so ``pipflow run`` works with no key and no
network, and it is the reference an LLM's output is compared with. It is deterministic and
honest: every name is read from the world (:mod:`names`), counts from words and sums
(:mod:`numbers`), relative and quantified amounts against the stock (:mod:`quantities`), robot
rules by word classes (:mod:`rules`). What it cannot resolve is a :class:`TranslationError`
that quotes the words; it never passes off a guess as certain.

How clauses bind (one sentence at a time, split at ``. ; ! ?``):

* counts before a shelf bind to it: "2 product2, 7 product3 in shelf3, 3 product2 in shelf2";
* a shelf that opens a clause ("On shelf4, there oughta be ...", "shelf4 has/stores ...") takes
  the counts that follow; a later "... and 5 product2 on shelf2" takes only its own count;
* "from A to B" moves units (B gains, A loses); "from A" alone removes them;
* "add/bring/move/deliver N X to S" adds N; "put/there should be N X on S" sets N.
* a sentence part that names a robot is a rule (:mod:`rules`), e.g. "But robot 0 should not ...";
  a rule that follows a goal in the same sentence and names no product or shelf of its own takes
  the goal's single product and single shelf or move (see :func:`_bind`);
* shelves listed together take counts "each"/"both"/"apiece", or "respectively" in order; a
  list with neither is an error (each, or a total?), except zero ("empty shelf1 and shelf2");
* a product may come before its count ("product1 should be 5 on shelf2", "product1: 5");
* bounds ("at least 5", "no more than 5", "5 or more", "about 5") are errors: goals are exact.
"""
from __future__ import annotations

from dataclasses import dataclass, field

from pipflow.errors import TranslationError
from pipflow.language import quantities as q
from pipflow.language.names import NameIndex, Tok, tokenize
from pipflow.language.quantities import Amount
from pipflow.language.rules import parse_rule, places_of, scoped

SENTENCE_END = {".", ";", "!", "?"}
RULE_BOUNDARY = {",", "and", "but", "while", "whereas", "however", ":"}
GOAL_RULE_BOUNDARY = {",", "and", "but", "using", "with", "by", "while", "whereas", "though", ":"}
FROM_PREPS = {"from", "off"}
TO_PREPS = {"in", "on", "at", "to", "into", "onto", "inside", "within", "for"}
ADD_VERBS = {"add", "adds", "bring", "brings", "move", "moves", "transfer", "deliver", "carry",
             "ship", "send", "shift", "relocate", "take", "restock"}
MORE = {"more", "extra", "additional"}
FEWER = {"fewer", "less"}
MULTIPLIERS = {"double": 2, "twice": 2, "triple": 3, "thrice": 3, "quadruple": 4}
FILLER = {"of", "the", "units", "unit", "pieces", "piece", "boxes", "box", "crates", "crate",
          "cases", "case", "pcs", "x", "as", "many", "much", "number", "amount", "count", "its",
          "their", "this", "that", "these", "those"}
EMPTY_WORDS = {"empty", "emptied", "nothing", "clear", "cleared", "vacant"}
FILL_WORDS = {"full", "fill", "filled", "fills"}
EVEN_WORDS = {"evenly", "equally"}
SPLIT_VERBS = {"split", "divide", "distribute", "share", "spread"}
BETWEEN = {"between", "among", "amongst", "across"}
ONLY_WORDS = {"only", "just", "exclusively", "solely"}
MOTION = {"go", "goes", "move", "moved", "moves", "transferred", "sent", "shipped", "relocated",
          "brought", "taken", "carried", "delivered", "shifted", "transfer", "ship", "relocate"}
FRACTIONS = {"half": 2, "halves": 2, "third": 3, "thirds": 3, "quarter": 4, "quarters": 4,
             "fourth": 4, "fourths": 4, "fifth": 5, "fifths": 5, "sixth": 6, "sixths": 6,
             "eighth": 8, "eighths": 8, "tenth": 10, "tenths": 10}
EACH_WORDS = {"each", "both", "apiece", "respectively"}
LIST_JOIN = {",", "and", "&", "the", "plus"}
# Between a product named first and its count: "product1 should be 5 on shelf2".
PRODUCT_FIRST = {"should", "must", "shall", "will", "would", "ought", "to", "be", "is", "are",
                 "needs", "need", "has", "have", "count", "number", "amount", "total", "of",
                 "exactly", "equal", "equals", "at", "on", "in", "inside", "the", "x", "set",
                 "becomes", "become", "go", "goes", "up", "with", ":", "=", "now", "then"}
# Bounds, not counts: the goal format fixes exact counts, so these cannot be written as a goal.
INEQUALITY = [("no", "more", "than"), ("not", "more", "than"), ("no", "fewer", "than"),
              ("no", "less", "than"), ("not", "less", "than"), ("not", "fewer", "than"),
              ("at", "least"), ("at", "most"), ("more", "than"), ("fewer", "than"),
              ("less", "than"), ("up", "to"), ("a", "maximum", "of"), ("a", "minimum", "of"),
              ("maximum", "of"), ("minimum", "of"), ("max",), ("min",), ("maximum",), ("minimum",),
              ("over",), ("under",), ("above",), ("below",), ("approximately",), ("roughly",),
              ("about",), ("around",), ("nearly",), ("almost",), ("some",), ("several",),
              ("a", "few"), ("few",), ("many",), ("lots", "of"), ("plenty", "of")]
INEQUALITY_AFTER = [("or", "more"), ("or", "fewer"), ("or", "less"), ("or", "so"), ("plus",),
                    ("at", "least"), ("at", "most"), ("max",), ("min",), ("tops",)]
STATE_RULE = {"broken", "faulty", "unavailable", "offline", "disabled", "damaged", "down", "idle",
              "unused", "busy", "charging", "malfunctioning", "out-of-service", "spare",
              "anything", "everything", "any", "all", "anywhere", "ever", "whatsoever"}


def _phrase(toks: list[Tok]) -> str:
    return " ".join(t.text for t in toks)


@dataclass
class _Item:
    product: str | None  # None: the amount covers the whole shelf ("empty")
    amount: Amount


@dataclass
class _Group:
    """Items read together, and the shelves they go to (or come from)."""

    items: list[_Item] = field(default_factory=list)
    head: str | None = None
    target: str | None = None
    source: str | None = None


class _Goal:
    """The goal being built, with the rule that one command may not set one count twice."""

    def __init__(self, world: dict):
        self.world = world
        self.counts: dict[str, dict[str, int]] = {}
        self.fixed: dict[tuple[str, str], str] = {}  # set absolutely, by these words
        self.fills: list[tuple[str, str, bool]] = []

    def current(self, shelf: str, product: str) -> int | None:
        return self.counts.get(shelf, {}).get(product)

    def set(self, shelf: str, product: str, value: int, words: str, absolute: bool) -> None:
        key = (shelf, product)
        old = self.current(shelf, product)
        if absolute and key in self.fixed and old != value:
            raise TranslationError(f"the command sets {product} on {shelf} twice: "
                                   f"'{self.fixed[key]}' gives {old}, '{words}' gives {value}")
        if absolute:
            self.fixed[key] = words
        self.counts.setdefault(shelf, {})[product] = value

    def apply(self, shelf: str, item: _Item, add: bool) -> None:
        a = item.amount
        if a.mode == "empty":
            for p, v in q.empty(self.world, shelf).items():
                self.set(shelf, p, v, a.text, absolute=True)
        elif a.mode in ("full", "full_only"):
            self.fills.append((shelf, str(item.product), a.mode == "full_only"))
        else:
            if add and a.mode == "exact":
                a = Amount("more", a.value, a.text)
            p = str(item.product)
            value = q.resolve(a, shelf, p, self.world, self.current(shelf, p))
            self.set(shelf, p, value, a.text, absolute=a.mode in ("exact", "all", "none"))

    def move(self, source: str, target: str | None, item: _Item) -> None:
        a = item.amount
        if a.mode == "empty":  # "remove everything from shelf4"
            for p, v in q.empty(self.world, source).items():
                self.set(source, p, v, a.text, absolute=True)
            return
        p = str(item.product)
        n = q.moved(a, source, p, self.world, self.current(source, p))
        left = q.resolve(Amount("fewer", n, a.text), source, p, self.world, self.current(source, p))
        self.set(source, p, left, a.text, absolute=False)
        if target is not None:
            self.set(target, p, q.resolve(Amount("more", n, a.text), target, p, self.world,
                                          self.current(target, p)), a.text, absolute=False)

    def finish(self) -> dict[str, dict[str, int]]:
        for shelf, product, only in self.fills:
            row = q.fill(self.world, shelf, product, self.counts.get(shelf, {}), only)
            for p, v in row.items():
                self.set(shelf, p, v, f"full of {product}", absolute=True)
        return self.counts


class _Reader:
    """Reads the goal clauses of one command against one world."""

    def __init__(self, world: dict, index: NameIndex, goal: _Goal):
        self.world, self.index, self.goal = world, index, goal
        self.consumed: set[int] = set()  # counts already read for a product named before them

    # -- names -------------------------------------------------------------------------------
    def shelf(self, t: Tok) -> str:
        if t.kind == "name":
            return str(t.value)
        shelves = self.index.by_kind["shelf"]
        if len(shelves) == 1:
            return shelves[0]
        raise TranslationError(f"'{t.text}' does not say which shelf "
                               f"(candidates: {self.index.candidates('shelf')})")

    def _no_product(self, t: Tok, words: str) -> TranslationError:
        return TranslationError(f"'{words}' does not say which product "
                                f"(candidates: {self.index.candidates('product')})")

    # -- items -------------------------------------------------------------------------------
    def _skip(self, toks: list[Tok], j: int, words: set[str]) -> int:
        while j < len(toks) and toks[j].kind == "word" and toks[j].value in words:
            j += 1
        return j

    def _elided(self, toks: list[Tok], j: int) -> bool:
        """A count followed by a shelf with no product: "3 product2 in shelf4, 5 in shelf2"."""
        k = self._skip(toks, j, MORE | FEWER)
        if k < len(toks) and toks[k].kind == "word" and toks[k].value in TO_PREPS | FROM_PREPS:
            k = self._skip(toks, k + 1, {"the"})
            return k < len(toks) and toks[k].of == "shelf"
        return False

    def item(self, toks: list[Tok], i: int, last: str | None, fill: bool, only: bool
             ) -> tuple[list[_Item], int] | None:
        """The amount and product at ``toks[i]``, or None when no item starts there."""
        t = toks[i]
        w = t.value if t.kind == "word" else None
        if t.kind == "num":
            j, mode = i + 1, "exact"
            if j < len(toks) and toks[j].is_word(*MORE):
                mode, j = "more", j + 1
            elif j < len(toks) and toks[j].is_word(*FEWER):
                mode, j = "fewer", j + 1
            elif j < len(toks) and toks[j].is_word("times") and j + 1 < len(toks) \
                    and toks[j + 1].is_word("as", "more"):
                mode, j = "times", j + 2
            if mode == "exact" and j < len(toks) and toks[j].is_word(*FRACTIONS):
                # "two thirds of the product1", "one quarter of"
                k = self._skip(toks, j + 1, FILLER)
                if k < len(toks) and toks[k].kind == "name" and toks[k].of == "product":
                    a = Amount("frac", int(t.value), _phrase(toks[i:k + 1]), FRACTIONS[toks[j].value])
                    return [_Item(str(toks[k].value), a)], k + 1
            k = self._skip(toks, j, FILLER)
            if k + 2 < len(toks) and toks[k].kind == "kind" and toks[k].of == "product" \
                    and toks[k + 1].is_word("of") and toks[k + 2].of == "product":
                k = self._skip(toks, k + 1, FILLER)  # "fifteen items of product1"
            if k < len(toks) and toks[k].kind == "name" and toks[k].of == "product":
                words = _phrase(toks[i:k + 1])
                return [_Item(str(toks[k].value), Amount(mode, int(t.value), words))], k + 1
            if k < len(toks) and toks[k].kind == "kind" and toks[k].of == "product":
                raise self._no_product(toks[k], _phrase(toks[i:k + 1]))
            if self._elided(toks, j) and last is not None:
                return [_Item(last, Amount(mode, int(t.value), _phrase(toks[i:j])))], j
            shown = _phrase(toks[i:min(k + 1, len(toks))])
            raise TranslationError(f"'{shown}': cannot tell which product this count is for "
                                   f"(candidates: {self.index.candidates('product')})")
        if w in MULTIPLIERS or w == "half":
            k = self._skip(toks, i + 1, FILLER)
            if k < len(toks) and toks[k].kind == "name" and toks[k].of == "product":
                words = _phrase(toks[i:k + 1])
                a = Amount("half", 0, words) if w == "half" else Amount("times", MULTIPLIERS[w], words)
                return [_Item(str(toks[k].value), a)], k + 1
            return None
        if w in ("all", "every", "each", "no", "none"):
            k = self._skip(toks, i + 1, FILLER | {"more"})
            mode = "none" if w in ("no", "none") else "all"
            if k < len(toks) and toks[k].kind == "name" and toks[k].of == "product":
                return [_Item(str(toks[k].value), Amount(mode, 0, _phrase(toks[i:k + 1])))], k + 1
            if k < len(toks) and toks[k].kind == "kind" and toks[k].of == "product":
                words = _phrase(toks[i:k + 1])
                if mode == "none":
                    return [_Item(None, Amount("empty", 0, words))], k + 1
                return [_Item(p, Amount("all", 0, words)) for p in self.index.by_kind["product"]], k + 1
            return None
        if w in ("a", "an", "one") and i + 1 < len(toks) and toks[i + 1].is_word(*FRACTIONS):
            k = self._skip(toks, i + 2, FILLER)
            if k < len(toks) and toks[k].kind == "name" and toks[k].of == "product":
                a = Amount("frac", 1, _phrase(toks[i:k + 1]), FRACTIONS[str(toks[i + 1].value)])
                return [_Item(str(toks[k].value), a)], k + 1
            return None
        if w in ("a", "an") and i + 1 < len(toks) and toks[i + 1].of == "product" \
                and toks[i + 1].kind == "name":
            return [_Item(str(toks[i + 1].value), Amount("exact", 1, _phrase(toks[i:i + 2])))], i + 2
        if w in EMPTY_WORDS:
            return [_Item(None, Amount("empty", 0, t.text))], i + 1
        if t.kind == "name" and t.of == "product":
            if fill:
                return [_Item(str(t.value), Amount("full_only" if only else "full", 0,
                                                   f"full of {t.text}"))], i + 1
            later = self._count_after(toks, i)
            if later is not None:
                return later
            raise TranslationError(f"'{t.text}': the command gives no count for it")
        return None

    def _count_after(self, toks: list[Tok], i: int) -> tuple[list[_Item], int] | None:
        """A product named before its count: "product1 should be 5 on shelf2", "product1: 5".

        The count is the first number after the product, across only linking words and shelves,
        that no product follows (so "product1 and 5 product2" is not read this way).
        """
        j = i + 1
        while j < len(toks):
            u = toks[j]
            if u.kind == "num":
                k = self._skip(toks, j + 1, MORE | FEWER)
                mode = "exact"
                if k > j + 1:
                    mode = "more" if toks[j + 1].value in MORE else "fewer"
                after = self._skip(toks, k, FILLER)
                if after < len(toks) and toks[after].of == "product":
                    return None
                self.consumed.add(j)
                words = _phrase(toks[i:k])
                return [_Item(str(toks[i].value), Amount(mode, int(u.value), words))], i + 1
            if u.of == "shelf" or (u.kind == "word" and u.value in PRODUCT_FIRST) or (
                    u.kind == "punct" and u.value in (":", "=")):
                j += 1
                continue
            return None
        return None

    # -- clauses -----------------------------------------------------------------------------
    def _prep(self, toks: list[Tok], i: int) -> str | None:
        j = i - 1
        while j >= 0 and toks[j].is_word("the"):
            j -= 1
        if j < 0 or toks[j].kind != "word":
            return None
        if toks[j].value in FROM_PREPS or (toks[j].value == "of" and j > 0 and toks[j - 1].is_word("out")):
            return "from"
        return "to" if toks[j].value in TO_PREPS else None

    def evenly(self, toks: list[Tok]) -> bool:
        """ "split 10 product1 evenly between shelf1 and shelf2": True when handled."""
        words = {t.value for t in toks if t.kind == "word"}
        if not (words & EVEN_WORDS or words & SPLIT_VERBS) or not words & BETWEEN:
            return False
        b = next(k for k, t in enumerate(toks) if t.is_word(*BETWEEN))
        shelves = [self.shelf(t) for t in toks[b:] if t.of == "shelf"]
        if len(shelves) < 2:
            raise TranslationError(f"'{_phrase(toks[b:])}' names fewer than two shelves to share between "
                                   f"(candidates: {self.index.candidates('shelf')})")
        items: list[tuple[str, int, str]] = []
        i = 0
        while i < b:
            t = toks[i]
            got = self.item(toks, i, None, False, False) if t.kind != "name" else None
            if got:
                for it in got[0]:
                    if it.amount.mode == "exact":
                        items.append((str(it.product), it.amount.value, it.amount.text))
                    elif it.amount.mode == "all":
                        items.append((str(it.product), q.total(self.world, str(it.product)), it.amount.text))
                    else:
                        raise TranslationError(f"'{it.amount.text}' cannot be shared evenly")
                i = got[1]
                continue
            if t.kind == "name" and t.of == "product":  # no count: all of it
                items.append((str(t.value), q.total(self.world, str(t.value)), t.text))
            i += 1
        if not items:
            raise self._no_product(toks[0], _phrase(toks))
        for product, units, words in items:
            for s, v in q.split_evenly(units, shelves).items():
                self.goal.set(s, product, v, words, absolute=True)
        return True

    def _shelf_runs(self, toks: list[Tok]) -> list[tuple[int, int, list[str]]]:
        """Shelves listed together ("shelf1 and shelf2", "shelf1, shelf2 and shelf3")."""
        runs = []
        i = 0
        while i < len(toks):
            if toks[i].of != "shelf":
                i += 1
                continue
            names, end, k = [self.shelf(toks[i])], i + 1, i + 1
            while k < len(toks):
                if toks[k].of == "shelf" and (toks[k - 1].is_word("and", "plus")
                                              or toks[k - 1].text in (",", "&", "the")):
                    names.append(self.shelf(toks[k]))
                    end = k + 1
                elif not (toks[k].is_word(*LIST_JOIN) or toks[k].text in (",", "&")):
                    break
                k += 1
            itemish = lambda ts: any(t.kind == "num" or t.of == "product"  # noqa: E731
                                     or t.is_word(*EMPTY_WORDS | FILL_WORDS) for t in ts)
            if len(names) > 1 and itemish(toks[:i]) and itemish(toks[end:]):
                names = names[:1]  # "5 product1 in shelf2, and shelf4 should be empty": two clauses
                end = i + 1
            if len(names) > 1:
                start = i
                while start > 0 and toks[start - 1].is_word("both", "the"):
                    start -= 1
                if start > 1 and toks[start - 1].is_word("of") and toks[start - 2].is_word("each", "both"):
                    start -= 2  # "on each of shelf1 and shelf2"
                runs.append((start, end, names))
            i = max(end, i + 1)
        return runs

    def shelf_list(self, toks: list[Tok]) -> bool:
        """Counts for several shelves at once; True when handled.

        "shelf1 and shelf2 should each hold 4 product2" (also "both", "apiece"): every shelf gets
        the counts. "shelf1 and shelf2 should hold 4 and 6 product1 respectively": in order.
        "empty shelf1 and shelf2", "no product3 on shelf1 and shelf2": zero is zero on each.
        Otherwise a count for a list of shelves could be each or a total: an error says so.
        """
        runs = self._shelf_runs(toks)
        if not runs:
            return False
        if len(runs) > 1:
            raise TranslationError(f"'{_phrase(toks)}' lists shelves more than once; "
                                   f"say the counts for each shelf separately")
        start, end, shelves = runs[0]
        words = {t.value for t in toks if t.kind == "word"}
        rest = toks[:start] + [Tok("kind", "SHELVES", "shelf", "shelf-list")] + toks[end:]
        if "respectively" in words:
            self.respectively(rest, shelves, _phrase(toks[start:end]))
            return True
        each = words & {"each", "both", "apiece", "every"} and not any(
            toks[k].is_word("each", "every", "both") and k + 1 < len(toks) and toks[k + 1].of == "product"
            for k in range(len(toks)))
        zero = not any(t.kind == "num" for t in toks) and bool(words & (EMPTY_WORDS | {"no", "none"}))
        if not each and not zero:
            raise TranslationError(
                f"'{_phrase(toks)}': the command does not say whether each of "
                f"{', '.join(shelves)} gets these counts or they share them (say 'each', "
                f"'respectively' or 'evenly between')")
        for shelf in shelves:
            one: list[Tok] = []
            for k, t in enumerate(rest):
                if t.of == "shelf-list":
                    one.append(Tok("name", shelf, shelf, "shelf"))
                elif t.is_word("each", "both", "apiece") and not (
                        k + 1 < len(rest) and rest[k + 1].of == "product"):
                    continue
                else:
                    one.append(t)
            self.clause(one)
        return True

    def respectively(self, rest: list[Tok], shelves: list[str], listed: str) -> None:
        """ "4 and 6 product1", "4 product1 and 6 product2" ... respectively, in the shelves' order."""
        add = bool({t.value for t in rest if t.kind == "word"} & ADD_VERBS)
        pairs: list[tuple[int, str | None, str]] = []
        for j, t in enumerate(rest):
            if t.kind != "num":
                continue
            k = self._skip(rest, j + 1, FILLER)
            product = str(rest[k].value) if k < len(rest) and rest[k].kind == "name" \
                and rest[k].of == "product" else None
            pairs.append((int(t.value), product, _phrase(rest[j:k + 1] if product else rest[j:j + 1])))
        named = [p for _, p, _ in pairs if p]
        if len(named) == 1 and pairs and pairs[-1][1] is not None:
            pairs = [(n, named[0], w) for n, _, w in pairs]  # "4 and 6 product1"
        if len(pairs) != len(shelves) or any(p is None for _, p, _ in pairs):
            raise TranslationError(
                f"'respectively': {len(pairs)} count(s) with products "
                f"({', '.join(w for _, _, w in pairs) or 'none'}) for {len(shelves)} shelves "
                f"({listed}); give one count and product per shelf")
        for shelf, (n, product, w) in zip(shelves, pairs):
            self.goal.apply(shelf, _Item(product, Amount("exact", n, w)), add)

    def clause(self, toks: list[Tok]) -> None:
        """Read one goal clause (a sentence, or its part before a rule)."""
        self.consumed = set()
        _no_bounds(toks)
        if self.evenly(toks):
            return
        if self.shelf_list(toks):
            return
        words = {t.value for t in toks if t.kind == "word"}
        add = bool(words & ADD_VERBS)
        fill = bool(words & FILL_WORDS)
        only = bool(words & ONLY_WORDS) or "nothing but" in " ".join(str(t.value) for t in toks)
        head: str | None = None
        cur = _Group()
        groups = [cur]
        last: str | None = None
        rest_empty = False
        i = 0
        while i < len(toks):
            t = toks[i]
            if t.of == "shelf":
                shelf = self.shelf(t)
                prep = self._prep(toks, i)
                if prep == "from":
                    if cur.source is not None or (cur.target is not None and not cur.items):
                        cur = _Group(head=head)
                        groups.append(cur)
                    cur.source = shelf
                elif prep == "to" and cur.items and cur.target is None:
                    if head is not None and shelf != head and len(cur.items) > 1 and cur.source is None:
                        moved = cur.items.pop()
                        cur = _Group([moved], head=head, target=shelf)
                        groups.append(cur)
                    else:
                        cur.target = shelf
                elif prep == "to" and cur.items and cur.target is not None and cur.source is None \
                        and words & MOTION:
                    cur.source, cur.target = cur.target, shelf  # "the product1 on shelf4 should go to shelf5"
                elif prep is None and cur.items and cur.target is None and cur.source is None \
                        and head is None:
                    cur.target = shelf  # "empty shelf4", "clear shelf4"
                else:
                    head = shelf
                    cur = _Group(head=head)
                    groups.append(cur)
                i += 1
                continue
            if fill and only and t.is_word("nothing") and i + 1 < len(toks) and toks[i + 1].is_word("but"):
                i += 2
                continue
            if t.is_word("nothing") and i + 1 < len(toks) and toks[i + 1].is_word("else", "more"):
                rest_empty = True  # "... in shelf3 and nothing else": other goods go to zero
                i += 2
                continue
            if i in self.consumed:
                i += 1
                continue
            got = self.item(toks, i, last, fill, only)
            if got is None:
                i += 1
                continue
            items, i = got
            if cur.target is not None:
                cur = _Group(head=head)
                groups.append(cur)
            cur.items.extend(items)
            last = items[-1].product or last
        for g in groups:
            if not g.items:
                continue
            if g.source is not None:
                for it in g.items:
                    self.goal.move(g.source, g.target, it)
                continue
            target = g.target or g.head
            if target is None:
                raise TranslationError(
                    f"'{', '.join(it.amount.text for it in g.items)}': the command does not say "
                    f"which shelf (candidates: {self.index.candidates('shelf')})")
            for it in g.items:
                self.goal.apply(target, it, add)
        if rest_empty:
            shelves = [g.target or g.head for g in groups if g.items and (g.target or g.head)]
            if not shelves:
                raise TranslationError("'nothing else': the command does not say on which shelf "
                                       f"(candidates: {self.index.candidates('shelf')})")
            row = self.goal.counts.get(shelves[-1], {})
            for p in q.held(self.world, shelves[-1]):
                if p not in row:
                    self.goal.set(shelves[-1], p, 0, "nothing else", absolute=True)


def _words_at(toks: list[Tok], start: int, seq: tuple[str, ...]) -> bool:
    return start >= 0 and start + len(seq) <= len(toks) and all(
        toks[start + k].is_word(w) for k, w in enumerate(seq))


def _no_bounds(toks: list[Tok]) -> None:
    """Raise on a bound ("at least 5", "no more than 5", "5 or more", "about 5")."""
    for j, t in enumerate(toks):
        if t.kind != "num":
            continue
        for seq in INEQUALITY:
            if _words_at(toks, j - len(seq), seq):
                words = _phrase(toks[j - len(seq):j + 1])
                break
        else:
            k = j + 1
            while k < len(toks) and (toks[k].is_word(*FILLER) or toks[k].of == "product"):
                k += 1
            seq = next((q_ for q_ in INEQUALITY_AFTER if _words_at(toks, k, q_)), None)
            if seq is None:
                continue
            words = _phrase(toks[j:k + len(seq)])
        raise TranslationError(
            f"'{words}' is a bound, not a count: a goal fixes exact counts, so a minimum, maximum "
            f"or approximate amount cannot be written as one (give the exact number)")


def _split(toks: list[Tok], ends: set[str]) -> list[list[Tok]]:
    out: list[list[Tok]] = [[]]
    for t in toks:
        if t.kind == "punct" and t.value in ends:
            out.append([])
        else:
            out[-1].append(t)
    return [s for s in out if s]


def _is_robot(t: Tok) -> bool:
    return t.kind == "name" and t.of == "robot"


def _boundary(t: Tok, words: set[str]) -> bool:
    return (t.kind == "punct" and t.value in words) or (t.kind == "word" and t.value in words)


def _bare(chunk: list[Tok]) -> bool:
    """A chunk that only lists robots ("robot 2", "and robot 3"): part of its neighbour's rule."""
    return all(t.kind in ("num", "punct") or t.of == "robot" or t.is_word("the", "and", "or")
               for t in chunk)


def _has_predicate(chunk: list[Tok]) -> bool:
    """Whether words follow the chunk's last robot ("robot 0 must not ..." yes, "only alpha" no)."""
    last = max((k for k, t in enumerate(chunk) if t.of == "robot"), default=-1)
    return any(t.kind in ("word", "name") and not t.is_word("and", "or", "the")
               for t in chunk[last + 1:])


def _parts(sentence: list[Tok]) -> tuple[list[Tok], list[list[Tok]]]:
    """Split a sentence into its goal part and its rule clauses (parts that name robots)."""
    first = next((k for k, t in enumerate(sentence) if _is_robot(t)), None)
    if first is None:
        return sentence, []
    cut = 0
    for k in range(first - 1, 0, -1):
        if _boundary(sentence[k], GOAL_RULE_BOUNDARY) and any(
                t.kind in ("num", "name") and t.of != "robot" for t in sentence[:k]) and any(
                t.of == "shelf" for t in sentence[:k]):
            cut = k
            break
    while cut > 0 and sentence[cut - 1].is_word("without", "not", "never", "but"):
        cut -= 1  # "... without using robot 3": the negation belongs to the rule
    goal, rest = sentence[:cut], sentence[cut:]
    chunks: list[list[Tok]] = [[]]
    for t in rest:
        if _boundary(t, RULE_BOUNDARY):
            chunks.append([t])
        else:
            chunks[-1].append(t)
    merged: list[list[Tok]] = []
    for c in chunks:
        if merged and (not _has_predicate(merged[-1]) or _bare(c) or not any(_is_robot(t) for t in c)):
            merged[-1].extend(c)
        elif c:
            merged.append(c)
    return goal, merged


def _goal_in_rule(chunk: list[Tok]) -> list[Tok]:
    """The goal a rule clause also states, from the words after its robots, else nothing.

    Read only when a count of a named product appears, so "from one shelf to another" or the
    numbers of "robots 8 to 11" are never taken for counts.
    """
    for i, t in enumerate(chunk):
        if t.kind != "num":
            continue
        k = i + 1
        while k < len(chunk) and chunk[k].kind == "word" and chunk[k].value in FILLER | MORE | FEWER:
            k += 1
        if k < len(chunk) and chunk[k].kind == "name" and chunk[k].of == "product":
            start = max((j + 1 for j in range(i) if _is_robot(chunk[j])), default=0)
            while start < i and (chunk[start].kind in ("num", "punct")
                                 or chunk[start].is_word("and", "or", "to", "through")):
                start += 1
            return [t for t in chunk[start:] if t.of != "robot"]
    return []


def _bind(rule: list[Tok], items: list[dict], goal_part: list[Tok]) -> list[dict]:
    """A rule split off a goal in the same sentence governs that goal's moves where unambiguous.

    "put 5 product1 on shelf2, but do not use robot 3 for that": the rule names no product and
    no shelf, so it takes the goal part's single product, and its place when the goal part names
    one shelf or one move "from A to B" (read as the rules module reads places, so "Move ... using
    only robot 5" and "Using only robot 5, move ..." give the same items). Several products or
    places leave that field open (the rule then covers them all); a state of the robot
    ("broken") or "anything"/"at all" is never narrowed.
    """
    if any(t.of in ("product", "shelf") for t in rule) or not goal_part or any(
            t.is_word(*STATE_RULE) for t in rule):
        return items
    products = list(dict.fromkeys(str(t.value) for t in goal_part if t.of == "product"
                                  and t.kind == "name"))
    places = places_of(goal_part)
    shelves = {v for p in places for v in p.values()}
    route = len(places) == 1 and len(places[0]) == 2
    use_places = places if (len(shelves) == 1 or route) else []
    use_products = products if len(products) == 1 else []
    out: list[dict] = []
    for item in items:
        side = "only" if "only" in item else "never"
        if len(item) > 1:  # already narrowed
            out.append(item)
            continue
        for new in scoped(side, item[side], use_products, use_places):
            if new not in out:
                out.append(new)
    return out


def translate(command: str, world: dict) -> dict:
    """Translate a command into ``{"goal": {SHELF: {PRODUCT: units}}, "constraints": [...]}``.

    ``world`` is the world file's content (shelves, products, stock, robots). Raises
    :class:`TranslationError` for what it cannot resolve and :class:`Refusal` for counts that
    cannot exist (below zero, over a shelf's capacity when filling it).
    """
    index = NameIndex(world)
    toks = tokenize(command, index)
    goal = _Goal(world)
    reader = _Reader(world, index, goal)
    constraints: list[dict] = []
    for sentence in _split(toks, SENTENCE_END):
        goal_part, rules = _parts(sentence)
        if goal_part:
            reader.clause(goal_part)
        for r in rules:
            counted = _goal_in_rule(r)
            if counted:  # "robot 3 should put 5 product1 on shelf2": a count and a rule
                reader.clause(counted)
            found = parse_rule(r, index)
            if not counted:
                found = _bind(r, found, goal_part)
            for item in found:
                if item not in constraints:
                    constraints.append(item)
    counts = goal.finish()
    if not counts and not constraints:
        raise TranslationError(f"found no goal and no robot rule in '{command}' "
                               f"(shelves: {index.candidates('shelf')}; "
                               f"products: {index.candidates('product')})")
    return {"goal": counts, "constraints": constraints}

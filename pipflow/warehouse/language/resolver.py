"""The resolver: an order and a world in, the exact goal, bounds, robot rules and their arithmetic out.

Parser and LLM produce orders that say what the user meant ("5 more", "everything except",
"swap", "the rest"); only here are those turned into counts against the world's stock, in one
place, each step written down in plain words ("shelf3 product4: 4 now, +5 -> 9, from '5 product4
more'") so that a user sees a misunderstanding before robots move. It is a pure function.

Rules, one each:

* statements apply in order; a relative amount ("more", "fewer", "times", a fraction) counts
  from the goal so far, else from the stock; "as many as <place> has now" reads the stock;
* "all <item>" on one place is the item's world total; a move of "all" or "the rest" takes what
  the source holds at that point; "except" removes places or items from an "all";
* a count set twice to different values is an error; a bound and a count must agree;
* "full" is the capacity minus what the goal keeps there (deferred to the end); "nothing else"
  zeroes the other goods a place holds; "keep" pins the counts, "nothing goes to" bounds them
  from above;
* impossible results are a :class:`Refusal` that says why: a count below zero, a move of more
  than the source holds, more of an item than the world has, more than a place's capacity.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from pipflow.errors import Refusal, TranslationError
from pipflow.warehouse.language.robots import select


@dataclass
class Resolved:
    """What an order means in one world."""

    goal: dict[str, dict[str, Any]]  # PLACE -> ITEM -> int | {"at_least"?, "at_most"?}
    constraints: list[dict]
    explanation: list[str] = field(default_factory=list)


def stock(world: dict, place: str, item: str) -> int:
    """Units of an item on a place in the initial state (missing means zero)."""
    return int(((world.get("stock") or {}).get(place) or {}).get(item, 0) or 0)


def world_total(world: dict, item: str) -> int:
    return sum(int((row or {}).get(item, 0) or 0) for row in (world.get("stock") or {}).values())


def split_evenly(units: int, places: list[str]) -> dict[str, int]:
    """Share ``units`` between places; the first-named places take one extra unit each."""
    base, extra = divmod(units, len(places))
    return {p: base + (1 if k < extra else 0) for k, p in enumerate(places)}


class _State:
    def __init__(self, world: dict):
        self.world = world
        self.products = [str(p) for p in world.get("products") or {}]
        self.places = [str(s) for s in world.get("shelves") or {}]
        self.counts: dict[tuple[str, str], int] = {}
        self.fixed: dict[tuple[str, str], str] = {}
        self.bounds: dict[tuple[str, str], dict] = {}
        self.lines: list[str] = []
        self.fills: list[dict] = []
        self.before_set: dict[tuple[str, str], int] = {}  # the count before a command fixed it
        self.changed_by: dict[tuple[str, str], str] = {}  # the words that last changed a count

    def cur(self, place: str, item: str) -> int:
        return self.counts.get((place, item), stock(self.world, place, item))

    def held(self, place: str) -> list[str]:
        return [p for p in self.products if self.cur(place, p) > 0]

    def check_names(self, places: list[str], items: list[str], words: str) -> None:
        for p in places:
            if p not in self.places:
                raise TranslationError(f"'{words}': no place {p} in this world "
                                       f"(candidates: {', '.join(self.places)})")
        for i in items:
            if i not in self.products:
                raise TranslationError(f"'{words}': no product {i} in this world "
                                       f"(candidates: {', '.join(self.products)})")

    def put(self, place: str, item: str, value: int, step: str, words: str, absolute: bool) -> None:
        before = self.cur(place, item)
        if value < 0:
            raise Refusal(f"'{words}' would leave {value} {item} on {place} ({before} now, {step}): "
                          f"a shelf cannot hold fewer than 0 units")
        key = (place, item)
        if absolute and key in self.fixed and self.counts.get(key) != value:
            raise TranslationError(f"the command sets {item} on {place} twice: '{self.fixed[key]}' gives "
                                   f"{self.counts[key]}, '{words}' gives {value}")
        if absolute:
            self.fixed[key] = words
            self.before_set.setdefault(key, before)
        if value != before:
            self.changed_by[key] = words
        self.counts[key] = value
        self.lines.append(f"{place} {item}: {before} now, {step} -> {value}, from '{words}'")

    def bound(self, place: str, item: str, lo: int | None, hi: int | None, words: str) -> None:
        b = self.bounds.setdefault((place, item), {})
        if lo is not None:
            b["at_least"] = max(lo, b.get("at_least", lo))
        if hi is not None:
            b["at_most"] = min(hi, b.get("at_most", hi))
        if b.get("at_least", 0) > b.get("at_most", b.get("at_least", 0)):
            raise Refusal(f"'{words}': {item} on {place} would need at least {b['at_least']} and at "
                          f"most {b['at_most']}")
        shown = " and ".join(x for x in (f">= {lo}" if lo is not None else "",
                                         f"<= {hi}" if hi is not None else "") if x)
        self.lines.append(f"{place} {item}: {self.cur(place, item)} now, {shown}, from '{words}'")


def _names(sel: dict | None, universe: list[str]) -> list[str]:
    if not sel:
        return []
    if "names" in sel:
        return [str(n) for n in sel["names"]]
    if sel.get("all"):
        excl = set(sel.get("except") or [])
        return [u for u in universe if u not in excl]
    return []


def _fraction(base: int, num: int, den: int, words: str, where: str) -> int:
    if den <= 0 or (base * num) % den:
        raise TranslationError(f"'{words}': {num}/{den} of {base} ({where}) is not a whole number and "
                               f"the command does not say how to round")
    return base * num // den


def _selection(st: "_State", s: dict) -> tuple[str, list[str], list[str]]:
    """A statement's source words and the places and items it selects, checked against the world."""
    words = s.get("words", "")
    places = _names(s.get("places"), st.places)
    items = _names(s.get("items"), st.products)
    st.check_names(places, items, words)
    return words, places, items


def _set(st: _State, s: dict) -> None:
    words, places, items = _selection(st, s)
    a = s["amount"]
    for p in places:
        for i in items:
            if "count" in a:
                _refuse_undoing_a_change(st, p, i, int(a["count"]), words)
                st.put(p, i, int(a["count"]), f"set {a['count']}", words, True)
            elif a.get("none"):
                st.put(p, i, 0, "set 0", words, True)
            elif a.get("all"):
                total = world_total(st.world, i)
                st.put(p, i, total, f"all {total} the world has", words, True)
                if len(places) == 1:
                    # all of it on one place is none anywhere else: the goal says so (the
                    # sources a move of "every X" empties are counts the command fixes)
                    for q in st.places:
                        if q != p and (q, i) not in st.fixed:
                            st.put(q, i, 0, f"0: all {i} go to {p}", words, True)
            elif "as_many_as" in a:
                # the count now of this item (or of the item ``of``) at a place, or at several together
                others = [a["as_many_as"], *a.get("together_with", [])]
                of = a.get("of", i)
                st.check_names(others, [of], words)
                k = int(a.get("times", 1))
                n = sum(stock(st.world, q, of) for q in others) * k + int(a.get("more", 0)) - int(a.get("fewer", 0))
                shown = f"{k} times " if k != 1 else ""
                shown += f"{a['more']} more than " if a.get("more") else f"{a['fewer']} fewer than " if a.get("fewer") else ""
                what = f" {of}" if of != i else ""
                st.put(p, i, n, f"{shown}as many as {' and '.join(others)} {'have' if len(others) > 1 else 'has'}"
                                f"{what} now ({n})", words, True)
            elif a.get("rest"):
                raise TranslationError(f"'{words}': 'the rest' of what? say where it comes from")
            else:
                raise TranslationError(f"'{words}': cannot tell the count")


def _refuse_undoing_a_change(st: _State, place: str, item: str, value: int, words: str) -> None:
    """Refuse a final count said after a statement that changed the same count to another one.

    "Take 4 X off P (it has 7 X now)", "take 4 X off P and P should have 7": read in turn, the
    count would silently undo the change (the robots would take nothing off). Which one is meant
    is not guessed; a count that agrees with the change ("move 3 to P and P should have 10" where P
    has 7) is read."""
    key = (place, item)
    if key not in st.fixed and key in st.changed_by and st.cur(place, item) != value:
        raise TranslationError(f"'{st.changed_by[key]}' changes {item} on {place} to {st.cur(place, item)}, "
                               f"but '{words}' says {value}: cannot tell which is meant")


def _change(st: _State, s: dict) -> None:
    words, places, items = _selection(st, s)
    a = s["amount"]
    for p in places:
        for i in items:
            base = st.cur(p, i)
            if "more" in a:
                st.put(p, i, base + int(a["more"]), f"+{a['more']}", words, False)
            elif "fewer" in a:
                st.put(p, i, base - int(a["fewer"]), f"-{a['fewer']}", words, False)
            elif "times" in a:
                st.put(p, i, base * int(a["times"]), f"x{a['times']}", words, False)
            elif "fraction" in a:
                num, den = a["fraction"]
                st.put(p, i, _fraction(base, num, den, words, f"{i} on {p}"), f"x {num}/{den}", words, False)


def _bound(st: _State, s: dict) -> None:
    words, places, items = _selection(st, s)
    a = s["amount"]
    for p in places:
        for i in items:
            if "at_least_more" in a:
                st.bound(p, i, st.cur(p, i) + int(a["at_least_more"]), None, words)
            else:
                st.bound(p, i, a.get("at_least"), a.get("at_most"), words)


def _transfer(st: _State, s: dict) -> None:
    words = s.get("words", "")
    a = s["amount"]
    target = _names(s.get("to"), st.places) if s.get("to") else []
    if len(target) > 1:
        raise TranslationError(f"'{words}': the command does not say how to share this between "
                               f"{', '.join(target)} (say 'each' or 'evenly between')")
    src_sel = s.get("from") or {}
    sources = _names(src_sel, st.places)
    if sources and set(sources) <= set(target):
        # "the rest upstairs to the mezz" where "upstairs" is also the mezzanine's word: a move
        # from a place to itself asks for nothing, so a word was read as the wrong role
        raise TranslationError(f"'{words}' would move things from {sources[0]} to {sources[0]} itself: "
                               f"cannot tell where they come from")
    sources = [p for p in sources if p not in target]   # "every place to rack B": the others
    st.check_names(sources + target, [], words)
    item_sel = s.get("items") or {}
    for src in sources:
        items = _names(item_sel, st.products) if "names" in item_sel else [
            i for i in _names(item_sel, st.products) if st.cur(src, i) > 0]
        st.check_names([], items, words)
        for i in items:
            have = st.cur(src, i)
            if "count" in a:
                if "names" not in src_sel and len(sources) > 1:
                    raise TranslationError(f"'{words}': the command does not say which place the "
                                           f"{a['count']} {i} come from")
                n = int(a["count"])
            elif a.get("rest") and (src, i) in st.fixed:
                # "keep 3 gears on rack B and send the rest to rack E": B is already at 3
                n = st.before_set[(src, i)] - have
                if n < 0:
                    raise Refusal(f"'{words}': {src} had only {st.before_set[(src, i)]} {i}")
                for dst in target:
                    st.put(dst, i, st.cur(dst, i) + n, f"+{n} (the rest) from {src}", words, False)
                continue
            elif a.get("all") or a.get("all_held") or a.get("rest"):
                n = have
                if "expect" in a and int(a["expect"]) != have:
                    raise TranslationError(f"'{words}': the command says {a['expect']} {i} but {src} "
                                           f"holds {have}; cannot tell which is meant")
            elif "fraction" in a:
                num, den = a["fraction"]
                n = _fraction(have, num, den, words, f"{i} on {src}")
            elif "up_to" in a:
                n = _missing(st, a, target, sources, i, words)
            else:
                raise TranslationError(f"'{words}': cannot tell how many {i} to move")
            if n > have:
                raise Refusal(f"'{words}' moves {n} {i} from {src}, which holds {have} at that point")
            st.put(src, i, have - n, f"-{n} moved out", words, False)
            for dst in target:
                st.put(dst, i, st.cur(dst, i) + n, f"+{n} from {src}", words, False)
    # what an "except" leaves behind is listed where it is, at its count now
    if "names" not in src_sel:
        for p in src_sel.get("except") or []:
            for i in _names(item_sel, st.products):
                st.put(p, i, st.cur(p, i), "left where it is (except)", words, False)
    for i in item_sel.get("except") or []:
        for src in sources:
            if st.cur(src, i) > 0:
                st.put(src, i, st.cur(src, i), "left where it is (except)", words, False)


def _missing(st: _State, a: dict, target: list[str], sources: list[str], item: str, words: str) -> int:
    """ "get staging to 10 X, taking them from rack 2": what the one target lacks of its count in all,
    moved from the one source (a count already over it is asked: moving none there would not bring it
    down)."""
    if len(target) != 1 or len(sources) != 1:
        raise TranslationError(f"'{words}': the command does not say which place gives what to which")
    now, want = st.cur(target[0], item), int(a["up_to"])
    if now > want:
        raise TranslationError(f"'{words}': {target[0]} holds {now} {item}, more than {want}; taking them from "
                               f"{sources[0]} cannot bring it down: say where the extra go")
    return want - now


def _swap(st: _State, s: dict) -> None:
    words = s.get("words", "")
    places = _names(s.get("places"), st.places)
    if len(places) != 2:
        raise TranslationError(f"'{words}': a swap needs exactly two places ({len(places)} given)")
    a, b = places
    st.check_names([a, b], [], words)
    sel = s.get("items") or {"all": True}
    items = _names(sel, st.products) if "names" in sel else [
        i for i in _names(sel, st.products) if st.cur(a, i) or st.cur(b, i)]
    before = {(p, i): st.cur(p, i) for p in (a, b) for i in items}
    for i in items:
        st.put(a, i, before[(b, i)], f"swapped with {b}", words, False)
        st.put(b, i, before[(a, i)], f"swapped with {a}", words, False)


def _empty(st: _State, s: dict) -> None:
    words = s.get("words", "")
    places = _names(s.get("places"), st.places)
    st.check_names(places, [], words)
    # "empty P" leaves P holding nothing: every product of the world at 0, including those it does
    # not hold now, so no other statement or the planner may park units there (one rule with the
    # benchmark's gold, docs/language.md and benchmarks/language/README.md, convention 3)
    sel = s.get("items") or {"all": True}
    for p in places:
        for i in _names(sel, st.products):
            st.put(p, i, 0, "emptied", words, True)


def _keep(st: _State, s: dict) -> None:
    words = s.get("words", "")
    places = _names(s.get("places"), st.places)
    st.check_names(places, [], words)
    sel = s.get("items") or {"all": True}
    for p in places:
        items = _names(sel, st.products)
        for i in items:
            if s.get("inflow_only"):
                st.bound(p, i, None, st.cur(p, i), words)
                continue
            now = stock(st.world, p, i)
            if st.cur(p, i) != now:
                # "Move everything from P to Q. Don't touch the pears": kept as they are, or moved?
                raise TranslationError(f"'{words}' keeps {i} on {p} as it is ({now}), but "
                                       f"'{st.changed_by[(p, i)]}' changes it to {st.cur(p, i)}: "
                                       f"cannot tell which is meant")
            st.put(p, i, now, "kept", words, True)


def _distribute(st: _State, s: dict) -> None:
    words, places, items = _selection(st, s)
    a = s["amount"]
    sources = _names(s.get("from"), st.places) if s.get("from") else []
    st.check_names(sources, [], words)
    if len(sources) > 1:
        raise TranslationError(f"'{words}': cannot tell which of {', '.join(sources)} the shares come from")
    if not places:   # "split two heaters between each of the two aisles": no place named to share between
        raise TranslationError(f"'{words}': names no place to share between; name them")
    for i in items:
        if sources:
            src = sources[0]
            have = st.cur(src, i)
            units = int(a["count"]) if "count" in a else have
            if units > have:
                raise Refusal(f"'{words}' shares {units} {i} from {src}, which holds {have}")
            if "expect" in a and int(a["expect"]) != have:
                raise TranslationError(f"'{words}': the command says {a['expect']} {i} but {src} holds {have}")
            st.put(src, i, have - units, f"-{units} shared out", words, False)
            for p, n in split_evenly(units, places).items():
                if units % len(places):
                    raise TranslationError(f"'{words}': {units} {i} do not split evenly between "
                                           f"{', '.join(places)}; say how many each gets")
                st.put(p, i, st.cur(p, i) + n, f"+{n} (a share of {units} from {src})", words, False)
            continue
        units = int(a["count"]) if "count" in a else world_total(st.world, i)
        for p, n in split_evenly(units, places).items():
            st.put(p, i, n, f"share {n} of {units}", words, True)


def _nothing_else(st: _State, s: dict, statements: list[dict]) -> None:
    words = s.get("words", "")
    for p in _names(s.get("places"), st.places):
        named = {i for (q, i) in list(st.counts) + list(st.bounds) if q == p}
        named |= {i for f in st.fills if p in f["places"] for i in f["items"]}
        for i in [x for x in st.products if stock(st.world, p, x) > 0 and x not in named]:
            st.put(p, i, 0, "nothing else", words, True)


def _fill(st: _State, f: dict) -> None:
    words = f["words"]
    for p in f["places"]:
        capacity = ((st.world.get("shelves") or {}).get(p) or {}).get("capacity")
        if capacity is None:
            raise TranslationError(f"'{p}' has no capacity in the world, so 'full' has no count")
        for item in f["items"]:
            if f["only"]:
                for other in st.held(p):
                    if other != item:
                        st.put(p, other, 0, "only " + item, words, True)
                st.put(p, item, int(capacity), f"full: capacity {capacity}", words, True)
                continue
            others = sum(st.cur(p, o) for o in st.products if o != item)
            if others > capacity:
                raise Refusal(f"{p} keeps {others} other units, more than its capacity {capacity}")
            st.put(p, item, int(capacity) - others, f"full: capacity {capacity} - {others} other units",
                   words, True)


def _check_feasible(st: _State) -> None:
    """Refuse what no plan can reach: more than a place holds, more than the world has."""
    need: dict[tuple[str, str], int] = {}
    for key in set(st.counts) | set(st.bounds):
        lo = st.counts.get(key, st.bounds.get(key, {}).get("at_least", 0))
        b = st.bounds.get(key, {})
        if key in st.counts:
            v = st.counts[key]
            if "at_least" in b and v < b["at_least"] or "at_most" in b and v > b["at_most"]:
                raise Refusal(f"{key[1]} on {key[0]}: the command asks for {v} and also for "
                              f"{'at least ' + str(b['at_least']) if 'at_least' in b else ''}"
                              f"{' and ' if 'at_least' in b and 'at_most' in b else ''}"
                              f"{'at most ' + str(b['at_most']) if 'at_most' in b else ''}")
        need[key] = lo
    for p in st.places:
        cap = ((st.world.get("shelves") or {}).get(p) or {}).get("capacity")
        total = sum(v for (q, _), v in need.items() if q == p)
        if cap is not None and total > int(cap):
            raise Refusal(f"{p} would have to hold {total} units, more than its capacity {cap}")
    for i in st.products:
        total = sum(v for (_, j), v in need.items() if j == i)
        have = world_total(st.world, i)
        if total > have:
            raise Refusal(f"the goal needs {total} {i} in all, but the world has only {have}")


def _covers(rule: dict, statements: list[dict]) -> bool:
    """Whether a scoped rule's scope takes in every statement of the order: each a move of its
    product from its ``from`` to its ``to`` (then the same rule said for the whole command, "Have
    R bring 1 X from A to B. Just R on this one.", restates it)."""
    def one(sel: dict | None) -> str | None:
        names = (sel or {}).get("names") or []
        return names[0] if len(names) == 1 and not (sel or {}).get("all") else None
    return bool(statements) and all(
        s.get("op") == "transfer" and all(rule.get(k) in (None, one(s.get(f)))
                                          for k, f in (("product", "items"), ("from", "from"), ("to", "to")))
        for s in statements)


def _rules(order: dict, world: dict, lines: list[str]) -> list[dict]:
    out: list[dict] = []
    resolved = []
    for r in order.get("rules") or []:
        words = r.get("words", "")
        item: dict = {r["mode"]: select(r["robots"], world, words)}
        for k in ("product", "from", "to"):
            if r.get(k):
                item[k] = r[k]
        resolved.append((r, item))
    scoped = [item for _, item in resolved if set(item) - {"only", "never"}
              and _covers(item, order.get("statements") or [])]
    for r, item in resolved:
        words = r.get("words", "")
        names = item[r["mode"]]
        if len(item) == 1 and any(s.get(r["mode"]) == names for s in scoped):
            continue  # the whole command's rule restates a rule whose scope is the whole command
        if item not in out:
            out.append(item)
            scope = " ".join(f"{k} {item[k]}" for k in ("product", "from", "to") if k in item) or "any move"
            verb = "only" if r["mode"] == "only" else "never"
            lines.append(f"robots {', '.join(names)}: {verb} for {scope}, from '{words}'")
    return out


HANDLERS = {"set": _set, "change": _change, "bound": _bound, "transfer": _transfer, "swap": _swap,
            "empty": _empty, "keep": _keep, "distribute": _distribute}


def resolve(order: dict, world: dict, check: bool = True) -> Resolved:
    """The goal (exact counts and bounds), robot rules and explanation of an order in a world.

    ``check`` False skips the test that the world can supply the goal (capacity, totals), for
    reading tests on made-up worlds; the arithmetic's own refusals (below zero, moving more than
    a source holds) always apply.
    """
    st = _State(world)
    statements = order.get("statements") or []
    for s in statements:
        op = s.get("op")
        if op == "fill":
            places = _names(s.get("places"), st.places)
            items = _names(s.get("items"), st.products)
            st.check_names(places, items, s.get("words", ""))
            st.fills.append({"places": places, "items": items, "only": bool(s.get("only")),
                             "words": s.get("words", "")})
        elif op == "nothing_else":
            _nothing_else(st, s, statements)
        elif op == "set_all_held":
            raise TranslationError(f"'{s.get('words', '')}': cannot tell how many of each to put there")
        elif op in HANDLERS:
            HANDLERS[op](st, s)
        else:
            raise TranslationError(f"unknown statement '{op}' in the order")
    for f in st.fills:
        _fill(st, f)
    if check:
        _check_feasible(st)
    goal: dict[str, dict[str, Any]] = {}
    for (p, i), v in st.counts.items():
        goal.setdefault(p, {})[i] = v
    for (p, i), b in st.bounds.items():
        if (p, i) in st.counts:
            continue
        goal.setdefault(p, {})[i] = {k: b[k] for k in ("at_least", "at_most") if k in b}
    lines = list(st.lines)
    constraints = _rules(order, world, lines)
    if not goal and not constraints:
        raise TranslationError("the command asks for no goal and no robot rule")
    return Resolved(goal=goal, constraints=constraints, explanation=lines)

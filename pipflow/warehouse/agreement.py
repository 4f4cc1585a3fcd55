"""The warehouse's second opinion on a model's reading: its stock goal and robot rules against the
offline reading (parser and resolver) of the command, or, when the parser does not read the
command, the doubts the command's names and numbers raise about it.

What is generic (firm versus loose, when a refusal is final, never handing the reading's value
to the model) is :mod:`pipflow.language.agreement`; this module knows shelves, products, counts
and robot rules, and which words of the command each goal entry comes from.
"""
from __future__ import annotations

import json
from typing import Any

from pipflow.goalcounts import describe, holds, is_bound
from pipflow.language.agreement import Finding, Opinion, judge, remembered_reading, words_note
from pipflow.warehouse.language.names import NameIndex, tokenize


def _read(command: str, world: dict) -> dict:
    """The offline reading with the order it comes from (the words of each statement and rule)."""
    # deferred: builds the lark parser (~300 ms; only a check of a model's reading needs it)
    from pipflow.warehouse.language.translator import understand

    got = understand(command, world)
    return {"goal": got["goal"], "constraints": list(got["constraints"]), "order": got["order"]}


def _now(world: dict, shelf: str, product: str) -> int:
    return int((world.get("stock", {}).get(shelf) or {}).get(product, 0))


def _changes(world: dict, shelf: str, product: str, value: Any) -> bool:
    """The goal value asks for something other than what the shelf holds now."""
    now = _now(world, shelf, product)
    return not (value == now or (is_bound(value) and holds(now, value)))


def _agrees(model_value: Any, want: Any) -> bool:
    """The model's value means what the reading means: equal, or an exact count that meets the
    reading's bound (a grounded answer can only state exact counts)."""
    if model_value == want:
        return True
    return is_bound(want) and not is_bound(model_value) and isinstance(model_value, int) and holds(model_value, want)


def _selected(selector: Any, universe: list[str]) -> set[str]:
    """The names an order selector picks: ``{"names": [...]}`` or ``{"all": true, "except": [...]}``."""
    if not isinstance(selector, dict):
        return set()
    if selector.get("all"):
        return set(universe) - set(selector.get("except") or [])
    return {str(n) for n in selector.get("names") or []}


def pair_words(order: dict, world: dict, shelf: str, product: str) -> str:
    """The words of the command's statements that speak of ``product`` on ``shelf`` (a statement
    with no item selector speaks of every product), joined; "" when none does."""
    shelves, products = list(world.get("shelves") or {}), list(world.get("products") or {})
    found = []
    for st in order.get("statements") or []:
        places = set().union(*(_selected(st.get(k), shelves) for k in ("places", "from", "to")))
        items = _selected(st.get("items"), products) if "items" in st else set(products)
        if shelf in places and product in items and st.get("words"):
            found.append(str(st["words"]))
    return "; ".join(dict.fromkeys(found))


def _rule_key(rule: dict) -> str:
    """A rule without its source words, robots sorted: two rules that mean the same compare equal."""
    kind = "only" if "only" in rule else "never"
    robots = rule.get(kind)
    robots = sorted([robots] if isinstance(robots, str) else list(robots or []))
    clean = {kind: robots, **{k: rule[k] for k in ("product", "from", "to") if rule.get(k) not in (None, "any")}}
    return json.dumps(clean, sort_keys=True)


def _rule_words(order: dict, rule: dict) -> str:
    """The words of the command's rules of the same kind and scope as ``rule`` (its robots are
    resolved from kinds and tags, so they are not compared), joined."""
    kind = "only" if "only" in rule else "never"
    scope = {k: rule.get(k) for k in ("product", "from", "to") if rule.get(k) not in (None, "any")}
    found = [str(r.get("words")) for r in order.get("rules") or []
             if r.get("mode") == kind and r.get("words")
             and {k: r.get(k) for k in ("product", "from", "to") if r.get(k) not in (None, "any")} == scope]
    return "; ".join(dict.fromkeys(found))


def _rule_in_words(rule: dict) -> str:
    """A rule of the model's own, in words (it is the model's value, not the reading's)."""
    kind = "only" if "only" in rule else "never"
    robots = rule.get(kind)
    robots = [robots] if isinstance(robots, str) else list(robots or [])
    scope = ", ".join(f"{k} {rule[k]}" for k in ("product", "from", "to") if rule.get(k) not in (None, "any"))
    return f"{kind} {', '.join(robots)}" + (f" ({scope})" if scope else "")


def compare_with_reading(command: str, goal: dict, constraints: list, reading: dict, world: dict) -> list[Finding]:
    """Where the model's goal and rules differ from the offline reading. A goal entry the reading
    does not have is no disagreement when it keeps the shelf's current count (a model may restate
    what stays); one that changes it is. The messages name the shelf and product (or the rule)
    and quote the command's words; the reading's counts and rules stay in ``said``."""
    found: list[Finding] = []
    order = reading.get("order") or {}
    want = reading["goal"]
    for shelf, items in want.items():
        for product, value in items.items():
            got = (goal.get(shelf) or {}).get(product)
            note = words_note(pair_words(order, world, shelf, product) or command)
            if got is None:
                found.append(Finding(
                    f"the command asks for {describe(value)} {product} on {shelf}; the model's goal does not say",
                    f"your goal leaves out {product} on {shelf}, which the command asks about {note}"))
            elif not _agrees(got, value):
                found.append(Finding(
                    f"the command asks for {describe(value)} {product} on {shelf}; the model's goal says {describe(got)}",
                    f"your goal's count of {product} on {shelf} is not what the command asks for {note}"))
    for shelf, items in goal.items():
        for product, value in items.items():
            if product in (want.get(shelf) or {}) or not _changes(world, shelf, product, value):
                continue
            found.append(Finding(
                f"the model's goal changes {product} on {shelf} to {describe(value)} (now "
                f"{_now(world, shelf, product)}); the command does not ask for that",
                f"your goal changes {product} on {shelf}, which the command does not ask for"))
    have = {_rule_key(r): r for r in constraints or []}
    need = {_rule_key(r): r for r in reading.get("constraints") or []}
    for key in sorted(set(need) - set(have)):
        note = words_note(_rule_words(order, need[key]) or command)
        found.append(Finding(f"the command states the robot rule {key}; the model's rules do not",
                             f"your rules leave out a rule the command states about which robots may move what {note}"))
    for key in sorted(set(have) - set(need)):
        found.append(Finding(f"the model's rule {key} is not in the command",
                             f"your rule '{_rule_in_words(have[key])}' is not one the command states"))
    return found


def command_words(command: str, world: dict) -> tuple[set[str], set[str], set[int]]:
    """The shelves, products and numbers a command names (typo-tolerant, as the parser reads
    names: "prodct1" is product1, "robot 0" is a robot and not the number 0)."""
    shelves, products, numbers = set(), set(), set()
    for tok in tokenize(command, NameIndex(world)):
        if tok.kind == "name" and tok.value in world.get("shelves", {}):
            shelves.add(str(tok.value))
        elif tok.kind == "name" and tok.value in world.get("products", {}):
            products.add(str(tok.value))
        elif tok.kind == "num" and isinstance(tok.value, int):
            numbers.add(int(tok.value))
    return shelves, products, numbers


def _stated(value: Any) -> list[int]:
    """The counts a goal value states (a bound's limits)."""
    if not is_bound(value):
        return [value] if isinstance(value, int) else []
    return [v for v in value.values() if isinstance(v, int)]


def doubts_from_words(command: str, goal: dict, constraints: list, world: dict) -> list[str]:
    """What the command's names and numbers make doubtful about a goal the parser could not
    check (none of them is proof: see :mod:`pipflow.language.agreement`):

    * a count changed on a shelf or of a product the command does not name;
    * a number of the command that is no count of the goal, no change of one, and no difference
      between one and the current count of a shelf and product the command names (a reference:
      "7 fewer than shelf4 has");
    * a shelf or product the command names that the goal neither changes, nor counts from, nor
      names in a rule.

    A goal entry that keeps a current count changes nothing, so restating a name proves nothing."""
    shelves, products, numbers = command_words(command, world)
    changed = [(s, p, v) for s, items in goal.items() for p, v in items.items() if _changes(world, s, p, v)]
    out = []
    for s, p, v in changed:
        strange = [n for n, named in ((s, shelves), (p, products)) if named and n not in named]
        if strange:
            out.append(f"the goal changes {p} on {s} (to {describe(v)}), but the command names no "
                       f"{' or '.join(strange)}")
    references = [(s, p) for s in shelves for p in products]
    counted_from: set[str] = set()
    for n in sorted(numbers):
        accounted = False
        for s, p, v in changed:
            for x in _stated(v):
                if n in (x, abs(x - _now(world, s, p))):
                    accounted = True
                for rs, rp in references:
                    if (rs, rp) != (s, p) and abs(x - _now(world, rs, rp)) == n:
                        accounted = True
                        counted_from |= {rs, rp}
        if not accounted:
            out.append(f"the command's number {n} is no count of the goal, no change of one, and no difference "
                       "from a count the command names")
    in_rules = {str(r.get(k)) for r in constraints or [] for k in ("product", "from", "to") if r.get(k)}
    used = {s for s, _, _ in changed} | {p for _, p, _ in changed} | counted_from | in_rules
    for name in sorted((shelves | products) - used):
        out.append(f"the command names {name}; the goal neither changes it nor counts from it")
    return out


def second_opinion(command: str, world: dict, goal: dict | None, constraints: list | None,
                   verifier_refusal: str | None, last: bool = False) -> Opinion:
    """The model's reading (``goal``, ``constraints``) against the command's (see
    :func:`pipflow.language.agreement.judge`)."""
    goal, constraints = goal or {}, constraints or []
    reading = remembered_reading(command, world, _read, "warehouse")
    return judge(reading, lambda data: compare_with_reading(command, goal, constraints, data, world),
                 lambda: doubts_from_words(command, goal, constraints, world), verifier_refusal, last)

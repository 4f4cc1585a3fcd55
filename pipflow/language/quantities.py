"""Turn what a command asks for ("two more", "all", "half", "full of") into unit counts.

Relative and quantified amounts only have a meaning against the world's stock, so they are kept
symbolic while the command is read and resolved here, in one place, with one rule each:

* ``more``/``fewer``/``times``/``half``/``frac`` ("a third of", "two quarters of"): relative to the count the goal already gives that shelf
  and product (from an earlier clause of the same command), else to the current stock;
* ``all``/``every``: the product's total over every shelf in the world;
* ``none``/``no``: zero; ``empty``: every product the shelf holds goes to zero;
* ``evenly``: floor division, the remainder handed out one unit each to the shelves in the order
  the command names them;
* ``full``: the shelf's capacity minus the other goods it keeps (their goal count when the command
  sets one, else their stock); "full of only X" is the capacity and the other goods go to zero.

Half of an odd count (a third of 10...) is not a whole number: that is a :class:`TranslationError` (the command
does not say which way to round). A count that would go below zero is a :class:`Refusal`.
"""
from __future__ import annotations

from dataclasses import dataclass

from pipflow.errors import Refusal, TranslationError


@dataclass(frozen=True)
class Amount:
    """An amount as the command states it; ``text`` is the words, for messages."""

    mode: str  # exact | more | fewer | times | half | frac | all | none | empty | full | full_only
    value: int = 0
    text: str = ""
    den: int = 1  # frac: value/den of the base ("a third of" is 1/3)


def stock(world: dict, shelf: str, product: str) -> int:
    """Units of a product on a shelf in the initial state (missing means zero)."""
    return int(((world.get("stock") or {}).get(shelf) or {}).get(product, 0) or 0)


def total(world: dict, product: str) -> int:
    """Units of a product over every shelf of the world."""
    return sum(int((units or {}).get(product, 0) or 0) for units in (world.get("stock") or {}).values())


def held(world: dict, shelf: str) -> list[str]:
    """Products a shelf holds at the start, in the world's product order."""
    units = (world.get("stock") or {}).get(shelf) or {}
    return [p for p in world.get("products") or {} if int(units.get(p, 0) or 0) > 0]


def _check(value: int, amount: Amount, shelf: str, product: str) -> int:
    if value < 0:
        raise Refusal(f"'{amount.text}' would leave {value} {product} on {shelf}: "
                      f"a shelf cannot hold fewer than 0 units")
    return value


def _half(base: int, amount: Amount, where: str) -> int:
    if base % 2:
        raise TranslationError(f"'{amount.text}': half of {base} ({where}) is not a whole "
                               f"number and the command does not say how to round")
    return base // 2


def _fraction(base: int, amount: Amount, where: str) -> int:
    if (base * amount.value) % amount.den:
        raise TranslationError(f"'{amount.text}': {amount.value}/{amount.den} of {base} ({where}) is "
                               f"not a whole number and the command does not say how to round")
    return base * amount.value // amount.den


def resolve(amount: Amount, shelf: str, product: str, world: dict, current: int | None) -> int:
    """The goal count for (shelf, product); ``current`` is the goal's count so far, if any."""
    base = stock(world, shelf, product) if current is None else current
    mode = amount.mode
    if mode == "exact":
        value = amount.value
    elif mode == "more":
        value = base + amount.value
    elif mode == "fewer":
        value = base - amount.value
    elif mode == "times":
        value = base * amount.value
    elif mode == "half":
        value = _half(base, amount, f"{product} on {shelf}")
    elif mode == "frac":
        value = _fraction(base, amount, f"{product} on {shelf}")
    elif mode == "all":
        value = total(world, product)
    elif mode == "none":
        value = 0
    else:
        raise TranslationError(f"'{amount.text}' is not an amount for one product")
    return _check(value, amount, shelf, product)


def moved(amount: Amount, source: str, product: str, world: dict, current: int | None) -> int:
    """Units a move takes from ``source``: "all"/"half" refer to what the source holds."""
    base = stock(world, source, product) if current is None else current
    if amount.mode == "exact":
        return amount.value
    if amount.mode == "all":
        return base
    if amount.mode == "half":
        return _half(base, amount, f"{product} on {source}")
    if amount.mode == "frac":
        return _fraction(base, amount, f"{product} on {source}")
    raise TranslationError(f"'{amount.text}' does not say how many {product} to move from {source}")


def split_evenly(units: int, shelves: list[str]) -> dict[str, int]:
    """Share ``units`` between shelves; the first-named shelves take one extra unit each."""
    base, extra = divmod(units, len(shelves))
    return {s: base + (1 if k < extra else 0) for k, s in enumerate(shelves)}


def fill(world: dict, shelf: str, product: str, goal_row: dict[str, int], only: bool) -> dict[str, int]:
    """Counts that make ``shelf`` full of ``product`` (see the module doc for the rule)."""
    capacity = (world.get("shelves") or {}).get(shelf, {}).get("capacity")
    if capacity is None:
        raise TranslationError(f"'{shelf}' has no capacity in the world, so 'full' has no count")
    if only:
        row = {p: 0 for p in held(world, shelf) if p != product}
        row[product] = int(capacity)
        return row
    others = 0
    for p in world.get("products") or {}:
        if p != product:
            others += goal_row[p] if p in goal_row else stock(world, shelf, p)
    if others > capacity:
        raise Refusal(f"{shelf} keeps {others} other units, more than its capacity {capacity}")
    return {product: int(capacity) - others}


def empty(world: dict, shelf: str) -> dict[str, int]:
    """Counts that empty a shelf: zero for each product it holds (every product if none)."""
    return {p: 0 for p in (held(world, shelf) or list(world.get("products") or {}))}

"""Linear forms of unified-planning numeric expressions and comparisons.

Why: two consumers need to *read* numeric PDDL rather than match fluent names. The transport
planner recognises a transport schema by the shape of its action (which fluent is decreased at
the source, which one bounds the target), and the deordering dependency graph needs every
precondition as ``sum(coef * fluent) + const  op  0`` to bound it over all orders a graph allows.
Both work on the same representation, built here once.

A :class:`Linear` is ``{key: coef}`` plus a constant, with exact ``Fraction`` arithmetic; a key is
``(fluent name, arg, ...)``, each arg an object name, a parameter name (``"?p"``) or a constant.
``values`` substitutes known (static) fluents while reading. Anything that is not linear
(a product of two fluents, a division by a fluent, a boolean fluent) raises :class:`NotLinear`.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from fractions import Fraction
from typing import Any, Callable, Optional

Key = tuple
Values = Optional[Callable[[Key], Optional[Fraction]]]


class NotLinear(Exception):
    """The expression is not a linear combination of numeric fluents."""


@dataclass
class Linear:
    """``sum(coef * key) + const``."""

    coefs: dict = field(default_factory=dict)
    const: Fraction = Fraction(0)

    def scaled(self, k: Fraction) -> "Linear":
        return Linear({x: c * k for x, c in self.coefs.items()}, self.const * k)

    def plus(self, other: "Linear") -> "Linear":
        coefs = dict(self.coefs)
        for x, c in other.coefs.items():
            coefs[x] = coefs.get(x, Fraction(0)) + c
        return Linear({x: c for x, c in coefs.items() if c}, self.const + other.const)

    def minus(self, other: "Linear") -> "Linear":
        return self.plus(other.scaled(Fraction(-1)))


@dataclass
class Comparison:
    """``form op 0`` with ``op`` one of ``">="``, ``">"``, ``"=="``."""

    form: Linear
    op: str

    def holds(self, value: Fraction) -> bool:
        """Whether ``value`` (of :attr:`form`) satisfies the comparison."""
        return value >= 0 if self.op == ">=" else value > 0 if self.op == ">" else value == 0


def _number(node: Any) -> Fraction:
    v = node.constant_value()
    return Fraction(v) if not isinstance(v, float) else Fraction(v).limit_denominator(10**9)


def key_of(node: Any) -> Key:
    """The key of a fluent application: objects by name, parameters as ``?name``."""
    args = []
    for a in node.args:
        if a.is_object_exp():
            args.append(a.object().name)
        elif a.is_parameter_exp():
            args.append("?" + a.parameter().name)
        elif a.is_constant():
            args.append(str(a.constant_value()))
        else:
            args.append("*")
    return (node.fluent().name, *args)


def linear(node: Any, values: Values = None) -> Linear:
    """The linear form of a numeric UP expression; :class:`NotLinear` when it is not linear."""
    if node.is_int_constant() or node.is_real_constant():
        return Linear({}, _number(node))
    if node.is_fluent_exp():
        key = key_of(node)
        known = values(key) if values else None
        if known is not None:
            return Linear({}, Fraction(known))
        return Linear({key: Fraction(1)}, Fraction(0))
    if node.is_plus():
        out = Linear()
        for a in node.args:
            out = out.plus(linear(a, values))
        return out
    if node.is_minus():
        first, *rest = node.args
        out = linear(first, values)
        for a in rest:
            out = out.minus(linear(a, values))
        return out
    if node.is_times():
        out = Linear({}, Fraction(1))
        for a in node.args:
            f = linear(a, values)
            if out.coefs and f.coefs:
                raise NotLinear(f"{node} multiplies two fluents")
            out = f.scaled(out.const) if not out.coefs else out.scaled(f.const)
        return out
    if node.is_div():
        num, den = node.args
        d = linear(den, values)
        if d.coefs or d.const == 0:
            raise NotLinear(f"{node} divides by a fluent or by zero")
        return linear(num, values).scaled(1 / d.const)
    raise NotLinear(f"{node} is not a numeric linear expression")


def comparison(node: Any, values: Values = None) -> Comparison:
    """A numeric condition (``<=``, ``<``, ``=``, possibly under ``not``) as ``form op 0``."""
    negate = False
    while node.is_not():
        negate = not negate
        node = node.args[0]
    if node.is_le() or node.is_lt():
        lhs, rhs = node.args
        form = linear(rhs, values).minus(linear(lhs, values))  # lhs <= rhs  <=>  rhs - lhs >= 0
        strict = node.is_lt()
        if negate:  # not (rhs - lhs >= 0)  <=>  lhs - rhs > 0
            return Comparison(form.scaled(Fraction(-1)), ">=" if strict else ">")
        return Comparison(form, ">" if strict else ">=")
    if node.is_equals() and not negate:
        lhs, rhs = node.args
        if lhs.type.is_bool_type() or lhs.type.is_user_type():
            raise NotLinear(f"{node} is not a numeric comparison")
        return Comparison(linear(lhs, values).minus(linear(rhs, values)), "==")
    raise NotLinear(f"{node} is not a numeric comparison")


def conjuncts(node: Any) -> list[Any]:
    """A condition's top-level ``and`` opened into a flat list."""
    out, stack = [], [node]
    while stack:
        n = stack.pop(0)
        if n.is_and():
            stack[:0] = list(n.args)
        elif n.is_true():
            continue
        else:
            out.append(n)
    return out

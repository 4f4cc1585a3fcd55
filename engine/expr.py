"""``${...}`` references and conditions, evaluated by jinja2's sandbox (never Python eval).

A string that is exactly one ``${expr}`` evaluates to the expression's value with its type
(a list stays a list); a string with text around one or more ``${...}`` is interpolated.
Inside the braces is a jinja2 expression over the run's namespace::

    ${inputs.command}              an input
    ${solve.plan}                  an output of step `solve`
    ${verify.ok and not debug.ok}  a condition
    ${env.PIPFLOW_MODEL | default('offline')}   an environment variable with a default
    ${previous.verify.messages}    in a loop: the previous iteration's output (None at first)

The dependencies of a step are the step ids its expressions name, read off jinja2's AST.

The sandbox also bounds what an expression may build, in two layers:

* **before**: ``${ 'a' * 10**10 }`` would allocate 10 GB before any check could look at the
  result, so what can grow without bound from a small input is checked *before* it runs:
  repetition, powers and products of integers, concatenation, padding, format widths, joins,
  replacements, escapes, translation tables (:data:`MAX_BUILD` characters or items,
  :data:`MAX_INT_BITS` bits); jinja2's compile-time constant folding, which would run them while
  compiling, is kept off for those operators.
* **after**: the result of *every* filter, method call and operator is checked against the same
  bounds, whatever the filter (``forceescape`` makes 4-5 characters of one, ``urlencode`` up to
  12, ``tojson`` up to 12): so no chain of filters can multiply a value past the bounds, and the
  most one step can build before it is refused is its own growth factor times
  :data:`MAX_BUILD`. A text made of several ``${...}`` is bounded the same way.
"""
from __future__ import annotations

import functools
import json
import math
import operator
import re
from collections.abc import Mapping, Sized
from dataclasses import dataclass
from typing import Any

from jinja2 import StrictUndefined, Undefined, nodes
from jinja2.exceptions import SecurityError, TemplateError, TemplateSyntaxError
from jinja2.parser import Parser
from jinja2.visitor import NodeTransformer
from jinja2.sandbox import ImmutableSandboxedEnvironment

_OPEN = "${"
_WHOLE = re.compile(r"^\s*\$\{(.*)\}\s*$", re.S)

MAX_BUILD = 10_000_000  # characters of a string / items of a list an expression may make
MAX_INT_BITS = 100_000  # bits of an integer an expression may compute (10**30000)
MAX_SOURCE = 100_000  # characters of one expression
_WIDE_FORMAT = re.compile(r"\d{8,}")  # a width or precision of 10**7 or more in a format string


class ExpressionError(Exception):
    """An expression cannot be parsed or evaluated; the message says why."""


class TooLarge(SecurityError):
    """An expression would build a value beyond the sandbox's bounds."""


def _weight(value: Any, limit: int = MAX_BUILD) -> int:
    """Characters and items a value spells out when written (as JSON, or joined), counting a
    list or string that appears many times (``[big] * n``) each time; stops counting past
    ``limit``. Linear in the distinct containers: each one's weight is computed once."""
    known: dict[int, int] = {}

    def weigh(v: Any) -> int:
        if isinstance(v, (str, bytes)):
            return len(v)
        if not isinstance(v, (list, tuple, dict)):
            return 1
        if id(v) in known:
            return known[id(v)]
        known[id(v)] = limit + 1  # a container inside itself weighs "too much"
        total = len(v)
        for item in (v.items() if isinstance(v, dict) else v):
            total += weigh(item)
            if total > limit:
                break
        known[id(v)] = total
        return total

    return weigh(value)


def _check_size(n: float, what: str) -> None:
    if n > MAX_BUILD:
        raise TooLarge(f"{what} would have {int(n)} characters or items, more than the {MAX_BUILD} "
                       "an expression may build")


def _check_result(value: Any, what: str) -> Any:
    """The value itself, if it is within the bounds; :class:`TooLarge` otherwise (the "after"
    layer of the module docstring: every filter, method and operator result passes here)."""
    if isinstance(value, int) and not isinstance(value, bool):
        if value.bit_length() > MAX_INT_BITS:
            raise TooLarge(f"{what} made an integer of {value.bit_length()} bits, more than the {MAX_INT_BITS} "
                           "an expression may build")
    elif isinstance(value, (str, bytes, list, tuple, dict)):
        if _weight(value) > MAX_BUILD:
            raise TooLarge(f"{what} made a value of more than {MAX_BUILD} characters or items, more than "
                           "an expression may build")
    return value


def _check_int(value: Any, what: str) -> None:
    if isinstance(value, int) and not isinstance(value, bool) and abs(value) > MAX_BUILD:
        raise TooLarge(f"{what}: {value} is larger than the {MAX_BUILD} an expression may use here")


def _check_format(template: Any) -> None:
    if isinstance(template, str) and _WIDE_FORMAT.search(template):
        raise TooLarge("a format width or precision of 10 million or more")


def _check_fields(template: Any, values: list, mark: str) -> None:
    """A format template fills each of its fields (``mark``: ``%`` or ``{``) with one of the
    values, and a field may name the same value again and again (``'{0}{0}{0}'``): what it can
    build is at most its length plus its fields times its largest value."""
    if isinstance(template, str) and values:
        largest = max(_weight(v, MAX_BUILD + 1) for v in values)
        _check_size(len(template) + template.count(mark) * largest, "formatting")


# calls whose whole-number arguments say how much they build (padding widths, counts of pieces)
_SIZED_CALLS = {"center", "ljust", "rjust", "zfill", "expandtabs", "do_center", "do_indent", "do_wordwrap",
                "do_batch", "do_slice", "do_format", "format", "format_map", "lipsum", "generate_lorem_ipsum",
                "to_bytes"}
#: characters an HTML escape adds to each character it replaces (markupsafe: & -> &amp;, " -> &#34;)
_ESCAPE_GROWTH = {"&": 4, "<": 3, ">": 3, '"': 4, "'": 4}


def _check_call(func: Any, args: tuple, kwargs: dict, value_first: bool = False) -> None:
    """Bounds on the arguments of a call or filter before it runs: the widths and counts of
    calls that build that much, format widths, and what ``replace``/``indent`` would make.
    ``value_first``: a filter, whose first argument is the value filtered (any size it has
    already exists)."""
    name = getattr(func, "__name__", "")
    owner = getattr(func, "__self__", None)
    given = args[1:] if value_first else args
    if name in _SIZED_CALLS:
        for value in [*given, *kwargs.values()]:
            _check_int(value, f"argument of {name.removeprefix('do_')}")
    if name in ("format", "format_map", "do_format"):
        template = owner if isinstance(owner, str) else (args[0] if args else None)
        _check_format(template)
        values = list(given if isinstance(owner, str) else args[1:]) + list(kwargs.values())
        values = [x for v in values for x in (v.values() if isinstance(v, Mapping) and name == "format_map" else [v])]
        _check_fields(template, values, "%" if name == "do_format" else "{")
    if name == "join" and isinstance(owner, (str, bytes)) and args and isinstance(args[0], (list, tuple, str)):
        _check_size(_weight(args[0]) + len(owner) * len(args[0]), "join")
    if name in ("escape", "do_forceescape") and args and isinstance(args[0], str):
        _check_size(len(args[0]) + sum(args[0].count(c) * k for c, k in _ESCAPE_GROWTH.items()), "escaping")
    if name == "translate" and isinstance(owner, str) and args and isinstance(args[0], Mapping):
        longest = max((len(v) for v in args[0].values() if isinstance(v, str)), default=1)
        _check_size(len(owner) * longest, "translate")
    if name in ("replace", "do_replace"):
        text, rest = (owner, args) if isinstance(owner, str) else (args[-3] if len(args) >= 3 else None, args[-2:])
        if isinstance(text, str) and len(rest) >= 2 and isinstance(rest[0], str) and isinstance(rest[1], str):
            count = (len(text) + 1) if rest[0] == "" else text.count(rest[0])
            _check_size(len(text) + count * len(rest[1]), "replace")
    if name == "expandtabs" and isinstance(owner, str) and args and isinstance(args[0], int):
        _check_size(len(owner) + owner.count("\t") * args[0], "expandtabs")
    if name in ("do_join", "sync_do_join", "do_sum", "sync_do_sum", "do_tojson") and args:
        items = args[0] if isinstance(args[0], (list, tuple, dict, str)) else []
        glue = next((a for a in [*args[1:], *kwargs.values()] if isinstance(a, str)), "")
        _check_size(_weight(items) + len(glue) * len(items), name.removeprefix("sync_").removeprefix("do_"))
        if "sum" in name and isinstance(items, (list, tuple)) and any(isinstance(i, (list, tuple, str)) for i in items[:1]):
            if len(items) * _weight(items) > MAX_BUILD * 100:  # each + copies all so far: quadratic
                raise TooLarge(f"summing {len(items)} lists or texts would copy them {len(items)} times over")
    if name == "do_indent" and len(args) >= 2 and isinstance(args[0], str) and isinstance(args[1], int):
        _check_size(len(args[0]) + (args[0].count("\n") + 1) * args[1], "indent")


def _bounded_filter(func: Any) -> Any:
    @functools.wraps(func)  # keeps jinja2's pass_context/pass_environment marks
    def checked(*args: Any, **kwargs: Any) -> Any:
        _check_call(func, _after_context(func, args), kwargs, value_first=True)
        return _check_result(func(*args, **kwargs), f"the filter {name}")
    name = getattr(func, "__name__", "?").removeprefix("sync_").removeprefix("do_")
    return checked


def _after_context(func: Any, args: tuple) -> tuple:
    """A filter's arguments without the context/environment jinja2 passes first to some."""
    return args[1:] if getattr(func, "jinja_pass_arg", None) is not None else args


def _bounded_concat(values: Any) -> str:
    """``a ~ b ~ c`` (jinja2's Concat node is rewritten to call this): sizes summed first."""
    _check_size(sum(_weight(v) for v in values), "the joined text")
    return "".join(v if isinstance(v, str) else str(v) for v in values)


def _bounded_format(template: str, attribute: str, method: Any) -> Any:
    """``template.format``/``format_map`` as jinja2's sandbox gives it, with its fields checked
    against its values first (the wrapper jinja2 returns no longer names the template)."""
    @functools.wraps(method)
    def bounded(*args: Any, **kwargs: Any) -> Any:
        values = list(args) + list(kwargs.values())
        if attribute == "format_map":
            values = [x for v in values for x in (v.values() if isinstance(v, Mapping) else [v])]
        _check_fields(template, values, "{")
        return method(*args, **kwargs)
    return bounded


def _whole(value: Any) -> bool:
    return isinstance(value, int) and not isinstance(value, bool)


class _Env(ImmutableSandboxedEnvironment):
    """Sandbox in which ``a.b`` on a mapping looks up the key first, so an output named
    ``items`` or ``keys`` is the output and not the dict method; whose operators, calls and
    filters check the size of what they would build before building it; and in which values
    cannot be changed in place (``l.extend(l)`` doubles a list per call: no bound would hold)."""

    intercepted_binops = frozenset({"*", "**", "+", "%", "//"})

    def getattr(self, obj: Any, attribute: str) -> Any:
        if isinstance(obj, Mapping):
            if attribute in obj:
                return obj[attribute]
            return self.undefined(obj=obj, name=attribute)
        if isinstance(obj, str) and attribute in ("format", "format_map"):
            _check_format(obj)  # jinja2 hands back its own wrapper, which no longer names the text
            return _bounded_format(obj, attribute, super().getattr(obj, attribute))
        return super().getattr(obj, attribute)

    def call_binop(self, context: Any, operator: str, left: Any, right: Any) -> Any:
        if operator == "*":
            for seq, times in ((left, right), (right, left)):
                if isinstance(seq, (str, bytes, list, tuple)) and isinstance(times, int) and times > 0:
                    _check_size(_weight(seq, MAX_BUILD // times + 1) * times, "repeating a value")
            if _whole(left) and _whole(right) and left.bit_length() + right.bit_length() > MAX_INT_BITS + 1:
                raise TooLarge(f"multiplying integers of {left.bit_length()} and {right.bit_length()} bits gives "
                               f"more than the {MAX_INT_BITS} bits an expression may build")
        elif operator == "**" and isinstance(left, int) and isinstance(right, int) and abs(left) > 1 and right > 0:
            if right * math.log2(abs(left)) > MAX_INT_BITS:
                raise TooLarge(f"{left} ** {right} has more than {MAX_INT_BITS} bits")
        elif operator == "+" and isinstance(left, Sized) and isinstance(right, Sized):
            _check_size(_weight(left) + _weight(right), "joining two values")
        elif operator == "%" and isinstance(left, str):
            _check_format(left)
            _check_fields(left, list(right.values()) if isinstance(right, Mapping)
                          else list(right) if isinstance(right, tuple) else [right], "%")
            if "*" in left:  # '%*d' takes its width from the values
                for value in (right if isinstance(right, tuple) else (right,)):
                    _check_int(value, "a width given to %*")
        return _check_result(super().call_binop(context, operator, left, right), f"the operator {operator}")

    def call(__self, __context: Any, __obj: Any, *args: Any, **kwargs: Any) -> Any:  # noqa: N805
        _check_call(__obj, args, kwargs)
        return _check_result(super().call(__context, __obj, *args, **kwargs),
                             f"{getattr(__obj, '__name__', 'a call')}()")


_ENV = _Env(undefined=StrictUndefined)
_ENV.filters = {name: _bounded_filter(f) for name, f in _ENV.filters.items()}
_ENV.filters["pipflow_concat"] = _bounded_concat
# lipsum(n=10**9) and friends build text from a number alone; expressions need none of them
_ENV.globals = {k: v for k, v in _ENV.globals.items() if k in ("range", "dict", "namespace")}


class _Concats(NodeTransformer):
    """Rewrite ``a ~ b`` into a call of the size-checking ``pipflow_concat`` filter."""

    def visit_Concat(self, node: nodes.Concat) -> nodes.Node:
        self.generic_visit(node)
        return nodes.Filter(nodes.List(node.nodes, lineno=node.lineno), "pipflow_concat", [], [], None, None,
                            lineno=node.lineno)


_BINOPS: dict[type, Any] = {nodes.Add: "+", nodes.Sub: operator.sub, nodes.Mul: "*", nodes.Div: operator.truediv,
                           nodes.FloorDiv: "//", nodes.Mod: "%", nodes.Pow: "**"}
_UNOPS: dict[type, Any] = {nodes.Neg: operator.neg, nodes.Pos: operator.pos, nodes.Not: operator.not_}
_COMPARE = {"eq": operator.eq, "ne": operator.ne, "gt": operator.gt, "gteq": operator.ge, "lt": operator.lt,
            "lteq": operator.le, "in": lambda a, b: a in b, "notin": lambda a, b: a not in b}


def _walkable(node: nodes.Node) -> bool:
    """Whether :func:`_walk` evaluates every node of this tree (the common shapes: names,
    attributes, items, arithmetic, comparisons, and/or/not, if-else, literals); anything else
    (filters, tests, calls, slices) is compiled by jinja2."""
    for n in (node, *node.find_all(nodes.Node)):
        if isinstance(n, (nodes.Const, nodes.Getattr, nodes.And, nodes.Or, nodes.Compare, nodes.Operand,
                          nodes.Dict, nodes.Pair)) or type(n) in _BINOPS or type(n) in _UNOPS:
            continue
        if isinstance(n, nodes.Name) and n.ctx == "load":
            continue
        if isinstance(n, nodes.Getitem) and not isinstance(n.arg, nodes.Slice):
            continue
        if isinstance(n, nodes.CondExpr) and n.expr2 is not None:
            continue
        if isinstance(n, (nodes.Tuple, nodes.List)) and getattr(n, "ctx", "load") == "load":
            continue
        return False
    return True


def _walk(node: nodes.Node, names: Mapping[str, Any]) -> Any:
    """Evaluate a tree that :func:`_walkable` accepts, doing exactly what the code jinja2
    generates for it does (the sandbox's ``getattr``/``getitem``, its checked operators for
    ``+ * ** % //``, Python's for the others, a StrictUndefined for a missing name) without
    generating and compiling that code: compiling costs ~1 ms per expression, and each step's
    expressions are different."""
    kind = type(node)
    if kind is nodes.Name:
        if node.name in names:
            return names[node.name]
        if node.name in _ENV.globals:
            return _ENV.globals[node.name]
        return _ENV.undefined(name=node.name)
    if kind is nodes.Getattr:
        return _ENV.getattr(_walk(node.node, names), node.attr)
    if kind is nodes.Const:
        return node.value
    if kind is nodes.Getitem:
        return _ENV.getitem(_walk(node.node, names), _walk(node.arg, names))
    op = _BINOPS.get(kind)
    if op is not None:
        left, right = _walk(node.left, names), _walk(node.right, names)
        return _ENV.call_binop(None, op, left, right) if isinstance(op, str) else op(left, right)
    op = _UNOPS.get(kind)
    if op is not None:
        return op(_walk(node.node, names))
    if kind is nodes.And:
        return _walk(node.left, names) and _walk(node.right, names)
    if kind is nodes.Or:
        return _walk(node.left, names) or _walk(node.right, names)
    if kind is nodes.Compare:  # a chain, as Python's: a < b < c is a < b and b < c, b evaluated once
        left, result = _walk(node.expr, names), True
        for operand in node.ops:
            right = _walk(operand.expr, names)
            result = _COMPARE[operand.op](left, right)
            if not result:
                return result
            left = right
        return result
    if kind is nodes.CondExpr:
        return _walk(node.expr1, names) if _walk(node.test, names) else _walk(node.expr2, names)
    if kind is nodes.List:
        return [_walk(item, names) for item in node.items]
    if kind is nodes.Tuple:
        return tuple(_walk(item, names) for item in node.items)
    if kind is nodes.Dict:
        return {_walk(pair.key, names): _walk(pair.value, names) for pair in node.items}
    raise AssertionError(f"not walkable: {kind.__name__}")  # _walkable said yes: a bug here


class _Expression:
    """A parsed expression: walked directly when its shape allows (:func:`_walkable`), otherwise
    compiled by jinja2 (what ``Environment.compile_expression`` returns, after the Concat
    rewrite)."""

    def __init__(self, source: str):
        parser = Parser(_ENV, source, state="variable")
        expr = parser.parse_expression()
        if "~" in source:  # only `~` makes a Concat node; the rewrite walks the whole tree
            expr = _Concats().visit(expr)
        if not parser.stream.eos:
            token = parser.stream.current
            raise TemplateSyntaxError(f"unexpected {token.type} {token.value!r}", token.lineno, None, None)
        # the free names it reads: only those are handed to jinja2, which copies what it is given
        # (a run's namespace holds every step's outputs: copying it per expression is quadratic)
        names = [expr, *expr.find_all(nodes.Name)]  # (find_all yields descendants only)
        self.names = tuple(dict.fromkeys(n.name for n in names if isinstance(n, nodes.Name) and n.ctx == "load"))
        self._tree: nodes.Node | None = expr if _walkable(expr) else None
        self._template = None
        if self._tree is None:
            body = [nodes.Assign(nodes.Name("result", "store"), expr, lineno=1)]
            self._template = _ENV.from_string(nodes.Template(body, lineno=1))

    def __call__(self, **namespace: Any) -> Any:
        return self.evaluate(namespace)

    def evaluate(self, namespace: Mapping[str, Any]) -> Any:
        """The value over ``namespace`` (only the names the expression reads are looked at)."""
        if self._tree is not None:
            return _walk(self._tree, namespace)
        context = self._template.new_context({k: namespace[k] for k in self.names if k in namespace})
        for _ in self._template.root_render_func(context):
            pass
        return context.vars["result"]


@dataclass(frozen=True)
class Reference:
    """A name an expression reads, with the first attribute after it (``step.output``)."""

    name: str
    attr: str | None


@functools.lru_cache(maxsize=4096)
def split_template(text: str) -> tuple[tuple[bool, str], ...]:
    """Split a string into literal parts (False, text) and expressions (True, source).

    Braces inside an expression may nest (dict literals) and may appear in quotes. Remembered
    per text: validation and the run split each argument several times."""
    return tuple(_split_template(text))


def _split_template(text: str) -> list[tuple[bool, str]]:
    parts: list[tuple[bool, str]] = []
    pos = 0
    while True:
        start = text.find(_OPEN, pos)
        if start < 0:
            if pos < len(text):
                parts.append((False, text[pos:]))
            return parts
        if start > pos:
            parts.append((False, text[pos:start]))
        end = _matching_brace(text, start + 2)
        if end < 0:
            raise ExpressionError(f"unclosed '${{' in {text!r}")
        parts.append((True, text[start + 2:end].strip()))
        pos = end + 1


def _matching_brace(text: str, i: int) -> int:
    depth, quote = 1, ""
    while i < len(text):
        ch = text[i]
        if quote:
            if ch == quote:
                quote = ""
        elif ch in "'\"":
            quote = ch
        elif ch == "{":
            depth += 1
        elif ch == "}":
            depth -= 1
            if depth == 0:
                return i
        i += 1
    return -1


def has_expression(value: Any) -> bool:
    return isinstance(value, str) and _OPEN in value


@functools.lru_cache(maxsize=4096)
def _compiled(source: str) -> _Expression:
    if len(source) > MAX_SOURCE:
        raise ExpressionError(f"an expression of {len(source)} characters is longer than the {MAX_SOURCE} allowed")
    try:
        return _Expression(source)
    except TemplateSyntaxError as err:
        raise ExpressionError(f"invalid expression ${{{source}}}: {err.message}") from None
    except (RecursionError, SyntaxError):  # jinja2's parser and Python's compiler recurse per bracket
        raise ExpressionError(f"invalid expression ${{{source[:60]}...}}: nested too deeply") from None


@functools.lru_cache(maxsize=4096)
def references(source: str) -> tuple[Reference, ...]:
    """The names an expression reads (with their first attribute), from jinja2's AST."""
    if len(source) > MAX_SOURCE:
        raise ExpressionError(f"an expression of {len(source)} characters is longer than the {MAX_SOURCE} allowed")
    try:
        tree = _ENV.parse("{{ (" + source + ") }}")
    except TemplateSyntaxError as err:
        raise ExpressionError(f"invalid expression ${{{source}}}: {err.message}") from None
    except (RecursionError, SyntaxError):  # jinja2's parser and Python's compiler recurse per bracket
        raise ExpressionError(f"invalid expression ${{{source[:60]}...}}: nested too deeply") from None
    found: list[Reference] = []
    seen_names: set[int] = set()
    for node in tree.find_all((nodes.Getattr, nodes.Getitem)):
        if isinstance(node.node, nodes.Name):
            if isinstance(node, nodes.Getattr):
                attr = node.attr
            elif isinstance(node.arg, nodes.Const) and isinstance(node.arg.value, str):
                attr = node.arg.value
            else:
                attr = None
            found.append(Reference(node.node.name, attr))
            seen_names.add(id(node.node))
    for node in tree.find_all(nodes.Name):
        if id(node) not in seen_names and node.ctx == "load":
            found.append(Reference(node.name, None))
    return tuple(dict.fromkeys(found))


def template_references(value: Any) -> list[Reference]:
    """Every reference in a value: strings, and strings nested in lists and dicts, each distinct
    reference once. Linear in the size of the value as written: a list or dict that YAML aliases
    share is scanned once, strings are scanned once each, and there is no recursion."""
    found: dict[Reference, None] = {}
    seen_containers: set[int] = set()
    seen_strings: set[str] = set()
    stack = [value]
    while stack:
        item = stack.pop()
        if isinstance(item, str):
            if _OPEN in item and item not in seen_strings:
                seen_strings.add(item)
                for is_expr, part in split_template(item):
                    if is_expr:
                        found.update(dict.fromkeys(references(part)))
        elif isinstance(item, (dict, list)):
            if id(item) in seen_containers:
                continue
            seen_containers.add(id(item))
            stack.extend(reversed(list(item.values() if isinstance(item, dict) else item)))
    return list(found)


_PLAIN = re.compile(r"^[A-Za-z_][A-Za-z0-9_]*(?:\.[A-Za-z_][A-Za-z0-9_]*)*$")
_MISSING = object()
_CONSTANTS = {"true", "false", "none", "True", "False", "None"}  # jinja2 literals, not names


def _plain_lookup(source: str, namespace: Mapping[str, Any]) -> Any:
    """``a.b.c`` through mappings only (the common case), without compiling the expression;
    ``_MISSING`` when jinja2 must decide (a missing key, a non-mapping), so errors stay the same."""
    if not _PLAIN.match(source):
        return _MISSING
    name, *attrs = source.split(".")
    if name in _CONSTANTS:
        return _MISSING
    value = namespace.get(name, _MISSING)
    for attr in attrs:
        if value is _MISSING or not isinstance(value, Mapping):
            return _MISSING
        value = value.get(attr, _MISSING)
    return value


def evaluate_expression(source: str, namespace: Mapping[str, Any]) -> Any:
    """Evaluate one expression; an undefined result names what was missing."""
    value = _plain_lookup(source, namespace)
    if value is not _MISSING:
        return value
    compiled = _compiled(source)
    try:
        result = compiled.evaluate(namespace)
    except TemplateError as err:
        raise ExpressionError(f"${{{source}}}: {err.message or err}") from None
    except Exception as err:  # a filter or operator failed on the values given
        raise ExpressionError(f"${{{source}}}: {type(err).__name__}: {err}") from None
    if isinstance(result, Undefined):
        try:
            str(result)
        except TemplateError as err:
            raise ExpressionError(f"${{{source}}}: {err.message}") from None
        raise ExpressionError(f"${{{source}}} is undefined")
    return result


def resolve(value: Any, namespace: Mapping[str, Any]) -> Any:
    """Resolve every ``${...}`` in a value (recursively through lists and dicts)."""
    if isinstance(value, str):
        if _OPEN not in value:
            return value
        whole = _WHOLE.match(value)
        if whole:
            parts = split_template(value)
            if len(parts) == 1 and parts[0][0]:
                return evaluate_expression(parts[0][1], namespace)
        pieces = []
        size = 0
        for is_expr, part in split_template(value):
            if not is_expr:
                pieces.append(part)
            else:
                result = evaluate_expression(part, namespace)
                pieces.append(result if isinstance(result, str) else json.dumps(result, default=str))
            size += len(pieces[-1])
            if size > MAX_BUILD:  # each piece is within the bounds; many of them together need not be
                raise ExpressionError(f"the text around ${{{part}}} would have more than {MAX_BUILD} characters, "
                                      "more than an expression may build")
        return "".join(pieces)
    if isinstance(value, dict):
        return {k: resolve(v, namespace) for k, v in value.items()}
    if isinstance(value, list):
        return [resolve(v, namespace) for v in value]
    return value


def truthy(value: Any, namespace: Mapping[str, Any]) -> bool:
    """A condition (``when:``/``until:``): a bool, or a string with ``${...}``."""
    result = resolve(value, namespace)
    if isinstance(result, str):
        return result.strip().lower() not in ("", "false", "0", "no", "none", "null")
    return bool(result)

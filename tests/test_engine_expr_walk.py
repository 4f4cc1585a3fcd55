"""Expressions of the common shapes are evaluated by walking jinja2's tree instead of compiling
it (engine/expr.py ``_walk``); the value, or the error, must be what jinja2's compiled code gives."""
from __future__ import annotations

import pytest
from jinja2 import nodes

from pipflow.engine import expr as E

NS = {"a": {"value": [1, 2], "n": 3, "s": "xy", "d": {"k": 0}, "f": 1.5, "t": True, "z": None},
      "inputs": {"n": 3, "name": "w"}, "env": {"HOME": "/h"}, "lst": [3, 4, 5]}

SOURCES = [
    "a.n + 1", "a.n - 1", "a.n * 2", "a.n / 2", "a.n // 2", "a.n % 2", "a.n ** 2", "-a.n", "+a.f", "not a.t",
    "a.s * 3", "a.s + 'z'", "a.value + lst", "lst[0]", "lst[-1]", "a['d']['k']", "a.d.k == 0", "1 < a.n < 5",
    "1 < a.n > 5", "a.n in lst", "a.n not in lst", "a.t and a.n", "a.z or 'dflt'", "a.n if a.t else 0",
    "[a.n, a.s, (1, 2)]", "{'x': a.n, a.s: 1}", "(a.n,)", "a.n != 3 or a.s == 'xy'", "a.value[1] >= 2",
    "nothere", "nothere.x", "a.nothere", "a.nothere.x", "a.n + nothere", "lst[10]", "a.n / 0", "a.s - 1",
    "a.s * 10000000", "2 ** 10000000", "a.items", "a.z.x", "lst.value", "not nothere", "a.t and nothere",
    "range", "'%s' % a.n", "a.n > 'x'", "true", "none", "a.d['k'] + 1.5", "1 if nothere else 2",
]


def _compiled_only(source: str):
    """The same expression through jinja2's code generation (the walk turned off)."""
    parsed = E._Expression(source)
    body = [nodes.Assign(nodes.Name("result", "store"), parsed._tree or nodes.Const(None), lineno=1)]
    template = E._ENV.from_string(nodes.Template(body, lineno=1))
    ctx = template.new_context({k: NS[k] for k in parsed.names if k in NS})
    for _ in template.root_render_func(ctx):
        pass
    return ctx.vars["result"]


def _outcome(fn, source):
    try:
        value = fn(source)
    except Exception as err:  # the kind and words of the error must agree too
        return ("error", type(err).__name__, str(err))
    if isinstance(value, E.Undefined):
        return ("undefined", value._undefined_name)
    return ("value", type(value).__name__, value)


@pytest.mark.parametrize("source", SOURCES)
def test_walking_agrees_with_jinja2s_compiled_code(source):
    assert E._Expression(source)._tree is not None, "this shape should be walked"
    assert _outcome(lambda s: E._Expression(s).evaluate(NS), source) == _outcome(_compiled_only, source)


@pytest.mark.parametrize("source", ["a.s | upper", "a.n is odd", "range(3)", "lst[0:2]", "a.s ~ 'z'", "lst.index(3)",
                                    "1 if a.t"])
def test_other_shapes_are_compiled(source):
    assert E._Expression(source)._tree is None
    E.evaluate_expression(source, NS)  # and still evaluate

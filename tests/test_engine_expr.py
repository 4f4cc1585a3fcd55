"""`${...}` evaluation: plain references take a fast path that must agree with jinja2."""
from __future__ import annotations

import pytest

from pipflow.engine.expr import ExpressionError, _compiled, evaluate_expression, resolve

NS = {"a": {"value": [1, 2], "items": "an output named items", "d": {"x": 0}}, "inputs": {"n": 3},
      "env": {"HOME": "/h"}, "True": {"value": "a step named True"}, "lst": [1, 2]}


@pytest.mark.parametrize("source", ["a.value", "a.items", "a.d.x", "inputs.n", "env.HOME", "a", "True"])
def test_plain_references_agree_with_jinja(source):
    assert evaluate_expression(source, NS) == _compiled(source)(**NS)


def test_whole_string_reference_keeps_its_type_and_text_interpolates():
    assert resolve("${a.value}", NS) == [1, 2]
    assert resolve("n=${inputs.n} v=${a.value}", NS) == "n=3 v=[1, 2]"


@pytest.mark.parametrize("source", ["a.nothere", "nothere.value", "lst.value", "a.d.x.y"])
def test_missing_references_raise(source):
    with pytest.raises(ExpressionError):
        evaluate_expression(source, NS)


def test_env_default_filter():
    assert resolve("${env.NOPE | default('fallback')}", NS) == "fallback"
    assert resolve("${env.HOME | default('fallback')}", NS) == "/h"

"""The fast workflow-schema validator (engine/validate.py: one shape per step node, ``$ref``
inlined) must accept exactly what the schema itself accepts: it decides whether the exact,
slower error report is needed at all."""
from __future__ import annotations

import jsonschema
from hypothesis import given, settings
from hypothesis import strategies as st

from pipflow.engine.validate import fast_validator, workflow_schema

SLOW = jsonschema.Draft202012Validator(workflow_schema())
FAST = fast_validator()

# every key any node shape knows, and a few it does not, with values of the kinds they take
# and of wrong kinds
KEYS = ["id", "uses", "loop", "with", "when", "timeout", "retry", "cache", "doc", "max", "until", "on_max", "extra"]
SCALARS = st.one_of(st.sampled_from(["a", "s1", "inputs", "fail", "continue", "${x.y}", "", "1bad"]),
                    st.integers(-1, 3), st.booleans(), st.none(), st.floats(-1, 2, allow_nan=False))
LOOP_BODY = st.fixed_dictionaries({}, optional={
    "max": st.one_of(st.integers(0, 3), st.just("${inputs.n}")), "until": SCALARS, "on_max": SCALARS,
    "steps": st.lists(st.fixed_dictionaries({"id": st.just("inner"), "uses": st.just("core.value")},
                                            optional={"with": st.just({}), "loop": st.just({})}), max_size=2),
    "extra": SCALARS})
VALUES = {"retry": st.one_of(st.just({"attempts": 2}), st.just({"attempts": 0}), st.just({"x": 1}), SCALARS),
          "with": st.one_of(st.just({"value": 1}), SCALARS), "loop": st.one_of(LOOP_BODY, SCALARS)}
NODE = st.builds(dict, st.lists(st.sampled_from(KEYS), unique=True).flatmap(
    lambda keys: st.fixed_dictionaries({k: VALUES.get(k, SCALARS) for k in keys})))


def test_the_fast_validator_exists_for_the_shipped_schema():
    assert FAST is not None


@settings(max_examples=400, deadline=None)
@given(st.lists(NODE, min_size=1, max_size=3))
def test_fast_and_exact_validators_agree_on_generated_nodes(steps):
    doc = {"pipflow": 1, "name": "w", "steps": steps}
    assert FAST.is_valid(doc) == SLOW.is_valid(doc), steps


def test_they_agree_on_each_shape_and_on_mixed_shapes():
    ok = [{"id": "a", "uses": "core.value"},
          {"id": "l", "loop": {"max": 2, "until": True, "steps": [{"id": "b", "uses": "core.value"}]}},
          {"id": "a", "with": {"value": 2}}]
    bad = [{"id": "a", "uses": "core.value", "loop": {}}, {"id": "a", "uses": "x", "max": 2},
           {"id": "l", "loop": {"max": 2, "until": True, "steps": []}}, {"id": "inputs", "uses": "x"}, {}]
    for node in ok:
        doc = {"pipflow": 1, "name": "w", "steps": [node]}
        assert FAST.is_valid(doc) and SLOW.is_valid(doc), node
    for node in bad:
        doc = {"pipflow": 1, "name": "w", "steps": [node]}
        assert not FAST.is_valid(doc) and not SLOW.is_valid(doc), node

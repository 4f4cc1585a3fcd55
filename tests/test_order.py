"""Orders and the resolver: the schema, the arithmetic per statement (and the words it shows),
the refusals that say why, and robot selectors resolved to the world's names."""
from __future__ import annotations

import json

import jsonschema
import pytest

from pipflow.errors import Refusal, TranslationError
from pipflow.warehouse.language.order import order_schema, validate_order
from pipflow.warehouse.language.resolver import resolve, split_evenly
from pipflow.resources import data_file

WORLD = {
    "shelves": {"a": {"capacity": 20}, "b": {"capacity": 20}, "c": {"capacity": 12}},
    "products": {"x": {}, "y": {}, "z": {}},
    "stock": {"a": {"x": 4, "y": 3}, "b": {"x": 6, "z": 2}, "c": {}},
    "robots": {"big": {"kind": "forklift", "tags": ["night"], "skills": {"carry": 3}},
               "mid": {"kind": "forklift", "skills": {"carry": 2}},
               "small": {"kind": "amr", "tags": ["night"], "skills": {"carry": 1}}},
}
A, B, C = {"names": ["a"]}, {"names": ["b"]}, {"names": ["c"]}
X, Y, Z = {"names": ["x"]}, {"names": ["y"]}, {"names": ["z"]}


def order(*statements: dict, rules: list[dict] | None = None) -> dict:
    out = {"statements": [{"words": "w", **s} for s in statements],
           "rules": [{"words": "r", **r} for r in rules or []]}
    validate_order(out)
    return out


def goal(*statements: dict) -> dict:
    return resolve(order(*statements), WORLD).goal


def test_the_schema_is_a_valid_draft_2020_12_schema() -> None:
    schema = json.loads(data_file("schemas/order.schema.json").read_text())
    jsonschema.Draft202012Validator.check_schema(schema)
    assert schema == order_schema()


@pytest.mark.parametrize("bad,where", [
    ({"statements": [{"op": "set", "words": "w", "places": A, "items": X, "amount": {"count": -1}}], "rules": []},
     "statements/0/amount"),
    ({"statements": [{"op": "teleport", "words": "w"}], "rules": []}, "statements/0/op"),
    ({"statements": [{"op": "set", "places": A, "items": X, "amount": {"count": 1}}], "rules": []}, "statements/0"),
    ({"statements": [], "rules": [{"mode": "maybe", "robots": {"names": ["big"]}, "words": "w"}]}, "rules/0/mode"),
    ({"statements": [], "rules": [{"mode": "only", "robots": {"names": []}, "words": "w"}]}, "rules/0/robots"),
    ({"statements": [{"op": "set", "words": "w", "places": {"all": False}, "items": X, "amount": {"count": 1}}],
      "rules": []}, "statements/0/places"),
])
def test_invalid_orders_are_refused_with_where(bad: dict, where: str) -> None:
    with pytest.raises(TranslationError, match=f"not valid at {where}"):
        validate_order(bad)


@pytest.mark.parametrize("statement,expected", [
    ({"op": "set", "places": A, "items": X, "amount": {"count": 7}}, {"a": {"x": 7}}),
    # all of an item on one place is none anywhere else: the goal lists those places at 0
    ({"op": "set", "places": C, "items": X, "amount": {"all": True}}, {"c": {"x": 10}, "a": {"x": 0}, "b": {"x": 0}}),
    ({"op": "set", "places": C, "items": {"all": True}, "amount": {"count": 1}}, {"c": {"x": 1, "y": 1, "z": 1}}),
    ({"op": "set", "places": C, "items": Y, "amount": {"as_many_as": "a"}}, {"c": {"y": 3}}),
    ({"op": "change", "places": A, "items": X, "amount": {"more": 5}}, {"a": {"x": 9}}),
    ({"op": "change", "places": A, "items": X, "amount": {"fewer": 4}}, {"a": {"x": 0}}),
    ({"op": "change", "places": A, "items": X, "amount": {"times": 2}}, {"a": {"x": 8}}),
    ({"op": "change", "places": B, "items": X, "amount": {"fraction": [2, 3]}}, {"b": {"x": 4}}),
    ({"op": "transfer", "items": X, "amount": {"count": 2}, "from": B, "to": C}, {"b": {"x": 4}, "c": {"x": 2}}),
    ({"op": "transfer", "items": X, "amount": {"all": True}, "from": {"all": True, "except": ["a"]}, "to": C},
     {"b": {"x": 0}, "c": {"x": 6}, "a": {"x": 4}}),
    ({"op": "transfer", "items": {"all": True, "except": ["z"]}, "amount": {"all_held": True}, "from": B, "to": A},
     {"b": {"x": 0, "z": 2}, "a": {"x": 10}}),
    ({"op": "swap", "places": {"names": ["a", "b"]}, "items": {"all": True}},
     {"a": {"x": 6, "y": 0, "z": 2}, "b": {"x": 4, "y": 3, "z": 0}}),
    # empty: every product of the world at 0, z too though a holds none (nothing may be parked there)
    ({"op": "empty", "places": A, "items": {"all": True}}, {"a": {"x": 0, "y": 0, "z": 0}}),
    ({"op": "fill", "places": A, "items": Z, "only": False}, {"a": {"z": 13}}),  # capacity 20 - 7 others
    ({"op": "keep", "places": A, "items": {"all": True}, "inflow_only": False}, {"a": {"x": 4, "y": 3, "z": 0}}),
    ({"op": "distribute", "places": {"names": ["a", "c"]}, "items": Y, "amount": {"count": 3}},
     {"a": {"y": 2}, "c": {"y": 1}}),
    ({"op": "bound", "places": C, "items": X, "amount": {"at_least": 2, "at_most": 5}},
     {"c": {"x": {"at_least": 2, "at_most": 5}}}),
    ({"op": "bound", "places": A, "items": X, "amount": {"at_least_more": 2}}, {"a": {"x": {"at_least": 6}}}),
])
def test_resolver_arithmetic(statement: dict, expected: dict) -> None:
    if statement["op"] == "fill":  # the world has only 2 z: reading is checked without supply
        assert resolve(order(statement), WORLD, check=False).goal == expected
        with pytest.raises(Refusal, match="world has only 2"):
            goal(statement)
        return
    assert goal(statement) == expected


def test_the_explanation_states_the_arithmetic_with_the_words() -> None:
    r = resolve(order({"op": "change", "places": A, "items": X, "amount": {"more": 5}, "words": "5 x more"},
                      rules=[{"mode": "never", "robots": {"kind": "forklift"}, "product": "x",
                              "words": "no forklift may carry x"}]), WORLD)
    assert r.explanation == ["a x: 4 now, +5 -> 9, from '5 x more'",
                             "robots big, mid: never for product x, from 'no forklift may carry x'"]
    assert r.constraints == [{"never": ["big", "mid"], "product": "x"}]


def test_statements_apply_in_order_and_the_rest_is_what_is_left() -> None:
    assert goal({"op": "transfer", "items": X, "amount": {"count": 2}, "from": B, "to": A},
                {"op": "transfer", "items": X, "amount": {"rest": True}, "from": B, "to": C}) == {
        "b": {"x": 0}, "a": {"x": 6}, "c": {"x": 4}}
    # "keep 1 x on b and send the rest to c": b is fixed first, the rest is what it had above that
    assert goal({"op": "set", "places": B, "items": X, "amount": {"count": 1}},
                {"op": "transfer", "items": X, "amount": {"rest": True}, "from": B, "to": C}) == {
        "b": {"x": 1}, "c": {"x": 5}}


@pytest.mark.parametrize("statements,error,match", [
    ([{"op": "change", "places": A, "items": Y, "amount": {"fewer": 4}}], Refusal, "fewer than 0"),
    ([{"op": "transfer", "items": X, "amount": {"count": 7}, "from": B, "to": C}], Refusal, "holds 6"),
    ([{"op": "set", "places": C, "items": Y, "amount": {"count": 4}}], Refusal, "world has only 3"),
    ([{"op": "set", "places": C, "items": X, "amount": {"count": 10}},
      {"op": "set", "places": C, "items": Z, "amount": {"count": 2}},
      {"op": "set", "places": C, "items": Y, "amount": {"count": 1}}], Refusal, "capacity 12"),
    ([{"op": "set", "places": A, "items": X, "amount": {"count": 1}},
      {"op": "set", "places": A, "items": X, "amount": {"count": 2}}], TranslationError, "twice"),
    ([{"op": "set", "places": A, "items": X, "amount": {"count": 1}},
      {"op": "bound", "places": A, "items": X, "amount": {"at_least": 3}}], Refusal, "at least 3"),
    ([{"op": "change", "places": A, "items": Y, "amount": {"fraction": [1, 2]}}], TranslationError, "1/2 of 3"),
    ([{"op": "transfer", "items": X, "amount": {"all": True, "expect": 5}, "from": B, "to": C}],
     TranslationError, "says 5 x but b holds 6"),
    ([{"op": "set", "places": {"names": ["nowhere"]}, "items": X, "amount": {"count": 1}}],
     TranslationError, "no place nowhere"),
])
def test_refusals_say_why(statements: list[dict], error: type, match: str) -> None:
    with pytest.raises(error, match=match):
        resolve(order(*statements), WORLD)


@pytest.mark.parametrize("robots,names", [
    ({"names": ["small", "big"]}, ["big", "small"]),
    ({"kind": "forklift"}, ["big", "mid"]),
    ({"tag": "night"}, ["big", "small"]),
    ({"skill": "carry", "at_least": 2}, ["big", "mid"]),
    ({"skill": "carry", "at_most": 1}, ["small"]),
    ({"extreme": "max", "skill": "carry"}, ["big"]),
    ({"extreme": "min", "skill": "carry"}, ["small"]),
])
def test_robot_selectors_resolve_to_names(robots: dict, names: list[str]) -> None:
    r = resolve(order(rules=[{"mode": "only", "robots": robots}]), WORLD)
    assert r.constraints == [{"only": names}]


def test_a_selector_that_matches_no_robot_is_refused() -> None:
    with pytest.raises(Refusal, match="no robot of kind tugger"):
        resolve(order(rules=[{"mode": "never", "robots": {"kind": "tugger"}}]), WORLD)


def test_split_evenly_gives_the_remainder_to_the_first_named() -> None:
    assert split_evenly(11, ["p", "q", "r"]) == {"p": 4, "q": 4, "r": 3}

"""Grounded decoding: the model answers with an ORDER whose every name is one of the world's.

Instead of free PDDL, a grounded call asks for an order (``schemas/order.schema.json``), the same
typed meaning the offline parser produces::

    {"statements": [{"op": "set", "places": {"names": ["shelf4"]}, "items": {"names": ["product3"]},
                     "amount": {"count": 14}, "words": "14 product3 on shelf4"}],
     "rules": [{"mode": "never", "robots": {"kind": "forklift"}, "product": "any", "from": "any",
                "to": "any", "words": "no forklift"}]}

and constrains decoding to a subset of that language in which places, items, robots, kinds,
tags and skills are enums of the world. Providers with JSON-schema structured output get
``response_format`` (:func:`response_format`, strict-mode compatible: every key required, so a
rule's scope the command does not state is ``"any"``); llama.cpp servers get the same language
as a GBNF grammar (:func:`gbnf`) whose lists, numbers, whitespace and ``words`` are bounded, so a
small model cannot run on until max_tokens. The resolver then computes goal, bounds, rules and
the explanation, and the problem writer writes the PDDL (:mod:`pipflow.warehouse.language.llm_orders`), so
a name such as ``prodcut3`` cannot reach the planner: the decoder never emits it.
"""
from __future__ import annotations

import json
from typing import Any

ANY = "any"
MAX_RULES = 8  # robot-use rules in one command; more is a model repeating itself
MAX_STATEMENTS = 16  # statements in one command; the grammar's lists must be bounded
WORDS_CHARS = 80  # the longest "words" the grammar lets a model write (a clause of the command)
PLACE_OPS = ["swap", "empty", "fill", "keep"]
#: the amount forms each op may take, each a tuple of keys (the order schema knows more; these
#: are the ones a clause maps to directly, and only those the resolver computes for that op, so
#: that a small model cannot write "set" with "more")
AMOUNT_FORMS: dict[str, list[tuple[str, ...]]] = {
    "set": [("count",)],
    "change": [("more",), ("fewer",)],
    "bound": [("at_least",), ("at_most",), ("at_least", "at_most")],
    "transfer": [("count",), ("all",), ("rest",)],
}
QUANTITY_OPS = ["set", "change", "bound"]
FLAGS = {"all", "rest"}  # amount keys whose value is ``true``, not a number


def vocabulary(world: dict) -> dict[str, list[str]]:
    """The world's names a grounded order may use, by role (empty roles are left out of the
    schema and grammar: an enum must not be empty)."""
    robots = world.get("robots") or {}
    kinds, tags, skills = set(), set(), set()
    for r in robots.values():
        r = r if isinstance(r, dict) else {}
        if r.get("kind"):
            kinds.add(str(r["kind"]))
        tags.update(str(t) for t in r.get("tags") or [])
        skills.update(str(s) for s in (r.get("skills") or {}))
    return {"places": sorted(str(s) for s in world.get("shelves") or {}),
            "items": sorted(str(p) for p in world.get("products") or {}),
            "robots": sorted(str(r) for r in robots), "kinds": sorted(kinds), "tags": sorted(tags),
            "skills": sorted(skills)}


def largest_count(world: dict) -> int:
    """The largest number an amount may state: a shelf's capacity or the world's stock of all items."""
    caps = [int((s or {}).get("capacity", 0) or 0) for s in (world.get("shelves") or {}).values()]
    total = sum(int(n or 0) for row in (world.get("stock") or {}).values() for n in (row or {}).values())
    return max(caps + [total, 1])


def answer_size(world: dict, reading: dict | None) -> tuple[int, int]:
    """``(goal items, rules)`` a grounded answer is expected to hold: the offline reading's goal
    counts and rules when the parser read the command, else half of every shelf x product (a
    command rarely states more) and two rules. The call's token budget comes from it."""
    if reading is not None:
        return sum(len(v) for v in reading.get("goal", {}).values()), len(reading.get("constraints") or [])
    return len(world.get("shelves") or {}) * len(world.get("products") or {}) // 2, 2


# ---------------------------------------------------------------- JSON schema


def _obj(props: dict[str, Any]) -> dict[str, Any]:
    return {"type": "object", "properties": props, "required": list(props), "additionalProperties": False}


def _enum(names: list[str]) -> dict[str, Any]:
    return {"type": "string", "enum": names}


def _selector(names: list[str]) -> dict[str, Any]:
    return {"anyOf": [
        _obj({"names": {"type": "array", "items": _enum(names), "minItems": 1, "maxItems": len(names)}}),
        _obj({"all": {"type": "boolean", "enum": [True]},
              "except": {"type": "array", "items": _enum(names), "maxItems": max(len(names) - 1, 0)}}),
    ]}


def json_schema(world: dict) -> dict[str, Any]:
    """The JSON Schema of a grounded order for ``world`` (strict-mode compatible): a subset of
    ``schemas/order.schema.json`` with the world's names as enums."""
    v = vocabulary(world)
    count = {"type": "integer", "minimum": 0, "maximum": largest_count(world)}

    def amount(op: str) -> dict[str, Any]:
        return {"anyOf": [_obj({k: ({"type": "boolean", "enum": [True]} if k in FLAGS else count) for k in form})
                          for form in AMOUNT_FORMS[op]]}

    places, items, words = _selector(v["places"]), _selector(v["items"]), {"type": "string"}
    statement = {"anyOf": [
        *(_obj({"op": _enum([op]), "places": places, "items": items, "amount": amount(op), "words": words})
          for op in QUANTITY_OPS),
        _obj({"op": _enum(["transfer"]), "items": items, "amount": amount("transfer"), "from": places,
              "to": places, "words": words}),
        _obj({"op": _enum(PLACE_OPS), "places": places, "words": words}),
    ]}
    robots = [_obj({"names": {"type": "array", "items": _enum(v["robots"]), "minItems": 1,
                              "maxItems": len(v["robots"])}})]
    if v["kinds"]:
        robots.append(_obj({"kind": _enum(v["kinds"])}))
    if v["tags"]:
        robots.append(_obj({"tag": _enum(v["tags"])}))
    if v["skills"]:
        robots += [_obj({"skill": _enum(v["skills"]), "at_least": {"type": "number"}}),
                   _obj({"skill": _enum(v["skills"]), "at_most": {"type": "number"}}),
                   _obj({"extreme": _enum(["max", "min"]), "skill": _enum(v["skills"])})]
    rule = _obj({"mode": _enum(["only", "never"]), "robots": {"anyOf": robots},
                 "product": _enum(v["items"] + [ANY]), "from": _enum(v["places"] + [ANY]),
                 "to": _enum(v["places"] + [ANY]), "words": words})
    return _obj({"statements": {"type": "array", "items": statement, "maxItems": MAX_STATEMENTS},
                 "rules": {"type": "array", "items": rule, "maxItems": MAX_RULES}})


def response_format(world: dict) -> dict[str, Any]:
    """OpenAI-style ``response_format`` for providers with JSON-schema structured output."""
    return {"type": "json_schema",
            "json_schema": {"name": "warehouse_order", "strict": True, "schema": json_schema(world)}}


# ---------------------------------------------------------------- GBNF


def _lit(text: str) -> str:
    """A GBNF literal that matches the JSON string ``"text"``."""
    body = json.dumps(text)[1:-1].replace("\\", "\\\\").replace('"', '\\"')
    return f'"\\"{body}\\""'


def _key(name: str) -> str:
    """A GBNF sequence for ``"name":`` followed by optional whitespace."""
    return f'"\\"{name}\\":" ws'


def _alts(names: list[str]) -> str:
    return "(" + " | ".join(_lit(n) for n in names) + ")"


def _list(elem: str, most: int, least: int = 0) -> str:
    """A JSON array of ``least``..``most`` ``elem`` (most >= 1)."""
    one = f'"[" ws {elem}' + (f' ("," ws {elem}){{0,{most - 1}}}' if most > 1 else "") + ' ws "]"'
    return one if least >= 1 else f'("[" ws "]" | {one})'


def _object(*fields: str) -> str:
    """A JSON object of the given ``key-sequence value`` fields in this order."""
    return '"{" ws ' + ' "," ws '.join(fields) + ' ws "}"'


def gbnf(world: dict) -> str:
    """The same language as :func:`json_schema`, as a llama.cpp GBNF grammar.

    Keys come in a fixed order, and whitespace, list lengths, numbers and ``words`` are bounded,
    so every path through the grammar is a valid order of bounded length."""
    v = vocabulary(world)
    digits = len(str(largest_count(world)))
    robot_alts = [_object(f"{_key('names')} {_list('robot', len(v['robots']), 1)}")]
    lines = [
        "root ::= " + _object(f"{_key('statements')} {_list('stmt', MAX_STATEMENTS)}",
                              f"{_key('rules')} {_list('rule', MAX_RULES)}"),
        "stmt ::= " + " | ".join(QUANTITY_OPS) + " | transfer | placeop",
        *(f"{op} ::= " + _object(f"{_key('op')} {_lit(op)}", f"{_key('places')} places", f"{_key('items')} items",
                                 f"{_key('amount')} amount-{op}", f"{_key('words')} words") for op in QUANTITY_OPS),
        "transfer ::= " + _object(f"{_key('op')} {_lit('transfer')}", f"{_key('items')} items",
                                  f"{_key('amount')} amount-transfer", f"{_key('from')} places",
                                  f"{_key('to')} places", f"{_key('words')} words"),
        "placeop ::= " + _object(f"{_key('op')} {_alts(PLACE_OPS)}", f"{_key('places')} places",
                                 f"{_key('words')} words"),
        *(f"amount-{op} ::= " + " | ".join(_object(*(_key(k) + (' "true"' if k in FLAGS else " num") for k in form))
                                           for form in forms) for op, forms in AMOUNT_FORMS.items()),
        "rule ::= " + _object(f"{_key('mode')} {_alts(['only', 'never'])}", f"{_key('robots')} robots",
                              f"{_key('product')} (item | {_lit(ANY)})", f"{_key('from')} (place | {_lit(ANY)})",
                              f"{_key('to')} (place | {_lit(ANY)})", f"{_key('words')} words"),
    ]
    for role, one in (("places", "place"), ("items", "item")):
        names = v[role]
        lines.append(f"{role} ::= " + _object(f"{_key('names')} {_list(one, len(names), 1)}") + " | "
                     + _object(f"{_key('all')} \"true\"", f"{_key('except')} "
                               + (_list(one, len(names) - 1) if len(names) > 1 else '"[" ws "]"')))
        lines.append(f"{one} ::= {_alts(names)}")
    if v["kinds"]:
        robot_alts.append(_object(f"{_key('kind')} kind"))
        lines.append(f"kind ::= {_alts(v['kinds'])}")
    if v["tags"]:
        robot_alts.append(_object(f"{_key('tag')} tag"))
        lines.append(f"tag ::= {_alts(v['tags'])}")
    if v["skills"]:
        robot_alts += [_object(f"{_key('skill')} skill", f"{_key('at_least')} num"),
                       _object(f"{_key('skill')} skill", f"{_key('at_most')} num"),
                       _object(f"{_key('extreme')} ({_lit('max')} | {_lit('min')})", f"{_key('skill')} skill")]
        lines.append(f"skill ::= {_alts(v['skills'])}")
    lines += [
        "robots ::= " + " | ".join(robot_alts),
        f"robot ::= {_alts(v['robots'])}",
        'num ::= "0" | [1-9]' + (f" [0-9]{{0,{digits - 1}}}" if digits > 1 else ""),
        f'words ::= "\\"" [^"\\\\\\x7F\\x00-\\x1F]{{0,{WORDS_CHARS}}} "\\""',
        "ws ::= [ \\t\\n]{0,8}",
    ]
    return "\n".join(lines) + "\n"

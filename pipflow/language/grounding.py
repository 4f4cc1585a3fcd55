"""Grounded decoding: the model may only answer with the world's names and valid counts.

Instead of free PDDL, a grounded call asks for a small JSON answer::

    {"goal": [{"shelf": "shelf4", "product": "product3", "units": 14}],
     "constraints": [{"rule": "never", "robots": ["robot0"], "product": "product1",
                      "from": "any", "to": "any"}]}

and constrains decoding to it, with every name an enum of the world's shelves, products and
robots and every count in 0..capacity of its shelf. Providers with JSON-schema structured output
get ``response_format`` (:func:`response_format`); llama.cpp servers get the same language as a
GBNF grammar (:func:`gbnf`). The PDDL problem is then written by the problem writer from the
answer, so a name such as ``prodcut3`` cannot reach the planner: the decoder never emits it.
"""
from __future__ import annotations

import json
from typing import Any

from pipflow.language.parsing import ParseIssue, validate_constraints

ANY = "any"
MAX_RULES = 8  # robot-use rules in one command; more is a model repeating itself


def _capacity_groups(world: dict) -> dict[int, list[str]]:
    """Shelves by capacity: each group shares one count range in the schema and the grammar."""
    groups: dict[int, list[str]] = {}
    for name, shelf in sorted(world["shelves"].items()):
        groups.setdefault(int(shelf["capacity"]), []).append(name)
    return dict(sorted(groups.items()))


def json_schema(world: dict) -> dict[str, Any]:
    """The JSON Schema of a grounded answer for ``world`` (strict-mode compatible)."""
    shelves, products = sorted(world["shelves"]), sorted(world["products"])
    robots = sorted(world["robots"])
    items = [{
        "type": "object",
        "properties": {"shelf": {"type": "string", "enum": names},
                       "product": {"type": "string", "enum": products},
                       "units": {"type": "integer", "enum": list(range(cap + 1))}},
        "required": ["shelf", "product", "units"], "additionalProperties": False,
    } for cap, names in _capacity_groups(world).items()]
    rule = {
        "type": "object",
        "properties": {"rule": {"type": "string", "enum": ["only", "never"]},
                       "robots": {"type": "array", "items": {"type": "string", "enum": robots},
                                  "maxItems": len(robots)},
                       "product": {"type": "string", "enum": products + [ANY]},
                       "from": {"type": "string", "enum": shelves + [ANY]},
                       "to": {"type": "string", "enum": shelves + [ANY]}},
        "required": ["rule", "robots", "product", "from", "to"], "additionalProperties": False,
    }
    return {
        "type": "object",
        "properties": {"goal": {"type": "array", "items": items[0] if len(items) == 1 else {"anyOf": items},
                                "maxItems": len(shelves) * len(products)},
                       "constraints": {"type": "array", "items": rule, "maxItems": MAX_RULES}},
        "required": ["goal", "constraints"], "additionalProperties": False,
    }


def response_format(world: dict) -> dict[str, Any]:
    """OpenAI-style ``response_format`` for providers with JSON-schema structured output."""
    return {"type": "json_schema",
            "json_schema": {"name": "warehouse_goal", "strict": True, "schema": json_schema(world)}}


def _lit(text: str) -> str:
    """A GBNF literal that matches the JSON string ``"text"``."""
    body = json.dumps(text)[1:-1].replace("\\", "\\\\").replace('"', '\\"')
    return f'"\\"{body}\\""'


def _alts(names: list[str]) -> str:
    return " | ".join(_lit(n) for n in names)


def gbnf(world: dict) -> str:
    """The same language as :func:`json_schema`, as a llama.cpp GBNF grammar.

    Keys come in a fixed order, and whitespace and list lengths are bounded, so a small model
    cannot wander off into endless spaces or repeat a name until max_tokens: every path through
    the grammar is a valid answer of bounded length."""
    shelves, products = sorted(world["shelves"]), sorted(world["products"])
    robots = sorted(world["robots"])
    max_goal = len(shelves) * len(products)
    lines = [
        'root ::= "{" ws "\\"goal\\":" ws goals "," ws "\\"constraints\\":" ws rules ws "}"',
        f'goals ::= "[" ws item ("," ws item){{0,{max_goal - 1}}} ws "]"',
        f'rules ::= "[" ws "]" | "[" ws rule ("," ws rule){{0,{MAX_RULES - 1}}} ws "]"',
        'rule ::= "{" ws "\\"rule\\":" ws ("\\"only\\"" | "\\"never\\"") "," ws '
        f'"\\"robots\\":" ws "[" ws robot ("," ws robot){{0,{len(robots) - 1}}} ws "]" "," ws '
        '"\\"product\\":" ws (product | anyname) "," ws "\\"from\\":" ws (shelf | anyname) "," ws '
        '"\\"to\\":" ws (shelf | anyname) ws "}"',
        f"shelf ::= {_alts(shelves)}",
        f"product ::= {_alts(products)}",
        f"robot ::= {_alts(robots)}",
        f"anyname ::= {_lit(ANY)}",
        'ws ::= [ \\t\\n]{0,8}',
    ]
    group_items = []
    for i, (cap, names) in enumerate(_capacity_groups(world).items()):
        group_items.append(f"item{i}")
        counts = " | ".join(f'"{n}"' for n in range(cap, -1, -1))  # longest first
        lines += [f"shelf{i} ::= {_alts(names)}", f"count{i} ::= {counts}",
                  f'item{i} ::= "{{" ws "\\"shelf\\":" ws shelf{i} "," ws "\\"product\\":" ws product '
                  f'"," ws "\\"units\\":" ws count{i} ws "}}"']
    lines.insert(1, "item ::= " + " | ".join(group_items))
    return "\n".join(lines) + "\n"


def parse_answer(text: str, world: dict) -> tuple[dict[str, dict[str, int]], list[dict[str, Any]]]:
    """The goal ``{shelf: {product: units}}`` and the constraints of a grounded answer.

    The decoder already limits names and counts; this re-checks them because a provider may
    ignore the schema, and reports a cut-off or contradictory answer precisely."""
    try:
        data = json.loads(text)
    except json.JSONDecodeError as exc:
        raise ParseIssue(f"the structured answer is not complete JSON ({exc.msg} at character "
                         f"{exc.pos}); raise max_tokens or shorten the answer") from None
    if not isinstance(data, dict) or not isinstance(data.get("goal"), list):
        raise ParseIssue('the structured answer must be {"goal": [...], "constraints": [...]}')
    goal: dict[str, dict[str, int]] = {}
    for n, item in enumerate(data["goal"], 1):
        shelf, product, units = (item.get(k) if isinstance(item, dict) else None
                                 for k in ("shelf", "product", "units"))
        if shelf not in world["shelves"] or product not in world["products"]:
            raise ParseIssue(f"goal item {n} names an unknown shelf or product: {json.dumps(item)}")
        cap = int(world["shelves"][shelf]["capacity"])
        if not isinstance(units, int) or isinstance(units, bool) or not 0 <= units <= cap:
            raise ParseIssue(f"goal item {n}: units must be a whole number 0..{cap} for {shelf}")
        previous = goal.setdefault(shelf, {}).setdefault(product, units)
        if previous != units:
            raise ParseIssue(f"the goal asks for both {previous} and {units} {product} on {shelf}")
    rules = []
    for item in data.get("constraints") or []:
        if not isinstance(item, dict) or item.get("rule") not in ("only", "never"):
            raise ParseIssue(f"constraint {json.dumps(item)} needs \"rule\": \"only\" or \"never\"")
        rule = {item["rule"]: item.get("robots")}
        rule.update({k: item[k] for k in ("product", "from", "to") if item.get(k) not in (None, ANY)})
        rules.append(rule)
    return goal, validate_constraints(rules, world)

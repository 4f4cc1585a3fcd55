"""Orders from a language model, for both LLM modes, so that everything after the generator
(resolver explanation, verifier, run summary) sees the same typed meaning as the offline path.

* Grounded mode: the model's answer IS an order (:mod:`pipflow.warehouse.language.grounding` constrains
  it). :func:`read_grounded` checks it against ``schemas/order.schema.json`` and the world, then
  resolves it; whatever is wrong becomes ONE message about the JSON the model was asked for
  (which statement, which key, which name, what to write instead), for the next round's prompt.
* The paper's mode: the model writes the PDDL problem. :func:`order_from_goal` reads its goal
  (``stock_goals``) back into an order of ``set``/``bound`` statements, and its JSON rules into
  order rules, so ``order`` and ``explanation`` exist for both modes.
"""
from __future__ import annotations

import json
from typing import Any

from pipflow.errors import Refusal, TranslationError
from pipflow.warehouse.language.grounding import ANY, vocabulary
from pipflow.warehouse.language.order import validate_order
from pipflow.language.parsing import ParseIssue, decode_answer_json
from pipflow.warehouse.language.resolver import resolve

#: the selector keys of a statement and the role of the names they hold
SELECTOR_ROLES = {"places": "places", "from": "places", "to": "places", "items": "items"}
ROLE_WORDS = {"places": "place", "items": "product", "robots": "robot", "kinds": "robot kind",
              "tags": "robot tag", "skills": "skill"}
SCOPE_ROLES = {"product": "items", "from": "places", "to": "places"}


def _normalize(order: dict) -> dict:
    """The order as ``schemas/order.schema.json`` has it: a rule's scope ``"any"`` (the grounded
    schema's way to say "not scoped", strict mode wanting every key) is left out."""
    rules = []
    for r in order.get("rules") or []:
        if isinstance(r, dict):
            r = {k: val for k, val in r.items() if not (k in SCOPE_ROLES and val == ANY)}
        rules.append(r)
    return {**order, "rules": rules}


def _unknown(name: Any, role: str, vocab: dict[str, list[str]], where: str) -> str:
    known = vocab.get(role) or []
    listed = ", ".join(f'"{n}"' for n in known) if known else "none in this world"
    return (f'{where}: "{name}" is not a {ROLE_WORDS[role]} of this world; write one of: {listed}')


def check_names(order: dict, world: dict) -> list[str]:
    """Every name of the order that the world lacks, as a message naming where it is."""
    vocab = vocabulary(world)
    out: list[str] = []
    for n, s in enumerate(order.get("statements") or [], 1):
        where = f'statement {n} ("{s.get("words", "")}")'
        for key, role in SELECTOR_ROLES.items():
            sel = s.get(key)
            if not isinstance(sel, dict):
                continue
            for name in list(sel.get("names") or []) + list(sel.get("except") or []):
                if name not in vocab[role]:
                    out.append(_unknown(name, role, vocab, f'{where} "{key}"'))
        other = (s.get("amount") or {}).get("as_many_as")
        if other is not None and other not in vocab["places"]:
            out.append(_unknown(other, "places", vocab, f'{where} "amount"'))
    for n, r in enumerate(order.get("rules") or [], 1):
        where = f'rule {n} ("{r.get("words", "")}")'
        sel = r.get("robots") or {}
        for key, role in (("names", "robots"), ("kind", "kinds"), ("tag", "tags"), ("skill", "skills")):
            for name in (sel.get(key) or []) if key == "names" else ([sel[key]] if key in sel else []):
                if name not in vocab[role]:
                    out.append(_unknown(name, role, vocab, f'{where} "robots"'))
        for key, role in SCOPE_ROLES.items():
            if key in r and r[key] not in vocab[role]:
                out.append(_unknown(r[key], role, vocab, f'{where} "{key}"') + ' or "any"')
    return out


def read_grounded(text: str, world: dict, command: str | None = None) -> dict[str, Any]:
    """``{"order", "goal", "constraints", "explanation"}`` of a grounded answer.

    Raises ParseIssue with feedback in the answer's own terms: JSON cut off, a key or value the
    order form does not allow (with its path), a name the world lacks, or what the resolver
    could not compute (a count below zero, more than there is, over capacity)."""
    try:
        data, end = decode_answer_json(text.strip())
    except json.JSONDecodeError as exc:
        raise ParseIssue(f"the structured answer is not complete JSON ({exc.msg} at character "
                         f"{exc.pos}); raise max_tokens or shorten the answer") from None
    if text.strip()[end:].strip():  # as json.loads says it
        raise ParseIssue(f"the structured answer is not complete JSON (Extra data at character {end}); raise "
                         "max_tokens or shorten the answer")
    if not isinstance(data, dict):
        raise ParseIssue('the structured answer must be one JSON object {"statements": [...], "rules": [...]}')
    if "goal" in data and "statements" not in data:
        data = legacy_order(data)
    order = _normalize(data)
    if command and "command" not in order:
        order["command"] = command
    try:
        validate_order(order)
    except TranslationError as exc:
        raise ParseIssue(f"the order JSON breaks its form: {str(exc).removeprefix('the order is not valid ')}"
                         ' (an order is {"statements": [{"op", ...}], "rules": [{"mode", "robots", ...}]})'
                         ) from None
    unknown = check_names(order, world)
    if unknown:
        raise ParseIssue("; ".join(unknown))
    try:  # no supply check: an impossible goal goes to the verifier, whose verdict llm.check weighs
        resolved = resolve(order, world, check=False)
    except Refusal as exc:
        raise ParseIssue(f"the order cannot be carried out in this world: {exc}. Check each statement's "
                         "op and amount against the command (\"set\" a count, \"change\" by more/fewer, "
                         "\"transfer\" from/to)") from None
    except TranslationError as exc:
        raise ParseIssue(f"the order does not say enough: {exc}") from None
    return {"order": order, "goal": resolved.goal, "constraints": resolved.constraints,
            "explanation": resolved.explanation}


def legacy_order(data: dict) -> dict[str, Any]:
    """An order from the earlier grounded form ``{"goal": [{"shelf", "product", "units"}],
    "constraints": [{"rule", "robots", "product", "from", "to"}]}``, still read because scripted
    answers and earlier feedback use it (the schema and grammar ask for orders only). Malformed
    items are passed through so that the order's validation names them."""
    statements: list[Any] = []
    for item in data.get("goal") if isinstance(data.get("goal"), list) else []:
        if not isinstance(item, dict):
            statements.append(item)
            continue
        shelf, product, units = (item.get(k) for k in ("shelf", "product", "units"))
        statements.append({"op": "set", "places": {"names": [shelf]}, "items": {"names": [product]},
                           "amount": {"count": units}, "words": f"{units} {product} on {shelf}"})
    rules: list[Any] = []
    for c in data.get("constraints") if isinstance(data.get("constraints"), list) else []:
        if not isinstance(c, dict):
            rules.append(c)
            continue
        rule = {"mode": c.get("rule"), "robots": {"names": c.get("robots")}, "words": json.dumps(c)}
        rule.update({k: c[k] for k in SCOPE_ROLES if c.get(k) not in (None, ANY)})
        rules.append(rule)
    return {"statements": statements, "rules": rules}


def _value_words(shelf: str, product: str, value: Any) -> str:
    if isinstance(value, dict):
        parts = ([f"(>= (stock {shelf} {product}) {value['at_least']})"] if "at_least" in value else []) + \
                ([f"(<= (stock {shelf} {product}) {value['at_most']})"] if "at_most" in value else [])
        return " ".join(parts)
    return f"(= (stock {shelf} {product}) {value})"


def order_from_goal(goal: dict[str, dict[str, Any]], constraints: list[dict] | None = None,
                    command: str | None = None) -> dict[str, Any]:
    """The order a PDDL goal states: one ``set`` per exact count, one ``bound`` per range (the
    words are the goal's conditions), plus the robot-use rules as name-selector rules."""
    statements: list[dict[str, Any]] = []
    for shelf, items in goal.items():
        for product, value in items.items():
            base = {"places": {"names": [shelf]}, "items": {"names": [product]},
                    "words": _value_words(shelf, product, value)}
            if isinstance(value, dict):
                amount = {k: int(value[k]) for k in ("at_least", "at_most") if k in value}
                statements.append({"op": "bound", **base, "amount": amount})
            else:
                statements.append({"op": "set", **base, "amount": {"count": int(value)}})
    rules = []
    for c in constraints or []:
        mode = "only" if "only" in c else "never"
        rule = {"mode": mode, "robots": {"names": list(c.get(mode) or [])},
                "words": json.dumps({k: val for k, val in c.items() if k != "words"})}
        rule.update({k: c[k] for k in SCOPE_ROLES if c.get(k)})
        rules.append(rule)
    order: dict[str, Any] = {"statements": statements, "rules": rules}
    if command:
        order["command"] = command
    return order


def explain_goal(goal: dict[str, dict[str, Any]], constraints: list[dict], world: dict,
                 command: str | None = None) -> dict[str, Any]:
    """``{"order", "explanation"}`` for a goal the model wrote as PDDL. The explanation is the
    resolver's, without the supply check (the verifier judges feasibility and names it); a goal
    the resolver cannot read (a contradiction, an unknown name) is explained by that reason."""
    order = order_from_goal(goal, constraints, command)
    try:
        validate_order(order)
        lines = resolve(order, world, check=False).explanation
    except (TranslationError, Refusal) as exc:
        lines = [f"the problem's goal cannot be read as an order: {exc}"]
    return {"order": order, "explanation": list(lines)}

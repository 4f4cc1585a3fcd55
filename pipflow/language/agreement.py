"""A second opinion on a model's reading of a command: does its goal say what the command says?

The debugger and the verifier check that a model's problem is well formed and possible in the
world; neither can see that it answers another command. A small model that writes product2 where
the command asked for product1 passes every check and robots move the wrong goods (issue 17,
wh-05). So the model's goal and robot rules are compared with a reading of the command that does
not come from the model:

* **the offline reading** (:func:`pipflow.language.offline.offline`: parser + resolver) when the
  parser understands the command. It never guesses, so a goal that differs from it is wrong: a
  *firm* disagreement, feedback for the next round, and never accepted.
* **the command's words** (its world names and numbers) when the parser does not understand it:
  weaker evidence, a *loose* disagreement. It is feedback too, but after the last round the goal
  is accepted and the run says so (output ``disagreement``).

The same comparison decides whether a verifier's refusal is final. A refusal is final only when
the *command* makes the goal impossible: the offline reading itself is a refusal, or the model's
impossible goal agrees with the reading of the command. An impossible goal the model invented
is feedback, not the end of the run.

Messages are phrased for the form the model was asked for (:mod:`pipflow.language.feedback`).
"""
from __future__ import annotations

import hashlib
import json
from dataclasses import dataclass, field
from typing import Any

from pipflow.errors import InputError, Refusal, TranslationError
from pipflow.goalcounts import describe, holds, is_bound
from pipflow.language import feedback as phrase
from pipflow.language.names import NameIndex, tokenize
from pipflow.language.offline import offline

OFFLINE = "offline reading"
WORDS = "command's words"
NONE = "none"


@dataclass
class Opinion:
    """``disagreement``: what the model's reading gets wrong, in mode-neutral words.
    ``messages``: the same, phrased as feedback for the mode. ``refusal``: the final refusal (the
    command makes the goal impossible), else None. ``firm``: the disagreement is with a full
    reading of the command (never accepted), not only with its words."""

    basis: str
    disagreement: list[str] = field(default_factory=list)
    messages: list[str] = field(default_factory=list)
    refusal: str | None = None
    firm: bool = False
    reading: dict | None = None  # the offline goal and rules, when the parser understood


_READINGS: dict[str, tuple[str, Any]] = {}


def offline_reading(command: str, world: dict) -> tuple[str, Any]:
    """``("read", {"goal", "constraints"})``, ``("refused", reason)`` or ``("unread", why)``:
    the offline parser's reading of ``command``, remembered per (command, world) in this process
    (the loop asks once per round)."""
    key = hashlib.sha256(json.dumps([command, world], sort_keys=True, default=str).encode()).hexdigest()
    if key not in _READINGS:
        try:
            got = offline(command, world)
            _READINGS[key] = ("read", {"goal": got["goal"], "constraints": got["constraints"],
                                       "explanation": got.get("explanation") or []})
        except Refusal as exc:
            _READINGS[key] = ("refused", str(exc))
        except (TranslationError, InputError) as exc:
            _READINGS[key] = ("unread", str(exc))
    return _READINGS[key]


def _rule_key(rule: dict) -> str:
    """A rule without its source words, robots sorted: two rules that mean the same compare equal."""
    kind = "only" if "only" in rule else "never"
    robots = rule.get(kind)
    robots = sorted([robots] if isinstance(robots, str) else list(robots or []))
    clean = {kind: robots, **{k: rule[k] for k in ("product", "from", "to") if rule.get(k) not in (None, "any")}}
    return json.dumps(clean, sort_keys=True)


def _now(world: dict, shelf: str, product: str) -> int:
    return int((world.get("stock", {}).get(shelf) or {}).get(product, 0))


def _agrees(model_value: Any, want: Any) -> bool:
    """The model's value means what the reading means: equal, or an exact count that meets the
    reading's bound (a grounded answer can only state exact counts)."""
    if model_value == want:
        return True
    return is_bound(want) and not is_bound(model_value) and isinstance(model_value, int) and holds(model_value, want)


def compare_with_reading(goal: dict, constraints: list, reading: dict, world: dict,
                         grounded: bool) -> tuple[list[str], list[str]]:
    """``(disagreement, messages)`` between the model's goal and rules and the offline reading.

    A goal entry the reading does not have is no disagreement when it keeps the shelf's current
    count (a model may restate what stays); one that changes it is."""
    said, feedback = [], []
    want = reading["goal"]
    for shelf, items in want.items():
        for product, value in items.items():
            got = (goal.get(shelf) or {}).get(product)
            if got is None:
                said.append(f"the command asks for {describe(value)} {product} on {shelf}; the model's goal does not say")
                feedback.append(f"the command asks for {describe(value)} {product} on {shelf}, but your goal "
                                f"does not set it: add {phrase.goal_entry(shelf, product, value, grounded)}")
            elif not _agrees(got, value):
                said.append(f"the command asks for {describe(value)} {product} on {shelf}; the model's goal says {describe(got)}")
                feedback.append(f"your goal asks for {describe(got)} {product} on {shelf}, but the command asks for "
                                f"{describe(value)}: write {phrase.goal_entry(shelf, product, value, grounded)}")
    for shelf, items in goal.items():
        for product, value in items.items():
            if product in (want.get(shelf) or {}):
                continue
            now = _now(world, shelf, product)
            if not (value == now or (is_bound(value) and holds(now, value))):
                said.append(f"the model's goal changes {product} on {shelf} to {describe(value)} (now {now}); "
                            "the command does not ask for that")
                feedback.append(f"your goal asks for {describe(value)} {product} on {shelf} (it holds {now} now), "
                                f"which the command does not ask for: leave {product} on {shelf} out of the goal")
    have = {_rule_key(r) for r in constraints or []}
    need = {_rule_key(r) for r in reading.get("constraints") or []}
    for rule in sorted(need - have):
        said.append(f"the command states the robot rule {rule}; the model's rules do not")
        feedback.append(f"the command states a robot-use rule your answer leaves out: add "
                        f"{phrase.rule(json.loads(rule), grounded)}")
    for rule in sorted(have - need):
        said.append(f"the model's rule {rule} is not in the command")
        feedback.append(f"your rule {phrase.rule(json.loads(rule), grounded)} is not what the command states: "
                        "leave it out")
    return said, feedback


def command_words(command: str, world: dict) -> tuple[set[str], set[str], set[int]]:
    """The shelves, products and numbers a command names (typo-tolerant, as the parser reads
    names: "prodct1" is product1, "robot 0" is a robot and not the number 0)."""
    shelves, products, numbers = set(), set(), set()
    for tok in tokenize(command, NameIndex(world)):
        if tok.kind == "name" and tok.value in world.get("shelves", {}):
            shelves.add(str(tok.value))
        elif tok.kind == "name" and tok.value in world.get("products", {}):
            products.add(str(tok.value))
        elif tok.kind == "num" and isinstance(tok.value, int):
            numbers.add(int(tok.value))
    return shelves, products, numbers


def compare_with_words(command: str, goal: dict, constraints: list, world: dict,
                       grounded: bool) -> tuple[list[str], list[str]]:
    """``(disagreement, messages)`` between the model's reading and the names and numbers of the
    command: a named shelf or product that the goal and rules leave out, a changed count of a
    shelf or product the command does not name, a number of the command found nowhere in the
    goal (as a count, or as the change from the current count)."""
    shelves, products, numbers = command_words(command, world)
    said, feedback = [], []
    in_rules = {r.get(k) for r in constraints or [] for k in ("product", "from", "to")}
    mentioned = {s for s in goal} | {p for items in goal.values() for p in items} | in_rules
    for name in sorted((shelves | products) - mentioned):
        said.append(f"the command names {name}; the model's goal and rules do not")
        feedback.append(f"the command names {name}, but your goal and rules leave it out")
    changed = [(s, p, v) for s, items in goal.items() for p, v in items.items() if v != _now(world, s, p)]
    for s, p, v in changed:
        strange = [n for n, named in ((s, shelves), (p, products)) if named and n not in named]
        if strange:
            said.append(f"the model's goal changes {p} on {s} to {describe(v)}; the command names no {' or '.join(strange)}")
            feedback.append(f"your goal changes {p} on {s} (to {describe(v)}), but the command does not name "
                            f"{' or '.join(strange)}: leave it out of the goal")
    seen: set[int] = set()
    for s, items in goal.items():
        for p, v in items.items():
            now = _now(world, s, p)
            for n in ([v] if not is_bound(v) else [x for x in v.values() if isinstance(x, int)]):
                seen |= {n, abs(n - now)}
    for n in sorted(numbers - seen):
        said.append(f"the command's number {n} appears nowhere in the model's goal")
        feedback.append(f"the command says {n}, but no count of your goal is {n} or changes a count by {n}")
    return said, feedback


def second_opinion(command: str, world: dict, goal: dict | None, constraints: list | None,
                   verifier_refusal: str | None, grounded: bool = False) -> Opinion:
    """The model's reading (``goal``, ``constraints``) against the command's; see the module
    docstring for what is firm, what is loose, and when a refusal is final."""
    goal, constraints = goal or {}, constraints or []
    state, reading = offline_reading(command, world)
    if state == "refused":  # the command itself is impossible, whatever the model wrote
        return Opinion(OFFLINE, refusal=f"the command cannot be done in this world: {reading}", firm=True)
    if state == "read":
        said, messages = compare_with_reading(goal, constraints, reading, world, grounded)
        basis, firm = OFFLINE, True
    else:
        try:
            said, messages = compare_with_words(command, goal, constraints, world, grounded)
        except Exception:  # no name index for this world: nothing to compare with
            return Opinion(NONE, refusal=verifier_refusal)
        basis, firm = WORDS, False
    if verifier_refusal and said:  # an impossible goal the model invented: feedback, not the end
        messages = ["the goal that cannot be done is your answer's, not the command's: "
                    "the command asks for something else (below)"] + messages
        return Opinion(basis, said, messages, None, firm, reading if state == "read" else None)
    return Opinion(basis, said, messages, verifier_refusal, firm and bool(said),
                   reading if state == "read" else None)


def refusal_opinion(command: str, world: dict, verifier_refusal: str | None) -> Opinion:
    """For a domain whose goals are not compared (household): only whether a verifier's refusal
    is final. The offline reading refuses the command: final, with its reason. It reads the
    command (so the command can be done): the refusal is of a goal the model invented, and it is
    feedback. It does not read it: the verifier's refusal stands, as nothing says otherwise."""
    state, reading = offline_reading(command, world)
    if state == "refused":
        return Opinion(OFFLINE, refusal=f"the command cannot be done in this world: {reading}", firm=True)
    if state == "read" and verifier_refusal:
        why = verifier_refusal.split(": ", 1)[-1] if ": " in verifier_refusal else verifier_refusal
        return Opinion(OFFLINE, messages=[f"your goal cannot be done ({why}); the goal that cannot be done is "
                                          "your answer's, not the command's: the command can be done, write "
                                          "the goal it states"])
    return Opinion(NONE if state != "read" else OFFLINE, refusal=verifier_refusal)

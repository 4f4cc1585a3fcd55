"""The garden's command language, read offline: a tiny lark grammar, then names resolved against
the world, then the arithmetic (counts in stores and beds) done here and said in words.

What it understands (keywords in capitals; ``,``, ``and``, ``then``, ``;``, ``.`` separate):

* ``WATER <beds>`` -- ``water north and east``, ``water every bed``
* ``PRUNE|TRIM|WEED <beds>`` -- ``prune the south bed``
* ``HARVEST|PICK|BRING <amount> <crop> [FROM <bed>] [INTO|TO|IN <store>]`` -- amount: a number
  (``3``, ``three``, ``a``), ``all [the]`` (every ripe unit), ``at least N``
* robot rules: ``ONLY <robots> MAY|CAN|SHOULD <verb>``, ``<robots> MUST|MAY|SHOULD|CAN NOT <verb>
  [<bed or crop>]`` (also ``cannot``), ``KEEP <robots> OUT OF|AWAY FROM <bed>``, ``DO NOT LET
  <robots> <verb> [<bed or crop>]``; robots by name, kind (``pickers``) or tag (``wet robots``).

Why it refuses so readily: a misread garden command sends robots to cut the wrong bed. A word the
grammar cannot place, a name that is not the world's, or a harvest that does not say which store
(when there are several) is a :class:`~pipflow.errors.TranslationError` quoting the words; a
command this garden cannot satisfy (more ripe units than grow, more than a store's room) is a
:class:`~pipflow.errors.Refusal` with the reason.

The reading is an *order* (what the command says, names resolved) and a *goal* (the final state
the order asks for): ``{"watered": [beds], "clear": [beds], "stored": {store: {crop: value}},
"ripe": {bed: {crop: value}}}`` where a value is an exact count or ``{"at_least": n}``.
"""
from __future__ import annotations

from functools import lru_cache
from typing import Any

from lark import Lark, Token, Transformer, UnexpectedInput

from pipflow.plugin import Refusal, TranslationError, closest

from pipflow_garden.world import ripe_total

GRAMMAR = r"""
start: clause (sep clause)* sep?
sep: (COMMA | SEPCHAR | AND | THEN)+
COMMA: ","
SEPCHAR: ";" | "."
?clause: water | prune | harvest | rule_only | rule_never | rule_keep | rule_let

water: WATER beds
prune: (PRUNE | TRIM | WEED) beds
harvest: (HARVEST | PICK | BRING) amount NAME source? dest?
source: FROM bed
dest: (INTO | TO | IN) THE? NAME

beds: every_bed | bed (listsep bed)*
every_bed: (EVERY | EACH) BED | ALL THE? BEDS
bed: THE? NAME BED?
listsep: COMMA AND? | AND

amount: count | ALL THE? -> every_unit | AT LEAST count -> at_least
count: NUMBER | A | AN | ONE | TWO | THREE | FOUR | FIVE | SIX | SEVEN | EIGHT | NINE | TEN | ELEVEN | TWELVE

rule_only: ONLY robots (MAY | CAN | SHOULD) verb target?
rule_never: robots (MUST | MAY | SHOULD | CAN) NOT verb target?
          | robots CANNOT verb target?
rule_keep: KEEP robots (OUT OF | AWAY FROM) bed
rule_let: DO NOT LET robots verb target?
robots: robot (listsep robot)*
robot: THE? NAME (ROBOT | ROBOTS)?
verb: WATER | PRUNE | TRIM | WEED | HARVEST | PICK | BRING
target: (FROM | IN)? THE? NAME BED?

WATER: "water"
PRUNE: "prune"
TRIM: "trim"
WEED: "weed"
HARVEST: "harvest"
PICK: "pick"
BRING: "bring"
FROM: "from"
INTO: "into"
TO: "to"
IN: "in"
THE: "the"
BED: "bed"
BEDS: "beds"
EVERY: "every"
EACH: "each"
ALL: "all"
AND: "and"
THEN: "then"
AT: "at"
LEAST: "least"
A: "a"
AN: "an"
ONLY: "only"
MAY: "may"
CAN: "can"
SHOULD: "should"
MUST: "must"
NOT: "not"
CANNOT: "cannot"
KEEP: "keep"
OUT: "out"
OF: "of"
AWAY: "away"
DO: "do"
LET: "let"
ROBOT: "robot"
ROBOTS: "robots"
ONE: "one"
TWO: "two"
THREE: "three"
FOUR: "four"
FIVE: "five"
SIX: "six"
SEVEN: "seven"
EIGHT: "eight"
NINE: "nine"
TEN: "ten"
ELEVEN: "eleven"
TWELVE: "twelve"
NUMBER: /[0-9]+/
NAME: /[a-z][a-z0-9_-]*/
%import common.WS
%ignore WS
"""

NUMBERS = {"a": 1, "an": 1, "one": 1, "two": 2, "three": 3, "four": 4, "five": 5, "six": 6, "seven": 7,
           "eight": 8, "nine": 9, "ten": 10, "eleven": 11, "twelve": 12}
#: the verb of a clause or a rule -> the team action it asks for
ACTIONS = {"water": "water", "prune": "prune", "trim": "prune", "weed": "prune", "harvest": "harvest",
           "pick": "harvest", "bring": "harvest"}


@lru_cache(maxsize=1)
def parser() -> Lark:
    """One Earley parser per process (a basic lexer: a keyword is never read as a name). Every
    reading is kept (``ambiguity="explicit"``): a command the grammar reads two ways is refused,
    never resolved by a silent preference."""
    return Lark(GRAMMAR, parser="earley", lexer="basic", propagate_positions=True, ambiguity="explicit")


class _Spans(Transformer):
    """The parse tree as plain data; each named thing keeps the words it was said with."""

    def __init__(self, text: str):
        super().__init__()
        self.text = text

    def _words(self, meta) -> str:
        return self.text[meta.start_pos:meta.end_pos]

    def __default__(self, data, children, meta):
        return {"kind": str(data), "children": children, "words": self._words(meta) if not meta.empty else ""}


def _tokens(children: list, kind: str) -> list[Token]:
    return [c for c in children if isinstance(c, Token) and c.type == kind]


def _sub(children: list, kind: str) -> list[dict]:
    return [c for c in children if isinstance(c, dict) and c["kind"] == kind]


def read_command(command: str, world: dict) -> dict:
    """The command read against ``world``: ``{"goal", "constraints", "order", "explanation"}``.

    Raises TranslationError quoting words it cannot place, Refusal when the garden cannot do it."""
    text = " ".join(str(command).lower().split())
    if not text:
        raise TranslationError("the command is empty")
    try:
        tree = parser().parse(text)
    except UnexpectedInput as err:
        raise TranslationError(f"could not place the words {_piece(text, err)!r} in the command "
                               f"(the garden language: water, prune, harvest, and robot rules)") from None
    for node in tree.find_data("_ambig"):  # lark gives the node no position: its readings have one
        spans = [(c.meta.start_pos, c.meta.end_pos) for c in node.children if not c.meta.empty]
        words = text[min(a for a, _ in spans):max(b for _, b in spans)] if spans else text
        raise TranslationError(f"could not place the words {words!r}: they can be read in more than one way")
    clauses = _Spans(text).transform(tree)["children"]
    reader = _Reader(world)
    for clause in clauses:
        if isinstance(clause, dict) and clause["kind"] != "sep":
            reader.clause(clause)
    return reader.result()


def _piece(text: str, err: UnexpectedInput) -> str:
    """The words around a parse failure: from the separator before it (``and``, ``then``, a word
    ending in ``,;.``) to the one after it, so the quote is the clause the reader could not place."""
    token = getattr(err, "token", None)
    pos = token.start_pos if isinstance(token, Token) and token.start_pos is not None else \
        getattr(err, "pos_in_stream", None)
    words = text.split(" ")
    ends = [len(" ".join(words[:i + 1])) for i in range(len(words))]  # where each word ends
    at = next((i for i, end in enumerate(ends) if pos is not None and pos <= end), len(words) - 1)

    def ends_clause(i: int) -> bool:  # word i closes a clause (or is a separator word)
        return words[i] in ("and", "then") or words[i].endswith((",", ";", "."))

    lo = at
    while lo > 0 and not ends_clause(lo - 1):
        lo -= 1
    hi = at
    while hi < len(words) - 1 and (not ends_clause(hi) or (hi == at and words[hi] in ("and", "then"))) and words[hi + 1] not in ("and", "then"):
        hi += 1
    return " ".join(words[lo:hi + 1]).strip(",;.")


class _Reader:
    """Resolves parsed clauses against the world and accumulates the goal and the rules."""

    def __init__(self, world: dict):
        self.world = world
        self.watered: list[str] = []
        self.clear: list[str] = []
        self.stored: dict[str, dict[str, Any]] = {}
        self.ripe: dict[str, dict[str, Any]] = {}
        self.rules: list[dict] = []
        self.order: list[dict] = []
        self.said: list[str] = []
        self._taken: dict[tuple[str, str | None], int] = {}  # (crop, bed) -> units asked for
        self._added: dict[tuple[str, str], int] = {}         # (store, crop) -> units added

    # ----------------------------------------------------------------------------- names
    def _name(self, token: str, choices, what: str, words: str) -> str:
        if token in choices:
            return token
        near = closest(token, choices)
        hint = f"; did you mean {' or '.join(repr(n) for n in near)}?" if near else f"; {what}s: {', '.join(choices)}"
        raise TranslationError(f"could not place the words {words!r}: this garden has no {what} {token!r}{hint}")

    def _crop(self, token: str, words: str) -> str:
        crops = self.world["crops"]
        for cand in (token, token[:-3] + "y" if token.endswith("ies") else None,
                     token[:-2] if token.endswith("es") else None, token[:-1] if token.endswith("s") else None):
            if cand and cand in crops:
                return cand
        return self._name(token, list(crops), "crop", words)

    def _bed(self, node: dict) -> str:
        return self._name(str(_tokens(node["children"], "NAME")[0]), list(self.world["beds"]), "bed", node["words"])

    def _beds(self, node: dict) -> list[str]:
        if _sub(node["children"], "every_bed"):
            return list(self.world["beds"])
        return [self._bed(b) for b in _sub(node["children"], "bed")]

    def _robots(self, node: dict) -> list[str]:
        robots = self.world["robots"]
        out: list[str] = []
        for r in _sub(node["children"], "robot"):
            word = str(_tokens(r["children"], "NAME")[0])
            stem = word[:-1] if word.endswith("s") else word
            if word in robots:
                chosen = [word]
            else:
                chosen = [n for n, spec in robots.items() if spec.get("kind") in (word, stem)] or \
                         [n for n, spec in robots.items() if word in spec.get("tags", ())]
            if not chosen:
                names = list(robots) + sorted({s["kind"] for s in robots.values() if s.get("kind")})
                self._name(word, names, "robot or kind of robot", r["words"])
            out += [n for n in chosen if n not in out]
        return out

    # ----------------------------------------------------------------------------- clauses
    def clause(self, node: dict) -> None:
        getattr(self, f"_{node['kind']}")(node)
        self.said.append(node["words"])

    def _water(self, node: dict) -> None:
        beds = self._beds(_sub(node["children"], "beds")[0])
        self.watered += [b for b in beds if b not in self.watered]
        self.order.append({"do": "water", "beds": beds, "words": node["words"]})

    def _prune(self, node: dict) -> None:
        beds = self._beds(_sub(node["children"], "beds")[0])
        self.clear += [b for b in beds if b not in self.clear]
        self.order.append({"do": "prune", "beds": beds, "words": node["words"]})

    def _harvest(self, node: dict) -> None:
        words = node["words"]
        crop = self._crop(str(_tokens(node["children"], "NAME")[0]), words)
        source = _sub(node["children"], "source")
        bed = self._bed(_sub(source[0]["children"], "bed")[0]) if source else None
        store = self._store(node, words)
        amount = _sub(node["children"], "amount") + _sub(node["children"], "every_unit") + \
            _sub(node["children"], "at_least")
        kind = amount[0]["kind"]
        # units earlier clauses asked for count against this one: from this bed, and from anywhere
        taken_all = sum(v for (c, _), v in self._taken.items() if c == crop)
        available = ripe_total(self.world, crop, None) - taken_all
        if bed:
            available = min(available, ripe_total(self.world, crop, bed) - self._taken.get((crop, bed), 0))
        n = available if kind == "every_unit" else _count(_sub(amount[0]["children"], "count")[0])
        where = f"in bed {bed}" if bed else "in the garden"
        if available == 0:
            raise Refusal(f"{words!r}: no {crop} is ripe {where} (nothing to harvest)")
        if n > available:
            earlier = f" after the {taken_all} the command's earlier harvests take" if taken_all else ""
            raise Refusal(f"{words!r}: only {available} unit{'' if available == 1 else 's'} of {crop} "
                          f"{'is' if available == 1 else 'are'} ripe {where}{earlier} (asked for {n})")
        free = self.world["stores"][store]["room"] - sum(self.world["stores"][store]["holds"].values()) - \
            sum(v for (s, _), v in self._added.items() if s == store)
        if n > free:
            raise Refusal(f"{words!r}: store {store} has room for {free} more units (asked for {n})")
        self._taken[(crop, bed)] = self._taken.get((crop, bed), 0) + n
        self._added[(store, crop)] = self._added.get((store, crop), 0) + n
        total = self.world["stores"][store]["holds"].get(crop, 0) + self._added[(store, crop)]
        self.stored.setdefault(store, {})[crop] = {"at_least": total} if kind == "at_least" else total
        if bed:
            left = ripe_total(self.world, crop, bed) - self._taken[(crop, bed)]
            self.ripe.setdefault(bed, {})[crop] = {"at_most": left} if kind == "at_least" else left
        self.order.append({"do": "harvest", "crop": crop, "count": "all" if kind == "every_unit" else n,
                           "at_least": kind == "at_least", "from": bed, "to": store, "words": words})

    def _store(self, node: dict, words: str) -> str:
        stores = list(self.world["stores"])
        dest = _sub(node["children"], "dest")
        if dest:
            return self._name(str(_tokens(dest[0]["children"], "NAME")[0]), stores, "store", dest[0]["words"])
        if len(stores) == 1:
            return stores[0]
        raise TranslationError(f"could not place the words {words!r}: say which store it goes to "
                               f"({' or '.join(stores)})")

    def _rule(self, kind: str, node: dict) -> None:
        robots = self._robots(_sub(node["children"], "robots")[0])
        rule: dict[str, Any] = {kind: robots}
        verb = _sub(node["children"], "verb")
        if verb:
            rule["action"] = ACTIONS[str(verb[0]["children"][0])]
        target = _sub(node["children"], "target") + _sub(node["children"], "bed")
        if target:
            word = str(_tokens(target[0]["children"], "NAME")[0])
            if word in self.world["beds"]:
                rule["bed"] = word
            else:
                rule["crop"] = self._crop(word, target[0]["words"])
        rule["words"] = node["words"]
        self.rules.append(rule)
        self.order.append({"rule": {k: v for k, v in rule.items() if k != "words"}, "words": node["words"]})

    def _rule_only(self, node: dict) -> None:
        self._rule("only", node)

    def _rule_never(self, node: dict) -> None:
        self._rule("never", node)

    def _rule_keep(self, node: dict) -> None:
        self._rule("never", node)

    def _rule_let(self, node: dict) -> None:
        self._rule("never", node)

    # ----------------------------------------------------------------------------- result
    def result(self) -> dict:
        goal = {k: v for k, v in (("watered", self.watered), ("clear", self.clear), ("stored", self.stored),
                                  ("ripe", self.ripe)) if v}
        if not goal:
            raise TranslationError("the command asks for nothing to be done (only robot rules): "
                                   f"{'; '.join(self.said)!r}")
        lines = [f"{o['words']!r} -> " + _explain(o, self.world) for o in self.order]
        return {"goal": goal, "constraints": self.rules, "order": self.order, "explanation": "\n".join(lines)}


def _count(node: dict) -> int:
    return NUMBERS.get(str(node["children"][0])) or int(str(node["children"][0]))


def _explain(item: dict, world: dict) -> str:
    """One line per clause saying what was understood and the arithmetic done."""
    if "rule" in item:
        return f"rule {item['rule']}"
    if item["do"] in ("water", "prune"):
        flag, state = ("watered", "watered already") if item["do"] == "water" else ("overgrown", "clear already")
        done = [b for b in item["beds"] if world["beds"][b][flag] == (item["do"] == "water")]
        return f"{item['do']} {', '.join(item['beds'])}" + (f" ({', '.join(done)}: {state})" if done else "")
    held = world["stores"][item["to"]]["holds"].get(item["crop"], 0)
    n = item["count"] if item["count"] != "all" else "every ripe"
    return (f"harvest {'at least ' if item['at_least'] else ''}{n} {item['crop']} "
            f"{'from ' + item['from'] + ' ' if item['from'] else ''}into {item['to']} (it holds {held} now)")

"""Read robot-use rules ("robot 0 should not move product1", "only robots 8 to 11 ...").

A rule becomes one or more ``{"only"|"never": [robots], "product"?, "from"?, "to"?}`` items, the
format of the task files. Which way a rule goes is read from a few word classes:

* an exception ("any robot except robot3") forbids the named robots, unless the clause is
  negative ("no robot other than robot1"), which requires them;
* a negation or a state of being unusable ("not", "never", "broken", "do not use it") forbids;
* "only"/"just"/"exclusively", or a plain instruction that robots do a move ("use robot1",
  "robot1 should move product3"), requires. A clause that is neither ("robot 3 can move
  product1": a permission that restricts nothing) is an error, not a guess.

Its scope comes from the products and shelves the clause names: a shelf after "from"/"off"/"out of"
is a ``from``, after "to"/"into"/"onto" a ``to``, and with no direction ("at", "on", no word) or
"away from" both, as two items (the format has no "or"). "from A to B" is one move, so one item
with both fields. Kind words alone ("product", "one shelf to another") narrow nothing. Robot
lists and ranges: "robots 1, 2 and 3", "robots 8 to 11", "robots 8-11", "r1 to r3".
"""
from __future__ import annotations

from pipflow.errors import TranslationError
from pipflow.language.names import NameIndex, Tok

NEGATIONS = {
    "not", "never", "no", "dont", "doesnt", "cant", "cannot", "mustnt", "shouldnt", "wont",
    "isnt", "arent", "without", "avoid", "forbidden", "prohibited", "banned", "broken", "faulty",
    "unavailable", "offline", "disabled", "damaged", "down", "away", "nobody", "neither", "nor",
    "idle", "unused", "excluded", "exclude", "skip", "busy", "charging", "malfunctioning",
    "out-of-service", "leave", "spare",
}
EXCEPTIONS = {"except", "besides", "excluding"}
ONLY = {"only", "just", "solely", "exclusively"}
OBLIGATION = {"must", "should", "shall", "will"}  # "robot1 should move product3": it does it
POSITIVE_USE = {"use", "using", "with", "by", "uses", "employ", "assign", "let"}
FROM_WORDS = {"from", "off"}
TO_WORDS = {"to", "into", "onto", "towards", "toward"}
PLACE_WORDS = {"at", "on", "in", "near", "around", "inside", "by"}
DELIVERY = {"put", "place", "deliver", "bring", "add", "stock", "store", "load"}
RANGE_WORDS = {"to", "through", "thru", "until", "till"}
LIST_WORDS = {",", "and", "or", "&"}


def _robots(toks: list[Tok], index: NameIndex) -> list[str]:
    """Robots the clause names, with lists and ranges ("robots 8 to 11", "robots 2 and 3")."""
    found: list[str] = []
    i = 0
    while i < len(toks):
        t = toks[i]
        if t.kind == "name" and t.of == "robot":
            found.append(str(t.value))
            digits = "".join(c for c in str(t.value) if c.isdigit())
            j = i + 1
            if (j + 1 < len(toks) and toks[j].is_word(*RANGE_WORDS) and toks[j + 1].kind == "num"
                    and digits):
                lo, hi = int(digits), int(toks[j + 1].value)
                if hi <= lo:
                    raise TranslationError(f"'{t.text} {toks[j].text} {toks[j + 1].text}' is not "
                                           f"an increasing range of robots")
                for n in range(lo + 1, hi + 1):
                    found.append(_robot_number(n, f"{t.text} {toks[j].text} {toks[j + 1].text}", index))
                i = j + 2
                continue
            if (j + 1 < len(toks) and toks[j].is_word(*RANGE_WORDS) and toks[j + 1].kind == "name"
                    and toks[j + 1].of == "robot" and digits):  # "r1 to r3"
                found += _name_range(t, toks[j], toks[j + 1], index)
                i = j + 2
                continue
            while j + 1 < len(toks) and toks[j].text.lower() in LIST_WORDS and toks[j + 1].kind == "num":
                found.append(_robot_number(int(toks[j + 1].value), toks[j + 1].text, index))
                j += 2
                if j < len(toks) and toks[j].is_word("and", "or") and j + 1 < len(toks) \
                        and toks[j + 1].kind == "num":
                    continue
            i = j
            continue
        i += 1
    order = {name: k for k, name in enumerate(index.by_kind["robot"])}
    return sorted(dict.fromkeys(found), key=lambda r: order.get(r, len(order)))


def _name_range(a: Tok, word: Tok, b: Tok, index: NameIndex) -> list[str]:
    """ "r1 to r3": the robots between two names that share their letters."""
    from pipflow.language.names import normalize, split_digits
    (la, da), (lb, db) = split_digits(normalize(str(a.value))), split_digits(normalize(str(b.value)))
    text = f"{a.text} {word.text} {b.text}"
    if la != lb or not da or not db or int(db) <= int(da):
        raise TranslationError(f"'{text}' is not an increasing range of robots "
                               f"(candidates: {index.candidates('robot')})")
    out = []
    for n in range(int(da) + 1, int(db) + 1):
        hit = [r for r in index.by_kind["robot"] if split_digits(normalize(r)) == (la, str(n))]
        if len(hit) != 1:
            raise TranslationError(f"'{text}': no robot {la}{n} in this world "
                                   f"(candidates: {index.candidates('robot')})")
        out.append(hit[0])
    return out


def _robot_number(n: int, text: str, index: NameIndex) -> str:
    same = index.with_digits("robot", str(n))
    if len(same) != 1:
        raise TranslationError(f"'{text}': no single robot numbered {n} in this world "
                               f"(candidates: {index.candidates('robot')})")
    return same[0]


def _polarity(toks: list[Tok]) -> str:
    words = {str(t.value) for t in toks if t.kind == "word"}
    texts = " ".join(str(t.value) for t in toks if t.kind == "word")
    negative = bool(words & NEGATIONS) or "out of order" in texts or "out of service" in texts
    if words & EXCEPTIONS or "other than" in texts or "apart from" in texts:
        return "only" if negative else "never"
    if negative:
        return "never"
    if words & ONLY or words & POSITIVE_USE or words & OBLIGATION:
        return "only"
    raise TranslationError(
        f"cannot tell whether '{' '.join(t.text for t in toks)}' requires or forbids the robots")


def _role(toks: list[Tok], i: int) -> str:
    """Direction of the shelf at ``toks[i]``: "from", "to" or "both", from the nearest preposition."""
    for j in range(i - 1, max(-1, i - 5), -1):
        t = toks[j]
        if t.kind != "word":
            break
        if t.value in FROM_WORDS and j > 0 and toks[j - 1].is_word("away", "clear"):
            return "both"  # "keep robot7 away from shelf3": no move from it nor to it
        if t.value in FROM_WORDS or (t.value == "of" and j > 0 and toks[j - 1].is_word("out")):
            return "from"
        if t.value in TO_WORDS:
            return "to"
        if t.value in PLACE_WORDS:
            # "put 5 product1 on shelf2": a delivery verb makes "on"/"in" a destination
            if any(x.kind == "word" and x.value in DELIVERY for x in toks[:i]):
                return "to"
            return "both"
    return "both"


def parse_rule(toks: list[Tok], index: NameIndex) -> list[dict]:
    """The constraint items of one clause that names robots."""
    robots = _robots(toks, index)
    if not robots:
        return []
    side = _polarity(toks)
    products = list(dict.fromkeys(str(t.value) for t in toks if t.kind == "name" and t.of == "product"))
    return scoped(side, robots, products, places_of(toks))


def places_of(toks: list[Tok]) -> list[dict]:
    """The shelves a clause names, as ``{"from": A}``, ``{"to": B}`` or one move ``{from, to}``."""
    shelves = [(i, str(t.value), _role(toks, i)) for i, t in enumerate(toks)
               if t.kind == "name" and t.of == "shelf"]
    places: list[dict] = []
    k = 0
    while k < len(shelves):
        i, name, role = shelves[k]
        if role == "from" and k + 1 < len(shelves) and shelves[k + 1][2] == "to" and all(
                x.kind == "word" for x in toks[i + 1:shelves[k + 1][0]]):
            place = {"from": name, "to": shelves[k + 1][1]}  # one move: "from A to B"
            if place not in places:
                places.append(place)
            k += 2
            continue
        for r in (("from", "to") if role == "both" else (role,)):
            if {r: name} not in places:
                places.append({r: name})
        k += 1
    return places


def scoped(side: str, robots: list[str], products: list[str], places: list[dict]) -> list[dict]:
    """One item per product and place the rule names (each a move it governs)."""
    items: list[dict] = []
    for product in products or [None]:
        for place in places or [None]:
            item: dict = {side: list(robots)}
            if product is not None:
                item["product"] = product
            if place is not None:
                item.update(place)
            items.append(item)
    return items

"""Robot selectors: which robots a rule means, by name, range, kind, tag or skill.

The parser keeps the selector as the words said it (``{"kind": "forklift"}``, ``{"skill":
"carry", "at_least": 3}``, ``{"extreme": "max", "skill": "carry"}``) so the order shows what the
user asked for; :func:`select` turns a selector into the world's robot names, for the resolver.
"""
from __future__ import annotations

from lark import Token, Tree

from pipflow.errors import Refusal, TranslationError
from pipflow.language.spelling import normalize, split_digits
from pipflow.warehouse.language.lexicon import DEFINITE, SUPERLATIVES
from pipflow.warehouse.language.names import NameIndex, stem_groups

SUPER_WORDS = set(SUPERLATIVES)
#: words that make a kind or tag said in the singular mean any or all robots of it
GROUP_WORDS = {"all", "every", "each", "any", "a", "an", "both", "either", "whichever", "crew", "team", "shift",
               "squad", "fleet", "lot"}


def _what(sel: dict) -> str:
    return f"of kind {sel['kind']}" if "kind" in sel else f"tagged {sel['tag']}"


def _robot_of(robots: dict, name: str) -> dict:
    r = robots.get(name)
    return r if isinstance(r, dict) else {}


class RobotSelector:
    """Reads the ``robots`` subtree of a parse into a selector."""

    def __init__(self, world: dict, index: NameIndex):
        self.world, self.index = world, index

    def read(self, node: Tree, words: str) -> dict:
        if any(isinstance(c, Tree) and c.data.startswith("r_") and c.data in (
                "r_kind", "r_skill_min", "r_skill_max", "r_super", "r_skill_cmp") for c in node.children):
            return self._group(next(c for c in node.children if isinstance(c, Tree)), words)
        names: list[str] = []
        for c in node.children:
            if not isinstance(c, Tree):
                continue
            vals = [t for t in c.scan_values(lambda v: isinstance(v, Token))]
            if c.data == "r_name":
                names.append(next(str(t.value) for t in vals if t.type == "ROBOT"))
            elif c.data == "r_range":
                first = next(str(t.value) for t in vals if t.type == "ROBOT")
                hi = int(next(t.value for t in vals if t.type == "NUM"))
                names += self._range(first, hi, words)
            elif c.data == "r_name_range":
                robots = [str(t.value) for t in vals if t.type == "ROBOT"]
                names += self._name_range(robots[0], robots[1], words)
            elif c.data == "r_number":
                n = int(next(t.value for t in vals if t.type == "NUM"))
                names.append(self._number(n, words))
        order = {name: k for k, name in enumerate(self.index.by_kind["robot"])}
        return {"names": sorted(dict.fromkeys(names), key=lambda r: order.get(r, len(order)))}

    def _group(self, node: Tree, words: str) -> dict:
        vals = list(node.scan_values(lambda v: isinstance(v, Token)))
        if node.data == "r_kind":
            t = next(v for v in vals if v.type in ("RKIND", "RTAG"))
            sel = self.group(t.type, str(t.value))
            self._check_one(sel, words, str(t.value))
            return sel
        if node.data in ("r_skill_min", "r_skill_max"):
            n = int(next(t.value for t in vals if t.type == "NUM"))
            skill = self._skill(vals, words)
            return {"skill": skill, "at_least" if node.data == "r_skill_min" else "at_most": n}
        if node.data == "r_skill_cmp":
            skill = self._skill(vals, words)
            cmp = next(c for c in node.children if isinstance(c, Tree) and c.data.startswith("cmp_"))
            n = int(next(t.value for t in cmp.scan_values(lambda v: isinstance(v, Token) and v.type == "NUM")))
            if cmp.data == "cmp_min":
                return {"skill": skill, "at_least": n}
            if cmp.data == "cmp_above":
                return {"skill": skill, "at_least": n + 1}
            if cmp.data == "cmp_max":
                return {"skill": skill, "at_most": n}
            return {"skill": skill, "at_most": n - 1}
        if node.data == "r_super":
            t = next(v for v in vals if v.type == "SUPER")
            said, noun = _superlative_and_noun(words)
            if vals[-1].type == "NUM" and vals[0].type == "SUPER" and noun != "one":
                raise TranslationError(f"'{words}': a number after '{said}' is not a group of robots")
            sel = {"extreme": str(t.value), "skill": self._skill([], words)}
            self._check_tie(sel, vals, words)
            return sel
        raise TranslationError(f"'{words}': cannot tell which robots")

    def group(self, terminal: str, value: str) -> dict:
        """The selector of a group word: a declared kind (RKIND) or tag (RTAG) of the world, else
        (RKIND of a name stem the lexicon found: "tugs") the robots whose names share the stem."""
        if terminal == "RTAG":
            return {"tag": value}
        robots = self.world.get("robots") or {}
        kinds = {str(_robot_of(robots, r).get("kind", "")).lower() for r in robots}
        if value.lower() in kinds:
            return {"kind": value}
        members = stem_groups([str(r) for r in robots]).get(normalize(value), [])
        if not members:
            raise TranslationError(f"'{value}': no robot kind, tag or name stem of this world")
        return {"names": members}

    def _check_one(self, sel: dict, words: str, said_as: str | None = None) -> None:
        """ "the AGV" (a kind or tag said in the singular after "the", "this", "our", ..., with no
        "all" / "any" / "a") names one robot: where the world has several of it, which one is not
        guessed (nor that all are meant); "the AGVs", "any AGV", "AGV crew" are the group, and so is
        a kind said bare, with no determiner ("forklift only", "AMR dont touch LCD"), as a sign or a
        learner of English without plurals says it. ``words`` holds the determiner said before the
        group (:meth:`~.lexicon.Lexicon._definite_groups`)."""
        said = [w for w in words.lower().replace("-", " ").replace("_", " ").split() if w.isalpha()]
        if not said or set(said) & GROUP_WORDS or not set(said) & DEFINITE:
            return   # "forklift only", "AMR dont touch LCD": a kind said bare is the kind, as on a sign
        # "robots of night_shift": the noun before "of" is the one said in the plural or not
        noun = said[said.index("of") - 1] if "of" in said[1:] else said[-1]
        value = said_as if said_as is not None else str(next(iter(sel.values())))
        if noun.endswith("s") and noun != normalize(value).replace(" ", ""):
            return  # plural: "forklifts", "night robots"
        matched = select(sel, self.world, words)
        if len(matched) > 1:
            what = _what(sel) if "names" not in sel else f"named {value} and a number or label"
            raise TranslationError(f"'{words}': {len(matched)} robots are {what} ({', '.join(matched)}); "
                                   f"cannot tell which one is meant (name it, or say all of them)")

    def _check_tie(self, sel: dict, vals: list[Token], words: str) -> None:
        """ "the strongest robot" names one robot: where several tie it is not guessed which (nor
        that all of them are meant); "the two strongest robots" must be as many as tie."""
        tied = select(sel, self.world, words)
        nums = [int(v.value) for v in vals if v.type == "NUM"]
        _, noun = _superlative_and_noun(words)
        plural = noun.endswith("s") and noun not in ("bus",)
        want = nums[0] if nums else (None if plural else 1)
        if want is not None and want != len(tied):
            raise TranslationError(f"'{words}': {len(tied)} robots tie for it ({', '.join(tied)}); "
                                   f"cannot tell which {'one' if want == 1 else str(want)} is meant")

    def check_apposition(self, sel: dict, kind: str, value: str, words: str) -> None:
        """ "Titan, our forklift, ...": the world must agree, or the command is not understood."""
        robots = self.world.get("robots") or {}
        key = "kind" if kind == "RKIND" else "tags"
        for name in sel.get("names", []):
            r = robots.get(name) or {}
            have = [str(r.get("kind", "")).lower()] if key == "kind" else [str(t).lower() for t in r.get("tags") or []]
            if value.lower() not in have:
                raise TranslationError(f"'{words}': {name} is not a {value} in this world")

    def _skill(self, vals: list[Token], words: str) -> str:
        """The skill named (a SKILL word) or, for a verb such as "carry", the world's skill of that
        name; a world with one skill needs no name ("the strongest robot")."""
        skills = list(dict.fromkeys(s for r in (self.world.get("robots") or {}).values()
                                    if isinstance(r, dict) for s in (r.get("skills") or {})))
        for t in vals:
            word = str(t.value).lower()
            for s in skills:
                if word in (s.lower(), s.lower() + "s", s.lower() + "es"):
                    return s
        if len(skills) == 1:
            return skills[0]
        raise TranslationError(f"'{words}': cannot tell which skill is meant "
                               f"(skills: {', '.join(skills) or 'none'})")

    def _number(self, n: int, words: str) -> str:
        same = self.index.with_digits("robot", str(n))
        if len(same) != 1:
            raise TranslationError(f"'{words}': no single robot numbered {n} in this world "
                                   f"(candidates: {self.index.candidates('robot')})")
        return same[0]

    def _range(self, first: str, hi: int, words: str) -> list[str]:
        alpha, digits = split_digits(normalize(first))
        if not digits or hi <= int(digits):
            raise TranslationError(f"'{words}' is not an increasing range of robots "
                                   f"(candidates: {self.index.candidates('robot')})")
        out = [first]
        for n in range(int(digits) + 1, hi + 1):
            hit = [r for r in self.index.by_kind["robot"] if split_digits(normalize(r)) == (alpha, str(n))]
            if len(hit) != 1:
                hit = self.index.with_digits("robot", str(n))
            if len(hit) != 1:
                raise TranslationError(f"'{words}': no robot numbered {n} in this world "
                                       f"(candidates: {self.index.candidates('robot')})")
            out.append(hit[0])
        return out

    def _name_range(self, a: str, b: str, words: str) -> list[str]:
        (la, da), (lb, db) = split_digits(normalize(a)), split_digits(normalize(b))
        if la != lb or not da or not db or int(db) <= int(da):
            raise TranslationError(f"'{words}' is not an increasing range of robots "
                                   f"(candidates: {self.index.candidates('robot')})")
        return self._range(a, int(db), words)


def select(selector: dict, world: dict, words: str = "") -> list[str]:
    """The world's robot names a selector means, in the world's order; none is a refusal."""
    robots = world.get("robots") or {}
    names = list(robots)
    if "names" in selector:
        unknown = [r for r in selector["names"] if r not in robots]
        if unknown:
            raise TranslationError(f"'{words}': no robot {', '.join(unknown)} in this world "
                                   f"(candidates: {', '.join(names)})")
        return [r for r in names if r in selector["names"]]
    if "kind" in selector:
        out = [r for r in names if str(_robot_of(robots, r).get("kind", "")).lower() == selector["kind"].lower()]
        what = f"of kind {selector['kind']}"
    elif "tag" in selector:
        out = [r for r in names if selector["tag"].lower() in
               [str(t).lower() for t in _robot_of(robots, r).get("tags") or []]]
        what = f"tagged {selector['tag']}"
    elif "extreme" in selector:
        skill = selector["skill"]
        levels = {r: float((_robot_of(robots, r).get("skills") or {}).get(skill, 0) or 0) for r in names}
        if not levels:
            out = []
        else:
            best = max(levels.values()) if selector["extreme"] == "max" else min(levels.values())
            out = [r for r in names if levels[r] == best]
        what = f"with the {'highest' if selector['extreme'] == 'max' else 'lowest'} {skill}"
    elif "skill" in selector:
        skill = selector["skill"]
        lo, hi = selector.get("at_least"), selector.get("at_most")
        out = []
        for r in names:
            level = float((_robot_of(robots, r).get("skills") or {}).get(skill, 0) or 0)
            if (lo is None or level >= lo) and (hi is None or level <= hi):
                out.append(r)
        what = f"with {skill} {'>= ' + str(lo) if lo is not None else '<= ' + str(hi)}"
    else:
        raise TranslationError(f"'{words}': cannot tell which robots")
    if not out:
        raise Refusal(f"'{words}': this world has no robot {what}")
    return out


def _superlative_and_noun(words: str) -> tuple[str, str]:
    """The superlative as said ("strongest") and the word after it ("robots", "one", ""), of the
    words of a robot group."""
    said = words.lower().split()
    k = next((i for i, w in enumerate(said) if w in SUPER_WORDS), len(said))
    return (said[k] if k < len(said) else ""), (said[k + 1] if k + 1 < len(said) else "")

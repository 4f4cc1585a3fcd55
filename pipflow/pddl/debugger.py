"""The paper's Debugger: parse a problem against the domain and say, in words a model can act on,
what is wrong and where.

UP's PDDLReader does all the parsing. Its errors are precise but terse (a pyparsing position, a
``SyntaxError`` with a character span, a ``KeyError`` for an unknown type); this module turns each
into one message with the line and column, the offending token, what was expected, and for an
undefined name the closest names that do exist (difflib). A problem that parses is then checked
against the world by the world's task domain (:meth:`pipflow.taskdomain.TaskDomain.world_mismatches`):
its objects and initial state must be exactly the world's, because a generated problem that
invents a shelf or a few units of stock would be "solved" in a world that is not ours. Every
mismatch is reported at once (the warehouse's check: :func:`pipflow.warehouse.problem.world_mismatches`).
"""
from __future__ import annotations

import re
from dataclasses import dataclass, field
from typing import Any

from pipflow.pddl.common import parse, read_domain_text
from pipflow.pddl.size import expected_size, size_issues
from pipflow.pddl.textpos import find_word, line_col, strip_comments
from pipflow.suggest import did_you_mean_clause
from pipflow.taskdomains import task_domain

_SPAN = re.compile(r"line: (\d+), col (\d+) to line: (\d+), col (\d+)")
_TOKEN = re.compile(r"[^\s()]+|[()]")


@dataclass
class DebugReport:
    """``ok`` when the problem parses and matches the world; ``messages`` otherwise."""

    ok: bool
    messages: list[str] = field(default_factory=list)
    problem: Any = None  # the parsed UP problem when it parsed


# ---------------------------------------------------------------------------------------------
# text helpers (positions only: no parsing here)
# ---------------------------------------------------------------------------------------------
def _offset(text: str, line: int, col: int) -> int:
    lines = text.splitlines(keepends=True)
    return sum(len(x) for x in lines[: line - 1]) + col - 1


def _token_at(text: str, offset: int) -> str:
    m = _TOKEN.search(text, offset)
    return m.group(0) if m else "end of text"


def paren_hint(text: str) -> str:
    """Where parentheses stop balancing, if they do: the most common syntax slip."""
    clean = strip_comments(text)
    stack: list[int] = []
    for i, ch in enumerate(clean):
        if ch == "(":
            stack.append(i)
        elif ch == ")":
            if not stack:
                line, col = line_col(text, i)
                return f" There is an extra ')' at line {line}, column {col}."
            stack.pop()
    if stack:
        line, col = line_col(text, stack[-1])
        return (f" {len(stack)} '(' never closed; the innermost unclosed one is at line {line}, "
                f"column {col}: {text.splitlines()[line - 1].strip()!r}.")
    return ""


#: what a problem's sections are called in messages ("the (:objects list ... is never closed")
_SECTION_WORD = {":objects": "list", ":init": "list"}


def unclosed_section(text: str) -> str:
    """A message for a problem section that is never closed, or ``""``.

    Sections (``(:objects``, ``(:init``, ``(:goal``, ...) are siblings inside ``(define``: one
    that opens while another is still open means the other was never closed. Naming it and where
    it opened is the useful message; the parser only notices later ("Expected ':init'") and points
    at the wrong place. A section still open at the end of the text is reported the same way,
    with its innermost unclosed '(' when that is not the section itself."""
    clean = strip_comments(text)
    stack: list[tuple[int, str]] = []  # (offset of '(', its head token)
    last_child: dict[int, tuple[int, int]] = {}  # section offset -> (start, end) of its last child form
    for i, ch in enumerate(clean):
        if ch == "(":
            head = _token_at(clean, i + 1).lower()
            if head.startswith(":"):
                open_section = next(((o, h) for o, h in reversed(stack) if h.startswith(":")), None)
                if open_section is not None:
                    return _never_closed(text, open_section, stack, last_child.get(open_section[0]),
                                         f"the ({head} on line {{l}}, column {{c}} starts inside it; close it "
                                         f"with ')' before ({head}", i)
            stack.append((i, head))
        elif ch == ")" and stack:
            start, _ = stack.pop()
            if stack and stack[-1][1].startswith(":"):
                last_child[stack[-1][0]] = (start, i)
    open_section = next(((o, h) for o, h in stack if h.startswith(":")), None)
    if open_section is not None:
        return _never_closed(text, open_section, stack, last_child.get(open_section[0]), "the text ends first", None)
    return ""


def _never_closed(text: str, section: tuple[int, str], stack: list[tuple[int, str]],
                  child: tuple[int, int] | None, why: str, at: int | None) -> str:
    """The message of :func:`unclosed_section`: the section and where it opened, why it is
    known to be open, and the likely missing ')': the innermost '(' still open in it, or its last
    form when that form runs over several lines (it took the section's ')' for its own)."""
    offset, head = section
    line, col = line_col(text, offset)
    if at is not None:
        l2, c2 = line_col(text, at)
        why = why.format(l=l2, c=c2)
    inner = stack[-1][0]
    extra = ""
    if inner != offset:
        il, ic = line_col(text, inner)
        extra = (f" The innermost '(' left open in it is at line {il}, column {ic}: "
                 f"{text.splitlines()[il - 1].strip()!r}.")
    elif child is not None:
        (cl, cc), (el, _) = line_col(text, child[0]), line_col(text, child[1])
        if el > cl:
            first = text[child[0]:].splitlines()[0].strip()
            extra = (f" Its last form, {first!r} (line {cl}, column {cc}), runs on to line {el}: "
                     "a ')' is probably missing in it.")
    return (f"line {line}, column {col}: the ({head} {_SECTION_WORD.get(head, 'section')} opened on line {line}, "
            f"column {col} is never closed: {why}.{extra}")


def find_form(text: str, head: str, *args: str) -> str:
    """``"line L, column C"`` of the first ``(head args...)`` in ``text``, or ``""``."""
    pattern = r"\(\s*" + r"\s+".join(re.escape(x) for x in (head,) + args) + r"\s*\)"
    m = re.search(pattern, strip_comments(text), flags=re.IGNORECASE)
    if not m:
        return ""
    line, col = line_col(text, m.start())
    return f"line {line}, column {col}: "


# ---------------------------------------------------------------------------------------------
# context: the domain's signatures and the problem's declared objects
# ---------------------------------------------------------------------------------------------
def _type_name(t: Any) -> str:
    """``place``, not UP's ``place - entity`` for a subtype."""
    return getattr(t, "name", None) or str(t)


def domain_signatures(domain_text: str) -> tuple[dict[str, list[tuple[str, str]]], list[str]]:
    """``({fluent: [(param, type), ...]}, [type names])`` of the domain, read by UP."""
    dom = parse(domain_text, None)
    sigs = {f.name: [(p.name, _type_name(p.type)) for p in f.signature] for f in dom.fluents}
    return sigs, [_type_name(t) for t in dom.user_types]


def type_lineage(domain_text: str) -> dict[str, set[str]]:
    """``{type: {type, its parent, ...}}``: a ``place`` may stand where an ``entity`` is asked."""
    out: dict[str, set[str]] = {}
    for t in parse(domain_text, None).user_types:
        names, f = {_type_name(t)}, getattr(t, "father", None)
        while f is not None:
            names.add(_type_name(f))
            f = getattr(f, "father", None)
        out[_type_name(t)] = names
    return out


def declared_objects(problem_text: str) -> dict[str, str]:
    """``{object: type}`` as the problem declares them (UP's PDDL grammar; {} if it fails)."""
    from unified_planning.io.pddl_reader import PDDLGrammar

    try:
        res = PDDLGrammar().problem.parse_string(problem_text, parse_all=True)
    except Exception:
        return {}
    out = {}
    for group in res["objects"]:
        names, typ = list(group[0]), (group[1] if len(group) > 1 else "object")
        for n in names:
            out[str(n)] = str(typ)
    return out


def _signature_text(name: str, sig: list[tuple[str, str]]) -> str:
    return f"({name} {' '.join(f'?{p} - {t}' for p, t in sig)})"


# ---------------------------------------------------------------------------------------------
# turning UP's exceptions into messages
# ---------------------------------------------------------------------------------------------
def explain_parse_error(exc: Exception, text: str, domain_text: str) -> str:
    """One actionable message for a PDDLReader failure on ``text``."""
    sigs, types = domain_signatures(domain_text)
    objects = declared_objects(text)

    if type(exc).__name__ in ("ParseException", "ParseSyntaxException", "ParseFatalException"):
        unclosed = unclosed_section(text)
        if unclosed:
            return unclosed
        line, col = getattr(exc, "lineno", 0), getattr(exc, "col", 0)
        loc = getattr(exc, "loc", None)
        token = _token_at(text, loc) if loc is not None else "?"
        expected = re.sub(r"\s*\(at char \d+\).*$", "", getattr(exc, "msg", str(exc)))
        expected = re.sub(r",?\s*found .*$", "", expected)
        source = text.splitlines()[line - 1].strip() if 0 < line <= len(text.splitlines()) else ""
        return (f"line {line}, column {col}: syntax error at {token!r}: {expected.strip()}."
                + (f" Line {line} reads: {source!r}." if source else "") + paren_hint(text))

    message = str(exc)
    span = _SPAN.search(message)
    where, snippet = "", ""
    if span:
        l1, c1, l2, c2 = map(int, span.groups())
        where = f"line {l1}, column {c1}: "
        snippet = text[_offset(text, l1, c1): _offset(text, l2, c2) + 1].strip()

    if isinstance(exc, SyntaxError) or type(exc).__name__ == "SyntaxError":
        m = re.search(r"Found invalid expression: (\S+?)\.? From", message)
        if m:
            name = m.group(1)
            return (f"{where}undefined name {name!r}: it is not an object of the problem"
                    f"{did_you_mean_clause(name, list(objects))} (objects: {', '.join(objects) or 'none'})")
        m = re.search(r"fluent: (\S+) has arity (\d+) but (\d+) parameters", message)
        if m:
            name, want, got = m.group(1), int(m.group(2)), int(m.group(3))
            sig = _signature_text(name, sigs.get(name, []))
            return f"{where}wrong arity in {snippet!r}: {name} takes {want} argument(s) {sig}, not {got}"
        if "not well-formed" in message and snippet:
            toks = _TOKEN.findall(snippet)
            head, args = (toks[1], [t for t in toks[2:] if t not in "()"]) if len(toks) > 2 else ("", [])
            if head in sigs:
                lineage = type_lineage(domain_text)
                wrong = [f"argument {i + 1} of {head} must be a {t}, but {a!r} is a {objects.get(a, 'undeclared name')}"
                         for i, ((_, t), a) in enumerate(zip(sigs[head], args))
                         if t not in lineage.get(objects.get(a, ""), {objects.get(a)})]
                if wrong:
                    return f"{where}wrong type in {snippet!r}: " + "; ".join(wrong) + f"; signature {_signature_text(head, sigs[head])}"
            return f"{where}wrong type in {snippet!r}: the arguments do not match the signature"
        m = re.search(r"Not able to handle: \(\s*([^\s()]+)", message)
        if m:
            head = m.group(1)
            if head not in sigs:
                return (f"{where}unknown function or predicate {head!r} in {snippet!r}{did_you_mean_clause(head, list(sigs))} "
                        f"(the domain declares {', '.join(_signature_text(n, s) for n, s in sigs.items())})")
            return f"{where}cannot read {snippet!r}: expected a fluent, a number or a comparison"
        return f"{where}{message.splitlines()[0]}" + (f" in {snippet!r}" if snippet else "")

    if isinstance(exc, KeyError):
        name = str(exc.args[0]) if exc.args else str(exc)
        where = find_word(text, name)
        return (f"{where}unknown type {name!r}{did_you_mean_clause(name, types)} "
                f"(the domain's types: {', '.join(types)})")
    m = re.search(r"Name (\S+) already defined", message)
    if m:
        name = m.group(1)
        where = find_word(text, name, 1) or find_word(text, name)
        return f"{where}name {name!r} is declared twice; declare each object once"
    return f"the problem does not parse: {type(exc).__name__}: {message.splitlines()[0] if message else ''}"


# ---------------------------------------------------------------------------------------------
# entry point
# ---------------------------------------------------------------------------------------------
def debug_problem(problem_text: str | None, domain: str, world: dict | None = None) -> DebugReport:
    """Parse ``problem_text`` against ``domain`` (a path or PDDL text) and check it against
    ``world``. Never raises for a bad problem: the messages say what is wrong."""
    if not problem_text or not problem_text.strip():
        return DebugReport(False, ["the problem is empty: write a (define (problem ...) ...) form"])
    domain_text = read_domain_text(domain)
    # what it would cost to parse, before parsing (a 270 KB answer of 40,000 objects: 156 s)
    example = task_domain(world).example_problem(world, domain_text) if world is not None else None
    expected = expected_size(world, example)
    too_large = size_issues(problem_text, expected, "the problem")
    if too_large:
        return DebugReport(False, too_large)
    try:
        parse(domain_text, None)
    except Exception as exc:  # the domain is ours: a failure here is a setup problem, say so
        return DebugReport(False, [f"the domain itself does not parse ({domain}): {exc}"])
    try:
        problem = parse(domain_text, problem_text)  # memoised: solve, verify and graph reuse it
    except Exception as exc:
        return DebugReport(False, [explain_parse_error(exc, problem_text, domain_text)])
    messages: list[str] = []
    m = re.search(r"\(\s*:domain\s+([^\s()]+)", strip_comments(problem_text), flags=re.IGNORECASE)
    dname = re.search(r"\(\s*domain\s+([^\s()]+)", strip_comments(domain_text), flags=re.IGNORECASE)
    if m and dname and m.group(1).lower() != dname.group(1).lower():
        messages.append(f"{find_word(problem_text, m.group(1))}the problem names domain {m.group(1)!r} "
                        f"but the domain is {dname.group(1)!r}")
    if world is not None:  # objects and initial state against the world: its task domain's check
        messages += task_domain(world).world_mismatches(problem, problem_text, world)
    return DebugReport(not messages, messages, problem)

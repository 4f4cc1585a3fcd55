"""Optional symbols of a lark grammar as nullable rules, for both domains' Earley parsers.

Why a module of its own: the warehouse's and the household's command grammars are both written
with many optional words, and both parsers are built from the grammar as
:func:`nullable_optionals` rewrites it (the same readings: ``tests/test_optionals.py``).
"""
from __future__ import annotations

import re


def nullable_optionals(grammar: str) -> str:
    """The grammar with each optional symbol ``x?`` replaced by a nullable rule ``_opt_x``.

    Lark expands every ``x?`` into two alternatives, so a production with five optional words
    becomes 32, and Earley then carries all of them at every word: the parse got slower by two
    orders of magnitude. A nullable rule is one symbol whatever follows it. Rules whose name
    starts with ``_`` are inlined by lark, so the tree keeps its shape.
    """
    made: dict[str, str] = {}

    def opt(m: re.Match) -> str:
        sym = m.group(1)
        prefix = "kw_" if sym.startswith('"') else ""
        said = sym.strip('"').lower()
        key = re.sub(r"[^a-z0-9_]", "_", said)
        if key != said:
            # a mark ("," or ":") has no letters to name it by: the two were one rule, so that
            # every ":"? of the grammar read as ","? (the name says the literal, in hex)
            key += "_" + said.encode().hex()
        name = f"_opt_{prefix}{key}"
        made[name] = sym
        return name

    groups: dict[str, str] = {}

    def group(m: re.Match) -> str:
        body = m.group(1)
        name = groups.get(body)
        if name is None:
            name = groups[body] = f"_grp{len(groups)}"
        return name

    text = "\n".join(line.partition("//")[0] for line in grammar.splitlines())
    # a group "(a | b)" is a rule of its own too, for the same reason (innermost first)
    while True:
        new = re.sub(r"\(([^()]*)\)", group, text)
        if new == text:
            break
        text = new
    text += "\n" + "\n".join(f"{name}: {body}" for body, name in groups.items())
    lines = [re.sub(r'("[^"]+"|\b[A-Za-z_][A-Za-z0-9_]*)\?', opt, line) for line in text.splitlines()]
    extra = [f"{name}: {sym} | " for name, sym in made.items()]
    return "\n".join(lines + extra) + "\n"

"""A team-level PDDL domain's actions as the skills a baseline's model may call.

The baselines plan with the actions of the team-level domain PIP-LLM plans with, each done by
robots the model names. Their papers call such actions skills: SMART-LLM writes them as
Python-like calls (``SwitchOff(robots[0], 'light', 'light')``), CoT and LaMMA-P as PDDL actions. One vocabulary for all three, read from the domain itself (UP), so a plugin's domain
gives its baselines their skills with no code.
"""
from __future__ import annotations

import re
from dataclasses import dataclass

from pipflow.errors import InputError, PDDLError
from pipflow.liberrors import UNIFIED_PLANNING, library_errors
from pipflow.pddl.common import parse


@dataclass(frozen=True)
class Skill:
    """One action of the domain: its PDDL name, its name as a call (CamelCase, as SMART-LLM
    writes skills), its parameters (without ``?``) and their PDDL types."""

    action: str
    call: str
    params: tuple[str, ...]
    types: tuple[str, ...]

    def signature(self) -> str:
        """``Carry(robots, i, from, to)``: how the prompt shows it as a call."""
        return f"{self.call}(robots, {', '.join(self.params)})" if self.params else f"{self.call}(robots)"

    def pddl(self) -> str:
        """``(carry ?i ?from ?to)``: how the prompt shows it as a PDDL action."""
        return f"({' '.join([self.action] + ['?' + p for p in self.params])})"


def call_name(action: str) -> str:
    """``switch-off`` -> ``SwitchOff``: a PDDL action name as a Python-like call name."""
    return "".join(part[:1].upper() + part[1:] for part in re.split(r"[-_]+", action) if part)


def domain_skills(domain_text: str) -> list[Skill]:
    """Every action of the PDDL domain, in the domain's order. Two actions whose call names
    collide (``pick-up`` and ``pick_up``) are refused: a call must name one action."""
    with library_errors(UNIFIED_PLANNING, PDDLError, "reading the domain's actions"):
        domain = parse(domain_text, None)
    skills = [Skill(a.name, call_name(a.name), tuple(p.name for p in a.parameters),
                    tuple(getattr(p.type, "name", str(p.type)) for p in a.parameters)) for a in domain.actions]
    seen: dict[str, str] = {}
    for s in skills:
        if s.call in seen:
            raise InputError(f"the domain's actions {seen[s.call]!r} and {s.action!r} have the same call name "
                             f"{s.call!r}; rename one")
        seen[s.call] = s.action
    return skills

"""Shared unified-planning plumbing: one quiet environment, parsing, plan conversion.

Every PDDL parse, solve and validation in pipflow goes through unified-planning (UP); this module
keeps the few conversions between UP objects and pipflow's JSON-like data in one place.
A plan, between steps, is ``[{"action": "move-product", "args": ["shelf1", "shelf3", ...]}]``.
"""
from __future__ import annotations

from functools import lru_cache
from pathlib import Path
from typing import Any


@lru_cache(maxsize=1)
def environment() -> Any:
    """UP's global environment with the credits banner silenced and pipflow's engines added."""
    from unified_planning.shortcuts import get_environment

    env = get_environment()
    env.credits_stream = None
    env.error_used_name = True
    from pipflow.pddl.transport import register

    register(env)
    return env


def read_domain_text(domain: str | Path) -> str:
    """The domain's text; ``domain`` is a path (PDDL text itself is accepted too)."""
    s = str(domain)
    if "(define" in s:
        return s
    return Path(s).read_text()


def parse(domain: str | Path, problem_text: str) -> Any:
    """Parse ``problem_text`` against ``domain`` with UP's PDDLReader; exceptions propagate
    (the debugger turns them into messages)."""
    from unified_planning.io import PDDLReader

    environment()
    return PDDLReader().parse_problem_string(read_domain_text(domain), problem_text)


def plan_to_data(plan: Any) -> list[dict]:
    """UP SequentialPlan -> pipflow plan list."""
    return [{"action": ai.action.name, "args": [str(p) for p in ai.actual_parameters]}
            for ai in plan.actions]


def data_to_plan(problem: Any, plan: list[dict]) -> Any:
    """pipflow plan list -> UP SequentialPlan over ``problem``; raises ``ValueError`` naming the
    first step that uses an unknown action or object, or the wrong number of arguments."""
    from unified_planning.plans import ActionInstance, SequentialPlan

    from pipflow.pddl.names import pddl_name

    actions = []
    for i, item in enumerate(plan, 1):
        name, args = item.get("action"), list(item.get("args") or [])
        if not problem.has_action(name):
            raise ValueError(f"plan step {i}: unknown action {name!r}")
        action = problem.action(name)
        if len(args) != len(action.parameters):
            raise ValueError(f"plan step {i}: {name} takes {len(action.parameters)} arguments, got {len(args)}")
        objs = []
        for a in args:
            a_pddl = a if problem.has_object(a) else pddl_name(a)  # plans keep the world's spelling
            if not problem.has_object(a_pddl):
                raise ValueError(f"plan step {i}: unknown object {a!r}")
            objs.append(problem.object(a_pddl))
        actions.append(ActionInstance(action, objs))
    return SequentialPlan(actions)


def format_plan(plan: list[dict]) -> str:
    """The plan as PDDL-style lines, ``(move-product shelf1 shelf3 product1 magnitude2)``."""
    return "".join(f"({p['action']} {' '.join(p['args'])})\n" for p in plan)


def initial_numbers(problem: Any) -> dict[tuple, float]:
    """Explicit initial numeric values: ``{(fluent, arg, ...): value}``."""
    out = {}
    for fexp, value in problem.explicit_initial_values.items():
        if fexp.is_fluent_exp() and (value.is_int_constant() or value.is_real_constant()):
            v = value.constant_value()
            key = (fexp.fluent().name,) + tuple(str(a) for a in fexp.args)
            out[key] = int(v) if float(v).is_integer() else float(v)
    return out


def goal_conditions(problem: Any) -> list[Any]:
    """The problem's goal as a flat list of conditions (nested ``and`` opened, order kept)."""
    out: list[Any] = []
    stack = list(problem.goals)
    while stack:
        g = stack.pop(0)
        if g.is_and():
            stack[:0] = list(g.args)
        else:
            out.append(g)
    return out


def stock_goals(problem: Any) -> tuple[dict[str, dict[str, int]], list[str]]:
    """Goal counts ``(= (stock s p) n)`` as ``{shelf: {product: n}}``, plus a list of goal
    conditions of any other form (as text) that pipflow's goal checks do not understand."""
    goal: dict[str, dict[str, int]] = {}
    other: list[str] = []
    for g in goal_conditions(problem):
        if g.is_equals():
            a, b = g.args
            if b.is_fluent_exp():
                a, b = b, a
            if (a.is_fluent_exp() and a.fluent().name == "stock" and len(a.args) == 2
                    and (b.is_int_constant() or b.is_real_constant())):
                v = b.constant_value()
                if float(v).is_integer():
                    goal.setdefault(str(a.args[0]), {})[str(a.args[1])] = int(v)
                    continue
        other.append(str(g))
    return goal, other

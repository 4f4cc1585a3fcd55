"""Between unified-planning objects and pipflow's data: plans as lists of ``{"action", "args"}``
and a problem's initial numbers as a dict.

Why a module of its own: the planners (the transport engine among them) and the UP environment
setup in :mod:`pipflow.pddl.common` both need these conversions; here they sit below both.
"""
from __future__ import annotations

from typing import Any

from pipflow.pddl.names import pddl_name


def plan_to_data(plan: Any) -> list[dict]:
    """UP SequentialPlan -> pipflow plan list."""
    return [{"action": ai.action.name, "args": [str(p) for p in ai.actual_parameters]}
            for ai in plan.actions]


def data_to_plan(problem: Any, plan: list[dict]) -> Any:
    """pipflow plan list -> UP SequentialPlan over ``problem``; raises ``ValueError`` naming the
    first step that uses an unknown action or object, or the wrong number of arguments."""
    from unified_planning.plans import ActionInstance, SequentialPlan


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


def initial_numbers(problem: Any) -> dict[tuple, float]:
    """Explicit initial numeric values: ``{(fluent, arg, ...): value}``."""
    out = {}
    for fexp, value in problem.explicit_initial_values.items():
        if fexp.is_fluent_exp() and (value.is_int_constant() or value.is_real_constant()):
            v = value.constant_value()
            key = (fexp.fluent().name,) + tuple(str(a) for a in fexp.args)
            out[key] = int(v) if float(v).is_integer() else float(v)
    return out

"""The paper's Verifier: is the plan valid for the problem, and is the goal one the world allows?

Two independent checks, both reported in full:

* **Plan**: UP's ``sequential_plan_validator``, named explicitly (with some engines installed UP
  would otherwise pick another validator). For an inapplicable action the message adds the values
  of the fluents in its failed precondition at that point, e.g. ``stock(shelf4, product2) = 0``,
  which is what a model needs to repair the problem.
* **Goal** (against the world): the world's task domain judges it
  (:meth:`pipflow.taskdomain.TaskDomain.check_goal`; the warehouse's is
  :func:`pipflow.warehouse.problem.goal_problems`). A goal no plan can reach in this world yields
  ``refusal``: the reason, in words, that the command cannot be done; the workflow ends there
  instead of looping.
"""
from __future__ import annotations

import re
from dataclasses import dataclass, field
from typing import Any

from pipflow.pddl.common import environment, format_plan
from pipflow.pddl.convert import data_to_plan
from pipflow.taskdomains import task_domain

_FLUENT = re.compile(r"([A-Za-z][\w-]*)\(([^()]*)\)")


@dataclass
class VerifyReport:
    ok: bool
    messages: list[str] = field(default_factory=list)
    refusal: str | None = None
    goal: dict = field(default_factory=dict)


def _explain_inapplicable(problem: Any, plan: Any, index: int, ups_message: str) -> str:
    """UP's message plus the values, just before step ``index``, of the fluents it mentions."""
    from unified_planning.shortcuts import SequentialSimulator

    try:
        with SequentialSimulator(problem=problem) as sim:
            state = sim.get_initial_state()
            for ai in plan.actions[:index]:
                state = sim.apply(state, ai)
            em = problem.environment.expression_manager
            values = []
            for name, args in dict.fromkeys(_FLUENT.findall(ups_message)):
                if not problem.has_fluent(name):
                    continue
                objs = [problem.object(a.strip()) for a in args.split(",") if a.strip()]
                values.append(f"{name}({', '.join(o.name for o in objs)}) = {state.get_value(em.FluentExp(problem.fluent(name), objs))}")
    except Exception:
        return ups_message
    return ups_message + (f" At that point {', '.join(values)}." if values else "")


def verify_plan(problem: Any, plan: list[dict] | None, world: dict | None = None) -> VerifyReport:
    """Validate ``plan`` on UP ``problem`` and check the problem's goal against ``world``."""
    from unified_planning.engines import ValidationResultStatus
    from unified_planning.shortcuts import PlanValidator

    environment()
    judged = task_domain(world).check_goal(problem, world)  # the goal against the world: the domain's
    goal, messages, refusal = judged.goal, list(judged.messages), judged.refusal
    if plan is None:
        messages.append("there is no plan to verify (the planner did not produce one)")
    else:
        try:
            up_plan = data_to_plan(problem, plan)
        except ValueError as exc:
            messages.append(f"the plan does not fit the problem: {exc}")
            up_plan = None
        if up_plan is not None:
            with PlanValidator(name="sequential_plan_validator") as validator:
                check = validator.validate(problem, up_plan)
            if check.status != ValidationResultStatus.VALID:
                ups = " ".join(m.message for m in check.log_messages or []) or str(check.reason)
                if check.inapplicable_action is not None:
                    index = next((i for i, ai in enumerate(up_plan.actions) if ai is check.inapplicable_action), None)
                    if index is None:
                        index = next((i for i, ai in enumerate(up_plan.actions) if str(ai) == str(check.inapplicable_action)), 0)
                    messages.append(f"plan step {index + 1} {format_plan([plan[index]]).strip()} cannot be executed: "
                                    + _explain_inapplicable(problem, up_plan, index, ups))
                else:
                    messages.append(f"the plan is not valid: {ups}")
    return VerifyReport(not messages and refusal is None, messages, refusal, goal)

"""One run's score, the same definitions in every task domain: success, GCR, Exe, RU, TC and the
violations, from the facts a domain's scoring hooks give (its initial state, the goal's
conditions in a state, RU's reference, the rules and checks of its own).

Why one function: each domain once wrote its own score and they drifted (a run whose right
answer was a refusal, not refused, had the simulation's Exe in one domain and 0 in another). The
metrics mean what :mod:`pipflow.metrics` says; which tasks expect a refusal,
:func:`pipflow.values.refusal_expected`. :meth:`pipflow.taskdomain.TaskDomain.score` and
``score_bench_run`` call it.
"""
from __future__ import annotations

from typing import Any, Iterable, Mapping

from pipflow.metrics import goal_condition_recall, travel_costs
from pipflow.values import Score, flat_simulation


def score_run(domain: Any, world: dict, goal: Any, *, constraints: list[dict] | None = None,
              feasible: bool = True, graph: dict | None = None, schedule: dict | None = None,
              simulation: Mapping[str, Any] | None = None, refusal: str | None = None,
              error: str | None = None) -> tuple[Score, Any]:
    """The score of one run in ``domain`` (a :class:`pipflow.taskdomain.TaskDomain`: its scoring
    hooks give the facts) and RU's reference it used (a ``Reference``; None: none was needed).

    * A task whose right answer is a refusal (``feasible`` false) succeeds exactly when the run was
      refused with a reason and nothing was planned or executed; Exe is then 1, and otherwise the
      simulation's (what a run that was not refused executed, like any run's).
    * A run with no simulation (refused, or failed before executing) fails; its GCR is that of the
      world's initial state (:func:`pipflow.metrics.goal_condition_recall`: 0 when the goal asks
      for any change).
    * Otherwise it succeeds when every goal condition holds in the simulation's final state, no
      subtask was refused, no robot's legs jump, no task rule is broken and the domain finds
      nothing else wrong (its ``extra_violations``). GCR from the goal's conditions at the start
      and at the end; Exe = executed / planned; RU = ``min(1, reference / planned)``
      (a plan of 0 actions: 1 exactly when none is needed); TC from the simulated travel
      (:func:`pipflow.metrics.travel_costs`).
    """
    sim = flat_simulation(simulation)
    got: Mapping[str, Any] = sim or {}
    planned = len((schedule or {}).get("subtasks", []))
    executed = int(got.get("executed", 0))
    base = {"planned": planned, "executed": executed, "refused": bool(refusal), "error": refusal or error or None,
            "makespan": float(got.get("makespan", (schedule or {}).get("makespan", 0.0)) or 0.0)}
    if not feasible:
        ok = bool(refusal and str(refusal).strip()) and executed == 0 and planned == 0
        violations = [] if ok else (["infeasible command was not refused"] if not refusal else
                                    ["refusal has no reason"] if not str(refusal).strip() else
                                    ["actions were executed"])
        return {**base, "success": ok, "goal_met": ok, "gcr": 1.0 if ok else 0.0,
                "exe": 1.0 if ok else float(got.get("exe", 0.0) or 0.0), "ru": 1.0 if ok else 0.0,
                **travel_costs(got.get("travel") or {}), "lower_bound": None, "violations": violations}, None
    start = domain.initial_state(world)
    at_start = [c.holds for c in domain.goal_conditions(world, start, goal)]
    if sim is None:  # refused or failed before execution: nothing changed, nothing recalled
        why = "refused a feasible command" if refusal else f"run failed: {error}" if error else "no simulation"
        return {**base, "success": False, "goal_met": False, "gcr": goal_condition_recall(at_start, at_start),
                "exe": 0.0, "ru": 0.0, **travel_costs({}), "lower_bound": None, "violations": [why]}, None
    final = domain.final_state(sim)
    end = domain.goal_conditions(world, start if final is None else final, goal)
    violations = [f"goal: {c.words}" for c in end if not c.holds]
    violations += [f"{f.get('subtask')} {f.get('action')} refused: {'; '.join(f.get('reasons') or [])}"
                   for f in got.get("failures") or []]
    violations += jump_violations(got.get("jumps") or {})
    violations += domain.rule_violations(constraints, graph, schedule, world)
    violations += domain.extra_violations(world, sim, graph, schedule)
    ref = domain.reference(world, goal)
    lb = ref.actions
    ru = min(1.0, (lb or 0) / planned) if planned else (1.0 if lb == 0 else 0.0)
    return {**base, "success": not violations, "goal_met": all(c.holds for c in end),
            "gcr": goal_condition_recall(at_start, [c.holds for c in end]),
            "exe": float(got.get("exe", executed / planned if planned else 1.0)), "ru": ru,
            **travel_costs(got.get("travel") or {}), "lower_bound": lb, "violations": violations}, ref


def jump_violations(jumps: Mapping[str, Iterable[Mapping[str, Any]]]) -> list[str]:
    """A robot whose legs do not connect (it would have to jump): a broken schedule."""
    return [f"{robot} jumps {j['metres']:g} m" + (f" at t={j['time']:g}" if j.get("time") is not None else "")
            + " (legs do not connect)" for robot, js in jumps.items() for j in js]

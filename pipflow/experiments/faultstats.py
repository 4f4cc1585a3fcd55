"""The bench's view of runs under faults (``--faults``, ``--matrix faults=...``): per run, what
went wrong and how the run recovered; per variant, SR with and without the runs a fault made
impossible, the refusals after a fault (right when the goal was out of reach, wrong otherwise),
makespan and TC, and the seconds each recovery took.

Why SR needs a second denominator: a run that loses the only robot able to open the fridge
cannot meet its goal, and its right answer is a clear refusal. ``sr`` stays the share of runs
whose goal was met in the end (as without faults); ``sr_feasible`` is that share among the runs
whose goal was still reachable after the faults, as the task domain's feasibility check judged
it from the observed state (never assumed); ``refused_right`` counts the refusals of runs it
judged unreachable, ``refused_wrong`` those it judged reachable. Rows of runs without faults
gain no key, so a bench without faults reads exactly as before.

Why runs are set apart as **not applicable**: a fault drawn by count strikes a target the run
offers (a robot with work, a passage on a route, a place the plan takes from); a task whose plan
offers none (it slices an apple and carries nothing: no object surprise can matter) is carried
out without it (:mod:`pipflow.execution.faults`). Such a run says nothing about recovery from
that fault, so every number of the variant's fault row but ``runs`` is over the runs none of
whose faults was set apart (``applied``; a run that ended before execution, an impossible command
refused, stays in as before); ``not_applicable`` counts the others, and ``not_applicable_why``
says per fault kind why and for which runs.
"""
from __future__ import annotations

from statistics import mean
from typing import Any

from pipflow.metrics import counts_for_travel

#: the columns runs.csv gains when some run had faults
FAULT_FIELDS = ["faults", "faults_not_applicable", "fault_outcome", "feasible_after_faults", "recoveries",
                "recovery_actions", "recovery_seconds"]
#: a run's fault_outcome when some fault it asked for did not apply to it
NOT_APPLICABLE = "fault not applicable"


def fault_columns(outputs: dict, status: str) -> dict:
    """The row's fault columns from a run's outputs (none: the run had no faults and none was
    set aside as not applicable)."""
    faults = [f for f in outputs.get("faults") or [] if isinstance(f, dict)]
    skipped = [f for f in outputs.get("faults_not_applicable") or [] if isinstance(f, dict)]
    if not faults and not skipped:
        return {}
    rounds = [r for r in outputs.get("recoveries") or [] if isinstance(r, dict)]
    feasible = outputs.get("feasible_after_faults")
    if skipped:
        outcome = NOT_APPLICABLE
    elif status == "succeeded":
        outcome = "succeeded"
    elif status == "refused":
        outcome = {False: "refused: out of reach", True: "refused: still reachable"}.get(feasible, "refused: not judged")
    else:
        outcome = status
    return {"faults": [f.get("name") or f.get("kind") for f in faults],
            "faults_not_applicable": [f"{f.get('name') or f.get('kind')}: {f.get('why')}" for f in skipped],
            "fault_detail": [{k: f.get(k) for k in ("kind", "robot", "time", "occurred", "detected") if f.get(k) is not None}
                             for f in faults],
            "fault_outcome": outcome, "feasible_after_faults": feasible, "recoveries": len(rounds),
            "recovery_actions": [r.get("action") for r in rounds],
            "recovery_seconds": [r.get("seconds") for r in rounds if r.get("seconds") is not None]}


def fault_summary(rows: list[dict]) -> dict | None:
    """Per variant (module docstring); None when no run of it had faults or set one aside."""
    if not any(r.get("faults") or r.get("faults_not_applicable") for r in rows):
        return None
    apart = [r for r in rows if r.get("faults_not_applicable")]
    why: dict[str, dict[str, list[str]]] = {}
    for r in apart:
        for item in r["faults_not_applicable"]:
            kind, _, reason = str(item).partition(": ")
            why.setdefault(kind, {}).setdefault(reason, []).append(f"{r.get('task')} seed {r.get('seed')}")
    every = len(rows)
    rows = [r for r in rows if not r.get("faults_not_applicable")]  # the runs that had the variant's faults
    reachable = [r for r in rows if r.get("feasible_after_faults") is not False]
    refused = [r for r in rows if r.get("status") == "refused" and r.get("faults")]
    ok = [r for r in rows if r.get("success")]
    moved = [r for r in rows if counts_for_travel(r)]
    seconds = [s for r in rows for s in r.get("recovery_seconds") or []]
    actions: dict[str, int] = {}
    for r in rows:
        for a in r.get("recovery_actions") or []:
            actions[a] = actions.get(a, 0) + 1
    kinds = sorted({str(name) for r in rows for name in r.get("faults") or []} | set(why))
    return {
        "runs": every, "not_applicable": len(apart), "not_applicable_why": why, "applied": len(rows),
        "with_faults": sum(1 for r in rows if r.get("faults")), "kinds": kinds,
        "sr": len(ok) / len(rows) if rows else None,
        "reachable": len(reachable),
        "sr_feasible": sum(1 for r in reachable if r.get("success")) / len(reachable) if reachable else None,
        "refused_right": sum(1 for r in refused if r.get("feasible_after_faults") is False),
        "refused_wrong": sum(1 for r in refused if r.get("feasible_after_faults") is True),
        "failed": sum(1 for r in rows if r.get("status") not in ("succeeded", "refused")),
        # ran to its end believing it done, the goal not met in the world as it was (a surprise
        # at a place no robot went to): neither a success nor a refusal
        "unmet": sum(1 for r in rows if r.get("status") == "succeeded" and not r.get("success")),
        "makespan": _mean([r.get("makespan") for r in moved]),
        "tc_max": _mean([r.get("tc_max") for r in moved]),
        "tc_avg": _mean([r.get("tc_avg") for r in moved]),
        "recoveries": actions, "recovery_seconds_mean": _mean(seconds),
        "recovery_seconds_max": max(seconds) if seconds else None,
    }


def _mean(xs: list[Any]) -> float | None:
    xs = [float(x) for x in xs if isinstance(x, (int, float))]
    return mean(xs) if xs else None


def _f(x: Any, digits: int = 1) -> str:
    return "--" if x is None else f"{x:.{digits}f}"


def _pct(x: Any) -> str:
    return "--" if x is None else f"{100 * x:.0f}"


def fault_table(results: dict) -> str | None:
    """SR, SR where the goal stayed reachable, refusals, makespan, TC and recovery seconds per
    variant, side by side (variants without faults included, for the comparison), over the runs
    that had the variant's faults; the runs a fault did not apply to in a column of their own and
    a note saying why; None when no variant had faults."""
    variants = results.get("variants") or []
    if not any(v.get("faults") for v in variants):
        return None
    lines = ["### Faults and recovery", "",
             "| variant | faults | runs | fault not applicable | SR (%) | goal still reachable | SR where reachable (%) "
             "| clear refusals (out of reach) | refused though reachable | ended, goal unmet | failed | makespan (s) "
             "| TC max/avg (m) | recoveries | recovery s (mean/max) |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    notes: list[str] = []
    for v in variants:
        f = v.get("faults")
        s = v.get("summary") or {}
        if f is None:  # no faults: every run's goal was reachable
            lines.append(f"| {v['name']} | none | {s.get('runs')} | -- | {_pct(s.get('sr'))} | {s.get('runs')} "
                         f"| {_pct(s.get('sr'))} | 0 | 0 | -- | -- | {_f(_variant_makespan(v))} "
                         f"| {_f(s.get('tc_max'))}/{_f(s.get('tc_avg'))} | -- | -- |")
            continue
        acts = ", ".join(f"{k} {n}" for k, n in sorted(f["recoveries"].items())) or "none"
        lines.append(f"| {v['name']} | {', '.join(f.get('kinds') or []) or '?'} | {f['runs']} "
                     f"| {f.get('not_applicable', 0)} | {_pct(f['sr'])} "
                     f"| {f['reachable']} | {_pct(f['sr_feasible'])} | {f['refused_right']} | {f['refused_wrong']} "
                     f"| {f.get('unmet', 0)} | {f['failed']} | {_f(f['makespan'])} | {_f(f['tc_max'])}/{_f(f['tc_avg'])} | {acts} "
                     f"| {_f(f['recovery_seconds_mean'], 3)}/{_f(f['recovery_seconds_max'], 3)} |")
        notes += _not_applicable_notes(v["name"], f)
    if notes:
        lines += ["", "Every number of a row but `runs` is over the runs that had all of the variant's faults; "
                      "not applicable (run without that fault):"] + notes
    return "\n".join(lines) + "\n"


def _not_applicable_notes(variant: str, summary: dict) -> list[str]:
    """One line per (fault kind, reason): how many runs, which ones (the first few)."""
    out = []
    for kind, reasons in sorted((summary.get("not_applicable_why") or {}).items()):
        for reason, runs in sorted(reasons.items()):
            shown = ", ".join(runs[:6]) + (f", ... ({len(runs) - 6} more)" if len(runs) > 6 else "")
            out.append(f"- {variant}: {kind} not applicable: {len(runs)} run(s) ({shown}): {reason}")
    return out


def _variant_makespan(variant: dict) -> float | None:
    return _mean([t.get("makespan") for t in variant.get("tasks") or []])

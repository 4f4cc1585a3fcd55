"""The bench's arithmetic over scored runs: one row per task, one summary per variant
(``results.json``). The same for every domain: it reads only the flat score keys every domain's
scoring returns (``success``, ``gcr``, ``exe``, ``ru``, ``tc_max``, ``tc_avg``, ...), whose
meaning :mod:`pipflow.metrics` defines."""
from __future__ import annotations

from pipflow.metrics import counts_for_travel


def _mean(xs: list[float]) -> float | None:
    return sum(xs) / len(xs) if xs else None


def aggregate_task(task_id: str, scores: list[dict]) -> dict:
    """One row of ``results.json["tasks"]``: rates over all runs; TC and makespan over the
    successful runs that executed their task (:func:`pipflow.metrics.counts_for_travel`: a right
    refusal travelled nowhere and is not a 0 m run), None when there is none."""
    ok = [s for s in scores if counts_for_travel(s)]
    errors = [s["error"] for s in scores if s.get("error")]
    return {
        "id": task_id, "runs": len(scores),
        "sr": _mean([1.0 if s.get("success") else 0.0 for s in scores]) or 0.0,
        "gcr": _mean([float(s.get("gcr", 0.0)) for s in scores]) or 0.0,
        "exe": _mean([float(s.get("exe", 0.0)) for s in scores]) or 0.0,
        "ru": _mean([float(s.get("ru", 0.0)) for s in scores]) or 0.0,
        "tc_max": _mean([float(s["tc_max"]) for s in ok]),
        "tc_avg": _mean([float(s["tc_avg"]) for s in ok]),
        "tc_avg_team": _mean([float(s.get("tc_avg_team", 0.0)) for s in ok]),
        "makespan": _mean([float(s.get("makespan", 0.0)) for s in ok]),
        "error": errors[0] if errors else None,
    }


def summarize(rows: list[dict]) -> dict:
    """``results.json["summary"]`` from task rows: run-weighted rates, TC the mean over tasks that
    had a successful run that executed."""
    runs = sum(r["runs"] for r in rows)

    def wmean(key: str) -> float:
        return sum(r[key] * r["runs"] for r in rows) / runs if runs else 0.0

    return {"runs": runs, "sr": wmean("sr"), "gcr": wmean("gcr"), "exe": wmean("exe"), "ru": wmean("ru"),
            "tc_max": _mean([r["tc_max"] for r in rows if r.get("tc_max") is not None]),
            "tc_avg": _mean([r["tc_avg"] for r in rows if r.get("tc_avg") is not None]),
            "tc_avg_team": _mean([r["tc_avg_team"] for r in rows if r.get("tc_avg_team") is not None])}

"""A bench folder read once, as variants x tasks of runs, with each figure's value and its
confidence interval over seeds: what the bench report, the matrix view, ``pipflow compare`` and
the MLflow export all show, so they cannot disagree.

Values are the bench's own (``results.json``: the per-task rows and summaries ``pipflow bench``
computed); intervals come from the runs behind them (``runs.json``), by the rules of
:mod:`pipflow.records.intervals`: Wilson for shares of runs, Student t for means over seeds. The
``all tasks`` row's interval is over seeds: each seed's figure over every task (SR over that
seed's runs, TC over that seed's runs that count for travel), then the t-interval of those.
"""
from __future__ import annotations

import json
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from pipflow.errors import InputError
from pipflow.metrics import counts_for_travel, upgrade_results, upgrade_travel_keys
from pipflow.records.intervals import t_interval, wilson
from pipflow.yamlsource import read_source, safe_load


@dataclass(frozen=True)
class Metric:
    """One figure of a bench: its key in results.json and runs.json, how tables name it, its
    unit, and how it is averaged over runs (``share``: of runs that are true; ``travel``: over
    runs that count for travel; ``all``: over every run that has it)."""

    key: str
    label: str
    unit: str = ""
    kind: str = "all"  # share | travel | all
    lower_is_better: bool = False

    @property
    def percent(self) -> bool:
        return self.kind == "share"

    def heading(self) -> str:
        return self.label + (" (%)" if self.percent else f" ({self.unit})" if self.unit else "")


#: the figures of a bench, in the order tables show them
METRICS: list[Metric] = [
    Metric("sr", "SR", kind="share"),
    Metric("understood", "understood", kind="share"),
    Metric("gcr", "GCR"),
    Metric("exe", "Exe"),
    Metric("ru", "RU"),
    Metric("tc_max", "TC-max", "m", "travel", True),
    Metric("tc_avg", "TC-avg", "m", "travel", True),
    Metric("makespan", "makespan", "s", "travel", True),
    Metric("seconds", "time per run", "s", "all", True),
]
BY_KEY = {m.key: m for m in METRICS}
#: what a run's row calls the figure when it differs from results.json (SR is a run's success)
ROW_KEY = {"sr": "success"}


@dataclass
class Figure:
    """A value with its interval (None when there are fewer than two seeds) and how many runs
    it is over."""

    value: float | None
    interval: tuple[float, float] | None = None
    n: int = 0


@dataclass
class Bench:
    """One bench folder: its variants (in the bench's order), task ids, task rows per variant,
    summaries, run rows and configuration."""

    path: Path
    results: dict
    runs: list[dict]
    variants: list[str]
    task_ids: list[str]
    tasks: dict[str, dict[str, dict]]  # variant -> task id -> results.json task row
    summaries: dict[str, dict]  # variant -> summary
    config: dict = field(default_factory=dict)

    def runs_of(self, variant: str, task: str | None = None) -> list[dict]:
        return [r for r in self.runs if r.get("variant", "default") == variant
                and (task is None or str(r.get("task")) == task)]

    def run_folder(self, run: dict) -> Path | None:
        """The record of a run row inside this bench folder. Rows name it as the bench saw it (a
        path relative to where the bench ran, or absolute); the folder may have moved since, so it
        is looked up by its name under ``records/`` first."""
        text = run.get("run_dir")
        if not text or ":" in str(text).split("/")[0]:  # none, or on a worker that kept it (host:path)
            return None
        p = Path(str(text))
        for candidate in (self.path / "records" / p.name, self.path / p, p):
            if (candidate / "run.json").is_file():
                return candidate
        return None

    def figure(self, variant: str, task: str | None, metric: Metric) -> Figure:
        """``metric`` of one task (or of all tasks: ``task`` None) under ``variant``."""
        row = self.summaries.get(variant, {}) if task is None else self.tasks.get(variant, {}).get(task, {})
        value = _number(row.get(metric.key))
        runs = self.runs_of(variant, task)
        if not runs:
            return Figure(value, None, int(row.get("runs") or 0) if task is not None else 0)
        values = _run_values(runs, metric)
        if value is None and values:  # a figure results.json does not keep (time per run): the runs' mean
            value = sum(values) / len(values)
        if task is None:
            return Figure(value, _over_seeds(runs, metric), len(runs))
        if metric.kind == "share":
            return Figure(value, wilson(sum(1 for v in values if v), len(values)), len(values))
        return Figure(value, t_interval(values), len(values))


def _number(x: Any) -> float | None:
    return float(x) if isinstance(x, (int, float)) and not isinstance(x, bool) else None


def _run_values(runs: list[dict], metric: Metric) -> list[float]:
    """The per-run values a figure averages: shares as 0/1 (unmeasured runs left out), travel
    over the runs that count for travel."""
    key = ROW_KEY.get(metric.key, metric.key)
    out = []
    for r in runs:
        if metric.kind == "travel" and not counts_for_travel(r):
            continue
        v = r.get(key)
        if metric.kind == "share":
            if v is not None:
                out.append(1.0 if v else 0.0)
        elif isinstance(v, (int, float)) and not isinstance(v, bool):
            out.append(float(v))
    return out


def _over_seeds(runs: list[dict], metric: Metric) -> tuple[float, float] | None:
    by_seed: dict[Any, list[dict]] = {}
    for r in runs:
        by_seed.setdefault(r.get("seed"), []).append(r)
    per_seed = []
    for rows in by_seed.values():
        values = _run_values(rows, metric)
        if values:
            per_seed.append(sum(values) / len(values))
    return t_interval(per_seed)


def _read(path: Path) -> Any:
    try:
        return json.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return None


def read_bench(d: Path) -> Bench:
    """Read a bench folder (``results.json``, and ``runs.json`` when ``pipflow bench`` wrote it)."""
    results = _read(d / "results.json")
    if not isinstance(results, dict) or "tasks" not in results:
        raise InputError(f"{d / 'results.json'}: not a results file (needs 'summary' and 'tasks')")
    results = upgrade_results(results)
    runs = [upgrade_travel_keys(r) for r in (_read(d / "runs.json") or []) if isinstance(r, dict)]
    variants = results.get("variants") or [{"name": "default", "summary": results.get("summary", {}),
                                            "tasks": results.get("tasks", [])}]
    names = [str(v.get("name", "default")) for v in variants]
    tasks = {n: {str(t.get("id")): t for t in v.get("tasks", []) if isinstance(t, dict)} for n, v in zip(names, variants)}
    ids: list[str] = []
    for n in names:
        ids += [t for t in tasks[n] if t not in ids]
    return Bench(d, results, runs, names, ids, tasks, {n: v.get("summary") or {} for n, v in zip(names, variants)},
                 results.get("config") or {})


def fmt_value(value: float | None, metric: Metric) -> str:
    if value is None:
        return "-"
    return f"{100 * value:.0f}%" if metric.percent else f"{value:.2f}"


def fmt_interval(interval: tuple[float, float] | None, metric: Metric) -> str:
    if interval is None:
        return ""
    lo, hi = interval
    return f"[{100 * lo:.0f}, {100 * hi:.0f}]" if metric.percent else f"[{lo:.2f}, {hi:.2f}]"


def fmt_difference(a: float | None, b: float | None, metric: Metric) -> str:
    """``b - a`` in the metric's unit (percentage points for shares)."""
    if a is None or b is None:
        return ""
    d = b - a
    return f"{100 * d:+.0f} pp" if metric.percent else f"{d:+.2f}"


def task_fields(config: dict, bench: Path | None = None) -> dict[str, dict]:
    """Each task of the bench's task file by id, read back (empty when the file is gone). An
    older bench names it relative to where it ran: then it is looked for beside the bench folder
    and above it too."""
    name = str(config.get("tasks") or "")
    candidates = [Path(name)] + ([bench.parent / name, bench.parent.parent / name] if bench is not None and name
                                 and not Path(name).is_absolute() else [])
    doc = None
    for candidate in candidates:
        try:
            doc = safe_load(read_source(str(candidate), "task file"))
            break
        except Exception:  # a moved or damaged task file only loses what is read from it
            continue
    if not isinstance(doc, dict):
        return {}
    return {str(t.get("id")): t for t in (doc or {}).get("tasks", []) if isinstance(t, dict)}


def task_commands(config: dict, bench: Path | None = None) -> dict[str, str]:
    """Each task's command, read back from the bench's task file (empty when it is gone)."""
    return {tid: str(t.get("command", "")) for tid, t in task_fields(config, bench).items()}

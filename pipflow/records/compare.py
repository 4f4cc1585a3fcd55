"""Runs or benches side by side (``pipflow compare A B [C ...]`` and the view's compare page).

Why one module for both faces: the text table and the HTML table must show the same figures and
the same differences, so both are drawn from :func:`comparison`. Benches are compared **per
variant**: every variant of every bench is a column (a matrix bench of four variants is four
columns), never only the first; each figure carries its 95% interval over seeds where there are
several (:mod:`pipflow.records.intervals`), shares print as percents and their differences in
percentage points. Runs are compared output by output.
"""
from __future__ import annotations

import html
import json
from dataclasses import dataclass
from typing import Callable
from pathlib import Path
from typing import Any

from pipflow.errors import InputError
from pipflow.meaning import misread_cell
from pipflow.metrics import counts_for_travel, upgrade_travel_keys
from pipflow.records.benchread import METRICS, Bench, fmt_difference, fmt_interval, fmt_value, read_bench
from pipflow.records.intervals import LEVEL, STUDENT, WILSON
from pipflow.records.matrix import matrix_html

RUN_FIELDS = [("status", None), ("goal", None), ("constraints", None), ("rounds", None), ("engine", None),
              ("makespan", "s"), ("tc_max", "m"), ("tc_avg", "m"), ("tc_avg_team", "m"), ("goal_met", None),
              ("exe", None), ("seconds", "s"), ("tokens", None), ("cost_usd", "USD")]


def _read(path: Path) -> Any:
    try:
        return json.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return None


def kind_of(d: Path) -> str:
    if (d / "results.json").is_file():
        return "bench"
    if (d / "run.json").is_file():
        return "run"
    raise InputError(f"{d}: neither a run directory (run.json) nor a bench directory (results.json)")


def _run_facts(d: Path) -> dict[str, Any]:
    info = _read(d / "run.json") or {}
    outputs = upgrade_travel_keys(_read(d / "outputs.json") or {})  # records of before TC-avg had one definition
    metrics = _read(d / "metrics.json") or {}
    llm = metrics.get("llm") or {}
    facts = {"status": info.get("status"), "seconds": info.get("seconds"),
             "tokens": llm.get("total_tokens"), "cost_usd": llm.get("cost_usd")}
    for key, _ in RUN_FIELDS:
        if key in outputs:
            facts[key] = outputs[key]
    return facts


@dataclass(frozen=True)
class Column:
    """One thing compared: a run, or one variant of a bench."""

    label: str  # A, B, ... (with the variant's name when the bench has several)
    path: Path
    variant: str | None = None
    record: int = 0  # which of the records compared (the same folder may be given twice)


@dataclass
class Row:
    """One line of a comparison: the label, each column's value (text) and each further column's
    difference to the first (text; empty when equal or not comparable)."""

    label: str
    cells: list[str]
    diffs: list[str]

    @property
    def differs(self) -> bool:
        return any(d and d not in ("+0.00", "+0 pp", "-0.00", "-0 pp") for d in self.diffs)


@dataclass
class Comparison:
    kind: str  # run | bench
    columns: list[Column]
    rows: list[Row]
    note: str = ""


def _letter(i: int) -> str:
    return chr(ord("A") + i) if i < 26 else f"R{i + 1}"


def comparison(*records: Path) -> Comparison:
    """Compare two or more runs, or two or more benches (per variant)."""
    paths = [Path(r) for r in records]
    if len(paths) < 2:
        raise InputError("compare needs at least two records (runs, or benches)")
    kinds = [kind_of(p) for p in paths]
    if len(set(kinds)) > 1:
        i = kinds.index(next(k for k in kinds if k != kinds[0]))
        raise InputError(f"cannot compare a {kinds[0]} ({paths[0]}) with a {kinds[i]} ({paths[i]})")
    if kinds[0] == "run":
        return _compare_runs(paths)
    return _compare_benches(paths)


def _compare_runs(paths: list[Path]) -> Comparison:
    facts = [_run_facts(p) for p in paths]
    columns = [Column(_letter(i), p, None, i) for i, p in enumerate(paths)]
    rows = []
    for key, unit in RUN_FIELDS:
        values = [f.get(key) for f in facts]
        if all(v is None for v in values):
            continue
        rows.append(Row(key + (f" ({unit})" if unit else ""), [fmt(v) for v in values],
                        [_diff_text(values[0], v) for v in values[1:]]))
    return Comparison("run", columns, rows)


def _compare_benches(paths: list[Path]) -> Comparison:
    benches = [read_bench(p) for p in paths]
    columns: list[Column] = []
    for i, b in enumerate(benches):
        for v in b.variants:
            columns.append(Column(_letter(i) + (f" {v}" if len(b.variants) > 1 else ""), b.path, v, i))
    task_ids: list[str] = []
    for b in benches:
        task_ids += [t for t in b.task_ids if t not in task_ids]
    rows: list[Row] = []
    for tid in task_ids + [None]:
        name = "all tasks" if tid is None else tid
        for metric in METRICS:
            figs = [benches[c.record].figure(c.variant, tid, metric) if tid is None or tid in benches[c.record].task_ids
                    else None for c in columns]
            if all(f is None or f.value is None for f in figs):
                continue
            cells = [("" if f is None else (fmt_value(f.value, metric) + " " + fmt_interval(f.interval, metric)).strip())
                     for f in figs]
            first = figs[0].value if figs[0] is not None else None
            diffs = [fmt_difference(first, f.value if f is not None else None, metric) for f in figs[1:]]
            rows.append(Row(f"{name} {metric.heading()}", cells, diffs))
        counts = [(benches[c.record].summaries.get(c.variant, {}) if tid is None else
                   benches[c.record].tasks.get(c.variant, {}).get(tid)) for c in columns]
        if any(isinstance(x, dict) and x.get("misread") is not None for x in counts):
            cells = [misread_cell(x) if isinstance(x, dict) else "" for x in counts]
            rows.append(Row(f"{name} misread (executed)", cells, ["" if c == cells[0] else "differs" for c in cells[1:]]))
    seeds = sorted({int(b.config.get("seeds") or 1) for b in benches})
    note = (f"[lo, hi]: {int(LEVEL * 100)}% interval over seeds ({WILSON} for SR and understood, {STUDENT} "
            "for the others; the all-tasks row over each seed's figure)") if max(seeds) > 1 else \
        "one seed per task: no intervals (bench with --seeds 2 or more for them)"
    return Comparison("bench", columns, rows, note)


def _diff_text(a: Any, b: Any) -> str:
    if isinstance(a, (int, float)) and isinstance(b, (int, float)) and not isinstance(a, bool) and not isinstance(b, bool):
        d = b - a
        return f"{d:+.2f}" if isinstance(d, float) else f"{d:+d}"
    return "" if a == b else "differs"


def fmt(value: Any) -> str:
    if isinstance(value, float):
        return f"{value:.2f}" if abs(value) < 1e6 else f"{value:.3g}"
    if isinstance(value, (dict, list)):
        return json.dumps(value, separators=(", ", ": "))
    return "" if value is None else str(value)


def _keys(c: Comparison) -> list[str]:
    """Short column names for the text table: A, B, ... for records; A1, A2, ... for the variants
    of a bench that has several (the legend says which is which)."""
    out = []
    for col in c.columns:
        same = [x for x in c.columns if x.record == col.record]
        out.append(_letter(col.record) + (str(same.index(col) + 1) if len(same) > 1 else ""))
    return out


def compare_text(*records: Path) -> str:
    """The comparison for a terminal: one column per run (or per variant of each bench), each
    further column's difference to the first in brackets after its value."""
    c = comparison(*records)
    keys = _keys(c)
    lines = [("benches" if c.kind == "bench" else "runs") + (" (a column per variant)" if c.kind == "bench" else "") + ":"]
    for key, col in zip(keys, c.columns):
        lines.append(f"  {key} = {col.path}" + (f"  {col.variant}" if col.variant and col.variant != "default" else ""))
    table = [[r.label, r.cells[0]] + [f"{x} ({d})" if d else x for x, d in zip(r.cells[1:], r.diffs)] for r in c.rows]
    heads = [keys[0]] + [f"{k} ({k} - {keys[0]})" for k in keys[1:]]
    widths = [max([len(r[0]) for r in table] + [5])] + [
        min(60, max([len(h)] + [len(r[i + 1]) for r in table])) for i, h in enumerate(heads)]
    lines.append("  ".join([" " * widths[0]] + [h.rjust(w) for h, w in zip(heads, widths[1:])]))
    for r in table:
        lines.append("  ".join([r[0].ljust(widths[0])] + [(x if len(x) <= w else x[: w - 3] + "...").rjust(w)
                                                           for x, w in zip(r[1:], widths[1:])]))
    if c.note:
        lines.append(c.note)
    return "\n".join(lines)


def compare_html(*records: Path, links: list[str] | None = None,
                 run_link: Callable[[Bench, dict], str | None] | None = None) -> str:
    """The comparison as a page; ``links``: where each record's report is (the view's URLs);
    ``run_link``: the URL of a bench run's report (the matrix's seed links)."""
    c = comparison(*records)
    heads = "".join(f"<th>{html.escape(col.label)}</th>" for col in c.columns)
    body = "".join(
        f"<tr{' class=diff' if r.differs else ''}><td>{html.escape(r.label)}</td>"
        + f"<td class='num'>{html.escape(r.cells[0])}</td>"
        + "".join(f"<td class='num'>{html.escape(x)}" + (f"<br><span class='d'>{html.escape(d)}</span>" if d else "")
                  + "</td>" for x, d in zip(r.cells[1:], r.diffs)) + "</tr>" for r in c.rows)
    paths = [next(col.path for col in c.columns if col.record == i) for i in range(len(records))]
    legend = "".join(f"<li><b>{_letter(i)}</b>: " + (f"<a href='{html.escape(links[i])}'>" if links else "")
                     + f"<code>{html.escape(str(p))}</code>" + ("</a>" if links else "") + "</li>"
                     for i, p in enumerate(paths))
    matrix = ""
    if c.kind == "bench":
        matrix = matrix_html([read_bench(p) for p in paths], run_link or (lambda b, r: None))
    return ("<!DOCTYPE html><html lang='en'><head><meta charset='utf-8'><title>pipflow compare</title><style>"
            "body{font-family:sans-serif;margin:1.5em 2em} table{border-collapse:collapse}"
            "td,th{border:1px solid #ccc;padding:.3em .6em} th{background:#eef2f7} tr.diff td{background:#fff8e1}"
            "td.num{text-align:right;font-variant-numeric:tabular-nums} .small{color:#555;font-size:.9em}"
            ".d{color:#8a4b00;font-size:.85em}</style></head><body>"
            f"<h1>Compare {len(paths)} {'benches' if c.kind == 'bench' else 'runs'}</h1><ul>{legend}</ul>{matrix}"
            f"<h2>Side by side</h2><p class='small'>Under each value from the second column on: its difference "
            f"to the first column. {html.escape(c.note)}</p>"
            f"<table id='comparison'><tr><th></th>{heads}</tr>{body}</table></body></html>")


def variants_side_by_side(results: dict[str, Any], rows: list[dict[str, Any]]) -> str:
    """The variants of one bench next to each other, per task: SR, TC-max (mean and, over
    several seeds, min-max), makespan, time per run; then each further variant's TC-max and
    makespan difference to the first; a summary row last. Text for the terminal."""
    names = [v["name"] for v in results.get("variants", [])]
    if len(names) < 2:
        return ""
    task_ids = [t["id"] for t in results["variants"][0]["tasks"]]

    def cell(name: str, tid: str | None) -> tuple[str, float | None, float | None]:
        runs = [r for r in rows if r.get("variant") == name and (tid is None or r.get("task") == tid)]
        sr = 100 * sum(1 for r in runs if r.get("success")) / len(runs) if runs else 0.0
        ok = [r for r in runs if counts_for_travel(r)]  # travel: over successful runs that executed
        tc = [float(r["tc_max"]) for r in ok if isinstance(r.get("tc_max"), (int, float))]
        ms = [float(r["makespan"]) for r in ok if isinstance(r.get("makespan"), (int, float))]
        tc_mean = sum(tc) / len(tc) if tc else None
        ms_mean = sum(ms) / len(ms) if ms else None
        spread = f" ({min(tc):.1f}-{max(tc):.1f})" if len(tc) > 1 and max(tc) > min(tc) else ""
        text = f"{sr:3.0f}% {'-' if tc_mean is None else f'{tc_mean:.1f}'}{spread} m {'-' if ms_mean is None else f'{ms_mean:.1f}'} s"
        return text, tc_mean, ms_mean

    head = ["task"] + names + [f"d TC-max/makespan {n}" for n in names[1:]]
    table = []
    for tid in task_ids + [None]:
        cells = [cell(n, tid) for n in names]
        diffs = []
        for c in cells[1:]:
            dtc = "-" if c[1] is None or cells[0][1] is None else f"{c[1] - cells[0][1]:+.1f} m"
            dms = "-" if c[2] is None or cells[0][2] is None else f"{c[2] - cells[0][2]:+.1f} s"
            diffs.append(f"{dtc} / {dms}")
        table.append(["all" if tid is None else tid] + [c[0] for c in cells] + diffs)
    widths = [max(len(str(r[i])) for r in [head] + table) for i in range(len(head))]
    lines = ["variants side by side (SR, TC-max mean (min-max over seeds), makespan):",
             "  ".join(h.ljust(w) for h, w in zip(head, widths))]
    lines += ["  ".join(str(c).ljust(w) for c, w in zip(r, widths)) for r in table]
    return "\n".join(lines)

"""Two runs or two benches side by side (``pipflow compare A B`` and the view's compare page).

Why one module for both faces: the text table and the HTML table must show the same figures and
the same differences, so both are drawn from :func:`comparison` (rows of label, A, B, B - A).
"""
from __future__ import annotations

import html
import json
from pathlib import Path
from typing import Any

from pipflow.errors import InputError
from pipflow.metrics import counts_for_travel, upgrade_results, upgrade_travel_keys

RUN_FIELDS = [("status", None), ("goal", None), ("constraints", None), ("rounds", None),
              ("makespan", "s"), ("tc_max", "m"), ("tc_avg", "m"), ("tc_avg_team", "m"), ("goal_met", None),
              ("exe", None), ("seconds", "s"), ("tokens", None), ("cost_usd", "USD")]
TASK_FIELDS = [("sr", "%"), ("understood", "%"), ("misread", None), ("misread_executed", None), ("gcr", None),
               ("tc_max", "m"), ("tc_avg", "m"), ("makespan", "s"), ("seconds", "s"), ("tokens", None)]


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


def comparison(a: Path, b: Path) -> tuple[str, list[list[Any]]]:
    """``(kind, rows)``; each row is ``[label, value in A, value in B, B - A or "" ]``."""
    ka, kb = kind_of(a), kind_of(b)
    if ka != kb:
        raise InputError(f"cannot compare a {ka} ({a}) with a {kb} ({b})")
    rows: list[list[Any]] = []
    if ka == "run":
        fa, fb = _run_facts(a), _run_facts(b)
        for key, unit in RUN_FIELDS:
            if fa.get(key) is not None or fb.get(key) is not None:
                rows.append([key + (f" ({unit})" if unit else ""), fa.get(key), fb.get(key), _diff(fa.get(key), fb.get(key))])
        return ka, rows
    ra, rb = upgrade_results(_read(a / "results.json") or {}), upgrade_results(_read(b / "results.json") or {})
    ta = {t.get("id"): t for t in ra.get("tasks", []) if isinstance(t, dict)}
    tb = {t.get("id"): t for t in rb.get("tasks", []) if isinstance(t, dict)}
    for tid in list(ta) + [t for t in tb if t not in ta]:
        for key, unit in TASK_FIELDS:
            va, vb = (ta.get(tid) or {}).get(key), (tb.get(tid) or {}).get(key)
            if va is not None or vb is not None:
                rows.append([f"{tid} {key}" + (f" ({unit})" if unit else ""), va, vb, _diff(va, vb)])
    for key, unit in TASK_FIELDS:
        va, vb = (ra.get("summary") or {}).get(key), (rb.get("summary") or {}).get(key)
        if va is not None or vb is not None:
            rows.append([f"all tasks {key}" + (f" ({unit})" if unit else ""), va, vb, _diff(va, vb)])
    return ka, rows


def _diff(a: Any, b: Any) -> Any:
    if isinstance(a, (int, float)) and isinstance(b, (int, float)) and not isinstance(a, bool) and not isinstance(b, bool):
        return b - a
    return "" if a == b else "differs"


def fmt(value: Any) -> str:
    if isinstance(value, float):
        return f"{value:+.2f}".lstrip("+") if abs(value) < 1e6 else f"{value:.3g}"
    if isinstance(value, (dict, list)):
        return json.dumps(value, separators=(", ", ": "))
    return "" if value is None else str(value)


def compare_text(a: Path, b: Path) -> str:
    kind, rows = comparison(a, b)
    width = max([len(r[0]) for r in rows] + [5])
    lines = [f"{kind}s: A = {a}", f"       B = {b}", f"{'':<{width}}  {'A':>14}  {'B':>14}  {'B - A':>10}"]
    for label, va, vb, d in rows:
        lines.append(f"{label:<{width}}  {fmt(va):>14}  {fmt(vb):>14}  {fmt(d) if not isinstance(d, str) else d:>10}")
    return "\n".join(lines)


def compare_html(a: Path, b: Path) -> str:
    kind, rows = comparison(a, b)
    body = "".join(
        f"<tr{' class=diff' if d not in ('', 0, 0.0) else ''}><td>{html.escape(label)}</td><td>{html.escape(fmt(va))}</td>"
        f"<td>{html.escape(fmt(vb))}</td><td>{html.escape(fmt(d) if not isinstance(d, str) else d)}</td></tr>"
        for label, va, vb, d in rows)
    return ("<!DOCTYPE html><html lang='en'><head><meta charset='utf-8'><title>pipflow compare</title><style>"
            "body{font-family:sans-serif;margin:1.5em 2em} table{border-collapse:collapse}"
            "td,th{border:1px solid #ccc;padding:.3em .6em} th{background:#eef2f7} tr.diff td{background:#fff8e1}"
            "</style></head><body>"
            f"<h1>Compare two {kind}s</h1><p>A: <code>{html.escape(str(a))}</code><br>B: <code>{html.escape(str(b))}</code></p>"
            f"<table id='comparison'><tr><th></th><th>A</th><th>B</th><th>B - A</th></tr>{body}</table></body></html>")


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

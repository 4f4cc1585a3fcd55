"""The report page of a bench directory (``pipflow bench``'s record).

``results.json`` with ``{"summary": {...}, "tasks": [{"id", "runs", "sr", "gcr", "exe", "ru",
"tc_max", "tc_avg", "error"}], "variants"?: [{"name", "summary", "tasks"}], ...}`` and, when
``pipflow bench`` wrote it, ``runs.json`` (one row per run: variant, task, seed, success, tc_max,
tc_avg, run_dir). Per-task plots come from those rows (or a task's own ``details``); run
directories inside the bench dir are linked to their own reports.
"""
from __future__ import annotations

import re
from pathlib import Path
from typing import Any

from pipflow import pictures
from pipflow.errors import UserError
from pipflow.meaning import misread_cell
from pipflow.records.benchread import BY_KEY, ROW_KEY, Bench, fmt_interval, fmt_value, task_commands, task_fields
from pipflow.records.htmlparts import Pictures, Raw, cell, esc, img, table
from pipflow.records.intervals import LEVEL, STUDENT, WILSON, wilson
from pipflow.records.matrix import matrix_html, relative_link
from pipflow.taskdomains import domain_named


def bench_body(bench: Bench, d: Path, drawn: Pictures) -> str:
    """A bench: its configuration, a summary row per variant (SR and the other shares as
    percents, each figure with its 95% interval over seeds), the matrix of variants x tasks (one
    click to each run), a table per group of tasks when the task domain groups them (household:
    per category), the tasks' table with each seed's run, the right refusals apart from the
    errors, and the per-task charts (drawn into ``drawn``; ``d`` is the bench's folder, which the
    matrix links from)."""
    names = bench.variants
    parts = [_bench_config(bench.results, bench.config)]
    parts.append("<h2 id='summary'>Summary</h2>" + _summary_table(bench) + f"<p class='small'>{esc(_ci_note(bench))}</p>")
    for group, labels in _task_groups(bench).items():
        parts.append(f"<h2 id='per-{esc(group)}'>Per {esc(group)}</h2>" + _group_table(bench, group, labels))
    parts.append(matrix_html([bench], relative_link(d)))
    constructions = [(n, (v.get("constructions") or {})) for n, v in zip(names, bench.results.get("variants") or [])]
    if any(c for _, c in constructions):
        rows = [[k, *[Raw(f"{esc(c.get(k, {}).get('runs', ''))} runs, {esc(_pct(c.get(k, {}).get('understood')) or '-')} "
                          f"understood, misread {esc(misread_cell(c.get(k, {})))}") if k in c else None
                      for _, c in constructions]]
                for k in sorted({k for _, c in constructions for k in c})]
        parts.append("<h2 id='constructions'>Understanding per construction</h2>"
                     + table(["construction", *names], rows))
    parts.append("<h2 id='tasks'>Tasks</h2>" + _tasks_table(bench))
    refusals, errors = _refusals_and_errors(bench)
    if refusals:
        parts.append("<h3 id='refusals'>Refused, as the task asks</h3><p class='small'>Commands the task file marks "
                     "impossible (or to refuse): a refusal with a reason is the right answer.</p><ul>" + "".join(
                         f"<li><b>{esc(tid)}</b>" + (f" [{esc(n)}]" if len(names) > 1 else "") + f": {esc(text)}</li>"
                         for n, tid, text in refusals) + "</ul>")
    if errors:
        parts.append("<h3 id='errors'>Errors</h3><p class='small'>Runs that did not succeed, with why.</p><ul>" + "".join(
            f"<li><b>{esc(tid)}</b>" + (f" [{esc(n)}]" if len(names) > 1 else "") + f": {esc(text)}</li>"
            for n, tid, text in errors) + "</ul>")
    if bench.task_ids:
        groups = _task_groups(bench)
        chart_groups = next(iter(groups.items()), None)
        parts.append("<h2 id='charts'>Per task</h2><p class='small'>At full size; scroll sideways in a wide "
                     "chart.</p>")
        sets = ([(label, [t for t in bench.task_ids if chart_groups[1].get(t) == label])
                 for label in dict.fromkeys(chart_groups[1].values())] if chart_groups else [("", bench.task_ids)])
        for k, (label, ids) in enumerate(sets):
            if not ids:
                continue
            name = f"overview{'-' + re.sub(r'[^A-Za-z0-9_-]', '_', str(label)) if label else ''}.png"
            _bench_overview(bench, ids, drawn.path(name), title=str(label))
            parts.append((f"<h3>{esc(label)}</h3>" if label else "")
                         + f"<div class='chart'>{img(drawn.src(name), f'SR and TC-max per task and variant {label}'.strip())}</div>")
    return "\n".join(parts)


def _ci_note(bench: Bench) -> str:
    seeds = int(bench.config.get("seeds") or 1)
    if seeds < 2:
        return "One seed per task: no intervals (run the bench with --seeds 2 or more for them)."
    return (f"[lo, hi]: the {int(LEVEL * 100)}% interval over the {seeds} seeds: {WILSON} for SR and understood, "
            f"{STUDENT} for the others; the all-tasks figures over each seed's figure of all tasks.")


def _figure_cell(bench: Bench, variant: str, task: str | None, key: str) -> Any:
    metric = BY_KEY[key]
    f = bench.figure(variant, task, metric)
    if f.value is None:
        return None
    interval = fmt_interval(f.interval, metric)
    return Raw(esc(fmt_value(f.value, metric)) + (f" <span class='small'>{esc(interval)}</span>" if interval else ""))


def _summary_table(bench: Bench) -> str:
    rows = []
    for v in bench.variants:
        s = bench.summaries.get(v, {})
        fallbacks = [r for r in bench.runs_of(v) if r.get("fallback")]
        rows.append([v, s.get("runs"), _figure_cell(bench, v, None, "sr"), _figure_cell(bench, v, None, "understood"),
                     misread_cell(s), _figure_cell(bench, v, None, "gcr"), _figure_cell(bench, v, None, "exe"),
                     _figure_cell(bench, v, None, "ru"), _figure_cell(bench, v, None, "tc_max"),
                     _figure_cell(bench, v, None, "tc_avg"), _figure_cell(bench, v, None, "makespan"),
                     _figure_cell(bench, v, None, "seconds"), _engines(bench.runs_of(v)),
                     Raw(f"<span class='bad'>{len(fallbacks)}</span>") if fallbacks else 0])
    return table(["variant", "runs", "SR", "understood", "misread (executed)", "GCR", "Exe", "RU", "TC-max (m)",
                   "TC-avg (m)", "makespan (s)", "time per run (s)", "planner", "planner fell back"], rows)


def _engines(runs: list[dict]) -> str:
    """Which planner answered, over the runs (``engine`` of each row; older rows have none)."""
    counts: dict[str, int] = {}
    for r in runs:
        if r.get("engine"):
            counts[str(r["engine"])] = counts.get(str(r["engine"]), 0) + 1
    return ", ".join(f"{k} ({n})" if len(counts) > 1 else k for k, n in counts.items()) or ""


def _task_groups(bench: Bench) -> dict[str, dict[str, str]]:
    """``{field: {task id: label}}`` for each field the bench's task domain groups its tasks by
    (:attr:`pipflow.taskdomain.TaskDomain.task_groups`), read from the task rows (or, for an
    older bench, from its task file)."""
    try:
        fields = tuple(domain_named(bench.config.get("domain")).task_groups)
    except UserError:  # a bench of a domain no longer installed: no groups
        return {}
    out: dict[str, dict[str, str]] = {}
    for field in fields:
        labels = {tid: str(row[field]) for v in bench.variants for tid, row in bench.tasks[v].items()
                  if row.get(field) is not None}
        if not labels:
            labels = {tid: str(t[field]) for tid, t in task_fields(bench.config, bench.path).items()
                      if t.get(field) is not None and tid in bench.task_ids}
        if labels:
            out[field] = labels
    return out


def _group_table(bench: Bench, field: str, labels: dict[str, str]) -> str:
    """One row per group (and all tasks) and variant: tasks, runs, SR, understood, misread, TC,
    GCR, RU, Exe; the rates over the group's runs, TC over its tasks that have a travel figure
    (as the bench's summary is made)."""
    rows = []
    for label in list(dict.fromkeys(labels.values())) + [None]:
        ids = [t for t in bench.task_ids if label is None or labels.get(t) == label]
        for v in bench.variants:
            runs = [r for r in bench.runs_of(v) if str(r.get("task")) in ids]
            tasks = [bench.tasks[v][t] for t in ids if t in bench.tasks[v]]
            n = sum(int(t.get("runs") or 0) for t in tasks)

            def share(key: str) -> Any:
                if runs:
                    vals = [bool(r.get(ROW_KEY.get(key, key))) for r in runs if r.get(ROW_KEY.get(key, key)) is not None]
                    if not vals:
                        return None
                    interval = fmt_interval(wilson(sum(vals), len(vals)), BY_KEY[key])
                    return Raw(f"{100 * sum(vals) / len(vals):.0f}%" + (f" <span class='small'>{interval}</span>" if interval else ""))
                vals = [(t.get(key), t.get("runs") or 0) for t in tasks if t.get(key) is not None]
                total = sum(w for _, w in vals)
                return _pct(sum(x * w for x, w in vals) / total) if total else None

            def mean(key: str, weighted: bool = True) -> Any:
                vals = [(float(t[key]), (t.get("runs") or 0) if weighted else 1) for t in tasks
                        if isinstance(t.get(key), (int, float))]
                total = sum(w for _, w in vals)
                return round(sum(x * w for x, w in vals) / total, 2) if total else None

            misread = {k: sum(int(t.get(k) or 0) for t in tasks) for k in ("misread", "misread_executed")}
            rows.append([Raw("<b>all</b>") if label is None else label] + ([v] if len(bench.variants) > 1 else [])
                        + [len(tasks), n, share("sr"), share("understood"), misread_cell(misread),
                           mean("tc_max", False), mean("tc_avg", False), mean("gcr"), mean("ru"), mean("exe")])
    head = [field] + (["variant"] if len(bench.variants) > 1 else []) + [
        "tasks", "runs", "SR", "understood", "misread (executed)", "TC-max (m)", "TC-avg (m)", "GCR", "RU", "Exe"]
    return table(head, rows)


def _tasks_table(bench: Bench) -> str:
    """Per task, each variant's SR (with each seed's run linked), TC-max and makespan (mean and
    interval over seeds), RU and Exe; then each further variant's TC-max difference to the
    first."""
    names = bench.variants
    commands = task_commands(bench.config, bench.path)
    link = relative_link(bench.path)
    rows = []
    for tid in bench.task_ids:
        row: list[Any] = [tid, commands.get(tid, "")]
        for n in names:
            vr = sorted(bench.runs_of(n, tid), key=lambda r: r.get("seed") or 0)
            links = " ".join(f"<a href='{esc(url)}'>seed {esc(r.get('seed'))}</a>" for r in vr for url in [link(bench, r)] if url)
            sr = _figure_cell(bench, n, tid, "sr")
            row += [Raw(f"{sr if sr is not None else '&ndash;'}<br><span class='small'>{links}</span>"),
                    _figure_cell(bench, n, tid, "tc_max"), _figure_cell(bench, n, tid, "makespan"),
                    _figure_cell(bench, n, tid, "ru"), _figure_cell(bench, n, tid, "exe")]
        base = bench.figure(names[0], tid, BY_KEY["tc_max"]).value
        for n in names[1:]:
            other = bench.figure(n, tid, BY_KEY["tc_max"]).value
            row.append(other - base if other is not None and base is not None else None)
        rows.append(row)
    return _grouped_table(names, rows)


def _refusals_and_errors(bench: Bench) -> tuple[list, list]:
    """Per variant and task, the refusals that were the right answer (the run succeeded by
    refusing) and the errors of runs that did not succeed, each text once."""
    refusals, errors = [], []
    for v in bench.variants:
        for tid in bench.task_ids:
            runs = bench.runs_of(v, tid)
            right = {str(r.get("error")) for r in runs if r.get("success") and r.get("error")}
            wrong = {str(r.get("error")) for r in runs if not r.get("success") and r.get("error")}
            t = bench.tasks[v].get(tid) or {}
            if not right and not wrong and t.get("error"):  # rows without errors (older): the task row's, by its SR
                (right if t.get("sr") == 1 else wrong).add(str(t["error"]))
            refusals += [(v, tid, text) for text in sorted(right)]
            errors += [(v, tid, text) for text in sorted(wrong)]
    return refusals, errors


def _grouped_table(names: list[str], rows: list[list[Any]]) -> str:
    """Per-task rows under a two-level header: one column group per variant (SR, TC-max,
    makespan, RU, Exe), then the difference in TC-max of each further variant to the first."""
    per = ("SR", "TC-max (m)", "makespan (s)", "RU", "Exe")
    top = "<th rowspan='2'>task</th><th rowspan='2' class='cmd'>command</th>" + "".join(
        f"<th colspan='{len(per)}'>{esc(n)}</th>" for n in names)
    if len(names) > 1:
        top += f"<th colspan='{len(names) - 1}'>\u0394 TC-max (m) vs {esc(names[0])}</th>"
    sub = "".join(f"<th>{h}</th>" for _ in names for h in per) + "".join(f"<th>{esc(n)}</th>" for n in names[1:])
    body = "".join("<tr>" + "".join(
        f"<td class='num'>{cell(c)}</td>" if isinstance(c, (int, float)) or c is None else
        f"<td class='cmd'>{cell(c)}</td>" if i == 1 else f"<td>{cell(c)}</td>"
        for i, c in enumerate(row)) + "</tr>" for row in rows)
    return f"<div class='wide'><table class='tasks'><tr>{top}</tr><tr>{sub}</tr>{body}</table></div>"


def _bench_config(results: dict, config: dict) -> str:
    rows = [[k, v] for k, v in config.items() if not isinstance(v, (dict, list))]
    for key in ("matrix", "inputs"):
        for k, v in (config.get(key) or {}).items():
            rows.append([f"{key}: {k}", ", ".join(map(str, v)) if isinstance(v, list) else v])
    rows += [[k, v] for k, v in results.items() if not isinstance(v, (dict, list))]
    return "<h2>Configuration</h2>" + table(["", ""], rows)


def _pct(x: Any) -> Any:
    return None if x is None else f"{100 * float(x):.0f}%"


def _bench_overview(bench: Bench, ids: list[str], path: Path, title: str = "") -> None:
    """SR and TC-max of tasks ``ids``, one bar per variant; TC-max bars carry the 95% interval
    over seeds (none with one seed). Drawn at a readable size (about 0.35 inch a bar), never
    squeezed: the page scrolls it; the legend sits above the axes, never on the bars."""
    plt = pictures._plt()  # matplotlib loads here, on first drawing
    x = list(range(len(ids)))
    k_vars = max(1, len(bench.variants))
    width = 0.8 / k_vars
    fig, (a1, a2) = plt.subplots(2, 1, figsize=(max(8.0, 0.35 * len(ids) * k_vars + 2.5), 7.5))
    for k, name in enumerate(bench.variants):
        xs = [i - 0.4 + width * (k + 0.5) for i in x]
        srs = [bench.figure(name, t, BY_KEY["sr"]).value for t in ids]
        a1.bar(xs, [100 * (v or 0.0) for v in srs], width, label=name)
        mid, lo, hi = [], [], []
        for t in ids:
            f = bench.figure(name, t, BY_KEY["tc_max"])
            m = f.value or 0.0
            mid.append(m)
            lo.append(m - f.interval[0] if f.interval else 0.0)
            hi.append(f.interval[1] - m if f.interval else 0.0)
        spread = any(lo) or any(hi)  # one seed: no interval, no whiskers
        a2.bar(xs, mid, width, yerr=[lo, hi] if spread else None, capsize=2 if spread else 0, label=name)
    a1.set_ylim(0, 105)
    a1.set_ylabel("SR (%)")
    a1.set_title("Success rate per task" + (f": {title}" if title else ""))
    a2.set_ylabel("TC-max (m), successful runs")
    a2.set_title("Longest robot travel per task (bars: 95% interval over seeds)")
    for a in (a1, a2):
        a.set_xticks(x)
        a.set_xticklabels(ids, rotation=60, ha="right", fontsize=9)
        a.set_xlim(-0.6, len(ids) - 0.4)
    if k_vars > 1:  # one legend for both charts, above them, a line per variant: it never covers a bar
        handles, labels = a1.get_legend_handles_labels()
        top = 0.22 * k_vars + 0.2  # inches
        fig.set_figheight(fig.get_figheight() + top)
        fig.legend(handles, labels, loc="upper left", ncol=1, fontsize=9, frameon=False, bbox_to_anchor=(0.01, 1.0))
        fig.tight_layout(rect=(0, 0, 1, 1 - top / fig.get_figheight()))
    else:
        fig.tight_layout()
    pictures.save_figure(fig, path, dpi=90)
    plt.close(fig)

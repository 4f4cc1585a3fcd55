"""The matrix view: variants x tasks, like promptfoo's grid of prompts x test cases.

Each row is a task (its command on hover), each column a variant of a bench (with several benches,
every variant of each: ``A graph_mode=paper``); each cell shows the success rate over the task's
seeds, a chosen figure (a menu above the grid switches it: TC-max, makespan, GCR, ...; with its
95% interval over seeds where there are several) and one link per seed, coloured by its
outcome, to that run's report. Clicking a cell opens a panel with each seed's links straight to
the prompt and answer, the plan and the pictures of the run, and its error. The last row is
all tasks. Plain HTML with a few lines of inline script: no network, works from a file.
"""
from __future__ import annotations

import html
from pathlib import Path
from typing import Callable

from pipflow.records.benchread import BY_KEY, METRICS, Bench, fmt_interval, fmt_value, task_commands

#: where in a run's report a seed's panel links to (the report's section ids)
SECTIONS = (("loop", "prompt & answer"), ("plan", "plan"), ("pictures", "pictures"))

_STYLE = """<style>
table.matrix { border-collapse: collapse; margin: .5em 0; }
table.matrix td, table.matrix th { border: 1px solid #bbb; padding: .3em .5em; vertical-align: top; }
table.matrix th { background: #eef2f7; font-weight: normal; }
table.matrix th.variant { font-weight: bold; max-width: 14em; }
table.matrix td.cell { cursor: pointer; min-width: 8.5em; }
table.matrix td.cell.picked { outline: 3px solid #1f4e8c; }
table.matrix .sr { font-weight: bold; } table.matrix .metric { font-variant-numeric: tabular-nums; }
table.matrix .seeds a { display: inline-block; min-width: 1.4em; text-align: center; margin: 1px; padding: 0 .2em;
  border-radius: 3px; font-size: .8em; text-decoration: none; color: white; }
table.matrix .seeds a.ok { background: #1a7f37; } table.matrix .seeds a.bad { background: #c62828; }
table.matrix .seeds a.none { background: #888; }
table.matrix tr.all td, table.matrix tr.all th { border-top: 2px solid #555; }
#matrix-panel { border: 1px solid #99a; border-radius: 6px; padding: .3em 1em; margin: .5em 0; background: #f7f9fc; }
</style>"""

_SCRIPT = """<script>
(function () {
  var menu = document.getElementById('matrix-metric');
  function show() {
    var key = menu.value;
    document.querySelectorAll('table.matrix td.cell').forEach(function (td) {
      td.querySelector('.metric').textContent = td.getAttribute('data-m-' + key) || '-';
    });
    document.querySelectorAll('.metric-name').forEach(function (el) {
      el.textContent = menu.options[menu.selectedIndex].text;
    });
  }
  menu.addEventListener('change', show);
  var panel = document.getElementById('matrix-panel');
  document.querySelectorAll('table.matrix td.cell').forEach(function (td) {
    td.addEventListener('click', function (ev) {
      if (ev.target.tagName === 'A') { return; }
      document.querySelectorAll('table.matrix td.picked').forEach(function (x) { x.classList.remove('picked'); });
      td.classList.add('picked');
      panel.innerHTML = td.querySelector('template').innerHTML;
      panel.hidden = false;
    });
  });
  show();
})();
</script>"""


def _colour(sr: float | None) -> str:
    """Red (0%) to green (100%), light enough for text."""
    if sr is None:
        return "#f2f2f2"
    return f"hsl({int(120 * sr)}, 55%, 86%)"


def _seed_class(run: dict) -> str:
    if run.get("success") is None:
        return "none"
    return "ok" if run.get("success") else "bad"


def matrix_html(benches: list[Bench], link: Callable[[Bench, dict], str | None],
                default_metric: str = "tc_max", letters: bool | None = None) -> str:
    """The matrix of ``benches`` (each a column per variant). ``link(bench, run_row)``: the URL of
    that run's report, or None (the seed is then shown without a link)."""
    letters = len(benches) > 1 if letters is None else letters
    columns = [(b, v, (f"{chr(ord('A') + i)} " if letters else "") + v) for i, b in enumerate(benches) for v in b.variants]
    task_ids: list[str] = []
    commands: dict[str, str] = {}
    for b in benches:
        task_ids += [t for t in b.task_ids if t not in task_ids]
        commands = {**task_commands(b.config, b.path), **commands}
    choices = [m for m in METRICS if m.key != "sr"]
    default = default_metric if default_metric in BY_KEY else "tc_max"
    menu = "".join(f"<option value='{m.key}'{' selected' if m.key == default else ''}>{html.escape(m.heading())}</option>"
                   for m in choices)
    head = "<tr><th>task</th>" + "".join(f"<th class='variant'>{html.escape(name).replace(',', ',<wbr>')}</th>"
                                         for _, _, name in columns) + "</tr>"
    body = []
    for tid in task_ids + [None]:
        cells = []
        for b, v, name in columns:
            if tid is not None and tid not in b.task_ids:
                cells.append("<td>&ndash;</td>")
                continue
            cells.append(_cell(b, v, tid, name, choices, link))
        label = "all tasks" if tid is None else tid
        title = commands.get(tid or "", "")
        body.append(f"<tr{' class=all' if tid is None else ''}><th title='{html.escape(title)}'>{html.escape(label)}"
                    + (f"<br><span class='small'>{html.escape(title[:60] + ('...' if len(title) > 60 else ''))}</span>"
                       if title else "") + "</th>" + "".join(cells) + "</tr>")
    return (f"{_STYLE}<h2 id='matrix'>Matrix</h2><p class='small'>Each cell: SR over the task's seeds (runs "
            "succeeded / runs) and <b class='metric-name'></b> "
            f"<select id='matrix-metric'>{menu}</select>; the numbered links open each seed's run report "
            "(green succeeded, red not); click a cell for its prompt, answer, plan and pictures.</p>"
            f"<table class='matrix'>{head}{''.join(body)}</table>"
            "<div id='matrix-panel' hidden></div>" + _SCRIPT)


def _cell(b: Bench, variant: str, tid: str | None, name: str, choices, link) -> str:
    sr = b.figure(variant, tid, BY_KEY["sr"])
    runs = b.runs_of(variant, tid)
    ok = sum(1 for r in runs if r.get("success"))
    attrs = []
    for m in choices:
        f = b.figure(variant, tid, m)
        text = (fmt_value(f.value, m) + " " + fmt_interval(f.interval, m)).strip() if f.value is not None else "-"
        attrs.append(f"data-m-{m.key}='{html.escape(text)}'")
    seeds = "" if tid is None else "".join(_seed_link(r, link(b, r)) for r in sorted(runs, key=lambda r: r.get("seed") or 0))
    rows = []
    for r in sorted(runs, key=lambda r: (str(r.get("task")), r.get("seed") or 0)) if tid is not None else []:
        url = link(b, r)
        where = " &middot; ".join(f"<a href='{html.escape(url)}#{anchor}'>{words}</a>" for anchor, words in SECTIONS) \
            if url else "(no run record)"
        outcome = "succeeded" if r.get("success") else "refused" if r.get("refused") else "did not succeed"
        figures = ", ".join(f"{m.label} {float(r[m.key]):.2f}{(' ' + m.unit) if m.unit else ''}"
                            for m in (BY_KEY["tc_max"], BY_KEY["makespan"]) if isinstance(r.get(m.key), (int, float))
                            and r.get("success") and not r.get("refused"))
        outcome += f" ({figures})" if figures else ""
        err = f"<br><span class='small'>{html.escape(str(r.get('error'))[:300])}</span>" if r.get("error") else ""
        rows.append(f"<li>seed {html.escape(str(r.get('seed')))}: {outcome}; "
                    + (f"<a href='{html.escape(url)}'>report</a>: " if url else "") + f"{where}{err}</li>")
    detail = (f"<p><b>{html.escape(name)}</b>, task <b>{html.escape(tid)}</b></p><ul>{''.join(rows)}</ul>"
              if tid is not None else f"<p><b>{html.escape(name)}</b>, all tasks: "
                                      f"{ok} of {len(runs)} runs succeeded</p>")
    sr_text = f"{ok}/{len(runs)} &middot; " if runs else ""
    return (f"<td class='cell' style='background:{_colour(sr.value)}' {' '.join(attrs)}>"
            f"<div class='sr'>{sr_text}{html.escape(fmt_value(sr.value, BY_KEY['sr']))}</div>"
            f"<div class='metric'></div><div class='seeds'>{seeds}</div>"
            f"<template>{detail}</template></td>")


def _seed_link(run: dict, url: str | None) -> str:
    seed = html.escape(str(run.get("seed")))
    title = f"seed {seed}: " + ("succeeded" if run.get("success") else "did not succeed")
    if url is None:
        return f"<a class='{_seed_class(run)}' title='{title}'>{seed}</a>"
    return f"<a class='{_seed_class(run)}' href='{html.escape(url)}' title='{title}'>{seed}</a>"


def relative_link(page_dir: Path) -> Callable[[Bench, dict], str | None]:
    """Links from a page in ``page_dir`` to the run reports inside a bench folder (the report
    must exist: the bench report writes them)."""
    import os

    def link(b: Bench, run: dict) -> str | None:
        p = b.run_folder(run)
        if p is None or not (p / "report.html").is_file():
            return None
        return Path(os.path.relpath(p / "report.html", page_dir)).as_posix()

    return link

"""The paper's tables (Sec. V) from a bench's runs: text (markdown), CSV and LaTeX (booktabs).

* **Table I** (the AI2-THOR table's shape): one row per framework and model (a bench variant),
  one column group per task group of the task file's domain (household: compound, complex,
  vague), each with SR, TC max/avg, GCR, RU and Exe.
* **Table II** (the warehouse table's shape): one row per task, one column group per framework
  and model, each with SR (%) and TC max/avg (m).
* **Table III** (the ablation table's shape): one row per ablation (and PIP-LLM itself, the
  paper's N = 4 row), one column group per task group (one group of all tasks where the domain
  has no groups), each with SR and TC max/avg; written when the bench has an ablation variant.

Which shape a bench gets is its domain's: a domain that groups its tasks for the paper
(:meth:`pipflow.taskdomain.TaskDomain.table_groups`) gets Tables I and III, one that does not
gets Tables II and III.

Every cell is computed from the runs it covers (``runs.json``), never from other cells: SR, GCR,
RU and Exe are means over all runs of the variant in the group; TC-max and TC-avg are means over
the runs that succeeded by executing their task (a right refusal moved nobody and is left out),
"--" when there is none, like the paper's "--/--". TC-avg is the paper's, over the robots that
moved (``tc_avg``; rows written before the metrics were renamed are read through
:func:`pipflow.metrics.upgrade_travel_keys`). A cell over fewer than ``min_runs`` runs (:data:`MIN_RUNS` unless
told) is marked: "(n=2)" in text, a dagger in LaTeX with a note under the table, and every CSV
cell group carries its run counts.
"""
from __future__ import annotations

import csv
import io
from dataclasses import dataclass
from pathlib import Path
from typing import Iterable

from pipflow.engine.store import atomic_write, read_json
from pipflow.errors import InputError
from pipflow.experiments.benchdomains import domain_named
from pipflow.metrics import upgrade_travel_keys

#: a cell averaged over fewer runs than this is marked as too few (the paper runs each warehouse
#: task 10 times; 3 is the fewest that can tell 0, 1/3, 2/3 and 1 apart)
MIN_RUNS = 3

#: the paper's names of the frameworks and ablations, by the method names pipflow's workflows
#: answer to (a workflow not listed is shown by its own name)
LABELS = {
    "pip-llm": "PIP-LLM", "pip-llm-checked": "PIP-LLM (checked loop)",
    "cot": "CoT", "smart-llm": "SMART-LLM", "lamma-p": "LaMMA-P",
    "pip-llm-no-domain": "PIP-LLM w/o D", "pip-llm-no-debugger": "PIP-LLM w/o B",
    "pip-llm-no-bv": "PIP-LLM w/o B&V", "pip-llm-n1": "PIP-LLM w/ N=1", "pip-llm-n2": "PIP-LLM w/ N=2",
    "pip-llm-n3": "PIP-LLM w/ N=3", "pip-llm-n4": "PIP-LLM w/ N=4", "pip-llm-no-as": "PIP-LLM w/o AS",
}
LATEX_LABELS = {
    "pip-llm-no-domain": r"PIP-LLM w/o $\mathcal{D}$", "pip-llm-no-debugger": r"PIP-LLM w/o $\mathcal{B}$",
    "pip-llm-no-bv": r"PIP-LLM w/o $\mathcal{B}\&\mathcal{V}$", "pip-llm-no-as": r"PIP-LLM w/o $\mathcal{AS}$",
    **{f"pip-llm-n{n}": rf"PIP-LLM w/ $\mathcal{{N}}={n}$" for n in range(1, 5)},
}
#: Table III's rows in the paper's order (w/o B is the issue's reading, after the paper's rows);
#: PIP-LLM itself is the paper's N = 4 row
ABLATION_ORDER = ("pip-llm-no-domain", "pip-llm-no-bv", "pip-llm-n1", "pip-llm-n2", "pip-llm-n3",
                  "pip-llm-n4", "pip-llm", "pip-llm-no-as", "pip-llm-no-debugger")
ABLATIONS = frozenset(ABLATION_ORDER) - {"pip-llm"}


# ------------------------------------------------------------------------------ cells
@dataclass(frozen=True)
class Cell:
    """The figures of one group of runs. ``runs``: how many runs; ``tc_runs``: how many of them
    the travel figures average over (successful runs that executed their task)."""

    runs: int
    sr: float | None
    gcr: float | None
    ru: float | None
    exe: float | None
    tc_max: float | None
    tc_avg: float | None
    tc_runs: int


def _mean(values: list[float]) -> float | None:
    return sum(values) / len(values) if values else None


def paper_tc_avg(row: dict) -> float:
    """The paper's TC-avg of one run (over the robots that moved), in either era of row names."""
    return float(upgrade_travel_keys(row).get("tc_avg") or 0.0)


def cell(rows: list[dict]) -> Cell:
    """One group's figures (module docstring)."""
    travelled = [r for r in rows if r.get("success") and not r.get("refused")]
    return Cell(runs=len(rows),
                sr=_mean([1.0 if r.get("success") else 0.0 for r in rows]),
                gcr=_mean([float(r.get("gcr") or 0.0) for r in rows]),
                ru=_mean([float(r.get("ru") or 0.0) for r in rows]),
                exe=_mean([float(r.get("exe") or 0.0) for r in rows]),
                tc_max=_mean([float(r.get("tc_max") or 0.0) for r in travelled]),
                tc_avg=_mean([paper_tc_avg(r) for r in travelled]),
                tc_runs=len(travelled))


# ------------------------------------------------------------------------------ the bench
@dataclass(frozen=True)
class Variant:
    """One bench variant as a row (or column group) of the tables."""

    name: str      # the bench's variant name
    method: str    # the method name of its workflow (pip-llm, pip-llm-no-as, cot, ...)
    model: str     # the model it ran with
    extra: str     # other matrix values, "key=value; ..." ("" when none)

    def label(self, latex: bool = False) -> str:
        base = (LATEX_LABELS.get(self.method) if latex else None) or LABELS.get(self.method, self.method)
        if latex and self.method not in LATEX_LABELS:
            base = latex_escape(base)
        detail = "; ".join(x for x in (self.model, self.extra) if x)
        if not detail:
            return base
        return f"{base} ({latex_escape(detail) if latex else detail})"


@dataclass
class Bench:
    """What the tables read from a bench folder: its variants, its runs and its task groups."""

    domain: str
    variants: list[Variant]
    rows: list[dict]
    task_ids: list[str]
    groups: list[tuple[str, list[str]]] | None

    def runs(self, variant: str, tasks: Iterable[str] | None = None) -> list[dict]:
        wanted = None if tasks is None else set(tasks)
        return [r for r in self.rows if r.get("variant") == variant and (wanted is None or r.get("task") in wanted)]


def load_bench(folder: Path) -> Bench:
    """A bench folder's results.json and runs.json, read for the tables; InputError when it is no
    bench folder."""
    folder = Path(folder)
    results, rows = read_json(folder / "results.json", None), read_json(folder / "runs.json", None)
    if not isinstance(results, dict) or not isinstance(rows, list) or "variants" not in results:
        raise InputError(f"{folder}: not a bench folder (needs results.json and runs.json from `pipflow bench`)")
    config = results.get("config") or {}
    domain_name = config.get("domain")
    task_ids = [t.get("id") for t in (results.get("tasks") or []) if isinstance(t, dict)]
    groups = config.get("groups")
    if groups is None and config.get("tasks") and Path(config["tasks"]).is_file():
        domain = domain_named(domain_name)  # a bench made before groups were recorded: its task file
        groups = domain.table_groups(domain.load_tasks(Path(config["tasks"]))["tasks"])
    groups = [(str(g), list(ids)) for g, ids in groups] if groups else None
    return Bench(domain=str(domain_name), variants=_variants(results, rows), rows=rows, task_ids=task_ids,
                 groups=groups)


def _variants(results: dict, rows: list[dict]) -> list[Variant]:
    """Each variant's method, model and other matrix values: from results.json's config (the
    values of each variant, the workflow each ran), else from the variant's name."""
    config = results.get("config") or {}
    values_of = config.get("variant_values") or {}
    methods = _method_names(config.get("domain"))
    out = []
    for v in results.get("variants") or []:
        name = v.get("name", "default")
        values = dict(values_of.get(name) or _values_from_name(name))
        workflow = values.pop("workflow", None) or config.get("workflow") or "pip-llm"
        stem = Path(str(workflow)).stem if str(workflow).endswith((".yaml", ".yml")) else str(workflow)
        model = values.pop("model", None) or (config.get("inputs") or {}).get("model") or \
            next((r.get("model") for r in rows if r.get("variant") == name and r.get("model")), None) or ""
        extra = "; ".join(f"{k}={val}" for k, val in values.items())
        out.append(Variant(name, methods.get(stem, stem), str(model), extra))
    return out


def _values_from_name(name: str) -> dict[str, str]:
    """``workflow=pip-llm,model=openai/gpt-4o`` -> its values (benches made before they were
    recorded); ``default`` -> none."""
    out = {}
    for part in name.split(","):
        if "=" in part:
            k, v = part.split("=", 1)
            out[k] = v
    return out


def _method_names(domain_name: str | None) -> dict[str, str]:
    """Workflow name -> method name for the domain (household -> pip-llm, ...)."""
    try:
        domain = domain_named(domain_name)
    except InputError:
        return {}
    names = {domain.workflow: "pip-llm"}
    names.update({wf: method for method, wf in domain.workflows.items()})
    return names


# ------------------------------------------------------------------------------ the tables
@dataclass
class Table:
    """One table: its title, its column groups (each a list of column names), its rows (a label
    and, per column group, a :class:`Cell`), and how its cells read."""

    key: str                       # table1, table2, table3
    title: str
    groups: list[Variant | str]    # column groups: task groups, or variants (Table II)
    columns: list[str]             # the figures of each group: sr, tc, gcr, ru, exe
    rows: list[tuple[Variant | str, list[Cell]]]
    percent: bool = False          # SR in percent (Table II), else a fraction
    min_runs: int = MIN_RUNS


def paper_tables(bench: Bench, min_runs: int = MIN_RUNS) -> list[Table]:
    """The tables of a bench (module docstring)."""
    if min_runs < 1:
        raise InputError(f"--min-runs {min_runs}: a cell needs at least 1 run")
    tables = []
    if bench.groups:
        tables.append(Table("table1", f"Table I shape: {bench.domain} tasks per group",
                            [g for g, _ in bench.groups], ["sr", "tc", "gcr", "ru", "exe"],
                            [(v, [cell(bench.runs(v.name, ids)) for _, ids in bench.groups]) for v in bench.variants],
                            min_runs=min_runs))
    else:
        tables.append(Table("table2", f"Table II shape: {bench.domain} tasks, one column group per framework",
                            list(bench.variants), ["sr", "tc"],
                            [(t, [cell(bench.runs(v.name, [t])) for v in bench.variants]) for t in bench.task_ids],
                            percent=True, min_runs=min_runs))
    ablations = [v for v in bench.variants if v.method in ABLATIONS]
    if ablations:
        groups = bench.groups or [("all tasks", bench.task_ids)]
        rows = sorted((v for v in bench.variants if v.method in ABLATION_ORDER),
                      key=lambda v: ABLATION_ORDER.index(v.method))
        tables.append(Table("table3", f"Table III shape: ablations on {bench.domain} tasks",
                            [g for g, _ in groups], ["sr", "tc"],
                            [(v, [cell(bench.runs(v.name, ids)) for _, ids in groups]) for v in rows],
                            min_runs=min_runs))
    return tables


# ------------------------------------------------------------------------------ formats
HEADS = {"sr": "SR", "tc": "TC max/avg", "gcr": "GCR", "ru": "RU", "exe": "Exe"}
LATEX_HEADS = {"sr": r"SR $\uparrow$", "tc": r"\small{TC max/avg} $\downarrow$", "gcr": r"GCR $\uparrow$",
               "ru": r"RU $\uparrow$", "exe": r"Exe $\uparrow$"}


def _number(value: float | None, percent: bool, digits: int = 2) -> str:
    if value is None:
        return "--"
    return f"{100 * value:.0f}" if percent else f"{value:.{digits}f}"


def _figure(c: Cell, column: str, percent: bool) -> tuple[str, int]:
    """A cell's text for one column and the number of runs behind it."""
    if column == "tc":
        if not c.tc_runs:
            return "--/--", 0
        return f"{c.tc_max:.1f}/{c.tc_avg:.1f}", c.tc_runs
    value = getattr(c, column)
    return _number(value, percent and column == "sr"), c.runs


def _row_label(row: Variant | str, latex: bool) -> str:
    if isinstance(row, Variant):
        return row.label(latex)
    return latex_escape(row) if latex else row


def text(table: Table) -> str:
    """A markdown table; a cell over fewer than ``min_runs`` runs says "(n=K)"."""
    first = "Methods" if table.key != "table2" else "Task"
    heads = [first] + [f"{_row_label(g, False)} {HEADS[c]}" for g in table.groups for c in table.columns]
    lines = [f"**{table.title}**", "", "| " + " | ".join(heads) + " |", "|" + "---|" * len(heads)]
    few = False
    for row, cells in table.rows:
        out = [_row_label(row, False)]
        for c in cells:
            for column in table.columns:
                shown, n = _figure(c, column, table.percent)
                if 0 < n < table.min_runs or c.runs == 0:
                    shown = f"{shown} (n={n})" if c.runs else "no runs"
                    few = True
                out.append(shown)
        lines.append("| " + " | ".join(out) + " |")
    if few:
        lines += ["", f"(n=K): the cell averages K < {table.min_runs} runs; TC cells average the successful runs only."]
    return "\n".join(lines)


def csv_text(table: Table) -> str:
    """The table flattened: one line per row, per column group its run counts and each figure
    (TC as two columns); empty where there is nothing to average."""
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    lead = ["label", "method", "model", "variant"] if table.key != "table2" else ["task"]
    figures = [f for c in table.columns for f in (("tc_max", "tc_avg") if c == "tc" else (c,))]
    w.writerow(lead + [f"{g.name if isinstance(g, Variant) else g}:{f}" for g in table.groups
                       for f in ("runs", *figures, "tc_runs")])
    for row, cells in table.rows:
        out = [row.label(), row.method, row.model, row.name] if isinstance(row, Variant) else [row]
        for c in cells:
            out.append(c.runs)
            for f in figures:
                value = getattr(c, f)
                out.append("" if value is None else round(value, 4))
            out.append(c.tc_runs)
        w.writerow(out)
    return buf.getvalue()


def latex(table: Table) -> str:
    """A booktabs table like the paper's source; a cell over fewer than ``min_runs`` runs carries
    a dagger, explained under the table."""
    per = len(table.columns)
    n_cols = 1 + per * len(table.groups)
    first = "Methods" if table.key != "table2" else "Task"
    spans = " & ".join(rf"\multicolumn{{{per}}}{{c}}{{{_group_title(g)}}}" for g in table.groups)
    rules = " ".join(rf"\cmidrule(lr){{{2 + k * per}-{1 + (k + 1) * per}}}" for k in range(len(table.groups)))
    heads = " & ".join(LATEX_HEADS[c] if not (c == "sr" and table.percent) else r"SR (\%) $\uparrow$"
                       for _ in table.groups for c in table.columns)
    lines = [r"\begin{table*}[t]", r"\centering",
             rf"\caption{{{latex_escape(table.title)}}}", rf"\label{{tab:pipflow-{table.key}}}",
             r"\resizebox{\textwidth}{!}{",
             rf"\begin{{tabular}}{{l *{{{n_cols - 1}}}{{c}}}}", r"\toprule",
             rf" & {spans} \\", rules, rf"{first} & {heads} \\", r"\midrule"]
    few = False
    for row, cells in table.rows:
        out = [_row_label(row, True)]
        for c in cells:
            for column in table.columns:
                shown, n = _figure(c, column, table.percent)
                if c.runs == 0:
                    shown, few = r"--$^{\dagger}$", True
                elif 0 < n < table.min_runs:
                    shown, few = shown + r"$^{\dagger}$", True
                out.append(shown)
        lines.append(" & ".join(out) + r" \\")
    lines += [r"\bottomrule", r"\end{tabular}", "}"]
    if few:
        lines.append(rf"\par\smallskip{{\footnotesize $^{{\dagger}}$ fewer than {table.min_runs} runs in the cell; "
                     r"TC averages the successful runs only.}")
    lines.append(r"\end{table*}")
    return "\n".join(lines) + "\n"


def _group_title(group: Variant | str) -> str:
    """A column group's LaTeX title: a variant's label, or a task group capitalised as the paper does."""
    return group.label(latex=True) if isinstance(group, Variant) else latex_escape(group[:1].upper() + group[1:])


_LATEX_SPECIAL = {"\\": r"\textbackslash{}", "&": r"\&", "%": r"\%", "$": r"\$", "#": r"\#", "_": r"\_",
                  "{": r"\{", "}": r"\}", "~": r"\textasciitilde{}", "^": r"\textasciicircum{}"}


def latex_escape(value: str) -> str:
    """Text as LaTeX typesets it literally."""
    return "".join(_LATEX_SPECIAL.get(ch, ch) for ch in str(value))


FORMATS = {"text": (text, "md"), "csv": (csv_text, "csv"), "latex": (latex, "tex")}


def render(tables: list[Table], fmt: str = "text") -> str:
    """Every table in one format, one after the other."""
    if fmt not in FORMATS:
        raise InputError(f"unknown table format {fmt!r}; use one of {', '.join(FORMATS)}")
    make = FORMATS[fmt][0]
    return "\n".join(make(t) for t in tables) if fmt == "csv" else "\n\n".join(make(t) for t in tables)


def write_tables(tables: list[Table], folder: Path) -> list[Path]:
    """``<folder>/<table>.md``, ``.csv`` and ``.tex`` for every table; returns the paths."""
    folder = Path(folder)
    written = []
    for t in tables:
        for make, ext in FORMATS.values():
            path = folder / f"{t.key}.{ext}"
            atomic_write(path, make(t) + ("" if ext == "csv" else "\n"))
            written.append(path)
    return written


def bench_tables(folder: Path, min_runs: int = MIN_RUNS) -> list[Table]:
    """The paper's tables of the bench in ``folder``."""
    return paper_tables(load_bench(folder), min_runs)


"""The paper's tables (Sec. V, Tables I-III) from a bench folder, as text, CSV and LaTeX.

The benches here are written by the test (results.json and runs.json with known rows), and every
expected cell is computed in the test from those rows with its own arithmetic; the tables are read
back from what the command prints or writes (markdown cells, CSV columns, LaTeX cells), never
from the code's own numbers. One test runs a real (offline) bench with ``--table paper``.
"""
from __future__ import annotations

import csv
import io
import json
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from pipflow.engine.cli import main

REPO = Path(__file__).resolve().parents[1]
CATEGORIES = ("compound", "complex", "vague")


def write_bench(folder: Path, domain: str, variants: dict[str, dict], rows: list[dict], task_ids: list[str],
                groups: list | None) -> Path:
    """A bench folder as `pipflow bench` leaves it (the parts the tables read)."""
    folder.mkdir(parents=True, exist_ok=True)
    results = {"summary": {}, "tasks": [{"id": t} for t in task_ids],
               "variants": [{"name": name} for name in variants],
               "config": {"domain": domain, "tasks": str(folder / "gone.yaml"), "workflow": None, "inputs": {},
                          "variant_values": variants, "groups": groups}}
    (folder / "results.json").write_text(json.dumps(results))
    (folder / "runs.json").write_text(json.dumps(rows))
    return folder


def row(variant: str, task: str, seed: int, success: bool, tc_max: float, tc_moved: float, gcr: float, ru: float,
        exe: float, refused: bool = False, model: str = "openai/gpt-4o") -> dict:
    return {"variant": variant, "task": task, "seed": seed, "success": success, "refused": refused,
            "tc_max": tc_max, "tc_avg": tc_moved, "tc_avg_team": tc_moved / 2, "gcr": gcr, "ru": ru, "exe": exe,
            "model": model, "status": "refused" if refused else ("succeeded" if success else "failed")}


def household_bench(tmp_path: Path) -> tuple[Path, list[dict], dict[str, list[str]]]:
    """Three variants (pip-llm, cot, two ablations) over six tasks, two per category, with runs of
    every kind: successes, failures, a right refusal (success, 0 m), and a category where one
    variant never succeeds."""
    tasks = {"compound": ["c1", "c2"], "complex": ["x1", "x2"], "vague": ["v1", "v2"]}
    variants = {"workflow=pip-llm": {"workflow": "pip-llm"}, "workflow=cot": {"workflow": "cot"},
                "workflow=pip-llm-no-as": {"workflow": "pip-llm-no-as"},
                "workflow=pip-llm-n1": {"workflow": "pip-llm-n1"}}
    rows = []
    k = 0
    for v in variants:
        for c, ids in tasks.items():
            for t in ids:
                for seed in range(2):
                    k += 1
                    ok = not (v == "workflow=cot" and c != "compound") and (k % 5 != 0)
                    refused = t == "v2" and seed == 1 and ok
                    rows.append(row(v, t, seed, ok, 0.0 if refused else 3.0 + k % 7, 0.0 if refused else 1.5 + k % 3,
                                    gcr=round(0.5 + (k % 4) / 8, 3), ru=round(0.6 + (k % 3) / 10, 3),
                                    exe=round(0.7 + (k % 2) / 5, 3), refused=refused))
    folder = write_bench(tmp_path / "household-bench", "household", variants, rows,
                         [t for ids in tasks.values() for t in ids], [[c, ids] for c, ids in tasks.items()])
    return folder, rows, tasks


def expected_cell(rows: list[dict]) -> dict:
    """A cell by the paper's definitions, computed here: rates over all runs, travel over the runs
    that succeeded by executing (not refused)."""
    n = len(rows)
    done = [r for r in rows if r["success"] and not r["refused"]]
    out = {"runs": n, "sr": sum(r["success"] for r in rows) / n, "gcr": sum(r["gcr"] for r in rows) / n,
           "ru": sum(r["ru"] for r in rows) / n, "exe": sum(r["exe"] for r in rows) / n, "tc_runs": len(done)}
    out["tc_max"] = sum(r["tc_max"] for r in done) / len(done) if done else None
    out["tc_avg"] = sum(r["tc_avg"] for r in done) / len(done) if done else None
    return out


def tc_text(c: dict) -> str:
    return "--/--" if c["tc_max"] is None else f"{c['tc_max']:.1f}/{c['tc_avg']:.1f}"


def run_cli(capsys, *argv) -> tuple[int, str, str]:
    try:
        code = main([str(a) for a in argv])
    except SystemExit as exc:
        code = exc.code if isinstance(exc.code, int) else 2
    out, err = capsys.readouterr()
    return code, out, err


def markdown_rows(text: str, title: str) -> list[list[str]]:
    """The cells of the markdown table under ``title`` (header first)."""
    block = text.split(title, 1)[1].split("\n\n", 2)[1]
    return [[c.strip() for c in line.strip().strip("|").split("|")] for line in block.splitlines()
            if line.startswith("|") and not line.startswith("|---")]


# --------------------------------------------------------------------------- Table I and III (household)
def test_table_one_text_csv_latex_from_the_rows(tmp_path, capsys):
    folder, rows, tasks = household_bench(tmp_path)
    code, out, err = run_cli(capsys, "bench-table", folder, "--min-runs", "3")
    assert code == 0, err
    table = markdown_rows(out, "Table I shape")
    head, body = table[0], table[1:]
    assert head[:6] == ["Methods", "compound SR", "compound TC max/avg", "compound GCR", "compound RU", "compound Exe"]
    labels = {"workflow=pip-llm": "PIP-LLM (openai/gpt-4o)", "workflow=cot": "CoT (openai/gpt-4o)",
              "workflow=pip-llm-no-as": "PIP-LLM w/o AS (openai/gpt-4o)", "workflow=pip-llm-n1": "PIP-LLM w/ N=1 (openai/gpt-4o)"}
    assert [r[0] for r in body] == list(labels.values())  # one row per variant, in the bench's order
    for line, variant in zip(body, labels):
        cells = line[1:]
        for g, c in enumerate(CATEGORIES):
            exp = expected_cell([r for r in rows if r["variant"] == variant and r["task"] in tasks[c]])
            sr, tc, gcr, ru, exe = cells[5 * g:5 * g + 5]
            assert sr == f"{exp['sr']:.2f}"  # 4 runs: enough
            assert gcr == f"{exp['gcr']:.2f}" and ru == f"{exp['ru']:.2f}" and exe == f"{exp['exe']:.2f}"
            if exp["tc_runs"] == 0:
                assert tc == "--/--"  # like the paper: no successful run, no travel
            elif exp["tc_runs"] < 3:
                assert tc == f"{tc_text(exp)} (n={exp['tc_runs']})"
            else:
                assert tc == tc_text(exp)
    assert "CoT (openai/gpt-4o)" in out and "--/--" in out  # CoT never succeeds off compound

    # CSV: the same cells, unrounded, with their run counts
    code, out, err = run_cli(capsys, "bench-table", folder, "--format", "csv")
    first = out.split("\n\n")[0]
    records = list(csv.DictReader(io.StringIO(first)))
    assert [r["variant"] for r in records] == list(labels)
    for rec in records:
        for c in CATEGORIES:
            exp = expected_cell([r for r in rows if r["variant"] == rec["variant"] and r["task"] in tasks[c]])
            assert int(rec[f"{c}:runs"]) == exp["runs"] and int(rec[f"{c}:tc_runs"]) == exp["tc_runs"]
            for key in ("sr", "gcr", "ru", "exe", "tc_max", "tc_avg"):
                got = rec[f"{c}:{key}"]
                assert (got == "") if exp[key] is None else (abs(float(got) - exp[key]) < 1e-3), (rec["variant"], c, key)
    assert records[1]["method"] == "cot" and records[2]["method"] == "pip-llm-no-as"


def test_table_three_lists_the_ablations_in_the_papers_order(tmp_path, capsys):
    folder, rows, tasks = household_bench(tmp_path)
    code, out, _ = run_cli(capsys, "bench-table", folder)
    table = markdown_rows(out, "Table III shape")
    assert table[0] == ["Methods", "compound SR", "compound TC max/avg", "complex SR", "complex TC max/avg",
                        "vague SR", "vague TC max/avg"]
    # N = 1 before PIP-LLM (the paper's N = 4 row) before w/o AS; no baseline in the ablation table
    assert [r[0] for r in table[1:]] == ["PIP-LLM w/ N=1 (openai/gpt-4o)", "PIP-LLM (openai/gpt-4o)",
                                         "PIP-LLM w/o AS (openai/gpt-4o)"]
    exp = expected_cell([r for r in rows if r["variant"] == "workflow=pip-llm-no-as" and r["task"] in tasks["vague"]])
    assert table[3][5] == f"{exp['sr']:.2f}"


def test_too_few_runs_are_marked_in_every_format(tmp_path, capsys):
    folder, rows, tasks = household_bench(tmp_path)
    code, text, _ = run_cli(capsys, "bench-table", folder, "--min-runs", "5")
    assert code == 0
    body = markdown_rows(text, "Table I shape")[1:]
    assert all(cell.endswith("(n=4)") for cell in body[0][1::5])  # every SR cell: 4 runs < 5
    assert "K < 5 runs" in text
    code, tex, _ = run_cli(capsys, "bench-table", folder, "--min-runs", "5", "--format", "latex")
    assert r"$^{\dagger}$ fewer than 5 runs" in tex
    first = tex.split(r"\end{table*}")[0]
    data = [line for line in first.splitlines() if line.endswith(r"\\") and line.startswith(("PIP", "CoT"))]
    assert all(cell.strip().endswith(r"$^{\dagger}$") or cell.strip() == "--/--"
               for line in data for cell in split_latex_row(line)[1:])
    code, tex, _ = run_cli(capsys, "bench-table", folder, "--format", "latex")  # default: 3 runs
    sr_cells = [split_latex_row(line)[1] for line in tex.split(r"\end{table*}")[0].splitlines()
                if line.startswith("PIP-LLM (")]
    assert sr_cells and r"\dagger" not in sr_cells[0]


def split_latex_row(line: str) -> list[str]:
    return [c.strip() for c in re.split(r"(?<!\\)&", line.rstrip().removesuffix(r"\\"))]


def check_latex(tex: str) -> None:
    """What a LaTeX compiler would choke on: braces, environments, booktabs order, and every
    row's cell count against the column spec."""
    unescaped = re.sub(r"\\[{}&%$#_]", "", tex)
    assert unescaped.count("{") == unescaped.count("}")
    for table in tex.split(r"\end{table*}")[:-1]:
        assert table.count(r"\begin{tabular}") == 1 and table.count(r"\end{tabular}") == 1
        spec = re.search(r"\\begin\{tabular\}\{l \*\{(\d+)\}\{c\}\}", table)
        assert spec, table
        width = 1 + int(spec.group(1))
        rules = [m.group(0) for m in re.finditer(r"\\(toprule|midrule|bottomrule)", table)]
        assert rules == [r"\toprule", r"\midrule", r"\bottomrule"]
        body = table.split(r"\midrule")[1].split(r"\bottomrule")[0]
        lines = [line for line in body.splitlines() if line.strip()]
        assert lines and all(len(split_latex_row(line)) == width for line in lines)
        spans = re.findall(r"\\multicolumn\{(\d+)\}", table)
        assert 1 + sum(map(int, spans)) == width
        for a, b in re.findall(r"\\cmidrule\(lr\)\{(\d+)-(\d+)\}", table):
            assert 2 <= int(a) <= int(b) <= width


def test_latex_is_booktabs_and_well_formed(tmp_path, capsys):
    folder, rows, tasks = household_bench(tmp_path)
    code, tex, _ = run_cli(capsys, "bench-table", folder, "--format", "latex")
    assert code == 0
    check_latex(tex)
    assert r"PIP-LLM w/o $\mathcal{AS}$ (openai/gpt-4o)" in tex and r"PIP-LLM w/ $\mathcal{N}=1$" in tex
    assert r"\multicolumn{5}{c}{Compound}" in tex and r"\cmidrule(lr){2-6}" in tex
    if shutil.which("pdflatex"):  # compile it for real where TeX is installed
        doc = tmp_path / "t.tex"
        doc.write_text("\\documentclass{article}\\usepackage{booktabs,graphicx,amsmath}\\begin{document}\n"
                       + tex + "\\end{document}\n")
        done = subprocess.run(["pdflatex", "-interaction=nonstopmode", doc.name], cwd=tmp_path,
                              capture_output=True, text=True, timeout=120)
        assert done.returncode == 0, done.stdout[-2000:]


# --------------------------------------------------------------------------- Table II (warehouse)
def test_table_two_one_column_group_per_framework(tmp_path, capsys):
    variants = {"workflow=pip-llm,model=openai/gpt-4o": {"workflow": "pip-llm", "model": "openai/gpt-4o"},
                "workflow=smart-llm,model=openai/gpt-4o": {"workflow": "smart-llm", "model": "openai/gpt-4o"}}
    tasks = [f"wh-{i:02d}" for i in range(1, 4)]
    rows = []
    for v in variants:
        for i, t in enumerate(tasks):
            for seed in range(3 if t != "wh-03" else 1):
                ok = "pip-llm" in v or t == "wh-01"
                rows.append(row(v, t, seed, ok and not (t == "wh-02" and seed == 2), 20.0 + 3 * i + seed,
                                15.0 + i + seed / 2, 1.0, 1.0, 1.0))
    folder = write_bench(tmp_path / "wb", "warehouse", variants, rows, tasks, None)
    code, out, err = run_cli(capsys, "bench-table", folder, "-o", tmp_path / "tables")
    assert code == 0, err
    table = markdown_rows(out, "Table II shape")
    assert table[0] == ["Task", "PIP-LLM (openai/gpt-4o) SR", "PIP-LLM (openai/gpt-4o) TC max/avg",
                        "SMART-LLM (openai/gpt-4o) SR", "SMART-LLM (openai/gpt-4o) TC max/avg"]
    for line in table[1:]:
        for g, v in enumerate(variants):
            exp = expected_cell([r for r in rows if r["variant"] == v and r["task"] == line[0]])
            sr, tc = line[1 + 2 * g:3 + 2 * g]
            few = f" (n={exp['runs']})" if exp["runs"] < 3 else ""
            assert sr == f"{100 * exp['sr']:.0f}{few}"  # percent, as the paper's Table II
            tc_few = f" (n={exp['tc_runs']})" if 0 < exp["tc_runs"] < 3 else ""
            assert tc == tc_text(exp) + tc_few
    assert table[2][3:] == ["0", "--/--"]  # SMART-LLM never solves wh-02: "--" like the paper
    assert "Table III" not in out  # no ablation in this bench
    written = sorted(p.name for p in (tmp_path / "tables").iterdir())
    assert written == ["table2.csv", "table2.md", "table2.tex"]
    check_latex((tmp_path / "tables" / "table2.tex").read_text())


def test_bench_table_refuses_what_is_no_bench(tmp_path, capsys):
    (tmp_path / "empty").mkdir()
    code, _, err = run_cli(capsys, "bench-table", tmp_path / "empty")
    assert code == 2 and "not a bench folder" in err


# --------------------------------------------------------------------------- a real bench
def test_bench_with_table_paper_writes_the_tables(tmp_path, capsys):
    """An offline bench of two paper tasks with pip-llm and its N = 1 ablation: --table paper
    writes Table II and Table III in three formats and prints them; a --min-runs without
    --table is refused before anything runs."""
    import yaml

    doc = yaml.safe_load((REPO / "benchmarks" / "warehouse" / "tasks.yaml").read_text())
    doc["world"] = str(REPO / "benchmarks" / "warehouse" / "world.yaml")
    doc["tasks"] = doc["tasks"][:2]
    tasks = tmp_path / "tasks.yaml"
    tasks.write_text(yaml.safe_dump(doc))
    code, _, err = run_cli(capsys, "bench", tasks, "--min-runs", "2", "--out", tmp_path / "nothing")
    assert code == 2 and "--table paper" in err and not (tmp_path / "nothing").exists()
    done = subprocess.run([sys.executable, "-m", "pipflow.engine.cli", "bench", str(tasks), "--matrix",
                           "workflow=pip-llm,pip-llm-n1", "--table", "paper", "--out", str(tmp_path / "b"),
                           "--jobs", "2", "-q", "--no-cache"], cwd=tmp_path, capture_output=True, text=True,
                          timeout=600)
    assert done.returncode == 0, done.stderr
    paper = tmp_path / "b" / "paper"
    assert sorted(p.name for p in paper.iterdir()) == [f"table{n}.{e}" for n in (2, 3) for e in ("csv", "md", "tex")]
    rows = json.loads((tmp_path / "b" / "runs.json").read_text())
    assert all(r["model"] == "offline" for r in rows)
    records = list(csv.DictReader(io.StringIO((paper / "table3.csv").read_text())))
    assert [r["method"] for r in records] == ["pip-llm-n1", "pip-llm"]
    for rec in records:
        exp = expected_cell([r for r in rows if r["variant"] == rec["variant"]])
        assert float(rec["all tasks:sr"]) == exp["sr"] == 1.0
        assert abs(float(rec["all tasks:tc_max"]) - exp["tc_max"]) < 1e-3
    assert "Table II shape" in done.stdout and "PIP-LLM w/ N=1 (offline)" in done.stdout
    check_latex((paper / "table2.tex").read_text() + (paper / "table3.tex").read_text())

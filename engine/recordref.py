"""Which record the user means: the one resolver behind ``show``, ``resume``, ``report``,
``compare``, ``view`` and ``mlflow-log``.

Why one: each command used to read its argument its own way (``show latest`` worked,
``report latest`` did not; ``resume`` took a bare run id, ``compare`` only paths), so a reference
that worked in one command failed in the next. A reference is, in this order:

- a path: a run folder (``run.json``) or a bench folder (``results.json``);
- ``latest`` or ``-N``: the newest run, or the N-th newest, in the runs folder (``--runs-dir``);
- a workflow's name: its newest run;
- a run folder's name, or a unique part of it: its start (``20261201T1923``) or its id, the end
  (``42c43a``);
- a bench folder's name (or a unique part of it) in ``bench-out/``, where ``pipflow bench``
  writes by default.

Anything else is a :class:`~pipflow.errors.UserError` saying what was looked for and where.
"""
from __future__ import annotations

from pathlib import Path
from typing import Any

from pipflow.errors import UserError

from .status import RunStatus
from .store import DamagedRecord, list_runs, read_json, shown_status, stale_note

#: where ``pipflow bench`` writes when no ``--out`` is given (relative to the working folder)
BENCH_DIR = Path("bench-out")


def run_infos(runs_dir: Path) -> list[tuple[Path, dict]]:
    """Every run under ``runs_dir`` with its ``run.json``, newest first by start time; a damaged
    record is listed with status ``damaged`` (one must not hide the others), one whose process
    died unrecorded as ``stale``."""
    out = []
    for run in list_runs(runs_dir):
        try:
            info = read_json(run / "run.json", None)
        except DamagedRecord as err:
            info = {"status": "damaged", "error": str(err)}
        info = info if isinstance(info, dict) else {"status": "damaged", "error": "run.json unreadable"}
        if shown_status(run, info) is RunStatus.STALE:  # its process died without saying how the run ended
            info = {**info, "status": RunStatus.STALE.value, "error": info.get("error") or stale_note(run, info)}
        out.append((run, info))
    # names have one-second resolution: two runs of one second tie on the name, not on `started`
    return sorted(out, key=lambda ri: (str(ri[1].get("started") or ""), ri[0].name), reverse=True)


def is_run(path: Path) -> bool:
    return (path / "run.json").is_file()


def is_bench(path: Path) -> bool:
    return (path / "results.json").is_file()


def bench_dirs(root: Path = BENCH_DIR) -> list[Path]:
    """The bench folders directly under ``root``, newest name first."""
    if not root.is_dir():
        return []
    try:
        return sorted((p for p in root.iterdir() if p.is_dir() and is_bench(p)), key=lambda p: p.name, reverse=True)
    except OSError:
        return []


def resolve_record(ref: str, runs_dir: str | Path = "runs", *, benches: bool = True,
                   bench_root: str | Path = BENCH_DIR) -> Path:
    """The run (or, with ``benches``, bench) folder that ``ref`` names (see the module's list)."""
    runs_dir, bench_root = Path(runs_dir), Path(bench_root)
    text = str(ref)
    p = Path(text).expanduser()
    if is_run(p) or (benches and is_bench(p)):
        return p
    if p.is_dir() and (text.endswith("/") or len(p.parts) > 1):
        what = "a run folder (run.json)" + (" or a bench folder (results.json)" if benches else "")
        raise UserError(f"{text}: a folder, but not {what}")
    if text == "latest" or (text.startswith("-") and text[1:].isdigit()):
        n = 1 if text == "latest" else int(text[1:])
        infos = run_infos(runs_dir)
        if not 1 <= n <= len(infos):
            raise UserError(f"{text}: there {'is' if len(infos) == 1 else 'are'} {len(infos)} run(s) in {runs_dir}"
                            + (" (--runs-dir names another folder)" if not infos else ""))
        return infos[n - 1][0]
    infos = run_infos(runs_dir)
    of_workflow = [run for run, info in infos if info.get("name") == text]
    if of_workflow:
        return of_workflow[0]
    runs = [run for run, _ in infos]
    hits = [r for r in runs if r.name == text] or \
        [r for r in runs if r.name.startswith(text) or r.name.endswith(text)]
    found = list(hits)
    if benches:
        marks = bench_dirs(bench_root)
        found += [b for b in marks if b.name == text] or [b for b in marks if b.name.startswith(text)]
    if len(found) == 1:
        return found[0]
    if len(found) > 1:
        raise UserError(f"{text!r} matches {len(found)} records: " + ", ".join(str(m) for m in found[:5])
                        + "; give more of the name, or the path")
    where = f"{runs_dir}" + (f" or {bench_root}/" if benches else "")
    raise UserError(f"no run{' or bench' if benches else ''} {text!r} in {where} (a path, latest, -N, a workflow's "
                    "name, or a run's id; see `pipflow runs`)")


# -- a record at a glance (``pipflow runs``, ``show``, the view's index) ----------------------

#: units of the figures a run summary prints (outputs of the built-in workflows)
UNITS = {"makespan": "s", "tc_max": "m", "tc_avg": "m", "tc_avg_team": "m", "seconds": "s"}
#: the outputs that say at a glance how a run went, in this order, when a workflow has them (the
#: simulation core's names: every domain's simulation reports them); shown by `runs` and `show`
HEADLINE = ("success", "goal_met", "makespan", "tc_max")


def headline(outputs: Any) -> str:
    """``goal met, makespan 47.9 s, TC-max 25.9 m``: the headline outputs of a run, in words."""
    if not isinstance(outputs, dict):
        return ""
    words = []
    for key in HEADLINE:
        value = outputs.get(key)
        if isinstance(value, bool):
            words.append(("succeeded" if value else "failed") if key == "success" else
                         ("goal met" if value else "goal NOT met"))
        elif isinstance(value, (int, float)):
            label = {"tc_max": "TC-max"}.get(key, key)
            words.append(f"{label} {value:.1f}" + (f" {UNITS[key]}" if key in UNITS else ""))
    return ", ".join(words)




def command_of(info: dict) -> str:
    """The command a run was given (its ``command`` input), or ``""``."""
    inputs = info.get("inputs") if isinstance(info.get("inputs"), dict) else {}
    command = inputs.get("command")
    return command if isinstance(command, str) else ""

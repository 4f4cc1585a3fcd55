#!/usr/bin/env python3
"""The understanding table: does the offline reading turn each command into its gold?

Usage: ``python benchmarks/translator.py [-v] [TASKS.yaml ...]``; without files, every task file
of ``benchmarks/language/`` and ``benchmarks/warehouse/tasks.yaml``. Each command goes through
``pipflow.language.generator.offline`` (what ``pipflow run`` does with model ``offline``) with the
world as the world loader gives it to the workflow, and is judged (benchmarks/language/README.md):

* ``understood``: goal and robot rules equal the gold (bounds compared exactly: an exact count is
  not a bound); for a ``feasible: false`` task, a refusal as impossible (a ``Refusal``, never a
  reader that could not place a word); for an ``expect: refuse`` task, a refusal to guess (as the
  bench's ``understood``: README "What the bench's numbers mean");
* ``refused``: a command refused without being understood (a lost command, but nothing moves):
  a clear, feasible command refused, an impossible one refused on a word it could not place, an
  ambiguous one refused as impossible instead of asked;
* an impossible command whose gold writes no goal (household: "no goal needed") and that the
  reader read into one is counted ``refused``: not credited, not blamed; the bench, which has the
  team and the planner, judges whether it was refused as impossible;
* ``misread``: a goal or rules different from the gold came out, or a command the world can do
  was refused as impossible: a meaning other than the command's was read. This is the defect that
  matters most, so any misread makes the exit status 1;
* ``crashed``: an exception that is not one of pipflow's errors (a bug; exit status 1 as well).

``candidate_recall`` (issue 23): of the clear, feasible commands refused as not understood, the share whose gold
reading is among the candidate readings the refusal offered (``TranslationError.candidates``).

The table is printed per construction (the task's ``construction`` label) and in total. It
times nothing that a test relies on; the mean time per command and the load average are printed
for the record only.
"""
from __future__ import annotations

import argparse
import json
import os
import sys
import time
from collections import Counter, defaultdict
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import yaml

ROOT = Path(__file__).resolve().parent.parent
if str(ROOT) not in sys.path:
    sys.path.insert(0, str(ROOT))

from pipflow.errors import PipflowError, Refusal, WorldError  # noqa: E402
from pipflow.meaning import rules_difference  # noqa: E402
from pipflow.taskdomains import task_domain  # noqa: E402
from pipflow.warehouse.meaning import goal_difference  # noqa: E402
from pipflow.values import states_goal  # noqa: E402

LANGUAGE = ROOT / "benchmarks" / "language"
PAPER_TASKS = ROOT / "benchmarks" / "warehouse" / "tasks.yaml"
VERDICTS = ("understood", "refused", "misread", "crashed")


@dataclass
class Outcome:
    """One task's verdict and what the reading produced (for the per-task lines)."""

    task_id: str
    file: str
    construction: str
    verdict: str
    detail: str
    #: for a refused clear, feasible command: whether its gold is among the readings the refusal
    #: offered (``candidates`` of the error); None for every other verdict
    gold_offered: bool | None = None


def default_task_files() -> list[Path]:
    """Every task file of the language set (a YAML mapping with ``tasks``) and the paper's ten."""
    files = [p for p in sorted(LANGUAGE.glob("*.yaml")) if "tasks" in (_read_yaml(p) or {})]
    return files + ([PAPER_TASKS] if PAPER_TASKS.exists() else [])


def _read_yaml(path: Path) -> Any:
    return yaml.safe_load(path.read_text(encoding="utf-8"))


def load_file(tasks_path: Path) -> tuple[dict, list[dict], str]:
    """(world, tasks, domain) of a task file, through its domain's loader, as ``pipflow bench``
    gets them: the world validated, the gold normalized (household ``on``/``off`` are words, not
    YAML booleans). Fields that loader does not keep (``construction``, ``expect``) come from the
    file itself. A bad file is a :class:`WorldError` that names where."""
    raw = _read_yaml(tasks_path)
    domain = raw.get("domain") or "warehouse"
    if domain == "household":
        from pipflow.household.scoring import load_tasks
    else:
        from pipflow.warehouse.world import load_tasks
    loaded = load_tasks(tasks_path)
    written = {str(t.get("id")): t for t in raw["tasks"]}
    return loaded["world"], [{**written[str(t["id"])], **t} for t in loaded["tasks"]], domain


def goal_value(value: Any) -> Any:
    """A goal count in one canonical form: an int stays an int; a bound mapping becomes
    ``("bound", at_least, at_most)`` (``None`` where open), except that equal bounds are the
    exact count. Anything else (a bool, a float, an unknown key) is kept as it is, so it can
    only equal itself."""
    if isinstance(value, bool):
        return ("bad", value)
    if isinstance(value, int):
        return value
    if isinstance(value, dict) and value and set(value) <= {"at_least", "at_most"}:
        lo, hi = value.get("at_least"), value.get("at_most")
        if lo is not None and lo == hi:
            return lo
        return ("bound", lo, hi)
    return ("bad", json.dumps(value, sort_keys=True, default=str))


def warehouse_goal(goal: dict | None) -> dict:
    """``{PLACE: {ITEM: canonical value}}``; empty places dropped (they fix nothing)."""
    return {place: {item: goal_value(v) for item, v in items.items()}
            for place, items in (goal or {}).items() if items}


def household_goal(goal: dict | None) -> str:
    """A household goal (``in`` / ``state`` / ``count``) as sorted JSON: lists are sets here."""
    def canon(x: Any) -> Any:
        if isinstance(x, dict):
            return {k: canon(v) for k, v in x.items() if v not in (None, [], {})}
        if isinstance(x, list):
            return sorted((canon(v) for v in x), key=lambda v: json.dumps(v, sort_keys=True))
        return x
    return json.dumps(canon(goal or {}), sort_keys=True)


def rules(constraints: list[dict] | None) -> list[str]:
    """Robot rules as a sorted set of canonical strings, compared by what they allow: robot
    lists as sets; the rule's source words and any other annotation left out; the order and
    repetition of rules irrelevant (rules are a conjunction); a ``never`` rule split into one
    rule per robot (never [a, b] forbids exactly what never [a] and never [b] forbid)."""
    out: set[str] = set()
    for rule in constraints or []:
        scope = {k: rule[k] for k in ("product", "from", "to") if k in rule}
        if "never" in rule:
            out |= {json.dumps({**scope, "never": [r]}, sort_keys=True) for r in rule["never"]}
        else:
            out.add(json.dumps({**scope, **{k: sorted(rule[k]) for k in ("only",) if k in rule}},
                               sort_keys=True))
    return sorted(out)


def judge(task: dict, got: dict | None, error: BaseException | None, domain: str = "warehouse",
          world: dict | None = None) -> tuple[str, str]:
    """(verdict, detail) of one reading: ``got`` is the reading's output, ``error`` what it raised.
    With the ``world``, warehouse goals are compared as the bench compares them, by the final
    stocks they accept (:func:`pipflow.warehouse.meaning.goal_difference`: zeros that conservation
    implies may be listed or not); without it, as written."""
    must_refuse = task.get("expect") == "refuse"
    infeasible = task.get("feasible", True) is False
    if error is not None:
        if not isinstance(error, PipflowError):
            return "crashed", f"{type(error).__name__}: {error}"
        return _refusal_verdict(must_refuse, infeasible, isinstance(error, Refusal)), f"refused: {error}"
    if must_refuse:
        return "misread", f"guessed {got.get('goal')} {got.get('constraints') or ''} instead of refusing"
    if infeasible and not states_goal(task):
        # an impossible command whose gold writes no goal: nothing to compare the reading with, and
        # only the whole pipeline (the team, the planner) refuses it: not credited, not blamed
        return "refused", f"read as {got.get('goal')}; the gold writes no goal to compare (the bench judges it)"
    if domain == "household":
        same = household_goal(got.get("goal")) == household_goal(task.get("goal"))
    else:
        goals = (goal_difference(world, task.get("goal"), got.get("goal")) is None if world is not None
                 else warehouse_goal(got.get("goal")) == warehouse_goal(task.get("goal")))
        same = goals and _same_rules(task.get("constraints"), got.get("constraints"), world)
    if same:
        return "understood", "gold"
    return "misread", (f"got goal {got.get('goal')} rules {got.get('constraints') or []}; "
                       f"gold goal {task.get('goal')} rules {task.get('constraints') or []}")


def _same_rules(gold: list | None, got: list | None, world: dict | None) -> bool:
    """Whether two rule sets mean the same. With the world, as the bench compares them: by the
    (robot, move) pairs they forbid (:func:`pipflow.meaning.rules_difference`: "only the day shift
    robots" and "never the night shift ones" where every robot is on one of them are one rule);
    without it, as :func:`rules` writes them."""
    if world is None:
        return rules(gold) == rules(got)
    fields = {f: list(names) for f, (names, _) in task_domain(world).rule_names(world).items()}
    return rules_difference(gold, got, list(world.get("robots") or {}), fields) is None


def _refusal_verdict(must_refuse: bool, infeasible: bool, as_impossible: bool) -> str:
    """The verdict of a refused reading, as the bench's ``understood`` and ``misread`` define it
    (README "What the bench's numbers mean", :func:`pipflow.meaning.judge`): an impossible command
    is understood only when it was refused as impossible (a ``Refusal``), never when the reader
    could not place its words; an ambiguous one only when the reader refused to guess; a command
    the world can do that is refused as impossible had an impossible meaning read into it."""
    if must_refuse and infeasible:
        return "understood"
    if must_refuse:
        return "refused" if as_impossible else "understood"
    if infeasible:
        return "understood" if as_impossible else "refused"
    return "misread" if as_impossible else "refused"


def read(command: str, world: dict) -> dict:
    """The offline reading of one command (the default path of ``pipflow run``)."""
    # deferred: the generator loads the whole language stack; the judge and the table need none of it
    from pipflow.language.generator import offline
    return offline(command, world)


def run_file(tasks_path: Path) -> list[Outcome]:
    """Every task of one file, judged. A world that does not load is a user error (exit 2)."""
    world, tasks, domain = load_file(tasks_path)
    default_label = tasks_path.parent.name if tasks_path == PAPER_TASKS else "(unlabelled)"
    out = []
    for task in tasks:
        got, error = None, None
        try:
            got = read(task["command"], world)
        except Exception as exc:  # judged: pipflow errors are refusals, anything else a crash
            error = exc
        verdict, detail = judge(task, got, error, domain, world)
        label = task.get("construction") or task.get("category") or default_label  # household: category
        file = f"{tasks_path.parent.name}/{tasks_path.stem}"
        offered = None
        clear = task.get("expect") != "refuse" and task.get("feasible", True) is not False
        if verdict == "refused" and clear:   # a clear, feasible command refused as not understood
            offered = any(judge(task, {"goal": c.get("goal"), "constraints": c.get("constraints")}, None, domain, world)[0]
                          == "understood" for c in getattr(error, "candidates", None) or [])
        out.append(Outcome(f"{file}/{task['id']}", file, label, verdict, detail, offered))
    return out


def table(outcomes: list[Outcome], by_file: bool = False) -> str:
    """Per construction (or per task file) and in total: n and the count of each verdict,
    understood as a share."""
    by: dict[str, Counter] = defaultdict(Counter)
    for o in outcomes:
        by[o.file if by_file else o.construction][o.verdict] += 1
    title = "task file" if by_file else "construction"
    width = max([len(title), len("total")] + [len(c) for c in by])
    head = f"{title:<{width}}  {'n':>4}  " + "  ".join(f"{v:>10}" for v in VERDICTS) + "  understood%"
    lines = [head, "-" * len(head)]
    for name in sorted(by):
        lines.append(_row(name, by[name], width))
    total = sum(by.values(), Counter())
    lines += ["-" * len(head), _row("total", total, width)]
    return "\n".join(lines)


def _row(name: str, counts: Counter, width: int) -> str:
    n = sum(counts.values())
    share = counts["understood"] / n if n else 0.0
    return (f"{name:<{width}}  {n:>4}  " + "  ".join(f"{counts[v]:>10}" for v in VERDICTS)
            + f"  {share:>10.1%}")


def main(argv: list[str]) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("-v", "--verbose", action="store_true", help="a line for every task, not only the misses")
    parser.add_argument("files", nargs="*", type=Path,
                        help="task files (default: every task file of benchmarks/language/ and the paper's tasks)")
    args = parser.parse_args(argv)
    verbose = args.verbose
    files = args.files or default_task_files()
    outcomes: list[Outcome] = []
    started = time.perf_counter()
    for path in files:
        if not path.is_file():
            print(f"error: {path}: no such task file", file=sys.stderr)
            return 2
        try:
            outcomes += run_file(path.resolve())
        except WorldError as exc:
            print(f"error: {exc}", file=sys.stderr)  # the message lists every problem, located
            return 2
    elapsed = time.perf_counter() - started
    for o in outcomes:
        if verbose or o.verdict != "understood":
            print(f"{o.verdict:<10} {o.task_id} [{o.construction}]: {o.detail}")
    print()
    print(table(outcomes))
    print()
    print(table(outcomes, by_file=True))
    n = len(outcomes)
    load1, load5, _ = os.getloadavg()
    if n:
        print(f"\n{n} commands in {len(files)} files; mean {elapsed / n * 1000:.1f} ms per command "
              f"(load average {load1:.2f} / {load5:.2f})")
    refused = [o for o in outcomes if o.gold_offered is not None]
    if refused:
        hit = sum(bool(o.gold_offered) for o in refused)
        print(f"candidate_recall: {hit}/{len(refused)} = {hit / len(refused):.2f} (refused clear, feasible "
              f"commands whose gold reading is among the readings the refusal offered)")
    bad = sum(o.verdict in ("misread", "crashed") for o in outcomes)
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))

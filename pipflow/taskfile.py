"""A bench task file in the plain form any domain may use (the default of
:meth:`pipflow.taskdomain.TaskDomain.load_tasks`): a world, an optional workflow and the tasks,
each checked with every problem located.

Why a shared reader: what a task file says besides its goals -- which world, ids and commands,
``feasible: false`` (a refusal as impossible is the right answer), ``expect: refuse`` (a refusal
to guess is), robot rules, per-task workflow inputs -- is the same in every domain; only the goal
is the domain's (checked by its ``goal_problems`` hook). The format, in a file's own words::

    domain: garden
    world: world.yaml            # relative to this file
    workflow: ../workflows/x.yaml  # optional, relative to this file (default: the domain's)
    tasks:
      - id: g-01
        command: water the north bed
        goal: {watered: [north]}       # the domain's goal form; not needed when a refusal is right
        constraints: [{never: [mule], action: harvest}]   # optional robot rules
        feasible: false                # optional; or expect: refuse
"""
from __future__ import annotations

from pathlib import Path
from typing import Any, Callable, Iterable

from pipflow.errors import Diagnostic, TaskFileError
from pipflow.suggest import did_you_mean
from pipflow.values import refusal_expected
from pipflow.worldfile import parse_mapping, read_world_file

#: the keys a task may have
TASK_KEYS = ("id", "command", "goal", "constraints", "feasible", "expect", "construction", "category", "inputs")
#: a problem a domain finds in a task's goal: the path inside the goal, the message, and whether
#: it is about a key (located at the key) rather than a value
GoalProblem = tuple[tuple, str, bool]


def load_task_file(path: str | Path, *, domain: str, load_world: Callable[[Path], dict], default_workflow: str,
                   goal_problems: Callable[[Any, dict], Iterable[GoalProblem]] | None = None) -> dict:
    """The task file at ``path`` of task domain ``domain`` read and checked, its world loaded with
    ``load_world``: ``{"path", "world_path", "world", "domain", "workflow", "tasks"}``. Every
    problem is located; :class:`TaskFileError` lists them all."""
    p, text = read_world_file(path)
    data, locate = parse_mapping(text, str(p), f"{domain} task")
    world_path = (p.parent / str(data.get("world", ""))).resolve()
    if not data.get("world") or not world_path.is_file():
        raise TaskFileError([Diagnostic(locate(("world",)), f"world file {data.get('world')!r} not found "
                                                            f"(looked at {world_path})")], f"invalid task file {p}")
    world = load_world(world_path)
    workflow = str((p.parent / data["workflow"]).resolve()) if data.get("workflow") else default_workflow
    diags: list[Diagnostic] = []
    tasks, seen = [], set()
    for i, t in enumerate(data.get("tasks") or []):
        where = ("tasks", i)
        if not isinstance(t, dict):
            diags.append(Diagnostic(locate(where), "a task must be a mapping"))
            continue
        tid = str(t.get("id"))
        diags += [Diagnostic(locate(where + (k,), key=True), f"task {tid}: unknown key {k!r}{did_you_mean(k, TASK_KEYS)}")
                  for k in t if k not in TASK_KEYS]
        if t.get("expect") not in (None, "refuse"):
            diags.append(Diagnostic(locate(where + ("expect",)), f"task {tid}: expect must be 'refuse', got {t.get('expect')!r}"))
        for key in ("id", "command") + (() if refusal_expected(t) else ("goal",)):
            if key not in t:
                diags.append(Diagnostic(locate(where), f"task {tid}: missing {key!r}"))
        if tid in seen:
            diags.append(Diagnostic(locate(where + ("id",)), f"duplicate task id {tid!r}"))
        seen.add(tid)
        if t.get("goal") is not None and goal_problems is not None:
            diags += [Diagnostic(locate(where + ("goal",) + inner, key=key), f"task {tid}: {message}")
                      for inner, message, key in goal_problems(t["goal"], world)]
        tasks.append({**t, "id": tid, "domain": domain, "feasible": t.get("feasible", True) is not False})
    if diags:
        raise TaskFileError(diags, f"invalid {domain} task file {p}")
    return {"path": str(p), "world_path": str(world_path), "world": world, "domain": domain,
            "workflow": workflow, "tasks": tasks}

"""Reading a run directory for its report: each step's outputs, the event log, and the family of
outputs each step declared (engine/store.py lays the directory out).

Steps are found by the family of outputs they declare (the ``shape`` of :mod:`pipflow.values`
their start event records), never by id nor by the keys of what they returned, so any workflow's
record of any task domain is reported with the same sections; a record made before shapes were
recorded is read through the registry's declaration of the step it used.
"""
from __future__ import annotations

import json
from pathlib import Path

from pipflow.engine.registry import default_registry
from pipflow.records.htmlparts import read_json


def step_outputs(d: Path) -> list[tuple[str, Path, dict]]:
    out = []
    for sd in sorted((d / "steps").glob("*")) if (d / "steps").is_dir() else []:
        outputs = read_json(sd / "outputs.json")
        if isinstance(outputs, dict):
            out.append((sd.name, sd, outputs))
    return out


def run_events(d: Path) -> list[dict]:
    """The readable events of a run's log (a torn or damaged line is skipped)."""
    try:
        lines = (d / "events.jsonl").read_text(encoding="utf-8", errors="replace").splitlines()
    except OSError:
        return []
    out = []
    for line in lines:
        try:
            event = json.loads(line)
        except json.JSONDecodeError:
            continue
        if isinstance(event, dict):
            out.append(event)
    return out


def step_shapes(d: Path) -> dict[str, str]:
    """The family of outputs each step of the record declared (its start event's ``shape``); for a
    step whose event has none (a record made before they were recorded), the declaration of the
    step it used (``uses``), as the registry holds it."""
    shapes: dict[str, str] = {}
    uses: dict[str, str] = {}
    for e in run_events(d):
        step = e.get("step")
        if e.get("event") in ("start", "skip") and isinstance(step, str):
            if isinstance(e.get("shape"), str):
                shapes[step] = e["shape"]
            elif isinstance(e.get("uses"), str):
                uses[step] = e["uses"]
    unknown = {s: u for s, u in uses.items() if s not in shapes}
    if unknown:
        registry = default_registry()
        for step, name in unknown.items():
            declared = registry.get(name)
            if declared is not None and declared.shape:
                shapes[step] = declared.shape
    return shapes


def find_step(steps, shapes: dict[str, str], family: str) -> tuple[str, Path, dict] | None:
    """The last step (in the record's order) whose outputs are of ``family``."""
    hits = [s for s in steps if shapes.get(s[0]) == family]
    return hits[-1] if hits else None

"""Experiment tracking: a run or a bench logged to MLflow (``pipflow mlflow-log RUN_OR_BENCH``),
so that it sits where many researchers already look, beside their other experiments.

The records stay pipflow's own: MLflow is a view of them, written after the fact from the record
folder alone (nothing of a run depends on MLflow; the ``mlflow`` extra installs it:
``pip install -e ".[mlflow]"``). What goes where:

* a **run** is one MLflow run named after its folder: parameters = its workflow inputs; metrics =
  its numeric outputs (makespan, TC, Exe, rounds, goal met as 0/1) and its time; tags =
  ``pipflow.workflow``, ``pipflow.model``, ``pipflow.status``, ``pipflow.kind``; artifacts = its
  report (``report.html``, written when missing) and the record's files;
* a **bench** is a parent run (parameters: the task file, seeds, workflow, backend, the matrix;
  artifacts: the report, results.json, runs.json/.csv, table.md and every run record) with one
  nested run per **variant** (parameters = the variant's matrix values and the bench's ``-i``
  inputs; metrics = its summary: SR, understood, GCR, Exe, RU, TC-max, TC-avg, makespan, and per
  task ``<metric>.<task id>``; tags: ``pipflow.variant``, ``pipflow.workflow``, ``pipflow.model``).

A record is logged once per tracking store: a second ``mlflow-log`` of the same folder finds it
by its ``pipflow.record`` tag and says so (``--again`` logs a new copy).
"""
from __future__ import annotations

import hashlib
import json
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from pipflow.errors import InputError, UserError
from pipflow.metrics import upgrade_travel_keys
from pipflow.records.benchread import METRICS, read_bench

#: MLflow's longest parameter value (longer values are cut, saying so)
PARAM_LIMIT = 500
#: the files of a run record that go to MLflow (its folder's top level, and the steps' outputs)
RUN_FILES = ("run.json", "inputs.json", "outputs.json", "metrics.json", "workflow.yaml", "events.jsonl",
             "report.html")
BENCH_FILES = ("results.json", "runs.json", "runs.csv", "table.md", "report.html")


@dataclass
class Logged:
    """What :func:`log_record` did: the MLflow run id (the parent's, for a bench), the experiment,
    where the store is, and whether it was already there."""

    run_id: str
    experiment_id: str
    tracking_uri: str
    existing: bool = False
    children: int = 0


def _mlflow():
    try:
        import mlflow  # deferred: mlflow is an optional extra (and ~1 s of import)
    except ImportError:
        raise UserError("MLflow is not installed: pip install -e \".[mlflow]\" (in pipflow's folder) or "
                        "pip install mlflow; the records themselves need nothing of it") from None
    return mlflow


def record_key(folder: Path) -> str:
    """A record's identity in a tracking store: the hash of its resolved path and its run.json or
    results.json (a record copied elsewhere is another record)."""
    folder = folder.resolve()
    marker = folder / ("results.json" if (folder / "results.json").is_file() else "run.json")
    digest = hashlib.sha256(str(folder).encode() + b"\0" + marker.read_bytes()).hexdigest()
    return digest[:24]


def _flat(value: Any, prefix: str = "") -> dict[str, str]:
    """Parameters from a nested value: ``{"a": {"b": 1}}`` -> ``{"a.b": "1"}``; long values cut."""
    if isinstance(value, dict) and value:
        out: dict[str, str] = {}
        for k, v in value.items():
            out.update(_flat(v, f"{prefix}.{k}" if prefix else str(k)))
        return out
    text = value if isinstance(value, str) else json.dumps(value, default=str)
    if len(text) > PARAM_LIMIT:
        text = text[: PARAM_LIMIT - 20] + f"... ({len(text)} chars)"
    return {_key(prefix): text}


def _key(name: str) -> str:
    """A name MLflow accepts as a key (letters, digits, ``_-. /``)."""
    return "".join(c if c.isalnum() or c in "_-. /" else "_" for c in str(name))[:250] or "_"


def _number(x: Any) -> float | None:
    if isinstance(x, bool):
        return 1.0 if x else 0.0
    return float(x) if isinstance(x, (int, float)) else None


def _read(path: Path) -> Any:
    try:
        return json.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return None


def log_record(folder: str | Path, tracking_uri: str | None = None, experiment: str = "pipflow",
               again: bool = False) -> Logged:
    """Log a run or bench folder to MLflow (see the module's docstring); returns what was done."""
    folder = Path(folder)
    is_bench = (folder / "results.json").is_file()
    if not is_bench and not (folder / "run.json").is_file():
        raise InputError(f"{folder}: neither a run folder (run.json) nor a bench folder (results.json)")
    mlflow = _mlflow()
    if tracking_uri:
        mlflow.set_tracking_uri(tracking_uri)
    uri = mlflow.get_tracking_uri()
    exp = mlflow.set_experiment(experiment)
    key = record_key(folder)
    if not again:
        found = mlflow.search_runs([exp.experiment_id], filter_string=f"tags.`pipflow.record` = '{key}'",
                                   output_format="list", max_results=1)
        if found:
            return Logged(found[0].info.run_id, exp.experiment_id, uri, existing=True)
    _write_report(folder)
    if is_bench:
        return _log_bench(mlflow, folder, exp.experiment_id, uri, key)
    run_id = _log_run(mlflow, folder, key)
    return Logged(run_id, exp.experiment_id, uri)


def _write_report(folder: Path) -> None:
    """The report goes with the record; written when missing (a record that cannot take it, on a
    read-only disk, goes without)."""
    from pipflow.records.report import write_report  # deferred: matplotlib, only when a report is missing

    if (folder / "report.html").is_file():
        return
    try:
        write_report(folder)
    except UserError:
        pass


def _log_run(mlflow: Any, folder: Path, key: str, nested: bool = False, artifact_path: str | None = None) -> str:
    info = _read(folder / "run.json") or {}
    inputs = info.get("inputs") if isinstance(info.get("inputs"), dict) else (_read(folder / "inputs.json") or {})
    outputs = upgrade_travel_keys(_read(folder / "outputs.json") or {})
    tags = {"pipflow.kind": "run", "pipflow.record": key, "pipflow.workflow": str(info.get("name") or ""),
            "pipflow.model": str(inputs.get("model") or ""), "pipflow.status": str(info.get("status") or ""),
            "pipflow.folder": str(folder.resolve())}
    if isinstance(inputs.get("command"), str):
        tags["pipflow.command"] = inputs["command"][:5000]
    metrics = {k: _number(v) for k, v in outputs.items() if _number(v) is not None}
    if _number(info.get("seconds")) is not None:
        metrics["seconds"] = _number(info.get("seconds"))
    with mlflow.start_run(run_name=folder.name, nested=nested, tags=tags) as run:
        params = {}
        for k, v in inputs.items():
            params.update(_flat(v, k))
        if params:
            mlflow.log_params(params)
        if metrics:
            mlflow.log_metrics({_key(k): v for k, v in metrics.items()})
        for name in RUN_FILES:
            if (folder / name).is_file():
                mlflow.log_artifact(str(folder / name), artifact_path=artifact_path)
        if (folder / "steps").is_dir():
            mlflow.log_artifacts(str(folder / "steps"), artifact_path="/".join(x for x in (artifact_path, "steps") if x))
        if (folder / "report").is_dir():
            mlflow.log_artifacts(str(folder / "report"), artifact_path="/".join(x for x in (artifact_path, "report") if x))
        return run.info.run_id


def _log_bench(mlflow: Any, folder: Path, experiment_id: str, uri: str, key: str) -> Logged:
    bench = read_bench(folder)
    config = bench.config
    inputs = config.get("inputs") if isinstance(config.get("inputs"), dict) else {}
    tags = {"pipflow.kind": "bench", "pipflow.record": key, "pipflow.workflow": str(config.get("workflow") or ""),
            "pipflow.model": str(inputs.get("model") or "(workflow default)"), "pipflow.folder": str(folder.resolve()),
            "pipflow.variants": str(len(bench.variants))}
    params = _flat({k: v for k, v in config.items() if k not in ("inputs", "matrix", "workflows")})
    params.update(_flat(config.get("matrix") or {}, "matrix"))
    params.update(_flat(inputs, "inputs"))
    with mlflow.start_run(run_name=folder.name, tags=tags) as parent:
        if params:
            mlflow.log_params(params)
        first = bench.variants[0]
        mlflow.log_metrics(_summary_metrics(bench, first))
        for name in BENCH_FILES:
            if (folder / name).is_file():
                mlflow.log_artifact(str(folder / name))
        for sub in ("report", "records"):
            if (folder / sub).is_dir():
                mlflow.log_artifacts(str(folder / sub), artifact_path=sub)
        workflows = config.get("workflows") if isinstance(config.get("workflows"), dict) else {}
        matrix = config.get("matrix") if isinstance(config.get("matrix"), dict) else {}
        for variant in bench.variants:
            values = _variant_values(variant, matrix)
            vtags = {"pipflow.kind": "bench variant", "pipflow.variant": variant, "pipflow.record": f"{key}/{variant}",
                     "pipflow.workflow": str(workflows.get(variant) or config.get("workflow") or ""),
                     "pipflow.model": str(values.get("model") or inputs.get("model") or "(workflow default)"),
                     "mlflow.parentRunId": parent.info.run_id}
            with mlflow.start_run(run_name=f"{folder.name} {variant}", nested=True, tags=vtags):
                vparams = {**_flat(inputs), **_flat(values)}
                vparams["variant"] = variant
                vparams["seeds"] = str(config.get("seeds", ""))
                mlflow.log_params(vparams)
                mlflow.log_metrics(_summary_metrics(bench, variant) | _task_metrics(bench, variant))
    return Logged(parent.info.run_id, experiment_id, uri, children=len(bench.variants))


def _variant_values(name: str, matrix: dict) -> dict[str, str]:
    """The matrix values a variant was made of (its name is ``k=v,k=v`` over the matrix keys)."""
    if not matrix:
        return {}
    out, rest = {}, name
    keys = list(matrix)
    for i, k in enumerate(keys):
        prefix = f"{k}="
        if not rest.startswith(prefix):
            return {"variant": name}
        rest = rest[len(prefix):]
        nxt = f",{keys[i + 1]}=" if i + 1 < len(keys) else None
        value, rest = (rest.split(nxt, 1)[0], nxt[1:] + rest.split(nxt, 1)[1]) if nxt and nxt in rest else (rest, "")
        out[k] = value
    return out


def _summary_metrics(bench: Any, variant: str) -> dict[str, float]:
    out = {}
    for m in METRICS:
        f = bench.figure(variant, None, m)
        if f.value is not None:
            out[m.key] = float(f.value)
            if f.interval is not None:
                out[f"{m.key}.ci_low"], out[f"{m.key}.ci_high"] = float(f.interval[0]), float(f.interval[1])
    s = bench.summaries.get(variant, {})
    for k in ("runs", "misread", "misread_executed"):
        if _number(s.get(k)) is not None:
            out[k] = float(s[k])
    return out


def _task_metrics(bench: Any, variant: str) -> dict[str, float]:
    out = {}
    for tid in bench.task_ids:
        for m in METRICS:
            f = bench.figure(variant, tid, m)
            if f.value is not None:
                out[_key(f"{m.key}.{tid}")] = float(f.value)
    return out


"""The ``pipflow`` command.

Exit codes: 0 success; 1 a step failed; 2 a user error (invalid workflow or world file, bad
input, unknown run, a full or read-only disk); 3 the command was refused as infeasible; 130
interrupted (128 + N for signal N: SIGTERM 143, SIGHUP 129).
``-v`` adds tracebacks and step logs; ``-q`` prints only errors and the result.
"""
from __future__ import annotations

import argparse
import json
import os
import sys
import traceback
from pathlib import Path
from typing import Any, Sequence

import yaml

from pipflow.errors import PipflowError, Refusal, UserError

from .cache import StepCache
from .cliargs import key_values, positive_int
from .progress import LiveProgress, PlainProgress
from .registry import default_registry
from .source import load_yaml, plain
from .interrupts import Interrupted, exit_code
from .recordref import UNITS, command_of as _command_of, headline, resolve_record, run_infos
from .status import RunStatus
from .store import DamagedRecord, RunStore, read_json, redact, register_secrets, shown_status, stale_note

EXIT_INTERRUPTED = 130  # Ctrl-C; other signals: interrupts.exit_code


_warned_plugins = False


def _registry():
    """The installed steps; a plugin that failed to load is a warning here (once), and an error
    only for a workflow that uses a step pipflow cannot find."""
    global _warned_plugins

    registry = default_registry()
    if registry.broken and not _warned_plugins:
        _warned_plugins = True
        for origin, why in registry.broken.items():
            print(f"warning: step plugin {origin} could not be loaded ({why}); its steps are unavailable",
                  file=sys.stderr)
    return registry


def _print_traceback(exc: BaseException) -> None:
    """``-v``: the traceback, with secrets redacted like every other line pipflow writes."""
    print(redact("".join(traceback.format_exception(exc))), file=sys.stderr, end="")


def _inputs(args: argparse.Namespace) -> tuple[dict, bool]:
    """Inputs from ``--inputs FILE`` (typed YAML) and ``-i k=v`` (text, coerced later)."""
    values: dict[str, Any] = {}
    if getattr(args, "inputs_file", None):
        data = plain(load_yaml(args.inputs_file, "inputs file"))
        if not isinstance(data, dict):
            raise UserError(f"{args.inputs_file}: an inputs file must be a mapping of input names to values")
        values.update(data)
    text_values = key_values(args.input or [])
    from_text = bool(text_values)
    if from_text:
        # typed YAML values and text values mix: render the YAML ones as text so all coerce alike
        values = {k: (v if isinstance(v, str) else yaml.safe_dump(v, default_flow_style=True).strip()) for k, v in values.items()}
        values.update(text_values)
    return values, from_text


def _options(args: argparse.Namespace, step_ids: list[str]):
    # deferred: pulls networkx and jsonschema (~350 ms; show, runs, cache and --help need neither)
    from .executor import RunOptions

    if args.quiet:
        display = None
    elif sys.stderr.isatty() and not args.verbose:
        display = LiveProgress(step_ids)
    else:
        display = PlainProgress(verbose=args.verbose)
    return RunOptions(jobs=args.jobs, use_cache=not args.no_cache, on_event=display), display




def _summary(value: Any, limit: int = 160, key: str = "") -> str:
    """One line per output: numbers rounded with their unit, a plan's first actions, lists of
    lines joined; other big values point to the run record instead of flooding the screen."""
    if isinstance(value, float):
        return f"{value:.2f}" + (f" {UNITS[key]}" if key in UNITS else "")
    if isinstance(value, list) and value and all(isinstance(a, dict) and "action" in a for a in value):
        acts = ["(" + " ".join([str(a["action"]), *map(str, a.get("args", []))]) + ")" for a in value]
        more = f" ... ({len(acts)} actions)" if len(acts) > 3 else ""
        return " ".join(acts[:3]) + more
    if isinstance(value, str) and len(value) <= 4 * limit:  # a sentence (a fallback's reason) is said whole
        return json.dumps(value)
    if isinstance(value, list) and value and all(isinstance(x, str) for x in value):
        text = "; ".join(value)
        if len(text) <= 4 * limit:
            return text
    text = json.dumps(value, default=str)
    if len(text) <= limit:
        return text
    size = f"{len(value)} items" if isinstance(value, (list, dict)) else f"{len(text)} chars"
    return f"<{type(value).__name__}, {size}: `pipflow show RUN --full` prints it whole>"


def _warnings(run_dir: Any) -> list[str]:
    """The warnings a run recorded (a planner's fallback, a cache not written...), as lines."""
    try:
        events = RunStore.open(Path(run_dir)).events() if run_dir else []
    except (OSError, UserError, ValueError):
        return []
    lines = []
    for e in events:
        if e.get("event") == "warning":
            it = f" #{e['iteration']}" if "iteration" in e else ""
            line = f"warning: step {e.get('step')}{it}: {e.get('message')}"
            if line not in lines:
                lines.append(line)
    return lines


def _print_result(result, quiet: bool) -> int:
    for line in _warnings(getattr(result, "run_dir", None)):  # said during the run; said again with the result
        print(redact(line), file=sys.stderr)
    if result.ok:
        if not quiet:
            for key, value in result.outputs.items():
                print(redact(f"{key}: {_summary(value, key=key)}"))
        print(f"run succeeded in {result.seconds:.2f}s: {result.run_dir}", file=sys.stderr)
        return 0
    where = f"step {result.error_step!r}: " if result.error_step else ""
    print(redact(f"run {result.status}: {where}{result.error}"), file=sys.stderr)
    print(f"run record: {result.run_dir}", file=sys.stderr)
    if isinstance(result.exception, Refusal):
        return 3
    if isinstance(result.exception, UserError):
        return 2
    return 1


# -- commands ------------------------------------------------------------------------------

def cmd_run(args: argparse.Namespace) -> int:
    # deferred: pulls networkx and jsonschema (~350 ms; show, runs, cache and --help need neither)
    from .runner import find_workflow, resolve_inputs, run_workflow
    # deferred: pulls networkx and jsonschema (~350 ms; show, runs, cache and --help need neither)
    from .validate import load_workflow

    values, from_text = _inputs(args)
    path = find_workflow(args.workflow)
    wf = load_workflow(path, _registry())
    if args.dry_run:
        resolved = resolve_inputs(wf, values, from_text=from_text)
        print(f"{path}: valid; would run {len(wf.all_steps())} step(s) with inputs:")

        print(redact(json.dumps(resolved, indent=2, default=str)))
        return 0
    in_order = [sid for n in wf.nodes for sid in [n.id, *(s.id for s in getattr(n, "steps", []))]]
    options, display = _options(args, in_order)
    try:
        result = run_workflow(path, values, runs_dir=args.runs_dir, options=options, inputs_from_text=from_text)
    finally:
        if display:
            display.close()
    if args.verbose and result.exception is not None and result.status is RunStatus.FAILED:
        _print_traceback(result.exception)
    chosen = _ask_reading(result, wf, values, args)
    if chosen is not None:
        _print_result(result, args.quiet)
        print(f"running reading {chosen}", file=sys.stderr)
        values = {**values, "reading": str(chosen) if from_text else chosen}
        options, display = _options(args, in_order)
        try:
            result = run_workflow(path, values, runs_dir=args.runs_dir, options=options, inputs_from_text=from_text)
        finally:
            if display:
                display.close()
    return _print_result(result, args.quiet)


#: the workflow input that runs one of the readings a refusal offered (1-based)
READING_INPUT = "reading"


def _ask_reading(result, wf, values: dict, args: argparse.Namespace) -> int | None:
    """On a terminal, a run refused with candidate readings asks which one to run (or none);
    with ``--no-input``, off a terminal, for a workflow without a ``reading`` input, or when a
    reading was already given, it asks nothing: the run stays refused, the candidates in its
    record (run.json ``candidates``). Returns the reading chosen, or None."""
    offered = result.candidates
    if (not offered or args.no_input or READING_INPUT not in getattr(wf, "inputs", {})
            or values.get(READING_INPUT) not in (None, "", "null") or not sys.stdin.isatty()):
        return None
    print("the command was not understood as said; it could mean:", file=sys.stderr)
    for k, c in enumerate(offered, 1):
        print(redact(f"  {k}. {c.get('reading')}  [from '{c.get('words')}']"), file=sys.stderr)
    while True:
        print(f"run which reading? [1-{len(offered)}, or Enter for none] ", end="", file=sys.stderr, flush=True)
        try:
            answer = input().strip()
        except EOFError:
            return None
        if answer.lower() in ("", "none", "n", "no", "0", "q"):
            return None
        if answer.isdigit() and 1 <= int(answer) <= len(offered):
            return int(answer)
        print(f"'{answer}': answer a number from 1 to {len(offered)}, or Enter for none", file=sys.stderr)


def cmd_validate(args: argparse.Namespace) -> int:
    # deferred: pulls networkx and jsonschema (~350 ms; show, runs, cache and --help need neither)
    from .validate import check_workflow

    failed = 0
    registry = _registry()
    for ref in args.files:
        # deferred: pulls networkx and jsonschema (~350 ms; show, runs, cache and --help need neither)
        from .runner import find_workflow

        try:
            path = find_workflow(ref)
        except UserError as err:
            print(err, file=sys.stderr)
            failed += 1
            continue
        wf, diagnostics = check_workflow(path, registry)
        defaults = _default_path_problems(wf) if wf is not None and not diagnostics else []
        if defaults:
            diagnostics = list(diagnostics) + defaults
        if diagnostics:
            failed += 1
            print(f"{path}: {len(diagnostics)} problem(s)", file=sys.stderr)
            for d in diagnostics:
                print(f"  {d}", file=sys.stderr)
        else:
            print(f"{path}: ok")
    return 2 if failed else 0


def _default_path_problems(wf) -> list[str]:
    """What a run would say of the workflow's path defaults (missing, or outside where the
    workflow may read by itself): a copied built-in workflow validated and then failed on its
    ``../benchmarks/...`` default. Checked by ``validate`` only, since a run may name the file."""
    # deferred: pulls networkx and jsonschema (~350 ms; show, runs, cache and --help need neither)
    from .runner import default_path_problem

    problems = []
    for name, spec in wf.inputs.items():
        value = spec.default
        if spec.type != "path" or not isinstance(value, str) or not value or "${" in value:
            continue
        base = Path(spec.loc.file).resolve().parent if spec.loc else Path(wf.file).parent
        resolved = str((base / Path(value).expanduser()).resolve())
        problem = default_path_problem(wf, name, value, resolved, base)
        if problem:
            problems.append(problem)
    return problems


def cmd_steps(args: argparse.Namespace) -> int:
    registry = _registry()
    if args.name:
        step = registry.get(args.name)
        if step is None:
            close = registry.closest(args.name)
            raise UserError(f"unknown step {args.name!r}" + (f"; did you mean {', '.join(close)}?" if close else "")
                            + registry.broken_hint())
        print(f"{step.name}  (version {step.version}{', cacheable' if step.cacheable else ''}; from {registry.origin(step.name)})")
        if step.doc:
            print(f"\n  {step.doc}\n")
        print("inputs:")
        for name, spec in step.inputs.items():
            default = "required" if spec.required else f"default {spec.default!r}"
            choices = f" (one of: {', '.join(map(str, spec.choices))})" if spec.choices else ""
            print(f"  {name:<14} {spec.type:<8} {default:<24} {spec.doc}{choices}")
        print("outputs:" + (f" (family: {step.shape})" if step.shape else ""))
        for name, type_name in step.outputs.items():
            print(f"  {name:<14} {type_name}")
        return 0
    for step in registry:
        print(f"{step.name:<22} {step.doc.splitlines()[0] if step.doc else ''}")
    if registry.broken:
        print("broken plugins (their steps are unavailable):")
        for origin, why in registry.broken.items():
            print(f"  {origin}: {why}")
    return 0


def cmd_graph(args: argparse.Namespace) -> int:
    # deferred: pulls networkx and jsonschema (~350 ms; show, runs, cache and --help need neither)
    from .graphview import render_graph
    # deferred: pulls networkx and jsonschema (~350 ms; show, runs, cache and --help need neither)
    from .runner import find_workflow
    # deferred: pulls networkx and jsonschema (~350 ms; show, runs, cache and --help need neither)
    from .validate import load_workflow

    wf = load_workflow(find_workflow(args.workflow), _registry())
    output = render_graph(wf, args.format, Path(args.output) if args.output else None)
    if output is not None:
        print(output)
    return 0


def _find_run(ref: str, runs_dir: Path) -> Path:
    """A run as every command reads a reference (:func:`.recordref.resolve_record`, runs only)."""
    return resolve_record(ref, runs_dir, benches=False)


def _outputs_of(run: Path) -> Any:
    try:
        return read_json(run / "outputs.json", None)
    except DamagedRecord:
        return None


def _clip(text: str, width: int) -> str:
    text = " ".join(str(text).split())
    return text if len(text) <= width else text[: width - 3] + "..."


def cmd_runs(args: argparse.Namespace) -> int:
    if Path(args.runs_dir).exists() and not Path(args.runs_dir).is_dir():
        raise UserError(f"--runs-dir {args.runs_dir}: a file, not a folder of runs")
    infos = run_infos(Path(args.runs_dir))
    if args.workflow:
        infos = [(r, i) for r, i in infos if args.workflow in (i.get("name"), Path(str(i.get("workflow", ""))).stem)]
    if args.status:
        infos = [(r, i) for r, i in infos if i.get("status") == args.status]
    if args.since:
        infos = [(r, i) for r, i in infos if str(i.get("started") or r.name) >= args.since]
    if not infos:
        missing = "" if Path(args.runs_dir).is_dir() else " (no such folder)"
        print(f"no runs in {args.runs_dir}{missing}" + (" that match" if args.workflow or args.status or args.since else ""))
        return 0
    for run, info in infos[: args.limit]:
        secs = info.get("seconds") if isinstance(info.get("seconds"), (int, float)) else None
        where = f"step {info['error_step']}: " if info.get("error_step") else ""
        why = where + str(info.get("error") or "")
        # a stale run's note is said whole: its end says how to continue it (`pipflow resume`)
        result = headline(_outputs_of(run)) if info.get("status") == RunStatus.SUCCEEDED else \
            why if info.get("status") == RunStatus.STALE else _clip(why, 70)
        command = _command_of(info)
        print(redact(f"{run.name:<44} {str(info.get('status', '?')):<11} {f'{secs:.1f}s' if secs is not None else '':>7}  "
                     f"{result:<42}  " + (f'"{_clip(command, 60)}"' if command else "")).rstrip())
    return 0


def cmd_show(args: argparse.Namespace) -> int:
    """A run in a screenful: what it was asked, how it ended, its headline figures and where to
    look further; ``--full`` prints every input, step and output (the whole record)."""
    store = RunStore.open(_find_run(args.run, Path(args.runs_dir)))
    problems: list[str] = []  # damaged parts of the record: reported, the rest still shown
    try:
        info = store.run_info()
    except DamagedRecord as err:
        info = {}
        problems.append(str(err))
    print(f"run       {store.root}")
    if shown_status(store.root, info) is RunStatus.STALE:
        info = {**info, "status": RunStatus.STALE.value, "error": info.get("error") or stale_note(store.root, info)}
    full = bool(getattr(args, "full", False))
    keys = ("name", "workflow", "status", "started", "finished", "seconds", "error_step", "error") if full else \
        ("name", "status", "started", "seconds", "error_step", "error")
    for key in keys:
        if info.get(key) not in (None, ""):
            value = info[key]
            shown = f"{value:.2f}" if key == "seconds" and isinstance(value, float) and not full else value
            print(redact(f"{key:<9} {shown}"))
    inputs = info.get("inputs") if isinstance(info.get("inputs"), dict) else {}
    events = store.events()
    if store.damaged_events:
        problems.append(f"{store.root / 'events.jsonl'}: damaged line(s) "
                        f"{', '.join(map(str, store.damaged_events[:10]))} skipped (a run killed while writing?)")
    try:
        outputs = read_json(store.root / "outputs.json")
    except DamagedRecord as err:
        outputs = None
        problems.append(str(err))
    if full:
        print("inputs:")
        for k, v in inputs.items():
            print(redact(f"  {k} = {json.dumps(v, default=str)[:100]}"))
        print("steps:")
        for e in events:
            if e.get("event") in ("end", "skip", "error") and e.get("step"):
                it = f" #{e['iteration']}" if "iteration" in e else ""
                status = e.get("status", "skipped" if e["event"] == "skip" else "")
                dur = f"{e['duration']:.3f}s" if isinstance(e.get("duration"), (int, float)) else ""
                print(f"  {str(e['step']) + it:<22} {str(status):<10} {dur:>9}" + (" cached" if e.get("cached") else ""))
        if outputs is not None:
            print("outputs:")
            print(redact("  " + json.dumps(outputs, indent=2, default=str).replace("\n", "\n  ")))
    else:
        if isinstance(inputs.get("command"), str):
            print(redact(f"command   {inputs['command']}"))
        given = [k for k in (info.get("given") or []) if k in inputs and k != "command"]
        if given:
            print(redact("given     " + ", ".join(f"{k}={json.dumps(inputs[k], default=str)[:60]}" for k in given)))
        ends = [e for e in events if e.get("event") in ("end", "skip", "error") and e.get("step")]
        if ends:
            counts: dict[str, int] = {}
            for e in ends:
                word = "skipped" if e["event"] == "skip" else "failed" if e["event"] == "error" else \
                    "cached" if e.get("cached") else "ran"
                counts[word] = counts.get(word, 0) + 1
            timed = [e for e in ends if isinstance(e.get("duration"), (int, float)) and "iterations" not in e
                     and not e.get("cached")]
            slow = max(timed, key=lambda e: e["duration"], default=None)
            it = f" #{slow['iteration']}" if slow and "iteration" in slow else ""
            print("steps     " + ", ".join(f"{n} {w}" for w, n in counts.items())
                  + (f"; slowest {slow['step']}{it} {slow['duration']:.2f}s" if slow else ""))
        if isinstance(outputs, dict) and outputs:
            line = headline(outputs)
            if line:
                print(f"result    {line}")
            print("outputs:")
            for key, value in outputs.items():
                print(redact(f"  {key}: {_summary(value, limit=100, key=key)}"))
        print(f"more      pipflow show {args.run} --full (every input, step and output); "
              f"pipflow report {args.run} (HTML with pictures); files in {store.root}")
    for problem in problems:
        print(f"warning: {problem}", file=sys.stderr)
    return 0


def cmd_resume(args: argparse.Namespace) -> int:
    # deferred: pulls networkx and jsonschema (~350 ms; show, runs, cache and --help need neither)
    from .runner import resume_run

    run_dir = _find_run(args.run, Path(args.runs_dir))
    options, display = _options(args, [])
    try:
        result = resume_run(run_dir, options=options, registry=_registry())
    finally:
        if display:
            display.close()
    return _print_result(result, args.quiet)


def cmd_cache(args: argparse.Namespace) -> int:
    cache = StepCache(Path(args.dir) if args.dir else None)
    count = cache.clear()  # refuses (exit 2) a folder pipflow did not mark as its cache
    print(f"removed {count} cache entr{'y' if count == 1 else 'ies'} from {cache.root}")
    others = cache.leftovers()
    if others:
        print(f"kept {len(others)} item(s) pipflow did not write: " + ", ".join(p.name for p in others[:5]),
              file=sys.stderr)
    return 0


# -- parser --------------------------------------------------------------------------------

def build_parser() -> argparse.ArgumentParser:
    common = argparse.ArgumentParser(add_help=False)
    common.add_argument("-v", "--verbose", action="store_true", help="tracebacks and step logs")
    common.add_argument("-q", "--quiet", action="store_true", help="only errors and the result")
    common.add_argument("--runs-dir", default="runs", help="where run records go (default: ./runs)")

    parser = argparse.ArgumentParser(prog="pipflow", description="PIP-LLM workflows: language command -> robot team plan.",
                                     parents=[common])
    # the sub-commands take the same options, without defaults of their own: a default there
    # would silently reset a value given before the command (`pipflow -q --runs-dir D run ...`)
    common = argparse.ArgumentParser(add_help=False, argument_default=argparse.SUPPRESS)
    common.add_argument("-v", "--verbose", action="store_true", help="tracebacks and step logs")
    common.add_argument("-q", "--quiet", action="store_true", help="only errors and the result")
    common.add_argument("--runs-dir", help="where run records go (default: ./runs)")
    sub = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")

    run = sub.add_parser("run", parents=[common], help="validate and run a workflow")
    run.add_argument("workflow", help="workflow file, or the name of a built-in workflow")
    run.add_argument("-i", "--input", action="append", metavar="KEY=VALUE", help="set an input (repeatable)")
    run.add_argument("--inputs", dest="inputs_file", metavar="FILE", help="YAML file of inputs")
    run.add_argument("--dry-run", action="store_true", help="validate and show the inputs; run nothing")
    run.add_argument("--jobs", type=positive_int, default=1, help="independent steps to run at once")
    run.add_argument("--no-cache", action="store_true", help="ignore and do not write the step cache")
    run.add_argument("--no-input", action="store_true",
                     help="never ask: a command refused with candidate readings stays refused (they are in the record)")
    run.set_defaults(func=cmd_run)

    val = sub.add_parser("validate", parents=[common], help="check workflow files; report every problem")
    val.add_argument("files", nargs="+")
    val.set_defaults(func=cmd_validate)

    steps = sub.add_parser("steps", parents=[common], help="list steps, or show one in full")
    steps.add_argument("name", nargs="?")
    steps.set_defaults(func=cmd_steps)

    graph = sub.add_parser("graph", parents=[common], help="show a workflow's DAG (text, dot or png)")
    graph.add_argument("workflow")
    graph.add_argument("--format", choices=["text", "dot", "png"], default="text")
    graph.add_argument("-o", "--output", help="file to write (png needs it)")
    graph.set_defaults(func=cmd_graph)

    runs = sub.add_parser("runs", parents=[common], help="list runs, newest first")
    runs.add_argument("--limit", type=positive_int, default=30)
    runs.add_argument("--workflow", help="only runs of this workflow (its name or file stem)")
    runs.add_argument("--status", help="only runs with this status (succeeded, failed, refused, ...)")
    runs.add_argument("--since", help="only runs started at or after this UTC date/time (2026-11-30, 2026-11-30T05)")
    runs.set_defaults(func=cmd_runs)

    show = sub.add_parser("show", parents=[common], help="summarise a run")
    show.add_argument("run", help="run directory, its name or a unique part of it (its id), a workflow's name "
                                  "(its newest run), latest, or -N (the N-th newest)")
    show.add_argument("--full", action="store_true", help="every input, step and output (default: a summary)")
    show.set_defaults(func=cmd_show)

    resume = sub.add_parser("resume", parents=[common], help="rerun only what did not finish")
    resume.add_argument("run")
    resume.add_argument("--jobs", type=positive_int, default=1)
    resume.add_argument("--no-cache", action="store_true")
    resume.set_defaults(func=cmd_resume)

    cache = sub.add_parser("cache", parents=[common], help="manage the step cache")
    cache_sub = cache.add_subparsers(dest="cache_command", required=True)
    clear = cache_sub.add_parser("clear", parents=[common], help="remove every cached step result")
    clear.add_argument("--dir", help="cache directory (default: $PIPFLOW_CACHE_DIR or ~/.cache/pipflow/steps)")
    clear.set_defaults(func=cmd_cache)

    _plugin_commands(sub, common)
    return parser


def _plugin_commands(sub, common: argparse.ArgumentParser) -> None:
    """Sub-commands registered by installed packages (entry-point group ``pipflow.commands``:
    a function ``register(subparsers, common)``); pipflow's own bench/report/view/compare come this
    way too, so the engine's CLI imports nothing of the library above it. A package whose
    commands fail to load is reported and skipped: the other commands still work."""
    from importlib.metadata import entry_points

    for ep in sorted(entry_points(group="pipflow.commands"), key=lambda e: e.name):
        try:
            ep.load()(sub, common)
        except Exception as err:  # a broken plugin must not take the whole CLI down
            print(f"warning: commands of {ep.value!r} not loaded: {type(err).__name__}: {err}", file=sys.stderr)


def main(argv: Sequence[str] | None = None) -> int:
    register_secrets()  # whatever this command prints or writes, secrets from the environment are redacted
    parser = build_parser()
    args = parser.parse_args(argv)
    try:
        return args.func(args)
    except KeyboardInterrupt as err:
        print(f"interrupted by {err.name}" if isinstance(err, Interrupted) else "interrupted", file=sys.stderr)
        return exit_code(err)
    except BrokenPipeError:  # `pipflow show RUN | head`: the reader left, nothing is wrong
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 0
    except PipflowError as err:
        if args.verbose:
            _print_traceback(err)

        print(redact(f"error: {err}" if not getattr(err, "diagnostics", None) else str(err)), file=sys.stderr)
        return err.exit_code


if __name__ == "__main__":
    sys.exit(main())

"""Validate a workflow before anything runs, and report every problem at once.

Checks, each located by file, line and column: YAML syntax, the JSON Schema
(``schemas/workflow.schema.json``), duplicate ids, unknown step names (with the closest known
names), unknown or missing arguments, literal arguments of the wrong type, references to unknown
inputs, steps or outputs (and their declared types), invalid expressions, and cycles (naming the
steps on the cycle). A loop without a maximum is a schema error.
"""
from __future__ import annotations

import functools
import json
from pathlib import Path
from typing import Any

import jsonschema
import networkx as nx

from pipflow.errors import Diagnostic, InputError, Location, SourceFileError, WorkflowError
from pipflow.resources import data_file
from pipflow.suggest import closest

from .expr import ExpressionError, Reference, has_expression, split_template, template_references
from .model import LoopSpec, StepSpec, Workflow, build_workflow, read_workflow_data
from .registry import Registry, default_registry
from .source import SourceDict, SourceList
from .store import looks_secret
from .types import type_matches

SPECIAL = {"inputs", "env", "previous", "iteration"}


@functools.lru_cache(maxsize=None)
def workflow_schema() -> dict:
    text = data_file("schemas/workflow.schema.json").read_text(encoding="utf-8")
    return json.loads(text)


def load_workflow(path: str | Path, registry: Registry | None = None) -> Workflow:
    """Load and validate; raise :class:`WorkflowError` listing every problem."""
    workflow, diagnostics = check_workflow(path, registry)
    if diagnostics:
        raise WorkflowError(diagnostics, title=f"{path}: {len(diagnostics)} problem(s); nothing was run")
    assert workflow is not None
    return workflow


def check_workflow(path: str | Path, registry: Registry | None = None) -> tuple[Workflow | None, list[Diagnostic]]:
    path = Path(path)
    diagnostics: list[Diagnostic] = []
    try:
        data, files = read_workflow_data(path, diagnostics)
    except SourceFileError as err:
        return None, err.diagnostics
    if not isinstance(data, SourceDict):
        return None, [Diagnostic(Location(str(path), 1, 1), "a workflow must be a mapping (name, inputs, steps, outputs)")]
    schema_problems = _schema_diagnostics(data, str(path))
    diagnostics += schema_problems
    if "extends" in data:  # the base could not be used (reported above): nothing more to check
        if not diagnostics:  # never "valid" without a merged workflow to run
            diagnostics.append(Diagnostic(data.where("extends"), "extends: the base workflow could not be merged"))
        return None, diagnostics
    steps = data.get("steps") if isinstance(data.get("steps"), list) else []
    for raw in steps:
        if isinstance(raw, SourceDict) and "id" in raw and "uses" not in raw and "loop" not in raw:
            # an override entry (only id/with/...) is valid only in a workflow that extends another;
            # merged ones are gone by now, so this one would be dropped without a word
            diagnostics.append(Diagnostic(raw.loc, f"step {raw['id']!r}: needs 'uses' (a step) or 'loop'; "
                                                   "changing only parts of a step needs 'extends'"))
    inner = [x for raw in steps if isinstance(raw, SourceDict) and isinstance(raw.get("loop"), dict)
             and isinstance(raw["loop"].get("steps"), list) for x in raw["loop"]["steps"]]
    for raw in [*steps, *inner]:
        if isinstance(raw, SourceDict) and "inside" in raw:  # merged ones are gone by now
            diagnostics.append(Diagnostic(raw.where("inside"), f"step {raw.get('id')!r}: 'inside' adds a step to an "
                                                               "inherited loop, which needs 'extends' (in a loop "
                                                               "of this file, list the step under its 'steps')"))
    if schema_problems:  # merge problems (remove/override of unknown ids) do not stop the checks below
        return None, diagnostics
    workflow = build_workflow(path, data, files)
    diagnostics += _semantic_diagnostics(workflow, registry or default_registry())
    return workflow, diagnostics


# --- schema -------------------------------------------------------------------------------

def _locate(data: Any, path: list, file: str) -> Location:
    node, loc = data, getattr(data, "loc", None)
    for key in path:
        if isinstance(node, (SourceDict, SourceList)):
            loc = node.where(key) or loc
        try:
            node = node[key]
        except (KeyError, IndexError, TypeError):
            break
        loc = getattr(node, "loc", None) or loc
    return loc or Location(file)


_NODE_SHAPES = [{"$ref": "#/$defs/step"}, {"$ref": "#/$defs/loop"}, {"$ref": "#/$defs/override"}]


@functools.lru_cache(maxsize=None)
def _validator() -> jsonschema.Draft202012Validator:
    return jsonschema.Draft202012Validator(workflow_schema())


@functools.lru_cache(maxsize=None)
def fast_validator() -> jsonschema.Draft202012Validator | None:
    """A validator that accepts exactly the workflows the schema accepts, several times faster,
    to answer "valid?" before the exact error messages are worked out (only for invalid files).

    Why it is faster: a step node is ``oneOf`` three shapes (step, loop, override), and jsonschema
    tries all three for every node; but the shapes exclude each other by key (a step has ``uses``,
    a loop ``loop`` and no ``uses``, an override neither), so the node is checked against the one
    shape its keys select (``if``/``then``/``else``). ``$ref`` to ``$defs`` are inlined (each
    lookup goes through the ``referencing`` registry otherwise). tests/test_engine_schema_fast.py
    checks that both validators agree on generated nodes. None if the schema's node is not the
    three-shape ``oneOf`` this rewrite assumes."""
    schema = workflow_schema()
    defs = dict(schema.get("$defs", {}))
    node = defs.get("node")
    if not isinstance(node, dict) or node.get("oneOf") != _NODE_SHAPES:
        return None
    defs["node"] = {**{k: v for k, v in node.items() if k != "oneOf"},
                    "if": {"required": ["uses"]}, "then": {"$ref": "#/$defs/step"},
                    "else": {"if": {"required": ["loop"]}, "then": {"$ref": "#/$defs/loop"},
                             "else": {"$ref": "#/$defs/override"}}}
    return jsonschema.Draft202012Validator(_inline_refs({**schema, "$defs": defs}, defs, ()))


def _inline_refs(value: Any, defs: dict, inside: tuple) -> Any:
    """``value`` with every ``{"$ref": "#/$defs/X"}`` replaced by (a copy of) X; a reference
    back into a definition being inlined (recursion) is kept as it is."""
    if isinstance(value, dict):
        ref = value.get("$ref")
        if len(value) == 1 and isinstance(ref, str) and ref.startswith("#/$defs/"):
            name = ref.removeprefix("#/$defs/")
            if name in defs and name not in inside:
                return _inline_refs(defs[name], defs, (*inside, name))
            return value
        return {k: (v if k == "$defs" else _inline_refs(v, defs, inside)) for k, v in value.items()}
    if isinstance(value, list):
        return [_inline_refs(v, defs, inside) for v in value]
    return value


def _schema_diagnostics(data: SourceDict, file: str) -> list[Diagnostic]:
    schema = workflow_schema()
    fast = fast_validator()
    if fast is not None and fast.is_valid(data):
        return []
    validator = _validator()
    out: list[Diagnostic] = []
    for error in sorted(validator.iter_errors(data), key=lambda e: list(map(str, e.absolute_path))):
        for leaf in _specific_errors(error, schema):
            path = list(leaf.absolute_path)
            where = ".".join(str(p) for p in path) or "top level"
            out.append(Diagnostic(_locate(data, path, file), f"{where}: {_message(leaf)}"))
    return out


def _specific_errors(error: jsonschema.ValidationError, schema: dict) -> list[jsonschema.ValidationError]:
    """A step node matches one of three shapes (step, loop, override); report the errors of
    the shape it was meant to be, not "is not valid under any of the given schemas"."""
    if error.validator != "oneOf" or not isinstance(error.instance, dict):
        return [error]
    node = error.instance
    shape = "loop" if "loop" in node else "step" if "uses" in node else "override"
    sub = jsonschema.Draft202012Validator({**schema["$defs"][shape], "$defs": schema["$defs"]})
    errors = []
    for e in sub.iter_errors(node):
        e.path.extendleft(reversed(list(error.absolute_path)))
        errors.append(e)
    return errors or [error]


def _message(error: jsonschema.ValidationError) -> str:
    if error.validator == "required":
        missing = [r for r in error.validator_value if r not in (error.instance or {})]
        if "max" in missing and "until" in getattr(error.instance, "keys", lambda: [])():
            return "a loop needs 'max' (the most iterations); unbounded loops are not allowed"
        return "missing required " + ", ".join(repr(m) for m in missing)
    if error.validator == "additionalProperties":
        extra = sorted(set(error.instance) - set(error.schema.get("properties", {})), key=str)  # keys may be null, numbers
        hints = []
        for e in extra:
            close = closest(str(e), list(error.schema.get("properties", {})), n=1)
            hints.append(f"{e!r}" + (f" (did you mean {close[0]!r}?)" if close else ""))
        return "unknown key " + ", ".join(hints)
    if error.validator == "not" and error.schema.get("anyOf"):
        return "cannot mix an override with 'uses' or 'loop'"
    return error.message


# --- semantics ----------------------------------------------------------------------------

def _semantic_diagnostics(wf: Workflow, registry: Registry) -> list[Diagnostic]:
    out: list[Diagnostic] = []
    steps = wf.all_steps()
    seen: dict[str, Location | None] = {}
    for node in [*wf.nodes, *[s for n in wf.nodes if isinstance(n, LoopSpec) for s in n.steps]]:
        if node.id in seen:
            out.append(Diagnostic(node.loc, f"duplicate step id {node.id!r} (first defined at {seen[node.id]})"))
        else:
            seen[node.id] = node.loc
    by_id = {s.id: s for s in steps}
    loops = {n.id: n for n in wf.nodes if isinstance(n, LoopSpec)}

    for name, spec in wf.inputs.items():
        if not spec.required and not type_matches(spec.default, spec.type, allow_expr=True):
            out.append(Diagnostic(spec.loc, f"input {name!r}: default {spec.default!r} is not of type {spec.type}"))

    for s in steps:
        step = registry.get(s.uses)
        if step is None:
            close = registry.closest(s.uses)
            hint = f"; did you mean {', '.join(repr(c) for c in close)}?" if close else ""
            out.append(Diagnostic(s.raw.where("uses"), f"step {s.id!r}: unknown step {s.uses!r}{hint}"
                                                       f"{registry.broken_hint()}"))
            continue
        for arg, value in s.args.items():
            if arg not in step.inputs:
                close = closest(arg, list(step.inputs), n=1)
                hint = f"; did you mean {close[0]!r}?" if close else f"; it takes {', '.join(step.inputs) or 'none'}"
                out.append(Diagnostic(s.arg_loc(arg), f"step {s.id!r} ({s.uses}): unknown argument {arg!r}{hint}"))
                continue
            declared = step.inputs[arg]
            if not type_matches(value, declared.type, allow_expr=True):
                out.append(Diagnostic(s.arg_loc(arg), f"step {s.id!r}: argument {arg!r} must be {declared.type}, got {value!r}"))
            problem = _value_problem(declared, value, wf)
            if problem:
                out.append(Diagnostic(s.arg_loc(arg), f"step {s.id!r}: argument {arg!r}: {problem}"))
            ref_type = _reference_type(value, wf, by_id, registry)
            if ref_type and declared.type not in ("any",) and ref_type not in ("any", declared.type) \
                    and not (declared.type == "number" and ref_type == "integer") \
                    and not (declared.type == "string" and ref_type == "path") \
                    and not (declared.type == "path" and ref_type == "string"):
                out.append(Diagnostic(s.arg_loc(arg), f"step {s.id!r}: argument {arg!r} must be {declared.type}, "
                                                      f"but {value} is {ref_type}"))
        for name, declared in step.inputs.items():
            if declared.required and name not in s.args:
                out.append(Diagnostic(s.loc, f"step {s.id!r} ({s.uses}): missing required argument {name!r}"
                                             + (f" ({declared.doc})" if declared.doc else "")))

    out += _reference_diagnostics(wf, by_id, loops, registry)
    out += _cycle_diagnostics(wf, by_id)
    return out


def _value_problem(declared: Any, value: Any, wf: Workflow, given: dict | None = None) -> str | None:
    """What the step input's ``Choices`` and its own ``check`` say of a literal value, or of the
    workflow input that the value is exactly a reference to (its given value, else its literal
    default, and every value the workflow input's own ``choices`` allow). Why here: a value outside
    a step's choices used to pass validation and fail the run after the whole refinement loop."""
    if declared.check is None and not declared.choices:
        return None
    name = None
    if isinstance(value, str) and has_expression(value):
        name = _input_reference(value)
        if name is None or name not in wf.inputs:
            return None
        if given is not None and name in given:
            value = given[name]
        else:
            spec = wf.inputs[name]
            if declared.choices and spec.choices:
                outside = [c for c in spec.choices if c not in declared.choices]
                if outside:
                    return (f"input {name!r} allows {', '.join(map(repr, outside))}, which this step does not accept "
                            f"(one of {', '.join(map(repr, declared.choices))})")
            value = spec.default
            if value is None or has_expression(value):
                return None
    if value is None:
        return None
    if declared.choices and value not in declared.choices:
        close = closest(str(value), declared.choices, n=1)
        via = f" (the {'given value' if given is not None and name in (given or {}) else 'default'} of input {name!r})" \
            if name else ""
        return (f"{value!r}{via} is not one of {', '.join(map(repr, declared.choices))}"
                + (f"; did you mean {close[0]!r}?" if close else ""))
    return declared.check(value, wf.file.parent) if declared.check is not None else None


def _plain_reference(value: Any) -> tuple[str, str] | None:
    """``(name, attr)`` when ``value`` is exactly one plain reference ``${name.attr}``."""
    if not isinstance(value, str):
        return None
    try:
        parts = split_template(value.strip())
    except ExpressionError:
        return None
    if len(parts) != 1 or not parts[0][0]:
        return None
    source = parts[0][1].strip()
    if not all(ch.isalnum() or ch in "._" for ch in source) or source.count(".") != 1:
        return None
    name, attr = source.split(".")
    return name, attr


def _input_reference(value: Any) -> str | None:
    """``X`` when ``value`` is exactly ``${inputs.X}``."""
    ref = _plain_reference(value)
    return ref[1] if ref and ref[0] == "inputs" else None


def check_given_values(wf: Workflow, registry: Registry, given: dict) -> None:
    """Run the argument checks on input values set for this run (``-i``, ``--inputs``, the API);
    raise :class:`InputError` naming the input, the step and the problem."""
    problems = []
    for s in wf.all_steps():
        step = registry.get(s.uses)
        for arg, value in (s.args.items() if step else ()):
            declared = step.inputs.get(arg)
            name = _input_reference(value)
            if declared is None or name is None or name not in given:
                continue
            problem = _value_problem(declared, value, wf, given)
            if problem:
                problems.append(f"input {name!r} (used by step {s.id!r}): {problem}")
    if problems:
        raise InputError("; ".join(problems))


def _reference_type(value: Any, wf: Workflow, by_id: dict, registry: Registry) -> str | None:
    """The declared type of a value that is exactly one plain reference, if known."""
    ref = _plain_reference(value)
    if ref is None:
        return None
    name, attr = ref
    if name == "inputs" and attr in wf.inputs:
        return wf.inputs[attr].type
    if name in by_id:
        step = registry.get(by_id[name].uses)
        if step and attr in step.outputs:
            return step.outputs[attr]
    return None


def _expressions_of(s: StepSpec | LoopSpec) -> list[tuple[Any, Location | None]]:
    if isinstance(s, LoopSpec):
        loop = s.raw["loop"]
        return [(s.when, s.raw.where("when")), (s.max, loop.where("max")), (s.until, loop.where("until"))]
    return [(v, s.arg_loc(k)) for k, v in s.args.items()] + [(s.when, s.raw.where("when"))]


def _reference_diagnostics(wf: Workflow, by_id: dict, loops: dict, registry: Registry) -> list[Diagnostic]:
    """Every ``${...}`` of every step, loop and output: it must parse and name what exists."""
    owners = wf.node_of()
    sites: list[tuple[str, Any, Location | None, Any, str | None]] = []  # label, value, where, node, loop
    for n in wf.nodes:
        members = [(n, n.id if isinstance(n, LoopSpec) else None)]
        if isinstance(n, LoopSpec):
            members += [(inner, n.id) for inner in n.steps]
        for node, loop_id in members:
            sites += [(f"step {node.id!r}", value, loc, node, loop_id) for value, loc in _expressions_of(node)]
    output_data = wf.data.get("outputs")
    for key, value in wf.outputs.items():
        loc = output_data.where(key) if isinstance(output_data, SourceDict) else None
        sites.append((f"output {key!r}", value, loc, None, None))
    out: list[Diagnostic] = []
    for name, spec in wf.inputs.items():  # a default is resolved before any step: env only
        try:
            refs = template_references(spec.default)
        except ExpressionError as err:
            out.append(Diagnostic(spec.loc, f"input {name!r}: default: {err}"))
            continue
        for ref in refs:
            problem = _check_env(ref, wf) if ref.name == "env" else \
                f"a default may read only environment variables (${{env.NAME}}), not {ref.name!r}"
            if problem:
                out.append(Diagnostic(spec.loc, f"input {name!r}: default: {problem}"))
    for label, value, loc, node, loop_id in sites:
        try:
            refs = template_references(value)
        except ExpressionError as err:
            out.append(Diagnostic(loc, f"{label}: {err}"))
            continue
        for ref in refs:
            problem = _check_reference(ref, node, loop_id, wf, by_id, loops, owners, registry)
            if problem:
                out.append(Diagnostic(loc, f"{label}: {problem}"))
    return out


def _check_env(ref: Reference, wf: Workflow) -> str | None:
    """A workflow reads only the environment variables it declares under ``env:`` (a shared
    workflow file must not be able to read a user's keys by naming them)."""
    if ref.attr is None:
        return "'env' must name one variable, as ${env.NAME}, declared under 'env:'"
    if looks_secret(ref.attr):  # declared or not: declaring it would not help
        declared = "declared" if ref.attr in wf.env else "not declared"
        return (f"environment variable {ref.attr!r} is {declared}, and it holds a key (its name says so): a "
                "workflow never reads a key as a value, which could reach a prompt or a server the workflow "
                "names. Providers read their keys from the environment themselves; remove ${env." + ref.attr
                + "} (listing it under 'env:' does not allow it)")
    if ref.attr not in wf.env:
        return (f"environment variable {ref.attr!r} is not declared; add it to the workflow's "
                f"top-level 'env:' list (env: [{', '.join([*wf.env, ref.attr])}])")
    return None


def _check_reference(ref: Reference, node, loop_id, wf: Workflow, by_id, loops, owners, registry) -> str | None:
    if ref.name == "inputs":
        if ref.attr is None or ref.attr in wf.inputs:
            return None
        close = closest(ref.attr, list(wf.inputs), n=1)
        return f"unknown input 'inputs.{ref.attr}'" + (f"; did you mean 'inputs.{close[0]}'?" if close else
                                                       f"; declared inputs: {', '.join(wf.inputs) or 'none'}")
    if ref.name == "env":
        return _check_env(ref, wf)
    if ref.name in ("previous", "iteration"):
        if loop_id is None:
            return f"'{ref.name}' is only defined inside a loop"
        if ref.name == "previous" and ref.attr is not None and ref.attr not in {s.id for s in loops[loop_id].steps}:
            return f"'previous.{ref.attr}': {ref.attr!r} is not a step of loop {loop_id!r}"
        return None
    if ref.name in loops:
        if ref.attr is not None and ref.attr not in ("iterations", "done"):
            return f"'{ref.name}.{ref.attr}': a loop's outputs are 'iterations' and 'done'"
        return None
    if ref.name not in by_id:
        close = closest(ref.name, list(by_id) + list(loops) + ["inputs", "env"], n=1)
        return f"unknown reference {ref.name!r}" + (f"; did you mean {close[0]!r}?" if close else "")
    if node is not None and ref.name == node.id:
        return f"step {ref.name!r} refers to its own outputs"
    target = by_id[ref.name]
    if loop_id is not None and isinstance(node, LoopSpec) and target.loop == loop_id:
        pass  # until/max of a loop may read its own steps
    step = registry.get(target.uses)
    if step is not None and step.outputs and ref.attr is not None and ref.attr not in step.outputs:
        close = closest(ref.attr, list(step.outputs), n=1)
        return (f"step {ref.name!r} ({target.uses}) has no output {ref.attr!r}"
                + (f"; did you mean {close[0]!r}?" if close else f"; its outputs: {', '.join(step.outputs)}"))
    return None


def dependency_graph(wf: Workflow) -> nx.DiGraph:
    """Edges between step ids (inner steps of loops included) read off their references."""
    graph = nx.DiGraph()
    ids = {s.id for s in wf.all_steps()} | {n.id for n in wf.nodes}
    for node in [*wf.nodes, *[s for n in wf.nodes if isinstance(n, LoopSpec) for s in n.steps]]:
        graph.add_node(node.id)
        for value, _ in _expressions_of(node):
            try:
                refs = template_references(value)
            except ExpressionError:
                continue
            for ref in refs:
                if ref.name in ids and ref.name != node.id:
                    if isinstance(node, LoopSpec) and ref.name in {s.id for s in node.steps}:
                        continue  # a loop's `until` reads its own steps: not a dependency
                    graph.add_edge(ref.name, node.id)
    return graph


def _cycle_diagnostics(wf: Workflow, by_id: dict) -> list[Diagnostic]:
    graph = dependency_graph(wf)
    out = []
    locations = {s.id: s.loc for s in wf.all_steps()} | {n.id: n.loc for n in wf.nodes}
    order = {sid: i for i, sid in enumerate(locations)}
    for cycle in nx.simple_cycles(graph):
        first = min(range(len(cycle)), key=lambda i: order.get(cycle[i], len(order)))
        cycle = cycle[first:] + cycle[:first]  # start at the step defined first: stable messages
        names = " -> ".join([*cycle, cycle[0]])
        out.append(Diagnostic(locations.get(cycle[0]), f"cycle between steps: {names}"))
        if len(out) >= 10:
            break
    if not out:  # steps inside a loop and outside it can still form a cycle through the loop
        owners = wf.node_of()
        nodes = nx.DiGraph((owners[a], owners[b]) for a, b in graph.edges if owners[a] != owners[b])
        for cycle in nx.simple_cycles(nodes):
            names = " -> ".join([*cycle, cycle[0]])
            out.append(Diagnostic(locations.get(cycle[0]), f"cycle between steps (through a loop): {names}"))
            break
    return out

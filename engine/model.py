"""The workflow model: a workflow file (after ``extends`` is merged) as typed specs.

Loading never raises on content problems: it records them as diagnostics so that
``pipflow validate`` can report every problem at once.
"""
from __future__ import annotations

import copy
import functools
import os
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Union

from pipflow.errors import Diagnostic, Location, SourceFileError
from pipflow.resources import data_dir

from .source import SourceDict, SourceList, load_yaml, plain


@dataclass
class InputSpec:
    name: str
    type: str = "any"
    default: Any = None
    required: bool = False
    doc: str = ""
    choices: list | None = None
    loc: Location | None = None


def folder_of(file: str) -> Path:
    """The resolved folder of a workflow file. Every step and argument of a file asks for the
    same folder, and ``Path.resolve`` stats each component: it is computed once per file (and
    per working folder, for a relative name)."""
    return _folder_of(str(file), "" if os.path.isabs(file) else os.getcwd())


@functools.lru_cache(maxsize=256)
def _folder_of(file: str, cwd: str) -> Path:
    return (Path(cwd) / file).resolve().parent


@dataclass
class StepSpec:
    id: str
    uses: str
    args: dict
    when: Any = None
    timeout: float | None = None
    retry: dict = field(default_factory=dict)
    cache: bool | None = None
    raw: SourceDict = field(default_factory=SourceDict)
    loop: str | None = None  # id of the enclosing loop, if any
    bases: dict[str, str] | None = None  # folders relative paths start from, when not where raw was read

    @property
    def loc(self) -> Location | None:
        return self.raw.loc

    def arg_loc(self, name: str) -> Location | None:
        args = self.raw.get("with")
        if isinstance(args, SourceDict) and name in args:
            return args.where(name)
        return self.raw.where("with") if "with" in self.raw else self.raw.loc

    @property
    def base_dir(self) -> Path:
        """Folder of the file that defines this step: relative paths in it start here."""
        if self.bases and "" in self.bases:
            return Path(self.bases[""])
        return folder_of(self.raw.loc.file) if self.raw.loc else Path.cwd()

    def arg_base(self, name: str) -> Path:
        """Folder a relative path in argument ``name`` starts from: that of the file that set
        the argument (an override in a child workflow may set it for a step of the base)."""
        if self.bases is not None:
            return Path(self.bases.get(name, self.bases.get("", str(Path.cwd()))))
        loc = self.arg_loc(name)
        return folder_of(loc.file) if loc and loc.file else self.base_dir

    def path_bases(self) -> dict[str, str]:
        """What :attr:`bases` must say for this step to resolve paths as here when it is
        rebuilt from a run's snapshot (``resume``)."""
        base = str(self.base_dir)
        out = {"": base}
        for name in self.args:
            arg = str(self.arg_base(name))
            if arg != base:
                out[name] = arg
        return out


@dataclass
class LoopSpec:
    id: str
    steps: list[StepSpec]
    max: Any
    until: Any
    on_max: str = "fail"
    when: Any = None
    raw: SourceDict = field(default_factory=SourceDict)

    @property
    def loc(self) -> Location | None:
        return self.raw.loc


Node = Union[StepSpec, LoopSpec]


@dataclass
class Workflow:
    file: Path
    name: str
    description: str
    inputs: dict[str, InputSpec]
    nodes: list[Node]
    outputs: dict
    data: SourceDict
    files: list[Path] = field(default_factory=list)  # this file and those it extends
    env: list[str] = field(default_factory=list)  # environment variables the workflow may read

    def all_steps(self) -> list[StepSpec]:
        out: list[StepSpec] = []
        for node in self.nodes:
            out.extend(node.steps if isinstance(node, LoopSpec) else [node])
        return out

    def node_of(self) -> dict[str, str]:
        """Every step id (inner steps of loops too) -> the id of its top-level node."""
        owner: dict[str, str] = {}
        for node in self.nodes:
            owner[node.id] = node.id
            if isinstance(node, LoopSpec):
                for inner in node.steps:
                    owner[inner.id] = node.id
        return owner

    def snapshot(self) -> dict:
        return plain(self.data)

    def path_bases(self) -> dict[str, dict[str, str]]:
        """Per step id, the folders its relative paths start from (saved with the snapshot)."""
        return {s.id: s.path_bases() for s in self.all_steps()}

    def apply_path_bases(self, bases: dict[str, dict[str, str]]) -> None:
        for s in self.all_steps():
            if isinstance(bases.get(s.id), dict):
                s.bases = dict(bases[s.id])


MAX_EXTENDS = 32  # files in one `extends` chain; real chains have two or three


def builtin_names() -> list[str]:
    """The names of pipflow's built-in workflows (``warehouse``, ``household``, ...)."""
    try:
        return sorted(p.stem for p in data_dir("workflows").glob("*.yaml"))
    except FileNotFoundError:
        return []


def builtin_workflow(ref: str) -> Path | None:
    """The built-in workflow a bare name means (``warehouse`` or ``warehouse.yaml``: no folder),
    or None."""
    if not isinstance(ref, str) or "/" in ref or "\\" in ref:
        return None
    name = ref if ref.endswith((".yaml", ".yml")) else f"{ref}.yaml"
    try:
        candidate = data_dir("workflows") / name
    except FileNotFoundError:
        return None
    return candidate if candidate.is_file() else None


def read_workflow_data(path: Path, diagnostics: list[Diagnostic], _seen: tuple = ()) -> tuple[Any, list[Path]]:
    """Load a workflow file and merge the chain of files it extends (base first).

    A base that cannot be used (missing, unreadable, empty, not a mapping, part of a cycle, or
    beyond :data:`MAX_EXTENDS` files) adds a diagnostic at the ``extends`` line; the child keeps
    its ``extends`` key, which tells the caller that the merge did not happen."""
    path = path.resolve()
    if path in _seen:
        chain = " -> ".join(str(p) for p in (*_seen, path))
        diagnostics.append(Diagnostic(Location(str(path)), f"'extends' forms a cycle: {chain}"))
        return SourceDict(), [path]
    data = load_yaml(path, "workflow file")
    if not isinstance(data, SourceDict) or "extends" not in data:
        return data, [path]
    base_ref = data["extends"]
    where = data.where("extends")
    if not isinstance(base_ref, str) or not base_ref.strip():
        diagnostics.append(Diagnostic(where, f"extends: expected the path of a workflow file, got {base_ref!r}"))
        return data, [path]
    if len(_seen) + 1 >= MAX_EXTENDS:
        diagnostics.append(Diagnostic(where, f"extends {base_ref!r}: a chain of more than {MAX_EXTENDS} "
                                             "workflow files (each extending the next) is not supported"))
        return data, [path]
    base_path = (path.parent / base_ref).resolve()
    if not base_path.exists():
        builtin = builtin_workflow(base_ref)
        if builtin is None:
            diagnostics.append(Diagnostic(where, f"extends {base_ref!r}: no such file ({base_path}) and no built-in "
                                                 f"workflow of that name (built-in: {', '.join(builtin_names())})"))
            return data, [path]
        base_path = builtin.resolve()  # `extends: warehouse`: the built-in workflow, with its own defaults
    try:
        base, files = read_workflow_data(base_path, diagnostics, (*_seen, path))
    except SourceFileError as err:
        diagnostics.append(Diagnostic(where, f"extends {base_ref!r}: the base workflow cannot be read"))
        diagnostics.extend(err.diagnostics)
        return data, [path]
    if not isinstance(base, SourceDict):
        what = "is empty" if base is None else f"is a {type(base).__name__.replace('Source', '').lower()}, not a mapping"
        diagnostics.append(Diagnostic(where, f"extends {base_ref!r}: the base workflow {what} "
                                             "(a workflow is a mapping of name, inputs, steps, outputs)"))
        return data, [path]
    if "extends" in base:  # the base's own base could not be used (reported above)
        return data, [path]
    return merge_workflows(base, data, diagnostics), [*files, path]


_LOOP_KEYS = ("max", "until", "on_max")


def merge_workflows(base: SourceDict, child: SourceDict, diagnostics: list[Diagnostic]) -> SourceDict:
    """Child overrides base: inputs and outputs key by key, steps by id.

    A child step with ``uses`` (or ``loop``) replaces the base step of that id or is added at
    the end (with ``inside: LOOP``, at the end of that inherited loop's steps); a child entry with only ``id`` and some of ``with``/``when``/``timeout``/
    ``retry``/``cache`` (or a loop's ``max``/``until``/``on_max``) changes just those parts;
    ``remove: [ids]`` drops inherited steps. The base is deep-copied first, so merging may
    change it in place; locations travel with the copies."""
    merged = copy.deepcopy(base)
    remove = child.get("remove")
    if remove is not None and not (isinstance(remove, list) and all(isinstance(r, str) for r in remove)):
        diagnostics.append(Diagnostic(child.where("remove"), f"remove: expected a list of step ids, got {remove!r}"))
    for key, value in child.items():
        if key in ("inputs", "outputs") and isinstance(value, dict) and isinstance(merged.get(key), dict):
            _merge_mapping(merged[key], value, deep=key == "inputs")
        elif key == "steps":
            if not isinstance(value, list):
                diagnostics.append(Diagnostic(child.where("steps"), f"steps: expected a list of steps, got {value!r}"))
            base_steps = merged.get("steps")
            merged["steps"] = _merge_steps(base_steps if isinstance(base_steps, SourceList) else SourceList(), value,
                                           child.get("remove") or [], diagnostics, child)
        elif key == "env" and isinstance(value, list) and isinstance(merged.get("env"), list):
            names = SourceList([*merged["env"], *(v for v in value if v not in merged["env"])])
            names.loc = getattr(value, "loc", None)
            merged["env"] = names
        elif key in ("extends", "remove"):
            continue
        else:
            merged[key] = value
        merged.locs[key] = child.where(key)
    return merged


def _merge_mapping(target: SourceDict, child: SourceDict, deep: bool) -> None:
    """Update ``target`` with ``child``; with ``deep``, mappings under a key merge too (an input
    override may change just its default)."""
    for key, value in child.items():
        if deep and isinstance(value, dict) and isinstance(target.get(key), dict):
            _merge_mapping(target[key], value, deep=False)
        else:
            target[key] = value
        target.locs[key] = child.where(key)


def _merge_steps(steps: SourceList, child_steps: Any, remove: list, diagnostics: list[Diagnostic],
                 child: SourceDict) -> SourceList:
    index = _index_steps(steps)
    removed = set()
    # ids of the wrong type (a list, a number) are left to the schema check, which names them
    for rid in (r for r in (remove if isinstance(remove, list) else []) if isinstance(r, str)):
        if rid in index:
            removed.add(rid)
        else:
            diagnostics.append(Diagnostic(child.where("remove"), f"remove: no inherited step {rid!r}"))
    for entry in child_steps if isinstance(child_steps, list) else []:
        sid = entry.get("id") if isinstance(entry, dict) else None
        sid = sid if isinstance(sid, str) else None
        found = index.get(sid) if sid is not None else None
        if isinstance(entry, dict) and "inside" in entry:
            _place_inside(steps, entry, found, diagnostics)
            continue
        if sid is None or not isinstance(entry, dict) or "uses" in entry or "loop" in entry:
            if found:
                container, i = found
                container[i] = entry
            else:
                steps.append(entry)
                steps.locs[len(steps) - 1] = getattr(entry, "loc", None)
            continue
        if not found or sid in removed:
            diagnostics.append(Diagnostic(entry.loc, f"step {sid!r} overrides nothing: no inherited step has that id"))
            continue
        container, i = found
        _override(container[i], entry)
    return _without(steps, removed)


def _place_inside(steps: SourceList, entry: SourceDict, found: tuple[list, int] | None,
                  diagnostics: list[Diagnostic]) -> None:
    """A child step with ``inside: LOOP``: added to the steps of the inherited loop ``LOOP`` (or,
    when the loop already has a step of that id, replacing it), so that a variant can add a step
    to a loop without copying the loop. ``inside`` itself is not kept."""
    loop_id = entry["inside"]
    where = entry.where("inside")
    step = SourceDict((k, v) for k, v in entry.items() if k != "inside")
    step.loc, step.locs = entry.loc, {k: v for k, v in entry.locs.items() if k != "inside"}
    if "uses" not in step:
        diagnostics.append(Diagnostic(where, f"step {entry.get('id')!r}: 'inside' adds a step to a loop; it needs "
                                             "'uses' (to change part of an inherited step, leave 'inside' out)"))
        return
    loop = next((s for s in steps if isinstance(s, dict) and s.get("id") == loop_id), None)
    inner = loop.get("loop", {}).get("steps") if isinstance(loop, dict) and isinstance(loop.get("loop"), dict) else None
    if not isinstance(inner, list):
        loops = [s["id"] for s in steps if isinstance(s, dict) and isinstance(s.get("loop"), dict)]
        diagnostics.append(Diagnostic(where, f"step {entry.get('id')!r}: inside {loop_id!r}: no inherited loop has "
                                             f"that id (loops: {', '.join(map(str, loops)) or 'none'})"))
        return
    if found is not None:
        container, i = found
        if container is not inner:
            diagnostics.append(Diagnostic(where, f"step {entry.get('id')!r}: inside {loop_id!r}, but the inherited "
                                                 f"step of that id is not in loop {loop_id!r}"))
            return
        container[i] = step
        return
    inner.append(step)
    if isinstance(inner, SourceList):
        inner.locs[len(inner) - 1] = step.loc


def _override(target: SourceDict, entry: SourceDict) -> None:
    """Apply an override entry (``id`` plus the parts to change) to an inherited step."""
    for key, value in entry.items():
        if key == "id":
            continue
        if key in _LOOP_KEYS and isinstance(target.get("loop"), dict):
            target["loop"][key] = value
            target["loop"].locs[key] = entry.where(key)
            continue
        if key == "with" and isinstance(target.get("with"), dict) and isinstance(value, dict):
            _merge_mapping(target["with"], value, deep=False)
        else:
            target[key] = value
        target.locs[key] = entry.where(key)


def _index_steps(steps: list) -> dict[str, tuple[list, int]]:
    """Step id -> (the list holding it, its position), inner steps of loops included."""
    index: dict[str, tuple[list, int]] = {}
    for i, s in enumerate(steps):
        if not isinstance(s, dict):
            continue
        if isinstance(s.get("id"), str):
            index[s["id"]] = (steps, i)
        inner = s.get("loop", {}).get("steps") if isinstance(s.get("loop"), dict) else None
        if isinstance(inner, list):
            for j, x in enumerate(inner):
                if isinstance(x, dict) and isinstance(x.get("id"), str):
                    index[x["id"]] = (inner, j)
    return index


def _without(steps: SourceList, removed: set) -> SourceList:
    """The steps minus the removed ids (inside loops too), locations kept."""
    if not removed:
        return steps
    out = SourceList()
    out.loc = steps.loc
    for s in steps:
        if isinstance(s, dict) and isinstance(s.get("id"), str) and s["id"] in removed:
            continue
        inner = s.get("loop", {}).get("steps") if isinstance(s, dict) and isinstance(s.get("loop"), dict) else None
        if isinstance(inner, SourceList):
            s["loop"]["steps"] = _without(inner, removed)
        out.locs[len(out)] = getattr(s, "loc", None)
        out.append(s)
    return out


def build_workflow(path: Path, data: SourceDict, files: list[Path]) -> Workflow:
    """Turn schema-valid data into specs (call after the schema check passed)."""
    inputs: dict[str, InputSpec] = {}
    for name, spec in (data.get("inputs") or {}).items():
        spec = spec or {}
        inputs[name] = InputSpec(
            name=name,
            type=spec.get("type", "any"),
            default=spec.get("default"),
            required="default" not in spec,
            doc=spec.get("doc", ""),
            choices=spec.get("choices"),
            loc=data["inputs"].where(name),
        )
    nodes: list[Node] = []
    for raw in data.get("steps") or []:
        if "loop" in raw:
            loop = raw["loop"]
            inner = [_step_spec(s, raw["id"]) for s in loop.get("steps") or []]
            nodes.append(LoopSpec(id=raw["id"], steps=inner, max=loop.get("max"), until=loop.get("until"),
                                  on_max=loop.get("on_max", "fail"), when=raw.get("when"), raw=raw))
        elif "uses" in raw:
            nodes.append(_step_spec(raw, None))
    return Workflow(file=path.resolve(), name=data.get("name", path.stem), description=data.get("description", ""),
                    inputs=inputs, nodes=nodes, outputs=dict(data.get("outputs") or {}), data=data, files=files,
                    env=list(data.get("env") or []))


def _step_spec(raw: SourceDict, loop: str | None) -> StepSpec:
    return StepSpec(id=raw["id"], uses=raw["uses"], args=dict(raw.get("with") or {}), when=raw.get("when"),
                    timeout=raw.get("timeout"), retry=dict(raw.get("retry") or {}), cache=raw.get("cache"),
                    raw=raw, loop=loop)

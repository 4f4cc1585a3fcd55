"""The workflow model: a workflow file (after ``extends`` is merged) as typed specs.

Loading never raises on content problems: it records them as diagnostics so that
``pipflow validate`` can report every problem at once.
"""
from __future__ import annotations

import copy
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Union

from pipflow.errors import Diagnostic, Location

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
        return Path(self.raw.loc.file).resolve().parent if self.raw.loc else Path.cwd()


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


def read_workflow_data(path: Path, diagnostics: list[Diagnostic], _seen: tuple = ()) -> tuple[Any, list[Path]]:
    """Load a workflow file and merge the chain of files it extends (base first)."""
    path = path.resolve()
    if path in _seen:
        chain = " -> ".join(str(p) for p in (*_seen, path))
        diagnostics.append(Diagnostic(Location(str(path)), f"'extends' forms a cycle: {chain}"))
        return SourceDict(), [path]
    data = load_yaml(path)
    if not isinstance(data, SourceDict) or "extends" not in data:
        return data, [path]
    base_ref = data["extends"]
    base_path = (path.parent / str(base_ref)).resolve()
    if not base_path.exists():
        diagnostics.append(Diagnostic(data.where("extends"), f"extends {base_ref!r}: no such file ({base_path})"))
        return data, [path]
    base, files = read_workflow_data(base_path, diagnostics, (*_seen, path))
    if not isinstance(base, SourceDict):
        return data, [path]
    return merge_workflows(base, data, diagnostics), [*files, path]


_OVERRIDABLE = ("with", "when", "timeout", "retry", "cache")
_LOOP_KEYS = ("max", "until", "on_max")


def merge_workflows(base: SourceDict, child: SourceDict, diagnostics: list[Diagnostic]) -> SourceDict:
    """Child overrides base: inputs and outputs key by key, steps by id.

    A child step with ``uses`` (or ``loop``) replaces the base step of that id or is added at
    the end; a child entry with only ``id`` and some of ``with``/``when``/``timeout``/
    ``retry``/``cache`` (or a loop's ``max``/``until``/``on_max``) changes just those parts."""
    merged = copy.copy(base)
    merged.locs = dict(base.locs)
    for key, value in child.items():
        if key in ("inputs", "outputs") and isinstance(value, dict) and isinstance(base.get(key), dict):
            merged[key] = _merge_mapping(base[key], value, deep=key == "inputs")
        elif key == "steps":
            merged["steps"] = _merge_steps(base.get("steps") or SourceList(), value, child.get("remove") or [], diagnostics, child)
        elif key in ("extends", "remove"):
            continue
        else:
            merged[key] = value
        merged.locs[key] = child.where(key)
    return merged


def _merge_mapping(base: SourceDict, child: SourceDict, deep: bool) -> SourceDict:
    out = copy.copy(base)
    out.locs = dict(base.locs)
    for k, v in child.items():
        if deep and isinstance(v, dict) and isinstance(base.get(k), dict):
            inner = copy.copy(base[k])
            inner.locs = dict(base[k].locs)
            inner.update(v)
            inner.locs.update(v.locs)
            out[k] = inner
        else:
            out[k] = v
        out.locs[k] = child.where(k)
    return out


def _merge_steps(base_steps: list, child_steps: Any, remove: list, diagnostics: list[Diagnostic], child: SourceDict) -> SourceList:
    steps = SourceList([copy.copy(s) for s in base_steps])
    steps.loc = getattr(base_steps, "loc", None)
    index = _index_steps(steps)
    for rid in remove:
        if rid not in index:
            diagnostics.append(Diagnostic(child.where("remove"), f"remove: no inherited step {rid!r}"))
            continue
        container, i = index[rid]
        container[i] = None
    if not isinstance(child_steps, list):
        return steps
    for entry in child_steps:
        if not isinstance(entry, dict) or "id" not in entry:
            steps.append(entry)
            continue
        sid = entry["id"]
        found = index.get(sid)
        if "uses" in entry or "loop" in entry:
            if found:
                found[0][found[1]] = entry
            else:
                steps.append(entry)
            continue
        if not found or found[0][found[1]] is None:
            diagnostics.append(Diagnostic(entry.loc, f"step {sid!r} overrides nothing: no inherited step has that id"))
            continue
        container, i = found
        target = copy.copy(container[i])
        target.locs = dict(container[i].locs)
        for key, value in entry.items():
            if key == "id":
                continue
            if key in _LOOP_KEYS and "loop" in target:
                loop = copy.copy(target["loop"])
                loop.locs = dict(target["loop"].locs)
                loop[key] = value
                loop.locs[key] = entry.where(key)
                target["loop"] = loop
            elif key == "with" and isinstance(target.get("with"), dict) and isinstance(value, dict):
                target["with"] = _merge_mapping(target["with"], value, deep=False)
            else:
                target[key] = value
            target.locs[key] = entry.where(key)
        container[i] = target
    out = SourceList()
    out.loc = steps.loc
    for s in steps:
        if s is None:
            continue
        if isinstance(s, dict) and isinstance(s.get("loop"), dict):
            inner = s["loop"].get("steps")
            if isinstance(inner, list) and any(x is None for x in inner):
                s = copy.copy(s)
                loop = copy.copy(s["loop"])
                loop.locs = dict(s["loop"].locs)
                kept = SourceList([x for x in inner if x is not None])
                kept.loc = inner.loc
                loop["steps"] = kept
                s["loop"] = loop
        out.locs[len(out)] = s.loc if isinstance(s, SourceDict) else None
        out.append(s)
    return out


def _index_steps(steps: list) -> dict[str, tuple[list, int]]:
    index: dict[str, tuple[list, int]] = {}
    for i, s in enumerate(steps):
        if not isinstance(s, dict):
            continue
        if "id" in s:
            index[s["id"]] = (steps, i)
        loop = s.get("loop")
        if isinstance(loop, dict) and isinstance(loop.get("steps"), list):
            loop = copy.copy(loop)
            loop.locs = dict(s["loop"].locs)
            inner = SourceList([copy.copy(x) for x in loop["steps"]])
            inner.loc = s["loop"]["steps"].loc
            inner.locs = dict(s["loop"]["steps"].locs)
            loop["steps"] = inner
            s = copy.copy(s)
            s.locs = dict(steps[i].locs)
            s["loop"] = loop
            steps[i] = s
            for j, x in enumerate(inner):
                if isinstance(x, dict) and "id" in x:
                    index[x["id"]] = (inner, j)
    return index


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
                    inputs=inputs, nodes=nodes, outputs=dict(data.get("outputs") or {}), data=data, files=files)


def _step_spec(raw: SourceDict, loop: str | None) -> StepSpec:
    return StepSpec(id=raw["id"], uses=raw["uses"], args=dict(raw.get("with") or {}), when=raw.get("when"),
                    timeout=raw.get("timeout"), retry=dict(raw.get("retry") or {}), cache=raw.get("cache"),
                    raw=raw, loop=loop)

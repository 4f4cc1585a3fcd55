"""Reading the YAML files a domain's checker validates (worlds, task files): bounded reading,
parsing with line/column locations, and the small shape checks they share.

A neutral module below every domain: the warehouse and household checkers both use these, and
neither borrows them from the other. Every failure is a :class:`~pipflow.errors.WorldError`
whose diagnostics say file, line and column."""
from __future__ import annotations

import json
from functools import lru_cache
from pathlib import Path
from typing import Any, Callable

import yaml

from pipflow.errors import Diagnostic, Location, SourceFileError, WorldError
from pipflow.resources import data_file
from pipflow.suggest import did_you_mean
from pipflow.yamlsource import load_with_locations, read_source, yaml_error_diagnostic

#: ``locate(*path)`` -> the Location of a key or item of the parsed file
Locate = Callable[..., Location]


def read_world_file(path: str | Path) -> tuple[Path, str]:
    """The resolved path and text of a world or task file; a missing, special, oversized or
    non-UTF-8 file is a located WorldError."""
    p = Path(path).expanduser().resolve()
    try:  # the shared reader: regular files only, size-capped, UTF-8 checked with a location
        return p, read_source(p, "file")
    except SourceFileError as exc:
        raise WorldError(exc.diagnostics) from None


def parse_mapping(text: str, file: str, kind: str) -> tuple[Any, Locate]:
    """The YAML mapping in ``text`` and its locator; bad YAML or a non-mapping is a WorldError."""
    try:
        data, locate = load_with_locations(text, file)
    except yaml.YAMLError as exc:
        raise WorldError([yaml_error_diagnostic(exc, file)], f"invalid {kind} file {file}") from None
    if not isinstance(data, dict):
        raise WorldError([Diagnostic(Location(file, 1, 1), f"a {kind} file must be a YAML mapping")],
                         f"invalid {kind} file {file}")
    return data, locate


def is_point(p: Any) -> bool:
    """An ``[x, y]`` pair of numbers."""
    return isinstance(p, list) and len(p) == 2 and all(isinstance(v, (int, float)) for v in p)


@lru_cache(maxsize=None)
def load_schema(name: str) -> dict:
    """A JSON Schema of ``schemas/`` by file name (cached: schemas do not change in a run)."""
    return json.loads(data_file(f"schemas/{name}").read_text())


# ---------------------------------------------------------------------------------------------
# schema pass
# ---------------------------------------------------------------------------------------------
def schema_diagnostics(data: Any, schema: dict, locate: Locate) -> list[Diagnostic]:
    """Every JSON-Schema violation of ``data``, located; unknown keys point at the key itself."""
    import jsonschema

    validator = jsonschema.Draft202012Validator(schema)
    out: list[Diagnostic] = []
    for err in sorted(validator.iter_errors(data), key=lambda e: list(map(str, e.absolute_path))):
        out += _error_diagnostics(err, locate)
    return out


def _error_diagnostics(err: Any, locate: Locate) -> list[Diagnostic]:
    """One schema error as diagnostics. For a ``oneOf``/``anyOf`` (a value of several allowed
    forms, such as a goal count or bound) the errors of the forms whose type does fit are the ones
    a user needs ("-1 is less than the minimum of 0", "unknown key 'at_leest'"), not "is not valid
    under any of the given schemas"."""
    path = tuple(err.absolute_path)
    where = "/".join(map(str, path)) or "top level"
    if err.validator in ("oneOf", "anyOf") and err.context:
        fitting = [c for c in err.context if c.validator != "type"]
        if fitting:
            return [d for c in fitting for d in _error_diagnostics(c, locate)]
        what = err.schema.get("description")
        return [Diagnostic(locate(path), f"{where}: {err.instance!r} is not valid"
                           + (f": {what}" if what else f" ({'; '.join(c.message for c in err.context)})"))]
    if err.validator == "additionalProperties" and isinstance(err.instance, dict):
        known = list((err.schema.get("properties") or {}).keys())
        return [Diagnostic(locate(path + (extra,), key=True),
                           f"unknown key {extra!r} in {where}{did_you_mean(extra, known)}"
                           + (f"; allowed: {', '.join(known)}" if known else ""))
                for extra in err.instance if extra not in known]
    if err.validator == "propertyNames":
        bad = err.instance
        return [Diagnostic(locate(path + (bad,), key=True),
                           f"invalid name {bad!r}: names start with a letter and use letters, "
                           "digits, '_' or '-' (they become PDDL object names)")]
    return [Diagnostic(locate(path), f"{where}: {err.message}")]


def duplicate_diagnostics(locate: Any) -> list[Diagnostic]:
    return [Diagnostic(loc, f"duplicate key {path[-1]!r} (YAML keeps only the last one)")
            for path, loc in getattr(locate, "duplicates", [])]


def checked_yaml(text: str, file: str, kind: str, schema: str,
                 semantic: Callable[[dict, Locate], list[Diagnostic]],
                 prepare: Callable[[dict], None] | None = None) -> dict:
    """Parse a YAML file's ``text`` and check it against a schema of ``schemas/`` and the
    ``semantic`` rules; raise :class:`WorldError` with every problem at once, in file order.
    World files of every domain go through here (``prepare`` may fix the parsed data first)."""
    data, locate = parse_mapping(text, file, kind)
    if prepare is not None:
        prepare(data)
    diags = duplicate_diagnostics(locate)
    diags += schema_diagnostics(data, load_schema(schema), locate)
    diags += semantic(data, locate)
    diags.sort(key=lambda d: (d.location.line, d.location.column) if d.location else (0, 0))
    if diags:
        raise WorldError(diags, f"invalid {kind} file {file} ({len(diags)} problem(s))")
    return data

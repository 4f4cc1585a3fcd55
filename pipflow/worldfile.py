"""Reading the YAML files a domain's checker validates (worlds, task files): bounded reading,
parsing with line/column locations, and the small shape checks they share.

A neutral module below every domain: the warehouse and household checkers both use these, and
neither borrows them from the other. Every failure is a :class:`~pipflow.errors.WorldError`
whose diagnostics say file, line and column."""
from __future__ import annotations

import json
import math
import os
from functools import lru_cache
from pathlib import Path
from typing import Any, Callable, Mapping

import yaml

from pipflow.errors import Diagnostic, InputError, Location, SourceFileError, WorldError
from pipflow.resources import data_file
from pipflow.suggest import did_you_mean
from pipflow.yamlsource import event_count, load_with_locations, read_source, section_sizes, yaml_error_diagnostic

#: ``locate(*path)`` -> the Location of a key or item of the parsed file
Locate = Callable[..., Location]

#: entries any top-level section of a world or task file may hold (robots, shelves, places,
#: tasks...) unless its domain says otherwise; a file over it is refused before it is loaded
SECTION_LIMIT = 20_000
#: the environment variable that sets the limits, by section: ``robots=50000,shelves=30000``
LIMITS_VARIABLE = "PIPFLOW_WORLD_LIMITS"
#: the largest number a world or task file may hold (metres, units, skill levels, masses): far
#: beyond any real floor or stock, and small enough for every solver pipflow drives (SCIP treats
#: 1e20 as infinity; ENHSP and UP compute in doubles)
LARGEST_NUMBER = 10**9


def read_world_file(path: str | Path) -> tuple[Path, str]:
    """The resolved path and text of a world or task file; a missing, special, oversized or
    non-UTF-8 file is a located WorldError."""
    p = Path(path).expanduser().resolve()
    try:  # the shared reader: regular files only, size-capped, UTF-8 checked with a location
        return p, read_source(p, "file")
    except SourceFileError as exc:
        raise WorldError(exc.diagnostics) from None


def size_limits(defaults: Mapping[str, int] | None = None) -> dict[str, int]:
    """The size limit of each section (``"*"``: any other): :data:`SECTION_LIMIT`, a domain's
    own ``defaults`` where it gives them, and what :data:`LIMITS_VARIABLE` sets over both
    (``*=N`` sets every section it does not name). A malformed variable is an InputError naming it."""
    limits = {"*": SECTION_LIMIT, **(defaults or {})}
    raw = os.environ.get(LIMITS_VARIABLE, "").strip()
    given: dict[str, int] = {}
    for item in filter(None, (part.strip() for part in raw.replace(";", ",").split(","))):
        name, sep, value = item.partition("=")
        if not sep or not name.strip() or not value.strip().isdigit() or int(value) < 1:
            raise InputError(f"{LIMITS_VARIABLE}={raw!r}: {item!r} is not SECTION=N with N a whole number of "
                             f"1 or more (for example {LIMITS_VARIABLE}=robots=50000,units=500000)")
        given[name.strip()] = int(value)
    if "*" in given:
        limits = dict.fromkeys(limits, given["*"])
    return {**limits, **given}


def size_diagnostics(text: str, file: str, kind: str, limits: Mapping[str, int] | None = None) -> list[Diagnostic]:
    """A located refusal for each top-level section of ``text`` with more entries than its limit
    (:func:`size_limits`): "this world file has 100,000 robots; the limit is 20,000", said before
    the file is loaded, in the time libyaml takes to read it (loading it could take minutes).
    Cheap for files far under every limit: libyaml's own count of the file's events bounds every
    section, and only a file whose count could break a limit has its sections counted."""
    limits = size_limits(limits)
    lowest = min(limits.values())
    if len(text) < 2 * lowest or event_count(text) <= lowest:  # no section can hold more entries than this
        return []
    out = []
    for section, (entries, line, column) in section_sizes(text).items():
        limit = limits.get(section, limits["*"])
        if entries > limit:
            out.append(Diagnostic(Location(file, line, column),
                                  f"this {kind} file has {entries:,} {section}; the limit is {limit:,} (settable: "
                                  f"{LIMITS_VARIABLE}={section}=N in the environment)"))
    return out


def number_diagnostics(data: Any, locate: Locate) -> list[Diagnostic]:
    """Every number of a parsed file that is not finite (``.nan``, ``.inf``, ``1e400``) or is
    larger than :data:`LARGEST_NUMBER`, located. Checked before any other rule, for every domain:
    a NaN compares false with everything, so each later check would pass it silently and it
    would fail far away ("cannot convert float NaN to integer"), and a count of 10**26 would be
    allocated for by whatever meets it first."""
    out: list[Diagnostic] = []
    stack: list[tuple[tuple, Any]] = [((), data)]
    seen: set[int] = set()
    while stack:
        path, value = stack.pop()
        if isinstance(value, dict | list):
            if id(value) in seen:  # an alias: checked where it is defined
                continue
            seen.add(id(value))
            items = value.items() if isinstance(value, dict) else enumerate(value)
            stack.extend((path + (k,), v) for k, v in items)
        elif isinstance(value, float) and not math.isfinite(value):
            out.append(Diagnostic(locate(path), f"{'/'.join(map(str, path)) or 'value'}: {value} is not a finite "
                                                "number (write the number itself)"))
        elif isinstance(value, int | float) and not isinstance(value, bool) and abs(value) > LARGEST_NUMBER:
            out.append(Diagnostic(locate(path), f"{'/'.join(map(str, path))}: {value:g} is larger than any distance, "
                                                f"count or skill pipflow works with (at most {LARGEST_NUMBER:,})"))
    return sorted(out, key=lambda d: (d.location.line, d.location.column) if d.location else (0, 0))


def parse_mapping(text: str, file: str, kind: str, limits: Mapping[str, int] | None = None) -> tuple[Any, Locate]:
    """The YAML mapping in ``text`` and its locator; bad YAML, a non-mapping, a section over its
    size limit (:func:`size_diagnostics`; ``limits``: the domain's own, by section) or a number
    that is not finite or too large (:func:`number_diagnostics`) is a WorldError."""
    sizes = size_diagnostics(text, file, kind, limits)
    if sizes:
        raise WorldError(sizes, f"{kind} file {file} is over a size limit")
    try:
        data, locate = load_with_locations(text, file)
    except yaml.YAMLError as exc:
        raise WorldError([yaml_error_diagnostic(exc, file)], f"invalid {kind} file {file}") from None
    if not isinstance(data, dict):
        raise WorldError([Diagnostic(Location(file, 1, 1), f"a {kind} file must be a YAML mapping")],
                         f"invalid {kind} file {file}")
    numbers = number_diagnostics(data, locate)
    if numbers:
        raise WorldError(numbers, f"invalid {kind} file {file} ({len(numbers)} problem(s))")
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
                 prepare: Callable[[dict], None] | None = None,
                 limits: Mapping[str, int] | None = None) -> dict:
    """Parse a YAML file's ``text`` and check it against a schema of ``schemas/`` and the
    ``semantic`` rules; raise :class:`WorldError` with every problem at once, in file order.
    World files of every domain go through here (``prepare`` may fix the parsed data first;
    ``limits``: the domain's own size limits by section, :func:`size_limits`)."""
    data, locate = parse_mapping(text, file, kind, limits)
    if prepare is not None:
        prepare(data)
    diags = duplicate_diagnostics(locate)
    diags += schema_diagnostics(data, load_schema(schema), locate)
    diags += semantic(data, locate)
    diags.sort(key=lambda d: (d.location.line, d.location.column) if d.location else (0, 0))
    if diags:
        raise WorldError(diags, f"invalid {kind} file {file} ({len(diags)} problem(s))")
    return data

"""Reading the YAML files a domain's checker validates (worlds, task files): bounded reading,
parsing with line/column locations, and the small shape checks they share.

A neutral module below every domain: the warehouse and household checkers both use these, and
neither borrows them from the other. Every failure is a :class:`~pipflow.errors.WorldError`
whose diagnostics say file, line and column."""
from __future__ import annotations

from pathlib import Path
from typing import Any, Callable

import yaml

from pipflow.errors import Diagnostic, Location, SourceFileError, WorldError
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

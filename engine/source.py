"""YAML loading that remembers where every value came from.

Validation must name file, line and column for every problem, also after a workflow has been
merged with the one it extends. So mappings and lists are loaded as :class:`SourceDict` and
:class:`SourceList`, plain ``dict``/``list`` subclasses that carry the location of the node
itself and of each of their keys or items; merging copies those along with the values.

Reading and composing go through :mod:`pipflow.yamlsource` (size, file kind, UTF-8, nesting
depth and alias-expansion limits), the one safe way pipflow reads a user's YAML.
"""
from __future__ import annotations

from pathlib import Path
from typing import Any

import yaml

from pipflow.errors import Diagnostic, Location, SourceFileError
from pipflow.yamlsource import BoundedComposer, CheckedValues, located_reader_error, read_source, yaml_problem


class SourceDict(dict):
    """A dict that knows its own location and the location of each key's value."""

    loc: Location | None = None
    locs: dict

    def __init__(self, *args: Any, **kwargs: Any):
        super().__init__(*args, **kwargs)
        self.locs = {}

    def where(self, key: Any = None) -> Location | None:
        return self.locs.get(key, self.loc) if key is not None else self.loc


class SourceList(list):
    """A list that knows its own location and the location of each item."""

    loc: Location | None = None
    locs: dict

    def __init__(self, *args: Any):
        super().__init__(*args)
        self.locs = {}

    def where(self, index: Any = None) -> Location | None:
        return self.locs.get(index, self.loc) if index is not None else self.loc


def _location(node: yaml.Node, file: str) -> Location:
    return Location(file, node.start_mark.line + 1, node.start_mark.column + 1)


class _Constructor(yaml.constructor.SafeConstructor):
    """SafeConstructor that builds Source containers (still no arbitrary objects)."""

    file = "<string>"

    def construct_mapping(self, node, deep=False):  # type: ignore[override]
        if not isinstance(node, yaml.MappingNode):
            raise yaml.constructor.ConstructorError(
                None, None, f"expected a mapping, found {node.id}", node.start_mark)
        written = sum(1 for k, _ in node.value if k.tag != "tag:yaml.org,2002:merge")
        self.flatten_mapping(node)  # pairs from `<<: *x` come first; keys written after them override
        merged = len(node.value) - written
        result = SourceDict()
        result.loc = _location(node, self.file)
        explicit: set = set()
        for i, (key_node, value_node) in enumerate(node.value):
            key = self.construct_object(key_node, deep=True)
            if i >= merged:
                if key in explicit:
                    raise _DuplicateKey(key, _location(key_node, self.file))
                explicit.add(key)
            result[key] = self.construct_object(value_node, deep=True)
            result.locs[key] = _location(value_node, self.file)
        return result

    def construct_sequence(self, node, deep=False):  # type: ignore[override]
        result = SourceList()
        result.loc = _location(node, self.file)
        for i, child in enumerate(node.value):
            result.append(self.construct_object(child, deep=True))
            result.locs[i] = _location(child, self.file)
        return result


_Constructor.add_constructor("tag:yaml.org,2002:map", _Constructor.construct_mapping)
_Constructor.add_constructor("tag:yaml.org,2002:seq", _Constructor.construct_sequence)


class _DuplicateKey(Exception):
    def __init__(self, key: Any, location: Location):
        self.key, self.location = key, location


class _Loader(CheckedValues, BoundedComposer, yaml.reader.Reader, yaml.scanner.Scanner, yaml.parser.Parser,
              _Constructor, yaml.resolver.Resolver):
    def __init__(self, stream: str, file: str):
        yaml.reader.Reader.__init__(self, stream)
        yaml.scanner.Scanner.__init__(self)
        yaml.parser.Parser.__init__(self)
        BoundedComposer.__init__(self)
        _Constructor.__init__(self)
        yaml.resolver.Resolver.__init__(self)
        self.file = file


if getattr(yaml, "__with_libyaml__", False):
    class _CLoader(CheckedValues, BoundedComposer, yaml._yaml.CParser, _Constructor, yaml.resolver.Resolver):  # type: ignore[name-defined]
        """The same loader on libyaml's parser (same marks, several times faster)."""

        def __init__(self, stream: str, file: str):
            yaml._yaml.CParser.__init__(self, stream)
            BoundedComposer.__init__(self)
            _Constructor.__init__(self)
            yaml.resolver.Resolver.__init__(self)
            self.file = file
else:  # pragma: no cover - PyYAML built without libyaml
    _CLoader = _Loader


def parse_yaml(text: str, file: str = "<string>") -> Any:
    """Parse YAML text into Source containers; syntax errors become a located UserError."""
    loader = _CLoader(text, file)
    try:
        try:
            return loader.get_single_data()
        except yaml.reader.ReaderError as err:
            raise located_reader_error(err, text) from None
    except _DuplicateKey as dup:
        raise SourceError([Diagnostic(dup.location, f"duplicate key {dup.key!r}")]) from None
    except yaml.MarkedYAMLError as err:
        mark = err.problem_mark or err.context_mark
        loc = Location(file, mark.line + 1, mark.column + 1) if mark else Location(file)
        what = "YAML" if isinstance(err, (yaml.composer.ComposerError, yaml.constructor.ConstructorError)) else "YAML syntax"
        raise SourceError([Diagnostic(loc, f"{what}: {yaml_problem(err)}")]) from None
    except yaml.YAMLError as err:  # e.g. a control character the reader refuses
        raise SourceError([Diagnostic(Location(file), f"YAML: {err}")]) from None
    finally:
        loader.dispose()


def load_yaml(path: str | Path, kind: str = "file") -> Any:
    """Read and parse a YAML file with locations; a missing, unreadable, oversized or binary
    file is a located :class:`SourceError`."""
    return parse_yaml(read_source(path, kind), str(path))


class SourceError(SourceFileError):
    """A YAML file cannot be read or parsed; ``diagnostics`` says where."""

    def __init__(self, diagnostics: list[Diagnostic]):
        super().__init__(diagnostics)


def plain(value: Any) -> Any:
    """Strip Source containers down to plain dicts and lists (for JSON and snapshots)."""
    if isinstance(value, dict):
        return {k: plain(v) for k, v in value.items()}
    if isinstance(value, list):
        return [plain(v) for v in value]
    return value

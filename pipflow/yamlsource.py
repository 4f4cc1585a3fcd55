"""YAML with source positions, so that validation errors can point at a line and column.

``yaml.safe_load`` forgets where values came from; ``yaml.compose`` keeps a node tree with marks.
:func:`load_with_locations` returns both the plain data and a ``locate`` function that maps a
path into the data (``("stock", "shelf9")``, ``("tasks", 3, "goal")``) to the
:class:`~pipflow.errors.Location` of that value in the text. A path that goes deeper than the
document (a missing key) resolves to the deepest node that exists, which is where a user would
add the missing piece. World, task and workflow files all use this.
"""
from __future__ import annotations

from typing import Any, Callable, Hashable, Sequence

import yaml

from pipflow.errors import Diagnostic, Location

Path = Sequence[Hashable]


class Locator:
    """Callable ``locate(path, key=False) -> Location``; ``key=True`` points at a mapping key
    instead of its value (better for "unknown name" messages). ``duplicates`` lists keys that
    appear twice in one mapping (YAML silently keeps the last; a user almost never means that)."""

    def __init__(self, root: yaml.Node | None, file: str):
        self.root = root
        self.file = file
        self.duplicates: list[tuple[tuple, Location]] = []
        if root is not None:
            self._find_duplicates(root, ())

    def __call__(self, path: Path = (), key: bool = False) -> Location:
        node, key_node = self.root, None
        for part in path:
            child = self._child(node, part)
            if child is None:
                break
            key_node, node = child
        target = key_node if (key and key_node is not None) else node
        return self._mark(target)

    def _mark(self, node: yaml.Node | None) -> Location:
        if node is None:
            return Location(self.file, 1, 1)
        mark = node.start_mark
        return Location(self.file, mark.line + 1, mark.column + 1)

    @staticmethod
    def _child(node: yaml.Node | None, part: Hashable) -> tuple[yaml.Node | None, yaml.Node] | None:
        if isinstance(node, yaml.MappingNode):
            for k, v in node.value:
                if isinstance(k, yaml.ScalarNode) and (k.value == str(part)):
                    return k, v
            return None
        if isinstance(node, yaml.SequenceNode) and isinstance(part, int):
            if 0 <= part < len(node.value):
                return None, node.value[part]
        return None

    def _find_duplicates(self, node: yaml.Node, path: tuple) -> None:
        if isinstance(node, yaml.MappingNode):
            seen: set[str] = set()
            for k, v in node.value:
                name = k.value if isinstance(k, yaml.ScalarNode) else None
                if name is not None and name in seen:
                    self.duplicates.append((path + (name,), self._mark(k)))
                seen.add(name)
                self._find_duplicates(v, path + (name,))
        elif isinstance(node, yaml.SequenceNode):
            for i, v in enumerate(node.value):
                self._find_duplicates(v, path + (i,))


def load_with_locations(text: str, file: str) -> tuple[Any, Callable[..., Location]]:
    """Parse YAML ``text`` (named ``file`` in messages); return ``(data, locate)``.

    Raises ``yaml.YAMLError`` on a syntax error; :func:`yaml_error_diagnostic` turns that into a
    located :class:`Diagnostic`."""
    root = yaml.compose(text, Loader=yaml.SafeLoader)
    data = yaml.safe_load(text) if root is not None else None
    return data, Locator(root, file)


def yaml_error_diagnostic(exc: yaml.YAMLError, file: str) -> Diagnostic:
    """A YAML syntax error as a diagnostic at the position PyYAML reports."""
    mark = getattr(exc, "problem_mark", None) or getattr(exc, "context_mark", None)
    problem = getattr(exc, "problem", None) or str(exc)
    context = getattr(exc, "context", None)
    message = f"YAML syntax error: {problem}" + (f" ({context})" if context else "")
    loc = Location(file, mark.line + 1, mark.column + 1) if mark else Location(file)
    return Diagnostic(loc, message)

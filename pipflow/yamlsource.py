"""YAML with source positions, so that validation errors can point at a line and column.

``yaml.safe_load`` forgets where values came from; ``yaml.compose`` keeps a node tree with marks.
:func:`load_with_locations` returns both the plain data and a ``locate`` function that maps a
path into the data (``("stock", "shelf9")``, ``("tasks", 3, "goal")``) to the
:class:`~pipflow.errors.Location` of that value in the text. A path that goes deeper than the
document (a missing key) resolves to the deepest node that exists, which is where a user would
add the missing piece. World, task and workflow files all use this.

It is also the one safe way pipflow reads YAML from a user (workflow, world, task and inputs
files, ``-i`` values): :func:`read_source` refuses what is not a regular file, is larger than any
real file (``/dev/zero``, a FIFO, a 20 GB log) or is not UTF-8 text, naming the file and line;
:class:`BoundedComposer` refuses nesting deeper than :data:`MAX_DEPTH`, more than
:data:`MAX_NODES` values once aliases are expanded (a 453-byte "billion laughs" document) and
aliases that contain themselves. PyYAML shares the objects an alias names, so such a document
loads quickly; it is every later walk over the data (validation, JSON records) that would expand
it, so the bound is on the expanded size, checked while composing, before anything walks it. The
message says which limit was met: a document whose values are mostly repeated by aliases is a
likely alias bomb; one that is simply that large is told its size and the limit, not an attack.
"""
from __future__ import annotations

import os
import stat
from typing import Any, Callable, Hashable, Sequence

import yaml

from pipflow.errors import Diagnostic, Location, SourceFileError

Path = Sequence[Hashable]

MAX_SOURCE_BYTES = 16 * 1024 * 1024  # a YAML file a person writes or a tool exports is far smaller
MAX_DEPTH = 100  # nesting levels of mappings and lists
MAX_NODES = 1_000_000  # values after alias expansion


def read_source(path: str | os.PathLike, kind: str = "file", limit: int = MAX_SOURCE_BYTES) -> str:
    """The text of a user's file, or a :class:`SourceFileError` that names the file and cause:
    missing, unreadable, not a regular file (a folder, a device such as ``/dev/zero``, a pipe),
    larger than ``limit`` bytes, or not UTF-8 (with the line and column of the first bad byte).
    Reads at most ``limit + 1`` bytes, so no file can make pipflow read without end."""
    file = str(path)
    try:
        fd = os.open(file, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0))  # a FIFO must not block the open
    except FileNotFoundError:
        raise _read_error(file, f"no such {kind}") from None
    except OSError as err:
        raise _read_error(file, f"cannot read the {kind} ({err.strerror or err})") from None
    try:
        info = os.fstat(fd)
        if not stat.S_ISREG(info.st_mode):
            what = "a folder" if stat.S_ISDIR(info.st_mode) else "a device, pipe or socket"
            raise _read_error(file, f"the {kind} is not a regular file but {what}; pipflow reads only ordinary files")
        if info.st_size > limit:
            raise _read_error(file, f"the {kind} has {info.st_size} bytes, more than the {limit} pipflow reads")
        with os.fdopen(fd, "rb", closefd=True) as fh:
            fd = -1
            data = fh.read(limit + 1)  # files under /proc report size 0: the cap still holds
    except OSError as err:
        raise _read_error(file, f"cannot read the {kind} ({err.strerror or err})") from None
    finally:
        if fd >= 0:
            os.close(fd)
    if len(data) > limit:
        raise _read_error(file, f"the {kind} has more than the {limit} bytes pipflow reads")
    return decode_text(data, file, kind)


def decode_text(data: bytes, file: str, kind: str = "file") -> str:
    """UTF-8 text (a leading BOM dropped); otherwise a :class:`SourceFileError` at the first bad byte."""
    try:
        return data.decode("utf-8-sig")
    except UnicodeDecodeError as err:
        line = data.count(b"\n", 0, err.start) + 1
        column = err.start - (data.rfind(b"\n", 0, err.start) + 1) + 1
        loc = Location(file, line, column)
        raise SourceFileError([Diagnostic(loc, f"the {kind} is not UTF-8 text (byte 0x{data[err.start]:02x}); "
                                               "is it a binary file?")]) from None


def _read_error(file: str, message: str) -> SourceFileError:
    return SourceFileError([Diagnostic(Location(file), message)])


class BoundedComposer(yaml.composer.Composer):
    """PyYAML's composer with limits: nesting depth, values after alias expansion, no alias
    inside its own anchor. Mixed in before the parser (also libyaml's ``CParser``, whose events
    it consumes), so every node goes through :meth:`compose_node`."""

    def __init__(self) -> None:
        super().__init__()
        self._depth = 0
        self._expanded = 0
        self._aliased = 0  # of those, values that aliases repeat
        self._sizes: dict[int, int] = {}  # id(node) -> values under it, aliases expanded

    def compose_node(self, parent, index):  # type: ignore[override]
        if self.check_event(yaml.events.AliasEvent):
            event = self.peek_event()
            target = self.anchors.get(event.anchor)
            if target is not None:
                size = self._sizes.get(id(target))
                if size is None:
                    raise yaml.composer.ComposerError(
                        None, None, f"alias *{event.anchor} is used inside its own anchor (a recursive document)",
                        event.start_mark)
                self._aliased += size
                self._grow(size, event.start_mark)
            return super().compose_node(parent, index)
        self._depth += 1
        event = self.peek_event()
        if self._depth > MAX_DEPTH:
            raise yaml.composer.ComposerError(None, None, f"nested deeper than {MAX_DEPTH} levels", event.start_mark)
        before = self._expanded
        try:
            node = super().compose_node(parent, index)
        finally:
            self._depth -= 1
        self._expanded += 1
        if event.anchor is not None:  # only what an alias can name needs its size kept
            self._sizes[id(node)] = self._expanded - before
        if self._expanded > MAX_NODES:
            self._grow(0, node.start_mark)
        return node

    def _grow(self, size: int, mark) -> None:
        self._expanded += size
        if self._expanded <= MAX_NODES:
            return
        if self._aliased * 2 > self._expanded:  # most of it repeated by aliases: a "billion laughs"
            problem = (f"more than {MAX_NODES} values once aliases are expanded, {self._aliased} of them "
                       "repeated by aliases (an alias bomb?)")
        else:  # a file that is simply this large: say its size and the limit, not "an attack"
            repeated = f" (counting {self._aliased} that aliases repeat)" if self._aliased else ""
            problem = (f"the file holds more than {MAX_NODES} values{repeated}, the most pipflow reads from one "
                       "YAML file")
        raise yaml.composer.ComposerError(None, None, problem, mark)


class CheckedValues:
    """Constructor mixin: a value PyYAML cannot build (``2026-13-45`` as a date, a mapping used
    as a key) is a located YAML error instead of a bare ``ValueError``/``TypeError``."""

    def construct_object(self, node, deep=False):  # type: ignore[no-untyped-def]
        try:
            return super().construct_object(node, deep)  # type: ignore[misc]
        except (ValueError, TypeError, OverflowError) as err:
            raise yaml.constructor.ConstructorError(None, None, f"cannot read this value ({err})",
                                                    node.start_mark) from None


class _SafeLoader(CheckedValues, BoundedComposer, yaml.SafeLoader):
    """The pure-Python safe loader, bounded."""


if getattr(yaml, "__with_libyaml__", False):
    class _SafeCLoader(CheckedValues, BoundedComposer, yaml._yaml.CParser, yaml.constructor.SafeConstructor,  # type: ignore[name-defined]
                       yaml.resolver.Resolver):
        """libyaml's parser (several times faster), composed and constructed safely and bounded."""

        def __init__(self, stream: str):
            yaml._yaml.CParser.__init__(self, stream)
            BoundedComposer.__init__(self)
            yaml.constructor.SafeConstructor.__init__(self)
            yaml.resolver.Resolver.__init__(self)
else:  # pragma: no cover - PyYAML built without libyaml
    _SafeCLoader = _SafeLoader


def _event_parser(text: str) -> Any:
    if getattr(yaml, "__with_libyaml__", False):
        return yaml._yaml.CParser(text)
    return yaml.SafeLoader(text)  # pragma: no cover - PyYAML built without libyaml


def event_count(text: str) -> int:
    """How many YAML events a text makes, counted by libyaml in C (no Python object per event:
    a 5 MB file in a fraction of a second); 0 when it is no YAML. Every entry of a mapping or list
    is at least one event, so this bounds every section's size before anything is read."""
    if not getattr(yaml, "__with_libyaml__", False):  # pragma: no cover
        return sum(1 for _ in yaml.parse(text, Loader=yaml.SafeLoader))
    try:
        return int(yaml._yaml.CParser(text).raw_parse())
    except yaml.YAMLError:
        return 0


_NULLS = ("", "~", "null", "Null", "NULL")


def top_level_scalar(text: str, key: str) -> str | None:
    """The value of ``key`` in a YAML document's root mapping, when it is a plain value (a
    file's ``domain:``), read from libyaml's events up to that key and no further; None when the
    key is absent, not a scalar, or the text is no YAML mapping (the loader then says why). A
    text without the word at all is answered without reading it."""
    if key not in text:
        return None
    parser = _event_parser(text)
    ev = yaml.events
    get = parser.get_event
    depth, children, found = 0, 0, False
    try:
        while True:
            event = get()
            kind = type(event)
            if event is None or kind is ev.StreamEndEvent:
                return None
            if kind in (ev.MappingStartEvent, ev.SequenceStartEvent):
                if depth == 0 and kind is not ev.MappingStartEvent:
                    return None
                if depth == 1:
                    if found:
                        return None
                    children += 1
                depth += 1
                if depth > MAX_DEPTH:
                    return None
            elif kind in (ev.MappingEndEvent, ev.SequenceEndEvent):
                depth -= 1
                if depth == 0:
                    return None
            elif kind in (ev.ScalarEvent, ev.AliasEvent) and depth == 1:
                if found:
                    if kind is not ev.ScalarEvent or (not event.style and event.value in _NULLS):
                        return None
                    return str(event.value)
                found = children % 2 == 0 and kind is ev.ScalarEvent and event.value == key
                children += 1
    except yaml.YAMLError:
        return None
    finally:
        getattr(parser, "dispose", lambda: None)()


def section_sizes(text: str) -> dict[str, tuple[int, int, int]]:
    """``{key: (entries, line, column)}`` for each top-level key of a YAML mapping document whose
    value is a mapping (its keys) or a list (its items): what a size limit counts ("this world
    file has 100,000 robots"), read from libyaml's events without composing a node or building a
    value (several times faster than loading). Aliases count as one entry (their expansion is
    :class:`BoundedComposer`'s to bound). Anything that is not such a document, or not YAML at
    all, gives what was counted so far or ``{}``: the loader reports it."""
    parser = _event_parser(text)
    ev = yaml.events
    starts, ends = (ev.MappingStartEvent, ev.SequenceStartEvent), (ev.MappingEndEvent, ev.SequenceEndEvent)
    nodes = (ev.ScalarEvent, ev.AliasEvent)
    sizes: dict[str, tuple[int, int, int]] = {}
    get = parser.get_event
    depth = 0
    root_children = 0            # nodes of the root mapping so far (keys and values alternate)
    key: tuple[str, int, int] | None = None
    section: tuple[str, int, int] | None = None   # the top-level key whose value is open
    section_mapping, count = True, 0
    try:
        while True:
            event = get()
            kind = type(event)
            if kind in nodes:
                if depth == 2:
                    count += 1
                elif depth == 1:
                    if root_children % 2 == 0:
                        key = (str(event.value), event.start_mark.line + 1, event.start_mark.column + 1) \
                            if kind is ev.ScalarEvent else None
                    root_children += 1
            elif kind in starts:
                if depth == 2:
                    count += 1
                elif depth == 1:
                    section = key if root_children % 2 == 1 else None
                    section_mapping, count = kind is ev.MappingStartEvent, 0
                    root_children += 1
                elif depth == 0 and kind is not ev.MappingStartEvent:
                    return {}
                depth += 1
                if depth > MAX_DEPTH:
                    break
            elif kind in ends:
                depth -= 1
                if depth == 1 and section is not None:
                    sizes[section[0]] = (count // 2 if section_mapping else count, section[1], section[2])
                    section = None
                elif depth == 0:
                    break
            elif event is None or kind is ev.StreamEndEvent:
                break
    except yaml.YAMLError:
        pass
    finally:
        getattr(parser, "dispose", lambda: None)()
    return sizes


def located_reader_error(err: yaml.reader.ReaderError, text: str) -> yaml.MarkedYAMLError:
    """A character the YAML reader refuses (a NUL, a control character) as an error with a line
    and column, like every other YAML error (the reader reports only an offset)."""
    pos = max(0, min(int(getattr(err, "position", 0) or 0), len(text)))
    line = text.count("\n", 0, pos)
    column = pos - (text.rfind("\n", 0, pos) + 1)
    mark = yaml.Mark("<unicode string>", pos, line, column, None, None)
    code = err.character if isinstance(err.character, int) else ord(err.character or "\0")
    return yaml.scanner.ScannerError(None, None, f"character #x{code:04x} is not allowed in YAML text ({err.reason})", mark)


def safe_load(text: str) -> Any:
    """``yaml.safe_load`` with the limits above; errors are ``yaml.YAMLError`` as there."""
    loader = _SafeCLoader(text)
    try:
        return loader.get_single_data()
    except yaml.reader.ReaderError as err:
        raise located_reader_error(err, text) from None
    finally:
        loader.dispose()


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

    def _find_duplicates(self, node: yaml.Node, path: tuple, seen_nodes: set[int] | None = None) -> None:
        seen_nodes = set() if seen_nodes is None else seen_nodes
        if id(node) in seen_nodes:  # an alias: its duplicates were reported where it is defined
            return
        seen_nodes.add(id(node))
        if isinstance(node, yaml.MappingNode):
            seen: set[str] = set()
            for k, v in node.value:
                name = k.value if isinstance(k, yaml.ScalarNode) else None
                if name is not None and name in seen:
                    self.duplicates.append((path + (name,), self._mark(k)))
                seen.add(name)
                self._find_duplicates(v, path + (name,), seen_nodes)
        elif isinstance(node, yaml.SequenceNode):
            for i, v in enumerate(node.value):
                self._find_duplicates(v, path + (i,), seen_nodes)


def load_with_locations(text: str, file: str) -> tuple[Any, Callable[..., Location]]:
    """Parse YAML ``text`` (named ``file`` in messages); return ``(data, locate)``.

    Raises ``yaml.YAMLError`` on a syntax error; :func:`yaml_error_diagnostic` turns that into a
    located :class:`Diagnostic`."""
    loader = _SafeCLoader(text)
    try:
        root = loader.get_single_node()
        locate = Locator(root, file)  # before constructing: that flattens `<<: *x` merges in place
        data = loader.construct_document(root) if root is not None else None
    except yaml.reader.ReaderError as err:
        raise located_reader_error(err, text) from None
    finally:
        loader.dispose()
    return data, locate


def yaml_problem(exc: yaml.YAMLError) -> str:
    """What a YAML error says is wrong, in our words where libyaml's differ: newer libyaml builds
    (PyPI's PyYAML wheels) refuse deep flow nesting while scanning ahead, before our composer's
    limit sees the events."""
    problem = getattr(exc, "problem", None) or str(exc)
    if "maximum nesting depth" in problem:
        problem = f"nested deeper than the YAML reader allows ({problem})"
    return problem


def yaml_error_diagnostic(exc: yaml.YAMLError, file: str) -> Diagnostic:
    """A YAML syntax error as a diagnostic at the position PyYAML reports."""
    mark = getattr(exc, "problem_mark", None) or getattr(exc, "context_mark", None)
    problem = yaml_problem(exc)
    context = getattr(exc, "context", None)
    message = f"YAML syntax error: {problem}" + (f" ({context})" if context else "")
    loc = Location(file, mark.line + 1, mark.column + 1) if mark else Location(file)
    return Diagnostic(loc, message)

"""The shared YAML reader and loader (pipflow.yamlsource): what it accepts, and where its limits
are. Ordinary anchors and aliases keep working; the limits sit far above any real file and far
below what would hurt."""
from __future__ import annotations

import os

import pytest
import yaml

from pipflow.engine.source import SourceDict, parse_yaml
from pipflow.errors import SourceFileError
from pipflow.yamlsource import (MAX_DEPTH, MAX_NODES, load_with_locations, read_source, safe_load,
                                yaml_error_diagnostic)


def _fan(levels: int, width: int = 9) -> tuple[str, int]:
    """A document of aliases ``levels`` deep, ``width`` wide; returns it and its expanded size."""
    lines = ["a0: &a0 [" + ", ".join(["x"] * width) + "]"]
    size = width + 1
    total = size
    for i in range(1, levels):
        lines.append(f"a{i}: &a{i} [" + ", ".join([f"*a{i - 1}"] * width) + "]")
        size = 1 + width * size
        total += size
    return "\n".join(lines) + "\n", total


def test_ordinary_anchors_aliases_and_merge_keys_load_with_locations():
    text = ("defaults: &d {retries: 2, timeout: 30}\n"
            "steps:\n"
            "  - {id: a, with: *d}\n"
            "  - {id: b, with: {<<: *d, timeout: 5}}\n")
    data = parse_yaml(text, "wf.yaml")
    assert data["steps"][0]["with"] == {"retries": 2, "timeout": 30}
    assert data["steps"][1]["with"] == {"retries": 2, "timeout": 5}
    assert isinstance(data["steps"][1], SourceDict) and str(data["steps"][1].where("with")) == "wf.yaml:4:19"
    plain, locate = load_with_locations(text, "w.yaml")
    assert plain["steps"][0]["with"]["timeout"] == 30 and str(locate(("steps", 1, "id"))) == "w.yaml:4:10"


def test_expansion_below_the_limit_loads_and_above_it_is_refused():
    below, size = _fan(6)
    assert size < MAX_NODES
    assert len(safe_load(below)["a5"]) == 9
    above, size = _fan(7)
    assert size > MAX_NODES
    for load in (safe_load, lambda t: parse_yaml(t, "f.yaml"), lambda t: load_with_locations(t, "f.yaml")):
        with pytest.raises((yaml.YAMLError, SourceFileError), match="aliases are expanded"):
            load(above)


def test_merge_key_bomb_is_refused():
    lines = ["a0: &a0 {k0: 1, k1: 2, k2: 3, k3: 4, k4: 5, k5: 6, k6: 7, k7: 8, k8: 9}"]
    lines += [f"a{i}: &a{i} {{<<: [" + ", ".join([f"*a{i - 1}"] * 9) + "]}" for i in range(1, 12)]
    with pytest.raises(yaml.YAMLError, match="aliases are expanded"):
        safe_load("\n".join(lines))


def test_nesting_limit_is_exact():
    assert safe_load("[" * MAX_DEPTH + "]" * MAX_DEPTH) is not None
    with pytest.raises(yaml.YAMLError, match=f"nested deeper than {MAX_DEPTH}"):
        safe_load("[" * (MAX_DEPTH + 1) + "]" * (MAX_DEPTH + 1))


def test_libyaml_nesting_limit_reads_like_ours():
    """Newer libyaml builds refuse deep flow nesting while scanning ahead, before our composer
    sees the events; the message must still say what is wrong in the user's words."""
    mark = yaml.Mark("w.yaml", 0, 1, 1006, None, None)
    err = yaml.scanner.ScannerError(None, None, "exceeded maximum nesting depth", mark)
    diag = yaml_error_diagnostic(err, "w.yaml")
    assert "nested deeper than the YAML reader allows" in diag.message
    assert (diag.location.line, diag.location.column) == (2, 1007)


def test_workflow_files_word_libyamls_nesting_limit_alike(monkeypatch):
    """The engine's located loader (workflow files) words libyaml's limit as the library's does."""
    import pipflow.engine.source as source

    mark = yaml.Mark("wf.yaml", 0, 3, 1011, None, None)

    def refuse(self):
        raise yaml.scanner.ScannerError(None, None, "exceeded maximum nesting depth", mark)

    monkeypatch.setattr(source._CLoader, "get_single_data", refuse)
    with pytest.raises(SourceFileError, match="wf.yaml:4:1012: YAML syntax: nested deeper than the YAML reader"):
        parse_yaml("a: 1\n", "wf.yaml")


def test_recursive_alias_is_refused_everywhere():
    for text in ("a: &a [*a]", "a: &a {b: *a}", "a: &a [1, [2, *a]]"):
        with pytest.raises(yaml.YAMLError, match="its own anchor"):
            safe_load(text)


def test_read_source_limits_and_encodings(tmp_path):
    path = tmp_path / "w.yaml"
    path.write_bytes(b"\xef\xbb\xbfname: w\n")  # a BOM (Windows editors) is dropped
    assert read_source(path) == "name: w\n"
    path.write_bytes(b"x" * 101)
    with pytest.raises(SourceFileError, match="more than the 100"):
        read_source(path, "world file", limit=100)
    path.write_text("name: w\n", encoding="utf-16")
    with pytest.raises(SourceFileError, match="not UTF-8"):
        read_source(path)
    fifo = tmp_path / "pipe"
    os.mkfifo(fifo)
    with pytest.raises(SourceFileError, match="not a regular file"):
        read_source(fifo, "world file")


def test_values_yaml_cannot_build_are_located():
    with pytest.raises(SourceFileError) as info:
        parse_yaml("a: 1\nwhen: 2026-02-30\n", "wf.yaml")
    assert str(info.value).startswith("wf.yaml:2:7: YAML: cannot read this value")
    with pytest.raises(SourceFileError, match="wf.yaml:2:8: YAML syntax: character #x0000"):
        parse_yaml("a: 1\nname: a\x00b\n", "wf.yaml")


def test_a_key_written_twice_is_still_an_error_next_to_merge_keys():
    with pytest.raises(SourceFileError, match="wf.yaml:3:3: duplicate key 'timeout'"):
        parse_yaml("d: &d {timeout: 1}\ne: {<<: *d, timeout: 2,\n  timeout: 3}\n", "wf.yaml")

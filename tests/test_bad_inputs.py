"""Bad inputs, as a hostile or clumsy user would give them (issue 13): workflow files, inputs,
world and task files, the step cache and run records.

Every case goes through the real CLI (``main()`` in-process, the same code as the ``pipflow``
command) and asserts the exit code, that the message names the file (and line, where there is
one) or the step, and the cause, that no traceback is shown, and that nothing the user had is
lost. LLM-server and bench cases live in tests/test_bad_inputs_llm.py."""
from __future__ import annotations

import hashlib
import json
import os
import shutil
import stat
import threading
from pathlib import Path

import pytest

from pipflow import Input, step
from pipflow.engine import registry as registry_module
from pipflow.engine.cli import main

REPO = Path(__file__).resolve().parents[1]
WORLD = REPO / "benchmarks" / "warehouse" / "world.yaml"
TASKS = REPO / "benchmarks" / "warehouse" / "tasks.yaml"

GOOD = """\
pipflow: 1
name: good
inputs:
  text: {type: string, default: hello}
  n: {type: integer, default: 2}
  mode: {type: string, default: a, choices: [a, b]}
  speed: {type: number, default: 1.0}
steps:
  - id: a
    uses: core.value
    with: {value: "${inputs.text}"}
outputs:
  v: ${a.value}
"""

WORLD_FLOW = """\
pipflow: 1
name: load-world
inputs:
  world: {type: path, default: world.yaml}
steps:
  - id: world
    uses: world.load
    with: {path: "${inputs.world}"}
outputs:
  name: ${world.world.name}
"""


def _bomb(levels: int = 9) -> str:
    lines = ["a0: &a0 [" + ", ".join(["x"] * 9) + "]"]
    for i in range(1, levels):
        lines.append(f"a{i}: &a{i} [" + ", ".join([f"*a{i - 1}"] * 9) + "]")
    return "\n".join(lines) + "\n"


def cli(capsys, *argv: str, traceback_ok: bool = False) -> tuple[int, str, str]:
    """Run the pipflow CLI in-process; returns (exit code, stdout, stderr). No traceback may show
    (unless asked for with -v)."""
    try:
        code = main([str(a) for a in argv])
    except SystemExit as exc:  # argparse's own user errors
        code = exc.code if isinstance(exc.code, int) else 2
    out, err = capsys.readouterr()
    assert traceback_ok or "Traceback" not in out + err, out + err
    return code, out, err


def snapshot(folder: Path) -> dict[str, str]:
    """Content hash of every file under ``folder`` (what the user had; pipflow's own run records
    and cache left out)."""
    return {str(p.relative_to(folder)): hashlib.sha256(p.read_bytes()).hexdigest()
            for p in sorted(folder.rglob("*")) if p.is_file() and not p.is_symlink()
            and p.relative_to(folder).parts[0] not in ("runs", "cache")}


def newest_run(ws: Path, before: set[Path]) -> Path:
    """The run directory that appeared since ``before`` (names sort by second only)."""
    new = set((ws / "runs").iterdir()) - before
    assert len(new) == 1, new
    return new.pop()


@pytest.fixture
def ws(engine_env: Path) -> Path:
    """A working folder with a private cache, a good workflow and a copy of the warehouse world."""
    (engine_env / "good.yaml").write_text(GOOD)
    (engine_env / "wf.yaml").write_text(WORLD_FLOW)
    shutil.copy(WORLD, engine_env / "world.yaml")
    return engine_env


# --- workflow files --------------------------------------------------------------------------------
# (content, [fragments the message must contain]); "{f}" is the file's name
WORKFLOWS: dict[str, tuple[str | bytes, list[str]]] = {
    "not utf-8": (b"pipflow: 1\nname: \xff\xfe\n", ["bad.yaml:2:7", "not UTF-8"]),
    "random bytes": (bytes(range(256)) * 4, ["bad.yaml", "not UTF-8"]),
    "nul byte": ("pipflow: 1\nname: a\x00b\n", ["bad.yaml:2", "YAML"]),
    "empty": ("", ["bad.yaml:1:1", "must be a mapping"]),
    "only a comment": ("# nothing here\n", ["bad.yaml:1:1", "must be a mapping"]),
    "a list": ("- 1\n- 2\n", ["bad.yaml:1:1", "must be a mapping"]),
    "a scalar": ("hello\n", ["bad.yaml:1:1", "must be a mapping"]),
    "unclosed bracket": ("pipflow: 1\nname: x\nsteps: [\n", ["bad.yaml:4", "YAML syntax"]),
    "tab indentation": ("pipflow: 1\nsteps:\n\t- id: a\n", ["bad.yaml:3", "YAML syntax"]),
    "bad indentation": ("pipflow: 1\nname: x\n  steps: []\n", ["bad.yaml:3", "YAML syntax"]),
    "duplicate key": ("pipflow: 1\nname: x\nname: y\nsteps: []\n", ["bad.yaml:3:1", "duplicate key 'name'"]),
    "alias bomb": ("pipflow: 1\nname: x\nsteps: []\noutputs:\n" + "".join("  " + line + "\n" for line in _bomb().splitlines()),
                   ["bad.yaml", "alias"]),
    "recursive alias": ("pipflow: 1\nname: x\nsteps: &s [*s]\n", ["bad.yaml:3", "its own anchor"]),
    "undefined alias": ("pipflow: 1\nname: x\nsteps: *nothere\n", ["bad.yaml:3", "undefined alias"]),
    "deep nesting": ("pipflow: 1\nname: x\nsteps: []\noutputs: {a: " + "[" * 5000 + "]" * 5000 + "}\n",
                     ["bad.yaml:4", "nested deeper than"]),
    "python tag": ("pipflow: 1\nname: !!python/object/apply:os.system ['echo pwned']\nsteps: []\n",
                   ["bad.yaml:2", "constructor"]),
    "impossible date": ("pipflow: 1\nname: x\ndescription: 2026-13-45\nsteps: []\n", ["bad.yaml:3", "cannot read this value"]),
    "mapping as key": ("pipflow: 1\nname: x\n? {a: 1}\n: 2\nsteps: []\n", ["bad.yaml", "cannot read this value"]),
    "null and number keys": ("pipflow: 1\nname: x\n~: 1\n5: 2\nsteps:\n  - {id: a, uses: core.value, with: {value: 1}, 7: 4}\n",
                             ["bad.yaml:1:1", "unknown key 5, None", "bad.yaml:6:5", "unknown key 7"]),
    "missing pipflow": ("name: x\nsteps: []\n", ["bad.yaml:1:1", "missing required 'pipflow'"]),
    "wrong format version": ("pipflow: 2\nname: x\nsteps: []\n", ["bad.yaml:1:10", "pipflow"]),
    "bad name": ("pipflow: 1\nname: 'a b'\nsteps: []\n", ["bad.yaml:2:7", "does not match"]),
    "unknown top-level key": ("pipflow: 1\nname: x\nstep: []\nsteps: []\n", ["bad.yaml:1:1", "unknown key 'step'"]),
    "steps not a list": ("pipflow: 1\nname: x\nsteps: {a: 1}\n", ["bad.yaml:3:8", "not of type 'array'"]),
    "step without id": ("pipflow: 1\nname: x\nsteps:\n  - uses: core.value\n    with: {value: 1}\n",
                        ["bad.yaml:4:5", "'id'"]),
    "reserved id": ("pipflow: 1\nname: x\nsteps:\n  - id: env\n    uses: core.value\n    with: {value: 1}\n",
                    ["bad.yaml:4:9", "env"]),
    "unknown step": ("pipflow: 1\nname: x\nsteps:\n  - id: a\n    uses: core.valu\n    with: {value: 1}\n",
                     ["bad.yaml:5:11", "unknown step 'core.valu'", "core.value"]),
    "unknown argument": ("pipflow: 1\nname: x\nsteps:\n  - id: a\n    uses: core.value\n    with: {value: 1, valu: 2}\n",
                         ["bad.yaml:6", "unknown argument 'valu'"]),
    "missing argument": ("pipflow: 1\nname: x\nsteps:\n  - id: a\n    uses: core.value\n",
                         ["bad.yaml:4:5", "missing required argument 'value'"]),
    "argument of wrong type": ("pipflow: 1\nname: x\nsteps:\n  - id: a\n    uses: core.fail\n    with: {message: [1]}\n",
                               ["bad.yaml:6", "'message' must be string"]),
    "duplicate step id": ("pipflow: 1\nname: x\nsteps:\n  - {id: a, uses: core.value, with: {value: 1}}\n"
                          "  - {id: a, uses: core.value, with: {value: 2}}\n", ["bad.yaml:5:5", "duplicate step id 'a'"]),
    "unknown reference": ("pipflow: 1\nname: x\nsteps:\n  - {id: a, uses: core.value, with: {value: '${b.value}'}}\n",
                          ["bad.yaml:4", "unknown reference 'b'"]),
    "unknown input": ("pipflow: 1\nname: x\nsteps:\n  - {id: a, uses: core.value, with: {value: '${inputs.nope}'}}\n",
                      ["bad.yaml:4", "unknown input 'inputs.nope'"]),
    "unknown output": ("pipflow: 1\nname: x\nsteps:\n  - {id: a, uses: core.value, with: {value: 1}}\n"
                       "  - {id: b, uses: core.value, with: {value: '${a.valu}'}}\n", ["bad.yaml:5", "no output 'valu'"]),
    "cycle": ("pipflow: 1\nname: x\nsteps:\n  - {id: a, uses: core.value, with: {value: '${b.value}'}}\n"
              "  - {id: b, uses: core.value, with: {value: '${a.value}'}}\n", ["bad.yaml:4:5", "cycle between steps: a -> b -> a"]),
    "self reference": ("pipflow: 1\nname: x\nsteps:\n  - {id: a, uses: core.value, with: {value: '${a.value}'}}\n",
                       ["bad.yaml:4", "refers to its own outputs"]),
    "invalid expression": ("pipflow: 1\nname: x\nsteps:\n  - {id: a, uses: core.value, with: {value: '${a.}'}}\n",
                           ["bad.yaml:4", "invalid expression"]),
    "deeply nested expression": ("pipflow: 1\nname: x\nsteps:\n  - {id: a, uses: core.value, with: {value: '${" + "[" * 400
                                 + "]" * 400 + "}'}}\n", ["bad.yaml:4", "nested too deeply"]),
    "unclosed expression": ("pipflow: 1\nname: x\nsteps:\n  - {id: a, uses: core.value, with: {value: '${inputs'}}\n",
                            ["bad.yaml:4", "unclosed"]),
    "loop without max": ("pipflow: 1\nname: x\nsteps:\n  - id: l\n    loop:\n      until: true\n      steps:\n"
                         "        - {id: a, uses: core.value, with: {value: 1}}\n", ["bad.yaml:6", "'max'"]),
    "loop max zero": ("pipflow: 1\nname: x\nsteps:\n  - id: l\n    loop:\n      max: 0\n      until: true\n      steps:\n"
                      "        - {id: a, uses: core.value, with: {value: 1}}\n", ["bad.yaml:6:12", "minimum"]),
    "previous outside a loop": ("pipflow: 1\nname: x\nsteps:\n  - {id: a, uses: core.value, with: {value: '${previous.a}'}}\n",
                                ["bad.yaml:4", "only defined inside a loop"]),
    "retry attempts zero": ("pipflow: 1\nname: x\nsteps:\n  - {id: a, uses: core.value, with: {value: 1}, retry: {attempts: 0}}\n",
                            ["bad.yaml:4", "minimum"]),
    "negative timeout": ("pipflow: 1\nname: x\nsteps:\n  - {id: a, uses: core.value, with: {value: 1}, timeout: -1}\n",
                         ["bad.yaml:4", "timeout"]),
    "undeclared env variable": ("pipflow: 1\nname: x\nsteps:\n  - {id: a, uses: core.value, with: {value: '${env.OPENAI_API_KEY}'}}\n",
                                ["bad.yaml:4", "'OPENAI_API_KEY' is not declared", "env:"]),
    "the whole environment": ("pipflow: 1\nname: x\nenv: [HOME]\nsteps: []\noutputs:\n  e: ${env}\n",
                              ["bad.yaml:6", "must name one variable"]),
    "env item by subscript": ("pipflow: 1\nname: x\nsteps: []\noutputs:\n  e: \"${env['SECRET_TOKEN']}\"\n",
                              ["bad.yaml:5", "'SECRET_TOKEN' is not declared", "it holds a key"]),
    "env name not a name": ("pipflow: 1\nname: x\nenv: ['1 X']\nsteps: []\n", ["bad.yaml:3", "does not match"]),
    "undeclared env in an input default": ("pipflow: 1\nname: x\ninputs:\n  k: {type: string, default: '${env.HF_TOKEN}'}\nsteps: []\n",
                                           ["bad.yaml:4", "'HF_TOKEN' is not declared"]),
    "input default reads a step": ("pipflow: 1\nname: x\ninputs:\n  k: {type: string, default: '${a.value}'}\nsteps:\n"
                                   "  - {id: a, uses: core.value, with: {value: 1}}\n", ["bad.yaml:4", "only environment variables"]),
    "input default of wrong type": ("pipflow: 1\nname: x\ninputs:\n  n: {type: integer, default: abc}\nsteps: []\n",
                                    ["bad.yaml:4", "not of type integer"]),
    "unknown input type": ("pipflow: 1\nname: x\ninputs:\n  n: {type: int}\nsteps: []\n", ["bad.yaml:4", "type"]),
    "extends of a missing file": ("pipflow: 1\nname: x\nextends: nothere.yaml\nsteps: []\n", ["bad.yaml:3:10", "no such file"]),
    "extends not a path": ("pipflow: 1\nname: x\nextends: 5\nsteps: []\n", ["bad.yaml:3:10", "extends"]),
    "extends itself": ("pipflow: 1\nname: x\nextends: bad.yaml\nsteps: []\n", ["bad.yaml", "cycle"]),
}


@pytest.mark.parametrize("case", sorted(WORKFLOWS))
def test_bad_workflow_file_is_a_located_user_error(ws, capsys, case):
    content, fragments = WORKFLOWS[case]
    bad = ws / "bad.yaml"
    bad.write_bytes(content if isinstance(content, bytes) else content.encode("utf-8"))
    before = snapshot(ws)
    for command in (["validate"], ["run"]):  # validate and run must agree
        code, out, err = cli(capsys, *command, bad)
        assert code == 2, (command, out, err)
        for fragment in fragments:
            assert fragment in err, (command, fragment, err)
    assert snapshot(ws) == before  # nothing of the user's changed
    assert not (ws / "runs").exists()  # an invalid workflow starts no run


# extends: bases that cannot be used
BASES: dict[str, tuple[bytes, str]] = {
    "empty base": (b"", "the base workflow is empty"),
    "base is a list": (b"- 1\n- 2\n", "is a list, not a mapping"),
    "base is a number": (b"42\n", "is a int, not a mapping"),
    "binary base": (bytes(range(128, 256)) * 3, "not UTF-8"),
    "base with a syntax error": (b"pipflow: 1\nsteps: [\n", "YAML syntax"),
    "base is an alias bomb": (_bomb().encode(), "alias"),
}


@pytest.mark.parametrize("case", sorted(BASES))
def test_unusable_extends_base_is_located_and_validate_agrees_with_run(ws, capsys, case):
    base, cause = BASES[case]
    (ws / "base.yaml").write_bytes(base)
    (ws / "child.yaml").write_text("pipflow: 1\nname: child\nextends: base.yaml\nsteps: []\n")
    for command in ("validate", "run"):
        code, _, err = cli(capsys, command, ws / "child.yaml")
        assert code == 2, (command, err)
        assert "child.yaml:3:10" in err and cause in err, err


CHILDREN = {  # a child of a good base, with parts of the wrong type (found by fuzzing the merge)
    "remove is a number": ("remove: -1\nsteps: []\n", "child.yaml:4:9", "remove: expected a list of step ids"),
    "remove holds a list": ("remove: [[a]]\nsteps: []\n", "child.yaml:4:9", "remove: expected a list of step ids"),
    "step id is a list": ("steps:\n  - {id: [q], with: {value: 2}}\n", "child.yaml:5", "is not of type 'string'"),
    "step id is a mapping": ("steps:\n  - {id: {a: 1}, uses: core.value, with: {value: 2}}\n", "child.yaml:5", "is not of type 'string'"),
    "steps is a mapping": ("steps: {a: 1}\n", "child.yaml:4:8", "steps: expected a list of steps"),
}


@pytest.mark.parametrize("case", sorted(CHILDREN))
def test_extends_child_with_parts_of_the_wrong_type(ws, capsys, case):
    body, where, cause = CHILDREN[case]
    (ws / "base.yaml").write_text("pipflow: 1\nname: base\nsteps:\n  - {id: a, uses: core.value, with: {value: 1}}\n")
    (ws / "child.yaml").write_text("pipflow: 1\nname: child\nextends: base.yaml\n" + body)
    for command in ("validate", "run"):
        code, _, err = cli(capsys, command, ws / "child.yaml")
        assert code == 2 and where in err and cause in err, (command, err)


def test_extends_chain_of_1500_files_is_a_depth_limit_not_a_recursion_error(ws, capsys):
    for i in range(1500):
        parent = f"extends: c{i + 1}.yaml\n" if i < 1499 else ""
        (ws / f"c{i}.yaml").write_text(f"pipflow: 1\nname: c{i}\n{parent}steps:\n"
                                       "  - {id: a, uses: core.value, with: {value: 1}}\n")
    for command in ("validate", "run"):
        code, _, err = cli(capsys, command, ws / "c0.yaml")
        assert code == 2
        assert "extends" in err and "more than 32 workflow files" in err and ":3:10" in err


def test_extends_of_a_folder_and_of_dev_zero(ws, capsys):
    (ws / "folder.yaml").mkdir()
    for target, cause in (("folder.yaml", "not a regular file"), ("/dev/zero", "not a regular file")):
        (ws / "child.yaml").write_text(f"pipflow: 1\nname: child\nextends: {target}\nsteps: []\n")
        code, _, err = cli(capsys, "run", ws / "child.yaml")
        assert code == 2 and cause in err and "child.yaml:3:10" in err


SPECIAL_FILES = ["folder", "dev-zero", "fifo", "sparse-20MB", "missing"]


def _special(ws: Path, kind: str) -> Path:
    if kind == "folder":
        (ws / "folder.yaml").mkdir(exist_ok=True)
        return ws / "folder.yaml"
    if kind == "dev-zero":
        return Path("/dev/zero")
    if kind == "fifo":
        path = ws / "pipe.yaml"
        if not path.exists():
            os.mkfifo(path)  # nobody writes to it: reading it would block for ever
        return path
    if kind == "sparse-20MB":
        path = ws / "huge.yaml"
        with open(path, "wb") as fh:
            fh.truncate(20 * 1024 * 1024)
        return path
    return ws / "missing.yaml"


@pytest.mark.parametrize("kind", SPECIAL_FILES)
def test_workflow_path_that_is_not_an_ordinary_file(ws, capsys, kind):
    path = _special(ws, kind)
    code, _, err = cli(capsys, "run", path)
    assert code == 2 and str(path) in err
    assert any(cause in err for cause in ("not a regular file", "more than", "no such workflow file")), err


# --- inputs: -i, --inputs, options ------------------------------------------------------------------
INPUTS: dict[str, tuple[list[str], list[str]]] = {
    "unknown input": (["-i", "txt=x"], ["unknown input 'txt'", "did you mean 'text'"]),
    "no equals sign": (["-i", "text"], ["-i 'text'", "key=value"]),
    "integer from text": (["-i", "n=abc"], ["input 'n'", "not an integer"]),
    "integer from a float": (["-i", "n=2.5"], ["input 'n'", "not an integer"]),
    "integer from broken YAML": (["-i", "n=[1,"], ["input 'n'", "not a YAML value"]),
    "integer from an alias bomb": (["-i", "n=" + _bomb(4).replace("\n", " ")], ["input 'n'"]),
    "number that is not a number": (["-i", "speed=.nan"], ["input 'speed'", "not a finite number"]),
    "infinite number": (["-i", "speed=-.inf"], ["input 'speed'", "not a finite number"]),
    "number beyond floats": (["-i", "speed=1" + "0" * 400], ["input 'speed'", "too large a number"]),
    "not one of the choices": (["-i", "mode=c"], ["input 'mode'", "one of a, b"]),
    "jobs zero": (["--jobs", "0"], ["--jobs", "1 or more"]),
    "jobs negative": (["--jobs", "-5"], ["--jobs", "1 or more"]),
    "jobs not a number": (["--jobs", "many"], ["--jobs", "not a whole number"]),
    "runs-dir is a file": (["--runs-dir", "afile"], ["--runs-dir afile", "a file, not a folder"]),
    "runs-dir under /proc": (["--runs-dir", "/proc/pipflow-runs"], ["--runs-dir /proc/pipflow-runs", "cannot write a run record"]),
    "runs-dir not writable": (["--runs-dir", "/sys/pipflow-runs"], ["--runs-dir /sys/pipflow-runs", "cannot write a run record"]),
    "runs-dir below a file": (["--runs-dir", "/dev/null/runs"], ["--runs-dir /dev/null/runs", "cannot write a run record"]),
}


@pytest.mark.parametrize("case", sorted(INPUTS))
def test_bad_inputs_and_options(ws, capsys, case):
    argv, fragments = INPUTS[case]
    (ws / "afile").write_text("the user's notes\n")
    before = snapshot(ws)
    code, _, err = cli(capsys, "run", ws / "good.yaml", *argv)
    assert code == 2, err
    for fragment in fragments:
        assert fragment in err, (fragment, err)
    assert snapshot(ws) == before


INPUT_FILES: dict[str, tuple[bytes, list[str]]] = {
    "not utf-8": (b"text: caf\xe9\n", ["inputs.yaml:1:10", "not UTF-8"]),
    "a list": (b"- text\n", ["inputs.yaml", "must be a mapping"]),
    "syntax error": (b"text: [\n", ["inputs.yaml:2", "YAML syntax"]),
    "alias bomb": (("text: x\nextra:\n" + "".join("  " + line + "\n" for line in _bomb().splitlines())).encode(),
                   ["inputs.yaml", "alias"]),
    "unknown key": (b"txt: hi\n", ["unknown input 'txt'"]),
    "wrong type": (b"n: [1, 2]\n", ["input 'n' must be integer"]),
    "duplicate key": (b"text: a\ntext: b\n", ["inputs.yaml:2:1", "duplicate key 'text'"]),
    "not a number": (b"speed: .nan\n", ["input 'speed'", "finite number"]),
    "number and null keys": (b"1: 2\n~: 3\n", ["unknown input 1, None"]),
}


@pytest.mark.parametrize("case", sorted(INPUT_FILES))
def test_bad_inputs_file(ws, capsys, case):
    content, fragments = INPUT_FILES[case]
    (ws / "inputs.yaml").write_bytes(content)
    code, _, err = cli(capsys, "run", ws / "good.yaml", "--inputs", ws / "inputs.yaml")
    assert code == 2, err
    for fragment in fragments:
        assert fragment in err, (fragment, err)


@pytest.mark.parametrize("kind", SPECIAL_FILES)
def test_inputs_file_that_is_not_an_ordinary_file(ws, capsys, kind):
    path = _special(ws, kind)
    code, _, err = cli(capsys, "run", ws / "good.yaml", "--inputs", path)
    assert code == 2 and str(path) in err
    assert any(c in err for c in ("not a regular file", "more than", "no such inputs file")), err


# --- expressions: what a sandboxed expression may build ---------------------------------------------
EXPRESSIONS = {
    "repeat a string 10**10 times": "${ 'a' * 10**10 }",
    "repeat a list": "${ [0] * 10**9 }",
    "huge power": "${ 10 ** 1000000 }",
    "pad with center": "${ 'x' | center(10**10) }",
    "pad with a method": "${ 'x'.ljust(10**10) }",
    "format width": "${ '%0100000000d' % 1 }",
    "str.format width": "${ '{:>100000000}'.format(1) }",
    "replace into every gap": "${ ('a' * 9000000).replace('', 'bb') }",
    "join big pieces": "${ ('a' * 6000000) ~ ('b' * 6000000) }",
    "add big strings": "${ ('a' * 6000000) + ('b' * 6000000) }",
    "repeat a repetition": "${ 'ab' * 100000 * 100000 }",
    "star width": "${ '%*d' % (10**9, 1) }",
    "repeat a list of big texts": "${ ['a' * 10**7] * 10**7 }",
    "join with a big glue": "${ ([''] * 10**7) | join('a' * 1000) }",
    "join many copies": "${ (['a' * 10**6] * 11) | join }",
    "json of many copies": "${ (['a' * 10**6] * 11) | tojson }",
    "sum of many lists": "${ ([[1] * 1000] * 5000) | sum(start=[]) }",
    "str.join of many copies": "${ ('x' * 10**6).join(['a'] * 10**6) }",
    "indent every line": "${ ('a\\n' * 5000000) | indent(1000) }",
    "slice into pieces": "${ [1, 2] | slice(10**9) | list }",
    "wordwrap width": "${ 'a b' | wordwrap(10**9) }",
}


def test_expressions_cannot_change_values_in_place(ws, capsys):
    """`[l.extend(l), l.extend(l), ...]` doubles a list per call: no size bound could hold."""
    wf = ws / "expr.yaml"
    wf.write_text("pipflow: 1\nname: expr\nsteps:\n  - {id: a, uses: core.value, with: {value: [1, 2]}}\n"
                  "  - id: grow\n    uses: core.value\n    with: {value: \"${ [a.value.extend(a.value)] * 40 }\"}\n")
    code, _, err = cli(capsys, "run", wf)
    assert code == 2 and "step 'grow'" in err and "extend" in err and "unsafe" in err


def test_ordinary_expressions_with_big_numbers_still_work(ws, capsys):
    wf = ws / "expr.yaml"
    wf.write_text("pipflow: 1\nname: expr\nsteps:\n  - id: ok\n    uses: core.value\n"
                  "    with: {value: \"${ [4294967295 | string, '%d' % 123456789012, 2 ** 64, '-' * 80, 'a\\nb' | indent(2)] }\"}\n"
                  "outputs:\n  v: ${ok.value}\n")
    code, out, err = cli(capsys, "run", wf)
    assert code == 0, err
    assert '"4294967295", "123456789012", 18446744073709551616' in out


@pytest.mark.parametrize("case", sorted(EXPRESSIONS))
def test_expression_that_would_build_too_much_is_refused_before_it_allocates(ws, capsys, case):
    wf = ws / "expr.yaml"
    wf.write_text("pipflow: 1\nname: expr\nsteps:\n  - id: big\n    uses: core.value\n"
                  f"    with: {{value: \"{EXPRESSIONS[case]}\"}}\n")
    code, _, err = cli(capsys, "run", wf)
    assert code == 2, err
    assert "step 'big'" in err and ("more than" in err or "larger than" in err or "10 million" in err), err
    run = next((ws / "runs").iterdir())
    assert json.loads((run / "run.json").read_text())["status"] == "failed"  # the record says what happened


# --- world files -------------------------------------------------------------------------------------
WORLDS: dict[str, tuple[bytes, list[str]]] = {
    "not utf-8": (b"name: w\nfloor: {width: 30, height: \xff}\n", ["bad_world.yaml:2:", "not UTF-8"]),
    "binary": (bytes(range(256)) * 8, ["bad_world.yaml", "not UTF-8"]),
    "empty": (b"", ["bad_world.yaml", "mapping"]),
    "a list": (b"- a\n", ["bad_world.yaml", "mapping"]),
    "syntax error": (b"name: w\nfloor: {width: 30\n", ["bad_world.yaml:3", "YAML"]),
    "alias bomb": (_bomb().encode(), ["bad_world.yaml", "alias"]),
    "recursive alias": (b"name: w\nfloor: &f {a: *f}\n", ["bad_world.yaml:2", "its own anchor"]),
    "deep nesting": (b"name: " + b"[" * 3000 + b"]" * 3000 + b"\n", ["bad_world.yaml:1", "nested deeper"]),
    "python tag": (b"name: !!python/name:os.system\n", ["bad_world.yaml:1", "constructor"]),
    "impossible date": (WORLD.read_bytes().replace(b"name: warehouse-4", b"name: 2026-02-30"),
                        ["bad_world.yaml", "cannot read this value"]),
    "duplicate key": (WORLD.read_bytes() + b"name: again\n", ["bad_world.yaml", "duplicate key 'name'"]),
}


@pytest.mark.parametrize("case", sorted(WORLDS))
def test_bad_world_file_fails_the_step_with_a_located_error(ws, capsys, case):
    content, fragments = WORLDS[case]
    (ws / "bad_world.yaml").write_bytes(content)
    before = snapshot(ws)
    code, _, err = cli(capsys, "run", ws / "wf.yaml", "-i", "world=bad_world.yaml", "--no-cache")
    assert code == 2, err
    assert "step 'world'" in err
    for fragment in fragments:
        assert fragment in err, (fragment, err)
    assert snapshot(ws) == before
    run = next((ws / "runs").iterdir())
    assert json.loads((run / "run.json").read_text())["status"] == "failed"  # the record is kept, not 'running'


@pytest.mark.parametrize("kind", SPECIAL_FILES)
def test_world_path_that_is_not_an_ordinary_file(ws, capsys, kind):
    """A world path of /dev/zero read until the kernel killed pipflow at 24 GB, leaving the run
    marked running; now it is a located error and the record says failed."""
    path = _special(ws, kind)
    code, _, err = cli(capsys, "run", ws / "wf.yaml", "-i", f"world={path}", "--no-cache")
    assert code == 2 and "step 'world'" in err and str(path) in err, err
    assert any(c in err for c in ("not a regular file", "not an ordinary file", "more than", "no such file")), err
    run = next((ws / "runs").iterdir())
    assert json.loads((run / "run.json").read_text())["status"] == "failed"


# --- task files (read by the bench and by pipflow.warehouse.world.load_tasks) ---------------------------------
TASK_FILES: dict[str, tuple[bytes, list[str]]] = {
    "not utf-8": (b"world: world.yaml\ntasks:\n  - id: \xff\n", ["tasks.yaml:3", "not UTF-8"]),
    "alias bomb": (b"world: world.yaml\n" + _bomb().encode(), ["tasks.yaml", "alias"]),
    "deep nesting": (b"world: world.yaml\ntasks: " + b"[" * 2000 + b"]" * 2000 + b"\n", ["tasks.yaml:2", "nested deeper"]),
    "a list": (b"- 1\n", ["tasks.yaml", "mapping"]),
    "syntax error": (b"world: world.yaml\ntasks: [\n", ["tasks.yaml:3", "YAML"]),
    "world is /dev/zero": (b"world: /dev/zero\ntasks:\n  - {id: t, command: x, goal: {shelf1: {product1: 1}}}\n",
                           ["/dev/zero", "not a regular file"]),
}


@pytest.mark.parametrize("case", sorted(TASK_FILES))
def test_bad_task_file_is_a_located_error(ws, case):
    from pipflow.errors import UserError
    from pipflow.warehouse.world import load_tasks

    content, fragments = TASK_FILES[case]
    (ws / "tasks.yaml").write_bytes(content)
    with pytest.raises(UserError) as info:
        load_tasks(ws / "tasks.yaml")
    for fragment in fragments:
        assert fragment in str(info.value), (fragment, str(info.value))


@pytest.mark.parametrize("kind", ["folder", "dev-zero", "fifo", "sparse-20MB"])
def test_task_path_that_is_not_an_ordinary_file(ws, kind):
    from pipflow.errors import UserError
    from pipflow.warehouse.world import load_tasks

    path = _special(ws, kind)
    with pytest.raises(UserError, match="not a regular file|more than"):
        load_tasks(path)


# --- the step cache ------------------------------------------------------------------------------------
def _cached_run(capsys, ws: Path) -> tuple[int, str, list[dict], Path]:
    before = set((ws / "runs").iterdir()) if (ws / "runs").exists() else set()
    code, _, err = cli(capsys, "run", ws / "wf.yaml")
    run = newest_run(ws, before)
    events = [json.loads(line) for line in (run / "events.jsonl").read_text().splitlines()]
    return code, err, events, run


def _entry(cache: Path) -> Path:
    entries = [p for shard in cache.iterdir() if shard.is_dir() for p in shard.iterdir() if len(p.name) == 64]
    assert len(entries) == 1
    return entries[0]


def _damage_outputs(entry: Path, content: bytes) -> None:
    (entry / "outputs.json").write_bytes(content)


DAMAGE = {
    "outputs not utf-8": lambda e: _damage_outputs(e, b"\xff\xfe{"),
    "outputs are []": lambda e: _damage_outputs(e, b"[]"),
    "outputs are {}": lambda e: _damage_outputs(e, b"{}"),
    "forged outputs": lambda e: _damage_outputs(e, (e / "outputs.json").read_bytes().replace(b"warehouse-4", b"forged-world")),
    "truncated outputs": lambda e: _damage_outputs(e, (e / "outputs.json").read_bytes()[:40]),
    "manifest removed": lambda e: (e / "manifest.json").unlink(),
    "manifest garbage": lambda e: (e / "manifest.json").write_bytes(b"\x00\x01garbage"),
    "manifest of another entry": lambda e: (e / "manifest.json").write_text(
        (e / "manifest.json").read_text().replace(e.name, "0" * 64)),
    "outputs.json is a folder": lambda e: ((e / "outputs.json").unlink(), (e / "outputs.json").mkdir()),
}


@pytest.mark.parametrize("case", sorted(DAMAGE))
def test_damaged_cache_entry_is_a_miss_and_is_removed(ws, capsys, case):
    code, _, events, _ = _cached_run(capsys, ws)
    assert code == 0
    entry = _entry(ws / "cache")
    DAMAGE[case](entry)
    code, err, events, run = _cached_run(capsys, ws)
    assert code == 0, err
    end = next(e for e in events if e["event"] == "end" and e.get("step") == "world")
    assert end["cached"] is False  # the damaged entry was not used...
    assert any(e["event"] == "warning" and "did not verify" in e["message"] for e in events)
    assert "did not verify" in err  # ...and the user is told
    assert json.loads((run / "outputs.json").read_text()) == {"name": "warehouse-4"}  # ...nor its forged value
    code, _, events, _ = _cached_run(capsys, ws)  # and the rewritten entry verifies again
    assert next(e for e in events if e["event"] == "end" and e.get("step") == "world")["cached"] is True


def test_truncated_or_extra_cache_artifact_is_a_miss(ws, capsys):
    from pipflow.engine.cache import StepCache

    cache = StepCache(ws / "cache")
    art = ws / "art"
    art.mkdir()
    (art / "plan.txt").write_text("move shelf1 shelf2 product1 3\n" * 10)
    cache.put("ab" + "c" * 62, {"plan": "p"}, art)
    entry = ws / "cache" / "ab" / ("ab" + "c" * 62)
    (entry / "artifacts" / "plan.txt").write_text("move shelf1")  # truncated
    assert cache.get("ab" + "c" * 62, ws / "out", ["plan"]) is None and not entry.exists()
    assert not (ws / "out").exists()  # nothing of the damaged entry reached the record
    cache.put("ab" + "c" * 62, {"plan": "p"}, art)
    (entry / "artifacts" / "forged.txt").write_text("x")
    assert cache.get("ab" + "c" * 62, ws / "out", ["plan"]) is None
    cache.put("ab" + "c" * 62, {"plan": "p"}, art)
    assert cache.get("ab" + "c" * 62, ws / "out", ["plan"]) == {"plan": "p"}
    assert (ws / "out" / "plan.txt").read_text() == (art / "plan.txt").read_text()


def test_cache_clear_refuses_a_folder_pipflow_did_not_write(ws, capsys, monkeypatch):
    """`PIPFLOW_CACHE_DIR=D pipflow cache clear` deleted D with the user's thesis in it."""
    thesis = ws / "D" / "thesis"
    thesis.mkdir(parents=True)
    (thesis / "t.tex").write_text("\\chapter{Results}\n")
    monkeypatch.setenv("PIPFLOW_CACHE_DIR", str(ws / "D"))
    code, _, err = cli(capsys, "cache", "clear")
    assert code == 2 and "not a pipflow step cache" in err and "nothing was removed" in err
    code, _, err = cli(capsys, "cache", "clear", "--dir", ws / "D")
    assert code == 2 and str(ws / "D") in err
    (ws / "notes.txt").write_text("n")
    code, _, err = cli(capsys, "cache", "clear", "--dir", ws / "notes.txt")
    assert code == 2
    assert (thesis / "t.tex").read_text() == "\\chapter{Results}\n" and (ws / "notes.txt").exists()


def test_cache_clear_removes_only_pipflows_entries(ws, capsys):
    assert cli(capsys, "run", ws / "wf.yaml")[0] == 0
    cache = ws / "cache"
    (cache / "mine.txt").write_text("a user's file put in the cache folder")
    (cache / "ab").mkdir(exist_ok=True)
    (cache / "ab" / "keep.txt").write_text("not an entry")
    code, out, err = cli(capsys, "cache", "clear")
    assert code == 0 and "removed 1 cache entry" in out and "kept" in err
    assert (cache / "mine.txt").exists() and (cache / "ab" / "keep.txt").exists()
    assert not [p for p in cache.rglob("*") if len(p.name) == 64]


def test_a_cache_written_before_caches_were_marked_is_still_pipflows(ws, capsys):
    assert cli(capsys, "run", ws / "wf.yaml")[0] == 0
    (ws / "cache" / "CACHEDIR.TAG").unlink()  # as an older pipflow left it
    code, _, events, _ = _cached_run(capsys, ws)
    assert code == 0 and next(e for e in events if e["event"] == "end")["cached"] is True
    assert not (ws / "cache" / "CACHEDIR.TAG").exists()  # a hit writes nothing
    code, out, _ = cli(capsys, "cache", "clear")
    assert code == 0 and "removed 1 cache entry" in out and not any((ws / "cache").rglob("*"))


def test_cache_clear_keeps_a_folder_pipflow_did_not_make(ws, capsys, monkeypatch):
    """An empty folder of the user's, named as the cache: used, cleared, but never removed."""
    mine = ws / "my-cache"
    mine.mkdir()
    monkeypatch.setenv("PIPFLOW_CACHE_DIR", str(mine))
    assert cli(capsys, "run", ws / "wf.yaml")[0] == 0
    assert (mine / "CACHEDIR.TAG").exists()
    code, out, _ = cli(capsys, "cache", "clear")
    assert code == 0 and "removed 1 cache entry" in out
    assert mine.is_dir()


def test_cache_that_cannot_be_written_is_a_warning(ws, capsys, monkeypatch):
    for bad in (ws / "afile", Path("/proc/pipflow-cache")):
        (ws / "afile").write_text("x")
        monkeypatch.setenv("PIPFLOW_CACHE_DIR", str(bad))
        code, out, err = cli(capsys, "run", ws / "wf.yaml")
        assert code == 0, err
        assert "warn" in err and "cache" in err and "warehouse-4" in out


def test_runs_dir_that_refuses_writes(ws, capsys, monkeypatch):
    """An unwritable folder (as a user without the rights sees it; the tests may run as root)."""
    real_mkdir = Path.mkdir

    def refuse(self, *args, **kwargs):
        if "refused-runs" in str(self):
            raise PermissionError(13, "Permission denied")
        return real_mkdir(self, *args, **kwargs)

    monkeypatch.setattr(Path, "mkdir", refuse)
    code, _, err = cli(capsys, "run", ws / "good.yaml", "--runs-dir", ws / "refused-runs")
    assert code == 2 and "refused-runs" in err and "Permission denied" in err


def test_cache_folder_with_user_files_gets_no_entries(ws, capsys, monkeypatch):
    user = ws / "mydata"
    user.mkdir()
    (user / "results.csv").write_text("a,b\n")
    monkeypatch.setenv("PIPFLOW_CACHE_DIR", str(user))
    code, _, err = cli(capsys, "run", ws / "wf.yaml")
    assert code == 0 and "holds files pipflow did not write" in err
    assert [p.name for p in user.iterdir()] == ["results.csv"]


def test_no_cache_writes_no_step_cache(ws, capsys):
    code, _, _ = cli(capsys, "run", ws / "wf.yaml", "--no-cache")
    assert code == 0 and not (ws / "cache").exists()


# --- run records -------------------------------------------------------------------------------------
def _runs(ws: Path) -> list[Path]:
    return sorted((ws / "runs").iterdir())


@pytest.mark.parametrize("damage", ["not json", "not utf-8", "a json list", "empty", "a folder"])
def test_one_damaged_run_json_does_not_break_runs_or_show(ws, capsys, damage):
    for _ in range(3):
        assert cli(capsys, "run", ws / "good.yaml", "-q")[0] == 0
    bad = _runs(ws)[1] / "run.json"
    if damage == "a folder":
        bad.unlink()
        bad.mkdir()
    else:
        bad.write_bytes({"not json": b'{"status": "succ', "not utf-8": b"\xff\xfe", "a json list": b"[1, 2]",
                         "empty": b""}[damage])
    code, out, err = cli(capsys, "runs")
    assert code == 0
    assert sum(line.split()[1] == "succeeded" for line in out.splitlines()) == 2
    assert "damaged" in out and _runs(ws)[1].name in out
    code, out, err = cli(capsys, "show", _runs(ws)[1].name)
    assert code == 0 and "warning" in err and "run.json" in err
    assert cli(capsys, "show", _runs(ws)[2].name)[0] == 0
    code, _, err = cli(capsys, "resume", _runs(ws)[1].name)
    assert code == 2 and "run.json" in err


def _interrupted_run(ws: Path) -> Path:
    """A run whose record says it stopped after step `a` (as after a kill)."""
    from pipflow.engine import run_workflow

    (ws / "two.yaml").write_text("pipflow: 1\nname: two\nsteps:\n  - {id: a, uses: core.value, with: {value: 1}}\n"
                                 "  - {id: b, uses: core.value, with: {value: '${a.value + 1}'}}\noutputs:\n  b: ${b.value}\n")
    result = run_workflow(ws / "two.yaml", runs_dir=ws / "runs")
    assert result.ok
    run = result.run_dir
    lines = (run / "events.jsonl").read_text().splitlines()
    keep = [line for line in lines if json.loads(line).get("step") != "b" and json.loads(line)["event"] != "error"]
    (run / "events.jsonl").write_text("\n".join(keep) + "\n")
    info = json.loads((run / "run.json").read_text())
    info["status"] = "interrupted"
    (run / "run.json").write_text(json.dumps(info))
    (run / "outputs.json").unlink()
    return run


@pytest.mark.parametrize("torn", [b'{"time": "2026', b"\xff\xfe\x00garbage", b'["a list"]'])
def test_torn_last_event_line_does_not_break_show_or_resume(ws, capsys, torn):
    run = _interrupted_run(ws)
    with open(run / "events.jsonl", "ab") as fh:
        fh.write(torn)  # no newline: the process was killed mid-line
    code, out, err = cli(capsys, "show", run)
    assert code == 0 and "events.jsonl" in err and "damaged line" in err
    code, out, err = cli(capsys, "resume", run)
    assert code == 0, err
    assert json.loads((run / "outputs.json").read_text()) == {"b": 2}
    # the events written after the torn line are readable (it did not swallow them)
    lines = (run / "events.jsonl").read_bytes().split(b"\n")
    readable = []
    for line in lines:
        try:
            readable.append(json.loads(line))
        except ValueError:
            continue
    assert any(isinstance(e, dict) and e.get("event") == "resume" for e in readable)


@pytest.mark.parametrize("damage", [b"{", b"\xff", b"[1]"])
def test_damaged_step_outputs_are_run_again_on_resume(ws, capsys, damage):
    run = _interrupted_run(ws)
    (run / "steps" / "a" / "outputs.json").write_bytes(damage)
    code, _, err = cli(capsys, "resume", run)
    assert code == 0, err
    assert json.loads((run / "outputs.json").read_text()) == {"b": 2}
    assert json.loads((run / "steps" / "a" / "outputs.json").read_text()) == {"value": 1}


def test_resume_uses_the_saved_workflow_not_the_edited_file(ws, capsys):
    run = _interrupted_run(ws)
    (ws / "two.yaml").write_text((ws / "two.yaml").read_text().replace("a.value + 1", "a.value + 100"))
    assert cli(capsys, "resume", run)[0] == 0
    assert json.loads((run / "outputs.json").read_text()) == {"b": 2}  # the run's own definition of b


def test_resume_works_when_the_workflow_file_is_gone(ws, capsys):
    run = _interrupted_run(ws)
    (ws / "two.yaml").unlink()
    code, _, err = cli(capsys, "resume", run)
    assert code == 0, err
    assert json.loads((run / "outputs.json").read_text()) == {"b": 2}


def test_resume_keeps_relative_paths_of_the_original_folder(ws, capsys):
    """The snapshot lives in the run folder; `world.yaml` must still mean the workflow's world."""
    from pipflow.engine import run_workflow

    (ws / "sub" / "worlds").mkdir(parents=True)
    shutil.copy(ws / "world.yaml", ws / "sub" / "worlds" / "world.yaml")
    (ws / "sub" / "wf.yaml").write_text(WORLD_FLOW.replace("default: world.yaml", "default: ''")
                                        .replace('"${inputs.world}"', "worlds/world.yaml"))
    result = run_workflow(ws / "sub" / "wf.yaml", runs_dir=ws / "runs")
    assert result.ok, result.error
    run = result.run_dir
    (run / "outputs.json").unlink()
    info = json.loads((run / "run.json").read_text())
    info["status"] = "interrupted"
    (run / "run.json").write_text(json.dumps(info))
    (run / "events.jsonl").write_text("")
    shutil.rmtree(run / "steps")
    code, _, err = cli(capsys, "resume", run, "--no-cache")
    assert code == 0, err
    assert json.loads((run / "outputs.json").read_text()) == {"name": "warehouse-4"}


@pytest.mark.parametrize("damage", ["snapshot gone", "snapshot not utf-8", "inputs.json damaged"])
def test_resume_of_a_damaged_record_is_a_user_error(ws, capsys, damage):
    run = _interrupted_run(ws)
    if damage == "snapshot gone":
        (run / "workflow.yaml").unlink()
    elif damage == "snapshot not utf-8":
        (run / "workflow.yaml").write_bytes(b"\xff\xfe")
    else:
        (run / "inputs.json").write_text("{")
    code, _, err = cli(capsys, "resume", run)
    assert code == 2 and str(run) in err


def test_resume_of_unknown_or_finished_runs(ws, capsys):
    assert cli(capsys, "run", ws / "good.yaml", "-q")[0] == 0
    code, _, err = cli(capsys, "resume", "nosuchrun")
    assert code == 2 and "no run 'nosuchrun'" in err
    code, _, err = cli(capsys, "resume", _runs(ws)[0])
    assert code == 2 and "already succeeded" in err
    code, _, err = cli(capsys, "show", "nosuchrun")
    assert code == 2 and "no run" in err
    code, _, err = cli(capsys, "runs", "--limit", "0")
    assert code == 2 and "--limit" in err


GATE = threading.Event()
ENTERED = threading.Event()


@step("test.gate", inputs={"tag": Input("string")}, outputs={"tag": "string"})
def gate(ctx, tag):
    ENTERED.set()
    assert GATE.wait(60), "the test never opened the gate"
    return {"tag": tag}


def test_a_running_run_cannot_be_resumed_twice(ws, monkeypatch):
    """Resuming a run that is still running ran its steps twice; the run directory is locked."""
    from pipflow.engine import resume_run, run_workflow
    from pipflow.engine.registry import Registry, default_registry
    from pipflow.errors import UserError

    registry = Registry()
    for s in default_registry():
        registry.add(s, "pipflow")
    registry.add(gate, "test")
    (ws / "gate.yaml").write_text("pipflow: 1\nname: gated\nsteps:\n  - {id: g, uses: test.gate, with: {tag: x}}\n")
    GATE.clear()
    ENTERED.clear()
    box = {}
    thread = threading.Thread(target=lambda: box.update(result=run_workflow(ws / "gate.yaml", runs_dir=ws / "runs",
                                                                            registry=registry)))
    thread.start()
    try:
        assert ENTERED.wait(60)
        run = _runs(ws)[0]
        with pytest.raises(UserError, match="another pipflow process .* is writing this run"):
            resume_run(run, registry=registry)
    finally:
        GATE.set()
        thread.join(60)
    assert box["result"].ok
    info = json.loads((run / "run.json").read_text())
    assert info["status"] == "succeeded"


def test_every_record_file_has_one_mode(ws, capsys):
    assert cli(capsys, "run", ws / "wf.yaml")[0] == 0
    run = _runs(ws)[0]
    modes = {stat.S_IMODE(p.stat().st_mode) for p in run.rglob("*") if p.is_file()}
    assert len(modes) == 1, modes


SECRET = "sk-test-9f8e7d6c5b4a39281706"


def test_secrets_never_reach_a_record_or_the_terminal(ws, capsys, monkeypatch):
    """A key pasted into an input by mistake is redacted everywhere pipflow writes; a workflow
    cannot read one at all (issue 21: ``${env.OPENAI_API_KEY}`` went into a request body)."""
    monkeypatch.setenv("OPENAI_API_KEY", SECRET)
    (ws / "env.yaml").write_text(
        "pipflow: 1\nname: env\nenv: [OPENAI_API_KEY, HOME]\n"
        "inputs:\n  key: {type: string, default: '${env.OPENAI_API_KEY}'}\n"
        "steps:\n  - {id: a, uses: core.value, with: {value: 'key=${env.OPENAI_API_KEY}'}}\n"
        "outputs:\n  k: ${a.value}\n")
    code, out, err = cli(capsys, "run", ws / "env.yaml")
    assert code == 2 and "env.yaml:5" in err and "env.yaml:7" in err and "holds a key" in err
    assert SECRET not in out + err and not (ws / "runs").exists()
    (ws / "paste.yaml").write_text(
        "pipflow: 1\nname: paste\ninputs:\n  key: {type: string, default: none}\n"
        "steps:\n  - {id: a, uses: core.value, with: {value: 'key=${inputs.key}'}}\n"
        "  - {id: b, uses: core.log, with: {message: '${inputs.key}'}}\n"
        "  - {id: c, uses: core.fail, with: {message: 'bad key ${inputs.key}', condition: true}}\n"
        "outputs:\n  k: ${a.value}\n")
    code, out, err = cli(capsys, "run", ws / "paste.yaml", "-i", f"key={SECRET}", "-v", traceback_ok=True)
    assert code == 1
    assert SECRET not in out + err and "[redacted OPENAI_API_KEY]" in err
    run = _runs(ws)[0]
    for path in run.rglob("*"):
        if path.is_file():
            assert SECRET.encode() not in path.read_bytes(), path
    assert "[redacted OPENAI_API_KEY]" in (run / "inputs.json").read_text()
    code, _, err = cli(capsys, "resume", run)  # the record never kept the key: a new run is needed
    assert code == 2 and "held a secret" in err and SECRET not in err


def test_dry_run_shows_no_secret(ws, capsys, monkeypatch):
    monkeypatch.setenv("HF_TOKEN", SECRET)
    (ws / "env.yaml").write_text("pipflow: 1\nname: env\n"
                                 "inputs:\n  token: {type: string, default: none}\nsteps: []\n")
    code, out, err = cli(capsys, "run", ws / "env.yaml", "--dry-run", "-i", f"token={SECRET}")
    assert code == 0 and SECRET not in out + err and "[redacted HF_TOKEN]" in out


def test_undeclared_environment_is_invisible_at_run_time(ws, capsys, monkeypatch):
    monkeypatch.setenv("PIPFLOW_TEST_VISIBLE", "yes")
    monkeypatch.setenv("PIPFLOW_TEST_HIDDEN", "no")
    (ws / "env.yaml").write_text("pipflow: 1\nname: env\nenv: [PIPFLOW_TEST_VISIBLE]\nsteps:\n"
                                 "  - {id: a, uses: core.value, with: {value: \"${env.PIPFLOW_TEST_VISIBLE}\"}}\n"
                                 "outputs:\n  v: ${a.value}\n  n: ${env | length}\n")
    code, out, err = cli(capsys, "run", ws / "env.yaml")
    assert code == 2 and "must name one variable" in err  # ${env} as a whole is refused by validation
    (ws / "env.yaml").write_text((ws / "env.yaml").read_text().replace("  n: ${env | length}\n", ""))
    code, out, err = cli(capsys, "run", ws / "env.yaml")
    assert code == 0 and 'v: "yes"' in out


def test_builtin_workflows_declare_the_environment_they_read(capsys):
    from pipflow.resources import data_dir

    for wf in sorted(data_dir("workflows").glob("*.yaml")):
        code, out, err = cli(capsys, "validate", wf)
        assert code == 0, (wf, err)


# --- plugins ------------------------------------------------------------------------------------------
@pytest.fixture
def broken_plugin(tmp_path, monkeypatch):
    """An installed (dist-info) step plugin whose module raises on import."""
    site = tmp_path / "site"
    (site / "pipflow_broken_plugin").mkdir(parents=True)
    (site / "pipflow_broken_plugin" / "__init__.py").write_text("raise ImportError('needs libfoo 2.0')\n")
    info = site / "pipflow_broken_plugin-0.1.dist-info"
    info.mkdir()
    (info / "METADATA").write_text("Metadata-Version: 2.1\nName: pipflow-broken-plugin\nVersion: 0.1\n")
    (info / "entry_points.txt").write_text("[pipflow.steps]\nbroken = pipflow_broken_plugin\n")
    monkeypatch.syspath_prepend(str(site))
    import importlib

    importlib.invalidate_caches()
    monkeypatch.setattr(registry_module, "_default", None)
    import pipflow.engine.cli as cli_module

    monkeypatch.setattr(cli_module, "_warned_plugins", False)
    yield
    monkeypatch.setattr(registry_module, "_default", None)


def test_a_broken_plugin_breaks_only_workflows_that_need_it(ws, capsys, broken_plugin):
    code, out, err = cli(capsys, "steps")
    assert code == 0 and "core.value" in out
    assert "broken plugins" in out and "pipflow-broken-plugin" in out and "needs libfoo 2.0" in out
    assert "warning: step plugin" in err
    code, out, err = cli(capsys, "run", ws / "good.yaml")
    assert code == 0, err
    (ws / "uses.yaml").write_text("pipflow: 1\nname: uses\nsteps:\n  - {id: a, uses: broken.step, with: {x: 1}}\n")
    code, _, err = cli(capsys, "validate", ws / "uses.yaml")
    assert code == 2 and "uses.yaml:4" in err and "unknown step 'broken.step'" in err and "needs libfoo 2.0" in err


@pytest.mark.parametrize("kind", ["dev-zero", "fifo"])
def test_path_argument_naming_a_device_or_pipe_is_refused_before_the_step_reads_it(ws, capsys, kind):
    """Any path-typed step argument (here the built-in warehouse workflow's PDDL domain)."""
    path = _special(ws, kind)
    code, _, err = cli(capsys, "run", "warehouse", "-i", f"domain={path}", "--no-cache", "-q")
    assert code == 2, err
    assert "argument 'domain'" in err and str(path) in err and "not an ordinary file" in err


# --- the real command, in its own process: no hang, no traceback, exit 2 ---------------------------
@pytest.mark.parametrize("case", ["alias bomb", "dev-zero world", "binary workflow"])
def test_the_pipflow_command_itself(ws, case):
    import subprocess
    import sys

    if case == "alias bomb":
        (ws / "bomb.yaml").write_text(WORKFLOWS["alias bomb"][0])
        argv = ["validate", "bomb.yaml"]
    elif case == "dev-zero world":
        argv = ["run", "wf.yaml", "-i", "world=/dev/zero", "--no-cache"]
    else:
        (ws / "bin.yaml").write_bytes(bytes(range(256)))
        argv = ["run", "bin.yaml"]
    proc = subprocess.run([sys.executable, "-m", "pipflow.engine.cli", *argv], cwd=ws, capture_output=True,
                          text=True, timeout=120)
    assert proc.returncode == 2, proc.stderr
    assert "Traceback" not in proc.stdout + proc.stderr
    assert proc.stderr.strip()


def test_bad_yaml_in_a_path_or_content_input_names_the_file_and_line_and_keeps_the_record(tmp_path, capsys):
    """A step input given as "a path or its content" (the action metadata here) read from a file
    with broken YAML: exit 2, the step, the file and its line; the run record says failed."""
    bad = tmp_path / "actions.yaml"
    bad.write_text("skills: [carry\n", encoding="utf-8")
    code, _, err = cli(capsys, "run", str(REPO / "workflows" / "warehouse.yaml"), "-i", f"actions={bad}",
                       "--no-cache", "--runs-dir", str(tmp_path / "runs"))
    assert code == 2, err
    assert "step 'graph'" in err and f"{bad}:2:" in err and "YAML" in err and "Traceback" not in err
    run = next((tmp_path / "runs").iterdir())
    assert json.loads((run / "run.json").read_text())["status"] == "failed"

"""Fuzzing the YAML loaders (workflow, world, task files) with random and mutated inputs: every
input ends in data or in a located user error, never a traceback, never a hang, and memory stays
bounded (an alias bomb or a deep nesting among the mutations must not expand)."""
from __future__ import annotations

import resource
from pathlib import Path

import pytest
import yaml
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from pipflow.engine.source import parse_yaml
from pipflow.engine.validate import check_workflow
from pipflow.errors import SourceFileError, UserError, WorldError
from pipflow.warehouse.world import load_tasks, world_from_text
from pipflow.yamlsource import decode_text

REPO = Path(__file__).resolve().parents[1]
SEEDS = {
    "workflow": (REPO / "workflows" / "warehouse.yaml").read_bytes(),
    "world": (REPO / "benchmarks" / "warehouse" / "world.yaml").read_bytes(),
    "tasks": (REPO / "benchmarks" / "warehouse" / "tasks.yaml").read_bytes(),
}
YAML_BITS = [b"&a ", b"*a", b"[", b"]", b"{", b"}", b": ", b"- ", b"!!", b"!!python/object:os.system ", b"|", b">",
             b"'", b'"', b"#", b"%", b"@", b"`", b"\n", b"\t", b"  ", b"? ", b"<<: *a\n", b"\x00", b"\xff", b"\xc3",
             b"${", b"}", b"${ 'a' * 10**10 }", b"2026-13-45", b"0x", b"1e999", b"---\n", b"...\n", b"~",
             b"a0: &a0 [x,x,x,x,x,x,x,x,x]\na1: &a1 [*a0,*a0,*a0,*a0,*a0,*a0,*a0,*a0,*a0]\n"
             b"a2: &a2 [*a1,*a1,*a1,*a1,*a1,*a1,*a1,*a1,*a1]\na3: &a3 [*a2,*a2,*a2,*a2,*a2,*a2,*a2,*a2,*a2]\n"
             b"a4: &a4 [*a3,*a3,*a3,*a3,*a3,*a3,*a3,*a3,*a3]\na5: &a5 [*a4,*a4,*a4,*a4,*a4,*a4,*a4,*a4,*a4]\n"
             b"a6: &a6 [*a5,*a5,*a5,*a5,*a5,*a5,*a5,*a5,*a5]\na7: [*a6,*a6,*a6,*a6,*a6,*a6,*a6,*a6,*a6]\n",
             b"[" * 300, b"{a: " * 300]


@st.composite
def mutated(draw, seed: bytes) -> bytes:
    """A seed file after a few random edits: cut, duplicate, insert YAML syntax or bad bytes."""
    data = bytearray(seed)
    for _ in range(draw(st.integers(1, 6))):
        at = draw(st.integers(0, len(data)))
        kind = draw(st.sampled_from(["cut", "dup", "insert", "bits", "flip"]))
        if kind == "cut":
            data[at:at + draw(st.integers(1, 200))] = b""
        elif kind == "dup":
            data[at:at] = data[at:at + draw(st.integers(1, 400))]
        elif kind == "insert":
            data[at:at] = draw(st.binary(max_size=20))
        elif kind == "bits":
            data[at:at] = draw(st.sampled_from(YAML_BITS))
        elif data:
            i = min(at, len(data) - 1)
            data[i] = draw(st.integers(0, 255))
    return bytes(data)


FUZZ = settings(max_examples=120, deadline=5000, derandomize=True,
                suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large, HealthCheck.function_scoped_fixture])


def _text(data: bytes) -> str | None:
    try:
        return decode_text(data, "fuzz.yaml")
    except SourceFileError:
        return None  # not UTF-8: a located error, checked in the file-level tests


@pytest.fixture(scope="module", autouse=True)
def bounded_memory():
    """No example may make the process grow by more than 400 MB (an expanded bomb would be GBs)."""
    before = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
    yield
    grown_mb = (resource.getrusage(resource.RUSAGE_SELF).ru_maxrss - before) / 1024
    assert grown_mb < 400, f"fuzzing grew the process by {grown_mb:.0f} MB"


@FUZZ
@given(st.one_of(st.text(max_size=400), st.binary(max_size=400).map(lambda b: b.decode("latin-1")),
                 mutated(SEEDS["workflow"]).map(lambda b: b.decode("utf-8", "replace"))))
def test_workflow_text_parses_or_is_a_located_error(text):
    try:
        parse_yaml(text, "fuzz.yaml")
    except SourceFileError as err:
        assert err.diagnostics and all(d.location and d.location.file == "fuzz.yaml" for d in err.diagnostics)


@FUZZ
@given(mutated(SEEDS["workflow"]))
def test_workflow_file_validates_or_lists_located_problems(tmp_path_factory, data):
    path = tmp_path_factory.mktemp("wf") / "fuzz.yaml"
    path.write_bytes(data)
    workflow, diagnostics = check_workflow(path)  # never raises: every problem is a diagnostic
    assert workflow is not None or diagnostics
    for d in diagnostics:
        assert d.location is not None and d.message


@FUZZ
@given(st.one_of(mutated(SEEDS["world"]), st.binary(max_size=300)))
def test_world_text_loads_or_is_a_world_error(data):
    text = _text(data)
    if text is None:
        return
    try:
        world_from_text(text, "fuzz.yaml")
    except WorldError as err:
        assert err.diagnostics and str(err)


@FUZZ
@given(mutated(SEEDS["tasks"]))
def test_task_file_loads_or_is_a_user_error(tmp_path_factory, data):
    folder = tmp_path_factory.mktemp("tasks")
    (folder / "world.yaml").write_bytes(SEEDS["world"])
    (folder / "tasks.yaml").write_bytes(data)
    try:
        load_tasks(folder / "tasks.yaml")
    except UserError as err:
        assert str(err)


# --- structure: values of every wrong type at every place of real workflows ---------------------
WORKFLOW_SEEDS = [REPO / "workflows" / "warehouse.yaml", REPO / "tests" / "fixtures" / "workflows" / "loop_demo.yaml",
                  REPO / "tests" / "fixtures" / "workflows" / "extends_child.yaml"]
ODD_VALUES = [None, 0, -1, 1.5, True, "", "${", "${a.}", "${env}", "${nosuch.x}", "${previous.x}", "${iteration}",
              [], [1, "a"], {}, {"uses": 5}, {"id": None}, [{"id": "q"}], {"loop": {}}, {"max": "x"}, ["x"],
              {"id": "z", "loop": {"max": 2, "until": True, "steps": [{"id": "w", "uses": "core.value"}]}}]


def _places(value, prefix=()):
    yield prefix
    if isinstance(value, dict):
        for k, v in value.items():
            yield from _places(v, prefix + (k,))
    elif isinstance(value, list):
        for i, v in enumerate(value):
            yield from _places(v, prefix + (i,))


@FUZZ
@given(st.sampled_from(WORKFLOW_SEEDS), st.lists(st.tuples(st.integers(0, 10**6), st.sampled_from(ODD_VALUES)),
                                                 min_size=1, max_size=3))
def test_workflow_with_values_of_the_wrong_type_validates_or_lists_problems(tmp_path_factory, seed, edits):
    import copy

    import yaml

    data = yaml.safe_load(seed.read_text())
    for where, value in edits:
        places = list(_places(data))[1:]
        place = places[where % len(places)]
        node = data
        for key in place[:-1]:
            node = node[key]
        node[place[-1]] = copy.deepcopy(value)
    folder = tmp_path_factory.mktemp("structure")
    for base in seed.parent.glob("*.yaml"):  # bases an `extends` names
        (folder / base.name).write_bytes(base.read_bytes())
    path = folder / "mutated.yaml"
    path.write_text(yaml.safe_dump(data))
    workflow, diagnostics = check_workflow(path)  # never raises
    assert workflow is not None or diagnostics


# --- inputs files, through the CLI ----------------------------------------------------------------
INPUTS_SEED = b"command: shelf4 stores a dozen product3\nrounds: 4\nseed: 7\ngrounded: false\nspeed: 1.5\n"


JSONISH = st.recursive(st.none() | st.booleans() | st.integers() | st.floats() | st.text(max_size=20),
                       lambda inner: st.lists(inner, max_size=4) | st.dictionaries(st.text(max_size=8), inner, max_size=4),
                       max_leaves=12)
INPUT_KEYS = st.sampled_from(["command", "rounds", "seed", "grounded", "speed", "world", "planner"]) | st.text(max_size=8) \
    | st.integers() | st.none()
INPUT_DOCS = st.dictionaries(INPUT_KEYS, JSONISH, max_size=4).map(lambda d: yaml.safe_dump(d).encode())


@FUZZ
@given(st.one_of(mutated(INPUTS_SEED), st.binary(max_size=200), INPUT_DOCS))
def test_inputs_file_is_used_or_refused_with_exit_2(tmp_path_factory, capsys, data):
    from pipflow.engine.cli import main

    folder = tmp_path_factory.mktemp("inputs")
    (folder / "inputs.yaml").write_bytes(data)
    code = main(["run", "warehouse", "--inputs", str(folder / "inputs.yaml"), "--dry-run"])
    out, err = capsys.readouterr()
    assert code in (0, 2) and "Traceback" not in out + err
    if code == 2:
        assert err.strip()

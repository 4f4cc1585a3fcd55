"""World and task files: normalization and located validation errors."""
from __future__ import annotations

from pathlib import Path

import pytest

from pipflow.errors import TaskFileError, WorldError
from pipflow.warehouse.world import load_tasks, load_world, world_from_text
from pipflow.yamlsource import load_with_locations

ROOT = Path(__file__).resolve().parents[1]
FIX = Path(__file__).parent / "fixtures" / "worlds"


def test_paper_world_normalized():
    w = load_world(ROOT / "benchmarks/warehouse/world.yaml")
    assert w["name"] == "warehouse-4" and Path(w["path"]).is_absolute()
    assert set(w["stock"]) == {"shelf1", "shelf2", "shelf3", "shelf4"}
    assert w["stock"]["shelf4"] == {"product1": 15, "product3": 2, "product4": 6}
    assert w["shelves"]["shelf1"]["access"] == [7, 12]
    assert w["robots"]["robot11"] == {"start": [28, 18], "skills": {"carry": 3}, "kind": None, "tags": []}


def test_paper_tasks_load():
    t = load_tasks(ROOT / "benchmarks/warehouse/tasks.yaml")
    assert [x["id"] for x in t["tasks"]] == [f"wh-{i:02d}" for i in range(1, 11)]
    assert t["tasks"][2]["constraints"] == [{"only": ["robot1"], "to": "shelf1"}]
    assert all(x["feasible"] for x in t["tasks"])


def _lines(err: WorldError) -> dict[int, str]:
    out: dict[int, str] = {}
    for d in err.diagnostics:
        out[d.location.line] = out.get(d.location.line, "") + d.message + "\n"
    return out


def test_every_world_problem_is_located():
    with pytest.raises(WorldError) as info:
        load_world(FIX / "bad.yaml")
    by_line = _lines(info.value)
    assert "capacity" in by_line[6] and "capcity" in str(info.value)          # schema: unknown key, missing key
    assert "did you mean 'capacity'" in str(info.value)
    assert "inside the footprint of shelf 'shelf2'" in by_line[5]             # access point in a footprint
    assert "unknown product 'pear'" in by_line[10]
    assert "holds 6 units but its capacity is 5" in by_line[11]
    assert "unknown shelf 'shelf9'" in by_line[12]
    assert "negative count -1" in by_line[13]
    assert "inside the footprint of shelf 'shelf1'" in by_line[15]            # robot start in a shelf
    assert "off the floor" in by_line[16]
    assert len(info.value.diagnostics) == 10                                  # all at once
    cols = {d.location.line: d.location.column for d in info.value.diagnostics if d.location.line in (12, 13)}
    assert cols[12] == 3 and cols[13] == 19


def test_yaml_syntax_error_located():
    with pytest.raises(WorldError) as info:
        world_from_text("floor: {width: 3\nshelves: [\n", "w.yaml")
    d = info.value.diagnostics[0]
    assert d.location.file == "w.yaml" and d.location.line >= 2 and "YAML syntax error" in d.message


def test_locate_paths_and_duplicates():
    data, locate = load_with_locations("a:\n  b: [1, 2]\n  c: 3\n  c: 4\n", "x.yaml")
    assert data == {"a": {"b": [1, 2], "c": 4}}
    assert (locate(("a", "b", 1)).line, locate(("a", "b", 1)).column) == (2, 10)
    assert locate(("a", "c"), key=True).line == 3
    assert locate(("a", "missing")).line == 2  # deepest existing node
    assert [p for p, _ in locate.duplicates] == [("a", "c")]


def test_task_names_checked(tmp_path):
    (tmp_path / "tasks.yaml").write_text(
        f"world: {ROOT / 'benchmarks/warehouse/world.yaml'}\n"
        "tasks:\n"
        "  - id: t1\n"
        "    command: move\n"
        "    goal: {shelve4: {product1: 3}}\n"
        "    constraints:\n"
        "      - {never: [robot99], product: prodcut1}\n")
    with pytest.raises(TaskFileError) as info:  # a WorldError too: callers catch both alike
        load_tasks(tmp_path / "tasks.yaml")
    assert isinstance(info.value, WorldError) and "invalid task file" in str(info.value)
    by_line = _lines(info.value)
    assert "unknown shelf 'shelve4'" in by_line[5] and "shelf4" in by_line[5]
    msgs = str(info.value)
    assert "unknown robot 'robot99'" in msgs and "unknown product 'prodcut1'" in msgs and "'product1'" in msgs


def test_seeded_starts_are_free_and_repeatable():
    from pipflow.warehouse.starts import vary_starts
    from pipflow.floorplan import inside_footprint

    w = load_world(ROOT / "benchmarks/warehouse/world.yaml")
    a, b = vary_starts(w, 3), vary_starts(w, 3)
    assert a["robots"] == b["robots"] and a["robots"] != w["robots"]
    for r in a["robots"].values():
        assert not any(inside_footprint(r["start"], s) for s in w["shelves"].values())
        assert 0 <= r["start"][0] <= 30 and 0 <= r["start"][1] <= 20


# ---------------------------------------------------------------- robots with kinds and tags
TEAM = """\
name: kinds
floor: {width: 20, height: 10}
shelves:
  bay1: {x: 2, y: 2, width: 4, depth: 2, capacity: 10, access: [4, 1]}
products:
  crate: {color: red}
stock:
  bay1: {crate: 4}
robots:
  lifter: {kind: forklift, tags: [day_shift, cold_store], start: [1, 7], skills: {carry: 4}}
  scout: {start: [12, 7], skills: {carry: 1}}
"""


def test_kind_and_tags_normalized():
    w = world_from_text(TEAM, "kinds.yaml")
    assert w["robots"]["lifter"] == {"start": [1, 7], "skills": {"carry": 4}, "kind": "forklift",
                                     "tags": ["day_shift", "cold_store"]}
    assert w["robots"]["scout"]["kind"] is None and w["robots"]["scout"]["tags"] == []


def test_seeded_starts_keep_kind_and_tags():
    from pipflow.warehouse.starts import vary_starts

    w = vary_starts(world_from_text(TEAM, "kinds.yaml"), 1)
    assert w["robots"]["lifter"]["kind"] == "forklift" and w["robots"]["lifter"]["tags"] == ["day_shift", "cold_store"]
    assert w["robots"]["scout"]["tags"] == []


@pytest.mark.parametrize("robot, line_has", [
    ("{kind: 7, start: [1, 7], skills: {}}", "robots/lifter/kind: 7 is not of type 'string'"),
    ("{kind: fork lift, start: [1, 7], skills: {}}", "robots/lifter/kind: 'fork lift' does not match"),
    ("{tags: day_shift, start: [1, 7], skills: {}}", "robots/lifter/tags: 'day_shift' is not of type 'array'"),
    ("{tags: [a, a], start: [1, 7], skills: {}}", "has non-unique elements"),
    ("{tags: [ok, 3], start: [1, 7], skills: {}}", "robots/lifter/tags/1: 3 is not of type 'string'"),
    ("{kinds: forklift, start: [1, 7], skills: {}}", "unknown key 'kinds' in robots/lifter (did you mean 'kind'?)"),
    ("{kind: Bay1, start: [1, 7], skills: {}}", "kind 'Bay1' of robot 'lifter' is also the name of shelf 'bay1'"),
    ("{tags: [night, crate], start: [1, 7], skills: {}}", "tag 'crate' of robot 'lifter' is also the name of product 'crate'"),
    ("{kind: scout, start: [1, 7], skills: {}}", "kind 'scout' of robot 'lifter' is also the name of robot 'scout'"),
    ("{tags: [Carry], start: [1, 7], skills: {}}", "tag 'Carry' of robot 'lifter' is also the name of skill 'carry'"),
])
def test_bad_kind_or_tags_located(robot, line_has):
    text = TEAM.replace("{kind: forklift, tags: [day_shift, cold_store], start: [1, 7], skills: {carry: 4}}", robot)
    with pytest.raises(WorldError) as info:
        world_from_text(text, "kinds.yaml")
    (d,) = info.value.diagnostics
    assert line_has in d.message, d.message
    assert d.location.file == "kinds.yaml" and d.location.line == 10

"""The language generalization set (benchmarks/language/, warehouse part).

Two kinds of checks. The data: every world loads through the project's world loader with its
robots' kinds and tags; every task file validates against schemas/tasks.schema.json and loads
through pipflow.warehouse.world.load_tasks; each gold is consistent with its world's stock and capacities
and follows the conventions of benchmarks/language/README.md where they can be computed (a wrong
gold would reward a misreading). The reading: the offline path misreads none of the commands
(the understood share is printed; the target is >= 95%, the 0-misread part is asserted).
The judge of benchmarks/translator.py is tested on its own too, since the table is only as
honest as its comparison.
"""
from __future__ import annotations

import importlib.util
import re
import sys
from collections import Counter
from functools import lru_cache
from pathlib import Path

import jsonschema
import pytest
import yaml

from pipflow.errors import Refusal, TranslationError
from pipflow.warehouse.world import load_schema, load_tasks, load_world

ROOT = Path(__file__).resolve().parent.parent
LANGUAGE = ROOT / "benchmarks" / "language"
README = LANGUAGE / "README.md"


def _yaml(path: Path) -> dict:
    return yaml.safe_load(path.read_text(encoding="utf-8")) or {}


def _warehouse_files() -> tuple[list[Path], list[Path]]:
    """(world files, task files) of the warehouse part; household files have their own tests."""
    worlds, tasks = [], []
    for path in sorted(LANGUAGE.glob("*.yaml")):
        data = _yaml(path)
        if "tasks" in data:
            world = _yaml(path.parent / data["world"])
            if data.get("domain") != "household" and world.get("domain") != "household":
                tasks.append(path)
        elif data.get("domain") != "household":
            worlds.append(path)
    return worlds, tasks


WORLDS, TASK_FILES = _warehouse_files()


@lru_cache(maxsize=None)
def _translator():
    """benchmarks/translator.py as a module (benchmarks/ is not a package; registered in
    sys.modules first because its dataclass looks its module up there)."""
    spec = importlib.util.spec_from_file_location("benchmarks_translator", ROOT / "benchmarks" / "translator.py")
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module
    spec.loader.exec_module(module)
    return module


def readme_labels() -> set[str]:
    """The construction labels of the README's table (so README and data cannot drift apart)."""
    text = README.read_text(encoding="utf-8").split("## Constructions", 1)[1]
    labels: set[str] = set()
    for line in text.splitlines():
        if line.startswith("| `"):
            labels |= set(re.findall(r"`([a-z-]+)`", line.split("|")[1]))
    return labels


def _tasks(path: Path) -> list[dict]:
    return _yaml(path)["tasks"]


def _world_of(path: Path) -> dict:
    return load_world(path.parent / _yaml(path)["world"])


def _low(v) -> int:
    return v if isinstance(v, int) else v.get("at_least", 0)


def _high(v) -> float:
    return v if isinstance(v, int) else v.get("at_most", float("inf"))


def _stock(world: dict, place: str, item: str) -> int:
    return int(world["stock"].get(place, {}).get(item, 0))


def _total(world: dict, item: str) -> int:
    return sum(int(items.get(item, 0)) for items in world["stock"].values())


# ---------------------------------------------------------------------------------------------
# the data
# ---------------------------------------------------------------------------------------------
def test_the_set_has_the_size_and_variety_the_issue_asks_for():
    commands = sum(len(_tasks(p)) for p in TASK_FILES)
    assert commands >= 150, commands
    assert len(WORLDS) >= 4
    worlds = [load_world(p) for p in WORLDS]
    kinds = [w for w in worlds if any(r.get("kind") for r in w["robots"].values())]
    assert len(kinds) >= 3, "at least the new worlds have robots of several kinds"
    assert all(len({r["kind"] for r in w["robots"].values()}) >= 3 for w in kinds)
    assert any(len(w["robots"]) == 3 for w in worlds), "a 3-robot team"
    ids = [t["id"] for p in TASK_FILES for t in _tasks(p)]
    assert len(ids) == len(set(ids)), [i for i, n in Counter(ids).items() if n > 1]


def test_every_readme_construction_is_used_and_every_used_label_is_documented():
    labels = readme_labels()
    used = Counter(t.get("construction") for p in TASK_FILES for t in _tasks(p))
    assert None not in used, "every task names its construction"
    assert set(used) <= labels, set(used) - labels
    assert labels <= set(used), labels - set(used)


@pytest.mark.parametrize("path", WORLDS, ids=lambda p: p.name)
def test_world_loads_with_its_robots_kinds_and_tags(path):
    world = load_world(path)
    raw = _yaml(path)["robots"]
    for name, robot in raw.items():
        assert world["robots"][name].get("kind") == robot.get("kind"), name
        assert list(world["robots"][name].get("tags") or []) == list(robot.get("tags") or []), name


@pytest.mark.parametrize("path", TASK_FILES, ids=lambda p: p.name)
def test_task_file_validates_against_the_task_schema_and_loads(path):
    jsonschema.Draft202012Validator(load_schema("tasks.schema.json")).validate(_yaml(path))
    loaded = load_tasks(path)  # names in goals and rules exist in the world
    assert len(loaded["tasks"]) == len(_tasks(path))


@pytest.mark.parametrize("path", TASK_FILES, ids=lambda p: p.name)
def test_gold_is_consistent_with_the_world(path):
    world = _world_of(path)
    products, shelves, robots = world["products"], world["shelves"], world["robots"]
    problems: list[str] = []
    for task in _tasks(path):
        tid, goal, label = task["id"], task["goal"], task["construction"]
        for rule in task.get("constraints") or []:
            for r in rule.get("only", []) + rule.get("never", []):
                if r not in robots:
                    problems.append(f"{tid}: unknown robot {r}")
        for place, items in goal.items():
            for item, v in items.items():
                if isinstance(v, dict) and _low(v) > _high(v):
                    problems.append(f"{tid}: bound {v} is empty")
        refuse = task.get("expect") == "refuse"
        infeasible = task.get("feasible", True) is False
        if refuse != (label in ("ambiguous", "unknown-name")) or infeasible != label.startswith("infeasible-"):
            problems.append(f"{tid}: label {label} does not match feasible/expect")
        if refuse and (goal or task.get("constraints") or infeasible):
            problems.append(f"{tid}: a command to refuse has no gold to execute")
        over_capacity = [p for p, items in goal.items()
                         if sum(_low(v) for v in items.values()) > shelves[p]["capacity"]]
        over_stock = [i for i in products
                      if sum(_low(items[i]) for items in goal.values() if i in items) > _total(world, i)]
        if label == "infeasible-capacity" and not over_capacity:
            problems.append(f"{tid}: gold is not over any capacity")
        if label == "infeasible-exceeds" and goal and not over_stock:
            problems.append(f"{tid}: gold does not ask for more than exists")
        if label == "infeasible-negative" and goal:
            problems.append(f"{tid}: a negative count has no goal to write")
        if infeasible or refuse:
            continue
        if over_capacity or over_stock:
            problems.append(f"{tid}: feasible gold over capacity {over_capacity} or stock {over_stock}")
        for item in products:  # a product that every place lists must account for all its units
            if all(item in goal.get(p, {}) for p in shelves):
                if sum(_high(goal[p][item]) for p in shelves) < _total(world, item):
                    problems.append(f"{tid}: every place lists {item} but the units do not fit")
        if label in {"transfer", "swap-all", "swap-some", "distribute", "selector-rest"}:
            for item in {i for items in goal.values() for i in items}:
                places = [p for p in goal if item in goal[p]]
                before = sum(_stock(world, p, item) for p in places)
                after = sum(goal[p][item] for p in places)
                if before != after:
                    problems.append(f"{tid}: {item} not conserved over {places} ({before} -> {after})")
        if label in {"swap-all", "swap-some"}:
            a, b = list(goal)
            for item in set(goal[a]) | set(goal[b]):
                if (goal[a].get(item), goal[b].get(item)) != (_stock(world, b, item), _stock(world, a, item)):
                    problems.append(f"{tid}: {item} is not swapped between {a} and {b}")
            if label == "swap-all":
                held = {i for i in products if _stock(world, a, i) or _stock(world, b, i)}
                if set(goal[a]) != held or set(goal[b]) != held:
                    problems.append(f"{tid}: a full swap lists every product either place holds")
        if label == "empty":
            (place, items), = goal.items()
            if items != {i: 0 for i in products}:
                problems.append(f"{tid}: emptying sets every product of the world to 0")
        if label == "fill":
            (place, items), = goal.items()
            (item, units), = items.items()
            others = sum(_stock(world, place, i) for i in products if i != item)
            if units != shelves[place]["capacity"] - others:
                problems.append(f"{tid}: filling {place} with {item} is capacity minus the others")
        if label == "selector-one-of-each" and not any(set(items) == set(products) for items in goal.values()):
            problems.append(f"{tid}: one of each lists every product of the world")
    assert not problems, "\n".join(problems)


def _replay(world: dict, moves: list) -> dict:
    """Final stock after ``moves``; raises AssertionError on a move the world does not allow."""
    stock = {s: dict(items) for s, items in world["stock"].items()}
    for m in moves:
        assert stock[m.src].get(m.product, 0) >= m.units, f"{m} takes more than {m.src} holds"
        stock[m.src][m.product] = stock[m.src].get(m.product, 0) - m.units
        stock[m.dst][m.product] = stock[m.dst].get(m.product, 0) + m.units
        assert sum(stock[m.dst].values()) <= world["shelves"][m.dst]["capacity"], f"{m} overfills {m.dst}"
    return stock


@pytest.mark.parametrize("path", TASK_FILES, ids=lambda p: p.name)
def test_the_team_planner_reaches_every_feasible_gold_and_no_infeasible_one(path):
    """The gold itself must be right about feasibility: for each feasible goal (bounds included)
    the transport planner's flow plan, replayed move by move within stock and capacities, ends
    in a state that meets the goal; each written infeasible goal is proven unsolvable. A gold
    that no plan reaches would score a correct reading as a failure."""
    from pipflow.warehouse.planner import Unsolvable, flow_plan, instance_from_world

    world = _world_of(path)
    wrong = []
    for task in _tasks(path):
        if task.get("expect") == "refuse" or not task["goal"]:
            continue
        try:
            final = _replay(world, flow_plan(instance_from_world(world, task["goal"])))
        except Unsolvable as exc:
            if task.get("feasible", True):
                wrong.append(f"{task['id']}: feasible gold, but the planner proves it unsolvable: {exc}")
            continue
        if not task.get("feasible", True):
            wrong.append(f"{task['id']}: marked infeasible, but the planner reaches it")
            continue
        for place, items in task["goal"].items():
            for item, v in items.items():
                if not _low(v) <= final[place].get(item, 0) <= _high(v):
                    wrong.append(f"{task['id']}: the plan leaves {final[place].get(item, 0)} {item} on {place}, gold {v}")
    assert not wrong, "\n".join(wrong)


# ---------------------------------------------------------------------------------------------
# the judge of the table
# ---------------------------------------------------------------------------------------------
def test_judge_compares_bounds_exactly_and_rules_as_sets():
    judge = _translator().judge
    task = {"goal": {"a": {"x": {"at_least": 3}}, "b": {"y": 2}},
            "constraints": [{"only": ["r1", "r2"], "product": "x"}, {"never": ["r3"]}]}
    same = {"goal": {"b": {"y": 2}, "a": {"x": {"at_least": 3}}},
            "constraints": [{"never": ["r3"], "words": "not r3"}, {"only": ["r2", "r1"], "product": "x"}]}
    assert judge(task, same, None)[0] == "understood"
    exact_for_bound = {"goal": {"a": {"x": 3}, "b": {"y": 2}}, "constraints": same["constraints"]}
    assert judge(task, exact_for_bound, None)[0] == "misread"
    unscoped = {"goal": same["goal"], "constraints": [{"never": ["r3"]}, {"only": ["r1", "r2"]}]}
    assert judge(task, unscoped, None)[0] == "misread"
    dropped = {"goal": same["goal"], "constraints": [{"never": ["r3"]}]}
    assert judge(task, dropped, None)[0] == "misread"
    split = {"goal": same["goal"], "constraints": [{"only": ["r1", "r2"], "product": "x"}, {"never": ["r3"]},
                                                   {"never": ["r3"]}]}
    assert judge(task, split, None)[0] == "understood"
    never_two = {"goal": {}, "constraints": [{"never": ["r1", "r2"], "to": "a"}]}
    assert judge(never_two, {"goal": {}, "constraints": [{"never": ["r2"], "to": "a"}, {"never": ["r1"], "to": "a"}]},
                 None)[0] == "understood"
    assert judge(never_two, {"goal": {}, "constraints": [{"never": ["r1"], "to": "a"}]}, None)[0] == "misread"
    only_two = {"goal": {}, "constraints": [{"only": ["r1", "r2"]}]}
    assert judge(only_two, {"goal": {}, "constraints": [{"only": ["r1"]}, {"only": ["r2"]}]}, None)[0] == "misread"
    point = {"goal": {"a": {"x": 4}}}
    assert judge(point, {"goal": {"a": {"x": {"at_least": 4, "at_most": 4}}}}, None)[0] == "understood"
    assert judge(point, {"goal": {"a": {"x": True}}}, None)[0] == "misread"


def test_judge_with_the_world_compares_goals_by_the_stocks_they_accept_as_the_bench_does():
    """ "All the fleece to the loft": the loft holding every unit implies 0 elsewhere, listed or
    not; a 0 the gold leaves open (a place that could end up with some) is another meaning."""
    judge = _translator().judge
    world = {"shelves": {"loft": {"capacity": 20}, "shed": {"capacity": 20}, "dock": {"capacity": 20}},
             "products": {"fleece": {}, "bale": {}},
             "stock": {"loft": {"fleece": 1}, "shed": {"fleece": 2, "bale": 3}, "dock": {"bale": 1}}}
    task = {"goal": {"loft": {"fleece": 3}}}
    zeros = {"goal": {"loft": {"fleece": 3}, "shed": {"fleece": 0}, "dock": {"fleece": 0}}}
    assert judge(task, zeros, None, "warehouse", world)[0] == "understood"
    assert judge(task, zeros, None)[0] == "misread"          # as written, without the world
    open_zero = {"goal": {"loft": {"fleece": 3}, "dock": {"bale": 0}}}
    assert judge(task, open_zero, None, "warehouse", world)[0] == "misread"


def test_judge_with_the_world_compares_rules_by_what_they_forbid_as_the_bench_does():
    """ "Only day shift robots please, night shift is off": "only [the day shift]" read with "never
    [the night shift]" beside it forbids what "only [the day shift]" does where every robot is on
    one shift (the bench's verdict, chinika zm1-41); a "never" that forbids one more robot does not."""
    judge = _translator().judge
    world = {"shelves": {"rack": {"capacity": 20}, "ramp": {"capacity": 20}}, "products": {"meal": {}},
             "stock": {"rack": {"meal": 4}},
             "robots": {"d1": {"tags": ["day"]}, "d2": {"tags": ["day"]}, "n1": {"tags": ["night"]}}}
    task = {"goal": {"ramp": {"meal": 2}}, "constraints": [{"only": ["d1", "d2"]}]}
    same = {"goal": {"ramp": {"meal": 2}}, "constraints": [{"only": ["d1", "d2"]}, {"never": ["n1"]}]}
    assert judge(task, same, None, "warehouse", world)[0] == "understood"
    assert judge(task, same, None)[0] == "misread"            # as written, without the world
    more = {"goal": {"ramp": {"meal": 2}}, "constraints": [{"only": ["d1", "d2"]}, {"never": ["d2"]}]}
    assert judge(task, more, None, "warehouse", world)[0] == "misread"
    scoped = {"goal": {"ramp": {"meal": 2}}, "constraints": [{"only": ["d1", "d2"], "to": "ramp"}]}
    assert judge(task, scoped, None, "warehouse", world)[0] == "misread"


def test_judge_verdicts_for_refusals_and_crashes():
    judge = _translator().judge
    clear = {"goal": {"a": {"x": 1}}}
    assert judge(clear, None, TranslationError("'zorp' is not understood"))[0] == "refused"
    assert judge(clear, None, KeyError("x"))[0] == "crashed"
    infeasible = {"goal": {"a": {"x": 99}}, "feasible": False}
    assert judge(infeasible, None, Refusal("over capacity"))[0] == "understood"
    assert judge(infeasible, {"goal": {"a": {"x": 99}}}, None)[0] == "understood"  # the verifier refuses it
    assert judge(infeasible, {"goal": {"a": {"x": 9}}}, None)[0] == "misread"
    ambiguous = {"goal": {}, "expect": "refuse"}
    assert judge(ambiguous, None, TranslationError("'a few' is not a number"))[0] == "understood"
    assert judge(ambiguous, {"goal": {"a": {"x": 3}}}, None)[0] == "misread"


def test_judge_counts_refusals_as_the_bench_does():
    """The table's verdicts are the bench's (README "What the bench's numbers mean"): a refusal is
    understood only for the right reason, and a doable command refused as impossible is misread."""
    judge = _translator().judge
    infeasible = {"goal": {"a": {"x": 99}}, "feasible": False}
    assert judge(infeasible, None, TranslationError("cannot place 'zorp'"))[0] == "refused"
    ambiguous = {"goal": {}, "expect": "refuse"}
    assert judge(ambiguous, None, Refusal("over capacity"))[0] == "refused"
    both = {"goal": {}, "expect": "refuse", "feasible": False}
    assert judge(both, None, Refusal("over capacity"))[0] == "understood"
    assert judge(both, None, TranslationError("two ways"))[0] == "understood"
    clear = {"goal": {"a": {"x": 1}}}
    assert judge(clear, None, Refusal("a would have to hold 40 units"))[0] == "misread"


@pytest.mark.parametrize("gold", [{}, {"in": {}, "state": {}}])
def test_judge_neither_credits_nor_blames_a_reading_of_an_impossible_command_without_a_goal(gold):
    """A household `feasible: false` task needs no goal: a reading of it cannot be compared with
    anything, and only the pipeline (team, planner) can refuse it as impossible. It was counted a
    misreading ("wash my crocs" read right, for a team that cannot wash)."""
    judge = _translator().judge
    task = {"goal": gold, "feasible": False}
    read = {"goal": {"in": {}, "state": {"crocs": ["clean"]}}}
    assert judge(task, read, None, domain="household")[0] == "refused"
    assert judge(task, None, Refusal("no robot of the team can wash"), domain="household")[0] == "understood"


def _one_task_file(tmp_path: Path, task: dict, world: str = "racks.yaml") -> Path:
    (tmp_path / world).write_text((LANGUAGE / world).read_text(encoding="utf-8"), encoding="utf-8")
    path = tmp_path / "tasks.yaml"
    path.write_text(yaml.safe_dump({"world": world, "tasks": [{"id": "t1", "construction": "set", **task}]}),
                    encoding="utf-8")
    return path


def test_table_exits_1_on_a_misread_0_when_all_is_understood_and_2_on_a_bad_file(tmp_path, capsys):
    main = _translator().main
    command = "Rack A should have 10 widgets."
    right = _one_task_file(tmp_path, {"command": command, "goal": {"rack_a": {"widget": 10}}})
    assert main([str(right)]) == 0
    wrong = _one_task_file(tmp_path, {"command": command, "goal": {"rack_a": {"widget": 11}}})
    assert main([str(wrong)]) == 1
    assert "misread" in capsys.readouterr().out
    unknown = _one_task_file(tmp_path, {"command": command, "goal": {"rack_z": {"widget": 10}}})
    assert main([str(unknown)]) == 2
    assert "rack_z" in capsys.readouterr().err


# ---------------------------------------------------------------------------------------------
# the reading
# ---------------------------------------------------------------------------------------------
def test_offline_reading_misreads_no_command_of_the_set():
    table = _translator()
    outcomes = [o for path in TASK_FILES for o in table.run_file(path)]
    print("\n" + table.table(outcomes))
    counts = Counter(o.verdict for o in outcomes)
    print(f"understood {counts['understood']}/{len(outcomes)} = {counts['understood'] / len(outcomes):.1%}")
    wrong = [f"{o.verdict} {o.task_id} [{o.construction}]: {o.detail}"
             for o in outcomes if o.verdict in ("misread", "crashed")]
    assert not wrong, f"{len(wrong)} misread or crashed:\n" + "\n".join(wrong)

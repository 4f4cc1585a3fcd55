"""The offline reader's problem is built with UP's API and shared, not parsed again: the built
object equals UP's parse of the written text (random worlds, exact counts and bounds), and the
debugger of a run then never calls UP's PDDL reader for it."""
from __future__ import annotations

import random

import pytest
from unified_planning.io import PDDLReader

from pipflow.pddl import common
from pipflow.pddl.common import parse, read_domain_text
from pipflow.pddl.debugger import debug_problem
from pipflow.resources import data_file
from pipflow.warehouse.domain import WarehouseDomain
from pipflow.warehouse.generate import scale_instance
from pipflow.warehouse.problem import problem_object, write_problem

DOMAIN = read_domain_text(data_file("domains/warehouse.pddl"))


def _goal(rng: random.Random, final: dict) -> dict:
    """Some cells of a reachable final state, as exact counts or bounds."""
    goal: dict = {}
    for s, items in final.items():
        for p, n in items.items():
            if rng.random() < 0.2:
                kind = rng.choice(["exact", "least", "most", "range"])
                goal.setdefault(s, {})[p] = {"exact": n, "least": {"at_least": max(0, n - 2)},
                                              "most": {"at_most": n + 1},
                                              "range": {"at_least": max(0, n - 1), "at_most": n + 3}}[kind]
    return goal


@pytest.mark.parametrize("seed", range(6))
def test_the_built_problem_equals_ups_parse_of_the_written_text(seed):
    rng = random.Random(seed)
    world, final = scale_instance(shelves=rng.randint(2, 12), products=rng.randint(1, 6), moved=30,
                                  capacity=40, seed=seed)
    world["robots"] = {f"r{i}": {"start": [0, 0], "skills": {"carry": rng.randint(1, 3)}} for i in range(rng.randint(1, 4))}
    goal = _goal(rng, final)
    text = write_problem(world, goal, domain="warehouse")
    built = problem_object(world, goal, DOMAIN)
    parsed = PDDLReader().parse_problem_string(DOMAIN, text)
    assert built == parsed
    # the comparison sees what matters: one initial value changed and they differ
    s, p = next((s, p) for s in world["shelves"] for p in world["products"])
    stock = built.fluent("stock")
    changed = built.clone()
    em = changed.environment.expression_manager
    changed.set_initial_value(stock(changed.object(s), changed.object(p)), em.Int(999))
    assert changed != parsed


def test_the_debugger_uses_the_offline_readers_problem_without_parsing(monkeypatch):
    world, _ = scale_instance(shelves=6, products=3, moved=10, capacity=40, seed=1)
    world["robots"] = {"r0": {"start": [0, 0], "skills": {"carry": 3}}}
    command = f"Empty {list(world['shelves'])[0]}."
    out = WarehouseDomain().read_offline(command, world, DOMAIN)

    def refuse(*args, **kwargs):
        raise AssertionError("UP's PDDL reader was called")

    parse(DOMAIN, None)  # the domain alone is parsed once per process anyway
    monkeypatch.setattr(PDDLReader, "parse_problem_string", refuse)
    report = debug_problem(out["problem"], DOMAIN, world)
    assert report.ok, report.messages
    # a text that is not the writer's (one changed character) is parsed as any other
    with pytest.raises(AssertionError, match="reader was called"):
        parse(DOMAIN, out["problem"].replace("(:goal", "(:goal ", 1))


def test_a_replaced_writer_gets_its_text_parsed(monkeypatch):
    """A writer replaced by a plugin may write another text for the same goal: nothing built
    from the goal may stand for it."""
    world, _ = scale_instance(shelves=4, products=2, moved=6, capacity=40, seed=2)
    world["robots"] = {"r0": {"start": [0, 0], "skills": {"carry": 3}}}
    common._PARSED.clear()
    monkeypatch.setattr(WarehouseDomain, "write_problem",
                        lambda self, w, g, d, name="task": write_problem(w, g, name="other", domain=d))
    out = WarehouseDomain().read_offline(f"Empty {list(world['shelves'])[0]}.", world, DOMAIN)
    assert len(common._PARSED) == 0
    assert parse(DOMAIN, out["problem"]).name == "other"

"""The task-domain registry and protocol (pipflow/taskdomain.py, pipflow/taskdomains.py): the
installed domains are found through the entry-point group, each implements the protocol with the
files it ships, worlds and files say their domain, an unknown domain is the user's error naming
the known ones, and the generic steps reach each domain through it."""
from __future__ import annotations

from pathlib import Path

import pytest

from pipflow import StepContext
from pipflow.errors import InputError
from pipflow.taskdomain import DEFAULT_DOMAIN, TaskDomain, pddl_domain_name
from pipflow.taskdomains import GROUP, declared_domain, domain_named, known_domains, task_domain

REPO = Path(__file__).resolve().parent.parent
HOUSEHOLD_WORLD = REPO / "benchmarks/household/world.yaml"
WAREHOUSE_WORLD = REPO / "benchmarks/warehouse/world.yaml"


def test_pipflow_registers_its_two_domains_as_any_plugin_would():
    from importlib.metadata import entry_points

    names = {ep.name: ep.value for ep in entry_points(group=GROUP)}
    assert names["warehouse"] == "pipflow.warehouse.domain:WarehouseDomain"
    assert names["household"] == "pipflow.household.domain:HouseholdDomain"
    assert {"warehouse", "household"} <= set(known_domains())


@pytest.mark.parametrize("name", ["warehouse", "household"])
def test_each_domain_implements_the_protocol_with_the_files_it_ships(name):
    domain = domain_named(name)
    assert isinstance(domain, TaskDomain) and domain.name == name
    assert domain is domain_named(name)  # built once per process
    assert domain.pddl_domain().is_file() and domain.action_metadata().is_file()
    text = domain.pddl_domain().read_text()
    assert pddl_domain_name(text, "?") == name
    assert domain.rule_fields and domain.default_prompt.endswith("_problem")


def test_a_world_says_its_domain_and_the_default_is_named_once():
    assert task_domain({}).name == DEFAULT_DOMAIN == "warehouse"
    assert task_domain(None).name == DEFAULT_DOMAIN
    assert task_domain({"domain": "household"}).name == "household"


def test_an_unknown_domain_is_the_users_error_naming_the_known_ones(tmp_path):
    with pytest.raises(InputError) as err:
        task_domain({"domain": "orchard"})
    assert "unknown task domain 'orchard'; known: " in str(err.value)
    assert "household" in str(err.value) and "warehouse" in str(err.value)
    world = tmp_path / "w.yaml"
    world.write_text("name: x\n# a comment\ndomain: orchard\n")
    with pytest.raises(InputError) as err:
        declared_domain(world)
    assert str(err.value).startswith(f"{world}:3: unknown task domain 'orchard'")
    assert err.value.exit_code == 2


def test_world_load_dispatches_on_the_files_domain(tmp_path):
    """One generic step loads either domain's world file with that domain's loader."""
    from pipflow.steps.world import load

    ctx = StepContext("world", tmp_path / "artifacts", base_dir=REPO)
    home = load.func(ctx, path=str(HOUSEHOLD_WORLD))["world"]
    assert home["domain"] == "household" and home["places"] and home["objects"]
    shop = load.func(ctx, path=str(WAREHOUSE_WORLD), seed=3)["world"]
    assert "domain" not in shop and shop["shelves"] and shop["stock"]
    assert shop["robots"] != load.func(ctx, path=str(WAREHOUSE_WORLD))["world"]["robots"]  # the seed moved them


def test_rule_names_are_checked_against_the_worlds_domain():
    from pipflow.language.parsing import ParseIssue, validate_constraints

    home = domain_named("household").load_world(HOUSEHOLD_WORLD)
    rule = {"never": [next(iter(home["robots"]))], "object": "apple", "to": "fridge"}
    assert validate_constraints([rule], home) == [rule]
    with pytest.raises(ParseIssue) as err:
        validate_constraints([{**rule, "to": "shelf1"}], home)
    assert "'shelf1' is not a place of this world" in str(err.value)
    with pytest.raises(ParseIssue) as err:  # a warehouse field is not a household one
        validate_constraints([{"only": [next(iter(home["robots"]))], "product": "apple"}], home)
    assert "unknown keys ['product']" in str(err.value)


def test_the_offline_reading_is_the_worlds_domains(tmp_path):
    from pipflow.language.offline import offline

    home = domain_named("household").load_world(HOUSEHOLD_WORLD)
    text = domain_named("household").pddl_domain().read_text()
    out = offline("Put away the fruit.", home, text)
    assert out["goal"]["in"] and "concrete" in out and "(:domain household)" in out["problem"]
    shop = domain_named("warehouse").load_world(WAREHOUSE_WORLD)
    shelf, product = next(iter(shop["shelves"])), next(iter(shop["products"]))
    out = offline(f"{shelf} holds 0 {product}", shop)
    assert out["goal"] == {shelf: {product: 0}} and "(:domain warehouse)" in out["problem"]


def test_the_score_steps_of_both_domains_return_one_shape():
    """A workflow or the bench reads ``success``, ``gcr``, ``tc_avg_moved``... the same way in
    either domain."""
    from pipflow.engine.registry import default_registry

    registry = default_registry()
    shapes = {name: dict(registry.get(name).outputs) for name in ("metrics.score", "household.score")}
    assert shapes["metrics.score"] == shapes["household.score"]


def test_household_scores_travel_over_the_robots_that_moved():
    from pipflow.household.scoring import score_run

    home = domain_named("household").load_world(HOUSEHOLD_WORLD)
    robots = list(home["robots"])
    sim = {"executed": 1, "exe": 1.0, "final_state": {}, "tc_max": 6.0, "tc_avg": 2.0,
           "travel": {robots[0]: 6.0, robots[1]: 0.0, robots[2]: 0.0}}
    score = score_run(home, {"in": {}, "state": {}}, schedule={"subtasks": [{"id": "s1"}]}, simulation=sim)
    assert score["tc_avg"] == 2.0 and score["tc_avg_moved"] == 6.0

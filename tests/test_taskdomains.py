"""The task-domain registry and protocol (pipflow/taskdomain.py, pipflow/taskdomains.py): the
installed domains are found through the entry-point group, each implements the protocol with the
files it ships, worlds and files say their domain, an unknown domain is the user's error naming
the known ones, and the generic steps reach each domain through it."""
from __future__ import annotations

from pathlib import Path

import pytest

from pipflow import StepContext
from pipflow.errors import InputError
from pipflow.taskdomain import DEFAULT_DOMAIN, Capability, TaskDomain, pddl_domain_name
from pipflow.taskdomains import GROUP, declared_domain, domain_named, known_domains, task_domain
from pipflow.values import Score, SimulationCore, refusal_expected

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


def test_a_workflow_written_for_one_domain_refuses_a_world_of_another_naming_its_workflows(tmp_path):
    """The built-in pip-llm is the warehouse's: given a household world it stops at once, saying
    which workflows the household has, and each domain names its own workflow for a method."""
    import pipflow

    result = pipflow.run("pip-llm", world=str(HOUSEHOLD_WORLD), runs_dir=tmp_path / "runs")
    assert result.status == "failed" and result.error_step == "world"
    assert "is a household world, but this workflow is written for warehouse worlds" in result.error
    assert "household, household-checked" in result.error
    home, shop = domain_named("household"), domain_named("warehouse")
    assert [home.workflow_for(n) for n in ("pip-llm", "pip-llm-checked", "warehouse-greedy")] == \
        ["household", "household-checked", "warehouse-greedy"]
    assert [shop.workflow_for(n) for n in ("pip-llm", "pip-llm-checked")] == ["pip-llm", "pip-llm-checked"]


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
    """A workflow or the bench reads ``success``, ``gcr``, ``tc_avg``... the same way in
    either domain."""
    from pipflow.engine.registry import default_registry

    registry = default_registry()
    shapes = {name: dict(registry.get(name).outputs) for name in ("metrics.score", "household.score")}
    assert shapes["metrics.score"] == shapes["household.score"]


def test_household_scores_travel_over_the_robots_that_moved():
    home = domain_named("household").load_world(HOUSEHOLD_WORLD)
    robots = list(home["robots"])
    sim = {"executed": 1, "exe": 1.0, "final_state": {}, "tc_max": 6.0, "tc_avg": 6.0,
           "travel": {robots[0]: 6.0, robots[1]: 0.0, robots[2]: 0.0}}
    score = domain_named("household").score(home, {"in": {}, "state": {}}, schedule={"subtasks": [{"id": "s1"}]},
                                            simulation=sim)
    assert score["tc_avg"] == 6.0 and score["tc_avg_team"] == 2.0  # TC-avg: over the robots that moved


# ------------------------------------------------------------------ simulate and score: one shape
def _run_generic_steps(tmp_path: Path, world: dict, schedule: dict, graph: dict | None, goal: dict) -> tuple[dict, dict]:
    """The generic steps ``simulate`` and ``score`` called as the engine calls them (their
    declared outputs checked like the engine does)."""
    from pipflow.engine.step import check_outputs
    from pipflow.steps.world import score, simulate

    ctx = StepContext("simulate", tmp_path / "simulate", base_dir=REPO)
    sim = simulate.func(ctx, world=world, schedule=schedule, graph=graph, goal=goal)
    check_outputs(simulate, sim, "simulate")
    scored = score.func(StepContext("score", tmp_path / "score", base_dir=REPO), world=world, goal=goal,
                        graph=graph, schedule=schedule, simulation=sim)
    check_outputs(score, scored, "score")
    return sim, scored


SIMULATION_CORE = tuple(SimulationCore.__annotations__)


def test_the_generic_steps_declare_the_protocols_core():
    """Their outputs are declared by their return types: the simulation core, and the score."""
    from pipflow.steps.world import score, simulate

    assert set(SIMULATION_CORE) <= set(simulate.outputs) and set(simulate.outputs) - set(SIMULATION_CORE) == {
        "pictures", "details"}
    assert simulate.outputs["final_state"] == "object" and simulate.outputs["tc_avg_team"] == "number"
    assert simulate.outputs["executed"] == "integer" and simulate.outputs["failures"] == "array"
    assert set(score.outputs) == set(Score.__annotations__) and score.outputs["success"] == "boolean"
    assert (simulate.shape, score.shape) == ("simulation", "score")


def test_warehouse_simulation_through_the_generic_steps(tmp_path):
    """A real pybullet run of task wh-01 (2 product1 shelf1 -> shelf3 by robot5): the core keys,
    the final stock as ``final_state``, the warehouse's own measures under ``details``, the
    trajectories as an artifact; the score reads the generic shape as it reads simulate.pybullet's."""
    import json

    from pipflow.steps.world import simulate as simulate_step
    from pipflow.warehouse.simulation import simulate as pybullet_run
    from sim_fixtures import load_world, wh01

    world = load_world()
    graph, schedule = wh01()
    goal = {"shelf3": {"product1": 7}}
    sim, scored = _run_generic_steps(tmp_path, world, schedule, graph, goal)
    assert set(SIMULATION_CORE) <= set(sim)
    assert sim["final_state"]["shelf3"]["product1"] == 7 and sim["goal_met"] and sim["executed"] == 1
    assert sim["tc_max"] == pytest.approx(28.0) and sim["tc_avg"] == pytest.approx(28.0, abs=1e-3)
    assert set(sim["details"]) == {"peak_load", "stray_units"} and sim["details"]["peak_load"]["shelf3"] == 18
    assert sim["pictures"] == []  # nothing drawn unless asked
    drawn = simulate_step.func(StepContext("s", tmp_path / "drawn", base_dir=REPO), world=world, schedule=schedule,
                               graph=graph, goal=goal, options={"picture": True})
    assert drawn["pictures"] and all((tmp_path / "drawn" / name).is_file() for name in drawn["pictures"])
    assert {k: v for k, v in drawn.items() if k != "pictures"} == {k: v for k, v in sim.items() if k != "pictures"}
    with pytest.raises(InputError, match=r"options 'animaton' are not switches of the 'warehouse' simulation "
                                         r"\(known: picture, animation\)"):
        from pipflow.steps.world import simulate

        simulate.func(StepContext("s", tmp_path / "s2", base_dir=REPO), world=world, schedule=schedule,
                      options={"animaton": True})
    saved = json.loads((tmp_path / "simulate" / "trajectories.json").read_text())
    assert set(saved) == {"trajectories", "events"} and saved["trajectories"]["robot5"]
    assert set(scored) == set(Score.__annotations__) and scored["success"] and scored["violations"] == []
    # the domain step's flat shape (final_stock) scores the same
    flat = pybullet_run(world, schedule, graph, goal)
    assert domain_named("warehouse").score(world, goal, graph=graph, schedule=schedule, simulation=flat) == scored


def test_household_simulation_through_the_generic_steps(tmp_path):
    """A household world with nothing to do: the core keys, the home's state as ``final_state``,
    the goal conditions under ``details``; scored like household.score."""
    world = domain_named("household").load_world(HOUSEHOLD_WORLD)
    assert world["objects"]["apple"]["in"] == "countertop"
    goal = {"in": {"countertop": ["apple"], "fridge": ["tomato"]}}  # one condition holds already
    schedule = {"subtasks": [], "robots": {}, "makespan": 0.0}
    sim, scored = _run_generic_steps(tmp_path, world, schedule, None, goal)
    assert set(SIMULATION_CORE) <= set(sim) and sim["executed"] == 0 and sim["tc_avg"] == 0.0
    assert sim["details"]["conditions"]["met"] == 1 and sim["details"]["conditions"]["total"] == 2
    # nothing executed: the condition that held from the start recalls nothing (README, "GCR")
    assert sim["gcr"] == 0.0 and not sim["goal_met"] and sim["final_state"]
    assert not scored["success"] and scored["gcr"] == 0.0
    assert set(scored) == set(Score.__annotations__)
    home = domain_named("household")
    assert scored == home.score(world, goal, schedule=schedule, simulation=home.simulate(world, schedule, None, goal,
                                                                                       log=lambda m: None))


def test_a_domain_result_without_the_core_is_named():
    from pipflow.values import simulation_outputs

    with pytest.raises(TypeError, match="lacks final_state, tc_avg_team"):
        simulation_outputs({"executed": 1, "failed": 0, "failures": [], "exe": 1.0, "travel": {}, "tc_max": 0.0,
                            "tc_avg": 0.0, "goal_met": True, "gcr": 1.0, "jumps": {}, "makespan": 0.0,
                            "final_stock": {}})


def test_goal_atoms_tells_an_empty_goal_from_a_nested_one():
    """The shared UP helper the household domain and the garden plugin both use: an empty
    ``(and)`` states nothing; nested ``and``s are opened, in the order written."""
    from pipflow.pddl.common import goal_atoms, parse

    domain = domain_named("household")
    world = domain.load_world(HOUSEHOLD_WORLD)
    empty = domain.write_problem(world, {}, "household")
    assert goal_atoms(parse(domain.pddl_domain(), empty)) == []
    nested = empty.replace("(:goal (and", "(:goal (and (and (is-open fridge)) (and (and (is-on floorlamp)))", 1)
    assert [str(g) for g in goal_atoms(parse(domain.pddl_domain(), nested))] == [
        "is-open(fridge)", "is-on(floorlamp)"]


def test_seeded_starts_are_one_rule_for_every_domain():
    """pipflow.floorplan.seeded_starts, which each domain's vary_starts calls with its footprints:
    reproducible by seed and label, every start on the lattice, inside the margin, clear of the
    grown footprints and access points and apart; a floor with no room left is a located error."""
    import math

    from pipflow.errors import WorldError
    from pipflow.floorplan import seeded_starts

    box = {"x": 4.0, "y": 4.0, "width": 2.0, "depth": 2.0, "access": [5.0, 3.5]}
    world = {"path": "tiny.yaml", "floor": {"width": 10, "height": 8},
             "robots": {f"r{i}": {"start": [0.0, 0.0]} for i in range(6)}}
    kw = dict(label="t", clearance=0.5, spacing=1.0, margin=1.0)
    a = seeded_starts(world, 3, [box], **kw)
    assert a == seeded_starts(world, 3, [box], **kw) and world["robots"]["r0"]["start"] == [0.0, 0.0]
    assert a != seeded_starts(world, 4, [box], **kw) and a != seeded_starts(world, 3, [box], **{**kw, "label": "u"})
    assert seeded_starts(world, None, [box], **kw) is world
    starts = [tuple(r["start"]) for r in a["robots"].values()]
    for x, y in starts:
        assert x * 2 == int(x * 2) and y * 2 == int(y * 2) and 1.0 <= x <= 9.0 and 1.0 <= y <= 7.0
        assert not (3.5 <= x <= 6.5 and 3.5 <= y <= 6.5) and math.dist((x, y), box["access"]) >= 1.0
    assert all(math.dist(p, q) >= 1.0 for i, p in enumerate(starts) for q in starts[i + 1:])
    crowded = {**world, "floor": {"width": 3, "height": 3}}
    with pytest.raises(WorldError) as err:
        seeded_starts(crowded, 1, [], **kw)
    assert "tiny.yaml" in str(err.value) and "the floor has room for 4 seeded starts" in str(err.value)
    assert "the world has 6 robots" in str(err.value) and "every seed is alike" in str(err.value)


def test_every_simulate_and_score_step_declares_the_core():
    """One shape per family, for every registered step of the two families (the generic ones and
    the domains' own), found by the family their return type declares: the simulation core
    (the warehouse's older step also keeps the final state as ``final_stock``) and the score."""
    from pipflow.engine.registry import default_registry
    from pipflow.steps.world import score, simulate

    steps = list(default_registry())
    simulates = [s for s in steps if s.shape == "simulation"]
    scores = [s for s in steps if s.shape == "score"]
    assert {"simulate", "simulate.pybullet", "household.simulate"} <= {s.name for s in simulates}
    assert {"score", "metrics.score", "household.score"} <= {s.name for s in scores}
    core = {k: simulate.outputs[k] for k in SIMULATION_CORE}
    for s in simulates:
        assert {k: s.outputs.get(k) for k in core} == core, s.name
    for s in scores:
        assert s.outputs == score.outputs, s.name


# ------------------------------------------------------------------ the protocol: core and capabilities
def test_a_domain_that_leaves_out_part_of_the_core_cannot_be_made():
    """The required core is abstract: a domain without, say, a simulation or the goal's conditions
    is refused when it is instantiated, naming what it lacks (never a None at run time)."""
    class Half(TaskDomain):
        name = "half"

        def load_world(self, path, *, seed=None, **options):
            return {}

    with pytest.raises(TypeError) as err:
        Half()
    for member in ("simulate", "goal_conditions", "read_command", "read_goal", "goal_problems", "reference"):
        assert member in str(err.value)


def test_capabilities_are_declared_by_mixins_and_asked_with_supports():
    warehouse, household = domain_named("warehouse"), domain_named("household")
    assert set(warehouse.capabilities()) == {Capability.GROUNDED_DECODING, Capability.SECOND_OPINION,
                                             Capability.TRANSPORT_PLANNER, Capability.UNDERSTANDING,
                                             Capability.EXECUTION}
    assert set(household.capabilities()) == {Capability.SECOND_OPINION, Capability.UNDERSTANDING,
                                             Capability.BENCH_TABLE, Capability.EXECUTION}
    assert not household.supports(Capability.GROUNDED_DECODING) and not hasattr(household, "planner_params")


def test_a_refusal_is_the_right_answer_in_one_definition():
    assert refusal_expected({"feasible": False}) and refusal_expected({"expect": "refuse"})
    assert not refusal_expected({}) and not refusal_expected({"feasible": True, "expect": None})


@pytest.mark.parametrize("name", ["warehouse", "household"])
def test_an_infeasible_task_that_was_not_refused_keeps_the_simulations_exe(name):
    """One definition of the score in every domain: a run whose right answer was a refusal but
    that executed fails, and its Exe is what the simulation measured (not 0, not 1)."""
    domain = domain_named(name)
    world = domain.load_world(WAREHOUSE_WORLD if name == "warehouse" else HOUSEHOLD_WORLD)
    sim = {"executed": 1, "exe": 0.5, "final_state": domain.initial_state(world), "travel": {}, "failures": [],
           "jumps": {}, "makespan": 3.0}
    schedule = {"subtasks": [{"id": "s1"}, {"id": "s2"}]}
    score = domain.score(world, {}, feasible=False, schedule=schedule, simulation=sim)
    assert not score["success"] and score["exe"] == 0.5 and score["violations"] == ["infeasible command was not refused"]
    refused = domain.score(world, {}, feasible=False, refusal="it cannot be done")
    assert refused["success"] and refused["exe"] == 1.0 and refused["lower_bound"] is None


def test_a_run_under_faults_is_scored_in_the_world_as_it_really_was():
    """The bench scores a run under faults against the world as the run found it (its surprises
    put in by the execution capability's ``as_it_was``), once in the protocol's score_bench_run:
    a unit the records missed is not a broken conservation; the same run judged on the records is."""
    domain = domain_named("warehouse")
    assert domain.supports(Capability.EXECUTION)
    world = domain.load_world(WAREHOUSE_WORLD)
    shelf, items = next((s, i) for s, i in world["stock"].items() if i)
    product, count = next(iter(items.items()))
    real = {s: dict(i) for s, i in world["stock"].items()}
    real[shelf][product] = count + 1
    surprise = {"kind": "surprise", "surprise": {"place": shelf, "product": product, "count": count + 1,
                                                  "records": count, "words": f"one more {product} on {shelf}"}}
    sim = {"final_state": real, "executed": 0, "failed": 0, "failures": [], "exe": 1.0, "travel": {}, "jumps": {},
           "makespan": 0.0}
    task = {"goal": {shelf: {product: count + 1}}}
    outputs = {"schedule": {"subtasks": []}, "simulation": sim}
    as_found = domain.score_bench_run(str(WAREHOUSE_WORLD), task, {**outputs, "faults": [surprise]}, None, None)
    assert as_found["success"], as_found["violations"]
    on_records = domain.score_bench_run(str(WAREHOUSE_WORLD), task, outputs, None, None)
    assert not on_records["success"]
    assert f"{product}: {sum(int(i.get(product, 0)) for i in world['stock'].values())} units before" in \
        " ".join(on_records["violations"])

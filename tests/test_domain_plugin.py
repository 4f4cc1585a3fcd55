"""A third task domain as an installed plugin (issue 14): the garden package of tests/plugins is
pip-installed into a private folder and found by pipflow only through its entry points
(``pipflow.task_domains``; it has no step of its own: pipflow's generic steps, ``simulate``
included, reach it through the protocol). ``pipflow run`` of the workflow it ships and
``pipflow bench`` of its task file run end to end in a fresh process; without the plugin the
domain is unknown. The in-process tests check the package's parts (world checks, the command
reader's refusals, the simulator) through the installed copy."""
from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from fake_openai import FakeOpenAI
from pipflow.errors import Refusal, TranslationError, WorldError
from cli_entry import PIPFLOW

PACKAGE = Path(__file__).resolve().parent / "plugins" / "pipflow_garden"


def pipflow(site: Path, cwd: Path, *args: str, timeout: float = 300, extra_env: dict | None = None
            ) -> subprocess.CompletedProcess:
    cmd = [PIPFLOW]
    env = {**{k: v for k, v in os.environ.items() if k != "PIPFLOW_MODEL"},  # offline unless a test says
           "PYTHONPATH": os.pathsep.join([str(site), os.environ.get("PYTHONPATH", "")]).rstrip(os.pathsep),
           "PIPFLOW_CACHE_DIR": str(cwd / "cache"), **(extra_env or {})}
    return subprocess.run([*cmd, *args], cwd=cwd, env=env, capture_output=True, text=True, timeout=timeout)


def only_run(runs: Path) -> Path:
    (run,) = runs.iterdir()
    return run


@pytest.fixture
def garden(garden_plugin_site, monkeypatch):
    """The installed plugin's modules, imported from the private site folder."""
    monkeypatch.syspath_prepend(str(garden_plugin_site))
    import importlib

    importlib.invalidate_caches()
    from pipflow_garden import language, simulation, world

    data = garden_plugin_site / "pipflow_garden" / "data"
    return {"language": language, "simulation": simulation, "world": world, "data": data,
            "allotment": world.load_world(data / "world.yaml")}


def test_the_plugin_imports_nothing_of_pipflow_but_its_public_face():
    """A plugin author imports ``pipflow.plugin`` and nothing else of pipflow (internals move)."""
    import ast

    seen = set()
    for path in (PACKAGE / "pipflow_garden").glob("*.py"):
        for node in ast.walk(ast.parse(path.read_text(), str(path))):
            names = [a.name for a in node.names] if isinstance(node, ast.Import) else \
                [node.module or ""] if isinstance(node, ast.ImportFrom) else []
            seen |= {(path.name, n) for n in names if n == "pipflow" or n.startswith("pipflow.")}
    assert seen and {n for _, n in seen} == {"pipflow.plugin"}, sorted(seen)


def test_an_infeasible_task_not_refused_keeps_the_simulations_exe_in_the_garden_too(garden):
    """The score is pipflow's one definition: the garden once gave such a run Exe 0.0 where the
    household gave the simulation's."""
    from pipflow_garden.domain import GardenDomain

    domain, world = GardenDomain(), garden["allotment"]
    sim = {"executed": 1, "exe": 0.5, "final_state": domain.initial_state(world), "travel": {}, "failures": [],
           "jumps": {}, "makespan": 3.0}
    score = domain.score(world, {}, feasible=False, schedule={"subtasks": [{"id": "s1"}, {"id": "s2"}]},
                         simulation=sim)
    assert not score["success"] and score["exe"] == 0.5 and score["violations"] == ["infeasible command was not refused"]


def test_plugin_package_declares_no_pipflow_dependency():
    text = (PACKAGE / "pyproject.toml").read_text()
    deps = text.split("dependencies =", 1)[1].split("]", 1)[0]
    assert "pipflow" not in deps, "pip must never fetch the unrelated `pipflow` from PyPI"
    assert '[project.entry-points."pipflow.task_domains"]' in text


# ---------------------------------------------------------------------------------- end to end
def test_workflow_runs_end_to_end_and_meets_the_goal(garden_plugin_site, tmp_path):
    workflow = garden_plugin_site / "pipflow_garden" / "workflows" / "garden.yaml"
    command = "Prune the south bed, then bring two pumpkins from south into the shed; the mule must not harvest."
    proc = pipflow(garden_plugin_site, tmp_path, "run", str(workflow), "-i", f"command={command}", "--runs-dir", "runs")
    assert proc.returncode == 0, proc.stderr
    run = only_run(tmp_path / "runs")
    assert json.loads((run / "run.json").read_text())["status"] == "succeeded"
    out = json.loads((run / "outputs.json").read_text())
    assert out["goal"] == {"clear": ["south"], "stored": {"shed": {"pumpkin": 2}}, "ripe": {"south": {"pumpkin": 0}}}
    assert out["constraints"] == [{"never": ["mule"], "action": "harvest",
                                   "words": "the mule must not harvest"}]
    # the plan: one prune, then two harvests that depend on it
    actions = [(p["action"], p["args"]) for p in out["plan"]]
    assert sorted(actions) == [("harvest", ["pumpkin", "south", "shed"])] * 2 + [("prune", ["south"])]
    ids = {n["id"]: n["action"] for n in out["graph"]["nodes"]}
    prune = next(i for i, a in ids.items() if a == "prune")
    assert {(u, v) for u, v in out["graph"]["edges"]} == {(prune, i) for i, a in ids.items() if a == "harvest"}
    # a pumpkin weighs 2 carry units: a coalition of two 1-unit pickers (the 2-unit mule is ruled out)
    by_action = {a["subtask"]: a["robots"] for a in out["allocation"]["assignments"]}
    for sid, action in ids.items():
        if action == "harvest":
            assert sorted(by_action[sid]) == ["picker1", "picker2"]
    # the garden's simulator executed everything, met the goal and measured travel from the paths
    sim = out["simulation"]  # pipflow's generic step: the simulation core, the garden's own under details
    assert sim["executed"] == 3 and sim["failures"] == [] and sim["goal_met"] is True
    assert sim["details"]["conditions"] == {"met": 3, "total": 3, "unmet": []}
    assert sim["final_state"]["stored"]["shed"]["pumpkin"] == 2 and sim["final_state"]["ripe"]["south"]["pumpkin"] == 0
    assert "south" not in sim["final_state"]["overgrown"]
    assert sim["travel"]["mule"] == 0 and sim["travel"]["picker1"] > 5
    assert out["tc_max"] == pytest.approx(max(sim["travel"].values()))


def test_a_command_it_cannot_place_is_refused_quoting_the_words(garden_plugin_site, tmp_path):
    workflow = garden_plugin_site / "pipflow_garden" / "workflows" / "garden.yaml"
    proc = pipflow(garden_plugin_site, tmp_path, "run", str(workflow), "-i",
                   "command=Water north and fertilise the south bed.", "--runs-dir", "runs")
    assert proc.returncode == 1
    assert "could not place the words 'fertilise the south bed'" in proc.stderr
    assert "Traceback" not in proc.stderr
    run = only_run(tmp_path / "runs")
    assert json.loads((run / "run.json").read_text())["status"] == "failed"
    assert not (run / "steps" / "allocate").exists()  # no robot was given anything to do


def test_an_impossible_command_is_refused_with_the_reason(garden_plugin_site, tmp_path):
    workflow = garden_plugin_site / "pipflow_garden" / "workflows" / "garden.yaml"
    proc = pipflow(garden_plugin_site, tmp_path, "run", str(workflow), "-i",
                   "command=Harvest 6 pumpkins into the crate.", "--runs-dir", "runs")
    assert proc.returncode == 3, proc.stderr
    assert "only 2 units of pumpkin are ripe in the garden (asked for 6)" in proc.stderr
    assert json.loads((only_run(tmp_path / "runs") / "run.json").read_text())["status"] == "refused"


def test_bench_scores_every_task_with_sr(garden_plugin_site, tmp_path):
    tasks = garden_plugin_site / "pipflow_garden" / "data" / "tasks.yaml"
    proc = pipflow(garden_plugin_site, tmp_path, "bench", str(tasks), "--seeds", "1", "--jobs", "1",
                   "--out", "out", "--runs-dir", "runs", "-q", timeout=600)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    results = json.loads((tmp_path / "out" / "results.json").read_text())
    assert results["config"]["domain"] == "garden"
    rows = {t["id"]: t for t in results["tasks"]}
    assert sorted(rows) == [f"g-0{i}" for i in range(1, 8)]
    assert all(rows[t]["runs"] == 1 and rows[t]["sr"] == 1.0 for t in rows), \
        {t: (r["sr"], r.get("error")) for t, r in rows.items()}
    assert all(rows[t]["understood"] == 1.0 and rows[t]["misread"] == 0 for t in rows)
    assert results["summary"]["sr"] == 1.0
    # a right refusal succeeds without moving: it is no 0 m run in the travel figures
    assert rows["g-03"]["tc_max"] > 0 and rows["g-06"]["sr"] == 1.0 and rows["g-06"]["tc_max"] is None


def test_without_the_plugin_the_domain_is_unknown(tmp_path):
    tasks = PACKAGE / "pipflow_garden" / "data" / "tasks.yaml"
    proc = pipflow(tmp_path / "empty", tmp_path, "bench", str(tasks), "--seeds", "1", "--out", "out")
    assert proc.returncode == 2
    # the file and line of its `domain:`, and the known domains
    assert "tasks.yaml:7: unknown task domain 'garden'; known: household, warehouse" in proc.stderr
    assert "Traceback" not in proc.stderr
    proc = pipflow(tmp_path / "empty", tmp_path, "run", str(PACKAGE / "pipflow_garden" / "workflows" / "garden.yaml"),
                   "--runs-dir", "runs")
    assert proc.returncode == 2 and "unknown task domain 'garden'" in proc.stderr, proc.stderr
    assert "Traceback" not in proc.stderr
    world = tmp_path / "world.yaml"
    shutil.copy(PACKAGE / "pipflow_garden" / "data" / "world.yaml", world)
    proc = pipflow(tmp_path / "empty", tmp_path, "run", "warehouse", "-i", f"world={world}", "--runs-dir", "runs")
    assert proc.returncode == 2, proc.stderr
    assert f"{world}:3: unknown task domain 'garden'; known: household, warehouse" in proc.stderr
    assert "Traceback" not in proc.stderr


def test_the_registry_finds_the_domain_through_its_entry_point(garden_plugin_site, tmp_path):
    code = ("from pipflow.taskdomains import domain_named, known_domains, task_domain\n"
            "d = domain_named('garden')\n"
            "w = d.load_world(d.pddl_domain().parent / 'world.yaml')\n"
            "print(known_domains(), type(task_domain(w)).__name__, d.pddl_domain().name, d.action_metadata().name)\n")
    env = {**{k: v for k, v in os.environ.items() if k != "PIPFLOW_MODEL"},  # offline unless a test says
           "PYTHONPATH": str(garden_plugin_site)}
    proc = subprocess.run([sys.executable, "-c", code], cwd=tmp_path, env=env, capture_output=True, text=True, timeout=60)
    assert proc.returncode == 0, proc.stderr
    assert "'garden'" in proc.stdout and "GardenDomain garden.pddl garden.actions.yaml" in proc.stdout
    workflow = garden_plugin_site / "pipflow_garden" / "workflows" / "garden.yaml"
    proc = pipflow(garden_plugin_site, tmp_path, "validate", str(workflow))
    assert proc.returncode == 0 and "garden.yaml: ok" in proc.stdout, proc.stderr
    proc = pipflow(garden_plugin_site, tmp_path, "steps")
    assert proc.returncode == 0 and "pipflow-garden" not in proc.stdout + proc.stderr, proc.stdout  # no step of its own


# ---------------------------------------------------------------------------------- the parts
@pytest.mark.parametrize("command, goal, rules", [
    ("Water the north bed and east, then prune south.", {"watered": ["north", "east"], "clear": ["south"]}, []),
    ("water every bed", {"watered": ["north", "south", "east", "herbs"]}, []),
    ("Harvest 3 tomatoes into the shed", {"stored": {"shed": {"tomato": 4}}}, []),  # the shed holds 1 already
    ("pick at least two beans from east into the crate",
     {"stored": {"crate": {"bean": {"at_least": 2}}}, "ripe": {"east": {"bean": {"at_most": 0}}}}, []),
    ("harvest all the basil from herbs into the crate and weed herbs",
     {"stored": {"crate": {"basil": 4}}, "ripe": {"herbs": {"basil": 0}}, "clear": ["herbs"]}, []),
    ("harvest all the basil from herbs into the crate, then harvest all the basil into the shed",  # the rest
     {"stored": {"crate": {"basil": 4}, "shed": {"basil": 3}}, "ripe": {"herbs": {"basil": 0}}}, []),
    ("keep the rovers away from the herbs bed. water north",
     {"watered": ["north"]}, [{"never": ["sprinkler", "shears"], "bed": "herbs"}]),
    ("only pickers may harvest; bring a pumpkin to the shed",
     {"stored": {"shed": {"pumpkin": 1}}}, [{"only": ["picker1", "picker2"], "action": "harvest"}]),
    ("the wet robots must not harvest pumpkins, water east",
     {"watered": ["east"]}, [{"never": ["sprinkler", "mule"], "action": "harvest", "crop": "pumpkin"}]),
])
def test_the_reader_resolves_commands(garden, command, goal, rules):
    read = garden["language"].read_command(command, garden["allotment"])
    assert read["goal"] == goal
    assert [{k: v for k, v in r.items() if k != "words"} for r in read["constraints"]] == rules


def test_the_reading_is_explained_before_robots_move(garden):
    read = garden["language"].read_command("prune every bed, then harvest two tomatoes from north into the shed",
                                           garden["allotment"])
    assert read["explanation"].splitlines() == [
        "'prune every bed' -> prune north, south, east, herbs (north, east: clear already)",
        "'harvest two tomatoes from north into the shed' -> harvest 2 tomato from north into shed (it holds 1 now)"]


@pytest.mark.parametrize("command, kind, words", [
    ("water north and fertilise south", TranslationError, "'fertilise south'"),
    ("prune north twice", TranslationError, "'prune north twice'"),
    ("water north, fertilise south; prune herbs", TranslationError, "could not place the words 'fertilise south' "),
    ("water and north", TranslationError, "'water and north'"),
    ("water the roses", TranslationError, "'the roses': this garden has no bed 'roses'"),
    ("bring 2 pumkins to the shed", TranslationError, "no crop 'pumkins'; did you mean 'pumpkin'"),
    ("harvest 3 carrots into the shed", TranslationError, "no crop 'carrots'; crops: tomato, basil, bean, pumpkin"),
    ("harvest 3 tomatoes", TranslationError, "say which store it goes to (shed or crate)"),
    ("harvest the basil into the shed", TranslationError, "'harvest the basil into the shed'"),
    ("the mule must not water", TranslationError, "asks for nothing to be done"),
    ("the goats must not water. water north", TranslationError, "no robot or kind of robot 'goats'"),
    ("harvest 5 tomatoes into the shed", Refusal, "only 4 units of tomato are ripe"),
    ("harvest 2 tomatoes from east into the shed", Refusal, "no tomato is ripe in bed east"),
    ("harvest 6 basil into the shed and harvest 2 basil from north into the crate", Refusal,
     "only 1 unit of basil is ripe in bed north after the 6 the command's earlier harvests take"),
    ("harvest all the beans into the crate", Refusal, "store crate has room for 4 more units (asked for 7)"),
])
def test_the_reader_refuses_rather_than_guesses(garden, command, kind, words):
    with pytest.raises(kind) as err:
        garden["language"].read_command(command, garden["allotment"])
    assert words in str(err.value)


def test_a_bad_world_file_lists_every_problem_located(garden, tmp_path):
    bad = tmp_path / "bad.yaml"
    bad.write_text(
        "domain: garden\n"
        "floor: {width: 10, height: 8}\n"
        "crops: {tomato: {weight: 1}}\n"
        "beds:\n"
        "  north: {x: 1, y: 1, width: 3, depth: 2, access: [2, 2], ripe: {tomatoe: 2}}\n"
        "  Big: {x: 5, y: 1, width: 3, depth: 2, access: [6, 0.5]}\n"
        "taps: {tap: {x: 0, y: 6, width: 0.5, depth: 0.5, access: [1, 6]}, "
        "spout: {x: 2, y: 2, width: 0.5, depth: 0.5, access: [2.2, 0.5]}}\n"
        "stores: {shed: {x: 8, y: 6, width: 3, depth: 1, access: [8, 5], room: 1, holds: {tomato: 2}}}\n"
        "robots:\n"
        "  r1: {start: [1, 7], skills: {water: 1, fly: 2}, kind: rover}\n"
        "  r2: {start: [2, 1.5], skills: {cut: 1}}\n")
    with pytest.raises(WorldError) as err:
        garden["world"].load_world(bad)
    text = str(err.value)
    for words in (f"{bad}:5:51: bed north: access point [2, 2] lies inside its own footprint",
                  f"{bad}:5:66: bed north: ripe: unknown crop 'tomatoe' (did you mean 'tomato'?)",
                  f"{bad}:6:3: bed name 'Big' must be lower case",
                  f"{bad}:7:8: tap name 'tap' is a word of the garden's PDDL domain",
                  f"{bad}:8:16: store shed lies outside the floor (10 x 8 m)",
                  f"{bad}:8:81: store shed holds 2 units, more than its room of 1",
                  f"{bad}:10:42: robot r1: unknown skill 'fly'; skills: water, cut, carry",
                  f"{bad}:11:15: robot r2 starts inside bed north",
                  f"{bad}:7:67: tap spout overlaps bed north",
                  f"{bad}:5:51: bed north: access point [2.0, 2.0] lies in tap spout"):
        assert words in text, text


def test_the_simulator_refuses_what_the_garden_cannot_do(garden):
    sim, world = garden["simulation"], garden["allotment"]
    p = world["places"]
    schedule = {"subtasks": [
        {"id": "s1", "action": "harvest", "args": ["pumpkin", "south", "shed"], "robots": ["picker1"], "start": 0, "end": 5},
        {"id": "s2", "action": "prune", "args": ["north"], "robots": ["shears"], "start": 1, "end": 6}],
        "robots": {"picker1": {"legs": [{"subtask": "s1", "from": world["robots"]["picker1"]["start"],
                                         "to": p["south"]["access"], "path": [world["robots"]["picker1"]["start"],
                                                                               p["south"]["access"]]}]},
                   "shears": {"legs": [{"subtask": "s2", "from": [0.5, 0.5], "to": p["north"]["access"],
                                        "path": [[0.5, 0.5], [0.5, 8.4], p["north"]["access"]]}]}},
        "makespan": 6}
    graph = {"nodes": [{"id": "s1", "skills": {"carry": 2.0}, "route": ["south", "shed"]},
                       {"id": "s2", "skills": {"cut": 1.0}, "route": ["north"]}]}
    out = sim.simulate(world, schedule, graph, {"stored": {"shed": {"pumpkin": 1}}}, log=lambda m: None)
    reasons = {f["subtask"]: " | ".join(f["reasons"]) for f in out["failures"]}
    assert "carry 1 < 2" in reasons["s1"] and "picker1 is not at shed" in reasons["s1"]
    assert "picker1 drives through south" in reasons["s1"]  # the straight line crosses the bed
    assert "bed north is not overgrown" in reasons["s2"]
    assert out["jumps"]["shears"][0]["subtask"] == "s2"  # it started at [11, 6], not [0.5, 0.5]
    assert out["executed"] == 0 and out["goal_met"] is False and out["conditions"]["unmet"]
    assert out["final_state"]["ripe"]["south"]["pumpkin"] == 2  # nothing changed
    # the protocol's one shape: pipflow's generic steps simulate and score take the garden's result
    from pipflow.values import Score, SimulationCore, simulation_outputs

    from pipflow_garden.domain import GardenDomain

    generic = simulation_outputs(out)
    assert set(SimulationCore.__annotations__) <= set(generic) and set(generic["details"]) == {"conditions"}
    scored = GardenDomain().score(world, {"stored": {"shed": {"pumpkin": 1}}}, graph=graph, schedule=schedule,
                                  simulation=generic)
    assert set(scored) == set(Score.__annotations__) and not scored["success"]
    assert scored == GardenDomain().score(world, {"stored": {"shed": {"pumpkin": 1}}}, graph=graph,
                                          schedule=schedule, simulation=out)  # the flat form scores the same


def test_a_problem_is_read_back_and_checked_against_the_garden(garden, garden_plugin_site):
    """The debugger's and verifier's hooks: a problem's goal read back in the garden's form (as
    the reader wrote it), an invented initial state named, an unreachable goal refused."""
    from pipflow.pddl.common import parse

    from pipflow_garden.domain import GardenDomain

    domain, world = GardenDomain(), garden["allotment"]
    read = garden["language"].read_command("prune south, then pick at least two beans from east into the crate",
                                           world)
    text = domain.write_problem(world, read["goal"], "garden", name="beans-1")
    assert text.startswith("(define (problem beans-1)\n  (:domain garden)")
    parsed = parse(domain.pddl_domain(), text)
    assert domain.read_problem(parsed, world, []) == {"goal": read["goal"]}
    assert domain.world_mismatches(parsed, text, world) == []
    assert domain.check_goal(parsed, world).refusal is None

    forged = domain.write_problem(world, {"stored": {"shed": {"pumpkin": 9}}}, "garden").replace(
        "(= (ripe north tomato) 4)", "(= (ripe north tomato) 9)")
    parsed = parse(domain.pddl_domain(), forged)
    assert domain.world_mismatches(parsed, forged, world) == [
        "initial state: (ripe north tomato) is 9 in the problem, 4 in the garden"]
    assert "shed cannot hold 9 pumpkin: at most 2 can be there" in domain.check_goal(parsed, world).refusal
    empty = parse(domain.pddl_domain(), domain.example_problem(world, "(define (domain garden))"))
    assert "states no condition" in domain.read_problem(empty, world, [])["errors"][0]


def test_a_models_problem_goes_through_the_refinement_loop(garden, garden_plugin_site, tmp_path):
    """The LLM path of pipflow's generic generator, debugger and verifier serves the garden: a
    model (a scripted OpenAI-compatible server on loopback) first invents an initial state, the
    garden's world check says so, the next answer is accepted and its goal read back."""
    from pipflow_garden.domain import GardenDomain

    good = GardenDomain().write_problem(garden["allotment"], {"stored": {"shed": {"tomato": 4}}}, "garden")
    forged = good.replace("(= (ripe north tomato) 4)", "(= (ripe north tomato) 9)")
    answer = "```pddl\n{}\n```\n```json\n{{\"constraints\": []}}\n```"
    workflow = garden_plugin_site / "pipflow_garden" / "workflows" / "garden.yaml"
    with FakeOpenAI([answer.format(forged), answer.format(good)]) as server:
        proc = pipflow(garden_plugin_site, tmp_path, "run", str(workflow), "-i", "command=Bring 3 tomatoes to the shed.",
                       "-i", "model=openai/fake", "-i", f"api_base={server.api_base}", "--runs-dir", "runs",
                       extra_env={"OPENAI_API_KEY": "sk-test-not-a-real-key-000"})
        assert proc.returncode == 0, proc.stderr
        assert len(server.requests) == 2
        second_prompt = json.dumps(server.requests[1]["messages"])
    assert "(ripe north tomato) is 9 in the problem, 4 in the garden" in second_prompt
    assert "bed north: clear, 4 ripe tomato, 3 ripe basil" in json.dumps(server.requests[0]["messages"])
    out = json.loads((only_run(tmp_path / "runs") / "outputs.json").read_text())
    assert out["rounds"] == 2 and out["goal"] == {"stored": {"shed": {"tomato": 4}}}
    assert out["goal_met"] is True and out["simulation"]["final_state"]["stored"]["shed"]["tomato"] == 4


def test_resource_use_is_measured_against_the_fewest_actions(garden):
    from pipflow_garden import scoring

    world = garden["allotment"]
    goal = {"clear": ["herbs"], "stored": {"crate": {"basil": 4}}, "ripe": {"herbs": {"basil": 0}}}
    assert scoring.reference_actions(world, goal) == 5  # one prune, four harvests
    # a pumpkin from the overgrown south bed needs its prune too; a bed watered twice is one water
    assert scoring.reference_actions(world, {"ripe": {"south": {"pumpkin": 1}}, "watered": ["north", "north"]}) == 3
    # a bound asks only for what is missing: the shed holds one tomato already
    assert scoring.reference_actions(world, {"stored": {"shed": {"tomato": {"at_least": 3}}}}) == 2
    done = {"final_state": {**garden["simulation"].initial_state(world)}, "executed": 7, "exe": 1.0}
    done["final_state"]["overgrown"] = ["south"]
    done["final_state"]["ripe"]["herbs"]["basil"] = 0
    done["final_state"]["stored"]["crate"] = {"basil": 4}
    subtasks = [{"id": f"s{i}", "action": "harvest", "robots": []} for i in range(7)]
    from pipflow_garden.domain import GardenDomain

    score = GardenDomain().score(world, goal, schedule={"subtasks": subtasks}, simulation=done)
    assert score["success"] is True and score["lower_bound"] == 5 and score["ru"] == pytest.approx(5 / 7)


def test_any_command_is_refused_or_read_into_a_goal_the_garden_can_meet(garden):
    """Commands built from the language's clauses with names right and wrong, counts large and
    small, and stray words: the reader either refuses (TranslationError, Refusal, with words) or
    returns a goal naming only the garden's beds, stores and crops, that no count of the garden
    forbids (checks.goal_refusal), whose stored counts add up to what the clauses ask for, and
    rules naming only its robots."""
    from hypothesis import HealthCheck, given, settings, strategies as st

    from pipflow_garden.checks import goal_refusal

    world, read = garden["allotment"], garden["language"].read_command
    beds = st.sampled_from(["north", "south", "east", "herbs", "the north bed", "the herbs bed", "roses", "shed"])
    crops = st.sampled_from(["tomatoes", "tomato", "basil", "pumpkins", "a pumpkin", "beans", "carrots"])
    amounts = st.one_of(st.integers(0, 14).map(str), st.sampled_from(["two", "all the", "at least 2", "a"]))
    stores = st.sampled_from(["", " into the shed", " to the crate", " into the barn"])
    sources = st.one_of(st.just(""), beds.map(lambda b: f" from {b}"))
    robots = st.sampled_from(["mule", "the pickers", "rovers", "wet robots", "goats"])
    verbs = st.sampled_from(["water", "prune", "harvest"])
    clause = st.one_of(
        st.builds(lambda v, bs: f"{v} {' and '.join(bs)}", st.sampled_from(["water", "prune", "weed"]),
                  st.lists(beds, min_size=1, max_size=3)),
        st.builds(lambda a, c, f, t: f"harvest {a} {c}{f}{t}", amounts, crops, sources, stores),
        st.builds(lambda r, v: f"{r} must not {v}", robots, verbs),
        st.builds(lambda r, b: f"keep {r} out of {b}", robots, beds),
        st.sampled_from(["please", "twice", "water north twice"]))

    @settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
    @given(st.lists(clause, min_size=1, max_size=4), st.sampled_from([", ", " and ", "; ", ", then "]))
    def check(clauses, sep):
        try:
            got = read(sep.join(clauses), world)
        except (TranslationError, Refusal) as err:
            assert str(err)
            return
        goal = got["goal"]
        assert set(goal.get("watered", [])) | set(goal.get("clear", [])) | set(goal.get("ripe", {})) <= set(world["beds"])
        assert set(goal.get("stored", {})) <= set(world["stores"])
        assert goal_refusal(world, goal) is None
        asked: dict = {}
        for item in got["order"]:
            if item.get("do") == "harvest":
                n = item["count"] if item["count"] != "all" else None
                asked.setdefault((item["to"], item["crop"]), []).append(n)
        for (store, crop), counts in asked.items():
            value = goal["stored"][store][crop]
            total = value["at_least"] if isinstance(value, dict) else value
            if None not in counts:
                assert total == world["stores"][store]["holds"].get(crop, 0) + sum(counts)
        for rule in got["constraints"]:
            assert set(rule.get("only", rule.get("never", []))) <= set(world["robots"]) and rule["words"]

    check()


def test_a_command_read_two_ways_is_refused(garden, monkeypatch):
    """The parser keeps every reading: were the grammar ever to allow two (here: a variant that
    reads "water north" as a bed list and as a single bed), the command is refused, not resolved
    by a silent preference."""
    language = garden["language"]
    ambiguous = language.GRAMMAR.replace("water: WATER beds", "water: WATER beds | WATER bed")
    assert ambiguous != language.GRAMMAR
    monkeypatch.setattr(language, "GRAMMAR", ambiguous)
    language.parser.cache_clear()
    try:
        with pytest.raises(TranslationError) as err:
            language.read_command("prune south and water north", garden["allotment"])
        assert "'water north': they can be read in more than one way" in str(err.value)
    finally:
        monkeypatch.undo()
        language.parser.cache_clear()
    assert language.read_command("water north", garden["allotment"])["goal"] == {"watered": ["north"]}


def test_the_package_readme_example_world_loads(garden):
    text = (PACKAGE / "README.md").read_text()
    example = text.split("```yaml\n", 1)[1].split("```", 1)[0]
    world = garden["world"].world_from_text(example, "README.md")
    assert set(world["places"]) == {"north", "faucet", "shed"} and world["robots"]["mule"]["tags"] == ["wet"]
    read = garden["language"].read_command("harvest 3 tomatoes from north, then water north", world)
    assert read["goal"] == {"stored": {"shed": {"tomato": 4}}, "ripe": {"north": {"tomato": 1}}, "watered": ["north"]}

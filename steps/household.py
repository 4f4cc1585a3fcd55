"""Household steps (the paper's AI2-THOR experiment on pipflow's own home simulator): load a
household world with its robot team, write the team-level problem for a command, execute the
schedule, score the final state. Thin faces of :mod:`pipflow.household`; the domain-general
steps (pddl.*, graph.dependencies, allocate.*, schedule) do the rest unchanged."""
from __future__ import annotations

import re
from typing import Annotated

from pipflow import Doc, PathStr, StepContext, step


@step("household.load",
      doc="Load a household world (places, objects, categories, robots), validated with every problem located; keep the task's team.",
      outputs={"world": "object"}, cacheable=True)
def load(
    ctx: StepContext,
    path: Annotated[PathStr, Doc("household world YAML file, relative to the workflow file")],
    team: Annotated[str | None, Doc("a team of the world, or robot names 'a,b,c' (none: every robot)")] = None,
    seed: Annotated[int | None, Doc("vary the robots' start positions reproducibly (none: as in the file)")] = None,
) -> dict:
    """Raises WorldError (exit 2) listing each problem with file:line:col."""
    from pipflow.household.world import load_world, select_team, vary_starts

    world = vary_starts(select_team(load_world(ctx.resolve_path(path)), team), seed)
    ctx.log(f"household world {world['name']}: {len(world['places'])} places, {len(world['objects'])} objects, "
            f"team {', '.join(world['robots'])}")
    return {"world": world}


@step("household.problem",
      doc="Translate a household command (offline, deterministic) into goal conditions and the team-level PDDL problem.",
      outputs={"problem": "string", "goal": "object", "concrete": "object", "constraints": "array", "errors": "array"},
      cacheable=True)
def problem(
    ctx: StepContext,
    command: Annotated[str, Doc("the natural-language command")],
    world: Annotated[dict, Doc("output of household.load")],
    domain: Annotated[PathStr, Doc("team-level PDDL domain (its name goes into the problem)")],
    feedback: Annotated[list | None, Doc("previous round's messages (the offline translator is deterministic "
                                         "and ignores them)")] = None,
) -> dict:
    """``goal`` keeps the command's conditions (counts included) for judging; ``concrete`` has the
    counts resolved to objects, which is what the problem asks for. Untranslatable commands raise
    TranslationError; impossible ones (slice a mug) raise Refusal with the reason."""
    from pipflow.household.problem import write_problem
    from pipflow.household.translator import translate

    result = translate(command, world)
    text = ctx.resolve_path(domain).read_text()
    m = re.search(r"\(\s*domain\s+([^\s()]+)", text, flags=re.IGNORECASE)
    pddl = write_problem(world, result["concrete"], domain=m.group(1) if m else "household")
    ctx.write_artifact("goal.json", result)
    ctx.write_artifact("problem.pddl", pddl)
    ctx.log(f"goal: {result['goal']}")
    return {"problem": pddl, "goal": result["goal"], "concrete": result["concrete"], "constraints": [], "errors": []}


@step("household.simulate",
      doc="Execute a schedule in the home: preconditions and coalition skills checked, state updated, travel measured, pybullet pictures.",
      outputs={"final_state": "object", "executed": "integer", "failed": "integer", "failures": "array",
               "exe": "number", "travel": "object", "tc_max": "number", "tc_avg": "number", "tc_avg_moved": "number",
               "goal_met": "boolean",
               "gcr": "number", "conditions": "object", "jumps": "object", "makespan": "number", "pictures": "array"},
      version="1")
def simulate(
    ctx: StepContext,
    world: Annotated[dict, Doc("output of household.load")],
    schedule: Annotated[dict, Doc("output of schedule")],
    graph: Annotated[dict | None, Doc("output of graph.dependencies (skills and route per subtask)")] = None,
    goal: Annotated[dict | None, Doc("goal conditions to judge the final state against")] = None,
    snapshots: Annotated[bool, Doc("save pybullet pictures of the start and the end")] = False,
) -> dict:
    from pipflow.household.simulation import simulate as run

    out_dir = ctx.artifact_path("home-start.png").parent if snapshots else None
    result = run(world, schedule, graph, goal, snapshots=snapshots, out_dir=out_dir, log=ctx.log)
    ctx.metrics.update({k: result[k] for k in ("exe", "tc_max", "tc_avg", "gcr")})
    ctx.log(f"executed {result['executed']}/{len(schedule.get('subtasks', []))}, goal conditions "
            f"{result['conditions']['met']}/{result['conditions']['total']}")
    return result


@step("household.score",
      doc="Score a household run's final state against ground-truth conditions (SR, GCR, Exe, RU, TC); "
          "the outputs of metrics.score, flat.",
      outputs={"success": "boolean", "goal_met": "boolean", "gcr": "number", "exe": "number", "ru": "number",
               "tc_max": "number", "tc_avg": "number", "tc_avg_moved": "number", "makespan": "number", "planned": "integer",
               "executed": "integer", "lower_bound": "any", "violations": "array", "refused": "boolean",
               "error": "any"})
def score(
    ctx: StepContext,
    world: Annotated[dict, Doc("output of household.load")],
    goal: Annotated[dict, Doc("ground-truth goal conditions")],
    schedule: Annotated[dict | None, Doc("output of schedule")] = None,
    graph: Annotated[dict | None, Doc("output of graph.dependencies")] = None,
    simulation: Annotated[dict | None, Doc("output of household.simulate")] = None,
) -> dict:
    """The same flat outputs as ``metrics.score`` (one shape per family), so a workflow or the
    bench reads ``success``/``gcr`` the same way in either domain."""
    from pipflow.household.scoring import score_run

    return score_run(world, goal, graph=graph, schedule=schedule, simulation=simulation)

"""Steps of the ``allocate`` family: skill-based MRTA over the dependency graph (paper Alg. 1 and
eq. 3), thin faces of :mod:`pipflow.team.allocation`. All of them output the allocation contract of
docs/architecture.md, so `schedule` and the metrics do not care which one ran, and `cost`: which
allocation cost c_i they used (``total``, the paper's, or ``subtask``; docs/paper.md)."""
from __future__ import annotations

from typing import Annotated, Any

from pipflow import Check, Choices, Doc, PathStr, StepContext, step
from pipflow.errors import AllocationError
from pipflow.language.asking import ModelCall, RoundRecord, require_model
from pipflow.language.cache import ResponseCache
from pipflow.language.llm import Retry
from pipflow.language.prompting import find_template, prompt_problem
from pipflow.liberrors import SCIP, library_errors
from pipflow.team.scheduling import COSTS, DEFAULT_COST
from pipflow.values import AllocationOutputs

# the inputs every allocator takes, named once (each step's signature is its contract)
Graph = Annotated[dict, Doc("output of graph.dependencies")]
World = Annotated[dict, Doc("output of world.load")]
RobotRules = Annotated[list | None, Doc("only/never rules: [{only|never: [robots], FIELD?: name, ...}], FIELD one of the world's task domain's rule fields")]
LinearRules = Annotated[list | None, Doc("extra linear constraints: [{robots: [..]|all, coef: n|{robot: n}, "
                                         "skill?, sense, rhs, <field>?}]")]
Speed = Annotated[float, Doc("robot speed, m/s (times in stats and frontier mode)")]
Handling = Annotated[float, Doc("seconds of loading/unloading per route stop")]
Cost = Annotated[str, Choices(*COSTS),
                 Doc("c_i of the IP: total = the robot's travel so far plus this subtask (the paper's, balances "
                     "work: lower TC-max and makespan); subtask = this subtask's approach and route only "
                     "(nearest robots: less travel in sum, one robot may do most subtasks)")]


def _run(ctx: StepContext, method: str, graph: dict, world: dict, **options: Any) -> dict:
    """One allocation with ``method``; ``options``: the step's other inputs, the keyword arguments of
    :func:`pipflow.team.allocation.allocate` (rules unset: none)."""
    # deferred: pulls numpy (~150 ms; the registry loads every step module, e.g. for `pipflow validate`)
    from pipflow.team.allocation import allocate

    options.update(constraints=options.get("constraints") or [], linear=options.get("linear") or [])
    with library_errors(SCIP, AllocationError, f"allocating with {method}"):
        result = allocate(graph, world, method=method, **options)
    ctx.write_artifact("allocation.json", result)
    st = result["stats"]
    ctx.metrics.update({"alloc_median_ms": st["solve_median_ms"], **{f"predicted_{k}": v for k, v in st["predicted"].items()}})
    ctx.log(f"allocated {st['subtasks']} subtasks ({result['method']}, cost {result['cost']}), "
            f"median solve {st['solve_median_ms']:.1f} ms")
    return {"allocation": result, "cost": result["cost"]}  # which c_i ran, for the run's outputs


@step("allocate.scip",
      doc="Lexicographic IP per subtask (min max cost, then min sum of costs) with SCIP; or frontier mode.", cacheable=True)
def scip(
    ctx: StepContext,
    graph: Graph,
    world: World,
    constraints: RobotRules = None,
    linear: LinearRules = None,
    speed: Speed = 1.0,
    handling: Handling = 2.0,
    mode: Annotated[str, Choices("subtask", "frontier"),
                    Doc("subtask: the paper's one IP per subtask; frontier: all ready subtasks in one IP")] = "subtask",
    time_limit: Annotated[float, Doc("seconds per frontier wave (frontier mode)")] = 10.0,
    naive: Annotated[bool, Doc("solve the first stage as a full SCIP model (slow; for comparison)")] = False,
    cost: Cost = DEFAULT_COST,
) -> AllocationOutputs:
    """The paper's allocator; the fast first stage gives the same optimum as the naive model."""
    return _run(ctx, "naive" if naive else "scip", graph, world, constraints=constraints, linear=linear,
                speed=speed, handling=handling, cost=cost, mode=mode, time_limit=time_limit)


@step("allocate.greedy", doc="Baseline: cheapest capable robots first until the skills are covered.", cacheable=True)
def greedy(ctx: StepContext, graph: Graph, world: World, constraints: RobotRules = None, linear: LinearRules = None,
           speed: Speed = 1.0, handling: Handling = 2.0, cost: Cost = DEFAULT_COST) -> AllocationOutputs:
    """Greedy baseline for comparison with the IP; "cheapest" by ``cost`` (subtask: the nearest)."""
    return _run(ctx, "greedy", graph, world, constraints=constraints, linear=linear, speed=speed,
                handling=handling, cost=cost)


@step("allocate.blind", doc="pipflow's cost-blind allocation: fewest robots by robot order, ignoring travel cost "
                            "(not the paper's w/o AS, which is allocate.llm).", cacheable=True)
def blind(ctx: StepContext, graph: Graph, world: World, constraints: RobotRules = None, linear: LinearRules = None,
          speed: Speed = 1.0, handling: Handling = 2.0, cost: Cost = DEFAULT_COST) -> AllocationOutputs:
    """Cost-blind allocation: shows what the allocation strategy buys. It never looks at costs;
    ``cost`` only says what the recorded ``costs`` of each assignment mean."""
    return _run(ctx, "blind", graph, world, constraints=constraints, linear=linear, speed=speed,
                handling=handling, cost=cost)


@step("allocate.llm",
      doc="The paper's 'w/o AS' ablation: a language model allocates the subtasks to robots and orders them "
          "(instead of the IP); its JSON answer is checked (skills, rules, order) and refused with feedback.",
      cacheable=True)
def llm(
    ctx: StepContext,
    graph: Graph,
    world: World,
    constraints: RobotRules = None,
    model: Annotated[str | None, Doc("litellm model string or local/smollm2 (offline has no model: a user "
                                     "error)")] = None,
    api_base: Annotated[str | None, Doc("base URL of an OpenAI-compatible server")] = None,
    prompt: Annotated[str, Check(prompt_problem), Doc("template name in prompts/ or a path")] = "allocate_llm",
    attempts: Annotated[int, Doc("answers the model may give in all: a refused answer (a coalition short of "
                                 "a skill, a robot a rule excludes, an order the graph forbids) is sent back "
                                 "with its problems")] = 3,
    speed: Speed = 1.0,
    handling: Handling = 2.0,
    cost: Cost = DEFAULT_COST,
    temperature: Annotated[float, Doc("sampling temperature")] = 0.0,
    max_tokens: Annotated[int, Doc("most tokens of an answer")] = 1024,
    timeout: Annotated[float, Doc("seconds per call")] = 60.0,
    deadline: Annotated[float | None, Doc("seconds per call, retries and waits included")] = None,
    cache_dir: Annotated[PathStr | None, Doc("response cache folder (default .pipflow-cache/llm)")] = None,
    cache: Annotated[bool, Doc("replay cached responses; false always calls the model")] = True,
) -> AllocationOutputs:
    """The model's coalitions in the model's order, timed as every allocation is (the recorded
    ``costs`` are what c_i would have been, for comparison with the IP); each question and answer
    is an artifact (``attemptN-messages.json``, ``attemptN-response.txt``)."""
    resolved = require_model(model, "the allocation of the w/o AS ablation (allocate.llm)")
    template = find_template(prompt, ctx.base_dir)
    ctx.check_readable(template, f"step {ctx.step_id!r}: prompt template {prompt!r}", named_as=prompt)
    # deferred: pulls numpy through pipflow.team.allocation (~150 ms; the registry loads every step module)
    from pipflow.language.allocator import allocate_by_model

    responses = ResponseCache(ctx.resolve_path(cache_dir) if cache_dir else None) if cache and ctx.use_cache else None
    result = allocate_by_model(
        graph, world, constraints=constraints, prompt=str(template), attempts=attempts,
        call=ModelCall(model=resolved, api_base=api_base, temperature=temperature, max_tokens=max_tokens,
                       named=ctx.named_by_user, retry=Retry(timeout=timeout, deadline=deadline)),
        record=RoundRecord(save=ctx.write_artifact, log=ctx.log, cache=responses),
        speed=speed, handling=handling, cost=cost)
    ctx.write_artifact("allocation.json", result)
    st = result["stats"]
    ctx.metrics.update({"attempts": st["attempts"], **{f"predicted_{k}": v for k, v in st["predicted"].items()}})
    ctx.log(f"allocated {st['subtasks']} subtasks (llm, {st['attempts']} answer(s)), cost {result['cost']}")
    return {"allocation": result, "cost": result["cost"]}

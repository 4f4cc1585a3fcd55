"""Steps of the paper's baselines (CoT, SMART-LLM, LaMMA-P; Sec. V, Tables I-III): thin faces of
:mod:`pipflow.baselines`. A baseline's workflow asks its model its questions (``baseline.ask``,
one step per stage of its paper), reads the last answer in its format (``baseline.read``; for
LaMMA-P ``baseline.summary`` and ``baseline.subplans``), and turns the robot plan into the graph
and allocation that ``schedule``, ``simulate`` and ``score`` judge as they judge PIP-LLM's
(``baseline.graph``). Nothing a model writes is executed.

UP, lark and litellm are imported where they are used, below these functions."""
from __future__ import annotations

from typing import Annotated, Any

from pipflow import Check, Choices, Doc, PathStr, StepContext, step
from pipflow.baselines.cot import read_cot
from pipflow.baselines.lammap import read_summary, subtasks_from_data
from pipflow.baselines.located import Unreadable
from pipflow.baselines.robotplan import schedule_input, steps_from_data
from pipflow.baselines.skills import domain_skills
from pipflow.baselines.smartllm import read_smart_llm
from pipflow.baselines.subplans import Planning, plan_subtasks, robot_level
from pipflow.errors import InputError
from pipflow.language.asking import ModelCall, RoundRecord, ask, require_model
from pipflow.language.cache import ResponseCache
from pipflow.language.llm import Retry, sum_usage
from pipflow.language.prompting import find_template, prompt_problem, render
from pipflow.pddl.solver import check_engine

#: the baselines, by the names their workflows and bench rows use
METHODS = ("cot", "smart-llm", "lamma-p")
#: the formats ``baseline.read`` reads, and what each answer is called in messages
FORMATS = {"cot": "a plan in the CoT format (PLAN: then `N. ROBOTS: (ACTION ARGS)` lines)",
           "smart-llm": "SMART-LLM code (functions of skill calls, threads)"}


def _text(ctx: StepContext, path: str, what: str) -> str:
    file = ctx.resolve_path(path)
    try:
        return file.read_text(encoding="utf-8")
    except OSError as exc:
        raise InputError(f"{what} {file}: {exc.strerror}") from None


def _team(world: dict) -> list[str]:
    """The robots in the order the prompts list them (``robots[0]`` first)."""
    return list((world.get("robots") or {}).keys())


def _skill_data(domain_text: str) -> list[dict]:
    return [{"action": s.action, "call": s.call, "params": list(s.params), "types": list(s.types),
             "signature": s.signature(), "pddl": s.pddl()} for s in domain_skills(domain_text)]


def _cut_off(usage: dict | None) -> int | None:
    """The answer's token count when the model stopped at its limit (``finish_reason: length``)."""
    if isinstance(usage, dict) and usage.get("finish_reason") == "length":
        return int(usage.get("completion_tokens") or 0) or None
    return None


def _usage(ctx: StepContext, usages: list[dict]) -> dict:
    total = sum_usage(usages)
    ctx.metrics["llm"] = total
    return total


# Model settings every asking step takes, named once.
Model = Annotated[str | None, Doc("litellm model string or local/smollm2 (a baseline needs a model: offline is "
                                  "refused); unset: $PIPFLOW_MODEL")]
ApiBase = Annotated[str | None, Doc("base URL of an OpenAI-compatible server")]
MaxTokens = Annotated[int, Doc("most tokens of the answer")]
Timeout = Annotated[float, Doc("seconds per request")]
Deadline = Annotated[float | None, Doc("seconds for the whole call, retries included")]
Prompt = Annotated[str, Check(prompt_problem), Doc("prompt template in prompts/ (or a path); its `stage` variable "
                                                  "says which question")]


def _ask(ctx: StepContext, *, name: str, prompt: str, variables: dict, call: ModelCall,
         cache: bool) -> tuple[str, dict, list]:
    """One question of a baseline's method: the template checked as every step's is (a template
    the workflow may read), the question and answer kept as ``<name>.messages.json`` and
    ``<name>.response.txt``."""
    template = find_template(prompt, ctx.base_dir)
    ctx.check_readable(template, f"step {ctx.step_id!r}: prompt template {prompt!r}", named_as=prompt)
    messages = render(str(template), variables)
    responses = ResponseCache() if cache and ctx.use_cache else None
    answer = ask(messages, call=call, record=RoundRecord(save=ctx.write_artifact, log=ctx.log, cache=responses),
                 name=f"{name}.")
    return answer["text"], answer["usage"], messages


def _model_call(ctx: StepContext, model: str, api_base: str | None, temperature: float, max_tokens: int,
                timeout: float, retries: int, deadline: float | None) -> ModelCall:
    """Who answers a baseline's questions, and how patiently; the provider key goes only to an
    ``api_base`` the user named."""
    return ModelCall(model=model, api_base=api_base, temperature=temperature, max_tokens=max_tokens,
                     named=ctx.named_by_user, retry=Retry(timeout=timeout, retries=retries, deadline=deadline))


@step("baseline.ask",
      doc="Ask a baseline's model one question of its method (a stage: decompose, allocate, code, summary, plan); "
          "the answer as text, read by a later step.",
      outputs={"text": "string", "messages": "array", "usage": "object"})
def ask_stage(
    ctx: StepContext,
    method: Annotated[str, Choices(*METHODS), Doc("the baseline asking")],
    stage: Annotated[str, Doc("which of its questions (the template's `stage` variable)")],
    command: Annotated[str, Doc("the natural-language command")],
    world: Annotated[dict, Doc("the world (output of world.load)")],
    domain: Annotated[PathStr, Doc("team-level PDDL domain file: its actions are the skills")],
    prompt: Prompt,
    answers: Annotated[dict | None, Doc("earlier stages' answers by stage name (the template shows them)")] = None,
    robot_domain: Annotated[PathStr | None, Doc("robot-level PDDL domain file (LaMMA-P)")] = None,
    model: Model = None,
    api_base: ApiBase = None,
    temperature: Annotated[float, Doc("sampling temperature")] = 0.0,
    max_tokens: MaxTokens = 1024,
    timeout: Timeout = 60.0,
    retries: Annotated[int, Doc("extra tries on provider errors (pipflow's one retry layer)")] = 2,
    deadline: Deadline = None,
    cache: Annotated[bool, Doc("replay cached responses; false always calls the model")] = True,
) -> dict:
    """The template gets ``command``, ``world``, ``stage``, ``method``, ``domain`` (the team-level
    PDDL text), ``skills`` (the domain's actions: ``call``, ``signature``, ``pddl``, ``params``,
    ``types``), ``team`` (robot names, ``robots[0]`` first), ``answers`` and ``robot_domain``."""
    resolved = require_model(model, f"the {method} baseline")
    if not isinstance(command, str) or not command.strip():
        raise InputError("command must be a non-empty string")
    domain_text = _text(ctx, domain, "domain file")
    variables = {"command": command, "world": world, "stage": stage, "method": method, "domain": domain_text,
                 "skills": _skill_data(domain_text), "team": _team(world), "answers": dict(answers or {}),
                 "robot_domain": _text(ctx, robot_domain, "robot-level domain file") if robot_domain else ""}
    call = _model_call(ctx, resolved, api_base, temperature, max_tokens, timeout, retries, deadline)
    text, usage, messages = _ask(ctx, name=stage, prompt=prompt, variables=variables, call=call, cache=cache)
    ctx.metrics["llm"] = usage
    return {"text": text, "messages": messages, "usage": usage}


@step("baseline.read",
      doc="Read a baseline's answer in its format (CoT plan, SMART-LLM code) as a robot plan; never executed. An "
          "answer outside the format fails the run with every problem located (line, column): these baselines get "
          "no further round.",
      outputs={"plan": "array", "steps": "integer"})
def read(
    ctx: StepContext,
    format: Annotated[str, Choices(*FORMATS), Doc("the answer's format")],
    text: Annotated[str, Doc("the model's answer")],
    world: Annotated[dict, Doc("the world (output of world.load): the team, robots[0] first")],
    domain: Annotated[PathStr, Doc("team-level PDDL domain file: its actions are the skills")],
    usage: Annotated[dict | None, Doc("the answer's usage (baseline.ask): a refusal says when it was cut off")] = None,
) -> dict:
    """``plan``: robot steps ``{id, action, args, robots, after, where, problems}``."""
    skills = domain_skills(_text(ctx, domain, "domain file"))
    try:
        steps = read_cot(text, skills) if format == "cot" else read_smart_llm(text, skills, _team(world))
    except Unreadable as bad:
        ctx.write_artifact("issues.txt", "\n".join(str(i) for i in bad.issues) + "\n")
        raise bad.refusal(format, FORMATS[format], _cut_off(usage)) from None
    plan = [s.data() for s in steps]
    ctx.write_artifact("plan.json", plan)
    ctx.log(f"read {len(plan)} actions")
    return {"plan": plan, "steps": len(plan)}


@step("baseline.summary",
      doc="Read LaMMA-P's allocation summary (SubTask / Assigned Robot / Objects Involved / After) as subtasks, every "
          "problem located; one round lets the model fix it (LaMMA-P re-asks for a subtask it cannot read once), then "
          "a subtask still malformed is skipped, and a summary with no readable subtask ends the run.",
      outputs={"subtasks": "array", "skipped": "array", "text": "string", "usage": "object"})
def summary(
    ctx: StepContext,
    text: Annotated[str, Doc("the model's summary answer")],
    command: Annotated[str, Doc("the natural-language command")],
    world: Annotated[dict, Doc("the world (output of world.load): the team")],
    domain: Annotated[PathStr, Doc("team-level PDDL domain file")],
    prompt: Prompt,
    usage: Annotated[dict | None, Doc("the answer's usage (baseline.ask): a refusal says when it was cut off")] = None,
    robot_domain: Annotated[PathStr | None, Doc("robot-level PDDL domain file")] = None,
    answers: Annotated[dict | None, Doc("earlier stages' answers by stage name")] = None,
    rounds: Annotated[int, Doc("rounds that let the model fix the summary (LaMMA-P: 1)")] = 1,
    model: Model = None,
    api_base: ApiBase = None,
    temperature: Annotated[float, Doc("sampling temperature")] = 0.0,
    max_tokens: MaxTokens = 1400,
    timeout: Timeout = 60.0,
    retries: Annotated[int, Doc("extra tries on provider errors")] = 2,
    deadline: Deadline = None,
    cache: Annotated[bool, Doc("replay cached responses; false always calls the model")] = True,
) -> dict:
    """``subtasks``: every subtask read, those with ``issues`` skipped (``skipped`` lists their
    numbers); ``text``: the summary read (the fixed one after a round)."""
    if rounds < 0:
        raise InputError(f"rounds must be 0 or more, got {rounds}")
    team = _team(world)
    reading, fatal = _summary_of(text, team)
    usages: list[dict] = []
    for k in range(rounds):
        found = fatal.issues if fatal is not None else reading.issues
        if not found:
            break
        resolved = require_model(model, "the lamma-p baseline")
        domain_text = _text(ctx, domain, "domain file")
        variables = {"command": command, "world": world, "stage": "summary-fix", "method": "lamma-p",
                     "domain": domain_text, "skills": _skill_data(domain_text), "team": team,
                     "answers": dict(answers or {}), "previous": text,
                     "feedback": (fatal or Unreadable(found)).lines(),
                     "robot_domain": _text(ctx, robot_domain, "robot-level domain file") if robot_domain else ""}
        call = _model_call(ctx, resolved, api_base, temperature, max_tokens, timeout, retries, deadline)
        text, usage, _ = _ask(ctx, name=f"summary-fix{k + 1}", prompt=prompt, variables=variables, call=call,
                              cache=cache)
        usages.append(usage)
        reading, fatal = _summary_of(text, team)
    if fatal is not None:
        ctx.write_artifact("issues.txt", "\n".join(str(i) for i in fatal.issues) + "\n")
        raise fatal.refusal("lamma-p", "a LaMMA-P allocation summary", _cut_off(usages[-1] if usages else usage))
    skipped = [s.number for s in reading.subtasks if s.issues]
    for s in reading.subtasks:
        if s.issues:
            ctx.log(f"subtask of line {s.line} skipped (as LaMMA-P skips a subtask it cannot read): {'; '.join(s.issues)}")
    data = [s.data() for s in reading.subtasks]
    ctx.write_artifact("subtasks.json", data)
    return {"subtasks": data, "skipped": skipped, "text": text, "usage": _usage(ctx, usages)}


def _summary_of(text: str, team: list[str]) -> tuple[Any, Unreadable | None]:
    """The summary read, or the reason none of it can be used."""
    try:
        return read_summary(text, team), None
    except Unreadable as bad:
        return None, bad


@step("baseline.subplans",
      doc="LaMMA-P's per-robot planning: for each subtask the model writes a PDDL problem in the robot-level domain, "
          "the debugger checks it (one validator round with its located messages, as LaMMA-P's one validation), a "
          "planner solves it; the sub-plans merged in time as the summary orders them.",
      outputs={"plan": "array", "subtasks": "array", "usage": "object"})
def subplans(
    ctx: StepContext,
    subtasks: Annotated[list, Doc("output of baseline.summary")],
    command: Annotated[str, Doc("the natural-language command")],
    world: Annotated[dict, Doc("the world (output of world.load)")],
    domain: Annotated[PathStr, Doc("team-level PDDL domain file")],
    robot_domain: Annotated[PathStr, Doc("robot-level PDDL domain file (actions name their robots)")],
    robot_actions_file: Annotated[Any, Doc("the robot-level actions' team actions (domains/*-robots.actions.yaml), "
                                           "a path or its content")],
    prompt: Prompt,
    answers: Annotated[dict | None, Doc("earlier stages' answers by stage name")] = None,
    rounds: Annotated[int, Doc("validator rounds per problem (LaMMA-P: 1)")] = 1,
    planner: Annotated[str, Doc("UP engine for the robot-level problems")] = "enhsp",
    planner_params: Annotated[dict | None, Doc("the engine's parameters, e.g. {params: '-planner sat-hmrphj'}")] = None,
    planner_timeout: Annotated[float, Doc("seconds per problem")] = 60.0,
    model: Model = None,
    api_base: ApiBase = None,
    temperature: Annotated[float, Doc("sampling temperature")] = 0.0,
    max_tokens: MaxTokens = 1400,
    timeout: Timeout = 60.0,
    retries: Annotated[int, Doc("extra tries on provider errors")] = 2,
    deadline: Deadline = None,
    cache: Annotated[bool, Doc("replay cached responses; false always calls the model")] = True,
) -> dict:
    """``subtasks``: per subtask its problem, the validator's messages, the planner's outcome and
    how many actions it got (:func:`pipflow.baselines.subplans.plan_subtasks`)."""
    resolved = require_model(model, "the lamma-p baseline")
    if rounds < 0:
        raise InputError(f"rounds must be 0 or more, got {rounds}")
    check_engine(planner)
    domain_text = _text(ctx, domain, "domain file")
    level = robot_level(_text(ctx, robot_domain, "robot-level domain file"),
                        ctx.read_yaml(robot_actions_file, "robot-level actions file"), domain_text)
    base = {"command": command, "world": world, "method": "lamma-p", "domain": domain_text,
            "skills": _skill_data(domain_text), "team": _team(world), "answers": dict(answers or {}),
            "robot_domain": level.text, "subtasks": subtasks}
    usages: list[dict] = []

    def ask_model(stage: str, name: str, variables: dict) -> str:
        text, usage, _ = _ask(ctx, name=name, prompt=prompt, variables={**base, **variables, "stage": stage},
                              call=_model_call(ctx, resolved, api_base, temperature, max_tokens, timeout, retries, deadline),
                              cache=cache)
        usages.append(usage)
        return text

    steps, report = plan_subtasks(subtasks_from_data(subtasks), level, world, ask_model, rounds=rounds,
                                  planning=Planning(planner, planner_params, planner_timeout),
                                  save=ctx.write_artifact, log=ctx.log)
    plan = [st.data() for st in steps]
    ctx.write_artifact("plan.json", plan)
    ctx.write_artifact("subtasks.json", report)
    return {"plan": plan, "subtasks": report, "usage": _usage(ctx, usages)}


@step("baseline.graph",
      doc="The dependency graph and allocation of a robot plan, as the model gave them (its order, its robots), for "
          "`schedule`; actions the world cannot place (unknown places or objects, robots outside the team) are kept "
          "as unexecutable: the simulation counts them as not executed.",
      outputs={"graph": "object", "allocation": "object", "unexecutable": "integer"})
def graph(
    ctx: StepContext,
    plan: Annotated[list, Doc("robot plan: output `plan` of baseline.read or baseline.subplans")],
    world: Annotated[dict, Doc("the world (output of world.load)")],
    domain: Annotated[PathStr, Doc("team-level PDDL domain file")],
    actions: Annotated[Any, Doc("the team domain's action metadata (domains/*.actions.yaml), a path or its content")],
    method: Annotated[str, Choices(*METHODS), Doc("the baseline whose plan it is")],
) -> dict:
    out = schedule_input(steps_from_data(plan), world, _text(ctx, domain, "domain file"),
                         ctx.read_yaml(actions, "action metadata"), method)
    ctx.write_artifact("graph.json", out["graph"])
    ctx.write_artifact("allocation.json", out["allocation"])
    for node in out["graph"]["nodes"]:
        if node.get("unexecutable"):
            ctx.log(f"{node['id']} {node['action']} {' '.join(node['args'])} cannot be placed in this world: "
                    f"{'; '.join(node['unexecutable'])}")
    ctx.metrics.update({"subtasks": len(out["graph"]["nodes"]), "unexecutable": out["unexecutable"]})
    return out

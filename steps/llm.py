"""Language steps: the PDDL problem generator (paper, Fig. 1, orange box).

Thin face of :mod:`pipflow.language.generator`; litellm is imported only when a model is called.
"""
from __future__ import annotations

from typing import Annotated

from pipflow import Check, Choices, Doc, PathStr, StepContext, step
from pipflow.errors import InputError, Refusal, StepError, TranslationError
from pipflow.language.agreement import refusal_opinion
from pipflow.language.asking import ModelCall, RoundRecord, ask, require_model
from pipflow.language.cache import ResponseCache
from pipflow.language.generator import READERS, LoopRound, generate
from pipflow.language.llm import Retry, resolve_model
from pipflow.language.parsing import ParseIssue
from pipflow.language.prompting import find_template, prompt_problem, render
from pipflow.language.teamplan import read_team_plan
from pipflow.pddl.common import format_plan
from pipflow.taskdomain import Capability, pddl_domain_name
from pipflow.taskdomains import task_domain
from pipflow.values import CheckOutputs, ProblemReading

#: the longest answer kept in the step's ``response`` output. The run record copies outputs (each
#: loop iteration, the loop's result), so a long answer is stored once in full, as the artifact
#: response.txt, and only its head in the outputs.
RESPONSE_OUTPUT_CHARS = 32_000


@step(
    "llm.problem",
    doc="Write the team-level PDDL problem for a command with a language model (or offline).",
)
def llm_problem(
    ctx: StepContext,
    command: Annotated[str, Doc("the natural-language command")],
    world: Annotated[dict, Doc("the world (output of world.load or a domain's own load step)")],
    domain: Annotated[PathStr, Doc("team-level PDDL domain file")],
    prompt: Annotated[str | None, Check(prompt_problem),
                      Doc("template name in prompts/ or a path; unset: the world's task domain's "
                          "default prompt")] = None,
    model: Annotated[str | None, Doc("litellm model string, local/smollm2 or offline; unset: $PIPFLOW_MODEL, "
                                     "else offline")] = None,
    temperature: Annotated[float, Doc("sampling temperature (0: the most likely answer)")] = 0.0,
    max_tokens: Annotated[int | None, Doc("most tokens of the answer; unset: from the expected answer's size "
                                          "(pipflow.language.budget)")] = None,
    timeout: Annotated[float, Doc("seconds per call")] = 60.0,
    retries: Annotated[int, Doc("extra tries on rate limits, time-outs, server errors, lost connections (the "
                                "only retry layer: 2 means at most 3 requests)")] = 2,
    api_base: Annotated[str | None, Doc("base URL of an OpenAI-compatible server")] = None,
    feedback: Annotated[list | None, Doc("messages of the previous round's debugger/verifier")] = None,
    grounded: Annotated[bool, Doc("constrain decoding to the world's names and counts")] = False,
    cache_dir: Annotated[PathStr | None, Doc("response cache folder (default .pipflow-cache/llm)")] = None,
    cache: Annotated[bool, Doc("replay cached responses; false always calls the model")] = True,
    deadline: Annotated[float | None, Doc("seconds for the whole call, retries and waits included; unset: no "
                                          "bound beyond timeout x tries")] = None,
    previous: Annotated[dict | None, Doc("the previous round's `round` output: a prompt that would repeat it "
                                         "is varied (output `varied` says how)")] = None,
    reader: Annotated[str, Choices(*READERS),
                      Doc("model: the model reads every command; offline-first: the offline parser reads it "
                          "when it understands it (no model call), the model only what the parser refuses as "
                          "not understood (a command the parser finds impossible is refused)")] = "model",
    locate: Annotated[bool, Doc("say which section of a problem that never closes is left open (the debugger's "
                                "reading); false in a workflow without the debugger (the 'w/o B' ablation)")] = True,
    reading: Annotated[int | None, Doc("offline: after a refusal that offered candidate readings, the one the "
                                       "user chose (1-based); a command read as said ignores it")] = None,
) -> ProblemReading:
    """``problem`` is "" when the answer held no usable problem; ``errors`` then says why, in
    words meant for the next round's prompt. ``goal`` is set by offline and grounded runs, and by
    every run of a domain that reads its goal back from the problem (household: its goal
    conditions). Offline, the world's task domain reads the command; `concrete` (the goal with
    counts resolved) is set where the domain has it (household), else None. ``reader`` says
    whose reading this round's goal is: ``offline`` (the parser's) or ``model``."""
    resolved = resolve_model(model)
    path = ctx.resolve_path(domain)
    try:  # offline too: the problem names the domain file's PDDL domain
        domain_text = path.read_text(encoding="utf-8")
    except OSError as exc:
        raise InputError(f"domain file {path}: {exc.strerror}") from None
    if prompt is not None and resolved != "offline":  # a file the workflow names is read where it lives
        template = find_template(prompt, ctx.base_dir)
        ctx.check_readable(template, f"step {ctx.step_id!r}: prompt template {prompt!r}", named_as=prompt)
        prompt = str(template)
    responses = ResponseCache(ctx.resolve_path(cache_dir) if cache_dir else None) if cache and ctx.use_cache else None
    out = generate(
        command, world, domain_text, prompt=prompt, base_dir=ctx.base_dir,
        call=ModelCall(model=resolved, api_base=api_base, temperature=temperature, max_tokens=max_tokens,
                       grounded=grounded, retry=Retry(timeout=timeout, retries=retries, deadline=deadline),
                       named=ctx.named_by_user),
        loop=LoopRound(feedback=feedback, previous=previous, reader=reader, locate=locate, reading=reading),
        record=RoundRecord(save=ctx.write_artifact, log=lambda m: _log(ctx, m), cache=responses))
    ctx.metrics["llm"] = out["usage"]
    text = out.get("response") or ""
    if len(text) > RESPONSE_OUTPUT_CHARS:  # the whole answer is kept once, as artifact response.txt
        out["response"] = (text[:RESPONSE_OUTPUT_CHARS] + f"\n... [{len(text):,} characters in all: the whole "
                           "answer is the artifact response.txt of this step]")
    return out


@step(
    "llm.check",
    doc="The checked loop's second opinion on the model's reading: its goal and robot rules against the offline "
        "parser's reading of the command (or the doubts the command's names and numbers raise); decides whether a "
        "refusal is final. Feedback names what disagrees and the command's words, never the parser's value.",
)
def llm_check(
    ctx: StepContext,
    command: Annotated[str, Doc("the natural-language command")],
    world: Annotated[dict, Doc("the world (output of world.load)")],
    goal: Annotated[dict | None, Doc("the goal the round's problem states (pddl.verify's goal, or the "
                                     "generator's where the domain reads its goal back)")] = None,
    constraints: Annotated[list | None, Doc("the round's robot-use rules (llm.problem's constraints)")] = None,
    refusal: Annotated[str | None, Doc("the verifier's refusal of this round's goal, if any")] = None,
    model: Annotated[str | None, Doc("the generator's model; offline: its reading is the parser's")] = None,
    reader: Annotated[str | None, Doc("who wrote the round's goal (llm.problem's reader); offline: the "
                                      "parser, nothing to compare")] = None,
    strict: Annotated[bool, Doc("a goal the command's words raise doubts about (the parser did not read the "
                                "command) ends the run, not executed, instead of being accepted with a warning")] = False,
    last: Annotated[bool, Doc("this is the loop's last round: a refusal nothing confirms or denies is then final")] = False,
) -> CheckOutputs:
    """``ok``: the reading agrees with the offline reading, or the parser does not read the
    command (its words raise doubts at most: accepted, the doubts in ``disagreement`` as
    warnings; with ``strict`` the run ends instead, TranslationError); ``messages``: a firm
    disagreement as feedback for the next round; ``refusal``: final only when the command makes
    the goal impossible, else None (the verifier's refusal of a goal the model invented is in
    ``messages`` instead); ``disagreement``: the doubts an accepted reading carries, else empty."""
    if resolve_model(model) == "offline" or reader == "offline":  # the reading is the parser's own
        return {"ok": True, "messages": [], "refusal": refusal, "disagreement": [], "basis": "none"}
    domain = task_domain(world)
    if domain.supports(Capability.SECOND_OPINION):
        opinion = domain.second_opinion(command, world, goal, constraints, refusal, last)
    else:  # a domain whose goals are not compared: only whether a refusal is final
        if strict:  # nothing can check the model's reading: offline-first executes only the parser's
            raise TranslationError(f"the offline parser does not read the command, and the {domain.name} domain "
                                   "cannot check a model's reading of it, so it is not executed; say the command "
                                   "in words the parser reads, or run without reader=offline-first")
        opinion = refusal_opinion(command, world, refusal, last)
    for line in opinion.disagreement:
        ctx.log(f"check ({opinion.basis}): {line}")
    doubts = [] if opinion.firm else list(opinion.disagreement)
    ok = not opinion.firm and not opinion.messages
    ctx.write_artifact("check.json", {"basis": opinion.basis, "disagreement": opinion.disagreement,
                                      "messages": opinion.messages, "refusal": opinion.refusal,
                                      "reading": opinion.reading, "ok": ok, "strict": strict})
    if strict and doubts and opinion.refusal is None:
        raise TranslationError(
            "the offline parser does not read the command, and the model's reading of it is not executed: the "
            "command's words raise doubts about it (" + "; ".join(doubts) + "); say the command in words the "
            "parser reads, or run without reader=offline-first")
    accepted = [f"warning: accepted although the parser does not read the command and its words raise a doubt: "
                f"{line}" for line in doubts] if ok and opinion.refusal is None else []
    return {"ok": ok, "messages": [] if ok else opinion.messages, "refusal": opinion.refusal,
            "disagreement": accepted, "basis": opinion.basis}


def _log(ctx: StepContext, message: str) -> None:
    """The generator's log lines; those it marks ``warning:`` (an unwritable response cache)
    become warnings of the run, which the user sees without ``-v``."""
    if message.startswith("warning: "):
        ctx.warn(message[len("warning: "):])
    else:
        ctx.log(message)


@step(
    "llm.team_plan",
    doc="The paper's 'w/o D' ablation: a model designs its own team-level actions (no PDDL domain shown) and "
        "writes the team plan with them; the answer (JSON) is read as data and each step mapped onto the task "
        "domain's executable team actions where it fits one (pipflow.language.teamplan).",
    outputs={"plan": "array", "problem": "string", "designed": "array", "steps": "array", "constraints": "array",
             "messages": "array", "response": "string", "usage": "object", "reader": "string"},
)
def llm_team_plan(
    ctx: StepContext,
    command: Annotated[str, Doc("the natural-language command")],
    world: Annotated[dict, Doc("the world (output of world.load or a domain's own load step)")],
    domain: Annotated[PathStr, Doc("the task domain's team-level PDDL domain: NOT shown to the model; its action "
                                   "schemas decide which of the model's steps the robots can execute")],
    prompt: Annotated[str, Check(prompt_problem), Doc("template name in prompts/ or a path (the world, the "
                                                      "command and the answer's JSON form; no PDDL domain)")],
    model: Annotated[str | None, Doc("litellm model string or local/smollm2 (offline has no model: a user error)")] = None,
    temperature: Annotated[float, Doc("sampling temperature (0: the most likely answer)")] = 0.0,
    max_tokens: Annotated[int | None, Doc("most tokens of the answer; unset: 1536")] = None,
    timeout: Annotated[float, Doc("seconds per call")] = 60.0,
    retries: Annotated[int, Doc("extra tries on rate limits, time-outs, server errors (2: at most 3 requests)")] = 2,
    api_base: Annotated[str | None, Doc("base URL of an OpenAI-compatible server")] = None,
    cache_dir: Annotated[PathStr | None, Doc("response cache folder (default .pipflow-cache/llm)")] = None,
    cache: Annotated[bool, Doc("replay cached responses; false always calls the model")] = True,
    deadline: Annotated[float | None, Doc("seconds for the whole call, retries and waits included")] = None,
) -> dict:
    """One answer, no refinement rounds: without a PDDL domain there is no problem for the
    debugger, planner and verifier to check (docs/paper.md, "Ablations"). A plan with a step the
    robots cannot execute is not executed: the step fails naming every such step (the mapping of
    each step is the artifact ``team_plan.json``); ``{"refuse": "why"}`` is a refusal (exit 3).
    ``problem`` is the world's own problem (its initial state), which the dependency graph reads."""
    resolved = require_model(model, "the team plan of the w/o D ablation (llm.team_plan)")
    path = ctx.resolve_path(domain)
    try:
        domain_text = path.read_text(encoding="utf-8")
    except OSError as exc:
        raise InputError(f"domain file {path}: {exc.strerror}") from None
    tdomain = task_domain(world)
    problem = tdomain.example_problem(world, domain_text) or tdomain.write_problem(
        world, {}, pddl_domain_name(domain_text, tdomain.name))
    ctx.check_readable(find_template(prompt, ctx.base_dir), f"step {ctx.step_id!r}: prompt template {prompt!r}",
                       named_as=prompt)
    messages = render(prompt, {"command": command, "world": world, "fields": list(tdomain.rule_fields)},
                      ctx.base_dir)
    responses = ResponseCache(ctx.resolve_path(cache_dir) if cache_dir else None) if cache and ctx.use_cache else None
    answer = ask(messages, stop=["\nCommand:"],
                 call=ModelCall(model=resolved, api_base=api_base, temperature=temperature,
                                max_tokens=max_tokens or 1536, named=ctx.named_by_user,
                                retry=Retry(timeout=timeout, retries=retries, deadline=deadline)),
                 record=RoundRecord(save=ctx.write_artifact, log=lambda m: _log(ctx, m), cache=responses))
    ctx.metrics["llm"] = answer["usage"]
    try:
        read = read_team_plan(answer["text"], domain_text, problem, world, tdomain.rule_fields)
    except ParseIssue as issue:
        raise StepError(f"the model's team plan cannot be read: {issue}") from None
    ctx.write_artifact("team_plan.json", {"designed": read.designed, "steps": read.steps,
                                          "problems": read.problems, "refusal": read.refusal})
    if read.refusal is not None:
        raise Refusal(f"the model refused the command: {read.refusal}")
    if read.problems:
        raise StepError(f"the model's team plan has {len(read.problems)} step(s) the robots cannot execute, so "
                        "none is executed: " + "; ".join(read.problems))
    ctx.write_artifact("plan.txt", format_plan(read.plan))
    ctx.log(f"team plan: {len(read.plan)} step(s) with {len(read.designed)} designed action(s)")
    return {"plan": read.plan, "problem": problem, "designed": read.designed, "steps": read.steps,
            "constraints": read.constraints, "messages": messages, "response": answer["text"][:RESPONSE_OUTPUT_CHARS],
            "usage": answer["usage"], "reader": "model"}

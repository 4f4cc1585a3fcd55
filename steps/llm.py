"""Language steps: the PDDL problem generator (paper, Fig. 1, orange box).

Thin face of :mod:`pipflow.language.generator`; litellm is imported only when a model is called.
"""
from __future__ import annotations

from typing import Annotated

from pipflow import Check, Choices, Doc, PathStr, StepContext, step
from pipflow.errors import InputError, TranslationError
from pipflow.language.agreement import refusal_opinion
from pipflow.language.generator import READERS, generate
from pipflow.language.llm import resolve_model
from pipflow.language.prompting import find_template, prompt_problem
from pipflow.taskdomain import Capability
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
    out = generate(
        command, world, domain_text, prompt=prompt, model=resolved, temperature=temperature,
        max_tokens=max_tokens, timeout=timeout, retries=retries, deadline=deadline, api_base=api_base,
        feedback=feedback, grounded=grounded,
        cache_dir=ctx.resolve_path(cache_dir) if cache_dir else None, use_cache=cache and ctx.use_cache,
        base_dir=ctx.base_dir, save=ctx.write_artifact, log=lambda m: _log(ctx, m), previous=previous,
        reader=reader, named=ctx.named_by_user)
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

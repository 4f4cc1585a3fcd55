"""The PDDL problem generator of the paper (Fig. 1, orange box) for any model.

One round: render the prompt (command, world facts, domain, last round's feedback), answer it
from the response cache or from the model, and read the answer as data. A model that writes
nothing usable does not stop the run: the round returns ``problem: ""`` and ``errors`` that say
precisely why, for the debugger/verifier loop to feed back. Model ``offline`` needs no prompt at
all: the deterministic translator reads the command and the problem writer writes the problem.

The generator serves every task domain (``world["domain"]``, :mod:`pipflow.taskdomains`): the
domain gives the default prompt template, the offline reader and problem writer, the example
problem shown in the prompt, the fields a robot-use rule may name, grounded decoding (if it has
it) and what to learn from a model's problem (its goal, an explanation). Prompt rendering, the
model call, the cache and the PDDL extraction are the same for all.
"""
from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Any

from pipflow.errors import InputError
from pipflow.language.agreement import offline_reading
from pipflow.language.budget import FREE_STOPS, answer_budget
from pipflow.language.feedback import vary
from pipflow.language.asking import ModelCall, RoundRecord, answer
from pipflow.language.llm import resolve_model
from pipflow.language.offline import offline
from pipflow.language.parsing import ParseIssue, extract_constraints, extract_problem, validate_constraints
from pipflow.language.prompting import render
from pipflow.pddl.common import parse
from pipflow.pddl.debugger import unclosed_section
from pipflow.pddl.size import expected_size, size_issues
from pipflow.taskdomain import Capability, TaskDomain
from pipflow.taskdomains import task_domain

#: who reads the command: ``model`` (every command, the paper's way), or ``offline-first`` (the
#: offline parser when it understands the command, the model only for what it refuses as not
#: understood)
READERS = ("model", "offline-first")

#: the head of an answer kept in the round record, for quoting it back when the next prompt
#: would repeat (the whole answer is the artifact response.txt)
ROUND_ANSWER_CHARS = 6000


def _digest(messages: list[dict[str, str]], temperature: float | None = None) -> str:
    """A short fingerprint of a prompt (and its temperature): rounds compare prompts by it."""
    import hashlib
    import json

    return hashlib.sha256(json.dumps([messages, temperature], sort_keys=True).encode()).hexdigest()[:16]


def default_prompt(world: Any) -> str:
    """The prompt template of the world's task domain."""
    return task_domain(world).default_prompt


def grounding_method(model: str, api_base: str | None) -> str:
    """``gbnf`` for llama.cpp servers (local aliases, or any self-hosted ``api_base``), else
    ``json_schema`` (OpenAI-style structured output, which litellm maps for other providers)."""
    return "gbnf" if model.startswith("local/") or api_base else "json_schema"


def request_extra(method: str, world: dict, domain: TaskDomain | None = None) -> dict[str, Any]:
    """The request fields that constrain decoding (the world's domain's grounding: ``domain``,
    when the caller has it already); part of the cache key."""
    domain = domain or task_domain(world)
    if not domain.supports(Capability.GROUNDED_DECODING):
        raise InputError(f"grounded decoding is not available for {domain.name} worlds")
    if method == "gbnf":
        return {"extra_body": {"grammar": domain.grounding_gbnf(world)}}  # type: ignore[attr-defined]
    return {"response_format": domain.grounding_schema(world)}  # type: ignore[attr-defined]


@dataclass(frozen=True)
class LoopRound:
    """Where the round stands in the refinement loop: the checks' ``feedback`` on the last round,
    the last round's ``round`` output (``previous``: it carries the fingerprints of every earlier
    prompt), and who reads the command (``reader``, one of :data:`READERS`). ``locate`` False: an
    answer whose problem never closes is said to be cut off, without the debugger's reading of
    which section is left open (the 'w/o B' ablation has no debugger)."""

    feedback: list[str] | None = None
    previous: dict[str, Any] | None = None
    reader: str = "model"
    locate: bool = True
    #: the candidate reading a user chose after a refusal that offered several (1-based; issue 23)
    reading: int | None = None


@dataclass
class _Prompt:
    """The messages a round sends, and how they came to be: the fingerprint of the prompt before
    any variation (``base``), the variation ``level`` and what it ``varied``, the temperature the
    call uses, and the fingerprints of the loop's earlier prompts (``history``)."""

    messages: list[dict[str, str]]
    base: str
    level: int
    varied: list[str]
    temperature: float
    history: list


def generate(
    command: str,
    world: dict,
    domain_text: str,
    *,
    prompt: str | None = None,
    base_dir: Path | None = None,
    call: ModelCall = ModelCall(),
    loop: LoopRound = LoopRound(),
    record: RoundRecord = RoundRecord(),
) -> dict[str, Any]:
    """One generator round; returns the outputs of step ``llm.problem``. ``prompt`` None: the
    world's domain's template (:attr:`pipflow.taskdomain.TaskDomain.default_prompt`), found from
    ``base_dir``.

    When this round's prompt would be the same as an earlier one's (:attr:`LoopRound.previous`),
    the prompt is varied (:func:`pipflow.language.feedback.vary`) and the ``varied`` output says
    how. Reader ``offline-first``: the offline reading when the parser understands the command
    (and its Refusal when it finds it impossible), the model only when it does not understand it.
    The output ``reader`` says whose reading the round's goal is (``offline`` or ``model``)."""
    model = resolve_model(call.model)
    domain = task_domain(world)
    if loop.reader not in READERS:
        raise InputError(f"reader {loop.reader!r}: expected one of {', '.join(READERS)}")
    if model == "offline":
        return {**offline(command, world, domain_text, record.save, loop.reading, domain), "reader": "offline"}
    if loop.reader == "offline-first":
        state, why = offline_reading(command, world)
        if state != "unread":  # read, or refused as impossible: the parser's word stands
            return {**offline(command, world, domain_text, record.save, loop.reading, domain), "reader": "offline"}
        record.log(f"offline-first: the parser does not read the command ({why}); asking {model}")
    if not isinstance(command, str) or not command.strip():
        raise InputError("command must be a non-empty string")
    if call.grounded and not domain.supports(Capability.GROUNDED_DECODING):
        raise InputError(f"grounded decoding is not available for {domain.name} worlds yet: run without "
                         "grounded (the debugger checks every name against the world)")
    feedback = [str(m) for m in (loop.feedback or []) if str(m).strip()]
    example = domain.example_problem(world, domain_text)
    variables = {"command": command, "world": world, "domain": domain_text, "feedback": feedback,
                 "grounded": bool(call.grounded), "example": example if not call.grounded else None}
    sent = _round_prompt(prompt or domain.default_prompt, variables, base_dir, call, loop.previous)
    if sent.varied:
        record.log(f"llm: the prompt would repeat an earlier round's: {'; '.join(sent.varied)}")
    max_tokens = call.max_tokens
    if max_tokens is None:
        reading = None
        if call.grounded:
            state, got = offline_reading(command, world)
            reading = got if state == "read" else None
        max_tokens = answer_budget(world, domain if call.grounded else None, example, reading)  # type: ignore[arg-type]
    extra = request_extra(grounding_method(model, call.api_base), world, domain) if call.grounded else {}
    if not call.grounded:
        extra = {**extra, "stop": list(FREE_STOPS)}
    params = {"temperature": sent.temperature, "max_tokens": max_tokens, **extra}
    text, invalid, usage, key = answer(model, sent.messages, params, extra, call, record)
    out = {"messages": sent.messages, "response": text, "usage": {**usage, "cache_key": key},
           "varied": "; ".join(sent.varied), "reader": "model",
           "round": {"base": sent.base, "sent": _digest(sent.messages, sent.temperature), "level": sent.level,
                     "answer": text[:ROUND_ANSWER_CHARS], "max_tokens": max_tokens, "history": sent.history}}
    out.update(_read_answer(text, world, call.grounded, domain_text, domain, loop.locate, example))
    if invalid:
        out.update(problem="", goal=None, errors=[
            f"the answer has {invalid} character{'s' if invalid > 1 else ''} that are not valid Unicode text (lone "
            "surrogates, such as an escaped \\ud800), shown here as U+FFFD: write plain text"] + list(out["errors"]))
    if usage.get("finish_reason") == "length" and out.get("errors"):  # the model must shorten, not we raise
        out["errors"] = out["errors"] + [
            f"the answer was cut off at the {max_tokens} tokens it may take: write only what the command asks "
            + ("for: one statement per clause of the command, rules only if it states them, short \"words\""
               if call.grounded else "for, and no text after the ```json block")]
    if record.save is not None and not call.grounded and out["goal"] is not None:  # a goal read back from the problem
        record.save("goal.json", out["goal"])
    return out


def _round_prompt(template: str, variables: dict[str, Any], base_dir: Path | None, call: ModelCall,
                  previous: Any) -> _Prompt:
    """The round's prompt: the template rendered with the command, the world, the domain, the
    example and the feedback (``variables``); varied, one level further each time, while it would
    be the same as a prompt an earlier round of the loop sent (feedback may also cycle: A, B, A)."""
    world, feedback = variables["world"], variables["feedback"]
    base = render(template, variables, base_dir)
    base_digest = _digest(base)
    previous = previous if isinstance(previous, dict) else {}
    # every earlier round of this loop: feedback may also cycle (A, B, A), not only repeat
    history = [h for h in previous.get("history") or [] if isinstance(h, list) and len(h) == 2]
    if previous.get("base"):
        history.append([previous["base"], previous.get("sent")])
    level = int(previous.get("level") or 0) + 1 if feedback and base_digest in {b for b, _ in history} else 0
    messages, varied = base, []
    while True:  # vary until the prompt differs from every one sent before (each level adds a line)
        if level:
            extra, temperature_now, varied = vary(level, str(previous.get("answer") or ""), feedback, world,
                                                  bool(call.grounded), call.temperature)
            messages = render(template, {**variables, "feedback": feedback + extra}, base_dir)
        else:
            temperature_now = call.temperature
        if _digest(messages, temperature_now) not in {sent for _, sent in history} or level >= 8:
            break
        level += 1
    return _Prompt(messages, base_digest, level, varied, temperature_now, history)


def _read_answer(text: str, world: dict, grounded: bool, domain_text: str, domain: TaskDomain,
                 locate: bool = True, example: str | None = None) -> dict[str, Any]:
    """Problem, goal (grounded, or read back from the problem by the domain), constraints and
    errors of one answer. A problem that declares far more than a problem of this world holds
    (``example``, :mod:`pipflow.pddl.size`) is not parsed: the errors say what to leave out."""
    if grounded and domain.supports(Capability.GROUNDED_DECODING):  # the answer is an order: checked, resolved, written
        try:
            return domain.read_grounded(text, world)  # type: ignore[attr-defined]
        except ParseIssue as issue:
            return {"problem": "", "goal": None, "constraints": [], "errors": [str(issue)]}
    errors, problem, constraints = [], "", []
    try:
        problem = extract_problem(text)
    except ParseIssue as issue:
        errors.append(str(issue) + (_unclosed_hint(text) if locate else ""))
    too_large = size_issues(problem, expected_size(world, example)) if problem else []
    if too_large:  # parsing it would cost minutes: the model is told what to leave out instead
        errors += too_large
        problem = ""
    try:
        constraints = validate_constraints(extract_constraints(text, domain.rule_fields), world, domain.rule_fields,
                                           domain=domain)
    except ParseIssue as issue:
        errors.append(str(issue))
    out = {"problem": problem, "goal": None, "constraints": constraints, "errors": errors}
    parsed = _parse_quietly(domain_text, problem) if problem else None
    if parsed is not None:  # what the domain learns from the model's problem (its goal, an explanation)
        learned = dict(domain.read_problem(parsed, world, constraints))
        if learned.get("errors"):
            out["errors"] = errors + list(learned.pop("errors"))
            out["problem"] = ""
        learned.pop("errors", None)
        out.update(learned)
    return out


def _unclosed_hint(text: str) -> str:
    """For a problem whose parentheses never balance: which section is left open and where it
    opened (the debugger's reading, lines counted from ``(define``), or ``""``."""
    import re


    starts = [m.start() for m in re.finditer(r"\(\s*define\s*\(\s*problem\b", text, re.IGNORECASE)]
    if not starts:
        return ""
    body = text[starts[-1]:].split("```", 1)[0]
    hint = unclosed_section(body)
    return f" Counting lines from `(define`: {hint}" if hint else ""


def _parse_quietly(domain_text: str, problem: str) -> Any:
    """The UP problem, or None if it does not parse (the debugger explains that)."""
    if not domain_text:
        return None
    try:
        return parse(domain_text, problem)
    except Exception:
        return None

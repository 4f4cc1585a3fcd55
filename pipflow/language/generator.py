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

import os
from pathlib import Path
from typing import Any, Callable

from pipflow.errors import InputError
from pipflow.language.agreement import offline_reading
from pipflow.language.budget import FREE_STOPS, answer_budget
from pipflow.language.cache import ResponseCache, cache_key
from pipflow.language.feedback import vary
from pipflow.language.llm import complete, resolve_model
from pipflow.language.local import ensure_server
from pipflow.language.offline import offline
from pipflow.language.parsing import ParseIssue, extract_constraints, extract_problem, validate_constraints
from pipflow.language.prompting import render
from pipflow.pddl.common import parse
from pipflow.pddl.debugger import unclosed_section
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


def generate(
    command: str,
    world: dict,
    domain_text: str,
    *,
    prompt: str | None = None,
    model: str | None = None,
    temperature: float = 0.0,
    max_tokens: int | None = None,
    timeout: float = 60.0,
    retries: int = 2,
    deadline: float | None = None,
    api_base: str | None = None,
    feedback: list[str] | None = None,
    grounded: bool = False,
    cache_dir: str | os.PathLike | None = None,
    use_cache: bool = True,
    base_dir: Path | None = None,
    save: Callable[[str, Any], Any] | None = None,
    log: Callable[[str], None] = lambda message: None,
    previous: dict[str, Any] | None = None,
    reader: str = "model",
    named: Callable[[str], bool] | None = None,
) -> dict[str, Any]:
    """One generator round; returns the outputs of step ``llm.problem``. ``prompt`` None: the
    world's domain's template (:attr:`pipflow.taskdomain.TaskDomain.default_prompt`).

    ``max_tokens`` None: a budget from the expected answer's size (:mod:`pipflow.language.budget`).
    ``previous``: the previous round's ``round`` output (it carries the fingerprints of every
    earlier prompt of the loop); when this round's prompt would be the same as an earlier one's,
    the prompt is varied (:func:`pipflow.language.feedback.vary`) and the ``varied`` output says
    how. ``reader`` ``offline-first``: the offline reading when the parser understands the command
    (and its Refusal when it finds it impossible), the model only when it does not understand it.
    The output ``reader`` says whose reading the round's goal is (``offline`` or ``model``).
    ``named(value)``: whether the user gave a value (a server that may receive the provider
    key: :func:`pipflow.language.llm.key_may_go_to`)."""
    model = resolve_model(model)
    domain = task_domain(world)
    if reader not in READERS:
        raise InputError(f"reader {reader!r}: expected one of {', '.join(READERS)}")
    if model == "offline":
        return {**offline(command, world, domain_text, save, domain), "reader": "offline"}
    if reader == "offline-first":
        state, why = offline_reading(command, world)
        if state != "unread":  # read, or refused as impossible: the parser's word stands
            return {**offline(command, world, domain_text, save, domain), "reader": "offline"}
        log(f"offline-first: the parser does not read the command ({why}); asking {model}")
    if not isinstance(command, str) or not command.strip():
        raise InputError("command must be a non-empty string")
    if grounded and not domain.supports(Capability.GROUNDED_DECODING):
        raise InputError(f"grounded decoding is not available for {domain.name} worlds yet: run without "
                         "grounded (the debugger checks every name against the world)")
    feedback = [str(m) for m in (feedback or []) if str(m).strip()]
    example = domain.example_problem(world, domain_text)
    variables = {"command": command, "world": world, "domain": domain_text, "feedback": feedback,
                 "grounded": bool(grounded), "example": example if not grounded else None}
    base = render(prompt or domain.default_prompt, variables, base_dir)
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
                                                  bool(grounded), temperature)
            messages = render(prompt or domain.default_prompt, {**variables, "feedback": feedback + extra}, base_dir)
        else:
            temperature_now = temperature
        if _digest(messages, temperature_now) not in {sent for _, sent in history} or level >= 8:
            break
        level += 1
    if varied:
        log(f"llm: the prompt would repeat an earlier round's: {'; '.join(varied)}")
    if max_tokens is None:
        reading = None
        if grounded:
            state, got = offline_reading(command, world)
            reading = got if state == "read" else None
        max_tokens = answer_budget(world, bool(grounded), example, reading)
    extra = request_extra(grounding_method(model, api_base), world, domain) if grounded else {}
    if not grounded:
        extra = {**extra, "stop": list(FREE_STOPS)}
    params = {"temperature": temperature_now, "max_tokens": max_tokens, **extra}
    if save is not None:  # the prompt is kept even when the call fails (provider error, time-out)
        save("messages.json", messages)
    key = cache_key(model, messages, params)
    cache = ResponseCache(cache_dir)
    use_cache = use_cache and os.environ.get("PIPFLOW_NO_CACHE", "") in ("", "0")
    entry = cache.get(key) if use_cache else None
    if entry is not None:
        text, usage = entry["text"], {**entry["usage"], "cached": True, "latency_s": 0.0}
        log(f"llm: {model} answered from cache {cache.path(key)}")
    else:
        call_model, call_base = model, api_base
        if model.startswith("local/"):
            call_model, call_base = ensure_server(model)
        answer = complete(messages, model=call_model, api_base=call_base, timeout=timeout,
                          retries=retries, temperature=temperature_now, max_tokens=max_tokens,
                          extra=extra, deadline=deadline, named=named)
        text, usage = answer.text, answer.usage
        log(f"llm: {model} answered in {usage['latency_s']} s, {usage.get('total_tokens')} tokens")
    if save is not None:  # the record first: a paid answer is kept even if the cache is not writable
        save("response.txt", text)
    if entry is None and use_cache:  # --no-cache writes no cache either
        try:
            cache.put(key, {"model": model, "params": params, "messages": messages, "text": text,
                            "usage": usage})
        except OSError as exc:
            log(f"warning: llm: the response cache {cache.directory} is not writable "
                f"({exc.strerror or exc}); the answer is kept in the run record only")
    out = {"messages": messages, "response": text, "usage": {**usage, "cache_key": key},
           "varied": "; ".join(varied), "reader": "model",
           "round": {"base": base_digest, "sent": _digest(messages, temperature_now), "level": level,
                     "answer": text[:ROUND_ANSWER_CHARS], "max_tokens": max_tokens, "history": history}}
    out.update(_read_answer(text, world, grounded, domain_text, domain))
    if usage.get("finish_reason") == "length" and out.get("errors"):  # the model must shorten, not we raise
        out["errors"] = out["errors"] + [
            f"the answer was cut off at the {max_tokens} tokens it may take: write only what the command asks "
            + ("for: one statement per clause of the command, rules only if it states them, short \"words\""
               if grounded else "for, and no text after the ```json block")]
    if save is not None and not grounded and out["goal"] is not None:  # a goal read back from the problem
        save("goal.json", out["goal"])
    return out


def _read_answer(text: str, world: dict, grounded: bool, domain_text: str, domain: TaskDomain) -> dict[str, Any]:
    """Problem, goal (grounded, or read back from the problem by the domain), constraints and
    errors of one answer."""
    if grounded and domain.supports(Capability.GROUNDED_DECODING):  # the answer is an order: checked, resolved, written
        try:
            return domain.read_grounded(text, world)  # type: ignore[attr-defined]
        except ParseIssue as issue:
            return {"problem": "", "goal": None, "constraints": [], "errors": [str(issue)]}
    errors, problem, constraints = [], "", []
    try:
        problem = extract_problem(text)
    except ParseIssue as issue:
        errors.append(str(issue) + _unclosed_hint(text))
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

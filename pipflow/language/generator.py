"""The PDDL problem generator of the paper (Fig. 1, orange box) for any model.

One round: render the prompt (command, world facts, domain, last round's feedback), answer it
from the response cache or from the model, and read the answer as data. A model that writes
nothing usable does not stop the run: the round returns ``problem: ""`` and ``errors`` that say
precisely why, for the debugger/verifier loop to feed back. Model ``offline`` needs no prompt at
all: the deterministic translator reads the command and the problem writer writes the problem.
"""
from __future__ import annotations

import os
from pathlib import Path
from typing import Any, Callable

from pipflow.errors import InputError
from pipflow.language import grounding
from pipflow.language.cache import ResponseCache, cache_key
from pipflow.language.llm import complete, resolve_model
from pipflow.language.parsing import ParseIssue, extract_constraints, extract_problem, validate_constraints
from pipflow.language.prompting import render

NO_USAGE: dict[str, Any] = {"calls": 0, "cached": False, "prompt_tokens": 0, "completion_tokens": 0,
                            "total_tokens": 0, "latency_s": 0.0, "cost_usd": 0.0}


def write_problem(world: dict, goal: dict) -> str:
    """The problem writer of :mod:`pipflow.pddl.writer` (imported late, like every pddl helper)."""
    from pipflow.pddl.writer import write_problem as writer

    return writer(world, goal)


def grounding_method(model: str, api_base: str | None) -> str:
    """``gbnf`` for llama.cpp servers (local aliases, or any self-hosted ``api_base``), else
    ``json_schema`` (OpenAI-style structured output, which litellm maps for other providers)."""
    return "gbnf" if model.startswith("local/") or api_base else "json_schema"


def request_extra(method: str, world: dict) -> dict[str, Any]:
    """The request fields that constrain decoding; part of the cache key."""
    if method == "gbnf":
        return {"extra_body": {"grammar": grounding.gbnf(world)}}
    return {"response_format": grounding.response_format(world)}


def offline(command: str, world: dict) -> dict[str, Any]:
    """Model ``offline``: the translator's goal and constraints, written as PDDL."""
    from pipflow.language.translator import translate

    result = translate(command, world)
    return {"problem": write_problem(world, result["goal"]), "goal": result["goal"],
            "constraints": list(result.get("constraints") or []), "messages": [], "response": "",
            "usage": dict(NO_USAGE), "errors": []}


def generate(
    command: str,
    world: dict,
    domain_text: str,
    *,
    prompt: str = "warehouse_problem",
    model: str | None = None,
    temperature: float = 0.0,
    max_tokens: int = 1024,
    timeout: float = 60.0,
    retries: int = 2,
    api_base: str | None = None,
    feedback: list[str] | None = None,
    grounded: bool = False,
    cache_dir: str | os.PathLike | None = None,
    use_cache: bool = True,
    base_dir: Path | None = None,
    save: Callable[[str, Any], Any] | None = None,
    log: Callable[[str], None] = lambda message: None,
) -> dict[str, Any]:
    """One generator round; returns the outputs of step ``llm.problem``."""
    model = resolve_model(model)
    if model == "offline":
        return offline(command, world)
    if not isinstance(command, str) or not command.strip():
        raise InputError("command must be a non-empty string")
    feedback = [str(m) for m in (feedback or []) if str(m).strip()]
    messages = render(prompt, {"command": command, "world": world, "domain": domain_text,
                               "feedback": feedback, "grounded": bool(grounded),
                               "example": _example(world) if not grounded else None}, base_dir)
    extra = request_extra(grounding_method(model, api_base), world) if grounded else {}
    params = {"temperature": temperature, "max_tokens": max_tokens, **extra}
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
            from pipflow.language.local import ensure_server

            call_model, call_base = ensure_server(model)
        answer = complete(messages, model=call_model, api_base=call_base, timeout=timeout,
                          retries=retries, temperature=temperature, max_tokens=max_tokens,
                          extra=extra)
        text, usage = answer.text, answer.usage
        cache.put(key, {"model": model, "params": params, "messages": messages, "text": text,
                        "usage": usage})
        log(f"llm: {model} answered in {usage['latency_s']} s, {usage.get('total_tokens')} tokens")
    if save is not None:
        save("messages.json", messages)
        save("response.txt", text)
    out = {"messages": messages, "response": text, "usage": {**usage, "cache_key": key}}
    out.update(_read_answer(text, world, grounded))
    return out


def _read_answer(text: str, world: dict, grounded: bool) -> dict[str, Any]:
    """Problem, goal (grounded only), constraints and errors of one answer."""
    if grounded:
        try:
            goal, constraints = grounding.parse_answer(text, world)
        except ParseIssue as issue:
            return {"problem": "", "goal": None, "constraints": [], "errors": [str(issue)]}
        return {"problem": write_problem(world, goal), "goal": goal, "constraints": constraints,
                "errors": []}
    errors, problem, constraints = [], "", []
    try:
        problem = extract_problem(text)
    except ParseIssue as issue:
        errors.append(str(issue))
    try:
        constraints = validate_constraints(extract_constraints(text), world)
    except ParseIssue as issue:
        errors.append(str(issue))
    return {"problem": problem, "goal": None, "constraints": constraints, "errors": errors}


def _example(world: dict) -> str | None:
    """A problem for this world (its current stock as the goal) to show the expected form, or
    None while no problem writer is installed."""
    stock = {s: dict(items) for s, items in world.get("stock", {}).items() if items}
    try:
        return write_problem(world, stock)
    except ImportError:
        return None

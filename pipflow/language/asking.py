"""One question to a language model that is not the problem generator's: answered from the
response cache or by the model, and kept in the run record.

Why a module of its own: the generator (:mod:`pipflow.language.generator`) has its own round
logic (feedback, varied prompts, grounded decoding); the ablations' model steps (the team plan
without a PDDL domain, the allocation by a model) ask plainer questions, but they must keep the
same guarantees: the rendered messages are recorded before the call (kept when it fails), the
raw answer is recorded before it is read, answers are cached by content (model, messages,
parameters) so an experiment replays offline, ``local/...`` aliases start their loopback server,
and pipflow's one retry layer (:func:`pipflow.language.llm.complete`) is the only one. The answer
is text: callers read it as data (JSON), never run it.
"""
from __future__ import annotations

import os
from typing import Any, Callable

from pipflow.errors import InputError
from pipflow.language.cache import ResponseCache, cache_key
from pipflow.language.llm import complete, resolve_model
from pipflow.language.local import ensure_server

#: what a step needs from its caller to keep records: ``save(name, data)`` (an artifact)
Save = Callable[[str, Any], Any]


def require_model(model: str | None, what: str) -> str:
    """The resolved model string; ``offline`` (no model) is the user's error for a step that
    only a model can do (``what`` says which), exit 2 before anything is asked."""
    resolved = resolve_model(model)
    if resolved == "offline":
        raise InputError(f"{what} is a language model's work, and the model is `offline` (the default): "
                         "give one, e.g. -i model=openai/gpt-4o, or -i model=local/smollm2 to try it "
                         "with a tiny local model")
    return resolved


def ask(messages: list[dict[str, str]], *, model: str, api_base: str | None = None,
        temperature: float = 0.0, max_tokens: int = 2048, timeout: float = 60.0, retries: int = 2,
        deadline: float | None = None, stop: list[str] | None = None,
        cache_dir: str | os.PathLike | None = None, use_cache: bool = True,
        save: Save | None = None, name: str = "", log: Callable[[str], None] = lambda m: None,
        named: Callable[[str], bool] | None = None) -> dict[str, Any]:
    """``{"text", "usage"}`` of one answer to ``messages``. ``name`` prefixes the artifacts
    (``<name>messages.json``, ``<name>response.txt``), so a step that asks several times keeps
    every question and answer. ``model`` must be a real model (see :func:`require_model`).
    ``named(value)``: whether the user gave a value, so the provider key may go to an ``api_base``
    the user named and never to one only a workflow file names
    (:func:`pipflow.language.llm.key_may_go_to`)."""
    model = resolve_model(model)
    params: dict[str, Any] = {"temperature": temperature, "max_tokens": max_tokens}
    if stop:
        params["stop"] = list(stop)
    if save is not None:  # the question is kept even when the call fails
        save(f"{name}messages.json", messages)
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
        answer = complete(messages, model=call_model, api_base=call_base, timeout=timeout, retries=retries,
                          temperature=temperature, max_tokens=max_tokens,
                          extra={"stop": list(stop)} if stop else None, deadline=deadline, named=named)
        text, usage = answer.text, answer.usage
        log(f"llm: {model} answered in {usage['latency_s']} s, {usage.get('total_tokens')} tokens")
    if save is not None:  # the record first: a paid answer is kept even if the cache is not writable
        save(f"{name}response.txt", text)
    if entry is None and use_cache:
        try:
            cache.put(key, {"model": model, "params": params, "messages": messages, "text": text, "usage": usage})
        except OSError as exc:
            log(f"warning: llm: the response cache {cache.directory} is not writable "
                f"({exc.strerror or exc}); the answer is kept in the run record only")
    return {"text": text, "usage": {**usage, "cache_key": key}}

"""One question to a language model and its answer as text, cached and recorded.

The problem generator (:mod:`pipflow.language.generator`) asks for a PDDL problem and reads it in
the same call; the paper's baselines (:mod:`pipflow.baselines`) ask several questions in a row
(decompose, allocate, write code) and read only the last answer, each in its own format. What
they share is here: the ``local/`` alias starts its loopback server, the response cache answers a
question asked before (same model, messages and parameters: a committed experiment replays
offline), the provider is called through :func:`pipflow.language.llm.complete` (its one retry
layer, its time-outs) otherwise, and the messages and the answer are kept in the run record
before anything reads them, so a paid answer is never lost to a reader that refuses it.
"""
from __future__ import annotations

import os
from dataclasses import dataclass, field
from typing import Any, Callable

from pipflow.errors import InputError
from pipflow.language.cache import ResponseCache, cache_key
from pipflow.language.llm import complete, resolve_model
from pipflow.language.local import ensure_server

#: ``save(name, data)``: keep an artifact of the step (the engine's ``ctx.write_artifact``)
Save = Callable[[str, Any], Any]


@dataclass(frozen=True)
class Answer:
    """The text of an answer and what it cost (``cached``: replayed from the response cache)."""

    text: str
    usage: dict[str, Any] = field(default_factory=dict)


def needs_model(model: str | None, purpose: str) -> str:
    """The model to ask, or :class:`InputError` (exit 2) when the run has none: ``offline`` is
    pipflow's own parser, which answers no free question. ``purpose`` names who asks ("the cot
    baseline"), so the message says what to do."""
    resolved = resolve_model(model)
    if resolved == "offline":
        raise InputError(f"{purpose} needs a language model: -i model=... (openai/gpt-4o, local/smollm2, "
                         "ollama/..., or any litellm model string; the offline parser writes no such answer)")
    return resolved


def ask(messages: list[dict[str, str]], *, model: str, api_base: str | None = None,
        temperature: float = 0.0, max_tokens: int = 1024, stop: list[str] | None = None,
        timeout: float = 60.0, retries: int = 2, deadline: float | None = None,
        cache_dir: str | os.PathLike | None = None, use_cache: bool = True,
        save: Save | None = None, name: str = "answer",
        log: Callable[[str], None] = lambda message: None) -> Answer:
    """Ask ``model`` (a litellm model string or a ``local/`` alias, never ``offline``) and return
    its answer. The messages are saved as ``<name>.messages.json`` before the call, the answer as
    ``<name>.txt`` after it; ``use_cache`` False (or ``PIPFLOW_NO_CACHE``) neither reads nor
    writes the response cache."""
    if model == "offline":
        raise InputError("ask: the offline parser answers no question; name a language model")
    params: dict[str, Any] = {"temperature": temperature, "max_tokens": max_tokens}
    if stop:
        params["stop"] = list(stop)
    if save is not None:
        save(f"{name}.messages.json", messages)
    key = cache_key(model, messages, params)
    cache = ResponseCache(cache_dir)
    use_cache = use_cache and os.environ.get("PIPFLOW_NO_CACHE", "") in ("", "0")
    entry = cache.get(key) if use_cache else None
    if entry is not None:
        text, usage = entry["text"], {**entry["usage"], "cached": True, "latency_s": 0.0}
        log(f"llm: {model} answered {name} from cache {cache.path(key)}")
    else:
        call_model, call_base = model, api_base
        if model.startswith("local/"):
            call_model, call_base = ensure_server(model)
        extra = {"stop": list(stop)} if stop else None
        answer = complete(messages, model=call_model, api_base=call_base, timeout=timeout, retries=retries,
                          temperature=temperature, max_tokens=max_tokens, extra=extra, deadline=deadline)
        text, usage = answer.text, answer.usage
        log(f"llm: {model} answered {name} in {usage['latency_s']} s, {usage.get('total_tokens')} tokens")
    if save is not None:  # the record first: a paid answer is kept even if the cache is not writable
        save(f"{name}.txt", text)
    if entry is None and use_cache:
        try:
            cache.put(key, {"model": model, "params": params, "messages": messages, "text": text, "usage": usage})
        except OSError as exc:
            log(f"warning: llm: the response cache {cache.directory} is not writable "
                f"({exc.strerror or exc}); the answer is kept in the run record only")
    return Answer(text, {**usage, "cache_key": key})


"""One question to a language model: answered from the response cache or by the model, and
kept in the run record.

Why a module of its own: the generator (:mod:`pipflow.language.generator`) adds its round logic
(feedback, varied prompts, grounded decoding) and the ablations' model steps (the team plan
without a PDDL domain, the allocation by a model) ask plainer questions, but every question keeps
the same guarantees: the rendered messages are recorded before the call (kept when it fails), the
raw answer is recorded before it is read, answers are cached by content (model, messages,
parameters) so an experiment replays offline, ``local/...`` aliases start their loopback server,
and pipflow's one retry layer (:func:`pipflow.language.llm.complete`) is the only one. The answer
is text: callers read it as data (JSON), never run it.
"""
from __future__ import annotations

import os
from dataclasses import dataclass, field
from typing import Any, Callable

from pipflow.errors import InputError
from pipflow.language.cache import ResponseCache, cache_key
from pipflow.language.llm import Retry, complete, resolve_model
from pipflow.language.local import ensure_server
from pipflow.language.parsing import plain_text

#: what a step needs from its caller to keep records: ``save(name, data)`` (an artifact)
Save = Callable[[str, Any], Any]


@dataclass(frozen=True)
class ModelCall:
    """Who answers, and how: ``model`` (None: ``$PIPFLOW_MODEL``, else offline), an
    OpenAI-compatible server (``api_base``), the sampling ``temperature``, ``max_tokens`` (None: a
    budget from the expected answer's size, :mod:`pipflow.language.budget`), ``grounded`` decoding
    (the world's names and counts only), how patiently (:class:`~pipflow.language.llm.Retry`), and
    ``named(value)``: whether the user gave a value (a server that may receive the provider key:
    :func:`pipflow.language.llm.key_may_go_to`)."""

    model: str | None = None
    api_base: str | None = None
    temperature: float = 0.0
    max_tokens: int | None = None
    grounded: bool = False
    retry: Retry = Retry()
    named: Callable[[str], bool] | None = None


@dataclass(frozen=True)
class RoundRecord:
    """Where a round leaves what it did: ``save(name, data)`` keeps an artifact (the prompt, the
    answer), ``log(line)`` a log line; ``cache``: the response cache it replays from and fills
    (None: the model is always asked, and nothing is cached)."""

    save: Callable[[str, Any], Any] | None = None
    log: Callable[[str], None] = lambda message: None
    cache: ResponseCache | None = field(default_factory=ResponseCache)


def require_model(model: str | None, what: str) -> str:
    """The resolved model string; ``offline`` (no model) is the user's error for a step that
    only a model can do (``what`` says which), exit 2 before anything is asked."""
    resolved = resolve_model(model)
    if resolved == "offline":
        raise InputError(f"{what} is a language model's work, and the model is `offline` (the default): "
                         "give one, e.g. -i model=openai/gpt-4o, or -i model=local/smollm2 to try it "
                         "with a tiny local model")
    return resolved


def answer(model: str, messages: list[dict[str, str]], params: dict[str, Any], extra: dict[str, Any],
           call: ModelCall, record: RoundRecord, name: str = "") -> tuple[str, int, dict[str, Any], str]:
    """``(text, invalid characters, usage, cache key)`` of one answer to ``messages`` (``params``:
    what the cache key holds; ``extra``: the provider fields among them): replayed from the
    response cache, or asked of the model and then kept. ``name`` prefixes the artifacts
    (``<name>messages.json``, ``<name>response.txt``): the question is kept before the call (and
    when it fails), the answer before the cache (a paid answer is kept even if the cache is not
    writable). A lone surrogate in the answer (a model's escaped ``\\ud800``) is shown as U+FFFD
    and counted: no file or terminal can take it."""
    if record.save is not None:
        record.save(f"{name}messages.json", messages)
    key = cache_key(model, messages, params)
    cache = record.cache if os.environ.get("PIPFLOW_NO_CACHE", "") in ("", "0") else None
    entry = cache.get(key) if cache is not None else None
    if entry is not None:
        text, usage = entry["text"], {**entry["usage"], "cached": True, "latency_s": 0.0}
        record.log(f"llm: {model} answered from cache {cache.path(key)}")
    else:
        call_model, call_base = model, call.api_base
        if model.startswith("local/"):
            call_model, call_base = ensure_server(model)
        got = complete(messages, model=call_model, api_base=call_base, temperature=params["temperature"],
                       max_tokens=params["max_tokens"], extra=extra or None, named=call.named, retry=call.retry)
        text, usage = got.text, got.usage
        record.log(f"llm: {model} answered in {usage['latency_s']} s, {usage.get('total_tokens')} tokens")
    text, invalid = plain_text(text)
    if record.save is not None:
        record.save(f"{name}response.txt", text)
    if entry is None and cache is not None:  # --no-cache writes no cache either
        try:
            cache.put(key, {"model": model, "params": params, "messages": messages, "text": text, "usage": usage})
        except OSError as exc:
            record.log(f"warning: llm: the response cache {cache.directory} is not writable "
                       f"({exc.strerror or exc}); the answer is kept in the run record only")
    return text, invalid, usage, key


def ask(messages: list[dict[str, str]], *, call: ModelCall, record: RoundRecord = RoundRecord(),
        stop: list[str] | None = None, name: str = "") -> dict[str, Any]:
    """``{"text", "usage"}`` of one answer to ``messages`` (:func:`answer`), at ``call.max_tokens``
    (None: 2048). ``call.model`` must be a real model (see :func:`require_model`); the provider key
    goes only to an ``api_base`` the user named (``call.named``,
    :func:`pipflow.language.llm.key_may_go_to`)."""
    model = resolve_model(call.model)
    params: dict[str, Any] = {"temperature": call.temperature,
                              "max_tokens": call.max_tokens if call.max_tokens is not None else 2048}
    extra = {"stop": list(stop)} if stop else {}
    text, _, usage, key = answer(model, messages, {**params, **extra}, extra, call, record, name)
    return {"text": text, "usage": {**usage, "cache_key": key}}

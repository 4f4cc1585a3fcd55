"""Language-model calls through litellm, so any provider works by its model string.

litellm is imported inside :func:`complete` only: its import costs about 2 s, which a run
without an LLM must not pay, and ``LITELLM_LOCAL_MODEL_COST_MAP`` must be set before that import
(otherwise litellm fetches its cost map from the network).

API keys are read by litellm from the environment. Nothing here puts them in a return value, and
:func:`redact` scrubs them from provider error messages before those reach logs or run records.
"""
from __future__ import annotations

import os
import re
import time
from dataclasses import dataclass, field
from typing import Any, Callable

from pipflow.errors import InputError, LLMError

DEFAULT_MODEL = "offline"
#: provider errors worth another try; everything else (bad key, bad request) fails at once
_RETRYABLE = ("RateLimitError", "Timeout", "APIConnectionError", "ServiceUnavailableError",
              "InternalServerError")
_SECRET_ENV = re.compile(r"(KEY|TOKEN|SECRET|PASSWORD)", re.IGNORECASE)


def resolve_model(model: str | None) -> str:
    """The model to use: the argument, else ``PIPFLOW_MODEL``, else the offline translator.

    Workflows should leave ``model`` unset (null) by default so that the environment variable
    can switch a whole run to a provider without editing the file."""
    return (model or os.environ.get("PIPFLOW_MODEL") or DEFAULT_MODEL).strip()


@dataclass
class Completion:
    """The text of one answer and what it cost. ``usage`` holds only JSON-safe numbers."""

    text: str
    usage: dict[str, Any] = field(default_factory=dict)


def redact(message: str) -> str:
    """Remove the values of secret-looking environment variables from a message."""
    for name, value in os.environ.items():
        if value and len(value) >= 8 and _SECRET_ENV.search(name):
            message = message.replace(value, "***")
    return message


def _import_litellm():
    os.environ.setdefault("LITELLM_LOCAL_MODEL_COST_MAP", "True")
    import litellm  # noqa: PLC0415 - deliberately lazy, see module docstring

    litellm.suppress_debug_info = True
    return litellm


def complete(
    messages: list[dict[str, str]],
    *,
    model: str,
    temperature: float = 0.0,
    max_tokens: int = 1024,
    timeout: float = 60.0,
    retries: int = 2,
    api_base: str | None = None,
    extra: dict[str, Any] | None = None,
    backoff: float = 1.0,
    sleep: Callable[[float], None] = time.sleep,
) -> Completion:
    """Ask ``model`` for one chat completion; retry rate limits, time-outs and dropped
    connections ``retries`` times with exponential backoff; raise :class:`LLMError` otherwise.

    ``extra`` carries provider-specific request fields (``response_format``, a llama.cpp
    ``grammar`` in ``extra_body``, litellm's ``mock_response`` in tests)."""
    if retries < 0 or max_tokens <= 0 or timeout <= 0:
        raise InputError("retries must be >= 0, max_tokens and timeout > 0")
    litellm = _import_litellm()
    kwargs: dict[str, Any] = dict(model=model, messages=messages, temperature=temperature,
                                  max_tokens=max_tokens, timeout=timeout, **(extra or {}))
    if api_base:
        kwargs["api_base"] = api_base
        if model.startswith("openai/") and not os.environ.get("OPENAI_API_KEY"):
            kwargs["api_key"] = "no-key"  # self-hosted OpenAI-compatible servers need none
    attempt = 0
    while True:
        start = time.perf_counter()
        try:
            # one of the provider's LLM slots across a dask cluster (a no-op elsewhere)
            from pipflow.executors import llm_slot

            with llm_slot(model):
                response = litellm.completion(**kwargs)
            break
        except Exception as exc:  # litellm maps every provider's error onto its own classes
            kind = type(exc).__name__
            retryable = any(isinstance(exc, getattr(litellm, name, ())) for name in _RETRYABLE)
            if retryable and attempt < retries:
                sleep(backoff * 2 ** attempt)
                attempt += 1
                continue
            tries = f" after {attempt + 1} attempts" if attempt else ""
            hint = (f" (is the server at {api_base} running?)"
                    if api_base and "connection error" in str(exc).lower() else "")
            raise LLMError(f"{model}: {kind}{tries}: {redact(str(exc))}{hint}") from None
    latency = time.perf_counter() - start
    text = response.choices[0].message.content or ""
    return Completion(text=text, usage=_usage(litellm, response, latency, attempt))


def _usage(litellm, response, latency: float, retried: int) -> dict[str, Any]:
    """Tokens, latency and cost (None where litellm does not know the model's price)."""
    u = getattr(response, "usage", None)
    tokens = {k: int(getattr(u, k, 0) or 0) for k in ("prompt_tokens", "completion_tokens",
                                                       "total_tokens")} if u else {}
    try:
        cost = float(litellm.completion_cost(completion_response=response))
    except Exception:  # unknown model price: say so rather than guess 0
        cost = None
    finish = getattr(response.choices[0], "finish_reason", None)
    return {**tokens, "latency_s": round(latency, 3), "cost_usd": cost, "retries": retried,
            "finish_reason": finish, "calls": 1, "cached": False}


def sum_usage(usages: list[dict[str, Any]]) -> dict[str, Any]:
    """Sum per-call usage into per-run totals (cost stays None if any call's cost is unknown)."""
    total: dict[str, Any] = {"calls": 0, "cached": 0, "prompt_tokens": 0, "completion_tokens": 0,
                             "total_tokens": 0, "latency_s": 0.0, "cost_usd": 0.0}
    for u in usages:
        total["calls"] += 1
        total["cached"] += 1 if u.get("cached") else 0
        for k in ("prompt_tokens", "completion_tokens", "total_tokens"):
            total[k] += int(u.get(k) or 0)
        total["latency_s"] = round(total["latency_s"] + float(u.get("latency_s") or 0), 3)
        if total["cost_usd"] is not None:
            total["cost_usd"] = None if u.get("cost_usd") is None else total["cost_usd"] + u["cost_usd"]
    return total

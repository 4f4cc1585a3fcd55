"""Language-model calls through litellm, so any provider works by its model string.

litellm is imported inside :func:`complete` only: its import costs about 2 s, which a run
without an LLM must not pay, and ``LITELLM_LOCAL_MODEL_COST_MAP`` must be set before that import
(otherwise litellm fetches its cost map from the network).

API keys are read by litellm from the environment. Nothing here puts them in a return value, and
:func:`redact` scrubs them from provider error messages before those reach logs or run records.
"""
from __future__ import annotations

import ipaddress
import json
import os
import re
import threading
import time
from dataclasses import dataclass, field
from typing import Any, Callable
from urllib.parse import urlsplit

from pipflow.engine.store import register_secrets, secrets_in
from pipflow.errors import InputError, LLMError
from pipflow.liberrors import LITELLM
from pipflow.llmslot import llm_slot

DEFAULT_MODEL = "offline"
#: provider errors worth another try; everything else (bad key, bad request) fails at once
_RETRYABLE = ("RateLimitError", "Timeout", "APIConnectionError", "ServiceUnavailableError",
              "InternalServerError", "BadGatewayError")
#: provider errors that the user causes (wrong key, unknown model): exit 2, no retry
_USER_FAULTS = ("AuthenticationError", "PermissionDeniedError", "NotFoundError")
_SECRET_ENV = re.compile(r"(KEY|TOKEN|SECRET|PASSWORD)", re.IGNORECASE)
#: the longest answer accepted, in characters. A real answer is bounded by ``max_tokens`` (a few
#: characters per token); 512 000 characters is beyond any real answer even at 100k tokens, so a
#: longer one is a broken or hostile server, and it is refused before it reaches the cache, the
#: record or the parsers.
MAX_ANSWER_CHARS = 512_000
#: environment variables in which a user names the server of a model (issue 13, defect 19)
_BASE_ENV = re.compile(r"(_API_BASE|_BASE_URL|_API_BASES)$")


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
    litellm.num_retries = 0  # one retry layer: ours (issue 13, defect 10)
    return litellm


def _norm_base(url: str) -> str:
    return url.strip().rstrip("/").lower()


def is_loopback(api_base: str) -> bool:
    """True for a server on this machine (127.0.0.0/8, ::1, localhost)."""
    host = (urlsplit(api_base.strip()).hostname or "").lower()
    if host == "localhost":
        return True
    try:
        return ipaddress.ip_address(host).is_loopback
    except ValueError:
        return False


def user_named(api_base: str, named: Callable[[str], bool] | None = None) -> bool:
    """True when the user named this server: in an environment variable that names a server
    (``OPENAI_API_BASE``, ``PIPFLOW_API_BASE``, ``*_BASE_URL``, ...) or as a value they gave the
    run (``-i api_base=...``, ``--inputs``, ``pipflow.run(api_base=...)``, a bench's ``-i`` or
    ``--matrix``), which the engine answers through ``named``
    (:meth:`pipflow.engine.step.StepContext.named_by_user`)."""
    want = _norm_base(api_base)
    for name, value in os.environ.items():
        if _BASE_ENV.search(name.upper()) and value:
            if want in (_norm_base(v) for v in value.split(",")):
                return True
    return named is not None and any(named(v) for v in {api_base, api_base.strip(), api_base.rstrip("/")})


def key_may_go_to(api_base: str | None, named: Callable[[str], bool] | None = None) -> bool:
    """Whether a provider key from the environment may be sent to ``api_base``: always to the
    provider's own server (no ``api_base``), else only to a loopback server or one the user named
    (a default in a shared workflow file must not collect keys)."""
    return not api_base or is_loopback(api_base) or user_named(api_base, named)


def check_no_secrets(model: str, messages: list[dict[str, str]], api_base: str | None, extra: dict | None) -> None:
    """Refuse a request that would carry the value of a key from the environment anywhere but
    the provider's own key header: in a message, the server address or another request field
    (a workflow that wrote ``${env.OPENAI_API_KEY}`` into a command, a prompt file holding a
    token). The record would show ``[redacted NAME]``, so the user could not even see it leave."""
    register_secrets()
    sent = {k: v for k, v in (extra or {}).items() if k != "mock_response"}  # litellm's canned answer stays here
    where = [("the prompt", json.dumps(messages, ensure_ascii=False)), ("the server address", api_base or ""),
             ("the request's fields", json.dumps(sent, default=str, ensure_ascii=False))]
    for part, text in where:
        names = secrets_in(text)
        if names:
            raise InputError(f"{model}: {part} would carry the value of {', '.join(names)} (a key from the "
                             "environment); pipflow sends a key only in the provider's key header, never inside "
                             "a prompt or a request's values. Remove it from the command, the prompt template and "
                             "the workflow")


#: the longest time-out or deadline accepted, in seconds (a day; more is a typo, and the
#: platform's timers overflow on numbers like 1e12)
MAX_SECONDS = 86_400.0


def check_limits(*, retries: int, max_tokens: int, timeout: float, deadline: float | None) -> None:
    """Raise :class:`InputError` for limits no call can honour (negative, zero, NaN, endless)."""
    problems = []
    if not isinstance(retries, int) or isinstance(retries, bool) or not 0 <= retries <= 100:
        problems.append(f"retries must be a whole number from 0 to 100, got {retries!r}")
    if not isinstance(max_tokens, int) or isinstance(max_tokens, bool) or max_tokens <= 0:
        problems.append(f"max_tokens must be a whole number > 0, got {max_tokens!r}")
    for name, value in (("timeout", timeout), ("deadline", deadline)):
        if value is None and name == "deadline":
            continue
        if not isinstance(value, (int, float)) or isinstance(value, bool) or not 0 < value <= MAX_SECONDS:
            problems.append(f"{name} must be a number of seconds above 0 and at most {MAX_SECONDS:g}, got {value!r}")
    if problems:
        raise InputError("; ".join(problems))


def check_api_base(api_base: str) -> None:
    """Raise :class:`InputError` unless ``api_base`` is an http(s) URL with a host."""
    try:
        parts = urlsplit(str(api_base).strip())
        ok = parts.scheme in ("http", "https") and bool(parts.hostname)
        parts.port  # noqa: B018 - raises ValueError for a port out of range
    except ValueError:
        ok = False
    if not ok:
        raise InputError(f"api_base {api_base!r} is not a server address; expected http://HOST[:PORT]/... "
                         "(e.g. http://127.0.0.1:8080/v1)")


#: providers whose credentials come from a cloud SDK's chain (profiles, instance roles, gcloud),
#: not necessarily from environment variables: their keys are not checked before the call
CREDENTIAL_CHAINS = ("bedrock", "bedrock_converse", "sagemaker", "sagemaker_chat", "vertex_ai", "vertex_ai_beta")


def check_model(litellm, model: str, api_base: str | None) -> None:
    """Fail before the first call when litellm does not know the model's provider, or when a
    hosted provider's key is missing from the environment (:class:`InputError`, exit 2)."""
    try:
        provider = litellm.get_llm_provider(model=model, api_base=api_base)[1]
    except Exception as exc:
        if not LITELLM.owns(exc):
            raise
        raise InputError(f"model {model!r}: litellm does not know its provider; write it as "
                         "provider/model (openai/gpt-4o, anthropic/..., ollama/...), or use "
                         "'offline' or 'local/smollm2'") from None
    if api_base or provider in CREDENTIAL_CHAINS:
        return  # a self-hosted server, or credentials that need not be in the environment
    try:
        missing = litellm.validate_environment(model=model).get("missing_keys") or []
    except Exception:  # litellm cannot tell: the call itself will say
        missing = []
    # only keys: a server address (OLLAMA_API_BASE), a project or a version has a default
    missing = [name for name in missing if _SECRET_ENV.search(name)]
    if missing:
        raise InputError(f"model {model!r}: no provider key in the environment; litellm looks for "
                         f"{' or '.join(missing)}, which {'is' if len(missing) == 1 else 'are'} not set; "
                         "set it, or use model=offline")


@dataclass(frozen=True)
class Retry:
    """How patiently one call asks. ``timeout``: seconds per request; ``retries``: more requests
    after a retryable failure (rate limits, time-outs, server errors, dropped connections), the
    n-th after a wait of ``backoff`` x 2**n seconds (``sleep`` waits; a test passes a fake);
    ``deadline``: seconds for the whole call, retries and waits included (None: no bound beyond
    timeout x tries)."""

    timeout: float = 60.0
    retries: int = 2
    deadline: float | None = None
    backoff: float = 1.0
    sleep: Callable[[float], None] = time.sleep


def complete(
    messages: list[dict[str, str]],
    *,
    model: str,
    temperature: float = 0.0,
    max_tokens: int = 1024,
    api_base: str | None = None,
    extra: dict[str, Any] | None = None,
    named: Callable[[str], bool] | None = None,
    retry: Retry = Retry(),
) -> Completion:
    """Ask ``model`` for one chat completion; retry rate limits, time-outs, server errors and
    dropped connections ``retry.retries`` times with exponential backoff; raise :class:`LLMError`
    otherwise (:class:`InputError` for what the user must fix: a missing key, an unknown model).

    This is the only retry layer: litellm's and the OpenAI client's own retries are switched off,
    so ``retries=2`` means at most 3 requests, and the error message counts them (:class:`Retry`:
    the time-out of one request, the deadline of the whole call). ``extra`` carries
    provider-specific request fields (``response_format``, a llama.cpp ``grammar`` in
    ``extra_body``, litellm's ``mock_response`` in tests). ``named(value)`` says whether the user
    gave a value (the provider key goes to ``api_base`` only if they named it or it is on
    loopback); no value of a key from the environment is ever sent in the request's content
    (:func:`check_no_secrets`)."""
    check_limits(retries=retry.retries, max_tokens=max_tokens, timeout=retry.timeout, deadline=retry.deadline)
    if api_base:
        check_api_base(api_base)
    check_no_secrets(model, messages, api_base, extra)
    litellm = _import_litellm()
    if not {"mock_response", "api_key"} & set(extra or {}):  # canned answers (tests), a key given
        check_model(litellm, model, api_base)
    kwargs: dict[str, Any] = dict(model=model, messages=messages, temperature=temperature,
                                  max_tokens=max_tokens, num_retries=0, max_retries=0, **(extra or {}))
    withheld = False
    if api_base:
        kwargs["api_base"] = api_base
        if not key_may_go_to(api_base, named):
            kwargs["api_key"] = "no-key"  # never the environment's provider key (see key_may_go_to)
            withheld = True
        elif model.startswith("openai/") and not os.environ.get("OPENAI_API_KEY"):
            kwargs["api_key"] = "no-key"  # self-hosted OpenAI-compatible servers need none
    response, attempt, latency = _ask(litellm, kwargs, retry, withheld)
    return Completion(text=_answer_text(model, response), usage=_usage(litellm, response, latency, attempt))


def _ask(litellm: Any, kwargs: dict[str, Any], retry: Retry, withheld: bool) -> tuple[Any, int, float]:
    """``(response, retries made, latency of the last request)``: the request of ``kwargs``, again
    after a retryable failure while :class:`Retry` allows; the error that ends it is raised in
    words (``withheld``: the provider key was not sent to the workflow's server)."""
    model, api_base = kwargs["model"], kwargs.get("api_base")
    started = time.monotonic()
    attempt = 0  # requests made so far, minus one
    while True:
        remaining = None if retry.deadline is None else retry.deadline - (time.monotonic() - started)
        kwargs["timeout"] = retry.timeout if remaining is None else max(0.001, min(retry.timeout, remaining))
        start = time.perf_counter()
        try:
            # one of the provider's LLM slots across a dask cluster (a no-op unless a bench backend
            # installed its limiter: pipflow.llmslot)
            with llm_slot(model):
                response = _within(litellm.completion, dict(kwargs), kwargs["timeout"] + GRACE)
            return response, attempt, time.perf_counter() - start
        except Exception as exc:  # litellm maps every provider's error onto its own classes
            if not (isinstance(exc, RequestOverrun) or LITELLM.owns(exc)):
                raise  # not the provider's answer but a bug: it keeps its traceback
            kind = "Timeout" if isinstance(exc, RequestOverrun) else type(exc).__name__
            retryable = isinstance(exc, RequestOverrun) or any(
                isinstance(exc, getattr(litellm, name, ())) for name in _RETRYABLE)
            user_fault = any(isinstance(exc, getattr(litellm, name, ())) for name in _USER_FAULTS)
            wait = retry.backoff * 2 ** attempt
            spent = time.monotonic() - started
            in_time = retry.deadline is None or spent + wait < retry.deadline
            if retryable and not user_fault and attempt < retry.retries and in_time:
                retry.sleep(wait)
                attempt += 1
                continue
            tries = f" after {attempt + 1} attempt{'s' if attempt else ''} in {spent:.1f} s"
            if retryable and attempt < retry.retries and not in_time:
                tries += f" (the call's deadline of {retry.deadline:g} s left no time for another)"
            hint = (f" (is the server at {api_base} running?)"
                    if api_base and "connection error" in str(exc).lower() else "")
            if withheld and user_fault:
                hint += (f" (no provider key was sent: {api_base} comes from the workflow, not from "
                         "you; name it with -i api_base=... or in an environment variable such as "
                         "PIPFLOW_API_BASE to send the key there)")
            message = f"{model}: {kind}{tries}: {_short(redact(str(exc)))}{hint}"
            raise (InputError if user_fault else LLMError)(message) from None


def _answer_text(model: str, response: Any) -> str:
    """The text of a provider's response, refused when there is none or it is no real answer."""
    try:
        text = response.choices[0].message.content or ""
    except (AttributeError, IndexError, TypeError, KeyError):
        raise LLMError(f"{model}: the server answered without a message (no choices in its "
                       "response); is it an OpenAI-compatible chat server?") from None
    if not isinstance(text, str):
        raise LLMError(f"{model}: the server's message is {type(text).__name__}, not text")
    if len(text) > MAX_ANSWER_CHARS:
        raise LLMError(f"{model}: the answer is {len(text):,} characters long, more than the "
                       f"{MAX_ANSWER_CHARS:,} that no real answer reaches; it was neither kept nor parsed")
    return text


#: seconds a request may run past its time-out before it is abandoned (see :func:`_within`)
GRACE = 1.0


class RequestOverrun(Exception):
    """A request still running when its time was up."""


def _within(call: Callable[..., Any], kwargs: dict[str, Any], limit: float) -> Any:
    """``call(**kwargs)``, abandoned after ``limit`` seconds. The HTTP client's time-out bounds
    each network operation, not the request: a server that trickles a byte at a time would hold
    a call for ever. The call runs in a daemon thread, which is left to finish on its own (its
    answer is dropped) when the time is up."""
    box: dict[str, Any] = {}

    def target() -> None:
        try:
            box["value"] = call(**kwargs)
        except BaseException as exc:  # handed to the caller's thread below
            box["error"] = exc

    worker = threading.Thread(target=target, name="pipflow-llm-call", daemon=True)
    worker.start()
    worker.join(limit)
    if worker.is_alive():
        raise RequestOverrun(f"no complete answer within {limit - GRACE:g} s (the server kept the "
                             "connection open without finishing its answer)")
    if "error" in box:
        raise box["error"]
    return box["value"]


def _short(message: str, limit: int = 600) -> str:
    """A provider message cut to a readable length (a server may echo megabytes)."""
    message = " ".join(message.split())
    return message if len(message) <= limit else message[:limit] + " ..."


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

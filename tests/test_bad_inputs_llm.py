"""Bad inputs on the LLM path (issue 13, defects 8, 10, 13, 14, 16, 19), against a scripted
OpenAI-compatible server on loopback (stdlib http.server in a thread) reached through litellm's
real HTTP client. Each case runs the `pipflow` command as a user would and asserts the exit code,
the message, that no traceback is shown, and how many requests the server really received (one
retry layer: ``retries=2`` is at most 3 requests, and the message says how many there were).
"""
from __future__ import annotations

import json
import os
import socket
import subprocess
import sys
import threading
import time
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer
from pathlib import Path
from typing import Any

import pytest
import yaml

from pipflow import StepContext

REPO = Path(__file__).resolve().parents[1]
WORKFLOW = REPO / "tests/fixtures/workflows/llm_bad.yaml"
WORLD_FILE = REPO / "benchmarks/warehouse/world.yaml"
DOMAIN = REPO / "domains/warehouse.pddl"
COMMAND = "There should be 7 product1 in shelf3."
SECRET = "sk-test-secret-4242424242"

pytestmark = pytest.mark.usefixtures("no_hang")


class Server:
    """A scripted chat-completions server: request i gets ``script[min(i, len-1)]``, which is a
    string (the answer), or a dict with ``status`` (an error code), ``body`` (raw bytes),
    ``delay`` (seconds before answering), ``size`` (an answer of that many characters) or
    ``trickle`` (seconds of sending a byte every 0.2 s without ever finishing)."""

    def __init__(self, script: list[Any], host: str = "127.0.0.1"):
        self.script = script
        self.requests: list[dict] = []
        self.auth: list[str | None] = []
        self.paths: list[str] = []
        server = self

        class Handler(BaseHTTPRequestHandler):
            def log_message(self, *args: Any) -> None:
                pass

            def do_GET(self) -> None:
                self.send(200, json.dumps({"data": [{"id": "fake"}]}).encode())

            def do_POST(self) -> None:
                body = self.rfile.read(int(self.headers.get("Content-Length") or 0))
                server.requests.append(json.loads(body or b"{}"))
                server.auth.append(self.headers.get("Authorization"))
                server.paths.append(self.path)
                entry = server.script[min(len(server.requests), len(server.script)) - 1]
                entry = {"text": entry} if isinstance(entry, str) else entry
                time.sleep(entry.get("delay", 0))
                if "trickle" in entry:  # headers, then a byte now and then, never the whole answer
                    self.send_response(200)
                    self.send_header("Content-Type", "application/json")
                    self.send_header("Content-Length", "100000")
                    self.end_headers()
                    ends = time.monotonic() + entry["trickle"]
                    try:
                        while time.monotonic() < ends:
                            self.wfile.write(b" ")
                            self.wfile.flush()
                            time.sleep(0.2)
                    except (BrokenPipeError, ConnectionResetError):
                        pass
                    return None
                if "body" in entry:
                    return self.send(entry.get("status", 200), entry["body"])
                if entry.get("status", 200) != 200:
                    error = {"message": entry.get("message", f"scripted {entry['status']}"),
                             "type": "invalid_request_error", "code": entry.get("code")}
                    return self.send(entry["status"], json.dumps({"error": error}).encode())
                text = "x" * entry["size"] if "size" in entry else entry["text"]
                self.send(200, json.dumps({
                    "id": "c1", "object": "chat.completion", "created": 0, "model": "fake",
                    "choices": [{"index": 0, "finish_reason": "stop",
                                 "message": {"role": "assistant", "content": text}}],
                    "usage": {"prompt_tokens": 10, "completion_tokens": 5, "total_tokens": 15}}).encode())

            def send(self, status: int, data: bytes) -> None:
                try:
                    self.send_response(status)
                    self.send_header("Content-Type", "application/json")
                    self.send_header("Content-Length", str(len(data)))
                    self.end_headers()
                    self.wfile.write(data)
                except (BrokenPipeError, ConnectionResetError):  # the client gave up (time-outs)
                    pass

        self.httpd = ThreadingHTTPServer((host, 0), Handler)
        self.httpd.daemon_threads = True
        self.api_base = f"http://{host}:{self.httpd.server_address[1]}/v1"
        threading.Thread(target=self.httpd.serve_forever, daemon=True).start()

    def close(self) -> None:
        self.httpd.shutdown()
        self.httpd.server_close()


@pytest.fixture
def serve():
    servers: list[Server] = []

    def start(script: list[Any], host: str = "127.0.0.1") -> Server:
        servers.append(Server(script, host))
        return servers[-1]

    yield start
    for s in servers:
        s.close()


def good_answer() -> str:
    from pipflow.warehouse.problem import write_problem
    from pipflow.warehouse.world import load_world

    return f"```pddl\n{write_problem(load_world(WORLD_FILE), {'shelf3': {'product1': 7}})}\n```"


def clean_env(**extra: str) -> dict[str, str]:
    """The environment without provider keys or servers named by whoever runs the tests."""
    env = {k: v for k, v in os.environ.items()
           if not (k.endswith(("_API_KEY", "_API_BASE", "_BASE_URL")) or k in ("PIPFLOW_MODEL", "PIPFLOW_GIVEN_INPUTS"))}
    return {**env, **extra}


def pipflow(tmp_path: Path, *args: str, env: dict | None = None, workflow: Path = WORKFLOW,
            timeout: float = 240) -> subprocess.CompletedProcess:
    cmd = [sys.executable, "-m", "pipflow.engine.cli", "run", str(workflow), "--runs-dir", str(tmp_path / "runs"),
           "-i", f"command={COMMAND}", *args]
    return subprocess.run(cmd, capture_output=True, text=True, timeout=timeout, cwd=tmp_path,
                          env=env or clean_env(PIPFLOW_CACHE_DIR=str(tmp_path / "stepcache")))


def no_traceback(proc: subprocess.CompletedProcess) -> None:
    assert "Traceback" not in proc.stderr and "Traceback" not in proc.stdout, proc.stderr


def record(tmp_path: Path) -> Path:
    (run,) = [p for p in (tmp_path / "runs").iterdir() if p.is_dir()]
    return run


# --- retries: one layer, honest counts, a deadline ----------------------------------------

def test_server_errors_are_retried_by_pipflow_alone_and_counted_honestly(tmp_path, serve):
    server = serve([{"status": 500}])
    proc = pipflow(tmp_path, "-i", f"api_base={server.api_base}", "-i", "retries=2", "--no-cache")
    assert proc.returncode == 1, proc.stderr
    assert "InternalServerError after 3 attempts" in proc.stderr
    assert len(server.requests) == 3, "pipflow's 3 tries, and no hidden retries of litellm or the OpenAI client"
    no_traceback(proc)
    assert json.loads((record(tmp_path) / "run.json").read_text())["status"] == "failed"


def test_rate_limits_then_an_answer_succeed_with_the_attempts_recorded(tmp_path, serve):
    server = serve([{"status": 429}, good_answer()])
    proc = pipflow(tmp_path, "-i", f"api_base={server.api_base}", "--no-cache")
    assert proc.returncode == 0, proc.stderr
    assert len(server.requests) == 2
    usage = json.loads((record(tmp_path) / "outputs.json").read_text())["usage"]
    assert usage["retries"] == 1 and usage["cached"] is False
    no_traceback(proc)


def test_garbage_from_the_server_fails_clearly_after_the_stated_attempts(tmp_path, serve):
    server = serve([{"body": b"\x00\xff<html>not json"}])
    proc = pipflow(tmp_path, "-i", f"api_base={server.api_base}", "-i", "retries=1", "--no-cache")
    assert proc.returncode == 1
    assert "after 2 attempts" in proc.stderr and len(server.requests) == 2
    assert "step 'generate'" in proc.stderr
    no_traceback(proc)


def test_a_slow_server_fails_within_the_calls_deadline(tmp_path, serve):
    server = serve([{"delay": 4, "text": "late"}])
    started = time.monotonic()
    proc = pipflow(tmp_path, "-i", f"api_base={server.api_base}", "-i", "timeout=1", "-i", "retries=5",
                   "-i", "deadline=2.5", "--no-cache")
    elapsed = time.monotonic() - started
    assert proc.returncode == 1
    assert "Timeout after 2 attempts" in proc.stderr and "deadline of 2.5 s" in proc.stderr, proc.stderr
    assert len(server.requests) == 2, "1 s + 1 s wait + 1 s: no time for a third request within 2.5 s"
    assert elapsed < 2.5 + 30  # the deadline, plus starting python and importing litellm
    no_traceback(proc)


def test_a_server_that_trickles_bytes_is_abandoned_at_the_time_out(serve):
    from pipflow.errors import LLMError
    from pipflow.language import llm

    server = serve([{"trickle": 20}])
    llm._import_litellm()  # its import takes seconds: not part of the call
    started = time.monotonic()
    with pytest.raises(LLMError, match=r"Timeout after 2 attempts.*kept the connection open"):
        llm.complete([{"role": "user", "content": "hi"}], model="openai/fake", api_base=server.api_base,
                     retry=llm.Retry(timeout=1, retries=1, backoff=0.1))
    assert time.monotonic() - started < 6, "two requests of 1 s (+1 s grace each), not 20 s of trickle"
    assert len(server.requests) == 2


@pytest.mark.parametrize("body", [b"{}", b"null", b'{"choices": []}', b'{"choices": [{"message": 5}]}',
                                  b'{"choices": [{"index": 0, "message": {"role": "assistant", "content"',
                                  b"[1, 2]", b'"text"'])
def test_malformed_answers_are_clear_errors(serve, body):
    from pipflow.errors import LLMError
    from pipflow.language import llm

    server = serve([{"body": body}])
    with pytest.raises(LLMError, match=r"^openai/fake: "):
        llm.complete([{"role": "user", "content": "hi"}], model="openai/fake", api_base=server.api_base,
                     retry=llm.Retry(retries=0, timeout=5))
    assert len(server.requests) == 1


# --- sizes ---------------------------------------------------------------------------------

def test_a_huge_answer_is_refused_and_stored_nowhere(tmp_path, serve):
    server = serve([{"size": 20_000_000}])
    cache = tmp_path / "llmcache"
    proc = pipflow(tmp_path, "-i", f"api_base={server.api_base}", "-i", "retries=0", "-i", f"cache_dir={cache}")
    assert proc.returncode == 1
    assert "20,000,000 characters" in proc.stderr and "no real answer" in proc.stderr
    assert len(server.requests) == 1
    size = sum(p.stat().st_size for p in record(tmp_path).rglob("*") if p.is_file())
    assert size < 1_000_000, f"the run record holds {size} bytes"
    assert not cache.exists() or not any(cache.iterdir())
    no_traceback(proc)


# --- user errors: exit 2, at once ----------------------------------------------------------

def test_an_unknown_model_name_is_a_user_error_without_retries(tmp_path, serve):
    server = serve([{"status": 404, "message": "The model `nosuch` does not exist", "code": "model_not_found"}])
    proc = pipflow(tmp_path, "-i", f"api_base={server.api_base}", "-i", "model=openai/nosuch", "--no-cache")
    assert proc.returncode == 2, proc.stderr
    assert "NotFoundError after 1 attempt" in proc.stderr and "does not exist" in proc.stderr
    assert len(server.requests) == 1
    no_traceback(proc)


def test_a_missing_provider_key_fails_before_any_call_naming_the_variable(tmp_path):
    started = time.monotonic()
    proc = pipflow(tmp_path, "-i", "model=openai/gpt-4o-mini", "--no-cache")
    assert proc.returncode == 2, proc.stderr
    assert "OPENAI_API_KEY" in proc.stderr and "not set" in proc.stderr
    assert time.monotonic() - started < 60  # no retries against the provider (was 22 s of them)
    no_traceback(proc)
    proc = pipflow(tmp_path, "-i", "model=anthropic/claude-3-5-haiku-latest", "--no-cache")
    assert proc.returncode == 2 and "ANTHROPIC_API_KEY" in proc.stderr


def test_only_missing_keys_block_a_call(monkeypatch):
    from pipflow.errors import InputError
    from pipflow.language import llm

    lit = llm._import_litellm()
    for name in ("OPENAI_API_KEY", "OLLAMA_API_BASE", "AWS_ACCESS_KEY_ID", "VERTEXAI_PROJECT"):
        monkeypatch.delenv(name, raising=False)
    for model in ("ollama/llama3", "bedrock/anthropic.claude-3", "vertex_ai/gemini-pro"):
        llm.check_model(lit, model, None)  # a default server address, or a cloud credential chain
    llm.check_model(lit, "openai/anything", "http://127.0.0.1:1/v1")  # self-hosted: no key needed
    with pytest.raises(InputError, match="looks for OPENAI_API_KEY, which is not set"):
        llm.check_model(lit, "openai/gpt-4o", None)


def test_a_model_string_without_a_known_provider_is_a_user_error(tmp_path):
    proc = pipflow(tmp_path, "-i", "model=nosuchprovider/big-model", "--no-cache")
    assert proc.returncode == 2 and "does not know its provider" in proc.stderr
    no_traceback(proc)
    proc = pipflow(tmp_path, "-i", "model=local/nosuch", "--no-cache")
    assert proc.returncode == 2 and "unknown local model 'local/nosuch'" in proc.stderr
    assert "local/smollm2" in proc.stderr
    no_traceback(proc)


@pytest.mark.parametrize("args, words", [
    ({"api_base": "not-a-url"}, "is not a server address"),
    ({"api_base": "ftp://127.0.0.1:1/v1"}, "is not a server address"),
    ({"api_base": "http://127.0.0.1:99999/v1"}, "is not a server address"),
    ({"timeout": 1e12}, "timeout must be"), ({"timeout": float("nan")}, "timeout must be"),
    ({"timeout": 0}, "timeout must be"), ({"deadline": float("inf")}, "deadline must be"),
    ({"retries": -1}, "retries must be"), ({"max_tokens": 0}, "max_tokens must be")])
def test_impossible_call_settings_are_user_errors_before_any_request(serve, args, words):
    from pipflow.errors import InputError
    from pipflow.language import llm

    server = serve(["never asked"])
    limits = {k: v for k, v in args.items() if k in ("timeout", "deadline", "retries")}
    call = {"model": "openai/fake", "api_base": server.api_base, "retry": llm.Retry(**limits),
            **{k: v for k, v in args.items() if k not in limits}}
    with pytest.raises(InputError, match=words):
        llm.complete([{"role": "user", "content": "hi"}], **call)
    assert server.requests == []


def test_a_bad_api_base_on_the_command_line_is_exit_2(tmp_path):
    proc = pipflow(tmp_path, "-i", "api_base=localhost:8080", "--no-cache")
    assert proc.returncode == 2 and "is not a server address" in proc.stderr
    no_traceback(proc)


# --- the provider key goes only where the user sends it ------------------------------------

def own_address() -> str | None:
    """This machine's address on its first non-loopback interface (no packet is sent)."""
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as s:
        try:
            s.connect(("10.255.255.255", 1))
            address = s.getsockname()[0]
        except OSError:
            return None
    return None if address.startswith("127.") else address


def test_a_key_goes_to_a_workflows_server_only_when_the_user_named_it(tmp_path, serve):
    host = own_address()
    if host is None:
        pytest.skip("this machine has no non-loopback interface to stand for a remote server")
    server = serve([good_answer()], host=host)
    shared = tmp_path / "shared.yaml"  # a shared workflow file that names a server by default
    shared.write_text(yaml.safe_dump({"pipflow": 1, "name": "shared", "extends": str(WORKFLOW),
                                      "inputs": {"api_base": {"default": server.api_base}}}))
    env = clean_env(OPENAI_API_KEY=SECRET, PIPFLOW_CACHE_DIR=str(tmp_path / "stepcache"))
    proc = pipflow(tmp_path, "--no-cache", env=env, workflow=shared)
    assert proc.returncode == 0, proc.stderr
    assert server.auth and not any(SECRET in (a or "") for a in server.auth), server.auth

    proc = pipflow(tmp_path, "--no-cache", "-i", f"api_base={server.api_base}", env=env, workflow=shared)
    assert proc.returncode == 0 and server.auth[-1] == f"Bearer {SECRET}"  # named on the command line
    proc = pipflow(tmp_path, "--no-cache", env={**env, "PIPFLOW_API_BASE": server.api_base}, workflow=shared)
    assert proc.returncode == 0 and server.auth[-1] == f"Bearer {SECRET}"  # named in the environment


def test_key_trust_rules():
    from pipflow.language import llm

    assert llm.is_loopback("http://127.0.0.1:8080/v1") and llm.is_loopback("http://localhost/v1")
    assert llm.is_loopback("http://[::1]:9/v1") and not llm.is_loopback("http://10.0.0.5/v1")
    assert llm.key_may_go_to(None)
    assert not llm.key_may_go_to("https://collector.example.com/v1")
    # the engine says which values the user gave (StepContext.named_by_user)
    given = {"https://collector.example.com/v1/"}
    assert llm.key_may_go_to("https://collector.example.com/v1/", named=given.__contains__)
    assert not llm.key_may_go_to("https://other.example.com/v1", named=given.__contains__)


# --- the response cache: verified or a miss; --no-cache writes none; unwritable is a warning --

def run_step(tmp_path: Path, name: str, api_base: str, **args) -> tuple[dict, Path, list[str]]:
    from pipflow.steps.llm import llm_problem

    logs: list[str] = []
    art = tmp_path / name
    ctx = StepContext("generate", art, base_dir=REPO / "workflows", log=logs.append)
    args = {"command": COMMAND, "world": yaml.safe_load(WORLD_FILE.read_text()), "domain": str(DOMAIN),
            "model": "openai/fake", "api_base": api_base, "retries": 0, "timeout": 10,
            "cache_dir": str(tmp_path / "cache"), **args}
    return llm_problem.func(ctx, **args), art, logs


@pytest.mark.parametrize("damage", [b"\xff\xfe\x00 not utf-8", b"{}", b"[]", b'{"text": 1}', b"{\"text\": \"x\"",
                                    "forged"])
def test_a_damaged_cache_entry_is_a_miss_never_a_failure(tmp_path, serve, damage):
    server = serve([good_answer()])
    first, _, _ = run_step(tmp_path, "first", server.api_base)
    (entry,) = (tmp_path / "cache").glob("*.json")
    if damage == "forged":  # a well-formed entry whose text was edited afterwards
        data = json.loads(entry.read_text())
        data["text"] = data["text"].replace("(define", "(define (problem forged)", 1)
        entry.write_text(json.dumps(data))
    else:
        entry.write_bytes(damage)
    again, _, _ = run_step(tmp_path, "again", server.api_base)
    assert len(server.requests) == 2, "the damaged entry was a miss: the model was asked again"
    assert again["usage"]["cached"] is False and again["problem"] == first["problem"]
    replay, _, _ = run_step(tmp_path, "replay", server.api_base)
    assert replay["usage"]["cached"] is True and len(server.requests) == 2  # rewritten whole


def test_no_cache_writes_no_response_cache(tmp_path, serve):
    server = serve([good_answer()])
    out, art, _ = run_step(tmp_path, "nocache", server.api_base, cache=False)
    assert out["problem"] and (art / "response.txt").read_text() == good_answer()
    assert not (tmp_path / "cache").exists()
    proc = pipflow(tmp_path, "-i", f"api_base={server.api_base}", "--no-cache")
    assert proc.returncode == 0, proc.stderr
    assert not (tmp_path / ".pipflow-cache" / "llm").exists()


def test_an_unwritable_cache_is_a_warning_and_the_answer_stays_in_the_record(tmp_path, serve):
    server = serve([good_answer()])
    blocker = tmp_path / "a-file"
    blocker.write_text("not a folder")
    out, art, logs = run_step(tmp_path, "ro", server.api_base, cache_dir=str(blocker / "cache"))
    assert out["problem"] and len(server.requests) == 1
    assert (art / "response.txt").read_text() == good_answer()
    assert any(line.startswith("llm: the response cache") and "not writable" in line for line in logs), logs
    assert blocker.read_text() == "not a folder"
    proc = pipflow(tmp_path, "-i", f"api_base={server.api_base}", "-i", f"cache_dir={blocker / 'cache'}")
    assert proc.returncode == 0, proc.stderr
    assert "warn" in proc.stderr and "not writable" in proc.stderr  # shown without -v
    events = (record(tmp_path) / "events.jsonl").read_text()
    assert '"warning"' in events and "not writable" in events


def test_a_long_answer_is_stored_once_in_the_run_record(tmp_path, serve, monkeypatch):
    from pipflow.engine.executor import RunOptions
    from pipflow.engine.runner import run_workflow

    answer = good_answer() + "\n" + "y" * 300_000  # long, yet under the cap: it is used
    server = serve([answer])
    monkeypatch.setenv("PIPFLOW_CACHE_DIR", str(tmp_path / "stepcache"))
    result = run_workflow(WORKFLOW, {"api_base": server.api_base, "command": COMMAND, "cache_dir": str(tmp_path / "c")},
                          runs_dir=tmp_path / "runs", options=RunOptions(use_cache=False))
    assert result.ok, result.error
    files = [p for p in result.run_dir.rglob("*") if p.is_file()]
    (whole,) = [p for p in files if p.name == "response.txt"]
    assert whole.read_text() == answer
    assert sum(p.stat().st_size for p in files) < 1.5 * len(answer), "the answer is stored once, not per copy of the outputs"

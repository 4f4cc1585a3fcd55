"""A scripted OpenAI-compatible server on loopback, for tests that drive the real LLM path
(litellm's HTTP client, pipflow's retries, caches and records) without a model.

Each request to ``/v1/chat/completions`` takes the next entry of the script (the last one
repeats), or, with ``answer=``, what ``answer(body)`` returns for the request's JSON body (for
benches whose runs ask in any order): a string is answered as the assistant's message; a dict may instead set ``status``
(an HTTP error code), ``body`` (raw bytes or text sent as is), ``delay`` (seconds before the
answer). The script may instead be a function of the request's JSON body that returns such an
entry: runs in parallel (a bench) get answers by what they ask, not by when they ask it. Every request's JSON body is kept in ``server.requests`` (headers in
``server.headers``), so tests can count attempts and read the prompts that were sent.

    with FakeOpenAI(["(define (problem p) ...)"]) as server:
        run(..., model="openai/fake", api_base=server.api_base)
        assert len(server.requests) == 1
"""
from __future__ import annotations

import json
import threading
import time
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer
from typing import Any, Callable


class FakeOpenAI:
    def __init__(self, script: list[Any] | Callable[[dict], Any] | None = None,
                 answer: Callable[[dict], Any] | None = None):
        # a responder answers by request (``answer=``, or a callable ``script``); else the script in turn
        self.respond = answer if answer is not None else (script if callable(script) else None)
        self.script = [] if callable(script) else (list(script or []) or [""])
        self.requests: list[dict] = []
        self.headers: list[dict] = []
        self._lock = threading.Lock()
        fake = self

        class Handler(BaseHTTPRequestHandler):
            def log_message(self, *args: Any) -> None:  # keep test output clean
                pass

            def do_GET(self) -> None:  # /v1/models, for clients that look first
                self._send(200, json.dumps({"object": "list", "data": [{"id": "fake", "object": "model"}]}))

            def do_POST(self) -> None:
                length = int(self.headers.get("Content-Length") or 0)
                raw = self.rfile.read(length)
                try:
                    body = json.loads(raw or b"{}")
                except json.JSONDecodeError:
                    body = {"raw": raw.decode("utf-8", "replace")}
                with fake._lock:
                    index = len(fake.requests)
                    fake.requests.append(body)
                    fake.headers.append(dict(self.headers))
                    entry = None if fake.respond else fake.script[min(index, len(fake.script) - 1)]
                if fake.respond is not None:
                    try:
                        entry = fake.respond(body)
                    except Exception as exc:  # the test's responder failed: say so as a bad request
                        entry = {"status": 400, "body": json.dumps({"error": {
                            "message": f"test responder: {type(exc).__name__}: {exc}", "type": "invalid_request_error"}})}
                if isinstance(entry, str):
                    entry = {"text": entry}
                if entry.get("delay"):
                    time.sleep(entry["delay"])
                if "body" in entry:
                    self._send(entry.get("status", 200), entry["body"])
                elif entry.get("status", 200) != 200:
                    self._send(entry["status"], json.dumps({"error": {"message": f"scripted {entry['status']}",
                                                                      "type": "server_error"}}))
                else:
                    text = entry.get("text", "")
                    self._send(200, json.dumps({
                        "id": f"chatcmpl-{index}", "object": "chat.completion", "created": int(time.time()),
                        "model": body.get("model", "fake"),
                        "choices": [{"index": 0, "finish_reason": "stop",
                                     "message": {"role": "assistant", "content": text}}],
                        "usage": {"prompt_tokens": 11, "completion_tokens": max(1, len(text) // 4),
                                  "total_tokens": 11 + max(1, len(text) // 4)}}))

            def _send(self, status: int, body: str | bytes) -> None:
                data = body.encode("utf-8") if isinstance(body, str) else body
                try:
                    self.send_response(status)
                    self.send_header("Content-Type", "application/json")
                    self.send_header("Content-Length", str(len(data)))
                    self.end_headers()
                    self.wfile.write(data)
                except (BrokenPipeError, ConnectionResetError):  # the client gave up (a time-out test)
                    pass

        self._server = ThreadingHTTPServer(("127.0.0.1", 0), Handler)
        self._server.daemon_threads = True
        self._thread = threading.Thread(target=self._server.serve_forever, daemon=True)

    @property
    def api_base(self) -> str:
        return f"http://127.0.0.1:{self._server.server_address[1]}/v1"

    def prompts(self) -> list[str]:
        """The last user message of every request, in order."""
        out = []
        for body in self.requests:
            users = [m.get("content") for m in body.get("messages", []) if m.get("role") == "user"]
            out.append(users[-1] if users else "")
        return out

    def __enter__(self) -> "FakeOpenAI":
        self._thread.start()
        return self

    def __exit__(self, *exc: Any) -> None:
        self._server.shutdown()
        self._server.server_close()

"""How many requests and seconds a failing model call costs (issue 13, defect 10).

A loopback OpenAI-compatible server answers every request with HTTP 500. Measured in one run on
this machine: a bare litellm call with its default settings (the OpenAI client's own retries),
pipflow's call with ``retries=2`` (its only retry layer: the client's are off), and the product
the two layers gave before (pipflow's tries x the client's). Then a server that answers after
5 s, with ``timeout=1``, ``retries=5`` and ``deadline=2.5``: the call ends within its deadline.

    python benchmarks/llm_retries.py
"""
from __future__ import annotations

import json
import os
import threading
import time
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer


def serve(status: int, delay: float = 0.0):
    hits: list[float] = []

    class Handler(BaseHTTPRequestHandler):
        def log_message(self, *args):
            pass

        def do_POST(self):
            self.rfile.read(int(self.headers.get("Content-Length") or 0))
            hits.append(time.monotonic())
            time.sleep(delay)
            body = json.dumps({"error": {"message": "scripted", "type": "server_error"}} if status != 200 else {
                "id": "c", "object": "chat.completion", "created": 0, "model": "m",
                "choices": [{"index": 0, "finish_reason": "stop", "message": {"role": "assistant", "content": "ok"}}],
                "usage": {"prompt_tokens": 1, "completion_tokens": 1, "total_tokens": 2}}).encode()
            try:
                self.send_response(status)
                self.send_header("Content-Type", "application/json")
                self.send_header("Content-Length", str(len(body)))
                self.end_headers()
                self.wfile.write(body)
            except OSError:
                pass

    httpd = ThreadingHTTPServer(("127.0.0.1", 0), Handler)
    httpd.daemon_threads = True
    threading.Thread(target=httpd.serve_forever, daemon=True).start()
    return httpd, f"http://127.0.0.1:{httpd.server_address[1]}/v1", hits


def main() -> None:
    from pipflow.language import llm

    litellm = llm._import_litellm()
    messages = [{"role": "user", "content": "hi"}]
    httpd, base, hits = serve(500)
    started = time.monotonic()
    try:
        litellm.completion(model="openai/m", messages=messages, api_base=base, api_key="x", timeout=5)
    except Exception:
        pass
    bare, bare_s = len(hits), time.monotonic() - started
    hits.clear()
    started = time.monotonic()
    try:
        llm.complete(messages, model="openai/m", api_base=base, retry=llm.Retry(retries=2, backoff=0.1))
    except Exception as exc:
        said = str(exc).split(":")[1].strip()
    ours, ours_s = len(hits), time.monotonic() - started
    httpd.shutdown()

    httpd, base, hits = serve(200, delay=5)
    started = time.monotonic()
    try:
        llm.complete(messages, model="openai/m", api_base=base,
                     retry=llm.Retry(timeout=1, retries=5, deadline=2.5, backoff=0.5))
    except Exception as exc:
        slow_said = str(exc).split(":")[1].strip()
    slow, slow_s = len(hits), time.monotonic() - started
    httpd.shutdown()

    print(f"load average: {os.getloadavg()[0]:.2f}")
    print(f"HTTP 500, one bare litellm call (client defaults): {bare} requests in {bare_s:.2f} s")
    print(f"HTTP 500, pipflow retries=2 (one layer):          {ours} requests in {ours_s:.2f} s; message: {said!r}")
    print(f"HTTP 500, two stacked layers as before:            {3 * bare} requests (3 tries x {bare})")
    print(f"ratio of requests, before / now:                   {3 * bare / ours:.1f}x")
    print(f"slow server (5 s), timeout 1, retries 5, deadline 2.5: {slow} requests, ended after {slow_s:.2f} s; "
          f"message: {slow_said!r}")


if __name__ == "__main__":
    main()

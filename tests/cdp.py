"""A real headless Chromium driven over the DevTools protocol, for tests that must act on a page
(set a slider, pick a menu entry, click a cell) and then look: ``--screenshot`` alone cannot.

The websocket client is aiohttp's (a dependency of litellm, so installed with pipflow); Chromium
is the system's (see tests/test_report.py: a missing Chromium fails the test, never skips it).
Screenshots are kept in ``$PIPFLOW_SCREENSHOTS`` when it is set (the lead's copies).
"""
from __future__ import annotations

import asyncio
import base64
import json
import os
import re
import shutil
import subprocess
import tempfile
import time
import urllib.request
from pathlib import Path
from typing import Any

from test_report import chromium


class Browser:
    """One headless Chromium with one page. ``with Browser() as b: b.goto(url); b.eval(js)``."""

    def __init__(self, width: int = 1400, height: int = 1000):
        self.width, self.height = width, height
        self.profile = tempfile.mkdtemp(prefix="pipflow-cdp-")
        self.proc = subprocess.Popen(
            [chromium(), "--headless", "--no-sandbox", "--disable-gpu", "--no-first-run", "--disable-sync",
             "--disable-background-networking", "--disable-component-update", "--allow-file-access-from-files",
             "--remote-debugging-port=0", "--remote-allow-origins=*", f"--user-data-dir={self.profile}",
             f"--window-size={width},{height}", "about:blank"],
            stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
        port = None
        deadline = time.monotonic() + 120
        while port is None:
            line = self.proc.stderr.readline()
            if not line and self.proc.poll() is not None:
                raise RuntimeError("chromium ended before it listened")
            m = re.search(r"DevTools listening on ws://127\.0\.0\.1:(\d+)/", line)
            if m:
                port = int(m.group(1))
            if time.monotonic() > deadline:
                raise TimeoutError("chromium did not start its DevTools server")
        self.port = port
        pages = json.loads(urllib.request.urlopen(f"http://127.0.0.1:{port}/json/list", timeout=30).read())
        page = next(p for p in pages if p.get("type") == "page")
        self.loop = asyncio.new_event_loop()
        self._id = 0
        self.events: list[dict] = []
        self.console: list[str] = []
        self.loop.run_until_complete(self._connect(page["webSocketDebuggerUrl"]))
        self.send("Page.enable")
        self.send("Runtime.enable")
        self.send("Emulation.setDeviceMetricsOverride", width=width, height=height, deviceScaleFactor=1, mobile=False)

    async def _connect(self, url: str) -> None:
        import aiohttp

        self.session = aiohttp.ClientSession()
        self.ws = await self.session.ws_connect(url, max_msg_size=0)

    async def _send(self, method: str, params: dict) -> Any:
        self._id += 1
        my = self._id
        await self.ws.send_str(json.dumps({"id": my, "method": method, "params": params}))
        while True:
            msg = json.loads((await self.ws.receive(timeout=120)).data)
            if msg.get("id") == my:
                if "error" in msg:
                    raise RuntimeError(f"{method}: {msg['error']}")
                return msg.get("result")
            self._event(msg)

    def _event(self, msg: dict) -> None:
        self.events.append(msg)
        if msg.get("method") == "Runtime.exceptionThrown":
            self.console.append("Uncaught " + json.dumps(msg["params"].get("exceptionDetails", {}))[:500])
        elif msg.get("method") == "Runtime.consoleAPICalled":
            self.console.append(" ".join(str(a.get("value")) for a in msg["params"].get("args", [])))

    async def _wait_for(self, method: str, timeout: float) -> None:
        end = time.monotonic() + timeout
        if any(e.get("method") == method for e in self.events):
            return
        while time.monotonic() < end:
            msg = json.loads((await self.ws.receive(timeout=max(1.0, end - time.monotonic()))).data)
            self._event(msg)
            if msg.get("method") == method:
                return
        raise TimeoutError(f"no {method} within {timeout} s")

    def send(self, method: str, **params: Any) -> Any:
        return self.loop.run_until_complete(self._send(method, params))

    def goto(self, url: str, timeout: float = 120) -> None:
        self.events.clear()
        self.send("Page.navigate", url=url)
        self.loop.run_until_complete(self._wait_for("Page.loadEventFired", timeout))

    def eval(self, expression: str) -> Any:
        """The value of a JavaScript expression in the page (thrown errors raise)."""
        out = self.send("Runtime.evaluate", expression=expression, returnByValue=True, awaitPromise=True)
        if out.get("exceptionDetails"):
            raise RuntimeError(f"{expression}: {out['exceptionDetails']}")
        return out["result"].get("value")

    def screenshot(self, path: Path, full_page: bool = False) -> Path:
        params: dict[str, Any] = {"format": "png"}
        if full_page:
            height = int(self.eval("Math.ceil(document.documentElement.scrollHeight)"))
            params["clip"] = {"x": 0, "y": 0, "width": self.width, "height": min(height, 16000), "scale": 1}
            params["captureBeyondViewport"] = True
        data = self.send("Page.captureScreenshot", **params)["data"]
        Path(path).write_bytes(base64.b64decode(data))
        keep(Path(path))
        return Path(path)

    def close(self) -> None:
        try:
            self.loop.run_until_complete(self.ws.close())
            self.loop.run_until_complete(self.session.close())
        except Exception:
            pass
        self.loop.close()
        self.proc.terminate()
        try:
            self.proc.wait(timeout=20)
        except subprocess.TimeoutExpired:
            self.proc.kill()
        shutil.rmtree(self.profile, ignore_errors=True)

    def __enter__(self) -> "Browser":
        return self

    def __exit__(self, *exc: Any) -> None:
        self.close()


def keep(shot: Path, name: str | None = None) -> None:
    """Copy a screenshot into ``$PIPFLOW_SCREENSHOTS`` (when set) for people to look at."""
    folder = os.environ.get("PIPFLOW_SCREENSHOTS")
    if folder:
        Path(folder).mkdir(parents=True, exist_ok=True)
        shutil.copy(shot, Path(folder) / (name or shot.name))


def looks_drawn(shot: Path, min_colour: float = 0.005) -> None:
    """A screenshot that is not blank and has some colour (pictures, coloured cells)."""
    import numpy as np
    from PIL import Image

    img = np.asarray(Image.open(shot).convert("RGB"), dtype=float)
    assert img.std() > 10, f"{shot} looks blank"
    assert (img.reshape(-1, 3).std(axis=1) > 30).mean() > min_colour, f"{shot} has no colour"

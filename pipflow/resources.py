"""Where pipflow's data folders are (schemas, prompts, workflows, domains, benchmarks).

In an installed copy they sit inside the package (``site-packages/pipflow/schemas``); in a
clone or an editable install they sit at the top of the repository, next to ``pipflow/``.
Looking in both places, without importing anything, works for ``pip install .`` and ``-e .``.
"""
from __future__ import annotations

from pathlib import Path

_HERE = Path(__file__).resolve().parent


def data_dir(name: str) -> Path:
    """The folder ``name`` (e.g. ``"schemas"`` or ``"benchmarks/warehouse"``)."""
    for base in (_HERE, _HERE.parent):
        candidate = base / name
        if candidate.is_dir():
            return candidate
    raise FileNotFoundError(f"pipflow data folder {name!r} is missing from this installation")


def data_file(name: str) -> Path:
    """A file in a data folder, e.g. ``data_file("schemas/world.schema.json")``."""
    folder, _, file = name.rpartition("/")
    return data_dir(folder) / file

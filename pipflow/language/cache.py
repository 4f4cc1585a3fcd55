"""Content-addressed cache of LLM responses, so a committed prompt experiment replays offline.

The key is the sha256 of the model string, the rendered messages and every parameter that can
change the answer (temperature, max tokens, response format, grammar). Where the server runs
(``api_base``), time-outs and retries are left out: they do not change what the model says, and a
local server gets a new port every time. One JSON file per key, pretty-printed with sorted keys,
so that the folder diffs well in git; the stored text is returned exactly as it was received.
"""
from __future__ import annotations

import hashlib
import json
import os
from pathlib import Path
from typing import Any

DEFAULT_DIR = Path(".pipflow-cache") / "llm"


def cache_key(model: str, messages: list[dict[str, str]], params: dict[str, Any]) -> str:
    """sha256 over a canonical JSON of what determines the answer."""
    material = json.dumps({"model": model, "messages": messages, "params": params},
                          sort_keys=True, ensure_ascii=False, separators=(",", ":"))
    return hashlib.sha256(material.encode("utf-8")).hexdigest()


class ResponseCache:
    """A folder of ``<key>.json`` entries. ``directory=None`` means the default folder under the
    current working directory."""

    def __init__(self, directory: str | os.PathLike | None = None):
        self.directory = Path(directory) if directory else DEFAULT_DIR

    def path(self, key: str) -> Path:
        return self.directory / f"{key}.json"

    def get(self, key: str) -> dict[str, Any] | None:
        """The stored entry (``text``, ``usage``, ``model``, ...) or None."""
        p = self.path(key)
        if not p.is_file():
            return None
        try:
            return json.loads(p.read_text(encoding="utf-8"))
        except (OSError, json.JSONDecodeError):
            return None  # a damaged entry is a miss, and is overwritten by the next live call

    def put(self, key: str, entry: dict[str, Any]) -> Path:
        """Store an entry atomically (a crash never leaves half a file that replays wrong)."""
        from pipflow.engine.store import atomic_write

        data = json.dumps(entry, indent=2, sort_keys=True, ensure_ascii=False) + "\n"
        atomic_write(self.path(key), data)
        return self.path(key)

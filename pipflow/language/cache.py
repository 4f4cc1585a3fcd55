"""Content-addressed cache of LLM responses, so a committed prompt experiment replays offline.

The key is the sha256 of the model string, the rendered messages and every parameter that can
change the answer (temperature, max tokens, response format, grammar). Where the server runs
(``api_base``), time-outs and retries are left out: they do not change what the model says, and a
local server gets a new port every time. One JSON file per key, pretty-printed with sorted keys,
so that the folder diffs well in git; the stored text is returned exactly as it was received.

An entry is trusted only when it verifies: it is UTF-8 JSON, its model, messages and params hash
to its file's key, and its text hashes to the ``text_sha256`` stored with it. Anything else (a
torn write, an edit by hand, another tool's file, an entry of an older pipflow) is a miss, never
a failure: the damaged file is removed and the next live answer takes its place.
"""
from __future__ import annotations

import hashlib
import json
import os
from pathlib import Path
from typing import Any
from pipflow.engine.store import atomic_write

DEFAULT_DIR = Path(".pipflow-cache") / "llm"


def cache_key(model: str, messages: list[dict[str, str]], params: dict[str, Any]) -> str:
    """sha256 over a canonical JSON of what determines the answer."""
    material = json.dumps({"model": model, "messages": messages, "params": params},
                          sort_keys=True, ensure_ascii=False, separators=(",", ":"))
    return hashlib.sha256(material.encode("utf-8")).hexdigest()


def text_digest(text: str) -> str:
    return hashlib.sha256(text.encode("utf-8")).hexdigest()


def verified(key: str, entry: Any) -> bool:
    """True when ``entry`` is a whole, unaltered answer stored under ``key``."""
    if not isinstance(entry, dict):
        return False
    text, usage = entry.get("text"), entry.get("usage")
    if not isinstance(text, str) or not isinstance(usage, dict):
        return False
    if entry.get("text_sha256") != text_digest(text):
        return False
    try:
        return cache_key(entry["model"], entry["messages"], entry["params"]) == key
    except (KeyError, TypeError, ValueError):
        return False


class ResponseCache:
    """A folder of ``<key>.json`` entries. ``directory=None`` means the default folder under the
    current working directory."""

    def __init__(self, directory: str | os.PathLike | None = None):
        self.directory = Path(directory) if directory else DEFAULT_DIR

    def path(self, key: str) -> Path:
        return self.directory / f"{key}.json"

    def get(self, key: str) -> dict[str, Any] | None:
        """The stored entry (``text``, ``usage``, ``model``, ...) if it verifies, else None."""
        p = self.path(key)
        if not p.is_file():
            return None
        try:
            entry = json.loads(p.read_text(encoding="utf-8"))
        except (OSError, UnicodeDecodeError, ValueError, RecursionError):
            entry = None
        if verified(key, entry):
            return entry
        try:
            p.unlink()  # our own <key>.json that does not verify: a miss, and out of the way
        except OSError:
            pass
        return None

    def put(self, key: str, entry: dict[str, Any]) -> Path:
        """Store an entry atomically (a crash never leaves half a file that replays wrong), with
        the hash of its text. Raises OSError when the folder cannot be written."""
        entry = {**entry, "text_sha256": text_digest(entry["text"])}
        data = json.dumps(entry, indent=2, sort_keys=True, ensure_ascii=False) + "\n"
        atomic_write(self.path(key), data)
        return self.path(key)

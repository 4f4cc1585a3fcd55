"""Command-line argument readers shared by the engine's commands and the commands the library
registers (``pipflow.commands``): one reading of ``-i key=value`` and of a positive count
everywhere, without the library importing the engine's CLI module."""
from __future__ import annotations

import argparse
from typing import Sequence

from pipflow.errors import UserError


def positive_int(text: str) -> int:
    """argparse type: a whole number >= 1 (``--jobs 0`` or ``-5`` is a user error, exit 2)."""
    try:
        value = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a whole number") from None
    if value < 1:
        raise argparse.ArgumentTypeError(f"{value} is not allowed; give a whole number of 1 or more")
    return value


def port_number(text: str) -> int:
    """argparse type: a TCP port, 0 (any free port) to 65535 (``--port 99999`` is a user error)."""
    try:
        value = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a port number") from None
    if not 0 <= value <= 65535:
        raise argparse.ArgumentTypeError(f"{value} is not a port; give 1 to 65535 (or 0: any free port)")
    return value


def key_values(pairs: Sequence[str]) -> dict[str, str]:
    """``["a=1", "b=x=y"]`` -> ``{"a": "1", "b": "x=y"}``; a pair without ``=`` is a UserError."""
    out: dict[str, str] = {}
    for pair in pairs:
        if "=" not in pair:
            raise UserError(f"-i {pair!r}: expected key=value")
        key, value = pair.split("=", 1)
        out[key.strip()] = value
    return out

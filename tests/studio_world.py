"""The studio flat of the household reader tests (benchmarks/language/household-studio-world.yaml:
the radio and the overhead light are on, the teacup is dirty, the icebox and the pantry are shut),
and the goal a command reads as there, without its empty parts."""
from __future__ import annotations

from pathlib import Path

from pipflow.household.language.translator import translate
from pipflow.household.world import load_world

STUDIO = load_world(Path(__file__).resolve().parent.parent / "benchmarks" / "language" / "household-studio-world.yaml")


def studio_goal(command: str) -> dict:
    """What ``command`` asks of the studio: the goal's non-empty parts ("in", "state", ...)."""
    return {k: v for k, v in translate(command, STUDIO)["goal"].items() if v}

"""Where each place's name is written on a floor drawing, so that every name can be read.

Why: names written at a fixed size in the middle of their place ran over each other and off the
floor wherever places are small or close (a light switch beside a floor lamp), and white ink
outside a place could not be read. The replay (SVG) and the matplotlib maps draw from the same
layout, so a name sits in the same spot in both.
"""
from __future__ import annotations

from dataclasses import dataclass

#: a place's footprint on the floor: x, y (its lower edge), width, depth, in metres (y up)
Box = tuple[float, float, float, float]

#: a label's average glyph width over its font size (a sans-serif's)
GLYPH = 0.6


@dataclass(frozen=True)
class Label:
    """One name as drawn: its centre on the floor (metres, y up) and font size (metres)."""

    x: float
    y: float
    size: float
    upright: bool  # turned a quarter to read along a tall, narrow place
    inside: bool   # inside its place (light ink on the place) or beside it (dark ink on the floor)


def place_labels(places: list[tuple[str, Box]], floor: tuple[float, float], *, largest: float = 0.42,
                 smallest: float = 0.2, beside: float = 0.3) -> list[Label]:
    """A label per place, in order: inside the place as large as fits, up to ``largest`` (upright
    along a tall, narrow place when that fits larger); a place that cannot hold its name at
    ``smallest`` has it written beside it at size ``beside``, on the first side (below, above,
    right, left, then below shifted either way) where it overlaps no place and no name already
    written beside another and stays on the floor; when no side is clear, the one that overlaps least."""
    fw, fh = floor
    boxes = [box for _, box in places]
    written: list[Box] = []
    out = []
    for k, (name, box) in enumerate(places):
        x, y, w, h = box
        n = max(len(name), 1)
        across = min(largest, 0.9 * w / (GLYPH * n), 0.8 * h)
        upright = min(largest, 0.9 * h / (GLYPH * n), 0.8 * w)
        if max(across, upright) >= smallest:
            out.append(Label(x + w / 2, y + h / 2, max(across, upright), upright > across, True))
            continue
        tw, th, gap = GLYPH * beside * n, beside, 0.06
        lower = (x + w / 2 - tw / 2, y - gap - th)
        sides = [lower, (lower[0], y + h + gap), (x + w + gap, y + h / 2 - th / 2), (x - gap - tw, y + h / 2 - th / 2),
                 (x, lower[1]), (x + w - tw, lower[1])]
        sides = [(min(max(sx, 0.0), max(fw - tw, 0.0)), min(max(sy, 0.0), max(fh - th, 0.0))) for sx, sy in sides]
        others = [b for j, b in enumerate(boxes) if j != k] + written
        sx, sy = min(sides, key=lambda s: sum(_overlap((s[0], s[1], tw, th), o) for o in others))
        written.append((sx, sy, tw, th))
        out.append(Label(sx + tw / 2, sy + th / 2, beside, False, False))
    return out


def _overlap(a: Box, b: Box) -> float:
    """The area two boxes share (0 when apart)."""
    dx = min(a[0] + a[2], b[0] + b[2]) - max(a[0], b[0])
    dy = min(a[1] + a[3], b[1] + b[3]) - max(a[1], b[1])
    return dx * dy if dx > 0 and dy > 0 else 0.0

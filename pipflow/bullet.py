"""pybullet helpers every domain's simulation shares: a headless client without the banner, the
one camera that renders a floor plan, world colour names as RGBA.

A neutral module below the domains (the warehouse and household simulations both use it, neither
borrows from the other); pybullet, numpy and matplotlib are imported inside the functions on
purpose, so that importing a simulation module stays cheap until a scene is built."""
from __future__ import annotations

import contextlib
import ctypes
import io
import os
import sys
from pathlib import Path
from typing import Any

from pipflow.engine.writes import write_file


#: The common colour names with matplotlib's (CSS) values: looked up without importing
#: matplotlib (0.25 s of CPU a run would pay only to colour the unit bodies); other names and
#: hex codes go to matplotlib, and without it become grey.
_COMMON_COLOURS = {
    "red": (1, 0, 0, 1), "green": (0, 128 / 255, 0, 1), "blue": (0, 0, 1, 1), "magenta": (1, 0, 1, 1),
    "yellow": (1, 1, 0, 1), "cyan": (0, 1, 1, 1), "black": (0, 0, 0, 1), "white": (1, 1, 1, 1),
    "orange": (1, 165 / 255, 0, 1), "purple": (128 / 255, 0, 128 / 255, 1), "grey": (128 / 255, 128 / 255, 128 / 255, 1),
    "gray": (128 / 255, 128 / 255, 128 / 255, 1), "brown": (165 / 255, 42 / 255, 42 / 255, 1),
}


def colour_rgba(name: str) -> tuple[float, float, float, float]:
    """World colour name (or hex) -> RGBA in 0..1; unknown names become grey, never an error,
    because a colour only affects pictures."""
    common = _COMMON_COLOURS.get(str(name).strip().lower())
    if common is not None:
        return tuple(float(c) for c in common)  # type: ignore[return-value]
    try:
        from matplotlib.colors import to_rgba  # heavy: only for names outside the common ones

        return tuple(float(c) for c in to_rgba(name))  # type: ignore[return-value]
    except Exception:
        return (0.5, 0.5, 0.5, 1.0)


@contextlib.contextmanager
def _quiet_c_output():
    """Silence file descriptors 1 and 2 while pybullet loads and connects: its C library prints
    "pybullet build time" there, which would clutter every ``pipflow run`` and bench log."""
    sys.stdout.flush()
    sys.stderr.flush()
    saved = [os.dup(1), os.dup(2)]
    try:
        with open(os.devnull, "w") as devnull:
            os.dup2(devnull.fileno(), 1)
            os.dup2(devnull.fileno(), 2)
            yield
            ctypes.CDLL(None).fflush(None)  # the C library buffers its line: flush it while silenced
    finally:
        os.dup2(saved[0], 1)
        os.dup2(saved[1], 2)
        for fd in saved:
            os.close(fd)


def connect_direct() -> tuple[Any, int]:
    """A headless (DIRECT) pybullet client: ``(pybullet module, client id)``, without the banner."""
    with _quiet_c_output():
        import pybullet as p

        cid = p.connect(p.DIRECT)
    return p, cid


#: a label on a snapshot: text, the point it names (x, y, z in metres) and its kind (``robot``:
#: white on the robot's colour; ``place``: dark on light)
Label = tuple  # (text, (x, y, z), kind[, rgba])


def render_floor(p: Any, cid: int, floor: dict, path: Path, width: int, height: int,
                 labels: list[Label] | None = None, caption: str = "") -> Path:
    """Render a pybullet scene seen obliquely from the floor's front edge into a PNG; every
    domain's scene uses this one camera, so pictures compare across runs. ``labels`` are drawn
    where their points project (robot names, place names: the tiny renderer draws no text) and
    ``caption`` (the time and the moment) in the top left corner."""
    import numpy as np

    fw, fh = float(floor["width"]), float(floor["height"])
    # far and high enough that the whole floor, its front edge included (where robots often
    # start), stays in the frame
    view = p.computeViewMatrix((fw / 2, -0.55 * fh, 0.95 * max(fw, fh)), (fw / 2, 0.45 * fh, 0), (0, 0, 1),
                               physicsClientId=cid)
    proj = p.computeProjectionMatrixFOV(50, width / height, 0.1, 400, physicsClientId=cid)
    _, _, rgba, _, _ = p.getCameraImage(width, height, view, proj, renderer=p.ER_TINY_RENDERER,
                                        physicsClientId=cid)
    img = np.reshape(np.asarray(rgba, dtype=np.uint8), (height, width, 4))[:, :, :3]
    if labels or caption:
        img = _draw_labels(img, view, proj, labels or [], caption)
    path.parent.mkdir(parents=True, exist_ok=True)
    _save_png(path, img)
    return path


def project(view: Any, proj: Any, point: tuple, width: int, height: int) -> tuple[float, float] | None:
    """Where a world point lands in the picture (pixels from the top left), or None when it is
    behind the camera. pybullet's matrices are column-major lists of 16."""
    import numpy as np

    v = np.asarray(view, dtype=float).reshape(4, 4).T
    pr = np.asarray(proj, dtype=float).reshape(4, 4).T
    clip = pr @ v @ np.array([point[0], point[1], point[2], 1.0])
    if clip[3] <= 1e-9:
        return None
    x, y = clip[0] / clip[3], clip[1] / clip[3]
    return (x + 1) / 2 * width, (1 - y) / 2 * height


def _draw_labels(img: Any, view: Any, proj: Any, labels: list[Label], caption: str) -> Any:
    """Text on the rendered picture (PIL, which matplotlib brings); without PIL, the picture
    as it is."""
    import numpy as np

    try:
        from PIL import Image, ImageDraw, ImageFont
    except ImportError:
        return img
    h, w = img.shape[:2]
    picture = Image.fromarray(np.ascontiguousarray(img))
    draw = ImageDraw.Draw(picture)
    try:
        font = ImageFont.load_default(size=12)
        big = ImageFont.load_default(size=15)
    except TypeError:  # Pillow before 10.1: one size
        font = big = ImageFont.load_default()
    for label in labels:
        text, point, kind = label[0], label[1], label[2]
        at = project(view, proj, point, w, h)
        if at is None or not (0 <= at[0] < w and 0 <= at[1] < h):
            continue
        box = draw.textbbox((0, 0), str(text), font=font)
        tw, th = box[2] - box[0], box[3] - box[1]
        x, y = at[0] - tw / 2, at[1] - th - 6
        if kind == "robot":
            rgba = label[3] if len(label) > 3 else (0.2, 0.2, 0.2, 1)
            fill = tuple(int(255 * c * 0.8) for c in rgba[:3])
            draw.rectangle((x - 3, y - 2, x + tw + 3, y + th + 4), fill=fill)
            draw.text((x, y - box[1]), str(text), font=font, fill=(255, 255, 255))
        else:
            draw.rectangle((x - 2, y - 1, x + tw + 2, y + th + 3), fill=(255, 255, 240), outline=(90, 64, 48))
            draw.text((x, y - box[1]), str(text), font=font, fill=(40, 30, 20))
    if caption:
        box = draw.textbbox((0, 0), caption, font=big)
        draw.rectangle((4, 4, 14 + box[2] - box[0], 12 + box[3] - box[1]), fill=(255, 255, 255), outline=(60, 60, 60))
        draw.text((9, 8 - box[1]), caption, font=big, fill=(0, 0, 0))
    return np.asarray(picture)


def _save_png(path: Path, img) -> None:
    """Encode in memory, then write through pipflow's one writer (a link at ``path`` is replaced,
    never written through; a full disk is a DiskError)."""
    buffer = io.BytesIO()
    try:
        from PIL import Image

        Image.fromarray(img).save(buffer, format="PNG")
    except ImportError:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.image as mpimg

        mpimg.imsave(buffer, img, format="png")
    write_file(path, buffer.getvalue())

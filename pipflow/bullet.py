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


def render_floor(p: Any, cid: int, floor: dict, path: Path, width: int, height: int) -> Path:
    """Render a pybullet scene seen obliquely from the floor's front edge into a PNG; every
    domain's scene uses this one camera, so pictures compare across runs."""
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
    path.parent.mkdir(parents=True, exist_ok=True)
    _save_png(path, img)
    return path


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

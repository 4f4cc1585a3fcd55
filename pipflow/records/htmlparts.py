"""The pieces every report page is made of: escaping, cells and tables, the page's style, the
script that checks its pictures load, and the folder where the report draws its own pictures.

Why a module of their own: the run page, the bench page and the run-under-faults sections all
write the same table cells the same way; one place keeps them alike.
"""
from __future__ import annotations

import html
import json
from pathlib import Path
from typing import Any

from pipflow.engine.writes import make_dirs


CHECK_SCRIPT = """<script>
window.addEventListener('load', function () {
  var imgs = Array.prototype.slice.call(document.images);
  var bad = imgs.filter(function (i) { return !(i.complete && i.naturalWidth > 0); });
  document.body.dataset.images = String(imgs.length);
  document.body.dataset.imagesOk = (bad.length === 0 && imgs.length > 0) ? 'true' : 'false';
  document.body.dataset.imagesBad = bad.map(function (i) { return i.getAttribute('src'); }).join(' ');
});
</script>"""


STYLE = """<style>
body { font-family: sans-serif; margin: 2em; max-width: 1350px; color: #222; }
h1 { font-size: 1.5em; } h2 { border-bottom: 1px solid #ccc; padding-bottom: .2em; margin-top: 1.6em; }
table { border-collapse: collapse; margin: .5em 0; } td, th { border: 1px solid #bbb; padding: .25em .6em; }
th { background: #eef2f7; } td.num { text-align: right; font-variant-numeric: tabular-nums; }
.ok { color: #1a7f37; font-weight: bold; } .bad { color: #c62828; font-weight: bold; }
img { max-width: 100%; border: 1px solid #ddd; margin: .3em 0; }
.wide { overflow-x: auto; max-width: 100%; } .chart { overflow-x: auto; max-width: 100%; border: 1px solid #eee; } .chart img { max-width: none; border: 0; }
.snaps figure { display: inline-block; width: 48%; margin: .3em .5%; } .snaps img { width: 100%; } figcaption { text-align: center; color: #444; } pre { background: #f6f8fa; padding: .6em; overflow-x: auto; white-space: pre-wrap; }
.round { border: 1px solid #ccd; border-radius: 6px; padding: .2em 1em .6em; margin: .8em 0; }
.cause { border: 2px solid #c62828; border-radius: 6px; padding: .2em 1em; background: #fff5f5; }
pre.answer { max-height: 24em; overflow-y: auto; } .small { font-size: .85em; color: #555; } td.cmd, th.cmd { min-width: 18em; max-width: 28em; }
</style>"""


#: how a picture the report draws is linked until the page's place is known (a scheme, so the
#: rebasing of record links leaves it alone)
PIC = "pipflowpic:"


class Pictures:
    """The folder where the report draws its own pictures (created on first use; below the record
    ``root`` without following a link) and how the page links them."""

    def __init__(self, folder: Path, root: Path | None):
        self.folder, self.root, self._made = folder, root, False

    def path(self, name: str) -> Path:
        if not self._made:
            make_dirs(self.folder, root=self.root)
            self._made = True
        return self.folder / name

    @staticmethod
    def src(name: str) -> str:
        return PIC + name


def esc(x: Any) -> str:
    return html.escape(str(x), quote=True)


def read_json(path: Path, default: Any = None) -> Any:
    try:
        return json.loads(path.read_text(encoding="utf-8"))
    except (FileNotFoundError, json.JSONDecodeError):
        return default


def img(src: str, alt: str) -> str:
    return f"<img src='{esc(src)}' alt='{esc(alt)}'>"


class Raw(str):
    """Trusted HTML for a table cell (links, coloured status), written without escaping."""


def cell(x: Any, digits: int = 2) -> str:
    if isinstance(x, Raw):
        return str(x)
    if x is None:
        return "&ndash;"
    if isinstance(x, bool):
        return "<span class='ok'>yes</span>" if x else "<span class='bad'>no</span>"
    if isinstance(x, (int, float)):
        return f"{x:.{digits}f}" if isinstance(x, float) else str(x)
    return esc(x)


def table(headers: list[str], rows: list[list[Any]]) -> str:
    """An HTML table; a key-value table (every header empty) has no header row, not an empty one."""
    head = "".join(f"<th>{esc(h)}</th>" for h in headers) if any(headers) else ""
    body = "".join("<tr>" + "".join(
        f"<td class='num'>{cell(c)}</td>" if isinstance(c, (int, float)) or c is None else f"<td>{cell(c)}</td>"
        for c in row) + "</tr>" for row in rows)
    return f"<table>{f'<tr>{head}</tr>' if head else ''}{body}</table>"

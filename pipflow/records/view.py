"""``pipflow view [DIR]``: a local, read-only web page over a folder of runs and benches.

Why a server at all when reports are static files: the index has to reflect what is in the folder
now (runs keep arriving), and reports are written on demand the first time they are opened. The
server is the standard library's ``ThreadingHTTPServer`` bound to loopback only; it serves GET
requests for files inside DIR and a few generated pages, refuses any path that leaves DIR, and
never writes anything but the ``report.html`` (and its pictures) of a record that is opened.

Several folders may be viewed at once (``pipflow view`` shows ``runs/`` and ``bench-out/``); each
is then served under its name (``/runs/...``, ``/bench-out/...``).

Pages:
- ``/``: every run and bench under the folders (newest first) with its command and its headline
  figures, with filters by workflow, status and date (query parameters ``workflow``, ``status``,
  ``since``; the form on the page sets them), each row linking to its report; the runs of a bench
  are reached through the bench (its matrix), not listed one by one; tick two or more rows and
  "compare" opens ``/compare?r=..&r=..``.
- ``/report/<relative dir>``: that record's report (written if missing or older than the record).
- ``/compare?r=<rel>&r=<rel>...`` (or ``a=..&b=..``): runs, or benches per variant, side by side
  (:mod:`pipflow.records.compare`).
- ``<record>/report.html`` of a run: written on demand when missing (the seed links of a bench).
- anything else: the file under the folders, read-only.
"""
from __future__ import annotations

import errno
import html
import ipaddress
import json
import sys
import threading
import traceback
import urllib.parse
import webbrowser
from dataclasses import dataclass
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer
from pathlib import Path
from typing import Any

from pipflow.engine.recordref import command_of, headline
from pipflow.engine.status import RunStatus
from pipflow.engine.store import shown_status, stale_note
from pipflow.errors import InputError, UserError
from pipflow.records.compare import compare_html
from pipflow.records.report import write_report

#: the names under which a browser on this machine reaches the server; any other ``Host`` is a
#: page elsewhere that pointed its own domain at 127.0.0.1 (DNS rebinding)
LOOPBACK_HOSTS = ("127.0.0.1", "localhost", "::1")

_STYLE = """<style>
body { font-family: sans-serif; margin: 1.5em 2em; color: #222; }
table { border-collapse: collapse; width: 100%; } td, th { border: 1px solid #ccc; padding: .3em .6em; text-align: left; }
th { background: #eef2f7; } tr:hover { background: #f7f9fc; }
.succeeded { color: #1a7f37; font-weight: bold; } .failed, .refused, .interrupted { color: #c62828; font-weight: bold; }
.running { color: #b26a00; } form { margin: .8em 0; } input, select, button { margin-right: .6em; padding: .2em .4em; }
.small { color: #666; font-size: .9em; } td.cmd { max-width: 28em; }
</style>"""


@dataclass
class Record:
    """One run or bench found under the viewed folder."""

    kind: str  # run | bench
    rel: str  # path relative to the folder, with /
    name: str
    workflow: str
    status: str
    started: str
    seconds: float | None
    detail: str
    command: str = ""
    result: str = ""


def scan(root: Path, prefix: str = "") -> list[Record]:
    """Runs (folders with run.json) and benches (folders with results.json) under ``root``, newest
    first; the runs inside a bench are left to the bench (its report and matrix reach each one).
    A damaged record (not JSON, not a mapping, a text where a number belongs) is listed with
    status ``damaged`` rather than hiding the rest. ``prefix``: the mount of ``root`` in the URLs."""
    found: list[Record] = []
    benches = {m.parent for m in root.rglob("results.json")}
    for marker in sorted(root.rglob("run.json")) + sorted(root.rglob("results.json")):
        d = marker.parent
        kind = "run" if marker.name == "run.json" else "bench"
        if kind == "run" and any(b in d.parents for b in benches):
            continue
        rel = "/".join(x for x in (prefix, d.relative_to(root).as_posix()) if x and x != ".") or "."
        try:
            info = json.loads(marker.read_text(encoding="utf-8"))
            if not isinstance(info, dict):
                raise ValueError("not a mapping")
            found.append(_run_record(d, rel, info) if kind == "run" else _bench_record(d, rel, info))
        except (OSError, ValueError, TypeError, AttributeError) as err:
            found.append(Record(kind, rel, d.name, "?", "damaged", "", None, f"{marker.name}: {err}"))
    return sorted(found, key=lambda r: (r.started or r.name, r.name), reverse=True)


def _number(value: Any) -> float | None:
    return float(value) if isinstance(value, (int, float)) and not isinstance(value, bool) else None


def _run_record(d: Path, rel: str, info: dict) -> Record:
    shown = shown_status(d, info)
    status = str(shown)  # the record's word: succeeded, failed, stale...
    detail = str(info.get("error") or (stale_note(d, info) if shown is RunStatus.STALE else ""))
    result = ""
    if shown is RunStatus.SUCCEEDED:
        try:
            result = headline(json.loads((d / "outputs.json").read_text(encoding="utf-8")))
        except (OSError, ValueError):
            result = ""
    return Record("run", rel, d.name, str(info.get("name") or Path(str(info.get("workflow", "?"))).stem),
                  status, str(info.get("started") or ""), _number(info.get("seconds")), detail,
                  command_of(info), result)


def _bench_record(d: Path, rel: str, info: dict) -> Record:
    summary = info.get("summary") if isinstance(info.get("summary"), dict) else {}
    config = info.get("config") if isinstance(info.get("config"), dict) else {}
    sr = summary.get("sr")
    if sr is not None and _number(sr) is None:
        raise ValueError(f"summary.sr is {sr!r}, not a number")
    variants = [v for v in info.get("variants") or [] if isinstance(v, dict)]
    matrix = config.get("matrix") if isinstance(config.get("matrix"), dict) else {}
    what = f"bench of {Path(str(config.get('tasks') or '?')).name}" + (
        "; matrix " + "; ".join(f"{k}={','.join(map(str, v))}" for k, v in matrix.items()) if matrix else "")
    if len(variants) > 1:
        parts = []
        for v in variants:
            vs = v.get("summary") if isinstance(v.get("summary"), dict) else {}
            if _number(vs.get("sr")) is not None:
                parts.append(f"{v.get('name')}: SR {100 * float(vs['sr']):.0f}%")
        result = f"{summary.get('runs', '?')} runs per variant; " + "; ".join(parts)
    else:
        result = f"{summary.get('runs', '?')} runs, SR {100 * float(sr):.0f}%" if sr is not None else ""
        tc = _number(summary.get("tc_max"))
        result += f", TC-max {tc:.1f} m" if tc is not None and result else ""
    return Record("bench", rel, d.name, Path(str(config.get("workflow") or "?")).stem, "bench",
                  str(info.get("created") or info.get("started") or d.name), _number(info.get("wall_seconds")),
                  "", what, result)


def index_html(roots: "Path | dict[str, Path]", query: dict[str, str]) -> str:
    mounts = roots if isinstance(roots, dict) else {"": roots}
    records = [r for prefix, root in mounts.items() for r in scan(root, prefix)]
    records.sort(key=lambda r: (r.started or r.name, r.name), reverse=True)
    wf, status, since = query.get("workflow", ""), query.get("status", ""), query.get("since", "")
    shown = [r for r in records if (not wf or r.workflow == wf) and (not status or r.status == status)
             and (not since or (r.started or r.name) >= since)]
    workflows = sorted({r.workflow for r in records})
    statuses = sorted({r.status for r in records})

    def options(values: list[str], chosen: str) -> str:
        return "<option value=''>all</option>" + "".join(
            f"<option{' selected' if v == chosen else ''}>{html.escape(v)}</option>" for v in values)

    rows = []
    for r in shown:
        q = urllib.parse.quote(r.rel)
        secs = f"{r.seconds:.1f} s" if isinstance(r.seconds, (int, float)) else ""
        rows.append(f"<tr><td><input type='checkbox' name='pick' value='{html.escape(r.rel)}'></td>"
                    f"<td>{r.kind}</td><td><a href='/report/{q}'>{html.escape(r.name)}</a></td>"
                    f"<td>{html.escape(r.workflow)}</td><td class='{html.escape(r.status)}'>{html.escape(r.status)}</td>"
                    f"<td class='cmd'>{html.escape(r.command[:200])}</td><td>{html.escape(r.result)}</td>"
                    f"<td>{html.escape(r.started[:19])}</td><td>{secs}</td><td>{html.escape(r.detail[:160])}</td></tr>")
    table = ("<table id='records'><tr><th></th><th>kind</th><th>record</th><th>workflow</th><th>status</th>"
             "<th>command</th><th>result</th><th>started (UTC)</th><th>time</th><th>detail</th></tr>"
             + "".join(rows) + "</table>")
    script = """<script>
document.getElementById('cmp').addEventListener('click', function () {
  var picked = Array.prototype.slice.call(document.querySelectorAll("input[name=pick]:checked")).map(function (x) { return x.value; });
  if (picked.length < 2) { alert('Tick two or more records to compare.'); return; }
  location.href = '/compare?' + picked.map(function (x) { return 'r=' + encodeURIComponent(x); }).join('&');
});
</script>"""
    return (f"<!DOCTYPE html><html lang='en'><head><meta charset='utf-8'><title>pipflow: "
            f"{html.escape(', '.join(map(str, mounts.values())))}</title>"
            f"{_STYLE}</head><body><h1>pipflow records</h1><p class='small'>"
            f"{html.escape(', '.join(str(r.resolve()) for r in mounts.values()))}: "
            f"{len(shown)} of {len(records)} shown (a bench's runs: in its report)</p>"
            f"<form method='get'>workflow <select name='workflow'>{options(workflows, wf)}</select>"
            f"status <select name='status'>{options(statuses, status)}</select>"
            f"since <input name='since' type='date' value='{html.escape(since)}'>"
            f"<button type='submit'>filter</button><button type='button' id='cmp'>compare the ticked</button></form>"
            f"{table}{script}</body></html>")


class ViewServer:
    """The read-only server over one folder, or several (each under its name); ``url`` once
    started."""

    def __init__(self, root: "str | Path | list[str | Path]", port: int = 0):
        roots = [Path(r) for r in root] if isinstance(root, (list, tuple)) else [Path(root)]
        for r in roots:
            if not r.is_dir():
                raise InputError(f"{r}: no such folder to view")
        resolved = list(dict.fromkeys(r.resolve() for r in roots))
        self.root = resolved[0]
        self.mounts: dict[str, Path] = {"": self.root}
        if len(resolved) > 1:  # several folders: each under its name (runs/, bench-out/)
            self.mounts = {}
            for r in resolved:
                name, k = r.name or "root", 1
                while name in self.mounts:
                    k += 1
                    name = f"{r.name}-{k}"
                self.mounts[name] = r
        if not isinstance(port, int) or not 0 <= port <= 65535:
            raise InputError(f"--port {port}: not a port; give 1 to 65535 (or 0: any free port)")
        try:
            self._server = ThreadingHTTPServer(("127.0.0.1", port), self._handler())
        except OSError as err:
            cause = "it is in use (another server listens there)" if err.errno == errno.EADDRINUSE else \
                "this user may not listen there" if err.errno == errno.EACCES else (err.strerror or str(err))
            raise InputError(f"--port {port}: cannot listen on 127.0.0.1:{port}: {cause}; choose another "
                             "port, or leave --port out for any free one") from None
        self._server.daemon_threads = True
        self._thread: threading.Thread | None = None

    @property
    def url(self) -> str:
        return f"http://127.0.0.1:{self._server.server_address[1]}/"

    def start(self) -> "ViewServer":
        self._thread = threading.Thread(target=self._server.serve_forever, daemon=True)
        self._thread.start()
        return self

    def serve_forever(self) -> None:
        self._server.serve_forever()

    def stop(self) -> None:
        self._server.shutdown()
        self._server.server_close()

    def _inside(self, rel: str) -> Path | None:
        """The path ``rel`` names inside the viewed folder, or None (outside it, or no path a
        file system accepts: a NUL byte, a name too long, too many levels)."""
        text = urllib.parse.unquote(rel).lstrip("/")
        if "\x00" in text or len(text) > 4096:
            return None
        root = self.root
        if "" not in self.mounts:
            mount, _, text = text.partition("/")
            if mount not in self.mounts:
                return None
            root = self.mounts[mount]
        try:
            p = (root / text).resolve()
        except (OSError, ValueError, RuntimeError):
            return None
        return p if p == root or root in p.parents else None

    def run_link(self, bench: Any, run: dict) -> str | None:
        """The URL of a bench run's report (written on demand when opened)."""
        folder = bench.run_folder(run)
        rel = self.url_of(folder) if folder is not None else None
        return None if rel is None else "/" + urllib.parse.quote(rel) + "/report.html"

    def url_of(self, folder: Path) -> str | None:
        """The path of ``folder`` in this server's URLs (None: not under a viewed folder)."""
        p = Path(folder).resolve()
        for mount, root in self.mounts.items():
            if p == root or root in p.parents:
                rel = p.relative_to(root).as_posix()
                return "/".join(x for x in (mount, rel) if x and x != ".")
        return None

    def _handler(self) -> type[BaseHTTPRequestHandler]:
        view = self

        class Handler(BaseHTTPRequestHandler):
            def log_message(self, *args: Any) -> None:
                pass

            def do_GET(self) -> None:
                if not _loopback_host(self.headers.get("Host")):
                    return self._error(403, "this server answers only requests to 127.0.0.1, localhost or [::1]")
                try:
                    self._get()
                except Exception as err:  # a fault of the server: an answer saying so, never a dropped connection
                    traceback.print_exc(file=sys.stderr)
                    return self._error(500, f"pipflow view failed on this request: {type(err).__name__}: {err}")

            def _get(self) -> None:
                url = urllib.parse.urlsplit(self.path)
                query = {k: v[-1] for k, v in urllib.parse.parse_qs(url.query).items()}
                try:
                    if url.path in ("/", "/index.html"):
                        return self._page(index_html(view.mounts, query))
                    if url.path.startswith("/report/"):
                        d = view._inside(url.path[len("/report/"):])
                        if d is None or not d.is_dir():
                            return self._error(404, "no such record")
                        page = d / "report.html"
                        marker = d / ("results.json" if (d / "results.json").is_file() else "run.json")
                        if page.is_symlink() or not page.is_file() or \
                                (marker.is_file() and marker.stat().st_mtime > page.stat().st_mtime):
                            try:
                                write_report(d)
                            except UserError as err:  # a link in the record, a read-only or full disk
                                return self._error(409, f"the report of {d.name} cannot be written: {err}; "
                                                        f"`pipflow report {d} -o FILE` writes it elsewhere")
                        return self._redirect("/" + urllib.parse.quote(view.url_of(page) or ""))
                    if url.path == "/compare":
                        picked = urllib.parse.parse_qs(url.query).get("r") or \
                            [query[k] for k in ("a", "b") if k in query]
                        records = [view._inside(x) for x in picked]
                        if len(records) < 2 or any(r is None for r in records):
                            return self._error(404, "compare needs two or more records inside the viewed folders")
                        return self._page(compare_html(*records, links=[f"/report/{urllib.parse.quote(x)}" for x in picked],
                                                       run_link=view.run_link))
                    f = view._inside(url.path)
                    if f is not None and f.name == "report.html" and not f.is_file() and (f.parent / "run.json").is_file():
                        try:  # a seed link of a bench whose report was written elsewhere: the run's report now
                            write_report(f.parent)
                        except UserError as err:
                            return self._error(409, f"the report of {f.parent.name} cannot be written: {err}")
                    if f is None or not f.is_file():
                        return self._error(404, "not found")
                    kind = CONTENT_TYPES.get(f.suffix, "text/plain; charset=utf-8")
                    return self._send(200, f.read_bytes(), kind)
                except UserError as err:
                    return self._error(400, str(err))

            def _page(self, text: str) -> None:
                self._send(200, text.encode("utf-8"), "text/html; charset=utf-8")

            def _redirect(self, to: str) -> None:
                self.send_response(302)
                self.send_header("Location", to)
                self.send_header("Content-Length", "0")
                self.end_headers()

            def _error(self, code: int, message: str) -> None:
                self._send(code, f"<!DOCTYPE html><p>{html.escape(message)}</p>".encode(), "text/html; charset=utf-8")

            def _send(self, code: int, data: bytes, kind: str) -> None:
                try:
                    self.send_response(code)
                    self.send_header("Content-Type", kind)
                    self.send_header("Content-Length", str(len(data)))
                    self.end_headers()
                    self.wfile.write(data)
                except (BrokenPipeError, ConnectionResetError):
                    pass

        return Handler


#: what a record's file is served as, by its suffix (anything else: plain text, never run by the browser)
CONTENT_TYPES = {".html": "text/html; charset=utf-8", ".png": "image/png", ".json": "application/json",
                 ".gif": "image/gif", ".svg": "image/svg+xml"}


def _loopback_host(host: str | None) -> bool:
    """Whether a ``Host`` header names this machine's loopback (any port); no header (HTTP/1.0, a
    client on this machine) is let through, since browsers always send one."""
    if host is None:
        return True
    name = host.strip().lower()
    if name.startswith("["):  # [::1]:port
        name = name[1:].split("]", 1)[0]
    elif name.count(":") == 1:
        name = name.split(":", 1)[0]
    if name in LOOPBACK_HOSTS or name.endswith(".localhost"):
        return True
    try:  # 127.0.0.2 is loopback too; "127.0.0.1.example.com" is not an address
        return ipaddress.ip_address(name).is_loopback
    except ValueError:
        return False


def serve(root: "str | Path | list[str | Path]", port: int = 0, open_browser: bool = True,
          opened: Path | None = None) -> None:
    """Serve until Ctrl-C, printing the address (and opening it, or ``opened``'s report, in the
    user's browser)."""
    server = ViewServer(root, port)
    page = server.url
    if opened is not None and server.url_of(opened) is not None:
        page = server.url + "report/" + urllib.parse.quote(server.url_of(opened) or "")
    print(f"pipflow view: {page} (read-only, loopback; Ctrl-C stops)"
          + (f"; folders: {', '.join(str(r) for r in server.mounts.values())}" if len(server.mounts) > 1 else ""),
          flush=True)
    if open_browser:
        webbrowser.open(page)
    try:
        server.serve_forever()
    finally:
        server.stop()

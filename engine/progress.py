"""Show a run's progress: a live per-step status table on a terminal, plain lines otherwise
(CI logs, pipes). Both are fed by the run's events."""
from __future__ import annotations

import sys
import threading
import time
from typing import TextIO


class PlainProgress:
    """One line per finished step, for logs."""

    def __init__(self, stream: TextIO | None = None, verbose: bool = False):
        self.stream = stream if stream is not None else sys.stderr  # the stderr of now, not of import time
        self.verbose = verbose
        self.started = time.perf_counter()

    def __call__(self, event: dict) -> None:
        kind, step = event.get("event"), event.get("step")
        it = f" #{event['iteration']}" if "iteration" in event else ""
        stamp = f"[{time.perf_counter() - self.started:7.2f}s]"
        if kind == "end":
            extra = " (cached)" if event.get("cached") else ""
            if "iterations" in event:
                extra = f" ({event['iterations']} iteration(s))"
            word = "no   " if event.get("verdict") == "rejected" else "ok   "
            self._print(f"{stamp} {word} {step}{it} {event.get('duration', 0):.2f}s{extra}")
        elif kind == "error":
            self._print(f"{stamp} {event.get('status') or 'failed'} {step or ''}".rstrip())
        elif kind == "skip":
            self._print(f"{stamp} skip  {step}{it}")
        elif kind == "retry":
            self._print(f"{stamp} retry {step}{it}: {event.get('error')}")
        elif kind == "iteration" and not event.get("done"):
            self._print(f"{stamp} loop  {step}: iteration {event['iteration']} did not meet its condition")
        elif kind == "warning":
            self._print(f"{stamp} warn  {step}: {event.get('message')}")
        elif kind == "log" and self.verbose:
            self._print(f"{stamp} log   {step}: {event.get('message')}")
        elif kind == "start" and self.verbose:
            self._print(f"{stamp} start {step}{it}")

    def _print(self, line: str) -> None:
        print(line, file=self.stream, flush=True)

    def close(self) -> None:
        pass


class LiveProgress:
    """A rich live table: one row per step with its status and time."""

    def __init__(self, step_ids: list[str], stream: TextIO = sys.stderr):
        from rich.console import Console
        from rich.live import Live

        self.rows: dict[str, list[str]] = {sid: ["waiting", ""] for sid in step_ids}
        self._lock = threading.Lock()
        self.live = Live(self._table(), console=Console(file=stream), refresh_per_second=8, transient=False)
        self.live.start()

    def _table(self):
        from rich.table import Table

        table = Table(show_header=True, header_style="bold", box=None)
        table.add_column("step")
        table.add_column("status")
        table.add_column("time", justify="right")
        styles = {"running": "yellow", "ok": "green", "skipped": "dim", "failed": "red", "cached": "cyan",
                  "rejected": "magenta", "not": "dim"}
        for sid, (status, secs) in self.rows.items():
            table.add_row(sid, f"[{styles.get(status.split()[0], 'white')}]{status}[/]", secs)
        return table

    def __call__(self, event: dict) -> None:
        kind, step = event.get("event"), event.get("step")
        if kind == "warning":
            from rich.markup import escape

            self.live.console.print(f"[yellow]warning[/] {escape(str(step))}: {escape(str(event.get('message')))}",
                                    markup=True, highlight=False)
        if step not in self.rows:
            return
        with self._lock:
            if kind == "start":
                it = f" (round {event['iteration']})" if "iteration" in event else ""
                self.rows[step] = ["running" + it, ""]
            elif kind == "end":
                status = "rejected" if event.get("verdict") == "rejected" else "cached" if event.get("cached") else "ok"
                self.rows[step] = [status, f"{event.get('duration', 0):.2f}s"]
            elif kind == "skip":
                self.rows[step] = ["skipped", ""]
            elif kind == "error":
                self.rows[step] = ["failed", ""]
                self._not_run()
            self.live.update(self._table())

    def _not_run(self) -> None:
        """After a failure nothing else starts: say so instead of leaving rows `waiting`."""
        for sid, (status, _) in self.rows.items():
            if status == "waiting":
                self.rows[sid] = ["not run", ""]

    def close(self) -> None:
        self.live.stop()

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


def _duration(seconds: float) -> str:
    """``1h 02m``, ``3m 10s``, ``42s``."""
    seconds = max(0, int(round(seconds)))
    h, rest = divmod(seconds, 3600)
    m, s = divmod(rest, 60)
    return f"{h}h {m:02d}m" if h else f"{m}m {s:02d}s" if m else f"{s}s"


class CountProgress:
    """Progress of many units of work (a bench's runs) where no terminal shows a live bar (CI,
    ``nohup``, output to a file): a line every ``every`` finished units (default: a twentieth of
    the total) and every ``seconds`` without one, with done/total, the rate and the time left::

        bench (local): 12/89 runs (13%), 4m 10s elapsed, 2.9 runs/min, about 26m 33s left
    """

    def __init__(self, label: str, total: int, done: int = 0, stream: TextIO | None = None,
                 every: int | None = None, seconds: float = 30.0):
        self.label, self.total, self.start_done, self.done = label, total, done, done
        self.stream = stream if stream is not None else sys.stderr
        self.every = every or max(1, total // 20)
        self.seconds = seconds
        self.started = time.monotonic()
        self._lock = threading.Lock()
        self._stop = threading.Event()
        self._last = self.started
        self._thread = threading.Thread(target=self._tick, name="pipflow-progress", daemon=True)
        self._thread.start()
        self._print()

    def line(self) -> str:
        elapsed = time.monotonic() - self.started
        fresh = self.done - self.start_done
        pct = f" ({100 * self.done / self.total:.0f}%)" if self.total else ""
        text = f"{self.label}: {self.done}/{self.total} runs{pct}, {_duration(elapsed)} elapsed"
        if fresh > 0 and elapsed > 0:
            rate = fresh / elapsed
            text += (f", {rate * 60:.1f} runs/min" if rate < 1 else f", {rate:.1f} runs/s")
            if self.done < self.total:
                text += f", about {_duration((self.total - self.done) / rate)} left"
        elif self.done < self.total:
            text += ", time left: after the first run"
        return text

    def advance(self, n: int = 1) -> None:
        with self._lock:
            self.done += n
            if self.done >= self.total or (self.done - self.start_done) % self.every == 0:
                self._print()

    def _print(self) -> None:
        self._last = time.monotonic()
        try:
            print(self.line(), file=self.stream, flush=True)
        except (OSError, ValueError):  # a closed stream must not stop the work
            pass

    def _tick(self) -> None:
        while not self._stop.wait(1.0):
            with self._lock:
                if time.monotonic() - self._last >= self.seconds and self.done < self.total:
                    self._print()

    def close(self) -> None:
        self._stop.set()

"""Commands that the library adds to the ``pipflow`` command line: report, view, compare.

Why here and not in ``engine/cli.py``: the engine knows no particular step and no part of the
library; these commands are registered through the ``pipflow.commands`` entry-point group (as
steps are through ``pipflow.steps``), so the CLI imports nothing above it. Each entry point is a
function ``register(subparsers, common)`` that adds its sub-commands.
"""
from __future__ import annotations

import argparse
from pathlib import Path


def register(sub: argparse._SubParsersAction, common: argparse.ArgumentParser) -> None:
    report = sub.add_parser("report", parents=[common], help="write a static HTML report of a run or a bench")
    report.add_argument("dir", help="run directory or bench output directory")
    report.add_argument("-o", "--output", help="HTML file (default: DIR/report.html)")
    report.set_defaults(func=cmd_report)

    view = sub.add_parser("view", parents=[common],
                          help="browse runs and benches in a local read-only web page (loopback)")
    view.add_argument("dir", nargs="?", default=None, help="folder of runs/benches (default: --runs-dir, ./runs)")
    view.add_argument("--port", type=int, default=0, help="port on 127.0.0.1 (default: any free port)")
    view.add_argument("--no-browser", action="store_true", help="print the address only")
    view.set_defaults(func=cmd_view)

    compare = sub.add_parser("compare", parents=[common], help="two runs or two benches side by side")
    compare.add_argument("a", help="run or bench directory")
    compare.add_argument("b", help="run or bench directory")
    compare.set_defaults(func=cmd_compare)


def cmd_report(args: argparse.Namespace) -> int:
    from pipflow.report import write_report

    print(write_report(Path(args.dir), Path(args.output) if args.output else None))
    return 0


def cmd_view(args: argparse.Namespace) -> int:
    from pipflow.view import serve

    serve(args.dir or getattr(args, "runs_dir", None) or "runs", port=args.port, open_browser=not args.no_browser)
    return 0


def cmd_compare(args: argparse.Namespace) -> int:
    from pipflow.compare import compare_text

    print(compare_text(Path(args.a), Path(args.b)))
    return 0

"""Errors of the libraries pipflow drives, translated at the boundary into pipflow's own.

unified-planning, SCIP (pyscipopt) and litellm each raise their own kinds of error, and some raise
plain builtins: UP's PDDL reader answers a bad problem with pyparsing's ``ParseException``, a
``SyntaxError`` or a ``KeyError``; pyscipopt raises ``Exception('SCIP: ...')``, ``Warning`` and
``ValueError``. A bare ``except Exception`` around such a call would also swallow pipflow's own
bugs and show them to the user as if the input were wrong. So a call into a library is wrapped in
:func:`library_errors` (the style of httpx's ``map_exceptions``), which translates an error *of
that library* into the pipflow error given, with a message that names the library and the
cause, and lets everything else through untouched::

    with library_errors(UNIFIED_PLANNING, PDDLError, "parsing the problem"):
        problem = parse(domain, text)

An error belongs to a library when it is an instance of one of the library's exception classes,
or when the innermost frame that raised it (standard-library frames skipped, so that an
``OSError`` from ``subprocess`` inside UP still counts as UP's) is in one of the library's
packages. pipflow's own errors always pass through unchanged (the library called back into
pipflow, which already said what went wrong).

Nothing here imports a library: the exception classes are looked up among the modules already
imported (an error of a library that was never imported cannot happen).
"""
from __future__ import annotations

import sys
from contextlib import contextmanager
from dataclasses import dataclass
from types import TracebackType
from typing import Iterator

from pipflow.errors import PipflowError

_STDLIB = frozenset(sys.stdlib_module_names) | {"builtins"}


@dataclass(frozen=True)
class Library:
    """A library whose errors pipflow translates: the name shown to the user, the top-level
    packages whose frames mark an error as the library's (``up_*``: every package so named), and
    its exception classes as ``(module, class name)`` pairs (looked up only if that module is
    already imported)."""

    name: str
    packages: tuple[str, ...]
    classes: tuple[tuple[str, str], ...] = ()

    def exception_types(self) -> tuple[type[BaseException], ...]:
        """The library's exception classes among the modules imported so far."""
        found = []
        for module, cls in self.classes:
            kind = getattr(sys.modules.get(module), cls, None)
            if isinstance(kind, type) and issubclass(kind, BaseException):
                found.append(kind)
        return tuple(found)

    def owns(self, exc: BaseException) -> bool:
        """Did this library raise ``exc``? (see the module docstring)"""
        if isinstance(exc, PipflowError):
            return False
        if isinstance(exc, self.exception_types()):
            return True
        origin = raised_in(exc)
        return origin is not None and any(origin == p or (p.endswith("*") and origin.startswith(p[:-1]))
                                          for p in self.packages)


def raised_in(exc: BaseException) -> str | None:
    """The top-level package of the innermost non-standard-library frame that ``exc`` passed
    through (``pyscipopt`` for an error in SCIP's Cython code), or None."""
    package = None
    tb: TracebackType | None = exc.__traceback__
    while tb is not None:
        name = str(tb.tb_frame.f_globals.get("__name__") or "")
        top = name.split(".", 1)[0]
        if top and top not in _STDLIB:
            package = top
        tb = tb.tb_next
    return package


UNIFIED_PLANNING = Library(
    "unified-planning",
    # the planners UP runs (ENHSP, Fast Downward, ...) are up_* packages; pyparsing is its PDDL reader
    packages=("unified_planning", "up_*", "pyparsing"),
    classes=(("unified_planning.exceptions", "UPException"), ("pyparsing.exceptions", "ParseBaseException")),
)
SCIP = Library("SCIP (pyscipopt)", packages=("pyscipopt",))
LITELLM = Library(
    "litellm",
    # litellm maps every provider's error onto its own classes, most of them openai's subclasses;
    # a transport error can still come up raw from the HTTP clients below it
    packages=("litellm", "openai", "httpx", "httpcore", "aiohttp"),
    classes=(("openai", "OpenAIError"), ("httpx", "HTTPError")),
)


def describe(library: Library, doing: str, exc: BaseException) -> str:
    """``unified-planning failed while parsing the problem: SyntaxError: ...`` on one line."""
    cause = " ".join(str(exc).split()) or "(no message)"
    if len(cause) > 600:
        cause = cause[:600] + " ..."
    return f"{library.name} failed while {doing}: {type(exc).__name__}: {cause}"


@contextmanager
def library_errors(library: Library, to: type[PipflowError], doing: str) -> Iterator[None]:
    """Raise ``to`` (a pipflow error) for an error of ``library`` inside the block, naming the
    library, what it was ``doing`` and the cause; the original stays chained as ``__cause__``
    for ``-v``. Every other exception passes through unchanged."""
    try:
        yield
    except Exception as exc:
        if not library.owns(exc):
            raise
        raise to(describe(library, doing, exc)) from exc

"""How a run stands: one enum for the engine, the records, the bench and the API.

Why an enum: the status is written by the runner and read by ``show``, ``runs``, the report, the
view, the bench and the API; as bare strings each reader spelled success its own way (the report
accepted five spellings). The members are strings (``RunStatus.SUCCEEDED == "succeeded"``), so
``run.json`` and every JSON record keep the same words as before, and a status read back from a
record is turned into a member by :meth:`RunStatus.of`.
"""
from __future__ import annotations

from enum import Enum


class RunStatus(str, Enum):
    """The status of a run record (``run.json``'s ``status``)."""

    #: the run's process is writing the record
    RUNNING = "running"
    #: every step finished; the outputs are in ``outputs.json``
    SUCCEEDED = "succeeded"
    #: a step failed (or the workflow could not go on): ``error`` and ``error_step`` say which
    FAILED = "failed"
    #: the command was refused as impossible (a :class:`pipflow.errors.Refusal`): nothing moved
    REFUSED = "refused"
    #: Ctrl-C, SIGTERM or SIGHUP ended the run; ``pipflow resume`` continues it
    INTERRUPTED = "interrupted"
    #: the record says ``running`` but no process holds its lock (killed, a power cut): shown by
    #: readers, never written
    STALE = "stale"

    def __str__(self) -> str:  # the word itself, as in the records (not "RunStatus.FAILED")
        return self.value

    @property
    def ok(self) -> bool:
        """Whether the run did what it was asked: only ``succeeded``."""
        return self is RunStatus.SUCCEEDED

    @property
    def finished(self) -> bool:
        """Whether the run ended (in any way) and its record is complete."""
        return self in (RunStatus.SUCCEEDED, RunStatus.FAILED, RunStatus.REFUSED, RunStatus.INTERRUPTED)

    @classmethod
    def of(cls, value: object) -> "RunStatus | None":
        """The status a record's text names, or None for a word that names none (a damaged or
        foreign record: readers show the word as it is, never as success)."""
        try:
            return cls(str(value))
        except ValueError:
            return None

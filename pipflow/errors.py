"""The one exception hierarchy of pipflow.

Every error a user can cause derives from :class:`PipflowError`; the CLI prints those as one
clear message and exits with the class's ``exit_code`` (no traceback unless ``-v``). Anything
else that escapes is a bug in pipflow and is shown with its traceback.

    PipflowError                      exit 1
    ├── UserError                     exit 2   bad file, bad input, missing key
    │   ├── WorkflowError                      workflow fails validation (carries diagnostics)
    │   ├── WorldError                         world file fails validation (carries diagnostics)
│   │   └── TaskFileError                  task file fails validation (itself or its world)
    │   ├── SourceFileError                    a file cannot be read or parsed as YAML (carries diagnostics)
    │   └── InputError                         a step argument or CLI input is wrong
    │       └── PDDLError                      a PDDL text does not parse against its domain
    ├── StepError                     exit 1   a step failed while running
    │   ├── PlanningError                      planner could not solve (time-out, engine error)
    │   ├── AllocationError                    no feasible coalition for a subtask
    │   │   └── TeamLacksSkill   (also a Refusal) no robot allowed has a skill a subtask needs: exit 3
    │   ├── LLMError                           provider call failed after retries
    │   ├── AnswerFormatError                  a model's answer is not in the form its method reads
    │   └── TranslationError                   the offline translator cannot resolve the command
    └── Refusal                       exit 3   the command is infeasible; the reason is the message

Errors of the libraries pipflow drives (unified-planning, SCIP, litellm) are translated into these
at the boundary by :func:`pipflow.liberrors.library_errors`, never caught with a bare ``except``.
"""
from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class Location:
    """Where something is in a source file (1-based line and column)."""

    file: str
    line: int = 0
    column: int = 0

    def __str__(self) -> str:
        if self.line:
            return f"{self.file}:{self.line}:{self.column}"
        return self.file


@dataclass(frozen=True)
class Diagnostic:
    """One problem found in a file, with where it is and, optionally, a hint."""

    location: Location | None
    message: str
    kind: str = "error"

    def __str__(self) -> str:
        where = f"{self.location}: " if self.location else ""
        return f"{where}{self.message}"


class PipflowError(Exception):
    """Root of every error pipflow raises on purpose."""

    exit_code = 1


class UserError(PipflowError):
    """The user's input is wrong: a file, an argument, a missing key."""

    exit_code = 2


class _DiagnosticsError(UserError):
    """A user error that lists every problem found at once."""

    def __init__(self, diagnostics: list[Diagnostic], title: str = ""):
        self.diagnostics = list(diagnostics)
        lines = [title] if title else []
        lines += [str(d) for d in self.diagnostics]
        super().__init__("\n".join(lines))


class WorkflowError(_DiagnosticsError):
    """A workflow file is invalid; ``diagnostics`` lists every problem with its location."""


class WorldError(_DiagnosticsError):
    """A world file is invalid; ``diagnostics`` lists every problem with its location."""


class TaskFileError(WorldError):
    """A task file (benchmarks/README.md) is invalid, or the world it names is; a WorldError
    because a task file is checked against its world and callers catch both alike."""


class SourceFileError(_DiagnosticsError):
    """A user's file cannot be read (missing, not a regular file, too big, not UTF-8) or parsed
    (YAML syntax, nesting or alias limits); ``diagnostics`` says where and why."""


class InputError(UserError):
    """A step argument or a CLI input is wrong."""


class PDDLError(InputError):
    """A PDDL problem (or domain) text does not parse against its domain: UP's reader rejected
    it. Raised by :func:`pipflow.liberrors.library_errors` with the reader's own words."""


class FaultNotApplicable(PipflowError):
    """A fault asked for by count has nothing in this run to strike: its target is drawn from the
    run (a robot with work, a passage on a route, a place the plan takes from) and the run offers
    none. Not a user error: the run goes on without that fault and records it as not applicable,
    with this message as the reason (:mod:`pipflow.execution.faults`). A fault that names its
    target never raises it: a target the world lacks is an :class:`InputError`."""


class StepError(PipflowError):
    """A step failed while running."""


class StepDefinitionError(PipflowError):
    """A step's code contradicts its contract (a parameter without a type, a default of another
    type, ``inputs=`` that drifted from the signature, an undeclared output): the step author's
    error, raised when the step is registered or returns."""


class PlanningError(StepError):
    """The planner failed: time-out, engine error, or an unusable plan."""


class AllocationError(StepError):
    """No coalition of robots can do a subtask under the skills and rules given."""


class LLMError(StepError):
    """A language-model call failed after its retries."""


class AnswerFormatError(StepError):
    """A model's answer is not in the form its method reads (a baseline's plan, code or summary),
    and the method gives it no further round; the message says where (line and column) and why.
    Not the user's error: the model wrote it."""


class TranslationError(StepError):
    """The offline translator cannot resolve part of a command (it never guesses).

    ``candidates``: up to three readings the reader could offer instead (each a dict with
    ``reading``, the plain words of what it would do, and ``words``, the command's words it rests
    on, plus the goal and rules it would give), for a user to choose from; empty when there is
    nothing to offer. A refusal stays a refusal: a candidate is never acted on unchosen."""

    def __init__(self, *args: object, candidates: list | None = None):
        super().__init__(*args)
        self.candidates: list = list(candidates or [])


class Refusal(PipflowError):
    """The command cannot be satisfied in this world; the message says why."""

    exit_code = 3


class TeamLacksSkill(AllocationError, Refusal):
    """A subtask needs a skill that no robot the command may use has at all ("pickup: the whole
    team has 0"): no plan and no solver can do it with this team, so the command is refused as
    impossible (exit 3, a refused run), as the household benchmark's tasks impossible only for
    their team expect. Still an :class:`AllocationError`, so a re-allocation after a fault
    handles it as one."""

    exit_code = 3

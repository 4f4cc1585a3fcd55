"""Generic steps that any workflow may use: pass a value along, log, refuse with a reason."""
from __future__ import annotations

from typing import Annotated, Any

from pipflow import Doc, StepContext, step
from pipflow.errors import InputError, Refusal, StepError


@step("core.value", doc="Pass a value through unchanged (constants, demos, renaming).",
      outputs={"value": "any"})
def value(
    ctx: StepContext,
    value: Annotated[Any, Doc("the value")],
) -> dict:
    return {"value": value}


@step("core.log", doc="Write a message into the run's event log.",
      outputs={"message": "string"})
def log(
    ctx: StepContext,
    message: Annotated[str, Doc("the text to log")],
) -> dict:
    ctx.log(message)
    return {"message": message}


@step("core.refuse", doc="End the run as refused (exit 3) when a reason is given; pass otherwise.",
      outputs={"refused": "boolean"})
def refuse(
    ctx: StepContext,
    reason: Annotated[Any, Doc("why the command cannot be done; empty = no refusal")] = None,
    detail: Annotated[Any, Doc("extra context kept in the run record")] = None,
) -> dict:
    if reason:
        if detail:
            ctx.write_artifact("refusal.json", {"reason": reason, "detail": detail})
        raise Refusal(str(reason))
    return {"refused": False}


@step("core.fail", doc="Fail the run with a message when the condition holds (assertions in workflows).",
      outputs={"failed": "boolean"})
def fail(
    ctx: StepContext,
    message: Annotated[str, Doc("the error message")],
    condition: Annotated[Any, Doc("fail only when this is true")] = True,
) -> dict:
    if condition:
        raise StepError(message)
    return {"failed": False}


@step("core.require", doc="Stop the run as the user's error (exit 2) unless a condition holds: a workflow's "
                          "requirement on its inputs (a model where only a model can do the work).",
      outputs={"ok": "boolean"})
def require(
    ctx: StepContext,
    condition: Annotated[Any, Doc("what must hold")],
    message: Annotated[str, Doc("what the user must change, when it does not")],
) -> dict:
    if not condition:
        raise InputError(message)
    return {"ok": True}

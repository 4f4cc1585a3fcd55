"""Generic steps that any workflow may use: pass a value along, log, refuse with a reason."""
from __future__ import annotations

from pipflow import Input, StepContext, step
from pipflow.errors import Refusal


@step("core.value", doc="Pass a value through unchanged (constants, demos, renaming).",
      inputs={"value": Input("any", doc="the value")}, outputs={"value": "any"})
def value(ctx: StepContext, value):
    return {"value": value}


@step("core.log", doc="Write a message into the run's event log.",
      inputs={"message": Input("string", doc="the text to log")}, outputs={"message": "string"})
def log(ctx: StepContext, message: str):
    ctx.log(message)
    return {"message": message}


@step("core.refuse", doc="End the run as refused (exit 3) when a reason is given; pass otherwise.",
      inputs={"reason": Input("any", default=None, doc="why the command cannot be done; empty = no refusal"),
              "detail": Input("any", default=None, doc="extra context kept in the run record")},
      outputs={"refused": "boolean"})
def refuse(ctx: StepContext, reason=None, detail=None):
    if reason:
        if detail:
            ctx.write_artifact("refusal.json", {"reason": reason, "detail": detail})
        raise Refusal(str(reason))
    return {"refused": False}


@step("core.fail", doc="Fail the run with a message when the condition holds (assertions in workflows).",
      inputs={"message": Input("string", doc="the error message"),
              "condition": Input("any", default=True, doc="fail only when this is true")},
      outputs={"failed": "boolean"})
def fail(ctx: StepContext, message: str, condition=True):
    from pipflow.errors import StepError

    if condition:
        raise StepError(message)
    return {"failed": False}

"""Built-in steps, one module per family. The registry imports each module listed here and
registers every :class:`pipflow.Step` it defines (entry point ``builtin`` of ``pipflow.steps``).
Step modules stay thin and import heavy libraries (UP, SCIP, pybullet, litellm) inside the step
functions, so that listing steps or running a workflow that does not use them stays fast."""

STEP_MODULES = [
    "pipflow.steps.core",
    "pipflow.steps.world",
    "pipflow.steps.pddl",
    "pipflow.steps.problem",
    "pipflow.steps.graph",
    "pipflow.steps.allocate",
    "pipflow.steps.schedule",
    "pipflow.steps.llm",
    "pipflow.steps.simulate",
    "pipflow.steps.metrics",
    "pipflow.steps.household",
]

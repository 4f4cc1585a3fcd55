"""pipflow-garden: a third task domain for pipflow, installed as a plugin.

Robots water beds (fetching water at a tap), prune overgrown beds and harvest ripe crops into
stores; heavy crops need a coalition of carriers. The package brings everything a task domain
needs -- a team-level PDDL domain and its action metadata (``data/``), a world file format
(:mod:`pipflow_garden.world`), an offline command reader (:mod:`pipflow_garden.language`), a problem
writer, a kinematic simulator, the facts of scoring, a task file and a workflow
(``workflows/garden.yaml``) -- and registers itself through the entry-point group
``pipflow.task_domains`` (the :class:`~pipflow_garden.domain.GardenDomain`). It changes nothing in
pipflow and imports nothing of it but the public face, :mod:`pipflow.plugin`.
"""

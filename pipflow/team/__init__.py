"""Team coordination: from a team plan to who does what, when, and along which path.

One sub-package so that the tree shows this stage of the pipeline (paper Sec. IV-B and IV-C);
every module here is generic (no task domain), below the steps that are its faces:

* :mod:`~pipflow.team.dependency`  plan -> subtask dependency DAG (Alg. 2: exact, paper, deorder)
* :mod:`~pipflow.team.deorder`     minimal deordering: orders kept only where a precondition needs them
* :mod:`~pipflow.team.allocation`  skill-based MRTA (SCIP lexicographic IP, fast first stage, baselines)
* :mod:`~pipflow.team.scheduling`  Alg. 1 timing: legs, start/end, makespan
* :mod:`~pipflow.team.travel`      obstacle-free shortest paths on a floor plan (the allocation's costs)
* :mod:`~pipflow.team.trajectory`  planned motion as data (legs in time), shared by simulations and pictures
"""

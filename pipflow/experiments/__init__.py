"""Experiments: running a task file's runs and summing them up (``pipflow bench``).

A sub-package above the steps and below the faces (api, commands); the library never imports it:

* :mod:`~pipflow.experiments.benchmarking`  the runner: tasks x seeds x variants, result rows, the tables
* :mod:`~pipflow.experiments.runspec`       one bench run (RunSpec, run_one), below both runner and backends
* :mod:`~pipflow.experiments.backends`      where the runs execute: a local process pool or a Dask cluster
  (named apart from the engine's executor, which runs the steps of one workflow)
* :mod:`~pipflow.experiments.benchdomains`  the bench's view of the task-domain registry (a task file's domain)
* :mod:`~pipflow.experiments.benchstats`    per-task rows and summaries of scored runs (every domain)

Why not ``pipflow.bench``: that name is the public function :func:`pipflow.bench`; a submodule of
that name would replace it on the package once imported.
"""

"""Records: reading what runs and benches left behind, never changing it.

A sub-package above the steps and below the experiments and the faces; the library never imports it:

* :mod:`~pipflow.records.report`   static HTML report of a run directory or a bench directory
* :mod:`~pipflow.records.view`     ``pipflow view``: a local server over the records
* :mod:`~pipflow.records.compare`  two runs or two benches side by side

:mod:`pipflow.pictures` stays in the library: the simulations draw with it too.
"""

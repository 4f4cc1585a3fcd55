"""The warehouse task domain: pallets of products moved between shelves and stations.

Its own room, a peer of :mod:`pipflow.household`: the world loader (:mod:`.world`), the
simulation (:mod:`.simulation`), the scoring (:mod:`.scoring`) and the domain object that the
generic code reaches only through :mod:`pipflow.taskdomains`.
"""

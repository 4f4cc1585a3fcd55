"""The warehouse task domain: pallets of products moved between shelves and stations.

Its own room, a peer of :mod:`pipflow.household`, shaped the same way: the world loader
(:mod:`.world`), the command language (:mod:`.language`), the problem writer and checks
(:mod:`.problem`), its planner (:mod:`.planner`), the simulation (:mod:`.simulation`), the
scoring (:mod:`.scoring`) and the domain object that the generic code reaches only through
:mod:`pipflow.taskdomains`.
"""

"""The household task domain: robots that tidy a home, the paper's AI2-THOR experiment on
pipflow's own home simulator.

Its own room, a peer of :mod:`pipflow.warehouse`, shaped the same way: the world loader
(:mod:`.world`), the command language (:mod:`.language`), the problem writer and checks
(:mod:`.problem`), the simulation (:mod:`.simulation`), the scoring (:mod:`.scoring`) and the
domain object that the generic code reaches only through :mod:`pipflow.taskdomains`.
"""

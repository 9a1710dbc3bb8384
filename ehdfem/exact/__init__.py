"""Exact reference solutions: the closed forms of the limits the models must reach.

One home for what tests, run-time guards, studies and closed forms compare with (in the
manner of a contact-mechanics reference-solutions module): the rigid sphere's squeeze film
(:mod:`ehdfem.exact.rigid_film`), the dry Hertz impact (:mod:`ehdfem.exact.hertz`), the
rigid-body impact with Coulomb friction (:mod:`ehdfem.exact.rigid_impact`) and the rigid
sphere sliding and spinning near a wall (:mod:`ehdfem.exact.sliding_sphere`). Each is derived in
its docstring and depends on nothing above :mod:`ehdfem.checks`.
"""

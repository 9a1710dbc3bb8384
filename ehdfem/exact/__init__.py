"""Exact reference solutions: the closed forms of the limits the models must reach.

One home for what tests, run-time guards, studies and closed forms compare with (in the
manner of a contact-mechanics reference-solutions module): the rigid sphere's squeeze film
(:mod:`ehdfem.exact.rigid_film`), the dry Hertz impact (:mod:`ehdfem.exact.hertz`), the
rigid-body impact with Coulomb friction (:mod:`ehdfem.exact.rigid_impact`), the rigid
sphere in the Stokes flow near a wall: sliding and spinning (:mod:`ehdfem.exact.sliding_sphere`)
and moving towards it (:mod:`ehdfem.exact.sphere_towards_wall`), the limits of the impact with
tangential compliance (:mod:`ehdfem.exact.compliant_impact`), Walton's three-parameter impact
law (:mod:`ehdfem.exact.walton_impact`) and the surface effects' first correction at weak
elasticity (:mod:`ehdfem.exact.surface_limit`). Each is derived in
its docstring and depends on nothing above :mod:`ehdfem.checks`.
"""

"""The axisymmetric forms of the liquid around a sphere, shared by its finite-element flows
(:mod:`ehdfem.bounce.wall_flow`, :mod:`ehdfem.bounce.sphere_flow`,
:mod:`ehdfem.bounce.near_wall_flow`): the velocity (u_r, u_z) in
the (r, z) plane without swirl, integrals r-weighted (times 2 pi for the volume), and the
force on the sphere from the weak form's residual.

Nothing here knows about scales: the forms carry the caller's (lengths by the sphere radius a
in both flows).
"""

from __future__ import annotations

import math

from ..solids.fe import dolfinx_compat


def strain_rate(r, w):
    """e(w) in (r, z, theta), with the hoop part w_r / r (UFL 3x3 tensor)."""
    import ufl

    shear = 0.5 * (w[0].dx(1) + w[1].dx(0))
    return ufl.as_tensor([[w[0].dx(0), shear, 0], [shear, w[1].dx(1), 0], [0, 0, w[0] / r]])


def divergence(r, w):
    """div w = dw_r/dr + w_r / r + dw_z/dz."""
    return w[0].dx(0) + w[0] / r + w[1].dx(1)


def transport(a, w):
    """(a . grad) w in the (r, z) plane."""
    import ufl

    return ufl.as_vector([ufl.dot(a, ufl.grad(w[i])) for i in (0, 1)])


def sphere_probe(space, sphere_facets):
    """The velocity part of a function of the Taylor-Hood ``space`` that is e_z on the dofs of
    the sphere's facets and 0 elsewhere: the weak form's residual tested with it is the force
    of the liquid on the sphere along -z over 2 pi (:func:`sphere_force`)."""
    import ufl

    probe = dolfinx_compat.function(space)
    probe.x.array[dolfinx_compat.velocity_component_dofs(space, 1, sphere_facets)] = 1.0
    return ufl.split(probe)[0]


def sphere_force(reaction, comm) -> float:
    """F_z = -2 pi int R r dr dz, the liquid's force on the sphere along +z from the residual
    ``reaction`` tested with :func:`sphere_probe` (in the units of the caller's forms)."""
    return -2.0 * math.pi * dolfinx_compat.integral(reaction, comm)

"""The axisymmetric forms of the liquid around a sphere, shared by its finite-element flows
(:mod:`ehdfem.bounce.wall_flow`, :mod:`ehdfem.bounce.sphere_flow`,
:mod:`ehdfem.bounce.near_wall_flow`): the velocity (u_r, u_z) in the (r, z) plane without
swirl, integrals r-weighted (times 2 pi for the volume), the force on the sphere from the weak
form's residual, and the Navier-Stokes flows' variable-step BDF2 and steady Newton solve.

Nothing here knows about scales: the forms carry the caller's (lengths by the sphere radius a
in every flow).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ..fenicsx import assembly, functions, solvers, spaces


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

    probe = functions.function(space)
    functions.local_values(probe)[spaces.velocity_component_dofs(space, 1, sphere_facets)] = 1.0
    return ufl.split(probe)[0]


def sphere_force(reaction, comm) -> float:
    """F_z = -2 pi int R r dr dz, the liquid's force on the sphere along +z from the residual
    ``reaction`` tested with :func:`sphere_probe` (in the units of the caller's forms)."""
    return -2.0 * math.pi * assembly.integral(reaction, comm)


def momentum_residual(r, viscosity, u, p, v, q, rate_of_u, convecting):
    """The r-weighted weak form of the momentum and mass balances, (du/dt + (a . grad) u, v) +
    2 nu (e(u), e(v)) - (p, div v) - (q, div u), with the rate ``rate_of_u`` and the convecting
    velocity a (``convecting``) given (UFL form; nu = ``viscosity``)."""
    import ufl

    momentum = ufl.inner(rate_of_u + transport(convecting, u), v)
    viscous = 2 * viscosity * ufl.inner(strain_rate(r, u), strain_rate(r, v))
    return (momentum + viscous - p * divergence(r, v) - q * divergence(r, u)) * r * ufl.dx


class Bdf2Steps:
    """The past of a flow in the Taylor-Hood ``space`` and the constants of its variable-step
    BDF2: the functions ``now``, ``last``, ``before``; the rate 1/dt (``rate``), the weights
    c_now, c_last, c_before of du/dt = rate (c_now u + c_last u_last + c_before u_before),
    and the extrapolation e_last u_last + e_before u_before of the convecting velocity."""

    def __init__(self, space):
        import ufl

        mesh = spaces.mesh_of(space)
        self.now, self.last, self.before = (functions.function(space) for _ in range(3))
        constants = [functions.constant(mesh, 0.0) for _ in range(6)]
        self.rate, self.c_now, self.c_last, self.c_before, self.e_last, self.e_before = constants
        last, before = ufl.split(self.last)[0], ufl.split(self.before)[0]
        self.history = self.c_last * last + self.c_before * before  # UFL
        self.extrapolated = self.e_last * last + self.e_before * before  # UFL
        self.step_size = None

    def weights(self, dt: float):
        """((c_now, c_last, c_before), (e_last, e_before)) of a step ``dt`` after the last:
        with w = dt / previous dt, ((1 + 2w)/(1 + w), -(1 + w), w^2/(1 + w)) and
        (1 + w, -w); BDF1 and a constant extrapolation on the first step."""
        if self.step_size is None:
            return (1.0, -1.0, 0.0), (1.0, 0.0)
        w = dt / self.step_size
        return ((1 + 2 * w) / (1 + w), -(1 + w), w * w / (1 + w)), (1 + w, -w)

    def prepare(self, dt: float):
        """Set the constants for a step ``dt`` and return its weights (:meth:`weights`)."""
        coefficients, extrapolation = self.weights(dt)
        for constant, value in zip(
            (self.c_now, self.c_last, self.c_before, self.e_last, self.e_before),
            (*coefficients, *extrapolation),
            strict=True,
        ):
            functions.set_constant(constant, value)
        functions.set_constant(self.rate, 1.0 / dt)
        return coefficients, extrapolation

    def accept(self, dt: float) -> None:
        """Make ``now`` the last step (of size ``dt``) and the last the one before."""
        values = functions.local_values
        values(self.before)[:] = values(self.last)
        values(self.last)[:] = values(self.now)
        self.step_size = dt

    def restart(self) -> None:
        """Make ``now`` the whole past (a steady flow): the next step is BDF1."""
        values = functions.local_values
        values(self.last)[:] = values(self.now)
        values(self.before)[:] = values(self.now)
        self.step_size = None


@dataclass(frozen=True)
class FlowForms:
    """The forms of a Navier-Stokes flow (:func:`navier_stokes_forms`): a BDF2 step's compiled
    ``bilinear`` and ``linear`` forms and its residual tested on the sphere (``reaction``), the
    steady flow's residual (``steady_residual``) and its test on the sphere
    (``steady_reaction``), the last three UFL forms."""

    bilinear: object
    linear: object
    reaction: object
    steady_residual: object
    steady_reaction: object


def navier_stokes_forms(steps, viscosity, probe_velocity, convecting, frame_velocity):
    """The :class:`FlowForms` of the flow whose past is ``steps`` (:class:`Bdf2Steps`), at the
    ``viscosity`` 1/Re (in the caller's scales), tested on the sphere with ``probe_velocity``
    (:func:`sphere_probe`): a step has the rate rate (c_now u + history) and the convecting
    velocity ``convecting`` (UFL); the steady flow has no rate and is convected by u -
    ``frame_velocity`` (UFL: the velocity of the frame in which it is steady)."""
    import ufl

    space = functions.space_of(steps.now)
    r = ufl.SpatialCoordinate(spaces.mesh_of(space))[0]

    def residual(u, p, v, q, rate_of_u, a):
        return momentum_residual(r, viscosity, u, p, v, q, rate_of_u, a)

    (u, p), (v, q) = ufl.TrialFunctions(space), ufl.TestFunctions(space)
    u_h, p_h = ufl.split(steps.now)
    rate_h = steps.rate * (steps.c_now * u_h + steps.history)
    relative, still = u_h - frame_velocity, 0 * u_h
    return FlowForms(
        bilinear=assembly.form(residual(u, p, v, q, steps.rate * steps.c_now * u, convecting)),
        linear=assembly.form(-steps.rate * ufl.inner(steps.history, v) * r * ufl.dx),
        reaction=residual(u_h, p_h, probe_velocity, 0.0, rate_h, convecting),
        steady_residual=residual(u_h, p_h, v, q, still, relative),
        steady_reaction=residual(u_h, p_h, probe_velocity, 0.0, still, relative),
    )


def solve_steady(residual, solution, bcs) -> None:
    """Solve the UFL ``residual`` (of ``solution``) = 0 with the Dirichlet ``bcs`` by Newton's
    method (MUMPS LU, relative tolerance 1e-10, absolute 1e-12, at most 40 iterations) from
    the values of ``solution``; raises if it does not converge."""
    import ufl

    jacobian = assembly.form(ufl.derivative(residual, solution))
    reason, _ = solvers.solve_nonlinear(
        assembly.form(residual), jacobian, bcs, solution, rtol=1e-10, atol=1e-12, max_iterations=40
    )
    if reason <= 0:
        raise RuntimeError(f"the steady flow did not converge (SNES reason {reason})")

"""The Navier-Stokes flow around a sphere whose velocity is prescribed, in an unbounded liquid at
rest far away, solved by finite elements in the sphere's frame (docs/bounce.md, "The reversal
in a resolved flow"): the force the reduced flight model replaces by a drag law, an added mass
and a history kernel.

Scaled: lengths by the sphere radius a, velocities by a speed V0, time by a/V0, pressure by
rho V0^2, forces by rho V0^2 a^2; Re_a = V0 a / nu (Re = 2 Re_a V for the diameter). In the
frame moving with the sphere (velocity V(t) e_z in the liquid's frame) the liquid obeys

    du/dt + (u . grad) u = -grad P + (1/Re_a) div(2 e(u)),   div u = 0,
    u = 0 on the sphere,   u = -V(t) e_z far away (the outer boundary, radius ``outer``),

axisymmetric (r, z) with Taylor-Hood elements (P2 velocity, P1 pressure), P = 0 where the
axis meets the outer boundary (the velocity is given on the rest of it). The frame's
acceleration is a uniform body force, absorbed in P; the force on the sphere in the liquid's
frame is then F = F_frame + m_f dV/dt (m_f = 4 pi / 3, the displaced liquid), with F_frame
from the weak form's residual on the sphere. Time: BDF2 with variable steps (BDF1 on the first),
the convecting velocity extrapolated to second order (linear in the unknowns: one LU solve a
step). :meth:`SphereFlow.steady` solves the steady flow by Newton's method.
"""

from __future__ import annotations

import math

import numpy as np

from meshes import liquid

from .. import checks
from ..fenicsx import assembly, domain, functions, solvers, spaces
from ..solids.fe.mesh import contact_mesh
from .liquid_forms import (
    Bdf2Steps,
    navier_stokes_forms,
    solve_steady,
    sphere_force,
    sphere_probe,
)

OUTER = 30.0  # the liquid's outer radius by a
FINE = 0.02  # element size on the sphere by a
GROWTH = 0.1  # element size added per unit distance from the sphere (resolves the near wake)
DISPLACED = 4.0 * math.pi / 3.0  # the liquid displaced by the sphere, by rho a^3


class SphereFlow:
    """The flow of the module docstring at ``reynolds`` = Re_a, meshed by :mod:`meshes.liquid`
    without a wall (``outer``, ``fine``, ``growth`` by a), over the ranks of ``comm``; the
    liquid starts at rest relative to the sphere's frame (u = 0) unless :meth:`steady` is called."""

    def __init__(
        self,
        comm,
        reynolds: float,
        outer: float = OUTER,
        fine: float = FINE,
        growth: float = GROWTH,
    ):
        import ufl

        checks.positive("reynolds", reynolds)
        self.comm, self.reynolds = comm, reynolds
        mesh, _, facets = contact_mesh(comm, liquid.build, (None, outer, fine, growth))
        self.cells = domain.cell_count(mesh)
        space = spaces.taylor_hood_space(mesh)
        self.steps = Bdf2Steps(space)
        self.now = self.steps.now
        self.far = functions.constant(mesh, 0.0)
        axis, sphere = domain.tagged(facets, liquid.AXIS), domain.tagged(facets, liquid.SPHERE)
        outer_facets = domain.tagged(facets, liquid.OUTER)
        # the velocity is given on the whole boundary but the axis: P is fixed at one point
        top = spaces.point_dofs(
            space, lambda x: np.isclose(x[0], 0.0) & np.isclose(x[1], outer), component=1
        )
        self.bcs = [
            assembly.velocity_component_condition(space, 0, axis, 0.0),
            assembly.velocity_component_condition(space, 0, sphere, 0.0),
            assembly.velocity_component_condition(space, 1, sphere, 0.0),
            assembly.velocity_component_condition(space, 0, outer_facets, 0.0),
            assembly.velocity_component_condition(space, 1, outer_facets, self.far),
            assembly.zero_condition(space, top, component=1),
        ]
        # in the sphere's frame: the steady flow is convected by itself
        self.forms = navier_stokes_forms(
            self.steps,
            1.0 / reynolds,
            sphere_probe(space, sphere),
            self.steps.extrapolated,
            ufl.as_vector([0.0, 0.0]),
        )

    def steady(self, velocity: float) -> float:
        """Solve the steady flow of a sphere moving at ``velocity`` (by V0) by Newton's method
        (MUMPS), make it the flow's past (both previous steps), and return its force (by
        rho V0^2 a^2, on the sphere, along +z)."""
        functions.set_constant(self.far, -velocity)
        functions.local_values(self.now)[:] = 0.0
        solve_steady(self.forms.steady_residual, self.now, self.bcs)
        self.steps.restart()
        return sphere_force(self.forms.steady_reaction, self.comm)

    def step(self, dt: float, velocity: float) -> float:
        """Advance the flow by ``dt`` (by a/V0) to the sphere velocity ``velocity`` (by V0) and
        return the force on the sphere in its frame, F_frame (by rho V0^2 a^2, along +z):
        BDF2 with the step ratio w = dt / previous dt, (1 + 2w)/(1 + w) u - (1 + w) u_last +
        w^2/(1 + w) u_before, convecting velocity (1 + w) u_last - w u_before; BDF1 first
        (:class:`ehdfem.bounce.liquid_forms.Bdf2Steps`)."""
        self.steps.prepare(dt)
        functions.set_constant(self.far, -velocity)
        forms = self.forms
        solvers.solve_linear(forms.bilinear, forms.linear, self.bcs, self.now)
        force = sphere_force(forms.reaction, self.comm)
        self.steps.accept(dt)
        return force

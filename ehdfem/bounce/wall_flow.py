"""The unsteady Stokes flow of a sphere moving normal to a plane wall, solved by finite elements
in the Laplace domain: the force's impedance, from which the wall-bounded history kernel is
taken (docs/bounce.md, "The wall's history kernel").

Scaled: lengths by the sphere radius a, velocities by the sphere's speed U, time by a^2/nu
(s = nu t / a^2), Laplace variable p = k^2 (k = a sqrt(p / nu) dimensionless), forces by
6 pi mu a U. A sphere at rest for t < 0 whose velocity is v(t) (Laplace transform v^) feels,
at a fixed gap h from the wall, the force F^ = -6 pi mu a Z(k) v^ with

    Z(k) = lambda(h) + (2/9) C_M(h) k^2 + k rho^(k),

lambda Brenner's steady factor, C_M the potential-flow added mass with the sphere's image and
k rho^(k) = p K^(p) the history kernel's part (rho^ = 1: Basset's kernel, unbounded liquid,
where Z = 1 + k + k^2/9 exactly). Z solves the Brinkman problem (the Laplace transform of the
unsteady Stokes equations, zero initial flow)

    k^2 u - div(2 e(u)) + grad p = 0,  div u = 0,   u = e_z on the sphere, 0 on the wall,

axisymmetric (r, z) with Taylor-Hood elements (P2 velocity, P1 pressure), zero traction on the
outer boundary (the natural condition of the weak form, which fixes the pressure; the wall
holds the liquid, and without a wall k > 0 decays within 1/k), and
Z = -F_z / (6 pi) from the reaction: F_z = -2 pi int (k^2 u.w + 2 e(u):e(w) - p div w) r dr dz
with w = e_z on the sphere's dofs, 0 elsewhere (the weak form's residual on the sphere).
"""

from __future__ import annotations

import math

from meshes import liquid

from ..fenicsx import assembly, domain, functions, solvers, spaces
from ..solids.fe.mesh import contact_mesh
from .liquid_forms import divergence, sphere_force, sphere_probe, strain_rate

OUTER = 40.0  # the liquid's outer radius by a, at least 8 centre distances (1 + h/a)
FINE = 5e-3  # the element size on the sphere and the wall by a (boundary layers down to 1/k)


class WallFlow:
    """The Brinkman problem of the module docstring for a sphere at ``gap`` (by a; None: no
    wall) in a liquid of radius ``outer`` (by a; None: OUTER, or 8 (1 + gap) if larger, so
    that the truncation's (centre distance / radius)^3 stays below 2e-3), meshed with
    elements ``fine`` (by a) on the sphere (:mod:`meshes.liquid`), over the ranks of
    ``comm``."""

    def __init__(self, comm, gap: float | None, outer: float | None = None, fine: float = FINE):
        import ufl

        self.comm, self.gap = comm, gap
        if outer is None:
            outer = max(OUTER, 8.0 * (1.0 + (gap or 0.0)))
        mesh, _, facets = contact_mesh(comm, liquid.build, (gap, outer, fine))
        self.cells = domain.cell_count(mesh)
        space = spaces.taylor_hood_space(mesh)
        self.solution = functions.function(space)
        (u, p), (v, q) = ufl.TrialFunctions(space), ufl.TestFunctions(space)
        r = ufl.SpatialCoordinate(mesh)[0]
        self.k2 = functions.constant(mesh, 0.0)

        def residual(u, p, v, q):
            viscous = 2 * ufl.inner(strain_rate(r, u), strain_rate(r, v))
            incompressible = p * divergence(r, v) + q * divergence(r, u)
            return (self.k2 * ufl.inner(u, v) + viscous - incompressible) * r * ufl.dx

        self.bilinear = assembly.form(residual(u, p, v, q))
        zero = functions.constant(mesh, 0.0)
        self.linear = assembly.form(zero * v[1] * r * ufl.dx)
        axis, sphere = domain.tagged(facets, liquid.AXIS), domain.tagged(facets, liquid.SPHERE)
        self.bcs = [
            assembly.velocity_component_condition(space, 0, axis, 0.0),
            assembly.velocity_component_condition(space, 0, sphere, 0.0),
            assembly.velocity_component_condition(space, 1, sphere, 1.0),
        ]
        if gap is not None:
            wall = domain.tagged(facets, liquid.WALL)
            self.bcs += [assembly.velocity_component_condition(space, i, wall, 0.0) for i in (0, 1)]
        u_h, p_h = ufl.split(self.solution)
        self.reaction = residual(u_h, p_h, sphere_probe(space, sphere), 0.0)

    def impedance(self, k: float) -> float:
        """Z(k) = -F_z / (6 pi mu a U) at k = a sqrt(p / nu) (module docstring); Z(0) is
        Brenner's lambda(h) (1 without a wall needs an unbounded liquid: use k > 0 there)."""
        functions.set_constant(self.k2, k * k)
        solvers.solve_linear(self.bilinear, self.linear, self.bcs, self.solution)
        return -sphere_force(self.reaction, self.comm) / (6.0 * math.pi)

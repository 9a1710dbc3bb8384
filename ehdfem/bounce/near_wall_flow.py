"""The Navier-Stokes flow of a sphere moving normal to a plane wall, its gap changing, solved by
finite elements on a moving mesh (docs/bounce.md, "The rebound in a resolved flow with the
wall"): the force the flight model replaces by a drag law, Brenner's wall factor, the image's
added mass and a history kernel, with nothing replaced.

Scaled: lengths by the sphere radius a, velocities by a speed V0, time by a/V0, pressure by
rho V0^2, forces by rho V0^2 a^2; Re_a = V0 a / nu. In the liquid's frame (the wall at z = 0 at
rest, the sphere's centre at z = 1 + h(t), its velocity V(t) e_z) the liquid obeys, written on
a mesh moving with the velocity w (arbitrary Lagrangian-Eulerian form),

    du/dt|_mesh + ((u - w) . grad) u = -grad P + (1/Re_a) div(2 e(u)),   div u = 0,
    u = V e_z on the sphere,   u = 0 on the wall,   zero traction on the outer boundary,

axisymmetric (r, z), Taylor-Hood elements (P2 velocity, P1 pressure). The mesh is
:mod:`meshes.liquid`'s at a reference gap h_ref, its points moved along z as the gap changes
by Delta = h - h_ref: above the column under the sphere they translate by Delta; the column
reaches up to the sphere's lower surface where r <= COLUMN_RADIUS and to that surface's height
at COLUMN_RADIUS elsewhere (beside the equator the surface is too steep: a stretch there turns
cells). In the column, of height T(r) at reference, a point at the
distance d from the column's top keeps the share d/T of the new column (Delta < 0: squeezed
uniformly) or moves to d + Delta (d/T)^2 (Delta > 0: the elements near the sphere keep their
size, those near the wall take the stretch); within MOVING_NEAR of the centre the move is
whole, falling linearly to none at MOVING_FAR. The mesh velocity w is the BDF rate of the
points' heights. Time: BDF2 with variable steps (BDF1 on the first), the convecting velocity
u extrapolated to second order (one LU solve a step). The force on the sphere is taken from
the weak form's residual on it. :meth:`NearWallFlow.steady` solves the flow steady in the
sphere's frame (the quasi-steady start of a run) by Newton's method.

The gap of the mesh and the sphere's velocity are given separately: a contact that the film
model resolves below the mesh's smallest gap is followed at a fixed mesh gap with the
sphere's velocity still imposed (the liquid outside the film sees the velocity's reversal).
"""

from __future__ import annotations

import math

import numpy as np

from meshes import liquid

from .. import checks
from ..fenicsx import assembly, domain, functions, solvers, spaces
from ..solids.fe.mesh import contact_mesh
from .liquid_forms import Bdf2Steps, navier_stokes_forms, solve_steady, sphere_force, sphere_probe
from .sphere_flow import FINE, GROWTH, OUTER  # the same liquid and elements around the sphere

MOVING_NEAR, MOVING_FAR = 2.0, 10.0  # the mesh translates with the sphere within the first,
# and stays beyond the second (distances from the centre by a)
COLUMN_RADIUS = 0.9  # the column under the sphere ends at the sphere's surface at this radius
# (by a) and below: beside the equator the surface is too steep to stretch under


def mesh_heights(r, z, reference_gap: float, gap: float):
    """The heights (by a) of the mesh's points at (r, z) (by a, the mesh at ``reference_gap``)
    when the sphere's lowest point is at ``gap`` (module docstring)."""
    centre = 1.0 + reference_gap
    surface = centre - np.sqrt(np.clip(1.0 - r * r, 0.0, None))
    top = np.minimum(surface, centre - math.sqrt(1.0 - COLUMN_RADIUS**2))  # at reference
    column = np.clip(z / top, 0.0, 1.0)  # the share of the column under the point
    change = gap - reference_gap
    shape = 1.0 - column if change < 0.0 else (1.0 - column) ** 2
    below = top + change - (top * (1.0 - column) + change * shape)  # the column's map
    moved = np.where(z < top, below, z + change)
    distance = np.hypot(r, z - centre)
    fade = np.clip((MOVING_FAR - distance) / (MOVING_FAR - MOVING_NEAR), 0.0, 1.0)
    return z + fade * (moved - z)


def signed_areas(corners):
    """Twice the signed areas of the triangles whose corners are ``corners`` (cells x 3 x 2)."""
    edges = corners[:, 1:] - corners[:, :1]  # the 2-D cross product (numpy 2 takes 3-D only)
    return edges[:, 0, 0] * edges[:, 1, 1] - edges[:, 0, 1] * edges[:, 1, 0]


class NearWallFlow:
    """The flow of the module docstring at ``reynolds`` = Re_a, on the mesh of
    :mod:`meshes.liquid` at ``reference_gap`` (``outer``, ``fine``, ``growth`` by a) over the
    ranks of ``comm``; :meth:`move` sets the gap. The liquid starts at rest (u = 0) unless
    :meth:`steady` is called."""

    def __init__(
        self,
        comm,
        reynolds: float,
        reference_gap: float,
        outer: float = OUTER,
        fine: float = FINE,
        growth: float = GROWTH,
    ):
        import ufl

        for name, value in (("reynolds", reynolds), ("reference_gap", reference_gap)):
            checks.positive(name, value)
        self.comm, self.reynolds, self.reference_gap = comm, reynolds, reference_gap
        mesh, _, facets = contact_mesh(comm, liquid.build, (reference_gap, outer, fine, growth))
        self.cells = domain.cell_count(mesh)
        self.nodes = domain.vertex_coordinates(mesh)
        self.reference = self.nodes[:, :2].copy()
        self.triangles = domain.cell_nodes(mesh)
        self.orientation = np.sign(signed_areas(self.reference[self.triangles]))
        rate_space = spaces.lagrange_space(mesh, 1)
        self.mesh_rate = functions.function(rate_space)
        self.rate_points = spaces.dof_coordinates(rate_space)[:, :2].copy()
        space = spaces.taylor_hood_space(mesh)
        self.steps = steps = Bdf2Steps(space)
        self.now = steps.now
        self.gaps = [reference_gap] * 2  # the mesh's gap at the last two steps (before, last)
        self.velocities = [0.0, 0.0]  # the sphere's velocity at the last two steps
        self.sphere_velocity = functions.constant(mesh, 0.0)
        axis, sphere = domain.tagged(facets, liquid.AXIS), domain.tagged(facets, liquid.SPHERE)
        wall = domain.tagged(facets, liquid.WALL)
        self.bcs = [
            assembly.velocity_component_condition(space, 0, axis, 0.0),
            assembly.velocity_component_condition(space, 0, sphere, 0.0),
            assembly.velocity_component_condition(space, 1, sphere, self.sphere_velocity),
            assembly.velocity_component_condition(space, 0, wall, 0.0),
            assembly.velocity_component_condition(space, 1, wall, 0.0),
        ]
        # a step is convected relative to the mesh; the steady start is steady with the sphere
        self.forms = navier_stokes_forms(
            steps,
            1.0 / reynolds,
            sphere_probe(space, sphere),
            steps.extrapolated - ufl.as_vector([0.0, self.mesh_rate]),
            ufl.as_vector([0.0, self.sphere_velocity]),
        )

    def move(self, gap: float) -> None:
        """Put the sphere's lowest point at ``gap`` (by a) above the wall (module docstring)."""
        checks.positive("gap", gap)
        r, z = self.reference.T
        self.nodes[:, 1] = mesh_heights(r, z, self.reference_gap, gap)
        if np.any(signed_areas(self.nodes[self.triangles, :2]) * self.orientation <= 0.0):
            raise ValueError(
                f"gap = {gap} a turns cells of the mesh made at {self.reference_gap} a"
            )

    def steady(self, gap: float, velocity: float) -> float:
        """Solve the flow at ``gap`` that is steady in the frame of the sphere moving at
        ``velocity`` (by V0), ((u - V e_z) . grad) u = -grad P + (1/Re_a) div(2 e(u)), the wall
        held where it is (the flow far from the wall is the translating one; near it this is
        the quasi-steady start of a run) (Newton, MUMPS), make it the flow's past (both
        previous steps), and return its force (by rho V0^2 a^2, on the sphere, along +z)."""
        self.move(gap)
        self.gaps, self.velocities = [gap, gap], [velocity, velocity]
        functions.set_constant(self.sphere_velocity, velocity)
        functions.local_values(self.now)[:] = 0.0
        solve_steady(self.forms.steady_residual, self.now, self.bcs)
        self.steps.restart()
        return sphere_force(self.forms.steady_reaction, self.comm)

    def step(self, dt: float, gap: float, velocity: float) -> float:
        """Advance the flow by ``dt`` (by a/V0) to the mesh gap ``gap`` (by a) and the sphere
        velocity ``velocity`` (by V0), and return the force on the sphere (by rho V0^2 a^2,
        along +z): BDF2 with the step ratio w = dt / previous dt, (1 + 2w)/(1 + w) x_now -
        (1 + w) x_last + w^2/(1 + w) x_before for x = u and for the mesh's heights, convecting
        velocity (1 + w) u_last - w u_before minus the mesh's; BDF1 first."""
        coefficients, _ = self.steps.prepare(dt)
        force = self._solve(dt, coefficients, gap, velocity)
        self._accept(dt, gap, velocity)
        return force

    def free_step(self, dt: float, mass: float, weight: float) -> tuple[float, float, float]:
        """Advance the flow and a free sphere together by ``dt`` (by a/V0): the sphere of
        ``mass`` (by rho a^3) under its ``weight`` less buoyancy (by rho V0^2 a^2, along -z)
        obeys mass dV/dt = F - weight, dh/dt = V, both in the BDF2 of :meth:`step`. The gap is
        that of the velocity extrapolated from the last two steps (second order); the force is
        affine in V at that gap, F = F(0) + V (F(1) - F(0)), so two solves give V implicitly
        (the added mass and the drag in it). Returns (gap, V, F)."""
        coefficients, extrapolation = self.steps.prepare(dt)
        now, last, before = coefficients
        guess = np.dot(extrapolation, list(reversed(self.velocities)))
        gap = (dt * guess - last * self.gaps[1] - before * self.gaps[0]) / now
        at_rest = self._solve(dt, coefficients, gap, 0.0)
        flow_at_rest = functions.local_values(self.now).copy()
        response = self._solve(dt, coefficients, gap, 1.0) - at_rest
        past = mass * (last * self.velocities[1] + before * self.velocities[0]) / dt
        velocity = (at_rest - weight - past) / (mass * now / dt - response)
        flow = functions.local_values(self.now)
        flow[:] = flow_at_rest + velocity * (flow - flow_at_rest)
        self._accept(dt, gap, velocity)
        return gap, velocity, at_rest + velocity * response

    def _solve(self, dt: float, coefficients, gap: float, velocity: float) -> float:
        """Solve the step's flow at the mesh gap ``gap`` and the sphere velocity ``velocity``
        into ``now`` and return its force; the past is left as it is."""
        r, z = self.rate_points.T
        heights = [mesh_heights(r, z, self.reference_gap, h) for h in (gap, *reversed(self.gaps))]
        functions.local_values(self.mesh_rate)[:] = np.dot(coefficients, heights) / dt
        functions.set_constant(self.sphere_velocity, velocity)
        self.move(gap)
        forms = self.forms
        solvers.solve_linear(forms.bilinear, forms.linear, self.bcs, self.now)
        return sphere_force(forms.reaction, self.comm)

    def _accept(self, dt: float, gap: float, velocity: float) -> None:
        """Make the step's flow, gap and sphere velocity the last ones."""
        self.steps.accept(dt)
        self.gaps = [self.gaps[1], gap]
        self.velocities = [self.velocities[1], velocity]

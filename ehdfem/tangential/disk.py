"""The full 2-D Reynolds film on the disk at one instant: the check of the mode-1 superposition.

The 1-D film model (:class:`ehdfem.film.mode_one.ModeOneFilm`) writes the pressure of a sliding
sphere as an axisymmetric part plus an azimuthal mode-1 part, P0(R) + q(R) cos(phi), with q = 0
where P0 sits at the cavitation limit. This module solves the film on the whole disk instead, with
the cavitation limit imposed pointwise, so the superposition can be checked against it.

All quantities are scaled (DSH 1986): the radius R and the Cartesian coordinates
X = R cos(phi), Y = R sin(phi) by sqrt(a x0), the film thickness H by x0, the pressure P by
mu0 V0 a / x0^2 and the time T by x0 / V0. At one instant, with the film thickness H(R, phi) > 0
and its rate dH/dT(R, phi) given, the film obeys

    (1/12) div(phi(P) H^3 grad P) = dH/dT - s (w/2) dH/dX,      R < R_edge,
    P = 0 on R = R_edge,     P >= P_cav,

where s w is the sliding coefficient (the sliding drive s (w/2) dH/dX), phi(P) = mu0/mu(P) the
fluidity (1 at constant viscosity) and R_edge the wetted edge. Where P = P_cav the equation is
not imposed: the pressure is the solution of the variational inequality (the obstacle problem)

    find P >= P_cav, P = 0 on R = R_edge:
        int (1/12) phi(P) H^3 grad P . grad(v - P) + (dH/dT - s (w/2) dH/dX) (v - P) dA >= 0
        for every v >= P_cav with v = 0 on R = R_edge,

which is the minimum of the film's dissipation functional over P >= P_cav at constant
viscosity. Without a limit (P_cav = -inf) and at constant viscosity the problem is linear.

H and dH/dT are given as an axisymmetric part plus an optional mode-1 part, f0(R) + f1(R)
cos(phi), each as nodal values on the film's radial nodes, piecewise linear in R (the 1-D
model's representation); the squeeze rate may instead be any callable of (X, Y).

Discretisation: continuous piecewise-linear (P1) triangles on a gmsh disk (a polygon inscribed
in R = R_edge) whose element size grows linearly from ``element_size`` at the centre to
``grading`` times that at the edge. With P1 the nodal bounds P_i >= P_cav are the pointwise
constraint exactly. H, dH/dT and the surface sum are interpolated at the mesh vertices (P1, as
the pressure), so the discrete problem is second-order accurate in L2. The constrained problem is
solved by PETSc's reduced-space active-set Newton method (SNES ``vinewtonrsls``), the
unconstrained one at constant viscosity by one linear solve (SNES ``ksponly``), and with a
pressure-dependent viscosity by Newton's method; every linear system by MUMPS LU.

The azimuthal Fourier amplitudes p0(R) = (1/2pi) int P dphi and p1(R) = (1/pi) int P cos(phi)
dphi are sampled at the radial nodes by evaluating the discrete pressure on ``angles`` equally
spaced angles per radius (the trapezoidal rule, exact for the modes below angles - 1): to the
discretisation error, at the nodes themselves. (Weighting the pressure with 1-D hat functions of
R instead would put kinks of the weight inside the triangles wherever the radial nodes are
closer than the mesh size, and lose accuracy there.) Points between the inscribed polygon and the
circle R = R_edge lie outside the discrete domain, where the discrete pressure is extended by
its boundary value 0. The integrals (force, moment, slope force) are assembled on the mesh.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from .. import checks
from ..fenicsx import assembly, domain, functions, solvers, spaces

DEGREE = 1  # of the Lagrange elements of the pressure and of the interpolated data
TOLERANCE = 1e-11  # relative residual of the nonlinear solves (SNES rtol)
CAVITATION_TOLERANCE = 1e-10  # a node is cavitated within this (times max(1, |P_cav|))


@dataclass(frozen=True)
class DiskFilmSolution:
    """The film pressure on the disk at one instant (scaled: P by mu0 V0 a / x0^2, lengths by
    sqrt(a x0)).

    ``mesh`` and ``pressure`` (a P1 Function on it) for pictures; ``radii`` the radial nodes;
    ``axisymmetric_pressure`` p0(R_i) = (1/2pi) int P dphi and ``mode_one_pressure``
    p1(R_i) = (1/pi) int P cos(phi) dphi at the nodes (zero beyond R_edge); ``normal_force``
    int P dA; ``pressure_moment`` int P X dA (= pi int p1 R^2 dR); ``slope_force``
    int P dSigma/dX dA for the given surface sum Sigma(R) (None without one);
    ``cavitated_nodes`` the number of mesh vertices at the cavitation limit; ``iterations``
    the solver's (Newton) iterations."""

    mesh: object
    pressure: object
    radii: np.ndarray
    axisymmetric_pressure: np.ndarray
    mode_one_pressure: np.ndarray
    normal_force: float
    pressure_moment: float
    slope_force: float | None
    cavitated_nodes: int
    iterations: int


def disk_mesh(edge_radius: float, element_size: float, grading: float = 4.0, comm=None):
    """A triangle mesh of the disk R < ``edge_radius`` (by sqrt(a x0)), meshed by gmsh on rank 0
    of ``comm`` (default MPI.COMM_WORLD) and distributed over it. The element size is
    ``element_size`` at the centre and grows linearly in R to ``grading`` times that at the
    edge (``grading`` >= 1); the boundary vertices lie on the circle."""
    import gmsh
    from mpi4py import MPI

    edge_radius = checks.positive("edge_radius", edge_radius)
    element_size = checks.number(
        "element_size", element_size, lower=0.0, upper=edge_radius, lower_open=True
    )
    grading = checks.number("grading", grading, lower=1.0)
    comm = MPI.COMM_WORLD if comm is None else comm
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    try:
        if comm.rank == 0:
            gmsh.model.add("disk")
            disk = gmsh.model.occ.addDisk(0.0, 0.0, 0.0, edge_radius, edge_radius)
            gmsh.model.occ.synchronize()
            gmsh.model.addPhysicalGroup(2, [disk], 1)
            size = gmsh.model.mesh.field.add("MathEval")
            gmsh.model.mesh.field.setString(
                size,
                "F",
                f"{element_size!r} * (1 + {grading - 1.0!r} * Sqrt(x*x + y*y) / {edge_radius!r})",
            )
            gmsh.model.mesh.field.setAsBackgroundMesh(size)
            for option in ("ExtendFromBoundary", "FromPoints", "FromCurvature"):
                gmsh.option.setNumber(f"Mesh.MeshSize{option}", 0)
            gmsh.model.mesh.generate(2)
        mesh, _, _ = domain.mesh_from_gmsh(gmsh.model, comm, 0, gdim=2)
    finally:
        gmsh.finalize()
    return mesh


def solve_disk_film(
    radii,
    film_thickness,
    squeeze_rate,
    *,
    film_thickness_mode_one=None,
    squeeze_rate_mode_one=None,
    sliding: float = 0.0,
    p_cav: float = -math.inf,
    edge_radius: float | None = None,
    fluidity: Callable | None = None,
    surface_sum=None,
    element_size: float | None = None,
    grading: float = 4.0,
    angles: int = 64,
    comm=None,
) -> DiskFilmSolution:
    """The film pressure on the disk R < R_edge at one instant (module docstring; scaled units).

    ``radii``: the film nodes R_i (by sqrt(a x0)), from 0, strictly increasing, reaching at
    least R_edge; the amplitudes are reported there. ``film_thickness``: H0(R_i) (by x0), and
    ``film_thickness_mode_one`` H1(R_i) (None: 0), with H0 > |H1| at every node so that
    H = H0 + H1 cos(phi) > 0. ``squeeze_rate``: dH/dT at the nodes (by V0), and
    ``squeeze_rate_mode_one`` its mode-1 part (None: 0); or a callable f(X, Y) of numpy arrays
    giving the whole dH/dT (then no mode-1 part). ``sliding``: s w. ``p_cav``: the cavitation
    limit, <= 0 (-inf: none). ``edge_radius``: R_edge (None: radii[-1]). ``fluidity``: None for
    a constant viscosity, or a callable giving mu0/mu of the UFL pressure as a UFL expression.
    ``surface_sum``: Sigma(R_i) (by x0) for the slope force int P dSigma/dX dA (None: not
    computed). ``element_size``: the mesh size at the centre (None: R_edge / 50), growing
    linearly to ``grading`` times that at the edge (:func:`disk_mesh`). ``angles``: sampling
    angles per radius for the Fourier amplitudes. ``comm``: the MPI communicator of the mesh
    (None: MPI.COMM_WORLD)."""
    radii = _radii(radii)
    edge_radius = radii[-1] if edge_radius is None else edge_radius
    edge_radius = checks.number(
        "edge_radius", edge_radius, lower=0.0, upper=radii[-1], lower_open=True
    )
    thickness = _nodal("film_thickness", film_thickness, radii)
    thickness_mode_one = _nodal("film_thickness_mode_one", film_thickness_mode_one, radii)
    if not np.all(thickness > np.abs(thickness_mode_one)):
        raise checks.InputError(
            "film_thickness must exceed |film_thickness_mode_one| at every node (H > 0)"
        )
    if callable(squeeze_rate):
        if squeeze_rate_mode_one is not None:
            raise checks.InputError("a callable squeeze_rate takes no squeeze_rate_mode_one")
    else:
        squeeze_rate = _nodal("squeeze_rate", squeeze_rate, radii)
    squeeze_rate_mode_one = _nodal("squeeze_rate_mode_one", squeeze_rate_mode_one, radii)
    sliding = checks.number("sliding", sliding)
    if p_cav != -math.inf:
        p_cav = checks.number("p_cav", p_cav, upper=0.0)
    if fluidity is not None and not callable(fluidity):
        raise checks.InputError(f"fluidity must be None or a callable, got {fluidity!r}")
    if surface_sum is not None:
        surface_sum = _nodal("surface_sum", surface_sum, radii)
    element_size = edge_radius / 50 if element_size is None else element_size
    angles = checks.integer("angles", angles, lower=8)

    mesh = disk_mesh(edge_radius, element_size, grading, comm)
    film = _DiskFilm(mesh, fluidity)
    film.set_data(radii, thickness, thickness_mode_one, squeeze_rate, squeeze_rate_mode_one)
    functions.set_constant(film.sliding, sliding)
    iterations = film.solve(p_cav)
    p0, p1 = film.fourier_amplitudes(radii, angles)
    return DiskFilmSolution(
        mesh=mesh,
        pressure=film.pressure,
        radii=radii,
        axisymmetric_pressure=p0,
        mode_one_pressure=p1,
        normal_force=film.integral(film.pressure),
        pressure_moment=film.integral(film.pressure * film.coordinates[0]),
        slope_force=None if surface_sum is None else film.slope_force(radii, surface_sum),
        cavitated_nodes=film.cavitated_nodes(p_cav),
        iterations=iterations,
    )


def _radii(radii) -> np.ndarray:
    radii = np.asarray(radii, dtype=float)
    if radii.ndim != 1 or radii.size < 2:
        raise checks.InputError("radii must be a 1-D array of at least 2 film nodes")
    if not (np.all(np.isfinite(radii)) and radii[0] == 0.0 and np.all(np.diff(radii) > 0)):
        raise checks.InputError("radii must be finite, start at 0 and increase strictly")
    return radii


def _nodal(name: str, values, radii: np.ndarray) -> np.ndarray:
    """``values`` as finite nodal values on ``radii`` (None: zeros)."""
    if values is None:
        return np.zeros_like(radii)
    values = np.asarray(values, dtype=float)
    if values.shape != radii.shape or not np.all(np.isfinite(values)):
        raise checks.InputError(f"{name} must be {radii.size} finite values (one per film node)")
    return values


def _radial_field(radii, axisymmetric, mode_one):
    """f0(R) + f1(R) cos(phi) at points x (3, n), both parts piecewise linear in R on radii."""

    def field(x):
        r = np.hypot(x[0], x[1])
        cosine = np.divide(x[0], r, out=np.zeros_like(r), where=r > 0)
        return np.interp(r, radii, axisymmetric) + np.interp(r, radii, mode_one) * cosine

    return field


class _DiskFilm:
    """The P1 film problem on ``mesh``: the data as Functions, the residual and Jacobian forms
    (with the UFL ``fluidity`` of the pressure, None: 1) and the solved pressure."""

    def __init__(self, mesh, fluidity):
        import ufl

        self.mesh = mesh
        self.comm = domain.communicator(mesh)
        self.space = space = spaces.lagrange_space(mesh, DEGREE)
        self.coordinates = ufl.SpatialCoordinate(mesh)
        self.pressure = functions.function(space, name="pressure")
        self.thickness = functions.function(space, name="film_thickness")
        self.squeeze_rate = functions.function(space, name="squeeze_rate")
        self.sliding = functions.constant(mesh, 0.0)
        self.fluidity = fluidity
        self.edge_facets = domain.exterior_facets(mesh)
        self.edge = assembly.zero_condition(space, spaces.entity_dofs(space, 1, self.edge_facets))
        test = ufl.TestFunction(space)
        mobility = self.thickness**3 / 12
        if fluidity is not None:
            mobility = fluidity(self.pressure) * mobility
        source = self.squeeze_rate - self.sliding / 2 * self.thickness.dx(0)
        residual = mobility * ufl.inner(ufl.grad(self.pressure), ufl.grad(test)) + source * test
        residual = residual * ufl.dx
        self.residual = assembly.form(residual)
        self.jacobian = assembly.form(
            ufl.derivative(residual, self.pressure, ufl.TrialFunction(space))
        )

    def set_data(self, radii, thickness, thickness_mode_one, squeeze_rate, squeeze_rate_mode_one):
        """Interpolate H and dH/dT (nodal on radii, or dH/dT a callable of (X, Y))."""
        functions.interpolate(self.thickness, _radial_field(radii, thickness, thickness_mode_one))
        if callable(squeeze_rate):
            functions.interpolate(self.squeeze_rate, lambda x: squeeze_rate(x[0], x[1]))
        else:
            rate = _radial_field(radii, squeeze_rate, squeeze_rate_mode_one)
            functions.interpolate(self.squeeze_rate, rate)

    def solve(self, p_cav: float) -> int:
        """Solve for the pressure (module docstring); return the SNES iterations."""
        functions.local_values(self.pressure)[:] = 0.0
        reason, iterations = solvers.solve_nonlinear(
            self.residual,
            self.jacobian,
            [self.edge],
            self.pressure,
            # a zero residual (no drive at all) is converged; otherwise relative to the first one
            rtol=TOLERANCE,
            atol=np.finfo(float).tiny,
            max_iterations=50,
            method="linear" if self.fluidity is None else "newton",
            lower_bound=None if p_cav == -math.inf else p_cav,
        )
        if reason <= 0:
            raise RuntimeError(f"the disk film did not converge (SNES reason {reason})")
        return iterations

    def integral(self, integrand) -> float:
        """int ``integrand`` dA over the disk, summed over the ranks."""
        import ufl

        return assembly.integral(integrand * ufl.dx, self.comm)

    def slope_force(self, radii, surface_sum) -> float:
        """int P dSigma/dX dA with the surface sum Sigma(R) interpolated at the vertices."""
        sigma = functions.function(self.space)
        functions.interpolate(sigma, _radial_field(radii, surface_sum, np.zeros_like(surface_sum)))
        return self.integral(self.pressure * sigma.dx(0))

    def cavitated_nodes(self, p_cav: float) -> int:
        """The number of owned vertices with P within CAVITATION_TOLERANCE of P_cav, summed."""
        from mpi4py import MPI

        limit = p_cav + CAVITATION_TOLERANCE * max(1.0, abs(p_cav))
        local = int(np.count_nonzero(functions.owned_values(self.pressure) <= limit))
        return self.comm.allreduce(local, op=MPI.SUM)

    def fourier_amplitudes(self, radii, angles):
        """(p0, p1) at ``radii`` from the pressure on ``angles`` equally spaced angles."""
        phi = 2 * np.pi * np.arange(angles) / angles
        points = np.zeros((radii.size * angles, 3))
        points[:, 0] = np.outer(radii, np.cos(phi)).ravel()
        points[:, 1] = np.outer(radii, np.sin(phi)).ravel()
        values = self._point_values(points).reshape(radii.size, angles)
        return values.mean(axis=1), 2 * (values @ np.cos(phi)) / angles

    def _point_values(self, points: np.ndarray) -> np.ndarray:
        """The pressure at ``points`` (n, 3) on every rank: each rank evaluates the points in
        its cells (owned and ghost), the values are averaged over the ranks that found them.
        Points found by none must lie between the inscribed polygon and the edge circle (outside
        the discrete domain, P = 0 there)."""
        from mpi4py import MPI

        values, found = functions.point_values(self.pressure, points)
        counts = found.astype(float)
        comm = self.comm
        comm.Allreduce(MPI.IN_PLACE, values, op=MPI.SUM)
        comm.Allreduce(MPI.IN_PLACE, counts, op=MPI.SUM)
        missing = counts == 0
        if np.any(np.hypot(points[missing, 0], points[missing, 1]) < self._inscribed_radius()):
            raise RuntimeError("a sampling point inside the disk mesh was found on no rank")
        return np.divide(values, counts, out=np.zeros_like(values), where=~missing)

    def _inscribed_radius(self) -> float:
        """The radius of the largest circle inside the polygonal boundary (all ranks)."""
        from mpi4py import MPI

        midpoints = domain.facet_midpoints(self.mesh, self.edge_facets)
        local = np.hypot(midpoints[:, 0], midpoints[:, 1]).min(initial=np.inf)
        return self.comm.allreduce(local, op=MPI.MIN)

"""The 2-D disk film against a manufactured solution, the 1-D mode-0 and mode-1 films (the
superposition P0(R) + s q(R) cos(phi) of the 1-D model), the exact axisymmetric obstacle solution
under cavitation and the Kirchhoff transform of a Barus viscosity. Runs on 2 ranks too.

The 1-D references solve (1/(12R)) (R H^3 f')' - m^2 H^3 f / (12 R^2) = g (m = 0, 1) by P1
finite elements with the weight R on a grid 16 times finer than the film nodes, with the same
piecewise-linear H0 as the disk film is given.
"""

import re
import time

import numpy as np
import pytest
import ufl
from dolfinx import fem
from mpi4py import MPI
from scipy.integrate import quad
from scipy.optimize import brentq
from scipy.sparse import diags
from scipy.sparse.linalg import spsolve

from ehdfem.checks import InputError
from ehdfem.fenicsx import domain, functions
from ehdfem.tangential.disk import solve_disk_film

GAP = 0.05  # X0, the central film thickness of the rigid paraboloid (by x0)
PARABOLOID_EDGE = np.sqrt(2 * (1 - GAP))  # where X0 + R^2/2 = 1
FLAT_EDGE = np.sqrt(1 + np.sqrt(3))  # where R^4 / (2 (1 + R^2)) = 1
GAUSS_XI, GAUSS_W = np.polynomial.legendre.leggauss(4)


def paraboloid(radii):
    """H0 = X0 + R^2/2, the rigid sphere's film."""
    return GAP + radii**2 / 2


def flattened(radii):
    """A flattened film with a central dimple: nearly flat (H0 ~ X0) inside R ~ 0.7, twice as
    thick at the centre, H0 = 1 at FLAT_EDGE."""
    return GAP * (1 + np.exp(-((radii / 0.3) ** 2))) + radii**4 / (2 * (1 + radii**2))


def report(text):
    """Print a measured number once (rank 0)."""
    if MPI.COMM_WORLD.rank == 0:
        print(text)


def refined(radii, factor=16):
    """``radii`` with every interval cut into ``factor`` equal parts."""
    steps = np.linspace(0.0, 1.0, factor + 1)[:-1]
    inner = (radii[:-1, None] + np.diff(radii)[:, None] * steps).ravel()
    return np.append(inner, radii[-1])


def radial_solution(radii, thickness, source, mode, first=0.0):
    """f on ``radii`` (from ``first``) with (1/(12R)) (R H^3 f')' - mode^2 H^3 f/(12 R^2) =
    source(R), f = 0 at the last node (and at the first for mode 1 or first > 0): P1 elements,
    4-point Gauss; ``thickness`` and ``source`` callables of R."""
    left, length = radii[:-1], np.diff(radii)
    r = left[:, None] + length[:, None] * (GAUSS_XI + 1) / 2
    weight = length[:, None] * GAUSS_W / 2 * r
    shape = ((1 - GAUSS_XI) / 2, (1 + GAUSS_XI) / 2)
    mobility = weight * thickness(r) ** 3 / 12
    stiffness_ab = -(mobility.sum(axis=1)) / length**2 + mode**2 * (
        mobility * shape[0] * shape[1] / r**2
    ).sum(axis=1)
    n = radii.size
    diagonal = np.zeros(n)
    for a, node in ((0, slice(0, -1)), (1, slice(1, None))):
        diagonal[node] += mobility.sum(axis=1) / length**2
        diagonal[node] += mode**2 * (mobility * shape[a] ** 2 / r**2).sum(axis=1)
    load = np.zeros(n)
    load[:-1] -= (weight * source(r) * shape[0]).sum(axis=1)
    load[1:] -= (weight * source(r) * shape[1]).sum(axis=1)
    fixed = [n - 1] + ([0] if mode or first > 0 else [])
    matrix = diags([stiffness_ab, diagonal, stiffness_ab], [-1, 0, 1]).tolil()
    for node in fixed:
        matrix.rows[node], matrix.data[node] = [node], [1.0]
        load[node] = 0.0
    return spsolve(matrix.tocsr(), load)


def on_nodes(radii, profile):
    """The piecewise-linear interpolant of ``profile`` at the nodes ``radii`` (a callable)."""
    values = profile(radii)
    return lambda r: np.interp(r, radii, values)


def slope(radii, profile):
    """The piecewise-constant derivative of that interpolant (a callable)."""
    chords = np.diff(profile(radii)) / np.diff(radii)
    return lambda r: chords[np.clip(np.searchsorted(radii, r) - 1, 0, chords.size - 1)]


def radial_integral(radii, values, weight):
    """int f(R) weight(R) dR for the P1 interpolant f of nodal ``values`` on ``radii``, 4-point
    Gauss on each element (``weight`` a callable of R, smooth inside the elements)."""
    length = np.diff(radii)
    r = radii[:-1, None] + length[:, None] * (GAUSS_XI + 1) / 2
    f = values[:-1, None] * (1 - GAUSS_XI) / 2 + values[1:, None] * (1 + GAUSS_XI) / 2
    return float((length[:, None] * GAUSS_W / 2 * f * weight(r)).sum())


def relative_max(values, reference):
    return np.abs(values - reference).max() / np.abs(reference).max()


def test_manufactured_solution_converges_at_second_order():
    """H = 0.3 + R^2/2 + 0.05 R cos(phi) (nodal, 401 nodes), s w = 1, exact
    P = (1 - R^2)(1 + 0.3 X) on R < 1, the squeeze rate the callable that makes it exact. At
    centre element sizes 0.04, 0.02, 0.01 (grading 2) the L2 error and the nodal errors of p0
    and p1 fall at second order in the mean cell size (measured orders 2.06, 2.03 (L2), 2.22,
    2.00 (p0), 2.09, 2.02 (p1); L2 error 3.1e-4 on the finest mesh)."""
    sliding = 1.0
    radii = np.linspace(0.0, 1.0, 401)

    def squeeze_rate(x, y):
        thickness = 0.3 + (x**2 + y**2) / 2 + 0.05 * x
        inside = 1 - x**2 - y**2
        p_x = -2 * x * (1 + 0.3 * x) + 0.3 * inside
        p_y = -2 * y * (1 + 0.3 * x)
        laplacian = -4 * (1 + 0.3 * x) - 1.2 * x
        divergence = 3 * thickness**2 * ((x + 0.05) * p_x + y * p_y) + thickness**3 * laplacian
        return divergence / 12 + sliding / 2 * (x + 0.05)

    errors, sizes = [], []
    for size in (0.04, 0.02, 0.01):
        solution = solve_disk_film(
            radii,
            0.3 + radii**2 / 2,
            squeeze_rate,
            film_thickness_mode_one=0.05 * radii,
            sliding=sliding,
            element_size=size,
            grading=2.0,
        )
        x = ufl.SpatialCoordinate(solution.mesh)
        exact = (1 - x[0] ** 2 - x[1] ** 2) * (1 + 0.3 * x[0])
        local = fem.assemble_scalar(fem.form((solution.pressure - exact) ** 2 * ufl.dx))
        l2 = np.sqrt(MPI.COMM_WORLD.allreduce(local, op=MPI.SUM))
        p0_error = np.abs(solution.axisymmetric_pressure - (1 - radii**2)).max()
        p1_error = np.abs(solution.mode_one_pressure - 0.3 * radii * (1 - radii**2)).max()
        errors.append((l2, p0_error, p1_error))
        sizes.append(domain.cell_count(solution.mesh) ** -0.5)
    errors, sizes = np.array(errors), np.array(sizes)
    orders = np.log(errors[:-1] / errors[1:]) / np.log(sizes[:-1, None] / sizes[1:, None])
    report(f"manufactured: errors (L2, p0, p1) {errors.tolist()}\n  orders {orders.tolist()}")
    assert np.all(orders > 1.8)
    assert errors[-1, 0] < 1e-3


@pytest.mark.slow
@pytest.mark.parametrize(
    "name, profile, squeeze, edge",
    [
        ("paraboloid", paraboloid, lambda r: -np.ones_like(r), PARABOLOID_EDGE),
        ("flattened", flattened, lambda r: -1 + 0.5 * r**2, FLAT_EDGE),
    ],
)
def test_axisymmetric_film_equals_the_one_dimensional_film(name, profile, squeeze, edge):
    """No sliding, no cavitation: p0 is the 1-D P0 and p1 = 0. Rigid approach (dH/dT = -1) of
    the paraboloid (also P0 = 3 (H^-2 - 1) exactly) and a non-uniform squeeze of the flattened
    film; 161 nodes, centre element size 0.005, grading 4: within 1e-3 of max P0 (measured
    6.7e-4 and 4.7e-4), p1 within 1e-4 of it (measured 1.2e-5 and 1.1e-5)."""
    radii = np.linspace(0.0, edge, 161)
    thickness = on_nodes(radii, profile)
    reference = radial_solution(refined(radii), thickness, on_nodes(radii, squeeze), 0)[::16]
    start = time.perf_counter()
    solution = solve_disk_film(radii, profile(radii), squeeze(radii), element_size=0.005)
    elapsed = time.perf_counter() - start
    p0_error = relative_max(solution.axisymmetric_pressure, reference)
    p1_error = np.abs(solution.mode_one_pressure).max() / np.abs(reference).max()
    report(f"axisymmetric {name}: p0 {p0_error:.2e}, p1 {p1_error:.2e}, {elapsed:.1f} s")
    assert p0_error < 1e-3
    assert p1_error < 1e-4
    if name == "paraboloid":
        # the 1-D film on the piecewise-linear H0 of 161 nodes against the exact P0 of the
        # paraboloid: the nodal H0's own error (measured 2.5e-4)
        assert relative_max(reference, 3 * (paraboloid(radii) ** -2 - 1)) < 5e-4


@pytest.mark.slow
@pytest.mark.parametrize(
    "name, profile, edge",
    [("paraboloid", paraboloid, PARABOLOID_EDGE), ("flattened", flattened, FLAT_EDGE)],
)
def test_sliding_film_is_the_mode_one_superposition(name, profile, edge):
    """Sliding s = 0.7 at w = 1 (s w = 0.7), no squeeze, no cavitation: p1 / s is the 1-D q of
    (1/(12R)) (R H0^3 q')' - H0^3 q / (12 R^2) = -(w/2) H0' within 1 % of max |q| (measured
    0.064 % and 0.056 %), p0 = 0 within 1e-4 s max |q| (measured 1.9e-5, 2.5e-5); the moment
    int P X dA = pi s int q R^2 dR and the slope force int P dSigma/dX dA = pi s int q Sigma' R dR
    (Sigma = H0) within 1 % (measured 0.045 %, 0.042 % and 0.039 %, 0.038 %)."""
    s, w = 0.7, 1.0
    radii = np.linspace(0.0, edge, 161)
    fine = refined(radii)
    q = radial_solution(
        fine, on_nodes(radii, profile), lambda r: -w / 2 * slope(radii, profile)(r), 1
    )
    solution = solve_disk_film(
        radii,
        profile(radii),
        np.zeros_like(radii),
        sliding=s * w,
        surface_sum=profile(radii),
        element_size=0.005,
    )
    q_error = relative_max(solution.mode_one_pressure / s, q[::16])
    moment = np.pi * s * radial_integral(fine, q, lambda r: r**2)
    slope_force = np.pi * s * radial_integral(fine, q, lambda r: slope(radii, profile)(r) * r)
    moment_error = abs(solution.pressure_moment / moment - 1)
    slope_error = abs(solution.slope_force / slope_force - 1)
    p0_error = np.abs(solution.axisymmetric_pressure).max() / (s * np.abs(q).max())
    report(
        f"sliding {name}: q {q_error:.2e}, p0 {p0_error:.1e},"
        f" moment {moment_error:.2e}, slope force {slope_error:.2e}"
    )
    assert q_error < 1e-2
    assert moment_error < 1e-2
    assert slope_error < 1e-2
    assert p0_error < 1e-4


def obstacle_pressure(p_cav):
    """The exact axisymmetric film of the paraboloid separating at dH/dT = 1 with the limit
    P_cav: P = P_cav on the cavitated disk R < R_c and, beyond it (flux and P continuous at R_c),
    P(R) = -int_R^R_edge 6 (r^2 - R_c^2) / (r H^3) dr, with R_c such that P(R_c) = P_cav.
    Returns (R_c, P as a callable of R)."""

    def pressure(radius, cavity):
        integrand = lambda r: 6 * (r**2 - cavity**2) / (r * paraboloid(r) ** 3)  # noqa: E731
        return -quad(integrand, radius, PARABOLOID_EDGE, epsabs=1e-13, epsrel=1e-12)[0]

    cavity = brentq(lambda c: pressure(c, c) - p_cav, 1e-6, PARABOLOID_EDGE - 1e-9, xtol=1e-14)
    return cavity, np.vectorize(lambda r: p_cav if r <= cavity else pressure(r, cavity))


@pytest.mark.parametrize("p_cav", [-1.0, -10.0])
def test_cavitation_limit_is_the_axisymmetric_obstacle_solution(p_cav):
    """A separating paraboloid (dH/dT = 1) sucks P down to P_cav over a central disk: P >= P_cav
    at every vertex exactly (P1: the nodal bounds are the pointwise limit), the limit binds
    (thousands of vertices), p0 is the exact obstacle solution (R_c = 1.054 at P_cav = -1,
    0.701 at -10) within 3e-3 of |P_cav| (measured 1.8e-3, 1.2e-3 at centre element size
    0.01), p0 = P_cav exactly well inside R_c, and p1 = 0 within 5e-3 |P_cav| (measured
    4.0e-4, 2.8e-4)."""
    radii = np.linspace(0.0, PARABOLOID_EDGE, 161)
    cavity, exact = obstacle_pressure(p_cav)
    solution = solve_disk_film(
        radii, paraboloid(radii), np.ones_like(radii), p_cav=p_cav, element_size=0.01
    )
    owned = functions.owned_values(solution.pressure)
    lowest = MPI.COMM_WORLD.allreduce(owned.min(), op=MPI.MIN)
    p0_error = relative_max(solution.axisymmetric_pressure, exact(radii))
    p1_error = np.abs(solution.mode_one_pressure).max() / abs(p_cav)
    report(
        f"cavitation P_cav = {p_cav}: R_c {cavity:.4f}, {solution.cavitated_nodes} vertices at the"
        f" limit, lowest P - P_cav {lowest - p_cav:.1e}, p0 {p0_error:.2e}, p1 {p1_error:.2e},"
        f" {solution.iterations} iterations"
    )
    assert lowest >= p_cav
    assert solution.cavitated_nodes > 1000
    assert p0_error < 3e-3
    assert p1_error < 5e-3
    assert np.all(solution.axisymmetric_pressure[radii < cavity - 0.05] == p_cav)


@pytest.mark.slow
def test_sliding_under_cavitation_is_the_mode_one_film_outside_the_cavity():
    """Sliding (s w = 0.05 at w = 1) on the separating paraboloid at P_cav = -10: the mode-1
    pressure the sliding adds, (p1(s) - p1(0)) / s (p1(0) the mesh's own asymmetry), is the
    1-D q with q = 0 on the cavitated disk (q(R_c) = 0, the 1-D model's rule) within 4 % of
    max |q| (measured 2.2 % at centre element size 0.01, 0.7 % at 0.005; the superposition's
    own error grows as about 0.1-0.2 s). P >= P_cav holds exactly."""
    s, p_cav = 0.05, -10.0
    radii = np.linspace(0.0, PARABOLOID_EDGE, 161)
    cavity, _ = obstacle_pressure(p_cav)
    film = [
        solve_disk_film(
            radii,
            paraboloid(radii),
            np.ones_like(radii),
            p_cav=p_cav,
            sliding=sliding,
            element_size=0.01,
        )
        for sliding in (0.0, s)
    ]
    wet = np.concatenate([[cavity], refined(radii[radii > cavity])])
    q = radial_solution(wet, paraboloid, lambda r: -0.5 * r, 1, first=cavity)
    reference = np.interp(radii, wet, q, left=0.0)
    added = (film[1].mode_one_pressure - film[0].mode_one_pressure) / s
    error = relative_max(added, reference)
    report(f"sliding under cavitation: q {error:.2e}")
    assert error < 4e-2
    lowest = functions.local_values(film[1].pressure).min()
    assert MPI.COMM_WORLD.allreduce(lowest, op=MPI.MIN) >= p_cav


def test_barus_viscosity_is_the_kirchhoff_transform_of_the_constant_one():
    """mu0/mu = exp(-alpha P): the Kirchhoff transform Psi = (1 - exp(-alpha P)) / alpha turns
    div(exp(-alpha P) H^3 grad P) into div(H^3 grad Psi), so P = -ln(1 - alpha P_const) / alpha
    with P_const the film at constant viscosity (rigid approach of the paraboloid, alpha P_const
    up to 1/2). Newton's iterations (5) agree with it within 3e-3 of max P (measured 4.5e-4)."""
    radii = np.linspace(0.0, PARABOLOID_EDGE, 161)
    alpha = 0.5 / (3 * (GAP**-2 - 1))
    films = [
        solve_disk_film(
            radii, paraboloid(radii), -np.ones_like(radii), fluidity=fluidity, element_size=0.01
        )
        for fluidity in (None, lambda p: ufl.exp(-alpha * p))
    ]
    transformed = -np.log(1 - alpha * films[0].axisymmetric_pressure) / alpha
    error = relative_max(films[1].axisymmetric_pressure, transformed)
    report(f"Barus: {error:.2e}, {films[1].iterations} Newton iterations")
    assert error < 3e-3
    assert films[1].iterations > 1


def test_same_film_on_every_rank_as_on_one():
    """The film distributed over MPI.COMM_WORLD (2 ranks under mpirun) against the same gmsh
    mesh on one process: amplitudes and integrals agree to 1e-9 (cavitation, sliding, a slope
    force; trivially on one rank)."""
    radii = np.linspace(0.0, PARABOLOID_EDGE, 81)
    films = [
        solve_disk_film(
            radii,
            paraboloid(radii),
            np.ones_like(radii),
            p_cav=-5.0,
            sliding=0.3,
            surface_sum=paraboloid(radii),
            element_size=0.02,
            comm=comm,
        )
        for comm in (MPI.COMM_SELF, MPI.COMM_WORLD)
    ]
    for name in ("axisymmetric_pressure", "mode_one_pressure"):
        one, every = (getattr(film, name) for film in films)
        assert np.abs(every - one).max() < 1e-9 * np.abs(one).max(), name
    for name in ("normal_force", "pressure_moment", "slope_force"):
        one, every = (getattr(film, name) for film in films)
        assert every == pytest.approx(one, rel=1e-9), name
    assert films[0].cavitated_nodes == films[1].cavitated_nodes


@pytest.mark.parametrize(
    "arguments, message",
    [
        ({"radii": [0.1, 1.0]}, "radii must be finite, start at 0"),
        ({"film_thickness": [1.0, 1.0]}, "film_thickness must be 3 finite values"),
        ({"film_thickness_mode_one": [0.0, 0.0, 2.0]}, "must exceed |film_thickness_mode_one|"),
        ({"p_cav": 1.0}, "p_cav = 1.0 is outside the allowed range"),
        ({"edge_radius": 2.0}, "edge_radius = 2.0 is outside the allowed range (0, 1]"),
        ({"element_size": 0.0}, "element_size = 0.0 is outside the allowed range"),
        ({"grading": 0.5}, "grading = 0.5 is outside the allowed range [1, inf)"),
        ({"angles": 4}, "angles = 4 is outside the allowed range"),
        ({"squeeze_rate_mode_one": [0.0, 0.0, 0.0]}, "a callable squeeze_rate takes no"),
    ],
)
def test_inputs_are_checked_before_any_work(arguments, message):
    """Each bad input raises InputError naming it, before a mesh is built."""
    inputs = {
        "radii": [0.0, 0.5, 1.0],
        "film_thickness": [0.1, 0.3, 1.0],
        "squeeze_rate": (lambda x, y: x) if "squeeze_rate_mode_one" in arguments else [0, 0, 0],
    }
    inputs.update(arguments)
    positional = [inputs.pop(name) for name in ("radii", "film_thickness", "squeeze_rate")]
    with pytest.raises(InputError, match=re.escape(message)):
        solve_disk_film(*positional, **inputs)

"""Mode-1 (cos phi) ring-load kernels of an elastic half-space against exact elastic results.

Units of :mod:`ehdfem.solids.halfspace_mode_one`: displacements by 4 (1 - nu^2)/(pi E) times
traction times length; beta = nu/(1 - nu), gamma = (1 - 2 nu)/(2 (1 - nu)).
"""

from functools import cache

import numpy as np
import pytest
from scipy.integrate import quad

from ehdfem.checks import InputError
from ehdfem.film.grid import radial_grid
from ehdfem.solids.halfspace_mode_one import (
    HalfSpaceModeOne,
    ring_kernel,
    surface_response,
)

NU = 0.3
BETA = NU / (1 - NU)
GAMMA = (1 - 2 * NU) / (2 * (1 - NU))


@cache
def disc_response(n):
    """surface_response on n uniform nodes over the loaded disc 0 <= R <= 1."""
    return surface_response(np.linspace(0.0, 1.0, n), NU)


def blocks(response):
    """The (3, 3) nodal blocks [displacement (U_r, U_phi, U_z)][load (A, B, Z)]."""
    n = len(response) // 3
    return [
        [response[i * n : (i + 1) * n, j * n : (j + 1) * n] for j in range(3)] for i in range(3)
    ]


def along_x(radius, traction, singular=False):
    """(U_r, U_phi, U_z)(R) of the continuous kernel for the traction tau(S) along x (A = B = tau)
    on S < 1, by adaptive quadrature (S = sin t when tau has the 1/sqrt(1 - S^2) edge)."""

    def integrand(s, component):
        k = ring_kernel(radius, s - radius, NU)
        return (k[component, 0] + k[component, 1]) * traction(s)

    def integral(component):
        if singular:
            f = lambda t: integrand(np.sin(t), component) * np.cos(t)  # noqa: E731
            upper, kink = np.pi / 2, np.arcsin(radius)
        else:
            f, upper, kink = (lambda s: integrand(s, component)), 1.0, radius
        points = [kink] if 0 < kink < upper else None
        return quad(f, 0, upper, points=points, limit=400, epsabs=1e-13, epsrel=1e-12)[0]

    return np.array([integral(c) for c in range(3)])


@pytest.mark.parametrize("radius", [0.0, 0.3, 0.7, 0.95])
def test_cattaneo_mindlin_traction_moves_the_disc_uniformly(radius):
    """Traction (1 - R^2)^(-1/2) along x: u_x = pi (2 - nu)/(4 G) inside, i.e. U_r = U_phi =
    pi^2 (2 - nu)/(8 (1 - nu)) (Johnson ch. 3), and U_z = -(gamma pi/(2R)) int_0^R tau S dS
    = -(gamma pi/(2R)) (1 - sqrt(1 - R^2)). Measured: 1.6e-12 relative (at R = 0.95; the
    adaptive reference), 1e-16 absolute."""
    u = along_x(radius, lambda s: 1 / np.sqrt(1 - s * s), singular=True)
    uniform = np.pi**2 * (2 - NU) / (8 * (1 - NU))
    normal = 0.0 if radius == 0 else -GAMMA * np.pi / (2 * radius) * (1 - np.sqrt(1 - radius**2))
    assert u[:2] == pytest.approx([uniform, uniform], rel=1e-11)
    assert u[2] == pytest.approx(normal, abs=1e-14)


@pytest.mark.parametrize("radius", [0.0, 0.3, 0.7, 0.95])
def test_hertz_type_tangential_traction(radius):
    """Traction sqrt(1 - R^2) along x: u_x = pi/(32 G) (4 (2 - nu) - (4 - 3 nu) x^2
    - (4 - nu) y^2) (Johnson ch. 7), i.e. U_r, U_phi = pi^2/(64 (1 - nu)) (4 (2 - nu)
    - (4 - 3 nu | 4 - nu) R^2). Measured: 5e-14 relative."""
    u = along_x(radius, lambda s: np.sqrt(1 - s * s))
    scale = np.pi**2 / (64 * (1 - NU))
    expected = scale * (4 * (2 - NU) - np.array([4 - 3 * NU, 4 - NU]) * radius**2)
    assert u[:2] == pytest.approx(expected, rel=1e-12)


def test_kernel_reciprocity():
    """Betti: k_ab(R, S)/S = k_ba(S, R)/R for every pair of components, on both sides of the
    switch between closed forms and trapezoidal rule (min/max = 1/4). Measured: 2e-16."""
    rng = np.random.default_rng(1)
    r = np.concatenate([rng.uniform(0.01, 2.0, 200), [1.0, 1.0, 1.0]])
    s = np.concatenate([rng.uniform(0.01, 2.0, 200), [0.25, 4.0, 1.0 + 1e-9]])
    forward = ring_kernel(r, s - r, NU) / s
    backward = np.swapaxes(ring_kernel(s, r - s, NU), 0, 1) / r
    assert np.abs(forward - backward).max() < 1e-14 * np.abs(forward).max()


def translated_pressure_errors(n):
    """Errors of (U_r, U_phi, U_z) for the mode-1 pressure p0'(R) cos phi, p0 = (1 - R^2)^(5/2),
    inside 0.9, against the x-derivative of the axisymmetric displacements of p0:
    U_z = -W0', W0 = (5 pi^2/64) (1 - 3x/2 + 9x^2/8 - 5x^3/16), x = R^2 (the deflection of p0);
    U_r = u0', U_phi = u0/R with u0 = -(gamma pi/(2R)) int_0^R p0 S dS the radial displacement
    (Johnson ch. 3)."""
    r = np.linspace(0.0, 1.0, n)
    response = disc_response(n)
    u = response[:, 2 * n :] @ (5 * r * (1 - r**2) ** 1.5)  # Z = -p0'
    inner = np.divide(1 - (1 - r**2) ** 3.5, 7 * r**2, out=np.full(n, 0.5), where=r > 0)
    expected = np.concatenate(
        [
            -GAMMA * np.pi / 2 * ((1 - r**2) ** 2.5 - inner),
            -GAMMA * np.pi / 2 * inner,
            -5 * np.pi**2 / 32 * r * (-1.5 + 9 / 4 * r**2 - 15 / 16 * r**4),
        ]
    )
    return np.abs(u - expected).reshape(3, n)[:, r <= 0.9].max(axis=1)


def test_translated_pressure_converges_at_second_order():
    """d/dx commutes with the half-space response. Errors at 41 nodes (h = 1/40): 9.4e-5 (U_r),
    6.7e-5 (U_phi), 3.1e-4 (U_z, of max 0.77); orders 1.96-2.05 from 41 to 161 nodes."""
    errors = np.array([translated_pressure_errors(n) for n in (41, 81, 161)])
    assert np.all(errors[0] < [1e-4, 1e-4, 4e-4]), errors[0]
    orders = np.log2(errors[:-1] / errors[1:])
    assert np.all((orders > 1.85) & (orders < 2.2)), orders


def test_discrete_hertz_type_tangential_traction():
    """A = B = sqrt(1 - R^2) on hat functions: the closed forms of
    :func:`test_hertz_type_tangential_traction` and U_z = -(gamma pi/(6R)) (1 - (1 - R^2)^(3/2)).
    The error is the linear interpolation of the square-root edge, of order h^(3/2): at 41
    nodes 5.1e-3 (U_r), 6.9e-3 (U_phi) relative, 5.0e-4 absolute (U_z); orders 1.33-1.48 to
    81 nodes."""

    def errors(n):
        r = np.linspace(0.0, 1.0, n)
        (ra, rb, _), (pa, pb, _), (za, zb, _) = blocks(disc_response(n))
        tau = np.sqrt(1 - r**2)
        scale = np.pi**2 / (64 * (1 - NU))
        hoop = scale * (4 * (2 - NU) - (4 - NU) * r**2)
        radial = scale * (4 * (2 - NU) - (4 - 3 * NU) * r**2)
        normal = -GAMMA * np.pi / 6 * np.divide(1 - tau**3, r, out=np.zeros(n), where=r > 0)
        return np.array(
            [
                np.abs((ra + rb) @ tau / radial - 1).max(),
                np.abs((pa + pb) @ tau / hoop - 1).max(),
                np.abs((za + zb) @ tau - normal).max(),
            ]
        )

    coarse, fine = errors(41), errors(81)
    assert np.all(coarse < [6e-3, 8e-3, 6e-4]), coarse
    orders = np.log2(coarse / fine)
    assert np.all((orders > 1.3) & (orders < 1.6)), orders


def test_uniform_disc_traction():
    """tau = 1 along x on R < c (a ramp over 1e-6 c to zero): centre u_x = (2 - nu) c/(2 G),
    i.e. U_r(0) = U_phi(0) = (pi/4)(2 + beta) c_eff with c_eff = c (1 + 5e-7) for the ramp;
    U_z = -(gamma pi/4) R inside and -(gamma pi/4) c^2/R outside. Measured: round-off at the
    centre, 1.8e-7 for U_z (the ramp)."""
    c = 0.8
    base = radial_grid(150, c, 3.0)
    r = np.unique(np.concatenate([base[np.abs(base - c) > 1e-2], [c, c * (1 + 1e-6)]]))
    n = len(r)
    (ra, rb, _), (pa, pb, _), (za, zb, _) = blocks(surface_response(r, NU))
    tau = (r <= c).astype(float)
    centre = np.pi / 4 * (2 + BETA) * c * (1 + 5e-7)
    assert (ra + rb)[0] @ tau == pytest.approx(centre, rel=1e-13)
    assert (pa + pb)[0] @ tau == pytest.approx(centre, rel=1e-13)
    outside = np.divide(c**2, r, out=np.zeros(n), where=r > 0)
    normal = -GAMMA * np.pi / 4 * np.where(r <= c, r, outside)
    assert np.abs((za + zb) @ tau - normal).max() < 5e-7


def test_betti_reciprocity_of_the_discrete_response():
    """int (U[L1] . L2) R dR = int (U[L2] . L1) R dR (consistent R-weighted mass) for smooth
    (A, B, Z) loads: the asymmetry, the nodal interpolation of the displacement, falls at second
    order: 2.3e-6, 5.1e-7 at 60, 120 nodes (orders 2.15, 2.08). (For single hats it falls at
    first order, like the axisymmetric kernel's.)"""

    def asymmetry(n):
        r = radial_grid(n, 0.5, 2.0)
        length, mass = np.diff(r), np.zeros((n, n))
        for i, (a, b) in enumerate(zip(r[:-1], r[1:], strict=True)):  # int phi_i phi_j R dR
            cell = length[i] / 12 * np.array([[3 * a + b, a + b], [a + b, a + 3 * b]])
            mass[i : i + 2, i : i + 2] += cell
        x, bump = r / 2, (1 - (r / 2) ** 2) ** 3
        first = np.concatenate([bump, np.cos(x) * bump, (1 + x) * bump])
        second = np.concatenate([x * bump, (1 - x**2) * bump, np.exp(-x) * bump])
        energy = np.kron(np.eye(3), mass) @ surface_response(r, NU)
        forward, backward = second @ energy @ first, first @ energy @ second
        return abs(forward - backward) / abs(forward)

    coarse, fine = asymmetry(60), asymmetry(120)
    assert coarse < 3e-6
    assert 1.9 < np.log2(coarse / fine) < 2.3


SOLIDS = [((1.0, 0.3), (1.0, 0.3)), ((3.0, 0.1), (0.5, 0.45)), ((1.0, -0.5), (20.0, 0.2))]


@cache
def mode_one(solids, eps=2.0, delta=0.04):
    return HalfSpaceModeOne(np.linspace(0.0, 2.0, 25), eps, delta, solids)


@pytest.mark.parametrize("solids", SOLIDS)
def test_mode_one_gap_does_not_depend_on_the_solids(solids):
    """The mode-1 gap opening from the pressure, sphere_normal - wall_normal, is eps times the
    nu-independent Z -> U_z block for Z = -q, whatever the moduli and Poisson ratios (1e-15);
    each face's share is its (1 - nu^2)/E over the sum."""
    solid = mode_one(solids)
    gap = solid.block("sphere_normal", "pressure") - solid.block("wall_normal", "pressure")
    _, _, (_, _, zz) = blocks(surface_response(solid.radii, 0.1))
    assert np.abs(gap - 2.0 * zz).max() < 1e-14 * np.abs(zz).max()
    share = [(1 - nu**2) / e for e, nu in solids]
    wall = solid.block("wall_normal", "pressure")
    assert np.abs(wall + 2.0 * share[1] / sum(share) * zz).max() < 1e-14 * np.abs(zz).max()


def test_identical_solids_are_loaded_symmetrically():
    """Identical solids: the pressure moves the faces apart symmetrically (sphere_normal =
    -wall_normal) and alike tangentially; equal and opposite shear tractions (Couette) leave
    the gap unchanged, equal ones (Poiseuille) change it; no face moves under the other face's
    shear; shear blocks scale with sqrt(delta)."""
    solid = mode_one(SOLIDS[0])
    b = solid.block
    assert np.array_equal(b("sphere_normal", "pressure"), -b("wall_normal", "pressure"))
    for comp in ("radial", "hoop"):
        assert np.array_equal(b(f"sphere_{comp}", "pressure"), b(f"wall_{comp}", "pressure"))
    for shear in ("radial", "hoop"):
        opposite = b("sphere_normal", f"sphere_{shear}") + b("wall_normal", f"wall_{shear}")
        assert np.array_equal(opposite, np.zeros_like(opposite))
        assert np.abs(b("sphere_normal", f"sphere_{shear}")).max() > 1e-3
        assert not np.any(b("wall_normal", f"sphere_{shear}"))
        assert not np.any(b("sphere_radial", f"wall_{shear}"))
    thinner = mode_one(SOLIDS[0], delta=0.01)
    for face in ("sphere", "wall"):
        shear = b(f"{face}_hoop", f"{face}_radial")
        assert np.allclose(thinner.block(f"{face}_hoop", f"{face}_radial"), 0.5 * shear, 1e-14, 0)
    assert solid.with_eps(4.0).matrix == pytest.approx(2 * solid.matrix, rel=1e-15)


@pytest.mark.parametrize(
    ("radii", "eps", "delta", "solids", "name"),
    [
        ([0.1, 0.2, 0.3], 1.0, 0.01, SOLIDS[0], "radii"),
        ([0.0, 0.2, 0.1], 1.0, 0.01, SOLIDS[0], "radii"),
        ([0.0, 0.1], 1.0, 0.01, SOLIDS[0], "radii"),
        ([0.0, 0.1, 0.2], -1.0, 0.01, SOLIDS[0], "eps"),
        ([0.0, 0.1, 0.2], 1.0, 0.0, SOLIDS[0], "delta"),
        ([0.0, 0.1, 0.2], 1.0, 1.5, SOLIDS[0], "delta"),
        ([0.0, 0.1, 0.2], 1.0, 0.01, ((0.0, 0.3), (1.0, 0.3)), "sphere Young's modulus"),
        ([0.0, 0.1, 0.2], 1.0, 0.01, ((1.0, 0.3), (1.0, 0.5)), "wall Poisson ratio"),
        ([0.0, 0.1, 0.2], 1.0, 0.01, ((1.0, 0.3),), "solids"),
    ],
)
def test_bad_input(radii, eps, delta, solids, name):
    with pytest.raises(InputError, match=name):
        HalfSpaceModeOne(np.array(radii), eps, delta, solids)
    if name == "wall Poisson ratio":
        with pytest.raises(InputError, match="poisson"):
            surface_response(np.array(radii), 0.5)

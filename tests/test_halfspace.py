"""Half-space ring-load kernel against exact elastic contact results."""

import warnings

import numpy as np
import pytest
from scipy.integrate import quad
from scipy.special import ellipkm1

from ehdfem.checks import InputError
from ehdfem.collision import DEFAULT_NODES, collide
from ehdfem.film.grid import radial_grid
from ehdfem.film.reynolds import Film
from ehdfem.inputs.scales import CollisionParameters
from ehdfem.solids import halfspace
from ehdfem.solids.compliance import FILM_REACH_LIMIT
from ehdfem.solids.halfspace import (
    COMPRESSION_LIMIT,
    LOAD_RADIUS_LIMIT,
    HalfSpaceCompliance,
    HalfSpaceRange,
    HalfSpaceRangeWarning,
    halfspace_range,
    influence_matrix,
    load_radius,
)
from ehdfem.solids.halfspace_mode_one import response_parts

pytestmark = pytest.mark.serial


def contact_grid(n, c=1.0, outer=2.5):
    """A film grid like the collisions' (fine radius = contact radius) with a node at R = c."""
    r = radial_grid(n, c, outer)
    r[np.argmin(np.abs(r - c))] = c
    return r


def hertz_deflection(r, c=1.0, p0=1.0, eps=1.0):
    """W for P = p0 sqrt(1 - R^2/c^2): pi^2 eps p0 (2c^2 - R^2)/(16 c) inside, and outside
    (pi eps p0 / (8 c)) ((2c^2 - R^2) asin(c/R) + c sqrt(R^2 - c^2))."""
    outside = np.maximum(r, c)
    return np.where(
        r <= c,
        np.pi**2 * eps * p0 * (2 * c**2 - r**2) / (16 * c),
        np.pi
        * eps
        * p0
        / (8 * c)
        * ((2 * c**2 - outside**2) * np.arcsin(c / outside) + c * np.sqrt(outside**2 - c**2)),
    )


def hertz_errors(n):
    r = contact_grid(n)
    w = HalfSpaceCompliance(r, 1.0).deflection(np.sqrt(np.clip(1 - r**2, 0, None)))
    return r, np.abs(w / hertz_deflection(r) - 1)


def test_hertz_pressure_at_the_default_grid():
    """At the default number of nodes: 1e-3 inside 0.9 c, 2e-3 at the rim and outside. The
    error is the linear interpolation of the square-root edge of the pressure, not the
    quadrature (checked separately below)."""
    r, err = hertz_errors(DEFAULT_NODES)
    assert err[r <= 0.9].max() < 1e-3
    assert err.max() < 2e-3


def test_hertz_error_converges_at_second_order():
    errors = [hertz_errors(n)[1][0] for n in (80, 160, 320)]
    orders = np.log2(np.array(errors[:-1]) / errors[1:])
    assert np.all((orders > 1.7) & (orders < 2.6)), orders


def test_uniform_disc_centre_and_rim():
    """Uniform P on R < c: W(0) = pi eps P c / 2 and W(c) = eps P c (2/pi of the centre). The
    jump is a ramp over 1e-6 c, which also tests cells right next to a much longer one."""
    c = 0.8
    base = radial_grid(150, c, 3.0)
    r = np.unique(np.concatenate([base[np.abs(base - c) > 1e-2], [c, c * (1 + 1e-6)]]))
    w = HalfSpaceCompliance(r, 2.0).deflection((r <= c).astype(float))
    assert w[0] == pytest.approx(np.pi * 2.0 * c / 2, rel=1e-5)
    assert w[r == c][0] == pytest.approx(2.0 * c, rel=2e-3)


def test_matrix_integrates_the_interpolant_exactly():
    """Against adaptive quadrature of the continuous integral of the same piecewise-linear
    pressure, cell by cell; on the cells next to R the substitution S = R +- L u^4 removes the
    logarithm. Agreement to 1e-8 of max |W| (the level at which adaptive references agree)."""
    r = radial_grid(60, 0.5, 2.0)
    p = np.clip(1 - r**2 / 4, 0, None) ** 2
    w = influence_matrix(r) @ p

    def integrand(offset, radius):  # at S = radius + offset
        s = radius + offset
        ring = s / (2 * radius + offset) * ellipkm1((offset / (2 * radius + offset)) ** 2)
        return np.interp(s, r, p) * ring

    def cell(a, b, radius):
        if radius in (a, b):  # S = radius + sign L u^4, dS = 4 L u^3 du
            sign, length = (1.0 if radius == a else -1.0), b - a
            return quad(
                lambda u: integrand(sign * length * u**4, radius) * 4 * length * u**3,
                0,
                1,
                epsabs=1e-14,
                epsrel=1e-12,
            )[0]
        return quad(lambda s: integrand(s - radius, radius), a, b, epsabs=1e-14, epsrel=1e-12)[0]

    for i in (0, 7, 23, 41, 59):
        reference = sum(cell(a, b, r[i]) for a, b in zip(r[:-1], r[1:], strict=True))
        assert w[i] == pytest.approx(reference, abs=1e-8 * np.abs(w).max())


def test_reciprocity():
    """Betti: int phi_i W[phi_j] R dR is symmetric. With the lumped masses M of the film, M A is
    symmetric up to the lumping error, which halves when the grid is refined (first order; its
    relative Frobenius norm is 0.9 % at 60 nodes)."""
    asymmetry = []
    for n in (60, 120, 240):
        r = radial_grid(n, 0.5, 2.0)
        energy = Film(r).full_mass[:, None] * influence_matrix(r)
        asymmetry.append(np.linalg.norm(energy - energy.T) / np.linalg.norm(energy))
    assert asymmetry[0] < 1e-2
    ratios = np.array(asymmetry[:-1]) / asymmetry[1:]
    assert np.all((ratios > 1.8) & (ratios < 2.2)), ratios


@pytest.mark.parametrize(
    ("radii", "eps"),
    [([0.1, 0.2, 0.3], 1.0), ([0.0, 0.2, 0.1], 1.0), ([0.0, 0.1], 1.0), ([0.0, 0.1, 0.2], -1.0)],
)
def test_bad_input(radii, eps):
    with pytest.raises(InputError):
        HalfSpaceCompliance(np.array(radii), eps)


def test_load_radius_of_a_hertz_pressure():
    """The radius carrying 95 % of the force of P = sqrt(1 - R^2): the force within r is
    1 - (1 - r^2)^(3/2) of the total, so r_95 = sqrt(1 - 0.05^(2/3)) = 0.92965; the trapezoid
    rule on 4000 nodes gets it to 1e-4 (the square root's edge is the error)."""
    radii = np.linspace(0.0, 1.5, 4001)
    pressure = np.sqrt(np.clip(1.0 - radii**2, 0.0, None))
    assert load_radius(radii, pressure) == pytest.approx(np.sqrt(1 - 0.05 ** (2 / 3)), abs=1e-4)
    assert load_radius(radii, -pressure) == 0.0  # a suction alone carries no load


@pytest.mark.slow
@pytest.mark.serial
def test_a_collision_beyond_the_theorys_range_is_flagged():
    """St 1000, eps 0.1, delta 0.1 compresses the sphere by 1.78 a (x0 = a / 10 and 17.8 x0):
    flagged, warned of and in the summary; a mild impact (St 12, eps 1e-3, delta 0.01:
    compression 0.013 a) is not."""
    with pytest.warns(HalfSpaceRangeWarning, match="compression 1.78 a"):
        hard = collide(CollisionParameters(St=1000, eps=0.1, delta=0.1))
    assert hard.halfspace_range.compression > COMPRESSION_LIMIT
    summary = hard.summary()
    assert summary["halfspace_range_flag"] is True
    assert summary["compression_by_radius"] == pytest.approx(1.78, abs=0.01)
    with warnings.catch_warnings():
        warnings.simplefilter("error", HalfSpaceRangeWarning)
        mild = collide(CollisionParameters(St=12, eps=1e-3, delta=0.01))
    assert not mild.halfspace_range.flagged
    assert mild.halfspace_range.load_radius < LOAD_RADIUS_LIMIT


def test_range_warning_points_to_the_fe_solids_only_where_they_take_the_film():
    """The FE solids take a film reaching FILM_REACH_LIMIT a at most: a flagged collision whose
    film stays inside is told to use them; one whose film reaches past (an immersed film's
    grid, R = 30 sqrt(a x0), reaches 9.5 a at delta = 0.1) is told the layer thickness at
    which they would take it, (FILM_REACH_LIMIT / reach)^2 times its own (the reach goes as
    sqrt(delta) on the same scaled grid), and not to use them."""
    radii = np.linspace(0.0, 30.0, 31)
    immersed = halfspace_range(radii, np.ones_like(radii), 0.2, 0.1)
    assert immersed.film_reach == pytest.approx(30.0 * np.sqrt(0.1), rel=1e-15)
    thinner = (FILM_REACH_LIMIT / immersed.film_reach) ** 2
    assert immersed.film_reach * np.sqrt(thinner) == pytest.approx(FILM_REACH_LIMIT, rel=1e-12)
    text = immersed.warning()
    assert f"about {thinner:.2g} times" in text and "use the FE solids" not in text
    inside = HalfSpaceRange(compression=0.2, load_radius=0.3, film_reach=0.5)
    assert "use the FE solids (model fem) here" in inside.warning()


def test_grid_matrices_are_kept_per_kind_read_only_and_as_built(monkeypatch):
    """kept_on_grid: a matrix of the same kind and grid is the one built (not rebuilt), read-only;
    a kind keeps its latest KEPT_KERNELS grids, whatever the other kinds hold; the kept mode-1
    response is the same bits as one built afresh."""
    monkeypatch.setattr(halfspace, "_kernels", {})
    monkeypatch.setattr(halfspace, "KEPT_KERNELS", 2)
    built = []

    def build(kind, radii):
        return halfspace.kept_on_grid(kind, radii, lambda: built.append(kind) or np.ones(3))

    grids = [np.linspace(0.0, 1.0 + k, 5) for k in range(3)]
    first = build("a", grids[0])
    assert build("a", grids[0]) is first and built == ["a"]
    with pytest.raises(ValueError):
        first[0] = 2.0
    build("b", grids[0])
    build("a", grids[1])
    build("a", grids[2])  # evicts ("a", grids[0]) alone
    assert build("b", grids[0]) is not None and built == ["a", "b", "a", "a"]
    build("a", grids[1])
    assert built == ["a", "b", "a", "a"]
    build("a", grids[0])
    assert built == ["a", "b", "a", "a", "a"]

    r = contact_grid(40)
    kept = response_parts(r)
    assert response_parts(r) is kept
    halfspace._kernels.clear()
    assert np.array_equal(response_parts(r), kept)


@pytest.mark.parametrize("layer", ["thin", "immersed"])
def test_fewer_gauss_points_on_far_cells_lose_nothing(layer):
    """The cells MIDDLE_CELLS and FAR_CELLS of their lengths from R_i take 6 and 4 Gauss points
    instead of 8: the pressure's influence matrix and the mode-1 response's parts agree with
    the same integrals by 16 points on every cell beyond one length (the graded rule kept) to
    1e-14 of their largest entry, on a default collision's grid (7e-15 measured, as with 8
    points everywhere)."""
    from ehdfem.solids import halfspace_mode_one

    radii = collide(CollisionParameters.from_settings(St=10.0, eps=1e-3, layer=layer)).normal.radii
    nodes, weights = np.polynomial.legendre.leggauss(16)
    sixteen = (0.5 * (nodes + 1.0), 0.5 * weights)
    for kernel, size in (
        (halfspace._ring_kernel, 1),
        (halfspace_mode_one._nonzero_parts, len(halfspace_mode_one._NONZERO)),
    ):
        reference = halfspace.hat_integrals(radii, kernel, size, gauss=(sixteen,) * 3)
        error = np.abs(halfspace.hat_integrals(radii, kernel, size) - reference)
        assert error.max() < 1e-14 * np.abs(reference).max()

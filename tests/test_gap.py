"""The exact sphere gap against closed forms and exact rigid-sphere solutions.

For a rigid sphere the quasi-steady film needs no paraboloid: R H^3 dP/dR = 6 V R^2 whatever
the undeformed gap S(R), so with H = X + S(R) and P = 0 at the wetted edge S(R_e) = 1 - X the
force is F = -V G(X), G(X) = int_0^R_e R^3 / H^3 dR, and the sphere slows as
St dV/dX = -G(X). Both are evaluated here by adaptive quadrature.
"""

import math

import numpy as np
import pytest
from scipy.integrate import quad
from scipy.optimize import brentq

from ehdfem.checks import InputError
from ehdfem.film.gap import ExactGap, ExactSpheres, Paraboloid, ParaboloidGap, default_gap
from ehdfem.film.grid import radial_grid
from ehdfem.film.reynolds import Film
from ehdfem.inputs.scales import CollisionParameters
from ehdfem.motion.normal import solve_normal
from ehdfem.motion.timestepping import IntegratorOptions
from ehdfem.solids.compliance import RigidSolids

pytestmark = pytest.mark.serial
DELTA = 0.1


def sphere_height(radius, rho=1.0, delta=DELTA):
    """(rho - sqrt(rho^2 - delta R^2)) / delta, the plain form."""
    return (rho - np.sqrt(rho**2 - delta * radius**2)) / delta


def edge(gap, shape):
    return brentq(lambda r: gap + shape.height(r) - 1.0, 0.0, 2.0)


def resistance(gap, shape):
    """G(X) = int_0^R_e R^3 / (X + S(R))^3 dR."""
    return quad(lambda r: r**3 / (gap + shape.height(r)) ** 3, 0.0, edge(gap, shape), limit=200)[0]


def test_exact_heights_and_their_series():
    """Sphere on a wall and two spheres against the plain formula (1e-13) and the series
    R^2/2 + delta R^4 (sum rho^-3)/8 + delta^2 R^6 (sum rho^-5)/16 (to O(delta^3 R^8))."""
    r = np.linspace(0.0, 2.0, 9)
    for radii in ((1.0, math.inf), (2.0, 2.0), (1.25, 5.0)):
        shape = ExactSpheres(DELTA, radii)
        finite = [rho for rho in radii if not math.isinf(rho)]
        plain = sum(sphere_height(r, rho) for rho in finite)
        assert shape.height(r) == pytest.approx(plain, rel=1e-13, abs=1e-15)
        series = (
            r**2 / 2
            + DELTA * r**4 * sum(rho**-3 for rho in finite) / 8
            + DELTA**2 * r**6 * sum(rho**-5 for rho in finite) / 16
        )
        assert np.abs(shape.height(r) - series).max() < 0.1 * DELTA**3 * r.max() ** 8


def test_between_nodes_is_the_height_minus_its_interpolant():
    """between_nodes and slope_between_nodes against the plain height and a central
    difference of it (1e-12 and 1e-7), and equal to the paraboloid's at delta -> 0."""
    shape = ExactSpheres(DELTA)
    left, length = np.array([0.0, 0.5, 1.3]), np.array([0.1, 0.2, 0.35])
    xi = np.array([0.1, 0.5, 0.9])
    points = left[:, None] + length[:, None] * xi
    chord = (1 - xi) * sphere_height(left)[:, None] + xi * sphere_height(left + length)[:, None]
    assert shape.between_nodes(left, length, xi) == pytest.approx(
        sphere_height(points) - chord, abs=1e-12
    )
    step = 1e-5
    slope = (sphere_height(points + step) - sphere_height(points - step)) / (2 * step)
    chord_slope = ((sphere_height(left + length) - sphere_height(left)) / length)[:, None]
    assert shape.slope_between_nodes(left, length, xi) == pytest.approx(
        slope - chord_slope, abs=1e-7
    )
    flat = ExactSpheres(1e-12)
    assert flat.between_nodes(left, length, xi) == pytest.approx(
        Paraboloid().between_nodes(left, length, xi), abs=1e-12
    )


def test_rigid_film_force_with_the_exact_gap_is_exact():
    """The film's quasi-steady force on a rigid true sphere (delta = 0.1, X = 0.01, thin layer)
    equals the quadrature of -V G(X) to 1e-10 on 50 to 200 nodes: the conductances are exact
    for a uniform squeeze with the undeformed gap exact between the nodes (measured 1e-13;
    the P1 Galerkin ones were 3.0e-4 off at 200 nodes). The paraboloid's force differs from
    the true sphere's by 1 %."""
    from test_film import quasi_steady

    gap, velocity, shape = 0.01, -1.0, ExactSpheres(DELTA)
    exact = -velocity * resistance(gap, shape)
    for n in (50, 100, 200):
        film = Film(radial_grid(n, np.sqrt(gap), 1.5), "thin", gap=shape)
        assert quasi_steady(film, gap, velocity)[1] / exact - 1 == pytest.approx(0, abs=1e-10)
    paraboloid = -velocity * resistance(gap, Paraboloid())
    assert abs(paraboloid / exact - 1) > 5e-3


@pytest.mark.slow
def test_rigid_true_sphere_slows_as_the_exact_quadrature():
    """A rigid true sphere (delta = 0.1) in a thin layer: |V| = 1 - int_X^1 G / St along the
    approach, within 0.005/St (the tolerance of the paraboloid's rigid test); 200 nodes."""
    St, shape = 3.0, ExactSpheres(DELTA)

    def loss(gap):
        return quad(lambda x: resistance(x, shape), gap, 1.0, limit=200)[0]

    stop = brentq(lambda x: loss(x) - St, 1e-6, 0.999)
    params = CollisionParameters(St=St, eps=1.0, delta=DELTA, gap=ExactGap())
    radii = radial_grid(200, np.sqrt(stop), 1.05 * np.sqrt(2))
    result = solve_normal(params, RigidSolids(radii), IntegratorOptions(rtol=1e-5))
    hist = result.history
    assert result.gap.name == "exact" and result.status == "stick"
    approaching = np.flatnonzero(hist.velocity < 0)[::10]
    exact_speed = np.array([1 - loss(x) / St for x in hist.gap[approaching]])
    assert np.abs(-hist.velocity[approaching] - exact_speed).max() < 0.005 / St
    assert hist.gap[-1] == pytest.approx(stop, rel=5e-3)


def test_exact_gap_refusals():
    """The exact gap needs a thin layer, and a film inside the sphere's equator; a gap is a
    registered choice (by name in the flat settings, an instance in the dataclass)."""
    with pytest.raises(InputError, match="gap = 'exact' needs layer = 'thin'"):
        CollisionParameters(St=10.0, eps=1e-3, layer="immersed", gap=ExactGap())
    with pytest.raises(InputError, match="gap"):
        CollisionParameters.from_settings(St=10.0, eps=1e-3, gap="spherical")
    with pytest.raises(InputError, match="gap must be one of the registered gap components"):
        CollisionParameters(St=10.0, eps=1e-3, gap="exact")
    with pytest.raises(InputError, match="equator"):
        ExactGap().shape(0.5).height(np.array([0.0, 1.5]))


def test_the_gap_is_chosen_by_name_and_defaults_to_the_solids_order():
    """The flat settings name the gap (None: the solids' default, the exact spheres for FE
    solids in a thin layer, the paraboloid otherwise) and round-trip it."""
    for name, cls in (("paraboloid", ParaboloidGap), ("exact", ExactGap)):
        params = CollisionParameters.from_settings(St=10.0, eps=1e-3, gap=name)
        assert params.gap == cls() and params.settings()["gap"] == name
        assert (
            CollisionParameters.from_settings(**params.settings(written=True), read=True) == params
        )
    unset = CollisionParameters(St=10.0, eps=1e-3)
    assert unset.gap is None and unset.settings()["gap"] is None
    assert CollisionParameters.from_settings(**unset.settings(written=True), read=True) == unset
    assert (
        default_gap("fem", "thin") == ExactGap()
        and default_gap("fem", "immersed") == ParaboloidGap()
    )
    assert default_gap("halfspace", "thin") == ParaboloidGap()


def test_exact_gap_film_tends_to_the_paraboloid_at_first_order_in_delta():
    """The rigid film's force with the true sphere differs from the paraboloid's by a term of
    order delta (the delta R^4/8 correction of the gap): the difference shrinks by 4.0 (within
    2 %) each time delta does, on one grid (X = 0.01, thin layer, 200 nodes)."""
    from test_film import quasi_steady

    radii = radial_grid(200, 0.1, 1.5)
    paraboloid = quasi_steady(Film(radii, "thin"), 0.01, -1.0)[1]
    differences = [
        quasi_steady(Film(radii, "thin", gap=ExactSpheres(d)), 0.01, -1.0)[1] - paraboloid
        for d in (0.04, 0.01, 0.0025)
    ]
    ratios = np.array(differences[:-1]) / differences[1:]
    assert differences[0] < 0  # the true sphere opens faster: less force
    assert ratios == pytest.approx(4.0, rel=0.02), ratios

"""Two spheres' leading logarithmic resistances across the line of centres
(ehdfem.exact.sphere_pair: Jeffrey & Onishi's 1984 closed forms), checked against exact
results: the equal-sphere values, the sphere-plane limit (Goldman, Cox & Brenner's 8/15, 2/15,
2/5), the exchange of the two spheres, reciprocity, the rigid motions of the pair (no
logarithm), and the sliding film's own split of the same coefficients (docs/tangential.md,
"Two spheres"), derived independently from the Reynolds film."""

from __future__ import annotations

import numpy as np
import pytest

from ehdfem.checks import InputError
from ehdfem.exact.sliding_sphere import LOGARITHMIC
from ehdfem.exact.sphere_pair import (
    coupling_log,
    cross_rotation_log,
    pair_logarithmic,
    rotation_log,
    sphere_logarithmic,
    translation_log,
)

pytestmark = pytest.mark.serial  # no parallel path: the MPI pass leaves it out

ROUNDING = 1e-14  # O(1) numbers from a few operations
RATIOS = [1.0, 0.8, 1.25, 3.0, 0.05, 40.0]  # a1/a2


def test_equal_spheres_have_the_known_values():
    """lambda = 1: Y^A_11 = 1/6, Y^B_11 = -1/4, Y^C_11 = 1/5, Y^C_12 = 1/20 (each times
    ln(1/h); Jeffrey & Onishi's normalisations)."""
    values = [f(1.0) for f in (translation_log, coupling_log, rotation_log, cross_rotation_log)]
    assert values == pytest.approx([1 / 6, -1 / 4, 1 / 5, 1 / 20], abs=ROUNDING)


def test_a_large_partner_gives_the_sphere_plane_logarithms():
    """lambda = a2/a1 -> infinity: Y^A_11 -> 8/15, Y^B_11 -> -1/5 (2/15 of 6 pi mu a^2),
    Y^C_11 -> 2/5, at first order in 1/lambda (the error times lambda tends to a constant), and
    the pair's matrix on (U, s1) tends to the sphere-plane's M = [[8/15, -2/15], [-2/15, 8/15]]
    (ehdfem.exact.sliding_sphere) likewise, the lower sphere's torque per unit radius 2/15."""
    limits = np.array([8 / 15, -1 / 5, 2 / 5])
    scaled = []
    for lam in (1e3, 1e4, 1e5):
        values = np.array([f(lam) for f in (translation_log, coupling_log, rotation_log)])
        scaled.append((values - limits) * lam)
        pair = pair_logarithmic(1.0 / lam)
        assert np.abs(pair[:2, :2] - LOGARITHMIC).max() < 2.0 / lam
    # first order: (value - limit) lambda settles (its own O(1/lambda) change: 2.2e-4 measured)
    assert scaled[2] == pytest.approx(scaled[1], rel=5e-4)
    assert pair_logarithmic(1e-12)[:2, :2] == pytest.approx(LOGARITHMIC, abs=1e-11)
    assert pair_logarithmic(1e-12)[1, 2] == pytest.approx(2 / 15, abs=1e-11)


@pytest.mark.parametrize("ratio", RATIOS)
def test_exchanging_the_spheres_is_the_inverse_ratio(ratio):
    """Sphere 2 seen as sphere 1 (the mirror image across the tangent plane: x velocities kept,
    both spins reversed, the spheres swapped) has the resistances of a1/a2 -> a2/a1: with P
    mapping (U1, U2, s1, s2) to (U2, U1, -s2, -s1), P R(r) P^T = R(1/r), to round-off."""
    mirror = np.array([[0, 1, 0, 0], [1, 0, 0, 0], [0, 0, 0, -1], [0, 0, -1, 0]], dtype=float)
    swapped = mirror @ sphere_logarithmic(ratio) @ mirror.T
    assert swapped == pytest.approx(sphere_logarithmic(1.0 / ratio), abs=ROUNDING)


@pytest.mark.parametrize("ratio", RATIOS)
def test_reciprocal_and_rigid_motions_unresisted(ratio):
    """R is symmetric (reciprocity: the torque of a translation is the force of the rotation)
    and positive semi-definite with rank 2; both spheres translating together and the pair
    turning rigidly about the contact point, v = (a1, -a2, a1, a2), meet no logarithmic
    resistance (the surfaces do not move relative to each other at the gap). This rigid
    rotation ties Y^A_11, Y^B_11, Y^C_11 and Y^C_12 together; each holds to round-off."""
    resistance = sphere_logarithmic(ratio)
    a1, a2 = 1.0 + ratio, 1.0 + 1.0 / ratio  # by the reduced radius
    assert np.abs(resistance - resistance.T).max() == 0.0
    for rigid in ([1.0, 1.0, 0.0, 0.0], [a1, -a2, a1, a2]):
        assert np.abs(resistance @ rigid).max() < ROUNDING * max(a1, a2)
    eigenvalues = np.linalg.eigvalsh(resistance)
    assert np.all(eigenvalues[:2] > -ROUNDING) and np.all(eigenvalues[2:] > 0.1)


@pytest.mark.parametrize("ratio", RATIOS)
def test_the_film_splits_them_into_slip_and_entrainment(ratio):
    """The sliding film's lubrication analysis (docs/tangential.md, "Two spheres"): the Couette
    shear of the slip u_s = U - s1 - s2 gives (1/3) e e^T, the mode-1 pressure of the
    entrainment w = rho U + s1 - s2, rho = (a2 - a1)/(a1 + a2), gives (1/5) g g^T, e = (1, -1,
    -1), g = (rho, 1, -1); Jeffrey & Onishi's closed forms give the same matrix on (U, s1, s2)
    to round-off."""
    rho = (1.0 - ratio) / (1.0 + ratio)
    slip, entrainment = np.array([1.0, -1.0, -1.0]), np.array([rho, 1.0, -1.0])
    film = np.outer(slip, slip) / 3.0 + np.outer(entrainment, entrainment) / 5.0
    assert pair_logarithmic(ratio) == pytest.approx(film, abs=ROUNDING)


def test_ratios_are_checked():
    """A size or radius ratio that is not finite and > 0 is refused by name."""
    with pytest.raises(InputError, match="size_ratio"):
        translation_log(np.array([1.0, -2.0]))
    with pytest.raises(InputError, match="radius_ratio"):
        pair_logarithmic(0.0)
    with pytest.raises(InputError, match="radius_ratio"):
        sphere_logarithmic(np.inf)

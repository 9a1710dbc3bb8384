"""A rigid sphere translating and rotating parallel to a plane wall at a small gap: the exact
resistances and those of the lubrication film cut at the sphere's radius.

Scales and signs of :mod:`ehdfem.tangential.motion`: on (U, a Omega) a resistance matrix R
gives the force -(R (U, a Omega))_1 by 6 pi mu a U and the torque over a, -(R (U, a Omega))_2,
by the same unit (the collision's resistance is delta R by 6 pi mu a^2 U0 / x0).

**Exact** (Goldman, Cox & Brenner 1967, matching O'Neill & Stewartson's 1967 lubrication
region to the outer Stokes flow). With L = ln(a/h), h the gap, a translating sphere feels the
force (8/15) L + 0.9588 (by 6 pi mu a U) and the torque (1/10) L - 0.1895 (by 8 pi mu a^2 U);
a rotating one the force (2/15) L - 0.2526 (by 6 pi mu a^2 Omega) and the torque
(2/5) L + 0.3817 (by 8 pi mu a^3 Omega), each to O((h/a) ln(h/a)). With the torques over a by
6 pi mu a U (times 4/3),

    R_exact = L M + C,   M = [[8/15, -2/15], [-2/15, 8/15]],
                         C = [[0.9588, 0.2526], [0.2526, (4/3) 0.3817]];

reciprocity makes it symmetric: (4/3) 0.1895 = 0.2526 (tested to the printed digits).

**The lubrication film cut at r = a** (what the sliding film computes for a rigid sphere). On
the paraboloid H = X + R^2/2 (gap X by x0, R by sqrt(a x0)) out to R_a = 1/sqrt(delta), with
L_a = ln(1 + R_a^2 / (2 X)) = L - ln 2 + O(delta X): the Couette shear gives (1/3) L_a on the
slip; the mode-1 pressure q = 6 w Pi (w = U + a Omega) solves
(1/R)(R H^3 Pi')' - H^3 Pi / R^2 = -R with Pi = 0 at R_a. Its particular solution R / (5 H^2)
gives the force (1/5)(L_a - 1) on w; the homogeneous one that makes Pi vanish at R_a grows
as R^(sqrt(10) - 3) in the far field (H ~ R^2/2) and adds -(2/5)/sqrt(10) to int Pi R^2 dR, a
constant. So

    R_film = L_a M - (1/5)(1 + 2/sqrt(10)) [[1, 1], [1, 1]]   (to O(delta X) and O(X/R_a^2)).

**Left out by the cut** at small gaps, R_exact - R_film = C + ln(2) M + (1/5)(1 + 2/sqrt(10))
[[1, 1], [1, 1]] = [[1.655, 0.487], [0.487, 1.205]]: positive definite, a resistance that only
dissipates, and a constant: the flow at r of order a (the sphere's far side, where the
lubrication approximation fails) does not see the gap, so it leaves out the same on a
deformed film whose contact is small against a.
"""

from __future__ import annotations

import math

import numpy as np

from .. import checks

LOGARITHMIC = np.array([[8.0, -2.0], [-2.0, 8.0]]) / 15.0  # M: the coefficients of ln(a/h)
# Goldman, Cox & Brenner (1967): translation force, the rotation's force and torque (4/3 of
# the torque by 8 pi mu a^3 Omega); the translation torque, 0.1895 by 8 pi mu a^2 U, is their
# reciprocal (4/3 0.1895 = 0.2527)
EXACT_CONSTANTS = np.array([[0.9588, 0.2526], [0.2526, 4.0 / 3.0 * 0.3817]])
TRANSLATION_TORQUE_CONSTANT = -0.1895  # by 8 pi mu a^2 U: the reciprocity check's other side
ROLLING = np.ones((2, 2))  # the pattern of a resistance on w = U + a Omega alone
MODE_ONE_END = (1.0 + 2.0 / math.sqrt(10.0)) / 5.0  # the cut film's pressure constant on w


def exact_resistance(gap_over_radius) -> np.ndarray:
    """Goldman, Cox & Brenner's R_exact = ln(a/h) M + C (module docstring) at h/a
    ``gap_over_radius`` (> 0, any shape; shape (..., 2, 2)), valid for h << a."""
    gap = np.asarray(gap_over_radius, dtype=float)
    if not np.all(gap > 0.0):
        raise checks.InputError("gap_over_radius must be > 0", "gap_over_radius")
    logarithm = -np.log(gap)[..., None, None]
    return logarithm * LOGARITHMIC + EXACT_CONSTANTS


def film_resistance(gap, delta: float) -> np.ndarray:
    """R_film of the lubrication film cut at the sphere's radius R_a = 1/sqrt(delta) on the
    paraboloid, at the gap X (by x0, > 0, any shape; delta = x0/a in (0, 1)): L_a M -
    (1/5)(1 + 2/sqrt(10)) [[1, 1], [1, 1]] with L_a = ln(1 + 1/(2 delta X)) (module
    docstring; to O(delta X))."""
    delta = checks.number("delta", delta, lower=0.0, upper=1.0, lower_open=True, upper_open=True)
    gap = np.asarray(gap, dtype=float)
    if not np.all(gap > 0.0):
        raise checks.InputError("gap must be > 0", "gap")
    logarithm = np.log1p(1.0 / (2.0 * delta * gap))[..., None, None]
    return logarithm * LOGARITHMIC - MODE_ONE_END * ROLLING


def left_out_by_cut() -> np.ndarray:
    """R_exact - R_film at small gaps: what the lubrication film cut at r = a leaves out of a
    rigid sphere's resistance, C + ln(2) M + (1/5)(1 + 2/sqrt(10)) [[1, 1], [1, 1]] (by
    6 pi mu a U, torque over a; module docstring)."""
    return EXACT_CONSTANTS + math.log(2.0) * LOGARITHMIC + MODE_ONE_END * ROLLING

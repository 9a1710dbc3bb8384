"""A rigid sphere moving towards a plane wall through a liquid at rest: Brenner's (1961) exact
Stokes resistance and its small-gap expansion.

The force on a sphere of radius a moving at V normal to a plane wall, its centre a + h from
it, is 6 pi mu a V lambda with (Brenner 1961, bispherical coordinates, cosh(alpha) = 1 + h/a)

    lambda = (4/3) sinh(alpha) sum_{n >= 1} n (n + 1) / ((2n - 1)(2n + 3))
             [ (2 sinh((2n + 1) alpha) + (2n + 1) sinh(2 alpha))
               / (4 sinh^2((n + 1/2) alpha) - (2n + 1)^2 sinh^2(alpha)) - 1 ].

For h << a it is a/h + (1/5) ln(a/h) + 0.9713 + O((h/a) ln(h/a)) (Cox & Brenner 1967): the
lubrication film's force 6 pi mu a^2 V / h (the immersed film's 1/X, scaled by
6 pi mu V a^2 / x0, :mod:`ehdfem.exact.rigid_film`) is its leading term; far from the wall it
tends to Stokes' drag, lambda -> 1 + (9/8) a/(a + h).
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from .. import checks

COX_BRENNER_CONSTANT = 0.9713  # the O(1) term of lambda at small gaps (Cox & Brenner 1967)
SMALLEST_GAP = 1e-5  # h/a: below it the series' first terms lose their digits to cancellation
LUBRICATION_GAP = 1e-4  # h/a below which :func:`resistance` is the small-gap expansion
SERIES_DECAY = 25.0  # the series' last term at n alpha = SERIES_DECAY (plus 50 terms)


def series_resistance(gap_over_radius: float) -> float:
    """Brenner's lambda at h/a = ``gap_over_radius`` (>= SMALLEST_GAP; module docstring). With
    k = 2n + 1 and sinh(alpha) = sqrt(h/a (2 + h/a)) (exact at small gaps), each bracket is
    summed as e^(-k alpha) (2 - 2 e^(-k alpha) + k sinh 2alpha + k^2 sinh^2 alpha) /
    ((1 - e^(-k alpha))^2 - k^2 sinh^2(alpha) e^(-k alpha)), the same quantity without
    overflow, over SERIES_DECAY/alpha + 50 terms (:func:`_brenner_sum`)."""
    gap = checks.number("gap_over_radius", gap_over_radius, lower=SMALLEST_GAP)
    return _brenner_sum(gap)


@njit(cache=True)
def _brenner_sum(gap: float) -> float:
    """Brenner's lambda at h/a = ``gap`` (:func:`series_resistance`), compiled: a flight asks
    for it at every evaluation of its forces. The terms fall as e^(-2 n alpha) times a
    quadratic in n: below 1e-19 of the sum after SERIES_DECAY/alpha + 50 of them. They are
    added from the last to the first, the smallest first, so that the sum's rounding is that
    of its last few terms."""
    root = math.sqrt(gap * (2.0 + gap))  # sinh(alpha)
    alpha = math.log1p(gap + root)  # acosh(1 + gap)
    sinh2 = root * root
    total = 0.0
    for i in range(int(SERIES_DECAY / alpha) + 50, 0, -1):
        n = float(i)
        k = 2.0 * n + 1.0
        decay = math.exp(-k * alpha)
        bracket = (
            decay
            * (2.0 - 2.0 * decay + k * 2.0 * root * (1.0 + gap) + k * k * sinh2)
            / (math.expm1(-k * alpha) ** 2 - k * k * sinh2 * decay)
        )
        total += n * (n + 1.0) / ((2.0 * n - 1.0) * (2.0 * n + 3.0)) * bracket
    return 4.0 / 3.0 * root * total


def resistance(gap_over_radius):
    """lambda at h/a = ``gap_over_radius`` (> 0; a float or an array): the series
    (:func:`series_resistance`) from LUBRICATION_GAP on, Cox & Brenner's expansion
    (:func:`small_gap_resistance`) below, where the two differ by less than 1e-8 relative.
    F = -6 pi mu a v lambda is the force on the sphere moving at v normal to the wall."""
    if np.ndim(gap_over_radius) == 0:
        gap = float(gap_over_radius)
        if gap >= LUBRICATION_GAP:
            return series_resistance(gap)
        return float(small_gap_resistance(gap))
    return np.array([resistance(g) for g in np.asarray(gap_over_radius, dtype=float)])


def small_gap_resistance(gap_over_radius) -> np.ndarray:
    """Cox & Brenner's a/h + (1/5) ln(a/h) + 0.9713 at h/a = ``gap_over_radius`` (> 0)."""
    gap = np.asarray(gap_over_radius, dtype=float)
    if not np.all(gap > 0.0):
        raise checks.InputError("gap_over_radius must be > 0", "gap_over_radius")
    return 1.0 / gap + 0.2 * np.log(1.0 / gap) + COX_BRENNER_CONSTANT

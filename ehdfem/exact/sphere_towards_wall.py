"""A rigid sphere moving towards a plane wall through a liquid at rest: Brenner's (1961) exact
Stokes resistance and its small-gap expansion.

The force on a sphere of radius a moving at V normal to a plane wall, its centre a + h from
it, is 6 pi mu a V lambda with (Brenner 1961, bispherical coordinates, cosh(alpha) = 1 + h/a)

    lambda = (4/3) sinh(alpha) sum_{n >= 1} n (n + 1) / ((2n - 1)(2n + 3))
             [ (2 sinh((2n + 1) alpha) + (2n + 1) sinh(2 alpha))
               / (4 sinh^2((n + 1/2) alpha) - (2n + 1)^2 sinh^2(alpha)) - 1 ].

For h << a it is a/h + (1/5) ln(a/h) + 0.971 + O((h/a) ln(h/a)) (Cox & Brenner 1967): the
lubrication film's force 6 pi mu a^2 V / h (the immersed film's 1/X, scaled by
6 pi mu V a^2 / x0, :mod:`ehdfem.exact.rigid_film`) is its leading term; far from the wall it
tends to Stokes' drag, lambda -> 1 + (9/8) a/(a + h).
"""

from __future__ import annotations

import math

import numpy as np

from .. import checks

COX_BRENNER_CONSTANT = 0.971  # the O(1) term of lambda at small gaps (Cox & Brenner 1967)


SMALLEST_GAP = 1e-5  # h/a: below it the series' first terms lose their digits to cancellation


def resistance(gap_over_radius: float, tolerance: float = 1e-14) -> float:
    """Brenner's lambda at h/a = ``gap_over_radius`` (>= SMALLEST_GAP; module docstring),
    summed until a term falls below ``tolerance`` times the sum (the terms fall as
    exp(-2 n alpha)); below SMALLEST_GAP :func:`small_gap_resistance` is exact to 4e-4 (its
    constant's printed digits; tests/test_outer_flow.py)."""
    gap = checks.number("gap_over_radius", gap_over_radius, lower=SMALLEST_GAP)
    root = math.sqrt(gap * (2.0 + gap))  # sinh(alpha), exact for small gaps
    alpha = math.log1p(gap + root)  # acosh(1 + gap)
    total, n = 0.0, 1
    while True:
        # exp(-(2n + 1) alpha) times numerator and denominator keeps them finite at large n
        decay = math.exp(-(2 * n + 1) * alpha)
        numerator = 1.0 - decay**2 + (2 * n + 1) * 2.0 * root * (1.0 + gap) * decay
        denominator = math.expm1(-(2 * n + 1) * alpha) ** 2 - (2 * n + 1) ** 2 * root**2 * decay
        term = n * (n + 1) / ((2 * n - 1) * (2 * n + 3)) * (numerator / denominator - 1.0)
        total += term
        if abs(term) <= tolerance * abs(total) and n > 2:
            return 4.0 / 3.0 * root * total
        n += 1


def small_gap_resistance(gap_over_radius) -> np.ndarray:
    """Cox & Brenner's a/h + (1/5) ln(a/h) + 0.971 at h/a = ``gap_over_radius`` (> 0)."""
    gap = np.asarray(gap_over_radius, dtype=float)
    if not np.all(gap > 0.0):
        raise checks.InputError("gap_over_radius must be > 0", "gap_over_radius")
    return 1.0 / gap + 0.2 * np.log(1.0 / gap) + COX_BRENNER_CONSTANT

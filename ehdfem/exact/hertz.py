"""The dry Hertz impact of a sphere, exact.

A sphere of mass m and radius a on a half-space (1/E* = sum (1 - nu^2)/E over the two solids)
at the normal speed V0 compresses to delta_max = (15 m V0^2 / (16 E* a^(1/2)))^(2/5) and stays
in contact for 2.87 (m^2 / (a E*^2 V0))^(1/5) (Johnson, Contact Mechanics, 1985, ch. 11).
"""

from __future__ import annotations

import math


def max_compression(eps, St):
    """delta_max scaled by x0: with m V0 = 6 pi mu a^2 St and 1/E* = pi theta, theta from eps
    = 4 theta mu V0 a^(3/2) / x0^(5/2), delta_max = (90 pi^2/64 eps St)^(2/5) x0 =
    (13.88 eps St)^(2/5) x0 (arrays broadcast)."""
    return (90.0 * math.pi**2 / 64.0 * eps * St) ** 0.4


def compression_force(eps, compression):
    """Hertz's force (4/3) E* a^(1/2) d^(3/2) for the compression d = ``compression`` x0
    (>= 0), by 6 pi mu V0 a^2 / x0: with 1/E* = pi theta and theta from eps (as in
    :func:`max_compression`), 8 / (9 pi^2 eps) d^(3/2) (arrays broadcast). Its work from 0 to
    delta_max at the speed V0 is St/2 (by 6 pi mu V0^2 a^2 / x0)."""
    return 8.0 / (9.0 * math.pi**2 * eps) * compression**1.5


def contact_time(mass: float, radius: float, modulus: float, speed: float) -> float:
    """Duration [s] of the Hertz contact for the (reduced) ``mass`` [kg] and ``radius`` [m],
    the contact modulus E* [Pa] and the normal ``speed`` [m/s]: 2.87 (m^2/(R E*^2 V))^(1/5)."""
    return 2.87 * (mass**2 / (radius * modulus**2) / speed) ** 0.2

"""Two rigid spheres translating and rotating across their line of centres at a small gap: the
leading logarithmic resistances (Jeffrey & Onishi 1984, J. Fluid Mech. 139; O'Neill &
Majumdar 1970), the two-sphere form of Goldman, Cox & Brenner's sphere-plane logarithms.

Sphere 1 (radius a1) lies above sphere 2 (a2), size ratio lambda = a2/a1, reduced radius
a = a1 a2/(a1 + a2), gap h << a. With L = ln(1/h) (+ O(1)) Jeffrey & Onishi's resistance
functions of the motions across the line of centres have the singular parts (their
normalisations: A_11 by 6 pi mu a1, B_11 by 4 pi mu a1^2, C_11 by 8 pi mu a1^3, C_12 by
pi mu (a1 + a2)^3; forces and torques the spheres exert on the fluid)

    Y^A_11 = (4/15) lambda (2 + lambda + 2 lambda^2) / (1 + lambda)^3  L,
    Y^B_11 = -(1/5) lambda (4 + lambda) / (1 + lambda)^2  L,
    Y^C_11 = (2/5) lambda / (1 + lambda)  L,
    Y^C_12 = (4/5) lambda^2 / (1 + lambda)^4  L,

sphere 2's own ones the same at 1/lambda (Y^B with the opposite sign: the partner lies on its
other side), and Y^A_12, Y^B_12 those that leave a translation of both spheres together
unresisted (Y^A_12 = -2 Y^A_11 / (1 + lambda)). lambda -> infinity gives the sphere-plane
values 8/15, -1/5 (= 2/15 by 6 pi mu a^2), 2/5 and Y^C_12 -> 0.

**In the project's axes and scales** (:mod:`ehdfem.tangential.pair`): the velocities
v = (U1, U2, s1, s2) along x, s_i = a_i Omega_i, both spins about the same axis (the surfaces
at the contact move at U1 - s1 and U2 + s2), and the generalised forces on the spheres
(F1, F2, T1/a1, T2/a2) = -L R v, by 6 pi mu a U (a the reduced radius): each torque over its
own sphere's radius, so that v . (F1, F2, T1/a1, T2/a2) is the power of the film on the
spheres. R is symmetric (reciprocity), positive semi-definite, and its null vectors are the
rigid motions of the pair: both translating together, and both turning about the contact
point (v = (a1, -a2, a1, a2)): no relative motion of the surfaces at the gap, no logarithm.
With U = U1 - U2 (R depends on it alone) it is the 3 x 3 matrix on (U, s1, s2) of
:func:`pair_logarithmic`, which the sliding film's lubrication analysis gives as

    R = (1/3) e e^T + (1/5) g g^T,   e = (1, -1, -1),   g = (rho, 1, -1),
    rho = (a2 - a1) / (a1 + a2):

the Couette shear of the slip u_s = U - s1 - s2 and the mode-1 pressure of the entrainment
w = rho U + s1 - s2 (docs/tangential.md, "Two spheres").
"""

from __future__ import annotations

import numpy as np

from .. import checks


def translation_log(size_ratio):
    """Y^A_11's coefficient of ln(1/h), by 6 pi mu a1: (4/15) lambda (2 + lambda + 2 lambda^2)
    / (1 + lambda)^3 at lambda = a2/a1 ``size_ratio`` (> 0, any shape)."""
    lam = _ratio(size_ratio)
    return 4.0 / 15.0 * lam * (2.0 + lam + 2.0 * lam**2) / (1.0 + lam) ** 3


def coupling_log(size_ratio):
    """Y^B_11's coefficient of ln(1/h), by 4 pi mu a1^2: -(1/5) lambda (4 + lambda) /
    (1 + lambda)^2 at lambda = a2/a1 ``size_ratio``."""
    lam = _ratio(size_ratio)
    return -0.2 * lam * (4.0 + lam) / (1.0 + lam) ** 2


def rotation_log(size_ratio):
    """Y^C_11's coefficient of ln(1/h), by 8 pi mu a1^3: (2/5) lambda / (1 + lambda) at
    lambda = a2/a1 ``size_ratio``."""
    lam = _ratio(size_ratio)
    return 0.4 * lam / (1.0 + lam)


def cross_rotation_log(size_ratio):
    """Y^C_12's coefficient of ln(1/h), by pi mu (a1 + a2)^3: (4/5) lambda^2 / (1 + lambda)^4
    at lambda = a2/a1 ``size_ratio``."""
    lam = _ratio(size_ratio)
    return 0.8 * lam**2 / (1.0 + lam) ** 4


def sphere_logarithmic(radius_ratio: float) -> np.ndarray:
    """The (4, 4) R of both spheres on v = (U1, U2, s1, s2) at a1/a2 ``radius_ratio`` (> 0):
    the coefficients of ln(1/h) in -(F1, F2, T1/a1, T2/a2), by 6 pi mu a U with a the reduced
    radius (module docstring), from Jeffrey & Onishi's Y^A_11, Y^B_11, Y^C_11 and Y^C_12,
    each sphere's own at its size ratio, and the translation of both together unresisted."""
    ratio = checks.positive("radius_ratio", radius_ratio)
    lam = 1.0 / ratio  # a2/a1
    upper, lower = 1.0 + ratio, 1.0 + lam  # a1/a, a2/a
    translation = upper * translation_log(lam)  # = lower * translation_log(1/lam)
    # the spins' resistances to U1: sphere 2's own (to U2) has Y^B's opposite sign, so to U1 its
    # sign is sphere 1's
    turns = (2.0 / 3.0 * upper * coupling_log(lam), 2.0 / 3.0 * lower * coupling_log(ratio))
    spins = (4.0 / 3.0 * upper * rotation_log(lam), 4.0 / 3.0 * lower * rotation_log(ratio))
    cross = (1.0 + lam) ** 4 / (6.0 * lam**2) * cross_rotation_log(lam)  # (a1 + a2)^3/(6 a a1 a2)
    relative = np.array([1.0, -1.0])  # U1 - U2
    resistance = np.zeros((4, 4))
    resistance[:2, :2] = translation * np.outer(relative, relative)
    resistance[2:, :2] = np.outer(turns, relative)
    resistance[:2, 2:] = resistance[2:, :2].T
    resistance[2:, 2:] = [[spins[0], cross], [cross, spins[1]]]
    return resistance


def pair_logarithmic(radius_ratio: float) -> np.ndarray:
    """The (3, 3) R on (U, s1, s2), U = U1 - U2, at a1/a2 ``radius_ratio``: the coefficients of
    ln(1/h) in -(F1, T1/a1, T2/a2) by 6 pi mu a U (:func:`sphere_logarithmic` with U2 = 0; the
    generalised force of U in the centre-of-mass frame is F1)."""
    return sphere_logarithmic(radius_ratio)[np.ix_([0, 2, 3], [0, 2, 3])]


def _ratio(size_ratio):
    ratio = np.asarray(size_ratio, dtype=float)
    if not np.all(np.isfinite(ratio) & (ratio > 0.0)):
        raise checks.InputError(
            f"size_ratio must be > 0 and finite, got {size_ratio!r}", "size_ratio"
        )
    return ratio

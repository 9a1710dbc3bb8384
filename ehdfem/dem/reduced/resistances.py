"""The lubrication forces that CFD-DEM codes add between two near spheres: the normal Reynolds
force and the leading logarithmic tangential forces and torques of two rigid spheres.

Sphere 1 (radius a1) above sphere 2 (a2) along the line of centres, reduced radius
a = a1 a2 / (a1 + a2), surface gap h << a; conventions of :mod:`ehdfem.tangential.pair`: U the
relative tangential velocity of the centres, s_i = a_i Omega_i the spins' surface speeds, both
about the same axis. The forces are

    normal force on sphere 1      F_n = -6 pi mu a^2 v / h                       (Reynolds),
    tangential, on (U, s1, s2)    -(F_1, T_1/a1, T_2/a2) = 6 pi mu a ln(a/h) R (U, s1, s2),

sphere 2 taking -F_1, with R Jeffrey & Onishi's (1984) logarithmic resistances of the pair
(:func:`ehdfem.exact.sphere_pair.pair_logarithmic`: the Couette shear of the slip
u_s = U - s1 - s2 and the mode-1 pressure of the entrainment w = rho U + s1 - s2). The torques
are given as the tangential forces at the contact point that exert them: G_1 = -T_1/a1 on
sphere 1 and G_2 = T_2/a2 on sphere 2, so that m1 k1 ds1/dt = -G_1 and m2 k2 ds2/dt = G_2 (the
signs of a contact force F_c, which acts as G_1 = F_c on sphere 1 and G_2 = -F_c on sphere 2).
The power they take from the pair is 6 pi mu a ln(a/h) v.R v >= 0. The O(1) constants of the
exact resistances and the terms of order h/a are left out, as the CFD-DEM codes do.

Scaled (time by x0/V0, velocities by V0, forces by 6 pi mu V0 a^2 / x0, gap H = h/x0,
delta = x0/a): F_n = -V/H and the tangential ones delta L R v with L = ln(1/(delta H)).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np


def normal_force(gap: float, velocity: float) -> float:
    """Reynolds' squeeze force on sphere 1, -V/H (scaled; ``gap`` H > 0, ``velocity`` V the
    rate of change of the gap): 6 pi mu a^2 v / h by 6 pi mu V0 a^2 / x0."""
    return -velocity / gap


@dataclass(frozen=True)
class TangentialForces:
    """The tangential lubrication forces of the module docstring (scaled by
    6 pi mu V0 a^2 / x0): ``upper`` F_1 (sphere 2 takes -F_1), ``upper_turning`` G_1 and
    ``lower_turning`` G_2; ``dissipation`` the power taken from the pair, delta L v.R v (by
    6 pi mu V0^2 a^2 / x0)."""

    upper: float
    upper_turning: float
    lower_turning: float
    dissipation: float


def tangential_forces(gap, delta, resistance, velocities) -> TangentialForces:
    """The leading-log tangential forces at the scaled ``gap`` H (delta H < 1) for ``delta`` =
    x0/a, the pair's 3 x 3 ``resistance`` R (:func:`ehdfem.exact.sphere_pair.pair_logarithmic`)
    and ``velocities`` (U, s1, s2) by V0."""
    scale = delta * math.log(1.0 / (delta * gap))
    generalised = -scale * (resistance @ velocities)  # (F_1, T_1/a1, T_2/a2)
    return TangentialForces(
        upper=float(generalised[0]),
        upper_turning=float(-generalised[1]),
        lower_turning=float(generalised[2]),
        dissipation=float(-np.dot(generalised, velocities)),
    )

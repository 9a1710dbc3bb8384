"""The lubrication resistances of two rigid spheres at a small gap, at leading order: the
forces and torques that CFD-DEM codes add between near particles.

Sphere 1 (radius a1) above sphere 2 (a2) along the line of centres, reduced radius
a = a1 a2 / (a1 + a2), surface gap h << a; conventions of :mod:`ehdfem.tangential.pair`: U the
relative tangential velocity of the centres, s_i = a_i Omega_i the spins' surface speeds, the
slip u_s = U - s1 - s2 and, with b = (a2 - a1)/(a1 + a2), the film's entrainment
w = b U + s1 - s2 (docs/tangential.md, "Two spheres"). With L = ln(a/h):

    normal force on sphere 1           F_n = -6 pi mu a^2 v / h          (Reynolds),
    tangential force on sphere 1       F_1 = -6 pi mu a L (u_s/3 + b w/5),
    contact force turning sphere 1     G_1 = -6 pi mu a L (u_s/3 - w/5),
    contact force turning sphere 2     G_2 = +6 pi mu a L (u_s/3 + w/5),

sphere 2 taking -F_1; G_i is the tangential force at the contact point that gives sphere i its
torque (a_i G_i about its centre): m1 k1 ds1/dt = -G_1, m2 k2 ds2/dt = G_2. The u_s/3 terms
are the Couette shear of the slip, 2 pi mu a L u_s; the w/5 terms the mode-1 pressure of the
entrainment, its shear traction (the same on both surfaces) and its tilt on the gap
(b times the gap's slope). These are Jeffrey & Onishi's (1984, J. Fluid Mech. 139) logarithmic
terms of the two-sphere resistances Y^A_11, Y^B_11, Y^C_11, and for a2 -> inf Goldman, Cox &
Brenner's (1967, Chem. Eng. Sci. 22) of a sphere near a wall (tests/test_reduced_pair.py). The
power they take from the pair, -6 pi mu a L (u_s^2/3 + w^2/5), is never positive. The O(1)
constants of the exact resistances and the terms of order h/a are left out, as the CFD-DEM
codes do.

Scaled (time by x0/V0, velocities by V0, forces by 6 pi mu V0 a^2 / x0, gap H = h/x0,
delta = x0/a): F_n = -V/H and the tangential ones delta L (...) with L = ln(1/(delta H)).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ... import checks


def entrainment_factor(radius_ratio: float) -> float:
    """b = (a2 - a1)/(a1 + a2) = (1 - r)/(1 + r) for ``radius_ratio`` r = a1/a2 > 0 (1 for a
    wall, 0 for equal spheres)."""
    ratio = checks.positive("radius_ratio", radius_ratio)
    return (1.0 - ratio) / (1.0 + ratio)


def normal_force(gap: float, velocity: float) -> float:
    """Reynolds' squeeze force on sphere 1, -V/H (scaled; ``gap`` H > 0, ``velocity`` V the
    rate of change of the gap): 6 pi mu a^2 v / h by 6 pi mu V0 a^2 / x0."""
    return -velocity / gap


@dataclass(frozen=True)
class TangentialForces:
    """The tangential lubrication forces of the module docstring (scaled by
    6 pi mu V0 a^2 / x0): ``upper`` F_1 (sphere 2 takes -F_1), ``upper_turning`` G_1 and
    ``lower_turning`` G_2; ``dissipation`` the power taken from the pair, delta L (u_s^2/3 +
    w^2/5) (by 6 pi mu V0^2 a^2 / x0)."""

    upper: float
    upper_turning: float
    lower_turning: float
    dissipation: float


def tangential_forces(gap, delta, b, velocity, upper_spin, lower_spin) -> TangentialForces:
    """The leading-log tangential forces at the scaled ``gap`` H (delta H < 1) for
    ``delta`` = x0/a, the :func:`entrainment_factor` ``b``, the relative tangential
    ``velocity`` U and the spins ``upper_spin`` s1, ``lower_spin`` s2 (all by V0)."""
    log = math.log(1.0 / (delta * gap))
    slip = velocity - upper_spin - lower_spin
    entrainment = b * velocity + upper_spin - lower_spin
    scale = delta * log
    return TangentialForces(
        upper=-scale * (slip / 3.0 + b * entrainment / 5.0),
        upper_turning=-scale * (slip / 3.0 - entrainment / 5.0),
        lower_turning=scale * (slip / 3.0 + entrainment / 5.0),
        dissipation=scale * (slip**2 / 3.0 + entrainment**2 / 5.0),
    )

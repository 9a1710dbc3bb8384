"""The impact of a rigid sphere on a plane with Coulomb friction, exact (rigid-body impact
theory: the normal impulse builds up while the friction opposes a slip of constant sign, and a
sphere on a plane has no coupling of the normal and tangential impulses).

psi = u_s U0 / (|V| V0), the contact point's tangential velocity over the normal approach
velocity; k = I / (m a^2), mu the friction coefficient, e_n the normal restitution. The
tangential impulse is at most mu (1 + e_n) m |V|, and changes psi by (1 + 1/k) times it over
m |V|: the contact slides throughout, or sticks (then rolls, psi_out = 0). Two free spheres
(:func:`pair_impact`) take the same law with both spheres' masses and moments of inertia.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


def frictional_impact(psi_in: float, mu: float, e_n: float, k: float) -> tuple[float, bool]:
    """(psi_out, stuck) of a rigid sphere's impact on a plane with Coulomb friction ``mu``,
    normal restitution ``e_n`` and inertia factor k (psi = contact-point tangential velocity
    over the normal approach velocity; module docstring): sliding throughout,
    psi_out = psi_in - (1 + 1/k) mu (1 + e_n) sign(psi_in); stuck (psi_out = 0) once
    |psi_in| <= (1 + 1/k) mu (1 + e_n)."""
    reach = (1.0 + 1.0 / k) * mu * (1.0 + e_n)
    if abs(psi_in) <= reach:
        return 0.0, True
    return psi_in - reach * np.sign(psi_in), False


@dataclass(frozen=True)
class PairImpact:
    """The outcome of a rigid two-sphere impact with Coulomb friction (:func:`pair_impact`), in
    the units of its inputs: ``impulse`` the tangential impulse on sphere 1 (sphere 2 takes
    -impulse), ``slip_after`` the contact points' slip after the impact, ``stuck`` whether the
    slip stopped, ``velocity_changes`` (dU1, dU2) of the centres and ``spin_changes``
    (dOmega1, dOmega2) of the spins about the common axis."""

    impulse: float
    slip_after: float
    stuck: bool
    velocity_changes: tuple[float, float]
    spin_changes: tuple[float, float]


def pair_impact(slip, approach_speed, mu, e_n, masses, radii, inertia_factors) -> PairImpact:
    """The impact of two rigid spheres with Coulomb friction ``mu`` and normal restitution
    ``e_n`` (rigid-body impact theory; the line of centres is the normal, so the normal and
    tangential impulses do not couple). ``slip``: the contact points' relative tangential
    velocity u_s = U1 - U2 - (a1 Omega1 + a2 Omega2) before it (both spins about the same axis,
    sphere 2's surface at the contact moving at U2 + a2 Omega2); ``approach_speed`` the
    centres' normal approach speed |V|; ``masses`` (m1, m2), ``radii`` (a1, a2),
    ``inertia_factors`` (k1, k2), I_i = k_i m_i a_i^2. The normal impulse is
    N = (1 + e_n) |V| m1 m2 / (m1 + m2); a tangential impulse J on sphere 1 changes

        dU1 = J / m1,  dU2 = -J / m2,  dOmega1 = -a1 J / I1,  dOmega2 = -a2 J / I2,
        du_s = J (1/m1 + 1/m2 + a1^2/I1 + a2^2/I2),

    and J is the impulse that stops the slip, clipped to [-mu N, mu N] (sliding throughout
    otherwise, J = -mu N sign(u_s)). Units: any consistent set (the outputs in those of the
    inputs)."""
    (m1, m2), (a1, a2), (k1, k2) = masses, radii, inertia_factors
    inertias = (k1 * m1 * a1**2, k2 * m2 * a2**2)
    normal = (1.0 + e_n) * approach_speed * m1 * m2 / (m1 + m2)
    compliance = 1.0 / m1 + 1.0 / m2 + a1**2 / inertias[0] + a2**2 / inertias[1]
    stopping = -slip / compliance
    stuck = abs(stopping) <= mu * normal
    impulse = stopping if stuck else -mu * normal * float(np.sign(slip))
    return PairImpact(
        impulse=float(impulse),
        slip_after=0.0 if stuck else float(slip + compliance * impulse),
        stuck=bool(stuck),
        velocity_changes=(impulse / m1, -impulse / m2),
        spin_changes=(-a1 * impulse / inertias[0], -a2 * impulse / inertias[1]),
    )
